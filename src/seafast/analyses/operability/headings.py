"""Allowable sea states per wave heading: the per-peak-period analysis once per heading, and the governing heading.

For each heading beta (180 deg = head seas, 90 = beam seas from starboard, 0 = following seas;
:mod:`seafast.config.schema`) the case is rebuilt with its sea state at that heading
(:func:`case_at_heading`, validated by the loader) and analysed by
:func:`~seafast.analyses.operability.allowable.allowable_sea_states` (or any function of the same
shape, injected). A heading whose analysis raises is recorded with its error (its allowable Hs NaN,
governing ``failed``) and the others still run; an invalid case (:class:`~seafast.config.CaseError`)
is bad input and is raised. The **governing heading** at a peak period is the heading of the
smallest allowable Hs there (the first in the order given among equal ones), and overall the
heading and Tp of the smallest allowable Hs of all; failed headings and NaN points take no part.
"""

from __future__ import annotations

import logging
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from enum import StrEnum

from seafast.analyses.operability.allowable import OperabilityPoint, OperabilityResult, OperabilitySettings, allowable_sea_states
from seafast.config.loader import CaseError, case_from_mapping
from seafast.config.schema import Case, max_significant_height_m
from seafast.parallel.executor import error_text

__all__ = [
    "HEADING_FAILED",
    "AllowableModel",
    "HeadingAnalysis",
    "CaseAtHeading",
    "HeadingOperability",
    "GoverningHeading",
    "HeadingOperabilityResult",
    "case_at_heading",
    "check_headings",
    "allowable_per_heading",
]

logger = logging.getLogger(__name__)

HEADING_FAILED = "failed"
"""The governing_* value of every peak period of a heading whose analysis raised."""

HeadingAnalysis = Callable[[Case, Sequence[float], OperabilitySettings], OperabilityResult]
"""``(case at one heading, peak periods [s], settings) -> OperabilityResult``: the analysis of one heading."""

CaseAtHeading = Callable[[Case, float], Case]
"""``(case, heading [deg]) -> the case with its sea state at that heading``."""


class AllowableModel(StrEnum):
    """Which allowable Hs: the linear spectral MPMs or the nonlinear design-wave MPMs."""

    LINEAR = "linear"
    NONLINEAR = "nonlinear"


@dataclass(frozen=True)
class HeadingOperability:
    """The allowable sea states at one heading.

    Attributes
    ----------
    heading_deg
        Wave heading beta [deg] as given (360 is analysed as 0).
    result
        Its allowable Hs per peak period; for a failed heading every point NaN, governing ``failed``.
    error
        ``Type: message`` of the exception its analysis raised; None when it ran.
    """

    heading_deg: float
    result: OperabilityResult
    error: str | None = None

    @property
    def failed(self) -> bool:
        """Its analysis raised."""
        return self.error is not None


@dataclass(frozen=True)
class GoverningHeading:
    """The heading with the smallest allowable Hs (at one peak period, or of all).

    Attributes
    ----------
    heading_deg
        Wave heading [deg].
    peak_period_s
        Tp [s] of that smallest allowable Hs.
    hs_allowable_m
        The smallest allowable Hs [m].
    governing
        What limits it there: ``saddle_force``, ``bending_stress``, off head seas a cradle limit (``pad_force``,
        ``lashing_tension``, ``transverse_slip``), or ``steepness``.
    """

    heading_deg: float
    peak_period_s: float
    hs_allowable_m: float
    governing: str


def _hs_and_limit(point: OperabilityPoint, model: AllowableModel) -> tuple[float, str]:
    if model is AllowableModel.LINEAR:
        return point.hs_allowable_linear_m, point.governing_linear
    return point.hs_allowable_nonlinear_m, point.governing_nonlinear


@dataclass(frozen=True)
class HeadingOperabilityResult:
    """Allowable sea states over headings and peak periods (what ``seafast operability --headings`` writes)."""

    case: Case
    headings: tuple[HeadingOperability, ...]
    peak_periods_s: tuple[float, ...]
    settings: OperabilitySettings

    @property
    def headings_deg(self) -> tuple[float, ...]:
        """The headings [deg], in the order given."""
        return tuple(h.heading_deg for h in self.headings)

    @property
    def converged(self) -> bool:
        """Every heading ran and every nonlinear search converged."""
        return all(not h.failed and h.result.converged for h in self.headings)

    def governing_per_peak_period(self, model: AllowableModel = AllowableModel.NONLINEAR) -> tuple[GoverningHeading | None, ...]:
        """Per peak period, the heading of the smallest allowable Hs (None: no heading has one there)."""
        out: list[GoverningHeading | None] = []
        for i, tp in enumerate(self.peak_periods_s):
            best: GoverningHeading | None = None
            for h in self.headings:
                hs, limit = _hs_and_limit(h.result.points[i], model)
                if h.failed or not math.isfinite(hs):
                    continue
                if best is None or hs < best.hs_allowable_m:
                    best = GoverningHeading(h.heading_deg, tp, hs, limit)
            out.append(best)
        return tuple(out)

    def governing_heading(self, model: AllowableModel = AllowableModel.NONLINEAR) -> GoverningHeading | None:
        """The heading and peak period of the smallest allowable Hs of all (the first among equal ones)."""
        best: GoverningHeading | None = None
        for g in self.governing_per_peak_period(model):
            if g is not None and (best is None or g.hs_allowable_m < best.hs_allowable_m):
                best = g
        return best


def check_headings(headings_deg: Sequence[float]) -> list[float]:
    """The headings as floats [deg]; ValueError naming the value unless each is finite in [0, 360] and none repeats."""
    out = [float(h) for h in headings_deg]
    if not out:
        raise ValueError("headings_deg: empty; allowed: one or more headings in [0, 360] deg")
    for h in out:
        if not (math.isfinite(h) and 0.0 <= h <= 360.0):
            raise ValueError(f"heading {h:g} deg: allowed 0 <= heading <= 360 (180 = head seas, 90 = beam seas)")
    seen: set[float] = set()
    for h in out:
        if h % 360.0 in seen:
            raise ValueError(f"heading {h:g} deg given twice (360 is 0); allowed: each heading once")
        seen.add(h % 360.0)
    return out


def case_at_heading(case: Case, heading_deg: float) -> Case:
    """The case with its sea state's waves at ``heading_deg`` [deg] (360 is 0), validated as a case file would be.

    Sets ``sea_state.heading_deg``.

    Raises
    ------
    seafast.config.CaseError
        The heading is not allowed by the schema.
    """
    heading = float(heading_deg) % 360.0
    return case_from_mapping(case.model_dump(mode="json"), f"(heading {heading:g} deg)", {"sea_state.heading_deg": heading})


def _failed_result(case: Case, peak_periods_s: Sequence[float], settings: OperabilitySettings) -> OperabilityResult:
    """The record of a heading whose analysis raised: every Hs NaN, governing ``failed``, not converged."""
    nan = math.nan
    points = tuple(
        OperabilityPoint(
            peak_period_s=tp,
            hs_allowable_linear_m=nan,
            hs_allowable_nonlinear_m=nan,
            hs_uplift_onset_m=nan,
            governing_linear=HEADING_FAILED,
            governing_nonlinear=HEADING_FAILED,
            hs_max_steepness_m=max_significant_height_m(tp, case.model.gravity_m_per_s2),
            hs_force_linear_m=nan,
            hs_stress_linear_m=nan,
            hs_force_nonlinear_m=nan,
            hs_stress_nonlinear_m=nan,
            converged=False,
            evaluations=0,
        )
        for tp in peak_periods_s
    )
    return OperabilityResult(case, points, settings)


def _analyse_heading(
    case: Case, heading: float, tps: list[float], settings: OperabilitySettings, analyse: HeadingAnalysis, at_heading: CaseAtHeading
) -> HeadingOperability:
    case_h = at_heading(case, heading)  # a CaseError here is bad input: raised
    try:
        result = analyse(case_h, tps, settings)
    except CaseError:
        raise
    except Exception as exc:  # noqa: BLE001 - one heading's failure is recorded, the other headings still run
        logger.warning("operability: heading %g deg failed: %s", heading, error_text(exc))
        return HeadingOperability(heading, _failed_result(case_h, tps, settings), error_text(exc))
    got = [p.peak_period_s for p in result.points]
    if got != tps:
        raise ValueError(f"heading {heading:g} deg: the analysis returned peak periods {got}, not the {tps} asked for")
    return HeadingOperability(heading, result)


def allowable_per_heading(
    case: Case,
    headings_deg: Sequence[float],
    peak_periods_s: Sequence[float],
    settings: OperabilitySettings = OperabilitySettings(),
    *,
    analyse: HeadingAnalysis = allowable_sea_states,
    at_heading: CaseAtHeading = case_at_heading,
    progress: Callable[[int, int], None] | None = None,
) -> HeadingOperabilityResult:
    """Allowable Hs per heading and peak period, linear and nonlinear (module docstring).

    Parameters
    ----------
    case
        The case (its sea state's heading is replaced by each of ``headings_deg``).
    headings_deg
        Wave headings [deg] in [0, 360] (:func:`check_headings`); 180 = head seas, 90 = beam seas.
    peak_periods_s
        Tp values [s], the same at every heading.
    settings
        Numerical settings of the search.
    analyse
        The analysis of one heading: ``analyse(case at the heading, peak periods, settings)``.
    at_heading
        The case at one heading (:func:`case_at_heading`).
    progress
        Called with (done, total) after each heading.

    Returns
    -------
    HeadingOperabilityResult
        One :class:`HeadingOperability` per heading, in the order given; a heading whose analysis
        raised carries its error, never raised.

    Raises
    ------
    ValueError
        A heading outside [0, 360] or given twice.
    seafast.config.CaseError
        The case is invalid at a heading, or its analysis refuses it (e.g. a heading it does not support).
    """
    headings = check_headings(headings_deg)
    tps = [float(t) for t in peak_periods_s]
    out = []
    for i, heading in enumerate(headings):
        out.append(_analyse_heading(case, heading, tps, settings, analyse, at_heading))
        if progress is not None:
            progress(i + 1, len(headings))
    return HeadingOperabilityResult(case, tuple(out), tuple(tps), settings)
