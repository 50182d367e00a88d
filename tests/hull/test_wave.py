"""Tests of the quasi-static regular-wave hull response (seafast.hull.wave): a box barge's closed form,
linearity in the amplitude, the base case's hogging at a crest and the harmonics."""

from __future__ import annotations

import numpy as np
import pytest

from hull_cases import RHO, G, box_hull
from seafast.hull.deck import deck_deflection_at, deck_harmonics_at
from seafast.hull.girder import HullGirder
from seafast.hull.rules import iacs_wave_bending_moments_Nm
from seafast.hull.wave import wave_response
from seafast.vessel.loading import VesselLoading, WeightItem


def test_wave_box_barge_closed_form_crest_and_trough():
    Lb, Bb, T = 100.0, 20.0, 5.0
    hull = box_hull(Lb, Bb, T)
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
