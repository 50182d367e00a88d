"""Shared pieces of the report: file names, result types and dataset accessors.

Everything here is package-internal plumbing used by several report modules (tables, findings,
figures, HTML, print figures); the public names are re-exported by :mod:`seafast.output.report`.
"""

from __future__ import annotations

import html
import json
import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:  # annotations only: the report's subcommand imports this module for its parser
    import numpy as np
    import xarray as xr
    from numpy.typing import NDArray

__all__ = [
    "rao_curves",
    "REPORT_FILENAME",
    "FIGURES_DIRNAME",
    "PDF_FILENAME",
    "PNG_DPI",
    "ReportError",
    "Finding",
    "ReportFigure",
    "ReportOutputs",
    "attr_float",
    "coord_labels",
    "has_variables",
    "saddle_label",
    "case_mapping",
    "study_keys",
    "total_load_case",
    "total_response",
    "base_value",
    "design_limits",
    "plain_table_html",
    "findings_html",
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
def attr_float(ds: xr.Dataset, name: str, default: float = math.nan) -> float:
    """Dataset attribute ``name`` as a float, ``default`` when missing or not a number."""
    try:
        return float(ds.attrs.get(name, default))
    except (TypeError, ValueError):
        return default


def coord_labels(da: xr.DataArray) -> list[str]:
    """The values of a coordinate (e.g. ``load_case``, ``model``) as strings."""
    return [str(v) for v in da.values]


def has_variables(ds: xr.Dataset, *names: str) -> bool:
    """Whether every one of ``names`` is a variable or coordinate of ``ds``."""
    return all(n in ds.variables for n in names)


def saddle_label(ds: xr.Dataset, j: int) -> str:
    """``saddle j (x = ... m, lashed)``: saddle j named by its position along the cargo [m]."""
    x = float(ds["saddle_x_m"].values[j]) if "saddle_x_m" in ds else math.nan
    lashed = "saddle_lashed" in ds and bool(ds["saddle_lashed"].values[j])
    return f"saddle {j} (x = {x:.1f} m{', lashed' if lashed else ''})"


def case_mapping(text: Any) -> dict[str, Any]:
    """The case as a dict from its JSON text (the ``case_json`` attribute); empty when unreadable."""
    if not text:
        return {}
    try:
        data = json.loads(str(text))
    except (TypeError, ValueError):
        return {}
    return data if isinstance(data, dict) else {}


# =============================================================================== study dataset helpers
def study_keys(sds: xr.Dataset) -> list[str]:
    """The study's axes: the dimensions of the results other than ``load_case`` and ``model``."""
    ref = "F_N" if "F_N" in sds else next(iter(sds.data_vars))
    return [str(d) for d in sds[ref].dims if d not in ("load_case", "model")]


def total_load_case(ds: xr.Dataset) -> str:
    """The load case holding the total response: ``dynamic``, else the last one present."""
    labels = coord_labels(ds["load_case"])
    return "dynamic" if "dynamic" in labels else labels[-1]


def total_response(sds: xr.Dataset) -> xr.Dataset:
    """The study results at the load case of the total response (see :func:`total_load_case`)."""
    if "load_case" not in sds.dims:
        return sds
    return sds.sel(load_case=total_load_case(sds))


def base_value(sds: xr.Dataset, key: str) -> float:
    """The base case's value of the study axis ``key`` (its ``base_value`` attribute), NaN if unknown."""
    try:
        return float(sds[key].attrs.get("base_value", math.nan))
    except (TypeError, ValueError):
        return math.nan


def design_limits(sds: xr.Dataset) -> dict[str, float]:
    """The study's design limits: ``F_N`` [N] and ``sigma_b_Pa`` [Pa] (defaults 7 MN, 20 MPa)."""
    return {"F_N": attr_float(sds, "max_saddle_force_N", 7e6), "sigma_b_Pa": attr_float(sds, "max_bending_stress_Pa", 20e6)}


def plain_table_html(header: Sequence[str], rows: Sequence[Sequence[Any]]) -> str:
    """An HTML table of escaped text cells (the report's sea-state and operability tables)."""
    head = "".join(f"<th>{html.escape(str(h))}</th>" for h in header)
    body = "".join("<tr>" + "".join(f"<td>{html.escape(str(v))}</td>" for v in r) + "</tr>" for r in rows)
    return f"<table><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"


def findings_html(findings: Sequence[Finding]) -> str:
    """The findings as the report's coloured boxes (level, title, text; escaped)."""
    return "".join(
        f'<div class="finding {f.level}"><span class="lvl">{html.escape(f.level)}</span><b>{html.escape(f.title)}</b>'
        + (f"<div>{html.escape(f.text)}</div>" if f.text else "")
        + "</div>"
        for f in findings
    )


def rao_curves(ds: xr.Dataset) -> tuple[list[tuple[str, float, str]], dict[str, NDArray[np.complex128]], str]:
    """The RAOs to plot: head seas' heave, pitch (and surge), or, off head seas, the six-DOF heave, roll and pitch at the case's heading."""
    import numpy as np  # here: the report's parser imports this module

    if "heave_rao_real" in ds:
        dofs = [("heave", 1.0, "m/m"), ("pitch", 180 / np.pi, "deg/m")]
        if "surge_rao_real" in ds:
            dofs.insert(0, ("surge", 1.0, "m/m"))
        curves = {n: ds[f"{n}_rao_real"].values + 1j * ds[f"{n}_rao_imag"].values for n, _, _ in dofs}
        return dofs, curves, "head seas"
    heading = float(ds.attrs.get("wave_heading_deg", 180.0))
    j = int(np.argmin(np.abs((ds["heading_deg"].values - heading + 180.0) % 360.0 - 180.0)))
    dofs = [("heave", 1.0, "m/m"), ("roll", 180 / np.pi, "deg/m"), ("pitch", 180 / np.pi, "deg/m")]
    curves = {n: ds[f"{n}_rao6_real"].values[:, j] + 1j * ds[f"{n}_rao6_imag"].values[:, j] for n, _, _ in dofs}
    return dofs, curves, f"heading {float(ds['heading_deg'].values[j]):g} deg"
