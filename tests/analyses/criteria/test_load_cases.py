"""The default motion criteria's table, selection, load cases and accelerations against hand formulas."""

from __future__ import annotations

import math

import numpy as np
import pytest

from seafast.analyses.criteria.load_cases import Motion, apparent_gravity_m_s2, default_load_cases
from seafast.analyses.criteria.standard import LARGE_BARGE, SMALL_BARGE, select_motion_criteria

G = 9.81


def test_roll_20_deg_over_10_s_gives_0_138_rad_s2():
    alpha = LARGE_BARGE.roll_angular_acceleration_rad_s2()
    assert alpha == pytest.approx(math.radians(20.0) * (2 * math.pi / 10.0) ** 2, rel=1e-14)
    assert alpha == pytest.approx(0.138, abs=5e-4)
    assert LARGE_BARGE.pitch_angular_acceleration_rad_s2() == pytest.approx(0.0862, abs=5e-4)
    assert SMALL_BARGE.roll_angular_acceleration_rad_s2() == pytest.approx(0.1723, abs=5e-4)


@pytest.mark.parametrize(
    ("length_m", "breadth_m", "expected"),
    [
        (171.0, 42.0, LARGE_BARGE),
        (76.5, 23.5, LARGE_BARGE),
        (60.0, 20.0, SMALL_BARGE),
        (120.0, 20.0, SMALL_BARGE),
        (70.0, 30.0, SMALL_BARGE),
    ],
)
def test_selection_by_size(length_m, breadth_m, expected):
    assert select_motion_criteria(length_m, breadth_m) is expected


def test_selection_refuses_a_bad_size():
    with pytest.raises(ValueError, match="allowed finite values > 0"):
        select_motion_criteria(-1.0, 20.0)


def test_eight_cases_each_sign_with_heave_up_and_down():
    cases = default_load_cases(LARGE_BARGE, G)
    assert len(cases) == 8 and len({c.name for c in cases}) == 8
    combos = {(c.motion, math.copysign(1, c.roll_deg + c.pitch_deg), math.copysign(1, c.heave_acceleration_m_s2)) for c in cases}
    assert len(combos) == 8
    for c in cases:
        assert abs(c.heave_acceleration_m_s2) == pytest.approx(0.2 * G, rel=1e-15)
        if c.motion is Motion.ROLL:
            assert (abs(c.roll_deg), c.pitch_deg, c.period_s, c.heading_deg) == (20.0, 0.0, 10.0, 90.0)
        else:
            assert (c.roll_deg, abs(c.pitch_deg), c.period_s, c.heading_deg) == (0.0, 12.5, 10.0, 180.0)


# the base case's cargo ends and middle from the motion origin (centre of flotation at the waterline) [m]
ENDS = np.array([[-18.2, 15.75, 10.5], [55.8, 15.75, 10.5], [18.8, 15.75, 10.5]])


def test_roll_apparent_gravity_against_the_hand_formula():
    roll_up = next(c for c in default_load_cases(LARGE_BARGE, G) if c.name == "roll+20_heave+")
    w2phi = (2 * math.pi / 10) ** 2 * math.radians(20)
    phi = math.radians(20)
    got = apparent_gravity_m_s2(roll_up, ENDS, G)
    for r, a in zip(ENDS, got, strict=True):
        # across: gravity's component to starboard plus the roll's tangential acceleration above the axis
        assert a[1] == pytest.approx(-G * math.sin(phi) - w2phi * r[2], rel=1e-13)
        # vertical: gravity's cosine, the roll's acceleration at the lever y (port side rises back), heave up
        assert a[2] == pytest.approx(-G * math.cos(phi) + w2phi * r[1] - 0.2 * G, rel=1e-13)
        assert a[0] == pytest.approx(0.0, abs=1e-14)
    # 20 deg and 10.5 m above the roll axis: 3.355 + 1.447 = 4.802 m/s^2 to starboard
    assert got[2, 1] == pytest.approx(-4.802, abs=5e-4)


def test_pitch_apparent_gravity_at_the_ends_tangential_and_normal_parts():
    bow_up = next(c for c in default_load_cases(LARGE_BARGE, G) if c.name == "pitch+12.5_heave-")
    theta = math.radians(12.5)
    alpha = (2 * math.pi / 10) ** 2 * theta
    got = apparent_gravity_m_s2(bow_up, ENDS, G)
    g_ship = G * np.array([-math.sin(theta), 0.0, -math.cos(theta)])
    for r, a in zip(ENDS, got, strict=True):
        assert a[0] == pytest.approx(-G * math.sin(theta) - alpha * r[2], rel=1e-13)
        assert a[2] == pytest.approx(-G * math.cos(theta) + alpha * r[0] + 0.2 * G, rel=1e-13)
        rotation = g_ship + np.array([0.0, 0.0, 0.2 * G]) - a  # alpha x r (heave down: a_h = -0.2 g)
        lever = np.array([r[0], 0.0, r[2]])  # the lever arm about the pitch axis (y)
        # at the extreme the angular velocity is zero: no normal (centripetal) part, the tangential part is alpha |r|
        assert float(rotation @ lever) == pytest.approx(0.0, abs=1e-12 * alpha * float(lever @ lever))
        assert float(np.linalg.norm(rotation)) == pytest.approx(alpha * float(np.linalg.norm(lever)), rel=1e-13)
    # bow up at its extreme, about to fall: the fore end accelerates down (lighter), the aft end up (heavier)
    assert got[1, 2] - got[0, 2] == pytest.approx(alpha * (ENDS[1, 0] - ENDS[0, 0]), rel=1e-13)
    assert got[1, 2] > got[0, 2]
