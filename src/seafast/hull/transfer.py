"""Hull-girder transfer functions: the quasi-static wave response per metre of wave amplitude.

:func:`wave_transfer_functions` solves two real load cases per frequency (the wave frozen at two
instants a quarter period apart), all frequencies at once; the result equals the first harmonic
of :func:`seafast.hull.wave.wave_response` per metre of amplitude while the hull stays immersed, at
any heading (the breadth-mean wave of :mod:`seafast.hull.oblique`). Conventions: :mod:`seafast.hull`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray
from scipy.interpolate import CubicHermiteSpline

from seafast.config.schema import HEAD_SEAS_DEG
from seafast.hull.balance import hydrostatic_balance
from seafast.hull.girder import HullBeam, HullGirder, shear_moment
from seafast.hull.grid import WeightSource, hull_grid, loading_breakpoints, weight_element_ends
from seafast.hull.oblique import along_ship_wave_number_per_m, breadth_factor, heading_cosines, max_local_draught_change

__all__ = ["WaveTransferFunctions", "wave_transfer_functions"]

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class WaveTransferFunctions:
    """Quasi-static hull-girder response per metre of wave amplitude, at several frequencies.

    First harmonics in the convention of :class:`~seafast.hull.wave.WaveHullResponse` (``w(x, t) = Re(W(x)
    exp(i omega t))``, wave ``zeta = zeta_a cos(omega t - k ((x - L/2) cos beta + y sin beta))``, in head
    seas ``zeta_a cos(omega t + k (x - L/2))``, deep water ``k = omega^2 / g``), divided by ``zeta_a``.

    Attributes
    ----------
    x_m
        Hull nodes from the AP [m], shape (n_x,) (the grid of :func:`~seafast.hull.wave.wave_response`).
    omega_rad_s
        Wave frequencies [rad/s], shape (n_w,).
    deflection_m_per_m, slope_rad_per_m, bending_moment_Nm_per_m
        Complex, shape (n_w, n_x): chord-relative deflection [m/m], slope dz/dx [rad/m] and
        bending moment (sagging +) [N m/m].
    emergence_amplitude_m
        Shape (n_w,): the regular-wave amplitude [m] at which the first section emerges (the
        local draught ``T + sinkage - trim (x - L/2) + zeta`` reaches 0 at some point of its
        waterline; the ship's heel, which the vertical balance leaves out, is not included). Below
        it the response is exactly linear in the amplitude; above it, not.
    heading_deg
        Wave heading beta [deg] (180 = head seas, 90 = beam seas, 0 = following seas).
    """

    x_m: FloatArray
    omega_rad_s: FloatArray
    deflection_m_per_m: NDArray[np.complex128]
    slope_rad_per_m: NDArray[np.complex128]
    bending_moment_Nm_per_m: NDArray[np.complex128]
    emergence_amplitude_m: FloatArray
    heading_deg: float = HEAD_SEAS_DEG

    def deck_at(self, x_m: FloatArray) -> tuple[NDArray[np.complex128], NDArray[np.complex128]]:
        """Deflection [m/m] and slope [rad/m] at ``x_m`` (cubic Hermite, as :func:`~seafast.hull.deck.deck_harmonics_at`), (n_w, n_q)."""
        xq = np.atleast_1d(np.asarray(x_m, dtype=float))
        out = []
        for part in (np.real, np.imag):
            spl = CubicHermiteSpline(self.x_m, part(self.deflection_m_per_m).T, part(self.slope_rad_per_m).T, axis=0)
            out.append((spl(xq).T, spl(xq, 1).T))
        return out[0][0] + 1j * out[1][0], out[0][1] + 1j * out[1][1]


def wave_transfer_functions(
    girder: HullGirder, loading: WeightSource, omega_rad_s: FloatArray, n_points: int = 343, *, heading_deg: float = HEAD_SEAS_DEG
) -> WaveTransferFunctions:
    """Hull-girder transfer functions per metre of wave amplitude, two real load cases per frequency.

    While every section stays immersed the wall-sided buoyancy is linear in the local draught,
    so the wave-induced response is linear in the wave: its first harmonic is the response to
    the wave frozen at t = 0 (``F cos k_x (x - L/2)``) plus i times the response to it a quarter
    period earlier (``F sin k_x (x - L/2)``), with the apparent wave number along the ship
    ``k_x = -k cos(beta)`` and the breadth factor ``F(x)`` of :mod:`seafast.hull.oblique` (head
    seas: ``k_x = k``, ``F = 1``). Both are solved for a 1 m wave, all frequencies in one
    vectorised balance on the grid of :func:`~seafast.hull.wave.wave_response`, so ``zeta_a`` times the result
    equals the first harmonic of :func:`~seafast.hull.wave.wave_response` (64 crest positions) to round-off for
    any wave that keeps the hull immersed (no emergence: ``zeta_a`` below about the draught).

    Parameters
    ----------
    girder, loading
        As for :func:`~seafast.hull.still_water.still_water_response`.
    omega_rad_s
        Wave frequencies [rad/s] (> 0), deep-water wave number ``omega^2 / g``.
    n_points
        Uniform nodes along the hull (plus break points), as :func:`~seafast.hull.wave.wave_response`.
    heading_deg
        Wave heading beta [deg]: the direction the waves travel, from the ship's x axis towards
        y (port); 180 = head seas (default), 90 = beam seas, 0 = following seas.
    """
    w = np.atleast_1d(np.asarray(omega_rad_s, dtype=float))
    if w.ndim != 1 or not np.all(np.isfinite(w)) or np.any(w <= 0):
        raise ValueError("wave_transfer_functions: omega_rad_s must be finite and > 0")
    bp = loading_breakpoints(girder, loading)
    x = hull_grid(girder, bp, n_points)
    wa, wb = weight_element_ends(girder, loading, x)
    k = w**2 / girder.gravity_m_per_s2
    phase = along_ship_wave_number_per_m(k, heading_deg)[:, None] * (x[None, :] - girder.midship_x_m)
    breadth = girder.hull.breadth_at(x)
    factor = breadth_factor(k[:, None], breadth[None, :], heading_deg)
    zeta = np.vstack([np.zeros((1, x.size)), factor * np.cos(phase), factor * np.sin(phase)])  # 1 m wave
    sink, trim, _, qa, qb = hydrostatic_balance(girder, x, wa, wb, zeta)
    V, M = shear_moment(np.diff(x), qa, qb)
    z, slope = HullBeam.build(x, girder).solve(qa, qb, V)
    n = w.size

    def first_harmonic(a: NDArray) -> NDArray[np.complex128]:
        d = a[1:] - a[0]
        return d[:n] + 1j * d[n:]

    arm = x - girder.midship_x_m
    still_draught = girder.hull.draft_m + sink[0] - trim[0] * arm
    # local draught change per metre of wave (complex), largest across the waterline: the wave at
    # y, exp(i phase - i k y sin(beta)), plus the ship's sinkage and trim
    ship = first_harmonic(sink)[:, None] - first_harmonic(trim)[:, None] * arm
    half_angle = 0.5 * k[:, None] * breadth[None, :] * abs(heading_cosines(heading_deg)[1])
    immersion = max_local_draught_change(np.exp(1j * phase), ship, half_angle)
    emergence = np.min(still_draught / np.maximum(immersion, 1e-300), axis=1)
    return WaveTransferFunctions(x, w, first_harmonic(z), first_harmonic(slope), first_harmonic(M), emergence, float(heading_deg))
