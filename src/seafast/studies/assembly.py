"""Study results from the point store: the labelled ``study.nc`` dataset and ``study.csv``.

Both are assembled from the finished :class:`~seafast.studies.store.PointRecord` of every point
(missing points are left NaN with the error ``"not evaluated"``) and written atomically
(temporary file, then rename), so a study killed while writing leaves the previous file or none.
Each row's typed warnings are the ``warnings`` column of ``study.csv`` (values joined by ``;``)
and the ``warning_flag`` of ``study.nc`` along its ``warning`` coordinate
(:mod:`seafast.studies.messages`).
"""

from __future__ import annotations

import csv
import json
import math
import os
from collections.abc import Iterable
from pathlib import Path
from typing import Any

import numpy as np
import xarray as xr

from seafast.results.cradle import CRADLE_FIELD_LONG_NAMES, CRADLE_SUMMARY_COLUMNS, FRICTION_SUMMARY_COLUMNS
from seafast.studies.limits import CRADLE_LIMITS
from seafast.studies.messages import warning_kinds, warning_values
from seafast.studies.spec import StudyError, StudyGrid, units_of_key
from seafast.studies.store import PointRecord

__all__ = [
    "CORE_COLUMNS",
    "SEA_STATE_FRICTION_COLUMNS",
    "WARNINGS_COLUMN",
    "LOAD_CASES",
    "MODELS",
    "assemble_dataset",
    "study_rows",
    "write_study_csv",
    "write_study_netcdf",
]

LOAD_CASES: tuple[str, ...] = ("static", "dynamic")
MODELS: tuple[str, ...] = ("linear", "nonlinear")

#: Columns of ``study.csv`` after the study's dotted keys (a contract: README, "Parametric studies").
CORE_COLUMNS: tuple[str, ...] = (
    "load_case",
    "model",
    "u_c_m",
    "u_s_m",
    "u_d_m",
    "F_N",
    "M_b_Nm",
    "sigma_b_Pa",
    "converged",
    "contact_preserved",
)
_FLOAT_RESULTS: tuple[str, ...] = ("u_c_m", "u_s_m", "u_d_m", "F_N", "M_b_Nm", "sigma_b_Pa")
_BOOL_RESULTS: tuple[str, ...] = ("converged", "contact_preserved")
_LONG_NAMES: dict[str, str] = {
    "u_c_m": "maximum cargo deflection u_c",
    "u_s_m": "maximum saddle compression u_s",
    "u_d_m": "maximum detachment (gap) u_d (nonlinear model only)",
    "F_N": "maximum saddle normal force F",
    "M_b_Nm": "maximum cargo bending moment M_b",
    "sigma_b_Pa": "maximum cargo bending stress sigma_b = M_b (D/2) / I",
    "converged": "nonlinear solver converged",
    "contact_preserved": "contact preserved at every saddle over the whole period (linear model valid)",
    "residual_norm": "final residual norm of the nonlinear solver",
    "iterations": "nonlinear solver iterations",
    "error": "error text of a point whose evaluation failed (empty when it succeeded)",
    "eval_seconds": "wall time to evaluate the point",
    "warning_flag": "typed warning raised by the row's solution or model (one per warning kind, coordinate warning)",
    **CRADLE_FIELD_LONG_NAMES,
    "pad_slip_m": "largest slip of a pad |w - w_rest| over the cradle design waves (sea-state study, frictional pads)",
}
WARNINGS_COLUMN = "warnings"
"""The column of ``study.csv`` (and the row key) holding a row's typed warnings."""


# --------------------------------------------------------------------------- assembly
def _axis_columns(grid: StudyGrid) -> list[str]:
    return list(grid.keys)


def _labels(records: Iterable[PointRecord], key: str, canonical: tuple[str, ...]) -> list[str]:
    """The labels the rows use: the canonical ones first (all of them when no row has a label, e.g. every
    point failed), then others in order of appearance (a sea-state study's ``sea_state`` load case)."""
    found: list[str] = []
    for r in records:
        for row in r.rows:
            v = row.get(key)
            if isinstance(v, str) and v not in found:
                found.append(v)
    if not found:
        return list(canonical)
    return [c for c in canonical if c in found] + [v for v in found if v not in canonical]


SEA_STATE_FRICTION_COLUMNS: tuple[str, ...] = ("pad_slip_m",)
"""The friction column a sea-state study's rows add after :data:`FRICTION_SUMMARY_COLUMNS` (as ``seastate.csv``)."""
_FRICTION_COLUMNS = FRICTION_SUMMARY_COLUMNS + SEA_STATE_FRICTION_COLUMNS


def _cradle_columns(records: Iterable[PointRecord]) -> tuple[str, ...]:
    """The cargo-on-its-cradles columns when some row has them (a point off head seas), else none (head seas); with
    frictional pads the friction's after them, as in ``summary.csv`` (and a sea-state study's pad slip, as in
    ``seastate.csv``)."""
    rows = [row for r in records for row in r.rows]
    cradle = CRADLE_SUMMARY_COLUMNS if any(k in row for row in rows for k in CRADLE_SUMMARY_COLUMNS) else ()
    return cradle + tuple(k for k in _FRICTION_COLUMNS if any(k in row for row in rows))


def _extra_keys(records: Iterable[PointRecord]) -> list[str]:
    core = {*CORE_COLUMNS, *CRADLE_SUMMARY_COLUMNS, *_FRICTION_COLUMNS, WARNINGS_COLUMN}
    extras: list[str] = []
    for r in records:
        for row in r.rows:
            for k in row:
                if k not in core and k not in extras:
                    extras.append(k)
    return extras


def _derived_values(grid: StudyGrid) -> dict[str, np.ndarray]:
    """Per-point values of the derived keys, over the study dimensions."""
    out: dict[str, np.ndarray] = {}
    if not grid.spec.derived:
        return out
    arrays = {k: np.full(grid.size, np.nan) for k in grid.spec.derived}
    for i in range(grid.size):
        try:
            overrides = grid.point_overrides(i)
        except Exception:  # noqa: BLE001 - the point's own record carries the error
            continue
        for k in arrays:
            arrays[k][i] = float(overrides[k])
    for k, a in arrays.items():
        out[k] = a.reshape(grid.shape)
    return out


def _warning_flags(
    records: dict[int, PointRecord], shape: tuple[int, int, int], lc_index: dict[str, int], m_index: dict[str, int], kinds: list[str]
) -> np.ndarray:
    """(point, load case, model, kind) booleans: the row raised the typed warning."""
    flags = np.zeros((*shape, len(kinds)), dtype=bool)
    for index, record in records.items():
        for row in record.rows:
            li, mi = lc_index.get(str(row.get("load_case"))), m_index.get(str(row.get("model")))
            if li is not None and mi is not None:
                raised = warning_values(row.get(WARNINGS_COLUMN))
                flags[index, li, mi] = [kind in raised for kind in kinds]
    return flags


def _coordinates(grid: StudyGrid, load_cases: list[str], models: list[str], kinds: list[str]) -> dict[str, Any]:
    """The study dataset's coordinates: the axes (units, scale, base value), derived keys, load cases, models, warnings."""
    coords: dict[str, Any] = {}
    for axis, key, c in zip(grid.spec.axes, grid.keys, grid.coordinates, strict=True):
        try:
            base_value = float(grid.base_value(key))
        except (StudyError, TypeError, ValueError):
            base_value = float("nan")
        coords[key] = (key, c, {"units": units_of_key(key), "long_name": key, "scale": axis.scale, "base_value": base_value})
    for key, a in _derived_values(grid).items():
        coords[key] = (grid.keys, a, {"units": units_of_key(key), "long_name": f"{key} = {grid.spec.derived[key]}"})
    coords["load_case"] = ("load_case", np.array(load_cases, dtype=str), {"long_name": "load case (dynamic = total response)"})
    coords["model"] = ("model", np.array(models, dtype=str), {"long_name": "response model"})
    coords["warning"] = (
        "warning",
        np.array(kinds, dtype=str),
        {"units": "1", "long_name": "typed warning (SolverWarning or ModelWarning value)"},
    )
    return coords


def _attributes(grid: StudyGrid, records: dict[int, PointRecord]) -> dict[str, Any]:
    """The study dataset's global attributes (identity, limits, counts)."""
    base_counts = "seafastening.saddle_count" not in grid.keys
    attrs = {
        "study": grid.spec.name,
        "description": grid.spec.description,
        "fingerprint": grid.fingerprint(),
        "axes": " ".join(grid.keys),
        "study_spec_json": json.dumps(grid.spec.model_dump(mode="json")),
        "base_case_json": json.dumps(grid.base),
        "max_saddle_force_N": grid.spec.limits.max_saddle_force_N,
        "max_bending_stress_Pa": grid.spec.limits.max_bending_stress_Pa,
        "points": grid.size,
        "failed_points": int(sum(1 for r in records.values() if r.error)),
    }
    for name, _ in CRADLE_LIMITS:  # recorded where set (a study without them keeps its attributes)
        if getattr(grid.spec.limits, name) is not None:
            attrs[name] = float(getattr(grid.spec.limits, name))
    if base_counts:
        attrs["saddle_count"] = int(grid.base["seafastening"]["saddle_count"])
    return attrs


def assemble_dataset(grid: StudyGrid, records: dict[int, PointRecord]) -> xr.Dataset:
    """The study's labelled results.

    Parameters
    ----------
    grid : StudyGrid
        The study.
    records : dict of int to PointRecord
        Finished points by flat index (missing points are left NaN with error ``"not evaluated"``).

    Returns
    -------
    xarray.Dataset
        Dimensions: the axis keys (dotted names), ``load_case`` (static, dynamic) and ``model``
        (linear, nonlinear). Variables ``u_c_m, u_s_m, u_d_m, F_N, M_b_Nm, sigma_b_Pa`` (float,
        NaN where missing), ``converged`` and ``contact_preserved`` (bool, False where missing),
        numeric diagnostics (e.g. ``residual_norm``, ``iterations``), ``warning_flag`` (bool, the
        study dimensions, ``load_case``, ``model`` and ``warning``: the row raised that typed
        warning), ``error`` (str per point) and ``eval_seconds``; each with ``units`` and
        ``long_name``.
    """
    values = list(records.values())
    load_cases = _labels(values, "load_case", LOAD_CASES)
    models = _labels(values, "model", MODELS)
    extras = _extra_keys(values)
    numeric_extras = [
        k for k in extras if all(isinstance(row.get(k), (int, float, bool)) or row.get(k) is None for r in values for row in r.rows)
    ]
    text_extras = [k for k in extras if k not in numeric_extras]
    n, nl, nm = grid.size, len(load_cases), len(models)
    floats = {k: np.full((n, nl, nm), np.nan) for k in (*_FLOAT_RESULTS, *_cradle_columns(values), *numeric_extras)}
    bools = {k: np.zeros((n, nl, nm), dtype=bool) for k in _BOOL_RESULTS}
    texts = {k: np.full((n, nl, nm), "", dtype=object) for k in text_extras}
    kinds = warning_kinds(values)
    error = np.full(n, "not evaluated", dtype=object)
    seconds = np.full(n, np.nan)
    lc_index = {v: i for i, v in enumerate(load_cases)}
    m_index = {v: i for i, v in enumerate(models)}
    for index, record in records.items():
        error[index] = record.error
        seconds[index] = record.seconds
        for row in record.rows:
            li, mi = lc_index.get(str(row.get("load_case"))), m_index.get(str(row.get("model")))
            if li is None or mi is None:
                continue
            for k, a in floats.items():
                v = row.get(k)
                if isinstance(v, (int, float)) and v is not None:
                    a[index, li, mi] = float(v)
            for k, a in bools.items():
                a[index, li, mi] = bool(row.get(k, False))
            for k, a in texts.items():
                a[index, li, mi] = "" if row.get(k) is None else str(row.get(k))
    dims = (*grid.keys, "load_case", "model")
    shape = (*grid.shape, nl, nm)
    data_vars: dict[str, Any] = {}
    for k, a in floats.items():
        data_vars[k] = (dims, a.reshape(shape), {"units": units_of_key(k), "long_name": _LONG_NAMES.get(k, k)})
    for k, a in bools.items():
        data_vars[k] = (dims, a.reshape(shape), {"units": "1", "long_name": _LONG_NAMES[k]})
    for k, a in texts.items():
        data_vars[k] = (dims, a.reshape(shape).astype(str), {"units": "1", "long_name": _LONG_NAMES.get(k, k)})
    flags = _warning_flags(records, (n, nl, nm), lc_index, m_index, kinds).reshape((*shape, len(kinds)))
    data_vars["warning_flag"] = ((*dims, "warning"), flags, {"units": "1", "long_name": _LONG_NAMES["warning_flag"]})
    data_vars["error"] = (grid.keys, error.reshape(grid.shape).astype(str), {"units": "1", "long_name": _LONG_NAMES["error"]})
    data_vars["eval_seconds"] = (grid.keys, seconds.reshape(grid.shape), {"units": "s", "long_name": _LONG_NAMES["eval_seconds"]})
    coords = _coordinates(grid, load_cases, models, kinds)
    attrs = _attributes(grid, records)
    return xr.Dataset(data_vars, coords=coords, attrs=attrs)


def _csv_value(value: Any) -> Any:
    if value is None:
        return ""
    if isinstance(value, float) and math.isnan(value):
        return ""
    return value


def study_rows(grid: StudyGrid, records: dict[int, PointRecord]) -> tuple[list[str], list[list[Any]]]:
    """Header and rows of ``study.csv``: one row per point, load case and model.

    Columns: the study's dotted keys, then ``load_case, model, u_c_m, u_s_m, u_d_m, F_N,
    M_b_Nm, sigma_b_Pa, converged, contact_preserved``, then the evaluator's diagnostics, the
    derived keys, ``warnings`` (the row's typed warnings' values joined by ``;``, empty when
    none) and ``error``. A failed point has empty result cells and its error text.
    """
    values = list(records.values())
    load_cases = _labels(values, "load_case", LOAD_CASES)
    models = _labels(values, "model", MODELS)
    extras = _extra_keys(values)
    derived = list(grid.spec.derived)
    cradle = _cradle_columns(values)
    header = [*_axis_columns(grid), *CORE_COLUMNS, *cradle, *extras, *derived, WARNINGS_COLUMN, "error"]
    derived_values = _derived_values(grid)
    rows: list[list[Any]] = []
    for index in range(grid.size):
        point = grid.point_values(index)
        record = records.get(index, PointRecord(index, (), "not evaluated"))
        by_label = {(r.get("load_case"), r.get("model")): r for r in record.rows}
        multi = np.unravel_index(index, grid.shape)
        dvals = [_csv_value(float(derived_values[k][multi])) for k in derived]
        for lc in load_cases:
            for m in models:
                row = by_label.get((lc, m), {})
                cells: list[Any] = [point[k] for k in grid.keys]
                cells += [lc, m]
                cells += [_csv_value(row.get(k)) for k in (*CORE_COLUMNS[2:], *cradle)]
                cells += [_csv_value(row.get(k)) for k in extras]
                cells += dvals
                cells.append(";".join(warning_values(row.get(WARNINGS_COLUMN))))
                cells.append(record.error)
                rows.append(cells)
    return header, rows


def _csv_text(value: Any) -> Any:
    """CSV cell text: booleans as true/false (as summary.csv), floats round-trip exact."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return repr(value)
    return value


def _atomic_path(path: Path) -> Path:
    return path.with_name(path.name + ".tmp")


def write_study_csv(path: Path, grid: StudyGrid, records: dict[int, PointRecord]) -> Path:
    """Write ``study.csv`` atomically; returns its path."""
    header, rows = study_rows(grid, records)
    tmp = _atomic_path(path)
    with open(tmp, "w", newline="", encoding="utf-8") as fh:
        writer = csv.writer(fh, lineterminator="\n")
        writer.writerow(header)
        for row in rows:
            writer.writerow([_csv_text(v) for v in row])
    os.replace(tmp, path)
    return path


def write_study_netcdf(path: Path, dataset: xr.Dataset) -> Path:
    """Write ``study.nc`` atomically; returns its path."""
    tmp = _atomic_path(path)
    dataset.to_netcdf(tmp)
    os.replace(tmp, path)
    return path
