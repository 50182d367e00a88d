"""The 3-D cargo's periodic response on pads, stoppers and slack lashings (docs/transverse.md#7-dynamics)."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from seafast.excitation.cargo_acceleration import acceleration_transfer
from seafast.excitation.cradle_loads import CradleExcitation, cradle_excitation, cradle_excitation_of
from seafast.excitation.harmonic import HarmonicExcitation
from seafast.model.cargo3d import Cargo3D, build_cargo3d, vertical_plane_restraint
from seafast.model.cradle import Lashing, PadPair, Side, SideStopper
from seafast.model.sections import CargoGeometry, TubeSegment
from seafast.model.structure import build_cargo_beam
from seafast.solvers.cradle_dynamics import CradleDynamics, cradle_dynamics_of, cradle_operators
from seafast.solvers.cradle_hbm import ADAPTIVE_HARMONICS, MARCH_SAMPLES, solve_cradle_hbm
from seafast.solvers.cradle_march import Periodicity, contact_correction_N, march_cradle
from seafast.solvers.hbm import HBMOptions, solve_hbm
from seafast.solvers.outcome import SolverOutcome
from seafast.solvers.references.cradle_quasi_static import solve_cradle_quasi_static
from seafast.solvers.references.cradle_time_domain import CradleTimeDomainOptions, solve_cradle_time_domain
from seafast.solvers.transverse_statics import CradleProblem, StaticsOutcome, solve_transverse_statics

RADIUS_M = 2.0
SADDLES_M = (5.0, 15.0)
OMEGA = 0.8


def small_cargo() -> Cargo3D:
    """A 20 m tube, 4 m across, on a 2 m mesh (11 nodes): small enough for the time-domain reference."""
    return build_cargo3d(build_cargo_beam(CargoGeometry((TubeSegment(0.0, 20.0, 4.0, 4.0, 0.04),)), np.array(SADDLES_M), 2.0))


def small_dynamics(alpha_deg: float = 15.0, pretension_N: float = 20e3) -> CradleDynamics:
    """Two cradles, a stopper each side (30 mm gap), a lashing each side of each cradle, an axial spring, 5 % damping."""
    cargo = small_cargo()
    pairs = tuple(PadPair(x, alpha_deg, RADIUS_M, 2e8) for x in SADDLES_M)
    stoppers = tuple(SideStopper(x, side, 0.03, 1e8) for x in SADDLES_M for side in (Side.PORT, Side.STARBOARD))
    lashings = tuple(
        Lashing((x, sy * RADIUS_M, 0.0), (x + dx, sy * (RADIUS_M + 3.0), -RADIUS_M - 2.0), 5e6, pretension_N)
        for x, dx in zip(SADDLES_M, (2.0, -2.0), strict=True)
        for sy in (1.0, -1.0)
    )
    springs = np.zeros(cargo.dof_count)
    springs[cargo.node_dofs(cargo.node_at(SADDLES_M[0]))[0]] = 1e8
    problem = CradleProblem(cargo, pairs, stoppers, lashings, spring_diagonal_N_per_m=springs)
    return CradleDynamics(problem, 2.0, 2e-3, np.array(SADDLES_M))


def small_excitation(cargo: Cargo3D, motions: np.ndarray, omega: float = OMEGA) -> CradleExcitation:
    """Six motions about a point 10 m aft of the cargo's end and 8 m below its axis; the vertical block from the same reading."""
    axis = (-10.0, 0.0, 8.0)
    n = cargo.node_count
    points = np.column_stack([cargo.node_x_m, np.zeros(n), np.zeros(n)]) + np.array(axis)
    f_z = acceleration_transfer(motions, omega, points)[:, 2]
    reading = np.zeros(2 * n, dtype=complex)
    reading[0::2] = f_z
    reading[1::2] = acceleration_transfer(motions, omega, points + [1.0, 0.0, 0.0])[:, 2] - f_z
    load = np.zeros((2, 2 * n), dtype=complex)
    load[1] = -cargo.vertical.mass @ reading
    vertical = HarmonicExcitation(omega, np.zeros((2, 4), dtype=complex), load, np.zeros((2, n - 1), dtype=complex))
    return cradle_excitation(cargo, vertical, motions, np.array(SADDLES_M), axis)


BEAM_SEA = np.array([0.0, 1.0, 2.5, 0.3, 0.0, 0.0], dtype=complex)
"""Sway 1 m, heave 2.5 m and roll 0.3 rad in phase: the high-side (port) pads lift, the starboard lashings slacken."""


@pytest.fixture(scope="module")
def beam_sea_pair():
    dynamics = small_dynamics()
    excitation = small_excitation(dynamics.problem.cargo, BEAM_SEA)
    hbm = solve_cradle_hbm(dynamics, excitation, HBMOptions(harmonics=128, time_samples=512))
    reference = solve_cradle_time_domain(dynamics, excitation, CradleTimeDomainOptions(time_samples=512))
    return hbm, reference


def test_harmonic_balance_matches_the_time_domain_where_a_pad_lifts_and_a_lashing_goes_slack(beam_sea_pair):
    hbm, reference = beam_sea_pair
    assert hbm.converged and reference.converged, (hbm.message, reference.message)
    # the case is the one asked for: the port pads lift, lashings go slack, in both solutions
    for result in (hbm, reference):
        assert np.all(result.open_fraction[[0, 2]] > 0.1)
        assert np.all(result.open_fraction[[1, 3]] == 0.0)
        assert np.all(result.open_fraction[8:] > 0.1)
    scale = np.max(reference.max_force_N)
    np.testing.assert_allclose(hbm.max_force_N, reference.max_force_N, rtol=5e-3, atol=5e-3 * 1e-3 * scale)
    np.testing.assert_allclose(hbm.min_force_N, reference.min_force_N, atol=1e-3 * scale)  # the least pad force: 1.6 kN
    np.testing.assert_allclose(hbm.open_fraction, reference.open_fraction, atol=4.0 / 512)
    # the whole pad-pair force histories on the same grid: within 1 % of the peak sample by sample (the ringing after
    # each re-contact is where 128 harmonics differ most; elsewhere far closer)
    np.testing.assert_allclose(hbm.pair_force_N, reference.pair_force_N, atol=1e-2 * scale)
    assert np.median(np.abs(hbm.pair_force_N - reference.pair_force_N)) < 1e-3 * scale


def test_a_slack_lashing_and_an_open_pad_carry_exactly_zero(beam_sea_pair):
    for result in beam_sea_pair:
        open_ = result.engagement_m <= 0.0
        assert np.any(open_[:, 8:])
        assert np.all(result.element_force_N[open_] == 0.0)
        assert np.all(result.lashing_tension_N[open_[:, 8:]] == 0.0)
        engaged = ~open_
        k = np.broadcast_to(small_dynamics().problem.element_stiffness_N_per_m, result.engagement_m.shape)
        np.testing.assert_allclose(result.element_force_N[engaged], k[engaged] * result.engagement_m[engaged], rtol=1e-12)


def test_the_adaptive_harmonic_balance_matches_the_time_domain_where_a_pad_lifts(beam_sea_pair):
    """The default (H chosen by the change of the peak forces) on the same case: the same peaks as the time domain
    within 0.5 %, and within 1e-3 of the largest of the fixed H = 128 solve."""
    fixed, reference = beam_sea_pair
    dynamics = small_dynamics()
    adaptive = solve_cradle_hbm(dynamics, small_excitation(dynamics.problem.cargo, BEAM_SEA), shooting=False)
    assert adaptive.converged, adaptive.message
    assert adaptive.harmonics in ADAPTIVE_HARMONICS[1:] and "adaptive H" in adaptive.message
    assert 0.0 < adaptive.peak_force_change <= 1e-3  # the peaks settled to the truncation tolerance
    assert np.all(adaptive.open_fraction[[0, 2]] > 0.1) and np.all(adaptive.open_fraction[8:] > 0.1)
    scale = np.max(reference.max_force_N)
    np.testing.assert_allclose(adaptive.max_force_N, reference.max_force_N, rtol=5e-3, atol=5e-6 * scale)
    np.testing.assert_allclose(adaptive.min_force_N, reference.min_force_N, atol=1e-3 * scale)
    np.testing.assert_allclose(adaptive.max_force_N, fixed.max_force_N, atol=1e-3 * scale)
    np.testing.assert_allclose(adaptive.open_fraction, reference.open_fraction, atol=4.0 / adaptive.time_s.size)


def test_the_adaptive_harmonic_balance_is_the_linear_solution_where_every_element_stays_engaged():
    """A small wave: no pad lifts, no lashing slackens; the first H's linear solution is the answer, exactly."""
    dynamics = small_dynamics()
    excitation = small_excitation(dynamics.problem.cargo, 0.05 * BEAM_SEA)
    adaptive = solve_cradle_hbm(dynamics, excitation)
    fixed = solve_cradle_hbm(dynamics, excitation, HBMOptions(harmonics=ADAPTIVE_HARMONICS[0]))
    assert adaptive.converged and adaptive.peak_force_change == 0.0 and adaptive.harmonics == ADAPTIVE_HARMONICS[0]
    assert np.all(adaptive.open_fraction[:4] == 0.0) and np.all(adaptive.open_fraction[8:] == 0.0)
    np.testing.assert_array_equal(adaptive.element_force_N, fixed.element_force_N)


def test_the_receptances_are_the_dense_dynamic_stiffness_solved_and_extend_to_more_harmonics():
    """``G_k = A K_d(k w)^-1 A^T`` by the uncoupled banded blocks (a pad pair's cross terms dropped as round-off, a block
    loaded at fewer DOFs than pads solved for unit loads) equals the dense solve of every DOF; operators extended from
    fewer harmonics are the ones built afresh."""
    dynamics = small_dynamics()
    problem = dynamics.problem
    pads_only = CradleDynamics(replace(problem, lashings=()), 2.0, 2e-3, np.array(SADDLES_M))
    for case in (dynamics, pads_only):
        excitation = small_excitation(case.problem.cargo, BEAM_SEA)
        ops = cradle_operators(case, excitation, 40)
        parts = case.linear_parts()
        K, M, D = parts.bilateral_stiffness, case.matrices[1], case.matrices[2]
        A = parts.engagement_matrix
        for k in (0, 1, 7, 40):
            w = k * excitation.omega_rad_s
            G = A @ np.linalg.solve(K - w**2 * M + 1j * w * D, A.T)
            np.testing.assert_allclose(ops.receptance_harmonics[k], G, rtol=1e-9, atol=1e-9 * np.max(np.abs(G)))
        extended = cradle_operators(case, excitation, 40, reuse=cradle_operators(case, excitation, 24))
        for name in ("receptance_harmonics", "linear_compression_m", "linear_cargo_displacement", "cargo_influence"):
            np.testing.assert_array_equal(getattr(extended, name), getattr(ops, name))
    assert len(pads_only.linear_parts().blocks) == 3  # axial, lateral, vertical: the pads do not couple them


@pytest.mark.parametrize("heel_deg", [2.0, -2.0])
def test_a_very_long_beam_sea_wave_tends_to_the_statics_of_the_heeled_ship(heel_deg):
    """Roll alone at 0.02 rad/s: at the roll's peak the forces are the exact statics at that heel.

    The harmonic load is gravity linearised, (0, -g phi, -g), against the statics' exact (0, -g sin phi, -g cos phi):
    they differ by phi^2 / 2 = 6e-4 at 2 deg; the inertia of the roll, omega^2 phi r_z, by 4e-4 of g phi.
    """
    dynamics = small_dynamics(alpha_deg=3.0, pretension_N=5e3)
    phi = np.deg2rad(heel_deg)
    excitation = small_excitation(dynamics.problem.cargo, np.array([0, 0, 0, phi, 0, 0], dtype=complex), omega=0.02)
    response = solve_cradle_hbm(dynamics, excitation, HBMOptions(harmonics=64))
    statics = solve_transverse_statics(dynamics.problem, heel_deg)
    assert response.converged and statics.outcome is StaticsOutcome.CONVERGED
    forces = np.concatenate([statics.pad_force_N.ravel(), statics.stopper_force_N, statics.lashing_tension_N])
    assert np.any(forces == 0.0) and np.any(statics.lashing_tension_N == 0.0)  # a pad lifted and a lashing slack
    np.testing.assert_allclose(response.element_force_N[0], forces, atol=2e-3 * np.max(forces))
    np.testing.assert_array_equal(response.element_force_N[0] == 0.0, forces == 0.0)
    # half a period later the ship is heeled the other way
    mirrored = solve_transverse_statics(dynamics.problem, -heel_deg)
    half = response.element_force_N[response.time_s.size // 2]
    np.testing.assert_allclose(half[:4], mirrored.pad_force_N.ravel(), atol=2e-3 * np.max(forces))
    # and the quasi-static exact-contact reference on the same grid (the cargo's inertia, (0.02 / 20)^2, neglected):
    # the kinks of the forces where pads lift and lashings slacken are what 64 harmonics smooth
    quasi_static = solve_cradle_quasi_static(dynamics, excitation, response.time_s.size)
    np.testing.assert_allclose(response.element_force_N, quasi_static.element_force_N, atol=5e-4 * np.max(forces))
    np.testing.assert_allclose(response.max_force_N, quasi_static.max_force_N, atol=2e-4 * np.max(forces))
    np.testing.assert_allclose(quasi_static.element_force_N[0], forces, atol=2e-3 * np.max(forces))


def test_the_quasi_static_reference_is_the_exact_statics_at_each_instant():
    """With the deck still and the motions frozen at an instant, the quasi-static reference is the heeled statics."""
    base = small_dynamics()  # the lashings' stretch from the undisplaced cargo: the rest does not depend on g
    dynamics = CradleDynamics(replace(base.problem, pretension_at_rest=False), 2.0, 2e-3, np.array(SADDLES_M))
    phi = 0.3
    excitation = small_excitation(dynamics.problem.cargo, np.array([0, 0, 0, phi, 0, 0], dtype=complex), omega=1e-6)
    response = solve_cradle_quasi_static(dynamics, excitation, 64)
    assert response.residual < 1e-12
    # linearised gravity (0, -g phi, -g) is the exact gravity of a heel atan(phi) with g scaled by sqrt(1 + phi^2)
    heel = np.rad2deg(np.arctan(phi))
    statics = solve_transverse_statics(dynamics.problem, heel, gravity_m_per_s2=9.81 * np.hypot(1.0, phi))
    forces = np.concatenate([statics.pad_force_N.ravel(), statics.stopper_force_N, statics.lashing_tension_N])
    assert np.any(forces == 0.0)
    np.testing.assert_allclose(response.element_force_N[0], forces, rtol=1e-9, atol=1e-9 * np.max(forces))


@pytest.fixture(scope="module")
def head_seas_base_case():
    from seafast.config.loader import load_case
    from seafast.excitation.vessel import vessel_excitation
    from seafast.model.from_case import build_model

    case = load_case()
    model = build_model(case)
    vessel = vessel_excitation(case)
    return model, vessel


@pytest.mark.parametrize("alpha_deg", [30.0, 45.0])
def test_head_seas_pad_pairs_carry_todays_saddle_forces(head_seas_base_case, alpha_deg):
    """Head seas on the base case (saddles lift): each pair's vertical push is the vertical plane's saddle force at the
    same H and N, and it pushes nothing across (the pads k_v / (2 cos^2 alpha) add to today's saddle exactly)."""
    model, vessel = head_seas_base_case
    cargo = build_cargo3d(model.cargo)
    springs, load = vertical_plane_restraint(model, cargo)
    springs[cargo.node_dofs(int(model.saddle_node[0]))[0]] += 1e8  # the surge's axial load held
    pairs = tuple(
        PadPair(float(x), alpha_deg, 4.0, float(k))
        for x, k in zip(model.saddle_x_m, model.saddle_unilateral_stiffness_N_per_m, strict=True)
    )
    stoppers = tuple(SideStopper(float(x), side, 0.02, 1e9) for x in model.saddle_x_m for side in (Side.PORT, Side.STARBOARD))
    dynamics = cradle_dynamics_of(model, CradleProblem(cargo, pairs, stoppers, spring_diagonal_N_per_m=springs, load_N=load))
    options = HBMOptions(harmonics=16)
    response = solve_cradle_hbm(dynamics, cradle_excitation_of(vessel, model, cargo), options)
    today = solve_hbm(model, vessel.cargo_excitation(model), options)
    assert response.converged and today.converged
    assert np.any(today.saddle_force_time_N == 0.0)  # a saddle lifts: the nonlinear regime
    scale = np.max(today.saddle_force_time_N)
    np.testing.assert_allclose(response.pair_force_N[:, :, 1], today.saddle_force_time_N, atol=1e-7 * scale)
    assert np.max(np.abs(response.pair_force_N[:, :, 0])) < 1e-7 * scale
    np.testing.assert_allclose(response.cargo_displacement_m[:, : model.cargo_dof_count], today.cargo_displacement_time_m, atol=1e-9)
    assert np.all(response.stopper_force_N == 0.0)


def test_the_march_of_the_correction_system_matches_the_time_domain_where_a_pad_lifts(beam_sea_pair):
    """The march (modes of the cargo on bilateral elements, the rest static; Newmark at T / 512) settles on the
    time domain's periodic state: peaks within 0.5 %, least forces within 0.3 % of the largest, open fractions
    within 2 samples."""
    _, reference = beam_sea_pair
    dynamics = small_dynamics()
    march = march_cradle(dynamics, small_excitation(dynamics.problem.cargo, BEAM_SEA), 512)
    assert march.periodicity is Periodicity.PERIODIC and march.period_multiple == 1
    assert march.period_change <= 1e-6 and march.periods < 20
    force = march.element_force_N
    np.testing.assert_array_equal(force, dynamics.problem.element_stiffness_N_per_m * np.maximum(march.engagement_m, 0.0))
    scale = np.max(reference.max_force_N)
    np.testing.assert_allclose(force.max(axis=0), reference.max_force_N, rtol=5e-3, atol=5e-3 * 1e-3 * scale)
    np.testing.assert_allclose(force.min(axis=0), reference.min_force_N, atol=3e-3 * scale)
    np.testing.assert_allclose(np.mean(march.engagement_m <= 0.0, axis=0), reference.open_fraction, atol=2.0 / 512)
    assert np.all(march.change_history[-1] <= 1e-6) and march.change_history[0] > 1e-3  # it did move from the linear start


def test_where_no_harmonic_balance_converges_directly_the_solve_marches_and_says_the_state_is_periodic():
    """1.5 times the beam sea: the port pads lift a third of the period and the stoppers close; capped at H = 32 without
    continuations no H converges directly, so the solve marches: the state repeats every wave period."""
    dynamics = small_dynamics()
    excitation = small_excitation(dynamics.problem.cargo, 1.5 * BEAM_SEA)
    response = solve_cradle_hbm(dynamics, excitation, HBMOptions(max_harmonics=32, continuation=False), shooting=False)
    march = response.march
    assert march is not None and response.periodicity is Periodicity.PERIODIC and march.period_multiple == 1
    assert response.outcome is not SolverOutcome.NOT_PERIODIC
    assert march.period_change <= 1e-6 and march.engagement_m.shape == (MARCH_SAMPLES, 12)
    open_fraction = np.mean(march.engagement_m <= 0.0, axis=0)
    assert np.all(open_fraction[[0, 2]] > 0.3) and np.all(open_fraction[4:8] < 0.99)  # strong lift-off; stoppers close
    assert response.harmonics == 32


def test_each_march_step_solves_its_contact_exactly():
    """The step's complementarity problem, ``s = s_p - G c``, ``c = k max(-s, 0)``: exact from any start of the active
    set, on a receptance of stiff elements on a soft structure (``diag(1/k) - G`` nearly singular)."""
    rng = np.random.default_rng(3)
    A = rng.normal(size=(8, 5))
    k = np.full(8, 1e9)
    G = A @ np.linalg.solve(A.T @ (k[:, None] * A) + 1e3 * np.eye(5), A.T)
    for _ in range(20):
        s_p = rng.normal(scale=1e-2, size=8)
        c, open_set = contact_correction_N(G, k, s_p, rng.random(8) < 0.5)
        s = s_p - G @ c
        assert np.all(c >= 0.0)
        np.testing.assert_allclose(c, k * np.maximum(-s, 0.0), atol=1e-6 * np.max(np.abs(k * s_p)))
        assert np.array_equal(open_set, c > 0.0) or np.allclose(c[open_set ^ (c > 0.0)], 0.0)


def test_a_march_that_does_not_repeat_is_reported_as_such_and_the_solve_says_not_periodic(monkeypatch):
    """The classification and its wiring: held to a tolerance no march meets (1e-300), the same march is NOT_PERIODIC,
    and the harmonic balance that needed it ends with the
    outcome NOT_PERIODIC, no ladder, the march on the response."""
    import seafast.solvers.cradle_hbm as cradle_hbm

    dynamics = small_dynamics()
    excitation = small_excitation(dynamics.problem.cargo, 1.5 * BEAM_SEA)
    march = march_cradle(dynamics, excitation, 256, max_periods=12, tolerance=1e-300)
    assert march.periodicity is Periodicity.NOT_PERIODIC and march.period_multiple == 0 and march.periods == 12
    assert march.period_change > 0.0 and march.change_history.size == 11 and np.all(np.isfinite(march.lag_change))
    monkeypatch.setattr(cradle_hbm, "march_cradle", lambda d, e, n: march_cradle(d, e, 256, max_periods=12, tolerance=1e-300))
    response = solve_cradle_hbm(dynamics, excitation, HBMOptions(max_harmonics=32, continuation=False), shooting=False)
    assert response.outcome is SolverOutcome.NOT_PERIODIC and not response.converged
    assert response.periodicity is Periodicity.NOT_PERIODIC and response.march is not None and response.march.periods == 12
