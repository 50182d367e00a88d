"""Tables of the report: the case inputs, the run summary and diagnostics, the study ranking.

Every function is pure (dataset or mapping in, rows out); the HTML module renders the rows.
"""

from __future__ import annotations

import csv
import functools
import math
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np
import xarray as xr

from seafast.output.report.common import coord_labels

__all__ = ["flatten_case", "input_rows", "summary_table_rows", "diagnostics_rows", "coupling_rows", "ranking_rows", "display_unit"]


# =============================================================================== inputs
def flatten_case(data: Mapping[str, Any], prefix: str = "") -> list[tuple[str, Any]]:
    """Flatten a nested case mapping into ``(dotted key, value)`` pairs, in file order.

    Lists of mappings (e.g. ``cargo.sections``) become ``key[i].subkey`` entries.
    """
    out: list[tuple[str, Any]] = []
    for key, value in data.items():
        dotted = f"{prefix}.{key}" if prefix else str(key)
        if isinstance(value, Mapping):
            out.extend(flatten_case(value, dotted))
        elif isinstance(value, (list, tuple)) and value and all(isinstance(v, Mapping) for v in value):
            for i, item in enumerate(value):
                out.extend(flatten_case(item, f"{dotted}[{i}]"))
        else:
            out.append((dotted, value))
    return out


def display_unit(key: str) -> str:
    """The unit of a dotted case key for display (``-`` when dimensionless or unknown)."""
    try:
        from seafast.studies.spec import units_of_key

        unit = units_of_key(key.split("[")[0] if key.endswith("]") else key)
    except Exception:  # noqa: BLE001 - units are a courtesy
        unit = "1"
    return "-" if unit in ("1", "") else unit


def _description_of(key: str) -> str:
    """The case schema's description of a dotted key ('' when it has none)."""
    try:
        from pydantic import BaseModel

        from seafast.config.schema import Case
    except ImportError:  # pragma: no cover
        return ""
    model: Any = Case
    parts = [p.split("[")[0] for p in key.split(".")]
    info = None
    for part in parts:
        if not (isinstance(model, type) and issubclass(model, BaseModel)) or part not in model.model_fields:
            return ""
        info = model.model_fields[part]
        model = info.annotation
        args = getattr(model, "__args__", ())
        for a in args:  # Optional[X] / tuple[X, ...]
            if isinstance(a, type) and issubclass(a, BaseModel):
                model = a
                break
    return (info.description or "") if info is not None else ""


def _format_value(value: Any) -> str:
    if value is None:
        return "default (computed)"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, float):
        return f"{value:.6g}"
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_format_value(v) for v in value) + "]"
    return str(value)


def input_rows(case: Mapping[str, Any]) -> list[dict[str, str]]:
    """Rows of the inputs table: every key of the case with its value, unit and meaning.

    Parameters
    ----------
    case : mapping
        The case as a nested mapping (``json.loads(ds.attrs["case_json"])``).

    Returns
    -------
    list of dict
        Keys ``key`` (dotted), ``value`` (text; ``null`` shown as "default (computed)"),
        ``unit`` (SI, from the key's suffix) and ``description`` (from the case schema).
    """
    return [
        {"key": k, "value": _format_value(v), "unit": display_unit(k), "description": _description_of(k)} for k, v in flatten_case(case)
    ]


# =============================================================================== tables
_QUANTITIES: tuple[tuple[str, str, float, str], ...] = (
    ("u_c_m", "u_c, max cargo deflection", 1e3, "mm"),
    ("u_s_m", "u_s, max saddle compression", 1e3, "mm"),
    ("u_d_m", "u_d, max detachment (gap)", 1e3, "mm"),
    ("F_N", "F, max saddle force", 1e-6, "MN"),
    ("M_b_Nm", "M_b, max bending moment", 1e-6, "MN m"),
    ("sigma_b_Pa", "sigma_b, max bending stress", 1e-6, "MPa"),
)


def summary_table_rows(ds: xr.Dataset) -> tuple[list[str], list[list[str]]]:
    """Summary of a run in engineering units, linear next to nonlinear.

    Returns
    -------
    header : list of str
        ``quantity``, ``unit``, then one column per (load case, model).
    rows : list of list of str
        One row per quantity of docs/conventions.md#8-summary-quantities, then ``contact preserved`` and ``converged``.
    """
    cols = [(lc, m) for lc in coord_labels(ds["load_case"]) for m in coord_labels(ds["model"])]
    header = ["quantity", "unit"] + [f"{lc} {m}" for lc, m in cols]
    rows: list[list[str]] = []
    for name, label, scale, unit in _QUANTITIES:
        if name not in ds:
            continue
        row = [label, unit]
        for lc, m in cols:
            v = float(ds[name].sel(load_case=lc, model=m)) * scale
            row.append("-" if not math.isfinite(v) else f"{v:.3f}" if unit == "MN" else f"{v:.2f}")
        rows.append(row)
    for name, label in (("contact_preserved", "contact preserved (linear theory valid)"), ("converged", "solver converged")):
        if name in ds:
            rows.append([label, "-"] + ["yes" if bool(ds[name].sel(load_case=lc, model=m)) else "NO" for lc, m in cols])
    return header, rows


def _largest_finite_cell(sel: xr.Dataset, name: str, fmt: str, scale: float = 1.0) -> str:
    """The largest finite value of ``sel[name]`` times ``scale``, formatted; ``-`` if absent or none finite."""
    if name not in sel:
        return "-"
    vals = np.asarray(sel[name].values, dtype=float) * scale
    vals = vals[np.isfinite(vals)] if vals.ndim else (vals[None] if np.isfinite(vals) else np.array([]))
    return format(float(vals.max()), fmt) if vals.size else "-"


def diagnostics_rows(ds: xr.Dataset) -> tuple[list[str], list[list[str]]]:
    """Convergence diagnostics per (load case, model).

    Columns: load case, model, converged, residual norm [-], iterations, largest harmonic
    truncation indicator [-] (share of the contact-force signal above harmonic H), largest
    estimated peak-force error from the harmonics above H [-] (relative to the saddle's force
    scale; compare ``solver.truncation_tolerance``), largest tensile force of the regularised
    contact law [kN], solver message; after a two-way run also the coupling's own residual and
    tolerance [m] and its steps.
    """
    header = [
        "load case",
        "model",
        "converged",
        "residual norm",
        "iterations",
        "truncation indicator",
        "peak-force truncation error",
        "tensile-force error [kN]",
        "solver message",
    ]
    coupled = "coupling_residual_m" in ds
    if coupled:
        header[-1:-1] = ["coupling residual [m]", "coupling tolerance [m]", "coupling steps"]
    rows = []
    for lc in coord_labels(ds["load_case"]):
        for m in coord_labels(ds["model"]):
            sel = ds.sel(load_case=lc, model=m)
            num = functools.partial(_largest_finite_cell, sel)
            rows.append(
                [
                    lc,
                    m,
                    ("yes" if bool(sel["converged"]) else "NO") if "converged" in sel else "-",
                    num("residual_norm", ".2e"),
                    str(int(sel["iterations"])) if "iterations" in sel else "-",
                    num("harmonic_truncation_indicator", ".2e"),
                    num("truncation_error", ".2e"),
                    num("tensile_force_error_N", ".1f", 1e-3),
                    *(
                        [num("coupling_residual_m", ".2e"), num("coupling_tolerance_m", ".2e"), str(int(sel["coupling_iterations"]))]
                        if coupled
                        else []
                    ),
                    str(sel["solver_message"].values.item()) if "solver_message" in sel else "",
                ]
            )
    return header, rows


def coupling_rows(ds: xr.Dataset) -> tuple[list[str], list[list[str]]]:
    """The two-way coupling of each (load case, model) from the ``coupling_*`` variables.

    Columns: load case, model, outcome, steps, coupling residual and tolerance [m], period-mean
    deck change under each saddle [mm] (two-way minus one-way, up +). Empty without them.
    """
    header = ["load case", "model", "outcome", "steps", "residual [m]", "tolerance [m]", "mean deck change under the saddles [mm]"]
    rows: list[list[str]] = []
    if "coupling_converged" not in ds:
        return header, rows
    for lc in coord_labels(ds["load_case"]):
        for m in coord_labels(ds["model"]):
            sel = ds.sel(load_case=lc, model=m)
            change = np.asarray(sel["coupling_mean_deck_change_m"].values, dtype=float) * 1e3
            rows.append(
                [
                    lc,
                    m,
                    str(sel["coupling_outcome"].values.item()).replace("_", " "),
                    str(int(sel["coupling_iterations"])),
                    f"{float(sel['coupling_residual_m']):.2e}",
                    f"{float(sel['coupling_tolerance_m']):.2e}",
                    ", ".join(f"{c:+.2f}" for c in change[np.isfinite(change)]),
                ]
            )
    return header, rows


def ranking_rows(sds: xr.Dataset, ranking_csv: Path | None = None) -> tuple[list[str], list[dict[str, Any]]]:
    """The compliant arrangements, best first: from ``ranking.csv`` when given, else computed from the study."""
    if ranking_csv is not None and ranking_csv.is_file():
        with open(ranking_csv, newline="", encoding="utf-8") as fh:
            reader = csv.DictReader(line for line in fh if not line.startswith("#"))
            rows = list(reader)
            return list(reader.fieldnames or []), rows
    from seafast.studies.limits import rank_compliant

    rows = rank_compliant(sds)
    return (list(rows[0].keys()) if rows else []), rows
