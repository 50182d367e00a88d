"""Tests of the still-water hull girder (seafast.hull.still_water): equilibrium, closed-form beams,
the Timoshenko shear term and the deflection from a bending-moment table."""

from __future__ import annotations

import numpy as np
import pytest

from hull_cases import RHO, G, box_hull, exact_moment_integral
from seafast.hull.girder import HullGirder
from seafast.hull.still_water import deflection_from_bending_moment, still_water_response
from seafast.vessel.loading import VesselLoading, WeightItem, base_hull_form


def test_base_still_water_equilibrium(base):
    girder, loading, r = base
    W = loading.total_mass_kg * G
    B = np.trapezoid(r.buoyancy_N_per_m, r.x_m)  # buoyancy is linear between nodes: exact
    assert abs(B - W) / W < 1e-6
    lcb = exact_moment_integral(r.x_m, r.buoyancy_N_per_m) / B
    assert lcb == pytest.approx(loading.lcg_m, abs=1e-6 * girder.length_m)
    # designed to float at even keel on the design draught
    assert abs(r.sinkage_m) < 1e-4 and abs(r.trim_rad) < 1e-6
    mmax = np.abs(r.bending_moment_Nm).max()
    assert abs(r.shear_force_N[-1]) < 1e-9 * W
    assert abs(r.bending_moment_Nm[0]) == 0.0 and abs(r.bending_moment_Nm[-1]) < 1e-9 * mmax
    assert r.deflection_m[0] == 0.0 and r.deflection_m[-1] == 0.0


def test_prismatic_barge_uniform_weight_has_no_bending():
    hull = box_hull()
    disp = RHO * 100 * 20 * 5
    ld = VesselLoading(None, (WeightItem("uniform", 0.0, 100.0, disp),))
    r = still_water_response(HullGirder(hull), ld)
    scale = disp * G * 100
    assert np.abs(r.bending_moment_Nm).max() < 1e-12 * scale
    assert np.abs(r.shear_force_N).max() < 1e-12 * disp * G
    assert np.abs(r.deflection_m).max() < 1e-12
    # a callable weight function gives the same
    r2 = still_water_response(HullGirder(hull), lambda x: np.full_like(x, disp * G / 100.0))
    assert np.abs(r2.bending_moment_Nm).max() < 1e-12 * scale


@pytest.mark.parametrize("shear_area", [np.inf, 0.3])
def test_box_barge_concentrated_weight_closed_form(shear_area):
    Lb, Bb, T = 100.0, 20.0, 5.0
    hull = box_hull(Lb, Bb, T)
    girder = HullGirder(hull, second_moment_m4=10.0, shear_area_m2=shear_area)
    disp = RHO * Lb * Bb * T
    Pm, c = 2.0e6, 2.0  # 2000 t over 2 m at midship
    ld = VesselLoading(None, (WeightItem("hull", 0, Lb, disp - Pm), WeightItem("point", 49.0, 51.0, Pm)))
    r = still_water_response(girder, ld)
    P = Pm * G
    i = int(np.argmin(np.abs(r.x_m - 50.0)))
    assert r.x_m[i] == pytest.approx(50.0)
    m_mid = P * (Lb - c) / 8.0  # sagging positive
    assert r.bending_moment_Nm[i] == pytest.approx(m_mid, rel=1e-9)
    EI = girder.bending_stiffness_Nm2
    # chord-relative = simply supported under the self-equilibrated load:
    # uniform upward P/L plus central patch load P over c
    w_eb = (5 * P * Lb**3 - P * (8 * Lb**3 - 4 * Lb * c**2 + c**3)) / (384 * EI)
    w_shear = 0.0 if np.isinf(shear_area) else -m_mid / girder.shear_stiffness_N
    assert r.deflection_m[i] == pytest.approx(w_eb + w_shear, rel=1e-6)
    assert r.deflection_m[i] < 0  # weight amidships: sagging, midship down
    assert r.slope_rad[i] == pytest.approx(0.0, abs=1e-6 * abs(w_eb) / Lb)


def test_timoshenko_exceeds_euler_bernoulli_by_shear_term(base):
    girder, loading, r = base
    eb = HullGirder(girder.hull, shear_area_m2=np.inf)
    r_eb = still_water_response(eb, loading)
    np.testing.assert_allclose(r_eb.bending_moment_Nm, r.bending_moment_Nm, rtol=0, atol=1e-9 * np.abs(r.bending_moment_Nm).max())
    # shear deflection relative to the chord through the ends: analytically -M / (G A_s)
    # (the FE reproduces it to ~1e-5: Hermite consistent loads on shear-flexible elements)
    diff = r.deflection_m - r_eb.deflection_m
    expected = -r.bending_moment_Nm / girder.shear_stiffness_N
    assert np.abs(diff - expected).max() < 1e-4 * np.abs(expected).max()
    assert np.abs(expected).max() > 0.1 * np.abs(r.deflection_m).max()  # the shear term matters here
    # hogging: Timoshenko deflection is larger (more upward) than EB amidships
    i = int(np.argmin(np.abs(r.x_m - 85.5)))
    assert r.deflection_m[i] > r_eb.deflection_m[i] > 0


def test_deflection_from_bending_moment_matches_fe(base):
    girder, _, r = base
    scale = np.abs(r.deflection_m).max()
    z1, s1 = deflection_from_bending_moment(girder, r.x_m, r.bending_moment_Nm, r.shear_force_N)
    z2, _ = deflection_from_bending_moment(girder, r.x_m, r.bending_moment_Nm)
    assert np.abs(z1 - r.deflection_m).max() < 1e-4 * scale
    assert np.abs(z2 - r.deflection_m).max() < 1e-4 * scale
    assert np.abs(s1 - r.slope_rad).max() < 1e-4 * np.abs(r.slope_rad).max()
    with pytest.raises(ValueError, match="anti-correlated"):
        deflection_from_bending_moment(girder, r.x_m, r.bending_moment_Nm, -r.shear_force_N)


def test_deflection_from_parabolic_hogging_moment_closed_form():
    girder = HullGirder(base_hull_form())
    L = 171.0
    x = np.linspace(0, L, 181)
    c = 1e5
    M = -c * x * (L - x)  # hogging, -c L^2 / 4 amidships
    z, _ = deflection_from_bending_moment(girder, x, M)
    EI, GA = girder.bending_stiffness_Nm2, girder.shear_stiffness_N
    z_exact = -(c / EI) * (L * x**3 / 6 - x**4 / 12 - L**3 * x / 12) + c * x * (L - x) / GA
    np.testing.assert_allclose(z, z_exact, rtol=0, atol=1e-9 * np.abs(z_exact).max())
    assert z[90] > 0  # hogging: midship up
