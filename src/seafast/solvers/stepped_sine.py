"""Time-domain stepped-sine sweeps: the reference for folds and jumps of a frequency response.

What a shaker test does, in the time domain: hold a frequency until the response settles, step
the frequency, carry the cargo's state over, settle again. Up- and down-sweeps of a softening
resonance jump at different frequencies -- the folds of the frequency response, where a stable
branch ends -- and never settle on the unstable branch between them. This module does it with
the exact contact law, independently of the harmonic balance (no truncation in harmonics, no
AFT), so the continuation's folds and its Floquet stability verdicts can be checked against it.

Equations: the correction system of :mod:`seafast.solvers.modal_correction` (the modes up to a
cutoff with their full modal damping and the static residual flexibility of the others, every
saddle bilateral in the linear part, the compression-only saddles through the correction forces
``c = k_u max(-delta, 0)``), marched by its Newmark average-acceleration rule with each step's
contact solved exactly. At each frequency the linear (bilateral) compressions are the steady
state of the excitation at that frequency (:func:`seafast.solvers.hbm.condensed_operators`, exact
for harmonic excitation), sampled at ``S`` steps per period; whole periods are marched, so every
frequency starts at phase 0 with the state (modal displacements, velocities, accelerations,
contact forces) the previous frequency ended with.

Step control and jumps: a step is accepted when the settled peak-to-peak compression changes by
at most ``jump_tolerance`` of its value; otherwise the step is halved and retried from the same
state. A change that persists down to ``min_step_fraction`` is a *jump*: the branch the sweep was
on has ended (a fold) between the two frequencies, and the sweep carries on from where it landed.

Units: SI (rad/s, s, m, N). Nothing here prints or reads files.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from seafast.excitation.harmonic import HarmonicExcitation
from seafast.fourier import harmonics_to_time, real_to_complex_harmonics
from seafast.model.structure import StructuralModel
from seafast.solvers.hbm import condensed_operators
from seafast.solvers.modal_correction import modal_correction_system
from seafast.solvers.transient import MarchState, march_period, newmark_step

__all__ = ["SweepJump", "SteppedSineSweep", "stepped_sine_sweep"]


@dataclass(frozen=True)
class SweepJump:
    """A jump of a stepped-sine sweep: the branch followed ended between two frequencies.

    Attributes
    ----------
    omega_before_rad_s, omega_after_rad_s
        The last frequency on the old branch and the first on the new one [rad/s].
    range_before_m, range_after_m
        Peak-to-peak saddle compression (largest over the saddles) before and after [m].
    """

    omega_before_rad_s: float
    omega_after_rad_s: float
    range_before_m: float
    range_after_m: float

    @property
    def omega_rad_s(self) -> float:
        """The jump's frequency: the middle of its bracket [rad/s]."""
        return 0.5 * (self.omega_before_rad_s + self.omega_after_rad_s)


@dataclass(frozen=True)
class SteppedSineSweep:
    """The settled states of a stepped-sine sweep, in sweep order.

    Attributes
    ----------
    omega_rad_s
        Frequencies held [rad/s].
    max_saddle_force_N, max_gap_m, compression_range_m
        Over the last period at each frequency: largest saddle force [N], largest detachment gap
        [m] and largest peak-to-peak compression [m].
    settled
        Whether the period-to-period change fell below the tolerance at each frequency.
    periods
        Periods marched at each frequency.
    jumps
        The jumps, in sweep order.
    """

    omega_rad_s: NDArray[np.float64]
    max_saddle_force_N: NDArray[np.float64]
    max_gap_m: NDArray[np.float64]
    compression_range_m: NDArray[np.float64]
    settled: NDArray[np.bool_]
    periods: NDArray[np.intp]
    jumps: tuple[SweepJump, ...]


@dataclass(frozen=True)
class _Held:
    state: MarchState
    force: float
    gap: float
    span: float
    settled: bool
    periods: int


def _hold(
    model: StructuralModel,
    excitation: HarmonicExcitation,
    cutoff_rad_s: float,
    start: MarchState,
    steps: int,
    tolerance: float,
    min_periods: int,
    max_periods: int,
) -> _Held:
    """March whole periods at one frequency from a copy of ``start`` until the compressions repeat (or ``max_periods``)."""
    ops = condensed_operators(model, excitation, max(excitation.harmonic_count - 1, 1))
    lin = np.ascontiguousarray(harmonics_to_time(real_to_complex_harmonics(ops.linear_compression_m), steps))
    system = newmark_step(model, 2.0 * math.pi / excitation.omega_rad_s / steps, cutoff_rad_s, minimum_modes=0)
    state = MarchState(start.eta.copy(), start.eta_dot.copy(), start.eta_ddot.copy(), start.force_N.copy(), start.detached.copy())
    scale = max(float(np.max(np.abs(lin))), 1e-12)
    previous: NDArray | None = None
    settled = False
    periods = 0
    delta = lin
    for periods in range(1, max_periods + 1):
        delta = march_period(system, lin, state)
        if previous is not None and periods >= min_periods:
            if float(np.max(np.abs(delta - previous))) <= tolerance * scale:
                settled = True
                break
        previous = delta
    k = system.reduced.unilateral_stiffness_N_per_m
    span = float(np.max(np.ptp(delta, axis=0)))
    return _Held(state, float(np.max(k * np.maximum(delta, 0.0))), float(max(-np.min(delta), 0.0)), span, settled, periods)


def stepped_sine_sweep(
    model: StructuralModel,
    excitation_at: Callable[[float], HarmonicExcitation],
    omega_start_rad_s: float,
    omega_end_rad_s: float,
    *,
    step_fraction: float = 0.01,
    min_step_fraction: float = 5e-4,
    jump_tolerance: float = 0.05,
    steps_per_period: int = 256,
    cutoff_rad_s: float | None = None,
    tolerance: float = 1e-7,
    min_periods: int = 4,
    max_periods: int = 3000,
) -> SteppedSineSweep:
    """Sweep the frequency from ``omega_start`` to ``omega_end`` (up or down), settling at each step.

    Parameters
    ----------
    model
        Cargo and sea-fastening.
    excitation_at
        ``omega -> HarmonicExcitation`` at that frequency (as for the continuation).
    omega_start_rad_s, omega_end_rad_s
        Sweep limits [rad/s] (> 0, different); the sweep starts from rest at ``omega_start``.
    step_fraction, min_step_fraction
        Largest and smallest frequency step as a share of the current frequency.
    jump_tolerance
        Largest relative change of the peak-to-peak compression accepted for one step.
    steps_per_period
        Newmark steps per period of the excitation (at least; raised so that the highest kept
        mode has 12 steps per period).
    cutoff_rad_s
        Highest natural frequency of the modes marched [rad/s]; default 4 times the ``n_s``-th
        natural frequency on bilateral saddles. The others respond quasi-statically.
    tolerance
        Settled when the compressions of two consecutive periods differ by at most this share of
        the largest linear compression.
    min_periods, max_periods
        Periods marched at each frequency at least / at most.
    """
    w0, w1 = float(omega_start_rad_s), float(omega_end_rad_s)
    if not (w0 > 0 and w1 > 0 and w0 != w1 and math.isfinite(w0) and math.isfinite(w1)):
        raise ValueError(
            f"omega_start_rad_s = {omega_start_rad_s!r}, omega_end_rad_s = {omega_end_rad_s!r}; allowed: two different positive frequencies"
        )
    if not (0 < min_step_fraction <= step_fraction < 1):
        raise ValueError(f"step fractions {min_step_fraction!r}, {step_fraction!r}; allowed: 0 < min_step_fraction <= step_fraction < 1")
    if cutoff_rad_s is None:
        cutoff_rad_s = 4.0 * float(model.natural_frequencies_rad_s(True, count=max(model.saddle_count, 1))[-1])
    kept = modal_correction_system(model, float(cutoff_rad_s))
    top = float(kept.natural_frequency_rad_s[-1]) if kept.mode_count else 0.0
    direction = 1.0 if w1 > w0 else -1.0

    def hold(omega: float, state: MarchState) -> _Held:
        steps = max(int(steps_per_period), 2 * math.ceil(6.0 * top / omega))
        return _hold(model, excitation_at(omega), float(cutoff_rad_s), state, steps, tolerance, min_periods, max_periods)

    at_rest = MarchState(
        np.zeros(kept.mode_count),
        np.zeros(kept.mode_count),
        np.zeros(kept.mode_count),
        np.zeros(kept.saddle_count),
        np.zeros(kept.saddle_count, dtype=bool),
    )
    current = hold(w0, at_rest)
    omega = w0
    rows = [(omega, current)]
    jumps: list[SweepJump] = []
    fraction = step_fraction
    while direction * (w1 - omega) > 1e-12 * w1:
        step = direction * min(fraction * omega, abs(w1 - omega))
        trial = hold(omega + step, current.state)
        change = abs(trial.span - current.span) / max(trial.span, current.span, 1e-12)
        if change > jump_tolerance and fraction > min_step_fraction:
            fraction = max(0.5 * fraction, min_step_fraction)
            continue
        if change > jump_tolerance:
            jumps.append(SweepJump(omega, omega + step, current.span, trial.span))
        omega += step
        current = trial
        rows.append((omega, current))
        fraction = min(1.5 * fraction, step_fraction)
    return SteppedSineSweep(
        omega_rad_s=np.array([r[0] for r in rows]),
        max_saddle_force_N=np.array([r[1].force for r in rows]),
        max_gap_m=np.array([r[1].gap for r in rows]),
        compression_range_m=np.array([r[1].span for r in rows]),
        settled=np.array([r[1].settled for r in rows], dtype=bool),
        periods=np.array([r[1].periods for r in rows], dtype=np.intp),
        jumps=tuple(jumps),
    )
