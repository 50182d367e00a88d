"""Tests of the hydrostatic balance (seafast.hull.balance): sinkage and trim of an unbalanced loading, and
the typed error of a hull that leaves the water."""

from __future__ import annotations

import numpy as np
import pytest

from hull_cases import RHO, G, box_hull, exact_moment_integral
from seafast.hull.balance import HydrostaticBalanceError
from seafast.hull.girder import HullGirder
from seafast.hull.still_water import still_water_response
from seafast.hull.wave import wave_response
from seafast.vessel.loading import VesselLoading, WeightItem


def test_trim_and_sinkage_solved_for_unbalanced_loading():
    hull = box_hull(100.0, 20.0, 5.0)
    disp = RHO * 100 * 20 * 5
    # 5 % heavier than design displacement, LCG 2 m forward of midship
    ld = VesselLoading(None, (WeightItem("w1", 0, 100, 0.9 * disp), WeightItem("w2", 47, 61, 0.15 * disp)))
    r = still_water_response(HullGirder(hull), ld)
    B = np.trapezoid(r.buoyancy_N_per_m, r.x_m)
    assert B == pytest.approx(ld.total_mass_kg * G, rel=1e-9)
    assert exact_moment_integral(r.x_m, r.buoyancy_N_per_m) / B == pytest.approx(ld.lcg_m, abs=1e-9 * 100)
    assert r.sinkage_m == pytest.approx(0.05 * 5.0, rel=1e-9)
    assert r.trim_rad < 0  # weight forward -> bow down (trim positive = bow up)
    # box: LCB shift = -trim L^2 / (12 d)
    assert -r.trim_rad * 100**2 / (12 * 5.25) == pytest.approx(ld.lcg_m - 50.0, rel=1e-9)


def test_a_wave_the_hull_cannot_float_on_is_a_clear_error(base):
    """A 300 m wave amplitude (millimetres typed for metres): the hull leaves the water and the wall-sided
    balance has no answer. A typed error (a ValueError: the command line's exit 2) naming the wave and the
    draught, not an internal RuntimeError."""
    girder, loading, _ = base
    with pytest.raises(HydrostaticBalanceError, match=r"wave surface of up to 300 m against the draught"):
        wave_response(girder, loading, 171.0, 300.0)
    assert issubclass(HydrostaticBalanceError, ValueError)
