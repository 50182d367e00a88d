"""Exact-event shooting of the 3-D cargo on its cradles (docs/transverse.md#7-dynamics): against the time domain, the
harmonic balance at large H and the march; the modal cutoff's convergence; the default cradle solve's wiring."""

from __future__ import annotations

import numpy as np
import pytest

from seafast.solvers.cradle_hbm import solve_cradle_hbm
from seafast.solvers.cradle_march import Periodicity, march_cradle
from seafast.solvers.cradle_shooting import solve_cradle_shooting
from seafast.solvers.hbm import HBMOptions
from seafast.solvers.hbm.harmonics import force_scale_N
from seafast.solvers.outcome import SolverOutcome
from seafast.solvers.references.cradle_time_domain import CradleTimeDomainOptions, solve_cradle_time_domain
from seafast.solvers.shooting import ShootingOptions
from test_cradle_dynamics import BEAM_SEA, small_dynamics, small_excitation


@pytest.fixture(scope="module")
def lifting():
    """The beam sea of the harmonic balance's checks: the port pads lift 21 % of the period, lashings slacken."""
    dynamics = small_dynamics()
    excitation = small_excitation(dynamics.problem.cargo, BEAM_SEA)
    reference = solve_cradle_time_domain(dynamics, excitation, CradleTimeDomainOptions(time_samples=512))
    return dynamics, excitation, solve_cradle_shooting(dynamics, excitation), reference


def test_shooting_matches_the_time_domain_where_a_pad_lifts_and_a_lashing_goes_slack(lifting):
    """Peaks and least forces within 0.5 % of LSODA's (measured 2e-5), open fractions within a sample of 512, the pair
    forces sample by sample (shooting's grid a multiple of 512) within 1 % of the largest (the ringing after each
    re-contact, as the harmonic balance's check; median below 0.1 %)."""
    dynamics, _, shot, reference = lifting
    assert shot.converged and reference.converged, shot.message
    assert "exact-event shooting" in shot.message
    assert np.all(shot.open_fraction[[0, 2]] > 0.1) and np.all(shot.open_fraction[[1, 3]] == 0.0) and np.all(shot.open_fraction[8:] > 0.1)
    scale = np.max(reference.max_force_N)
    np.testing.assert_allclose(shot.max_force_N, reference.max_force_N, rtol=5e-3, atol=1e-6 * scale)
    np.testing.assert_allclose(shot.min_force_N, reference.min_force_N, atol=1e-3 * scale)
    step = shot.time_s.size // 512
    assert step >= 1 and shot.time_s.size == 512 * step
    np.testing.assert_allclose(shot.open_fraction, reference.open_fraction, atol=1.5 / 512)
    np.testing.assert_allclose(shot.pair_force_N[::step], reference.pair_force_N, atol=1e-2 * scale)  # measured 6.6e-3
    assert np.median(np.abs(shot.pair_force_N[::step] - reference.pair_force_N)) < 1e-3 * scale
    # exact zeros where open or slack, k s where engaged
    k = dynamics.problem.element_stiffness_N_per_m
    np.testing.assert_array_equal(shot.element_force_N, k * np.maximum(shot.engagement_m, 0.0))


def test_the_engagements_follow_from_the_cargo_displacements(lifting):
    """The reported cargo DOFs give back every engagement, ``s = s0 + A q + E x_o(t)`` (the modal part, the residual
    flexibility's static part and the linear solution reassembled): 1e-9 of the largest engagement."""
    dynamics, excitation, shot, _ = lifting
    N = shot.time_s.size
    phase = np.exp(2j * np.pi * np.arange(N) / N)
    xo = excitation.deck_displacement
    deck = np.real(xo[0])[None] + np.real(np.outer(phase, xo[1]))
    s = dynamics.initial_engagement_m + shot.cargo_displacement_m @ dynamics.problem.engagement_matrix.T + deck @ dynamics.deck_engagement.T
    np.testing.assert_allclose(s, shot.engagement_m, atol=1e-9 * np.max(np.abs(shot.engagement_m)))


def test_shooting_is_the_harmonic_balance_converged_in_h(lifting):
    """The harmonic balance at H = 256 (converged to its truncation) carries the same peaks within 0.1 % of the largest."""
    dynamics, excitation, shot, _ = lifting
    hbm = solve_cradle_hbm(dynamics, excitation, HBMOptions(harmonics=256))
    assert hbm.converged, hbm.message
    np.testing.assert_allclose(shot.max_force_N, hbm.max_force_N, atol=1e-3 * np.max(hbm.max_force_N))


def test_strong_lift_off_with_the_stoppers_closing_matches_every_mode_and_the_march():
    """1.5 times the beam sea: the port pads lift a third of the period, every stopper closes (brought into the linear
    part), the cutoff is doubled for their impacts. Converged; within 0.2 % of the largest from the solve with every
    mode kept (the reduction exact; measured 7e-5); the Newmark march (T / 2048) within 0.2 % of each pad's and
    lashing's peak (measured 1.1e-3) and 2 % of each stopper's (their impacts are short and Newmark's contact switches
    at its steps; measured 1.1e-2). (LSODA on 2048 samples, 16 s, is within 0.06 % of the pads' and lashings' sampled
    peaks and 1.2 % of the stoppers'.)"""
    dynamics = small_dynamics()
    excitation = small_excitation(dynamics.problem.cargo, 1.5 * BEAM_SEA)
    shot = solve_cradle_shooting(dynamics, excitation)
    assert shot.converged, shot.message
    assert "cutoff doubled" in shot.message and "0 stopper(s) open all period" in shot.message
    assert np.all(shot.open_fraction[[0, 2]] > 0.3) and np.all(shot.max_force_N[4:8] > 0.0)
    exact = solve_cradle_shooting(dynamics, excitation, ShootingOptions(cutoff_factor=1e5))
    assert "every mode" in exact.message
    largest = np.max(exact.max_force_N)
    np.testing.assert_allclose(shot.max_force_N, exact.max_force_N, atol=2e-3 * largest)
    march = march_cradle(dynamics, excitation, 2048)
    assert march.periodicity is Periodicity.PERIODIC
    change = np.abs(march.element_force_N.max(axis=0) - shot.max_force_N) / force_scale_N(shot.max_force_N)
    assert np.all(change[[0, 1, 2, 3, 8, 9, 10, 11]] <= 2e-3) and np.all(change[4:8] <= 2e-2), change


def test_the_modal_cutoff_converges():
    """The peaks as the cutoff grows (4, 8, 16, 32 times the reference frequency, then every mode): each within 2e-3
    of the largest from every mode kept from 8 on, and 16 (the default) within 5e-4 (measured 3e-6)."""
    dynamics = small_dynamics()
    excitation = small_excitation(dynamics.problem.cargo, BEAM_SEA)
    peaks = {
        f: solve_cradle_shooting(dynamics, excitation, ShootingOptions(cutoff_factor=f)).max_force_N for f in (4.0, 8.0, 16.0, 32.0, 1e5)
    }
    exact = peaks.pop(1e5)
    largest = np.max(exact)
    errors = {f: float(np.max(np.abs(p - exact))) / largest for f, p in peaks.items()}
    assert errors[8.0] <= 2e-3 and errors[16.0] <= 5e-4 and errors[32.0] <= 5e-4, errors


def test_the_default_cradle_solve_is_the_shooting_and_a_fixed_h_the_harmonic_balance(lifting):
    dynamics, excitation, shot, _ = lifting
    default = solve_cradle_hbm(dynamics, excitation)
    np.testing.assert_array_equal(default.element_force_N, shot.element_force_N)
    assert default.harmonics == shot.time_s.size // 2 - 1
    fixed = solve_cradle_hbm(dynamics, excitation, HBMOptions(harmonics=64))
    assert "harmonic balance, H = 64" in fixed.message and fixed.harmonics == 64


def test_where_shooting_fails_the_march_says_what_the_state_is_and_the_default_falls_back(monkeypatch):
    """Newton allowed one step from the linear solution, no march: not converged, with its residual; the march of the
    correction system says the state is periodic. The default cradle solve then answers by the adaptive harmonic
    balance and says so."""
    import seafast.solvers.cradle_hbm as cradle_hbm

    dynamics = small_dynamics()
    excitation = small_excitation(dynamics.problem.cargo, BEAM_SEA)
    weak = ShootingOptions(march_periods=0, max_iterations=1, tolerance=1e-15)
    failed = solve_cradle_shooting(dynamics, excitation, weak)
    assert failed.outcome is SolverOutcome.NOT_CONVERGED and failed.residual > 1e-15 and "not converged" in failed.message
    assert failed.march is not None and failed.periodicity is Periodicity.PERIODIC
    original = cradle_hbm.solve_cradle_shooting
    monkeypatch.setattr(cradle_hbm, "solve_cradle_shooting", lambda d, e: original(d, e, weak))
    fallback = solve_cradle_hbm(dynamics, excitation)
    assert fallback.converged and "adaptive H" in fallback.message and "exact-event shooting did not converge" in fallback.message


def base_case_cradles(alpha_deg: float, wave_factor: float):
    """The base case in beam seas (90 deg) on pads of ``alpha_deg`` at its saddles, a side stopper each side (20 mm gap,
    1e9 N/m), its lashing springs, an axial spring; the wave ``wave_factor`` times as high (benchmarks/bench_cradle.py's)."""
    from dataclasses import replace

    from seafast.config.loader import load_case
    from seafast.excitation.cradle_loads import cradle_excitation_of
    from seafast.excitation.vessel import vessel_excitation
    from seafast.model.cargo3d import build_cargo3d, vertical_plane_restraint
    from seafast.model.cradle import PadPair, Side, SideStopper
    from seafast.model.from_case import build_model
    from seafast.solvers.cradle_dynamics import cradle_dynamics_of
    from seafast.solvers.transverse_statics import CradleProblem

    case = load_case(overrides={"wave.heading_deg": 90.0})
    model = build_model(case)
    cargo = build_cargo3d(model.cargo)
    springs, load = vertical_plane_restraint(model, cargo)
    springs[cargo.node_dofs(int(model.saddle_node[0]))[0]] += 1e8
    stiffness = model.saddle_unilateral_stiffness_N_per_m
    pairs = tuple(PadPair(float(x), alpha_deg, 4.0, float(k)) for x, k in zip(model.saddle_x_m, stiffness, strict=True))
    stoppers = tuple(SideStopper(float(x), side, 0.02, 1e9) for x in model.saddle_x_m for side in (Side.PORT, Side.STARBOARD))
    dynamics = cradle_dynamics_of(model, CradleProblem(cargo, pairs, stoppers, spring_diagonal_N_per_m=springs, load_N=load))
    excitation = cradle_excitation_of(vessel_excitation(case), model, cargo)
    rows = np.array([[1.0], [wave_factor]])
    return dynamics, replace(excitation, cargo_load_N=excitation.cargo_load_N * rows, deck_displacement=excitation.deck_displacement * rows)


def test_the_base_case_strong_lift_off_repeats_every_two_wave_periods():
    """20 deg pads at 1.3 times the base case's beam sea (the high-side pads lift a third of the period, every stopper
    closes): the periodic orbit Newton finds (from halfway between the two states the flow alternates between) has a
    Floquet multiplier near -5, real and negative: it is unstable and the period doubles. The exact-event flow
    settles on a response repeating every two wave periods (to 1e-6; 4e-2 over one), the same at two successive
    cutoffs; the default cradle solve returns that
    orbit of two wave periods (CONVERGED_SUBHARMONIC, Newton on the two-period map, stable) with the verdict, no
    harmonic balance; its peaks, over both periods, at least the flow's over its last one (to 0.1 % of the force
    scale: the flow's grid is coarser)."""
    from seafast.fourier import real_to_complex_harmonics
    from seafast.solvers.cradle_dynamics import cradle_operators
    from seafast.solvers.cradle_shooting_system import (
        cradle_correction_system,
        cradle_modes,
        first_harmonic_time,
        reference_frequency_rad_s,
    )
    from seafast.solvers.shooting.orbit import guarded, shoot_orbit
    from seafast.solvers.shooting.period import PeriodGrid, flow_period
    from seafast.solvers.shooting.states import ContactStates

    dynamics, excitation = base_case_cradles(20.0, 1.3)
    response = solve_cradle_hbm(dynamics, excitation)
    assert response.outcome is SolverOutcome.CONVERGED_SUBHARMONIC and "harmonic balance" not in response.message
    assert response.period_multiple == 2 and "largest Floquet multiplier 0." in response.message
    march = response.march
    assert march is not None and march.periodicity is Periodicity.SUBHARMONIC and march.period_multiple == 2
    assert march.lag_change[1] <= 1e-6 and march.lag_change[0] > 1e-2 and "still changed" not in response.message
    assert np.all(np.mean(march.engagement_m[:, [0, 4]] <= 0.0, axis=0) > 0.3) and np.all(march.element_force_N[:, 6:12].max(axis=0) > 0.0)
    peaks = march.element_force_N.max(axis=0)
    assert np.all(response.max_force_N >= peaks - 1e-3 * force_scale_N(peaks))
    included = np.ones(len(dynamics.problem.engagements), dtype=bool)
    ops = cradle_operators(dynamics, excitation, 1, included)
    modes = cradle_modes(dynamics, included)
    cutoff = 16.0 * reference_frequency_rad_s(modes, modes.engagement_modes, 3)
    system = cradle_correction_system(dynamics, ops, included, modes, cutoff)
    D = real_to_complex_harmonics(ops.linear_compression_m)
    states = ContactStates(system, D, excitation.omega_rad_s)
    scale = float(np.max(np.abs(first_harmonic_time(D, 64))))
    # Newton started halfway between the two states the flow alternates between (a flip's unstable orbit lies between
    # them); from ten marched periods it found it on one machine's BLAS and wandered off on another's
    grid, x = PeriodGrid(states, 2048), np.zeros(states.state_size)
    for _ in range(40):
        x = flow_period(states, x, grid, monodromy=False, guard=guarded(states)).end_state
    other = flow_period(states, x, grid, monodromy=False, guard=guarded(states)).end_state
    options = ShootingOptions(march_periods=0, max_iterations=60)
    orbit = shoot_orbit(states, 2048, scale, options, system.unilateral_stiffness_N_per_m, start=0.5 * (x + other))
    assert orbit.residual <= 1e-8 and not orbit.converged  # a periodic orbit, unstable
    assert orbit.flow.monodromy is not None
    multipliers = np.linalg.eigvals(orbit.flow.monodromy)
    flip = multipliers[np.argmax(np.abs(multipliers))]
    assert abs(flip.imag) < 1e-9 and flip.real < -2.0
