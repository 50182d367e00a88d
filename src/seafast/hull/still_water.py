"""The hull girder in still water: balance, shear force, bending moment and deflection.

:func:`still_water_response` solves the ship of a loading on calm water;
:func:`deflection_from_bending_moment` turns a loading computer's still-water moment table
into the deflection of the same Timoshenko hull. Conventions: :mod:`seafast.hull`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray
from scipy.interpolate import CubicSpline

from seafast.hull.balance import hydrostatic_balance
from seafast.hull.girder import HullBeam, HullGirder, shear_moment
from seafast.hull.grid import WeightSource, hull_grid, loading_breakpoints, nodal_weight, weight_element_ends

__all__ = ["HullGirderResponse", "still_water_response", "deflection_from_bending_moment"]

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class HullGirderResponse:
    """Still-water hull-girder response at the nodes ``x_m``.

    Attributes
    ----------
    x_m
        Node positions from the AP [m], shape (n_x,).
    weight_N_per_m
        Weight per metre [N/m] (positive = downward load); at a discontinuity the mean of the
        two sides.
    buoyancy_N_per_m
        Buoyancy per metre [N/m] (upward).
    shear_force_N
        ``V(x) = int_0^x (b - w)`` [N].
    bending_moment_Nm
        Bending moment [N m], sagging positive, hogging negative; zero at AP and FP.
    deflection_m
        Deflection [m], positive up, relative to the chord through AP and FP (zero at both).
    slope_rad
        dz/dx of the deflection line [rad] (Timoshenko: bending rotation plus shear strain).
    sinkage_m
        Parallel sinkage from the design draught [m], positive deeper.
    trim_rad
        Trim angle [rad], positive bow up.
    """

    x_m: FloatArray
    weight_N_per_m: FloatArray
    buoyancy_N_per_m: FloatArray
    shear_force_N: FloatArray
    bending_moment_Nm: FloatArray
    deflection_m: FloatArray
    slope_rad: FloatArray
    sinkage_m: float
    trim_rad: float


def still_water_response(girder: HullGirder, loading: WeightSource, n_points: int = 343) -> HullGirderResponse:
    """Still-water equilibrium, shear force, bending moment and deflection of the hull girder.

    Parameters
    ----------
    girder
        The hull girder.
    loading
        A :class:`~seafast.vessel.loading.VesselLoading`, or a callable ``x_m -> weight [N/m]``
        (downward positive). The total weight should be close to the displacement at the design
        draught (it need not be equal: sinkage and trim are solved).
    n_points
        Number of uniformly spaced nodes (break points of the hull form and the loading are
        added); the default gives 0.5 m elements on a 171 m hull.

    Returns
    -------
    HullGirderResponse
        Buoyancy equals weight and LCB = LCG to round-off; V and M vanish at both ends to
        round-off; the deflection is relative to the chord through AP and FP (see
        :mod:`seafast.hull`), positive up, so a hogging hull shows a positive deflection amidships.
    """
    bp = loading_breakpoints(girder, loading)
    x = hull_grid(girder, bp, n_points)
    wa, wb = weight_element_ends(girder, loading, x)
    s, tr, b, qa, qb = hydrostatic_balance(girder, x, wa, wb, np.zeros(x.size))
    h = np.diff(x)
    V, M = shear_moment(h, qa, qb)
    beam = HullBeam.build(x, girder)
    z, slope = beam.solve(qa, qb, V)
    return HullGirderResponse(
        x_m=x,
        weight_N_per_m=nodal_weight(wa, wb),
        buoyancy_N_per_m=b,
        shear_force_N=V,
        bending_moment_Nm=M,
        deflection_m=z,
        slope_rad=slope,
        sinkage_m=float(s),
        trim_rad=float(tr),
    )


def deflection_from_bending_moment(
    girder: HullGirder,
    x_m: FloatArray,
    bending_moment_Nm: FloatArray,
    shear_force_N: FloatArray | None = None,
) -> tuple[FloatArray, FloatArray]:
    """Hull deflection from a given still-water bending-moment distribution (loading computer).

    Integrates the Timoshenko curvature ``z'' = M / (E I) - V' / (G A_s)`` exactly for a cubic
    spline through the table: ``z = int int M / (EI) - int V / (G A_s)``, then removes the
    chord through the first and last table points (normally AP and FP; the same definiteness
    as :func:`still_water_response`).

    Parameters
    ----------
    girder
        Supplies EI and G A_s (the hull form is not used).
    x_m
        Table positions from the AP [m], strictly increasing, at least 4 points.
    bending_moment_Nm
        Still-water bending moment [N m], sagging positive, hogging negative (note: many
        loading computers print hogging positive; flip the sign of such tables).
    shear_force_N
        Optional shear force [N] in the seafast convention ``V = dM/dx``; if omitted it is the
        derivative of the moment spline and the shear deflection is ``-(M - M(x_0)) / G A_s``.

    Returns
    -------
    deflection_m, slope_rad
        At ``x_m``: deflection [m] (positive up, zero at both ends) and dz/dx [rad].

    Raises
    ------
    ValueError
        On a malformed table, or if ``shear_force_N`` has the opposite sign convention
        (anti-correlated with dM/dx).
    """
    x = np.asarray(x_m, dtype=float)
    M = np.asarray(bending_moment_Nm, dtype=float)
    if x.ndim != 1 or x.shape != M.shape or x.size < 4:
        raise ValueError("deflection_from_bending_moment: x_m and bending_moment_Nm must be 1-D of equal length >= 4")
    if np.any(np.diff(x) <= 0) or not (np.all(np.isfinite(x)) and np.all(np.isfinite(M))):
        raise ValueError("deflection_from_bending_moment: x_m must be strictly increasing and all values finite")
    EI = girder.bending_stiffness_Nm2
    GA = girder.shear_stiffness_N
    spl = CubicSpline(x, M)
    S1 = spl.antiderivative(1)
    S2 = spl.antiderivative(2)
    dMdx = spl.derivative(1)(x)
    if shear_force_N is None:
        V = dMdx
        intV = M - M[0]
    else:
        V = np.asarray(shear_force_N, dtype=float)
        if V.shape != x.shape or not np.all(np.isfinite(V)):
            raise ValueError("deflection_from_bending_moment: shear_force_N must match x_m and be finite")
        if np.dot(V, dMdx) < 0:
            raise ValueError(
                "deflection_from_bending_moment: shear_force_N is anti-correlated with dM/dx; seafast uses V = dM/dx "
                "(flip the sign of the shear-force table)"
            )
        vs = CubicSpline(x, V).antiderivative(1)
        intV = vs(x) - vs(x[0])
    shear_term = 0.0 if np.isinf(GA) else 1.0 / GA
    z = (S2(x) - S2(x[0]) - S1(x[0]) * (x - x[0])) / EI - shear_term * intV
    slope = (S1(x) - S1(x[0])) / EI - shear_term * V
    chord_slope = (z[-1] - z[0]) / (x[-1] - x[0])
    z = z - z[0] - chord_slope * (x - x[0])
    slope = slope - chord_slope
    return z, slope
