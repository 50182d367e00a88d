"""The cargo across the ship: cradle pad pairs, side stoppers and lashings, and their engagements.

Frame and signs (docs/transverse.md)
------------------------------------
The cargo's section frame is parallel to the ship frame of docs/headings.md: ``x`` forward along
the cargo axis from its aft end, ``y`` to port, ``z`` up; its origin on the cargo axis at the
section. Each cargo node has five DOFs, in the local order :data:`NODE_DOFS`:

* ``u`` axial translation (x, forward +) [m];
* ``v`` lateral translation (y, to port +) [m];
* ``w`` vertical translation (z, up +) [m], today's ``z``;
* ``psi = dv/dx`` [rad], the rotation about z (bow to port +);
* ``theta = dw/dx`` [rad], today's rotation (rises forward +; the right-handed rotation about y is
  ``-theta``).

Torsion about the axis is not a DOF: a round tube on frictionless pads has no torsional stiffness
from them (docs/transverse.md, what is left out). A point at ``r = (r_x, r_y, r_z)`` from the axis at
the node's section moves, for small rotations, by

``d = (u - theta r_z - psi r_y,  v + psi r_x,  w + theta r_x)``.

Engagements
-----------
Every unilateral element is an :class:`Engagement`: ``s = initial_m + gradient . d_node`` [m],
linear in the node's five DOFs; the element carries ``F = k max(s, 0)`` [N], engaged when
``s > 0``, and pushes the cargo with the generalised nodal force ``-F gradient``. For a pad ``s`` is
its compression, for a side stopper its overclosure (movement beyond the gap), for a lashing its
stretch ``T0 / k + elongation`` (``F`` its tension, zero when slack).
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import StrEnum

import numpy as np
from numpy.typing import NDArray

__all__ = [
    "NODE_DOFS",
    "Side",
    "PadPair",
    "SideStopper",
    "Lashing",
    "Engagement",
    "pad_engagements",
    "stopper_engagement",
    "lashing_engagement",
]

NODE_DOFS = ("u", "v", "w", "psi", "theta")
"""The local order of a node's five DOFs in an :class:`Engagement`'s gradient."""


class Side(StrEnum):
    """A side of the cargo: port (``y > 0``) or starboard (``y < 0``)."""

    PORT = "port"
    STARBOARD = "starboard"

    @property
    def sign(self) -> float:
        """+1 for port, -1 for starboard (the sign of ``y`` on that side)."""
        return 1.0 if self is Side.PORT else -1.0


def _positive(name: str, value: float, allowed: str = "a finite number > 0") -> None:
    if not (np.isfinite(value) and value > 0.0):
        raise ValueError(f"{name} = {value!r}: allowed {allowed}")


@dataclass(frozen=True)
class PadPair:
    """A cradle: two compression-only pads at ``+-alpha`` from bottom dead centre.

    Parameters
    ----------
    x_m
        Position along the cargo from its aft end [m] (a node of the cargo mesh).
    contact_angle_deg
        alpha, the angle of each pad's normal from the vertical [deg], ``0 < alpha < 90``. No
        default: it is the saddle's geometry (a contact arc of ``2 alpha``), read from its drawing;
        seafast found no published value to stand in for it.
    tube_radius_m
        The cargo's outer radius at the cradle [m]: where the pads touch.
    saddle_stiffness_N_per_m
        k_v, the pair's vertical stiffness with both pads in contact [N/m] (today's compression-only
        saddle stiffness). Each pad's normal stiffness is ``k_v / (2 cos^2 alpha)``, so that in head
        seas the pair acts vertically exactly as today's spring; its lateral stiffness is then
        ``k_v tan^2 alpha``.
    """

    x_m: float
    contact_angle_deg: float
    tube_radius_m: float
    saddle_stiffness_N_per_m: float

    def __post_init__(self) -> None:
        if not (np.isfinite(self.contact_angle_deg) and 0.0 < self.contact_angle_deg < 90.0):
            raise ValueError(f"contact_angle_deg = {self.contact_angle_deg!r}: allowed 0 < alpha < 90 deg (from bottom dead centre)")
        _positive("tube_radius_m", self.tube_radius_m)
        _positive("saddle_stiffness_N_per_m", self.saddle_stiffness_N_per_m)
        if not np.isfinite(self.x_m):
            raise ValueError(f"x_m = {self.x_m!r}: allowed a finite position along the cargo [m]")

    @property
    def contact_angle_rad(self) -> float:
        return float(np.deg2rad(self.contact_angle_deg))

    @property
    def pad_stiffness_N_per_m(self) -> float:
        """Each pad's normal stiffness ``k_v / (2 cos^2 alpha)`` [N/m]."""
        return float(self.saddle_stiffness_N_per_m / (2.0 * np.cos(self.contact_angle_rad) ** 2))

    @property
    def lateral_stiffness_N_per_m(self) -> float:
        """The pair's lateral stiffness with both pads in contact, ``k_v tan^2 alpha`` [N/m]."""
        return float(self.saddle_stiffness_N_per_m * np.tan(self.contact_angle_rad) ** 2)

    def pad_normal(self, side: Side) -> NDArray[np.float64]:
        """Unit (y, z) direction of the pad's push on the cargo: up and towards the axis [-]."""
        a = self.contact_angle_rad
        return np.array([-side.sign * np.sin(a), np.cos(a)])

    def pad_point_m(self, side: Side) -> NDArray[np.float64]:
        """(y, z) of the pad's contact point from the cargo axis [m]."""
        return -self.tube_radius_m * self.pad_normal(side)


@dataclass(frozen=True)
class SideStopper:
    """A compression-only side stopper beside the cargo, engaged after a gap.

    Parameters
    ----------
    x_m
        Position along the cargo [m] (a node of the cargo mesh).
    side
        The side it stands on: a port stopper is met when the cargo moves to port (``v > gap``)
        and pushes it to starboard; a starboard stopper the other way.
    gap_m
        Clearance before contact [m], ``>= 0``.
    stiffness_N_per_m
        Its stiffness in contact [N/m], ``> 0``.
    """

    x_m: float
    side: Side
    gap_m: float
    stiffness_N_per_m: float

    def __post_init__(self) -> None:
        if not (np.isfinite(self.gap_m) and self.gap_m >= 0.0):
            raise ValueError(f"gap_m = {self.gap_m!r}: allowed a finite clearance >= 0 m")
        _positive("stiffness_N_per_m", self.stiffness_N_per_m)
        Side(self.side)  # a wrong side names its value


@dataclass(frozen=True)
class Lashing:
    """A tension-only lashing (wire or chain) from a point on the cargo to a deck anchor.

    Its tension is ``T = max(T0 + k e, 0)`` with ``e`` the elongation of the chord from the cargo's
    small displacement: a slack lashing carries exactly zero. The chord's rotation (the pretension's
    geometric stiffness ``T0 / L``) is neglected beside ``EA / L``.

    Parameters
    ----------
    cargo_point_m
        (x, y, z) of the attachment [m]: x along the cargo from its aft end (a node of the mesh),
        (y, z) from the cargo axis (y to port, z up), e.g. a padeye on the tube's surface.
    anchor_point_m
        (x, y, z) of the deck anchor in the same frame [m].
    stiffness_N_per_m
        Axial stiffness EA / L of the whole lashing [N/m], ``> 0``.
    pretension_N
        T0 [N], ``>= 0``: the tension with the cargo at its reference position (by default the cargo
        at rest on its pads, :class:`seafast.solvers.transverse_statics.CradleProblem`), where the
        engagement's stretch is ``T0 / k``.
    """

    cargo_point_m: tuple[float, float, float]
    anchor_point_m: tuple[float, float, float]
    stiffness_N_per_m: float
    pretension_N: float = 0.0

    def __post_init__(self) -> None:
        _positive("stiffness_N_per_m", self.stiffness_N_per_m)
        if not (np.isfinite(self.pretension_N) and self.pretension_N >= 0.0):
            raise ValueError(f"pretension_N = {self.pretension_N!r}: allowed a finite tension >= 0 N")
        for name in ("cargo_point_m", "anchor_point_m"):
            point = np.asarray(getattr(self, name), dtype=float)
            if point.shape != (3,) or not np.all(np.isfinite(point)):
                raise ValueError(f"{name} = {getattr(self, name)!r}: allowed three finite coordinates (x, y, z) [m]")
        if self.length_m <= 0.0:
            raise ValueError(f"anchor_point_m = {self.anchor_point_m!r}: allowed a point away from cargo_point_m (zero length)")

    @property
    def length_m(self) -> float:
        """Chord length from the cargo point to the anchor [m]."""
        return float(np.linalg.norm(np.subtract(self.anchor_point_m, self.cargo_point_m)))

    @property
    def direction(self) -> NDArray[np.float64]:
        """Unit vector (x, y, z) from the cargo point towards the anchor: the pull on the cargo [-]."""
        return np.subtract(self.anchor_point_m, self.cargo_point_m) / self.length_m


@dataclass(frozen=True)
class Engagement:
    """A unilateral element's engagement ``s = initial_m + gradient . d_node`` [m] and stiffness.

    ``gradient`` is over the node's five DOFs in :data:`NODE_DOFS` order [m/m, m/rad]; the element
    at ``x_m`` carries ``k max(s, 0)`` [N].
    """

    x_m: float
    initial_m: float
    gradient: NDArray[np.float64]
    stiffness_N_per_m: float


def _translation_gradient(direction_yz_or_xyz: NDArray[np.float64]) -> NDArray[np.float64]:
    """``d s / d(u, v, w, psi, theta)`` of ``s = n . d`` for a point on the axis, n in (x, y, z)."""
    n = np.asarray(direction_yz_or_xyz, dtype=float)
    return np.array([n[0], n[1], n[2], 0.0, 0.0])


def pad_engagements(pair: PadPair) -> tuple[Engagement, Engagement]:
    """The (port, starboard) pads' compressions, ``s = -m . (v, w)``, m the pad's push (rigid deck).

    The contact point's normal displacement does not depend on the section's rotations (the normal
    passes through the axis), so only ``v`` and ``w`` enter.
    """
    out = []
    for side in (Side.PORT, Side.STARBOARD):
        m = pair.pad_normal(side)
        out.append(Engagement(pair.x_m, 0.0, -_translation_gradient(np.array([0.0, m[0], m[1]])), pair.pad_stiffness_N_per_m))
    return out[0], out[1]


def stopper_engagement(stopper: SideStopper) -> Engagement:
    """The stopper's overclosure ``s = sign v - gap`` (sign +1 port, -1 starboard) [m]."""
    sign = Side(stopper.side).sign
    return Engagement(stopper.x_m, -float(stopper.gap_m), _translation_gradient(np.array([0.0, sign, 0.0])), stopper.stiffness_N_per_m)


def lashing_engagement(lashing: Lashing) -> Engagement:
    """The lashing's stretch ``s = T0 / k - e . d_P`` [m], e its direction, d_P its cargo point's displacement.

    With ``r = (0, r_y, r_z)`` (the point at its node's section) ``d_P = (u - theta r_z - psi r_y, v, w)``.
    """
    e = lashing.direction
    _, r_y, r_z = (float(c) for c in lashing.cargo_point_m)
    gradient = np.array([-e[0], -e[1], -e[2], e[0] * r_y, e[0] * r_z])
    return Engagement(
        float(lashing.cargo_point_m[0]), lashing.pretension_N / lashing.stiffness_N_per_m, gradient, lashing.stiffness_N_per_m
    )
