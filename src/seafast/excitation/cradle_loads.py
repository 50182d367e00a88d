"""The periodic loads on the 3-D cargo in a regular wave at any heading (docs/transverse.md#7-dynamics).

The cargo's displacements are relative to the vessel's rigid-body frame, as in the vertical plane
(docs/theory.md#37-excitation-of-the-cargo-model): the rigid-body motions act on the cargo as the
inertia of their accelerations in the ship frame plus gravity's roll and pitch components, and the deck
points under the saddles carry the hull's elastic deflection. Per unit mass the dynamic load is
``-f`` with ``f = -omega^2 T q + g G q`` the accelerometer reading of
:func:`~seafast.excitation.cargo_acceleration.acceleration_transfer` (``q`` the six motions), so that a
roll ``phi`` (starboard down +) loads the cargo to starboard by ``m g phi`` and an upward heave
acceleration presses it onto its pads.

Along the cargo the reading is linear in x (the rotations' lever ``r_x``), so the Hermite shape functions
interpolate it exactly: the consistent nodal loads are ``-M_block a`` with ``a`` the reading and its
x-derivative at the nodes, for the lateral block ``(v, psi)``; ``-M_axial f_x`` for the axial bars. The
vertical block is the vertical plane's own load (:class:`~seafast.excitation.harmonic.HarmonicExcitation`,
``-M a_rb`` of heave, roll at the unit's ``y`` and pitch), kept as it is, so that head seas load the
vertical block exactly as today. Units: loads [N, N m], deck DOFs [m, rad].
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
from numpy.typing import NDArray

from seafast.excitation.cargo_acceleration import acceleration_transfer
from seafast.excitation.harmonic import HarmonicExcitation
from seafast.excitation.vessel import VesselExcitation
from seafast.model.cargo3d import Cargo3D
from seafast.model.structure import StructuralModel

__all__ = ["CradleExcitation", "cradle_excitation", "cradle_excitation_of"]


@dataclass(frozen=True)
class CradleExcitation:
    """The static and first-harmonic excitation of the 3-D cargo (k = 0, 1).

    Attributes
    ----------
    omega_rad_s
        Wave (encounter) frequency [rad/s].
    cargo_load_N
        Complex amplitudes of the vessel-induced nodal loads on the 3-D cargo's DOFs
        (:mod:`seafast.model.cargo3d`'s block order) [N, N m], shape (2, 5 n). Row 0 holds no weight: the
        weight and the given loads belong to the problem (:class:`~seafast.solvers.transverse_statics.CradleProblem`).
    deck_displacement
        The vertical plane's deck DOFs (z [m] up, theta [rad] under each saddle, in the vertical model's
        order), shape (2, 2 n_s): row 0 the still-water deflection, row 1 the wave's.
    deck_x_m
        Cargo x of each deck point (the vertical model's saddles) [m], shape (n_s,).
    source
        Provenance, for people.
    """

    omega_rad_s: float
    cargo_load_N: NDArray[np.complex128]
    deck_displacement: NDArray[np.complex128]
    deck_x_m: NDArray[np.float64]
    source: str = ""

    def __post_init__(self) -> None:
        if np.shape(self.deck_displacement) != (2, 2 * np.size(self.deck_x_m)):
            raise ValueError(
                f"deck_displacement: shape {np.shape(self.deck_displacement)}; allowed (2, {2 * np.size(self.deck_x_m)}): "
                "z and theta under each deck point, rows k = 0, 1"
            )
        if np.ndim(self.cargo_load_N) != 2 or np.shape(self.cargo_load_N)[0] != 2:
            raise ValueError(f"cargo_load_N: shape {np.shape(self.cargo_load_N)}; allowed (2, 5 n), rows k = 0, 1")

    def still_water(self) -> CradleExcitation:
        """The static part alone (k = 0 kept, k = 1 zero): the loads and deck deflection of still water."""
        keep = np.array([[1.0], [0.0]])
        return replace(self, cargo_load_N=self.cargo_load_N * keep, deck_displacement=self.deck_displacement * keep)


def _reading_at_nodes(
    motions: NDArray[np.complex128], omega_rad_s: float, points_m: NDArray[np.float64], gravity_m_per_s2: float
) -> tuple[NDArray[np.complex128], NDArray[np.complex128]]:
    """The reading f (n, 3) at the points and its x-derivative (exact: f is linear in x) [m/s^2, 1/s^2]."""
    f = acceleration_transfer(motions, omega_rad_s, points_m, gravity_m_per_s2)
    shifted = points_m + np.array([1.0, 0.0, 0.0])
    return f, acceleration_transfer(motions, omega_rad_s, shifted, gravity_m_per_s2) - f


def cradle_excitation(
    cargo: Cargo3D,
    vertical: HarmonicExcitation,
    motions: NDArray[np.complex128],
    deck_x_m: NDArray[np.float64],
    axis_from_reference_m: tuple[float, float, float],
    gravity_m_per_s2: float = 9.81,
) -> CradleExcitation:
    """The loads on the 3-D cargo and the deck's motion in a regular wave at any heading.

    Parameters
    ----------
    cargo
        The 3-D cargo, on the vertical model's mesh.
    vertical
        The vertical plane's excitation of the same cargo (``VesselExcitation.cargo_excitation``): its deck
        DOFs and its cargo loads (k = 0, 1) become the vertical block's, unchanged.
    motions
        The six motions at the wave, complex (surge, sway, heave [m], roll starboard down +, pitch bow up
        +, yaw bow to port + [rad]) about the reference point; a NaN (no surge in the data) counts as 0.
    deck_x_m
        Cargo x of the vertical model's deck points (its saddles) [m].
    axis_from_reference_m
        (x, y, z) of the cargo axis at the cargo's aft end from the motions' reference point (ship frame:
        x forward, y to port, z up) [m].
    gravity_m_per_s2
        g [m/s^2].
    """
    n = cargo.node_count
    if vertical.cargo_load_N.shape[1] != 2 * n:
        raise ValueError(f"vertical: {vertical.cargo_load_N.shape[1]} cargo DOFs; allowed {2 * n}, the 3-D cargo's vertical block")
    q = np.nan_to_num(np.asarray(motions, dtype=complex), nan=0.0)
    if q.shape != (6,):
        raise ValueError(f"motions: shape {q.shape}; allowed (6,): surge, sway, heave, roll, pitch, yaw")
    points = np.column_stack([cargo.node_x_m, np.zeros(n), np.zeros(n)]) + np.asarray(axis_from_reference_m, dtype=float)
    f, slope = _reading_at_nodes(q, float(vertical.omega_rad_s), points, gravity_m_per_s2)
    load = np.zeros((2, cargo.dof_count), dtype=complex)
    rows = min(2, vertical.harmonic_count)
    load[:rows, : 2 * n] = vertical.cargo_load_N[:rows]
    lateral = np.empty(2 * n, dtype=complex)
    lateral[0::2], lateral[1::2] = f[:, 1], slope[:, 1]
    load[1, 2 * n : 4 * n] = -cargo.mass[2 * n : 4 * n, 2 * n : 4 * n] @ lateral
    load[1, 4 * n :] = -cargo.mass[4 * n :, 4 * n :] @ f[:, 0]
    deck = np.zeros((2, vertical.deck_displacement.shape[1]), dtype=complex)
    deck[:rows] = vertical.deck_displacement[:rows]
    return CradleExcitation(float(vertical.omega_rad_s), load, deck, np.asarray(deck_x_m, dtype=float), vertical.source)


def cradle_excitation_of(vessel: VesselExcitation, model: StructuralModel, cargo: Cargo3D) -> CradleExcitation:
    """:func:`cradle_excitation` of a case's vessel excitation: its six motions, deck and unit's position.

    ``model`` is the vertical-plane model whose mesh ``cargo`` was built on (``build_cargo3d(model.cargo)``);
    the motions' reference point is the vessel's (``rigid_body``), the unit's axis its ``cargo_points``.
    """
    rigid, points, q = vessel.rigid_body, vessel.cargo_points, vessel.motion_amplitudes
    if rigid is None or points is None or q is None:
        raise ValueError("vessel: no rigid-body motions (vessel.motions = 'none' or a zero wave): allowed a vessel with motions")
    if not np.isfinite(rigid.reference_z_m):
        raise ValueError("vessel: the motions' reference point has no height (reference_z_m): allowed motions with one")
    axis = (vessel.cargo_aft_end_x_m - rigid.reference_x_m, points.y_m, points.z_m - rigid.reference_z_m)
    vertical = vessel.cargo_excitation(model)
    return cradle_excitation(cargo, vertical, q, model.saddle_x_m, axis, vessel.gravity_m_per_s2)
