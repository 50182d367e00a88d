"""The default motion criteria's load cases and the apparent gravity they put on any cargo point (docs/criteria.md).

Frame and signs (docs/headings.md, docs/transverse.md): ship frame, ``x`` forward, ``y`` to port, ``z`` up; roll
``phi`` starboard down +, pitch ``theta`` bow up +. The roll and pitch axes pass through the motion origin: the
vessel's centre of flotation on the centreline, at the waterline. Each case stands at the extreme of its motion,
where the angle is ``phi_a`` (or ``theta_a``), the angular velocity is zero and the angular acceleration is
``-(2 pi / T)^2`` times the angle (towards upright); the heave acceleration ``a_h`` (+ up) acts along the ship's
``z``. The rotation vector of roll is ``(phi, 0, 0)`` and of pitch ``(0, -theta, 0)`` (bow up is a negative
right-handed rotation about ``y``), so the angular acceleration is

``alpha = (2 pi / T)^2 (-phi_a, theta_a, 0)``

and a point at ``r`` from the motion origin accelerates by ``a = alpha x r + (0, 0, a_h)``. The *apparent
gravity* at the point, the force per unit mass the cargo's mass puts on its restraints, is

``g_app = g (-sin theta, -cos theta sin phi, -cos theta cos phi) - a``

(the exact gravity components of the angles, :func:`seafast.model.cargo3d.gravity_direction`): in roll,
``(0, -g sin phi - w^2 phi r_z, -g cos phi + w^2 phi r_y - a_h)``, the design rules' ``g sin phi + r phi''``
across the ship above the roll axis.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from enum import StrEnum

import numpy as np
from numpy.typing import ArrayLike, NDArray

from seafast.analyses.criteria.standard import MotionCriteria
from seafast.model.cargo3d import gravity_direction

__all__ = ["Motion", "CriteriaLoadCase", "default_load_cases", "apparent_gravity_m_s2"]


class Motion(StrEnum):
    """The angular motion of a load case."""

    ROLL = "roll"
    PITCH = "pitch"
    HEAVE = "heave"


@dataclass(frozen=True)
class CriteriaLoadCase:
    """One quasi-static load case: an angle at its extreme with a heave acceleration.

    Attributes
    ----------
    name
        E.g. ``roll+20_heave+`` (the angle's sign and value, the heave's sign).
    motion
        Roll or pitch.
    roll_deg, pitch_deg
        The angles [deg] (roll starboard down +, pitch bow up +); the other one is zero.
    period_s
        The motion's full-cycle period [s].
    heave_acceleration_m_s2
        Heave acceleration [m/s^2], + up.
    origin_acceleration_m_s2
        The motion origin's acceleration (x, y, z), ship frame [m/s^2]; None: ``(0, 0, heave_acceleration_m_s2)``
        (the default criteria). The motion-analysis cases give all three.
    rotation_acceleration_rad_s2
        The angular acceleration as a right-handed rotation vector, ship frame [rad/s^2]; None: the extreme of the
        angle over its period (``(2 pi / T)^2 (-phi, theta, 0)``).
    wave_heading_deg
        The sea's heading [deg]; None: 90 for roll, 180 for pitch (the seas the default criteria stand for).
    """

    name: str
    motion: Motion
    roll_deg: float
    pitch_deg: float
    period_s: float
    heave_acceleration_m_s2: float
    origin_acceleration_m_s2: tuple[float, float, float] | None = None
    rotation_acceleration_rad_s2: tuple[float, float, float] | None = None
    wave_heading_deg: float | None = None

    @property
    def heading_deg(self) -> float:
        """The wave heading [deg]: the case's own, else 90 (beam seas) for roll, 180 (head seas) for pitch."""
        if self.wave_heading_deg is not None:
            return self.wave_heading_deg
        return 90.0 if self.motion is Motion.ROLL else 180.0

    @property
    def linear_acceleration_m_s2(self) -> NDArray[np.float64]:
        """The motion origin's acceleration (x, y, z), ship frame [m/s^2]."""
        if self.origin_acceleration_m_s2 is not None:
            return np.array(self.origin_acceleration_m_s2, dtype=float)
        return np.array([0.0, 0.0, self.heave_acceleration_m_s2])

    @property
    def angular_acceleration_rad_s2(self) -> NDArray[np.float64]:
        """``alpha = (2 pi / T)^2 (-phi, theta, 0)`` in the ship frame [rad/s^2] (module docstring), or the case's own."""
        if self.rotation_acceleration_rad_s2 is not None:
            return np.array(self.rotation_acceleration_rad_s2, dtype=float)
        w2 = (2.0 * math.pi / self.period_s) ** 2
        return w2 * np.array([-math.radians(self.roll_deg), math.radians(self.pitch_deg), 0.0])


def default_load_cases(criteria: MotionCriteria, gravity_m_per_s2: float = 9.81) -> tuple[CriteriaLoadCase, ...]:
    """The eight cases: roll +- with heave +-, pitch +- with heave +- (the standard's combinations)."""
    heave = criteria.heave_acceleration_g * gravity_m_per_s2
    cases = []
    for motion, angle, period in (
        (Motion.ROLL, criteria.roll_deg, criteria.roll_period_s),
        (Motion.PITCH, criteria.pitch_deg, criteria.pitch_period_s),
    ):
        for sign in (1.0, -1.0):
            for heave_sign in (1.0, -1.0):
                roll, pitch = (sign * angle, 0.0) if motion is Motion.ROLL else (0.0, sign * angle)
                name = f"{motion.value}{sign * angle:+g}_heave{'+' if heave_sign > 0 else '-'}"
                cases.append(CriteriaLoadCase(name, motion, roll, pitch, period, heave_sign * heave))
    return tuple(cases)


def apparent_gravity_m_s2(load_case: CriteriaLoadCase, points_m: ArrayLike, gravity_m_per_s2: float = 9.81) -> NDArray[np.float64]:
    """The apparent gravity ``g_app = g_ship - alpha x r - a_0`` at points ``r`` from the motion origin.

    ``a_0`` is the origin's acceleration, ``(0, 0, a_h)`` for the default criteria.

    Parameters
    ----------
    load_case
        The case.
    points_m
        (x, y, z) from the motion origin (centre of flotation, centreline, waterline) [m], shape (3,) or (n, 3).
    gravity_m_per_s2
        g [m/s^2].

    Returns
    -------
    numpy.ndarray
        The force per unit mass on the restraints at each point, ship frame [m/s^2], the shape of ``points_m``.
    """
    r = np.asarray(points_m, dtype=float)
    g_ship = gravity_m_per_s2 * gravity_direction(load_case.roll_deg, load_case.pitch_deg)
    rotation = np.cross(load_case.angular_acceleration_rad_s2, r)
    return g_ship - rotation - load_case.linear_acceleration_m_s2
