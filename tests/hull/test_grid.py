"""Tests of the hull girder's discretisation (seafast.hull.grid): the node grid and the weight on its elements."""

from __future__ import annotations

import numpy as np
import pytest

from hull_cases import G, box_hull
from seafast.hull.girder import HullGirder
from seafast.hull.grid import hull_grid, loading_breakpoints, nodal_weight, weight_element_ends
from seafast.vessel.loading import VesselLoading, WeightItem


def test_every_break_point_is_a_node_and_the_spacing_stays_near_uniform(base):
    girder, loading, _ = base
    breakpoints = loading_breakpoints(girder, loading)
    assert breakpoints == loading.breakpoints_m and len(breakpoints) > 5  # lightship thirds, cargo and tanks
    x = hull_grid(girder, breakpoints, 343)
    x0, x1 = girder.hull.station_x_m[0], girder.hull.station_x_m[-1]
    assert x[0] == x0 and x[-1] == x1
    assert set(breakpoints) | set(girder.hull.station_x_m) <= set(x)
    h = (x1 - x0) / 342
    # a uniform node within 0.3 h of a break point gives way to it
    assert np.all(np.diff(x) > 0) and np.max(np.diff(x)) <= 1.3 * h * (1 + 1e-12)
    assert x.size >= 343


def test_element_weights_are_the_one_sided_limits_of_a_piecewise_linear_load():
    girder = HullGirder(box_hull())
    x = hull_grid(girder, (40.0, 50.0), 21)  # 5 m spacing: 40 and 50 are nodes already
    wa, wb = weight_element_ends(girder, lambda xx: 2.0e4 + 300.0 * xx, x)
    np.testing.assert_allclose(wa, 2.0e4 + 300.0 * x[:-1], rtol=1e-14)
    np.testing.assert_allclose(wb, 2.0e4 + 300.0 * x[1:], rtol=1e-14)
    item = VesselLoading(None, (WeightItem("block", 40.0, 50.0, 1000.0),))
    wa, wb = weight_element_ends(girder, item, x)
    inside = (x[:-1] >= 40.0) & (x[1:] <= 50.0)
    np.testing.assert_allclose(wa, np.where(inside, 100.0 * G, 0.0), rtol=1e-14, atol=0)
    np.testing.assert_allclose(wb, wa, rtol=1e-14, atol=0)
    # at the item's ends a node carries the mean of the two sides
    w = nodal_weight(wa, wb)
    assert w[np.searchsorted(x, 40.0)] == pytest.approx(50.0 * G, rel=1e-14)
    assert w[np.searchsorted(x, 45.0)] == pytest.approx(100.0 * G, rel=1e-14)


def test_a_weight_overhanging_the_hull_is_refused_by_name():
    girder = HullGirder(box_hull())
    overhang = VesselLoading(None, (WeightItem("crane boom", 95.0, 104.0, 5.0e4),))
    with pytest.raises(ValueError, match=r"weight item 'crane boom' \[95.00, 104.00\] m extends beyond the hull \[0.00, 100.00\] m"):
        loading_breakpoints(girder, overhang)
    assert loading_breakpoints(girder, np.zeros_like) == ()
