"""The hull girder on a regular wave at a heading, quasi-static: re-balanced at steps of one period.

:func:`wave_response` gives the wave-induced deflection, bending moment and slope time series and
their harmonics (through :mod:`seafast.fourier`), and the still-water state it is measured from.
The wave at a heading is the breadth-mean wave of :mod:`seafast.hull.oblique`. Conventions: :mod:`seafast.hull`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from seafast.config.schema import HEAD_SEAS_DEG
from seafast.fourier import period_fraction, time_to_harmonics
from seafast.hull.balance import hydrostatic_balance
from seafast.hull.girder import HullBeam, HullGirder, shear_moment
from seafast.hull.grid import WeightSource, hull_grid, loading_breakpoints, nodal_weight, weight_element_ends
from seafast.hull.oblique import along_ship_wave_number_per_m, breadth_factor
from seafast.hull.still_water import HullGirderResponse

__all__ = ["WaveHullResponse", "wave_response", "wave_surfaces"]

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class WaveHullResponse:
    """Quasi-static hull-girder response on a regular wave, wave-induced part.

    Wave (breadth mean, :mod:`seafast.hull.oblique`): ``zeta(x, t) = F(x) zeta_a cos(omega t + k_x (x - L/2))``,
    ``k_x = -k cos(heading)``; in head seas (the default) ``F = 1`` and ``k_x = k``: crest at midship
    at t = 0, travelling from bow to stern. ``deflection_m`` and ``bending_moment_Nm`` are the
    wave-induced parts (total minus still water, ``still_water`` holds the latter).
    Harmonics: ``w(x, t) = Re(sum_k W_k(x) exp(i k omega t))``, k = 0 the (real) mean.

    Attributes
    ----------
    x_m
        Node positions [m], shape (n_x,).
    period_fraction
        s = t / T at the time steps, shape (n_t,), in [0, 1).
    deflection_m, bending_moment_Nm, slope_rad
        Wave-induced deflection [m] (chord-relative), moment [N m] and slope [rad], shape (n_t, n_x).
    deflection_harmonics_m, bending_moment_harmonics_Nm, slope_harmonics_rad
        Complex harmonics, shape (n_harmonics + 1, n_x).
    sinkage_m, trim_rad
        Wave-induced sinkage [m] and trim [rad] time series, shape (n_t,).
    wave_length_m, wave_amplitude_m, frequency_rad_s
        The wave (frequency from deep-water dispersion).
    still_water
        The still-water response of the same loading.
    heading_deg
        Wave heading beta [deg] (180 = head seas, 90 = beam seas, 0 = following seas).
    """

    x_m: FloatArray
    period_fraction: FloatArray
    deflection_m: FloatArray
    bending_moment_Nm: FloatArray
    deflection_harmonics_m: NDArray[np.complex128]
    bending_moment_harmonics_Nm: NDArray[np.complex128]
    slope_rad: FloatArray = field(default_factory=lambda: np.zeros((0, 0)))
    slope_harmonics_rad: NDArray[np.complex128] = field(default_factory=lambda: np.zeros((0, 0), complex))
    sinkage_m: FloatArray = field(default_factory=lambda: np.zeros(0))
    trim_rad: FloatArray = field(default_factory=lambda: np.zeros(0))
    wave_length_m: float = float("nan")
    wave_amplitude_m: float = float("nan")
    frequency_rad_s: float = float("nan")
    still_water: HullGirderResponse | None = None
    heading_deg: float = HEAD_SEAS_DEG


def wave_response(
    girder: HullGirder,
    loading: WeightSource,
    wave_length_m: float,
    wave_amplitude_m: float,
    n_steps: int = 64,
    n_harmonics: int = 5,
    n_points: int = 343,
    *,
    heading_deg: float = HEAD_SEAS_DEG,
) -> WaveHullResponse:
    """Quasi-static hull-girder response on a regular wave at a heading over one period.

    Wave elevation (phase convention relied on by other modules), head seas::

        zeta(x, t) = zeta_a cos(omega t + k (x - L/2)),   k = 2 pi / lambda,

    crest at midship at t = 0, waves travelling from bow to stern; ``omega = sqrt(g k)``
    (deep water); at a heading, the breadth-mean wave of :func:`wave_surfaces` (head seas
    unchanged bit for bit). At each of ``n_steps`` equal steps of the period fraction
    ``s = t / T`` in [0, 1) the ship is re-balanced (sinkage and trim) on the wave surface with
    wall-sided sections (buoyancy to the local wave surface; the Smith effect and dynamics are
    ignored), and the bending moment and chord-relative deflection follow as in still water. The
    wave-induced part (total minus still water) is returned. While no section emerges (local
    draught > 0 everywhere) the response is exactly linear in ``zeta_a`` and purely first-harmonic;
    emergence (very steep waves or light draught) makes it nonlinear, which the Newton balance
    handles (at a heading on the breadth-mean draught, an approximation once a side emerges).

    A crest amidships (t = 0) gives hogging (negative moment, midship deflected up); a trough
    amidships (s = 0.5) gives sagging. Following seas (0 deg) give the head-sea response reversed
    in time (``s -> 1 - s``, complex-conjugate harmonics) for any hull and loading.

    Parameters
    ----------
    girder, loading
        As for :func:`~seafast.hull.still_water.still_water_response`.
    wave_length_m, wave_amplitude_m
        Wave length lambda [m] and amplitude zeta_a [m].
    n_steps
        Time steps per period (> 2 n_harmonics).
    n_harmonics
        Highest harmonic returned.
    n_points
        Uniform nodes along the hull (plus break points).
    heading_deg
        Wave heading beta [deg]: the direction the waves travel, from the ship's x axis towards
        y (port); 180 = head seas (default), 90 = beam seas, 0 = following seas.

    Returns
    -------
    WaveHullResponse
    """
    if not (wave_length_m > 0) or not np.isfinite(wave_amplitude_m):
        raise ValueError("wave_response: wave_length_m must be > 0 and wave_amplitude_m finite")
    if n_steps <= 2 * n_harmonics:
        raise ValueError(f"wave_response: n_steps = {n_steps} must exceed 2 n_harmonics = {2 * n_harmonics}")
    x = hull_grid(girder, loading_breakpoints(girder, loading), n_points)
    wa, wb = weight_element_ends(girder, loading, x)
    sfrac = period_fraction(n_steps)
    zeta = np.vstack([np.zeros((1, x.size)), wave_surfaces(girder, x, sfrac, wave_length_m, wave_amplitude_m, heading_deg)])
    s, tr, b, qa, qb = hydrostatic_balance(girder, x, wa, wb, zeta)
    V, M = shear_moment(np.diff(x), qa, qb)
    z, slope = HullBeam.build(x, girder).solve(qa, qb, V)
    still = HullGirderResponse(
        x_m=x,
        weight_N_per_m=nodal_weight(wa, wb),
        buoyancy_N_per_m=b[0],
        shear_force_N=V[0],
        bending_moment_Nm=M[0],
        deflection_m=z[0],
        slope_rad=slope[0],
        sinkage_m=float(s[0]),
        trim_rad=float(tr[0]),
    )
    zw = z[1:] - z[0]
    Mw = M[1:] - M[0]
    sw = slope[1:] - slope[0]
    return WaveHullResponse(
        x_m=x,
        period_fraction=sfrac,
        deflection_m=zw,
        bending_moment_Nm=Mw,
        deflection_harmonics_m=time_to_harmonics(zw, n_harmonics),
        bending_moment_harmonics_Nm=time_to_harmonics(Mw, n_harmonics),
        slope_rad=sw,
        slope_harmonics_rad=time_to_harmonics(sw, n_harmonics),
        sinkage_m=s[1:] - s[0],
        trim_rad=tr[1:] - tr[0],
        wave_length_m=float(wave_length_m),
        wave_amplitude_m=float(wave_amplitude_m),
        frequency_rad_s=float(np.sqrt(girder.gravity_m_per_s2 * (2.0 * np.pi / wave_length_m))),
        still_water=still,
        heading_deg=float(heading_deg),
    )


def wave_surfaces(
    girder: HullGirder, x: FloatArray, fraction: FloatArray, wave_length_m: float, wave_amplitude_m: float, heading_deg: float
) -> FloatArray:
    """The breadth-mean wave elevation [m] at the nodes ``x`` [m] at the period fractions ``fraction`` (s = t / T), (n_t, n_x).

    ``F(x) zeta_a cos(2 pi s + k_x (x - L/2))`` with ``k_x = -k cos(heading)`` and the breadth factor ``F``
    of :mod:`seafast.hull.oblique`; in head seas exactly ``zeta_a cos(2 pi s + k (x - L/2))``.
    """
    k = 2.0 * np.pi / wave_length_m
    k_x = float(along_ship_wave_number_per_m(k, heading_deg))
    amplitude = wave_amplitude_m * breadth_factor(k, girder.hull.breadth_at(x), heading_deg)
    return np.asarray(amplitude * np.cos(2.0 * np.pi * fraction[:, None] + k_x * (x[None, :] - girder.midship_x_m)), dtype=float)
