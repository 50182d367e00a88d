"""Coulomb friction at the cradle pads: the pads' tangential motion and the friction's parameters.

Each pad of a :class:`~seafast.model.cradle.PadPair` touches the tube at ``r = -R m`` from the axis, ``m`` its
push in (y, z) (docs/transverse.md#3-the-restraints). Its contact point moves, relative to the pad, along two
tangential directions (docs/transverse.md#8-friction-at-the-pads):

* circumferential ``t = (m_z, -m_y)`` in (y, z), normal to the push and pointing to port on both pads
  (port pad ``(cos a, sin a)``, starboard pad ``(cos a, -sin a)``): ``delta_c = t . (v, w)``;
* axial ``x`` (forward +): ``delta_x = u - theta r_z - psi r_y``, the contact point's axial displacement
  (the section's rotations move a point off the axis along it).

Both are linear in the node's five DOFs, as the normal engagement is; the deck under the pair moves
vertically by ``z_deck``, so the relative circumferential motion loses ``t_z z_deck`` and the axial one
nothing. Each pad carries a two-dimensional Jenkins element on ``(delta_c, delta_x)``: a tangential
stiffness in series with a Coulomb slider whose limit is ``mu`` times the pad's own normal force
(:mod:`seafast.solvers.friction_cone`).

Units: [m], [N/m]; the gradients over :data:`~seafast.model.cradle.NODE_DOFS` [m/m, m/rad].
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from seafast.model.cradle import PadPair, Side

__all__ = ["PadFriction", "TANGENTIAL_DIRECTIONS", "pad_tangent", "pad_tangential_gradients", "pad_tangential_deck"]

TANGENTIAL_DIRECTIONS = ("circumferential", "axial")
"""The order of a pad's two tangential coordinates."""


@dataclass(frozen=True)
class PadFriction:
    """Coulomb friction at every pad: a Jenkins element on each pad's tangential motion.

    Parameters
    ----------
    friction_coefficient
        mu [-], ``>= 0`` (the case's ``seafastening.friction_coefficient``): the slider's limit is
        ``mu max(F_n, 0)``, ``F_n`` the pad's normal force; 0 is frictionless.
    tangential_stiffness_ratio
        The pad's tangential stiffness over its normal stiffness ``k_v / (2 cos^2 alpha)`` [-], ``> 0``, the same
        in both tangential directions. The default 1 makes each pad isotropic (``k_t = k_n``: the pad's stiffness
        matrix in (y, z) is ``k_n I``); a pad of elastomer or timber is softer in shear than in compression (a
        ratio below 1). It sets the stick displacement (``F_t / k_t``) and when a pad starts to slip, not the
        forces in gross slip.
    """

    friction_coefficient: float
    tangential_stiffness_ratio: float = 1.0

    def __post_init__(self) -> None:
        mu, ratio = self.friction_coefficient, self.tangential_stiffness_ratio
        if not (np.isfinite(mu) and mu >= 0.0):
            raise ValueError(f"friction_coefficient = {mu!r}: allowed a finite number >= 0")
        if not (np.isfinite(ratio) and ratio > 0.0):
            raise ValueError(f"tangential_stiffness_ratio = {ratio!r}: allowed a finite number > 0 (k_t / k_n)")

    def tangential_stiffness_N_per_m(self, pair: PadPair) -> float:
        """Each pad's tangential stiffness ``ratio k_v / (2 cos^2 alpha)`` [N/m]."""
        return float(self.tangential_stiffness_ratio * pair.pad_stiffness_N_per_m)


def pad_tangent(pair: PadPair, side: Side) -> NDArray[np.float64]:
    """The pad's circumferential direction ``t = (m_z, -m_y)`` in (y, z): normal to its push, to port [-]."""
    m = pair.pad_normal(side)
    return np.array([m[1], -m[0]])


def pad_tangential_gradients(pair: PadPair) -> NDArray[np.float64]:
    """``d delta / d(u, v, w, psi, theta)`` of each pad's (circumferential, axial) motion, (2 pads, 2, 5).

    Port pad first. Circumferential ``t . (v, w)``; axial ``u - theta r_z - psi r_y`` at the contact point
    ``(r_y, r_z) = -R m``.
    """
    out = np.zeros((2, 2, 5))
    for i, side in enumerate((Side.PORT, Side.STARBOARD)):
        t = pad_tangent(pair, side)
        r_y, r_z = pair.pad_point_m(side)
        out[i, 0] = [0.0, t[0], t[1], 0.0, 0.0]
        out[i, 1] = [1.0, 0.0, 0.0, -r_y, -r_z]
    return out


def pad_tangential_deck(pair: PadPair) -> NDArray[np.float64]:
    """``d delta / d z_deck`` of each pad's (circumferential, axial) motion, (2 pads, 2) [m/m]: the pad rises with
    the deck, so the relative circumferential motion changes by ``-t_z z_deck``; the axial by nothing."""
    return np.array([[-pad_tangent(pair, side)[1], 0.0] for side in (Side.PORT, Side.STARBOARD)])
