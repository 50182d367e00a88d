"""The axial load on the cargo from the ship's motions (docs/axial.md).

In the ship's frame (x forward along the deck, z up, pitch ``theta`` bow up), a point at height
``z`` above the pitch reference (height ``z_ref``) moves forward by ``X_s - theta (z - z_ref)``
(``X_s`` the surge of the reference point). The cargo's axis (its centre of gravity) sits at
``h = z_axis - z_ref`` above the reference; its absolute axial acceleration is
``X_s'' - h theta'' + u''`` (``u`` its displacement relative to the deck), and gravity has the
component ``-g sin(theta) ~ -g theta`` along the tilted deck (bow up pushes the cargo aft). The
axial equation of the cargo is therefore ``m u'' + restraints(u) = F(t)`` with

    F(t) = -m (X_s'' - h theta'') - m g theta,   per harmonic   F_k = m [(k w)^2 (X_k - h Theta_k) - g Theta_k].

Heave does not load the cargo axially (to first order). The still-water part is zero at even
keel (no trim), as seafast's ship is.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from seafast.config.schema import Case
from seafast.excitation.deck_motion import RigidBodyAmplitudes
from seafast.model.from_case import cargo_geometry

__all__ = ["AxialLoad", "axial_load", "axial_load_of", "cargo_axis_height_m"]


@dataclass(frozen=True)
class AxialLoad:
    """Axial force on the rigid cargo, harmonics ``k = 0 .. n_k - 1`` [N] (forward +).

    Attributes
    ----------
    omega_rad_s
        Fundamental frequency [rad/s].
    force_N
        Complex amplitudes ``F_k`` [N], ``F(t) = Re(sum_k F_k exp(i k omega t))``; row 0 real.
    surge_inertia_N, pitch_inertia_N, gravity_N
        The three parts of ``F_1`` [N]: ``m w^2 X_s``, ``-m w^2 h Theta``, ``-m g Theta``.
    lever_m
        ``h``: height of the cargo's axis above the pitch reference [m].
    source
        Provenance (which motions, or why there is no load).
    """

    omega_rad_s: float
    force_N: NDArray[np.complex128]
    surge_inertia_N: complex = 0j
    pitch_inertia_N: complex = 0j
    gravity_N: complex = 0j
    lever_m: float = float("nan")
    source: str = ""

    def static_part(self) -> AxialLoad:
        """Only the still-water (k = 0) part."""
        return AxialLoad(self.omega_rad_s, self.force_N[:1], lever_m=self.lever_m, source=self.source + " (still water)")


def axial_load(
    cargo_mass_kg: float,
    omega_rad_s: float,
    rigid_body: RigidBodyAmplitudes | None,
    axis_height_above_keel_m: float,
    gravity_m_per_s2: float = 9.81,
) -> AxialLoad:
    """Axial load harmonics (k = 0, 1) on a cargo of ``cargo_mass_kg`` from the rigid-body motions.

    Parameters
    ----------
    cargo_mass_kg
        Cargo mass [kg].
    omega_rad_s
        Wave frequency [rad/s].
    rigid_body
        Surge [m], heave, pitch [rad] amplitudes and the reference point; ``None`` for no motion.
    axis_height_above_keel_m
        Height of the cargo's axis above the keel [m].
    gravity_m_per_s2
        g [m/s^2].

    Raises
    ------
    ValueError
        If ``rigid_body`` carries no surge (imported hydrodynamic data without surge): the axial
        load cannot be formed without it, and surge is never assumed zero.
    """
    force = np.zeros(2, dtype=complex)
    if rigid_body is None:
        return AxialLoad(float(omega_rad_s), force, source="no rigid-body motion: no axial load")
    if rigid_body.surge_m is None:
        raise ValueError(
            "the axial analysis needs the ship's surge, and the hydrodynamic data hold none (heave and pitch only); "
            "give vessel.motions = bem, or a capytaine file with a Surge dof / WAMIT files with mode 1, "
            "or unset seafastening.friction_coefficient (the vertical analysis runs without surge)"
        )
    if not np.isfinite(rigid_body.reference_z_m):
        raise ValueError("the axial analysis needs the height of the pitch reference above the keel (unknown for these motions)")
    m, w2, g = float(cargo_mass_kg), float(omega_rad_s) ** 2, float(gravity_m_per_s2)
    h = float(axis_height_above_keel_m) - float(rigid_body.reference_z_m)
    # surge and pitch of one (the coupled) solution; the 2-DOF pitch if only it is given
    theta = complex(rigid_body.coupled_pitch_rad if rigid_body.coupled_pitch_rad is not None else rigid_body.pitch_rad)
    surge = m * w2 * complex(rigid_body.surge_m)
    pitch = -m * w2 * h * theta
    gravity = -m * g * theta
    force[1] = surge + pitch + gravity
    return AxialLoad(float(omega_rad_s), force, surge, pitch, gravity, h, "surge, pitch and gravity along the pitched deck")


def cargo_axis_height_m(case: Case) -> float:
    """Height of the cargo's axis above the keel [m]: deck + saddle height + half the largest diameter."""
    c = case.cargo
    d = c.diameter_m if c.sections is None else max(max(s.diameter_start_m, s.diameter_end_m) for s in c.sections)
    return case.vessel.deck_height_m + case.seafastening.saddle_height_m + 0.5 * d


def axial_load_of(case: Case, vessel: object, cargo_mass_kg: float | None = None) -> AxialLoad:
    """The case's axial load, from the vessel's rigid-body amplitudes (``VesselExcitation.rigid_body``).

    ``cargo_mass_kg``: the cargo's mass when known (the structural model's), else from its geometry.
    """
    rigid = getattr(vessel, "rigid_body", None)
    omega = case.wave_frequency_rad_s()
    mass = cargo_mass_kg if cargo_mass_kg is not None else cargo_geometry(case).mass_kg()
    load = axial_load(mass, omega, rigid, cargo_axis_height_m(case), case.model.gravity_m_per_s2)
    if rigid is None:
        why = (
            "vessel.motions = none"
            if case.vessel.motions == "none"
            else "no wave (wave.amplitude_m = 0)"
            if case.wave.amplitude_m == 0
            else "no rigid-body motion"
        )
        return AxialLoad(load.omega_rad_s, load.force_N, source=f"{why}: no axial load")
    return load
