"""Tests of the ship weight distribution (seafast.vessel.loading)."""

from __future__ import annotations

import numpy as np
import pytest

from seafast.vessel.hull_form import HullForm
from seafast.vessel.loading import (
    BASE_LIGHTSHIP_FRACTION,
    BASE_STILL_WATER_MOMENT_NM,
    BallastTank,
    LightshipDistribution,
    VesselLoading,
    WeightItem,
    balance_ballast,
    base_hull_form,
    base_vessel_loading,
    mass_distribution_kg_per_m,
    monopile_mass_kg,
    still_water_moment_even_keel_Nm,
    weight_distribution_N_per_m,
)

L = 171.0


def _integrals(loading: VesselLoading, x0: float = -1.0, x1: float = L + 1.0, n: int = 400_001):
    x = np.linspace(x0, x1, n)
    m = mass_distribution_kg_per_m(x, loading)
    total = np.trapezoid(m, x)
    return total, np.trapezoid(m * x, x) / total


def test_monopile_mass_base_case():
    m = monopile_mass_kg(74.0, 8.0, 0.080)
    assert m == pytest.approx(1.156e6, rel=2e-3)
    # closed form check, independent of the implementation
    assert m == pytest.approx(7850 * np.pi * 8.0 * 0.080 * (1 - 0.080 / 8.0) * 74.0, rel=1e-12)


@pytest.mark.parametrize("lcg_frac", [0.5, 0.46, 0.55, 0.42])
def test_prohaska_lightship_mass_and_lcg(lcg_frac):
    ls = LightshipDistribution(1.2e7, lcg_frac * L, L, 0.75)
    total, lcg = _integrals(VesselLoading(ls, ()), 0.0, L)
    assert total == pytest.approx(1.2e7, rel=1e-6)
    assert lcg == pytest.approx(lcg_frac * L, abs=1e-3)
    a_aft, a_fore = ls.end_ordinates
    assert a_aft + a_fore == pytest.approx(1.5)
    assert ls.middle_ordinate == pytest.approx(1.125)
    # ordinates as fractions of the mean
    w_mean = 1.2e7 / L
    assert ls.mass_per_length_kg_per_m(0.0) == pytest.approx(a_aft * w_mean)
    assert ls.mass_per_length_kg_per_m(L / 2) == pytest.approx(1.125 * w_mean)
    # LCG aft of midship -> heavier aft end
    if lcg_frac < 0.5:
        assert a_aft > a_fore


def test_prohaska_rejects_unreachable_lcg():
    with pytest.raises(ValueError, match="negative end ordinate"):
        LightshipDistribution(1e7, 0.2 * L, L, 0.75)


def test_weight_item_validation_and_distribution():
    with pytest.raises(ValueError, match=r"x_end_m = 5\.0 must be > x_start_m = 10\.0"):
        WeightItem("bad", 10.0, 5.0, 1.0)
    with pytest.raises(ValueError, match=r"mass_kg = -1\.0; must be finite and >= 0"):
        WeightItem("bad", 0.0, 5.0, -1.0)
    it = WeightItem("cargo", 48.5, 122.5, 4.0e6)
    loading = VesselLoading(None, (it,))
    total, lcg = _integrals(loading)
    assert total == pytest.approx(4.0e6, rel=1e-4)
    assert lcg == pytest.approx(85.5, abs=1e-3)
    x = np.array([48.0, 50.0, 122.0, 123.0])
    np.testing.assert_allclose(weight_distribution_N_per_m(x, loading, 9.81), 9.81 * np.array([0, 4e6 / 74, 4e6 / 74, 0]), rtol=1e-12)


def test_base_vessel_loading_is_balanced_and_documented():
    hull = base_hull_form()
    ld = base_vessel_loading()
    disp = 1025.0 * 32000.0
    assert ld.total_mass_kg == pytest.approx(disp, rel=1e-6)
    assert ld.lcg_m == pytest.approx(hull.centre_of_buoyancy_x_m(n=20001), abs=1e-6 * L)
    assert ld.lightship is not None
    assert ld.lightship.mass_kg == pytest.approx(BASE_LIGHTSHIP_FRACTION * disp, rel=1e-6)
    assert 0.30 <= ld.lightship.mass_kg / disp <= 0.40
    cargo = ld.item("cargo")
    assert cargo.mass_kg == pytest.approx(4 * 1.156e6, rel=2e-3)
    assert (cargo.x_start_m, cargo.x_end_m) == pytest.approx((85.5 - 37.0, 85.5 + 37.0))
    ballast = [it for it in ld.items if it.name.startswith("ballast")]
    assert len(ballast) == 3 and all(b.mass_kg >= 0 for b in ballast)
    # the documented ballast plan hits the still-water moment target at the cargo midpoint
    m = still_water_moment_even_keel_Nm(hull, ld, 85.5)
    assert m == pytest.approx(BASE_STILL_WATER_MOMENT_NM, rel=1e-6)
    assert m < 0  # hogging
    # the integrated distribution agrees with the item bookkeeping
    total, lcg = _integrals(ld)
    assert total == pytest.approx(disp, rel=1e-5)
    assert lcg == pytest.approx(ld.lcg_m, abs=1e-3)


def test_base_loading_cargo_position_and_two_tank_balance():
    hull = base_hull_form()
    ld = base_vessel_loading(cargo_position_m=95.0, still_water_moment_Nm=None)
    assert ld.item("cargo").lcg_m == pytest.approx(95.0)
    assert len([it for it in ld.items if it.name.startswith("ballast")]) == 2
    assert ld.total_mass_kg == pytest.approx(1025.0 * hull.displaced_volume_m3(n=20001), rel=1e-9)
    assert ld.lcg_m == pytest.approx(hull.centre_of_buoyancy_x_m(n=20001), abs=1e-6)


def test_balance_ballast_errors():
    hull = base_hull_form()
    ld = VesselLoading(LightshipDistribution(1e7, 80.0, L), ())
    with pytest.raises(ValueError, match="tank groups"):
        balance_ballast(hull, ld, [BallastTank("a", 0, 10)])
    # both tanks forward of the LCB cannot trim the ship aft -> negative mass
    with pytest.raises(ValueError, match="negative ballast"):
        balance_ballast(hull, ld, [BallastTank("a", 120, 130), BallastTank("b", 150, 160)])


def _box(length=100.0, breadth=20.0, draft=5.0) -> HullForm:
    return HullForm(np.array([0.0, length]), np.array([breadth, breadth]), draft)


def test_even_keel_moment_box_barge_closed_form():
    # box barge, uniform weight plus a concentrated (short) weight at midship
    Lb, B, T, rho, g = 100.0, 20.0, 5.0, 1025.0, 9.81
    hull = _box(Lb, B, T)
    disp = rho * Lb * B * T
    P, c = 2.0e6, 2.0
    ld = VesselLoading(None, (WeightItem("hull", 0, Lb, disp - P), WeightItem("point", 49.0, 51.0, P)))
    m_mid = still_water_moment_even_keel_Nm(hull, ld, 50.0)
    # sagging (positive): P g L / 8 - P g c / 8
    assert m_mid == pytest.approx(P * g * (Lb - c) / 8.0, rel=1e-9)
    # uniform weight alone: no moment
    ld0 = VesselLoading(None, (WeightItem("hull", 0, Lb, disp),))
    assert abs(still_water_moment_even_keel_Nm(hull, ld0, 37.0)) < 1e-6 * disp * g * Lb


def test_hull_integrals_are_kept_and_equal_a_fresh_hull():
    from seafast.vessel.hull_form import HullForm

    cb = 32000.0 / (171.0 * 42.0 * 6.5)
    hull = HullForm.tapered_box(171.0, 42.0, 6.5, cb)
    first = (hull.displaced_volume_m3(20001), hull.centre_of_buoyancy_x_m(20001), hull.displaced_volume_m3())
    fresh = HullForm.tapered_box(171.0, 42.0, 6.5, cb)
    assert first == (fresh.displaced_volume_m3(20001), fresh.centre_of_buoyancy_x_m(20001), fresh.displaced_volume_m3())
    assert first[0] == pytest.approx(32000.0, rel=1e-6) and first[2] != first[0]  # kept per quadrature size


def test_the_ballast_follows_the_cargo():
    from seafast.vessel.loading import base_vessel_loading

    light, heavy = (base_vessel_loading(cargo_mass_kg=m) for m in (3.0e6, 4.6e6))
    assert light.items[-1].mass_kg != heavy.items[-1].mass_kg
    # the tanks take up the difference: the same displacement
    assert light.total_mass_kg == pytest.approx(heavy.total_mass_kg, rel=1e-12)
