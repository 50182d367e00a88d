"""seastate.nc's variables of the cargo on its cradles off head seas (docs/seastate.md#5-outputs).

Per element (dimension ``cradle_element``: the pads port and starboard per saddle, the side stoppers, the lashing
wires) and per saddle the still water and the linear dynamic MPMs, and the cradle design waves (dimension
``cradle_design_wave``) with what each is read for; ``units`` and ``long_name`` on every variable. On frictional pads
(``seafastening.friction_coefficient`` above 0) the design waves' readings are the frictional solves', and seastate.csv
and the design waves gain the pads' friction utilisation and slip (:data:`CRADLE_FRICTION_QUANTITIES`).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
import xarray as xr

from seafast.analyses.seastate.cradle_design_wave import CradleSeaState, cradle_design_wave_readings
from seafast.analyses.seastate.cradle_extremes import CRADLE_COLUMNS, cradle_columns
from seafast.analyses.seastate.cradle_friction_wave import CRADLE_FRICTION_COLUMNS
from seafast.analyses.seastate.cradle_statistics import CradleStatistics
from seafast.analyses.seastate.spectral import SEASTATE_COLUMNS
from seafast.results.labelled import labelled_variable as _var

__all__ = [
    "CRADLE_QUANTITIES",
    "CRADLE_FRICTION_QUANTITIES",
    "CRADLE_TABLE_HEAD",
    "CRADLE_FRICTION_TABLE_HEAD",
    "cradle_table_head",
    "seastate_columns",
    "cradle_table_cells",
    "cradle_table_variables",
    "cradle_variables",
    "cradle_coords",
    "monte_carlo_cradle_columns",
]

CRADLE_TABLE_HEAD = ("F_pad [MN]", "F_stopper [MN]", "T_max [kN]", "T_min [kN]", "slip [mm]")
"""The cradle columns' heads in the terminal table (off head seas)."""

CRADLE_FRICTION_TABLE_HEAD = ("mu use [-]", "pad slip [mm]")
"""The heads of :data:`CRADLE_FRICTION_QUANTITIES` in the terminal table (on frictional pads)."""

_TABLE_SCALE = {
    "F_pad_N": 1e-6,
    "F_stopper_N": 1e-6,
    "lashing_tension_max_N": 1e-3,
    "lashing_tension_min_N": 1e-3,
    "transverse_slip_m": 1e3,
}
_FRICTION_TABLE_SCALE = {"pad_friction_utilisation": (1.0, 3), "pad_slip_m": (1e3, 2)}

CRADLE_QUANTITIES = {
    "F_pad_N": ("most probable maximum pad force over the saddles and sides, still water included", "N"),
    "F_stopper_N": ("most probable maximum side-stopper force, still water included (0: no stopper, or none closes)", "N"),
    "lashing_tension_max_N": ("most probable maximum lashing-wire tension, still water included (0: no wires)", "N"),
    "lashing_tension_min_N": (
        "most probable minimum lashing-wire tension, still water included (linear: below 0 where a wire would go slack)",
        "N",
    ),
    "transverse_slip_m": (
        "most probable maximum lateral displacement of the cargo axis relative to the deck at a saddle, still water included",
        "m",
    ),
}
"""The cradle columns (off head seas): long name and unit."""

CRADLE_FRICTION_QUANTITIES = {
    "pad_friction_utilisation": (
        (
            "largest pad friction utilisation |f| / (mu F_n) over the cradle design waves, or its most probable maximum "
            "over the duration in the nonlinear Monte Carlo row (frictional pads; 1 where a pad slips)"
        ),
        "1",
    ),
    "pad_slip_m": (
        (
            "largest slip of a pad, its slider's displacement from rest |w - w_rest|, over the cradle design waves, or its "
            "most probable maximum over the duration in the nonlinear Monte Carlo row (frictional pads)"
        ),
        "m",
    ),
}
"""The columns after the cradle columns on frictional pads (the design-wave and nonlinear Monte Carlo rows'): long name
and unit."""


def _has_friction(rows: Sequence[Mapping[str, Any]]) -> bool:
    return any(c in r for r in rows for c in CRADLE_FRICTION_COLUMNS)


def seastate_columns(rows: Sequence[Mapping[str, Any]]) -> tuple[str, ...]:
    """seastate.csv's columns: today's, and the cradle columns after ``converged`` when a row carries them (off head seas),
    then the friction's (:data:`CRADLE_FRICTION_QUANTITIES`) when a row carries them (frictional pads)."""
    cradle = any(c in r for r in rows for c in CRADLE_COLUMNS)
    return SEASTATE_COLUMNS + (CRADLE_COLUMNS if cradle else ()) + (CRADLE_FRICTION_COLUMNS if _has_friction(rows) else ())


def cradle_table_head(rows: Sequence[Mapping[str, Any]]) -> tuple[str, ...]:
    """The cradle heads of the terminal table: :data:`CRADLE_TABLE_HEAD`, then the friction's on frictional pads."""
    return CRADLE_TABLE_HEAD + (CRADLE_FRICTION_TABLE_HEAD if _has_friction(rows) else ())


def cradle_table_variables(rows: Sequence[Mapping[str, Any]], models: list[str], methods: list[str]) -> dict[str, xr.Variable]:
    """The cradle columns of seastate.csv over (model, estimate_method), NaN where not computed; none in head seas."""
    v: dict[str, xr.Variable] = {}
    if len(seastate_columns(rows)) == len(SEASTATE_COLUMNS):
        return v
    quantities = CRADLE_QUANTITIES | (CRADLE_FRICTION_QUANTITIES if _has_friction(rows) else {})
    for q, (long_name, unit) in quantities.items():
        table = np.full((len(models), len(methods)), np.nan)
        for r in rows:
            if r.get(q) is not None:
                table[models.index(r["model"]), methods.index(r["method"])] = r[q]
        v[q] = _var(("model", "estimate_method"), table, long_name + " (NaN: not computed)", unit)
    return v


def cradle_variables(cradle: CradleSeaState) -> dict[str, xr.Variable]:
    """The cradle quantities off head seas: per element (dimension ``cradle_element``) and saddle, and their design waves."""
    e, problem = cradle.spectral, cradle.sea.dynamics.problem
    kinds = [f"pad_{side}" for _ in problem.pad_pairs for side in ("port", "starboard")]
    kinds += [f"stopper_{s.side.value}" for s in problem.stoppers] + ["lashing"] * len(problem.lashings)
    saddle = [i // 2 for i in range(e.pad_count)] + [i // 2 for i in range(e.stopper_count)] + list(cradle.sea.cradle.lashing_saddle)
    c, s = ("cradle_element",), ("saddle",)
    v: dict[str, xr.Variable] = {
        "cradle_element_kind": xr.Variable(
            c, np.array(kinds, dtype=str), {"long_name": "pad (port, starboard), side stopper or lashing wire", "units": "1"}
        ),
        "cradle_element_saddle": _var(c, np.asarray(saddle, dtype=np.int64), "saddle index of the element", "1"),
        "still_water_cradle_element_force_N": _var(
            c, e.still_water.element_force_N, "still-water force of the element (exact statics)", "N"
        ),
        "still_water_cradle_element_engagement_m": _var(
            c, e.still_water.engagement_m, "still-water engagement: pad compression, stopper overclosure, wire stretch (<= 0 open)", "m"
        ),
        "cradle_element_force_mpm_dynamic_N": _var(
            c, e.element_force.mpm, "Rayleigh most probable maximum of the dynamic element force (linear; stoppers open: 0)", "N"
        ),
        "cradle_element_engagement_mpm_dynamic_m": _var(
            c, e.engagement.mpm, "Rayleigh most probable maximum of the dynamic engagement of the element (linear)", "m"
        ),
        "still_water_lateral_displacement_m": _var(
            s, e.still_water.lateral_displacement_m, "still-water lateral displacement of the cargo axis at the saddle, to port +", "m"
        ),
        "lateral_displacement_mpm_dynamic_m": _var(
            s, e.lateral_displacement.mpm, "Rayleigh most probable maximum of the dynamic lateral displacement at the saddle (linear)", "m"
        ),
    }
    design = cradle.design
    if design is None:
        return v
    d = ("cradle_design_wave",)
    w = design.waves
    v["cradle_design_wave_quantity"] = xr.Variable(
        d, np.array([x.quantity for x in w], dtype=str), {"long_name": "seastate.csv column the wave is designed for", "units": "1"}
    )
    v["cradle_design_wave_location"] = _var(
        d, [x.location for x in w], "element (cradle_element) or saddle (transverse_slip_m) designed for", "1"
    )
    v["cradle_design_wave_omega_rad_s"] = _var(d, [x.omega_rad_s for x in w], "design wave frequency", "rad/s")
    v["cradle_design_wave_amplitude_m"] = _var(
        d, [x.amplitude_m for x in w], "design wave amplitude (linear response = linear spectral MPM)", "m"
    )
    v["cradle_design_wave_heading_deg"] = _var(d, [x.heading_deg for x in w], "design wave heading (180 = head seas)", "deg")
    v["cradle_design_wave_reading"] = _var(
        d, design.readings, "the element's largest (lashing_tension_min_N: least) value over the wave's period (nonlinear)", "N or m"
    )
    v["cradle_design_wave_harmonics"] = _var(
        d, [r.harmonics for r in design.responses], "harmonics H of the harmonic balance that solved the wave", "1"
    )
    v["cradle_design_wave_converged"] = _var(
        d, np.array([r.converged for r in design.responses], dtype=np.int8), "harmonic balance converged (1) or not (0)", "1"
    )
    return v | _design_wave_friction_variables(cradle)


def _design_wave_friction_variables(cradle: CradleSeaState) -> dict[str, xr.Variable]:
    """On frictional pads, per design wave its friction utilisation and pad slip and its frictionless reading."""
    design = cradle.design
    if design is None or design.frictional is None or design.frictionless is None:
        return {}
    d = ("cradle_design_wave",)
    frictional, frictionless = design.frictional, design.frictionless
    return {
        "cradle_design_wave_pad_friction_utilisation": _var(
            d,
            [float(np.max(f.friction_utilisation, initial=0.0)) for f in frictional],
            "largest pad friction utilisation |f| / (mu F_n) over the wave's period",
            "1",
        ),
        "cradle_design_wave_pad_slip_m": _var(
            d,
            [float(np.max(f.max_slip_m, initial=0.0)) for f in frictional],
            "largest slip of a pad |w - w_rest| over the wave's period",
            "m",
        ),
        "cradle_design_wave_reading_frictionless": _var(
            d,
            cradle_design_wave_readings(cradle.sea.dynamics.problem, design.waves, frictionless),
            "the reading of the same wave on frictionless pads (nonlinear)",
            "N or m",
        ),
        "cradle_design_wave_frictionless_converged": _var(
            d, np.array([r.converged for r in frictionless], dtype=np.int8), "the frictionless solve converged (1) or not (0)", "1"
        ),
    }


def cradle_table_cells(row: Mapping[str, Any], friction: bool = False) -> list[str]:
    """A row's cradle cells in the terminal table (MN, kN, mm; "not computed" where empty); with ``friction`` also the
    pads' friction utilisation [-] and slip [mm]."""
    cells = ["not computed" if row.get(q) is None else f"{row[q] * s:.{3 if s == 1e-6 else 2}f}" for q, s in _TABLE_SCALE.items()]
    if friction:
        cells += ["not computed" if row.get(q) is None else f"{row[q] * s:.{n}f}" for q, (s, n) in _FRICTION_TABLE_SCALE.items()]
    return cells


def cradle_coords(cradle: CradleSeaState) -> dict[str, xr.Variable]:
    """The coordinates ``cradle_element`` and (with the design waves) ``cradle_design_wave``."""
    coords = {"cradle_element": _var(("cradle_element",), np.arange(cradle.spectral.element_force.mpm.size), "cradle element index", "1")}
    if cradle.design is not None:
        n = len(cradle.design.waves)
        coords["cradle_design_wave"] = _var(("cradle_design_wave",), np.arange(n), "cradle design wave index", "1")
    return coords


def monte_carlo_cradle_columns(statistics: CradleStatistics | None) -> dict[str, float | None]:
    """The five cradle columns of a Monte Carlo row: one model's most probable extremes
    (:class:`~seafast.analyses.seastate.cradle_statistics.CradleStatistics`), or empty cells (None) without them; on
    frictional pads the nonlinear model's friction columns (:data:`CRADLE_FRICTION_QUANTITIES`) too."""
    columns = cradle_columns(None if statistics is None else statistics.mpm)
    if statistics is not None:
        columns.update({q: float(statistics.mpm[q]) for q in CRADLE_FRICTION_COLUMNS if q in statistics.mpm})
    return columns
