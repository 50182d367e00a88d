"""The saddles' correction system in modal coordinates, marched in time with exact contact.

With every saddle bilateral the cargo is linear: its response to any deck motion and vessel load is the
linear (bilateral) response ``delta_lin`` (known, e.g. from the frequency domain). The unilateral saddles
differ from it only by the *correction forces* ``c = k_u max(-delta, 0)`` at the saddles, the tension a
bilateral saddle would carry, removed::

    M q_c'' + D q_c' + K q_c = B c,      delta = delta_lin - B^T q_c,      c = k_u max(-delta, 0)

(``K`` with the saddles bilateral, ``B`` the saddle z DOFs). This is exactly the condensed formulation of
the harmonic balance and of the references (``docs/theory.md``, section 5). Here ``q_c`` is reduced to the
cargo's modes below a cutoff (mass-normalised, the non-diagonal modal damping ``Phi^T D Phi`` kept) plus the
static residual flexibility of the truncated modes at the saddles (``R = B^T K^-1 B - Phi_s Omega^-2
Phi_s^T``), so the modes above the cutoff respond quasi-statically and the reduced system is exact at
zero frequency. It is marched with the Newmark average-acceleration rule (no numerical damping) and the
contact of each step is solved exactly over the saddles (active set on ``n_s`` unknowns).

Uses: a start for the high-harmonic HBM solves (a few periods of the march land in the basin of the
semi-smooth Newton, where a start from fewer harmonics does not), and non-periodic marches.

The stepping loop is compiled with numba: it cannot be vectorised (each step's contact depends on the
previous step) and a Python loop costs 20-60 us a step against about 1 us compiled.
"""

from __future__ import annotations

import weakref
from dataclasses import dataclass

import numpy as np
from numba import njit
from numpy.typing import NDArray
from scipy.linalg import eigh

from seafast.model.structure import StructuralModel

__all__ = ["ModalBasis", "ModalCorrectionSystem", "MarchResult", "modal_basis", "modal_correction_system"]


@dataclass(frozen=True)
class ModalCorrectionSystem:
    """The correction system reduced to ``m`` modes plus static residual flexibility at the saddles.

    Attributes
    ----------
    natural_frequency_rad_s
        Undamped natural frequencies of the kept modes (saddles bilateral, deck fixed) [rad/s], (m,).
    modal_damping
        ``Phi^T D Phi`` [1/s], (m, m), mass-normalised modes.
    saddle_mode_shape
        ``Phi_s = B^T Phi``, the modes' z at the saddles [m per unit modal coordinate], (n_s, m).
    residual_flexibility_m_per_N
        Static flexibility of the truncated modes at the saddles [m/N], (n_s, n_s).
    unilateral_stiffness_N_per_m
        ``k_u`` of each saddle [N/m], (n_s,).
    cutoff_rad_s
        Modes at or below this frequency are kept [rad/s].
    """

    natural_frequency_rad_s: NDArray[np.float64]
    modal_damping: NDArray[np.float64]
    saddle_mode_shape: NDArray[np.float64]
    residual_flexibility_m_per_N: NDArray[np.float64]
    unilateral_stiffness_N_per_m: NDArray[np.float64]
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
        """
        w = np.atleast_1d(np.asarray(omega_rad_s, dtype=float))
        m = self.mode_count
        R = self.residual_flexibility_m_per_N
        if m == 0:
            return np.broadcast_to(R, (w.size,) + R.shape).astype(complex)
        A = np.diag(self.natural_frequency_rad_s**2)[None] - (w**2)[:, None, None] * np.eye(m)[None] + 1j * w[:, None, None] * self.modal_damping[None]
        Ps = self.saddle_mode_shape
        X = np.linalg.solve(A, np.broadcast_to(Ps.T.astype(complex), (w.size, m, Ps.shape[0])))
        return np.einsum("tm,kms->kts", Ps, X) + R[None]

    def march(
        self,
        linear_compression_m: NDArray[np.float64],
        time_step_s: float,
        state: NDArray[np.float64] | None = None,
    ) -> "MarchResult":
        """March the correction system through the given linear compressions.

        Parameters
        ----------
        linear_compression_m
            ``delta_lin`` at the step times ``t_0 .. t_{n-1}`` (step ``time_step_s``), (n, n_s) [m].
            The state given is the one at ``t_0``; the compression at ``t_0`` is not recomputed.
        time_step_s
            Step [s], > 0.
        state
            ``(eta, eta', eta'', c)`` at ``t_0`` stacked as one vector of length ``3 m + n_s``; default at rest
            with no correction force.

        Returns
        -------
        MarchResult
            The compressions ``delta`` at every step (row 0 is ``delta_lin[0]`` minus the initial state's
            correction) and the state after the last step.
        """
        d_lin = np.ascontiguousarray(linear_compression_m, dtype=float)
        m, n_s = self.mode_count, self.saddle_count
        if d_lin.ndim != 2 or d_lin.shape[1] != n_s:
            raise ValueError(f"linear_compression_m: shape {d_lin.shape}; must be (steps, {n_s})")
        if not (np.isfinite(time_step_s) and time_step_s > 0):
            raise ValueError(f"time_step_s = {time_step_s!r}; must be a finite number > 0")
        s0 = np.zeros(3 * m + n_s) if state is None else np.array(state, dtype=float)
        if s0.shape != (3 * m + n_s,):
            raise ValueError(f"state: length {s0.size}; must be 3 m + n_s = {3 * m + n_s}")
        delta, final = _march(
            d_lin,
            float(time_step_s),
            self.natural_frequency_rad_s**2,
            self.modal_damping,
            self.saddle_mode_shape,
            self.residual_flexibility_m_per_N,
            self.unilateral_stiffness_N_per_m,
            s0,
        )
        return MarchResult(delta, final)

    def periodic(
        self,
        linear_compression_m: NDArray[np.float64],
        period_s: float,
        *,
        max_periods: int = 50,
        tolerance: float = 1e-6,
    ) -> tuple[NDArray[np.float64], int, float]:
        """March period after period until the compressions repeat (the attracting periodic state).

        Parameters
        ----------
        linear_compression_m
            ``delta_lin`` over one period at ``t_n = n T / N``, (N, n_s) [m].
        period_s
            T [s].
        max_periods, tolerance
            Stop when the largest change of ``delta`` between two periods is below ``tolerance`` times the
            largest linear compression, or after ``max_periods``.

        Returns
        -------
        delta, periods, change
            The last period's compressions (N, n_s) [m], the periods marched and the last relative change.
        """
        d_lin = np.asarray(linear_compression_m, dtype=float)
        N = d_lin.shape[0]
        dt = float(period_s) / N
        scale = max(float(np.max(np.abs(d_lin))), 1e-12)
        # one extra sample closes the period: the state at t_N is the next period's start
        closed = np.concatenate([d_lin, d_lin[:1]])
        state = None
        previous: NDArray[np.float64] | None = None
        change = np.inf
        periods = 0
        delta = d_lin
        for periods in range(1, int(max_periods) + 1):
            result = self.march(closed, dt, state)
            state = result.state
            delta = result.compression_m[1:]  # t_1 .. t_N = t_0 of the next period
            delta = np.roll(delta, 1, axis=0)
            if previous is not None:
                change = float(np.max(np.abs(delta - previous))) / scale
                if change <= tolerance:
                    break
            previous = delta
        return delta, periods, change


@dataclass(frozen=True)
class MarchResult:
    """Compressions at every step [m] (n, n_s) and the final state ``(eta, eta', eta'', c)``."""

    compression_m: NDArray[np.float64]
    state: NDArray[np.float64]


@dataclass(frozen=True)
class ModalBasis:
    """The lowest undamped modes of the cargo on bilateral saddles (deck fixed), mass-normalised.

    Attributes
    ----------
    natural_frequency_rad_s
        (m,) ascending [rad/s].
    mode_shape
        (n_c, m) [m or rad per unit modal coordinate].
    static_saddle_flexibility_m_per_N
        ``B^T K^-1 B`` (n_s, n_s) [m/N], the complete static flexibility at the saddles.
    complete
        Whether every mode of the model is in the basis (else modes above the last one exist).
    """

    natural_frequency_rad_s: NDArray[np.float64]
    mode_shape: NDArray[np.float64]
    static_saddle_flexibility_m_per_N: NDArray[np.float64]
    complete: bool


_BASIS_CACHE: dict[int, tuple[weakref.ref, ModalBasis]] = {}
_DENSE_EIGEN_LIMIT = 400  # DOFs; above it, the few lowest modes come from a shift-invert Lanczos


def modal_basis(model: StructuralModel, cutoff_rad_s: float) -> ModalBasis:
    """Modes of the model at least up to ``cutoff_rad_s`` (cached per model; grows when asked for more).

    Small models take every mode from a dense generalised eigensolve; large ones (long or finely
    meshed cargo) the lowest ones from ARPACK in shift-invert mode on the banded K, doubling the
    count until the cutoff is passed.
    """
    hit = _BASIS_CACHE.get(id(model))
    if hit is not None and hit[0]() is model:
        basis = hit[1]
        if basis.complete or basis.natural_frequency_rad_s[-1] > cutoff_rad_s:
            return basis
    K = model.cargo.stiffness + model.spring_matrices(True)[0]
    M = model.cargo.mass
    n = K.shape[0]
    sad = model.saddle_cargo_dof
    B = np.zeros((n, sad.size))
    B[sad, np.arange(sad.size)] = 1.0
    static = np.linalg.solve(K, B)[sad] if n <= _DENSE_EIGEN_LIMIT else _sparse_static(K, B)[sad]
    if n <= _DENSE_EIGEN_LIMIT:
        w2, phi = eigh(K, M)
        complete = True
    else:
        from scipy.sparse import csc_matrix
        from scipy.sparse.linalg import eigsh

        count = 8
        while True:
            count = min(count, n - 2)
            w2, phi = eigsh(csc_matrix(K), k=count, M=csc_matrix(M), sigma=0.0, which="LM")
            order = np.argsort(w2)
            w2, phi = w2[order], phi[:, order]
            complete = False
            if np.sqrt(max(w2[-1], 0.0)) > cutoff_rad_s or count >= n - 2:
                break
            count *= 2
    basis = ModalBasis(np.sqrt(np.maximum(w2, 0.0)), np.ascontiguousarray(phi), 0.5 * (static + static.T), complete)
    try:
        _BASIS_CACHE[id(model)] = (weakref.ref(model), basis)
    except TypeError:  # pragma: no cover - models without weakref support are not cached
        pass
    if len(_BASIS_CACHE) > 64:
        for key in [k for k, (ref, _) in _BASIS_CACHE.items() if ref() is None]:
            del _BASIS_CACHE[key]
    return basis


def _sparse_static(K: NDArray, B: NDArray) -> NDArray:
    from scipy.sparse import csc_matrix
    from scipy.sparse.linalg import splu

    return np.asarray(splu(csc_matrix(K)).solve(B))


def modal_correction_system(model: StructuralModel, cutoff_rad_s: float) -> ModalCorrectionSystem:
    """Reduce the model's correction system to the modes at or below ``cutoff_rad_s``.

    Parameters
    ----------
    model
        The cargo model (its K with the saddles bilateral, M, and Rayleigh D).
    cutoff_rad_s
        Highest natural frequency kept [rad/s] (e.g. the Nyquist frequency of the march's time step: the
        modes above it respond quasi-statically through the residual flexibility).
    """
    basis = modal_basis(model, cutoff_rad_s)
    w = basis.natural_frequency_rad_s
    m = int(np.searchsorted(w, float(cutoff_rad_s), side="right"))
    w, phi = w[:m], basis.mode_shape[:, :m]
    phis = phi[model.saddle_cargo_dof]
    residual = basis.static_saddle_flexibility_m_per_N - (phis / w**2) @ phis.T if m else basis.static_saddle_flexibility_m_per_N
    return ModalCorrectionSystem(
        natural_frequency_rad_s=np.ascontiguousarray(w),
        modal_damping=np.ascontiguousarray(phi.T @ model.damping_cc @ phi),
        saddle_mode_shape=np.ascontiguousarray(phis),
        residual_flexibility_m_per_N=np.ascontiguousarray(0.5 * (residual + residual.T)),
        unilateral_stiffness_N_per_m=np.asarray(model.saddle_unilateral_stiffness_N_per_m, dtype=float).copy(),
        cutoff_rad_s=float(cutoff_rad_s),
    )


@njit(cache=True)
def _contact(pred: NDArray, W: NDArray, k: NDArray, detached: NDArray) -> NDArray:
    """Exact ``delta = pred - W c``, ``c = k max(-delta, 0)`` by active set from ``detached`` (updated in place)."""
    n = pred.size
    # the common step: every saddle in contact before and after (no correction force)
    free = True
    for i in range(n):
        if detached[i] or pred[i] < 0.0:
            free = False
            break
    if free:
        return pred.copy()
    delta = pred.copy()
    A = np.empty((n, n))
    for _ in range(2 * n + 4):
        for i in range(n):
            for j in range(n):
                A[i, j] = (1.0 if i == j else 0.0) - (W[i, j] * k[j] if detached[j] else 0.0)
        delta = np.linalg.solve(A, pred)
        same = True
        for i in range(n):
            if (delta[i] < 0.0) != detached[i]:
                same = False
                detached[i] = delta[i] < 0.0
        if same:
            return delta
    # cycling (rare): enumerate the sets, keep the least violating one
    best = delta.copy()
    best_violation = np.inf
    trial = np.zeros(n, dtype=np.bool_)
    for code in range(1 << n):
        for i in range(n):
            trial[i] = (code >> i) & 1
        for i in range(n):
            for j in range(n):
                A[i, j] = (1.0 if i == j else 0.0) - (W[i, j] * k[j] if trial[j] else 0.0)
        d = np.linalg.solve(A, pred)
        violation = 0.0
        for i in range(n):
            v = d[i] if trial[i] else -d[i]
            if v > violation:
                violation = v
        if violation < best_violation:
            best_violation = violation
            best = d.copy()
            for i in range(n):
                detached[i] = trial[i]
            if violation == 0.0:
                break
    return best


@njit(cache=True)
def _march(
    d_lin: NDArray, dt: float, w2: NDArray, Cm: NDArray, Ps: NDArray, R: NDArray, k: NDArray, s0: NDArray
) -> tuple[NDArray, NDArray]:
    n_t, n_s = d_lin.shape
    m = w2.size
    beta, gamma = 0.25, 0.5
    c1 = 1.0 / (beta * dt * dt)
    c2 = gamma / (beta * dt)
    A = c2 * Cm.copy()
    for i in range(m):
        A[i, i] += c1 + w2[i]
    E = np.linalg.inv(A) if m else np.zeros((0, 0))
    PsE = np.ascontiguousarray(Ps) @ E
    PsT = np.ascontiguousarray(Ps.T)
    W = PsE @ PsT + R
    eta = s0[:m].copy()
    v = s0[m : 2 * m].copy()
    a = s0[2 * m : 3 * m].copy()
    c = s0[3 * m :].copy()
    out = np.empty((n_t, n_s))
    out[0] = d_lin[0] - Ps @ eta - R @ c
    detached = np.zeros(n_s, dtype=np.bool_)
    for i in range(n_s):
        detached[i] = c[i] > 0.0
    for n in range(n_t - 1):
        eta_t = eta + dt * v + dt * dt * (0.5 - beta) * a
        v_t = v + dt * (1.0 - gamma) * a
        rhs = c1 * eta_t + Cm @ (c2 * eta_t - v_t)
        pred = d_lin[n + 1] - PsE @ rhs
        delta = _contact(pred, W, k, detached)
        for i in range(n_s):
            c[i] = k[i] * max(-delta[i], 0.0)
        eta_new = E @ (rhs + PsT @ c)
        a = c1 * (eta_new - eta_t)
        v = v_t + gamma * dt * a
        eta = eta_new
        out[n + 1] = delta
    final = np.empty(3 * m + n_s)
    final[:m] = eta
    final[m : 2 * m] = v
    final[2 * m : 3 * m] = a
    final[3 * m :] = c
    return out, final
