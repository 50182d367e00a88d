"""The pads' tangential motion (docs/transverse.md#8-friction-at-the-pads): directions and gradients from the section's kinematics."""

from __future__ import annotations

import numpy as np
import pytest

from seafast.model.cradle import PadPair, Side, pad_engagements
from seafast.model.pad_friction import PadFriction, pad_tangent, pad_tangential_deck, pad_tangential_gradients


@pytest.mark.parametrize("alpha_deg", [15.0, 35.0, 60.0])
def test_the_tangents_are_normal_to_the_pushes_and_point_to_port(alpha_deg):
    pair = PadPair(4.0, alpha_deg, 2.5, 1e8)
    a = np.deg2rad(alpha_deg)
    np.testing.assert_allclose(pad_tangent(pair, Side.PORT), [np.cos(a), np.sin(a)], rtol=1e-15)
    np.testing.assert_allclose(pad_tangent(pair, Side.STARBOARD), [np.cos(a), -np.sin(a)], rtol=1e-15)
    for side in Side:
        assert abs(pad_tangent(pair, side) @ pair.pad_normal(side)) < 1e-15


def test_the_tangential_motion_is_the_contact_points_displacement_along_its_directions():
    """A section moved by (u, v, w, psi, theta): its contact point moves by d = (u - theta r_z - psi r_y, v, w) (small
    rotations, docs/transverse.md#2-the-cargo-beam-in-three-dimensions); the pad's coordinates are t . (d_y, d_z) and d_x."""
    pair = PadPair(4.0, 35.0, 2.5, 1e8)
    rng = np.random.default_rng(7)
    grads = pad_tangential_gradients(pair)
    for _ in range(5):
        u, v, w, psi, theta = rng.normal(size=5)
        dofs = np.array([u, v, w, psi, theta])
        for i, side in enumerate((Side.PORT, Side.STARBOARD)):
            r_y, r_z = pair.pad_point_m(side)
            d = np.array([u - theta * r_z - psi * r_y, v, w])
            np.testing.assert_allclose(grads[i] @ dofs, [pad_tangent(pair, side) @ d[1:], d[0]], rtol=1e-13, atol=1e-14)


def test_a_cargo_rising_with_the_deck_does_not_move_on_its_pads():
    pair = PadPair(4.0, 35.0, 2.5, 1e8)
    z = 0.37
    dofs = np.array([0.0, 0.0, z, 0.0, 0.0])
    np.testing.assert_allclose(pad_tangential_gradients(pair) @ dofs + pad_tangential_deck(pair) * z, 0.0, atol=1e-15)
    for i, engagement in enumerate(pad_engagements(pair)):  # the compression too (the deck's cos(alpha) z)
        assert abs(engagement.gradient @ dofs + pair.pad_normal((Side.PORT, Side.STARBOARD)[i])[1] * z) < 1e-15


def test_the_tangential_stiffness_is_its_ratio_of_the_pads_normal_one():
    pair = PadPair(4.0, 30.0, 2.5, 1e8)
    assert PadFriction(0.2).tangential_stiffness_N_per_m(pair) == pair.pad_stiffness_N_per_m
    np.testing.assert_allclose(PadFriction(0.2, 0.25).tangential_stiffness_N_per_m(pair), 1e8 / (2 * 0.75) * 0.25, rtol=1e-15)
