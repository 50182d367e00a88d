"""Allowable significant wave height per peak period: linear (closed form) and nonlinear (design waves).

For a peak period Tp (the case's spectrum shape, duration and limits), with every linear MPM
proportional to Hs (``MPM = sigma sqrt(2 ln(D / Tz))``, sigma proportional to Hs, Tz independent of it):

* **linear allowable** ``min over saddles (F_max - F_0,s) / m_F,s`` and ``min over x (sigma_max -
  |sigma_0(x)|) / m_sigma(x)``, m the MPM per metre of Hs, capped by the limiting steepness
  (:func:`seafast.config.schema.max_significant_height_m`); 0 when the still water alone exceeds a limit;
* **uplift onset** ``min over saddles delta_0,s / m_delta,s``: the Hs at which the MPM of some
  saddle's compression reaches its still-water compression (where Rice's expected number of
  uplift events over the duration is exactly one); empty above the steepness limit;
* **nonlinear allowable**: the Hs at which the design-wave estimate
  (:mod:`seafast.analyses.seastate.design_wave`) of F or sigma_b reaches its limit, by bracketing from the
  linear allowable (steps of :attr:`OperabilitySettings.expansion`) and Brent's method
  (``scipy.optimize.brentq``); the design frequencies do not change with Hs, so at a fixed H every
  evaluation reuses the wave operators and starts each solve from the previous Hs's solution at that
  frequency (the converged design waves, the default, are solved afresh by exact-event shooting).

Off head seas, each cradle limit set (``limits.max_pad_force_N``, ``limits.max_lashing_tension_N``,
``limits.max_transverse_slip_m``) is one more limit of both models, in closed form and by the cradle design waves
(:mod:`seafast.analyses.operability.cradle`); the limits are searched in the order the linear model reaches them.
On frictional pads (``seafastening.friction_coefficient`` above 0) the cradle design waves are the frictional ones of
``seafast seastate``; their search is led by the same waves at H = 16 (:func:`_led_limit_hs`: secant steps from the
still water), whose answer is then read by the case's waves and kept when that reading is within the Hs tolerance of
the limit (else corrected by secant steps on the case's waves, else their own search).

The sea states share their transfer functions (:mod:`seafast.analyses.operability.family`).

Size: over 400 lines because the search's three parts (the bracketing and Brent search, the proxy-led search of the
frictional cradle limits, the order of the limits) and the point they answer read best together.
"""

from __future__ import annotations

import logging
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np
from numpy.typing import NDArray
from scipy.optimize import brentq

from seafast.analyses.operability.cradle import (
    cradle_at_peak_period,
    cradle_design_wave_value,
    cradle_linear_limits,
    cradle_still_value,
    proxy_friction,
)
from seafast.analyses.operability.family import MASTER_STEP_RAD_S, SeaStateFamily, analysis_at, rescaled, sea_state_family
from seafast.analyses.operability.limits import GOVERNING, VERTICAL_LIMITS, linear_limit_hs, vertical_limits
from seafast.analyses.seastate.design_wave import DesignWaveSettings, design_wave_extremes
from seafast.analyses.seastate.spectral import SpectralAnalysis
from seafast.analyses.seastate.wave_response import WaveOperators, WaveSolution
from seafast.config.schema import Case, max_significant_height_m
from seafast.parallel.executor import ExecutionOptions, map_batches, plan_batches

__all__ = [
    "GOVERNING",
    "OperabilitySettings",
    "OperabilityPoint",
    "OperabilityResult",
    "CRADLE_OPERABILITY_COLUMNS",
    "allowable_sea_states",
]

logger = logging.getLogger(__name__)

_LIMIT_QUANTITY = {name: column for name, _, column in VERTICAL_LIMITS}


@dataclass(frozen=True)
class OperabilitySettings:
    """Numerical settings of the allowable-Hs search (not case keys; defaults verified).

    Attributes
    ----------
    design_wave
        The design-wave rule and its solve (by default each wave's converged periodic answer: near the saturation
        of the saddle force in heavy lift-off the allowable Hs is sensitive to a per cent of the MPM, and the
        H = 16 design waves, 2-3 % low there, can move it by metres: docs/operability.md).
    master_step_rad_s
        Spacing of the master grid the transfer functions are computed on [rad/s].
    hs_tolerance_m
        Absolute tolerance of the nonlinear allowable Hs [m] (Brent's ``xtol``).
    expansion
        Factor of each bracketing step in Hs [-].
    """

    design_wave: DesignWaveSettings = field(default_factory=DesignWaveSettings)
    master_step_rad_s: float = MASTER_STEP_RAD_S
    hs_tolerance_m: float = 1e-3
    expansion: float = 1.25


@dataclass(frozen=True)
class OperabilityPoint:
    """Allowable sea states at one peak period.

    Attributes
    ----------
    peak_period_s
        Tp [s].
    hs_allowable_linear_m, hs_allowable_nonlinear_m
        Largest Hs within both limits [m], linear spectral and nonlinear design-wave MPMs (NaN:
        the nonlinear search failed).
    hs_uplift_onset_m
        Hs at which the MPM compression of a saddle reaches its still-water compression [m]
        (NaN: not within the steepness limit).
    governing_linear, governing_nonlinear
        The limit reached first (:data:`GOVERNING`).
    hs_max_steepness_m
        The steepest sea state at this Tp [m] (the cap of the search).
    hs_force_linear_m, hs_stress_linear_m, hs_force_nonlinear_m, hs_stress_nonlinear_m
        Hs at which each limit alone is reached [m] (inf: not below the steepness limit). The
        nonlinear search looks for the limit the linear model reaches first, then for the other
        only below that Hs: NaN when the other limit is not reached there (not searched), or the
        search did not converge (``converged``).
    converged
        Every harmonic-balance solve of the search converged.
    evaluations
        Design-wave evaluations (each a few harmonic-balance solves) of the nonlinear search.
    hs_pad_force_linear_m, hs_lashing_tension_linear_m, hs_transverse_slip_linear_m
        Hs at which each cradle limit alone is reached by the linear spectral MPMs [m] (beyond the steepness limit
        where it is not reached below it; inf: never; NaN: not checked, i.e. the limit is not set or the sea is a
        head sea).
    hs_pad_force_nonlinear_m, hs_lashing_tension_nonlinear_m, hs_transverse_slip_nonlinear_m
        The same by the cradle design waves [m] (inf: not below the steepness limit; NaN also: not searched, another
        limit reached first, or the search did not converge).
    """

    peak_period_s: float
    hs_allowable_linear_m: float
    hs_allowable_nonlinear_m: float
    hs_uplift_onset_m: float
    governing_linear: str
    governing_nonlinear: str
    hs_max_steepness_m: float
    hs_force_linear_m: float
    hs_stress_linear_m: float
    hs_force_nonlinear_m: float
    hs_stress_nonlinear_m: float
    converged: bool
    evaluations: int
    hs_pad_force_linear_m: float = math.nan
    hs_lashing_tension_linear_m: float = math.nan
    hs_transverse_slip_linear_m: float = math.nan
    hs_pad_force_nonlinear_m: float = math.nan
    hs_lashing_tension_nonlinear_m: float = math.nan
    hs_transverse_slip_nonlinear_m: float = math.nan

    def row(self) -> dict[str, Any]:
        """The row of operability.csv."""
        return {
            "peak_period_s": self.peak_period_s,
            "hs_allowable_linear_m": self.hs_allowable_linear_m,
            "hs_allowable_nonlinear_m": self.hs_allowable_nonlinear_m,
            "hs_uplift_onset_m": self.hs_uplift_onset_m,
            "governing_linear": self.governing_linear,
            "governing_nonlinear": self.governing_nonlinear,
        }

    def cradle_row(self) -> dict[str, float]:
        """The cradle limits' columns of operability.csv (:data:`CRADLE_OPERABILITY_COLUMNS`): each limit's Hs [m]."""
        return {c: float(getattr(self, c)) for c in CRADLE_OPERABILITY_COLUMNS}


CRADLE_OPERABILITY_COLUMNS = (
    "hs_pad_force_linear_m",
    "hs_lashing_tension_linear_m",
    "hs_transverse_slip_linear_m",
    "hs_pad_force_nonlinear_m",
    "hs_lashing_tension_nonlinear_m",
    "hs_transverse_slip_nonlinear_m",
)
"""The columns operability.csv adds when a cradle limit is set: the Hs at which each cradle limit alone is reached [m]."""


@dataclass(frozen=True)
class OperabilityResult:
    """Allowable sea states over peak periods (what ``seafast operability`` writes)."""

    case: Case
    points: tuple[OperabilityPoint, ...]
    settings: OperabilitySettings

    @property
    def converged(self) -> bool:
        """Every point's nonlinear search converged."""
        return all(p.converged for p in self.points)


def _governing(candidates: dict[str, float], cap: float) -> tuple[float, str]:
    name = min(candidates, key=lambda k: candidates[k])
    hs = candidates[name]
    if not hs < cap:
        return cap, "steepness"
    return hs, name


def _nonlinear_limit_hs(
    value: Callable[[float], tuple[float, bool]], limit: float, start_hs: float, cap: float, settings: OperabilitySettings
) -> tuple[float, bool, int]:
    """Smallest Hs <= cap where ``value(Hs) = limit`` by bracketing from ``start_hs`` and Brent; (hs, converged, evaluations).

    ``value`` returns the nonlinear estimate and whether its solves converged. inf when the
    limit is not reached at the cap.
    """
    ok = [True]
    seen: dict[float, float] = {}  # Brent starts by evaluating the bracket again: reuse, never re-solve

    def g(hs: float) -> float:
        if hs not in seen:
            v, conv = value(hs)
            ok[0] &= conv
            seen[hs] = v / limit - 1.0
        return seen[hs]

    hs = min(max(start_hs, 1e-3), cap)
    f = g(hs)
    if abs(f) <= 1e-7:  # no lift-off in the design waves: the nonlinear answer is the linear one (to the peak reading)
        return hs, ok[0], len(seen)
    if f < 0.0:
        lo, hi, f_hi = hs, hs, f
        while f_hi < 0.0:
            if hi >= cap:
                return math.inf, ok[0], len(seen)
            lo, hi = hi, min(hi * settings.expansion, cap)
            f_hi = g(hi)
    else:
        lo, hi, f_lo = hs, hs, f
        while f_lo > 0.0:
            hi, lo = lo, lo / settings.expansion
            if lo < 1e-3:
                return 0.0, ok[0], len(seen)
            f_lo = g(lo)
    root = brentq(g, lo, hi, xtol=settings.hs_tolerance_m, rtol=1e-10)
    return float(root), ok[0], len(seen)


def _uplift_onset(still_compression_m: NDArray[np.float64], compression_mpm_m: NDArray[np.float64], cap: float) -> float:
    """The Hs at which some saddle's MPM compression reaches its still-water compression [m] (NaN beyond ``cap``)."""
    if np.any(still_compression_m <= 0.0):
        onset = 0.0
    else:
        with np.errstate(divide="ignore"):
            mpm = compression_mpm_m
            onset = float(np.min(np.where(mpm > 0, still_compression_m / np.where(mpm > 0, mpm, 1.0), np.inf)))
    return onset if onset <= cap else math.nan


Value = Callable[[float], tuple[float, bool]]
"""``value(Hs) -> (the nonlinear design-wave estimate of a limit's quantity, every solve converged)``."""


def _vertical_values(family: SeaStateFamily, ref: SpectralAnalysis, settings: OperabilitySettings) -> dict[str, Value]:
    """The design-wave estimates of the saddle force and the bending stress at an Hs (operators and warm starts shared)."""
    operators: dict[tuple[int, int, int], WaveOperators] = {}
    warm: dict[int, WaveSolution] = {}

    def value_of(quantity: str) -> Value:
        def value(hs: float) -> tuple[float, bool]:
            dw = design_wave_extremes(
                rescaled(ref, hs),
                family.static,
                settings.design_wave,
                quantities=(quantity,),
                operators=operators,
                moments=family.moments,
                warm=warm,
            )
            return float(dw.totals[quantity]), dw.converged

        return value

    return {name: value_of(quantity) for name, quantity in _LIMIT_QUANTITY.items()}


def _slope_near(points: Sequence[tuple[float, float]], hs: float) -> float:
    """The secant slope of ``value(Hs)`` [per m] between the evaluations nearest ``hs`` on each side (or the two
    nearest when all lie on one side); NaN with fewer than two."""
    below = [p for p in points if p[0] < hs]
    above = [p for p in points if p[0] > hs]
    if below and above:
        a, b = max(below), min(above)
    else:
        near = sorted(points, key=lambda p: abs(p[0] - hs))[:2]
        if len(near) < 2 or near[0][0] == near[1][0]:
            return math.nan
        a, b = sorted(near)
    return (b[1] - a[1]) / (b[0] - a[0])


@dataclass(frozen=True)
class _Proxy:
    """A cheaper estimate of a limit's value (the frictional cradle design waves at a smaller H) and its still water."""

    value: Value
    still: float


def _secant_hs(value: Value, limit: float, start_hs: float, cap: float, still: float, tolerance: float) -> tuple[float, bool]:
    """Secant steps on ``value`` from the still water (Hs = 0) and ``start_hs``: (hs, converged) with ``value(hs)``
    within half the Hs tolerance's worth of the limit, or the next step when it moves less than the tolerance (after
    two evaluations: the secant's root, not evaluated); NaN when it does not get there in 8 steps, a slope is not
    positive, or a step is held at the cap or the floor (the bracketing search then decides)."""
    last = (0.0, still)
    hs = min(max(start_hs, 1e-3), cap)
    for _ in range(8):
        v, ok = value(hs)
        if not ok:
            return math.nan, False
        slope = (v - last[1]) / (hs - last[0])
        if not slope > 0.0:
            return math.nan, True
        if abs(v - limit) <= 0.5 * slope * tolerance:
            return hs, True
        step = min(max(hs + (limit - v) / slope, 0.5 * hs, 1e-3), 2.0 * hs, cap)
        if step == hs:
            return math.nan, True
        if last[0] > 0.0 and abs(step - hs) <= tolerance:
            return step, True
        last, hs = (hs, v), step
    return math.nan, True


def _led_limit_hs(
    value: Value, proxy: _Proxy, limit: float, start_hs: float, cap: float, settings: OperabilitySettings
) -> tuple[float, bool, int]:
    """:func:`_nonlinear_limit_hs` of ``value`` led by a cheaper ``proxy`` of it: (hs, converged, evaluations).

    The proxy's root (secant steps from the still water, :func:`_secant_hs`; else the bracketing search on it) is read
    by ``value`` itself; it is the answer when every solve converged and the reading is within the search's tolerance
    of the limit, ``|value - limit| <= slope hs_tolerance_m`` (the slope the proxy's evaluations nearest it show: the
    root of ``value`` within ``hs_tolerance_m`` of it), else the secant step with that slope is read, up to three
    readings, and then ``value``'s own search from there answers, with steps of 1 % in Hs. A reading that does not
    converge answers NaN, not converged. Where the proxy reaches no root below the cap, ``value``'s search starts at
    the cap (one reading when it is not reached there either); where the proxy's solves do not converge, it starts
    where the proxy's did. An answer is always a reading of ``value``, never of the proxy.
    """
    points: list[tuple[float, float]] = []

    def recorded(hs: float) -> tuple[float, bool]:
        v, ok = proxy.value(hs)
        points.append((hs, v))
        return v, ok

    hs, ok = _secant_hs(recorded, limit, start_hs, cap, proxy.still, settings.hs_tolerance_m)
    if ok and math.isnan(hs):
        hs, ok, _ = _nonlinear_limit_hs(recorded, limit, start_hs, cap, settings)
    count, slope = len(points), _slope_near(points, hs)
    near = ok and 0.0 < hs < cap and slope > 0.0
    for _ in range(3 if near else 0):
        v, conv = value(hs)
        count += 1
        if not conv:
            return math.nan, False, count  # flagged, as value's own search would be from here on
        if abs(v - limit) <= slope * settings.hs_tolerance_m:
            return hs, True, count
        hs = min(max(hs - (v - limit) / slope, 1e-3), cap)  # the secant's estimate of value's root
    start = (cap if hs == math.inf else hs) if ok else start_hs  # no root below the cap: value at the cap decides
    steps = replace(settings, expansion=min(settings.expansion, 1.01)) if near else settings
    root, converged, more = _nonlinear_limit_hs(value, limit, start, cap, steps)
    return root, converged, count + more


def _nonlinear_limits(
    linear: dict[str, float],
    limits: dict[str, float],
    values: dict[str, Value],
    cap: float,
    settings: OperabilitySettings,
    proxies: dict[str, _Proxy] | None = None,
) -> tuple[dict[str, float], bool, int]:
    """Each limit's nonlinear Hs (NaN: not searched), whether every solve converged, and the evaluations.

    The limit the linear model reaches first is searched first; each other only below the smallest Hs found so far,
    and not at all when it is still within its limit there (the MPMs grow with Hs). A limit with a proxy of its value
    (``proxies``: the frictional cradle design waves at a smaller H) is searched led by it (:func:`_led_limit_hs`).
    """
    proxies = {} if proxies is None else proxies
    nonlinear = dict.fromkeys(limits, math.nan)
    evaluations, converged, bound = 0, True, cap
    for name in sorted(limits, key=lambda n: linear[n]):
        if linear[name] == 0.0:
            nonlinear[name] = 0.0  # the still water alone exceeds the limit: no waves allowed, either model
            break
        value = values[name]
        if bound < cap:
            v, ok = value(bound)
            evaluations += 1
            converged &= ok
            if v < limits[name]:
                continue  # within its limit where another is reached: not searched (NaN)
        start = min(linear[name], bound)
        if name in proxies:
            hs, ok, count = _led_limit_hs(value, proxies[name], limits[name], start, bound, settings)
        else:
            hs, ok, count = _nonlinear_limit_hs(value, limits[name], start, bound, settings)
        evaluations += count
        converged &= ok
        nonlinear[name] = hs if ok else math.nan
        if ok and math.isfinite(hs):
            bound = min(bound, hs)
    return nonlinear, converged, evaluations


def _point(family: SeaStateFamily, tp: float, settings: OperabilitySettings) -> OperabilityPoint:
    case = family.case
    cap = max_significant_height_m(tp, case.model.gravity_m_per_s2)
    ref = analysis_at(family, tp, 1.0)  # MPMs per metre of Hs
    e, sw = ref.extremes, family.still
    limits = vertical_limits(case)
    linear = {
        "saddle_force": linear_limit_hs(sw.saddle_force_N, e.saddle_force.mpm, limits["saddle_force"]),
        "bending_stress": linear_limit_hs(np.abs(sw.bending_stress_Pa), e.bending_stress.mpm, limits["bending_stress"]),
    }
    values = _vertical_values(family, ref, settings)
    proxies: dict[str, _Proxy] = {}
    if family.cradle is not None:  # off head seas with a cradle limit set
        at = cradle_at_peak_period(family.cradle, ref)
        limits |= family.cradle.limits
        linear |= cradle_linear_limits(at)
        band, friction = settings.design_wave.band_fraction, family.cradle.friction
        spectrum_at = lambda hs: rescaled(ref, hs).spectrum  # noqa: E731
        values |= {n: cradle_design_wave_value(at, n, spectrum_at, band, friction) for n in family.cradle.limits}
        if (proxy := proxy_friction(friction)) is not None:
            for n in family.cradle.limits:
                proxies[n] = _Proxy(cradle_design_wave_value(at, n, spectrum_at, band, proxy), cradle_still_value(at, n))
    hs_lin, gov_lin = _governing(linear, cap)
    onset = _uplift_onset(sw.saddle_compression_m, e.saddle_compression.mpm, cap)
    nonlinear, converged, evaluations = _nonlinear_limits(linear, limits, values, cap, settings, proxies)
    if converged:
        hs_nl, gov_nl = _governing({k: (math.inf if math.isnan(v) else v) for k, v in nonlinear.items()}, cap)
    else:
        hs_nl, gov_nl = math.nan, "not_converged"
        logger.warning("operability: Tp = %g s: a harmonic-balance solve of the nonlinear search did not converge", tp)
    cradle = {f"hs_{n}_linear_m": v for n, v in linear.items() if n not in _LIMIT_QUANTITY}
    cradle |= {f"hs_{n}_nonlinear_m": v for n, v in nonlinear.items() if n not in _LIMIT_QUANTITY}
    return OperabilityPoint(
        peak_period_s=float(tp),
        hs_allowable_linear_m=float(hs_lin),
        hs_allowable_nonlinear_m=float(hs_nl),
        hs_uplift_onset_m=float(onset),
        governing_linear=gov_lin,
        governing_nonlinear=gov_nl,
        hs_max_steepness_m=float(cap),
        hs_force_linear_m=linear["saddle_force"],
        hs_stress_linear_m=linear["bending_stress"],
        hs_force_nonlinear_m=nonlinear["saddle_force"],
        hs_stress_nonlinear_m=nonlinear["bending_stress"],
        converged=converged,
        evaluations=evaluations,
        **{k: float(v) for k, v in cradle.items()},
    )


def allowable_sea_states(
    case: Case,
    peak_periods_s: Sequence[float],
    settings: OperabilitySettings = OperabilitySettings(),
    *,
    family: SeaStateFamily | None = None,
    progress: Callable[[int, int], None] | None = None,
    execution: ExecutionOptions | None = None,
) -> OperabilityResult:
    """Allowable Hs per peak period, linear and nonlinear, and the uplift onset (module docstring).

    Parameters
    ----------
    case
        The case: its sea state's spectrum shape, gamma and duration (its Hs and Tp are not
        used), its limits (``limits.max_saddle_force_N``, ``limits.max_bending_stress_Pa``; off head seas also the
        cradle limits set).
    peak_periods_s
        Tp values [s].
    settings
        Numerical settings.
    family
        The shared part (:func:`~seafast.analyses.operability.family.sea_state_family`) when already computed for these Tp.
    progress
        Called with (done, total) after each peak period.
    execution
        Local worker processes (or a Dask scheduler) over the peak periods, one Tp per task
        (:func:`~seafast.parallel.executor.map_batches`; each Tp's answer is the serial one); None or serial: the peak
        periods one after the other in this process.

    Returns
    -------
    OperabilityResult
        A nonlinear search that fails is reported in its point (``not_converged``), never raised.

    Raises
    ------
    seafast.config.CaseError
        See :func:`~seafast.analyses.operability.family.sea_state_family`.
    """
    tps = [float(t) for t in peak_periods_s]
    fam = sea_state_family(case, tps, settings.master_step_rad_s) if family is None else family
    if execution is not None and execution.mode() != "serial" and len(tps) > 1:
        done: dict[int, OperabilityPoint] = {}
        batches = plan_batches(list(range(len(tps))), execution.worker_count(), batch_size=1)
        for out in map_batches(_points_task, (fam, settings, tps), batches, execution):
            done |= dict(out)
            if progress is not None:
                progress(len(done), len(tps))
        return OperabilityResult(case, tuple(done[i] for i in range(len(tps))), settings)
    points = []
    for i, tp in enumerate(tps):
        points.append(_point(fam, tp, settings))
        if progress is not None:
            progress(i + 1, len(tps))
    return OperabilityResult(case, tuple(points), settings)


def _points_task(shared: tuple[SeaStateFamily, OperabilitySettings, list[float]], batch: list[int]) -> list[tuple[int, OperabilityPoint]]:
    """The points of a batch of peak-period indices (a task of :func:`allowable_sea_states` on worker processes)."""
    family, settings, tps = shared
    return [(i, _point(family, tps[i], settings)) for i in batch]
