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

Everything here depends only on the vessel, cargo-mass and wave parts of the case. A
:class:`VesselCache` keeps the excitations of a sequence of cases for whoever owns it (a study
keeps one for its points, so a study over the sea-fastening computes its vessel once), with the
hull forms and the BEM data behind them (a study over the cargo reads the BEM data once).
Without one nothing is kept: :func:`vessel_excitation` computes afresh. The case's vessel keys
are read in :mod:`seafast.excitation.vessel_inputs`, the labelled variables built in
:mod:`seafast.excitation.vessel_dataset`.
"""

from __future__ import annotations

import functools
import json
import threading
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from contextvars import ContextVar
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import xarray as xr
from numpy.typing import NDArray
from scipy.interpolate import CubicHermiteSpline

from seafast.config.modes import MotionCoupling
from seafast.config.schema import Case
from seafast.excitation.deck_motion import RigidBodyAmplitudes, assemble_excitation
from seafast.excitation.deck_table import DeckDeflectionTable, read_deck_deflection_table
from seafast.excitation.harmonic import HarmonicExcitation
from seafast.excitation.hydrodynamics.memory_cache import HydrodynamicsCache
from seafast.excitation.hydrodynamics.motions import RigidBodyMotions
from seafast.excitation.rao_extension import extended_rao
from seafast.excitation.vessel_dataset import (
    moment_table_variables,
    rao_dataset,
    rigid_body_attributes,
    still_water_variables,
    wave_variables,
)
from seafast.excitation.vessel_inputs import (
    DeckLine,
    cargo_unit_mass_kg,
    hull_form_of,
    read_two_column_table,
    rigid_body_motions,
    vessel_loading_of,
)
from seafast.hull.girder import DEFAULT_SHEAR_AREA_M2, HullGirder
from seafast.hull.still_water import HullGirderResponse, deflection_from_bending_moment, still_water_response
from seafast.hull.wave import WaveHullResponse, wave_response
from seafast.model.structure import StructuralModel
from seafast.vessel.hull_form import HullForm
from seafast.vessel.loading import VesselLoading

__all__ = ["VesselExcitation", "VesselCache", "shared_vessel_cache", "vessel_excitation"]


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
        The rigid-body motions (RAOs) or None; ``rigid_body`` the amplitudes at the case's wave.
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
    still_water_curve: DeckLine | None
    motions: RigidBodyMotions | None
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
        coords: dict[str, Any] = {}
        data: dict[str, Any] = {}
        attrs = {"cargo_aft_end_x_m": self.cargo_aft_end_x_m, "vessel_source": self.source}
        if isinstance(self.still_water, HullGirderResponse):
            coords, data = still_water_variables(self.still_water)
        elif self.still_water_curve is not None:
            coords, data = moment_table_variables(self.still_water_curve)
        if isinstance(self.wave, WaveHullResponse):
            wave_variables(self.wave, coords, data)
        ds = xr.Dataset(data, coords=coords, attrs=attrs)
        if self.motions is not None:
            ds = xr.merge([ds, rao_dataset(self.motions)])
            if self.rigid_body is not None:
                ds.attrs.update(rigid_body_attributes(self.rigid_body))
        ds.attrs.update(attrs)
        return ds


class VesselCache:
    """The vessel excitations of a sequence of cases, kept by whoever evaluates them.

    Keeps, each up to ``max_vessels`` (the oldest goes first):

    * the excitations, by the parts of the case they depend on (vessel, wave, the cargo's mass,
      length and position, gravity): a study over the sea-fastening computes its vessel once;
    * the tapered-box hull forms, by their four particulars: one hull, with the integrals it
      keeps, for all the loadings of a cargo study;
    * the BEM data, ``hydrodynamics`` (a
      :class:`~seafast.excitation.hydrodynamics.memory_cache.HydrodynamicsCache`): the dataset
      read from the disk cache and its coefficients, for every loading of the same hull.

    Pass it to :func:`vessel_excitation`, or share it with the code a block calls
    (``with cache.shared(): ...``): the pipeline, the sea-state analysis and the rest call
    ``vessel_excitation(case)`` and find it there. What it keeps is what a fresh computation
    gives, to the bit; only the time differs.

    Parameters
    ----------
    max_vessels
        Excitations (and hull forms) kept [-], >= 1.
    """

    def __init__(self, max_vessels: int = 16) -> None:
        if max_vessels < 1:
            raise ValueError(f"VesselCache: max_vessels = {max_vessels!r}; must be >= 1")
        self.max_vessels = int(max_vessels)
        self.hydrodynamics = HydrodynamicsCache()
        self._excitations: dict[str, VesselExcitation] = {}
        self._hull_forms: dict[tuple[float, float, float, float], HullForm] = {}
        self._lock = threading.Lock()  # Dask runs batches on threads: the bookkeeping, not the computing, is serialised

    def __len__(self) -> int:
        """Number of excitations kept."""
        return len(self._excitations)

    def excitation(self, case: Case) -> VesselExcitation:
        """The vessel excitation of ``case``: the one kept for its vessel, or computed and kept."""
        key = _vessel_key(case)
        held = self._excitations.get(key)
        if held is None:
            held = _compute_vessel_excitation(case, self)
            self._keep(self._excitations, key, held)
        return held

    def hull_form(self, case: Case) -> HullForm:
        """:func:`~seafast.excitation.vessel_inputs.hull_form_of` of the case; a tapered box is kept by its particulars."""
        v = case.vessel
        if v.hull_form_table is not None:
            return hull_form_of(case)
        key = (v.length_m, v.breadth_m, v.draft_m, v.displacement_m3)
        held = self._hull_forms.get(key)
        if held is None:
            held = hull_form_of(case)
            self._keep(self._hull_forms, key, held)
        return held

    def _keep(self, store: dict, key: object, value: object) -> None:
        """Put ``value`` in ``store``, dropping the oldest entry when it holds ``max_vessels``."""
        with self._lock:
            if len(store) >= self.max_vessels:
                store.pop(next(iter(store)))
            store[key] = value

    @contextmanager
    def shared(self) -> Iterator[VesselCache]:
        """Within the block (this thread or task), :func:`vessel_excitation` called without a cache uses this one."""
        token = _SHARED.set(self)
        try:
            yield self
        finally:
            _SHARED.reset(token)


_SHARED: ContextVar[VesselCache | None] = ContextVar("seafast_shared_vessel_cache", default=None)
"""The cache the innermost ``with cache.shared()`` block shares; None outside every such block."""


def shared_vessel_cache() -> VesselCache | None:
    """The :class:`VesselCache` the innermost ``with cache.shared()`` block around this call shares, or None."""
    return _SHARED.get()


def _vessel_key(case: Case) -> str:
    """The parts of the case the vessel depends on (not the whole case: a study over the sea-fastening shares it)."""
    return json.dumps(
        {
            "vessel": case.vessel.model_dump(mode="json"),
            "wave": case.wave.model_dump(mode="json"),
            "cargo_mass": case.cargo.units_abreast * cargo_unit_mass_kg(case),
            "cargo_length": case.cargo.length_m,
            "cargo_position": case.cargo_position_m(),
            "g": case.model.gravity_m_per_s2,
        },
        sort_keys=True,
    )


def vessel_excitation(case: Case, cache: VesselCache | None = None) -> VesselExcitation:
    """The vessel's excitation for ``case``.

    Parameters
    ----------
    case
        The validated case.
    cache
        Where to keep the result and find it again (with the hull form and the BEM data behind
        it); default: the cache shared by the innermost ``with cache.shared()`` block around
        this call, else none (computed afresh at every call).
    """
    cache = cache if cache is not None else _SHARED.get()
    return _compute_vessel_excitation(case, None) if cache is None else cache.excitation(case)


def _compute_vessel_excitation(case: Case, cache: VesselCache | None) -> VesselExcitation:
    """The vessel excitation of ``case``, its hull form and BEM data from ``cache`` when given."""
    v = case.vessel
    omega = case.wave_frequency_rad_s()
    aft = case.cargo_position_m() - 0.5 * case.cargo.length_m
    amplitude = case.wave.amplitude_m
    hull = hull_form_of(case) if cache is None else cache.hull_form(case)
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
        wave = wave_response(girder, loading, case.wave.length_m, amplitude, heading_deg=case.wave.heading_deg) if amplitude > 0 else None
        if v.still_water_bending_moment_table is not None:
            x, moment = read_two_column_table(
                v.still_water_bending_moment_table, "vessel.still_water_bending_moment_table", ("x_m", "bending_moment_Nm")
            )
            z, s = deflection_from_bending_moment(girder, x, moment)
            curve = DeckLine(x, z, s)
            parts.append(f"still-water moment table '{Path(v.still_water_bending_moment_table).name}'")
        else:
            still = wave.still_water if wave is not None else still_water_response(girder, loading)
            parts.append(f"hull girder ({loading_note}, still water)")
        if wave is not None:
            parts.append(f"quasi-static wave lambda = {case.wave.length_m:g} m, zeta_a = {amplitude:g} m")
    motions = rigid_body_motions(case, hull, loading, None if cache is None else cache.hydrodynamics)
    rigid = None
    if motions is not None and amplitude > 0:
        rigid, description = _rigid_body_amplitudes(case, motions, omega, amplitude)
        parts.append(description)
    elif v.motions == "none":
        parts.append("no rigid-body motion")
    girder_used = None if v.deck_deflection_table is not None else girder
    return VesselExcitation(omega, amplitude, aft, still, wave, curve, motions, rigid, loading, "; ".join(parts), girder_used)


def _rigid_body_amplitudes(case: Case, motions: RigidBodyMotions, omega: float, amplitude: float) -> tuple[RigidBodyAmplitudes, str]:
    """Heave, pitch (and surge, coupled, when the data hold it) at the case's wave, and a description of their source.

    The RAOs are the BEM's inside its grid, blended into the long-wave limits below it and decayed
    above it (:func:`~seafast.excitation.rao_extension.extended_rao`); surge only inside the grid.
    """
    v = case.vessel
    heave_rao, pitch_rao = extended_rao(motions, omega, gravity_m_per_s2=case.model.gravity_m_per_s2, draught_m=v.draft_m)
    heave, pitch = complex(heave_rao), complex(pitch_rao)  # per metre of wave, at the one frequency
    surge = coupled_pitch = None
    inside = bool(motions.omega_rad_s[0] <= omega <= motions.omega_rad_s[-1])
    if motions.has_surge and inside:
        surge_c, heave_c, pitch_c = (complex(q) * amplitude for q in motions.coupled_at(omega))
        surge, coupled_pitch = surge_c, pitch_c
    vertical = "heave/pitch (2-DOF)"
    if v.motion_coupling is MotionCoupling.SURGE_HEAVE_PITCH and motions.has_surge and inside:
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
    return rigid, f"{vertical} from {'capytaine BEM' if v.motions == 'bem' else Path(v.motions).name}{axial}"
