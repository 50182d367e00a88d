"""A cradle design wave whose response repeats every two wave periods (docs/seastate.md): the design-wave solve takes the
subharmonic orbit as its answer, read over both periods, and asks no harmonic balance."""

from __future__ import annotations

import numpy as np

from seafast.analyses.seastate import cradle_design_wave
from seafast.analyses.seastate.cradle_design_wave import solve_cradle_design_wave
from seafast.solvers.outcome import SolverOutcome
from test_cradle_subharmonic import doubling_case


def test_a_period_doubled_design_wave_is_the_two_period_orbit_read_over_both_periods(monkeypatch):
    """The small tube's flip (30 deg pads, 3.5 times the beam sea): converged as a subharmonic of two wave periods, on
    samples spanning 2 T, no harmonic balance called; its peaks are the maxima over both periods, and the two halves
    differ (by more than 1e-3 of the largest peak: reading one period would be another answer)."""
    dynamics, excitation = doubling_case()
    calls: list[int] = []
    monkeypatch.setattr(cradle_design_wave, "solve_cradle_hbm", lambda *a: calls.append(1))
    response = solve_cradle_design_wave(dynamics, excitation)
    assert response.outcome is SolverOutcome.CONVERGED_SUBHARMONIC and response.converged and not calls, response.message
    assert response.period_multiple == 2
    N = response.time_s.size
    period_s = 2.0 * np.pi / excitation.omega_rad_s
    assert abs(response.time_s[-1] + response.time_s[1] - response.time_s[0] - 2.0 * response.time_s[0] - 2.0 * period_s) <= 1e-9 * period_s
    forces = response.element_force_N
    np.testing.assert_array_equal(response.max_force_N, forces.max(axis=0))
    halves = np.abs(forces[: N // 2].max(axis=0) - forces[N // 2 :].max(axis=0))
    assert np.max(halves) > 1e-3 * np.max(forces), halves
