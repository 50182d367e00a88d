"""Accelerations of cargo points in the ship frame from the six rigid-body motions (docs/headings.md#6-accelerations-of-the-cargo).

A point at ``r`` from the centre of gravity (ship frame: x forward, y to port, z up) moves by ``u = xi + Omega x r`` with
``xi = (surge, sway, heave)`` and the rotation vector ``Omega = (phi, -theta, psi)`` in right-handed components (roll
``phi`` starboard down +, pitch ``theta`` bow **up** +, yaw ``psi`` bow to port +):

    u_x = surge - theta r_z - psi r_y,   u_y = sway + psi r_x - phi r_z,   u_z = heave + phi r_y + theta r_x.

Its acceleration ``a = -omega^2 u``. Gravity in the ship frame, linearised, is ``g_ship = (-g theta, -g phi, -g)``
(``(g eta_5, -g phi, -g)`` with the bow-down pitch ``eta_5 = -theta``; gravity points to the low side). The reported
**acceleration** is what an accelerometer fixed to the cargo reads beyond the static ``g``, the force per unit mass the
restraints must supply:

    f = a - (g_ship - (0, 0, -g)) = a + (g theta, g phi, 0),

so the roll's angular acceleration above the roll axis and its gravity component add, as in the design rules' transverse
acceleration (``g sin phi + r phi_dd``).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["CargoPoints", "point_displacement_matrix", "acceleration_transfer", "GRAVITY_ROWS"]


@dataclass(frozen=True)
class CargoPoints:
    """Points of the analysed cargo unit: on its axis at cargo x ``x_cargo_m``.

    Attributes
    ----------
    x_cargo_m
        Cargo x of each point (from the cargo's aft end) [m], shape (n_p,).
    x_ship_m
        Ship x of each point (from the AP) [m], shape (n_p,).
    y_m
        The unit's axis from the centreline (+ to port) [m].
    z_m
        The unit's axis above the keel [m].
    """

    x_cargo_m: NDArray[np.float64]
    x_ship_m: NDArray[np.float64]
    y_m: float
    z_m: float

    def relative_to(self, x_ref_m: float, z_ref_m: float) -> NDArray[np.float64]:
        """Positions (n_p, 3) relative to the point (x_ref_m, 0, z_ref_m) [m] (the CoG: x from the AP, z above the keel)."""
        n = self.x_ship_m.size
        return np.column_stack([self.x_ship_m - x_ref_m, np.full(n, self.y_m), np.full(n, self.z_m - z_ref_m)])


def point_displacement_matrix(points_m: ArrayLike) -> NDArray[np.float64]:
    """``T`` (n_p, 3, 6) with ``u = T q``: the displacement of points ``r`` (n_p, 3) [m] from the CoG by the six motions.

    ``q = (surge, sway, heave, roll, pitch bow up, yaw)`` [m, rad]; see the module docstring.
    """
    r = np.atleast_2d(np.asarray(points_m, dtype=float))
    t = np.zeros((r.shape[0], 3, 6))
    rx, ry, rz = r[:, 0], r[:, 1], r[:, 2]
    t[:, 0, 0] = t[:, 1, 1] = t[:, 2, 2] = 1.0
    t[:, 0, 4], t[:, 0, 5] = -rz, -ry
    t[:, 1, 3], t[:, 1, 5] = -rz, rx
    t[:, 2, 3], t[:, 2, 4] = ry, rx
    return t


GRAVITY_ROWS = np.array([[0.0, 0.0, 0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 0.0, 0.0, 0.0, 0.0]])
"""``G`` (3, 6): the dynamic gravity part of the reading per unit g, ``(theta, phi, 0)``, from ``q``."""


def acceleration_transfer(
    motions: ArrayLike, omega_rad_s: ArrayLike, points_m: ArrayLike, gravity_m_per_s2: float = 9.81
) -> NDArray[np.complex128]:
    """The accelerometer reading ``f = -omega^2 T q + g G q`` (..., n_p, 3) of points ``r`` from the CoG [m/s^2 per unit of q].

    Parameters
    ----------
    motions
        Complex six-DOF amplitudes ``q`` (..., 6), per metre of wave amplitude (RAOs) or for the case's wave.
    omega_rad_s
        Frequency [rad/s], broadcast against ``motions[..., 0]``.
    points_m
        (n_p, 3) positions relative to the CoG, ship frame [m].
    gravity_m_per_s2
        g [m/s^2].

    Returns
    -------
    ndarray (..., n_p, 3)
        Complex amplitudes (x, y, z in the ship frame) [m/s^2 per unit of ``q``'s amplitude].
    """
    q = np.asarray(motions, dtype=complex)
    w2 = np.asarray(omega_rad_s, dtype=float) ** 2
    t = point_displacement_matrix(points_m)  # (n_p, 3, 6)
    op = -w2[..., None, None, None] * t + gravity_m_per_s2 * GRAVITY_ROWS  # (..., n_p, 3, 6)
    return np.einsum("...pij,...j->...pi", op, q)
