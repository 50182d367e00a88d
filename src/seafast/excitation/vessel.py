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

from seafast.config.schema import Case
from seafast.excitation.cargo_acceleration import CargoPoints
from seafast.excitation.deck_motion import RigidBodyAmplitudes, assemble_excitation
from seafast.excitation.deck_table import DeckDeflectionTable, read_deck_deflection_table
from seafast.excitation.harmonic import HarmonicExcitation
from seafast.excitation.hydrodynamics.heading_motions import SixDofMotions
from seafast.excitation.hydrodynamics.memory_cache import HydrodynamicsCache
from seafast.excitation.hydrodynamics.motions import RigidBodyMotions
from seafast.excitation.vessel_amplitudes import rigid_body_amplitudes, six_dof_amplitudes
from seafast.excitation.vessel_dataset import (
    moment_table_variables,
    rao_dataset,
    rigid_body_attributes,
    six_motion_variables,
    still_water_variables,
    wave_variables,
)
from seafast.excitation.vessel_inputs import (
    HEAD_SEAS_DEG,
    DeckLine,
    cargo_axis_height_m,
    cargo_points_of,
    cargo_unit_mass_kg,
    hull_form_of,
    is_head_seas,
    read_two_column_table,
    rigid_body_motions,
    six_dof_motions_of,
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
    heading_deg
        Wave heading [deg] (180: head seas, the heave-pitch model; otherwise the six-DOF motions).
    motions6
        The six motions at every heading (off head seas; ``motions`` is then None), or None.
    cargo_points
        The analysed unit's points whose accelerations are reported (with motions), or None.
    motion_amplitudes
        The six motions at the case's wave (surge, sway, heave [m], roll, pitch bow up, yaw [rad]; complex), or None;
        in head seas sway, roll and yaw are 0 and surge is the coupled one (NaN without surge in the data).
    gravity_m_per_s2
        g [m/s^2] (the gravity parts of the cargo's accelerations).
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
    heading_deg: float = HEAD_SEAS_DEG
    motions6: SixDofMotions | None = None
    cargo_points: CargoPoints | None = None
    motion_amplitudes: NDArray[np.complex128] | None = None
    gravity_m_per_s2: float = 9.81

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
            ds = xr.merge([ds, rao_dataset(self.motions)], compat="no_conflicts", join="outer")
            if self.rigid_body is not None:
                ds.attrs.update(rigid_body_attributes(self.rigid_body))
        ds = six_motion_variables(
            ds, self.motions, self.motions6, self.cargo_points, self.omega_rad_s, self.motion_amplitudes, self.heading_deg
        )
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
            "cargo_transverse_position": case.cargo_transverse_position_m(),
            "cargo_axis_height": cargo_axis_height_m(case),
            "units_abreast": case.cargo.units_abreast,
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
    memory = None if cache is None else cache.hydrodynamics
    head = is_head_seas(case)
    motions = rigid_body_motions(case, hull, loading, memory) if head else None
    motions6 = None if head else six_dof_motions_of(case, hull, loading, memory)
    rigid = q = None
    if motions is not None and amplitude > 0:
        rigid, description = rigid_body_amplitudes(case, motions, omega, amplitude)
        q = np.array([rigid.surge_m if rigid.surge_m is not None else np.nan, 0.0, rigid.heave_m, 0.0, rigid.pitch_rad, 0.0], dtype=complex)
        parts.append(description)
    elif motions6 is not None and amplitude > 0:
        rigid, q, description = six_dof_amplitudes(case, motions6, omega, amplitude)
        parts.append(description)
    elif v.motions == "none":
        parts.append("no rigid-body motion")
    girder_used = None if v.deck_deflection_table is not None else girder
    points = cargo_points_of(case) if (motions is not None or motions6 is not None) else None
    return VesselExcitation(
        omega,
        amplitude,
        aft,
        still,
        wave,
        curve,
        motions,
        rigid,
        loading,
        "; ".join(parts),
        girder_used,
        heading_deg=case.wave.heading_deg,
        motions6=motions6,
        cargo_points=points,
        motion_amplitudes=q,
        gravity_m_per_s2=case.model.gravity_m_per_s2,
    )
