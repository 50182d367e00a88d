"""The default motion criteria checked on the cargo in its cradles, each case solved exactly (docs/criteria.md).

For each load case (:mod:`seafast.analyses.criteria.load_cases`) the cargo's mass times the apparent gravity
field is applied to the 3-D cargo on its pads, side stoppers, lashings and axial holds
(:func:`seafast.model.cradle_case.build_cradle_case`), and the statics are solved exactly with the unilateral
contact (:func:`seafast.solvers.transverse_statics.solve_transverse_statics`): the angle's gravity through the
solver's heel and trim, the motion's acceleration as consistent nodal loads ``M p`` (the cargo's mass matrix
times the acceleration field, exact for the field, linear along the cargo). Per case: the saddles' vertical
forces, the pads', stoppers' and lashings' forces, the axial hold, the cargo's bending moment (the resultant of
the vertical and lateral ones) and stress, and the utilisations against ``limits.max_saddle_force_N`` and
``limits.max_bending_stress_Pa``; then (:func:`with_design`) the same checks in the case's design format
(:mod:`seafast.analyses.criteria.design`: LRFD solves each case again under its load combinations) and the friction
credit.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from enum import StrEnum

import numpy as np
from numpy.typing import NDArray

from seafast.analyses.cradle_run import cradle_problem
from seafast.analyses.criteria.design import LRFD_COMBINATIONS, UNFACTORED, DesignCheck, FrictionCredit, design_checks, friction_credit
from seafast.analyses.criteria.load_cases import CriteriaLoadCase, apparent_gravity_m_s2, default_load_cases
from seafast.analyses.criteria.standard import MotionCriteria, select_motion_criteria
from seafast.config.modes import DesignFormat
from seafast.config.schema import Case
from seafast.excitation.vessel_inputs import cargo_axis_height_m, hull_form_of
from seafast.model.beam import bending_moment_line
from seafast.model.cargo3d import gravity_direction
from seafast.model.cradle_case import CradleCase, build_cradle_case
from seafast.solvers.transverse_statics import StaticsOutcome, TransverseStatics, solve_transverse_statics

__all__ = [
    "Verdict",
    "MotionOrigin",
    "CriteriaCaseResult",
    "CriteriaResult",
    "motion_origin",
    "cargo_axis_points_m",
    "criteria_check",
    "solve_load_case",
    "with_design",
]

MOMENT_POINTS_PER_ELEMENT = 4
"""Samples of the bending moment inside each element (its ends included)."""

RESIDUAL_FRACTION = 1e-6
"""A converged statics whose equilibrium residual exceeds this fraction of the cargo's weight is reported as
``not_converged`` (the solver's sign tolerance is relative to the largest engagement, which a very soft lashing's
stretch ``T0 / k`` can make coarse)."""

SMALL_DISPLACEMENT_FRACTION = 0.01
"""The statics are linear in the cargo's displacement (docs/transverse.md): a case whose cargo axis rises at a saddle
above its pads' touching position by more than this fraction of the tube's radius (rolled out over its low-side pads and held
only by its lashings' stretch) has left its cradles, outside the model, and fails."""


class Verdict(StrEnum):
    """A check's verdict."""

    PASS = "pass"
    FAIL = "fail"


@dataclass(frozen=True)
class MotionOrigin:
    """Where the roll and pitch axes cross: the centre of flotation, on the centreline, at the waterline.

    Attributes
    ----------
    x_m
        From the aft perpendicular [m] (the waterplane's centroid).
    z_above_keel_m
        The waterline above the keel, the draught [m].
    """

    x_m: float
    z_above_keel_m: float


@dataclass(frozen=True)
class CriteriaCaseResult:
    """One load case solved and checked.

    Attributes
    ----------
    load_case
        The case.
    statics
        The exact statics (forces, displacements, outcome).
    apparent_gravity_cog_m_s2
        The apparent gravity at the cargo's centre of gravity (on its axis at its centre of mass), ship frame [m/s^2]:
        the field is linear along the axis, so this is the resultant load over the mass.
    saddle_vertical_force_N
        Each saddle's pad pair's push on the cargo along the ship's z [N] (F of the vertical model).
    axial_hold_force_N
        The axial holds' total force on the cargo along x [N] (taken by friction or end stops).
    bending_moment_Nm, bending_stress_Pa
        The largest resultant bending moment [N m] and stress [Pa] along the cargo.
    utilisation_force, utilisation_stress
        ``F_N / max_saddle_force_N`` and ``sigma_b / max_bending_stress_Pa`` [-] (inf when not converged).
    rise_max_m
        The cargo axis's largest rise at a saddle above its pads' touching position [m] (negative: pressed into its
        pads).
    residual_limit_N
        The largest equilibrium residual accepted as converged (:data:`RESIDUAL_FRACTION` of the weight) [N].
    rise_limit_m
        The small-displacement limit of the rise (:data:`SMALL_DISPLACEMENT_FRACTION` of the smallest radius) [m].
    """

    load_case: CriteriaLoadCase
    statics: TransverseStatics
    apparent_gravity_cog_m_s2: NDArray[np.float64]
    saddle_vertical_force_N: NDArray[np.float64]
    axial_hold_force_N: float
    bending_moment_Nm: float
    bending_stress_Pa: float
    utilisation_force: float
    utilisation_stress: float
    rise_max_m: float
    rise_limit_m: float
    residual_limit_N: float
    design: tuple[DesignCheck, DesignCheck] | None = None
    friction: FrictionCredit | None = None

    @property
    def outcome(self) -> str:
        """The statics' outcome; ``large_displacement`` when converged with the cargo risen out of its cradles, else
        ``not_converged`` when converged with a residual above its limit."""
        if self.statics.outcome is StaticsOutcome.CONVERGED:
            if self.rise_max_m > self.rise_limit_m:
                return "large_displacement"
            if self.statics.residual_N > self.residual_limit_N:
                return StaticsOutcome.NOT_CONVERGED.value
        return self.statics.outcome.value

    @property
    def saddle_force_N(self) -> float:
        """F_N: the largest saddle pair's vertical force [N]."""
        return float(np.max(self.saddle_vertical_force_N))

    @property
    def utilisation(self) -> float:
        return max(self.utilisation_force, self.utilisation_stress)

    @property
    def verdict(self) -> Verdict:
        """Pass when solved exactly within small displacements and both utilisations are at most 1."""
        ok = self.outcome == StaticsOutcome.CONVERGED.value and self.utilisation <= 1.0
        return Verdict.PASS if ok else Verdict.FAIL


@dataclass(frozen=True)
class CriteriaResult:
    """The default motion criteria of a case, every load case solved and checked.

    Attributes
    ----------
    criteria
        The standard's row used (by the vessel's length and breadth).
    origin
        The motion axes' origin.
    cargo_axis_aft_m
        The cargo axis's aft end from the motion origin (x, y, z) [m].
    cargo_length_m
        [m].
    cases
        The load cases' results.
    max_saddle_force_N, max_bending_stress_Pa
        The limits checked against [N], [Pa].
    """

    criteria: MotionCriteria
    origin: MotionOrigin
    cargo_axis_aft_m: NDArray[np.float64]
    cargo_length_m: float
    cases: tuple[CriteriaCaseResult, ...]
    max_saddle_force_N: float
    max_bending_stress_Pa: float

    @property
    def governing(self) -> CriteriaCaseResult:
        """The case of the largest utilisation."""
        return max(self.cases, key=lambda c: c.utilisation)

    @property
    def verdict(self) -> Verdict:
        return Verdict.PASS if all(c.verdict is Verdict.PASS for c in self.cases) else Verdict.FAIL


def motion_origin(case: Case) -> MotionOrigin:
    """The centre of flotation (the centroid of the hull form's waterplane) at the waterline."""
    hull = hull_form_of(case)
    x = np.linspace(0.0, hull.length_m, 4001)
    b = np.asarray(hull.breadth_at(x), dtype=float)
    return MotionOrigin(float(np.trapezoid(b * x, x) / np.trapezoid(b, x)), float(case.vessel.draft_m))


def cargo_axis_points_m(case: Case, node_x_m: NDArray[np.float64], origin: MotionOrigin) -> NDArray[np.float64]:
    """The cargo's axis at its nodes from the motion origin, (n, 3) [m]: x from the cargo's position, y its
    transverse position, z its axis height above the keel less the draught."""
    aft = case.cargo_position_m() - 0.5 * case.cargo.length_m
    points = np.zeros((np.size(node_x_m), 3))
    points[:, 0] = aft + np.asarray(node_x_m, dtype=float) - origin.x_m
    points[:, 1] = case.cargo_transverse_position_m()
    points[:, 2] = cargo_axis_height_m(case) - origin.z_above_keel_m
    return points


def _field_load_N(cradle: CradleCase, field: NDArray[np.float64], slope: NDArray[np.float64]) -> NDArray[np.float64]:
    """Consistent nodal loads ``M p`` of a force-per-mass field linear along the cargo: ``p`` its nodal values (n, 3) and
    its slope along the axis (3,) [m/s^2, 1/s^2] (exact for such a field)."""
    cargo = cradle.cargo
    n = cargo.node_count
    p = np.zeros(cargo.dof_count)
    p[0 : 2 * n : 2], p[1 : 2 * n : 2] = field[:, 2], slope[2]
    p[2 * n : 4 * n : 2], p[2 * n + 1 : 4 * n : 2] = field[:, 1], slope[1]
    p[4 * n :] = field[:, 0]
    return np.asarray(cargo.mass @ p, dtype=float)


def _motion_load_N(cradle: CradleCase, load_case: CriteriaLoadCase, points_m: NDArray[np.float64], g: float) -> NDArray[np.float64]:
    """Consistent nodal loads of the motion's part of the field (gravity left to the solver): ``M p`` with p the
    field's nodal values and slopes along the cargo (exact for a field linear along it)."""
    field = apparent_gravity_m_s2(load_case, points_m, g) - g * gravity_direction(load_case.roll_deg, load_case.pitch_deg)
    slope = -np.cross(load_case.angular_acceleration_rad_s2, np.array([1.0, 0.0, 0.0]))
    return _field_load_N(cradle, field, slope)


def _bending(cradle: CradleCase, statics: TransverseStatics, field: NDArray[np.float64]) -> tuple[float, float]:
    """The largest resultant bending moment [N m] and stress [Pa] along the cargo."""
    beam = cradle.cargo.vertical
    n, m = beam.node_count, beam.element_mass_per_length_kg_per_m
    mid = 0.5 * (field[1:] + field[:-1])  # the field at the elements' middles (linear along the cargo)
    q = statics.displacement
    args = (beam.node_x_m, beam.element_bending_stiffness_Nm2)
    _, vertical = bending_moment_line(
        args[0], q[: 2 * n], args[1], load_N_per_m=m * mid[:, 2], points_per_element=MOMENT_POINTS_PER_ELEMENT
    )
    _, lateral = bending_moment_line(
        args[0], q[2 * n : 4 * n], args[1], load_N_per_m=m * mid[:, 1], points_per_element=MOMENT_POINTS_PER_ELEMENT
    )
    moment = np.hypot(vertical, lateral)
    modulus = np.repeat(beam.element_second_moment_m4 / (0.5 * beam.element_outer_diameter_m), MOMENT_POINTS_PER_ELEMENT + 1)
    return float(np.max(moment)), float(np.max(moment / modulus))


def solve_load_case(
    case: Case, cradle: CradleCase, load_case: CriteriaLoadCase, origin: MotionOrigin, factors: tuple[float, float] | None = None
) -> CriteriaCaseResult:
    """One load case on the cradle case, solved exactly and checked against the case's limits.

    ``factors``: ``(gamma_G, gamma_E)``, the load factors of an LRFD combination: the permanent part of the apparent
    gravity (upright gravity ``(0, 0, -g)``) times ``gamma_G``, the environmental part (the rest: the angles' gravity
    components and the motion's acceleration) times ``gamma_E``; the lashings' pretensions are not factored. None: the
    unfactored case. Either way the angle's gravity goes through the solver's heel and trim and the rest of the field is
    applied as consistent nodal loads, so that factors of one give the unfactored case exactly.
    """
    g = case.model.gravity_m_per_s2
    points = cargo_axis_points_m(case, cradle.cargo.node_x_m, origin)
    field = apparent_gravity_m_s2(load_case, points, g)
    if factors is None:
        load = _motion_load_N(cradle, load_case, points, g)
    else:
        gamma_g, gamma_e = factors
        upright = np.array([0.0, 0.0, -g])
        slope = -np.cross(load_case.angular_acceleration_rad_s2, np.array([1.0, 0.0, 0.0]))
        field = gamma_g * upright + gamma_e * (field - upright)
        load = _field_load_N(cradle, field - g * gravity_direction(load_case.roll_deg, load_case.pitch_deg), gamma_e * slope)
    statics = solve_transverse_statics(cradle_problem(cradle, load), load_case.roll_deg, load_case.pitch_deg, gravity_m_per_s2=g)
    return _checked(case, cradle, load_case, origin, statics, field, factors)


def _checked(
    case: Case,
    cradle: CradleCase,
    load_case: CriteriaLoadCase,
    origin: MotionOrigin,
    statics: TransverseStatics,
    field: NDArray[np.float64],
    factors: tuple[float, float] | None,
) -> CriteriaCaseResult:
    """The solved case's forces, moments and utilisations; ``field`` the (factored) apparent gravity at the cargo's nodes
    [m/s^2]."""
    g = case.model.gravity_m_per_s2
    moment, stress = _bending(cradle, statics, field)
    hold = cradle.spring_diagonal_N_per_m * statics.displacement
    axial = float(-np.sum(hold[4 * cradle.cargo.node_count :]))
    converged = statics.outcome is StaticsOutcome.CONVERGED
    force = statics.pair_vertical_force_N
    beam = cradle.cargo.vertical
    weight = beam.element_mass_per_length_kg_per_m * np.diff(beam.node_x_m)
    cog = cargo_axis_points_m(case, np.array([float(weight @ beam.element_mid_x_m / weight.sum())]), origin)[0]
    at_cog = apparent_gravity_m_s2(load_case, cog, g)
    if factors is not None:
        upright = np.array([0.0, 0.0, -g])
        at_cog = factors[0] * upright + factors[1] * (at_cog - upright)
    lim = case.limits
    saddles = np.array([cradle.cargo.node_at(float(x)) for x in cradle.saddle_x_m], dtype=np.intp)
    return CriteriaCaseResult(
        load_case=load_case,
        statics=statics,
        apparent_gravity_cog_m_s2=at_cog,
        saddle_vertical_force_N=force,
        axial_hold_force_N=axial,
        bending_moment_Nm=moment,
        bending_stress_Pa=stress,
        utilisation_force=float(np.max(force)) / lim.max_saddle_force_N if converged else np.inf,
        utilisation_stress=stress / lim.max_bending_stress_Pa if converged else np.inf,
        rise_max_m=float(np.max(statics.displacement[2 * saddles])),
        rise_limit_m=SMALL_DISPLACEMENT_FRACTION * float(np.min(cradle.tube_radius_m)),
        residual_limit_N=RESIDUAL_FRACTION * float(weight.sum()) * g,
    )


def cargo_mass_kg(cradle: CradleCase) -> float:
    """The analysed cargo unit's mass [kg]."""
    beam = cradle.cargo.vertical
    return float(np.sum(beam.element_mass_per_length_kg_per_m * np.diff(beam.node_x_m)))


def with_design(case: Case, cradle: CradleCase, item: CriteriaCaseResult, origin: MotionOrigin) -> CriteriaCaseResult:
    """``item`` with its checks in the case's design format (LRFD: solved again under each ULS combination) and its
    friction credit (docs/criteria.md)."""
    settings = case.criteria.design
    converged = StaticsOutcome.CONVERGED.value
    if settings.format is DesignFormat.LRFD:
        solved = [(c, solve_load_case(case, cradle, item.load_case, origin, (c.gamma_G, c.gamma_E))) for c in LRFD_COMBINATIONS]
    else:
        solved = [(UNFACTORED, item)]
    effects = [(c, r.saddle_force_N, r.bending_stress_Pa, r.outcome == converged) for c, r in solved]
    friction = friction_credit(
        case.criteria.friction.contact,
        case.friction_coefficients(),
        cargo_mass_kg(cradle),
        float(item.apparent_gravity_cog_m_s2[2]),
        item.axial_hold_force_N,
    )
    return replace(item, design=design_checks(settings, case.limits.max_saddle_force_N, effects), friction=friction)


def criteria_check(case: Case, cradle: CradleCase | None = None) -> CriteriaResult:
    """The standard's default motion criteria for the case's vessel, every load case solved and checked.

    Raises
    ------
    ValueError
        On a case the cradles cannot be built from (naming the key).
    """
    cradle = build_cradle_case(case) if cradle is None else cradle
    criteria = select_motion_criteria(case.vessel.length_m, case.vessel.breadth_m)
    origin = motion_origin(case)
    g = case.model.gravity_m_per_s2
    cases = tuple(with_design(case, cradle, solve_load_case(case, cradle, lc, origin), origin) for lc in default_load_cases(criteria, g))
    return CriteriaResult(
        criteria=criteria,
        origin=origin,
        cargo_axis_aft_m=cargo_axis_points_m(case, np.zeros(1), origin)[0],
        cargo_length_m=float(case.cargo.length_m),
        cases=cases,
        max_saddle_force_N=case.limits.max_saddle_force_N,
        max_bending_stress_Pa=case.limits.max_bending_stress_Pa,
    )
