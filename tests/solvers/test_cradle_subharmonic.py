"""The 3-D cargo's period-doubled response by exact-event shooting (docs/transverse.md#7-dynamics): the orbit of two
wave periods against the exact-event flow marched long from rest, its stability, and the default solve's answer."""

from __future__ import annotations

import numpy as np
import pytest

from seafast.fourier import real_to_complex_harmonics
from seafast.solvers.cradle_dynamics import cradle_operators
from seafast.solvers.cradle_hbm import solve_cradle_hbm
from seafast.solvers.cradle_march import Periodicity
from seafast.solvers.cradle_shooting_system import (
    cradle_correction_system,
    cradle_modes,
    deck_time_m,
    first_harmonic_time,
    reference_frequency_rad_s,
    subharmonic_harmonics,
)
from seafast.solvers.outcome import SolverOutcome
from seafast.solvers.shooting import ShootingOptions
from seafast.solvers.shooting.orbit import shoot_orbit, state_change
from seafast.solvers.shooting.period import PeriodGrid, flow_period
from seafast.solvers.shooting.states import ContactStates
from test_cradle_dynamics import BEAM_SEA, small_dynamics, small_excitation

DOUBLING = (30.0, 3.5, 1.4)
"""30 deg pads, 3.5 times the beam sea of the harmonic balance's checks at 1.4 rad/s: the small tube's pads lift, its
stoppers close, and the response repeats every two wave periods (found by a scan of angle, amplitude and frequency)."""


def doubling_case():
    alpha_deg, factor, omega = DOUBLING
    dynamics = small_dynamics(alpha_deg)
    return dynamics, small_excitation(dynamics.problem.cargo, BEAM_SEA * factor, omega)


@pytest.fixture(scope="module")
def doubled():
    dynamics, excitation = doubling_case()
    return dynamics, excitation, solve_cradle_hbm(dynamics, excitation)


def test_the_two_period_orbit_is_the_state_the_exact_event_flow_settles_on():
    """Every element in, the reduced system at the default cutoff: the wave-period orbit has a real Floquet multiplier
    below -1 (-1.009, a flip: the period doubles); Newton on the two-period map (the wave's harmonic at 2, base frequency
    w / 2) from ten marched wave periods converges on a stable orbit, and its start is the flow's state marched from
    rest until it repeats every two periods (to 1e-10), at the matching phase, to 1e-6 of the largest linear
    engagement, while the two halves of that state differ by more than 1e-3 (not a wave-period orbit)."""
    dynamics, excitation = doubling_case()
    included = np.ones(len(dynamics.problem.engagements), dtype=bool)
    ops = cradle_operators(dynamics, excitation, 1, included)
    modes = cradle_modes(dynamics, included)
    system = cradle_correction_system(dynamics, ops, included, modes, 16.0 * reference_frequency_rad_s(modes, modes.engagement_modes, 3))
    D = real_to_complex_harmonics(ops.linear_compression_m)
    scale = float(np.max(np.abs(first_harmonic_time(D, 64))))
    k = system.unilateral_stiffness_N_per_m
    wave = ContactStates(system, D, excitation.omega_rad_s)
    single = shoot_orbit(wave, 1024, scale, ShootingOptions(march_periods=10, max_iterations=60), k)
    assert single.residual <= 1e-8 and not single.converged and single.flow.monodromy is not None
    multipliers = np.linalg.eigvals(single.flow.monodromy)
    flip = multipliers[np.argmax(np.abs(multipliers))]
    assert abs(flip.imag) < 1e-9 and flip.real < -1.005  # measured -1.009: just past the flip
    grid = PeriodGrid(wave, 1024)
    states = [np.zeros(wave.state_size)]
    while len(states) < 600 and (len(states) < 3 or state_change(wave, states[-1] - states[-3], scale) > 1e-10):
        states.append(flow_period(wave, states[-1], grid, monodromy=False).end_state)
    assert state_change(wave, states[-1] - states[-3], scale) <= 1e-10
    assert state_change(wave, states[-1] - states[-2], scale) > 1e-3
    doubled_states = ContactStates(system, subharmonic_harmonics(D, 2), excitation.omega_rad_s / 2.0)
    orbit = shoot_orbit(doubled_states, 2048, scale, ShootingOptions(), k, start=states[10])
    assert orbit.converged and orbit.residual <= 1e-9 and orbit.floquet_multiplier_max < 1.0
    start = orbit.flow.state_samples[0]
    change = min(state_change(wave, start - states[-1], scale), state_change(wave, start - states[-2], scale))
    assert change <= 1e-6


def test_the_default_solve_returns_the_subharmonic_over_two_wave_periods(doubled):
    """The default cradle solve: CONVERGED_SUBHARMONIC (converged), period_multiple 2, the march's verdict kept; its
    samples span two wave periods; its engagements follow from its cargo displacements and the deck's motion over
    those two periods (1e-9 of the largest); the halves differ (by over 1 % of the largest pad force in some pad);
    the maxima are over both."""
    dynamics, excitation, response = doubled
    assert response.outcome is SolverOutcome.CONVERGED_SUBHARMONIC and response.converged and response.period_multiple == 2
    assert response.march is not None and response.periodicity is Periodicity.SUBHARMONIC and response.march.period_multiple == 2
    assert "repeating every 2 wave periods" in response.message
    N = response.time_s.size
    period_s = 2.0 * np.pi / excitation.omega_rad_s
    assert response.time_s[-1] + response.time_s[1] == pytest.approx(2.0 * period_s, rel=1e-12)
    problem = dynamics.problem
    s = dynamics.initial_engagement_m + response.cargo_displacement_m @ problem.engagement_matrix.T
    s += deck_time_m(excitation, N, 2) @ dynamics.deck_engagement.T
    assert np.max(np.abs(s - response.engagement_m)) <= 1e-9 * np.max(np.abs(response.engagement_m))
    pads = response.pad_force_N.reshape(N, -1)
    first, second = pads[: N // 2], pads[N // 2 :]
    assert np.max(np.abs(first - second)) > 1e-2 * np.max(pads)
    assert np.allclose(
        response.max_force_N, np.maximum(response.element_force_N[: N // 2].max(0), response.element_force_N[N // 2 :].max(0))
    )
