"""The motion-analysis branch of ``seafast criteria``: the case's sea state at each heading, beside the default criteria.

Per heading (docs/criteria.md, section "The motion-analysis branch"):

1. the sea state's spectral analysis at that mean heading, as ``seafast seastate`` does it
   (:func:`seafast.analyses.seastate.spectral.spectral_analysis`, with the same model), and its nonlinear design waves
   (:func:`seafast.analyses.seastate.design_wave.sea_state_design_waves`): the vertical-plane most probable maxima of
   F, M_b and sigma_b (``spectral`` and ``design_wave`` rows), still water included;
2. the six motions (:mod:`seafast.analyses.criteria.motion_statistics`): the MPMs of roll, pitch, the heave acceleration
   at the motions' reference and the accelerations at the cargo's aft end, centre of gravity and fore end;
3. quasi-static load cases at the extreme of each governing response, roll, pitch and the vertical acceleration at the
   cargo's centre of gravity, each sign: the governing response at its MPM, every other motion and acceleration its
   expected simultaneous value (the Gaussian sea's regression), about the motions' reference, solved exactly on the
   cradles as the default criteria (:func:`seafast.analyses.criteria.check.solve_load_case`).

The governing case over both branches is the one of largest utilisation.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from seafast.analyses.criteria.check import (
    CriteriaCaseResult,
    CriteriaResult,
    MotionOrigin,
    Verdict,
    cargo_axis_points_m,
    criteria_check,
    solve_load_case,
    with_design,
)
from seafast.analyses.criteria.design import LRFD_COMBINATIONS, UNFACTORED, DesignCheck, LoadCombination, design_checks, factored_value
from seafast.analyses.criteria.load_cases import CriteriaLoadCase, Motion
from seafast.analyses.criteria.motion_statistics import PITCH, ROLL, LinearResponse, SeaStateMotions, sea_state_motions
from seafast.analyses.seastate.design_wave import sea_state_design_waves
from seafast.analyses.seastate.spectral import SpectralAnalysis, spectral_analysis
from seafast.config.modes import DesignFormat
from seafast.config.schema import Case
from seafast.excitation.vessel import VesselCache
from seafast.model.cradle_case import CradleCase, build_cradle_case
from seafast.model.from_case import build_model

__all__ = [
    "MOTION_SOURCE",
    "CARGO_POINTS",
    "MotionMaxima",
    "SeaStateCheck",
    "HeadingCriteria",
    "CriteriaAnalysis",
    "motion_headings_deg",
    "motion_maxima",
    "motion_load_cases",
    "heading_criteria",
    "criteria_analysis",
]

CARGO_POINTS = ("aft", "cog", "fore")
"""The cargo points whose accelerations are reported: its axis at its aft end, centre of gravity and fore end."""

MOTION_SOURCE = "seafast motion analysis: sea_state at the heading, Rayleigh MPM over sea_state.duration_s"


@dataclass(frozen=True)
class MotionMaxima:
    """The most probable maxima of the motions at one heading (Rayleigh, over the sea state's duration).

    Attributes
    ----------
    roll_deg, pitch_deg
        Roll and pitch [deg].
    roll_period_s, pitch_period_s
        Their mean zero-crossing periods [s] (inf without motion).
    heave_acceleration_m_s2
        The heave acceleration at the motions' reference [m/s^2].
    cargo_acceleration_m_s2
        (3, 3) the accelerometer's reading beyond g at the cargo's aft end, centre of gravity and fore end (rows) along
        the ship's x, y, z (columns) [m/s^2].
    """

    roll_deg: float
    roll_period_s: float
    pitch_deg: float
    pitch_period_s: float
    heave_acceleration_m_s2: float
    cargo_acceleration_m_s2: NDArray[np.float64]


@dataclass(frozen=True)
class SeaStateCheck:
    """A vertical-plane most probable maximum of the sea-state analysis checked against the limits.

    Attributes
    ----------
    name
        E.g. ``motion_h135_spectral``.
    heading_deg
        [deg].
    method
        ``spectral`` (linear) or ``design_wave`` (nonlinear), as seastate.csv's rows.
    F_N, M_b_Nm, sigma_b_Pa
        The maxima, still water included [N], [N m], [Pa].
    still_F_N, still_sigma_b_Pa
        The still-water saddle force and stress where the linear extreme is largest [N], [Pa] (the permanent part of a
        factored check).
    converged
        Whether the nonlinear solves converged (True for the linear row).
    utilisation_force, utilisation_stress
        ``F_N / max_saddle_force_N``, ``sigma_b / max_bending_stress_Pa`` [-].
    design
        The checks in the case's design format.
    """

    name: str
    heading_deg: float
    method: str
    F_N: float
    M_b_Nm: float
    sigma_b_Pa: float
    still_F_N: float
    still_sigma_b_Pa: float
    converged: bool
    utilisation_force: float
    utilisation_stress: float
    design: tuple[DesignCheck, DesignCheck]

    @property
    def utilisation(self) -> float:
        return max(self.utilisation_force, self.utilisation_stress)

    @property
    def verdict(self) -> Verdict:
        return Verdict.PASS if self.converged and self.utilisation <= 1.0 else Verdict.FAIL


@dataclass(frozen=True)
class HeadingCriteria:
    """The motion-analysis branch at one heading.

    Attributes
    ----------
    heading_deg
        The sea's mean heading [deg].
    origin
        The motions' reference (the vessel's centre of gravity), the load cases' motion origin.
    maxima
        The motions' MPMs.
    cases
        The quasi-static load cases solved on the cradles.
    sea_state
        The vertical-plane maxima of the sea-state analysis (spectral, and design-wave when computed).
    """

    heading_deg: float
    origin: MotionOrigin
    maxima: MotionMaxima
    cases: tuple[CriteriaCaseResult, ...]
    sea_state: tuple[SeaStateCheck, ...]


@dataclass(frozen=True)
class CriteriaAnalysis:
    """Both branches: the default criteria and the motion analysis per heading (empty when not asked for)."""

    default: CriteriaResult
    headings: tuple[HeadingCriteria, ...]

    def rows(self) -> list[tuple[str, float, Verdict]]:
        """Every case of both branches: ``(name, utilisation, verdict)``."""
        out = [(c.load_case.name, c.utilisation, c.verdict) for c in self.default.cases]
        for h in self.headings:
            out += [(c.load_case.name, c.utilisation, c.verdict) for c in h.cases]
            out += [(s.name, s.utilisation, s.verdict) for s in h.sea_state]
        return out

    @property
    def governing(self) -> tuple[str, float]:
        """The case of the largest utilisation over both branches: ``(name, utilisation)``."""
        name, u, _ = max(self.rows(), key=lambda r: r[1])
        return name, u

    @property
    def verdict(self) -> Verdict:
        return Verdict.PASS if all(v is Verdict.PASS for _, _, v in self.rows()) else Verdict.FAIL


def motion_headings_deg(case: Case) -> tuple[float, ...]:
    """The branch's headings [deg]: ``criteria.motion_analysis.headings_deg``, else the sea state's own; () when off."""
    m = case.criteria.motion_analysis
    if not m.enabled:
        return ()
    return tuple(float(h) for h in m.headings_deg) if m.headings_deg is not None else (float(case.sea_state.heading_deg),)


def _cargo_points(case: Case, cradle: CradleCase, origin: MotionOrigin) -> NDArray[np.float64]:
    """The cargo's axis at its aft end, centre of gravity and fore end from the origin, (3, 3) [m]."""
    beam = cradle.cargo.vertical
    weight = beam.element_mass_per_length_kg_per_m * np.diff(beam.node_x_m)
    x = np.array([0.0, float(weight @ beam.element_mid_x_m / weight.sum()), float(case.cargo.length_m)])
    return cargo_axis_points_m(case, x, origin)


def motion_maxima(motions: SeaStateMotions, points_m: NDArray[np.float64]) -> MotionMaxima:
    """The MPMs of roll, pitch, the heave acceleration and the accelerations at ``points_m`` (3, 3) from the reference."""
    roll, pitch = motions.motion(ROLL), motions.motion(PITCH)
    acc = np.array([[motions.mpm(motions.point_acceleration(p, k)) for k in range(3)] for p in points_m])
    return MotionMaxima(
        roll_deg=math.degrees(motions.mpm(roll)),
        roll_period_s=motions.zero_crossing_period_s(roll),
        pitch_deg=math.degrees(motions.mpm(pitch)),
        pitch_period_s=motions.zero_crossing_period_s(pitch),
        heave_acceleration_m_s2=motions.mpm(motions.motion_acceleration(2)),
        cargo_acceleration_m_s2=acc,
    )


def _conditional_case(motions: SeaStateMotions, name: str, motion: Motion, governing: LinearResponse, level: float) -> CriteriaLoadCase:
    """The load case at ``governing = level``: every motion and acceleration its expected simultaneous value."""

    def at(y: LinearResponse) -> float:
        return motions.conditional(y, governing, level)

    linear = tuple(at(motions.motion_acceleration(k)) for k in range(3))
    # the rotation vector of (roll, pitch bow up, yaw) is (phi, -theta, psi)
    rotation = (at(motions.motion_acceleration(ROLL)), -at(motions.motion_acceleration(PITCH)), at(motions.motion_acceleration(5)))
    return CriteriaLoadCase(
        name=name,
        motion=motion,
        roll_deg=math.degrees(at(motions.motion(ROLL))),
        pitch_deg=math.degrees(at(motions.motion(PITCH))),
        period_s=motions.zero_crossing_period_s(governing),
        heave_acceleration_m_s2=linear[2],
        origin_acceleration_m_s2=(linear[0], linear[1], linear[2]),
        rotation_acceleration_rad_s2=rotation,
        wave_heading_deg=motions.heading_deg,
    )


def motion_load_cases(motions: SeaStateMotions, cog_m: NDArray[np.float64]) -> tuple[CriteriaLoadCase, ...]:
    """Roll, pitch and the vertical acceleration at the cargo's centre of gravity ``cog_m`` (from the reference), each
    at + and - its MPM with the simultaneous rest (responses without variance give no case)."""
    out = []
    for motion, response in (
        (Motion.ROLL, motions.motion(ROLL)),
        (Motion.PITCH, motions.motion(PITCH)),
        (Motion.HEAVE, motions.point_acceleration(cog_m, 2)),
    ):
        mpm = motions.mpm(response)
        if not mpm > 0.0:
            continue
        for sign, label in ((1.0, "+"), (-1.0, "-")):
            name = f"motion_h{motions.heading_deg:g}_{motion.value}{label}"
            out.append(_conditional_case(motions, name, motion, response, sign * mpm))
    return tuple(out)


def _sea_state_checks(case: Case, analysis: SpectralAnalysis, nonlinear: bool) -> tuple[SeaStateCheck, ...]:
    """The spectral (and design-wave) rows of F, M_b, sigma_b at the analysis's heading, checked."""
    ext = analysis.extremes
    still = ext.still_water
    f_still = float(still.saddle_force_N[int(np.argmax(still.saddle_force_N + ext.saddle_force.mpm))])
    s_still = float(np.abs(still.bending_stress_Pa)[int(np.argmax(np.abs(still.bending_stress_Pa) + ext.bending_stress.mpm))])
    rows = [ext.row()]
    if nonlinear:
        rows.append(sea_state_design_waves(analysis).row())
    lim, settings = case.limits, case.criteria.design
    combos: tuple[LoadCombination, ...] = LRFD_COMBINATIONS if settings.format is DesignFormat.LRFD else (UNFACTORED,)
    heading = float(case.sea_state.heading_deg)
    out = []
    for row in rows:
        f, s, ok = float(row["F_N"]), float(row["sigma_b_Pa"]), bool(row["converged"])
        effects = [(c, factored_value(f, f_still, c), factored_value(s, s_still, c), ok) for c in combos]
        out.append(
            SeaStateCheck(
                name=f"motion_h{heading:g}_{row['method']}",
                heading_deg=heading,
                method=str(row["method"]),
                F_N=f,
                M_b_Nm=float(row["M_b_Nm"]),
                sigma_b_Pa=s,
                still_F_N=f_still,
                still_sigma_b_Pa=s_still,
                converged=ok,
                utilisation_force=f / lim.max_saddle_force_N,
                utilisation_stress=s / lim.max_bending_stress_Pa,
                design=design_checks(settings, lim.max_saddle_force_N, effects),
            )
        )
    return tuple(out)


def heading_criteria(case: Case, cradle: CradleCase, heading_deg: float) -> HeadingCriteria:
    """The motion-analysis branch at one mean heading of the case's sea state (module docstring)."""
    at = case.model_copy(update={"sea_state": case.sea_state.model_copy(update={"heading_deg": float(heading_deg)})})
    analysis = spectral_analysis(at, build_model(at))
    motions = sea_state_motions(analysis)
    origin = MotionOrigin(motions.reference_x_m, motions.reference_z_m)
    points = _cargo_points(at, cradle, origin)
    cases = tuple(with_design(at, cradle, solve_load_case(at, cradle, lc, origin), origin) for lc in motion_load_cases(motions, points[1]))
    return HeadingCriteria(
        heading_deg=float(heading_deg),
        origin=origin,
        maxima=motion_maxima(motions, points),
        cases=cases,
        sea_state=_sea_state_checks(at, analysis, at.criteria.motion_analysis.nonlinear),
    )


def criteria_analysis(case: Case, headings_deg: tuple[float, ...] | None = None) -> CriteriaAnalysis:
    """Both branches of ``seafast criteria``: the default criteria and the motion analysis at ``headings_deg`` [deg]
    (None: :func:`motion_headings_deg`).

    Raises
    ------
    ValueError, seafast.config.CaseError
        On a case the cradles or the sea state cannot be built from (naming the key).
    """
    cradle = build_cradle_case(case)
    default = criteria_check(case, cradle)
    headings = motion_headings_deg(case) if headings_deg is None else tuple(float(h) for h in headings_deg)
    if not headings:
        return CriteriaAnalysis(default, ())
    with VesselCache().shared():
        per = tuple(heading_criteria(case, cradle, h) for h in headings)
    return CriteriaAnalysis(default, per)
