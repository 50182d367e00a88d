"""Assemble the cargo model's excitation from the vessel: deck deflection and rigid-body inertia.

Inputs are functions of ship position (still-water deflection, wave-deflection harmonic) and
the vessel's rigid-body heave/pitch amplitudes; output is the
:class:`~seafast.excitation.harmonic.HarmonicExcitation` the solvers take.

Frame: cargo displacements are reported relative to the vessel's rigid-body frame, so the deck
points carry only the hull's elastic deflection and the rigid-body motion acts on the cargo
as the inertial load ``-M a_rb`` (docs/theory.md#37-excitation-of-the-cargo-model), with
``a_rb(x) = -omega^2 (heave + pitch (x - x_ref))`` and pitch = dz/dx positive bow up.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from seafast.excitation.harmonic import HarmonicExcitation
from seafast.model.structure import StructuralModel

__all__ = ["RigidBodyAmplitudes", "assemble_excitation"]

DeflectionFn = Callable[[NDArray[np.float64]], tuple[NDArray, NDArray]]


@dataclass(frozen=True)
class RigidBodyAmplitudes:
    """Complex amplitudes of heave [m] and pitch [rad] (bow up positive) at the wave frequency.

    ``reference_x_m`` is the ship x [m] about which pitch rotates. The vertical excitation uses
    ``heave_m`` and ``pitch_rad`` only. ``surge_m`` [m] (forward +) and ``coupled_pitch_rad``
    [rad] are the surge of the reference point and the pitch of the coupled surge-heave-pitch
    solution (the axial load, docs/axial.md), ``None`` when the hydrodynamic data hold no surge;
    ``reference_z_m`` the reference point's height above the keel [m].
    """

    heave_m: complex
    pitch_rad: complex
    reference_x_m: float
    surge_m: complex | None = None
    reference_z_m: float = float("nan")
    coupled_pitch_rad: complex | None = None


def assemble_excitation(
    model: StructuralModel,
    cargo_aft_end_x_m: float,
    omega_rad_s: float,
    still_water: DeflectionFn | None,
    wave: DeflectionFn | None,
    rigid_body: RigidBodyAmplitudes | None = None,
    source: str = "",
) -> HarmonicExcitation:
    """Build the two-harmonic (k = 0, 1) excitation of the cargo model.

    Parameters
    ----------
    model
        The cargo structural model (saddle positions along the cargo).
    cargo_aft_end_x_m
        Ship x of the cargo's aft end [m] (cargo x and ship x point the same way).
    omega_rad_s
        Wave frequency [rad/s].
    still_water
        ``x_ship -> (z [m], slope [rad])`` real still-water deck deflection, or None.
    wave
        ``x_ship -> (Z [m], slope [rad])`` complex wave-deflection amplitudes, or None.
    rigid_body
        Heave and pitch amplitudes, or None for no rigid-body motion.
    """
    n_s = model.saddle_count
    x_ship = cargo_aft_end_x_m + model.saddle_x_m
    deck = np.zeros((2, 2 * n_s), dtype=complex)
    if still_water is not None:
        z, s = still_water(x_ship)
        deck[0, 0::2] = z
        deck[0, 1::2] = s
    if wave is not None:
        z, s = wave(x_ship)
        deck[1, 0::2] = z
        deck[1, 1::2] = s
    load = np.zeros((2, model.cargo_dof_count), dtype=complex)
    line = np.zeros((2, model.cargo.element_count), dtype=complex)
    if rigid_body is not None:
        node_ship_x = cargo_aft_end_x_m + model.cargo.node_x_m
        w2 = omega_rad_s**2
        accel = np.zeros(model.cargo_dof_count, dtype=complex)
        accel[0::2] = -w2 * (rigid_body.heave_m + rigid_body.pitch_rad * (node_ship_x - rigid_body.reference_x_m))
        accel[1::2] = -w2 * rigid_body.pitch_rad
        # Hermite shape functions interpolate this linear field exactly: -M a is the consistent load.
        load[1] = -model.cargo.mass @ accel
        mid_ship_x = cargo_aft_end_x_m + model.cargo.element_mid_x_m
        line[1] = (
            model.cargo.element_mass_per_length_kg_per_m
            * w2
            * (rigid_body.heave_m + rigid_body.pitch_rad * (mid_ship_x - rigid_body.reference_x_m))
        )
    return HarmonicExcitation(omega_rad_s, deck, load, line, source)
