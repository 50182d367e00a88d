"""The case's vessel keys read into what the vessel excitation is built from.

The hull form (:func:`hull_form_of`: the user's breadth table or the tapered box), the default
loading with the case's cargo (:func:`vessel_loading_of`), the user's two-column tables
(:func:`read_two_column_table`), the still-water deck line of a moment table (:class:`DeckLine`)
and the rigid-body motions of ``vessel.motions`` (:func:`rigid_body_motions`, the BEM on
:data:`BEM_FREQUENCIES_RAD_S`). Assembled by :func:`seafast.excitation.vessel.vessel_excitation`.
"""

from __future__ import annotations

import csv
import functools
import logging
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import NDArray
from scipy.interpolate import CubicHermiteSpline

from seafast.config.arrangement import abreast_lanes_m
from seafast.config.schema import HEAD_SEAS_DEG, Case
from seafast.excitation.cargo_acceleration import CargoPoints
from seafast.excitation.hydrodynamics.heading_motions import SixDofMotions
from seafast.excitation.hydrodynamics.memory_cache import HydrodynamicsCache
from seafast.excitation.hydrodynamics.motions import RigidBodyMotions
from seafast.excitation.hydrodynamics.six_dof import LoadedShip
from seafast.model.from_case import cargo_geometry
from seafast.vessel.hull_form import HullForm
from seafast.vessel.loading import VesselLoading, base_vessel_loading, mass_distribution_kg_per_m
from seafast.vessel.mass_properties import loaded_ship_properties

__all__ = [
    "BEM_FREQUENCIES_RAD_S",
    "DeckLine",
    "read_two_column_table",
    "hull_form_of",
    "cargo_unit_mass_kg",
    "vessel_loading_of",
    "rigid_body_motions",
    "HEAD_SEAS_DEG",
    "is_head_seas",
    "cargo_points_of",
    "loaded_ship_of",
    "six_dof_motions_of",
]


def is_head_seas(case: Case) -> bool:
    """Whether ``wave.heading_deg`` is head seas (180 deg): the heave-pitch model, unchanged, serves it."""
    return case.wave.heading_deg == HEAD_SEAS_DEG


logger = logging.getLogger(__name__)

BEM_FREQUENCIES_RAD_S = np.round(np.concatenate([np.linspace(0.2, 0.95, 16), np.linspace(1.0, 1.8, 9)]), 6)
"""Frequencies of the BEM run [rad/s]: fixed, so the disk cache serves every wave length;
the RAOs at the case's frequency are interpolated linearly, on a 0.05 rad/s grid up to
0.95 rad/s where heave and pitch vary fast (waves of 68 m to 1540 m) and 0.1 rad/s above.
1.8 rad/s (a 19 m wave) is the shortest wave the 3 m panels resolve (panel radius <
wavelength / 8) and well beyond the waves that bend a 171 m hull."""


@dataclass(frozen=True)
class DeckLine:
    """Deflection [m] and slope [rad] along the ship as a C1 Hermite interpolant (the still-water deck of a moment table).

    Attributes
    ----------
    x_m, deflection_m, slope_rad
        Table positions from the AP [m], deflection [m] (up +) and slope dz/dx [rad] there.
    """

    x_m: NDArray[np.float64]
    deflection_m: NDArray[np.float64]
    slope_rad: NDArray[np.float64]

    def __call__(self, x: NDArray[np.float64]) -> tuple[NDArray, NDArray]:
        spl = CubicHermiteSpline(self.x_m, self.deflection_m, self.slope_rad)
        return spl(x), spl(x, 1)


def read_two_column_table(path: str | Path, key: str, columns: tuple[str, str]) -> tuple[NDArray, NDArray]:
    """The two named columns of a CSV table (``#`` comment lines skipped), the first strictly increasing.

    Raises
    ------
    ValueError
        Naming ``key`` and the file: unreadable, a missing column, a non-number, fewer than two rows.
    """
    p = Path(path)
    try:
        rows = list(csv.reader(line for line in p.read_text(encoding="utf-8").splitlines() if line.strip() and not line.startswith("#")))
    except (OSError, UnicodeDecodeError) as exc:
        raise ValueError(f"{key} = '{p}': cannot read it ({getattr(exc, 'strerror', exc)})") from None
    header = [h.strip() for h in rows[0]] if rows else []
    if any(c not in header for c in columns):
        raise ValueError(f"{key} = '{p}': expected columns {', '.join(columns)}; header is {header}")
    idx = [header.index(c) for c in columns]
    out = []
    for i, r in enumerate(rows[1:], start=2):
        try:
            vals = [float(r[j]) for j in idx]
        except (ValueError, IndexError):
            raise ValueError(f"{key} = '{p}', line {i}: values must be numbers") from None
        if not all(math.isfinite(v) for v in vals):
            raise ValueError(f"{key} = '{p}', line {i}: values must be finite")
        out.append(vals)
    a = np.array(out, dtype=float).reshape(-1, 2)
    if a.shape[0] < 2 or np.any(np.diff(a[:, 0]) <= 0):
        raise ValueError(f"{key} = '{p}': needs at least 2 rows with {columns[0]} strictly increasing")
    return a[:, 0], a[:, 1]


def hull_form_of(case: Case) -> HullForm:
    """The hull form: the user's breadth table (read at every call), or the tapered box of L, B, T and displacement.

    A :class:`~seafast.excitation.vessel.VesselCache` keeps the tapered box for the next case with
    the same four particulars (one hull, with the integrals it keeps, for all the loadings of a
    cargo study).
    """
    v = case.vessel
    if v.hull_form_table is not None:
        x, b = read_two_column_table(v.hull_form_table, "vessel.hull_form_table", ("x_m", "breadth_m"))
        if np.any(b < 0):
            raise ValueError(f"vessel.hull_form_table = '{v.hull_form_table}': breadth_m must be >= 0")
        return HullForm(station_x_m=x - x[0], waterline_breadth_m=b, draft_m=v.draft_m)
    cb = v.displacement_m3 / (v.length_m * v.breadth_m * v.draft_m)
    if not 0.3 < cb <= 1.0:
        raise ValueError(
            f"vessel.displacement_m3 = {v.displacement_m3} gives a block coefficient {cb:.3f} for L x B x T = "
            f"{v.length_m} x {v.breadth_m} x {v.draft_m}; allowed 0.3 < C_b <= 1"
        )
    try:
        return HullForm.tapered_box(v.length_m, v.breadth_m, v.draft_m, cb)
    except ValueError as exc:
        raise ValueError(f"vessel: {exc}") from None


def cargo_unit_mass_kg(case: Case) -> float:
    """Mass of one cargo unit [kg], from the same geometry the cargo model is built from."""
    return cargo_geometry(case).mass_kg()


def vessel_loading_of(case: Case, hull: HullForm) -> tuple[VesselLoading, str]:
    """The documented default loading with the case's cargo (all units abreast).

    The default ballast plan also sets a moderate still-water hogging moment at the cargo (the
    calibration). When a heavy cargo leaves no positive ballast that achieves it, the plan falls
    back to balancing displacement and trim only (aft and fore tanks), and says so.

    Returns
    -------
    loading, description
    """
    cargo_mass_kg = case.cargo.units_abreast * cargo_unit_mass_kg(case)
    default_loading = functools.partial(
        base_vessel_loading,
        hull=hull,
        cargo_position_m=case.cargo_position_m(),
        cargo_length_m=case.cargo.length_m,
        cargo_mass_kg=cargo_mass_kg,
        lightship_mass_kg=case.vessel.lightship_mass_kg,
        water_density_kg_per_m3=case.vessel.water_density_kg_per_m3,
        gravity_m_per_s2=case.model.gravity_m_per_s2,
    )
    try:
        return default_loading(), "default loading"
    except ValueError:
        pass
    try:
        loading = default_loading(still_water_moment_Nm=None)
        logger.debug("vessel loading: the cargo is too heavy for the default hogging ballast plan; ballast for even keel only")
        return loading, "default loading, ballast for even keel only (cargo too heavy for the default hogging plan)"
    except ValueError as exc:
        raise ValueError(
            f"vessel loading: {exc}; the cargo ({case.cargo.units_abreast} units abreast, "
            f"{cargo_mass_kg / 1e3:.0f} t) cannot be ballasted to the design draught - reduce cargo.units_abreast "
            "or give vessel.deck_deflection_table / vessel.still_water_bending_moment_table"
        ) from None


def rigid_body_motions(
    case: Case, hull: HullForm, loading: VesselLoading | None, memory_cache: HydrodynamicsCache | None = None
) -> RigidBodyMotions | None:
    """The vessel's rigid-body motions of ``vessel.motions``: the BEM (from its disk cache), a file, or None for ``none``.

    The mass properties are those of ``loading`` when given (mass, LCG and pitch inertia of the
    actual weight distribution), else of a uniform-density body; ``memory_cache`` keeps the BEM
    data for the next loading (:class:`~seafast.excitation.hydrodynamics.memory_cache.HydrodynamicsCache`).
    """
    v = case.vessel
    if v.motions == "none":
        return None
    from seafast.excitation import hydrodynamics as hydro

    props = hydro.base_vessel_mass_properties(hull, water_density_kg_per_m3=v.water_density_kg_per_m3)
    if v.vertical_centre_of_gravity_m is not None:
        props["centre_of_gravity_m"] = (*props["centre_of_gravity_m"][:2], float(v.vertical_centre_of_gravity_m))
    if loading is not None:
        # mass, LCG and pitch inertia of the actual loading (not a uniform-density body)
        x = np.linspace(0.0, hull.length_m, 4001)
        m = mass_distribution_kg_per_m(x, loading)
        mass = float(np.trapezoid(m, x))
        xg = float(np.trapezoid(m * x, x) / mass)
        radius = math.sqrt(float(np.trapezoid(m * (x - xg) ** 2, x)) / mass)
        props = {"mass_kg": mass, "centre_of_gravity_m": (xg, 0.0, props["centre_of_gravity_m"][2]), "pitch_radius_of_gyration_m": radius}
    common = dict(water_density_kg_per_m3=v.water_density_kg_per_m3, gravity_m_per_s2=case.model.gravity_m_per_s2, **props)
    if v.motions == "bem":
        return hydro.compute_motions(
            hull, omega_rad_s=BEM_FREQUENCIES_RAD_S, panel_size_m=v.bem_panel_size_m, **common, memory_cache=memory_cache
        )
    path = Path(v.motions)
    if not path.exists():
        raise ValueError(
            f"vessel.motions = '{v.motions}': no such file; allowed: bem, none, or a path to capytaine NetCDF / WAMIT .1 output"
        )
    return hydro.load_motions(path, hull, **common, memory_cache=memory_cache)


def _cargo_sections(case: Case) -> tuple[float, float]:
    """The cargo unit's mass-weighted mean outer radius [m] and own radius of gyration about its axis [m]."""
    geometry = cargo_geometry(case)
    x = np.linspace(0.0, geometry.length_m, 2001)
    d, t = geometry.section_at(x)
    r_o, r_i = 0.5 * d, 0.5 * d - t
    area = r_o**2 - r_i**2  # proportional to the mass per metre
    mean_r_o = float(np.trapezoid(area * r_o, x) / np.trapezoid(area, x))
    own = float(np.trapezoid(area * 0.5 * (r_o**2 + r_i**2), x) / np.trapezoid(area, x))
    return mean_r_o, math.sqrt(own)


def cargo_axis_height_m(case: Case) -> float:
    """Height of the cargo unit's axis above the keel [m]: deck + saddle height + the mean outer radius."""
    return case.vessel.deck_height_m + case.seafastening.saddle_height_m + _cargo_sections(case)[0]


def loaded_ship_of(case: Case, hull: HullForm, loading: VesselLoading | None) -> LoadedShip:
    """The loaded ship of the six-DOF motions: :func:`~seafast.vessel.mass_properties.loaded_ship_properties` of the loading.

    ``vessel.vertical_centre_of_gravity_m`` and ``vessel.roll_radius_of_gyration_m`` override KG and the roll radius;
    ``vessel.roll_damping_ratio`` is the additional roll damping. Without a loading (a deck-deflection table) the
    documented default loading with the case's cargo is used.
    """
    v = case.vessel
    if loading is None:
        loading = vessel_loading_of(case, hull)[0]
    props = loaded_ship_properties(
        loading,
        length_m=hull.length_m,
        breadth_m=hull.breadth_m,
        depth_m=v.deck_height_m,
        cargo_vcg_m=cargo_axis_height_m(case),
        lanes_y_m=abreast_lanes_m(case.cargo.units_abreast, hull.breadth_m),
        cargo_radius_of_gyration_m=_cargo_sections(case)[1],
    )
    kg = props.kg_m if v.vertical_centre_of_gravity_m is None else float(v.vertical_centre_of_gravity_m)
    roll = props.roll_radius_m if v.roll_radius_of_gyration_m is None else float(v.roll_radius_of_gyration_m)
    return LoadedShip(props.mass_kg, (props.lcg_m, 0.0, kg), roll, props.pitch_radius_m, props.yaw_radius_m, v.roll_damping_ratio)


def cargo_points_of(case: Case) -> CargoPoints:
    """The points of the analysed unit whose accelerations results.nc reports: its aft end, middle and fore end, on its axis."""
    length = case.cargo.length_m
    x_cargo = np.array([0.0, 0.5 * length, length])
    aft = case.cargo_position_m() - 0.5 * length
    return CargoPoints(x_cargo, aft + x_cargo, case.cargo_transverse_position_m(), cargo_axis_height_m(case))


def six_dof_motions_of(
    case: Case, hull: HullForm, loading: VesselLoading | None, memory_cache: HydrodynamicsCache | None = None
) -> SixDofMotions | None:
    """The six motions at every heading for ``vessel.motions``: the BEM over headings (its own disk cache file), a file, or None.

    Only cases off head seas need it (:func:`is_head_seas`): head seas keep :func:`rigid_body_motions`.
    """
    v = case.vessel
    if v.motions == "none":
        return None
    from seafast.excitation import hydrodynamics as hydro
    from seafast.excitation.hydrodynamics.load import load_six_dof_coefficients
    from seafast.excitation.hydrodynamics.six_dof import capytaine_six_dof_coefficients, six_dof_motions

    g, rho = case.model.gravity_m_per_s2, v.water_density_kg_per_m3
    if v.motions == "bem":
        ds = hydro.six_dof_dataset(
            hull,
            omega_rad_s=BEM_FREQUENCIES_RAD_S,
            panel_size_m=v.bem_panel_size_m,
            water_density_kg_per_m3=rho,
            gravity_m_per_s2=g,
            memory_cache=memory_cache,
        )
        coefficients = capytaine_six_dof_coefficients(ds, float(ds.attrs["seafast_origin_x_m"]), g)
        source = f"capytaine BEM over headings, cache key {ds.attrs.get('seafast_cache_key', '?')}"
    else:
        path = Path(v.motions)
        if not path.exists():
            raise ValueError(
                f"vessel.motions = '{v.motions}': no such file; allowed: bem, none, or a path to capytaine NetCDF / WAMIT .1 output"
            )
        coefficients = load_six_dof_coefficients(path, hull, water_density_kg_per_m3=rho, gravity_m_per_s2=g, memory_cache=memory_cache)
        source = f"file {path.name}"
    ship = loaded_ship_of(case, hull, loading)
    return six_dof_motions(coefficients, hull, ship, water_density_kg_per_m3=rho, gravity_m_per_s2=g, source=source)
