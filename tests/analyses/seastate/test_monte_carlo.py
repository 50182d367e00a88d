"""The Monte Carlo reference: synthesis, plan, linear Monte Carlo against the spectral method,
nonlinear = linear where nothing lifts, independence of the numerical settings, statistics, store.

Runtime: about a minute (the linear-vs-spectral check runs 20 one-hour realisations).
"""

from __future__ import annotations

import json
import math
from dataclasses import replace

import numpy as np
import pytest
from scipy import stats

import seafast
from seafast.analyses.seastate.extremes import gumbel_fit, most_probable_maximum
from seafast.analyses.seastate.monte_carlo import MonteCarloSettings, build_plan, run_monte_carlo
from seafast.analyses.seastate.realisation import QUANTITIES, evaluate_realisation
from seafast.analyses.seastate.spectral import rayleigh_mpm, spectral_analysis
from seafast.analyses.seastate.spectrum import jonswap_density
from seafast.analyses.seastate.synthesis import amplitude_factors, realisation_phases, synthesis_grid, synthesise
from seafast.analyses.seastate.transfer import transfer_functions
from seafast.parallel.errors import ForeignStoreError


def case_of(**sea_state):
    return seafast.load_case(None, {f"sea_state.{k}": v for k, v in sea_state.items()})


@pytest.fixture(scope="module")
def plan3():
    """Base case, Hs 3 m, Tp 10 s, one hour: the base case lifts off a few times an hour."""
    case = case_of(duration_s=3600.0)
    return case, build_plan(case)


# ---------------------------------------------------------------------------- synthesis
def test_synthesis_is_the_random_phase_sum_and_its_variance_is_spectral():
    grid = synthesis_grid((0.3, 1.5), lambda w: np.exp(-((w - 0.7) ** 2) / 0.02), 600.0, 0.25)
    assert grid.frequency_step_rad_s == pytest.approx(2 * math.pi / 600.0)
    phases = realisation_phases(7, 3, grid.omega_rad_s.size)
    H = np.column_stack([np.ones(grid.omega_rad_s.size), 0.3j * grid.omega_rad_s**2])
    x = synthesise(grid, phases, H)
    t = np.arange(grid.samples) * grid.time_step_s
    for n in (0, 17, grid.samples // 2, grid.samples - 1):
        direct = np.real(np.sum(grid.amplitude_m[:, None] * H * np.exp(1j * (grid.omega_rad_s[:, None] * t[n] + phases[:, None])), axis=0))
        assert np.allclose(x[n], direct, rtol=1e-10, atol=1e-12)
    # random phase, deterministic amplitude: each record's variance is the spectral sum
    assert np.mean(x[:, 0] ** 2) == pytest.approx(grid.variance_m2, rel=1e-10)
    assert np.mean(x[:, 1] ** 2) == pytest.approx(np.sum(grid.amplitude_m**2 * np.abs(H[:, 1]) ** 2) / 2, rel=1e-10)


def test_phases_are_reproducible_per_realisation_in_any_order():
    a = realisation_phases(5, 2, 1000)
    assert np.array_equal(a, realisation_phases(5, 2, 1000))
    child = np.random.SeedSequence(5).spawn(3)[2]
    assert np.array_equal(a, np.random.default_rng(child).uniform(0, 2 * math.pi, 1000))
    assert not np.allclose(a, realisation_phases(5, 1, 1000))
    assert not np.allclose(a, realisation_phases(6, 2, 1000))
    assert a.min() >= 0.0 and a.max() < 2 * math.pi


def test_random_amplitudes_are_rayleigh_with_the_same_phases_and_make_the_records_gaussian():
    # Tucker, Challenor & Carter (1984): with Rayleigh amplitudes a_j r_j (r_j^2 standard exponential) and
    # uniform phases the coefficients are complex Gaussian: a record's variance then scatters between
    # records as sum_j (a_j^2 / 2)^2 / m0^2 (relative variance), and its maxima scatter more than with
    # deterministic amplitudes, whose records all have the spectral variance
    count = 20000
    r = amplitude_factors(5, 2, count, True)
    assert np.array_equal(amplitude_factors(5, 2, count, True), r) and not np.allclose(amplitude_factors(5, 1, count, True), r)
    assert np.array_equal(amplitude_factors(5, 2, count, False), np.ones(count))
    assert np.mean(r**2) == pytest.approx(1.0, abs=3.0 / math.sqrt(count))  # E r^2 = 1, sd(r^2) = 1
    assert stats.kstest(r**2, "expon").pvalue > 1e-3
    assert np.array_equal(realisation_phases(5, 2, count), realisation_phases(5, 2, count))  # phases drawn first, unchanged
    grid = synthesis_grid((0.3, 2.0), lambda w: jonswap_density(w, 3.0, 10.0, 3.3), 1800.0, 0.25)
    n, unit = 6000, np.ones(grid.omega_rad_s.size)
    maxima, variance = np.empty((2, n)), np.empty((2, n))
    for i in range(n):
        phases = realisation_phases(3, i, grid.omega_rad_s.size)
        for k, random in enumerate((False, True)):
            x = synthesise(grid, phases, unit, amplitude_factors(3, i, grid.omega_rad_s.size, random))
            maxima[k, i], variance[k, i] = x.max(), np.mean(x**2)
    assert np.ptp(variance[0]) < 1e-12 * grid.variance_m2  # deterministic: every record has the spectral variance
    rel = variance[1] / grid.variance_m2 - 1.0
    expected = math.sqrt(np.sum((grid.amplitude_m**2 / 2) ** 2)) / grid.variance_m2  # 0.092
    assert abs(rel.mean()) < 3.0 * expected / math.sqrt(n)
    assert rel.std() == pytest.approx(expected, rel=3.0 / math.sqrt(2 * n) * 1.5)  # sd of a sample sd, a little kurtosis
    # the maxima' scatter: wider with random amplitudes (8 % here, 30-minute records), beyond 3 paired-bootstrap errors
    pick = np.random.default_rng(0).integers(0, n, (400, n))
    ratio = maxima[1].std() / maxima[0].std()
    error = np.std(maxima[1][pick].std(axis=1) / maxima[0][pick].std(axis=1))
    assert ratio - 1.0 > 3.0 * error, (ratio, error)


def test_deterministic_amplitudes_give_every_record_the_spectral_variance(plan3):
    case, _ = plan3
    off = case.model_copy(update={"sea_state": case.sea_state.model_copy(update={"random_amplitudes": False})})
    plan = build_plan(off)
    assert not plan.random_amplitudes and plan.describe()["random_amplitudes"] is False
    spec = spectral_analysis(off).extremes.saddle_force
    for i in (0, 1):
        record, _ = evaluate_realisation(plan, i)
        # synthesis grid (5.8e-4 rad/s, splined transfer functions) against the 256-point trapezoid: 3e-4 measured
        assert np.allclose(record["std_saddle_force_N"], spec.sigma, rtol=1e-3)


def _below_rayleigh(grid, transfer, n):
    """z-score of the count of maxima below the Rayleigh MPM (binomial(n, 1/e) if it is their 1/e quantile), quantile ratio, bandwidth q."""
    w, p = grid.omega_rad_s, math.exp(-1.0)
    maxima = np.empty(n)
    for i in range(n):
        x = synthesise(grid, realisation_phases(0, i, w.size), transfer, amplitude_factors(0, i, w.size, True))
        k = int(np.argmax(x))
        y0, y1, y2 = x[k - 1], x[k], x[(k + 1) % x.size]  # the peak between samples (a parabola): sampled, 0.3 % short
        maxima[i] = y1 - (y2 - y0) ** 2 / (8.0 * (y0 - 2.0 * y1 + y2))
    a2 = (grid.amplitude_m * np.abs(transfer)) ** 2 / 2.0
    m0, m1, m2 = (float(np.sum(w**j * a2)) for j in (0, 1, 2))
    mpm = float(rayleigh_mpm(np.array(m0), np.array(m2), grid.duration_s))
    z = (np.count_nonzero(maxima < mpm) - n * p) / math.sqrt(n * p * (1 - p))
    return z, float(np.quantile(maxima, p) / mpm), math.sqrt(1.0 - m1**2 / (m0 * m2))


def test_rayleigh_mpm_is_the_quantile_of_the_maximum_for_a_broad_band_and_conservative_for_a_narrow_one(plan3):
    # sigma sqrt(2 ln(D / Tz)) counts zero up-crossings as independent chances (Poisson): then it is exactly
    # the 1/e quantile of the maximum over D (the Gumbel mode the Monte Carlo reports). Under that hypothesis
    # the number of records whose maximum is below it is binomial(n, 1/e): z-scores from the sample itself.
    # A Pierson-Moskowitz wave elevation over 3 h (bandwidth q = sqrt(1 - m1^2 / (m0 m2)) = 0.37) bears it
    # out; the base case's saddle force (q = 0.12, a narrow response) has its large peaks in groups, fewer
    # independent chances: its maximum's 1/e quantile is about 3 % below Rayleigh over one hour (1.6-1.8 %
    # over three, docs/monte_carlo.md), the formula's conservatism, not sampling
    _, plan = plan3
    s = 1  # the middle saddle: the force's linear extreme
    z, ratio, q = _below_rayleigh(plan.grid, plan.transfer[:, s] * plan.stiffness_N_per_m[s], 2000)
    assert q < 0.15 and z > 6.0 and 0.96 < ratio < 0.99, (q, z, ratio)  # measured q 0.117, z 9.2, 0.971
    wave = synthesis_grid((0.2, 4.0), lambda w: jonswap_density(w, 3.0, 10.0, 1.0), 10800.0, 0.25)
    z, ratio, q = _below_rayleigh(wave, np.ones(wave.omega_rad_s.size), 3000)
    assert q > 0.3 and abs(z) < 3.5 and abs(ratio - 1.0) < 0.005, (q, z, ratio)


def test_plan_grid_does_not_repeat_within_the_duration(plan3):
    case, plan = plan3
    grid = plan.grid
    assert grid.duration_s == 3600.0
    assert grid.frequency_step_rad_s <= 2 * math.pi / case.sea_state.duration_s * (1 + 1e-12)
    assert plan.fine_step_s * plan.ratio == pytest.approx(grid.time_step_s, rel=1e-12)
    assert plan.fine_step_s <= 2 * math.pi / 72.11 / 16  # 16 steps per period of the 72 rad/s mode


def test_interpolated_transfer_functions_match_direct_evaluation(plan3):
    """The plan's transfer functions (cubic splines from a 0.01 rad/s grid) at synthesis frequencies."""
    case, plan = plan3
    model = seafast.model.from_case.build_model(case)
    pick = np.linspace(0, plan.grid.omega_rad_s.size - 1, 61).astype(int)[1:-1] + 3  # off the spline knots
    tf = transfer_functions(case, model, plan.grid.omega_rad_s[pick], heading_deg=180.0)
    n_s = plan.saddle_count
    comp = plan.transfer[pick, :n_s]
    assert np.max(np.abs(comp - tf.saddle_compression_m)) < 1e-4 * np.max(np.abs(tf.saddle_compression_m))
    moment = plan.transfer[pick, n_s:] @ plan.moment_basis.T
    assert np.max(np.abs(moment - tf.bending_moment_Nm)) < 1e-4 * np.max(np.abs(tf.bending_moment_Nm))


# ---------------------------------------------------------------------------- linear MC against spectral
def test_linear_monte_carlo_reproduces_the_spectral_method(tmp_path):
    """20 one-hour realisations of the base case in Hs 3 m, Tp 10 s against B1's spectral extremes."""
    case = case_of(duration_s=3600.0, realisations=20)
    spec = spectral_analysis(case).extremes
    mc = run_monte_carlo(case, tmp_path, workers=1, progress=False)
    assert mc.linear.converged and mc.nonlinear.converged
    # standard deviations: a Gaussian record of duration T estimates sigma with relative standard error
    # sqrt(2 pi int S_r^2 dw / T) / (2 m0) (4-5 % here); the records (random amplitudes: Gaussian) scatter so
    w = spectral_analysis(case).spectrum.omega_rad_s
    n = mc.std_saddle_force_N.shape[0]
    for stat, mc_std in ((spec.saddle_force, mc.std_saddle_force_N), (spec.bending_moment, mc.std_bending_moment_Nm)):
        sampling = np.sqrt(2 * math.pi * np.trapezoid(stat.spectrum**2, w, axis=0) / case.sea_state.duration_s) / (2 * stat.m0)
        loc = np.flatnonzero(stat.sigma > 0.05 * stat.sigma.max())
        rel = mc_std[:, loc] / stat.sigma[loc] - 1.0
        assert np.all(np.abs(rel.mean(axis=0)) < 3.0 * sampling[loc] / math.sqrt(n))  # unbiased
        scatter = np.sqrt(np.mean(rel**2, axis=0)) / sampling[loc]  # sqrt(chi2_20 / 20): 0.5-1.6 at 99.9 %
        assert np.all((0.5 < scatter) & (scatter < 1.6)), scatter
    # most probable maxima over the hour within 5 %
    for q in ("F_N", "M_b_Nm", "sigma_b_Pa", "u_s_m"):
        assert mc.linear.mpm[q] == pytest.approx(spec.totals[q], rel=0.05), q
        lo, hi = mc.linear.mpm_interval[q]
        assert lo <= mc.linear.mpm[q] <= hi
    assert mc.linear.mpm["u_d_m"] == 0.0 and mc.linear.mpm_method["u_d_m"] == "constant"
    # uplift rate: downward zero crossings counted in the records against Rice's formula, within 3 standard
    # errors of the mean count (the counts' own scatter: Poisson, and the records' variance in a Gaussian sea)
    expected = spec.totals["uplift_per_hour"]
    hours = case.sea_state.duration_s / 3600.0
    counts = mc.linear.uplift_events / hours
    assert expected > 1.0
    assert abs(mc.linear.uplift_per_hour - expected) < 3.0 * max(counts.std(ddof=1), math.sqrt(expected / hours)) / math.sqrt(n)
    # lift-off lowers the nonlinear saddle force and moment below the linear ones
    assert mc.nonlinear.mpm["F_N"] < mc.linear.mpm["F_N"]
    assert mc.nonlinear.mpm["M_b_Nm"] < mc.linear.mpm["M_b_Nm"]
    assert mc.nonlinear.mpm["u_d_m"] > 0.0 and mc.nonlinear.uplift_per_hour > 0.0


def test_nonlinear_equals_linear_where_no_saddle_lifts(tmp_path):
    case = case_of(significant_height_m=0.5, duration_s=3600.0, realisations=3)
    plan = build_plan(case)
    for i in range(3):
        record, _ = evaluate_realisation(plan, i)
        assert record["windows"] == 0 and record["nonlinear"]["uplift_events"] == 0
        assert record["nonlinear"] == record["linear"]
    mc = run_monte_carlo(case, tmp_path, workers=1, progress=False)
    for q in QUANTITIES:
        assert np.array_equal(mc.nonlinear.maxima[q], mc.linear.maxima[q])
    assert mc.nonlinear.uplift_per_hour == 0.0


# ---------------------------------------------------------------------------- numerical settings do not matter
def _realisation_with_lift_off(plan):
    for i in range(10):
        record, _ = evaluate_realisation(plan, i)
        if record["nonlinear"]["uplift_events"] > 0:
            return i, record
    raise AssertionError("no realisation lifts off")


@pytest.mark.parametrize(
    "change, tol, tol_gap",
    [
        ({"decay_tolerance": 1e-7}, 1e-6, 1e-4),  # windows end later: nothing changes
        ({"steps_per_period": 32}, 1.5e-3, 1e-2),  # half the step
        ({"cutoff_factor": 12.0}, 5e-4, 2e-3),  # more modes (7 instead of 4)
        ({"coarse_step_factor": 0.075}, 1e-3, 1e-3),  # half the coarse step
    ],
)
def test_maxima_do_not_depend_on_the_numerical_settings(plan3, change, tol, tol_gap):
    case, plan = plan3
    index, ref = _realisation_with_lift_off(plan)
    other = build_plan(case, replace(MonteCarloSettings(), **change))
    record, _ = evaluate_realisation(other, index)
    for q in ("F_N", "M_b_Nm", "sigma_b_Pa", "u_s_m"):
        assert record["nonlinear"][q] == pytest.approx(ref["nonlinear"][q], rel=tol), q
    assert record["nonlinear"]["u_d_m"] == pytest.approx(ref["nonlinear"]["u_d_m"], rel=tol_gap)
    assert record["nonlinear"]["uplift_events"] == pytest.approx(ref["nonlinear"]["uplift_events"], abs=2)


def test_example_series_marks_lift_off(plan3):
    _, plan = plan3
    index, ref = _realisation_with_lift_off(plan)
    record, series = evaluate_realisation(plan, index, capture=True)
    assert record == {**ref, "seconds": record["seconds"]}
    lifted = series.saddle_lifted.any(axis=1)
    assert lifted.any()
    # where a saddle is lifted at the sample its nonlinear force is zero; the linear model pulls there
    at = series.saddle_lifted & (series.nonlinear_saddle_force_N == 0.0)
    assert at.any()
    assert np.max(series.nonlinear_saddle_force_N) <= ref["nonlinear"]["F_N"] * (1 + 1e-12)
    assert series.time_s[1] - series.time_s[0] == pytest.approx(0.25, rel=0.2)


# ---------------------------------------------------------------------------- statistics
def test_gumbel_fit_equals_scipy():
    rng = np.random.default_rng(11)
    for scale in (1.0, 3e5, 2e-3):
        x = stats.gumbel_r.rvs(loc=10 * scale, scale=scale, size=20, random_state=rng)
        loc, beta = gumbel_fit(x)
        ref = stats.gumbel_r.fit(x)
        assert float(loc) == pytest.approx(ref[0], rel=1e-9)
        assert float(beta) == pytest.approx(ref[1], rel=1e-7)


def test_mpm_estimators():
    rng = np.random.default_rng(2)
    x = stats.gumbel_r.rvs(loc=5.0, scale=0.5, size=40, random_state=rng)
    est = most_probable_maximum(x, seed=1)
    assert est.method == "gumbel_mode" and est.interval[0] < est.value < est.interval[1]
    assert est.value == pytest.approx(float(gumbel_fit(x)[0]), rel=1e-12)
    assert est.interval[0] < 5.0 < est.interval[1]
    assert most_probable_maximum(x, seed=1) == est  # seeded bootstrap: reproducible
    gaps = np.r_[np.zeros(6), rng.uniform(1e-3, 5e-3, 14)]
    est = most_probable_maximum(gaps)
    assert est.method == "empirical_quantile" and est.value == pytest.approx(np.quantile(gaps, math.exp(-1)))
    est = most_probable_maximum(np.zeros(20))
    assert est.method == "constant" and est.value == 0.0 and est.interval == (0.0, 0.0)
    assert math.isnan(most_probable_maximum(np.full(5, np.nan)).value)


def test_dataset_has_units_and_long_names(tmp_path):
    case = case_of(significant_height_m=3.0, duration_s=900.0, realisations=3)
    mc = run_monte_carlo(case, tmp_path, workers=1, progress=False)
    ds = mc.to_dataset()
    for name, var in {**ds.data_vars, **ds.coords}.items():
        if name in ("model",):
            continue
        assert "units" in var.attrs and "long_name" in var.attrs, name
    assert ds["mc_F_N"].sizes == {"model": 2, "realisation": 3}
    ds.to_netcdf(tmp_path / "mc.nc")
    assert json.loads(ds.attrs["mc_settings_json"])["modes_kept"] == 4


# ---------------------------------------------------------------------------- the store
def test_more_realisations_extend_the_store(tmp_path):
    case = case_of(significant_height_m=2.0, duration_s=600.0, realisations=3)
    first = run_monte_carlo(case, tmp_path, workers=1, progress=False)
    more = run_monte_carlo(
        case.model_copy(update={"sea_state": case.sea_state.model_copy(update={"realisations": 5})}), tmp_path, workers=1, progress=False
    )
    assert more.reused == 3
    assert np.array_equal(more.linear.maxima["F_N"][:3], first.linear.maxima["F_N"])
    other = case_of(significant_height_m=2.5, duration_s=600.0, realisations=3)
    with pytest.raises(ForeignStoreError, match="another run"):
        run_monte_carlo(other, tmp_path, workers=1, progress=False)


def test_progress_off_a_terminal_is_plain_lines_as_a_study_s(tmp_path, monkeypatch, caplog):
    """The Monte Carlo reports through seafast.parallel.progress (as a study does): off a terminal, plain lines."""
    import logging

    import seafast.parallel.progress

    monkeypatch.setattr(seafast.parallel.progress, "PROGRESS_MIN_INTERVAL_S", 0.0)
    case = case_of(significant_height_m=2.0, duration_s=600.0, realisations=3)
    with caplog.at_level(logging.INFO, logger="seafast.parallel.progress"):
        run_monte_carlo(case, tmp_path, workers=1, progress=True)
    lines = [r.getMessage() for r in caplog.records if r.name == "seafast.parallel.progress"]
    assert [line.split(" (")[0] for line in lines] == [f"Monte Carlo {case.name}: {i}/3 realisations" for i in (1, 2, 3)]
