"""Tests of deck sampling (seafast.hull.deck): the base case's calibrated deck rise and the Hermite
interpolation of the nodal deflections and slopes."""

from __future__ import annotations

import numpy as np
import pytest

from seafast.hull.deck import deck_deflection_at, deck_rise_m
from seafast.vessel.loading import BASE_STILL_WATER_MOMENT_NM


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
