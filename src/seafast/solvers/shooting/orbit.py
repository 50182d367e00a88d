"""The periodic orbit of a piecewise-linear correction system by exact-event shooting, whatever the structure.

:func:`shoot_orbit` finds the state ``x0`` one period maps onto itself (:mod:`seafast.solvers.shooting.solve`'s
Newton on the monodromy matrix, started by marching from the linear solution), refines the event grid until the
sampled peaks are the continuous ones, and says how it ended (:class:`Orbit`). It knows only the
:class:`~seafast.solvers.shooting.states.ContactStates` of a reduced correction system: the vertical plane's saddles
(:func:`~seafast.solvers.shooting.solve_shooting`) and the 3-D cargo's engagements
(:mod:`seafast.solvers.cradle_shooting`) call it alike, the rows of ``saddle_mode_shape`` being their contacts.

Units: SI (m, rad, N, s). Nothing here prints, reads or writes files.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from seafast.solvers.hbm.harmonics import force_scale_N
from seafast.solvers.modal_correction import CorrectionBasis
from seafast.solvers.shooting.options import ShootingOptions
from seafast.solvers.shooting.period import PeriodFlow, PeriodGrid, flow_period, peak_compressions, state_runs
from seafast.solvers.shooting.states import ContactStates

__all__ = [
    "ROUND_OFF_FACTOR",
    "STABILITY_MARGIN",
    "Orbit",
    "attainable",
    "guarded",
    "measured_floor",
    "missed_peak",
    "period_residual",
    "periodic_state",
    "sampled_contact",
    "shoot_orbit",
    "state_change",
    "with_peaks",
]

STABILITY_MARGIN = 1e-6
"""A Floquet multiplier above 1 + this: an unstable orbit."""

ROUND_OFF_FACTOR = 1e4
"""How many times the double precision of the state's own size a period's march repeats a periodic state to
(the eigenvector bases of the contact states, their conditioning and the events' times: :func:`attainable`)."""

NOISE_FACTOR = 10.0
"""A Newton that stalls above :func:`attainable` is converged within this multiple of the period map's round-off
noise measured at its best state (:func:`measured_floor`)."""
NOISE_CAP = 1e-7
"""... and never above this residual [-] (1e-4 of the peak tolerance: what the noise may leave on a peak force)."""
_NOISE_SHIFTS = (4.0, -4.0, 16.0, -16.0)  # the start moved by these multiples of the double precision


@dataclass(frozen=True)
class Orbit:
    """The periodic orbit found (or the best state reached) and how the search ended.

    Attributes
    ----------
    flow
        The period marched from the orbit's start, recorded (states and contact codes at the samples, monodromy).
    residual
        How far the period's end is from its start (:func:`period_residual`) [-].
    periods, newton_steps
        Periods marched, Newton steps taken.
    samples
        N, the event grid's samples per period (doubled until the sampled peaks are the continuous ones).
    compression_m, correction_N
        Each contact's compression and correction force at the samples, (N, n_s) [m], [N].
    missed
        Per contact, how much of its peak force the grid misses, over its force scale (n_s,) [-].
    floquet_multiplier_max
        The largest modulus of the monodromy matrix's eigenvalues [-].
    converged
        The residual within its target (:func:`attainable`) and the orbit stable (multipliers at most
        1 + :data:`STABILITY_MARGIN`).
    residual_target
        The residual the orbit is converged at: the tolerance, or the march's round-off floor if higher [-].
    times
        Each sample's time where a guarded march put a continuous peak in place of a grid sample (:func:`with_peaks`)
        (N,) [s]; None: the grid's ``t_n = n T / N``.
    """

    flow: PeriodFlow
    residual: float
    periods: int
    newton_steps: int
    samples: int
    compression_m: NDArray[np.float64]
    correction_N: NDArray[np.float64]
    missed: NDArray[np.float64]
    floquet_multiplier_max: float
    converged: bool
    residual_target: float
    times: NDArray[np.float64] | None = None


def shoot_orbit(
    states: ContactStates,
    samples: int,
    scale_m: float,
    opts: ShootingOptions,
    stiffness_N_per_m: NDArray,
    start: NDArray | None = None,
) -> Orbit:
    """The periodic orbit from the linear solution (``x0 = 0``) or ``start``: Newton on ``P(x0) = x0``, the grid refined.

    ``samples``: the event grid's first N; ``scale_m``: the largest linear compression (the residual's scale);
    ``stiffness_N_per_m``: each contact's ``k`` (the peak forces the grid must resolve); ``start``: the state
    (2m,) the march and Newton start from (None: ``x0 = 0``, the linear solution).
    The grid is doubled (up to ``opts.max_samples``) while it misses more than ``opts.peak_tolerance`` of a peak
    force; the events are exact whatever the grid, so a finer grid usually keeps the orbit and Newton runs only if not.

    Raises
    ------
    SingularStateError, TooManyEventsError
        A contact state without stiffness against a rigid-body motion; a chattering contact.
    """
    N = int(samples)
    x_start = np.zeros(states.state_size) if start is None else np.array(start, dtype=float)
    periods = steps = 0
    guard = guarded(states)
    while True:
        grid = PeriodGrid(states, N)
        flow = flow_period(states, x_start, grid, record=True, max_events=opts.max_events, guard=guard) if periods else None
        residual = period_residual(states, flow, x_start, scale_m) if flow is not None else math.inf
        if flow is None or residual > attainable(states, x_start, scale_m, opts.tolerance):
            # the events are exact whatever the grid, so a finer grid usually keeps the orbit: Newton only if not
            flow, residual, marched, newton, x_start = periodic_state(states, grid, scale_m, opts, x_start, fresh=periods == 0)
            periods, steps = periods + marched, steps + newton
        else:
            periods += 1
        compression, correction = sampled_contact(states, grid, flow)
        continuous, times = peak_compressions(states, grid, flow, compression), None
        if flow.peaks is not None:
            # the guarded march's continuous peaks (impacts shorter than a sample) into the samples nearest them
            continuous = np.maximum(continuous, flow.peaks.compression_m)
            flow, times = with_peaks(grid, flow)
            compression, correction = sampled_contact(states, grid, flow, times)
        missed = missed_peak(compression, continuous, stiffness_N_per_m)
        target = attainable(states, x_start, scale_m, opts.tolerance)
        if residual > target:  # stalled: is it the period map's own round-off?
            target = max(target, min(NOISE_FACTOR * measured_floor(states, grid, x_start, scale_m, opts, flow), NOISE_CAP))
        if float(np.max(missed, initial=0.0)) <= opts.peak_tolerance or N >= opts.max_samples or residual > target:
            break
        N *= 2  # the grid misses part of a peak: the same orbit on a finer grid
    assert flow.monodromy is not None  # every period a solve reports forms it
    largest = float(np.max(np.abs(np.linalg.eigvals(flow.monodromy)), initial=0.0))
    converged = residual <= target and largest <= 1.0 + STABILITY_MARGIN
    return Orbit(flow, float(residual), periods, steps, N, compression, correction, missed, largest, bool(converged), float(target), times)


def guarded(states: ContactStates) -> bool:
    """Whether the period marches are guarded (stiff saddles, the lifted basis: impacts shorter than a sample)."""
    return states.system.basis is CorrectionBasis.LIFTED


def with_peaks(grid: PeriodGrid, flow: PeriodFlow) -> tuple[PeriodFlow, NDArray]:
    """The flow with each contact's continuous peak (a guarded march's) in place of the sample nearest it, and the times.

    The samples are exact states of the orbit; each replaced one is at its peak's time instead of its own (at most
    a sample's spacing away: where the nearest is taken by another contact's peak, the next nearest). Returns the flow
    and each sample's time (N,) [s].
    """
    assert flow.peaks is not None and flow.state_samples is not None and flow.state_codes is not None
    peaks, N = flow.peaks, grid.samples
    times = grid.times[:-1].copy()
    samples, codes = flow.state_samples.copy(), flow.state_codes.copy()
    taken: set[int] = set()
    for i in np.argsort(-peaks.compression_m):
        if not np.isfinite(peaks.compression_m[i]):
            continue
        position = peaks.time_s[i] / grid.times[1]
        nearest = int(np.floor(position + 0.5))
        for n in (nearest, nearest + 1 if position >= nearest else nearest - 1):
            if n % N not in taken:
                taken.add(n % N)
                samples[n % N], codes[n % N], times[n % N] = peaks.state[i], peaks.code[i], peaks.time_s[i]
                break
    return PeriodFlow(flow.end_state, flow.monodromy, samples, codes, flow.events, flow.peaks), times


def missed_peak(compression: NDArray, continuous: NDArray, stiffness_N_per_m: NDArray) -> NDArray:
    """Per contact, how much of its peak force the samples miss, over its force scale (:func:`force_scale_N`) [-].

    ``compression``: the sampled compressions (N, n_s) [m]; ``continuous``: each contact's largest compression in
    continuous time (:func:`~seafast.solvers.shooting.period.peak_compressions`) [m].
    """
    sampled = np.max(compression, axis=0)
    k = np.asarray(stiffness_N_per_m, dtype=float)
    peak = k * np.maximum(continuous, 0.0)
    return np.asarray(k * (np.maximum(continuous, 0.0) - np.maximum(sampled, 0.0)) / force_scale_N(peak), dtype=float)


def sampled_contact(states: ContactStates, grid: PeriodGrid, flow: PeriodFlow, times: NDArray | None = None) -> tuple[NDArray, NDArray]:
    """The contacts' compressions and correction forces at the recorded samples, each (N, n_s) [m], [N].

    ``times``: each sample's time (N,) [s] where some are not the grid's (:func:`with_peaks`); None: the grid's.
    """
    assert flow.state_samples is not None and flow.state_codes is not None
    # the forcing d(t_n) (N, n_s) [m]
    d = np.real(grid.phase[:-1] @ states.harmonics) if times is None else states.forcing(times)
    delta, correction = np.empty_like(d), np.empty_like(d)
    x = flow.state_samples
    for code, a, b in state_runs(flow.state_codes):
        cs = states.get(states.lifted_of(code))
        delta[a:b] = x[a:b] @ cs.compression_state.T + d[a:b] @ cs.compression_forcing.T
        correction[a:b] = x[a:b] @ cs.force_state.T + d[a:b] @ cs.force_forcing.T
    return delta, correction


def periodic_state(
    states: ContactStates, grid: PeriodGrid, scale_m: float, opts: ShootingOptions, x_start: NDArray, *, fresh: bool
) -> tuple[PeriodFlow, float, int, int, NDArray]:
    """Newton on ``P(x0) = x0`` from ``x_start`` (``fresh``: from the linear solution, marching a few periods first).

    Returns the recorded flow of the best state, its residual, the periods marched, the Newton steps and the state.
    """
    size = states.state_size
    guard = guarded(states)

    def flow_from(x: NDArray, record: bool = False, monodromy: bool = True) -> PeriodFlow:
        return flow_period(states, x, grid, record=record, monodromy=monodromy, max_events=opts.max_events, guard=guard)

    x0 = np.array(x_start, dtype=float)
    periods = steps = 0
    marches = opts.march_periods if fresh else 0
    flow = flow_from(x0, monodromy=marches == 0)  # only the period Newton starts from needs its monodromy matrix
    periods += 1
    for i in range(marches):
        x0 = flow.end_state
        flow = flow_from(x0, monodromy=i == marches - 1)
        periods += 1
    residual = period_residual(states, flow, x0, scale_m)
    best = (flow, residual, x0)
    while residual > attainable(states, x0, scale_m, opts.tolerance) and steps < opts.max_iterations:
        assert flow.monodromy is not None
        try:
            step = np.linalg.solve(flow.monodromy - np.eye(size), flow.end_state - x0)
        except np.linalg.LinAlgError:
            step = x0 - flow.end_state  # a multiplier at 1: march one period instead
        trial = x0 - step
        trial_flow = flow_from(trial, record=True)  # recorded: the step that converges is the period reported
        periods += 1
        steps += 1
        trial_residual = period_residual(states, trial_flow, trial, scale_m)
        if trial_residual < best[1]:
            x0, flow, residual = trial, trial_flow, trial_residual
            best = (flow, residual, x0)
        else:
            # Newton did not improve: march on from the best state (towards the attractor), then try again
            x0 = best[0].end_state
            flow = flow_from(x0)
            periods += 1
            residual = period_residual(states, flow, x0, scale_m)
            if residual < best[1]:
                best = (flow, residual, x0)
    if best[0].state_samples is not None:
        return best[0], best[1], periods, steps, best[2]
    return flow_from(best[2], record=True), best[1], periods + 1, steps, best[2]


def attainable(states: ContactStates, x0: NDArray, scale_m: float, tolerance: float) -> float:
    """The residual a periodic state is converged at: ``tolerance``, or the march's round-off floor if higher [-].

    The residual measures the period's change of the state on the compressions' scale (:func:`period_residual`); the
    state itself, on the same measure, is the motion at the contacts (the lift-off, some 1e-2 m), while near-rigid
    saddles' linear compressions (the scale) tend to zero with 1 / k: :data:`ROUND_OFF_FACTOR` times the double
    precision of the state's size over the scale is as close as a period's march can repeat it (1e-11 on the base
    case's 1.1e9 N/m saddles, 5e-8 on 1e14 N/m ones).
    """
    floor = ROUND_OFF_FACTOR * float(np.finfo(float).eps) * state_change(states, x0, 1.0) / scale_m
    return max(float(tolerance), floor)


def measured_floor(states: ContactStates, grid: PeriodGrid, x0: NDArray, scale_m: float, opts: ShootingOptions, flow: PeriodFlow) -> float:
    """The period map's round-off noise at ``x0`` [-]: the largest change of the period's end when the start moves by
    a few units of the double precision, less what the monodromy matrix carries of that move.

    :func:`attainable`'s floor is an estimate calibrated on one machine; the march's actual round-off depends on the
    BLAS (the contact states' eigenvector bases and the events' times), so a Newton that stalls is asked this of its
    own state, as the frequency continuation asks its corrector.
    """
    eps = float(np.finfo(float).eps)
    noise = 0.0
    for shift in _NOISE_SHIFTS:
        moved = x0 * (1.0 + shift * eps)
        end = flow_period(states, moved, grid, monodromy=False, max_events=opts.max_events, guard=guarded(states)).end_state
        carried = flow.monodromy @ (moved - x0) if flow.monodromy is not None else 0.0
        noise = max(noise, state_change(states, end - flow.end_state - carried, scale_m))
    return noise


def period_residual(states: ContactStates, flow: PeriodFlow, x0: NDArray, scale_m: float) -> float:
    """How far the period's end is from its start, as the compression and its rate over a period could move [-]."""
    return state_change(states, flow.end_state - x0, scale_m)


def state_change(states: ContactStates, change: NDArray, scale_m: float) -> float:
    """How far a change of the state ``[eta; eta']`` moves a contact's compression, with its rate over a modal period,
    at most, over ``scale_m`` [-]."""
    s = states.system
    m = s.mode_count
    bound = np.abs(s.saddle_mode_shape) @ np.hypot(change[:m], change[m:] / np.maximum(s.natural_frequency_rad_s, 1e-12))
    return float(np.max(bound, initial=0.0) / scale_m)
