"""Linear spectral extremes: closed forms (Rayleigh MPM, Rice), totals with still water, linearity in Hs."""

from __future__ import annotations

import math

import numpy as np
import pytest

import seafast
from seafast.analyses.seastate.spectral import (
    downcrossing_rate_per_s,
    rayleigh_mpm,
    response_statistics,
    spectral_analysis,
)
from seafast.analyses.seastate.spectrum import sea_state_spectrum


@pytest.fixture(scope="module")
def base():
    return spectral_analysis(seafast.load_case(None))


def test_rayleigh_mpm_and_rice_rate_closed_forms():
    tz = 8.0
    m0, m2 = 4.0, 4.0 * (2 * math.pi / tz) ** 2
    assert rayleigh_mpm(np.array([m0]), np.array([m2]), 10800.0)[0] == pytest.approx(2.0 * math.sqrt(2 * math.log(10800 / tz)), rel=1e-12)
    # fewer than one cycle, or no response: no maximum beyond the mean
    assert rayleigh_mpm(np.array([m0, 0.0]), np.array([m2, 0.0]), 4.0).tolist() == [0.0, 0.0]
    # Rice: zero-mean process crosses zero downwards once per Tz; a mean of 2 sigma: exp(-2) of that
    assert downcrossing_rate_per_s(np.array([0.0]), np.array([m0]), np.array([m2]))[0] == pytest.approx(1 / tz, rel=1e-12)
    assert downcrossing_rate_per_s(np.array([4.0]), np.array([m0]), np.array([m2]))[0] == pytest.approx(math.exp(-2) / tz, rel=1e-12)
    assert downcrossing_rate_per_s(np.array([1.0]), np.array([0.0]), np.array([0.0]))[0] == 0.0


def test_unit_transfer_function_gives_the_wave_statistics():
    case = seafast.load_case(None, {"sea_state.spectrum": "pierson_moskowitz"})
    sp = sea_state_spectrum(case)
    stats = response_statistics(np.ones((sp.omega_rad_s.size, 1), complex), sp, 10800.0)
    assert stats.sigma[0] == pytest.approx(3.0 / 4.0, rel=0.005)  # Hs = 4 sigma
    assert stats.zero_crossing_period_s[0] == pytest.approx(2 * math.pi * math.sqrt(sp.moment(0) / sp.moment(2)), rel=1e-12)
    # a transfer function omega^2 turns m0 into m4 of the unit one
    quad = response_statistics((sp.omega_rad_s**2)[:, None].astype(complex), sp, 10800.0)
    assert quad.m0[0] == pytest.approx(stats.m4[0], rel=1e-12)


def test_totals_add_still_water_with_the_governing_sign(base):
    e = base.extremes
    sw = e.still_water
    assert e.totals["F_N"] == pytest.approx(np.max(sw.saddle_force_N + e.saddle_force.mpm), rel=1e-14)
    assert e.totals["M_b_Nm"] == pytest.approx(np.max(np.abs(sw.bending_moment_Nm) + e.bending_moment.mpm), rel=1e-14)
    assert e.totals["sigma_b_Pa"] == pytest.approx(np.max(np.abs(sw.bending_stress_Pa) + e.bending_stress.mpm), rel=1e-14)
    assert e.totals["u_s_m"] == pytest.approx(np.max(sw.saddle_compression_m + e.saddle_compression.mpm), rel=1e-14)
    assert e.totals["u_d_m"] == 0.0
    # the static saddle reactions carry the cargo: their sum is its weight (a sign or factor slip fails)
    weight = base.model.cargo.mass_kg * 9.81
    stiff_part = base.model.saddle_unilateral_stiffness_N_per_m / base.model.saddle_stiffness_N_per_m
    assert np.sum(sw.saddle_force_N / stiff_part) == pytest.approx(weight + base.case.seafastening.lashing.pretension_N, rel=0.01)
    # saddle force = unilateral stiffness x compression, per frequency and hence per moment
    k = base.model.saddle_unilateral_stiffness_N_per_m
    assert np.allclose(e.saddle_force.sigma, k * e.saddle_compression.sigma, rtol=1e-12)
    # stress statistics = moment statistics / section modulus (uniform tube)
    assert np.allclose(e.bending_stress.sigma, e.bending_moment.sigma / base.transfer.bending_section_modulus_m3, rtol=1e-12)
    assert e.row()["model"] == "linear" and e.row()["method"] == "spectral" and e.row()["converged"] is True


def test_dynamic_extremes_scale_with_hs_and_uplift_follows_rice(base):
    double = spectral_analysis(seafast.load_case(None, {"sea_state.significant_height_m": 6.0}), base.model)
    e1, e2 = base.extremes, double.extremes
    assert np.allclose(e2.saddle_force.mpm, 2 * e1.saddle_force.mpm, rtol=1e-10)
    assert np.allclose(e2.bending_moment.sigma, 2 * e1.bending_moment.sigma, rtol=1e-10)
    # Rice: rate(2 sigma) / rate(sigma) = exp(mu^2 / 2 m0 (1 - 1/4)) for each saddle
    mu, m0 = e1.still_water.saddle_compression_m, e1.saddle_compression.m0
    assert np.allclose(e2.uplift_per_hour_per_saddle / e1.uplift_per_hour_per_saddle, np.exp(mu**2 / (2 * m0) * 0.75), rtol=1e-10)
    assert e1.totals["uplift_per_hour"] == pytest.approx(np.sum(e1.uplift_per_hour_per_saddle), rel=1e-14)


def test_longer_duration_raises_the_mpm_as_sqrt_ln_cycles(base):
    e = base.extremes
    longer = spectral_analysis(seafast.load_case(None, {"sea_state.duration_s": 4 * 10800.0}), base.model).extremes
    tz = e.saddle_force.zero_crossing_period_s
    ratio = np.sqrt(np.log(4 * 10800.0 / tz) / np.log(10800.0 / tz))
    assert np.allclose(longer.saddle_force.mpm / e.saddle_force.mpm, ratio, rtol=1e-12)


def test_grid_convergence_of_the_response_moments(base):
    # the 256-point grid integrates the response spectra as a 2048-point one does, within 0.5 %
    from seafast.analyses.seastate.spectral import spectral_extremes
    from seafast.analyses.seastate.transfer import still_water, transfer_functions

    fine_sp = sea_state_spectrum(base.case, n_points=2048)
    fine = spectral_extremes(
        transfer_functions(base.case, base.model, fine_sp.omega_rad_s, heading_deg=180.0),
        fine_sp,
        still_water(base.case, base.model),
        base.case.sea_state.duration_s,
    )
    for name in ("saddle_force", "bending_moment"):
        coarse_stats, fine_stats = getattr(base.extremes, name), getattr(fine, name)
        assert np.allclose(coarse_stats.m0, fine_stats.m0, rtol=5e-3), name
        assert np.allclose(coarse_stats.m2, fine_stats.m2, rtol=5e-3), name
