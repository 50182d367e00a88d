"""A regular wave at a heading, as the hull girder sees it: the wave along the ship, averaged across its breadth.

Wave at heading beta (the direction the waves travel, from the ship's x axis towards y, port;
180 deg = head seas, 90 = beam seas from starboard, 0 = following seas), deep water, zero speed::

    zeta(x, y, t) = zeta_a cos(omega t - k ((x - L/2) cos beta + y sin beta)),   k = 2 pi / lambda,

y from the centreline to port. The wall-sided section of waterline breadth ``B(x)`` (immersed
area ``C_s B d`` at draught ``d``, :class:`~seafast.vessel.hull_form.HullForm`) takes the mean of
the local draught across its waterline: the vertical hydrostatic force per metre is ``rho g C_s``
times the integral of the draught over ``-B/2 <= y <= B/2``, and its wave part is exactly::

    rho g C_s B(x) F(x) zeta_a cos(omega t + k_x (x - L/2)),
    F(x) = sin(k B(x) sin(beta) / 2) / (k B(x) sin(beta) / 2),   k_x = -k cos(beta),

the head-sea form with the apparent wave number ``k_x`` along the ship (wave length
``lambda / |cos beta|``) and the elevation scaled by the breadth factor ``F``. The part of the wave
odd in y (``sin(k y sin beta)``) has zero mean across the section: it heels the section (a roll
moment per metre, the torsional load of the hull girder) but adds no vertical force, and for the
same reason a quasi-static heel of the ship changes no section's vertical force. While every
point of the waterline stays immersed this is exact for the model's sections; once a section's
side emerges, the model takes the breadth-mean draught (the buoyancy is ``max(mean draught, 0)``),
an approximation. The Smith effect (pressure decay with depth) is not modelled, for any heading.

Conventions: :mod:`seafast.hull`; headings: ``docs/theory.md`` (hull girder in oblique seas).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["heading_cosines", "breadth_factor", "along_ship_wave_number_per_m", "max_local_draught_change"]

FloatArray = NDArray[np.float64]


_QUADRANTS = ((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0))


def heading_cosines(heading_deg: float) -> tuple[float, float]:
    """``(cos beta, sin beta)`` of the heading [deg], exact (0 and +/-1) at multiples of 90 deg.

    Exact values keep head seas bit-identical to the head-sea-only model (``k_x = k`` exactly,
    breadth factor exactly 1) and give beam seas no spurious wave component along the ship.

    Raises
    ------
    ValueError
        For a heading that is not finite.
    """
    beta = float(heading_deg)
    if not np.isfinite(beta):
        raise ValueError(f"wave heading: heading_deg = {heading_deg!r}; must be finite (degrees, 180 = head seas)")
    quadrant, rest = divmod(beta, 90.0)
    if rest == 0.0:
        return _QUADRANTS[int(quadrant) % 4]
    r = np.deg2rad(beta)
    return float(np.cos(r)), float(np.sin(r))


def along_ship_wave_number_per_m(wave_number_per_m: ArrayLike, heading_deg: float) -> NDArray[np.float64]:
    """Apparent wave number along the ship ``k_x = -k cos(beta)`` [1/m] (= k in head seas, 0 in beam seas).

    The breadth-mean wave is ``F zeta_a cos(omega t + k_x (x - L/2))``: head seas keep the head-sea
    phase ``k (x - L/2)`` exactly; following seas have ``k_x = -k`` (the wave travels aft to fore).
    """
    cos_beta, _ = heading_cosines(heading_deg)
    return -cos_beta * np.asarray(wave_number_per_m, dtype=float)


def breadth_factor(wave_number_per_m: ArrayLike, breadth_m: ArrayLike, heading_deg: float) -> NDArray[np.float64]:
    """Mean of the wave across a waterline of breadth B over its centreline value: ``sin(a) / a``, ``a = k B sin(beta) / 2``.

    Parameters
    ----------
    wave_number_per_m
        Wave number k [1/m] (broadcast against ``breadth_m``).
    breadth_m
        Waterline breadth B [m].
    heading_deg
        Wave heading beta [deg].

    Returns
    -------
    numpy.ndarray
        The factor [-]: 1 in head and following seas (exactly), ``sin(k B / 2) / (k B / 2)`` in beam
        seas; it vanishes where the transverse wave length ``lambda / |sin beta|`` is ``B`` / n.
    """
    _, sin_beta = heading_cosines(heading_deg)
    a = 0.5 * np.asarray(wave_number_per_m, dtype=float) * np.asarray(breadth_m, dtype=float) * sin_beta
    return np.asarray(np.sinc(a / np.pi), dtype=float)


def max_local_draught_change(
    wave: NDArray[np.complex128], ship: NDArray[np.complex128], half_angle_rad: NDArray[np.float64]
) -> NDArray[np.float64]:
    """Largest amplitude across the breadth of the local draught change ``wave exp(-i theta) + ship``.

    At a section the wave's complex amplitude at ``y`` is ``wave exp(-i k y sin beta)`` and the
    ship's sinkage and trim add ``ship`` (the same across the breadth); ``theta = k y sin beta``
    runs over ``[-half_angle, half_angle]``, ``half_angle = k B |sin beta| / 2``. The modulus
    ``|wave exp(-i theta) + ship|`` is largest at ``theta = arg(wave conj(ship))`` clipped to that
    interval (exact: ``|wave| + |ship|`` once the interval covers the circle). Shapes broadcast.
    """
    phi = np.angle(wave * np.conj(ship))
    theta = np.clip(phi, -half_angle_rad, half_angle_rad)
    return np.asarray(np.abs(wave * np.exp(-1j * theta) + ship), dtype=float)
