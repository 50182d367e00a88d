"""Tests of the hull-girder transfer functions (seafast.hull.transfer): a box barge's closed forms and the
first harmonic of the regular-wave response per metre of amplitude."""

from __future__ import annotations

import numpy as np
import pytest

from hull_cases import RHO, G, box_hull
from seafast.hull.deck import deck_harmonics_at
from seafast.hull.girder import HullGirder
from seafast.hull.transfer import wave_transfer_functions
from seafast.hull.wave import wave_response
from seafast.vessel.loading import VesselLoading, WeightItem

L, B, T = 100.0, 20.0, 5.0


@pytest.fixture(scope="module")
def barge():
    """A box barge with its displacement spread uniformly, and its transfer functions at three wave lengths."""
    girder = HullGirder(box_hull(L, B, T))
    loading = VesselLoading(None, (WeightItem("uniform", 0.0, L, RHO * L * B * T),))
    lengths = np.array([0.7 * L, L, 2.0 * L])
    omega = np.sqrt(2 * np.pi * G / lengths)
    return girder, loading, lengths, wave_transfer_functions(girder, loading, omega, n_points=401)


def test_a_box_barge_on_a_wave_of_its_length_hogs_at_the_crest_by_the_closed_form(barge):
    """Crest amidships at t = 0: the moment amidships is ``-rho g B L^2 / (2 pi^2)`` per metre of wave, real
    (in phase with the crest), and the ends emerge first, at ``T`` over the largest local draught change
    ``|exp(i k u) - i 12 u / (k L^2)|`` (u = x - L/2; the box's trim ``12 zeta_a / (k L^2)`` a quarter
    period after the crest)."""
    _, _, _, tf = barge
    mid = int(np.argmin(np.abs(tf.x_m - 0.5 * L)))
    moment = tf.bending_moment_Nm_per_m[1, mid]
    exact = RHO * G * B * L**2 / (2 * np.pi**2)
    assert moment.real == pytest.approx(-exact, rel=1e-4)
    assert abs(moment.imag) < 1e-9 * exact
    k = 2 * np.pi / L
    u = tf.x_m - 0.5 * L
    change = np.abs(np.exp(1j * k * u) - 1j * 12 * u / (k * L**2))
    assert tf.emergence_amplitude_m[1] == pytest.approx(T / np.max(change), rel=1e-4)
    assert np.all(tf.emergence_amplitude_m > 0.5 * T)


def test_the_transfer_functions_are_the_first_harmonic_of_the_wave_response_per_metre(barge):
    girder, loading, lengths, tf = barge
    xq = np.array([12.5, 50.0, 81.3])
    for i, wave_length in enumerate(lengths):
        amplitude = 0.5 * float(tf.emergence_amplitude_m[i])  # well inside the linear range
        r = wave_response(girder, loading, float(wave_length), amplitude, n_points=401)
        assert np.array_equal(r.x_m, tf.x_m) and r.frequency_rad_s == pytest.approx(tf.omega_rad_s[i], rel=1e-15)
        for harmonic, transfer in (
            (r.deflection_harmonics_m[1], tf.deflection_m_per_m[i]),
            (r.slope_harmonics_rad[1], tf.slope_rad_per_m[i]),
            (r.bending_moment_harmonics_Nm[1], tf.bending_moment_Nm_per_m[i]),
        ):
            np.testing.assert_allclose(harmonic / amplitude, transfer, rtol=0, atol=1e-9 * np.max(np.abs(transfer)))
        z, s = deck_harmonics_at(r, xq)
        z_tf, s_tf = tf.deck_at(xq)
        np.testing.assert_allclose(z[1] / amplitude, z_tf[i], rtol=0, atol=1e-9 * np.max(np.abs(z_tf[i])))
        np.testing.assert_allclose(s[1] / amplitude, s_tf[i], rtol=0, atol=1e-9 * np.max(np.abs(s_tf[i])))


def test_frequencies_must_be_positive_and_finite(barge):
    girder, loading, _, _ = barge
    for bad in (np.array([0.5, 0.0]), np.array([np.nan]), np.array([-1.0])):
        with pytest.raises(ValueError, match="omega_rad_s must be finite and > 0"):
            wave_transfer_functions(girder, loading, bad)
