"""Linear (bilateral-saddle) response: static plus frequency domain, partitioned form.

For each harmonic k (docs/theory.md#4-linear-model)::

    K_d^cc(k omega) X^c_k = F^c_k - K_d^co(k omega) X^o_k      (cargo response)
    F^o_k = K_d^oc X^c_k + K_d^oo X^o_k                        (forces needed at the deck)

with every saddle a bilateral spring of its full stiffness. k = 0 uses K alone and carries the
cargo weight and lashing pretension.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray
from scipy.linalg import cho_factor, cho_solve, lu_factor, lu_solve

from seafast.excitation.harmonic import HarmonicExcitation
from seafast.model.structure import StructuralModel
from seafast.solvers.dynamic_stiffness import linear_force_harmonics, quadratic_matrices, solve_dynamic_stack

__all__ = ["LinearResponse", "solve_linear", "solve_harmonic"]


@dataclass(frozen=True)
class LinearResponse:
    """Harmonic amplitudes of the linear response, k = 0 .. n_k - 1.

    Attributes
    ----------
    cargo_displacement
        Cargo DOFs (z [m], theta [rad]) relative to the vessel's rigid-body frame, (n_k, n_c).
    saddle_compression_m
        delta = z_deck - z_cargo at each saddle [m], positive compressed, (n_k, n_s).
    saddle_force_N
        Saddle normal force on the cargo [N], positive pushing up, (n_k, n_s): the saddle's
        compression part (k_sad - k_z) times the compression. Negative = tension, which a real
        saddle cannot carry (the linear model's known defect).
    deck_force_N
        Forces the deck must exert to impose its motion [N, N m], (n_k, n_o).
    """

    omega_rad_s: float
    cargo_displacement: NDArray[np.complex128]
    saddle_compression_m: NDArray[np.complex128]
    saddle_force_N: NDArray[np.complex128]
    deck_force_N: NDArray[np.complex128]


def solve_harmonic(
    model: StructuralModel, omega_rad_s: float, cargo_load: NDArray, deck_displacement: NDArray, include_saddles: bool = True
) -> NDArray:
    """Solve K_d^cc x = f - K_d^co x_o at one frequency; several right-hand sides allowed.

    ``cargo_load`` has shape (n_c,) or (n_c, n_rhs); ``deck_displacement`` (n_o,) or (n_o, n_rhs).
    At omega = 0 the symmetric positive-definite K is Cholesky-factorised.
    """
    Kd_cc, Kd_co, _, _ = model.dynamic_stiffness(omega_rad_s, include_saddles)
    rhs = cargo_load - Kd_co @ deck_displacement
    if omega_rad_s == 0.0:
        return cho_solve(cho_factor(Kd_cc), rhs.real) + (1j * cho_solve(cho_factor(Kd_cc), rhs.imag) if np.iscomplexobj(rhs) else 0.0)
    return lu_solve(lu_factor(Kd_cc), rhs)


def solve_linear(model: StructuralModel, excitation: HarmonicExcitation) -> LinearResponse:
    """Linear response of the cargo to the excitation (all harmonics), static part included.

    One banded LU per harmonic (:func:`~seafast.solvers.dynamic_stiffness.solve_dynamic_stack`, the
    factorisation the harmonic balance's condensation uses, so both see the same linear solution to the bit).
    """
    n_k = excitation.harmonic_count
    q = quadratic_matrices(model, True)
    loads = linear_force_harmonics(model, excitation, quasi_static=False)  # f_static + f_vessel - K_d^co x_o
    X = solve_dynamic_stack(q, excitation.omega_rad_s * np.arange(n_k), loads[:, :, None])[:, :, 0]
    X[0] = X[0].real
    F_o = np.zeros((n_k, model.deck_dof_count), dtype=complex)
    for k in range(n_k):
        _, _, Kd_oc, Kd_oo = model.dynamic_stiffness(k * excitation.omega_rad_s, True)
        F_o[k] = Kd_oc @ X[k] + Kd_oo @ excitation.deck_displacement[k]
    delta = excitation.deck_displacement[:, model.saddle_deck_dof] - X[:, model.saddle_cargo_dof]
    force = delta * model.saddle_unilateral_stiffness_N_per_m
    return LinearResponse(excitation.omega_rad_s, X, delta, force, F_o)
