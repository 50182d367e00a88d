"""Importing the vessel's hydrodynamics from a file: :func:`load_motions` (capytaine NetCDF or WAMIT)."""

from __future__ import annotations

import math
import os
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Literal

import numpy as np

from seafast.excitation.hydrodynamics.capytaine_io import motions_from_capytaine, read_capytaine_netcdf
from seafast.excitation.hydrodynamics.coefficients import motions_from_rigid_coefficients
from seafast.excitation.hydrodynamics.equations import wavenumber_rad_per_m
from seafast.excitation.hydrodynamics.memory_cache import HydrodynamicsCache
from seafast.excitation.hydrodynamics.motions import RigidBodyMotions
from seafast.excitation.hydrodynamics.six_dof import SixDofCoefficients, capytaine_six_dof_coefficients, mirrored_headings
from seafast.excitation.hydrodynamics.wamit import read_wamit_1, read_wamit_3, read_wamit_3_headings, wamit_has_surge
from seafast.vessel.hull_form import HullForm

__all__ = ["load_motions", "load_six_dof_coefficients"]


def load_motions(
    path: str | os.PathLike,
    hull: HullForm,
    *,
    mass_kg: float,
    centre_of_gravity_m: Sequence[float],
    pitch_radius_of_gyration_m: float,
    format: Literal["auto", "capytaine", "wamit"] = "auto",  # noqa: A002 - the public keyword users' scripts pass
    origin_x_m: float | None = None,
    ulen_m: float = 1.0,
    water_density_kg_per_m3: float = 1025.0,
    gravity_m_per_s2: float = 9.81,
    water_depth_m: float = math.inf,
    frequency_column: Literal["period", "omega"] = "period",
    memory_cache: HydrodynamicsCache | None = None,
) -> RigidBodyMotions:
    """Import hydrodynamic coefficients and solve heave and pitch with given mass properties.

    Parameters
    ----------
    path
        A capytaine NetCDF file (``.nc``, as written by ``capytaine.export_dataset``; complex
        values split and merged back with capytaine's ``merge_complex_values``), or a WAMIT
        output: the ``.1`` file, the ``.3`` file or their common stem (both must exist).
    hull
        Hull form (hydrostatics are computed from it, consistently with :func:`compute_motions`).
    mass_kg, centre_of_gravity_m, pitch_radius_of_gyration_m
        Mass properties, as in :func:`compute_motions` (z above keel).
    format
        ``"auto"``: ``.nc`` -> capytaine, otherwise WAMIT.
    origin_x_m
        seafast ``x`` (from the AP) of the file's coordinate origin, which is also the phase
        reference of its incident wave. Default: the ``seafast_origin_x_m`` attribute of a
        seafast-written capytaine file, otherwise ``L/2`` (midship).
    ulen_m
        WAMIT ``ULEN`` [m] (non-dimensionalising length).
    water_density_kg_per_m3, gravity_m_per_s2
        WAMIT's ``rho`` and ``g`` used to dimensionalise, and used for the hydrostatics.
    water_depth_m
        Water depth for the wave number (WAMIT only; capytaine files carry their wave numbers).
    frequency_column
        WAMIT: whether the first column holds periods [s] (default, WAMIT's usual output) or
        angular frequencies [rad/s].
    memory_cache
        Keeps a capytaine file's dataset for the next call (a study's next loading); None: read
        at every call.

    Notes
    -----
    WAMIT assumptions: modes 3 (heave) and 5 (pitch, rotation about +y, i.e. bow down with the
    body x-axis pointing forward, parallel to seafast x), coefficients about the WAMIT body
    origin, which lies on the waterline at ``x = origin_x_m``; head seas ``beta = 180 deg``;
    ``exp(+i omega t)`` with phases relative to the incident wave crest at the origin. When both
    files hold mode 1 (surge), surge, heave and pitch are solved together about the CoG (x and
    height); otherwise the heave-pitch coefficients are transferred to the CoG x, couplings
    with surge are ignored and the motions carry no surge (``surge_rao_m_per_m = None``).
    A capytaine file with a ``Surge`` dof is treated the same way.
    """
    p = Path(path)
    fmt = format
    if fmt == "auto":
        fmt = "capytaine" if p.suffix.lower() in (".nc", ".netcdf", ".cdf") else "wamit"
    mass = _MassProperties(mass_kg, centre_of_gravity_m, pitch_radius_of_gyration_m, water_density_kg_per_m3, gravity_m_per_s2)
    if fmt == "capytaine":
        ds = read_capytaine_netcdf(p) if memory_cache is None else memory_cache.dataset(p)
        return motions_from_capytaine(
            ds,
            hull,
            origin_x_m=origin_x_m,
            source=f"capytaine file {p}",
            mass_kg=mass.mass_kg,
            centre_of_gravity_m=mass.centre_of_gravity_m,
            pitch_radius_of_gyration_m=mass.pitch_radius_of_gyration_m,
            water_density_kg_per_m3=mass.water_density_kg_per_m3,
            gravity_m_per_s2=mass.gravity_m_per_s2,
        )
    if fmt != "wamit":
        raise ValueError(f"load_motions: unknown format {format!r}")
    return _wamit_motions(p, hull, mass, origin_x_m, ulen_m, water_depth_m, frequency_column)


@dataclass(frozen=True)
class _MassProperties:
    """The loading's mass properties and the water's, as :func:`load_motions` takes them."""

    mass_kg: float
    centre_of_gravity_m: Sequence[float]
    pitch_radius_of_gyration_m: float
    water_density_kg_per_m3: float
    gravity_m_per_s2: float


def _wamit_files(p: Path) -> tuple[Path, Path]:
    """The ``.1`` and ``.3`` files of ``p`` (either file, or their common stem); both must exist."""
    stem = p.with_suffix("") if p.suffix in (".1", ".3") else p
    f1, f3 = Path(f"{stem}.1"), Path(f"{stem}.3")
    for f in (f1, f3):
        if not f.is_file():
            raise FileNotFoundError(f"load_motions: WAMIT file {f} not found")
    return f1, f3


def _wamit_motions(
    p: Path,
    hull: HullForm,
    mass: _MassProperties,
    origin_x_m: float | None,
    ulen_m: float,
    water_depth_m: float,
    frequency_column: Literal["period", "omega"],
) -> RigidBodyMotions:
    """Motions from WAMIT ``.1``/``.3`` output (see :func:`load_motions`, Notes), on the frequencies both files hold."""
    f1, f3 = _wamit_files(p)
    rho, g = mass.water_density_kg_per_m3, mass.gravity_m_per_s2
    modes = (1, 3, 5) if wamit_has_surge(f1, f3) else (3, 5)
    w1, a, b = read_wamit_1(f1, ulen_m=ulen_m, water_density_kg_per_m3=rho, frequency_column=frequency_column, modes=modes)
    w3, x = read_wamit_3(f3, ulen_m=ulen_m, water_density_kg_per_m3=rho, gravity_m_per_s2=g, frequency_column=frequency_column, modes=modes)
    if w1.shape != w3.shape or not np.allclose(w1, w3, rtol=1e-6):
        common_w = np.intersect1d(np.round(w1, 9), np.round(w3, 9))
        if common_w.size == 0:
            raise ValueError("load_motions: the .1 and .3 files share no frequency")
        i1 = np.isin(np.round(w1, 9), common_w)
        i3 = np.isin(np.round(w3, 9), common_w)
        w1, a, b, x = w1[i1], a[i1], b[i1], x[i3]
    x_mid = 0.5 * (hull.station_x_m[0] + hull.station_x_m[-1])
    origin = x_mid if origin_x_m is None else float(origin_x_m)
    k = wavenumber_rad_per_m(w1, water_depth_m, g)
    return motions_from_rigid_coefficients(
        w1,
        k,
        a,
        b,
        x,
        hull,
        coeff_reference_x_m=origin,
        wave_phase_origin_x_m=origin,
        source=f"WAMIT files {f1}, {f3} (ULEN = {ulen_m} m)",
        mass_kg=mass.mass_kg,
        centre_of_gravity_m=mass.centre_of_gravity_m,
        pitch_radius_of_gyration_m=mass.pitch_radius_of_gyration_m,
        water_density_kg_per_m3=rho,
        gravity_m_per_s2=g,
    )


def load_six_dof_coefficients(
    path: str | os.PathLike,
    hull: HullForm,
    *,
    format: Literal["auto", "capytaine", "wamit"] = "auto",  # noqa: A002 - the keyword of load_motions
    origin_x_m: float | None = None,
    ulen_m: float = 1.0,
    water_density_kg_per_m3: float = 1025.0,
    gravity_m_per_s2: float = 9.81,
    water_depth_m: float = math.inf,
    frequency_column: Literal["period", "omega"] = "period",
    memory_cache: HydrodynamicsCache | None = None,
) -> SixDofCoefficients:
    """Import the six-DOF coefficients over headings (docs/headings.md#2-what-is-computed) from a file.

    A capytaine NetCDF file with the six rigid-body DOFs and a ``wave_direction`` dimension, or WAMIT ``.1``/``.3``
    output with modes 1-6 and several headings (``BETA``). Headings within [0, 180] deg are used and mirrored to
    [0, 360) by the hull's port-starboard symmetry. The WAMIT body origin lies on the waterline at ``x = origin_x_m``
    (default midship); the other parameters as in :func:`load_motions`.

    Raises
    ------
    ValueError
        A missing DOF or mode, a single heading, files without common frequencies.
    """
    p = Path(path)
    fmt = format if format != "auto" else ("capytaine" if p.suffix.lower() in (".nc", ".netcdf", ".cdf") else "wamit")
    x_mid = 0.5 * (hull.station_x_m[0] + hull.station_x_m[-1])
    if fmt == "capytaine":
        ds = read_capytaine_netcdf(p) if memory_cache is None else memory_cache.dataset(p)
        origin = float(ds.attrs.get("seafast_origin_x_m", x_mid)) if origin_x_m is None else float(origin_x_m)
        return capytaine_six_dof_coefficients(ds, origin, gravity_m_per_s2)
    if fmt != "wamit":
        raise ValueError(f"load_six_dof_coefficients: unknown format {format!r}")
    f1, f3 = _wamit_files(p)
    rho, g = water_density_kg_per_m3, gravity_m_per_s2
    modes = (1, 2, 3, 4, 5, 6)
    w1, a, b = read_wamit_1(f1, ulen_m=ulen_m, water_density_kg_per_m3=rho, frequency_column=frequency_column, modes=modes)
    w3, betas, x = read_wamit_3_headings(
        f3, ulen_m=ulen_m, water_density_kg_per_m3=rho, gravity_m_per_s2=g, frequency_column=frequency_column
    )
    common = np.intersect1d(np.round(w1, 9), np.round(w3, 9))
    if common.size == 0:
        raise ValueError("load_six_dof_coefficients: the .1 and .3 files share no frequency")
    i1, i3 = np.isin(np.round(w1, 9), common), np.isin(np.round(w3, 9), common)
    headings, f = mirrored_headings(betas, x[i3])
    origin = x_mid if origin_x_m is None else float(origin_x_m)
    return SixDofCoefficients(
        omega_rad_s=w1[i1],
        wavenumber_rad_per_m=wavenumber_rad_per_m(w1[i1], water_depth_m, g),
        headings_deg=headings,
        added_mass=a[i1],
        radiation_damping=b[i1],
        excitation_force=f,
        reference_x_m=origin,
        reference_z_wl_m=0.0,
        wave_phase_origin_x_m=origin,
    )
