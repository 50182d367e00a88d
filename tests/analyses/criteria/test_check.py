"""The default motion criteria on the cargo in its cradles against the closed forms of a two-saddle tube."""

from __future__ import annotations

import math

import numpy as np
import pytest

from seafast.analyses.criteria.check import cargo_axis_points_m, criteria_check, motion_origin
from seafast.analyses.criteria.load_cases import apparent_gravity_m_s2
from seafast.config import load_case
from seafast.model.cradle_case import build_cradle_case
from seafast.solvers.transverse_statics import StaticsOutcome

TWO_SADDLES = {"seafastening.saddle_positions_m": [14.8, 59.2]}


def _closed_form_pushes(case, result, item):
    """Each saddle's push (lateral, vertical) [N] by the lever rule on the load field and the lashings' pulls."""
    cradle = build_cradle_case(case)
    beam = cradle.cargo.vertical
    m = float(beam.element_mass_per_length_kg_per_m[0])
    L = case.cargo.length_m
    ends = cargo_axis_points_m(case, np.array([0.0, L]), motion_origin(case))
    field = apparent_gravity_m_s2(item.load_case, ends, case.model.gravity_m_per_s2)  # linear along the cargo
    a, b = field[0], (field[1] - field[0]) / L  # field = a + b x
    force = m * (a * L + b * L**2 / 2)
    moment = m * (a * L**2 / 2 + b * L**3 / 3)  # about the aft end
    x1, x2 = cradle.saddle_x_m
    pull = np.zeros((2, 3))
    for wire, tension in zip(cradle.lashings, item.statics.lashing_tension_N, strict=True):
        pull[0 if wire.cargo_point_m[0] == x1 else 1] += tension * wire.direction
    force_total = force + pull.sum(axis=0)
    moment_total = moment + x1 * pull[0] + x2 * pull[1]
    r2 = -(moment_total - x1 * force_total) / (x2 - x1)
    r1 = -force_total - r2
    return np.array([r1[1:], r2[1:]])  # (y, z) per saddle


def _pads(push, alpha_deg):
    a = math.radians(alpha_deg)
    h, v = push[:, 0], push[:, 1]
    return np.column_stack([0.5 * (v / math.cos(a) - h / math.sin(a)), 0.5 * (v / math.cos(a) + h / math.sin(a))])


@pytest.mark.parametrize("alpha_deg", [45.0, 60.0])
def test_two_saddle_tube_pad_and_lashing_forces_against_the_closed_form(alpha_deg):
    case = load_case(overrides={**TWO_SADDLES, "seafastening.saddle_contact_angle_deg": alpha_deg})
    result = criteria_check(case)
    lashing = case.seafastening.lashing
    t0 = lashing.pretension_N / (2 * 2 * math.sin(math.radians(lashing.angle_deg)))
    for item in result.cases:
        st = item.statics
        assert st.outcome is StaticsOutcome.CONVERGED, item.load_case.name
        push = _closed_form_pushes(case, result, item)
        scale = float(np.max(np.abs(push)))
        assert np.allclose(np.column_stack([st.pair_lateral_force_N, st.pair_vertical_force_N]), push, rtol=0, atol=1e-8 * scale)
        assert np.allclose(st.pad_force_N, _pads(push, alpha_deg), rtol=0, atol=1e-8 * scale), item.load_case.name
        assert np.allclose(st.lashing_tension_N, t0, rtol=0, atol=1e-2 * t0)  # taut, near their pretension (mm of stretch)
        assert item.outcome == "converged" and item.rise_max_m < 0.0  # pressed into its pads
        assert item.saddle_force_N == pytest.approx(float(np.max(push[:, 1])), rel=1e-8)
        # the axial holds take the field's resultant along the cargo
        assert item.axial_hold_force_N == pytest.approx(-_axial_resultant(case, item), rel=1e-8, abs=1e-6 * scale)


def _axial_resultant(case, item):
    L = case.cargo.length_m
    ends = cargo_axis_points_m(case, np.array([0.0, L]), motion_origin(case))
    mass = build_cradle_case(case).cargo.vertical.mass_kg
    return mass * float(np.mean(apparent_gravity_m_s2(item.load_case, ends, case.model.gravity_m_per_s2)[:, 0]))


def test_roll_bending_moment_of_the_uniform_field_against_the_closed_form():
    case = load_case(overrides=TWO_SADDLES)
    result = criteria_check(case)
    cradle = build_cradle_case(case)
    beam = cradle.cargo.vertical
    m = float(beam.element_mass_per_length_kg_per_m[0])
    L = case.cargo.length_m
    overhang, span = 14.8, 59.2 - 14.8
    for item in (c for c in result.cases if c.load_case.motion.value == "roll"):
        q = m * np.hypot(*item.apparent_gravity_cog_m_s2[1:])  # the field is the same along the cargo in roll
        moment = q * max(overhang**2 / 2, span**2 / 8 - overhang**2 / 2)
        # the lashings pull at the saddles: no moment of their own; the section's modulus I / (D / 2)
        assert item.bending_moment_Nm == pytest.approx(moment, rel=1e-6)
        modulus = float(beam.element_second_moment_m4[0] / (0.5 * beam.element_outer_diameter_m[0]))
        assert item.bending_stress_Pa == pytest.approx(moment / modulus, rel=1e-6)
        assert L == 74.0


def test_a_lifting_pad_onto_the_stoppers_and_a_mechanism_without_them():
    overrides = {**TWO_SADDLES, "seafastening.saddle_contact_angle_deg": 20.0}
    free = criteria_check(load_case(overrides=overrides))
    roll = [c for c in free.cases if c.load_case.motion.value == "roll"]
    tilted = [c for c in roll if abs(c.apparent_gravity_cog_m_s2[1] / c.apparent_gravity_cog_m_s2[2]) > 1.05 * math.tan(math.radians(20.0))]
    assert len(tilted) == 3  # roll-20 with heave up leans 0.3597 < tan(20 deg) = 0.364: both pads stay
    # the high-side pads lift and only the lashings' stretch holds the cargo, metres out of its cradles: outside the
    # small-displacement statics, a fail
    assert all(c.outcome in ("mechanism", "large_displacement") and c.verdict.value == "fail" for c in tilted)
    assert all(c.rise_max_m > 1.0 for c in tilted if c.outcome == "large_displacement")
    assert free.verdict.value == "fail"
    held_case = load_case(
        overrides={**overrides, "seafastening.side_stopper.gap_m": 0.01, "seafastening.side_stopper.stiffness_N_per_m": 1e8}
    )
    held = criteria_check(held_case)
    alpha = math.radians(20.0)
    names = {c.load_case.name for c in tilted}
    for item in (c for c in held.cases if c.load_case.name in names):
        st = item.statics
        assert st.outcome is StaticsOutcome.CONVERGED and item.outcome == "converged"
        push = _closed_form_pushes(held_case, held, item)
        h, v = push[:, 0], push[:, 1]
        low = 1 if h[0] > 0 else 0  # pushed to port by the restraints: the starboard (low) pad and stopper hold it
        assert np.all(st.pad_force_N[:, 1 - low] == 0.0)  # the high-side pads lift, exactly
        scale = float(np.max(np.abs(push)))
        assert np.allclose(st.pad_force_N[:, low], v / math.cos(alpha), rtol=0, atol=1e-8 * scale)
        stopper = st.stopper_force_N.reshape(2, 2)  # per saddle: port, starboard
        assert np.allclose(stopper[:, low], np.abs(h) - v * math.tan(alpha), rtol=0, atol=1e-8 * scale)
        assert np.all(stopper[:, 1 - low] == 0.0)
        assert item.utilisation < 1.0 and item.verdict.value == "pass"


def test_three_saddles_with_stoppers_balance_the_fields_resultant_force_and_moment():
    """Statically indeterminate: the restraints' forces and moments against the load field's, integrated apart."""
    case = load_case(overrides={"seafastening.side_stopper.gap_m": 0.001, "seafastening.side_stopper.stiffness_N_per_m": 5e8})
    result = criteria_check(case)
    cradle = build_cradle_case(case)
    beam = cradle.cargo.vertical
    x = beam.node_x_m
    # the field on a fine grid, integrated by the midpoint rule (exact for a field linear along a uniform tube)
    xs = np.linspace(0.0, case.cargo.length_m, 74001)
    mid = 0.5 * (xs[1:] + xs[:-1])
    dm = float(beam.element_mass_per_length_kg_per_m[0]) * np.diff(xs)
    stops = np.repeat(cradle.saddle_x_m, 2)
    assert sum(c.statics.stopper_force_N.max() > 0.0 for c in result.cases) == 4  # every roll meets a stopper
    for item in result.cases:
        st = item.statics
        assert item.outcome == "converged", item.load_case.name
        field = apparent_gravity_m_s2(item.load_case, cargo_axis_points_m(case, mid, motion_origin(case)), case.model.gravity_m_per_s2)
        load = dm @ field
        load_moment = np.array([-(dm * mid) @ field[:, 2], (dm * mid) @ field[:, 1]])  # about the aft end: -sum x f_z, sum x f_y
        stopper_y = st.stopper_force_N * np.tile([-1.0, 1.0], len(cradle.saddle_x_m))  # a port stopper pushes to starboard
        pull = np.array([t * w.direction for t, w in zip(st.lashing_tension_N, cradle.lashings, strict=True)])
        xw = np.array([w.cargo_point_m[0] for w in cradle.lashings])
        reaction = np.array(
            [
                item.axial_hold_force_N + pull[:, 0].sum(),
                st.pair_lateral_force_N.sum() + stopper_y.sum() + pull[:, 1].sum(),
                st.pair_vertical_force_N.sum() + pull[:, 2].sum(),
            ]
        )
        reaction_moment = np.array(
            [
                -(cradle.saddle_x_m @ st.pair_vertical_force_N + xw @ pull[:, 2]),
                cradle.saddle_x_m @ st.pair_lateral_force_N + stops @ stopper_y + xw @ pull[:, 1],
            ]
        )
        scale = float(np.linalg.norm(load))
        assert np.allclose(reaction, -load, rtol=0, atol=1e-8 * scale), item.load_case.name
        assert np.allclose(reaction_moment, -load_moment, rtol=0, atol=1e-8 * scale * x[-1]), item.load_case.name


def test_a_coarse_solve_is_not_reported_converged():
    """A 1 N/m lashing stretches T0 / k = 1.5e5 m at rest, which loosens the solver's sign tolerance (relative to the
    largest engagement): a converged outcome must still hold equilibrium to 1e-6 of the weight."""
    case = load_case(
        overrides={**TWO_SADDLES, "seafastening.lashing.stiffness_N_per_m": 1.0, "seafastening.saddle_contact_angle_deg": 35.0}
    )
    result = criteria_check(case)
    weight = build_cradle_case(case).cargo.vertical.mass_kg * case.model.gravity_m_per_s2
    assert any(c.statics.residual_N > 1e-6 * weight for c in result.cases)  # the solver's own word is not enough here
    for item in result.cases:
        if item.statics.residual_N > 1e-6 * weight:
            assert item.outcome in ("not_converged", "large_displacement") and item.verdict.value == "fail"
        if item.outcome == "converged":
            assert item.statics.residual_N <= 1e-6 * weight
