"""Tests of the hull-girder still-water and wave response (seafast.excitation.hull_girder)."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.interpolate import CubicHermiteSpline

from seafast.excitation.hull_girder import (
    HullGirder,
    HydrostaticBalanceError,
    deck_deflection_at,
    deck_harmonics_at,
    deck_load_influence,
    deck_rise_m,
    deflection_from_bending_moment,
    iacs_wave_bending_moments_Nm,
    iacs_wave_coefficient,
    patch_load_response,
    still_water_response,
    wave_response,
)
from seafast.vessel.hull_form import HullForm
from seafast.vessel.loading import (
    BASE_STILL_WATER_MOMENT_NM,
    VesselLoading,
    WeightItem,
    base_hull_form,
    base_vessel_loading,
)

RHO, G = 1025.0, 9.81


def _box(length=100.0, breadth=20.0, draft=5.0) -> HullForm:
    return HullForm(np.array([0.0, length]), np.array([breadth, breadth]), draft)


def _exact_moment_integral(x, f):
    """int x f dx, exact for f linear between nodes."""
    h = np.diff(x)
    return float(np.sum(h * (x[:-1] * (2 * f[:-1] + f[1:]) + x[1:] * (f[:-1] + 2 * f[1:])) / 6.0))


@pytest.fixture(scope="module")
def base():
    girder = HullGirder(base_hull_form())
    loading = base_vessel_loading()
    return girder, loading, still_water_response(girder, loading)


# ------------------------------------------------------------------ still water: equilibrium
def test_base_still_water_equilibrium(base):
    girder, loading, r = base
    W = loading.total_mass_kg * G
    B = np.trapezoid(r.buoyancy_N_per_m, r.x_m)  # buoyancy is linear between nodes: exact
    assert abs(B - W) / W < 1e-6
    lcb = _exact_moment_integral(r.x_m, r.buoyancy_N_per_m) / B
    assert lcb == pytest.approx(loading.lcg_m, abs=1e-6 * girder.length_m)
    # designed to float at even keel on the design draught
    assert abs(r.sinkage_m) < 1e-4 and abs(r.trim_rad) < 1e-6
    mmax = np.abs(r.bending_moment_Nm).max()
    assert abs(r.shear_force_N[-1]) < 1e-9 * W
    assert abs(r.bending_moment_Nm[0]) == 0.0 and abs(r.bending_moment_Nm[-1]) < 1e-9 * mmax
    assert r.deflection_m[0] == 0.0 and r.deflection_m[-1] == 0.0


def test_trim_and_sinkage_solved_for_unbalanced_loading():
    hull = _box(100.0, 20.0, 5.0)
    disp = RHO * 100 * 20 * 5
    # 5 % heavier than design displacement, LCG 2 m forward of midship
    ld = VesselLoading(None, (WeightItem("w1", 0, 100, 0.9 * disp), WeightItem("w2", 47, 61, 0.15 * disp)))
    r = still_water_response(HullGirder(hull), ld)
    B = np.trapezoid(r.buoyancy_N_per_m, r.x_m)
    assert B == pytest.approx(ld.total_mass_kg * G, rel=1e-9)
    assert _exact_moment_integral(r.x_m, r.buoyancy_N_per_m) / B == pytest.approx(ld.lcg_m, abs=1e-9 * 100)
    assert r.sinkage_m == pytest.approx(0.05 * 5.0, rel=1e-9)
    assert r.trim_rad < 0  # weight forward -> bow down (trim positive = bow up)
    # box: LCB shift = -trim L^2 / (12 d)
    assert -r.trim_rad * 100**2 / (12 * 5.25) == pytest.approx(ld.lcg_m - 50.0, rel=1e-9)


def test_prismatic_barge_uniform_weight_has_no_bending():
    hull = _box()
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


# ------------------------------------------------------------------ closed-form beam checks
@pytest.mark.parametrize("shear_area", [np.inf, 0.3])
def test_box_barge_concentrated_weight_closed_form(shear_area):
    Lb, Bb, T = 100.0, 20.0, 5.0
    hull = _box(Lb, Bb, T)
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


# ------------------------------------------------------------------ calibration
def test_base_case_calibration_deck_rise(base):
    girder, _, r = base
    rise = deck_rise_m(r, 85.5, 22.2)  # at the cargo midpoint over the outer saddles
    assert rise == pytest.approx(5.75e-3, rel=0.02)
    i = int(np.argmin(np.abs(r.x_m - 85.5)))
    assert r.bending_moment_Nm[i] == pytest.approx(BASE_STILL_WATER_MOMENT_NM, rel=1e-6)
    # hull hogging curvature over the cargo region ~ 2.3e-5 1/m (bending part)
    curv = -r.bending_moment_Nm[i] / girder.bending_stiffness_Nm2
    assert 1.5e-5 < curv < 3.0e-5


def test_deck_deflection_at_interpolates_nodes(base):
    _, _, r = base
    z, s = deck_deflection_at(r, r.x_m[10:20])
    np.testing.assert_allclose(z, r.deflection_m[10:20], rtol=0, atol=1e-15)
    np.testing.assert_allclose(s, r.slope_rad[10:20], rtol=0, atol=1e-15)
    # between nodes: smooth and consistent with finite differences of itself
    xq = np.array([60.123, 85.5, 107.7])
    z0, s0 = deck_deflection_at(r, xq)
    eps = 1e-4
    zp, _ = deck_deflection_at(r, xq + eps)
    zm, _ = deck_deflection_at(r, xq - eps)
    np.testing.assert_allclose((zp - zm) / (2 * eps), s0, rtol=1e-5)
    zs, _ = deck_deflection_at(r, 85.5)
    assert np.ndim(zs) == 0 and zs == pytest.approx(z0[1])


# ------------------------------------------------------------------ wave
def test_wave_box_barge_closed_form_crest_and_trough():
    Lb, Bb, T = 100.0, 20.0, 5.0
    hull = _box(Lb, Bb, T)
    disp = RHO * Lb * Bb * T
    ld = VesselLoading(None, (WeightItem("uniform", 0, Lb, disp),))
    a = 1.5
    w = wave_response(HullGirder(hull), ld, wave_length_m=Lb, wave_amplitude_m=a, n_steps=64, n_points=401)
    i = int(np.argmin(np.abs(w.x_m - 50.0)))
    m_exact = RHO * G * Bb * a * Lb**2 / (2 * np.pi**2)
    # crest amidships (s = 0): hogging (negative), trough amidships (s = 0.5): sagging
    assert w.bending_moment_Nm[0, i] == pytest.approx(-m_exact, rel=1e-4)
    assert w.bending_moment_Nm[32, i] == pytest.approx(+m_exact, rel=1e-4)
    assert w.deflection_m[0, i] > 0 > w.deflection_m[32, i]
    assert w.frequency_rad_s == pytest.approx(np.sqrt(2 * np.pi * G / Lb))
    # waves travel from bow to stern: a quarter period later the crest sits L/4 aft of midship,
    # lifting the stern: bow-down trim (trim positive = bow up) of -12 a / (k L^2) on a box
    k = 2 * np.pi / Lb
    assert w.trim_rad[16] == pytest.approx(-12 * a / (k * Lb**2), rel=1e-4)
    assert w.trim_rad[48] == pytest.approx(+12 * a / (k * Lb**2), rel=1e-4)
    assert np.abs(w.sinkage_m).max() < 1e-6 * a


def test_a_wave_the_hull_cannot_float_on_is_a_clear_error(base):
    """A 300 m wave amplitude (millimetres typed for metres): the hull leaves the water and the wall-sided
    balance has no answer. A typed error (a ValueError: the command line's exit 2) naming the wave and the
    draught, not an internal RuntimeError."""
    girder, loading, _ = base
    with pytest.raises(HydrostaticBalanceError, match=r"wave surface of up to 300 m against the draught"):
        wave_response(girder, loading, 171.0, 300.0)
    assert issubclass(HydrostaticBalanceError, ValueError)


def test_wave_response_linear_in_amplitude(base):
    girder, loading, _ = base
    w1 = wave_response(girder, loading, 171.0, 0.5)
    w2 = wave_response(girder, loading, 171.0, 1.0)
    np.testing.assert_allclose(w2.bending_moment_Nm, 2 * w1.bending_moment_Nm, rtol=0, atol=1e-9 * np.abs(w2.bending_moment_Nm).max())
    np.testing.assert_allclose(w2.deflection_m, 2 * w1.deflection_m, rtol=0, atol=1e-9 * np.abs(w2.deflection_m).max())
    # linear -> purely first harmonic
    assert np.abs(w2.deflection_harmonics_m[[0, 2, 3]]).max() < 1e-9 * np.abs(w2.deflection_harmonics_m[1]).max()


def test_wave_base_case_hogging_at_crest_and_iacs_magnitude(base):
    girder, loading, _ = base
    w = wave_response(girder, loading, 171.0, 3.0)
    i = int(np.argmin(np.abs(w.x_m - 85.5)))
    assert w.bending_moment_Nm[0, i] < 0  # crest amidships: hogging
    assert w.bending_moment_Nm[32, i] > 0  # trough amidships: sagging
    cb = 32000.0 / (171 * 42 * 6.5)
    hog, sag = iacs_wave_bending_moments_Nm(171.0, 42.0, cb)
    m_amp = np.abs(w.bending_moment_harmonics_Nm[1]).max()
    ratio = m_amp / (0.5 * (hog - sag))
    assert 0.2 < ratio < 5, f"wave bending moment amplitude {m_amp:.3e} N m; IACS UR S11 mean |M_w| {0.5 * (hog - sag):.3e} N m"


def test_harmonics_reconstruct_time_series(base):
    girder, loading, _ = base
    w = wave_response(girder, loading, 150.0, 3.0, n_steps=64, n_harmonics=31)
    s = w.period_fraction
    k = np.arange(w.deflection_harmonics_m.shape[0])
    e = np.exp(1j * 2 * np.pi * np.outer(s, k))
    for series, harm in (
        (w.deflection_m, w.deflection_harmonics_m),
        (w.bending_moment_Nm, w.bending_moment_harmonics_Nm),
        (w.slope_rad, w.slope_harmonics_rad),
    ):
        rec = np.real(e @ harm)
        # the Nyquist term (k = 32) is not in the set; it is negligible here
        assert np.abs(rec - series).max() < 1e-6 * np.abs(series).max()
        assert np.all(harm[0].imag == 0)
    # the first harmonic alone captures the response (linear hull)
    rec1 = np.real(np.outer(np.exp(1j * 2 * np.pi * s), w.deflection_harmonics_m[1]))
    assert np.abs(rec1 - w.deflection_m).max() < 1e-3 * np.abs(w.deflection_m).max()
    # deck harmonics interpolate consistently with the time series
    zk, sk = deck_harmonics_at(w, np.array([63.3, 85.5, 107.7]))
    zt, st = deck_deflection_at(w, np.array([63.3, 85.5, 107.7]))
    assert zk.shape == (32, 3) and zt.shape == (64, 3)
    np.testing.assert_allclose(np.real(e @ zk), zt, rtol=0, atol=1e-6 * np.abs(zt).max())
    np.testing.assert_allclose(np.real(e @ sk), st, rtol=0, atol=1e-6 * np.abs(st).max())


def test_iacs_formula():
    assert iacs_wave_coefficient(171.0) == pytest.approx(10.75 - 1.29**1.5)
    hog, sag = iacs_wave_bending_moments_Nm(171.0, 42.0, 0.686)
    cw = 10.75 - 1.29**1.5
    assert hog == pytest.approx(190 * cw * 171**2 * 42 * 0.686, rel=1e-12)
    assert sag == pytest.approx(-110 * cw * 171**2 * 42 * (0.686 + 0.7), rel=1e-12)
    assert hog > 0 > sag


def test_deck_load_influence_equals_hull_solutions_with_the_loads_added(base):
    """The vectorised compliance (all probe loads in one set of solves) against one full
    still-water solution per load (the hull model is linear while no section emerges)."""
    girder, loading, still = base
    start = np.array([60.0, 84.5, 110.0])
    end = start + 1.0
    targets = 0.5 * (start + end)
    z, s = deck_load_influence(girder, loading, start, end, targets)
    z0, s0 = deck_deflection_at(still, targets)
    for j in range(start.size):
        probe = WeightItem(f"probe {j}", start[j], end[j], 2.0e6 / G)
        zj, sj = deck_deflection_at(still_water_response(girder, loading.with_items(probe)), targets)
        np.testing.assert_allclose(z[:, j], (zj - z0) / 2.0e6, rtol=1e-5, atol=1e-16)
        np.testing.assert_allclose(s[:, j], (sj - s0) / 2.0e6, rtol=1e-4, atol=1e-17)
    assert z[1, 1] < 0.0  # a load pushes the deck under it down (relative to its neighbours)
    assert z[1, 1] < z[0, 1] and z[1, 1] < z[2, 1]
    with pytest.raises(ValueError, match="load_end_m > load_start_m"):
        deck_load_influence(girder, loading, end, start, targets)


def test_patch_load_response_equals_hull_solutions_with_the_loads_added(base):
    """The lines along the ship for extra patch loads (vectorised over load sets, evaluated
    between nodes) against one full still-water solution per load set with the loads added as
    weight items; a load set that is twice another gives twice the response (linear hull)."""
    girder, loading, still = base
    start = np.array([60.0, 84.5, 110.0])
    end = start + np.array([1.0, 0.5, 2.0])
    loads = np.array([[2.0e6, 5.0e6, 1.0e6], [4.0e6, 10.0e6, 2.0e6], [0.0, 3.0e6, 0.0]])
    x = np.linspace(0.3, girder.length_m - 0.3, 97)  # between the hull's nodes
    r = patch_load_response(girder, loading, start, end, loads.reshape(3, 1, 3), x)
    assert r.bending_moment_Nm.shape == (3, 1, x.size) and r.sinkage_m.shape == (3, 1)
    for j in range(3):
        items = [WeightItem(f"probe {i}", start[i], end[i], loads[j, i] / G) for i in range(3) if loads[j, i] > 0]
        fresh = still_water_response(girder, loading.with_items(*items))
        z, s = deck_deflection_at(fresh, x)
        z0, s0 = deck_deflection_at(still, x)
        # M is cubic per element with M' = V: its Hermite spline is exact, and so is its derivative
        m_fresh = CubicHermiteSpline(fresh.x_m, fresh.bending_moment_Nm, fresh.shear_force_N)
        m_still = CubicHermiteSpline(still.x_m, still.bending_moment_Nm, still.shear_force_N)
        moment, shear = m_fresh(x) - m_still(x), m_fresh(x, 1) - m_still(x, 1)
        assert np.abs(moment).max() > 1e7
        np.testing.assert_allclose(r.bending_moment_Nm[j, 0], moment, rtol=0, atol=1e-6 * np.abs(moment).max())
        np.testing.assert_allclose(r.shear_force_N[j, 0], shear, rtol=0, atol=1e-6 * np.abs(shear).max())
        np.testing.assert_allclose(r.deflection_m[j, 0], z - z0, rtol=0, atol=1e-6 * np.abs(z - z0).max())
        np.testing.assert_allclose(r.slope_rad[j, 0], s - s0, rtol=0, atol=1e-5 * np.abs(s - s0).max())
        assert r.sinkage_m[j, 0] == pytest.approx(fresh.sinkage_m - still.sinkage_m, rel=1e-6)
    np.testing.assert_allclose(r.bending_moment_Nm[1], 2.0 * r.bending_moment_Nm[0], rtol=1e-9, atol=1.0)
    with pytest.raises(ValueError, match="one per patch"):
        patch_load_response(girder, loading, start, end, loads[:, :2], x)


def test_end_resultants_equal_the_ends_of_the_running_integrals():
    # the balance's residual (net force and moment) by weighted sums, vs integrating V and M along the hull
    from seafast.excitation.hull_girder import _end_resultants, _shear_moment

    rng = np.random.default_rng(3)
    h = rng.uniform(0.1, 1.0, 340)
    qa, qb = rng.normal(size=(2, 65, 340)) * 1e5
    V, M = _shear_moment(h, qa, qb)
    ends = _end_resultants(h, qa, qb)
    np.testing.assert_allclose(ends[..., 0], V[..., -1], rtol=0, atol=1e-13 * np.max(np.abs(V)))
    np.testing.assert_allclose(ends[..., 1], M[..., -1], rtol=0, atol=1e-13 * np.max(np.abs(M)))
