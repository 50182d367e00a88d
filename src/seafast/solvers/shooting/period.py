"""One period of the piecewise-linear correction system, from a state, with exact contact events.

Between events the state follows its contact state's closed form (:mod:`seafast.solvers.shooting.states`), in
the state's modal coordinates. The compiled march (:func:`~seafast.solvers.shooting.kernel.march_events`)
evaluates every saddle's compression sample by sample on the period's grid ``t_n = n T / N``; the first sample
where one has the wrong sign (a compressed saddle below zero, a lifted one above) brackets the event, and
safeguarded Newton iterations on the closed form find its time to :data:`EVENT_TIME_TOLERANCE` of the period.
The saddle changes state there and the march goes on. An event that starts and ends between two samples is
missed: the grid resolves the fastest mode the saddles drive (:func:`~seafast.solvers.shooting.solve.event_samples`).

Units: SI (m, rad, N, s).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from seafast.solvers.shooting.kernel import DONE, TOO_MANY_EVENTS, march_events
from seafast.solvers.shooting.states import ContactState, ContactStates, lifted_code, modal_exponential

__all__ = [
    "EVENT_TIME_TOLERANCE",
    "GUARD_MIN_STEP",
    "ContinuousPeaks",
    "PeriodFlow",
    "PeriodGrid",
    "TooManyEventsError",
    "flow_period",
    "initial_contact",
    "peak_compressions",
    "state_runs",
]

EVENT_TIME_TOLERANCE = 1e-12
"""Event times are found to this fraction of the period."""


GUARD_MIN_STEP = 1e-9
"""A guarded march's shortest sub-step, as a share of the period (an impact shorter than that could be missed)."""

PEAK_REACH = 0.05
"""Local maxima of a sampled compression this share of its range below the largest one are refined."""


class TooManyEventsError(RuntimeError):
    """More contact events in one period than allowed (a chattering contact)."""


@dataclass(frozen=True)
class PeriodFlow:
    """One period marched from a state.

    Attributes
    ----------
    end_state
        ``x(T) = [eta; eta']`` (2m,).
    monodromy
        ``d x(T) / d x(0)`` (2m, 2m): the product of each segment's ``e^{A_L tau}``; None when not formed.
    state_samples
        ``x(t_n)`` at the samples (N, 2m) when recorded, else None.
    state_codes
        The contact state at each sample (N,), bit i set when saddle i is lifted, when recorded, else None.
    events
        Contact events in the period (state changes of one saddle each).
    peaks
        Guarded marches only (else None): each saddle's largest compression in continuous time
        (:class:`ContinuousPeaks`).
    """

    end_state: NDArray[np.float64]
    monodromy: NDArray[np.float64] | None
    state_samples: NDArray[np.float64] | None
    state_codes: NDArray[np.int64] | None
    events: int
    peaks: ContinuousPeaks | None = None


@dataclass(frozen=True)
class ContinuousPeaks:
    """Each saddle's largest compression over a guarded period march, found in continuous time.

    Attributes
    ----------
    compression_m
        The largest compression of each saddle while in contact [m], (n_s,); ``-inf`` where none was found
        between the march's points (the samples then carry the peak).
    time_s
        When [s], (n_s,).
    state
        The state ``x = [eta; eta']`` there, (n_s, 2m).
    code
        The contact state there (bit i set when saddle i is lifted), (n_s,).
    sub_steps
        The sub-steps between samples the guard took in the period.
    """

    compression_m: NDArray[np.float64]
    time_s: NDArray[np.float64]
    state: NDArray[np.float64]
    code: NDArray[np.int64]
    sub_steps: int


class PeriodGrid:
    """The period's sample grid ``t_n = n T / N``, n = 0 .. N, and the excitation's phases on it."""

    def __init__(self, states: ContactStates, samples: int):
        self.omega_rad_s = states.omega_rad_s
        self.samples = int(samples)
        self.period_s = 2.0 * np.pi / states.omega_rad_s
        self.times = np.arange(self.samples + 1) * (self.period_s / self.samples)
        k = np.arange(states.harmonics.shape[0])
        self.phase = np.ascontiguousarray(np.exp(1j * states.omega_rad_s * np.outer(self.times, k)))  # (N+1, n_k)

    def particular_state(self, s: ContactState, t_s: float) -> NDArray[np.float64]:
        """The particular solution's state at one time, (1, 2m)."""
        k = np.arange(s.particular.shape[0])
        return (np.real(np.exp(1j * self.omega_rad_s * k * t_s) @ s.particular) + s.drift * t_s)[None, :]


def initial_contact(states: ContactStates, x: NDArray[np.float64], t_s: float) -> NDArray[np.bool_]:
    """The lifted set consistent with state ``x`` at time ``t_s``: an active-set iteration, enumeration as fallback."""
    d = states.forcing(np.array([t_s]))[0]
    n_s = d.size
    lifted = np.zeros(n_s, dtype=bool)
    for _ in range(2 * n_s + 2):
        s = states.get(lifted)
        proposed = (s.compression_state @ x + s.compression_forcing @ d) < 0.0
        if np.array_equal(proposed, lifted):
            return lifted
        lifted = proposed
    for code in range(2**n_s):
        trial = np.array([(code >> i) & 1 == 1 for i in range(n_s)])
        s = states.get(trial)
        if np.array_equal((s.compression_state @ x + s.compression_forcing @ d) < 0.0, trial):
            return trial
    return lifted


def flow_period(
    states: ContactStates,
    x0: NDArray[np.float64],
    grid: PeriodGrid,
    *,
    record: bool = False,
    monodromy: bool = True,
    max_events: int = 100_000,
    guard: bool = False,
) -> PeriodFlow:
    """March one period ``[0, T]`` from ``x(0) = x0`` with exact events (see the module docstring).

    ``record``: keep the state and the contact state at every sample (the period a solve reports).
    ``monodromy``: form the monodromy matrix (two (2m)^3 products an event); False for a period that only leads to
    the next one (the flow's ``monodromy`` is then None).
    ``guard``: between samples, step on by steps over which no compression can reach zero (bounded by its rate and
    curvature), so that an impact shorter than a sample is not missed, and find each saddle's largest compression in
    continuous time (the flow's ``peaks``; :data:`GUARD_MIN_STEP` of the period at least a step).

    Raises
    ------
    TooManyEventsError
        After ``max_events`` events in the period.
    """
    N, size = grid.samples, states.state_size
    carry_t = np.zeros(1)
    carry_i = np.array([0, lifted_code(initial_contact(states, x0, 0.0)), 0, 0], dtype=np.int64)
    x = np.array(x0, dtype=float)
    jacobian = np.eye(size)
    out_e = np.zeros((N, size) if record else (1, size), dtype=np.complex128)
    out_code = np.zeros(N, dtype=np.int64)
    n_s = states.system.saddle_count
    peak_value, peak_time = np.full(n_s, -np.inf), np.zeros(n_s)
    peak_state, peak_code = np.zeros((n_s, size)), np.zeros(n_s, dtype=np.int64)
    while True:
        arrays = states.arrays
        status = march_events(
            arrays.table, arrays.eigenvalues, arrays.eigenvectors, arrays.inverse_eigenvectors, arrays.modal_compression,
            arrays.particular_compression, arrays.particular, arrays.drift_compression, arrays.drift, arrays.lifted,
            states.omega_rad_s, grid.times, grid.phase,
            EVENT_TIME_TOLERANCE, int(max_events), bool(record), bool(monodromy), carry_t, carry_i, x, jacobian, out_e, out_code,
            bool(guard), GUARD_MIN_STEP * grid.period_s, peak_value, peak_time, peak_state, peak_code,
        )  # fmt: skip
        if status == DONE:
            kept = jacobian if monodromy else None
            peaks = ContinuousPeaks(peak_value, peak_time, peak_state, peak_code, int(carry_i[3])) if guard else None
            if not record:
                return PeriodFlow(x, kept, None, None, int(carry_i[2]), peaks)
            return PeriodFlow(x, kept, _recorded_states(states, grid, out_e, out_code), out_code, int(carry_i[2]), peaks)
        if status == TOO_MANY_EVENTS:
            raise TooManyEventsError(f"more than {max_events} contact events in one period")
        states.get(states.lifted_of(int(status)))  # a new contact state: build it, then resume


def _recorded_states(states: ContactStates, grid: PeriodGrid, modal: NDArray[np.complex128], codes: NDArray[np.int64]) -> NDArray:
    """The states ``x(t_n) = Re(V e_n) + Re(phase_n ps) + xd t_n`` (N, 2m) from the march's modal coordinates ``e_n``
    (N, 2m).

    A real matrix product per run of samples in one contact state, on the interleaved real and imaginary parts
    (``Re(V e) = [Re e, Im e] [Re V; -Im V]^T``): forming each sample in the compiled loop cost (2m)^2 scalar
    products a sample, twice the march itself.
    """
    arrays, n = states.arrays, codes.size
    out = np.empty(modal.shape, dtype=float)
    modal_parts, phase_parts = modal.view(np.float64), grid.phase[:n].view(np.float64)
    maps: dict[int, tuple[NDArray, NDArray]] = {}
    for code, a, b in state_runs(codes):
        if code not in maps:
            s = arrays.table[code]
            maps[code] = (_real_part_map(arrays.eigenvectors[s].T), _real_part_map(arrays.particular[s]))
        modal_map, particular_map = maps[code]
        out[a:b] = modal_parts[a:b] @ modal_map + phase_parts[a:b] @ particular_map
        drift = arrays.drift[arrays.table[code]]
        if np.any(drift):  # a mechanism's state: the drift of the constant load along it
            out[a:b] += grid.times[a:b, None] * drift[None, :]
    return out


def state_runs(codes: NDArray[np.int64]) -> list[tuple[int, int, int]]:
    """The runs of samples in one contact state: ``(code, first, end)``, samples ``first .. end - 1`` (slices, not masks)."""
    starts = np.flatnonzero(np.diff(codes, prepend=codes[0] - 1)) if codes.size else np.zeros(0, dtype=np.int64)
    ends = [*starts[1:].tolist(), int(codes.size)]
    return [(int(codes[a]), int(a), int(b)) for a, b in zip(starts.tolist(), ends, strict=True)]


def _real_part_map(matrix: NDArray[np.complex128]) -> NDArray[np.float64]:
    """``W`` (2p, q) with ``Re(z @ matrix) = z.view(float) @ W`` for complex rows ``z`` (p,) and ``matrix`` (p, q)."""
    W = np.empty((2 * matrix.shape[0], matrix.shape[1]))
    W[0::2], W[1::2] = matrix.real, -matrix.imag
    return W


def peak_compressions(
    states: ContactStates, grid: PeriodGrid, flow: PeriodFlow, compression_m: NDArray, points: int = 33, candidates: int = 8
) -> NDArray:
    """Each saddle's largest compression in continuous time, from the closed form between samples (n_s,) [m].

    Around each of the (at most ``candidates``) highest local maxima of a saddle's sampled compression within
    :data:`PEAK_REACH` of its range below the largest sample whose parabola through the neighbours could, with three
    times its rise, pass the largest sample (only those can hide a higher peak), ``delta(t)`` is
    evaluated at ``points`` times over ``[t_{n-1}, t_{n+1}]`` in the contact state of sample n (a neighbour in another
    state bounds the interval at ``t_n``: no event inside the interval evaluated), forward from its first sample
    (backwards, a damped mode grows without bound). Compared with the largest sample it says how much of a peak the
    grid misses.
    """
    assert flow.state_samples is not None and flow.state_codes is not None
    N, dt = grid.samples, grid.times[1]
    peaks = np.max(compression_m, axis=0)
    codes = flow.state_codes
    for i in range(compression_m.shape[1]):
        c = compression_m[:, i]
        reach = peaks[i] - PEAK_REACH * (peaks[i] - float(np.min(c)))
        local = np.nonzero((c >= np.roll(c, 1)) & (c >= np.roll(c, -1)) & (c > 0.0) & (c >= reach))[0]
        # a parabola through each maximum and its neighbours estimates what lies between the samples: refine only
        # those that could, with three times that margin, pass the largest sample
        left, right = c[(local - 1) % N], c[(local + 1) % N]
        curvature = np.maximum(2.0 * c[local] - left - right, 1e-300)
        rise = (right - left) ** 2 / (8.0 * curvature)
        local = local[c[local] + 3.0 * rise >= peaks[i]]
        for n in local[np.argsort(c[local])[::-1][:candidates]]:
            first = n - 1 if n > 0 and codes[n - 1] == codes[n] else n
            last = n + 1 if n + 1 < N and codes[n + 1] == codes[n] else n
            if first == last:
                continue
            s = states.get(states.lifted_of(int(codes[n])))
            t_0 = grid.times[first]
            z = s.inverse_eigenvectors @ (flow.state_samples[first] - grid.particular_state(s, t_0)[0])
            tau = np.linspace(0.0, (last - first) * dt, points)
            homogeneous = np.real((modal_exponential(np.outer(tau, s.eigenvalues)) * z[None, :]) @ s.modal_compression[i])
            k = np.arange(s.particular_compression.shape[0])
            particular = np.real(np.exp(1j * states.omega_rad_s * np.outer(t_0 + tau, k)) @ s.particular_compression[:, i])
            particular += s.drift_compression[i] * (t_0 + tau)
            peaks[i] = max(peaks[i], float(np.max(homogeneous + particular)))
    return peaks
