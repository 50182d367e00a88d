"""The cargo's axial restraint: lashing geometry, friction capacity and shares, stoppers, validation."""

from __future__ import annotations

import math

import numpy as np
import pytest

from seafast.config import CaseError, load_case
from seafast.model.axial import AxialRestraint, lashing_axial_stiffness_N_per_m
from seafast.model.from_case import DEFAULT_TANGENTIAL_STIFFNESS_N_PER_M, axial_restraint


def test_lashing_axial_stiffness_geometry():
    # fore/aft wires at 60 deg: each of the two lashed saddles gives k_l cos^2(60) = k_l / 4
    assert lashing_axial_stiffness_N_per_m(40e3, 60.0, 2) == pytest.approx(2 * 40e3 / 4)
    assert lashing_axial_stiffness_N_per_m(40e3, 90.0, 2) == pytest.approx(0.0, abs=1e-9)
    with pytest.raises(ValueError, match="angle"):
        lashing_axial_stiffness_N_per_m(40e3, 0.0, 2)


def test_restraint_from_the_base_case_and_overrides():
    r = axial_restraint(load_case(None, {"seafastening.friction_coefficient": [0.1, 0.2, 0.3]}))
    assert r.cargo_mass_kg == pytest.approx(7850 * math.pi / 4 * (8.0**2 - 7.84**2) * 74.0, rel=1e-6)
    np.testing.assert_array_equal(r.friction_coefficient, [0.1, 0.2, 0.3])
    assert r.lashing_axial_stiffness_N_per_m == pytest.approx(2 * 37.5e3 * 0.5)  # 45 deg, two lashed saddles
    assert r.stick_stiffness_N_per_m == pytest.approx(3 * DEFAULT_TANGENTIAL_STIFFNESS_N_PER_M)
    assert not r.has_stoppers
    given = axial_restraint(
        load_case(
            None,
            {
                "seafastening.friction_coefficient": 0.2,
                "seafastening.lashing.axial_stiffness_N_per_m": 1e5,
                "seafastening.stopper.gap_m": 0.05,
                "seafastening.stopper.stiffness_N_per_m": 1e8,
            },
        )
    )
    assert given.lashing_axial_stiffness_N_per_m == 1e5 and given.stopper_gap_m == 0.05
    with pytest.raises(ValueError, match="friction_coefficient is not set"):
        axial_restraint(load_case(None))


def test_capacity_shares_and_stoppers():
    r = AxialRestraint(1e6, np.array([0.1, 0.3]), np.array([1e12, 1e12]), 1e4, stopper_gap_m=0.1, stopper_stiffness_N_per_m=1e7)
    normal = np.array([[2e6, 1e6], [-5e5, 1e6], [0.0, 0.0]])  # tension (linear model) holds nothing
    np.testing.assert_allclose(r.capacity_N(normal), [0.5e6, 0.3e6, 0.0])
    np.testing.assert_allclose(r.saddle_shares(normal), [[0.4, 0.6], [0.0, 1.0], [0.5, 0.5]])
    lashing, stop = r.restoring_force_N(np.array([0.05, 0.3, -0.3]))
    np.testing.assert_allclose(lashing, [500.0, 3000.0, -3000.0])
    np.testing.assert_allclose(stop, [0.0, 2e6, -2e6])  # engaged beyond the 0.1 m gap, resisting
    np.testing.assert_allclose(r.stopper_tangent_N_per_m(np.array([0.05, 0.3])), [0.0, 1e7])


@pytest.mark.parametrize(
    "overrides, key",
    [
        ({"seafastening.friction_coefficient": -0.2}, "seafastening.friction_coefficient"),
        ({"seafastening.friction_coefficient": [0.1, 0.2]}, "seafastening.friction_coefficient"),
        ({"seafastening.lashing.angle_deg": 95}, "seafastening.lashing.angle_deg"),
        ({"seafastening.stopper.gap_m": 0.05}, "seafastening.stopper"),
        ({"seafastening.stopper.stiffness_N_per_m": 0}, "seafastening.stopper.stiffness_N_per_m"),
        ({"vessel.deck_height_m": 0}, "vessel.deck_height_m"),
        ({"solver.axial_harmonics": 0}, "solver.axial_harmonics"),
    ],
)
def test_invalid_axial_keys_name_the_field(overrides, key):
    with pytest.raises(CaseError) as err:
        load_case(None, overrides)
    assert key in str(err.value)


def test_restraint_validation():
    with pytest.raises(ValueError, match="friction_coefficient"):
        AxialRestraint(1e6, np.array([-0.1]), np.array([1e9]))
    with pytest.raises(ValueError, match="stopper"):
        AxialRestraint(1e6, np.array([0.1]), np.array([1e9]), stopper_gap_m=0.1, stopper_stiffness_N_per_m=0.0)
