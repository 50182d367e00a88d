"""Reading capytaine datasets: the NetCDF export, and its head-sea rigid-body coefficients.

A capytaine dataset (capytaine's conventions: ``exp(-i omega t)``, pitch ``eta_5`` bow down,
coordinates relative to its origin) becomes seafast motions through
:func:`~seafast.excitation.hydrodynamics.coefficients.motions_from_rigid_coefficients`.
"""

from __future__ import annotations

import math
import os
from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import NamedTuple

import numpy as np
import xarray as xr
from numpy.typing import NDArray

from seafast.excitation.hydrodynamics.coefficients import motions_from_rigid_coefficients
from seafast.excitation.hydrodynamics.equations import wavenumber_rad_per_m
from seafast.excitation.hydrodynamics.motions import RigidBodyMotions
from seafast.vessel.hull_form import HullForm

__all__ = ["read_capytaine_netcdf", "merge_complex_values", "RigidCoefficients", "capytaine_rigid_coefficients", "motions_from_capytaine"]


class RigidCoefficients(NamedTuple):
    """Head-sea rigid-body coefficients of a capytaine dataset, in capytaine's DOFs (see :func:`capytaine_rigid_coefficients`)."""

    omega: NDArray[np.float64]
    k: NDArray[np.float64]
    added_mass: NDArray[np.float64]
    damping: NDArray[np.float64]
    excitation_conj: NDArray[np.complex128]
    x_rot: float
    z_rot_wl: float


def read_capytaine_netcdf(path: str | os.PathLike) -> xr.Dataset:
    """Read a capytaine NetCDF export (complex values merged back); a
    :class:`~seafast.excitation.hydrodynamics.memory_cache.HydrodynamicsCache` keeps it for the next loading."""
    with xr.open_dataset(Path(path)) as raw:
        ds = merge_complex_values(raw.load())
    return ds


def merge_complex_values(ds: xr.Dataset) -> xr.Dataset:
    """Each variable of a capytaine export with a ``complex`` dimension (``re``, ``im``) as one complex array.

    What ``capytaine.io.xarray.merge_complex_values`` does, without importing capytaine (about
    0.4 s, which a run reading its BEM cache need not pay).
    """
    if "complex" not in ds.coords:
        return ds
    ds = ds.copy()
    for name in list(ds.data_vars):
        da = ds[name]
        if "complex" in da.coords:
            ds[name] = xr.DataArray(da.sel(complex="re").data + 1j * da.sel(complex="im").data, dims=[d for d in da.dims if d != "complex"])
    return ds.drop_vars("complex")


def _has_dof(values: Iterable[object], name: str) -> bool:
    return name.lower() in [str(v).lower() for v in values]


def _dof_index(values: Iterable[object], name: str) -> int:
    found = list(values)
    names = [str(v).lower() for v in found]
    if name.lower() not in names:
        raise ValueError(f"capytaine dataset: dof {name!r} missing (found {found})")
    return names.index(name.lower())


def motions_from_capytaine(
    ds: xr.Dataset,
    hull: HullForm,
    *,
    mass_kg: float,
    centre_of_gravity_m: Sequence[float],
    pitch_radius_of_gyration_m: float,
    origin_x_m: float | None,
    water_density_kg_per_m3: float,
    gravity_m_per_s2: float,
    source: str,
) -> RigidBodyMotions:
    """Convert a capytaine dataset (heave + pitch radiation, head-sea diffraction) to seafast motions."""
    x_mid = 0.5 * (hull.station_x_m[0] + hull.station_x_m[-1])
    if origin_x_m is None:
        origin_x_m = float(ds.attrs.get("seafast_origin_x_m", x_mid))
    omega, k, a_c, b_c, f_conj, x_rot, z_rot_wl = capytaine_rigid_coefficients(ds, origin_x_m, gravity_m_per_s2)
    return motions_from_rigid_coefficients(
        omega,
        k,
        a_c,
        b_c,
        f_conj,
        hull,
        coeff_reference_x_m=x_rot,
        wave_phase_origin_x_m=origin_x_m,
        coeff_reference_z_wl_m=z_rot_wl,
        mass_kg=mass_kg,
        centre_of_gravity_m=centre_of_gravity_m,
        pitch_radius_of_gyration_m=pitch_radius_of_gyration_m,
        water_density_kg_per_m3=water_density_kg_per_m3,
        gravity_m_per_s2=gravity_m_per_s2,
        source=source,
    )


def capytaine_rigid_coefficients(ds: xr.Dataset, origin_x_m: float, gravity_m_per_s2: float) -> RigidCoefficients:
    """Added mass, damping and excitation of a capytaine dataset, by frequency.

    Returns ``(omega, k, a, b, conj(f), x_rot, z_rot_wl)``: frequencies [rad/s] ascending,
    wavenumbers [rad/m], added mass and damping (n_w, d, d) and the conjugated head-sea excitation
    (n_w, d) in capytaine's (heave, pitch) DOFs, or (surge, heave, pitch) when the dataset holds
    surge, about ``x_rot`` (ship x of the dataset's rotation centre) and ``z_rot_wl`` [m] above the
    waterline.
    """
    if "omega" not in ds.dims:
        if "omega" in ds.coords:
            ds = ds.swap_dims({next(d for d in ds["omega"].dims): "omega"})
        else:
            raise ValueError("capytaine dataset: no 'omega' coordinate")
    ds = ds.sortby("omega")
    for v in ("added_mass", "radiation_damping", "excitation_force"):
        if v not in ds:
            raise ValueError(f"capytaine dataset: variable {v!r} missing")
    omega = np.asarray(ds["omega"].values, dtype=float)
    # head seas: wave_direction = pi
    exc = ds["excitation_force"]
    if "wave_direction" in exc.dims:
        wd = np.asarray(exc["wave_direction"].values, dtype=float)
        i = int(np.argmin(np.abs(np.angle(np.exp(1j * (wd - np.pi))))))
        if abs(np.angle(np.exp(1j * (wd[i] - np.pi)))) > 1e-6:
            raise ValueError(f"capytaine dataset: no head-sea (wave_direction = pi) case, found {wd}")
        exc = exc.isel(wave_direction=i)
    elif "wave_direction" in exc.coords and abs(float(exc["wave_direction"]) - np.pi) > 1e-6:
        raise ValueError("capytaine dataset: excitation is not for wave_direction = pi")
    for d in [d for d in exc.dims if d not in ("omega", "influenced_dof")]:
        exc = exc.isel({d: 0})
    inf_dofs = ds["influenced_dof"].values
    rad_dofs = ds["radiating_dof"].values
    ih, ip = _dof_index(inf_dofs, "Heave"), _dof_index(inf_dofs, "Pitch")
    jh, jp = _dof_index(rad_dofs, "Heave"), _dof_index(rad_dofs, "Pitch")
    rows, cols = [ih, ip], [jh, jp]
    has_surge = _has_dof(inf_dofs, "Surge") and _has_dof(rad_dofs, "Surge")
    if has_surge:  # (surge, heave, eta5)
        rows, cols = [_dof_index(inf_dofs, "Surge"), *rows], [_dof_index(rad_dofs, "Surge"), *cols]

    def mat(v: str) -> NDArray[np.float64]:
        da = ds[v]
        for d in [d for d in da.dims if d not in ("omega", "influenced_dof", "radiating_dof")]:
            da = da.isel({d: 0})
        values = da.transpose("omega", "influenced_dof", "radiating_dof").values
        return np.real(values[:, rows][:, :, cols])

    a_c, b_c = mat("added_mass"), mat("radiation_damping")
    f_c = exc.transpose("omega", "influenced_dof").values[:, rows]
    if "wavenumber" in ds.coords or "wavenumber" in ds:
        k = np.broadcast_to(np.asarray(ds["wavenumber"].values, dtype=float), omega.shape).copy()
    else:
        depth = float(ds["water_depth"].values) if "water_depth" in ds.coords else math.inf
        k = wavenumber_rad_per_m(omega, depth, gravity_m_per_s2)

    # rotation centre of the dataset (capytaine frame: x relative to origin_x_m)
    z_rot_wl = 0.0
    if "rotation_center" in ds.coords or "rotation_center" in ds:
        rc = np.asarray(ds["rotation_center"].values, dtype=float).reshape(-1)[:3]
        x_rot = origin_x_m + float(rc[0])
        z_rot_wl = float(rc[2])
    else:
        x_rot = origin_x_m
    return RigidCoefficients(omega, k, a_c, b_c, np.conj(f_c), x_rot, z_rot_wl)
