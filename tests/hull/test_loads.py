"""Tests of extra loads on the hull girder (seafast.hull.loads): deck-load influence and patch loads against
one full still-water solution per load."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.interpolate import CubicHermiteSpline

from hull_cases import G
from seafast.hull.deck import deck_deflection_at
from seafast.hull.loads import deck_load_influence, patch_load_response
from seafast.hull.still_water import still_water_response
from seafast.vessel.loading import WeightItem


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
