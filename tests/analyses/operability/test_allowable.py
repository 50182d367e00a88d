"""Allowable sea states (docs/operability.md): closed forms, the nonlinear search, and consistency with
`seafast seastate` at the reported Hs."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

import seafast
from seafast.analyses.operability.allowable import OperabilitySettings, allowable_sea_states
from seafast.analyses.operability.family import analysis_at, rescaled, sea_state_family
from seafast.analyses.seastate.design_wave import sea_state_design_waves
from seafast.analyses.seastate.spectral import spectral_analysis, spectral_extremes
from seafast.analyses.seastate.spectrum import jonswap_density, sea_state_spectrum
from seafast.analyses.seastate.transfer import transfer_functions
from seafast.config import CaseError
from seafast.config.schema import max_significant_height_m

RAISED = {"limits.max_saddle_force_N": 11.5e6, "limits.max_bending_stress_Pa": 28.0e6}
"""Limits the base case reaches only after its saddles lift off (the source's 7 MN is reached in still water + 0.4 m)."""


@pytest.fixture(scope="module")
def raised():
    case = seafast.load_case(None, RAISED)
    tps = [7.0, 9.0, 10.0, 12.0]
    family = sea_state_family(case, tps)
    return case, family, allowable_sea_states(case, tps, family=family)


@pytest.fixture(scope="module")
def base():
    case = seafast.load_case(None)
    tps = [6.0, 10.0, 14.0]
    return case, allowable_sea_states(case, tps)


def _seastate(overrides):
    an = spectral_analysis(seafast.load_case(None, overrides))
    return an, sea_state_design_waves(an)


def test_interpolated_transfer_functions_equal_direct_ones(raised):
    # the splines on the 0.005 rad/s master grid against transfer functions computed on the sea
    # state's own grid; the RAOs are linear between BEM frequencies, whose slope kinks a spline
    # rounds off (2e-3 of the inertia load there), but the extremes agree to 1e-6
    case, family, _ = raised
    for tp in (7.0, 10.0, 12.0):
        an = analysis_at(family, tp, 1.0)
        direct = transfer_functions(case, family.model, an.spectrum.omega_rad_s, heading_deg=180.0)
        for name, tol in (
            ("saddle_force_N", 2e-4),
            ("bending_moment_Nm", 1e-4),
            ("saddle_compression_m", 2e-4),
            ("deck_displacement", 1e-6),
            ("cargo_load_N", 4e-3),
        ):
            a, b = getattr(an.transfer, name), getattr(direct, name)
            assert np.max(np.abs(a - b)) <= tol * np.max(np.abs(b)), (tp, name)
        fresh = spectral_extremes(direct, an.spectrum, family.still, case.sea_state.duration_s)
        for q in ("F_N", "M_b_Nm", "sigma_b_Pa", "u_s_m", "uplift_per_hour"):
            assert an.extremes.totals[q] == pytest.approx(fresh.totals[q], rel=1e-6), (tp, q)


def test_rescaling_in_hs_equals_a_fresh_spectral_analysis(raised):
    _, family, _ = raised
    ref = analysis_at(family, 9.0, 1.0)
    at3 = rescaled(ref, 3.0)
    w = ref.spectrum.omega_rad_s
    # the sea-state grid does not depend on Hs (to round-off); the Hs = 3 m density from the formula on it
    assert np.allclose(sea_state_spectrum(at3.case).omega_rad_s, w, rtol=1e-11, atol=0)
    spectrum = replace(ref.spectrum, density_m2_s_per_rad=jonswap_density(w, 3.0, 9.0, 3.3), significant_height_m=3.0)
    fresh = spectral_extremes(ref.transfer, spectrum, family.still, at3.case.sea_state.duration_s)
    for q, v in fresh.totals.items():
        assert at3.extremes.totals[q] == pytest.approx(v, rel=1e-12, abs=1e-300), q
    assert np.allclose(at3.extremes.bending_moment.mpm, fresh.bending_moment.mpm, rtol=1e-12)


def test_linear_allowable_reaches_the_limit_in_seafast_seastate(base):
    # closed form against an independent path: the sea state's own spectral analysis at the
    # reported Hs (its own grid and directly computed transfer functions)
    case, result = base
    for p in result.points:
        assert p.governing_linear == "saddle_force" and p.hs_allowable_linear_m > 0
        an = spectral_analysis(
            seafast.load_case(None, {"sea_state.significant_height_m": p.hs_allowable_linear_m, "sea_state.peak_period_s": p.peak_period_s})
        )
        assert an.extremes.totals["F_N"] == pytest.approx(case.limits.max_saddle_force_N, rel=1e-4)
        assert an.extremes.totals["sigma_b_Pa"] < case.limits.max_bending_stress_Pa


def test_uplift_onset_is_where_rice_expects_one_uplift_in_the_duration(raised):
    case, family, result = raised
    hours = case.sea_state.duration_s / 3600.0
    for p in result.points:
        if not math.isfinite(p.hs_uplift_onset_m):
            continue
        an = rescaled(analysis_at(family, p.peak_period_s, 1.0), p.hs_uplift_onset_m)
        events = an.extremes.uplift_per_hour_per_saddle * hours
        # the saddle nearest to lifting off: one event (Rayleigh MPM = the level crossed once in N cycles)
        assert float(np.max(events)) == pytest.approx(1.0, rel=1e-9)
        below = rescaled(an, 0.9 * p.hs_uplift_onset_m)
        assert float(np.max(below.extremes.uplift_per_hour_per_saddle * hours)) < 0.3


def test_without_lift_off_below_the_limit_the_nonlinear_allowable_is_the_linear_one(base):
    _, result = base
    for p in result.points:
        assert p.hs_uplift_onset_m > p.hs_allowable_linear_m or math.isnan(p.hs_uplift_onset_m)
        assert p.hs_allowable_nonlinear_m == p.hs_allowable_linear_m
        assert p.governing_nonlinear == p.governing_linear
        assert p.converged


def test_nonlinear_allowable_gives_the_limit_in_seafast_seastate_within_one_percent(raised):
    # consistency: the design-wave row of `seafast seastate` at the reported
    # allowable Hs reaches the governing limit (searched on interpolated transfer functions,
    # checked on directly computed ones)
    case, _, result = raised
    checked = 0
    for p in result.points:
        if p.governing_nonlinear not in ("saddle_force", "bending_stress"):
            continue
        _, dw = _seastate(
            {**RAISED, "sea_state.significant_height_m": p.hs_allowable_nonlinear_m, "sea_state.peak_period_s": p.peak_period_s}
        )
        q, limit = (
            ("F_N", case.limits.max_saddle_force_N)
            if p.governing_nonlinear == "saddle_force"
            else ("sigma_b_Pa", case.limits.max_bending_stress_Pa)
        )
        assert dw.totals[q] == pytest.approx(limit, rel=0.01), p.peak_period_s
        checked += 1
    assert checked >= 2


def test_lift_off_raises_the_allowable_sea_state_above_the_linear_one(raised):
    # the outer saddles lift off before the limit: the linear model overestimates the force, and
    # the allowable Hs it gives is conservative; the search converges in a handful of evaluations
    _, _, result = raised
    by_tp = {p.peak_period_s: p for p in result.points}
    for tp in (9.0, 10.0):
        p = by_tp[tp]
        assert p.hs_uplift_onset_m < p.hs_allowable_linear_m < p.hs_allowable_nonlinear_m
        assert p.evaluations <= 30  # bracketing and Brent, not a grid
    assert by_tp[10.0].hs_allowable_nonlinear_m / by_tp[10.0].hs_allowable_linear_m > 1.05


def test_a_limit_never_reached_below_the_limiting_steepness_is_reported_as_steepness(raised):
    _, _, result = raised
    p = next(p for p in result.points if p.peak_period_s == 7.0)
    cap = max_significant_height_m(7.0)
    assert p.governing_linear == "steepness" and p.hs_allowable_linear_m == pytest.approx(cap)
    assert p.hs_allowable_nonlinear_m == pytest.approx(cap) and math.isinf(p.hs_force_nonlinear_m)
    assert math.isnan(p.hs_uplift_onset_m)  # no lift-off in any sea state that steep


def test_still_water_above_a_limit_allows_no_waves():
    case = seafast.load_case(None, {"limits.max_saddle_force_N": 6.0e6})  # the still-water force is 6.31 MN
    p = allowable_sea_states(case, [10.0]).points[0]
    assert p.hs_allowable_linear_m == 0.0 == p.hs_allowable_nonlinear_m
    assert p.governing_linear == "saddle_force" == p.governing_nonlinear


def test_a_tighter_search_tolerance_moves_the_nonlinear_allowable_by_less_than_it(raised):
    case, family, result = raised
    tight = allowable_sea_states(case, [10.0], OperabilitySettings(hs_tolerance_m=1e-5), family=family).points[0]
    p = next(p for p in result.points if p.peak_period_s == 10.0)
    assert abs(tight.hs_allowable_nonlinear_m - p.hs_allowable_nonlinear_m) <= 1e-3


def test_a_family_at_a_heading_equals_that_heading_s_sea_states():
    """Operability at one sea_state.heading_deg: the family's interpolated sea state against seafast seastate's."""
    case = seafast.load_case(None, {"sea_state.heading_deg": 120.0})
    family = sea_state_family(case, [8.0, 11.0])
    an = analysis_at(family, 11.0, 2.0)
    direct = spectral_analysis(
        seafast.load_case(None, {"sea_state.heading_deg": 120.0, "sea_state.peak_period_s": 11.0, "sea_state.significant_height_m": 2.0})
    )
    assert an.transfer.heading_deg == 120.0
    for q in ("F_N", "M_b_Nm", "sigma_b_Pa", "u_s_m"):
        assert an.extremes.totals[q] == pytest.approx(direct.extremes.totals[q], rel=1e-5), q
    head = analysis_at(sea_state_family(seafast.load_case(None), [11.0]), 11.0, 2.0)
    assert abs(an.extremes.totals["F_N"] / head.extremes.totals["F_N"] - 1.0) > 0.05  # another sea state
    with pytest.raises(CaseError, match=r"sea_state\.spreading_exponent = 4"):
        sea_state_family(seafast.load_case(None, {"sea_state.spreading_exponent": 4.0}), [10.0])
