"""Exact statics of the 3-D cargo on cradle pads, side stoppers and lashings (docs/transverse.md, section 6)."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from seafast.config.loader import load_case
from seafast.excitation.harmonic import HarmonicExcitation
from seafast.model.beam import assemble_beam
from seafast.model.cargo3d import Cargo3D, build_cargo3d, vertical_plane_restraint
from seafast.model.cradle import Lashing, PadPair, Side, SideStopper
from seafast.model.from_case import build_model
from seafast.model.seafastening import SeaFastening
from seafast.model.sections import CargoGeometry, TubeSegment
from seafast.model.structure import StructuralModel, build_cargo_beam, build_structural_model
from seafast.solvers.references import solve_quasi_static
from seafast.solvers.transverse_statics import CradleProblem, StaticsOutcome, TransverseStatics, solve_transverse_statics

TUBE = CargoGeometry((TubeSegment(0.0, 74.0, 8.0, 8.0, 0.08),))
RADIUS_M = 4.0
K_V = 1.1e9


def cargo_on(positions_m, geometry: CargoGeometry = TUBE, element_m: float = 1.0) -> Cargo3D:
    return build_cargo3d(build_cargo_beam(geometry, np.asarray(positions_m, dtype=float), element_m))


def axial_spring(cargo: Cargo3D, x_m: float, k_N_per_m: float = 1e8) -> np.ndarray:
    """A bilateral axial restraint at ``x_m`` (the statics needs the axial motion held)."""
    springs = np.zeros(cargo.dof_count)
    springs[cargo.node_dofs(cargo.node_at(x_m))[0]] = k_N_per_m
    return springs


def saddle_weights_N(cargo: Cargo3D, x_a: float, x_b: float) -> np.ndarray:
    """The weight each of two saddles carries (lever rule about the uniform tube's middle)."""
    W = cargo.vertical.mass_kg * 9.81
    x_g = 0.5 * (cargo.node_x_m[0] + cargo.node_x_m[-1])
    return W * np.array([(x_b - x_g) / (x_b - x_a), (x_g - x_a) / (x_b - x_a)])


def pad_forces_both_compressed(W_s, heel_deg, alpha_deg):
    """(port, starboard) pad forces ((V / cos a -+ H / sin a) / 2), V = W_s cos phi, H = W_s sin phi."""
    a, phi = np.deg2rad(alpha_deg), np.deg2rad(heel_deg)
    V, H = W_s * np.cos(phi), W_s * np.sin(phi)
    return np.column_stack([(V / np.cos(a) - H / np.sin(a)) / 2, (V / np.cos(a) + H / np.sin(a)) / 2])


def check_complementarity(result: TransverseStatics, problem: CradleProblem) -> None:
    """No tensile pad, stopper or lashing force; open elements not penetrated; engaged ones carry k s."""
    k = problem.element_stiffness_N_per_m
    forces = np.concatenate([result.pad_force_N.ravel(), result.stopper_force_N, result.lashing_tension_N])
    s = result.engagement_m
    tol = 1e-9 * max(float(np.max(np.abs(s))), 1e-6)
    assert np.all(forces >= 0.0)
    assert np.all(s[forces == 0.0] <= tol)
    np.testing.assert_allclose(forces[forces > 0.0], k[forces > 0.0] * s[forces > 0.0], rtol=1e-12)


# ---------------------------------------------------------------- (a) two saddles, both pads compressed


@pytest.mark.parametrize("heel_deg", [0.0, 5.0, 20.0, -20.0, 34.0])
@pytest.mark.parametrize("alpha_deg", [35.0, 45.0])
def test_two_saddles_under_heel_share_by_the_pad_angle(heel_deg, alpha_deg):
    xs = (10.0, 52.0)  # asymmetric: the saddles carry different weights
    cargo = cargo_on(xs)
    problem = CradleProblem(
        cargo, tuple(PadPair(x, alpha_deg, RADIUS_M, K_V) for x in xs), spring_diagonal_N_per_m=axial_spring(cargo, xs[0])
    )
    result = solve_transverse_statics(problem, heel_deg)
    assert result.outcome is StaticsOutcome.CONVERGED
    expected = pad_forces_both_compressed(saddle_weights_N(cargo, *xs), heel_deg, alpha_deg)
    # round-off 1e-9 of the largest force (the high-side pad's force is a difference near the lift-off)
    np.testing.assert_allclose(result.pad_force_N, expected, rtol=1e-9, atol=1e-9 * np.max(expected))
    assert not result.pad_open.any()
    check_complementarity(result, problem)
    W = cargo.vertical.mass_kg * 9.81
    assert result.residual_N < 1e-9 * W


# ---------------------------------------------------------------- (b) three saddles: lateral shares differ


def three_equal_saddles_reactions(q_N_per_m, L, EI, k):
    """Ends and middle reactions of a beam on three equal springs at 0, L/2, L under a uniform load q.

    Compatibility: the middle spring's compression is the ends' plus the simply supported midspan deflection
    under q and the middle reaction R2, ``R2 / k = R1 / k + 5 q L^4 / (384 EI) - R2 L^3 / (48 EI)``, with
    ``2 R1 + R2 = q L``.
    """
    R2 = (q_N_per_m * L / (2 * k) + 5 * q_N_per_m * L**4 / (384 * EI)) / (3 / (2 * k) + L**3 / (48 * EI))
    return np.array([(q_N_per_m * L - R2) / 2, R2, (q_N_per_m * L - R2) / 2])


@pytest.mark.parametrize("alpha_deg", [30.0, 40.0])
def test_three_equal_saddles_lateral_shares_follow_tan_squared_alpha(alpha_deg):
    L = 60.0
    geometry = CargoGeometry((TubeSegment(0.0, L, 8.0, 8.0, 0.08),))
    xs = (0.0, 30.0, 60.0)
    cargo = cargo_on(xs, geometry, 2.0)
    problem = CradleProblem(
        cargo, tuple(PadPair(x, alpha_deg, RADIUS_M, K_V) for x in xs), spring_diagonal_N_per_m=axial_spring(cargo, 30.0)
    )
    heel = 8.0
    result = solve_transverse_statics(problem, heel)
    assert result.outcome is StaticsOutcome.CONVERGED and not result.pad_open.any()
    beam = cargo.vertical
    EI, m = float(beam.element_bending_stiffness_Nm2[0]), float(beam.element_mass_per_length_kg_per_m[0])
    g, phi, a = 9.81, np.deg2rad(heel), np.deg2rad(alpha_deg)
    vertical = three_equal_saddles_reactions(m * g * np.cos(phi), L, EI, K_V)
    lateral = three_equal_saddles_reactions(m * g * np.sin(phi), L, EI, K_V * np.tan(a) ** 2)
    np.testing.assert_allclose(result.pair_vertical_force_N, vertical, rtol=1e-9)
    np.testing.assert_allclose(result.pair_lateral_force_N, lateral, rtol=1e-9)  # heeled to starboard, the pads push to port
    # the middle saddle's share differs across and up by more than a wrong factor could hide
    share_v, share_h = vertical[1] / vertical.sum(), lateral[1] / lateral.sum()
    assert abs(share_v - share_h) > 0.02
    np.testing.assert_allclose(
        result.pad_force_N,
        np.column_stack([vertical / np.cos(a) - lateral / np.sin(a), vertical / np.cos(a) + lateral / np.sin(a)]) / 2,
        rtol=1e-9,
    )


def test_four_saddles_against_a_dense_solve_of_each_plane():
    """Uneven saddles, all pads compressed: each plane is a beam on linear springs, k_v up, k_v tan^2 a across."""
    xs = np.array([6.0, 25.0, 41.0, 70.0])
    k_v = np.array([0.6, 1.1, 2.0, 0.9]) * K_V
    alpha = 38.0
    cargo = cargo_on(xs, element_m=1.5)
    problem = CradleProblem(
        cargo,
        tuple(PadPair(x, alpha, RADIUS_M, k) for x, k in zip(xs, k_v, strict=True)),
        spring_diagonal_N_per_m=axial_spring(cargo, 41.0),
    )
    heel = 6.0
    result = solve_transverse_statics(problem, heel)
    assert result.outcome is StaticsOutcome.CONVERGED and not result.pad_open.any()
    beam, a, phi = cargo.vertical, np.deg2rad(alpha), np.deg2rad(heel)
    nodes = np.array([cargo.node_at(x) for x in xs])
    reactions = []
    for load, k in ((np.cos(phi), k_v), (np.sin(phi), k_v * np.tan(a) ** 2)):
        m = beam.element_mass_per_length_kg_per_m
        K, _, f = assemble_beam(beam.node_x_m, beam.element_bending_stiffness_Nm2, m, load_N_per_m=-m * 9.81 * load)
        K[2 * nodes, 2 * nodes] += k
        reactions.append(-k * np.linalg.solve(K, f)[2 * nodes])
    np.testing.assert_allclose(result.pair_vertical_force_N, reactions[0], rtol=1e-8)
    np.testing.assert_allclose(result.pair_lateral_force_N, reactions[1], rtol=1e-8)


# ---------------------------------------------------------------- (c) the high-side pad lifts, a stopper carries the rest


@pytest.mark.parametrize("heel_deg, alpha_deg", [(40.0, 35.0), (33.0, 30.0), (-40.0, 35.0)])
def test_high_side_pad_lifts_and_the_stopper_carries_the_rest(heel_deg, alpha_deg):
    xs = (10.0, 52.0)
    cargo = cargo_on(xs)
    low = Side.STARBOARD if heel_deg > 0 else Side.PORT
    stoppers = tuple(SideStopper(x, side, 0.01, 2e8) for x in xs for side in (Side.PORT, Side.STARBOARD))
    problem = CradleProblem(
        cargo, tuple(PadPair(x, alpha_deg, RADIUS_M, K_V) for x in xs), stoppers, spring_diagonal_N_per_m=axial_spring(cargo, 10.0)
    )
    result = solve_transverse_statics(problem, heel_deg)
    assert result.outcome is StaticsOutcome.CONVERGED
    check_complementarity(result, problem)
    W_s = saddle_weights_N(cargo, *xs)
    phi, a = np.deg2rad(abs(heel_deg)), np.deg2rad(alpha_deg)
    high, low_column = (0, 1) if low is Side.STARBOARD else (1, 0)
    np.testing.assert_array_equal(result.pad_force_N[:, high], 0.0)  # exactly nothing on the high side
    np.testing.assert_allclose(result.pad_force_N[:, low_column], W_s * np.cos(phi) / np.cos(a), rtol=1e-9)
    stopper = result.stopper_force_N.reshape(2, 2)  # (saddle, port/starboard)
    np.testing.assert_allclose(stopper[:, low_column], W_s * (np.sin(phi) - np.cos(phi) * np.tan(a)), rtol=1e-9)
    np.testing.assert_array_equal(stopper[:, high], 0.0)
    # the cargo has moved past the gap towards the low side
    v = result.displacement[2 * cargo.node_count : 4 * cargo.node_count : 2][[cargo.node_at(x) for x in xs]]
    assert np.all(np.abs(v) > 0.01) and np.all(np.sign(v) == (-1 if low is Side.STARBOARD else 1))


def test_below_the_pad_angle_both_pads_hold_and_the_stopper_stays_open():
    xs = (10.0, 52.0)
    cargo = cargo_on(xs)
    stoppers = tuple(SideStopper(x, Side.STARBOARD, 0.01, 2e8) for x in xs)
    problem = CradleProblem(
        cargo, tuple(PadPair(x, 35.0, RADIUS_M, K_V) for x in xs), stoppers, spring_diagonal_N_per_m=axial_spring(cargo, 10.0)
    )
    result = solve_transverse_statics(problem, 30.0)
    assert result.outcome is StaticsOutcome.CONVERGED
    np.testing.assert_allclose(result.pad_force_N, pad_forces_both_compressed(saddle_weights_N(cargo, *xs), 30.0, 35.0), rtol=1e-9)
    np.testing.assert_array_equal(result.stopper_force_N, 0.0)


def test_without_a_stopper_a_cargo_heeled_beyond_the_pads_is_a_mechanism():
    xs = (10.0, 52.0)
    cargo = cargo_on(xs, element_m=3.0)
    problem = CradleProblem(cargo, tuple(PadPair(x, 35.0, RADIUS_M, K_V) for x in xs), spring_diagonal_N_per_m=axial_spring(cargo, 10.0))
    result = solve_transverse_statics(problem, 40.0)
    assert result.outcome is StaticsOutcome.MECHANISM
    assert "cannot hold" in result.message and result.residual_N > 1e3


# ---------------------------------------------------------------- (d) lashings: slack carries zero, taut T0 + k e


def lashed_section_forces(W_s, heel_deg, alpha_deg, k_pad, lashings, taut):
    """The saddle section's pad forces and lashing tensions from its own 2x2 equilibrium in a given set.

    The lashings stand at the saddles, normal to the axis, so rotations do not stretch them and each
    saddle section carries its own weight share (two saddles: statically determinate in each plane).
    At rest (no heel) both pads carry the weight and the pretensions ``T0``; from there a lashing's tension
    is ``T0 - k e . (d - d_rest)`` while taut, zero when slack.
    """
    a, phi = np.deg2rad(alpha_deg), np.deg2rad(heel_deg)
    normals = [np.array([-np.sin(a), np.cos(a)]), np.array([np.sin(a), np.cos(a)])]  # port, starboard pads' push
    K_pads = sum(k_pad * np.outer(m, m) for m in normals)
    directions = [lashing.direction[1:] for lashing in lashings]
    d_rest = np.linalg.solve(
        K_pads, W_s * np.array([0.0, -1.0]) + sum(lashing.pretension_N * e for lashing, e in zip(lashings, directions, strict=True))
    )
    K, load = K_pads.copy(), W_s * np.array([-np.sin(phi), -np.cos(phi)])
    for lashing, e, is_taut in zip(lashings, directions, taut, strict=True):
        if is_taut:
            K += lashing.stiffness_N_per_m * np.outer(e, e)
            load += (lashing.pretension_N + lashing.stiffness_N_per_m * (e @ d_rest)) * e
    d = np.linalg.solve(K, load)
    pads = np.array([k_pad * max(-m @ d, 0.0) for m in normals])
    tensions = np.array(
        [lashing.pretension_N - lashing.stiffness_N_per_m * (e @ (d - d_rest)) for lashing, e in zip(lashings, directions, strict=True)]
    )
    return pads, tensions


@pytest.mark.parametrize("heel_deg, taut", [(0.0, (True, True)), (20.0, (True, False)), (-20.0, (False, True))])
def test_a_slack_lashing_carries_exactly_zero_and_a_taut_one_its_pretension_plus_stretch(heel_deg, taut):
    xs = (17.0, 57.0)  # symmetric about the middle: equal shares
    cargo = cargo_on(xs)
    alpha, T0, k_l = 35.0, 5e4, 5e7
    lashings = tuple(
        Lashing((x, side.sign * RADIUS_M, 0.0), (x, side.sign * (RADIUS_M + 2.5), -RADIUS_M - 1.0), k_l, T0)
        for x in xs
        for side in (Side.PORT, Side.STARBOARD)
    )
    problem = CradleProblem(
        cargo, tuple(PadPair(x, alpha, RADIUS_M, K_V) for x in xs), (), lashings, spring_diagonal_N_per_m=axial_spring(cargo, 17.0)
    )
    result = solve_transverse_statics(problem, heel_deg)
    assert result.outcome is StaticsOutcome.CONVERGED
    check_complementarity(result, problem)
    W_s = saddle_weights_N(cargo, *xs)[0]
    pads, tensions = lashed_section_forces(W_s, heel_deg, alpha, PadPair(0, alpha, RADIUS_M, K_V).pad_stiffness_N_per_m, lashings[:2], taut)
    assert np.all(np.where(taut, tensions > 0.0, tensions < 0.0))  # the set assumed is the consistent one
    tension = result.lashing_tension_N.reshape(2, 2)
    for saddle in range(2):
        np.testing.assert_allclose(result.pad_force_N[saddle], pads, rtol=1e-9)
        for side in range(2):
            if taut[side]:
                assert tension[saddle, side] == pytest.approx(tensions[side], rel=1e-9)
                # at rest exactly the pretension; heeled, pretension plus stiffness times elongation
                assert tension[saddle, side] == pytest.approx(T0, rel=1e-9) if heel_deg == 0.0 else tension[saddle, side] > 1.1 * T0
            else:
                assert tension[saddle, side] == 0.0  # exactly
    assert bool(result.lashing_slack.any()) == (heel_deg != 0.0)


def test_a_very_soft_lashing_does_not_loosen_the_pads_signs():
    """Lashings whose pretension over stiffness is 1e5 m, heeled just past the pad angle: the high-side pads must
    lift and the stoppers take the rest. The sign check is on forces: one relative to that 1e5 m engagement passed
    the first set, every pad engaged and the high-side ones pulling, 1.1 kN out of balance."""
    xs = (10.0, 52.0)
    cargo = cargo_on(xs)
    alpha, heel = 35.0, 35.01
    lashings = tuple(
        Lashing((x, side.sign * RADIUS_M, 0.0), (x, side.sign * (RADIUS_M + 2.5), -RADIUS_M - 1.0), 1e-8, 1e-3)
        for x in xs
        for side in (Side.PORT, Side.STARBOARD)
    )
    stoppers = tuple(SideStopper(x, side, 0.01, 2e8) for x in xs for side in (Side.PORT, Side.STARBOARD))
    problem = CradleProblem(
        cargo, tuple(PadPair(x, alpha, RADIUS_M, K_V) for x in xs), stoppers, lashings, spring_diagonal_N_per_m=axial_spring(cargo, 10.0)
    )
    result = solve_transverse_statics(problem, heel)
    assert result.outcome is StaticsOutcome.CONVERGED
    W_s = saddle_weights_N(cargo, *xs)
    assert result.residual_N <= 1e-9 * float(np.sum(W_s))
    phi, a = np.deg2rad(heel), np.deg2rad(alpha)
    np.testing.assert_array_equal(result.pad_force_N[:, 0], 0.0)  # the high (port) side lifted
    stopper = result.stopper_force_N.reshape(2, 2)
    np.testing.assert_allclose(stopper[:, 1], W_s * (np.sin(phi) - np.cos(phi) * np.tan(a)), rtol=1e-5)  # 1e-3 N lashings aside


# ---------------------------------------------------------------- (e) zero heel: today's exact statics


def todays_static_saddle_forces(model: StructuralModel) -> tuple[np.ndarray, np.ndarray]:
    """Saddle forces [N] and cargo displacement of the vertical-plane exact statics on a rigid deck (still water)."""
    excitation = HarmonicExcitation(
        0.5,
        np.zeros((1, model.deck_dof_count), dtype=complex),
        np.zeros((1, model.cargo_dof_count), dtype=complex),
        np.zeros((1, model.cargo.element_count), dtype=complex),
    )
    response = solve_quasi_static(model, excitation)
    return response.saddle_force_time_N[0], response.cargo_displacement_time_m[0]


def cradles_of(model: StructuralModel, alpha_deg: float) -> CradleProblem:
    cargo = build_cargo3d(model.cargo)
    springs, load = vertical_plane_restraint(model, cargo)
    springs[cargo.node_dofs(int(model.saddle_node[0]))[0]] += 1e8  # an axial restraint (uncoupled at zero heel)
    pairs = tuple(
        PadPair(float(x), alpha_deg, RADIUS_M, float(k))
        for x, k in zip(model.saddle_x_m, model.saddle_unilateral_stiffness_N_per_m, strict=True)
    )
    return CradleProblem(cargo, pairs, spring_diagonal_N_per_m=springs, load_N=load)


@pytest.mark.parametrize("alpha_deg", [30.0, 45.0])
def test_zero_heel_gives_todays_saddle_forces_on_the_base_case(alpha_deg):
    model = build_model(load_case())
    forces, displacement = todays_static_saddle_forces(model)
    result = solve_transverse_statics(cradles_of(model, alpha_deg), 0.0, gravity_m_per_s2=model.gravity_m_per_s2)
    assert result.outcome is StaticsOutcome.CONVERGED
    np.testing.assert_allclose(result.pair_vertical_force_N, forces, rtol=1e-9)
    np.testing.assert_allclose(result.pad_force_N[:, 0], result.pad_force_N[:, 1], rtol=1e-12)
    np.testing.assert_allclose(result.displacement[: model.cargo_dof_count], displacement, rtol=1e-9, atol=1e-12)
    assert np.max(np.abs(result.pair_lateral_force_N)) < 1e-9 * np.max(forces)


def test_zero_heel_gives_todays_saddle_forces_when_a_saddle_lifts():
    """A short span beside a long one lifts the end saddle in still water: a nontrivial contact set."""
    sf = SeaFastening(np.array([1.0, 10.0, 70.0]), np.full(3, 2e10), np.array([True, False, True]))  # stiff saddles
    model = build_structural_model(TUBE, sf, target_element_length_m=1.0)
    forces, _ = todays_static_saddle_forces(model)
    assert forces[0] == 0.0 and np.all(forces[1:] > 0.0)
    result = solve_transverse_statics(cradles_of(model, 35.0), 0.0, gravity_m_per_s2=model.gravity_m_per_s2)
    assert result.outcome is StaticsOutcome.CONVERGED
    np.testing.assert_allclose(result.pair_vertical_force_N, forces, rtol=1e-9, atol=1e-9 * np.max(forces))
    np.testing.assert_array_equal(result.pad_open[0], True)


# ---------------------------------------------------------------- properties: complementarity and equilibrium


def resultant(problem: CradleProblem, result: TransverseStatics, heel_deg: float, trim_deg: float) -> np.ndarray:
    """The (x, y, z) force and (x-lever) moments of every element's push plus the weight, from the geometry alone [N, N m]."""
    cargo = problem.cargo
    W = cargo.vertical.mass_kg * 9.81
    phi, theta = np.deg2rad(heel_deg), np.deg2rad(trim_deg)
    gravity = W * np.array([-np.sin(theta), -np.cos(theta) * np.sin(phi), -np.cos(theta) * np.cos(phi)])
    x = cargo.node_x_m
    x_g = float(np.sum(cargo.vertical.element_mass_per_length_kg_per_m * np.diff(x) * 0.5 * (x[1:] + x[:-1])) / cargo.vertical.mass_kg)
    forces = [(gravity, x_g, (0.0, 0.0))]
    for pair, pads in zip(problem.pad_pairs, result.pad_force_N, strict=True):
        for side, F in zip((Side.PORT, Side.STARBOARD), pads, strict=True):
            forces.append((F * np.r_[0.0, pair.pad_normal(side)], pair.x_m, tuple(pair.pad_point_m(side))))
    for stopper, F in zip(problem.stoppers, result.stopper_force_N, strict=True):
        forces.append((np.array([0.0, -Side(stopper.side).sign * F, 0.0]), stopper.x_m, (Side(stopper.side).sign * RADIUS_M, 0.0)))
    for lashing, T in zip(problem.lashings, result.lashing_tension_N, strict=True):
        forces.append((T * lashing.direction, lashing.cargo_point_m[0], tuple(lashing.cargo_point_m[1:])))
    spring = problem.spring_diagonal_N_per_m
    u_dofs = 4 * cargo.node_count + np.arange(cargo.node_count)
    axial = -(spring[u_dofs] * result.displacement[u_dofs]).sum()
    total = sum(f for f, _, _ in forces) + np.array([axial, 0.0, 0.0])
    # moments about the aft end's axis point, of the lateral and vertical planes: x f_y - y f_x and x f_z - z f_x
    moments = sum(np.array([f[1] * at - r[0] * f[0], f[2] * at - r[1] * f[0]]) for f, at, r in forces)
    return np.concatenate([total, moments])


@settings(max_examples=60, deadline=None)
@given(
    heel_deg=st.floats(-50.0, 50.0),
    trim_deg=st.floats(-5.0, 5.0),
    alpha_deg=st.floats(20.0, 60.0),
    stiffness_factors=st.lists(st.floats(0.05, 5.0), min_size=2, max_size=4),
    gap_m=st.floats(0.0, 0.05),
    pretension_N=st.floats(0.0, 3e5),
    lashing_k=st.floats(1e6, 1e8),
)
def test_random_cradles_are_complementary_and_in_equilibrium(
    heel_deg, trim_deg, alpha_deg, stiffness_factors, gap_m, pretension_N, lashing_k
):
    n = len(stiffness_factors)
    xs = np.linspace(8.0, 66.0, n)
    cargo = cargo_on(xs, element_m=2.9)
    pairs = tuple(PadPair(float(x), alpha_deg, RADIUS_M, f * K_V) for x, f in zip(xs, stiffness_factors, strict=True))
    stoppers = tuple(SideStopper(float(x), side, gap_m, 3e8) for x in (xs[0], xs[-1]) for side in (Side.PORT, Side.STARBOARD))
    lashings = tuple(
        Lashing((float(x), side.sign * RADIUS_M * 0.7, RADIUS_M * 0.7), (float(x) + 2.0, side.sign * 6.0, -5.0), lashing_k, pretension_N)
        for x in (xs[0], xs[-1])
        for side in (Side.PORT, Side.STARBOARD)
    )
    problem = CradleProblem(cargo, pairs, stoppers, lashings, spring_diagonal_N_per_m=axial_spring(cargo, float(xs[0]), 1e7))
    result = solve_transverse_statics(problem, heel_deg, trim_deg)
    assert result.outcome is StaticsOutcome.CONVERGED, result.message
    check_complementarity(result, problem)
    W = cargo.vertical.mass_kg * 9.81
    # force balance from the geometry (independent of the stiffness matrix) and of the y and z moments
    np.testing.assert_allclose(resultant(problem, result, heel_deg, trim_deg), 0.0, atol=1e-8 * W * 74.0)
    assert result.residual_N < 1e-8 * W
