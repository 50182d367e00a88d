"""The saddles' correction system reduced to the cargo's lowest modes plus static residual flexibility.

With every saddle bilateral the cargo is linear: its response to any deck motion and vessel load is the
linear (bilateral) response ``delta_lin`` (known, e.g. from the frequency domain). The unilateral saddles
differ from it only by the *correction forces* ``c = k_u max(-delta, 0)`` at the saddles, the tension a
bilateral saddle would carry, removed::

    M q_c'' + D q_c' + K q_c = B c,      delta = delta_lin - B^T q_c,      c = k_u max(-delta, 0)

(``K`` with the saddles bilateral, ``B`` the saddle z DOFs). This is exactly the condensed formulation of
the harmonic balance and of the references (``docs/theory.md``, section 5). Here ``q_c`` is reduced to the
cargo's modes below a cutoff (mass-normalised, the non-diagonal modal damping ``Phi^T D Phi`` kept: the
springs are undamped, so Rayleigh damping on the beam is not modal) plus the static residual flexibility
of the truncated modes (``K^-1 B - Phi Omega^-2 Phi_B^T``), so the modes above the cutoff respond
quasi-statically and the reduced system is exact at zero frequency.

This module is the reduction alone (no time step): the one transient integrator,
:mod:`seafast.solvers.transient` (Newmark average acceleration, exact contact per step, compiled), marches
it -- for the sea-state Monte Carlo, and periodically for the start of the high-harmonic HBM solves
(:mod:`seafast.solvers.hbm.harmonics`, which also uses :meth:`ModalCorrectionSystem.receptance` for its
truncation estimate).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np
from numpy.typing import NDArray
from scipy.linalg import eigh, solve_banded

from seafast.model.structure import StructuralModel

__all__ = ["ModalBasis", "ModalCorrectionSystem", "modal_basis", "modal_correction_system"]


@dataclass(frozen=True)
class ModalCorrectionSystem:
    """The correction system reduced to ``m`` modes plus static residual flexibility.

    Attributes
    ----------
    natural_frequency_rad_s
        Undamped natural frequencies of the kept modes (saddles bilateral, deck fixed) [rad/s], (m,).
    modal_damping
        ``Phi^T D Phi`` [1/s], (m, m), mass-normalised modes.
    mode_shape
        ``Phi`` on the cargo DOFs [m or rad per unit modal coordinate], (n_c, m).
    saddle_mode_shape
        ``Phi_s = B^T Phi``, the modes' z at the saddles [m per unit modal coordinate], (n_s, m).
    residual_displacement_m_per_N
        ``K^-1 B - Phi Omega^-2 Phi_s^T``: the cargo DOFs' static response to unit saddle forces carried by
        the truncated modes [m/N], (n_c, n_s).
    residual_flexibility_m_per_N
        Its rows at the saddles, symmetrised [m/N], (n_s, n_s).
    static_flexibility_m_per_N
        ``B^T K^-1 B``, the complete static flexibility at the saddles, symmetrised [m/N], (n_s, n_s).
    unilateral_stiffness_N_per_m
        ``k_u`` of each saddle [N/m], (n_s,).
    saddle_dof
        Cargo DOF index of each saddle's z, (n_s,).
    cutoff_rad_s
        Modes at or below this frequency are kept [rad/s] (``inf``: every mode).
    """

    natural_frequency_rad_s: NDArray[np.float64]
    modal_damping: NDArray[np.float64]
    mode_shape: NDArray[np.float64]
    saddle_mode_shape: NDArray[np.float64]
    residual_displacement_m_per_N: NDArray[np.float64]
    residual_flexibility_m_per_N: NDArray[np.float64]
    static_flexibility_m_per_N: NDArray[np.float64]
    unilateral_stiffness_N_per_m: NDArray[np.float64]
    saddle_dof: NDArray[np.intp]
    cutoff_rad_s: float

    @property
    def mode_count(self) -> int:
        return int(self.natural_frequency_rad_s.size)

    @property
    def saddle_count(self) -> int:
        return int(self.unilateral_stiffness_N_per_m.size)

    def receptance(self, omega_rad_s: NDArray[np.float64]) -> NDArray[np.complex128]:
        """``G(w) = Phi_s (Omega^2 - w^2 + i w Phi^T D Phi)^-1 Phi_s^T + R`` at each frequency, (n_w, n_s, n_s) [m/N].

        Exact at w = 0; the modes above the cutoff are taken as static, so it is accurate well below the cutoff.
        Evaluated through the complex modes of the reduced system (one eigendecomposition of its 2m x 2m
        state matrix, then a sum of 2m poles per frequency), which equals the per-frequency solve to round-off
        and costs nothing per frequency.
        """
        w = np.atleast_1d(np.asarray(omega_rad_s, dtype=float))
        R = self.residual_flexibility_m_per_N
        if self.mode_count == 0:
            return np.broadcast_to(R, (w.size,) + R.shape).astype(complex)
        left, poles, right = self._poles
        pole_terms = 1.0 / (1j * w[:, None] - poles[None, :])  # (n_w, 2m)
        n_s = R.shape[0]
        residues = (left[:, :, None] * right[None, :, :]).transpose(1, 0, 2).reshape(poles.size, n_s * n_s)  # (2m, n_s n_s)
        return (pole_terms @ residues).reshape(w.size, n_s, n_s) + R[None]

    @cached_property
    def _poles(self) -> tuple[NDArray[np.complex128], NDArray[np.complex128], NDArray[np.complex128]]:
        """``Phi_s V_eta``, the poles, ``(V^-1)_(:, eta') Phi_s^T`` of ``z' = S z + [0; I] f``, ``z = [eta; eta']``.

        ``S = [[0, I], [-Omega^2, -Phi^T D Phi]]`` = ``V diag(poles) V^-1``, so ``(Omega^2 - w^2 + i w Xi)^-1 =
        [I 0] (i w - S)^-1 [0; I] = V_eta diag(1 / (i w - poles)) (V^-1)_(:, eta')``.
        """
        m = self.mode_count
        S = np.zeros((2 * m, 2 * m))
        S[:m, m:] = np.eye(m)
        S[m:, :m] = -np.diag(self.natural_frequency_rad_s**2)
        S[m:, m:] = -self.modal_damping
        poles, V = np.linalg.eig(S)
        V_inv = np.linalg.inv(V)
        Ps = self.saddle_mode_shape
        # complex arrays whatever eig returns (its output dtype depends on the eigenvalues found)
        return (
            np.asarray(Ps @ V[:m], dtype=np.complex128),
            np.asarray(poles, dtype=np.complex128),
            np.asarray(V_inv[:, m:] @ Ps.T, dtype=np.complex128),
        )


@dataclass(frozen=True)
class ModalBasis:
    """The lowest undamped modes of the cargo on bilateral saddles (deck fixed), mass-normalised.

    Attributes
    ----------
    natural_frequency_rad_s
        (m,) ascending [rad/s].
    mode_shape
        (n_c, m) [m or rad per unit modal coordinate].
    static_saddle_response_m_per_N
        ``K^-1 B`` (n_c, n_s) [m/N], the cargo DOFs' static response to unit saddle forces.
    static_saddle_flexibility_m_per_N
        ``B^T K^-1 B`` (n_s, n_s) [m/N], the complete static flexibility at the saddles (symmetrised).
    modal_damping
        ``Phi^T D Phi`` of every mode in the basis [1/s], (m, m).
    complete
        Whether every mode of the model is in the basis (else modes above the last one exist).
    """

    natural_frequency_rad_s: NDArray[np.float64]
    mode_shape: NDArray[np.float64]
    static_saddle_response_m_per_N: NDArray[np.float64]
    static_saddle_flexibility_m_per_N: NDArray[np.float64]
    modal_damping: NDArray[np.float64]
    complete: bool


_BASIS_KEY = "modal_basis"  # the model's derived_cache entry
_DENSE_EIGEN_LIMIT = 400  # DOFs; above it, the few lowest modes come from a shift-invert Lanczos


def modal_basis(model: StructuralModel, cutoff_rad_s: float) -> ModalBasis:
    """Modes of the model at least up to ``cutoff_rad_s`` (kept in the model's ``derived_cache``; grows when asked for more).

    Small models (or ``cutoff_rad_s = inf``) take every mode from a dense generalised eigensolve; large
    ones (long or finely meshed cargo) the lowest ones from ARPACK in shift-invert mode on the banded K,
    doubling the count until the cutoff is passed.
    """
    cached = model.derived_cache.get(_BASIS_KEY)
    if isinstance(cached, ModalBasis) and (cached.complete or cached.natural_frequency_rad_s[-1] > cutoff_rad_s):
        return cached
    n = model.cargo_dof_count
    sad = model.saddle_cargo_dof
    B = np.zeros((n, sad.size))
    B[sad, np.arange(sad.size)] = 1.0
    if n <= _DENSE_EIGEN_LIMIT or not math.isfinite(cutoff_rad_s):
        K = np.asarray(model.dynamic_stiffness(0.0, True)[0], dtype=float)  # every saddle bilateral
        w2, phi = eigh(K, np.asarray(model.cargo.mass, dtype=float))
        static = np.linalg.solve(K, B)
        damping_phi = model.damping_cc @ phi
        complete = True
    else:
        # a long or finely meshed cargo: the lowest modes by the model's banded shift-invert Lanczos, doubling the
        # count until the cutoff is passed, and every product with K and D in band storage (O(n), no n x n array)
        b, K_band, _, D_band, _ = model.banded_quadratic(True)
        count = 8
        while True:
            count = min(count, n - 2)
            w, phi_or_none = model.lowest_modes(True, count, vectors=True)
            assert phi_or_none is not None
            phi, w2 = phi_or_none, w**2
            if w[-1] > cutoff_rad_s or count >= n - 2:
                break
            count *= 2
        static = solve_banded((b, b), K_band, B)
        damping_phi = _band_product(D_band, b, phi)
        complete = False
    flexibility = static[sad]
    phi = np.ascontiguousarray(phi)
    basis = ModalBasis(np.sqrt(np.maximum(w2, 0.0)), phi, static, 0.5 * (flexibility + flexibility.T), phi.T @ damping_phi, complete)
    model.derived_cache[_BASIS_KEY] = basis
    return basis


def _band_product(band: NDArray[np.float64], bandwidth: int, X: NDArray[np.float64]) -> NDArray[np.float64]:
    """``A @ X`` for A in full band storage ``band[b + i - j, j] = A[i, j]`` (the layout of ``solve_banded``)."""
    n = band.shape[1]
    out = np.zeros((n,) + X.shape[1:])
    for r in range(2 * bandwidth + 1):
        shift = r - bandwidth  # i - j
        lo, hi = max(0, -shift), min(n, n - shift)
        out[lo + shift : hi + shift] += band[r, lo:hi, None] * X[lo:hi]
    return out


def modal_correction_system(model: StructuralModel, cutoff_rad_s: float, *, minimum_modes: int = 0) -> ModalCorrectionSystem:
    """Reduce the model's correction system to the modes at or below ``cutoff_rad_s``.

    Parameters
    ----------
    model
        The cargo model (its K with the saddles bilateral, M, and Rayleigh D).
    cutoff_rad_s
        Highest natural frequency kept [rad/s] (e.g. the Nyquist frequency of a march's time step: the
        modes above it respond quasi-statically through the residual flexibility); ``inf`` keeps every mode.
    minimum_modes
        Keep at least this many modes (the lowest), whatever the cutoff.
    """
    basis = modal_basis(model, cutoff_rad_s)
    w = basis.natural_frequency_rad_s
    m = max(int(np.searchsorted(w, float(cutoff_rad_s), side="right")), min(int(minimum_modes), w.size))
    w, phi = w[:m], basis.mode_shape[:, :m]
    sad = np.asarray(model.saddle_cargo_dof)
    phis = phi[sad]
    residual = basis.static_saddle_response_m_per_N - phi @ (phis.T / w[:, None] ** 2) if m else basis.static_saddle_response_m_per_N
    residual_s = residual[sad]
    return ModalCorrectionSystem(
        natural_frequency_rad_s=np.ascontiguousarray(w),
        modal_damping=np.ascontiguousarray(basis.modal_damping[:m, :m]),
        mode_shape=np.ascontiguousarray(phi),
        saddle_mode_shape=np.ascontiguousarray(phis),
        residual_displacement_m_per_N=np.ascontiguousarray(residual),
        residual_flexibility_m_per_N=np.ascontiguousarray(0.5 * (residual_s + residual_s.T)),
        static_flexibility_m_per_N=basis.static_saddle_flexibility_m_per_N,
        unilateral_stiffness_N_per_m=np.asarray(model.saddle_unilateral_stiffness_N_per_m, dtype=float).copy(),
        saddle_dof=sad,
        cutoff_rad_s=float(cutoff_rad_s),
    )
