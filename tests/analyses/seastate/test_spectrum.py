"""Wave spectra: DNV-RP-C205 closed forms, normalisation Hs = 4 sqrt(m0), grid coverage, tables, bad input."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad

import seafast
from seafast.analyses.seastate.spectrum import (
    MAX_VARIANCE_OUTSIDE,
    OMEGA_MAX_RAD_S,
    OMEGA_MIN_RAD_S,
    jonswap_density,
    jonswap_normalisation,
    pierson_moskowitz_density,
    sea_state_spectrum,
)
from seafast.config import CaseError, load_case


def _case(**sea):
    return seafast.load_case(None, {f"sea_state.{k}": v for k, v in sea.items()})


def test_pierson_moskowitz_integrates_to_hs2_over_16_and_peaks_at_tp():
    hs, tp = 3.0, 10.0
    m0 = quad(lambda w: float(pierson_moskowitz_density(w, hs, tp)), 0.05, 50.0, points=[0.628], limit=200)[0]
    assert m0 == pytest.approx(hs**2 / 16, rel=1e-6)
    w = np.linspace(0.3, 2.0, 170001)
    assert w[np.argmax(pierson_moskowitz_density(w, hs, tp))] == pytest.approx(2 * math.pi / tp, rel=1e-4)
    # S scales with Hs^2 (a wrong exponent of Hs fails)
    assert pierson_moskowitz_density(0.7, 2 * hs, tp) == pytest.approx(4 * pierson_moskowitz_density(0.7, hs, tp), rel=1e-14)


@pytest.mark.parametrize("gamma", [1.0, 2.0, 3.3, 5.0, 7.0])
def test_jonswap_normalisation_against_dnv_approximation(gamma):
    # DNV-RP-C205's A_gamma = 1 - 0.287 ln(gamma) normalises to within 2 % for gamma <= 7 (0.2 % at 3.3; independent of the quadrature)
    assert jonswap_normalisation(gamma) == pytest.approx(1 - 0.287 * math.log(gamma), rel=0.02 if gamma > 5 else 0.01)
    # the peak is gamma times the PM peak, times the normalisation
    wp = 2 * math.pi / 9.0
    assert jonswap_density(wp, 2.0, 9.0, gamma) == pytest.approx(
        jonswap_normalisation(gamma) * gamma * pierson_moskowitz_density(wp, 2.0, 9.0), rel=1e-12
    )


def test_jonswap_widths_are_sigma_007_below_and_009_above_the_peak():
    hs, tp, gamma = 2.0, 8.0, 3.3
    wp = 2 * math.pi / tp
    for sigma, u in ((0.07, 0.95), (0.09, 1.05)):
        ratio = jonswap_density(u * wp, hs, tp, gamma) / (jonswap_normalisation(gamma) * pierson_moskowitz_density(u * wp, hs, tp))
        assert ratio == pytest.approx(gamma ** math.exp(-((u - 1) ** 2) / (2 * sigma**2)), rel=1e-12)


@pytest.mark.parametrize(
    "spectrum,hs,tp,gamma",
    [
        ("jonswap", 3.0, 10.0, 3.3),
        ("jonswap", 1.0, 6.0, 3.3),
        ("jonswap", 6.0, 16.0, 5.0),
        ("pierson_moskowitz", 3.0, 10.0, 3.3),
        ("jonswap", 0.5, 25.0, 1.5),
    ],
)
def test_spectrum_on_its_grid_integrates_to_hs2_over_16_within_1_percent(spectrum, hs, tp, gamma):
    sp = sea_state_spectrum(_case(spectrum=spectrum, significant_height_m=hs, peak_period_s=tp, peak_enhancement=gamma))
    assert sp.moment(0) == pytest.approx(hs**2 / 16, rel=0.01)
    w = sp.omega_rad_s
    assert np.all(np.diff(w) > 0) and w[0] >= OMEGA_MIN_RAD_S and w[-1] <= OMEGA_MAX_RAD_S
    assert sp.variance_outside_grid_m2 <= MAX_VARIANCE_OUTSIDE * hs**2 / 16
    assert sp.peak_period_s == tp and sp.significant_height_m == hs


def test_pierson_moskowitz_second_moment_closed_form_and_grid_quadrature():
    # PM: m2 = 5/64 Hs^2 omega_p^2 sqrt(pi / 1.25) over (0, inf), so Tz = 0.7104 Tp
    hs, tp = 3.0, 10.0
    wp = 2 * math.pi / tp

    def m2_density(w):
        return w**2 * float(pierson_moskowitz_density(w, hs, tp))

    m2_exact = 5 / 64 * hs**2 * wp**2 * math.sqrt(math.pi / 1.25)
    full = quad(m2_density, 0.05, 2.0, points=[wp], limit=200)[0] + quad(m2_density, 2.0, np.inf, limit=200)[0]
    assert full == pytest.approx(m2_exact, rel=1e-6)
    sp = sea_state_spectrum(_case(spectrum="pierson_moskowitz", significant_height_m=hs, peak_period_s=tp))
    w = sp.omega_rad_s
    # the grid integrates m2 of its band to 0.1 % (the omega^-3 tail beyond 4 rad/s, 3 % of the
    # wave's m2, is left out: the ship's transfer functions vanish there)
    assert sp.moment(2) == pytest.approx(quad(m2_density, w[0], w[-1], points=[wp], limit=200)[0], rel=1e-3)
    assert 2 * math.pi * math.sqrt(hs**2 / 16 / m2_exact) == pytest.approx(0.7104 * tp, rel=1e-3)


def test_spectrum_table_read_rescaled_and_resolved_against_the_case_folder(tmp_path):
    w = np.linspace(0.2, 3.0, 300)
    s = jonswap_density(w, 2.0, 9.0, 3.3)
    (tmp_path / "tables").mkdir()
    np.savetxt(tmp_path / "tables" / "sea.csv", np.c_[w, s], delimiter=",", header="omega_rad_s,S_m2_s_per_rad", comments="")
    case_file = tmp_path / "case.yaml"
    case_file.write_text("sea_state: {spectrum: tables/sea.csv, significant_height_m: null, peak_period_s: null}\n")
    sp = sea_state_spectrum(load_case(case_file))
    assert sp.significant_height_m == pytest.approx(2.0, rel=0.01)
    assert sp.moment(0) == pytest.approx(4.0 / 16, rel=0.01)
    assert sp.peak_period_s == pytest.approx(9.0, rel=0.01)
    rescaled = sea_state_spectrum(load_case(case_file, {"sea_state.significant_height_m": 4.0}))
    assert rescaled.moment(0) == pytest.approx(16.0 / 16, rel=0.01)
    assert np.interp(1.0, rescaled.omega_rad_s, rescaled.density_m2_s_per_rad) == pytest.approx(
        (4.0 / sp.significant_height_m) ** 2 * np.interp(1.0, sp.omega_rad_s, sp.density_m2_s_per_rad), rel=1e-9
    )


@pytest.mark.parametrize(
    "text,needle",
    [
        ("omega,S\n0.5,1\n0.6,2\n0.7,1\n", "expected columns omega_rad_s,S_m2_s_per_rad"),
        ("omega_rad_s,S_m2_s_per_rad\n0.5,1\n0.4,2\n0.7,1\n", "strictly increasing"),
        ("omega_rad_s,S_m2_s_per_rad\n0.5,1\n0.6,-2\n0.7,1\n", "line 3"),
        ("omega_rad_s,S_m2_s_per_rad\n0.5,1\n0.6,abc\n0.7,1\n", "must be numbers"),
        ("omega_rad_s,S_m2_s_per_rad\n0.5,0\n0.6,0\n0.7,0\n", "zero everywhere"),
        ("omega_rad_s,S_m2_s_per_rad\n3.0,1\n5.0,1\n6.0,1\n", "above 4 rad/s"),
    ],
)
def test_bad_spectrum_table_names_the_key_and_file(tmp_path, text, needle):
    p = tmp_path / "bad.csv"
    p.write_text(text)
    with pytest.raises(CaseError) as err:
        sea_state_spectrum(_case(spectrum=str(p), peak_period_s=None))
    assert "sea_state.spectrum" in str(err.value) and needle in str(err.value)


def test_missing_table_and_missing_parameters_are_clear_errors(tmp_path):
    with pytest.raises(CaseError, match=r"sea_state.spectrum = .*cannot read it"):
        sea_state_spectrum(_case(spectrum=str(tmp_path / "nope.csv"), peak_period_s=None))
    with pytest.raises(CaseError, match=r"sea_state.significant_height_m = null: required"):
        sea_state_spectrum(seafast.load_case(None, {"sea_state": {"peak_period_s": 8.0}}))


def test_short_peak_period_refused_with_the_allowed_bound():
    with pytest.raises(CaseError) as err:
        sea_state_spectrum(_case(significant_height_m=1.0, peak_period_s=4.0))
    msg = str(err.value)
    assert msg.startswith("sea_state.peak_period_s = 4.0") and "above 4 rad/s" in msg
    tp_min = float(msg.split("peak_period_s >= ")[1].split(" s")[0])
    assert 4.0 < tp_min < 5.0
    # the bound is the honest one: just above it passes, just below it is refused
    sea_state_spectrum(_case(significant_height_m=1.0, peak_period_s=tp_min + 0.01))
    with pytest.raises(CaseError):
        sea_state_spectrum(_case(significant_height_m=1.0, peak_period_s=tp_min - 0.02))


@pytest.mark.parametrize(
    "overrides,needle",
    [
        ({"sea_state.significant_height_m": -1}, "sea_state.significant_height_m = -1"),
        ({"sea_state.peak_period_s": 0}, "sea_state.peak_period_s = 0"),
        ({"sea_state.peak_enhancement": 0.5}, "sea_state.peak_enhancement = 0.5"),
        ({"sea_state.duration_s": 10}, "sea_state.duration_s = 10"),
        ({"sea_state.realisations": 2}, "sea_state.realisations = 2"),
        ({"sea_state.seed": -3}, "sea_state.seed = -3"),
        ({"sea_state.significant_height_m": 12.0}, "allowed Hs <= 9.22 m"),
        ({"sea_state.spectrum": "table.csv"}, "peak_period_s = 10.0: with a spectrum table"),
        ({"sea_state.colour": "blue"}, "sea_state.colour: unknown key"),
        ({"limits.max_saddle_force_N": 0}, "limits.max_saddle_force_N = 0"),
    ],
)
def test_bad_sea_state_keys_are_refused_naming_the_key(overrides, needle):
    with pytest.raises(CaseError) as err:
        seafast.load_case(None, overrides)
    assert needle in str(err.value)
