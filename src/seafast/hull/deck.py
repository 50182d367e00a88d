"""Sampling the hull-girder response on deck: deflection, slope and their harmonics at given x, deck rise.

C1 cubic Hermite interpolants through the nodal deflections and slopes of the Timoshenko
solution, so values between nodes are consistent with the FE result. Conventions:
:mod:`seafast.hull`.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray
from scipy.interpolate import CubicHermiteSpline

from seafast.hull.still_water import HullGirderResponse
from seafast.hull.wave import WaveHullResponse

__all__ = ["deck_deflection_at", "deck_harmonics_at", "deck_rise_m"]

FloatArray = NDArray[np.float64]


def deck_deflection_at(response: HullGirderResponse | WaveHullResponse, x_m: FloatArray | float) -> tuple[NDArray, NDArray]:
    """Deck deflection [m] and slope dz/dx [rad] at ``x_m`` by cubic Hermite interpolation.

    The interpolant uses the nodal deflections and the nodal slopes of the Timoshenko
    solution, so it is C1 and consistent with the FE result. For a
    :class:`~seafast.hull.wave.WaveHullResponse` the wave-induced time series is interpolated: the outputs have
    shape (n_t,) + shape(x_m).
    """
    xq = np.asarray(x_m, dtype=float)
    x = response.x_m
    if isinstance(response, WaveHullResponse):
        spl = CubicHermiteSpline(x, response.deflection_m.T, response.slope_rad.T, axis=0)
        z = np.moveaxis(spl(xq), -1, 0) if xq.ndim else spl(xq)
        sl = np.moveaxis(spl(xq, 1), -1, 0) if xq.ndim else spl(xq, 1)
        return np.asarray(z), np.asarray(sl)
    spl = CubicHermiteSpline(x, response.deflection_m, response.slope_rad)
    return np.asarray(spl(xq)), np.asarray(spl(xq, 1))


def deck_harmonics_at(response: WaveHullResponse, x_m: FloatArray | float) -> tuple[NDArray[np.complex128], NDArray[np.complex128]]:
    """Complex harmonics of the wave-induced deck deflection [m] and slope [rad] at ``x_m``.

    Returns arrays of shape (n_harmonics + 1,) + shape(x_m) in the convention
    ``w(t) = Re(sum_k W_k exp(i k omega t))``; ``abs(W_1)`` and ``angle(W_1)`` are the
    ``wave_amplitude_m`` and ``wave_phase_rad`` of a deck deflection table.
    """
    xq = np.asarray(x_m, dtype=float)
    x = response.x_m
    out_z = []
    out_s = []
    for part in (np.real, np.imag):
        spl = CubicHermiteSpline(x, part(response.deflection_harmonics_m).T, part(response.slope_harmonics_rad).T, axis=0)
        zz = spl(xq)
        ss = spl(xq, 1)
        out_z.append(np.moveaxis(zz, -1, 0) if xq.ndim else zz)
        out_s.append(np.moveaxis(ss, -1, 0) if xq.ndim else ss)
    return out_z[0] + 1j * out_z[1], out_s[0] + 1j * out_s[1]


def deck_rise_m(response: HullGirderResponse, centre_x_m: float, half_span_m: float) -> float:
    """Deck rise [m] at ``centre_x_m`` above the mean of the deck at ``centre_x_m +/- half_span_m``.

    The one non-rigid combination of three deck points: positive when the hull hogs between
    them (the middle saddle of a three-saddle cargo is then the most loaded).
    """
    z, _ = deck_deflection_at(response, np.array([centre_x_m - half_span_m, centre_x_m, centre_x_m + half_span_m]))
    return float(z[1] - 0.5 * (z[0] + z[2]))
