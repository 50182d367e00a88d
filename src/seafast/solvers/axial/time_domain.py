"""Time-domain reference of the axial stick-slip: rigid Coulomb friction, event-driven (docs/axial.md).

No tangential stiffness: the cargo either sticks (``u`` constant, the friction carries
``F(t) - r(u)``, ``r`` the lashings and stoppers) or slides with
``m u'' = F(t) - r(u) - c u' - sign(u') C(t)``. Sliding phases are integrated with the classical
Runge-Kutta scheme on a fine grid aligned with the samples of ``C(t)`` (so its kinks fall on
step ends and the scheme keeps its 4th order); the event ``u' = 0`` is located inside its step
on the cubic Hermite interpolant of the velocity, and there the cargo sticks if
``|F - r(u)| <= C`` and reverses otherwise. A stuck cargo breaks loose at the first instant
``|F(t) - r(u)| > C(t)``, located by Brent's method. Periods are integrated from the as-placed
state (``u = u' = 0``, stuck) until the state at the period's start repeats and the distance
still to go, extrapolated from the last two periods' changes (:func:`remaining_distance`), is
within the tolerance too: a walk into shakedown converges like ``1/n``, and its last step is far
smaller than the distance left. While the cargo walks, the start position is extrapolated to its
limit: Aitken's delta-squared every three periods when the walk is geometric, the edge of the
lock range (:func:`~seafast.solvers.axial.response.lock_range_m`) when it heads there at the
rate of the ``1/n`` law (:class:`_Walk`): a shorter path, the same periodic state. The estimated
distance left is reported (``residual_drift_m``). A cargo that nothing restrains walks for ever:
the message gives its drift per period. ``C(t)`` is the linear interpolation of the vertical solution's samples, as
in the harmonic balance.

Independent of the harmonic balance (no harmonics, no AFT, no Jenkins spring): the reference the
HBM is checked against, and the limit the Jenkins element converges to as its stiffness grows.
Checked itself against Den Hartog's closed form (tests).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray
from scipy.optimize import brentq

from seafast.excitation.axial import AxialLoad
from seafast.model.axial import AxialRestraint
from seafast.solvers.axial.response import AxialResponse, lock_range_m

__all__ = ["remaining_distance", "solve_axial_time_domain"]


class _System:
    """Plain-float evaluation of the load, capacity and restoring force (called ~10^5 times)."""

    def __init__(self, restraint: AxialRestraint, load: AxialLoad, normal: NDArray):
        self.w = float(load.omega_rad_s)
        self.T = 2.0 * math.pi / self.w
        f = np.asarray(load.force_N, dtype=complex)
        self.f0 = float(f[0].real)
        self.terms = [(k * self.w, float(c.real), float(-c.imag)) for k, c in enumerate(f[1:], start=1) if c != 0]
        cap = restraint.capacity_N(normal)
        self.n = int(cap.size)
        self.cap = [float(v) for v in cap] + [float(cap[0])]
        self.m = float(restraint.cargo_mass_kg)
        self.c = float(restraint.damping_N_s_per_m)
        self.ka = float(restraint.lashing_axial_stiffness_N_per_m)
        self.gap = None if restraint.stopper_gap_m is None else float(restraint.stopper_gap_m)
        self.ks = float(restraint.stopper_stiffness_N_per_m)

    def force(self, t: float) -> float:
        out = self.f0
        for kw, a, b in self.terms:
            out += a * math.cos(kw * t) + b * math.sin(kw * t)
        return out

    def capacity(self, t: float) -> float:
        x = (t % self.T) / self.T * self.n
        i = min(int(x), self.n - 1)
        return self.cap[i] + (x - i) * (self.cap[i + 1] - self.cap[i])

    def restoring(self, u: float) -> float:
        out = self.ka * u
        if self.gap is not None:
            if u > self.gap:
                out += self.ks * (u - self.gap)
            elif u < -self.gap:
                out += self.ks * (u + self.gap)
        return out

    def accel(self, t: float, u: float, v: float, sign: int) -> float:
        return (self.force(t) - self.restoring(u) - self.c * v - sign * self.capacity(t)) / self.m

    def rk4(self, t: float, u: float, v: float, h: float, sign: int) -> tuple[float, float, float]:
        """One RK4 step; returns (u, v, a at the start)."""
        a1 = self.accel(t, u, v, sign)
        u2, v2 = u + 0.5 * h * v, v + 0.5 * h * a1
        a2 = self.accel(t + 0.5 * h, u2, v2, sign)
        u3, v3 = u + 0.5 * h * v2, v + 0.5 * h * a2
        a3 = self.accel(t + 0.5 * h, u3, v3, sign)
        u4, v4 = u + h * v3, v + h * a3
        a4 = self.accel(t + h, u4, v4, sign)
        return u + h * (v + 2 * v2 + 2 * v3 + v4) / 6.0, v + h * (a1 + 2 * a2 + 2 * a3 + a4) / 6.0, a1

    def demand(self, t: float, u: float) -> float:
        """Friction needed to hold the cargo at ``u`` (forward push of the load minus restraints)."""
        return self.force(t) - self.restoring(u)


def _hermite(y0: float, d0: float, y1: float, d1: float, h: float, s: float) -> float:
    """Cubic Hermite interpolant on [0, h] at s."""
    x = s / h
    h00, h10, h01, h11 = 2 * x**3 - 3 * x**2 + 1, x**3 - 2 * x**2 + x, -2 * x**3 + 3 * x**2, x**3 - x**2
    return h00 * y0 + h10 * h * d0 + h01 * y1 + h11 * h * d1


def _advance(sys_: _System, t: float, h: float, state: list) -> float:
    """Advance ``state = [sign, u, v]`` from ``t`` over at most ``h``; returns the time reached (an event or t + h)."""
    sign, u, v = state
    if sign == 0:
        if abs(sys_.demand(t + h, u)) <= sys_.capacity(t + h):
            return t + h

        def excess(tt: float) -> float:  # demand beyond the friction capacity: > 0 once it slides
            return abs(sys_.demand(tt, u)) - sys_.capacity(tt)

        t_go = brentq(excess, t, t + h, xtol=1e-14 * sys_.T) if excess(t) < 0 else t
        state[0] = 1 if sys_.demand(t_go, u) > 0 else -1
        state[2] = 0.0
        return t_go
    u1, v1, a0 = sys_.rk4(t, u, v, h, sign)
    if sign * v1 > 0:
        state[1], state[2] = u1, v1
        return t + h
    # velocity back to zero inside the step: locate it on the Hermite interpolant of v
    a1 = sys_.accel(t + h, u1, v1, sign)
    lo, hi = 0.0, h
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if sign * _hermite(v, a0, v1, a1, h, mid) > 0:
            lo = mid
        else:
            hi = mid
    s = 0.5 * (lo + hi)
    if s <= 1e-12 * h:  # already at rest at the step's start
        s = 0.0
    ue = _hermite(u, v, u1, v1, h, s)
    te = t + s
    need = sys_.demand(te, ue)
    state[0] = 0 if abs(need) <= sys_.capacity(te) else (1 if need > 0 else -1)
    state[1], state[2] = ue, 0.0
    return te if s > 0 else t + min(h, 1e-9 * sys_.T)


def _aitken(x: list[float]) -> float | None:
    """Aitken's limit of three terms of a geometrically converging sequence (None if it is not one)."""
    d1, d2 = x[1] - x[0], x[2] - x[1]
    if d1 == 0.0 or d2 == 0.0 or d1 * d2 < 0.0:
        return None
    ratio = d2 / d1
    if not 0.0 < ratio < 1.0 - 1e-9:
        return None
    return x[2] + d2 * ratio / (1.0 - ratio)


def remaining_distance(changes: list[float]) -> float:
    """Estimated distance to the limit of a converging sequence from its last two steps (same units).

    With ``rho`` the ratio of the last step to the one before, the remaining distance is
    ``c rho / (1 - rho)`` for a geometric sequence and ``c (q + 1) / (q (1 - rho))`` for an
    algebraic one whose distance decays like ``n^-q`` (``c`` the last step); ``2 c / (1 - rho)``
    bounds both for ``q >= 1``, the walk into a shakedown state (``1/n``, docs/axial.md) included.
    ``inf`` when the steps do not decrease (or fewer than two are known), 0 after a zero step.
    """
    if changes and changes[-1] == 0.0:
        return 0.0
    if len(changes) < 2 or changes[-2] <= 0.0:
        return math.inf
    rho = changes[-1] / changes[-2]
    return 2.0 * changes[-1] / (1.0 - rho) if rho < 1.0 else math.inf


class _Walk:
    """The period-start states of a cargo settling towards its periodic state, and the jumps to its limit.

    A cargo that starts its periods stuck and walks approaches its limit either geometrically
    (Aitken's extrapolation finds it) or, when it walks into the edge of the range of positions
    where it can stay locked (shakedown, :func:`~seafast.solvers.axial.response.lock_range_m`),
    like ``1/n``: every period's slip shrinks with the square of the distance left. That limit
    is the edge itself, a static quantity: once the walk is seen heading there at the rate of
    that law, the start jumps to it.
    """

    def __init__(self, lock: tuple[float, float] | None, u_scale: float):
        self.lock = lock
        self.u_scale = u_scale
        self.starts: list[float] = []  # start positions of periods that start stuck, since the last jump
        self.changes: list[float] = []  # period-to-period changes (of the scales), since the last jump
        self.jumps: list[str] = []

    def reset(self) -> None:
        self.starts.clear()
        self.changes.clear()

    def edge_jump(self) -> float | None:
        """The lock range's edge when the last stuck starts walk into it at the rate of the ``1/n`` law."""
        if self.lock is None or len(self.starts) < 3:
            return None
        x0, x1, x2 = self.starts[-3:]
        lo, hi = self.lock
        edge = hi if x2 > hi else (lo if x2 < lo else None)
        d1, d2 = x1 - x0, x2 - x1
        if edge is None or d1 == 0.0 or d2 * d1 <= 0.0 or (edge - x2) * d2 <= 0.0:
            return None  # inside the range (it stays), or not walking towards the edge
        rho = d2 / d1
        if not 0.25 <= rho < 1.0:
            return None  # not yet in the asymptotic walk (a large slip could still overshoot the edge)
        # distance left by the 1/n law (slip ~ distance^2): d = |d2| sqrt(rho) / (1 - sqrt(rho))
        predicted = abs(d2) * math.sqrt(rho) / (1.0 - math.sqrt(rho))
        return edge if 0.25 <= predicted / abs(edge - x2) <= 4.0 else None

    def next_start(self, s: _System, t0: float, u: float) -> float | None:
        """The jumped start position for a period starting stuck at ``u`` (None: no jump)."""
        self.starts.append(u)
        edge = self.edge_jump()
        if edge is not None:
            self.jumps.append("edge of the lock range (shakedown)")
            return edge
        if len(self.starts) >= 3:
            jump = _aitken(self.starts[-3:])
            if jump is not None and self.lock is not None:  # a walk from outside the lock range ends at its near edge
                lo, hi = self.lock
                jump = hi if u > hi > jump else (lo if u < lo < jump else jump)
            if jump is not None and abs(s.demand(t0, jump)) <= s.capacity(t0):
                self.jumps.append("Aitken")
                return jump  # the walk converges geometrically: jump to its limit
        return None


def _period(s: _System, state: list, t0: float, h: float, steps: int, record_every: int, rec: NDArray) -> float:
    """Integrate one period from ``t0`` (``state`` updated in place, samples into ``rec``); returns the slip [m]."""
    slip = 0.0
    for j in range(steps):
        if j % record_every == 0:
            rec[j // record_every] = state
        t, t_end = t0 + j * h, t0 + (j + 1) * h
        while t < t_end - 1e-12 * h:
            u_before = state[1]
            moving = state[0] != 0
            t = _advance(s, t, t_end - t, state)
            if moving:
                slip += abs(state[1] - u_before)
    return slip


def _lock_range(s: _System, restraint: AxialRestraint, steps: int) -> tuple[float, float] | None:
    """:func:`lock_range_m` on the integration grid (the kinks of ``C(t)`` are on it)."""
    t = np.arange(steps) * s.T / steps
    return lock_range_m(restraint, np.array([s.force(x) for x in t]), np.array([s.capacity(x) for x in t]))


def solve_axial_time_domain(
    restraint: AxialRestraint,
    load: AxialLoad,
    normal_force_N: NDArray[np.float64],
    *,
    time_samples: int = 512,
    steps_per_sample: int = 8,
    max_periods: int = 400,
    tolerance: float = 1e-7,
) -> AxialResponse:
    """Steady periodic axial response by event-driven rigid-Coulomb integration.

    Parameters
    ----------
    restraint, load, normal_force_N
        As :func:`~seafast.solvers.axial.solve_axial_hbm` (``normal_force_N`` shape (N_v, n_s)).
    time_samples
        Samples of the returned period (a multiple or a divisor of N_v).
    steps_per_sample
        RK4 steps per interval of the finer of the two sample grids.
    max_periods
        Periods integrated at most before giving up (``converged=False``).
    tolerance
        The period closes when the start state repeats within ``tolerance`` times the
        displacement scale ``max|F| / (m w^2)`` (and the velocity scale ``max|F| / (m w)``)
        and the distance still to go, extrapolated from the last two periods' changes
        (:func:`remaining_distance`: valid for the geometric and the ``1/n`` walk), is within
        ``tolerance`` of the scales too. ``residual_drift_m`` reports that distance.
    """
    normal = np.asarray(normal_force_N, dtype=float).reshape(np.shape(normal_force_N)[0], -1)
    s = _System(restraint, load, normal)
    n_v = normal.shape[0]
    grid = max(n_v, time_samples)
    if grid % n_v or grid % time_samples:
        raise ValueError(f"time_samples = {time_samples} and the {n_v} normal-force samples must divide one another")
    steps = grid * steps_per_sample
    h = s.T / steps
    f_max = max(abs(s.force(i * s.T / 256)) for i in range(256)) or 1.0
    u_scale, v_scale = f_max / (s.m * s.w**2), f_max / (s.m * s.w)
    state: list = [0, 0.0, 0.0]
    converged, change, remaining, periods = False, math.inf, math.inf, 0
    rec = np.zeros((time_samples, 3))
    slip = 0.0
    walk = _Walk(_lock_range(s, restraint, steps), u_scale)
    start: tuple = tuple(state)
    for periods in range(1, max_periods + 1):
        t0 = (periods - 1) * s.T
        jump = walk.next_start(s, t0, state[1]) if state[0] == 0 else None
        if state[0] != 0:
            walk.starts.clear()
        if jump is not None:
            state[1] = jump
            walk.reset()
        start = tuple(state)
        slip = _period(s, state, t0, h, steps, steps // time_samples, rec)
        change = max(abs(state[1] - start[1]) / u_scale, abs(state[2] - start[2]) / v_scale)
        walk.changes.append(change)
        remaining = remaining_distance(walk.changes)
        settled = change <= 1e-3 * tolerance or remaining <= tolerance  # round-off, or the walk's rest is within tolerance
        if change <= tolerance and settled and (state[0] == start[0] or (state[0] != 0 and start[0] != 0)):
            converged = True
            break
    return _response(s, restraint, rec, state, start, periods, steps, converged, change, remaining, slip, walk, tolerance, max_periods)


def _response(
    s: _System,
    restraint: AxialRestraint,
    rec: NDArray,
    state: list,
    start: tuple,
    periods: int,
    steps: int,
    converged: bool,
    change: float,
    remaining: float,
    slip: float,
    walk: _Walk,
    tolerance: float,
    max_periods: int,
) -> AxialResponse:
    """The last period as an :class:`AxialResponse`, with the message saying how it ended."""
    time_samples = rec.shape[0]
    t_out = (periods - 1) * s.T + np.arange(time_samples) * s.T / time_samples
    sign, u, v = rec[:, 0].astype(int), rec[:, 1].copy(), rec[:, 2].copy()
    load_t = np.array([s.force(t) for t in t_out])
    cap = np.array([s.capacity(t) for t in t_out])
    lashing, stop = restraint.restoring_force_N(u)
    friction = np.where(sign == 0, lashing + stop - load_t, -sign * cap)
    drift_m = state[1] - start[1]
    if math.isfinite(remaining):
        residual_m = remaining * walk.u_scale
        where = f"estimated {residual_m:.3g} m from the periodic state"
    else:  # the changes do not decrease: at round-off (converged) or not settling; the last change is all there is
        residual_m = change * walk.u_scale
        where = "the changes no longer decrease" if converged else "the changes do not decrease"
    msg = (
        f"axial time domain (rigid Coulomb, event-driven RK4, {steps} steps per period): "
        f"{'periodic' if converged else 'NOT periodic'} after {periods} periods, last change {change:.2e} "
        f"of the displacement scale {walk.u_scale:.3g} m (drift {drift_m:+.3g} m in the last period, {where})"
    )
    if walk.jumps:
        msg += f"; start extrapolated to the walk's limit {len(walk.jumps)} time(s) (last: {walk.jumps[-1]})"
    walks = not converged and abs(state[2] - start[2]) <= tolerance * s.w * walk.u_scale
    if walks:
        msg += f"; the cargo moves {drift_m:+.4g} m per period (walks)"
    return AxialResponse(
        "time_domain",
        s.w,
        u,
        v,
        friction,
        cap,
        -lashing,
        -stop,
        load_t,
        sign != 0,
        slip,
        converged,
        float(change),
        periods,
        msg,
        None,
        {"time_samples": time_samples, "steps_per_period": steps, "max_periods": max_periods, "tolerance": tolerance},
        residual_drift_m=float(residual_m),
        walk_m_per_period=float(drift_m) if walks else None,
    )
