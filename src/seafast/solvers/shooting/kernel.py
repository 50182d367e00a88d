"""The compiled period march of the shooting solver (numba): sample by sample, events refined, resumable.

:func:`march_events` marches the closed-form segments of :mod:`seafast.solvers.shooting.period` on the sample
grid and refines each event by safeguarded Newton iterations; it returns to its caller when the period ends, or
when it enters a contact state not built yet (the caller builds it and calls again: the march resumes where it
stopped), or after too many events. Compiled kernels are exempt from the house's function length (one loop each).

Guarded (stiff saddles): between two samples it steps on by the longest step over which no compression can reach
zero -- the positive root of ``g + g' h - a h^2 / 2``, ``a`` a bound on ``|g''|`` from the modes' amplitudes
(:func:`_point`, :func:`_safe_step`) -- so an impact shorter than a sample is found, and it finds each saddle's
largest compression where its rate turns from rising to falling (:func:`_track_peaks`).

Size: over 400 lines because the guard's compiled helpers share the march's private exponential and state layout;
apart, they would be a second module of the same loop's internals.
"""

from __future__ import annotations

import numba
import numpy as np
from numpy.typing import NDArray

__all__ = ["DONE", "TOO_MANY_EVENTS", "march_events"]

DONE = -1
"""The period was marched to its end."""

TOO_MANY_EVENTS = -2
"""More events than allowed."""

_SMALLEST_EXPONENT = -300.0


@numba.njit(cache=True)
def _exp(z: complex) -> complex:  # pragma: no cover - compiled
    re = z.real if z.real > _SMALLEST_EXPONENT else _SMALLEST_EXPONENT
    return np.exp(complex(re, z.imag))


@numba.njit(cache=True)
def _signed(  # pragma: no cover - compiled
    i: int,
    tau: float,
    t0: float,
    lam: NDArray,
    mc: NDArray,
    zz: NDArray,
    pc: NDArray,
    pd: NDArray,
    omega: float,
    lifted: NDArray,
    rate: bool,
) -> float:
    """Signed compression of saddle i at time tau (or its rate) in the current state (``pd``: its drift rate)."""
    acc = complex(pd[i] if rate else pd[i] * tau)
    for j in range(lam.size):
        e = _exp(lam[j] * (tau - t0)) * zz[j]
        acc += mc[i, j] * (e * lam[j] if rate else e)
    for k in range(pc.shape[0]):
        p = np.exp(1j * omega * k * tau) * pc[k, i]
        acc += p * (1j * omega * k) if rate else p
    return -acc.real if lifted[i] else acc.real


@numba.njit(cache=True)
def _point(  # pragma: no cover - compiled
    e: NDArray,
    lam: NDArray,
    mc: NDArray,
    pc: NDArray,
    pd: NDArray,
    t: float,
    phase_row: NDArray,
    omega: float,
    lifted: NDArray,
    out: NDArray,
) -> None:
    """Each saddle's signed compression, its rate and a bound on |its second derivative| from here on, into out (n_s, 3).

    ``e`` the homogeneous part's modal coordinates here, ``phase_row`` the harmonics' phases here (``t`` [s], for the
    drift ``pd t``). The bound holds for every later time of the segment: no mode grows (``Re lambda <= 0``), so
    ``|e_j|`` only decays, and the drift has no curvature.
    """
    for i in range(mc.shape[0]):
        g = complex(pd[i] * t)
        r = complex(pd[i])
        a = 0.0
        for j in range(lam.size):
            term = mc[i, j] * e[j]
            g += term
            r += term * lam[j]
            a += abs(term) * (lam[j].real ** 2 + lam[j].imag ** 2)
        for k in range(pc.shape[0]):
            p = phase_row[k] * pc[k, i]
            g += p
            r += p * (1j * omega * k)
            a += abs(pc[k, i]) * (omega * k) ** 2
        sign = -1.0 if lifted[i] else 1.0
        out[i, 0] = sign * g.real
        out[i, 1] = sign * r.real
        out[i, 2] = a


@numba.njit(cache=True)
def _safe_step(values: NDArray) -> float:  # pragma: no cover - compiled
    """The longest step over which no saddle's signed compression can reach zero (from :func:`_point`'s values).

    ``g(t + h) >= g + g' h - a h^2 / 2``: the positive root of that parabola, the smallest over the saddles.
    """
    h = np.inf
    for i in range(values.shape[0]):
        g = max(values[i, 0], 0.0)
        r, a = values[i, 1], values[i, 2]
        if a > 0.0:
            hi = (r + np.sqrt(r * r + 2.0 * a * g)) / a
        elif r < 0.0:
            hi = g / -r
        else:
            hi = np.inf
        h = min(h, hi)
    return h


@numba.njit(cache=True)
def _derivative(  # pragma: no cover - compiled
    i: int, tau: float, t0: float, lam: NDArray, mc: NDArray, zz: NDArray, pc: NDArray, pd: NDArray, omega: float, order: int
) -> float:
    """The ``order``-th time derivative (0, 1, 2) of saddle i's compression at time tau in the current state."""
    acc = complex(pd[i] * tau if order == 0 else (pd[i] if order == 1 else 0.0))
    for j in range(lam.size):
        acc += mc[i, j] * _exp(lam[j] * (tau - t0)) * zz[j] * lam[j] ** order
    for k in range(pc.shape[0]):
        acc += np.exp(1j * omega * k * tau) * pc[k, i] * (1j * omega * k) ** order
    return acc.real


@numba.njit(cache=True)
def _track_peaks(  # pragma: no cover - compiled
    lo: float,
    hi: float,
    rate_lo: NDArray,
    rate_hi: NDArray,
    t0: float,
    lam: NDArray,
    V: NDArray,
    mc: NDArray,
    zz: NDArray,
    pc: NDArray,
    ps: NDArray,
    pd: NDArray,
    xd: NDArray,
    omega: float,
    lifted: NDArray,
    code: int,
    tol: float,
    peak_value: NDArray,
    peak_time: NDArray,
    peak_state: NDArray,
    peak_code: NDArray,
) -> None:
    """A saddle in contact whose compression rate turns from rising to falling in ``[lo, hi]`` has a maximum there:
    found (safeguarded Newton on the rate) and kept if it is the saddle's largest so far, with the state there."""
    for i in range(mc.shape[0]):
        if lifted[i] or not (rate_lo[i] > 0.0 and rate_hi[i] <= 0.0):
            continue
        a, b = lo, hi
        tau = 0.5 * (a + b)
        for _ in range(100):
            r = _derivative(i, tau, t0, lam, mc, zz, pc, pd, omega, 1)
            if r > 0.0:
                a = tau
            else:
                b = tau
            c = _derivative(i, tau, t0, lam, mc, zz, pc, pd, omega, 2)
            newton = tau - r / c if c < 0.0 else np.inf
            if b - a <= tol:
                break
            tau = newton if a < newton < b else 0.5 * (a + b)
        value = _derivative(i, tau, t0, lam, mc, zz, pc, pd, omega, 0)
        if value > peak_value[i]:
            peak_value[i] = value
            peak_time[i] = tau
            peak_code[i] = code
            E = np.empty(lam.size, dtype=np.complex128)
            for j in range(lam.size):
                E[j] = _exp(lam[j] * (tau - t0)) * zz[j]
            xs = np.real(V @ E) + xd * tau
            for k in range(ps.shape[0]):
                ph = np.exp(1j * omega * k * tau)
                for j in range(xs.size):
                    xs[j] += (ph * ps[k, j]).real
            peak_state[i, :] = xs


@numba.njit(cache=True)
def march_events(  # pragma: no cover - compiled
    table: NDArray,
    lam_all: NDArray,
    V_all: NDArray,
    Vinv_all: NDArray,
    mc_all: NDArray,
    pc_all: NDArray,
    ps_all: NDArray,
    pd_all: NDArray,
    xd_all: NDArray,
    lifted_all: NDArray,
    omega: float,
    times: NDArray,
    phase: NDArray,
    tol: float,
    max_events: int,
    record: bool,
    track_monodromy: bool,
    carry_t: NDArray,
    carry_i: NDArray,
    x: NDArray,
    monodromy: NDArray,
    out_e: NDArray,
    out_code: NDArray,
    guard: bool,
    min_step: float,
    peak_value: NDArray,
    peak_time: NDArray,
    peak_state: NDArray,
    peak_code: NDArray,
) -> int:
    """March from the carried position to the period's end; see the module docstring.

    Carried (updated in place): ``carry_t[0]`` the time, ``carry_i = [next sample, state code, events, sub-steps]``,
    ``x`` the state, ``monodromy`` (when ``track_monodromy``). Recorded: ``out_e`` (N, 2m), the homogeneous part's
    modal coordinates at each sample (the state is ``Re(V e) + Re(phase ps) + xd t``, formed by the caller with one
    matrix product per contact state), and ``out_code`` (N,). ``pd_all``, ``xd_all``: each state's drift rates of
    the compressions and the state (zero but in a state with a rigid-body motion the constant load drives:
    :class:`~seafast.solvers.shooting.states.ContactState`). Returns :data:`DONE`, :data:`TOO_MANY_EVENTS`, or
    the code (bit i: saddle i lifted) of a state to build before calling again.

    ``guard``: between two samples, step on by the longest step over which no compression can reach zero
    (:func:`_safe_step`, at least ``min_step`` [s]), so that no event between samples is missed however short the
    impact; and keep each saddle's largest compression in continuous time (``peak_value`` [m], ``peak_time`` [s],
    ``peak_state`` the state there, ``peak_code`` its contact state; updated in place where larger).
    """
    N = times.shape[0] - 1
    size = x.size
    n_s = mc_all.shape[1]
    T = times[N]
    here = np.zeros((n_s, 3))
    there = np.zeros((n_s, 3))
    rate_lo = np.zeros(n_s)
    rate_hi = np.zeros(n_s)
    e_sub = np.empty(size, dtype=np.complex128)
    phase_sub = np.empty(phase.shape[1], dtype=np.complex128)
    while True:
        t = carry_t[0]
        n = carry_i[0]
        code = carry_i[1]
        s = table[code]
        lam = lam_all[s]
        V = V_all[s]
        Vinv = Vinv_all[s]
        mc = mc_all[s]
        pc = pc_all[s]
        ps = ps_all[s]
        pd = pd_all[s]
        xd = xd_all[s]
        lifted = lifted_all[s]
        # modal coordinates of the homogeneous part at t
        xp = xd * t
        for k in range(ps.shape[0]):
            ph = np.exp(1j * omega * k * t)
            for j in range(size):
                xp[j] += (ph * ps[k, j]).real
        zz = Vinv @ (x - xp).astype(np.complex128)
        event_sample = -1
        bracket_lo = t
        bracket_hi = t
        lo_t = t
        if guard:
            for k in range(phase_sub.size):
                phase_sub[k] = np.exp(1j * omega * k * t)
            _point(zz, lam, mc, pc, pd, t, phase_sub, omega, lifted, here)
            for i in range(n_s):
                rate_lo[i] = here[i, 1]
        e = np.empty(size, dtype=np.complex128)
        step = np.empty(size, dtype=np.complex128)
        if n <= N:
            for j in range(size):
                e[j] = _exp(lam[j] * (times[n] - t)) * zz[j]
                step[j] = _exp(lam[j] * (times[1] - times[0]))
        first = True
        while n <= N:
            if not first:
                for j in range(size):
                    e[j] *= step[j]
                    if abs(e[j].real) + abs(e[j].imag) < 1e-200:
                        e[j] = 0.0  # a decayed mode: never subnormal
            first = False
            if guard:
                # sub-steps no compression can cross zero within, up to the sample
                while True:
                    h = max(_safe_step(here), min_step)
                    tau = lo_t + h
                    if tau >= times[n]:
                        break
                    for j in range(size):
                        e_sub[j] = _exp(lam[j] * (tau - t)) * zz[j]
                    for k in range(phase_sub.size):
                        phase_sub[k] = np.exp(1j * omega * k * tau)
                    _point(e_sub, lam, mc, pc, pd, tau, phase_sub, omega, lifted, there)
                    carry_i[3] += 1
                    for i in range(n_s):
                        rate_hi[i] = there[i, 1]
                    crossed = False
                    if tau - t > tol * T:
                        for i in range(n_s):
                            if there[i, 0] < 0.0:
                                crossed = True
                    if crossed:
                        event_sample = n
                        bracket_lo, bracket_hi = lo_t, tau
                        break
                    _track_peaks(
                        lo_t, tau, rate_lo, rate_hi, t, lam, V, mc, zz, pc, ps, pd, xd, omega, lifted, code, tol * T,
                        peak_value, peak_time, peak_state, peak_code,
                    )  # fmt: skip
                    lo_t = tau
                    here[:, :] = there
                    rate_lo[:] = rate_hi
                if event_sample >= 0:
                    break
            if times[n] - t > tol * T:
                for i in range(n_s):
                    acc = complex(pd[i] * times[n])
                    for j in range(size):
                        acc += mc[i, j] * e[j]
                    for k in range(pc.shape[0]):
                        acc += phase[n, k] * pc[k, i]
                    g = -acc.real if lifted[i] else acc.real
                    if g < 0.0:
                        event_sample = n
                        bracket_lo = times[n - 1] if n > 0 else t
                        if bracket_lo < lo_t:
                            bracket_lo = lo_t
                        bracket_hi = times[n]
                        break
            if event_sample >= 0:
                break
            if guard:
                _point(e, lam, mc, pc, pd, times[n], phase[n], omega, lifted, there)
                for i in range(n_s):
                    rate_hi[i] = there[i, 1]
                if times[n] > lo_t:
                    _track_peaks(
                        lo_t, times[n], rate_lo, rate_hi, t, lam, V, mc, zz, pc, ps, pd, xd, omega, lifted, code, tol * T,
                        peak_value, peak_time, peak_state, peak_code,
                    )  # fmt: skip
                    lo_t = times[n]
                here[:, :] = there
                rate_lo[:] = rate_hi
            if record and n < N:
                for j in range(size):
                    out_e[n, j] = e[j]
            if n < N:
                out_code[n] = code
            n += 1
        if event_sample < 0:
            tau_end = T
        else:
            # the event: the earliest zero of any saddle that is negative at the bracket's end
            a = bracket_lo
            if a < t + tol * T:
                a = t + tol * T
            b = bracket_hi
            t_event = b
            flips = np.zeros(n_s, dtype=np.bool_)
            roots = np.full(n_s, np.inf)
            for i in range(n_s):
                if _signed(i, b, t, lam, mc, zz, pc, pd, omega, lifted, False) >= 0.0:
                    continue
                lo, hi = a, b
                f_lo = _signed(i, lo, t, lam, mc, zz, pc, pd, omega, lifted, False)
                if f_lo < 0.0:
                    roots[i] = lo
                    continue
                f_hi = _signed(i, hi, t, lam, mc, zz, pc, pd, omega, lifted, False)
                tau = lo - f_lo * (hi - lo) / (f_hi - f_lo)
                for _ in range(80):
                    f = _signed(i, tau, t, lam, mc, zz, pc, pd, omega, lifted, False)
                    r = _signed(i, tau, t, lam, mc, zz, pc, pd, omega, lifted, True)
                    if f >= 0.0:
                        lo = tau
                    else:
                        hi = tau
                    newton = tau - f / r if r != 0.0 else np.inf
                    if abs(newton - tau) <= tol * T:
                        tau = min(max(newton, lo), hi)
                        break
                    if hi - lo <= tol * T:
                        break
                    tau = newton if lo < newton < hi else 0.5 * (lo + hi)
                roots[i] = tau
            t_event = np.min(roots)
            for i in range(n_s):
                flips[i] = roots[i] <= t_event + tol * T
            tau_end = t_event
        if guard and tau_end > lo_t:
            # a maximum between the last point and the segment's end (an impact's peak before its lift-off)
            for i in range(n_s):
                rate_hi[i] = _derivative(i, tau_end, t, lam, mc, zz, pc, pd, omega, 1)
            _track_peaks(
                lo_t, tau_end, rate_lo, rate_hi, t, lam, V, mc, zz, pc, ps, pd, xd, omega, lifted, code, tol * T,
                peak_value, peak_time, peak_state, peak_code,
            )  # fmt: skip
        # the segment's propagator and the state at its end
        E = np.empty(size, dtype=np.complex128)
        for j in range(size):
            E[j] = _exp(lam[j] * (tau_end - t))
        if track_monodromy:
            P = np.ascontiguousarray(np.real((V * E) @ Vinv))
            monodromy[:, :] = P @ monodromy
        xe = np.real(V @ (E * zz)) + xd * tau_end
        for k in range(ps.shape[0]):
            ph = np.exp(1j * omega * k * tau_end)
            for j in range(size):
                xe[j] += (ph * ps[k, j]).real
        x[:] = xe
        carry_t[0] = tau_end
        if event_sample < 0:
            carry_i[0] = N + 1
            return -1
        carry_i[0] = event_sample
        new_code = code
        count = 0
        for i in range(n_s):
            if flips[i]:
                new_code ^= 1 << i
                count += 1
        carry_i[1] = new_code
        carry_i[2] += count
        if carry_i[2] > max_events:
            return -2
        if table[new_code] < 0:
            return new_code
