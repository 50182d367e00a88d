"""The Monte Carlo realisations of the 3-D cargo on its cradles off head seas: linear synthesis, windowed march, contact.

Checks against independent solutions: each record's variance against the spectral method's (deterministic
amplitudes: exact), the maxima of a few hundred records against the spectral most probable maxima (sampling
statistics), the windowed march against the same march over the whole record where pads lift, stoppers close and
lashings slacken, the nonlinear extremes equal to the linear ones where nothing changes state, and the step's
contact problem with elements open in the linear system against its definition.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.interpolate import CubicSpline

import seafast
from seafast.analyses.seastate.cradle_design_wave import cradle_sea_state, scaled_excitation
from seafast.analyses.seastate.cradle_realisation import (
    CRADLE_QUANTITIES,
    CradleRealisationSettings,
    cradle_realisation_plan,
    evaluate_cradle_realisation,
)
from seafast.analyses.seastate.cradle_transfer import cradle_linear_transfer, cradle_transfer_functions, cradle_unit_excitations
from seafast.analyses.seastate.directional_transfer import sea_state_roll_damping, sea_state_transfer
from seafast.analyses.seastate.spectral import spectral_analysis
from seafast.analyses.seastate.synthesis import amplitude_factors, realisation_phases, synthesise
from seafast.solvers.cradle_march import (
    STEPS_PER_MODE_PERIOD_INV,
    Periodicity,
    contact_correction_N,
    cradle_stepper,
    march_cradle,
    march_step,
    pivoting_correction_N,
)
from seafast.solvers.cradle_window import march_cradle_window

COARSE = {"model.element_length_m": 4.0, "sea_state.peak_period_s": 10.0}
MODERATE = {**COARSE, "sea_state.heading_deg": 120.0, "sea_state.significant_height_m": 2.0}
SEVERE = {
    **COARSE,
    "sea_state.heading_deg": 90.0,
    "sea_state.significant_height_m": 9.0,
    "sea_state.duration_s": 60.0,
    "seafastening.side_stopper.gap_m": 2e-3,
    "seafastening.side_stopper.stiffness_N_per_m": 2e9,
    "seafastening.lashing.pretension_N": 0.0,
}


def _plan(overrides, settings=None):
    """The case's cradle sea state (no design waves), cradle realisation plan and spectral analysis."""
    case = seafast.load_case(None, overrides)
    analysis = spectral_analysis(case)
    cradle = cradle_sea_state(analysis, design_waves=False)
    roll = sea_state_roll_damping(case, analysis.spectrum)

    def transfer_at(w):
        return [cradle_transfer_functions(cradle.sea, tf) for tf in sea_state_transfer(case, analysis.model, w, roll).per_direction]

    plan = cradle_realisation_plan(
        case, analysis.spectrum, transfer_at, cradle.sea.dynamics, cradle.spectral.still_water, settings or CradleRealisationSettings()
    )
    return cradle, plan, analysis


@pytest.fixture(scope="module")
def moderate():
    """120 deg, Hs 2 m, Tp 10 s, 20-min records: nothing lifts, no stoppers."""
    return _plan({**MODERATE, "sea_state.duration_s": 1200.0})


def test_each_record_has_the_spectral_variance_with_deterministic_amplitudes():
    """Deterministic amplitudes: every record's variance of every engagement and lateral displacement is the spectral
    method's sigma^2 (the synthesis grid and splined transfer functions against the spectrum's grid: 2e-4 measured)."""
    cradle, plan, _ = _plan({**MODERATE, "sea_state.duration_s": 300.0, "sea_state.random_amplitudes": False})
    m, n_f = plan.element_count, plan.grid.omega_rad_s.size
    sigma = np.concatenate([cradle.spectral.engagement.sigma, cradle.spectral.lateral_displacement.sigma])
    for index in (0, 1):
        X = synthesise(plan.grid, realisation_phases(plan.seed, index, n_f), plan.transfer, amplitude_factors(plan.seed, index, n_f, False))
        np.testing.assert_allclose(X.std(axis=0), sigma, rtol=1e-3)
        assert X.shape[1] == m + cradle.spectral.lateral_displacement.sigma.size


def test_linear_maxima_of_many_records_match_the_spectral_most_probable_maxima(moderate):
    """200 twenty-minute records (random amplitudes): the 1/e quantile of the linear pad-force maxima (the Gumbel mode,
    what the spectral MPM is under Poisson up-crossings) against the spectral column ``static + MPM``; the mean record
    variance of the largest pad's engagement against sigma^2.

    Sampling: the quantile's standard deviation is about ``e sqrt(p (1 - p) / n) beta`` with beta ~ MPM / (2 ln N)
    (N ~ 150 cycles): 1.1 % of the dynamic MPM; a narrow-band response's peaks come in groups (fewer independent
    chances), the MPM formula's conservatism, a few per cent (docs/monte_carlo.md). The dynamic part within
    [-8 %, +4 %]; the variance within 4 standard errors computed from the components (exponential amplitudes)."""
    cradle, plan, _ = moderate
    n = 200
    records = [evaluate_cradle_realisation(plan, i) for i in range(n)]
    spectral = cradle.spectral
    pads = slice(0, plan.pad_count)
    best = int(np.argmax(spectral.element_totals()["F_pad_N"]))
    static, mpm = spectral.still_water.element_force_N[pads][best], spectral.element_force.mpm[pads][best]
    maxima = np.array([r["linear"]["F_pad_N"] for r in records])
    ratio = (np.quantile(maxima, math.exp(-1.0)) - static) / mpm
    assert 0.92 < ratio < 1.04, ratio
    assert all(r["nonlinear"] == r["linear"] for r in records if r["windows"] == 0)
    # the variance of the largest pad's engagement: E var = sigma^2, var(var) = sum (a_j^2 |H_j|^2 / 2)^2 (r_j^2 ~ Exp(1))
    m, n_f = plan.element_count, plan.grid.omega_rad_s.size
    channel = np.flatnonzero(np.arange(m) < plan.pad_count)[best]
    power = (plan.grid.amplitude_m * np.abs(plan.transfer[:, channel])) ** 2 / 2.0
    variances = [
        synthesise(
            plan.grid, realisation_phases(plan.seed, i, n_f), plan.transfer[:, channel], amplitude_factors(plan.seed, i, n_f, True)
        ).var()
        for i in range(n)
    ]
    z = (np.mean(variances) - power.sum()) / math.sqrt(np.sum(power**2) / n)
    assert abs(z) < 4.0, z
    assert power.sum() == pytest.approx(spectral.engagement.sigma[channel] ** 2, rel=1e-3)


@pytest.fixture(scope="module")
def severe():
    """Beam sea, Hs 9 m, one-minute records, stoppers 2 mm off, lashings without pretension: everything changes state
    (16 steps a period: the windows' check, not the step's)."""
    return _plan(SEVERE, CradleRealisationSettings(steps_per_period=16))


def test_windowed_march_equals_the_march_over_the_whole_record(severe):
    """Where pads lift, stoppers close and lashings slacken, the windows (started at rest, ended on the decay rule,
    linear elsewhere) give the extremes of the march over every fine step of the record to 1e-3 (the free vibration
    dropped at a window's end is below 1e-4 of the largest still-water engagement)."""
    _, plan, _ = severe
    windowed, whole = (evaluate_cradle_realisation(plan, 1, windowed=w) for w in (True, False))
    assert windowed["solved"] and whole["solved"] and whole["windows"] == 1
    assert 0 < windowed["window_steps"] < whole["window_steps"]
    nl, ref, lin = windowed["nonlinear"], whole["nonlinear"], windowed["linear"]
    assert ref["F_stopper_N"] > 0.0 and ref["lashing_slack_fraction"] > 0.1 and ref["pad_lifted_fraction"] > 0.1
    for q in CRADLE_QUANTITIES:
        assert nl[q] == pytest.approx(ref[q], rel=1e-3, abs=1e-3 * abs(lin[q]) + 1e-12), q
    for q in ("pad_lifted_fraction", "lashing_slack_fraction"):
        assert nl[q] == pytest.approx(ref[q], abs=2e-3), q
    # the contact limits the stoppers' force and holds the cargo across: less than the linear reading
    assert nl["F_stopper_N"] < lin["F_stopper_N"] and nl["transverse_slip_m"] < lin["transverse_slip_m"]
    assert nl["lashing_tension_min_N"] >= 0.0 > lin["lashing_tension_min_N"]


def test_nonlinear_extremes_are_the_linear_ones_exactly_where_nothing_changes_state(moderate):
    """No element near a change of state: no window, the nonlinear record is the linear one sample by sample; marched
    over a whole one-minute record anyway, no element is ever corrected and the extremes differ from the coarse
    samples' only by the fine steps between them (at most ``1 - cos(omega_s dt_c / 2)`` = 0.28 %)."""
    _, plan, _ = moderate
    record = evaluate_cradle_realisation(plan, 3)
    assert record["windows"] == 0 and record["nonlinear"] == record["linear"]
    _, short, _ = _plan({**MODERATE, "sea_state.duration_s": 60.0})
    whole = evaluate_cradle_realisation(short, 0, windowed=False)
    nl, lin = whole["nonlinear"], whole["linear"]
    assert whole["windows"] == 1 and nl["pad_lifted_fraction"] == 0.0 == nl["lashing_slack_fraction"]
    for q in ("F_pad_N", "lashing_tension_max_N", "transverse_slip_m"):
        assert lin[q] <= nl[q] <= lin[q] * (1.0 + 2.8e-3), q
    assert lin["lashing_tension_min_N"] >= nl["lashing_tension_min_N"] >= lin["lashing_tension_min_N"] * (1.0 - 2.8e-3)


def test_the_compiled_window_is_the_python_step(severe):
    """The compiled window (:mod:`seafast.solvers.cradle_kernels`) against :func:`march_step` step by step over 4000
    fine steps of the severe record (pads lift, stoppers close, wires slacken): the same maxima, least forces, slip
    and corrected steps to round-off."""
    _, plan, _ = severe
    n_f, m = plan.grid.omega_rad_s.size, plan.element_count
    X = synthesise(plan.grid, realisation_phases(plan.seed, 1, n_f), plan.transfer, amplitude_factors(plan.seed, 1, n_f, True))
    totals = np.hstack([plan.engagement_static_m, plan.lateral_static_m]) + X
    t = np.arange(totals.shape[0] + 1) * plan.grid.time_step_s
    spline = CubicSpline(t, np.vstack([totals, totals[:1]]), axis=0, bc_type="periodic")
    dt_f = plan.grid.time_step_s / plan.ratio

    def linear_at(first, count):
        return spline((first + np.arange(count)) * dt_f)

    n = 4000
    window = march_cradle_window(plan.stepper, linear_at, np.ones(plan.grid.samples, dtype=bool), plan.ratio, 0, n, 1e-300)
    st, k = plan.stepper, plan.stiffness_N_per_m
    x, chosen = np.zeros(3 * st.engagement_modes.shape[1]), np.zeros(m, dtype=bool)
    hi, lo, slip, corrected = np.full(m, -np.inf), np.full(m, np.inf), np.zeros(plan.lateral_static_m.size), np.zeros(m, int)
    r = st.engagement_modes.shape[1]
    for row in linear_at(1, n):
        x, chosen, s, c = march_step(st, x, chosen, row[:m])
        hi, lo = np.maximum(hi, k * np.maximum(s, 0.0)), np.minimum(lo, k * np.maximum(s, 0.0))
        slip = np.maximum(slip, np.abs(row[m:] + st.output_modes @ x[:r] + st.output_residual @ c))
        corrected += chosen
    assert window.end == n and window.solved and corrected[:6].max() > 100 and corrected[-4:].max() > 100
    scale = np.max(hi)
    np.testing.assert_allclose(window.max_force_N, hi, rtol=1e-9, atol=1e-9 * scale)
    np.testing.assert_allclose(window.min_force_N, lo, rtol=1e-9, atol=1e-9 * scale)
    np.testing.assert_allclose(window.max_abs_output, slip, rtol=1e-9)
    np.testing.assert_array_equal(window.corrected_steps, corrected)


def _marched_periods(dynamics, s_lin, dt, periods):
    """The correction of the stoppers-open linear system marched over ``periods`` repeats of ``s_lin`` (N, m) from
    rest: the engagements over the last period at t_0 .. t_{N-1}."""
    stepper = cradle_stepper(dynamics, dt, STEPS_PER_MODE_PERIOD_INV * 2.0 * np.pi / dt, dynamics.damping_set)
    x, chosen = np.zeros(3 * stepper.engagement_modes.shape[1]), np.zeros(s_lin.shape[1], dtype=bool)
    out = np.empty_like(s_lin)
    n = s_lin.shape[0]
    for _ in range(periods):
        for i in range(n):
            x, chosen, out[i], _ = march_step(stepper, x, chosen, s_lin[(i + 1) % n])
    return np.roll(out, 1, axis=0)


def test_the_stepper_with_stoppers_open_matches_the_march_with_every_element_bilateral(severe):
    """A regular beam wave of 10 m at the pads' resonance (pads lift, stoppers close, lashings slacken), marched with
    the sea state's split (pads and lashings bilateral, stoppers open: the correction closes them) and with
    :func:`march_cradle`'s (every element bilateral: the correction removes the stoppers' tension): the same
    periodic state. Contact events make Newmark first order in the step: the difference of the element forces, over
    the largest pad force, halves with the step (0.018 at T / 256, 0.008 at T / 512, measured) and the open fractions
    agree to a few samples; a wrong sign of the stoppers' correction would be off by their whole force."""
    cradle, _, analysis = severe
    dynamics = cradle.sea.dynamics
    transfer = cradle.transfer.per_direction[0]
    j = int(np.argmax(np.abs(transfer.element_force_N[:, 2])))
    unit = cradle_unit_excitations(cradle.sea, analysis.directional.per_direction[0], [j])[0]
    excitation = scaled_excitation(unit, 10.0)
    linear = cradle_linear_transfer(dynamics, [excitation], transfer.heading_deg).engagement_m[0]
    k = dynamics.problem.element_stiffness_N_per_m
    errors = []
    for n in (256, 512):
        phase = 2.0 * np.pi * np.arange(n) / n
        s_lin = cradle.spectral.still_water.engagement_m + np.real(linear[None, :] * np.exp(1j * phase)[:, None])
        mine = _marched_periods(dynamics, s_lin, 2.0 * np.pi / excitation.omega_rad_s / n, 20)
        reference = march_cradle(dynamics, excitation, n)
        assert reference.periodicity is Periodicity.PERIODIC
        force, force_ref = k * np.maximum(mine, 0.0), reference.element_force_N
        assert np.all(force_ref[:, 6:12].max(axis=0)[[1, 5]] > 1e5) and np.all(np.mean(mine[:, :6] <= 0.0, axis=0)[[0, 1]] > 0.1)
        np.testing.assert_allclose(np.mean(mine <= 0.0, axis=0), np.mean(reference.engagement_m <= 0.0, axis=0), atol=6.0 / n)
        errors.append(float(np.max(np.abs(force - force_ref)) / np.max(force_ref[:, :6])))
    assert errors[1] < 0.012 and errors[1] < 0.6 * errors[0], errors


def test_the_step_contact_with_elements_open_in_the_linear_system_is_exact():
    """``s = s_p - G c``; bilateral elements ``c = k max(-s, 0)``, elements open in the linear system ``c = k max(s, 0)``:
    from any start, on stiff elements (``diag(1/k) - sign G`` nearly singular), the correction meets its definition."""
    rng = np.random.default_rng(5)
    A = rng.normal(size=(8, 5))
    k = np.full(8, 1e9)
    sign = np.array([1, 1, 1, 1, -1, -1, 1, -1], dtype=float)
    bilateral = sign > 0
    G = A @ np.linalg.solve(A[bilateral].T @ (k[bilateral, None] * A[bilateral]) + 1e3 * np.eye(5), A.T)
    for _ in range(20):
        s_p = rng.normal(scale=1e-2, size=8)
        c, chosen = contact_correction_N(G, k, s_p, rng.random(8) < 0.5, sign)
        s = s_p - G @ c
        assert np.all(c >= 0.0)
        np.testing.assert_allclose(c, k * np.maximum(-sign * s, 0.0), atol=1e-6 * np.max(np.abs(k * s_p)))
        assert np.all(c[~chosen] == 0.0)
        c_pivot, chosen_pivot = pivoting_correction_N(G, k, s_p, sign)  # the fallback, on its own
        np.testing.assert_allclose(c_pivot, c, atol=1e-6 * np.max(np.abs(k * s_p)))
        assert np.all(c_pivot[~chosen_pivot] == 0.0)
