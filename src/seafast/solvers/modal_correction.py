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

**The lifted basis** (:attr:`CorrectionBasis.LIFTED`, for stiff saddles). With the bilateral modes, a lifted
saddle's stiffness is *removed* from the modal stiffness (``Omega^2 - Phi_L^T W_L Phi_L``): with near-rigid
saddles a difference of huge numbers. Written on the cargo with every saddle lifted (the lashings hold it,
``K_f = K - B K_u B^T``), the same equations read::

    M q_c'' + D q_c' + K_f q_c = B g,      g = f - K_u delta_lin,      f = k_u max(delta, 0)

(``K_u delta_lin`` the bilateral linear saddle forces, finite however stiff the saddles): contact *adds* its
stiffness to the lifted cargo's modes, and nothing cancels. The reduction is the same (the lifted cargo's modes
below the cutoff plus the static residual flexibility of ``K_f``), with ``g`` the input in place of ``c``.

This module is the reduction alone (no time step): the one transient integrator,
:mod:`seafast.solvers.transient` (Newmark average acceleration, exact contact per step, compiled), marches
it -- for the sea-state Monte Carlo, and periodically for the start of the high-harmonic HBM solves
(:mod:`seafast.solvers.hbm.harmonics`, which also uses :meth:`ModalCorrectionSystem.receptance` for its
truncation estimate).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from enum import StrEnum
from functools import cached_property

import numpy as np
from numpy.typing import NDArray
from scipy.linalg import eigh, solve_banded

from seafast.model.structure import StructuralModel

__all__ = [
    "CorrectionBasis",
    "ModalBasis",
    "ModalCorrectionSystem",
    "UnsupportedBasisError",
    "lashings_hold",
    "modal_basis",
    "modal_correction_system",
]


class CorrectionBasis(StrEnum):
    """Which cargo's modes the correction system is reduced on.

    ``BILATERAL``: every saddle bilateral (the input is the correction force ``c = k_u max(-delta, 0)``);
    ``LIFTED``: every saddle lifted, the lashings holding the cargo (the input is ``g = f - K_u delta_lin``, the
    saddle force less the bilateral linear one): see the module docstring.
    """

    BILATERAL = "bilateral"
    LIFTED = "lifted"


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
    basis
        :class:`CorrectionBasis`: the modes of the cargo on bilateral saddles (the input is the correction force
        ``c``) or with every saddle lifted (the input is ``g = f - K_u delta_lin``); the residual flexibilities
        and frequencies above are of that cargo.
    complete
        Whether every mode of the model is kept (the residual flexibility is then zero: the reduction is exact).
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
    basis: CorrectionBasis = CorrectionBasis.BILATERAL
    complete: bool = False

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


_BASIS_KEY = "modal_basis"  # the model's derived_cache entry (the lifted basis: with " lifted")
_DENSE_EIGEN_LIMIT = 400  # DOFs; above it, the few lowest modes come from a shift-invert Lanczos


class UnsupportedBasisError(ValueError):
    """The cargo with every saddle lifted is not held (no lashing against a rigid-body motion): no lifted basis."""


def modal_basis(model: StructuralModel, cutoff_rad_s: float, basis: CorrectionBasis = CorrectionBasis.BILATERAL) -> ModalBasis:
    """Modes of the model at least up to ``cutoff_rad_s`` (kept in the model's ``derived_cache``; grows when asked for more).

    Small models (or ``cutoff_rad_s = inf``) take every mode from a dense generalised eigensolve; large
    ones (long or finely meshed cargo) the lowest ones from ARPACK in shift-invert mode on the banded K,
    doubling the count until the cutoff is passed. ``basis``: the cargo on bilateral saddles, or with every
    saddle lifted (lashings only; :class:`UnsupportedBasisError` if they do not hold it).
    """
    bilateral = basis is CorrectionBasis.BILATERAL
    if not bilateral and not lashings_hold(model):
        raise UnsupportedBasisError("the lashings do not hold the cargo with every saddle lifted against a rigid-body heave and pitch")
    key = _BASIS_KEY if bilateral else f"{_BASIS_KEY} {basis.value}"
    cached = model.derived_cache.get(key)
    if isinstance(cached, ModalBasis) and (cached.complete or cached.natural_frequency_rad_s[-1] > cutoff_rad_s):
        return cached
    n = model.cargo_dof_count
    sad = model.saddle_cargo_dof
    B = np.zeros((n, sad.size))
    B[sad, np.arange(sad.size)] = 1.0
    if n <= _DENSE_EIGEN_LIMIT or not math.isfinite(cutoff_rad_s):
        K = np.asarray(model.dynamic_stiffness(0.0, bilateral)[0], dtype=float)
        M = np.asarray(model.cargo.mass, dtype=float)
        w2, phi = eigh(K, M) if bilateral else _two_sided_modes(K, M)
        complete = True
        static = np.linalg.solve(K, B)
        damping_phi = model.damping_cc @ phi
    else:
        # a long or finely meshed cargo: the lowest modes by the model's banded shift-invert Lanczos, doubling the
        # count until the cutoff is passed, and every product with K and D in band storage (O(n), no n x n array)
        b, K_band, _, D_band, _ = model.banded_quadratic(bilateral)
        count = 8
        while True:
            count = min(count, n - 2)
            try:
                w, phi_or_none = model.lowest_modes(bilateral, count, vectors=True)
            except (np.linalg.LinAlgError, RuntimeError, ValueError) as error:
                raise UnsupportedBasisError(f"no modes of the cargo with every saddle lifted: {error}") from None
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
    found = ModalBasis(np.sqrt(np.maximum(w2, 0.0)), phi, static, 0.5 * (flexibility + flexibility.T), phi.T @ damping_phi, complete)
    model.derived_cache[key] = found
    return found


def _two_sided_modes(K: NDArray[np.float64], M: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Every mode of ``K phi = w^2 M phi`` (ascending, mass-normalised), each to its own relative precision.

    ``eigh(K, M)`` finds each ``w^2`` to about ``eps w_max^2``: the soft modes of a cargo held by its lashings alone
    (0.1 rad/s beside 9e5 rad/s) would carry percent errors. ``eigh(M, K)`` finds ``1 / w^2`` to ``eps / w_min^2``:
    accurate at the bottom, not at the top. The modes below the spectrum's geometric mean come from the second,
    the others from the first (both to about ``eps sqrt(w_max^2 / w_min^2)`` at the split).
    """
    w2, phi = eigh(K, M)
    mu, psi = eigh(M, K)  # psi^T K psi = I, psi^T M psi = mu
    low = np.sort(1.0 / mu)
    split = math.sqrt(max(float(low[0]), 1e-300) * float(w2[-1]))
    count = int(np.searchsorted(low, split))
    order = np.argsort(1.0 / mu)[:count]
    w2_low, phi_low = 1.0 / mu[order], psi[:, order] / np.sqrt(mu[order])[None, :]
    return np.concatenate([w2_low, w2[count:]]), np.hstack([phi_low, phi[:, count:]])


def lashings_hold(model: StructuralModel) -> bool:
    """Whether the lashings alone hold the cargo against its rigid-body heave and pitch (the lifted basis exists).

    A rigid motion ``w(x) = a + b x`` stores ``sum_i k_z,i (a + b x_i)^2 + k_theta,i b^2`` in the lashings: they hold
    the cargo if that 2 x 2 form is positive definite (relative to its largest eigenvalue, beyond round-off).
    """
    sf = model.seafastening
    x = np.asarray(model.saddle_x_m, dtype=float) - float(np.mean(model.saddle_x_m))
    kz = np.asarray(sf.lashing_vertical_stiffness_N_per_m, dtype=float)
    kt = np.asarray(sf.lashing_rotational_stiffness_Nm_per_rad, dtype=float)
    form = np.array([[kz.sum(), kz @ x], [kz @ x, kz @ x**2 + kt.sum()]])
    eig = np.linalg.eigvalsh(form)
    return bool(eig[-1] > 0.0 and eig[0] > 1e-9 * eig[-1])


def _band_product(band: NDArray[np.float64], bandwidth: int, X: NDArray[np.float64]) -> NDArray[np.float64]:
    """``A @ X`` for A in full band storage ``band[b + i - j, j] = A[i, j]`` (the layout of ``solve_banded``)."""
    n = band.shape[1]
    out = np.zeros((n,) + X.shape[1:])
    for r in range(2 * bandwidth + 1):
        shift = r - bandwidth  # i - j
        lo, hi = max(0, -shift), min(n, n - shift)
        out[lo + shift : hi + shift] += band[r, lo:hi, None] * X[lo:hi]
    return out


def modal_correction_system(
    model: StructuralModel, cutoff_rad_s: float, *, minimum_modes: int = 0, basis: CorrectionBasis = CorrectionBasis.BILATERAL
) -> ModalCorrectionSystem:
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
    basis
        :class:`CorrectionBasis`: the modes of the cargo on bilateral saddles (the default) or with every saddle
        lifted (:class:`UnsupportedBasisError` where the lashings do not hold the cargo).
    """
    modes = modal_basis(model, cutoff_rad_s, basis)
    w = modes.natural_frequency_rad_s
    m = max(int(np.searchsorted(w, float(cutoff_rad_s), side="right")), min(int(minimum_modes), w.size))
    complete = bool(modes.complete and m == w.size)
    w, phi = w[:m], modes.mode_shape[:, :m]
    sad = np.asarray(model.saddle_cargo_dof)
    phis = phi[sad]
    if modes.complete and basis is CorrectionBasis.LIFTED:
        # every mode is known: the residual as the truncated modes' own static flexibility, without subtracting the
        # soft lashing modes' large share from the static response (a difference of large numbers)
        rest, shapes = modes.natural_frequency_rad_s[m:], modes.mode_shape[:, m:]
        residual = shapes @ (shapes[sad].T / rest[:, None] ** 2)
    elif m:
        residual = modes.static_saddle_response_m_per_N - phi @ (phis.T / w[:, None] ** 2)
    else:
        residual = modes.static_saddle_response_m_per_N
    if complete:
        residual = np.zeros_like(residual)  # every mode kept: nothing is left to respond statically (round-off dropped)
    residual_s = residual[sad]
    return ModalCorrectionSystem(
        natural_frequency_rad_s=np.ascontiguousarray(w),
        modal_damping=np.ascontiguousarray(modes.modal_damping[:m, :m]),
        mode_shape=np.ascontiguousarray(phi),
        saddle_mode_shape=np.ascontiguousarray(phis),
        residual_displacement_m_per_N=np.ascontiguousarray(residual),
        residual_flexibility_m_per_N=np.ascontiguousarray(0.5 * (residual_s + residual_s.T)),
        static_flexibility_m_per_N=modes.static_saddle_flexibility_m_per_N,
        unilateral_stiffness_N_per_m=np.asarray(model.saddle_unilateral_stiffness_N_per_m, dtype=float).copy(),
        saddle_dof=sad,
        cutoff_rad_s=float(cutoff_rad_s),
        basis=basis,
        complete=complete,
    )
