"""Extra loads on the hull girder: deck-load influence and the response to patch loads.

Both re-balance the still-water ship for every load, all at once on one grid that has every
patch edge as a node: :func:`deck_load_influence` gives the deck deflection and slope at some
points per newton on each patch (the hull's compliance, for the two-way coupling);
:func:`patch_load_response` the change of every line along the ship for given loads.
Conventions: :mod:`seafast.hull`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray
from scipy.interpolate import CubicHermiteSpline

from seafast.hull.balance import hydrostatic_balance
from seafast.hull.girder import HullBeam, HullGirder, shear_moment
from seafast.hull.grid import WeightSource, hull_grid, loading_breakpoints, weight_element_ends

__all__ = ["deck_load_influence", "HullLoadResponse", "patch_load_response"]

FloatArray = NDArray[np.float64]


def _patches(
    girder: HullGirder, loading: WeightSource, load_start_m: FloatArray, load_end_m: FloatArray, n_points: int
) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray, NDArray[np.bool_]]:
    """Patch edges, a grid with every edge as a node, its weight ends and the patch of each element."""
    start = np.asarray(load_start_m, dtype=float).ravel()
    end = np.asarray(load_end_m, dtype=float).ravel()
    if start.size != end.size or np.any(end <= start):
        raise ValueError("hull girder: every load patch needs load_end_m > load_start_m")
    bp = tuple(loading_breakpoints(girder, loading)) + tuple(start) + tuple(end)
    x = hull_grid(girder, bp, n_points)
    wa, wb = weight_element_ends(girder, loading, x)
    mid = 0.5 * (x[:-1] + x[1:])
    inside = (mid[None, :] > start[:, None]) & (mid[None, :] < end[:, None])  # (n_loads, n_el)
    return start, end, x, np.vstack([wa, wb]), inside


def _solve_with_extra(girder: HullGirder, x: FloatArray, w_ends: FloatArray, extra: NDArray) -> tuple[NDArray, ...]:
    """The still-water state (row 0) and one per row of ``extra`` [N/m per element], re-balanced.

    Returns sinkage, trim, qa, qb, V, M, z, slope with a leading axis of 1 + len(extra).
    """
    wa, wb = w_ends
    wa_all = np.vstack([wa[None, :], wa[None, :] + extra])
    wb_all = np.vstack([wb[None, :], wb[None, :] + extra])
    zeta = np.zeros((wa_all.shape[0], x.size))
    s, tr, _, qa, qb = hydrostatic_balance(girder, x, wa_all, wb_all, zeta)
    V, M = shear_moment(np.diff(x), qa, qb)
    z, slope = HullBeam.build(x, girder).solve(qa, qb, V)
    return s, tr, qa, qb, V, M, z, slope


def deck_load_influence(
    girder: HullGirder,
    loading: WeightSource,
    load_start_m: FloatArray,
    load_end_m: FloatArray,
    target_x_m: FloatArray,
    n_points: int = 343,
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Deck deflection and slope at ``target_x_m`` per newton of extra downward load on patches.

    Each load j is 1 N spread uniformly over ``[load_start_m[j], load_end_m[j]]``; the ship is
    re-balanced in sinkage and trim for every load, all at once (vectorised still-water solves
    on one grid that has every patch edge as a node). While no section emerges the hull
    model is linear, so the result is exact and independent of the probe size.

    Returns
    -------
    deflection_m_per_N, slope_rad_per_N
        Shape (n_targets, n_loads): response at target i to load j, relative to the still-water
        state of ``loading`` (chord through AP and FP, as :func:`~seafast.hull.still_water.still_water_response`).
    """
    start, end, x, w_ends, inside = _patches(girder, loading, load_start_m, load_end_m, n_points)
    probe_N = 1.0e6  # numerically comfortable against the ship's ~3e8 N weight; exact by linearity
    extra = probe_N / (end - start)[:, None] * inside
    *_, z, slope = _solve_with_extra(girder, x, w_ends, extra)
    spl = CubicHermiteSpline(x, z.T, slope.T, axis=0)
    xt = np.asarray(target_x_m, dtype=float).ravel()
    zt, st = spl(xt), spl(xt, 1)  # (n_targets, 1 + n_loads)
    return (zt[:, 1:] - zt[:, :1]) / probe_N, (st[:, 1:] - st[:, :1]) / probe_N


@dataclass(frozen=True)
class HullLoadResponse:
    """Change of the still-water hull-girder response caused by extra loads (the ship re-balanced).

    Returned by :func:`patch_load_response`; every line has the shape of the load sets' leading
    axes + (n_x,), and is the loaded state minus the still-water state of the same loading, in
    the conventions of :class:`~seafast.hull.still_water.HullGirderResponse` (deflection up +, chord through AP and FP;
    ``V = dM/dx``; sagging moment +).

    Attributes
    ----------
    x_m
        Where the lines are evaluated, from the AP [m], shape (n_x,).
    deflection_m, slope_rad, shear_force_N, bending_moment_Nm
        Changes of deflection [m], slope dz/dx [rad], shear force [N] and bending moment [N m].
    sinkage_m, trim_rad
        Changes of sinkage [m] (deeper +) and trim [rad] (bow up +), shape of the leading axes.
    """

    x_m: FloatArray
    deflection_m: FloatArray
    slope_rad: FloatArray
    shear_force_N: FloatArray
    bending_moment_Nm: FloatArray
    sinkage_m: FloatArray
    trim_rad: FloatArray


def patch_load_response(
    girder: HullGirder,
    loading: WeightSource,
    load_start_m: FloatArray,
    load_end_m: FloatArray,
    load_N: NDArray,
    x_m: FloatArray,
    n_points: int = 343,
) -> HullLoadResponse:
    """The hull girder's response along the ship to extra downward loads on patches.

    Load set ``load_N[..., j]`` [N, downward +] puts ``load_N[..., j]`` spread uniformly over
    ``[load_start_m[j], load_end_m[j]]`` on the still-water ship of ``loading``, which is
    re-balanced in sinkage and trim (the same vectorised solves as :func:`deck_load_influence`;
    negative loads lift). The lines are evaluated at ``x_m`` exactly for the grid's piecewise
    linear load (shear force quadratic and bending moment cubic within each element), the
    deflection and slope by the C1 Hermite interpolant of :func:`~seafast.hull.deck.deck_deflection_at`.

    Parameters
    ----------
    girder, loading
        As for :func:`~seafast.hull.still_water.still_water_response`.
    load_start_m, load_end_m
        Patch ends from the AP [m], shape (n_loads,), ``load_end_m > load_start_m``.
    load_N
        Total load on each patch [N], shape (..., n_loads): one load set per leading index.
    x_m
        Where to evaluate the lines, from the AP [m], within the hull.

    Returns
    -------
    HullLoadResponse
        The loaded minus the still-water response, per load set.
    """
    start, end, x, w_ends, inside = _patches(girder, loading, load_start_m, load_end_m, n_points)
    loads = np.asarray(load_N, dtype=float)
    if loads.shape[-1:] != start.shape or not np.all(np.isfinite(loads)):
        raise ValueError(f"patch_load_response: load_N must be finite with a last axis of {start.size} (one per patch)")
    lead = loads.shape[:-1]
    extra = (loads.reshape(-1, start.size) / (end - start)) @ inside.astype(float)
    s, tr, qa, qb, V, M, z, slope = _solve_with_extra(girder, x, w_ends, extra)
    xt = np.asarray(x_m, dtype=float).ravel()
    i = np.clip(np.searchsorted(x, xt, side="right") - 1, 0, x.size - 2)
    d = xt - x[i]
    h = x[i + 1] - x[i]
    dq = qb[:, i] - qa[:, i]
    Vt = V[:, i] + qa[:, i] * d + dq * d * d / (2.0 * h)
    Mt = M[:, i] + V[:, i] * d + qa[:, i] * d * d / 2.0 + dq * d**3 / (6.0 * h)
    spl = CubicHermiteSpline(x, z.T, slope.T, axis=0)
    zt, st = spl(xt).T, spl(xt, 1).T

    def change(a: NDArray) -> NDArray:
        return (a[1:] - a[:1]).reshape(lead + a.shape[1:])

    return HullLoadResponse(xt, change(zt), change(st), change(Vt), change(Mt), change(s), change(tr))
