"""The 3-D cargo on frictional pads marched in time to its periodic steady state (:func:`march_cradle_friction`).

The frictionless march's correction system (:mod:`seafast.solvers.cradle_march`) with the pads' sliders. The linear
system is the harmonic balance's linear part (:func:`~seafast.solvers.cradle_friction.stuck_linear_solution`): every
element bilateral and every pad's tangential spring ``k_t`` stuck at the slider's rest, ``K_s = K_lin + A_t^T K_t
A_t``; its periodic response ``z_s(t)`` = (engagements ``s``, tangential motions ``delta``). The nonlinear response is
``z = z_s + [A; A_t] q_c`` with ``q_c`` the response of the same linear system to the corrections ``C``::

    M q_c'' + D q_c' + K_s q_c = -[A; A_t]^T C,    C = [k max(-s, 0);  -k_t (w - delta_rest)],

the normal correction (the tension a bilateral element would carry, removed) and the sliders' offsets from rest
(the actual friction force ``f = k_t (delta - w)`` minus the stuck spring's ``k_t (delta - delta_rest)``), ``w``
each pad's slider. Newmark's average acceleration at ``T / N`` in the modes of ``(K_s, M)`` kept (the others static,
their residual flexibility exact), as the frictionless march. Per step the predictor gives ``z = z_p - G C(z)``
(``G = [A; A_t] K_eff^-1 [A; A_t]^T`` plus the residual flexibility), where ``C`` couples the normal law and the
sliders' return map from the step before's positions (:mod:`seafast.solvers.friction_cone`: the trial force
``k_t (delta - w_prev)`` kept inside the cone ``mu k_n max(s_pad, 0)`` of the same step's normal force, else scaled
onto it). That small problem is solved to round-off by a semi-smooth Newton on ``R(z) = z - z_p + G C(z)``
(Jacobian ``I + G dC/dz``: the normal law's slope, the return map's radial projection, the limit's slope) started
from the step before's corrections, with a backtracking line search on ``|R|``; should it miss the tolerance it is
restarted from no correction, and a step that still misses is counted (``unresolved_steps``: the march is then
not converged).

From the stuck linear solution at rest (``q_c = 0``, sliders at rest), period after period until the engagements,
tangential motions and sliders repeat (:class:`~seafast.solvers.cradle_march.Periodicity`, as
:func:`~seafast.solvers.cradle_march.march_cradle`). Meant where the harmonic balance does not converge (pads that
lift and slip): :func:`~seafast.solvers.cradle_friction_solve.solve_cradle_friction` dispatches.

Units: engagements and motions [m]; forces [N]; time [s].
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray
from scipy.linalg import eigh

from seafast.excitation.cradle_loads import CradleExcitation
from seafast.fourier import harmonics_to_time, real_harmonics_to_time
from seafast.model.pad_friction import PadFriction
from seafast.solvers.cradle_dynamics import CradleDynamics
from seafast.solvers.cradle_friction import relaxed_at, stuck_linear_solution
from seafast.solvers.cradle_march import (
    STEPS_PER_MODE_PERIOD_INV,
    SUBHARMONIC_ORDERS,
    CradleStepper,
    Periodicity,
    newmark_advance,
)
from seafast.solvers.pad_tangential import PadTangents, pad_tangents

__all__ = ["FrictionMarchOptions", "FrictionalMarch", "friction_stepper", "march_cradle_friction"]


@dataclass(frozen=True)
class FrictionMarchOptions:
    """Settings of the frictional march.

    Parameters
    ----------
    time_samples
        Steps per wave period N (>= 16; the samples reported). The default is the frictionless march's: where whole
        pad pairs lift on the base case, halving the step moved the peaks by 1.8e-2 from 1024, 4.2e-3 from 2048.
    max_periods
        Wave periods marched at most (>= 12, to test the subharmonics).
    tolerance
        Periodic when the engagements, tangential motions and sliders change over one wave period (or
        ``period_multiple``) by at most this times the largest linear engagement or motion amplitude [-].
    step_tolerance
        A step's problem is solved when ``max |R|`` is below this times that amplitude [-].
    cutoff_rad_s
        The modes of ``(K_s, M)`` kept (None: those spanning at least two steps, as the frictionless march).
    """

    time_samples: int = 2048
    max_periods: int = 200
    tolerance: float = 1e-6
    step_tolerance: float = 1e-11
    cutoff_rad_s: float | None = None

    def __post_init__(self) -> None:
        if int(self.time_samples) < 16:
            raise ValueError(f"time_samples = {self.time_samples!r}: allowed an integer >= 16")
        if int(self.max_periods) < 2 * max(SUBHARMONIC_ORDERS):
            raise ValueError(f"max_periods = {self.max_periods!r}: allowed an integer >= {2 * max(SUBHARMONIC_ORDERS)}")
        for name in ("tolerance", "step_tolerance"):
            if not 0.0 < float(getattr(self, name)) < 1.0:
                raise ValueError(f"{name} = {getattr(self, name)!r}: allowed a number in (0, 1)")
        if self.cutoff_rad_s is not None and not float(self.cutoff_rad_s) > 0.0:
            raise ValueError(f"cutoff_rad_s = {self.cutoff_rad_s!r}: allowed a number > 0 or None")


@dataclass(frozen=True)
class FrictionalMarch:
    """The last ``period_multiple`` wave periods of a frictional march (the last one where not periodic).

    Attributes
    ----------
    engagement_m, tangential_m
        Every element's engagement (N', m) and every pad's tangential motion (N', P, 2) [m] at ``t_n = n T / N``.
    slider_m, friction_force_N
        Each pad's slider ``w`` and friction force ``k_t (delta - w)`` (N', P, 2) [m], [N].
    slipped
        Where a pad's slider moved in the step ending at the sample (N', P).
    cargo_displacement_m
        The cargo's displacements (N', 5 n) [m, rad].
    periodicity, period_multiple, periods, period_change
        As :class:`~seafast.solvers.cradle_march.CradleMarch`: what the steady state is, after how many wave periods
        it repeats (0 not periodic), the periods marched, the change over the last period (or multiple) [-].
    unresolved_steps
        Steps whose per-step problem missed ``step_tolerance`` (0 when every step was solved to it).
    tangents
        The pads' tangential kinematics with the sliders' rest used.
    """

    engagement_m: NDArray[np.float64]
    tangential_m: NDArray[np.float64]
    slider_m: NDArray[np.float64]
    friction_force_N: NDArray[np.float64]
    slipped: NDArray[np.bool_]
    cargo_displacement_m: NDArray[np.float64]
    periodicity: Periodicity
    period_multiple: int
    periods: int
    period_change: float
    unresolved_steps: int
    tangents: PadTangents


def friction_stepper(dynamics: CradleDynamics, tangents: PadTangents, dt: float, cutoff_rad_s: float) -> CradleStepper:
    """Newmark's average acceleration for the frictional correction system at the step ``dt`` [s].

    :func:`~seafast.solvers.cradle_march.cradle_stepper` on the stuck stiffness ``K_s`` with the rows
    ``[A; A_t]`` (m + 2 P) and every cargo DOF as output; ``stiffness_N_per_m`` is ``[k; k_t per row]``.
    """
    problem = dynamics.problem
    R = np.concatenate([problem.engagement_matrix, tangents.rows], axis=0)
    kt = np.repeat(tangents.stiffness_N_per_m, 2)
    K = dynamics.linear_parts().bilateral_stiffness + tangents.rows.T @ (kt[:, None] * tangents.rows)
    _, M, D = dynamics.matrices
    w2, phi = eigh(K, M)
    kept = w2 <= cutoff_rad_s**2
    w2, phi = w2[kept], phi[:, kept]
    B = phi.T @ R.T
    static = np.linalg.solve(K, R.T)
    residual = R @ static - B.T @ (B / w2[:, None])
    r = w2.size
    eye, Xi = np.eye(r), phi.T @ D @ phi
    K_eff = np.diag(w2) + (2.0 / dt) * Xi + (4.0 / dt**2) * eye
    solved = np.linalg.solve(K_eff, np.hstack([(4.0 / dt**2) * eye + (2.0 / dt) * Xi, (4.0 / dt) * eye + Xi, eye, B]))
    flexibility = np.asarray(solved[:, 3 * r :], dtype=float)
    receptance = B.T @ flexibility + residual
    return CradleStepper(
        np.ascontiguousarray(solved[:, : 3 * r]),
        flexibility,
        np.ascontiguousarray(B.T),
        0.5 * (receptance + receptance.T),
        np.concatenate([problem.element_stiffness_N_per_m, kt]),
        dt,
        None,
        w2,
        np.ascontiguousarray(phi),
        -(static - phi @ (B / w2[:, None])),
    )


class _StepProblem:
    """The per-step problem ``R(z) = z - z_p + G C(z)`` (module docstring) and its semi-smooth Newton."""

    def __init__(self, stepper: CradleStepper, tangents: PadTangents, m: int, tolerance: float) -> None:
        self.G, self.m, self.P = stepper.receptance, m, tangents.pad_count
        self.k = stepper.stiffness_N_per_m[:m]
        self.kt = tangents.stiffness_N_per_m.tolist()
        self.mu_kn = (tangents.friction_coefficient * tangents.normal_stiffness_N_per_m).tolist()
        self.rest = tangents.rest_m.ravel()
        self.kt_rows = np.repeat(tangents.stiffness_N_per_m, 2)
        self.tolerance = float(tolerance)
        self.eye = np.eye(m + 2 * self.P)

    def forces(
        self, z: NDArray[np.float64], w_prev: list[list[float]], slope: bool
    ) -> tuple[NDArray[np.float64], list[list[float]], list[bool], NDArray[np.float64] | None]:
        """``C(z)``, the sliders, where they slipped and (``slope``) ``dC/dz``."""
        m, P = self.m, self.P
        s = z[:m]
        C = np.empty(m + 2 * P)
        C[:m] = self.k * np.maximum(-s, 0.0)
        dC = None
        if slope:
            dC = np.zeros((m + 2 * P, m + 2 * P))
            dC[np.arange(m), np.arange(m)] = np.where(s < 0.0, -self.k, 0.0)
        w, slipped = [], []
        zl = z.tolist()
        for p in range(P):
            kt = self.kt[p]
            dx, dy = zl[m + 2 * p], zl[m + 2 * p + 1]
            wx, wy = w_prev[p]
            fx, fy = kt * (dx - wx), kt * (dy - wy)
            norm = math.hypot(fx, fy)
            cap = self.mu_kn[p] * max(zl[p], 0.0)
            slip = norm > cap
            if slip:
                ex, ey = fx / norm, fy / norm
                wx, wy = dx - cap * ex / kt, dy - cap * ey / kt
                if dC is not None:
                    r = cap / norm
                    rows = slice(m + 2 * p, m + 2 * p + 2)
                    dC[rows, rows] = -kt * (np.eye(2) - r * (np.eye(2) - np.outer((ex, ey), (ex, ey))))
                    if zl[p] > 0.0:
                        dC[rows, p] = (ex * self.mu_kn[p], ey * self.mu_kn[p])
            w.append([wx, wy])
            slipped.append(slip)
        C[m:] = -self.kt_rows * (np.ravel(w) - self.rest)
        return C, w, slipped, dC

    def solve(
        self, z_p: NDArray[np.float64], C_prev: NDArray[np.float64], w_prev: list[list[float]], scale: float
    ) -> tuple[NDArray[np.float64], NDArray[np.float64], list[list[float]], list[bool], bool]:
        """``(z, C, sliders, slipped, solved)`` of one step; Newton from ``C_prev``, then from no correction."""
        best = None
        for start in (C_prev, np.zeros_like(C_prev)):
            z = z_p - self.G @ start
            for _ in range(40):
                C, w, slipped, dC = self.forces(z, w_prev, True)
                R = z - z_p + self.G @ C
                norm = float(np.max(np.abs(R)))
                if best is None or norm < best[0]:
                    best = (norm, z, C, w, slipped)
                if norm <= self.tolerance * scale:
                    return z, C, w, slipped, True
                assert dC is not None
                step = np.asarray(np.linalg.solve(self.eye + self.G @ dC, -R), dtype=np.float64)
                z = self._line_search(z, step, z_p, w_prev, norm)
        assert best is not None
        return best[1], best[2], best[3], best[4], False

    def _line_search(
        self, z: NDArray[np.float64], step: NDArray[np.float64], z_p: NDArray[np.float64], w_prev: list[list[float]], norm: float
    ) -> NDArray[np.float64]:
        """The full step, else halved (up to 1/64) while ``max |R|`` does not fall."""
        t = 1.0
        for _ in range(7):
            trial = z + t * step
            C = self.forces(trial, w_prev, False)[0]
            if float(np.max(np.abs(trial - z_p + self.G @ C))) < norm:
                return trial
            t *= 0.5
        return z + step


@dataclass(frozen=True)
class MarchState:
    """The march's state at a wave period's start: the modal state (eta, eta', eta'') of the modes kept (3 r,), the
    corrections ``C`` (m + 2 P,) [N] and the sliders ``w`` (P, 2) [m]. Valid for another step with the same modes."""

    modal: NDArray[np.float64]
    correction_N: NDArray[np.float64]
    slider_m: NDArray[np.float64]


@dataclass
class _Period:
    """One wave period's samples at t_1 .. t_N (rolled to t_0 .. t_N-1 by :func:`_march_period`)."""

    z: NDArray[np.float64]
    w: NDArray[np.float64]
    slipped: NDArray[np.bool_]
    q: NDArray[np.float64]


def _march_period(
    stepper: CradleStepper, problem: _StepProblem, z_s: NDArray[np.float64], state: list, scale: float
) -> tuple[_Period, int]:
    """N steps from ``state`` = [x, C, w] (updated); the period's samples and the steps left unresolved."""
    x, C, w = state
    N = z_s.shape[0]
    dt = stepper.dt
    A, F = stepper.engagement_modes, stepper.flexibility
    assert stepper.output_modes is not None and stepper.output_residual is not None
    out = _Period(
        np.empty_like(z_s), np.empty((N, problem.P, 2)), np.zeros((N, problem.P), dtype=bool), np.empty((N, stepper.output_modes.shape[0]))
    )
    unresolved = 0
    for i in range(N):
        q_p = stepper.predictor @ x
        z_p = z_s[(i + 1) % N] + A @ q_p
        z, C, w, slipped, solved = problem.solve(z_p, C, w, scale)
        unresolved += not solved
        q = q_p - F @ C
        x = newmark_advance(x, q, dt)
        out.z[i], out.w[i], out.slipped[i] = z, w, slipped
        out.q[i] = stepper.output_modes @ q + stepper.output_residual @ C
    state[:] = [x, C, w]
    return _Period(
        np.roll(out.z, 1, axis=0), np.roll(out.w, 1, axis=0), np.roll(out.slipped, 1, axis=0), np.roll(out.q, 1, axis=0)
    ), unresolved


def march_cradle_friction(
    dynamics: CradleDynamics,
    friction: PadFriction,
    excitation: CradleExcitation,
    options: FrictionMarchOptions | None = None,
    *,
    rest: CradleExcitation | None = None,
    start: MarchState | None = None,
) -> tuple[FrictionalMarch, MarchState]:
    """March the frictional correction system from the stuck linear solution until it repeats (module docstring).

    Parameters
    ----------
    dynamics, friction, excitation
        The cargo on its cradles, the pads' friction, the loads and deck motion.
    options
        N, periods, tolerances, modal cutoff.
    rest
        Where the sliders are relaxed, as :func:`~seafast.solvers.cradle_friction.solve_cradle_friction_hbm`'s.
    start
        The state to start from (a march's :class:`MarchState` with the same modes kept); None: the stuck linear
        solution with the sliders at rest.

    Returns
    -------
    FrictionalMarch, MarchState
        The last period(s) and what the steady state is; the state at the end (the next period's start).
    """
    options = options if options is not None else FrictionMarchOptions()
    tangents = pad_tangents(dynamics.problem, friction, dynamics.deck_x_m, dynamics.gravity_m_per_s2)
    if rest is not None:
        tangents = relaxed_at(tangents, dynamics, rest)
    N, m, P = int(options.time_samples), dynamics.problem.element_stiffness_N_per_m.size, tangents.pad_count
    z_lin, X_stuck = stuck_linear_solution(dynamics, excitation, tangents)
    z_s = real_harmonics_to_time(z_lin, N)
    scale = max(float(np.max(np.abs(z_lin[1:]))), 1e-12)
    dt = 2.0 * np.pi / float(excitation.omega_rad_s) / N
    cutoff = STEPS_PER_MODE_PERIOD_INV * 2.0 * np.pi / dt if options.cutoff_rad_s is None else float(options.cutoff_rad_s)
    stepper = friction_stepper(dynamics, tangents, dt, cutoff)
    problem = _StepProblem(stepper, tangents, m, options.step_tolerance)
    r = stepper.flexibility.shape[0]
    if start is None:
        state: list = [np.zeros(3 * r), np.zeros(m + 2 * P), tangents.rest_m.tolist()]
    else:
        state = [np.array(start.modal, dtype=float), np.array(start.correction_N, dtype=float), np.asarray(start.slider_m).tolist()]
    kept: list[_Period] = []
    lags = np.full(max(SUBHARMONIC_ORDERS), np.nan)
    unresolved, periods = 0, 0
    while periods < int(options.max_periods):
        periods += 1
        period, missed = _march_period(stepper, problem, z_s, state, scale)
        unresolved += missed
        kept = [*kept[-max(SUBHARMONIC_ORDERS) :], period]
        lags = _lag_changes(kept, scale)
        if lags[0] <= options.tolerance:
            break
    multiple = 1 if lags[0] <= options.tolerance else next((L for L in SUBHARMONIC_ORDERS if lags[L - 1] <= options.tolerance), 0)
    last = kept[-max(multiple, 1) :]
    q = np.concatenate([p.q for p in last]) + np.tile(harmonics_to_time(X_stuck, N), (len(last), 1))
    march = _assembled(last, q, tangents, m, (multiple, periods, float(lags[max(multiple, 1) - 1]), unresolved))
    return march, MarchState(state[0], state[1], np.asarray(state[2], dtype=float))


def _assembled(
    last: list[_Period], q: NDArray[np.float64], tangents: PadTangents, m: int, verdict: tuple[int, int, float, int]
) -> FrictionalMarch:
    """The :class:`FrictionalMarch` of the periods ``last`` (the cargo's displacements ``q``); ``verdict`` = (period
    multiple, periods marched, period change, unresolved steps)."""
    multiple, periods, change, unresolved = verdict
    periodicity = (Periodicity.PERIODIC, Periodicity.SUBHARMONIC)[multiple > 1] if multiple else Periodicity.NOT_PERIODIC
    z, w = np.concatenate([p.z for p in last]), np.concatenate([p.w for p in last])
    delta = z[:, m:].reshape(-1, tangents.pad_count, 2)
    return FrictionalMarch(
        z[:, :m],
        delta,
        w,
        tangents.stiffness_N_per_m[None, :, None] * (delta - w),
        np.concatenate([p.slipped for p in last]),
        q,
        periodicity,
        multiple,
        periods,
        change,
        unresolved,
        tangents,
    )


def _lag_changes(kept: list[_Period], scale: float) -> NDArray[np.float64]:
    """The largest change of the engagements, motions and sliders over 1 .. 6 wave periods (NaN where fewer kept) [-]."""
    lags = np.full(max(SUBHARMONIC_ORDERS), np.nan)
    last = kept[-1]
    for lag in range(1, len(kept)):
        other = kept[-1 - lag]
        change = max(float(np.max(np.abs(last.z - other.z))), float(np.max(np.abs(last.w - other.w))))
        lags[lag - 1] = change / scale
    return lags
