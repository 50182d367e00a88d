"""The cradle elements (pad pairs, side stoppers, lashings), their engagements, and the 3-D cargo beam."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from seafast.config.loader import load_case
from seafast.model.cargo3d import build_cargo3d, gravity_direction
from seafast.model.cradle import Lashing, PadPair, Side, SideStopper, lashing_engagement, pad_engagements, stopper_engagement
from seafast.model.from_case import build_model
from seafast.model.sections import CargoGeometry, TubeSegment, tube_area_m2
from seafast.model.structure import build_cargo_beam


@pytest.mark.parametrize("alpha_deg", [20.0, 35.0, 45.0, 60.0])
def test_pad_pair_acts_vertically_as_the_saddle_and_laterally_tan_squared(alpha_deg):
    pair = PadPair(10.0, alpha_deg, 4.0, 1.1e9)
    a = np.deg2rad(alpha_deg)
    assert pair.pad_stiffness_N_per_m == pytest.approx(1.1e9 / (2 * np.cos(a) ** 2), rel=1e-14)
    # the pair's (y, z) stiffness with both pads in contact, from the engagements' gradients
    K = sum(e.stiffness_N_per_m * np.outer(e.gradient[1:3], e.gradient[1:3]) for e in pad_engagements(pair))
    np.testing.assert_allclose(K, np.diag([1.1e9 * np.tan(a) ** 2, 1.1e9]), rtol=1e-12, atol=1e-6)
    assert pair.lateral_stiffness_N_per_m == pytest.approx(1.1e9 * np.tan(a) ** 2, rel=1e-12)
    # the pads stand on the tube below the axis, the port one at y > 0, and push up and towards the axis
    port, starboard = pair.pad_point_m(Side.PORT), pair.pad_point_m(Side.STARBOARD)
    np.testing.assert_allclose(port, [4.0 * np.sin(a), -4.0 * np.cos(a)], rtol=1e-14)
    np.testing.assert_allclose(starboard, [-4.0 * np.sin(a), -4.0 * np.cos(a)], rtol=1e-14)
    np.testing.assert_allclose(pair.pad_normal(Side.PORT), -port / 4.0, rtol=1e-14)


def test_a_pad_compresses_by_the_normal_approach_of_its_contact_point():
    pair = PadPair(0.0, 35.0, 4.0, 1e9)
    port, starboard = pad_engagements(pair)
    # the cargo moved down by 1 mm and to starboard by 1 mm: the starboard pad compresses by the
    # approach along its normal, (sin a + cos a) mm; the port pad by (cos a - sin a) mm
    d = np.array([0.0, -1e-3, -1e-3, 0.3, -0.2])  # rotations do not move the contact point along its normal
    a = np.deg2rad(35.0)
    assert starboard.gradient @ d == pytest.approx(1e-3 * (np.sin(a) + np.cos(a)), rel=1e-14)
    assert port.gradient @ d == pytest.approx(1e-3 * (np.cos(a) - np.sin(a)), rel=1e-14)


def test_a_stopper_engages_after_its_gap_on_its_side():
    port = stopper_engagement(SideStopper(5.0, Side.PORT, 0.02, 1e8))
    starboard = stopper_engagement(SideStopper(5.0, Side.STARBOARD, 0.02, 1e8))
    v = np.array([0.0, 0.03, 0.0, 0.0, 0.0])  # 30 mm to port
    assert port.initial_m + port.gradient @ v == pytest.approx(0.01, rel=1e-14)
    assert starboard.initial_m + starboard.gradient @ v == pytest.approx(-0.05, rel=1e-14)


@pytest.mark.parametrize(
    "cargo_point, anchor",
    [((20.0, 4.0, 0.0), (20.0, 7.0, -5.0)), ((20.0, -2.8, 2.8), (17.0, -7.0, -5.0)), ((20.0, 0.0, 4.0), (24.0, 3.0, -5.0))],
)
def test_a_lashing_stretches_by_its_chord_under_a_small_rigid_motion(cargo_point, anchor):
    """The engagement's linear map against the exact chord of a rigidly moved section (rotation matrices)."""
    lashing = Lashing(cargo_point, anchor, 2e7, 1e5)
    e = lashing_engagement(lashing)
    assert e.initial_m == pytest.approx(1e5 / 2e7, rel=1e-15)
    rng = np.random.default_rng(3)
    for _ in range(5):
        q = rng.normal(size=5) * 1e-6  # u, v, w [m], psi, theta [rad]
        u, v, w, psi, theta = q
        r = np.array([0.0, cargo_point[1], cargo_point[2]])
        rotation = Rotation.from_rotvec([0.0, -theta, psi])  # psi about z, theta = dw/dx is -rotation about y
        moved = np.array(cargo_point) + np.array([u, v, w]) + rotation.apply(r) - r
        elongation = np.linalg.norm(np.subtract(anchor, moved)) - lashing.length_m
        # the second-order terms (r theta^2, |d|^2 / L) are a fraction of about |q| (1 + |r|) of the first-order motion
        # |q| (1 + |r|): 1e-11 m here; a wrong sign or lever arm is wrong by the first order, some 1e-6 m
        first_order = np.max(np.abs(q)) * (1.0 + np.linalg.norm(r))
        assert e.gradient @ q == pytest.approx(elongation, abs=1e-5 * first_order)


@pytest.mark.parametrize(
    "make, message",
    [
        (lambda: PadPair(0.0, 90.0, 4.0, 1e9), "contact_angle_deg = 90.0"),
        (lambda: PadPair(0.0, 0.0, 4.0, 1e9), "contact_angle_deg = 0.0"),
        (lambda: PadPair(0.0, 35.0, -4.0, 1e9), "tube_radius_m = -4.0"),
        (lambda: PadPair(0.0, 35.0, 4.0, 0.0), "saddle_stiffness_N_per_m = 0.0"),
        (lambda: SideStopper(0.0, Side.PORT, -0.01, 1e8), "gap_m = -0.01"),
        (lambda: SideStopper(0.0, "aft", 0.01, 1e8), "'aft' is not a valid Side"),
        (lambda: Lashing((0, 1, 0), (0, 1, 0), 1e7, 0.0), "anchor_point_m"),
        (lambda: Lashing((0, 1, 0), (0, 3, -2), 1e7, -5.0), "pretension_N = -5.0"),
        (lambda: Lashing((0, 1), (0, 3, -2), 1e7, 0.0), "cargo_point_m"),
    ],
)
def test_bad_elements_are_refused_by_name(make, message):
    with pytest.raises(ValueError, match=message.replace("(", r"\(").replace(")", r"\)")):
        make()


@pytest.fixture(scope="module")
def base_model():
    return build_model(load_case())


def test_the_vertical_block_is_todays_cargo_on_the_base_case_mesh(base_model):
    cargo = build_cargo3d(base_model.cargo)
    n = base_model.cargo.node_count
    for block in (slice(0, 2 * n), slice(2 * n, 4 * n)):  # vertical, then lateral (I_y = I_z)
        np.testing.assert_array_equal(cargo.stiffness[block, block], base_model.cargo.stiffness)
        np.testing.assert_array_equal(cargo.mass[block, block], base_model.cargo.mass)
    np.testing.assert_array_equal(cargo.gravity_load_N(0.0, 0.0, base_model.gravity_m_per_s2)[: 2 * n], base_model.cargo.gravity_load_N)
    # the blocks are uncoupled in the beam
    assert not np.any(cargo.stiffness[: 2 * n, 2 * n :]) and not np.any(cargo.stiffness[4 * n :, : 4 * n])


def test_axial_bar_stretches_by_FL_over_EA_and_carries_the_mass():
    geometry = CargoGeometry((TubeSegment(0.0, 30.0, 8.0, 8.0, 0.08), TubeSegment(30.0, 60.0, 8.0, 6.0, 0.06)))
    beam = build_cargo_beam(geometry, np.array([20.0]), 2.0)
    cargo = build_cargo3d(beam)
    n = cargo.node_count
    K = cargo.stiffness[4 * n :, 4 * n :]
    # end 0 held, a pull P at the far end: u(L) = P sum(L_e / EA_e), exact for bars with a point load
    P = 1e6
    u = np.linalg.solve(K[1:, 1:], np.r_[np.zeros(n - 2), P])
    area = tube_area_m2(beam.element_outer_diameter_m, beam.element_wall_thickness_m)
    assert u[-1] == pytest.approx(P * np.sum(np.diff(beam.node_x_m) / (210e9 * area)), rel=1e-10)
    # rigid-body motions: no strain, and the mass matrix gives back the cargo's mass in each translation
    R = cargo.rigid_body_modes()
    assert np.max(np.abs(cargo.stiffness @ R)) < 1e-9 * np.max(np.abs(cargo.stiffness))
    translations = np.zeros((cargo.dof_count, 3))
    translations[4 * n :, 0] = translations[2 * n : 4 * n : 2, 1] = translations[0 : 2 * n : 2, 2] = 1.0
    np.testing.assert_allclose(np.diag(translations.T @ cargo.mass @ translations), beam.mass_kg, rtol=1e-12)


@pytest.mark.parametrize("heel_deg, trim_deg", [(0.0, 0.0), (15.0, 0.0), (-25.0, 3.0), (90.0, -10.0)])
def test_weight_at_heel_and_trim_resolves_into_the_ship_frame(heel_deg, trim_deg):
    beam = build_cargo_beam(CargoGeometry((TubeSegment(0.0, 50.0, 7.0, 7.0, 0.07),)), np.array([10.0, 40.0]), 2.5)
    cargo = build_cargo3d(beam)
    n = cargo.node_count
    f = cargo.gravity_load_N(heel_deg, trim_deg, 9.81)
    W = beam.mass_kg * 9.81
    phi, theta = np.deg2rad(heel_deg), np.deg2rad(trim_deg)
    expected = W * np.array([-np.sin(theta), -np.cos(theta) * np.sin(phi), -np.cos(theta) * np.cos(phi)])
    totals = [f[4 * n :].sum(), f[2 * n : 4 * n : 2].sum(), f[0 : 2 * n : 2].sum()]
    np.testing.assert_allclose(totals, expected, rtol=1e-12, atol=1e-9 * W)
    np.testing.assert_allclose(gravity_direction(heel_deg, trim_deg), expected / W, rtol=1e-12, atol=1e-15)
    # heeled to starboard, gravity points to starboard (-y); trimmed bow up, aft (-x)
    if heel_deg > 0:
        assert totals[1] < 0
    if trim_deg > 0:
        assert totals[0] < 0
