"""Shared pieces of the report: file names, result types and dataset accessors.

Everything here is package-internal plumbing used by several report modules (tables, findings,
figures, HTML, print figures); the public names are re-exported by :mod:`seafast.output.report`.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import xarray as xr

__all__ = [
    "REPORT_FILENAME",
    "FIGURES_DIRNAME",
    "PDF_FILENAME",
    "PNG_DPI",
    "ReportError",
    "Finding",
    "ReportFigure",
    "ReportOutputs",
]

REPORT_FILENAME = "report.html"
FIGURES_DIRNAME = "report_figures"
PDF_FILENAME = "report_figures.pdf"
PNG_DPI = 200
"""Resolution of the print figures [dpi]."""


class ReportError(ValueError):
    """The directory cannot be reported (missing, or holds neither results.nc nor study.nc)."""


@dataclass(frozen=True)
class Finding:
    """A diagnostic statement shown as a coloured box.

    Attributes
    ----------
    level : str
        ``"WARNING"`` (a result must not be trusted), ``"NOTE"`` (worth knowing) or ``"OK"``.
    title : str
        One-line headline.
    text : str
        Explanation and what to do (plain text).
    """

    level: str
    title: str
    text: str = ""


@dataclass(frozen=True)
class ReportFigure:
    """An interactive figure of the report.

    Attributes
    ----------
    id : str
        HTML id of the figure's div (``fig-...``); stable, tests look for it.
    title : str
        Caption headline.
    figure : plotly.graph_objects.Figure
        The figure.
    caption : str
        What the figure shows (plain text).
    """

    id: str
    title: str
    figure: Any
    caption: str = ""


@dataclass(frozen=True)
class ReportOutputs:
    """Files written by :func:`write_report`."""

    html: Path
    pngs: tuple[Path, ...] = ()
    pdf: Path | None = None
    figure_ids: tuple[str, ...] = ()
    findings: tuple[Finding, ...] = field(default_factory=tuple)


# =============================================================================== dataset helpers
def _attr_float(ds: xr.Dataset, name: str, default: float = math.nan) -> float:
    try:
        return float(ds.attrs.get(name, default))
    except (TypeError, ValueError):
        return default


def _labels(da: xr.DataArray) -> list[str]:
    return [str(v) for v in da.values]


def _has(ds: xr.Dataset, *names: str) -> bool:
    return all(n in ds.variables for n in names)


def _saddle_label(ds: xr.Dataset, j: int) -> str:
    x = float(ds["saddle_x_m"].values[j]) if "saddle_x_m" in ds else math.nan
    lashed = "saddle_lashed" in ds and bool(ds["saddle_lashed"].values[j])
    return f"saddle {j} (x = {x:.1f} m{', lashed' if lashed else ''})"


def _case_mapping(text: Any) -> dict[str, Any]:
    if not text:
        return {}
    try:
        data = json.loads(str(text))
    except (TypeError, ValueError):
        return {}
    return data if isinstance(data, dict) else {}


# =============================================================================== study dataset helpers
def _study_keys(sds: xr.Dataset) -> list[str]:
    ref = "F_N" if "F_N" in sds else next(iter(sds.data_vars))
    return [d for d in sds[ref].dims if d not in ("load_case", "model")]


def _total_load_case(ds: xr.Dataset) -> str:
    """The load case holding the total response: ``dynamic``, else the last one present."""
    labels = _labels(ds["load_case"])
    return "dynamic" if "dynamic" in labels else labels[-1]


def _total(sds: xr.Dataset) -> xr.Dataset:
    if "load_case" not in sds.dims:
        return sds
    return sds.sel(load_case=_total_load_case(sds))


def _base(sds: xr.Dataset, key: str) -> float:
    try:
        return float(sds[key].attrs.get("base_value", math.nan))
    except (TypeError, ValueError):
        return math.nan


def _limits(sds: xr.Dataset) -> dict[str, float]:
    return {"F_N": _attr_float(sds, "max_saddle_force_N", 7e6), "sigma_b_Pa": _attr_float(sds, "max_bending_stress_Pa", 20e6)}
