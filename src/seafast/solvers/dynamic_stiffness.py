"""Dynamic stiffness of the cargo DOFs, banded, and its solves per harmonic.

The structural model gives ``K_d(omega) = K - omega^2 M + i omega D`` of the cargo DOFs (and
of the cargo-deck coupling). The harmonic balance, the exact references and the continuation
all solve ``K_d^cc(k omega) x_k = rhs_k`` for many harmonics k; this module splits K_d into
K, M and D once per model (kept in the model's ``derived_cache``), stores them in LAPACK band form, and
solves one harmonic (:func:`solve_dynamic`) or all of them (:func:`solve_dynamic_stack`).

Units: K [N/m, N m/rad], M [kg, kg m^2], D [N s/m]; rhs in N (N m for rotations); solutions in
m (rad). Saddles are bilateral springs of their full stiffness when ``include_saddles`` is
True.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np
from numpy.typing import NDArray
from scipy.linalg import solve_banded

from seafast.excitation.harmonic import HarmonicExcitation
from seafast.model.structure import StructuralModel
from seafast.solvers.banded import solve_dynamic_band_stack

__all__ = [
    "QuadraticMatrices",
    "quadratic_matrices",
    "from_band",
    "solve_dynamic",
    "solve_dynamic_stack",
    "saddle_selection",
    "linear_force_harmonics",
]


@dataclass(frozen=True)
class QuadraticMatrices:
    """K, M, D of the cargo DOFs (saddles bilateral) and of the cargo-deck coupling, banded.

    Attributes
    ----------
    coupling_stiffness, coupling_mass, coupling_damping
        The cargo-deck blocks, (n_c, n_o): K_co of the springs, zero mass (the deck carries none), and the damping's
        coupling to the deck velocities ``D_co`` (:attr:`~seafast.model.structure.StructuralModel.support_damping_coupling`:
        the cargo is damped on its motion relative to the quasi-static support motion).
    bandwidth
        Half bandwidth of K, M, D together.
    banded_stiffness, banded_mass, banded_damping
        K [N/m], M [kg], D [N s/m] of the cargo DOFs in LAPACK general band storage, (2 bandwidth + 1, n_c).
    stiffness, mass, damping
        The same dense, (n_c, n_c), formed from the bands on first use (the references need them; the
        harmonic balance never does, so a fine mesh pays O(n) here, not O(n^2)).
    """

    coupling_stiffness: NDArray[np.float64]
    coupling_mass: NDArray[np.float64]
    coupling_damping: NDArray[np.float64]
    bandwidth: int
    banded_stiffness: NDArray[np.float64]
    banded_mass: NDArray[np.float64]
    banded_damping: NDArray[np.float64]

    @cached_property
    def stiffness(self) -> NDArray[np.float64]:
        return from_band(self.banded_stiffness, self.bandwidth)

    @cached_property
    def mass(self) -> NDArray[np.float64]:
        return from_band(self.banded_mass, self.bandwidth)

    @cached_property
    def damping(self) -> NDArray[np.float64]:
        return from_band(self.banded_damping, self.bandwidth)


def from_band(ab: NDArray, bandwidth: int) -> NDArray:
    """The dense matrix of band storage ``ab[bw + i - j, j] = A[i, j]``."""
    n = ab.shape[1]
    A = np.zeros((n, n), dtype=ab.dtype)
    for offset in range(-bandwidth, bandwidth + 1):
        i = np.arange(max(0, -offset), min(n, n - offset))
        A[i, i + offset] = ab[bandwidth - offset, i + offset]
    return A


def quadratic_matrices(model: StructuralModel, include_saddles: bool = True) -> QuadraticMatrices:
    """``model.dynamic_stiffness`` as K - w^2 M + i w D, banded (``model.banded_quadratic``, O(n)).

    Computed once per model and ``include_saddles``, kept in the model's ``derived_cache``.
    """
    key = f"quadratic_matrices(include_saddles={bool(include_saddles)})"
    cached = model.derived_cache.get(key)
    if isinstance(cached, QuadraticMatrices):
        return cached
    bw, K, M, D, Kco = model.banded_quadratic(include_saddles)
    Kco = np.asarray(Kco, dtype=float)
    # the deck carries no mass; the damping couples to the deck velocities through the quasi-static support motion
    q = QuadraticMatrices(Kco, np.zeros_like(Kco), np.asarray(model.support_damping_coupling, dtype=float), int(bw), K, M, D)
    model.derived_cache[key] = q
    return q


def solve_dynamic(q: QuadraticMatrices, omega: float, rhs: NDArray) -> NDArray:
    """Solve (K - w^2 M + i w D) x = rhs (banded when the band is narrow); omega [rad/s]."""
    n = q.banded_stiffness.shape[1]
    if q.bandwidth < n // 4:
        if omega == 0.0:
            ab = q.banded_stiffness
        else:
            ab = q.banded_stiffness - omega**2 * q.banded_mass + 1j * omega * q.banded_damping
        return solve_banded((q.bandwidth, q.bandwidth), ab, rhs, check_finite=False)
    A = q.stiffness if omega == 0.0 else q.stiffness - omega**2 * q.mass + 1j * omega * q.damping
    return np.linalg.solve(A, rhs)


def solve_dynamic_stack(q: QuadraticMatrices, omegas: NDArray, rhs: NDArray) -> NDArray:
    """Solve K_d(w_k) x_k = rhs_k for all k at once, shape (n_k, n_c, n_rhs); omegas [rad/s].

    Banded LU with partial pivoting of every harmonic in one compiled loop
    (:func:`seafast.solvers.banded.solve_dynamic_band_stack`): its cost is the arithmetic, where
    LAPACK's banded LU spends most of its time in per-column BLAS calls at this bandwidth.
    """
    _, n, _ = rhs.shape
    if q.bandwidth < n // 4:
        return solve_dynamic_band_stack(q.banded_stiffness, q.banded_mass, q.banded_damping, np.asarray(omegas, dtype=float), rhs)
    return np.stack([solve_dynamic(q, float(wk), rhs[k]) for k, wk in enumerate(omegas)])


def saddle_selection(model: StructuralModel) -> NDArray[np.float64]:
    """B (n_c, n_s): column s is 1 at the cargo z DOF over saddle s (saddle force -> cargo load)."""
    B = np.zeros((model.cargo_dof_count, model.saddle_count))
    B[model.saddle_cargo_dof, np.arange(model.saddle_count)] = 1.0
    return B


def linear_force_harmonics(model: StructuralModel, excitation: HarmonicExcitation, quasi_static: bool) -> NDArray:
    """Harmonics of f_static + f_vessel - K_d^co x_o on the cargo DOFs (n_k, n_c) [N, N m].

    ``K_d^co(k w) = K_co + i k w D_co``. ``quasi_static``: the cargo-deck coupling at omega = 0 for every
    harmonic (no damping of the deck's motion).
    """
    q = quadratic_matrices(model, True)
    P = np.zeros((excitation.harmonic_count, model.cargo_dof_count), dtype=complex)
    for k in range(excitation.harmonic_count):
        wk = 0.0 if quasi_static else k * excitation.omega_rad_s
        Kco = q.coupling_stiffness - wk**2 * q.coupling_mass + 1j * wk * q.coupling_damping
        P[k] = excitation.cargo_load_N[k] + (model.static_load_N if k == 0 else 0.0) - Kco @ excitation.deck_displacement[k]
    P[0] = P[0].real
    return P
