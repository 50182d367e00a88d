"""The design format (LRFD combinations, allowable stress) and the friction credit of ``seafast criteria``."""

from __future__ import annotations

import math

import numpy as np
import pytest

from seafast.analyses.criteria.check import criteria_check, motion_origin, solve_load_case
from seafast.analyses.criteria.design import LRFD_COMBINATIONS, bending_resistance_Pa, friction_credit
from seafast.analyses.criteria.load_cases import CriteriaLoadCase, Motion
from seafast.config import load_case
from seafast.config.modes import ContactSurface, DesignFormat
from seafast.model.cargo3d import gravity_direction
from seafast.model.cradle_case import build_cradle_case


@pytest.fixture(scope="module")
def base():
    case = load_case()
    cradle = build_cradle_case(case)
    return case, cradle, criteria_check(case, cradle)


def _mass_kg(cradle):
    beam = cradle.cargo.vertical
    return float(np.sum(beam.element_mass_per_length_kg_per_m * np.diff(beam.node_x_m)))


def test_allowable_stress_checks_the_unfactored_effects_against_0_6_fy(base):
    case, _, result = base
    assert case.criteria.design.format is DesignFormat.ALLOWABLE_STRESS
    for item in result.cases:
        force, stress = item.design
        assert force.combination == stress.combination == "unfactored"
        assert (force.value, force.resistance) == (item.saddle_force_N, 7.0e6)
        assert stress.value == item.bending_stress_Pa and stress.resistance == pytest.approx(0.6 * 355e6, rel=1e-15)
        assert stress.utilisation == pytest.approx(item.bending_stress_Pa / 213e6, rel=1e-14)
        assert force.passed == (item.saddle_force_N <= 7.0e6)


def _equivalent_unfactored(lc: CriteriaLoadCase, gamma_g: float, gamma_e: float, g: float) -> CriteriaLoadCase:
    """The factored field ``gamma_G g0 + gamma_E (g_app - g0)`` written as an unfactored case at the same angles: the
    origin acceleration and angular acceleration chosen so that ``g dir(phi, theta) - a0' - alpha' x r`` is that field."""
    g0 = np.array([0.0, 0.0, -g])
    ship = g * gravity_direction(lc.roll_deg, lc.pitch_deg)
    a0 = (1.0 - gamma_e) * ship - (gamma_g - gamma_e) * g0 + gamma_e * lc.linear_acceleration_m_s2
    alpha = gamma_e * lc.angular_acceleration_rad_s2
    return CriteriaLoadCase(
        "equivalent",
        lc.motion,
        lc.roll_deg,
        lc.pitch_deg,
        lc.period_s,
        float(a0[2]),
        tuple(float(v) for v in a0),
        tuple(float(v) for v in alpha),
    )


@pytest.mark.parametrize("combination", LRFD_COMBINATIONS, ids=lambda c: c.name)
def test_an_lrfd_combination_is_the_factored_field_solved_exactly(base, combination):
    """Each default case under a ULS combination against the same field built by hand as an upright unfactored case
    (1e-8 of the largest pad force): forces, stress, outcome."""
    case, cradle, result = base
    origin = motion_origin(case)
    g = case.model.gravity_m_per_s2
    factors = (combination.gamma_G, combination.gamma_E)
    for item in result.cases:
        factored = solve_load_case(case, cradle, item.load_case, origin, factors)
        hand = solve_load_case(case, cradle, _equivalent_unfactored(item.load_case, *factors, g), origin)
        assert factored.outcome == hand.outcome
        np.testing.assert_allclose(factored.apparent_gravity_cog_m_s2, hand.apparent_gravity_cog_m_s2, rtol=0, atol=1e-12)
        if factored.outcome != "converged":
            continue
        scale = float(np.max(hand.statics.pad_force_N))
        np.testing.assert_allclose(factored.statics.pad_force_N, hand.statics.pad_force_N, rtol=0, atol=1e-8 * scale)
        assert factored.bending_stress_Pa == pytest.approx(hand.bending_stress_Pa, rel=1e-8)


def test_unit_factors_give_the_unfactored_case(base):
    case, cradle, result = base
    origin = motion_origin(case)
    for item in result.cases:
        same = solve_load_case(case, cradle, item.load_case, origin, (1.0, 1.0))
        assert same.saddle_force_N == pytest.approx(item.saddle_force_N, rel=1e-12)
        assert same.bending_stress_Pa == pytest.approx(item.bending_stress_Pa, rel=1e-12)
        np.testing.assert_allclose(same.apparent_gravity_cog_m_s2, item.apparent_gravity_cog_m_s2, rtol=0, atol=1e-13)


def test_lrfd_takes_the_larger_combination_against_fy_over_gamma_m():
    case = load_case(overrides={"criteria.design.format": "lrfd"})
    cradle = build_cradle_case(case)
    result = criteria_check(case, cradle)
    assert bending_resistance_Pa(case.criteria.design) == pytest.approx(355e6 / 1.15, rel=1e-15)
    origin = motion_origin(case)
    item = next(c for c in result.cases if c.load_case.name == "pitch-12.5_heave+")
    solved = [solve_load_case(case, cradle, item.load_case, origin, (c.gamma_G, c.gamma_E)) for c in LRFD_COMBINATIONS]
    force, stress = item.design
    k = int(np.argmax([s.saddle_force_N for s in solved]))
    assert force.combination == LRFD_COMBINATIONS[k].name and force.value == solved[k].saddle_force_N
    assert stress.value == max(s.bending_stress_Pa for s in solved)
    assert stress.utilisation == pytest.approx(stress.value / (355e6 / 1.15), rel=1e-14)
    # b) 1.0 G + 1.3 E against the unfactored: the environmental part of this case adds load, so b) exceeds it
    assert solved[1].saddle_force_N > item.saddle_force_N


def _hand_normal_m_s2(case, item, origin):
    """g cos(angle) + a_h - omega^2 angle r at the CoG, the design rules' vertical reading (docs/criteria.md)."""
    lc = item.load_case
    g = case.model.gravity_m_per_s2
    w2 = (2.0 * math.pi / lc.period_s) ** 2
    if lc.motion is Motion.ROLL:
        phi = math.radians(lc.roll_deg)
        return g * math.cos(phi) + lc.heave_acceleration_m_s2 - w2 * phi * case.cargo_transverse_position_m()
    theta = math.radians(lc.pitch_deg)
    beam = build_cradle_case(case).cargo.vertical
    m = beam.element_mass_per_length_kg_per_m * np.diff(beam.node_x_m)
    x_cog = case.cargo_position_m() - 0.5 * case.cargo.length_m + float(m @ beam.element_mid_x_m / m.sum()) - origin.x_m
    return g * math.cos(theta) + lc.heave_acceleration_m_s2 - w2 * theta * x_cog


def test_friction_on_timber_is_mu_times_the_weight_reduced_by_the_vertical_acceleration():
    case = load_case(overrides={"criteria.friction.contact": "steel_on_timber", "seafastening.friction_coefficient": [0.25, 0.2, 0.3]})
    cradle = build_cradle_case(case)
    mass = _mass_kg(cradle)
    origin = motion_origin(case)
    for item in criteria_check(case, cradle).cases:
        f = item.friction
        normal = mass * _hand_normal_m_s2(case, item, origin)
        assert f.counted and f.coefficient == 0.2  # the smallest of the saddles'
        assert f.normal_force_N == pytest.approx(normal, rel=1e-12)
        assert f.capacity_N == pytest.approx(0.2 * normal, rel=1e-12)
        assert f.axial_unresisted_N == pytest.approx(max(abs(item.axial_hold_force_N) - 0.2 * normal, 0.0), rel=1e-12, abs=1e-6)
    pitch = next(c for c in criteria_check(case, cradle).cases if c.load_case.name == "pitch+12.5_heave-")
    assert pitch.friction.axial_unresisted_N > 1e6  # 3.5 MN along the axis, 1.4 MN of friction


def test_no_friction_is_counted_steel_on_steel_or_without_a_coefficient(base):
    case, cradle, result = base
    assert case.criteria.friction.contact is ContactSurface.STEEL_ON_STEEL
    for item in result.cases:
        assert not item.friction.counted and item.friction.capacity_N == 0.0
        assert item.friction.axial_unresisted_N == abs(item.axial_hold_force_N)
        assert "steel on steel" in item.friction.reason
    steel = criteria_check(load_case(overrides={"seafastening.friction_coefficient": 0.3}), cradle)
    assert all(not c.friction.counted and c.friction.coefficient == 0.3 for c in steel.cases)
    none = friction_credit(ContactSurface.STEEL_ON_RUBBER, None, 1e6, -9.81, 5e5)
    assert not none.counted and "friction_coefficient" in none.reason and none.axial_unresisted_N == 5e5
    lifted = friction_credit(ContactSurface.STEEL_ON_RUBBER, (0.5,), 1e6, 0.2, 5e5)
    assert not lifted.counted and lifted.normal_force_N == pytest.approx(-2e5) and lifted.capacity_N == 0.0
    held = friction_credit(ContactSurface.STEEL_ON_RUBBER, (0.5,), 1e6, -9.81, -4e6)
    assert held.counted and held.capacity_N == pytest.approx(4.905e6) and held.axial_unresisted_N == 0.0
