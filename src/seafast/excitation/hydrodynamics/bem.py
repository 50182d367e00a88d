"""The vessel's hydrodynamics from capytaine (BEM), cached on disk: :func:`compute_motions`.

The cache key (:func:`compute_motions`, Notes) must not change without a reason: it names the
files of every user's cache (``motions_<key>.nc``); bump :data:`MESH_ALGORITHM_VERSION` to
invalidate them on purpose.

The run over headings (:func:`six_dof_dataset`: six DOFs, diffraction at every 15 deg) has its own key and file
(``motions6_<key>.nc``), so head seas never pay for it.

Size: over 400 lines because the two runs, head seas and every heading, share one disk cache (its keys, its atomic
writes, its reading through the memory cache), whose private helpers stay in one module.
"""

from __future__ import annotations

import hashlib
import importlib.metadata
import json
import logging
import math
import os
import tempfile
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import xarray as xr
from numpy.typing import ArrayLike, NDArray

from seafast.excitation.hydrodynamics.capytaine_io import capytaine_rigid_coefficients, read_capytaine_netcdf
from seafast.excitation.hydrodynamics.coefficients import motions_from_rigid_coefficients
from seafast.excitation.hydrodynamics.memory_cache import HydrodynamicsCache
from seafast.excitation.hydrodynamics.motions import RigidBodyMotions
from seafast.parallel.threads import blas_on_every_core
from seafast.vessel.hull_form import HullForm
from seafast.vessel.hull_mesh import hull_mesh_arrays

__all__ = [
    "compute_motions",
    "default_cache_dir",
    "BEM_DOFS",
    "MESH_ALGORITHM_VERSION",
    "SIX_DOFS",
    "BEM_HEADINGS_DEG",
    "six_dof_dataset",
]

logger = logging.getLogger(__name__)

#: Bump when the mesher or the post-processing changes, to invalidate cached BEM results.
MESH_ALGORITHM_VERSION = "seafast-hull-mesh-1"

#: Radiating DOFs of the BEM run (surge added for the axial analysis; part of the cache key).
BEM_DOFS: tuple[str, ...] = ("Surge", "Heave", "Pitch")

#: The six rigid-body DOFs of the run over headings (capytaine's names and order).
SIX_DOFS: tuple[str, ...] = ("Surge", "Sway", "Heave", "Roll", "Pitch", "Yaw")

#: Wave headings of the diffraction run over headings [deg]: 0 (following) to 180 (head seas) every 15 deg; the hull's
#: port-starboard symmetry gives 180-360 (docs/headings.md#2-what-is-computed).
BEM_HEADINGS_DEG: tuple[float, ...] = tuple(float(b) for b in range(0, 181, 15))


def default_cache_dir() -> Path:
    """``$SEAFAST_CACHE_DIR`` if set, else ``~/.cache/seafast/hydrodynamics``."""
    env = os.environ.get("SEAFAST_CACHE_DIR")
    return Path(env) if env else Path.home() / ".cache" / "seafast" / "hydrodynamics"


def _cache_key(payload: dict) -> str:
    return hashlib.sha256(json.dumps(payload, sort_keys=True).encode()).hexdigest()[:32]


def _run_payload(
    hull: HullForm, omega: NDArray[np.float64], panel_size_m: float, rho: float, g: float, depth: float, capytaine_version: str
) -> dict[str, object]:
    """What every BEM run's cache key hashes: the hull's sections, the frequencies, the panel size, the water, the
    capytaine and mesher versions (each run adds its DOFs, rotation centre and headings; the keys are sorted)."""
    return {
        "stations": [repr(float(v)) for v in hull.station_x_m],
        "breadth": [repr(float(v)) for v in hull.waterline_breadth_m],
        "draft": repr(float(hull.draft_m)),
        "cs": repr(float(hull.section_area_coefficient)),
        "omega": [repr(float(v)) for v in omega],
        "panel": repr(panel_size_m),
        "rho": repr(rho),
        "g": repr(g),
        "depth": repr(depth),
        "capytaine": capytaine_version,
        "mesh": MESH_ALGORITHM_VERSION,
    }


def _capytaine_version() -> str:
    """capytaine's version (``capytaine.__version__``) from the package's metadata, without importing it (0.4 s)."""
    return importlib.metadata.version("capytaine")


def _run_bem(
    hull: HullForm,
    omega: NDArray[np.float64],
    rotation_center_wl: NDArray[np.float64],
    panel_size_m: float,
    rho: float,
    g: float,
    depth: float,
) -> xr.Dataset:
    """Radiation (:data:`BEM_DOFS`: surge, heave, pitch) and head-sea diffraction; returns capytaine's dataset.

    Frame: origin at midship on the waterline (see :mod:`seafast.vessel.hull_mesh`).
    """
    import capytaine as cpt

    hm = hull_mesh_arrays(hull, panel_size_m)
    mesh, lid = hm.to_capytaine()
    body = cpt.FloatingBody(
        mesh=mesh,
        lid_mesh=lid,
        dofs=cpt.rigid_body_dofs(only=list(BEM_DOFS), rotation_center=rotation_center_wl),
        center_of_mass=rotation_center_wl,
        name="seafast_vessel",
    )
    solver = cpt.BEMSolver()
    problems = []
    for w in omega:
        kw = dict(body=body, omega=float(w), rho=rho, g=g, water_depth=depth)
        problems += [cpt.RadiationProblem(radiating_dof=d, **kw) for d in BEM_DOFS]
        problems.append(cpt.DiffractionProblem(wave_direction=np.pi, **kw))
    # the BEM's dense complex solves do profit from every core (callers may have pinned BLAS)
    with blas_on_every_core():
        results = solver.solve_all(problems, progress_bar=False)
    ds = cpt.assemble_dataset(results, hydrostatics=False)
    ds.attrs["seafast_origin_x_m"] = float(hm.x_mid_m)
    ds.attrs["seafast_panel_size_m"] = float(panel_size_m)
    ds.attrs["seafast_nb_panels_hull"] = hm.nb_hull_panels_full
    ds.attrs["seafast_nb_panels_lid"] = hm.nb_lid_panels_full
    return ds


def _run_six_dof_bem(
    hull: HullForm, omega: NDArray[np.float64], headings_deg: Sequence[float], panel_size_m: float, rho: float, g: float, depth: float
) -> xr.Dataset:
    """Radiation of the six rigid-body DOFs about (LCB, 0, waterline) and diffraction at ``headings_deg``; capytaine's dataset.

    Frame: origin at midship on the waterline (see :mod:`seafast.vessel.hull_mesh`). Per frequency capytaine builds and
    factorises the influence matrices once (its engine keeps the last ones), so the 13 diffraction problems cost a
    back-substitution each.
    """
    import capytaine as cpt

    hm = hull_mesh_arrays(hull, panel_size_m)
    mesh, lid = hm.to_capytaine()
    centre = np.array([hull.centre_of_buoyancy_x_m() - hm.x_mid_m, 0.0, 0.0])
    body = cpt.FloatingBody(
        mesh=mesh, lid_mesh=lid, dofs=cpt.rigid_body_dofs(rotation_center=centre), center_of_mass=centre, name="seafast_vessel"
    )
    problems = []
    for w in omega:
        kw = dict(body=body, omega=float(w), rho=rho, g=g, water_depth=depth)
        problems += [cpt.RadiationProblem(radiating_dof=d, **kw) for d in SIX_DOFS]
        problems += [cpt.DiffractionProblem(wave_direction=math.radians(b), **kw) for b in headings_deg]
    with blas_on_every_core():
        results = cpt.BEMSolver().solve_all(problems, progress_bar=False)
    ds = cpt.assemble_dataset(results, hydrostatics=False)
    ds.attrs["seafast_origin_x_m"] = float(hm.x_mid_m)
    ds.attrs["seafast_panel_size_m"] = float(panel_size_m)
    ds.attrs["seafast_nb_panels_hull"] = hm.nb_hull_panels_full
    ds.attrs["seafast_nb_panels_lid"] = hm.nb_lid_panels_full
    return ds


@dataclass(frozen=True)
class _SixDofRun:
    """What the six-DOF run over headings depends on (and its cache key hashes): hull, frequencies, headings, panel size, water.

    The rotation centre is fixed at the hull's LCB on the waterline, so the run depends on the hull alone: every loading
    (KG, roll inertia) reuses it, the coefficients moved to the loading's CoG afterwards.
    """

    hull: HullForm
    omega: NDArray[np.float64]
    headings_deg: tuple[float, ...]
    panel_size_m: float
    rho: float
    g: float
    depth: float

    def cache_key(self, capytaine_version: str) -> str:
        """The disk cache's key of the run (file ``motions6_<key>.nc``)."""
        payload = _run_payload(self.hull, self.omega, self.panel_size_m, self.rho, self.g, self.depth, capytaine_version)
        payload.update(headings_deg=[repr(float(b)) for b in self.headings_deg], dofs=list(SIX_DOFS), rotation_center="lcb-waterline")
        return _cache_key(payload)

    def dataset(self) -> xr.Dataset:
        """Run capytaine (:func:`_run_six_dof_bem`)."""
        return _run_six_dof_bem(self.hull, self.omega, self.headings_deg, self.panel_size_m, self.rho, self.g, self.depth)


def six_dof_dataset(
    hull: HullForm,
    *,
    omega_rad_s: ArrayLike,
    headings_deg: Sequence[float] = BEM_HEADINGS_DEG,
    panel_size_m: float = 3.0,
    water_density_kg_per_m3: float = 1025.0,
    gravity_m_per_s2: float = 9.81,
    water_depth_m: float = math.inf,
    cache_dir: str | os.PathLike | None = None,
    use_cache: bool = True,
    memory_cache: HydrodynamicsCache | None = None,
) -> xr.Dataset:
    """capytaine's dataset of the six rigid-body DOFs over headings, from the disk cache or computed (and cached).

    Radiation of surge, sway, heave, roll, pitch and yaw about the hull's LCB on the waterline (capytaine's DOFs and
    signs); diffraction at ``headings_deg`` (capytaine's ``wave_direction``, 0 to 180 deg: the hull's symmetry gives the
    rest). Only the runs over headings pay for it: head seas keep :func:`compute_motions` and its three-DOF file.

    Parameters
    ----------
    hull
        Hull form, meshed as in :func:`compute_motions`.
    omega_rad_s
        Wave frequencies [rad/s] (> 0; sorted, duplicates removed).
    headings_deg
        Wave headings of the diffraction problems [deg], within [0, 180].
    panel_size_m, water_density_kg_per_m3, gravity_m_per_s2, water_depth_m, cache_dir, use_cache, memory_cache
        As in :func:`compute_motions`.

    Returns
    -------
    xarray.Dataset
        capytaine's dataset (``added_mass``, ``radiation_damping``, ``excitation_force`` over ``omega``,
        ``wave_direction``, ``radiating_dof``, ``influenced_dof``), attributes ``seafast_origin_x_m`` and
        ``seafast_cache_key``.
    """
    omega, _ = _checked_inputs(omega_rad_s, 1.0, 1.0, (0.0, 0.0, 0.0))
    headings = tuple(sorted({float(b) for b in headings_deg}))
    if not headings or headings[0] < 0.0 or headings[-1] > 180.0:
        raise ValueError(f"six_dof_dataset: headings_deg = {list(headings_deg)!r}; must lie within [0, 180] deg")
    run = _SixDofRun(
        hull, omega, headings, float(panel_size_m), float(water_density_kg_per_m3), float(gravity_m_per_s2), float(water_depth_m)
    )
    key = run.cache_key(_capytaine_version())
    cdir = Path(cache_dir) if cache_dir is not None else default_cache_dir()
    return _cached_or_computed(run, key, cdir, use_cache, memory_cache, prefix="motions6")


def _checked_inputs(
    omega_rad_s: ArrayLike, mass_kg: float, pitch_radius_of_gyration_m: float, centre_of_gravity_m: Sequence[float]
) -> tuple[NDArray[np.float64], tuple[float, ...]]:
    """The frequencies sorted without duplicates [rad/s] and the CoG as floats [m], after checking them and the mass properties."""
    omega = np.unique(np.asarray(omega_rad_s, dtype=float).ravel())
    if omega.size == 0 or not np.all(np.isfinite(omega)) or np.any(omega <= 0):
        raise ValueError(f"compute_motions: omega_rad_s must be finite and > 0, got {omega_rad_s!r}")
    if not mass_kg > 0 or not pitch_radius_of_gyration_m > 0:
        raise ValueError("compute_motions: mass_kg and pitch_radius_of_gyration_m must be > 0")
    cog = tuple(float(c) for c in centre_of_gravity_m)
    if len(cog) != 3:
        raise ValueError("compute_motions: centre_of_gravity_m must be (x, y, z)")
    return omega, cog


@dataclass(frozen=True)
class _BEMRun:
    """What a BEM run depends on (and its cache key hashes): hull, frequencies, pitch axis, panel size, water."""

    hull: HullForm
    omega: NDArray[np.float64]
    rotation_center: NDArray[np.float64]
    panel_size_m: float
    rho: float
    g: float
    depth: float

    def cache_key(self, capytaine_version: str) -> str:
        """The disk cache's key (see :func:`compute_motions`, Notes): unchanged, so every user's cache file stays a hit."""
        payload = _run_payload(self.hull, self.omega, self.panel_size_m, self.rho, self.g, self.depth, capytaine_version)
        payload.update(rotation_center=[repr(float(c)) for c in self.rotation_center], dofs=list(BEM_DOFS))
        return _cache_key(payload)

    def dataset(self) -> xr.Dataset:
        """Run capytaine (:func:`_run_bem`)."""
        return _run_bem(self.hull, self.omega, self.rotation_center, self.panel_size_m, self.rho, self.g, self.depth)


def _cached_or_computed(
    run: _BEMRun | _SixDofRun, key: str, cdir: Path, use_cache: bool, memory_cache: HydrodynamicsCache | None, prefix: str = "motions"
) -> xr.Dataset:
    """The run's capytaine dataset: read from ``cdir`` (through ``memory_cache`` when given), else computed and written there."""
    path = cdir / f"{prefix}_{key}.nc"
    if use_cache and path.is_file():
        try:
            ds = read_capytaine_netcdf(path) if memory_cache is None else memory_cache.dataset(path)
            logger.debug("BEM cache hit: %s", path)
            return ds
        except Exception:  # noqa: BLE001 - a corrupt or foreign cache file, whatever the error: recompute it
            logger.warning("BEM cache file %s is unreadable; recomputing it", path)
    logger.info("computing the vessel's hydrodynamics with capytaine (BEM, tens of seconds); cache: %s", path if use_cache else "off")
    ds = run.dataset()
    if use_cache:
        _write_cache(ds, key, path)
    return ds


def _write_cache(ds: xr.Dataset, key: str, path: Path) -> None:
    """Write ``ds`` to ``path`` with capytaine's NetCDF export, atomically (a temporary file, then a rename)."""
    import capytaine as cpt

    path.parent.mkdir(parents=True, exist_ok=True)
    ds.attrs["seafast_cache_key"] = key
    fd, tmp = tempfile.mkstemp(suffix=".nc", dir=path.parent)
    os.close(fd)
    try:
        cpt.export_dataset(tmp, ds)
        os.replace(tmp, path)
    finally:
        if os.path.exists(tmp):
            os.remove(tmp)


def compute_motions(
    hull: HullForm,
    *,
    mass_kg: float,
    centre_of_gravity_m: Sequence[float],
    pitch_radius_of_gyration_m: float,
    omega_rad_s: ArrayLike,
    panel_size_m: float = 3.0,
    water_density_kg_per_m3: float = 1025.0,
    gravity_m_per_s2: float = 9.81,
    water_depth_m: float = math.inf,
    cache_dir: str | os.PathLike | None = None,
    use_cache: bool = True,
    memory_cache: HydrodynamicsCache | None = None,
) -> RigidBodyMotions:
    """Heave and pitch RAOs of the vessel in head seas from capytaine (BEM), cached on disk.

    Parameters
    ----------
    hull
        Hull form; meshed with :func:`seafast.vessel.hull_mesh.hull_mesh_arrays` (sides, bottom,
        transom, plus an interior waterplane lid removing irregular frequencies; y-symmetry used).
    mass_kg
        Ship mass [kg] (given explicitly; capytaine's uniform-density default is not used).
    centre_of_gravity_m
        ``(x from AP, y, z above keel)`` [m]. Pitch acts about ``x_G``; ``z_G`` enters the
        pitch restoring term ``-m g z_G`` and the rotation centre.
    pitch_radius_of_gyration_m
        Radius of gyration about the transverse axis through the CoG [m].
    omega_rad_s
        Wave frequencies [rad/s] (> 0; sorted internally, duplicates removed).
    panel_size_m
        Target panel size [m]: 3 m for production, ~8 m for quick checks.
    water_density_kg_per_m3, gravity_m_per_s2
        Passed to capytaine explicitly (its default density is 1000).
    water_depth_m
        Water depth [m] (``inf``: deep water).
    cache_dir
        Directory of cached capytaine datasets; default :func:`default_cache_dir`.
    use_cache
        Read and write the cache (default True).
    memory_cache
        Keeps the dataset read from the disk cache and its coefficients for the next call (a
        study's next loading of the same hull); None: read and extracted at every call.

    Returns
    -------
    RigidBodyMotions
        About ``reference_x_m = x_G``; phases relative to the wave crest at ``L/2``.

    Notes
    -----
    The cache key hashes the hull geometry, the BEM pitch axis (LCB x at the CoG height),
    frequencies, panel size, density, gravity, depth, the capytaine version and
    :data:`MESH_ALGORITHM_VERSION`; mass, CoG x and inertia are applied after the BEM, so a
    change of loading reuses the cached hydrodynamic coefficients. The cache file is
    the capytaine dataset written with capytaine's own NetCDF export, so it can be read back with
    :func:`load_motions` as well.
    """
    omega, cog = _checked_inputs(omega_rad_s, mass_kg, pitch_radius_of_gyration_m, centre_of_gravity_m)
    x_mid = 0.5 * (hull.station_x_m[0] + hull.station_x_m[-1])
    # The BEM pitch axis is fixed at the hull's LCB (at the CoG height): the radiation and
    # diffraction coefficients then depend on the hull alone, so one cached BEM run serves every
    # loading (studies vary the cargo and with it the CoG); they are moved to the CoG x below.
    rotation_center = np.array([hull.centre_of_buoyancy_x_m() - x_mid, 0.0, cog[2] - hull.draft_m])
    run = _BEMRun(
        hull, omega, rotation_center, float(panel_size_m), float(water_density_kg_per_m3), float(gravity_m_per_s2), float(water_depth_m)
    )
    capytaine_version = _capytaine_version()
    key = run.cache_key(capytaine_version)
    cdir = Path(cache_dir) if cache_dir is not None else default_cache_dir()
    ds = _cached_or_computed(run, key, cdir, use_cache, memory_cache)
    # the coefficients depend on the hull alone (a cargo study changes the loading, hence mass and
    # CoG, at every point, not the hull): a memory cache extracts them once per dataset
    if memory_cache is None:
        coefficients = capytaine_rigid_coefficients(ds, x_mid, gravity_m_per_s2)
    else:
        coefficients = memory_cache.rigid_coefficients(ds, x_mid, gravity_m_per_s2)
    omega_c, k_c, a_c, b_c, f_c, x_rot, z_rot_wl = coefficients
    return motions_from_rigid_coefficients(
        omega_c,
        k_c,
        a_c,
        b_c,
        f_c,
        hull,
        coeff_reference_x_m=x_rot,
        wave_phase_origin_x_m=x_mid,
        coeff_reference_z_wl_m=z_rot_wl,
        mass_kg=mass_kg,
        centre_of_gravity_m=cog,
        pitch_radius_of_gyration_m=pitch_radius_of_gyration_m,
        water_density_kg_per_m3=water_density_kg_per_m3,
        gravity_m_per_s2=gravity_m_per_s2,
        source=f"capytaine {capytaine_version} BEM, panel size {panel_size_m} m, cache key {key}",
    )
