"""The six rigid-body motions at any wave heading (docs/headings.md): coefficients, the loaded ship's equation, RAOs.

Conventions (docs/headings.md#1-conventions): time ``exp(+i omega t)``; ship frame ``x`` forward from the AP, ``y`` to
port, ``z`` up; DOFs in the order (surge, sway, heave, roll, pitch, yaw) about the centre of gravity; surge, sway and
heave [m], roll ``phi`` about ``x`` (starboard down +), pitch ``theta = dz/dx`` (bow **up** +, the project's sign:
``theta = -eta_5`` of capytaine and WAMIT), yaw ``psi`` about ``z`` (bow to port +). Wave heading ``beta`` = the
direction the waves travel, from ``x`` towards ``y``; the incident wave per metre of amplitude is
``exp(-i k ((x - x_mid) cos beta + y sin beta))``, its crest on the centreline amidships at ``t = 0`` (head seas,
``beta = 180 deg``, are the heave-pitch model's wave).

:func:`capytaine_six_dof_coefficients` reads a capytaine dataset (six DOFs, ``wave_direction`` 0-180 deg) and extends it
to 360 deg by the hull's port-starboard symmetry; :func:`six_dof_motions` moves the coefficients to the loaded ship's
centre of gravity and builds :class:`SixDofMotions`, whose :meth:`~SixDofMotions.rao_at` solves the 6x6 equation at any
frequency and heading with the additional linear roll damping.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import xarray as xr
from numpy.typing import NDArray

from seafast.excitation.hydrodynamics.equations import (
    hydrostatic_stiffness_matrix,
    roll_hydrostatic_stiffness_Nm_per_rad,
    wavenumber_rad_per_m,
)
from seafast.excitation.hydrodynamics.heading_motions import SixDofMotions
from seafast.vessel.hull_form import HullForm

__all__ = [
    "SixDofCoefficients",
    "LoadedShip",
    "capytaine_six_dof_coefficients",
    "rigid_transfer_matrix",
    "six_dof_hydrostatic_stiffness",
    "six_dof_motions",
    "mirrored_headings",
]

_SIGN = np.array([1.0, 1.0, 1.0, 1.0, -1.0, 1.0])
"""capytaine / WAMIT DOFs -> seafast's (pitch bow up)."""

_MIRROR = np.array([1.0, -1.0, 1.0, -1.0, 1.0, -1.0])
"""y -> -y: sway, roll and yaw change sign (any sign convention of pitch)."""

_CAPYTAINE_DOFS = ("Surge", "Sway", "Heave", "Roll", "Pitch", "Yaw")


@dataclass(frozen=True)
class SixDofCoefficients:
    """Hydrodynamic coefficients of the six DOFs in capytaine's / WAMIT's signs (pitch bow down) about one point.

    Attributes
    ----------
    omega_rad_s, wavenumber_rad_per_m
        Frequencies [rad/s] ascending and their wave numbers [rad/m], shape (n_w,).
    headings_deg
        Wave headings [deg], ascending over [0, 360), shape (n_b,).
    added_mass, radiation_damping
        (n_w, 6, 6) [kg, kg m, kg m^2 and the same per second].
    excitation_force
        (n_w, n_b, 6) per metre of wave amplitude, ``exp(+i omega t)`` [N/m, N m/m], the wave's crest at
        ``wave_phase_origin_x_m`` on the centreline at ``t = 0``.
    reference_x_m, reference_z_wl_m
        The point the coefficients refer to: x from the AP [m], height above the waterline [m] (on the centreline).
    wave_phase_origin_x_m
        x from the AP [m] of the source's wave phase origin.
    """

    omega_rad_s: NDArray[np.float64]
    wavenumber_rad_per_m: NDArray[np.float64]
    headings_deg: NDArray[np.float64]
    added_mass: NDArray[np.float64]
    radiation_damping: NDArray[np.float64]
    excitation_force: NDArray[np.complex128]
    reference_x_m: float
    reference_z_wl_m: float
    wave_phase_origin_x_m: float


def mirrored_headings(headings_deg: NDArray[np.float64], excitation: NDArray[np.complex128]) -> tuple[NDArray, NDArray]:
    """Headings over [0, 360) from the headings within [0, 180] by the hull's port-starboard symmetry (others are dropped).

    The mirror image of a wave of heading ``beta`` is the wave of ``360 - beta``; mirrored, sway, roll and yaw change
    sign. ``excitation`` has shape (n_w, n_b, 6) in any sign convention of pitch.

    Returns
    -------
    (headings [deg] ascending, excitation (n_w, n_b', 6))
    """
    b_all = np.asarray(headings_deg, dtype=float) % 360.0
    keep = b_all <= 180.0 + 1e-9
    if np.count_nonzero(keep) < 2:
        raise ValueError(f"mirrored_headings: headings {b_all.tolist()} deg; at least two within [0, 180] deg are needed")
    b, excitation = b_all[keep], np.asarray(excitation)[:, keep, :]
    inner = (b > 1e-9) & (b < 180.0 - 1e-9)
    heads = np.concatenate([b, 360.0 - b[inner]])
    exc = np.concatenate([excitation, excitation[:, inner, :] * _MIRROR], axis=1)
    order = np.argsort(heads)
    return heads[order], exc[:, order, :]


def _dataset_by_omega(ds: xr.Dataset) -> xr.Dataset:
    """``ds`` with ``omega`` as its frequency dimension, sorted."""
    if "omega" not in ds.dims:
        if "omega" not in ds.coords:
            raise ValueError("capytaine dataset: no 'omega' coordinate")
        ds = ds.swap_dims({next(d for d in ds["omega"].dims): "omega"})
    return ds.sortby("omega")


def capytaine_six_dof_coefficients(ds: xr.Dataset, origin_x_m: float, gravity_m_per_s2: float) -> SixDofCoefficients:
    """The six-DOF coefficients of a capytaine dataset over its headings, mirrored to [0, 360).

    Parameters
    ----------
    ds
        capytaine dataset with the six rigid-body DOFs (capytaine's names ``Surge`` ... ``Yaw``), radiated and
        influenced, and ``excitation_force`` over ``wave_direction`` [rad] within [0, pi].
    origin_x_m
        seafast x [m] of the dataset's origin (its wave phase origin).
    gravity_m_per_s2
        For the wave numbers when the dataset has none.

    Raises
    ------
    ValueError
        A DOF, variable or the ``wave_direction`` dimension missing, or headings outside [0, 180] deg.
    """
    ds = _dataset_by_omega(ds)
    for v in ("added_mass", "radiation_damping", "excitation_force"):
        if v not in ds:
            raise ValueError(f"capytaine dataset: variable {v!r} missing")
    exc = ds["excitation_force"]
    if "wave_direction" not in exc.dims:
        raise ValueError("capytaine dataset: excitation_force has no 'wave_direction' dimension (one heading only)")
    names_in = [str(v).lower() for v in ds["influenced_dof"].values]
    names_rad = [str(v).lower() for v in ds["radiating_dof"].values]
    missing = [d for d in _CAPYTAINE_DOFS if d.lower() not in names_in or d.lower() not in names_rad]
    if missing:
        raise ValueError(f"capytaine dataset: dofs {missing} missing (found {list(ds['radiating_dof'].values)})")
    rows = [names_in.index(d.lower()) for d in _CAPYTAINE_DOFS]
    cols = [names_rad.index(d.lower()) for d in _CAPYTAINE_DOFS]

    def matrix(name: str) -> NDArray[np.float64]:
        da = ds[name]
        for d in [d for d in da.dims if d not in ("omega", "influenced_dof", "radiating_dof")]:
            da = da.isel({d: 0})
        return np.real(da.transpose("omega", "influenced_dof", "radiating_dof").values[:, rows][:, :, cols])

    for d in [d for d in exc.dims if d not in ("omega", "wave_direction", "influenced_dof")]:
        exc = exc.isel({d: 0})
    beta = np.degrees(np.asarray(exc["wave_direction"].values, dtype=float))
    f = np.conj(exc.transpose("omega", "wave_direction", "influenced_dof").values[:, :, rows])
    headings, f = mirrored_headings(np.round(beta, 9), f)
    omega = np.asarray(ds["omega"].values, dtype=float)
    if "wavenumber" in ds.coords or "wavenumber" in ds:
        k = np.broadcast_to(np.asarray(ds["wavenumber"].values, dtype=float), omega.shape).copy()
    else:
        depth = float(ds["water_depth"].values) if "water_depth" in ds.coords else math.inf
        k = wavenumber_rad_per_m(omega, depth, gravity_m_per_s2)
    rc = (
        np.asarray(ds["rotation_center"].values, dtype=float).reshape(-1)[:3]
        if "rotation_center" in ds.coords or "rotation_center" in ds
        else np.zeros(3)
    )
    return SixDofCoefficients(
        omega, k, headings, matrix("added_mass"), matrix("radiation_damping"), f, origin_x_m + float(rc[0]), float(rc[2]), origin_x_m
    )


def rigid_transfer_matrix(old_minus_new_m: Sequence[float]) -> NDArray[np.float64]:
    """``P`` (6, 6) with ``q_old = P q_new`` when the reference point of rigid-body DOFs moves by ``-d`` (``d = old - new``).

    A point ``p`` moves by ``xi + Omega x (p - r)``, so ``xi_old = xi_new + Omega x (r_old - r_new) = xi_new - [d]x Omega``;
    matrices transform as ``P^T A P``, forces as ``P^T F``. Right-handed rotations (capytaine's / WAMIT's signs).
    """
    dx, dy, dz = (float(c) for c in old_minus_new_m)
    skew = np.array([[0.0, -dz, dy], [dz, 0.0, -dx], [-dy, dx, 0.0]])
    p = np.eye(6)
    p[:3, 3:] = -skew
    return p


@dataclass(frozen=True)
class LoadedShip:
    """The loaded ship's mass properties for the six-DOF equation.

    Attributes
    ----------
    mass_kg
        Mass [kg].
    centre_of_gravity_m
        (x from the AP, y, KG above the keel) [m]; y is 0 (the loading is symmetric).
    roll_radius_m, pitch_radius_m, yaw_radius_m
        Radii of gyration about the axes through the CoG [m].
    roll_damping_ratio
        Additional linear roll damping, fraction of critical ``2 sqrt((I44 + A44) C44)`` [-].
    """

    mass_kg: float
    centre_of_gravity_m: tuple[float, float, float]
    roll_radius_m: float
    pitch_radius_m: float
    yaw_radius_m: float
    roll_damping_ratio: float = 0.0

    def mass_matrix(self) -> NDArray[np.float64]:
        """``diag(m, m, m, m r_xx^2, m r_yy^2, m r_zz^2)`` about the CoG [kg, kg m^2] (products of inertia neglected)."""
        m = float(self.mass_kg)
        return np.diag([m, m, m, m * self.roll_radius_m**2, m * self.pitch_radius_m**2, m * self.yaw_radius_m**2])


def six_dof_hydrostatic_stiffness(
    hull: HullForm, ship: LoadedShip, water_density_kg_per_m3: float, gravity_m_per_s2: float
) -> NDArray[np.float64]:
    """Hydrostatic stiffness (6, 6) of the wall-sided hull about the CoG, seafast's DOFs and signs.

    The heave-pitch block is :func:`~seafast.excitation.hydrodynamics.equations.hydrostatic_stiffness_matrix`; roll
    ``C44 = rho g V GM`` (:func:`~seafast.excitation.hydrodynamics.equations.roll_hydrostatic_stiffness_Nm_per_rad`);
    roll-yaw ``C46 = -rho g V (x_B - x_G)`` (zero when the ship floats level, x_B = x_G); no restoring in surge, sway, yaw.
    """
    c = np.zeros((6, 6))
    m, cog = ship.mass_kg, ship.centre_of_gravity_m
    rho, g = water_density_kg_per_m3, gravity_m_per_s2
    heave_pitch = hydrostatic_stiffness_matrix(hull, mass_kg=m, centre_of_gravity_m=cog, water_density_kg_per_m3=rho, gravity_m_per_s2=g)
    c[np.ix_([2, 4], [2, 4])] = heave_pitch
    c[3, 3] = roll_hydrostatic_stiffness_Nm_per_rad(
        hull, mass_kg=m, centre_of_gravity_m=cog, water_density_kg_per_m3=rho, gravity_m_per_s2=g
    )
    rg_v = water_density_kg_per_m3 * gravity_m_per_s2 * hull.displaced_volume_m3()
    c[3, 5] = -rg_v * (hull.centre_of_buoyancy_x_m() - ship.centre_of_gravity_m[0])
    return c


def six_dof_motions(
    coefficients: SixDofCoefficients,
    hull: HullForm,
    ship: LoadedShip,
    *,
    water_density_kg_per_m3: float = 1025.0,
    gravity_m_per_s2: float = 9.81,
    source: str = "",
) -> SixDofMotions:
    """The loaded ship's six motions: ``coefficients`` moved to its CoG, in seafast's signs, with its mass and stiffness.

    Parameters
    ----------
    coefficients
        From :func:`capytaine_six_dof_coefficients` (or WAMIT), capytaine's signs, about their reference point.
    hull
        Hull form (hydrostatics, midship).
    ship
        Mass properties (CoG with KG above the keel) and the additional roll damping ratio.
    water_density_kg_per_m3, gravity_m_per_s2
        For the hydrostatics.
    source
        Free text kept in the record.
    """
    c = coefficients
    x_mid = 0.5 * (hull.station_x_m[0] + hull.station_x_m[-1])
    x_g, _, kg = ship.centre_of_gravity_m
    p = rigid_transfer_matrix((c.reference_x_m - x_g, 0.0, c.reference_z_wl_m - (kg - hull.draft_m)))
    a = p.T @ c.added_mass @ p
    b = p.T @ c.radiation_damping @ p
    f = c.excitation_force @ p
    # the source's wave crest at its origin -> seafast's crest amidships: exp(-i k cos(beta) (x_o - x_mid))
    cos_b = np.cos(np.radians(c.headings_deg))
    f = f * np.exp(-1j * c.wavenumber_rad_per_m[:, None] * cos_b[None, :] * (c.wave_phase_origin_x_m - x_mid))[:, :, None]
    s = np.diag(_SIGN)
    return SixDofMotions(
        omega_rad_s=c.omega_rad_s,
        wavenumber_rad_per_m=c.wavenumber_rad_per_m,
        headings_deg=c.headings_deg,
        added_mass=s @ a @ s,
        radiation_damping=s @ b @ s,
        excitation_force=f * _SIGN,
        mass_matrix=ship.mass_matrix(),
        hydrostatic_stiffness=six_dof_hydrostatic_stiffness(hull, ship, water_density_kg_per_m3, gravity_m_per_s2),
        roll_damping_ratio=ship.roll_damping_ratio,
        reference_x_m=float(x_g),
        reference_z_m=float(kg),
        wave_phase_reference_x_m=float(x_mid),
        source=source,
    )
