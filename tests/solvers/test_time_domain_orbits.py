"""Which orbit the time-domain reference reaches, on a bistable case.

The case: the base cargo on 1 % saddles (1.1e7 N/m; bounce 4.53 rad/s, pitch 5.34 rad/s on bilateral
saddles), no rigid-body motions (``vessel.motions: none``), the hull's quasi-static deck deflection of a
9 m wave applied at 3.8 rad/s (0.84 of the bounce and 0.71 of the pitch frequency): the deck under the
saddles moves by about 0.35 m, as much as the saddles' static compression. Two attractors coexist:

* orbit A, a periodic lift-off motion (peak saddle force 8.14 MN, gaps of 40 mm), which the linear
  periodic solution leads to;
* a bouncing motion, the cargo thrown off its saddles by up to 1-3 m and landing with 13-20 MN, not
  periodic (what the full-DOF formulation found from its former quasi-static start).

The harmonic balance also has unstable periodic solutions: from a start shifted by half a period it
converges to orbit C (9.70 MN, 187 mm gaps), which a time integration leaves.

Checked: both formulations started from the same state (the linear periodic solution, or the HBM's
orbit) reach the HBM's orbit A and agree with each other to the period-to-period tolerance; a start
from orbit C is reported as ``OTHER_ORBIT`` (and what it reached is A) or, from a finer H, ``NOT_PERIODIC``; a start from the quasi-static
state is reported as ``NOT_PERIODIC``. CI-sized: a 4 m mesh (42 DOFs) and 32 samples per period (512 steps).
"""

from __future__ import annotations

import logging

import numpy as np
import pytest
from threadpoolctl import threadpool_limits

from seafast.config import load_case
from seafast.config.modes import TimeDomainStart
from seafast.excitation.vessel import vessel_excitation
from seafast.fourier import harmonics_to_time
from seafast.model.from_case import build_model
from seafast.solvers.hbm import HBMOptions, solve_hbm
from seafast.solvers.linear import solve_linear
from seafast.solvers.outcome import SolverOutcome
from seafast.solvers.references import TimeDomainOptions, solve_time_domain
from seafast.solvers.references.orbit import ORBIT_TOLERANCE, orbit_distance, settling_periods, start_state

N = 32
BISTABLE = {
    "seafastening.saddle_stiffness_N_per_m": 1.1e7,
    "vessel.motions": "none",
    "wave.amplitude_m": 9.0,
    "wave.frequency_rad_s": 3.8,
    "model.element_length_m": 4.0,
}


@pytest.fixture(scope="module")
def case():
    with threadpool_limits(1):
        c = load_case(overrides=BISTABLE)
        model = build_model(c)
        ex = vessel_excitation(c).cargo_excitation(model, c)
        hbm = solve_hbm(model, ex)  # default: exact law, adaptive H, started from the march of the linear solution
    return model, ex, hbm


@pytest.fixture(scope="module")
def from_linear(case):
    model, ex, _ = case
    with threadpool_limits(1):
        return {f: solve_time_domain(model, ex, TimeDomainOptions(time_samples=N, formulation=f)) for f in ("full", "condensed")}


def on_grid(response, n: int = N) -> np.ndarray:
    """Saddle compressions of a response on the n-sample grid (the HBM's N is a multiple of it)."""
    delta = response.saddle_compression_time_m
    assert delta.shape[0] % n == 0
    return delta[:: delta.shape[0] // n]


def test_the_case_has_the_frequencies_and_the_deck_motion_described(case):
    model, ex, _ = case
    w = model.natural_frequencies_rad_s(True, 2)
    np.testing.assert_allclose(w, [4.532, 5.340], rtol=1e-3)
    assert 0.65 < ex.omega_rad_s / w[1] < 0.75 and 0.8 < ex.omega_rad_s / w[0] < 0.9
    lin = solve_linear(model, ex)
    delta = harmonics_to_time(lin.saddle_compression_m, 256)
    assert delta.min() < 0.0  # the linear model pulls: the cargo lifts off
    assert np.abs(ex.deck_displacement[1, model.saddle_deck_dof]).max() > 0.3  # deck motion ~ static compression
    # the slowest free vibration decays at alpha/2 = 0.097 1/s, 0.16 per period: 200 periods allowed
    assert settling_periods(model, ex.omega_rad_s, 1e-7) == pytest.approx(201, abs=2)


def test_both_formulations_and_the_hbm_reach_the_same_orbit_from_the_linear_solution(case, from_linear):
    model, _, hbm = case
    assert hbm.converged and not hbm.contact_preserved
    assert hbm.max_saddle_force_N == pytest.approx(8.141e6, rel=1e-3)
    assert hbm.max_gap_m == pytest.approx(0.0402, rel=0.01)
    k_u = model.saddle_unilateral_stiffness_N_per_m
    full, condensed = from_linear["full"], from_linear["condensed"]
    for r in (full, condensed):
        assert r.outcome is SolverOutcome.CONVERGED, r.message
        assert r.orbit.start is TimeDomainStart.LINEAR and r.orbit.periodic and r.orbit.distance_from_start is None
        assert 40 < r.orbit.periods < r.options["max_periods"]  # it takes ~75 periods: the former 40 were too few
        # the same orbit as the HBM's: RMS force difference and peak force and gap within 1e-3
        assert orbit_distance(r.saddle_compression_time_m, on_grid(hbm), k_u) < 1e-3
        assert r.max_saddle_force_N == pytest.approx(hbm.max_saddle_force_N, rel=1e-3)
        assert r.max_gap_m == pytest.approx(hbm.max_gap_m, rel=1e-2)
    # one discrete map, one start: the formulations differ by round-off and the period-to-period tolerance
    scale = full.max_saddle_force_N
    assert np.max(np.abs(full.saddle_force_time_N - condensed.saddle_force_time_N)) < 1e-6 * scale
    assert full.orbit.periods == condensed.orbit.periods


def test_started_on_the_hbm_orbit_both_formulations_stay_on_it(case):
    model, ex, hbm = case
    with threadpool_limits(1):
        runs = {f: solve_time_domain(model, ex, TimeDomainOptions(time_samples=N, formulation=f), start=hbm) for f in ("full", "condensed")}
    for r in runs.values():
        assert r.outcome is SolverOutcome.CONVERGED, r.message
        assert r.orbit.start is TimeDomainStart.GIVEN and r.orbit.start_method == "hbm"
        assert r.orbit.same_as_start is True and r.orbit.distance_from_start < 1e-3 < ORBIT_TOLERANCE
    assert np.max(np.abs(runs["full"].saddle_force_time_N - runs["condensed"].saddle_force_time_N)) < 1e-6 * hbm.max_saddle_force_N


#: Orbit C is unstable: which attractor a march from it reaches is decided by the start's own error along
#: the unstable direction, i.e. by the HBM's truncation (1e-4 .. 1e-6, twelve orders above round-off),
#: so it is deterministic for a fixed H. Measured: from H = 8 or 10 the march settles on orbit A; from
#: H = 6, 12, 14, 16, 20, 24 it is thrown into the bouncing motion. The tests pin H.
ORBIT_C_TO_A_HARMONICS = 10
ORBIT_C_TO_BOUNCING_HARMONICS = 24


def orbit_c(model, ex, harmonics: int):
    lin = harmonics_to_time(solve_linear(model, ex).saddle_compression_m, 256)
    return solve_hbm(model, ex, HBMOptions(continuation=False, harmonics=harmonics), initial_compression_m=np.roll(lin, 128, axis=0))


def test_a_start_on_another_orbit_is_reported_as_another_orbit(case, from_linear):
    """The HBM from a start shifted by half a period finds orbit C, an unstable periodic solution; the
    time-domain reference started there (at H = 10) leaves it for orbit A and says so."""
    model, ex, hbm = case
    k_u = model.saddle_unilateral_stiffness_N_per_m
    with threadpool_limits(1):
        other = orbit_c(model, ex, ORBIT_C_TO_A_HARMONICS)
        assert other.converged and other.max_saddle_force_N == pytest.approx(9.700e6, rel=2e-3)
        assert orbit_distance(on_grid(other), on_grid(hbm), k_u) > 0.1  # a different periodic solution of the HBM
        r = solve_time_domain(model, ex, TimeDomainOptions(time_samples=N), start=other)
    assert r.outcome is SolverOutcome.OTHER_ORBIT and r.converged, r.message
    assert r.orbit.periodic and r.orbit.same_as_start is False and r.orbit.distance_from_start > 0.1
    # what it reached is orbit A, the linear start's
    assert orbit_distance(r.saddle_compression_time_m, from_linear["full"].saddle_compression_time_m, k_u) < 1e-4


def test_a_start_on_orbit_c_that_leads_to_the_bouncing_motion_is_not_periodic(case):
    """From orbit C solved at H = 24 the march is thrown off its saddles: never the start's orbit, and
    reported NOT_PERIODIC with the impacts' forces, not as converged."""
    model, ex, _ = case
    with threadpool_limits(1):
        other = orbit_c(model, ex, ORBIT_C_TO_BOUNCING_HARMONICS)
        assert other.converged and other.max_saddle_force_N == pytest.approx(9.700e6, rel=2e-3)
        r = solve_time_domain(model, ex, TimeDomainOptions(time_samples=N), start=other)
    assert r.outcome is SolverOutcome.NOT_PERIODIC and not r.converged, r.message
    assert r.orbit.same_as_start is not True and r.orbit.distance_from_start > 0.1
    assert r.max_saddle_force_N > 1.4 * other.max_saddle_force_N  # landing impacts of 13-20 MN


def test_a_coarse_solution_of_the_same_orbit_is_the_same_orbit():
    """The source's preset (tanh law, H = 5) is a coarse picture of the base-like test wave's one orbit:
    started there, the reference stays on that orbit and says so. The orbits are compared through the
    start's 5 harmonics (the ringing after each re-contact, which 5 harmonics cannot carry, is not
    another orbit): 1.0e-2, within the tolerance, where the whole histories differ by 1.5e-2."""
    from seafast.solvers.hbm import SOURCE_OPTIONS
    from solver_cases import base_model, wave_excitation

    model = base_model()
    ex = wave_excitation(model)
    with threadpool_limits(1):
        source = solve_hbm(model, ex, SOURCE_OPTIONS)
        r = solve_time_domain(model, ex, TimeDomainOptions(time_samples=128), start=source)
    assert r.outcome is SolverOutcome.CONVERGED and r.orbit.same_as_start, r.message
    assert 2e-3 < r.orbit.distance_from_start < 0.5 * ORBIT_TOLERANCE
    k_u = model.saddle_unilateral_stiffness_N_per_m
    whole = orbit_distance(r.saddle_compression_time_m, source.saddle_compression_time_m, k_u)
    assert whole > r.orbit.distance_from_start
    assert orbit_distance(r.saddle_compression_time_m, source.saddle_compression_time_m, k_u, 5) == pytest.approx(
        r.orbit.distance_from_start, rel=1e-12
    )


@pytest.mark.parametrize("formulation", ["full", "condensed"])
def test_the_quasi_static_start_escapes_to_the_bouncing_motion(case, formulation):
    """What the former quasi-static start found: from the exact-contact quasi-static state at t = 0 the cargo is thrown off its
    saddles within four periods and bounces, not periodically, with twice orbit A's forces."""
    model, ex, hbm = case
    with threadpool_limits(1):
        r = solve_time_domain(
            model, ex, TimeDomainOptions(time_samples=N, formulation=formulation, start=TimeDomainStart.QUASI_STATIC, max_periods=30)
        )
    assert r.outcome is SolverOutcome.NOT_PERIODIC and not r.converged
    assert r.orbit.start is TimeDomainStart.QUASI_STATIC and not r.orbit.periodic and r.orbit.periods == 30
    assert r.orbit.period_change > 0.1  # far from repeating
    assert r.max_saddle_force_N > 1.5 * hbm.max_saddle_force_N and r.max_gap_m > 0.5


def test_start_states(case):
    """The linear start is the linear periodic solution at t = 0; a given start is the solution's state at t = 0."""
    model, ex, hbm = case
    dt = 2 * np.pi / ex.omega_rad_s / (16 * N)
    lin = solve_linear(model, ex).cargo_displacement
    s = start_state(model, ex, TimeDomainStart.LINEAR, N, dt)
    np.testing.assert_allclose(s.displacement, np.real(lin.sum(axis=0)), rtol=1e-12, atol=1e-15)
    k = np.arange(lin.shape[0])[:, None]
    np.testing.assert_allclose(s.velocity, np.real((1j * k * ex.omega_rad_s * lin).sum(axis=0)), rtol=1e-12, atol=1e-15)
    g = start_state(model, ex, hbm, N, dt)
    np.testing.assert_allclose(g.displacement, hbm.cargo_displacement_time_m[0], rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(g.compression_m, on_grid(hbm), rtol=1e-9, atol=1e-12)
    # the velocity: the central difference of the sampled solution, to the difference's own O(dt^2) error
    x = hbm.cargo_displacement_time_m
    h = 2 * np.pi / ex.omega_rad_s / x.shape[0]
    np.testing.assert_allclose(g.velocity, (x[1] - x[-1]) / (2 * h), rtol=0, atol=2e-3 * np.max(np.abs(g.velocity)))


def test_bad_starts_are_refused(case):
    model, ex, hbm = case
    from dataclasses import replace

    with pytest.raises(ValueError, match="start: a solution at"):
        solve_time_domain(model, ex, TimeDomainOptions(time_samples=N), start=replace(hbm, omega_rad_s=1.0))
    with pytest.raises(ValueError, match="start = "):
        solve_time_domain(model, ex, TimeDomainOptions(time_samples=N, start=TimeDomainStart.GIVEN))
    with pytest.raises(ValueError, match="orbit_tolerance"):
        solve_time_domain(model, ex, TimeDomainOptions(time_samples=N, orbit_tolerance=0.0))
    logging.getLogger(__name__).debug("refused as expected")
