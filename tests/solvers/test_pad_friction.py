"""Coulomb friction at the cradle pads: the cone law and the statics against closed forms (docs/transverse.md#8-friction-at-the-pads)."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import brentq

from seafast.fourier import real_dft_matrices
from seafast.model.cargo3d import build_cargo3d
from seafast.model.cradle import Lashing, PadPair, Side, SideStopper
from seafast.model.pad_friction import PadFriction, pad_tangent
from seafast.model.sections import CargoGeometry, TubeSegment
from seafast.model.structure import build_cargo_beam
from seafast.solvers.axial.jenkins import march_jenkins
from seafast.solvers.friction_cone import cone_return_map, cone_sensitivity, march_cone
from seafast.solvers.frictional_statics import solve_frictional_statics
from seafast.solvers.transverse_statics import CradleProblem, StaticsOutcome, solve_transverse_statics

SADDLES_M = (5.0, 15.0)
ALPHA_DEG, K_V, MU = 30.0, 2e8, 0.1


def test_the_return_map_scales_the_trial_force_radially_onto_the_cone():
    trial = np.array([[3.0, 4.0], [0.3, -0.4], [-6.0, 8.0], [1.0, 1.0]])
    force, slipped = cone_return_map(trial, np.array([2.5, 1.0, 5.0, 0.0]))
    np.testing.assert_array_equal(slipped, [True, False, True, True])
    np.testing.assert_allclose(force[0], [1.5, 2.0], rtol=1e-15)  # |f| = C along the trial
    np.testing.assert_array_equal(force[1], trial[1])  # inside the cone: unchanged
    np.testing.assert_allclose(force[2], [-3.0, 4.0], rtol=1e-15)
    np.testing.assert_array_equal(force[3], [0.0, 0.0])  # an open pad carries exactly nothing


def test_in_one_direction_the_cone_is_the_axial_jenkins_element():
    rng = np.random.default_rng(3)
    N = 200
    t = np.arange(N) / N
    u = 2e-3 * np.sin(2 * np.pi * t) + 5e-4 * np.cos(6 * np.pi * t + 0.3) + 1e-4 * rng.normal(size=N)
    capacity = 1e5 * (1.2 + np.sin(2 * np.pi * t + 1.0))
    delta = np.zeros((N, 1, 2))
    delta[:, 0, 0] = u
    cone = march_cone(delta, capacity[:, None], np.array([1e8]), np.zeros((1, 2)))
    jenkins = march_jenkins(u, capacity, 1e8)
    assert np.any(jenkins.slipped) and not np.all(jenkins.slipped)
    np.testing.assert_allclose(cone.force_N[:, 0, 0], jenkins.force_N, atol=1e-9 * np.max(capacity))
    np.testing.assert_array_equal(cone.force_N[:, 0, 1], 0.0)


def test_the_forward_mode_derivatives_are_the_finite_differences_of_the_march():
    H, N, p = 8, 128, 3
    inverse = real_dft_matrices(H, N)[0]
    rng = np.random.default_rng(1)
    Zd = rng.normal(size=(2 * H + 1, p, 2)) * np.array([1.0, 0.5]) * 1e-2 / np.arange(1, 2 * H + 2)[:, None, None]
    Zc = rng.normal(size=(2 * H + 1, p)) * 1e5 / np.arange(1, 2 * H + 2)[:, None]
    Zc[0] = 1e5
    k = np.array([1e8, 2e8, 5e7])

    def run(Zd, Zc):
        delta = np.einsum("nj,jpb->npb", inverse, Zd)
        capacity = np.maximum(inverse @ Zc, 0.0)
        return delta, capacity, march_cone(delta, capacity, k, np.zeros((p, 2)))

    delta, capacity, period = run(Zd, Zc)
    assert 0.2 < np.mean(period.slipped) < 0.95 and np.any(capacity == 0.0)
    d_delta, d_cap = cone_sensitivity(period, delta, capacity, k, inverse, (capacity > 0.0)[:, :, None] * inverse[:, None, :])
    for j, pad, b in [(0, 0, 0), (3, 1, 1), (5, 2, 0), (1, 0, 1)]:
        Z2 = Zd.copy()
        Z2[j, pad, b] += 1e-9
        fd = (run(Z2, Zc)[2].force_N[:, pad] - period.force_N[:, pad]) / 1e-9
        np.testing.assert_allclose(d_delta[:, pad, :, b, j], fd, atol=1e-6 * np.max(k))  # the step's round-off: 1e-7 of k
    for j, pad in [(0, 0), (4, 1)]:
        Z2 = Zc.copy()
        Z2[j, pad] += 1e-3
        fd = (run(Zd, Z2)[2].force_N[:, pad] - period.force_N[:, pad]) / 1e-3
        np.testing.assert_allclose(d_cap[:, pad, :, j], fd, atol=1e-5)  # of derivatives up to 1


@pytest.fixture(scope="module")
def rigid_tube() -> tuple[CradleProblem, float]:
    """A 20 m tube made rigid (E x 1000) on two cradles symmetric about its middle: each carries half the weight
    across and up (the lever rule), and both sections move alike; an axial spring of 1 MN/m holds it along."""
    geometry = CargoGeometry((TubeSegment(0.0, 20.0, 4.0, 4.0, 0.04),), youngs_modulus_Pa=210e12)
    cargo = build_cargo3d(build_cargo_beam(geometry, np.array(SADDLES_M), 2.0))
    springs = np.zeros(cargo.dof_count)
    springs[cargo.node_dofs(cargo.node_at(SADDLES_M[0]))[0]] = 1e6
    problem = CradleProblem(cargo, tuple(PadPair(x, ALPHA_DEG, 2.0, K_V) for x in SADDLES_M), spring_diagonal_N_per_m=springs)
    weight = -float(np.sum(cargo.gravity_load_N()[: 2 * cargo.node_count : 2]))
    return problem, weight


def _stick(phi: float, half_weight: float, ratio: float = 1.0) -> tuple[np.ndarray, np.ndarray]:
    """Closed form with both pads stuck: (normal forces, friction forces resisting the circumferential motion), port first.

    From rest (N0 = W_s / (2 cos a) each, no friction) the load changes by W_s (-sin phi, 1 - cos phi) in (y, z);
    the pair's stiffness is diag(2 (k_n s^2 + k_t c^2), 2 (k_n c^2 + k_t s^2)) (each pad k_n m m^T + k_t t t^T).
    """
    a = np.deg2rad(ALPHA_DEG)
    kn = K_V / (2 * np.cos(a) ** 2)
    kt = ratio * kn
    s, c = np.sin(a), np.cos(a)
    d = np.array(
        [-half_weight * np.sin(phi) / (2 * (kn * s**2 + kt * c**2)), half_weight * (1 - np.cos(phi)) / (2 * (kn * c**2 + kt * s**2))]
    )
    pair = PadPair(0.0, ALPHA_DEG, 2.0, K_V)
    normal = np.array([half_weight / (2 * c) - kn * pair.pad_normal(side) @ d for side in (Side.PORT, Side.STARBOARD)])
    friction = np.array([kt * pad_tangent(pair, side) @ d for side in (Side.PORT, Side.STARBOARD)])
    return normal, friction


def _full_slip(phi: float, half_weight: float) -> np.ndarray:
    """Closed form with both pads slipping (the cargo moving to starboard): N_p (m_p + mu t_p) + N_s (m_s + mu t_s) =
    W_s (sin phi, cos phi), statically determinate; returns (N_p, N_s)."""
    pair = PadPair(0.0, ALPHA_DEG, 2.0, K_V)
    columns = [pair.pad_normal(side) + MU * pad_tangent(pair, side) for side in (Side.PORT, Side.STARBOARD)]
    return np.linalg.solve(np.column_stack(columns), half_weight * np.array([np.sin(phi), np.cos(phi)]))


def test_a_heeled_cargo_sticks_below_the_closed_form_limit_and_slides_beyond_it(rigid_tube):
    problem, weight = rigid_tube
    half = weight / 2
    # the high-side (port) pad slips first: |T_p| = mu N_p at the heel phi_1
    phi_1 = brentq(lambda phi: abs(_stick(phi, half)[1][0]) - MU * _stick(phi, half)[0][0], 1e-4, 0.5)
    phi_2 = brentq(lambda phi: abs(_stick(phi, half)[1][1]) - MU * _stick(phi, half)[0][1], 1e-4, 0.5)
    assert phi_1 < phi_2  # the low-side pad, more loaded, would slip later
    friction = PadFriction(MU)
    below = solve_frictional_statics(problem, friction, np.rad2deg(0.97 * phi_1))
    assert below.outcome is StaticsOutcome.CONVERGED and not np.any(below.slipped)
    np.testing.assert_array_equal(below.slip_m, 0.0)
    normal, tangential = _stick(0.97 * phi_1, half)
    np.testing.assert_allclose(below.pad_force_N, np.tile(normal, 2), rtol=1e-6)
    np.testing.assert_allclose(below.friction_force_N[:, 0], np.tile(tangential, 2), rtol=1e-5)
    beyond = solve_frictional_statics(problem, friction, np.rad2deg(1.03 * phi_1))
    assert beyond.outcome is StaticsOutcome.CONVERGED
    # once the high-side pads slip, the low-side ones take their share and slip too (with k_t = k_n): all slide
    assert np.all(beyond.slipped) and np.all(beyond.slip_m[:, 0] < 0.0)
    np.testing.assert_allclose(np.hypot(*beyond.friction_force_N.T), MU * beyond.pad_force_N, rtol=1e-12)
    np.testing.assert_allclose(beyond.pad_force_N, np.tile(_full_slip(1.03 * phi_1, half), 2), rtol=1e-6)
    # far beyond, both pads slip: the pad forces are the statically determinate closed form, whatever k_t
    for ratio in (1.0, 0.3):
        far = solve_frictional_statics(problem, PadFriction(MU, ratio), 15.0)
        assert far.outcome is StaticsOutcome.CONVERGED and np.all(far.slipped)
        np.testing.assert_allclose(far.pad_force_N, np.tile(_full_slip(np.deg2rad(15.0), half), 2), rtol=1e-6)


def test_a_trimmed_cargo_stays_put_on_the_vee_of_its_pads_until_tan_trim_reaches_mu_over_cos_alpha():
    """Along the cargo only friction holds it (and a 10 kN/m spring): the pads' normal forces sum to W cos(trim) / cos(a)
    (the vee wedges the tube), so the friction can hold W sin(trim) while tan(trim) < mu / cos(a)."""
    geometry = CargoGeometry((TubeSegment(0.0, 20.0, 4.0, 4.0, 0.04),), youngs_modulus_Pa=210e12)
    cargo = build_cargo3d(build_cargo_beam(geometry, np.array(SADDLES_M), 2.0))
    springs = np.zeros(cargo.dof_count)
    u_spring = cargo.node_dofs(cargo.node_at(SADDLES_M[0]))[0]
    springs[u_spring] = 1e4
    problem = CradleProblem(cargo, tuple(PadPair(x, ALPHA_DEG, 2.0, K_V) for x in SADDLES_M), spring_diagonal_N_per_m=springs)
    weight = -float(np.sum(cargo.gravity_load_N()[: 2 * cargo.node_count : 2]))
    limit = np.arctan(MU / np.cos(np.deg2rad(ALPHA_DEG)))
    below = solve_frictional_statics(problem, PadFriction(MU), 0.0, np.rad2deg(0.98 * limit))
    assert below.outcome is StaticsOutcome.CONVERGED
    # held: the friction carries the axial weight (the spring less than 1e-4 of it); the pitching moment of the
    # friction below the axis unloads the forward cradle, whose pads slip, the aft ones stick
    assert not np.all(below.slipped)
    axial_weight = weight * np.sin(0.98 * limit)
    assert abs(1e4 * below.displacement[u_spring]) < 1e-4 * axial_weight
    np.testing.assert_allclose(-np.sum(below.friction_force_N[:, 1]), axial_weight, rtol=1e-4)
    for factor in (1.02, 1.2):
        beyond = solve_frictional_statics(problem, PadFriction(MU), 0.0, np.rad2deg(factor * limit))
        assert beyond.outcome is StaticsOutcome.CONVERGED and np.all(beyond.slipped)
        trim = factor * limit
        # sliding aft: the spring takes what the friction cannot, W sin(trim) - mu W cos(trim) / cos(a)
        excess = weight * (np.sin(trim) - MU * np.cos(trim) / np.cos(np.deg2rad(ALPHA_DEG)))
        np.testing.assert_allclose(-1e4 * beyond.displacement[u_spring], excess, rtol=1e-3)
        assert np.all(beyond.slip_m[:, 1] < -0.1)


def test_at_zero_heel_the_frictional_statics_is_the_frictionless_rest(rigid_tube):
    problem, _ = rigid_tube
    statics = solve_frictional_statics(problem, PadFriction(MU), 0.0)
    assert statics.outcome is StaticsOutcome.CONVERGED and statics.iterations == 0
    assert np.max(np.abs(statics.friction_force_N)) == 0.0


@pytest.mark.parametrize("heel_deg", [10.0, 25.0])
def test_without_friction_the_statics_is_the_exact_frictionless_one(heel_deg):
    """Two 15 deg cradles with stoppers (30 mm gaps), pretensioned lashings and an axial spring: mu = 0 gives the exact
    statics."""
    cargo = build_cargo3d(build_cargo_beam(CargoGeometry((TubeSegment(0.0, 20.0, 4.0, 4.0, 0.04),)), np.array(SADDLES_M), 2.0))
    stoppers = tuple(SideStopper(x, side, 0.03, 1e8) for x in SADDLES_M for side in Side)
    lashings = tuple(
        Lashing((x, sy * 2.0, 0.0), (x + dx, sy * 5.0, -4.0), 5e6, 20e3)
        for x, dx in zip(SADDLES_M, (2.0, -2.0), strict=True)
        for sy in (1.0, -1.0)
    )
    pairs = tuple(PadPair(x, 15.0, 2.0, 2e8) for x in SADDLES_M)
    springs = np.zeros(cargo.dof_count)
    springs[cargo.node_dofs(cargo.node_at(SADDLES_M[0]))[0]] = 1e8
    problem = CradleProblem(cargo, pairs, stoppers, lashings, spring_diagonal_N_per_m=springs)
    frictionless = solve_transverse_statics(problem, heel_deg)
    statics = solve_frictional_statics(problem, PadFriction(0.0), heel_deg)
    assert statics.outcome is StaticsOutcome.CONVERGED and frictionless.outcome is StaticsOutcome.CONVERGED
    exact = np.concatenate([frictionless.pad_force_N.ravel(), frictionless.stopper_force_N, frictionless.lashing_tension_N])
    np.testing.assert_allclose(statics.element_force_N, exact, atol=1e-9 * np.max(exact))
    assert np.max(np.abs(statics.friction_force_N)) == 0.0
    held = solve_frictional_statics(problem, PadFriction(0.3), heel_deg)  # with friction too: converged, on the cone
    assert held.outcome is StaticsOutcome.CONVERGED
    assert np.all(np.hypot(*held.friction_force_N.T) <= 0.3 * held.pad_force_N * (1 + 1e-12))


def test_bad_friction_parameters_are_refused_naming_the_field():
    with pytest.raises(ValueError, match=r"friction_coefficient = -0\.1"):
        PadFriction(-0.1)
    with pytest.raises(ValueError, match="tangential_stiffness_ratio = 0"):
        PadFriction(0.2, 0.0)
