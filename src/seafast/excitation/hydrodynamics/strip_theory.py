"""An independent estimate of heave and pitch: zero-speed strip theory (a check on the BEM)."""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
from numpy.typing import ArrayLike

from seafast.excitation.hydrodynamics.equations import hydrostatic_stiffness_matrix, mass_matrix, solve_heave_pitch, wavenumber_rad_per_m
from seafast.excitation.hydrodynamics.motions import RigidBodyMotions
from seafast.vessel.hull_form import HullForm

__all__ = ["strip_theory_estimate"]


def strip_theory_estimate(
    hull: HullForm,
    *,
    mass_kg: float,
    centre_of_gravity_m: Sequence[float],
    pitch_radius_of_gyration_m: float,
    omega_rad_s: ArrayLike,
    water_density_kg_per_m3: float = 1025.0,
    gravity_m_per_s2: float = 9.81,
    n_sections: int = 400,
) -> RigidBodyMotions:
    """Independent zero-speed strip-theory estimate of heave and pitch in deep-water head seas.

    Relative-motion strip theory: each section of waterline breadth ``b(x)`` has hydrostatic
    stiffness ``c = rho g b``, a frequency-independent flat-plate added mass
    ``a = rho pi b^2 / 8`` and a 2-D radiation damping ``d = rho g^2 Abar^2 / omega^3`` with the
    wave-amplitude ratio ``Abar = 2 sin(k b / 2) exp(-k T)``. The section force is
    ``(c - omega^2 a + i omega d) (zeta*(x) - w(x))`` with the Smith-corrected wave
    ``zeta*(x) = exp(-k T_m) exp(i k (x - x_mid))`` (``T_m`` = sectional area / breadth, the
    mean draught of the section), which is exact Froude-Krylov for box sections in head seas.
    Integrated along the ship with the ``(1, x - x_G)`` weights, plus the ``rho g V z_B - m g z_G``
    pitch restoring term, it gives a 2-DOF system like the BEM one. Valid at low frequency
    (long waves); no 3-D end effects, no forward speed.
    """
    omega = np.asarray(omega_rad_s, dtype=float).ravel()
    if omega.size == 0 or np.any(omega <= 0) or np.any(np.diff(omega) <= 0):
        raise ValueError("strip_theory_estimate: omega_rad_s must be > 0 and strictly increasing")
    rho, g = float(water_density_kg_per_m3), float(gravity_m_per_s2)
    x_mid = 0.5 * (hull.station_x_m[0] + hull.station_x_m[-1])
    x_g = float(centre_of_gravity_m[0])
    x = np.unique(np.concatenate([np.linspace(hull.station_x_m[0], hull.station_x_m[-1], n_sections + 1), hull.station_x_m]))
    b = hull.breadth_at(x)
    t_mean = hull.section_area_coefficient * hull.draft_m
    k = wavenumber_rad_per_m(omega, math.inf, g)
    lever = x - x_g
    wts = np.stack([np.ones_like(x), lever])  # (2, n_x)
    a_sec = rho * np.pi * b**2 / 8.0
    c_sec = rho * g * b
    a_mat = np.zeros((omega.size, 2, 2))
    b_mat = np.zeros((omega.size, 2, 2))
    f = np.zeros((omega.size, 2), dtype=complex)
    for n, (w, kk) in enumerate(zip(omega, k, strict=True)):
        abar = 2.0 * np.sin(kk * b / 2.0) * np.exp(-kk * hull.draft_m)
        d_sec = rho * g**2 * abar**2 / w**3
        a_mat[n] = np.trapezoid(a_sec * wts[:, None, :] * wts[None, :, :], x, axis=-1)
        b_mat[n] = np.trapezoid(d_sec * wts[:, None, :] * wts[None, :, :], x, axis=-1)
        zeta_star = np.exp(-kk * t_mean) * np.exp(1j * kk * (x - x_mid))
        f[n] = np.trapezoid((c_sec - w**2 * a_sec + 1j * w * d_sec) * zeta_star * wts, x, axis=-1)
    m = mass_matrix(mass_kg, pitch_radius_of_gyration_m)
    c = hydrostatic_stiffness_matrix(
        hull, mass_kg=mass_kg, centre_of_gravity_m=centre_of_gravity_m, water_density_kg_per_m3=rho, gravity_m_per_s2=g
    )
    heave, pitch = solve_heave_pitch(omega, a_mat, b_mat, f, m, c)
    return RigidBodyMotions(
        omega_rad_s=omega,
        heave_rao_m_per_m=heave,
        pitch_rao_rad_per_m=pitch,
        added_mass=a_mat,
        radiation_damping=b_mat,
        excitation_force=f,
        reference_x_m=x_g,
        mass_matrix=m,
        hydrostatic_stiffness=c,
        wave_phase_reference_x_m=x_mid,
        wavenumber_rad_per_m=k,
        source="strip theory estimate",
    )
