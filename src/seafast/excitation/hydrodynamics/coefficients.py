"""Hydrodynamic coefficients in capytaine's or WAMIT's DOFs to seafast motions (the importers' back end).

Both sources use a rotation about ``+y`` (``eta_5``, bow down), so ``theta = -eta_5``; their
excitation (already in ``exp(+i omega t)`` here) refers to the incident wave at their origin,
moved to the crest at midship; the coefficients are moved from their reference point to the
CoG. With surge in the data, surge, heave and pitch are also solved together (3-DOF).
Conventions: :mod:`seafast.excitation.hydrodynamics`.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

import numpy as np
from numpy.typing import NDArray

from seafast.excitation.hydrodynamics.equations import hydrostatic_stiffness_matrix, mass_matrix, solve_heave_pitch, solve_rigid_body
from seafast.excitation.hydrodynamics.motions import RigidBodyMotions
from seafast.vessel.hull_form import HullForm

__all__ = ["motions_from_rigid_coefficients"]

_T = np.diag([1.0, -1.0])  # capytaine/WAMIT (heave, eta5) -> seafast (heave, theta)
_T3 = np.diag([1.0, 1.0, -1.0])  # capytaine/WAMIT (surge, heave, eta5) -> seafast (surge, heave, theta)


def _shift_reference(dx_ref_minus_new: float) -> NDArray[np.float64]:
    """Matrix ``P`` with ``q_old = P q_new`` when pitch moves from ``x_old`` to ``x_new``.

    ``w_old = w_new + theta (x_old - x_new)``; forces transform with ``P^T``.
    """
    return np.array([[1.0, dx_ref_minus_new], [0.0, 1.0]])


def motions_from_rigid_coefficients(
    omega: NDArray[np.float64],
    k: NDArray[np.float64],
    a_eta: NDArray[np.float64],
    b_eta: NDArray[np.float64],
    f_eta_plus: NDArray[np.complex128],
    hull: HullForm,
    *,
    coeff_reference_x_m: float,
    wave_phase_origin_x_m: float,
    mass_kg: float,
    centre_of_gravity_m: Sequence[float],
    pitch_radius_of_gyration_m: float,
    water_density_kg_per_m3: float,
    gravity_m_per_s2: float,
    source: str,
    coeff_reference_z_wl_m: float = 0.0,
) -> RigidBodyMotions:
    """Common back end of the importers.

    Inputs in (heave, eta5) DOFs (eta5 = rotation about +y, bow down) about
    ``coeff_reference_x_m``, excitation in the ``exp(+i omega t)`` convention with the incident
    wave phase referred to ``wave_phase_origin_x_m``. With 3x3 inputs the DOFs are (surge,
    heave, eta5) about the point (``coeff_reference_x_m``, ``coeff_reference_z_wl_m`` above the
    waterline), and surge, heave and pitch are solved together (:func:`_coupled_surge_motions`).

    Parameters
    ----------
    omega, k
        Frequencies [rad/s] (ascending) and their wave numbers [rad/m], shape (n_w,).
    a_eta, b_eta
        Added mass and radiation damping, shape (n_w, d, d), d = 2 or 3 [kg, kg m, kg m^2 and
        the same per second].
    f_eta_plus
        Excitation per metre of wave amplitude, shape (n_w, d) [N/m, N m/m].
    hull
        Hull form (hydrostatic stiffness, midship).
    coeff_reference_x_m, coeff_reference_z_wl_m
        Reference point of the coefficients: x from the AP [m], height above the waterline [m].
    wave_phase_origin_x_m
        x from the AP [m] where the source's incident wave has its crest at ``t = 0``.
    mass_kg, centre_of_gravity_m, pitch_radius_of_gyration_m, water_density_kg_per_m3, gravity_m_per_s2
        As in :func:`~seafast.excitation.hydrodynamics.bem.compute_motions` (CoG z above the keel).
    source
        Free text stored in the result.

    Returns
    -------
    RigidBodyMotions
        About the CoG x, phases relative to the wave crest at midship; with surge fields when
        d = 3.
    """
    surge = np.shape(a_eta)[-1] == 3
    # heave and pitch by the 2-DOF solve of their block (unchanged by surge), plus the coupled solution with surge
    two = _heave_pitch_motions(
        omega,
        k,
        np.asarray(a_eta)[:, 1:, 1:] if surge else a_eta,
        np.asarray(b_eta)[:, 1:, 1:] if surge else b_eta,
        np.asarray(f_eta_plus)[:, 1:] if surge else f_eta_plus,
        hull,
        coeff_reference_x_m=coeff_reference_x_m,
        wave_phase_origin_x_m=wave_phase_origin_x_m,
        mass_kg=mass_kg,
        centre_of_gravity_m=centre_of_gravity_m,
        pitch_radius_of_gyration_m=pitch_radius_of_gyration_m,
        water_density_kg_per_m3=water_density_kg_per_m3,
        gravity_m_per_s2=gravity_m_per_s2,
        source=source,
    )
    if not surge:
        return two
    x3 = _coupled_surge_motions(
        omega,
        k,
        a_eta,
        b_eta,
        f_eta_plus,
        hull,
        coeff_reference_x_m=coeff_reference_x_m,
        coeff_reference_z_wl_m=coeff_reference_z_wl_m,
        wave_phase_origin_x_m=wave_phase_origin_x_m,
        mass_kg=mass_kg,
        centre_of_gravity_m=centre_of_gravity_m,
        pitch_radius_of_gyration_m=pitch_radius_of_gyration_m,
        water_density_kg_per_m3=water_density_kg_per_m3,
        gravity_m_per_s2=gravity_m_per_s2,
    )
    return replace(two, surge_rao_m_per_m=x3[:, 0], coupled_heave_rao_m_per_m=x3[:, 1], coupled_pitch_rao_rad_per_m=x3[:, 2])


def _heave_pitch_motions(
    omega: NDArray[np.float64],
    k: NDArray[np.float64],
    a_eta: NDArray[np.float64],
    b_eta: NDArray[np.float64],
    f_eta_plus: NDArray[np.complex128],
    hull: HullForm,
    *,
    coeff_reference_x_m: float,
    wave_phase_origin_x_m: float,
    mass_kg: float,
    centre_of_gravity_m: Sequence[float],
    pitch_radius_of_gyration_m: float,
    water_density_kg_per_m3: float,
    gravity_m_per_s2: float,
    source: str,
) -> RigidBodyMotions:
    """The 2-DOF heave-pitch motions about the CoG x from (heave, eta5) coefficients (see :func:`motions_from_rigid_coefficients`)."""
    x_mid = 0.5 * (hull.station_x_m[0] + hull.station_x_m[-1])
    x_g = float(centre_of_gravity_m[0])
    # eta5 -> theta (bow up)
    a = _T @ a_eta @ _T
    b = _T @ b_eta @ _T
    f = f_eta_plus @ _T
    # incident wave phase: unit crest at the origin <-> seafast wave exp(i k (x - x_mid))
    f = f * np.exp(1j * k * (wave_phase_origin_x_m - x_mid))[:, None]
    # move the pitch reference from the coefficient reference to the CoG x
    p = _shift_reference(coeff_reference_x_m - x_g)
    a = p.T @ a @ p
    b = p.T @ b @ p
    f = f @ p
    m = mass_matrix(mass_kg, pitch_radius_of_gyration_m)
    c = hydrostatic_stiffness_matrix(
        hull,
        mass_kg=mass_kg,
        centre_of_gravity_m=centre_of_gravity_m,
        water_density_kg_per_m3=water_density_kg_per_m3,
        gravity_m_per_s2=gravity_m_per_s2,
    )
    heave, pitch = solve_heave_pitch(omega, a, b, f, m, c)
    return RigidBodyMotions(
        omega_rad_s=omega,
        heave_rao_m_per_m=heave,
        pitch_rao_rad_per_m=pitch,
        added_mass=a,
        radiation_damping=b,
        excitation_force=f,
        reference_x_m=x_g,
        mass_matrix=m,
        hydrostatic_stiffness=c,
        wave_phase_reference_x_m=x_mid,
        wavenumber_rad_per_m=k,
        source=source,
        reference_z_m=float(centre_of_gravity_m[2]),
    )


def _shift_reference_3(dx_new_minus_old: float, dz_new_minus_old: float) -> NDArray[np.float64]:
    """``P`` with ``q_old = P q_new`` for (surge, heave, theta) when the reference point moves.

    A point's displacement is ``(X - theta (z - z_ref), W + theta (x - x_ref))``, so
    ``X_old = X_new + theta dz`` and ``W_old = W_new - theta dx`` (``d = new - old``);
    forces transform with ``P^T``.
    """
    return np.array([[1.0, 0.0, dz_new_minus_old], [0.0, 1.0, -dx_new_minus_old], [0.0, 0.0, 1.0]])


def _coupled_surge_motions(
    omega: NDArray[np.float64],
    k: NDArray[np.float64],
    a_eta: NDArray[np.float64],
    b_eta: NDArray[np.float64],
    f_eta_plus: NDArray[np.complex128],
    hull: HullForm,
    *,
    coeff_reference_x_m: float,
    coeff_reference_z_wl_m: float,
    wave_phase_origin_x_m: float,
    mass_kg: float,
    centre_of_gravity_m: Sequence[float],
    pitch_radius_of_gyration_m: float,
    water_density_kg_per_m3: float,
    gravity_m_per_s2: float,
) -> NDArray[np.complex128]:
    """Surge, heave and pitch solved together about the CoG (x_G, z_G), from (surge, heave, eta5) data.

    Mass ``diag(m, m, m r^2)`` about the CoG; hydrostatic stiffness: the heave-pitch block of
    :func:`hydrostatic_stiffness_matrix` (no restoring in surge).

    Returns
    -------
    ndarray (n_w, 3)
        (surge [m/m], heave [m/m], pitch [rad/m]) per metre of wave amplitude, seafast conventions.
    """
    x_mid = 0.5 * (hull.station_x_m[0] + hull.station_x_m[-1])
    x_g, z_g_keel = float(centre_of_gravity_m[0]), float(centre_of_gravity_m[2])
    a = _T3 @ np.asarray(a_eta, dtype=float) @ _T3
    b = _T3 @ np.asarray(b_eta, dtype=float) @ _T3
    f = np.asarray(f_eta_plus, dtype=complex) @ _T3
    f = f * np.exp(1j * k * (wave_phase_origin_x_m - x_mid))[:, None]
    p = _shift_reference_3(x_g - coeff_reference_x_m, (z_g_keel - hull.draft_m) - coeff_reference_z_wl_m)
    a = p.T @ a @ p
    b = p.T @ b @ p
    f = f @ p
    m3 = np.zeros((3, 3))
    c3 = np.zeros((3, 3))
    m3[0, 0] = float(mass_kg)
    m3[1:, 1:] = mass_matrix(mass_kg, pitch_radius_of_gyration_m)
    c3[1:, 1:] = hydrostatic_stiffness_matrix(
        hull,
        mass_kg=mass_kg,
        centre_of_gravity_m=centre_of_gravity_m,
        water_density_kg_per_m3=water_density_kg_per_m3,
        gravity_m_per_s2=gravity_m_per_s2,
    )
    return solve_rigid_body(omega, a, b, f, m3, c3)
