"""The 3-D cargo on frictional pads in a regular wave: harmonic balance against the time domain.

docs/transverse.md#8-friction-at-the-pads.
"""

from __future__ import annotations

import numpy as np
import pytest

from seafast.excitation.cargo_acceleration import acceleration_transfer
from seafast.excitation.cradle_loads import CradleExcitation, cradle_excitation
from seafast.excitation.harmonic import HarmonicExcitation
from seafast.model.cargo3d import Cargo3D, build_cargo3d
from seafast.model.cradle import PadPair
from seafast.model.pad_friction import PadFriction
from seafast.model.sections import CargoGeometry, TubeSegment
from seafast.model.structure import build_cargo_beam
from seafast.solvers.cradle_dynamics import CradleDynamics
from seafast.solvers.cradle_friction import FrictionHBMOptions, solve_cradle_friction_hbm
from seafast.solvers.cradle_hbm import solve_cradle_hbm
from seafast.solvers.hbm import HBMOptions
from seafast.solvers.references.cradle_friction_time_domain import FrictionTimeDomainOptions, solve_cradle_friction_time_domain
from seafast.solvers.transverse_statics import CradleProblem

SADDLES_M = (5.0, 15.0)
OMEGA = 0.8
MOTIONS = np.array([0.6, 1.0, 0.8, 0.15, 0.03, 0.0], dtype=complex)
"""Surge 0.6 m, sway 1 m, heave 0.8 m, roll 0.15 rad, pitch 0.03 rad in phase, about a point aft and below."""


def tube_dynamics() -> CradleDynamics:
    """A 20 m tube, 4 m across, on a 5 m mesh (the time domain's cost), on two 30 deg cradles (2e8 N/m), Rayleigh damping.

    An axial spring of 50 MN/m (a lashing's fore-and-aft stiffness) pins the cargo's mean axial position: with a weak
    one the axial friction alone holds it, periodic states form a near-continuum in the mean axial slip, and the
    time domain creeps along it for many periods.
    """
    cargo = build_cargo3d(build_cargo_beam(CargoGeometry((TubeSegment(0.0, 20.0, 4.0, 4.0, 0.04),)), np.array(SADDLES_M), 5.0))
    springs = np.zeros(cargo.dof_count)
    springs[cargo.node_dofs(cargo.node_at(SADDLES_M[0]))[0]] = 5e7
    problem = CradleProblem(cargo, tuple(PadPair(x, 30.0, 2.0, 2e8) for x in SADDLES_M), spring_diagonal_N_per_m=springs)
    return CradleDynamics(problem, 2.0, 2e-3, np.array(SADDLES_M))


def tube_excitation(cargo: Cargo3D, motions: np.ndarray = MOTIONS) -> CradleExcitation:
    """The beam-sea wave on the tube: the six vessel ``motions`` (default :data:`MOTIONS`) at OMEGA about a point aft and below."""
    axis = (-10.0, 0.0, 8.0)
    n = cargo.node_count
    points = np.column_stack([cargo.node_x_m, np.zeros(n), np.zeros(n)]) + np.array(axis)
    f_z = acceleration_transfer(motions, OMEGA, points)[:, 2]
    reading = np.zeros(2 * n, dtype=complex)
    reading[0::2] = f_z
    reading[1::2] = acceleration_transfer(motions, OMEGA, points + [1.0, 0.0, 0.0])[:, 2] - f_z
    load = np.zeros((2, 2 * n), dtype=complex)
    load[1] = -cargo.vertical.mass @ reading
    vertical = HarmonicExcitation(OMEGA, np.zeros((2, 4), dtype=complex), load, np.zeros((2, n - 1), dtype=complex))
    return cradle_excitation(cargo, vertical, motions, np.array(SADDLES_M), axis)


@pytest.fixture(scope="module")
def stick_slip_pair():
    dynamics = tube_dynamics()
    excitation = tube_excitation(dynamics.problem.cargo)
    friction = PadFriction(0.1)
    hbm = solve_cradle_friction_hbm(dynamics, friction, excitation, FrictionHBMOptions(harmonics=32, time_samples=256))
    options = FrictionTimeDomainOptions(time_samples=256, relaxation_fraction=1e-6, relative_tolerance=1e-6, max_periods=4)
    reference = solve_cradle_friction_time_domain(dynamics, friction, excitation, options)  # peaks settled, sliders' mean still creeping
    return hbm, reference


def test_harmonic_balance_with_friction_matches_the_time_domain_where_pads_stick_and_slip(stick_slip_pair):
    hbm, reference = stick_slip_pair
    assert hbm.converged, hbm.cradle.message
    # every pad sticks part of the period and slips the rest, in both solutions
    for result in (hbm, reference):
        slipping = np.mean(result.friction_utilisation > 0.999, axis=0)
        assert np.all((slipping > 0.15) & (slipping < 0.5)), slipping
    np.testing.assert_allclose(hbm.cradle.max_force_N, reference.cradle.max_force_N, rtol=5e-3)
    np.testing.assert_allclose(hbm.cradle.min_force_N, reference.cradle.min_force_N, rtol=5e-3)
    np.testing.assert_allclose(hbm.max_friction_N, reference.max_friction_N, rtol=5e-3)
    # the slip over the period (peak to peak per direction) within 0.5 % of the largest (measured 0.46 %: the slips'
    # onsets between the samples and the truncation at H = 32); the largest slip from rest within 1 % (measured 0.5 %:
    # it adds the sliders' mean, still settling in the time domain by 0.03 % a period)
    np.testing.assert_allclose(hbm.slip_range_m, reference.slip_range_m, atol=5e-3 * np.max(reference.slip_range_m))
    np.testing.assert_allclose(hbm.max_slip_m, reference.max_slip_m, atol=1e-2 * np.max(reference.max_slip_m))
    assert np.max(reference.slip_range_m) > 2e-4


def test_the_friction_stays_on_its_cone(stick_slip_pair):
    hbm, _ = stick_slip_pair
    assert np.all(hbm.friction_magnitude_N <= 0.1 * hbm.normal_force_N * (1 + 1e-12))
    np.testing.assert_allclose(np.max(hbm.friction_utilisation), 1.0, rtol=1e-12)


def test_without_friction_the_answer_is_the_frictionless_solve():
    dynamics = tube_dynamics()
    excitation = tube_excitation(dynamics.problem.cargo)
    response = solve_cradle_friction_hbm(dynamics, PadFriction(0.0), excitation, FrictionHBMOptions(harmonics=16, time_samples=128))
    frictionless = solve_cradle_hbm(dynamics, excitation, HBMOptions(harmonics=16, time_samples=128))
    np.testing.assert_array_equal(response.cradle.element_force_N, frictionless.element_force_N)
    assert np.max(np.abs(response.friction_force_N)) == 0.0 and np.max(response.max_slip_m) > 0.0  # free sliding
