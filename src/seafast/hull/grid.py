"""The hull girder's discretisation: the node grid and the weight on its elements.

Nodes at a uniform spacing plus every break point of the hull form and the loading
(:func:`hull_grid`); within each element the weight is linear between its end values
(:func:`weight_element_ends`, one-sided limits, so the discontinuities of the weight at item ends
are exact). Conventions: :mod:`seafast.hull`.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from numpy.typing import NDArray

from seafast.hull.girder import HullGirder
from seafast.vessel.loading import VesselLoading, weight_distribution_N_per_m

__all__ = ["WeightSource", "hull_grid", "weight_element_ends", "loading_breakpoints", "nodal_weight"]

FloatArray = NDArray[np.float64]
WeightSource = VesselLoading | Callable[[FloatArray], FloatArray]
"""The ship's weight: a :class:`~seafast.vessel.loading.VesselLoading`, or a callable ``x_m -> weight [N/m]``
(downward positive)."""


def hull_grid(girder: HullGirder, breakpoints: tuple[float, ...], n_points: int) -> FloatArray:
    """Node positions: uniform spacing plus all break points (nearby uniform nodes dropped)."""
    x0 = float(girder.hull.station_x_m[0])
    x1 = float(girder.hull.station_x_m[-1])
    if n_points < 3:
        raise ValueError(f"hull girder: n_points = {n_points}; must be >= 3")
    base = np.linspace(x0, x1, n_points)
    h = (x1 - x0) / (n_points - 1)
    tol = 1e-9 * (x1 - x0)
    bp = np.array(sorted({x0, x1, *girder.hull.station_x_m, *breakpoints}))
    bp = bp[(bp >= x0 - tol) & (bp <= x1 + tol)]
    bp = np.clip(bp, x0, x1)
    keep = np.ones(base.size, bool)
    for p in bp:
        keep &= np.abs(base - p) > 0.3 * h
    x = np.unique(np.concatenate([base[keep], bp]))
    # merge nodes closer than tol (round-off duplicates)
    x = x[np.concatenate([[True], np.diff(x) > tol])]
    return x


def weight_element_ends(girder: HullGirder, loading: WeightSource, x: FloatArray) -> tuple[FloatArray, FloatArray]:
    """Weight per metre at the start and end of each element (one-sided limits) [N/m]."""
    fun: Callable[[FloatArray], FloatArray]
    if isinstance(loading, VesselLoading):
        vessel_loading = loading

        def from_loading(xx: FloatArray) -> FloatArray:
            return weight_distribution_N_per_m(xx, vessel_loading, girder.gravity_m_per_s2)

        fun = from_loading
    elif callable(loading):
        fun = loading
    else:
        raise TypeError("hull girder: loading must be a VesselLoading or a callable x_m -> weight_N_per_m")
    h = np.diff(x)
    x25 = x[:-1] + 0.25 * h
    x75 = x[:-1] + 0.75 * h
    w25 = np.asarray(fun(x25), dtype=float)
    w75 = np.asarray(fun(x75), dtype=float)
    # exact for a load linear inside each element
    wa = 1.5 * w25 - 0.5 * w75
    wb = 1.5 * w75 - 0.5 * w25
    return wa, wb


def loading_breakpoints(girder: HullGirder, loading: WeightSource) -> tuple[float, ...]:
    """Break points of the weight distribution [m from the AP] (none for a callable), after checking
    that every weight item lies on the hull.

    Raises
    ------
    ValueError
        If a weight item of a :class:`~seafast.vessel.loading.VesselLoading` overhangs the hull.
    """
    if not isinstance(loading, VesselLoading):
        return ()
    x0 = float(girder.hull.station_x_m[0])
    x1 = float(girder.hull.station_x_m[-1])
    tol = 1e-9 * (x1 - x0)
    for it in loading.items:
        if it.x_start_m < x0 - tol or it.x_end_m > x1 + tol:
            raise ValueError(
                f"hull girder: weight item {it.name!r} [{it.x_start_m:.2f}, {it.x_end_m:.2f}] m extends beyond "
                f"the hull [{x0:.2f}, {x1:.2f}] m; overhanging weights are not modelled"
            )
    return loading.breakpoints_m


def nodal_weight(wa: FloatArray, wb: FloatArray) -> FloatArray:
    """Nodal weight values: mean of the one-sided limits at interior nodes."""
    w = np.empty(wa.size + 1)
    w[0] = wa[0]
    w[-1] = wb[-1]
    w[1:-1] = 0.5 * (wb[:-1] + wa[1:])
    return w
