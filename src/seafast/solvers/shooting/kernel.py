"""The compiled period march of the shooting solver (numba): sample by sample, events refined, resumable.

:func:`march_events` marches the closed-form segments of :mod:`seafast.solvers.shooting.period` on the sample
grid and refines each event by safeguarded Newton iterations; it returns to its caller when the period ends, or
when it enters a contact state not built yet (the caller builds it and calls again: the march resumes where it
stopped), or after too many events. Compiled kernels are exempt from the house's function length (one loop each).
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
    i: int, tau: float, t0: float, lam: NDArray, mc: NDArray, zz: NDArray, pc: NDArray, omega: float, lifted: NDArray, rate: bool
) -> float:
    """Signed compression of saddle i at time tau (or its rate) in the current state."""
    acc = 0.0 + 0.0j
    for j in range(lam.size):
        e = _exp(lam[j] * (tau - t0)) * zz[j]
        acc += mc[i, j] * (e * lam[j] if rate else e)
    for k in range(pc.shape[0]):
        p = np.exp(1j * omega * k * tau) * pc[k, i]
        acc += p * (1j * omega * k) if rate else p
    return -acc.real if lifted[i] else acc.real


@numba.njit(cache=True)
def march_events(  # pragma: no cover - compiled
    table: NDArray,
    lam_all: NDArray,
    V_all: NDArray,
    Vinv_all: NDArray,
    mc_all: NDArray,
    pc_all: NDArray,
    ps_all: NDArray,
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
) -> int:
    """March from the carried position to the period's end; see the module docstring.

    Carried (updated in place): ``carry_t[0]`` the time, ``carry_i = [next sample, state code, events]``, ``x``
    the state, ``monodromy`` (when ``track_monodromy``). Recorded: ``out_e`` (N, 2m), the homogeneous part's
    modal coordinates at each sample (the state is ``Re(V e) + Re(phase ps)``, formed by the caller with one
    matrix product per contact state), and ``out_code`` (N,). Returns :data:`DONE`, :data:`TOO_MANY_EVENTS`, or
    the code (bit i: saddle i lifted) of a state to build before calling again.
    """
    N = times.shape[0] - 1
    size = x.size
    n_s = mc_all.shape[1]
    T = times[N]
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
        lifted = lifted_all[s]
        # modal coordinates of the homogeneous part at t
        xp = np.zeros(size)
        for k in range(ps.shape[0]):
            ph = np.exp(1j * omega * k * t)
            for j in range(size):
                xp[j] += (ph * ps[k, j]).real
        zz = Vinv @ (x - xp).astype(np.complex128)
        event_sample = -1
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
            if times[n] - t > tol * T:
                for i in range(n_s):
                    acc = 0.0 + 0.0j
                    for j in range(size):
                        acc += mc[i, j] * e[j]
                    for k in range(pc.shape[0]):
                        acc += phase[n, k] * pc[k, i]
                    g = -acc.real if lifted[i] else acc.real
                    if g < 0.0:
                        event_sample = n
                        break
            if event_sample >= 0:
                break
            if record and n < N:
                for j in range(size):
                    out_e[n, j] = e[j]
            if n < N:
                out_code[n] = code
            n += 1
        if event_sample < 0:
            tau_end = T
        else:
            # the event: the earliest zero of any saddle that is negative at the sample
            a = times[event_sample - 1] if event_sample > 0 else t
            if a < t + tol * T:
                a = t + tol * T
            b = times[event_sample]
            t_event = b
            flips = np.zeros(n_s, dtype=np.bool_)
            roots = np.full(n_s, np.inf)
            for i in range(n_s):
                if _signed(i, b, t, lam, mc, zz, pc, omega, lifted, False) >= 0.0:
                    continue
                lo, hi = a, b
                f_lo = _signed(i, lo, t, lam, mc, zz, pc, omega, lifted, False)
                if f_lo < 0.0:
                    roots[i] = lo
                    continue
                f_hi = _signed(i, hi, t, lam, mc, zz, pc, omega, lifted, False)
                tau = lo - f_lo * (hi - lo) / (f_hi - f_lo)
                for _ in range(80):
                    f = _signed(i, tau, t, lam, mc, zz, pc, omega, lifted, False)
                    r = _signed(i, tau, t, lam, mc, zz, pc, omega, lifted, True)
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
        # the segment's propagator and the state at its end
        E = np.empty(size, dtype=np.complex128)
        for j in range(size):
            E[j] = _exp(lam[j] * (tau_end - t))
        if track_monodromy:
            P = np.ascontiguousarray(np.real((V * E) @ Vinv))
            monodromy[:, :] = P @ monodromy
        xe = np.real(V @ (E * zz))
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
