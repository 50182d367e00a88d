"""Rigid-body heave-pitch physics: dispersion, hydrostatics, mass, the equation of motion.

Pure functions in seafast's DOFs (heave at the CoG x, pitch bow up; conventions in
:mod:`seafast.excitation.hydrodynamics`), shared by the BEM, the file importers and the strip
theory estimate.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
from numpy.typing import ArrayLike, NDArray

from seafast.vessel.hull_form import HullForm
from seafast.vessel.hull_mesh import section_profile

__all__ = [
    "wavenumber_rad_per_m",
    "hydrostatic_stiffness_matrix",
    "mass_matrix",
    "solve_heave_pitch",
    "solve_rigid_body",
    "base_vessel_mass_properties",
    "transverse_metacentric_height_m",
    "roll_hydrostatic_stiffness_Nm_per_rad",
]


def wavenumber_rad_per_m(omega_rad_s: ArrayLike, water_depth_m: float = math.inf, gravity_m_per_s2: float = 9.81) -> NDArray[np.float64]:
    """Wave number from the linear dispersion relation ``omega^2 = g k tanh(k h)`` [rad/m]."""
    w = np.asarray(omega_rad_s, dtype=float)
    k = w**2 / gravity_m_per_s2
    if math.isinf(water_depth_m):
        return k
    h = float(water_depth_m)
    k = np.where(k > 0, k, 0.0)
    k = np.maximum(k, w / math.sqrt(gravity_m_per_s2 * h))
    for _ in range(100):  # Newton on f(k) = g k tanh(kh) - w^2
        th = np.tanh(k * h)
        f = gravity_m_per_s2 * k * th - w**2
        df = gravity_m_per_s2 * (th + k * h * (1 - th**2))
        dk = np.where(df > 0, f / np.where(df > 0, df, 1.0), 0.0)
        k = k - dk
        if np.all(np.abs(dk) <= 1e-14 * np.maximum(k, 1e-30)):
            break
    return k


def _section_centroid_below_wl(hull: HullForm) -> float:
    """Height of the sectional-area centroid relative to the waterline [m] (negative)."""
    prof = section_profile(hull.section_area_coefficient, hull.draft_m)
    poly = np.vstack([prof, [[0.0, 0.0]]])  # close along the centre line and the waterline
    y, z = poly[:, 0], poly[:, 1]
    cross = y * np.roll(z, -1) - np.roll(y, -1) * z
    area = 0.5 * np.sum(cross)
    return float(np.sum((z + np.roll(z, -1)) * cross) / (6.0 * area))


def _x_grid(hull: HullForm, n: int = 4001) -> NDArray[np.float64]:
    return np.unique(np.concatenate([np.linspace(hull.station_x_m[0], hull.station_x_m[-1], n), hull.station_x_m]))


def hydrostatic_stiffness_matrix(
    hull: HullForm,
    *,
    mass_kg: float,
    centre_of_gravity_m: Sequence[float],
    water_density_kg_per_m3: float = 1025.0,
    gravity_m_per_s2: float = 9.81,
) -> NDArray[np.float64]:
    """Heave-pitch hydrostatic stiffness of the wall-sided hull about the CoG x (seafast DOFs).

    ``C_ww = rho g A_wp``; ``C_wt = C_tw = rho g int b (x - x_G) dx``;
    ``C_tt = rho g int b (x - x_G)^2 dx + rho g V z_B - m g z_G`` with heights relative to the
    waterline (``z_G`` given above the keel in ``centre_of_gravity_m``).

    Returns
    -------
    ndarray (2, 2)
        [[N/m, N/rad], [N, N m/rad]].
    """
    x = _x_grid(hull)
    b = hull.breadth_at(x)
    xg, zg_keel = float(centre_of_gravity_m[0]), float(centre_of_gravity_m[2])
    rg = water_density_kg_per_m3 * gravity_m_per_s2
    c11 = rg * np.trapezoid(b, x)
    c12 = rg * np.trapezoid(b * (x - xg), x)
    c22 = rg * np.trapezoid(b * (x - xg) ** 2, x)
    zb = _section_centroid_below_wl(hull)
    zg = zg_keel - hull.draft_m
    c22 += rg * hull.displaced_volume_m3() * zb - mass_kg * gravity_m_per_s2 * zg
    return np.array([[c11, c12], [c12, c22]])


def transverse_metacentric_height_m(hull: HullForm, vertical_centre_of_gravity_m: float) -> float:
    """GM = KB + BM - KG of the wall-sided hull at its design draught [m] (all heights above the keel).

    ``KB = T + z_B`` (``z_B`` the sectional-area centroid below the waterline: ``T/2`` for a box section) and
    ``BM = I_T / V`` with the waterplane's transverse second moment ``I_T = int b^3 / 12 dx``. A box barge gives
    ``T/2 + B^2 / (12 T) - KG``.
    """
    x = _x_grid(hull)
    i_t = float(np.trapezoid(hull.breadth_at(x) ** 3, x)) / 12.0
    volume = hull.displaced_volume_m3()
    kb = hull.draft_m + _section_centroid_below_wl(hull)
    return kb + i_t / volume - float(vertical_centre_of_gravity_m)


def roll_hydrostatic_stiffness_Nm_per_rad(
    hull: HullForm,
    *,
    mass_kg: float,
    centre_of_gravity_m: Sequence[float],
    water_density_kg_per_m3: float = 1025.0,
    gravity_m_per_s2: float = 9.81,
) -> float:
    """Roll restoring ``C44 = rho g (I_T + V z_B) - m g z_G`` [N m/rad] (heights from the waterline; z_G given above the keel).

    With the ship floating freely (``m = rho V``) this is ``rho g V GM``
    (:func:`transverse_metacentric_height_m`), the form of the pitch term of :func:`hydrostatic_stiffness_matrix`.
    """
    rg = water_density_kg_per_m3 * gravity_m_per_s2
    x = _x_grid(hull)
    i_t = float(np.trapezoid(hull.breadth_at(x) ** 3, x)) / 12.0
    zg = float(centre_of_gravity_m[2]) - hull.draft_m
    return rg * (i_t + hull.displaced_volume_m3() * _section_centroid_below_wl(hull)) - float(mass_kg) * gravity_m_per_s2 * zg


def mass_matrix(mass_kg: float, pitch_radius_of_gyration_m: float) -> NDArray[np.float64]:
    """Rigid-body mass matrix about the CoG: ``diag(m, m r_yy^2)`` [kg, kg m^2]."""
    return np.diag([float(mass_kg), float(mass_kg) * float(pitch_radius_of_gyration_m) ** 2])


def solve_heave_pitch(
    omega_rad_s: ArrayLike,
    added_mass: ArrayLike,
    radiation_damping: ArrayLike,
    excitation_force: ArrayLike,
    mass_matrix_: ArrayLike,
    hydrostatic_stiffness: ArrayLike,
) -> tuple[NDArray[np.complex128], NDArray[np.complex128]]:
    """Solve ``[-omega^2 (M + A) + i omega B + C] X = F`` per frequency (seafast conventions).

    Returns
    -------
    (heave [m/m], pitch [rad/m]), each complex (n_w,).
    """
    w = np.asarray(omega_rad_s, dtype=float)
    a = np.asarray(added_mass, dtype=float)
    b = np.asarray(radiation_damping, dtype=float)
    f = np.asarray(excitation_force, dtype=complex)
    m = np.asarray(mass_matrix_, dtype=float)
    c = np.asarray(hydrostatic_stiffness, dtype=float)
    z = -(w[:, None, None] ** 2) * (m[None] + a) + 1j * w[:, None, None] * b + c[None]
    x = np.linalg.solve(z, f[..., None])[..., 0]
    return x[:, 0], x[:, 1]


def solve_rigid_body(
    omega_rad_s: ArrayLike,
    added_mass: ArrayLike,
    radiation_damping: ArrayLike,
    excitation_force: ArrayLike,
    mass_matrix_: ArrayLike,
    hydrostatic_stiffness: ArrayLike,
) -> NDArray[np.complex128]:
    """Solve ``[-omega^2 (M + A) + i omega B + C] X = F`` per frequency, any number of DOFs.

    Returns
    -------
    ndarray (n_w, n_dof)
        Complex amplitudes per metre of wave amplitude, in the DOF order of the inputs.
    """
    z = rigid_body_impedance(omega_rad_s, added_mass, radiation_damping, mass_matrix_, hydrostatic_stiffness)
    return np.asarray(np.linalg.solve(z, np.asarray(excitation_force, dtype=complex)[..., None])[..., 0], dtype=np.complex128)


def rigid_body_impedance(
    omega_rad_s: ArrayLike, added_mass: ArrayLike, radiation_damping: ArrayLike, mass_matrix_: ArrayLike, hydrostatic_stiffness: ArrayLike
) -> NDArray[np.complex128]:
    """``-omega^2 (M + A) + i omega B + C`` per frequency, (n_w, n_dof, n_dof), in the SI units of each DOF."""
    w = np.asarray(omega_rad_s, dtype=float)
    return np.asarray(
        -(w[:, None, None] ** 2) * (np.asarray(mass_matrix_, dtype=float)[None] + np.asarray(added_mass, dtype=float))
        + 1j * w[:, None, None] * np.asarray(radiation_damping, dtype=float)
        + np.asarray(hydrostatic_stiffness, dtype=float)[None],
        dtype=complex,
    )


def base_vessel_mass_properties(hull: HullForm, *, water_density_kg_per_m3: float = 1025.0) -> dict:
    """Documented default mass properties of the vessel (keyword arguments of :func:`compute_motions`).

    * ``mass_kg = rho * V`` (free floating at the design draught; 1025 * 32 000 kg for the base hull),
    * ``centre_of_gravity_m = (x_LCB, 0, 8.0)``: x at the longitudinal centre of buoyancy (even
      keel), z = 8 m **above the keel** (internally 8 - T = 1.5 m above the waterline),
    * ``pitch_radius_of_gyration_m = 0.25 L``.
    """
    return {
        "mass_kg": float(water_density_kg_per_m3 * hull.displaced_volume_m3()),
        "centre_of_gravity_m": (float(hull.centre_of_buoyancy_x_m()), 0.0, 8.0),
        "pitch_radius_of_gyration_m": 0.25 * hull.length_m,
    }
