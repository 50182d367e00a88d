"""Harmonic balance solver: formulations, solvers, limits and diagnostics (speed: benchmarks/bench_hbm.py)."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
from threadpoolctl import threadpool_limits

from seafast.fourier import harmonics_to_time
from seafast.solvers.hbm import HBMOptions, solve_hbm
from seafast.solvers.linear import solve_linear
from seafast.solvers.newton import NewtonStop
from seafast.solvers.outcome import HBMPath, HBMRoute, HBMStart, SolverOutcome, SolverWarning
from seafast.solvers.references import QuasiStaticOptions, solve_quasi_static
from solver_cases import base_model, peak_moment, static_excitation, wave_excitation


@pytest.fixture(autouse=True, scope="module")
def _one_blas_thread():
    with threadpool_limits(1):
        yield


@pytest.fixture(scope="module")
def model():
    return base_model()


@pytest.fixture(scope="module")
def coarse():
    return base_model(element_length_m=4.0)


def test_static_calibration_linear_and_nonlinear(model):
    """H = 0 with the static excitation: contact is kept, so the nonlinear static = linear static."""
    ex = static_excitation(model)
    lin = solve_linear(model, ex)
    r = solve_hbm(model, ex, HBMOptions(harmonics=0, time_samples=2, contact_law="exact"))
    assert r.converged and r.contact_preserved
    assert r.saddle_force_time_N.shape == (2, 3)
    assert np.allclose(r.saddle_force_time_N[0], lin.saddle_force_N[0].real, rtol=1e-9)
    assert r.max_saddle_force_N == pytest.approx(6.3e6, rel=0.01)
    assert peak_moment(model, r) == pytest.approx(49.0e6, rel=0.01)
    assert r.max_saddle_compression_m == pytest.approx(5.73e-3, rel=0.01)


def test_response_shapes_and_diagnostics(model):
    ex = wave_excitation(model)
    r = solve_hbm(model, ex, HBMOptions(harmonics=5, time_samples=128, contact_law="tanh"))  # the source's law and grid
    N, n_c, n_s = 128, model.cargo_dof_count, model.saddle_count
    assert r.method == "hbm" and r.converged and r.residual_norm <= 1e-10
    assert r.period_fraction.shape == (N,) and r.period_fraction[1] == 1 / N
    assert r.cargo_displacement_time_m.shape == (N, n_c)
    assert r.cargo_displacement_harmonics.shape == (6, n_c)
    assert r.saddle_compression_time_m.shape == r.saddle_force_time_N.shape == r.contact_state.shape == (N, n_s)
    assert r.harmonic_truncation_indicator.shape == (n_s,)
    assert np.all((0 <= r.harmonic_truncation_indicator) & (r.harmonic_truncation_indicator < 0.05))
    assert not r.contact_preserved and r.max_gap_m > 1e-3  # the middle saddle lifts off in the sag
    assert r.contact_state[:, 1].mean() < 0.95 and r.contact_state[:, [0, 2]].all()
    # the tanh law pulls: up to 0.139 k / kappa
    assert 0 < r.tensile_force_error_N <= 0.1393 * model.saddle_unilateral_stiffness_N_per_m.max() / 1000
    assert r.options["harmonics"] == 5 and r.function_evaluations >= r.iterations
    # time signal = harmonics
    t = r.period_fraction
    z = np.real(np.exp(2j * np.pi * np.outer(t, np.arange(6))) @ r.cargo_displacement_harmonics)
    assert np.allclose(z, r.cargo_displacement_time_m, atol=1e-12)


@pytest.mark.parametrize("law", ["softplus", "exact"])
def test_non_negative_laws_give_no_tension(model, law):
    r = solve_hbm(model, wave_excitation(model), HBMOptions(contact_law=law))
    assert r.converged and r.tensile_force_error_N == 0.0 and r.saddle_force_time_N.min() >= 0.0


def test_contact_preserved_equals_linear(model):
    ex = wave_excitation(model, relative_mm=3.0, second_harmonic_mm=-1.0)
    lin = solve_linear(model, ex)
    r = solve_hbm(model, ex, HBMOptions(contact_law="exact"))
    assert r.contact_preserved and r.iterations == 0
    assert np.allclose(r.cargo_displacement_harmonics[:3], lin.cargo_displacement, rtol=0, atol=1e-12)


@pytest.mark.parametrize("law", ["tanh", "softplus", "exact"])
def test_condensed_equals_full(coarse, law):
    ex = wave_excitation(coarse)
    opts = dict(harmonics=4, time_samples=32, contact_law=law)
    rc = solve_hbm(coarse, ex, HBMOptions(**opts))
    rf = solve_hbm(coarse, ex, HBMOptions(formulation="full", **opts))
    assert rc.converged and rf.converged
    scale_f = np.abs(rc.saddle_force_time_N).max()
    scale_x = np.abs(rc.cargo_displacement_time_m).max()
    assert np.abs(rf.saddle_force_time_N - rc.saddle_force_time_N).max() <= 1e-6 * scale_f
    assert np.abs(rf.cargo_displacement_time_m - rc.cargo_displacement_time_m).max() <= 1e-6 * scale_x


@pytest.mark.parametrize("formulation", ["condensed", "full"])
def test_hybr_equals_newton(coarse, formulation):
    ex = wave_excitation(coarse)
    a = solve_hbm(coarse, ex, HBMOptions(harmonics=3, time_samples=16, solver="newton", formulation=formulation))
    b = solve_hbm(coarse, ex, HBMOptions(harmonics=3, time_samples=16, solver="hybr", formulation=formulation))
    assert a.converged and b.converged
    assert np.allclose(a.saddle_force_time_N, b.saddle_force_time_N, rtol=0, atol=1e-7 * a.max_saddle_force_N)


def test_static_nonlinear_lift_off_matches_quasi_static(coarse):
    """H = 0: a large static hog lifts the outer saddles; the nonlinear static = exact static."""
    ex = wave_excitation(coarse, static_mid_mm=25.0).static_part()
    r = solve_hbm(coarse, ex, HBMOptions(harmonics=0, time_samples=2, contact_law="exact"))
    qs = solve_quasi_static(coarse, ex, QuasiStaticOptions(time_samples=2))
    assert r.converged and not r.contact_preserved
    assert np.allclose(r.saddle_force_time_N, qs.saddle_force_time_N, rtol=0, atol=1e-6 * qs.max_saddle_force_N)
    assert np.allclose(r.cargo_displacement_time_m, qs.cargo_displacement_time_m, rtol=0, atol=1e-9)


def test_non_convergence_is_reported_not_raised(model):
    ex = wave_excitation(model)
    r = solve_hbm(model, ex, HBMOptions(harmonics=5, contact_law="tanh", max_iterations=1, continuation=False, tolerance=1e-14))
    assert not r.converged and r.outcome is SolverOutcome.NOT_CONVERGED
    assert r.residual_norm > 1e-14 and r.path == HBMPath(HBMStart.PREDICTOR, HBMRoute.NONE, NewtonStop.MAX_ITERATIONS)


@pytest.mark.parametrize("law", ["tanh", "exact"])
def test_fallback_continuation_reaches_the_solution(model, law):
    """The fallback exercised deterministically: from the mirrored linear compression (each compressed saddle
    lifted as far as it was compressed) the direct Newton at H = 10 stagnates (without the fallback it fails);
    the continuation in kappa reaches the solution the direct solve finds from the quasi-static predictor."""
    ex = wave_excitation(model)
    options = HBMOptions(harmonics=10, time_samples=64, contact_law=law)
    mirrored = -harmonics_to_time(solve_linear(model, ex).saddle_compression_m, 64)
    direct = solve_hbm(model, ex, options)
    without = solve_hbm(model, ex, replace(options, continuation=False), initial_compression_m=mirrored)
    r = solve_hbm(model, ex, options, initial_compression_m=mirrored)
    assert direct.path == HBMPath(HBMStart.PREDICTOR, HBMRoute.DIRECT, NewtonStop.CONVERGED)
    assert not without.converged and without.path == HBMPath(HBMStart.GIVEN, HBMRoute.NONE, NewtonStop.STAGNATED)
    assert r.outcome is SolverOutcome.CONVERGED_BY_CONTINUATION
    assert r.path == HBMPath(HBMStart.GIVEN, HBMRoute.KAPPA_CONTINUATION, NewtonStop.CONVERGED)
    # the same periodic solution (measured 2e-12 and 7e-15 of the peak force)
    np.testing.assert_allclose(r.saddle_force_time_N, direct.saddle_force_time_N, rtol=0, atol=1e-8 * direct.max_saddle_force_N)


def test_dropped_harmonics_are_reported(model):
    r = solve_hbm(model, wave_excitation(model), HBMOptions(harmonics=1, time_samples=8))
    assert r.converged and SolverWarning.HARMONICS_ABOVE_H_IGNORED in r.warnings
    assert (
        SolverWarning.HARMONICS_ABOVE_H_IGNORED
        not in solve_hbm(model, wave_excitation(model), HBMOptions(harmonics=2, time_samples=8)).warnings
    )


def test_a_warm_start_from_the_solution_returns_it(model):
    ex = wave_excitation(model)
    opts = HBMOptions(harmonics=5, time_samples=64)
    cold = solve_hbm(model, ex, opts)
    warm = solve_hbm(model, ex, opts, initial_compression_m=cold.saddle_compression_time_m)
    assert warm.converged and warm.iterations <= 1 and warm.path.start is HBMStart.GIVEN and cold.path.start is HBMStart.PREDICTOR
    np.testing.assert_allclose(warm.saddle_force_time_N, cold.saddle_force_time_N, rtol=0, atol=1e-6 * cold.max_saddle_force_N)
    with pytest.raises(ValueError, match="initial_compression_m"):
        solve_hbm(model, ex, opts, initial_compression_m=np.zeros((64, 2)))  # 3 saddles, not 2
