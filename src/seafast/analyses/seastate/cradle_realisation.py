"""One random-phase realisation of a sea state off head seas for the 3-D cargo on its cradles: linear and nonlinear maxima.

The counterpart across the ship of :mod:`seafast.analyses.seastate.realisation` (the vertical plane's): the plan
(:func:`cradle_realisation_plan`, once per run) holds everything a realisation needs and
:func:`evaluate_cradle_realisation` is a pure function of the plan and the realisation index. The wave record is the
vertical realisation's (same grid of components, phases, amplitude factors and, short-crested, directions: the
same seed and index give the same sea); only the coarse sampling is the cradle quantities' own.

Per realisation
---------------
1. **Linear model** (:mod:`seafast.analyses.seastate.cradle_transfer`: pads and lashings bilateral, side stoppers
   open): every element's engagement ``s`` and the cargo's lateral displacement ``v`` at each saddle synthesised by
   inverse FFT on the coarse grid ``dt_c`` (:mod:`seafast.analyses.seastate.synthesis`), plus the exact still
   water. Maxima over the coarse samples, as the spectral columns
   (:mod:`seafast.analyses.seastate.cradle_extremes`) read them: pad force ``max k s``, stopper force
   ``max k max(s, 0)``, lashing tension ``max k s`` and ``min k s`` (negative where the linear wire would push),
   slip ``max |v|``; the largest fraction of the record a pad is lifted (``s < 0``) and a lashing slack. ``dt_c =
   coarse_step_factor / omega_s``, omega_s the frequency below which every channel has 1 - 1e-5 of its variance:
   a sampled peak is short by at most ``1 - cos(omega dt_c / 2)`` (0.28 % at omega_s).
2. **Nonlinear model**: ``q = q_lin + q_c`` (:mod:`seafast.solvers.cradle_window`). The correction is marched at
   ``dt_f = dt_c / ratio`` in windows that start at the coarse sample before one where some element may change
   state (a pad's or lashing's linear engagement below, a stopper's above ``-``, the margin
   ``dt_c^2 / 8 sum_j omega_j^2 |X_j|``: the largest dip between two samples) and end once no element is corrected,
   the trigger is off and the correction's free vibration is below ``decay_tolerance`` times the largest
   still-water engagement; inside, the linear record comes from the coarse samples by periodic cubic splines and
   the maxima are taken at every fine step. Outside the windows the nonlinear response is the linear one, sample
   by sample (a pad's and a lashing's force ``k s``, a stopper's 0): with no window, the nonlinear maxima are
   the linear ones exactly. The step: ``steps_per_period`` steps a period of the highest of the six lowest
   natural frequencies of the cargo on its linear restraints; modes up to ``cutoff_factor`` times it, the others
   static.

Units: SI (forces [N], displacements [m], time [s]).
"""

from __future__ import annotations

import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import NDArray
from scipy.interpolate import CubicSpline
from scipy.linalg import eigh

from seafast.analyses.seastate.cradle_extremes import element_groups
from seafast.analyses.seastate.cradle_transfer import CradleStillWater, CradleTransfer
from seafast.analyses.seastate.realisation import drawn_transfer, spectral_density, variance_frequency_rad_s
from seafast.analyses.seastate.spectrum import WaveSpectrum
from seafast.analyses.seastate.synthesis import (
    SynthesisGrid,
    amplitude_factors,
    interpolate_transfer,
    realisation_phases,
    record_grids,
    synthesise,
)
from seafast.config.schema import Case
from seafast.solvers.cradle_dynamics import CradleDynamics
from seafast.solvers.cradle_march import CradleStepper, cradle_stepper
from seafast.solvers.cradle_window import CradleWindow, march_cradle_window, quasi_static_state

__all__ = [
    "CRADLE_QUANTITIES",
    "CradleRealisationSettings",
    "CradleRealisationPlan",
    "cradle_realisation_plan",
    "evaluate_cradle_realisation",
    "fine_interpolant",
    "record_extremes",
    "record_fractions",
    "synthesised_record",
]

CRADLE_QUANTITIES: tuple[str, ...] = ("F_pad_N", "F_stopper_N", "lashing_tension_max_N", "lashing_tension_min_N", "transverse_slip_m")
"""Per-realisation extremes (still water included), the cradle columns of seastate.csv; the lashing minimum is a least."""

FRACTIONS: tuple[str, ...] = ("pad_lifted_fraction", "lashing_slack_fraction")
"""Per realisation, the largest fraction of the record a pad is lifted and a lashing slack [-]."""


@dataclass(frozen=True)
class CradleRealisationSettings:
    """Numerical settings of the cradle realisations (not case keys), as :class:`~seafast.analyses.seastate.realisation.MonteCarloSettings`.

    Attributes
    ----------
    steps_per_period
        Fine steps per period of the reference frequency (the highest of the six lowest natural frequencies). On
        two-minute beam-sea records where pads lift, 2 GN/m stoppers close and lashings slacken, against 64: the
        stopper force within 0.35 % (1.8 % at 16), pad force, lashing tensions and slip within 0.02 %.
    cutoff_factor
        Modes kept up to this multiple of the reference frequency.
    decay_tolerance
        A window ends when the correction's free vibration is below this fraction of the largest still-water
        engagement [-].
    coarse_step_factor
        ``omega_s dt_c`` of the coarse grid [rad].
    transfer_step_rad_s
        Spacing of the frequencies the transfer functions are computed at before interpolation [rad/s].
    """

    steps_per_period: int = 32
    cutoff_factor: float = 4.0
    decay_tolerance: float = 1e-4
    coarse_step_factor: float = 0.15
    transfer_step_rad_s: float = 0.01


@dataclass(frozen=True)
class CradleRealisationPlan:
    """Everything a cradle realisation needs (picklable; computed once per run).

    Attributes
    ----------
    seed, duration_s, random_amplitudes
        Phase seed, record length [s], Rayleigh amplitudes (:mod:`seafast.analyses.seastate.synthesis`).
    grid
        The synthesis grid (the vertical plan's components; the coarse sampling this plan's).
    transfer
        (n_f, m + n_s) every element's engagement [m/m] then the lateral displacement at each saddle [m/m];
        short-crested (n_d, n_f, m + n_s), one block per direction of the quadrature.
    direction_weights
        (n_d,) the quadrature's weights short-crested, None long-crested.
    engagement_static_m, lateral_static_m
        (m,) and (n_s,) the exact still water [m].
    stiffness_N_per_m
        (m,) [N/m].
    sign
        (m,) +1 the elements bilateral in the linear model (pads, lashings), -1 those open in it (stoppers).
    pad_count, stopper_count
        To split the elements.
    stepper
        The correction system's fine step (outputs: the lateral DOF at each saddle).
    ratio
        Fine steps per coarse sample.
    tolerance_m
        Window-end tolerance on the correction's free vibration [m].
    """

    seed: int
    duration_s: float
    grid: SynthesisGrid
    transfer: NDArray[np.complex128]
    engagement_static_m: NDArray[np.float64]
    lateral_static_m: NDArray[np.float64]
    stiffness_N_per_m: NDArray[np.float64]
    sign: NDArray[np.float64]
    pad_count: int
    stopper_count: int
    stepper: CradleStepper
    ratio: int
    tolerance_m: float
    settings: CradleRealisationSettings = field(default_factory=CradleRealisationSettings)
    random_amplitudes: bool = True
    direction_weights: NDArray[np.float64] | None = None

    @property
    def element_count(self) -> int:
        return int(self.engagement_static_m.size)

    def describe(self) -> dict[str, Any]:
        """The numerical settings of the cradle realisations (recorded in outputs)."""
        return {
            "cradle_coarse_step_s": self.grid.time_step_s,
            "cradle_integrator_step_s": self.grid.time_step_s / self.ratio,
            "cradle_modes_kept": int(self.stepper.engagement_modes.shape[1]),
            "cradle_window_tolerance_m": self.tolerance_m,
        }


def _reference_frequency_rad_s(dynamics: CradleDynamics, included: NDArray[np.bool_]) -> float:
    """The highest of the six lowest natural frequencies of the cargo on its linear restraints [rad/s]."""
    K = dynamics.linear_parts(included).bilateral_stiffness
    M = dynamics.matrices[1]
    w2 = eigh(K, M, eigvals_only=True, subset_by_index=[0, min(6, K.shape[0]) - 1])
    return float(np.sqrt(max(float(w2[-1]), 0.0)))


def cradle_realisation_plan(
    case: Case,
    spectrum: WaveSpectrum,
    transfer_at: Callable[[NDArray[np.float64]], CradleTransfer | Sequence[CradleTransfer]],
    dynamics: CradleDynamics,
    still: CradleStillWater,
    settings: CradleRealisationSettings = CradleRealisationSettings(),
    direction_weights: NDArray[np.float64] | None = None,
) -> CradleRealisationPlan:
    """Build the plan of the case's cradle realisations.

    Parameters
    ----------
    case
        The case (its ``sea_state``).
    spectrum
        Its sea-state spectrum (the synthesis band).
    transfer_at
        ``omega -> CradleTransfer`` (:func:`~seafast.analyses.seastate.cradle_transfer.cradle_transfer_functions`),
        or a short-crested sea's sequence of them, one per direction.
    dynamics, still
        The cargo on its cradles and its exact still water.
    settings, direction_weights
        Numerical settings; a short-crested sea's quadrature weights (None: long-crested).
    """
    ss = case.sea_state
    lo, hi = float(spectrum.omega_rad_s[0]), float(spectrum.omega_rad_s[-1])
    density = spectral_density(case, spectrum)
    omega_i = np.linspace(lo, hi, max(int(np.ceil((hi - lo) / settings.transfer_step_rad_s)) + 1, 8))
    held = transfer_at(omega_i)
    tfs = (held,) if isinstance(held, CradleTransfer) else tuple(held)
    if direction_weights is not None and len(tfs) != np.size(direction_weights):
        raise ValueError(f"cradle_realisation_plan: {len(tfs)} directions' transfer functions for {np.size(direction_weights)} weights")
    channels = [np.hstack([t.engagement_m, t.lateral_displacement_m]) for t in tfs]
    amplitude_i = np.sqrt(np.maximum(density(omega_i), 0.0))
    omega_s = max(variance_frequency_rad_s(omega_i, np.abs(ch) ** 2 * amplitude_i[:, None] ** 2, 1e-5) for ch in channels)
    included = dynamics.damping_set
    reference = _reference_frequency_rad_s(dynamics, included)
    dt_f_max = 2.0 * np.pi / reference / int(settings.steps_per_period)
    grid, ratio = record_grids((lo, hi), density, ss.duration_s, omega_s, settings.coarse_step_factor, dt_f_max)
    per = [interpolate_transfer(omega_i, ch, grid.omega_rad_s) for ch in channels]
    cargo = dynamics.problem.cargo
    lateral = np.array([cargo.node_dofs(cargo.node_at(pair.x_m))[1] for pair in dynamics.problem.pad_pairs], dtype=np.intp)
    stepper = cradle_stepper(dynamics, grid.time_step_s / ratio, settings.cutoff_factor * reference, included, lateral)
    s0 = np.asarray(still.engagement_m, dtype=float)
    scale = float(np.max(np.abs(s0))) if s0.size and np.max(np.abs(s0)) > 0 else 1e-3
    return CradleRealisationPlan(
        seed=int(ss.seed),
        duration_s=float(ss.duration_s),
        grid=grid,
        transfer=np.ascontiguousarray(np.stack(per) if direction_weights is not None else per[0]),
        engagement_static_m=s0,
        lateral_static_m=np.asarray(still.lateral_displacement_m, dtype=float),
        stiffness_N_per_m=np.asarray(dynamics.problem.element_stiffness_N_per_m, dtype=float),
        sign=np.where(included, 1.0, -1.0),
        pad_count=tfs[0].pad_count,
        stopper_count=tfs[0].stopper_count,
        stepper=stepper,
        ratio=int(ratio),
        tolerance_m=settings.decay_tolerance * scale,
        settings=settings,
        random_amplitudes=bool(ss.random_amplitudes),
        direction_weights=None if direction_weights is None else np.asarray(direction_weights, dtype=float),
    )


def record_extremes(plan: CradleRealisationPlan, force: NDArray, low: NDArray, slip: NDArray) -> dict[str, float]:
    """The five quantities from per-element largest ``force`` and least ``low`` forces [N] and the largest ``slip`` [m]."""
    pads, stoppers, lashings = element_groups(plan.pad_count, plan.stopper_count, plan.element_count)
    return {
        "F_pad_N": float(np.max(force[pads], initial=0.0)),
        "F_stopper_N": float(np.max(force[stoppers], initial=0.0)),
        "lashing_tension_max_N": float(np.max(force[lashings], initial=0.0)),
        "lashing_tension_min_N": float(np.min(low[lashings])) if low[lashings].size else 0.0,
        "transverse_slip_m": float(np.max(slip, initial=0.0)),
    }


def record_fractions(plan: CradleRealisationPlan, per_element: NDArray) -> dict[str, float]:
    """The largest fraction of the record a pad is lifted and a lashing slack, from per-element fractions [-]."""
    pads, _, lashings = element_groups(plan.pad_count, plan.stopper_count, plan.element_count)
    return {
        "pad_lifted_fraction": float(np.max(per_element[pads], initial=0.0)),
        "lashing_slack_fraction": float(np.max(per_element[lashings], initial=0.0)),
    }


def _linear_record(plan: CradleRealisationPlan, s: NDArray, v: NDArray) -> dict[str, float]:
    """The linear model's extremes and fractions from the coarse samples of ``s`` (n_t, m) and ``v`` (n_t, n_s)."""
    k = plan.stiffness_N_per_m
    force = np.where(plan.sign > 0, k * s, k * np.maximum(s, 0.0))
    extremes = record_extremes(plan, force.max(axis=0), force.min(axis=0), np.abs(v).max(axis=0))
    return {**extremes, **record_fractions(plan, np.mean(plan.sign * s < 0.0, axis=0))}


@dataclass
class _Tally:
    """The windows of one realisation, summed."""

    covered: NDArray[np.bool_]
    force_max: NDArray[np.float64]
    force_min: NDArray[np.float64]
    slip_max: NDArray[np.float64]
    corrected_steps: NDArray[np.int64]
    windows: int = 0
    window_steps: int = 0
    solved: bool = True

    def add(self, out: CradleWindow, start: int, ratio: int) -> None:
        self.covered[start // ratio + 1 : out.end // ratio + 1] = True
        self.force_max = np.maximum(self.force_max, out.max_force_N)
        self.force_min = np.minimum(self.force_min, out.min_force_N)
        self.slip_max = np.maximum(self.slip_max, out.max_abs_output)
        self.corrected_steps += out.corrected_steps
        self.windows += 1
        self.window_steps += out.end - start
        self.solved = self.solved and out.solved


def fine_interpolant(plan: CradleRealisationPlan, totals: NDArray[np.float64]) -> Callable[[int, int], NDArray[np.float64]]:
    """``linear_at(first, count)``: the coarse record ``totals`` (n_tc, ...) at the fine steps ``first ..
    first + count - 1`` (the fine step ``dt_c / ratio``), by periodic cubic splines built at the first call."""
    splines: list[CubicSpline] = []
    dt_f = plan.grid.time_step_s / plan.ratio

    def linear_at(first: int, count: int) -> NDArray[np.float64]:
        if not splines:
            t = np.arange(plan.grid.samples + 1) * plan.grid.time_step_s
            splines.append(CubicSpline(t, np.vstack([totals, totals[:1]]), axis=0, bc_type="periodic"))
        return np.asarray(splines[0]((first + np.arange(count)) * dt_f), dtype=float)

    return linear_at


def _windows(plan: CradleRealisationPlan, totals: NDArray, trigger: NDArray[np.bool_]) -> _Tally:
    """March the correction in every window ``trigger`` opens (the module docstring, step 2)."""
    n_tc, ratio, m = plan.grid.samples, plan.ratio, plan.element_count
    linear_at = fine_interpolant(plan, totals)  # splines built at the first window
    tally = _Tally(
        np.zeros(n_tc, dtype=bool), np.full(m, -np.inf), np.full(m, np.inf), np.zeros(totals.shape[1] - m), np.zeros(m, dtype=np.int64)
    )
    starts = np.flatnonzero(trigger)
    n_fine, position = n_tc * ratio, -1
    while True:
        later = starts[starts > position // ratio + 1] if position >= 0 else starts
        if later.size == 0:
            break
        i = int(later[0])
        if i == 0:
            start, state = 0, quasi_static_state(plan.stepper, totals[0, :m])
            tally.covered[0] = True  # the record's first instant, quasi-static, is not read
        else:
            start, state = (i - 1) * ratio, None
        out = march_cradle_window(plan.stepper, linear_at, trigger, ratio, start, n_fine - 1, plan.tolerance_m, state)
        tally.add(out, start, ratio)
        position = out.end
        if out.end >= n_fine - 1:
            break
    return tally


def synthesised_record(
    plan: CradleRealisationPlan, transfer: NDArray[np.complex128], index: int
) -> tuple[NDArray[np.float64], NDArray[np.complex128], NDArray[np.float64]]:
    """Realisation ``index``'s record of the quantities whose transfer functions are ``transfer`` (on ``plan``'s
    components; short-crested one block per direction) on the coarse grid (n_tc, ...) [m], with the transfer functions
    drawn for it (one direction per component) [m/m] and its amplitude factors [-]: the same sea whatever ``transfer``."""
    grid = plan.grid
    phases = realisation_phases(plan.seed, index, grid.omega_rad_s.size)
    factors = amplitude_factors(plan.seed, index, grid.omega_rad_s.size, plan.random_amplitudes)
    drawn = drawn_transfer(transfer, plan.direction_weights, plan.seed, index)
    return synthesise(grid, phases, drawn, factors), drawn, factors


def evaluate_cradle_realisation(plan: CradleRealisationPlan, index: int, windowed: bool = True) -> dict[str, Any]:
    """The cradle extremes of realisation ``index``, linear and nonlinear.

    ``windowed`` False marches the correction over the whole record (one window from sample 0: the reference the
    windows are checked against).

    Returns
    -------
    dict
        ``{"index", "linear": {...}, "nonlinear": {...}, "solved", "windows", "window_steps", "seconds"}`` (plain
        JSON types); per model the :data:`CRADLE_QUANTITIES` [N, N, N, N, m] and :data:`FRACTIONS` [-].
    """
    t0 = time.perf_counter()
    grid, m = plan.grid, plan.element_count
    X, transfer, factors = synthesised_record(plan, plan.transfer, index)  # (n_tc, m + n_s)
    totals = np.hstack([plan.engagement_static_m, plan.lateral_static_m]) + X
    s, v = totals[:, :m], totals[:, m:]
    linear = _linear_record(plan, s, v)
    margin = grid.time_step_s**2 / 8.0 * (grid.omega_rad_s**2 @ (np.abs(transfer[:, :m]) * (grid.amplitude_m * factors)[:, None]))
    trigger = np.any(plan.sign * s < margin, axis=1) if windowed else np.ones(grid.samples, dtype=bool)
    tally = _windows(plan, totals, trigger)
    free = ~tally.covered
    k = plan.stiffness_N_per_m
    if free.any():  # outside the windows the nonlinear response is the linear one
        force_free = k * np.maximum(s[free], 0.0)
        tally.force_max = np.maximum(tally.force_max, force_free.max(axis=0))
        tally.force_min = np.minimum(tally.force_min, force_free.min(axis=0))
        tally.slip_max = np.maximum(tally.slip_max, np.abs(v[free]).max(axis=0))
    nonlinear = {
        **record_extremes(plan, tally.force_max, tally.force_min, tally.slip_max),
        **record_fractions(plan, tally.corrected_steps / float(grid.samples * plan.ratio)),
    }
    return {
        "index": int(index),
        "linear": linear,
        "nonlinear": nonlinear,
        "solved": bool(tally.solved),
        "windows": int(tally.windows),
        "window_steps": int(tally.window_steps),
        "seconds": time.perf_counter() - t0,
    }
