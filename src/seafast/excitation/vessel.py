"""The vessel side of a case: hull-girder deflection and rigid-body motions -> deck excitation.

Sources, in order of precedence (docs/theory.md#35-user-supplied-hull-data, docs/interface.md#3-input-tables):

* ``vessel.deck_deflection_table``: the user's own hull deflection (still water and wave);
  replaces the hull-girder model entirely.
* ``vessel.still_water_bending_moment_table``: still-water moment from a loading computer,
  turned into deflection by the Timoshenko hull beam; the wave part is still computed.
* Otherwise the hull-girder model: documented default loading of the vessel (lightship by a
  Prohaska distribution, the cargo units abreast, ballast balanced to even keel) on the
  tapered-box hull, still water and quasi-static regular wave.

Rigid-body heave and pitch (and surge, coupled, when the data hold it: the BEM does):
``vessel.motions`` = ``bem`` (capytaine on the same hull form, cached on disk), ``none``, or a
path to capytaine NetCDF / WAMIT output.

Everything here depends only on the vessel, cargo-mass and wave parts of the case, so it is
memoised per process: a parametric study over saddles computes it once.

Size: over 400 lines because it is the one place that turns the case's vessel keys into the deck
excitation (hull form, loading, girder, tables, motions, their labelled dataset); each source is a
short function.
"""

from __future__ import annotations

import csv
import functools
import json
import logging
import math
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import xarray as xr
from numpy.typing import NDArray
from scipy.interpolate import CubicHermiteSpline

from seafast.config.schema import Case
from seafast.excitation.deck_motion import RigidBodyAmplitudes, assemble_excitation
from seafast.excitation.deck_table import DeckDeflectionTable, read_deck_deflection_table
from seafast.excitation.harmonic import HarmonicExcitation
from seafast.excitation.rao_extension import extended_rao
from seafast.hull.girder import DEFAULT_SHEAR_AREA_M2, HullGirder
from seafast.hull.still_water import HullGirderResponse, deflection_from_bending_moment, still_water_response
from seafast.hull.wave import WaveHullResponse, wave_response
from seafast.model.from_case import cargo_geometry
from seafast.model.structure import StructuralModel
from seafast.vessel.hull_form import HullForm
from seafast.vessel.loading import VesselLoading, base_vessel_loading, mass_distribution_kg_per_m

__all__ = ["VesselExcitation", "vessel_excitation", "BEM_FREQUENCIES_RAD_S", "hull_form_of", "vessel_loading_of"]

logger = logging.getLogger(__name__)

BEM_FREQUENCIES_RAD_S = np.round(np.concatenate([np.linspace(0.2, 0.95, 16), np.linspace(1.0, 1.8, 9)]), 6)
"""Frequencies of the BEM run [rad/s]: fixed, so the disk cache serves every wave length;
the RAOs at the case's frequency are interpolated linearly, on a 0.05 rad/s grid up to
0.95 rad/s where heave and pitch vary fast (waves of 68 m to 1540 m) and 0.1 rad/s above.
1.8 rad/s (a 19 m wave) is the shortest wave the 3 m panels resolve (panel radius <
wavelength / 8) and well beyond the waves that bend a 171 m hull."""


_ONE_WAY = "one-way: the cargo as a weight spread over its length (with vessel.coupling = two_way see the *_coupled_* variables)"


def _hull_coupling_attr(name: str) -> dict[str, str]:
    """``hull_coupling = one_way`` on the hull lines that the cargo's load distribution changes."""
    return {"hull_coupling": "one_way"} if name in _ONE_WAY_LINES else {}


_ONE_WAY_LINES = (
    "hull_still_water_deflection_m",
    "hull_still_water_bending_moment_Nm",
    "hull_still_water_shear_force_N",
    "hull_weight_N_per_m",
)


@dataclass(frozen=True)
class _Curve:
    """Deflection [m] and slope [rad] along the ship as a C1 Hermite interpolant."""

    x_m: NDArray[np.float64]
    deflection_m: NDArray[np.float64]
    slope_rad: NDArray[np.float64]

    def __call__(self, x: NDArray[np.float64]) -> tuple[NDArray, NDArray]:
        spl = CubicHermiteSpline(self.x_m, self.deflection_m, self.slope_rad)
        return spl(x), spl(x, 1)


@dataclass(frozen=True)
class VesselExcitation:
    """What the vessel does, independent of the sea-fastening.

    Attributes
    ----------
    omega_rad_s
        Wave frequency [rad/s].
    cargo_aft_end_x_m
        Ship x of the cargo's aft end [m].
    still_water, wave
        Still-water hull response / deck table, and wave hull response / deck table.
    still_water_curve
        Interpolant of the still-water deck deflection (when it came from a moment table).
    motions
        ``RigidBodyMotions`` or None; ``rigid_body`` the amplitudes at the case's wave.
    loading
        The ship's weight distribution (computed hull only).
    girder
        The hull girder (computed hull only), for the two-way coupling.
    source
        Human-readable provenance.
    """

    omega_rad_s: float
    wave_amplitude_m: float
    cargo_aft_end_x_m: float
    still_water: HullGirderResponse | DeckDeflectionTable | None
    wave: WaveHullResponse | DeckDeflectionTable | None
    still_water_curve: _Curve | None
    motions: Any
    rigid_body: RigidBodyAmplitudes | None
    loading: VesselLoading | None
    source: str
    girder: HullGirder | None = None

    def __getstate__(self) -> dict[str, Any]:
        # the cached interpolants below are closures: rebuilt after unpickling, not pickled
        return {k: v for k, v in self.__dict__.items() if k not in ("_still_water_fn", "_wave_fn")}

    # The deck interpolants are built once per vessel (a study assembles the excitation of a new
    # cargo model at every point against the same vessel).
    @functools.cached_property
    def _still_water_fn(self) -> Callable[[NDArray], tuple[NDArray, NDArray]] | None:
        if self.still_water_curve is not None:
            return self.still_water_curve
        if isinstance(self.still_water, DeckDeflectionTable):
            return self.still_water.still_water_at
        if isinstance(self.still_water, HullGirderResponse):
            # the C1 interpolant of deck_deflection_at (nodal deflections and slopes)
            spline = CubicHermiteSpline(self.still_water.x_m, self.still_water.deflection_m, self.still_water.slope_rad)
            return lambda x: (np.asarray(spline(x)), np.asarray(spline(x, 1)))
        return None

    @functools.cached_property
    def _wave_fn(self) -> Callable[[NDArray], tuple[NDArray, NDArray]] | None:
        if isinstance(self.wave, DeckDeflectionTable):
            return self.wave.wave_at
        if isinstance(self.wave, WaveHullResponse):
            # the first harmonic of deck_harmonics_at: its real and imaginary parts' interpolants
            w = self.wave
            parts = [
                CubicHermiteSpline(w.x_m, part(w.deflection_harmonics_m[1]), part(w.slope_harmonics_rad[1])) for part in (np.real, np.imag)
            ]

            def first_harmonic(x: NDArray) -> tuple[NDArray, NDArray]:
                return parts[0](x) + 1j * parts[1](x), parts[0](x, 1) + 1j * parts[1](x, 1)

            return first_harmonic
        return None

    def cargo_excitation(self, model: StructuralModel, case: Case | None = None) -> HarmonicExcitation:
        """The two-harmonic excitation of ``model`` (still water k = 0, wave k = 1)."""
        return assemble_excitation(
            model, self.cargo_aft_end_x_m, self.omega_rad_s, self._still_water_fn, self._wave_fn, self.rigid_body, self.source
        )

    def to_dataset(self) -> xr.Dataset:
        """Hull deflection/moment and RAOs as labelled variables (merged into results.nc)."""
        data: dict[str, Any] = {}
        coords: dict[str, Any] = {}
        attrs = {"cargo_aft_end_x_m": self.cargo_aft_end_x_m, "vessel_source": self.source}
        sw = self.still_water
        if isinstance(sw, HullGirderResponse):
            coords["hull_x_m"] = ("hull_x_m", sw.x_m, {"long_name": "x along the ship from the aft perpendicular", "units": "m"})
            for name, values, long_name, units in (
                (
                    "hull_still_water_deflection_m",
                    sw.deflection_m,
                    f"still-water hull deflection (chord through AP and FP, up +), {_ONE_WAY}",
                    "m",
                ),
                (
                    "hull_still_water_bending_moment_Nm",
                    sw.bending_moment_Nm,
                    f"still-water hull bending moment (sagging +), {_ONE_WAY}",
                    "N m",
                ),
                ("hull_still_water_shear_force_N", sw.shear_force_N, f"still-water hull shear force, {_ONE_WAY}", "N"),
                (
                    "hull_weight_N_per_m",
                    sw.weight_N_per_m,
                    "ship weight per metre, the cargo spread over its length (one-way loading)",
                    "N/m",
                ),
                ("hull_buoyancy_N_per_m", sw.buoyancy_N_per_m, "still-water buoyancy per metre", "N/m"),
            ):
                data[name] = ("hull_x_m", values, {"long_name": long_name, "units": units, **_hull_coupling_attr(name)})
        elif self.still_water_curve is not None:
            c = self.still_water_curve
            coords["hull_x_m"] = ("hull_x_m", c.x_m, {"long_name": "x along the ship from the aft perpendicular", "units": "m"})
            data["hull_still_water_deflection_m"] = (
                "hull_x_m",
                c.deflection_m,
                {"long_name": "still-water hull deflection from the moment table", "units": "m"},
            )
        wv = self.wave
        if isinstance(wv, WaveHullResponse) and "hull_x_m" in coords and np.array_equal(wv.x_m, coords["hull_x_m"][1]):
            coords["hull_period_fraction"] = (
                "hull_period_fraction",
                wv.period_fraction,
                {"long_name": "t/T of the hull wave balance", "units": "1"},
            )
            data["hull_wave_deflection_m"] = (
                ("hull_period_fraction", "hull_x_m"),
                wv.deflection_m,
                {"long_name": f"wave-induced hull deflection, {_ONE_WAY}", "units": "m", "hull_coupling": "one_way"},
            )
            data["hull_wave_bending_moment_Nm"] = (
                ("hull_period_fraction", "hull_x_m"),
                wv.bending_moment_Nm,
                {"long_name": f"wave-induced hull bending moment (sagging +), {_ONE_WAY}", "units": "N m", "hull_coupling": "one_way"},
            )
            if "hull_still_water_bending_moment_Nm" not in data:
                data["hull_still_water_bending_moment_Nm"] = (
                    "hull_x_m",
                    np.zeros_like(wv.x_m),
                    {"long_name": "not computed", "units": "N m"},
                )
        ds = xr.Dataset(data, coords=coords, attrs=attrs)
        if self.motions is not None:
            m = self.motions
            rao = xr.Dataset(
                {
                    "heave_rao_real": ("rao_omega_rad_s", m.heave_rao_m_per_m.real, {"long_name": "heave RAO, real part", "units": "m/m"}),
                    "heave_rao_imag": (
                        "rao_omega_rad_s",
                        m.heave_rao_m_per_m.imag,
                        {"long_name": "heave RAO, imaginary part", "units": "m/m"},
                    ),
                    "pitch_rao_real": (
                        "rao_omega_rad_s",
                        m.pitch_rao_rad_per_m.real,
                        {"long_name": "pitch RAO (bow up), real part", "units": "rad/m"},
                    ),
                    "pitch_rao_imag": (
                        "rao_omega_rad_s",
                        m.pitch_rao_rad_per_m.imag,
                        {"long_name": "pitch RAO (bow up), imaginary part", "units": "rad/m"},
                    ),
                },
                coords={"rao_omega_rad_s": ("rao_omega_rad_s", m.omega_rad_s, {"long_name": "wave frequency", "units": "rad/s"})},
            )
            if getattr(m, "surge_rao_m_per_m", None) is not None:
                rao["surge_rao_real"] = (
                    "rao_omega_rad_s",
                    m.surge_rao_m_per_m.real,
                    {"long_name": "surge RAO (forward +, at the pitch reference), real part", "units": "m/m"},
                )
                rao["surge_rao_imag"] = (
                    "rao_omega_rad_s",
                    m.surge_rao_m_per_m.imag,
                    {"long_name": "surge RAO (forward +, at the pitch reference), imaginary part", "units": "m/m"},
                )
            ds = xr.merge([ds, rao])
            if self.rigid_body is not None:
                rb = self.rigid_body
                ds.attrs.update(
                    heave_amplitude_m=abs(rb.heave_m),
                    heave_phase_rad=float(np.angle(rb.heave_m)),
                    pitch_amplitude_rad=abs(rb.pitch_rad),
                    pitch_phase_rad=float(np.angle(rb.pitch_rad)),
                    pitch_reference_x_m=rb.reference_x_m,
                )
                if rb.surge_m is not None:
                    ds.attrs.update(
                        surge_amplitude_m=abs(rb.surge_m), surge_phase_rad=float(np.angle(rb.surge_m)), pitch_reference_z_m=rb.reference_z_m
                    )
        ds.attrs.update(attrs)
        return ds


# ------------------------------------------------------------------------------ builders
def _read_two_columns(path: str | Path, key: str, columns: tuple[str, str]) -> tuple[NDArray, NDArray]:
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
    """The hull form: the user's breadth table, or the tapered box of L, B, T and displacement.

    The tapered box is memoised on its four particulars (one hull, with its integrals, for all
    the loadings of a cargo study); a table is read at every call.
    """
    v = case.vessel
    if v.hull_form_table is None:
        key = (v.length_m, v.breadth_m, v.draft_m, v.displacement_m3)
        hull = _HULL_CACHE.get(key)
        if hull is None:
            hull = _build_hull_form(case)
            if len(_HULL_CACHE) >= 16:
                _HULL_CACHE.pop(next(iter(_HULL_CACHE)))
            _HULL_CACHE[key] = hull
        return hull
    return _build_hull_form(case)


_HULL_CACHE: dict[tuple[float, float, float, float], HullForm] = {}


def _build_hull_form(case: Case) -> HullForm:
    v = case.vessel
    if v.hull_form_table is not None:
        x, b = _read_two_columns(v.hull_form_table, "vessel.hull_form_table", ("x_m", "breadth_m"))
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


def _cargo_mass_kg(case: Case) -> float:
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
    cargo_mass_kg = case.cargo.units_abreast * _cargo_mass_kg(case)
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


def _motions(case: Case, hull: HullForm, loading: VesselLoading | None) -> Any:
    v = case.vessel
    if v.motions == "none":
        return None
    from seafast.excitation import hydrodynamics as hydro

    props = hydro.base_vessel_mass_properties(hull, water_density_kg_per_m3=v.water_density_kg_per_m3)
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
        return hydro.compute_motions(hull, omega_rad_s=BEM_FREQUENCIES_RAD_S, panel_size_m=v.bem_panel_size_m, **common)
    path = Path(v.motions)
    if not path.exists():
        raise ValueError(
            f"vessel.motions = '{v.motions}': no such file; allowed: bem, none, or a path to capytaine NetCDF / WAMIT .1 output"
        )
    return hydro.load_motions(path, hull, **common)


def vessel_excitation(case: Case) -> VesselExcitation:
    """The vessel's excitation for ``case`` (memoised on the parts of the case it depends on)."""
    key = json.dumps(
        {
            "vessel": case.vessel.model_dump(mode="json"),
            "wave": case.wave.model_dump(mode="json"),
            "cargo_mass": case.cargo.units_abreast * _cargo_mass_kg(case),
            "cargo_length": case.cargo.length_m,
            "cargo_position": case.cargo_position_m(),
            "g": case.model.gravity_m_per_s2,
        },
        sort_keys=True,
    )
    cached = _VESSEL_CACHE.get(key)
    if cached is None:
        cached = _compute_vessel_excitation(case)
        if len(_VESSEL_CACHE) >= 16:
            _VESSEL_CACHE.pop(next(iter(_VESSEL_CACHE)))
        _VESSEL_CACHE[key] = cached
    return cached


# keyed by the parts of the case the vessel depends on (not the whole case: a study over the
# sea-fastening must hit it at every point)
_VESSEL_CACHE: dict[str, VesselExcitation] = {}


def _compute_vessel_excitation(case: Case) -> VesselExcitation:
    v = case.vessel
    omega = case.wave_frequency_rad_s()
    aft = case.cargo_position_m() - 0.5 * case.cargo.length_m
    amplitude = case.wave.amplitude_m
    hull = hull_form_of(case)
    parts: list[str] = []
    still: Any = None
    wave: Any = None
    curve = None
    loading = None
    if v.deck_deflection_table is not None:
        table = read_deck_deflection_table(v.deck_deflection_table)
        still = wave = table
        parts.append(f"deck deflection table '{Path(v.deck_deflection_table).name}'")
    else:
        girder = HullGirder(
            hull,
            second_moment_m4=v.hull_second_moment_m4,
            shear_area_m2=v.hull_shear_area_m2 or DEFAULT_SHEAR_AREA_M2,
            youngs_modulus_Pa=v.youngs_modulus_Pa,
            shear_modulus_Pa=v.youngs_modulus_Pa / (2.0 * (1.0 + v.poisson_ratio)),
            water_density_kg_per_m3=v.water_density_kg_per_m3,
            gravity_m_per_s2=case.model.gravity_m_per_s2,
        )
        loading, loading_note = vessel_loading_of(case, hull)
        # the wave response balances the still-water state too (its first row): solved once
        wave = wave_response(girder, loading, case.wave.length_m, amplitude) if amplitude > 0 else None
        if v.still_water_bending_moment_table is not None:
            x, moment = _read_two_columns(
                v.still_water_bending_moment_table, "vessel.still_water_bending_moment_table", ("x_m", "bending_moment_Nm")
            )
            z, s = deflection_from_bending_moment(girder, x, moment)
            curve = _Curve(x, z, s)
            parts.append(f"still-water moment table '{Path(v.still_water_bending_moment_table).name}'")
        else:
            still = wave.still_water if wave is not None else still_water_response(girder, loading)
            parts.append(f"hull girder ({loading_note}, still water)")
        if wave is not None:
            parts.append(f"quasi-static wave lambda = {case.wave.length_m:g} m, zeta_a = {amplitude:g} m")
    motions = _motions(case, hull, loading)
    rigid = None
    if motions is not None and amplitude > 0:
        # BEM inside its grid, blended into the long-wave limits below it and decayed above it
        heave_rao, pitch_rao = extended_rao(motions, omega, gravity_m_per_s2=case.model.gravity_m_per_s2, draught_m=v.draft_m)
        heave, pitch = complex(heave_rao), complex(pitch_rao)  # per metre of wave, at the one frequency
        surge = coupled_pitch = None
        inside = bool(motions.omega_rad_s[0] <= omega <= motions.omega_rad_s[-1])
        if motions.has_surge and inside:
            surge_c, heave_c, pitch_c = (complex(q) * amplitude for q in motions.coupled_at(omega))
            surge, coupled_pitch = surge_c, pitch_c
        vertical = "heave/pitch (2-DOF)"
        if v.motion_coupling == "surge_heave_pitch" and motions.has_surge and inside:
            heave, pitch = heave_c / amplitude, pitch_c / amplitude
            vertical = "heave/pitch coupled with surge"
        rigid = RigidBodyAmplitudes(
            heave * amplitude,
            pitch * amplitude,
            float(motions.reference_x_m),
            surge_m=surge,
            reference_z_m=float(motions.reference_z_m),
            coupled_pitch_rad=coupled_pitch,
        )
        axial = (
            ("; surge (coupled) for the axial analysis" if inside else "; no surge outside the BEM grid")
            if motions.has_surge
            else "; no surge in the data"
        )
        parts.append(f"{vertical} from {'capytaine BEM' if v.motions == 'bem' else Path(v.motions).name}{axial}")
    elif v.motions == "none":
        parts.append("no rigid-body motion")
    girder_used = None if v.deck_deflection_table is not None else girder
    return VesselExcitation(omega, amplitude, aft, still, wave, curve, motions, rigid, loading, "; ".join(parts), girder_used)
