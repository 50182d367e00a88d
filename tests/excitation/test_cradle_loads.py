"""The loads on the 3-D cargo at any heading (docs/transverse.md#7-dynamics): resultants against rigid-body closed forms."""

from __future__ import annotations

import numpy as np
import pytest

from seafast.excitation.cradle_loads import cradle_excitation
from seafast.excitation.harmonic import HarmonicExcitation
from seafast.model.cargo3d import build_cargo3d
from seafast.model.sections import CargoGeometry, TubeSegment
from seafast.model.structure import build_cargo_beam

G = 9.81
OMEGA = 0.7
AXIS = (-12.0, 3.0, 9.0)  # the cargo's aft end from the motions' reference point (x, y, z) [m]


@pytest.fixture(scope="module")
def cargo():
    return build_cargo3d(build_cargo_beam(CargoGeometry((TubeSegment(0.0, 30.0, 5.0, 5.0, 0.05),)), np.array([8.0, 22.0]), 1.5))


def loads(cargo, motions, vertical_load=None):
    n = cargo.node_count
    load = np.zeros((2, 2 * n), dtype=complex) if vertical_load is None else vertical_load
    deck = np.array([[0.01, 1e-4, 0.02, -1e-4], [0.03j, 0.0, 0.01, 2e-4j]])
    vertical = HarmonicExcitation(OMEGA, deck, load, np.zeros((2, n - 1), dtype=complex))
    return cradle_excitation(cargo, vertical, np.asarray(motions, dtype=complex), np.array([8.0, 22.0]), AXIS, G)


def resultants(cargo, exc):
    """Lateral and axial force [N] and the lateral force's moment about z at the aft end [N m] (moment DOFs included)."""
    n = cargo.node_count
    lateral = exc.cargo_load_N[1, 2 * n : 4 * n]
    axial = exc.cargo_load_N[1, 4 * n :]
    moment = np.sum(lateral[0::2] * cargo.node_x_m) + np.sum(lateral[1::2])
    return np.sum(lateral[0::2]), np.sum(axial), moment


def test_sway_surge_and_yaw_load_the_cargo_by_its_mass_times_the_acceleration(cargo):
    m, L = cargo.vertical.mass_kg, 30.0
    w2 = OMEGA**2
    lateral, axial, _ = resultants(cargo, loads(cargo, [0.4, 1.3, 0, 0, 0, 0]))
    assert lateral == pytest.approx(m * w2 * 1.3, rel=1e-12)  # -m a, a = -omega^2 sway
    assert axial == pytest.approx(m * w2 * 0.4, rel=1e-12)
    yaw = 0.02
    lateral, _, moment = resultants(cargo, loads(cargo, [0, 0, 0, 0, 0, yaw]))
    x0 = AXIS[0]  # u_y = psi r_x along the cargo: a linear load; its resultant and its moment about the aft end
    assert lateral == pytest.approx(m * w2 * yaw * (x0 + L / 2), rel=1e-12)
    assert moment == pytest.approx(m / L * w2 * yaw * (x0 * L**2 / 2 + L**3 / 3), rel=1e-12)


def test_roll_and_pitch_add_their_gravity_components_to_the_inertia(cargo):
    m, w2 = cargo.vertical.mass_kg, OMEGA**2
    phi, theta = 0.1, 0.03
    lateral, axial, _ = resultants(cargo, loads(cargo, [0, 0, 0, phi, 0, 0]))
    # starboard down: gravity's g phi and the roll's acceleration above the axis both push to starboard (-y)
    assert lateral == pytest.approx(-m * phi * (G + w2 * AXIS[2]), rel=1e-12)
    assert axial == pytest.approx(0.0, abs=1e-9 * m * G * phi)
    lateral, axial, _ = resultants(cargo, loads(cargo, [0, 0, 0, 0, theta, 0]))
    assert axial == pytest.approx(-m * theta * (G + w2 * AXIS[2]), rel=1e-12)  # bow up: gravity and inertia aft
    assert lateral == pytest.approx(0.0, abs=1e-9 * m * G * theta)


def test_the_vertical_block_and_the_deck_are_the_vertical_planes_bit_for_bit(cargo):
    n = cargo.node_count
    rng = np.random.default_rng(3)
    vertical_load = rng.normal(size=(2, 2 * n)) + 1j * rng.normal(size=(2, 2 * n))
    exc = loads(cargo, [0.1, 0.5, 1.0, 0.05, 0.01, 0.002], vertical_load)
    np.testing.assert_array_equal(exc.cargo_load_N[:, : 2 * n], vertical_load)
    np.testing.assert_array_equal(exc.deck_displacement, [[0.01, 1e-4, 0.02, -1e-4], [0.03j, 0.0, 0.01, 2e-4j]])
    assert np.all(exc.cargo_load_N[0, 2 * n :] == 0.0)  # no static lateral or axial load: the weight is the problem's


def test_bad_motions_are_refused_naming_the_field(cargo):
    with pytest.raises(ValueError, match="motions"):
        loads(cargo, [0.0, 1.0, 2.0])
