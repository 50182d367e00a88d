"""Harmonic balance with Alternating Frequency-Time (HBM/AFT) for the unilateral saddles.

Equation of motion (MODEL.md section 5), cargo DOFs q, deck DOFs x_o prescribed::

    M q'' + D q' + K q = f_static + f_vessel(t) - K_co x_o(t) + B f(delta(t)),
    delta = z_deck - z_cargo  (saddle compression, positive compressed),

with f the contact law of the compression-only saddle part (force on the cargo, upward) and B
the map from saddles to cargo z DOFs. The periodic steady state is expanded in H harmonics
``x(t) = Re(sum_{k=0..H} X_k exp(i k omega t))``; the nonlinear force goes through AFT: inverse
DFT to N time samples ``t_n = n T / N``, the contact law per sample, DFT back.

Real harmonic layout (used by every unknown vector here): coefficient row 0 is the mean,
rows 2k-1 and 2k are the cosine and sine coefficients a_k, b_k of harmonic k, so
``x(t) = a_0 + sum_k a_k cos(k w t) + b_k sin(k w t)`` and ``X_k = a_k - i b_k``.

Two formulations, giving the same answer (to the solver tolerance):

``condensed`` (default)
    Every saddle is kept *bilaterally* in the linear part (well conditioned, never a
    mechanism); the nonlinearity is the correction force ``c = f(delta) - k_u delta`` that
    removes the tension a bilateral spring would carry. Per harmonic the receptance
    ``G_k = B^T (K_d^cc(k omega))^-1 B`` (one banded factorisation per harmonic) condenses the
    problem exactly onto the saddle compressions: unknowns are their n_s (2H+1) harmonic
    coefficients and ``R = delta - delta_lin + G DFT[c(IDFT delta)] = 0``, Jacobian
    ``I + G DFT diag(f'(delta) - k_u) IDFT``. Where contact is kept, c = 0 and the linear answer
    is exact. Cargo harmonics follow as ``X_k = X_lin,k + (K_d^cc)^-1 B C_k``.
``full`` (as the source)
    All cargo DOFs (n_c (2H+1) unknowns, the corrections to the linear response), linear part
    without the compression-only saddle springs, contact force from AFT on the saddle DOFs,
    analytic Jacobian. The linear part is block diagonal per harmonic and banded, coupled only
    through the saddle DOFs: the Jacobian is assembled sparse on a fixed pattern and factorised
    by a sparse LU (SuperLU) once per Newton iteration. Roughly 15x slower than ``condensed``
    (a dense LU per iteration, as the source, costs seconds); kept as a check and for fidelity
    to the source.

Start: the better (smaller residual) of the linear solution and the *quasi-static
exact-contact predictor* -- each AFT sample of the linear compression corrected by the exact
static contact problem with the static receptance G_0 (active-set solver of
:mod:`seafast.solvers.references`), then transformed back to harmonics. For wave excitation
(far below the cargo's modes) it is within a few per cent of the HBM solution, so Newton
converges in 2-6 iterations even where the piecewise-linear exact law makes Newton from the
linear solution cycle.

Solvers: ``newton`` (semi-smooth Newton with the exact law; globalised by a non-monotone
Armijo line search on ``||R||^2 / 2``, a Levenberg-Marquardt step where the line search fails,
and an early exit on stagnation) and ``hybr`` (MINPACK's Powell hybrid method via
``scipy.optimize.root`` with the analytic Jacobian, as the source). If the direct solve fails,
a second direct solve starts from the linear solution, then the solver continues in the
contact-law sharpness kappa (soft to the requested law) and then in the dynamic excitation
amplitude (static state to full amplitude) before giving up; failure is reported
(``converged=False``), never raised. The message starts with ``"direct: "`` when no
continuation was needed and names the start used.
"""

from __future__ import annotations

import functools
import weakref
from dataclasses import asdict, dataclass
from functools import lru_cache
from typing import Any, Callable

import numpy as np
from numpy.typing import NDArray
from scipy import sparse
from scipy.linalg import solve_banded
from scipy.optimize import root
from scipy.sparse.linalg import splu

from seafast.excitation.harmonic import HarmonicExcitation
from seafast.model.structure import StructuralModel
from seafast.solvers.contact import CONTACT_LAWS, ContactLaw
from seafast.solvers.periodic import PeriodicResponse, harmonics_to_time, high_harmonic_energy_share

__all__ = [
    "HBMOptions",
    "FORMULATIONS",
    "SOLVERS",
    "solve_hbm",
    "real_dft_matrices",
    "CondensedOperators",
    "condensed_operators",
    "solve_condensed",
    "CondensedSolution",
    "complex_to_real_harmonics",
    "real_to_complex_harmonics",
]

FORMULATIONS: tuple[str, ...] = ("condensed", "full")
SOLVERS: tuple[str, ...] = ("newton", "hybr")


# ====================================================================== options
@dataclass(frozen=True, kw_only=True)
class HBMOptions:
    """Settings of the harmonic balance solver (keyword-only, validated).

    Parameters
    ----------
    harmonics
        H >= 0, number of harmonics above the mean (H = 0: the nonlinear static problem).
    time_samples
        N >= 2H + 2 AFT samples per period (any integer; powers of 2 not required).
    contact_law
        ``tanh`` (the source's regularisation), ``softplus`` or ``exact``.
    regularisation_per_m
        kappa [1/m] of ``tanh``/``softplus``, > 0 (default 1000, the source's value).
    formulation
        ``condensed`` (default, fast) or ``full`` (all cargo DOFs, as the source).
    solver
        ``newton`` (default) or ``hybr`` (Powell hybrid, as the source).
    tolerance
        Relative residual at convergence (> 0, < 1): condensed, max |R| over the largest linear
        saddle compression; full, max |R| over the largest load/saddle force.
    max_iterations
        Nonlinear iterations per solve attempt (>= 1).
    continuation
        Whether a failed direct solve falls back on continuation (in kappa, then in the dynamic
        excitation amplitude).
    """

    harmonics: int = 5
    time_samples: int = 128
    contact_law: str = "tanh"
    regularisation_per_m: float = 1000.0
    formulation: str = "condensed"
    solver: str = "newton"
    tolerance: float = 1e-10
    max_iterations: int = 100
    continuation: bool = True

    def __post_init__(self) -> None:
        def bad(name: str, allowed: str) -> ValueError:
            return ValueError(f"HBMOptions.{name} = {getattr(self, name)!r}; allowed: {allowed}")

        def is_int(v: Any) -> bool:
            return isinstance(v, (int, np.integer)) and not isinstance(v, (bool, np.bool_))

        if not is_int(self.harmonics) or self.harmonics < 0:
            raise bad("harmonics", "an integer >= 0")
        if not is_int(self.time_samples) or self.time_samples < 2 * self.harmonics + 2:
            raise bad("time_samples", f"an integer >= 2*harmonics + 2 = {2 * int(self.harmonics) + 2}")
        if self.contact_law not in CONTACT_LAWS:
            raise bad("contact_law", " | ".join(CONTACT_LAWS))
        if (
            isinstance(self.regularisation_per_m, bool)
            or not isinstance(self.regularisation_per_m, (int, float, np.floating, np.integer))
            or not np.isfinite(self.regularisation_per_m)
            or self.regularisation_per_m <= 0
        ):
            raise bad("regularisation_per_m", "a finite number > 0 [1/m]")
        if self.formulation not in FORMULATIONS:
            raise bad("formulation", " | ".join(FORMULATIONS))
        if self.solver not in SOLVERS:
            raise bad("solver", " | ".join(SOLVERS))
        if (
            isinstance(self.tolerance, bool)
            or not isinstance(self.tolerance, (int, float, np.floating))
            or not (0.0 < float(self.tolerance) < 1.0)
        ):
            raise bad("tolerance", "a number in (0, 1)")
        if not is_int(self.max_iterations) or self.max_iterations < 1:
            raise bad("max_iterations", "an integer >= 1")
        if not isinstance(self.continuation, (bool, np.bool_)):
            raise bad("continuation", "True | False")

    @property
    def law(self) -> ContactLaw:
        """The contact law object."""
        return ContactLaw(self.contact_law, float(self.regularisation_per_m))

    def to_dict(self) -> dict[str, Any]:
        """Plain dict of the settings."""
        return asdict(self)


# ====================================================================== DFT matrices
@lru_cache(maxsize=64)
def real_dft_matrices(harmonics: int, time_samples: int) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Real inverse and forward DFT matrices of the layout ``[a0, a1, b1, ..., aH, bH]``.

    Returns
    -------
    inverse, forward
        ``inverse`` (N, 2H+1) maps coefficients to samples at ``t_n = n T / N``;
        ``forward`` (2H+1, N) maps samples to coefficients (``forward @ inverse = I`` for
        N >= 2H + 1). Read-only, cached per (H, N).
    """
    H, N = int(harmonics), int(time_samples)
    phase = 2.0 * np.pi * np.outer(np.arange(N), np.arange(1, H + 1)) / N  # (N, H)
    inverse = np.empty((N, 2 * H + 1))
    inverse[:, 0] = 1.0
    inverse[:, 1::2] = np.cos(phase)
    inverse[:, 2::2] = np.sin(phase)
    forward = inverse.T * (2.0 / N)
    forward[0] *= 0.5
    inverse.flags.writeable = False
    forward = np.ascontiguousarray(forward)
    forward.flags.writeable = False
    return inverse, forward


def complex_to_real_harmonics(X: NDArray) -> NDArray[np.float64]:
    """Complex amplitudes (H+1, ...) to real coefficients (2H+1, ...): a_k = Re X_k, b_k = -Im X_k."""
    X = np.asarray(X)
    out = np.empty((2 * X.shape[0] - 1,) + X.shape[1:])
    out[0] = X[0].real
    out[1::2] = X[1:].real
    out[2::2] = -X[1:].imag
    return out


def real_to_complex_harmonics(U: NDArray) -> NDArray[np.complex128]:
    """Real coefficients (2H+1, ...) to complex amplitudes (H+1, ...): X_k = a_k - i b_k."""
    U = np.asarray(U, dtype=float)
    out = np.empty(((U.shape[0] + 1) // 2,) + U.shape[1:], dtype=complex)
    out[0] = U[0]
    out[1:] = U[1::2] - 1j * U[2::2]
    return out


# ====================================================================== linear operators
@dataclass(frozen=True)
class _QuadraticMatrices:
    """K, M, D of the cargo DOFs (saddles bilateral) and of the cargo-deck coupling, banded.

    The dense K, M, D (for the references) are formed from the bands on first use.
    """

    coupling_stiffness: NDArray[np.float64]
    coupling_mass: NDArray[np.float64]
    coupling_damping: NDArray[np.float64]
    bandwidth: int
    banded_stiffness: NDArray[np.float64]
    banded_mass: NDArray[np.float64]
    banded_damping: NDArray[np.float64]

    @functools.cached_property
    def stiffness(self) -> NDArray[np.float64]:
        return _from_banded(self.banded_stiffness, self.bandwidth)

    @functools.cached_property
    def mass(self) -> NDArray[np.float64]:
        return _from_banded(self.banded_mass, self.bandwidth)

    @functools.cached_property
    def damping(self) -> NDArray[np.float64]:
        return _from_banded(self.banded_damping, self.bandwidth)


def _from_banded(ab: NDArray, bandwidth: int) -> NDArray:
    """The dense matrix of full band storage ``ab[b + i - j, j] = A[i, j]``."""
    n = ab.shape[1]
    A = np.zeros((n, n), dtype=ab.dtype)
    for offset in range(-bandwidth, bandwidth + 1):
        i = np.arange(max(0, -offset), min(n, n - offset))
        A[i, i + offset] = ab[bandwidth - offset, i + offset]
    return A


_QUADRATIC_CACHE: dict[tuple[int, bool], tuple[weakref.ref, _QuadraticMatrices]] = {}


def _quadratic_matrices(model: StructuralModel, include_saddles: bool = True) -> _QuadraticMatrices:
    """``model.dynamic_stiffness`` as K - w^2 M + i w D, banded (``model.banded_quadratic``, O(n)), cached per model."""
    key = (id(model), bool(include_saddles))
    hit = _QUADRATIC_CACHE.get(key)
    if hit is not None and hit[0]() is model:
        return hit[1]
    bw, K, M, D, Kco = model.banded_quadratic(include_saddles)
    Kco = np.asarray(Kco, dtype=float)
    q = _QuadraticMatrices(Kco, np.zeros_like(Kco), np.zeros_like(Kco), bw, K, M, D)
    if len(_QUADRATIC_CACHE) > 64:
        for k in [k for k, (ref, _) in _QUADRATIC_CACHE.items() if ref() is None]:
            del _QUADRATIC_CACHE[k]
    try:
        _QUADRATIC_CACHE[key] = (weakref.ref(model), q)
    except TypeError:  # pragma: no cover - objects without weakref support are not cached
        pass
    return q


def _solve_dynamic(q: _QuadraticMatrices, omega: float, rhs: NDArray) -> NDArray:
    """Solve (K - w^2 M + i w D) x = rhs (banded when the band is narrow)."""
    n = q.banded_stiffness.shape[1]
    if q.bandwidth < n // 4:
        if omega == 0.0:
            ab = q.banded_stiffness
        else:
            ab = q.banded_stiffness - omega**2 * q.banded_mass + 1j * omega * q.banded_damping
        return solve_banded((q.bandwidth, q.bandwidth), ab, rhs, check_finite=False)
    A = q.stiffness if omega == 0.0 else q.stiffness - omega**2 * q.mass + 1j * omega * q.damping
    return np.linalg.solve(A, rhs)


def _solve_dynamic_stack(q: _QuadraticMatrices, omegas: NDArray, rhs: NDArray) -> NDArray:
    """Solve K_d(w_k) x_k = rhs_k for all k at once, shape (n_k, n_c, n_rhs).

    The block-diagonal system of all harmonics is itself banded with the same bandwidth, so a
    single banded LU (LAPACK gbsv) solves every harmonic in one call.
    """
    n_k, n, n_rhs = rhs.shape
    if q.bandwidth < n // 4:
        w = np.asarray(omegas, dtype=float)[:, None, None]
        ab = q.banded_stiffness[None] - w**2 * q.banded_mass[None] + 1j * w * q.banded_damping[None]
        ab = np.ascontiguousarray(ab.transpose(1, 0, 2)).reshape(2 * q.bandwidth + 1, n_k * n)
        x = solve_banded((q.bandwidth, q.bandwidth), ab, rhs.reshape(n_k * n, n_rhs), check_finite=False)
        return x.reshape(n_k, n, n_rhs)
    return np.stack([_solve_dynamic(q, float(wk), rhs[k]) for k, wk in enumerate(omegas)])


@dataclass(frozen=True)
class CondensedOperators:
    """The linear problem condensed onto the saddle compressions, harmonics 0 .. H.

    Attributes
    ----------
    omega_rad_s, harmonics
        Fundamental frequency [rad/s] and H.
    saddle_stiffness_N_per_m
        k_u, the compression-only stiffness of each saddle [N/m], shape (n_s,).
    receptance
        Real block-diagonal receptance [m/N], shape (n_u, n_u), n_u = (2H+1) n_s, unknown
        ordering ``row * n_s + saddle`` in the real harmonic layout; ``-receptance @ C`` is the
        change in saddle compression caused by upward cargo forces C at the saddles.
    linear_compression_m
        Saddle compression of the linear (bilateral) model, real layout (2H+1, n_s), split
        into its static row and the dynamic rows (for amplitude continuation).
    linear_cargo_displacement
        Linear cargo harmonics (H+1, n_c) complex [m, rad].
    cargo_influence
        ``(K_d^cc(k w))^-1 B``, shape (H+1, n_c, n_s) complex [m/N]: cargo response to unit
        upward saddle forces per harmonic.
    ignored_harmonics
        Whether the excitation had nonzero harmonics above H (they are dropped).
    """

    omega_rad_s: float
    harmonics: int
    saddle_stiffness_N_per_m: NDArray[np.float64]
    receptance: NDArray[np.float64]
    linear_compression_m: NDArray[np.float64]
    linear_cargo_displacement: NDArray[np.complex128]
    cargo_influence: NDArray[np.complex128]
    ignored_harmonics: bool

    @property
    def saddle_count(self) -> int:
        return int(self.saddle_stiffness_N_per_m.size)

    @property
    def compression_scale_m(self) -> float:
        """Residual normalisation: the largest linear compression coefficient (>= 1 um)."""
        return float(max(np.max(np.abs(self.linear_compression_m)), 1e-6))

    def linear_compression_at(self, amplitude_scale: float) -> NDArray[np.float64]:
        """Linear compression with the dynamic harmonics scaled by ``amplitude_scale``."""
        if amplitude_scale == 1.0:
            return self.linear_compression_m
        out = self.linear_compression_m * amplitude_scale
        out[0] = self.linear_compression_m[0]
        return out


def condensed_operators(model: StructuralModel, excitation: HarmonicExcitation, harmonics: int) -> CondensedOperators:
    """Receptances and linear solution per harmonic (saddles bilateral), k = 0 .. H.

    The static load of the model (gravity, pretension) is added at k = 0.
    """
    H = int(harmonics)
    q = _quadratic_matrices(model, True)
    n_c, n_s = model.cargo_dof_count, model.saddle_count
    sad_c = model.saddle_cargo_dof
    sad_o = model.saddle_deck_dof
    n_k = excitation.harmonic_count
    ignored = bool(n_k > H + 1 and (np.any(excitation.deck_displacement[H + 1 :]) or np.any(excitation.cargo_load_N[H + 1 :])))
    w = float(excitation.omega_rad_s)
    B = np.zeros((n_c, n_s))
    B[sad_c, np.arange(n_s)] = 1.0
    xo = np.zeros((H + 1, model.deck_dof_count), dtype=complex)
    f = np.zeros((H + 1, n_c), dtype=complex)
    m = min(n_k, H + 1)
    xo[:m] = excitation.deck_displacement[:m]
    f[:m] = excitation.cargo_load_N[:m]
    f[0] = (f[0] + model.static_load_N).real
    xo[0] = xo[0].real
    wk = w * np.arange(H + 1)
    coupling = (
        q.coupling_stiffness[None] - (wk**2)[:, None, None] * q.coupling_mass[None] + 1j * wk[:, None, None] * q.coupling_damping[None]
    )
    rhs = np.empty((H + 1, n_c, n_s + 1), dtype=complex)
    rhs[:, :, :n_s] = B
    rhs[:, :, n_s] = f - np.einsum("kco,ko->kc", coupling, xo)
    sol = _solve_dynamic_stack(q, wk, rhs)  # (H+1, n_c, n_s+1)
    Y = sol[:, :, :n_s]
    X_lin = sol[:, :, n_s]
    X_lin[0] = X_lin[0].real
    delta_lin = xo[:, sad_o] - X_lin[:, sad_c]
    G = Y[:, sad_c, :]  # (H+1, n_s, n_s) complex receptance
    n_u = (2 * H + 1) * n_s
    Greal = np.zeros((n_u, n_u))
    Greal[:n_s, :n_s] = G[0].real
    for k in range(1, H + 1):
        a = slice((2 * k - 1) * n_s, 2 * k * n_s)
        b = slice(2 * k * n_s, (2 * k + 1) * n_s)
        Gr, Gi = G[k].real, G[k].imag
        Greal[a, a] = Gr
        Greal[a, b] = Gi
        Greal[b, a] = -Gi
        Greal[b, b] = Gr
    return CondensedOperators(
        omega_rad_s=w,
        harmonics=H,
        saddle_stiffness_N_per_m=np.asarray(model.saddle_unilateral_stiffness_N_per_m, dtype=float),
        receptance=Greal,
        linear_compression_m=complex_to_real_harmonics(delta_lin),
        linear_cargo_displacement=X_lin,
        cargo_influence=Y,
        ignored_harmonics=ignored,
    )


# ====================================================================== nonlinear systems
def _static_contact_compressions(delta_lin: NDArray, receptance: NDArray, stiffness: NDArray) -> NDArray:
    """Exact static contact ``delta = delta_lin - G_0 k max(-delta, 0)`` at every sample (n_t, n_s).

    Samples whose linear compressions are all positive keep contact (``delta = delta_lin``);
    the others go through the exact active-set solver of :mod:`seafast.solvers.references`.
    """
    delta = np.array(delta_lin, dtype=float)
    rows = np.nonzero(np.any(delta < 0.0, axis=1))[0]
    if rows.size:
        from seafast.solvers.references import solve_exact_contact  # lazy: references imports this module

        delta[rows] = solve_exact_contact(delta[rows], receptance, stiffness)[0]
    return delta


class _CondensedProblem:
    """R(u) = u - u_lin + G vec(DFT[c(IDFT u)]), u the saddle-compression coefficients."""

    def __init__(self, ops: CondensedOperators, time_samples: int):
        self.ops = ops
        self.n_s = ops.saddle_count
        self.n_h = 2 * ops.harmonics + 1
        self.size = self.n_h * self.n_s
        self.inverse, self.forward = real_dft_matrices(ops.harmonics, time_samples)
        self.k_u = ops.saddle_stiffness_N_per_m
        # receptance columns per saddle, (n_s, n_u, n_h): the Jacobian is then one batched matmul
        self.G_by_saddle = np.ascontiguousarray(ops.receptance.reshape(self.size, self.n_h, self.n_s).transpose(2, 0, 1))
        self.scale = ops.compression_scale_m
        self._eye = np.eye(self.size)

    def initial_guess(self, amplitude: float) -> NDArray:
        return self.ops.linear_compression_at(amplitude).ravel().copy()

    def predictor_compression(self, amplitude: float) -> NDArray:
        """Saddle compressions (N, n_s) of the quasi-static exact-contact predictor.

        Each sample of the linear (bilateral) compression is corrected by the exact static
        contact problem with the static receptance ``G_0``: exact when the excitation is
        quasi-static (wave frequencies far below the cargo's first mode), and a start inside
        the semi-smooth Newton's basin of attraction otherwise.
        """
        d_lin = self.inverse @ self.ops.linear_compression_at(amplitude)
        return _static_contact_compressions(d_lin, self.ops.receptance[: self.n_s, : self.n_s], self.k_u)

    def predictor(self, amplitude: float) -> NDArray:
        """Harmonics of :meth:`predictor_compression` (the linear solution when contact is kept)."""
        d_lin = self.inverse @ self.ops.linear_compression_at(amplitude)
        if not np.any(d_lin < 0.0):
            return self.initial_guess(amplitude)
        return (self.forward @ self.predictor_compression(amplitude)).ravel()

    def evaluate(self, u: NDArray, law: ContactLaw, amplitude: float) -> tuple[NDArray, Any]:
        U = u.reshape(self.n_h, self.n_s)
        delta = self.inverse @ U
        f, fp = law.force_and_derivative(delta, self.k_u)
        correction = f - self.k_u * delta
        C = self.forward @ correction
        R = u - self.ops.linear_compression_at(amplitude).ravel() + self.ops.receptance @ C.ravel()
        return R, fp

    def jacobian(self, fp: NDArray) -> NDArray:
        w = fp - self.k_u  # (N, n_s)
        PW = self.forward[None, :, :] * w.T[:, None, :]  # (n_s, n_h, N)
        T = PW @ self.inverse  # (n_s, n_h, n_h): d C[i, s] / d U[j, s]
        GT = self.G_by_saddle @ T  # (n_s, n_u, n_h): column (j, s) of G . dC/dU
        return self._eye + GT.transpose(1, 2, 0).reshape(self.size, self.size)

    def factorise(self, fp: NDArray) -> "_DenseJacobian":
        return _DenseJacobian(self.jacobian(fp))


class _DenseJacobian:
    """A dense Jacobian with the solves the nonlinear solvers need."""

    def __init__(self, J: NDArray):
        self.J = J

    def solve(self, rhs: NDArray) -> NDArray | None:
        try:
            x = np.linalg.solve(self.J, rhs)
        except np.linalg.LinAlgError:
            return None
        return x if np.all(np.isfinite(x)) else None

    def gradient(self, R: NDArray) -> NDArray:
        return self.J.T @ R

    def levenberg_marquardt(self, R: NDArray, mu: float) -> NDArray | None:
        A = self.J.T @ self.J
        A[np.diag_indices_from(A)] += mu * np.maximum(np.diag(A), 1e-300)
        try:
            x = np.linalg.solve(A, -(self.J.T @ R))
        except np.linalg.LinAlgError:
            return None
        return x if np.all(np.isfinite(x)) else None


class _SparseJacobian:
    """A sparse Jacobian factorised once (SuperLU) for Newton steps; LM steps on demand."""

    def __init__(self, J: Any):
        self.J = J.tocsc()
        try:
            self.lu = splu(self.J)
        except RuntimeError:  # exactly singular
            self.lu = None

    def solve(self, rhs: NDArray) -> NDArray | None:
        if self.lu is None:
            return None
        x = self.lu.solve(rhs)
        return x if np.all(np.isfinite(x)) else None

    def gradient(self, R: NDArray) -> NDArray:
        return self.J.T @ R

    def levenberg_marquardt(self, R: NDArray, mu: float) -> NDArray | None:
        A = (self.J.T @ self.J).tocsc()
        d = A.diagonal()
        A = A + sparse.diags(mu * np.maximum(d, 1e-300), format="csc")
        try:
            x = splu(A).solve(-(self.J.T @ R))
        except RuntimeError:
            return None
        return x if np.all(np.isfinite(x)) else None


class _FullProblem:
    """R(q) = L q - F - B DFT[f(delta(IDFT q))], q all cargo-DOF coefficients.

    The unknowns are the corrections ``u = q - q_lin`` to the linear (bilateral-saddle)
    response, so ``R = L u + r_lin - B DFT[f]`` with ``r_lin = L q_lin - F`` evaluated once in
    extended precision. In absolute coordinates the round-off of ``L q`` (stiffness terms up to
    ~1e13 N/m times the rigid-body part of q, ~0.1 m) is ~1e-10 of the load scale -- as large
    as the tolerance -- so the residual could not be driven below it; the corrections are
    small, and the shifted residual is accurate to ~1e-14.

    ``L`` (the linear part without the compression-only saddle springs) is block diagonal per
    harmonic, each block banded; the contact couples the harmonics of the saddle DOFs only. It
    is kept sparse: the Jacobian ``L + E T E^T`` (E the saddle-DOF selection, T the AFT block
    of each saddle) is assembled on a fixed sparsity pattern and factorised by a sparse LU
    (SuperLU) once per Newton iteration.
    """

    def __init__(self, model: StructuralModel, excitation: HarmonicExcitation, H: int, N: int, ops: CondensedOperators):
        self.ops = ops
        self.n_c = model.cargo_dof_count
        self.n_s = model.saddle_count
        self.n_h = 2 * H + 1
        self.size = self.n_h * self.n_c
        self.sad = model.saddle_cargo_dof
        self.inverse, self.forward = real_dft_matrices(H, N)
        self.k_u = np.asarray(model.saddle_unilateral_stiffness_N_per_m, dtype=float)
        ex = excitation.padded(H + 1)
        n_c = self.n_c
        rows: list[NDArray] = []
        cols: list[NDArray] = []
        vals: list[NDArray] = []

        def put(A: NDArray, r0: int, c0: int) -> None:
            i, j = np.nonzero(A)
            rows.append(i + r0)
            cols.append(j + c0)
            vals.append(A[i, j])

        F = np.zeros((H + 1, n_c), dtype=complex)
        for k in range(H + 1):
            Kd_cc, Kd_co, _, _ = model.dynamic_stiffness(k * ex.omega_rad_s, False)
            F[k] = ex.cargo_load_N[k] + (model.static_load_N if k == 0 else 0.0) - Kd_co @ ex.deck_displacement[k]
            if k == 0:
                put(np.real(Kd_cc), 0, 0)
            else:
                a, b = (2 * k - 1) * n_c, 2 * k * n_c
                Kr, Ki = np.real(Kd_cc), np.imag(Kd_cc)
                put(Kr, a, a)
                put(Ki, a, b)
                put(-Ki, b, a)
                put(Kr, b, b)
        self.index = np.arange(self.n_h)[None, :] * n_c + self.sad[:, None]  # (n_s, n_h)
        L_rows, L_cols, L_vals = np.concatenate(rows), np.concatenate(cols), np.concatenate(vals)
        self.L = sparse.csr_matrix((L_vals, (L_rows, L_cols)), shape=(self.size, self.size))
        # fixed pattern of L + E T E^T; T's entries are scattered into it per iteration
        T_rows = np.broadcast_to(self.index[:, :, None], (self.n_s, self.n_h, self.n_h)).ravel()
        T_cols = np.broadcast_to(self.index[:, None, :], (self.n_s, self.n_h, self.n_h)).ravel()
        all_rows = np.concatenate([L_rows, T_rows])
        all_cols = np.concatenate([L_cols, T_cols])
        pattern = sparse.csc_matrix(
            (np.arange(1, all_rows.size + 1, dtype=float), (all_rows, all_cols)), shape=(self.size, self.size)
        )
        pattern.sum_duplicates()
        pattern.sort_indices()
        # position of every (row, col) entry in the CSC data array
        key = pattern.indices.astype(np.int64) + self.size * np.repeat(np.arange(self.size, dtype=np.int64), np.diff(pattern.indptr))
        pos = np.searchsorted(key, all_rows.astype(np.int64) + self.size * all_cols.astype(np.int64))
        self._pattern_indices, self._pattern_indptr = pattern.indices, pattern.indptr
        self._base = np.zeros(pattern.data.size)
        np.add.at(self._base, pos[: L_rows.size], L_vals)
        self._T_pos = pos[L_rows.size :]
        self.F = complex_to_real_harmonics(F)
        self.deck_z = complex_to_real_harmonics(ex.deck_displacement[:, model.saddle_deck_dof])
        self.q_lin = complex_to_real_harmonics(ops.linear_cargo_displacement)
        # residual and saddle compressions of the linear response (extended-precision L q_lin)
        x = np.longdouble
        r_lin = np.zeros(self.size, dtype=x)
        np.add.at(r_lin, L_rows, L_vals.astype(x) * self.q_lin.ravel().astype(x)[L_cols])
        self.r_lin = (r_lin - self.F.ravel().astype(x)).astype(float).reshape(self.n_h, self.n_c)
        self.delta_lin = self.deck_z - self.q_lin[:, self.sad]
        force_lin = self.k_u * np.abs(ops.linear_compression_m)
        self.scale = float(max(np.max(np.abs(self.F)), np.max(force_lin), 1.0))

    def _at(self, A: NDArray, amplitude: float) -> NDArray:
        if amplitude == 1.0:
            return A
        out = A * amplitude
        out[0] = A[0]
        return out

    def initial_guess(self, amplitude: float) -> NDArray:
        """The linear response: zero correction (at any amplitude, the linear part scales)."""
        return np.zeros(self.size)

    def cargo_displacement(self, u: NDArray, amplitude: float = 1.0) -> NDArray:
        """Real harmonics (2H+1, n_c) of the cargo DOFs for the correction ``u``."""
        return self._at(self.q_lin, amplitude) + u.reshape(self.n_h, self.n_c)

    def predictor(self, amplitude: float) -> NDArray:
        """The condensed quasi-static exact-contact predictor mapped to every cargo DOF."""
        d_lin = self.inverse @ self.ops.linear_compression_at(amplitude)
        if not np.any(d_lin < 0.0):
            return self.initial_guess(amplitude)
        delta = _CondensedProblem(self.ops, self.inverse.shape[0]).predictor_compression(amplitude)
        C = real_to_complex_harmonics(self.forward @ (self.k_u * np.maximum(-delta, 0.0)))
        return complex_to_real_harmonics(np.einsum("kcs,ks->kc", self.ops.cargo_influence, C)).ravel()

    def evaluate(self, u: NDArray, law: ContactLaw, amplitude: float) -> tuple[NDArray, Any]:
        Q = u.reshape(self.n_h, self.n_c)
        delta = self.inverse @ (self._at(self.delta_lin, amplitude) - Q[:, self.sad])
        f, fp = law.force_and_derivative(delta, self.k_u)
        Fc = self.forward @ f  # (n_h, n_s)
        R = (self.L @ u).reshape(self.n_h, self.n_c) + self._at(self.r_lin, amplitude)
        R[:, self.sad] -= Fc
        return R.ravel(), fp

    def sparse_jacobian(self, fp: NDArray) -> Any:
        PW = self.forward[None, :, :] * fp.T[:, None, :]
        T = PW @ self.inverse  # (n_s, n_h, n_h)
        data = self._base.copy()
        np.add.at(data, self._T_pos, T.ravel())
        return sparse.csc_matrix((data, self._pattern_indices, self._pattern_indptr), shape=(self.size, self.size))

    def jacobian(self, fp: NDArray) -> NDArray:
        return self.sparse_jacobian(fp).toarray()

    def factorise(self, fp: NDArray) -> _SparseJacobian:
        return _SparseJacobian(self.sparse_jacobian(fp))


# ====================================================================== nonlinear solvers
@dataclass
class _Attempt:
    u: NDArray
    converged: bool
    residual: float  # relative, inf-norm
    iterations: int
    evaluations: int
    note: str


_ARMIJO = 1e-4
_NONMONOTONE_MEMORY = 4
_MIN_STEP = 1.0 / 1024
_STAGNATION_WINDOW = 12


def _newton(problem: Any, law: ContactLaw, amplitude: float, u0: NDArray, tol: float, max_iter: int) -> _Attempt:
    """Globalised (semi-smooth) Newton on the merit ``theta = ||R||^2 / 2``.

    Each iteration takes the Newton direction ``d = -J^-1 R`` (with the exact law J is an
    element of the generalised Jacobian: semi-smooth Newton) and backtracks with a
    non-monotone Armijo rule (Grippo-Lampariello-Lucidi: ``theta`` must fall below the largest
    of the last few accepted values by ``1e-4 alpha ||R||^2``), which lets the iteration cross
    the kinks of the piecewise-linear exact law instead of stalling in front of them. When no
    step length down to 1/1024 is accepted (a kink right ahead, a near-singular J), a
    Levenberg-Marquardt step ``(J^T J + mu diag(J^T J)) d = -J^T R`` with increasing mu is taken
    instead, monotone in ``theta``; Newton resumes at the next iteration. The attempt is
    abandoned (for the caller's fallbacks) when ``theta`` has not fallen tenfold over 12
    iterations: near a solution semi-smooth Newton terminates in a few steps, so this is a
    zig-zag between contact patterns, not slow progress.
    """
    scale = problem.scale
    u = u0.copy()
    R, state = problem.evaluate(u, law, amplitude)
    nfev = 1
    theta = 0.5 * float(R @ R)
    history = [theta]
    lm_steps = 0
    for it in range(max_iter + 1):
        rel = float(np.max(np.abs(R))) / scale
        if not np.isfinite(rel):
            return _Attempt(u, False, rel, it, nfev, "non-finite residual")
        if rel <= tol:
            extra = f", {lm_steps} Levenberg-Marquardt step(s)" if lm_steps else ""
            return _Attempt(u, True, rel, it, nfev, f"newton converged in {it} iteration(s){extra}")
        if it == max_iter:
            break
        if len(history) > 2 * _STAGNATION_WINDOW and min(history[-_STAGNATION_WINDOW:]) > 0.1 * min(history[:-_STAGNATION_WINDOW]):
            return _Attempt(u, False, rel, it, nfev, f"newton stagnated (merit not reduced tenfold in {_STAGNATION_WINDOW} iterations)")
        jac = problem.factorise(state)
        step = jac.solve(-R)
        accepted = False
        if step is not None:
            reference = max(history[-_NONMONOTONE_MEMORY:])
            alpha = 1.0
            while alpha >= _MIN_STEP:
                u_try = u + alpha * step
                R_try, state_try = problem.evaluate(u_try, law, amplitude)
                nfev += 1
                th_try = 0.5 * float(R_try @ R_try)
                if np.isfinite(th_try) and th_try <= reference - _ARMIJO * alpha * 2.0 * theta:
                    accepted = True
                    break
                alpha *= 0.5
        if not accepted:
            g = jac.gradient(R)
            mu = 1e-6
            while mu <= 1e6:
                step = jac.levenberg_marquardt(R, mu)
                if step is not None:
                    u_try = u + step
                    R_try, state_try = problem.evaluate(u_try, law, amplitude)
                    nfev += 1
                    th_try = 0.5 * float(R_try @ R_try)
                    if np.isfinite(th_try) and th_try <= theta + _ARMIJO * float(g @ step):
                        accepted = True
                        lm_steps += 1
                        break
                mu *= 10.0
            if not accepted:
                return _Attempt(u, False, rel, it, nfev, "newton line search and Levenberg-Marquardt steps failed")
        u, R, state, theta = u_try, R_try, state_try, th_try
        history.append(theta)
    return _Attempt(u, False, float(np.max(np.abs(R))) / scale, max_iter, nfev, "newton reached max_iterations")


def _hybr(problem: Any, law: ContactLaw, amplitude: float, u0: NDArray, tol: float, max_iter: int) -> _Attempt:
    """MINPACK hybrj (Powell hybrid) with the analytic Jacobian."""
    cache: dict[str, Any] = {}
    counter = {"fev": 0, "jev": 0}

    def fun(u: NDArray) -> NDArray:
        R, state = problem.evaluate(u, law, amplitude)
        counter["fev"] += 1
        cache["u"], cache["state"] = u.copy(), state
        return R

    def jac(u: NDArray) -> NDArray:
        counter["jev"] += 1
        if "u" in cache and np.array_equal(cache["u"], u):
            return problem.jacobian(cache["state"])
        return problem.jacobian(problem.evaluate(u, law, amplitude)[1])

    sol = root(fun, u0, jac=jac, method="hybr", options={"xtol": max(tol, 1e-14), "maxfev": 50 * max_iter})
    u = np.asarray(sol.x, dtype=float)
    R, _ = problem.evaluate(u, law, amplitude)
    rel = float(np.max(np.abs(R))) / problem.scale
    ok = bool(np.isfinite(rel) and rel <= max(tol, 1e-13) * 10.0)
    note = f"hybr: {sol.message.strip()}"
    if ok and not sol.success:
        # MINPACK stops on its own progress test; the residual is what decides convergence here
        note += f" (residual {rel:.1e} within tolerance: accepted)"
    return _Attempt(u, ok, rel, counter["jev"], counter["fev"] + 1, note)


_SOLVER_FUNCTIONS: dict[str, Callable[..., _Attempt]] = {"newton": _newton, "hybr": _hybr}


def _start(problem: Any, law: ContactLaw, amplitude: float) -> tuple[NDArray, str]:
    """The better (smaller residual) of the linear solution and the quasi-static contact predictor."""
    u_lin = problem.initial_guess(amplitude)
    u_pre = problem.predictor(amplitude)
    if u_pre is u_lin or np.array_equal(u_pre, u_lin):
        return u_lin, "linear solution"
    r_lin = float(np.linalg.norm(problem.evaluate(u_lin, law, amplitude)[0]))
    r_pre = float(np.linalg.norm(problem.evaluate(u_pre, law, amplitude)[0]))
    if r_pre <= r_lin:
        return u_pre, "quasi-static contact predictor"
    return u_lin, "linear solution"


def _solve_with_fallback(problem: Any, law: ContactLaw, options: HBMOptions, u_start: NDArray | None = None) -> _Attempt:
    """Direct solve; on failure continuation in kappa, then in the dynamic amplitude.

    The direct solve starts from ``u_start`` if given, else from the better of the linear
    solution and the quasi-static exact-contact predictor. ``note`` records the path taken:
    it starts with ``"direct: "`` for a direct solve and says ``"continuation"`` otherwise.
    """
    solve = _SOLVER_FUNCTIONS[options.solver]
    tol, maxit = float(options.tolerance), int(options.max_iterations)
    if u_start is None:
        u0, origin = _start(problem, law, 1.0)
    else:
        u0, origin = u_start, "given initial guess"
    first = solve(problem, law, 1.0, u0, tol, maxit)
    total_it, total_ev = first.iterations, first.evaluations
    if first.converged or not options.continuation:
        return _Attempt(first.u, first.converged, first.residual, total_it, total_ev, f"direct: {first.note} (start: {origin})")
    notes = [f"direct solve failed ({first.note}, start: {origin}, residual {first.residual:.2e})"]
    best = first
    if u_start is None and origin != "linear solution":
        # a second direct attempt from the linear solution (another path across the kinks)
        second = solve(problem, law, 1.0, problem.initial_guess(1.0), tol, maxit)
        total_it += second.iterations
        total_ev += second.evaluations
        if second.converged:
            return _Attempt(second.u, True, second.residual, total_it, total_ev, f"direct: {second.note} (start: linear solution, after a failed start from the {origin})")
        notes.append(f"direct solve from the linear solution failed ({second.note}, residual {second.residual:.2e})")
        best = second if second.residual < best.residual else best

    # (1) continuation in the sharpness kappa, from a soft law to the requested one
    delta_scale = float(getattr(problem, "compression_scale", None) or 1e-3)
    soft_name = "softplus" if law.name == "exact" else law.name
    kappa_target = law.regularisation_per_m if law.name != "exact" else 1e4 / delta_scale
    kappa_start = min(1.0 / delta_scale, kappa_target / 10.0)
    if kappa_start < kappa_target:
        u = u0
        kappas = list(np.geomspace(kappa_start, kappa_target, 1 + int(np.ceil(2 * np.log10(kappa_target / kappa_start)))))
        reached = 0
        for kappa in kappas:
            a = solve(problem, ContactLaw(soft_name, float(kappa)), 1.0, u, tol, maxit)
            total_it += a.iterations
            total_ev += a.evaluations
            if not a.converged:
                break
            u, reached = a.u, reached + 1
        if reached:
            # the requested law from the sharpest soft solution reached (the whole path, or the
            # part of it that converged: a sharp soft law can be harder than the exact one)
            final = solve(problem, law, 1.0, u, tol, maxit)
            total_it += final.iterations
            total_ev += final.evaluations
            if final.converged:
                notes.append(f"converged by continuation in kappa over {reached} of {len(kappas)} step(s)")
                return _Attempt(final.u, True, final.residual, total_it, total_ev, "; ".join(notes))
            best = final if final.residual < best.residual else best
        notes.append("kappa continuation failed")

    # (2) continuation in the dynamic excitation amplitude, from the static state
    static = solve(problem, law, 0.0, _start(problem, law, 0.0)[0], tol, maxit)
    total_it += static.iterations
    total_ev += static.evaluations
    if static.converged:
        lam, step, u = 0.0, 0.25, static.u
        n_steps = 0
        while lam < 1.0 and step >= 1.0 / 2048:
            lam_try = min(1.0, lam + step)
            guess = u + (problem.initial_guess(lam_try) - problem.initial_guess(lam))
            a = solve(problem, law, lam_try, guess, tol, maxit)
            total_it += a.iterations
            total_ev += a.evaluations
            n_steps += 1
            if a.converged:
                lam, u = lam_try, a.u
                step = min(2.0 * step, 0.5)
            else:
                step *= 0.5
        if lam >= 1.0:
            R, _ = problem.evaluate(u, law, 1.0)
            notes.append(f"converged by continuation in excitation amplitude ({n_steps} step(s))")
            return _Attempt(u, True, float(np.max(np.abs(R))) / problem.scale, total_it, total_ev, "; ".join(notes))
        notes.append(f"amplitude continuation stalled at {lam:.3g} of the excitation")
    else:
        notes.append("the static state did not converge")
    return _Attempt(best.u, False, best.residual, total_it, total_ev, "; ".join(notes) + "; NOT CONVERGED")


# ====================================================================== public API
@dataclass(frozen=True)
class CondensedSolution:
    """Raw condensed HBM solution (for continuation and post-processing).

    ``saddle_compression`` is the real coefficient array (2H+1, n_s) [m]; ``correction_force``
    the real coefficients (2H+1, n_s) [N] of ``c = f(delta) - k_u delta``.
    """

    saddle_compression: NDArray[np.float64]
    correction_force: NDArray[np.float64]
    converged: bool
    residual_norm: float
    iterations: int
    function_evaluations: int
    message: str


def solve_condensed(
    ops: CondensedOperators,
    options: HBMOptions,
    initial_compression: NDArray | None = None,
) -> CondensedSolution:
    """Solve the condensed HBM system for given operators (used by :func:`solve_hbm` and continuation)."""
    problem = _CondensedProblem(ops, options.time_samples)
    problem.compression_scale = ops.compression_scale_m
    u0 = None if initial_compression is None else np.asarray(initial_compression, dtype=float).ravel()
    a = _solve_with_fallback(problem, options.law, options, u0)
    U = a.u.reshape(problem.n_h, problem.n_s)
    delta = problem.inverse @ U
    corr = problem.forward @ (options.law.force(delta, problem.k_u) - problem.k_u * delta)
    return CondensedSolution(U, corr, a.converged, a.residual, a.iterations, a.evaluations, a.note)


def solve_hbm(
    model: StructuralModel,
    excitation: HarmonicExcitation,
    options: HBMOptions | None = None,
    *,
    initial_compression_m: NDArray | None = None,
) -> PeriodicResponse:
    """Periodic steady state with unilateral saddles by harmonic balance + AFT.

    Parameters
    ----------
    model
        The cargo and sea-fastening model.
    excitation
        Deck motion and vessel loads per harmonic (harmonics above ``options.harmonics`` are
        dropped, and the message says so). The model's static load (gravity, pretension) is
        added at k = 0. With ``harmonics = 0`` only the static part is solved: the nonlinear
        static solution.
    options
        :class:`HBMOptions` (defaults: H = 5, N = 128, tanh law, kappa = 1000 1/m, condensed,
        Newton).
    initial_compression_m
        Optional start: saddle compressions sampled on the options' time grid, (N, n_s) [m]
        (e.g. a neighbouring solution's ``saddle_compression_time_m``; condensed formulation
        only). Default: the better of the linear solution and the quasi-static predictor.

    Returns
    -------
    PeriodicResponse
        ``method = "hbm"``; never raises for non-convergence (``converged=False``). Its
        ``residual_norm`` is relative (see :class:`HBMOptions` ``tolerance``).
    """
    options = HBMOptions() if options is None else options
    H, N = int(options.harmonics), int(options.time_samples)
    law = options.law
    ops = condensed_operators(model, excitation, H)
    if options.formulation == "condensed":
        start = None
        if initial_compression_m is not None:
            samples = np.asarray(initial_compression_m, dtype=float)
            if samples.shape != (N, model.saddle_count):
                raise ValueError(f"initial_compression_m: shape {samples.shape}; must be (time_samples, n_saddles) = {(N, model.saddle_count)}")
            start = real_dft_matrices(H, N)[1] @ samples
        sol = solve_condensed(ops, options, start)
        C = real_to_complex_harmonics(sol.correction_force)  # (H+1, n_s)
        X = ops.linear_cargo_displacement + np.einsum("kcs,ks->kc", ops.cargo_influence, C)
        U = sol.saddle_compression
        converged, resid, its, nfev, note = sol.converged, sol.residual_norm, sol.iterations, sol.function_evaluations, sol.message
    else:
        problem = _FullProblem(model, excitation, H, N, ops)
        problem.compression_scale = ops.compression_scale_m
        a = _solve_with_fallback(problem, law, options)
        Q = problem.cargo_displacement(a.u)
        X = real_to_complex_harmonics(Q)
        U = problem.deck_z - Q[:, model.saddle_cargo_dof]
        converged, resid, its, nfev, note = a.converged, a.residual, a.iterations, a.evaluations, a.note
    inverse, _ = real_dft_matrices(H, N)
    delta = inverse @ U
    force = law.force(delta, ops.saddle_stiffness_N_per_m)
    if ops.ignored_harmonics:
        note += f"; WARNING: excitation harmonics above H={H} were ignored"
    return PeriodicResponse(
        method="hbm",
        omega_rad_s=float(excitation.omega_rad_s),
        cargo_displacement_time_m=harmonics_to_time(X, N),
        cargo_displacement_harmonics=X,
        saddle_compression_time_m=delta,
        saddle_force_time_N=force,
        converged=bool(converged),
        residual_norm=float(resid),
        iterations=int(its),
        message=note,
        harmonic_truncation_indicator=high_harmonic_energy_share(force, H),
        function_evaluations=int(nfev),
        options=options.to_dict(),
    )
