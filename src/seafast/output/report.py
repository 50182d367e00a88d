"""``seafast report DIR``: one self-contained HTML report of a run or study directory.

The report holds interactive plotly figures (plotly.js embedded inline once, so the file opens
without a network), tables in engineering units (mm, MN, MN m, MPa) and clearly visible WARNING
boxes where a result should not be trusted. The same figures are written at print quality as
PNG (matplotlib, at least :data:`PNG_DPI` dpi, units on every axis) into ``report_figures/``
next to the HTML, and collected into ``report_figures.pdf``.

Inputs
------
* A run directory (``seafast run -o DIR``): ``results.nc`` (required), ``summary.csv``,
  ``case.yaml``.
* A study directory (``seafast study NAME -o DIR``): ``study.nc`` (required), ``ranking.csv``
  (read when present, else the ranking is computed from ``study.nc``), ``compliance.csv``.

Design: every figure and table is a pure function ``Dataset -> plotly Figure / rows``; reading
files and writing the report happen only in :func:`write_report` and the command handler.
The print (PNG/PDF) figures reuse :mod:`seafast.output.plots` (run) and
:mod:`seafast.studies.figures` (study).
"""

from __future__ import annotations

import argparse
import csv
import html
import json
import math
import sys
from contextlib import contextmanager
from dataclasses import dataclass, field
from datetime import datetime, timezone
from pathlib import Path
from typing import Any, Iterator, Mapping, Sequence

import numpy as np
import xarray as xr

__all__ = [
    "REPORT_FILENAME",
    "FIGURES_DIRNAME",
    "PDF_FILENAME",
    "PNG_DPI",
    "TRUNCATION_LIMIT",
    "ReportError",
    "Finding",
    "ReportFigure",
    "ReportOutputs",
    "flatten_case",
    "input_rows",
    "summary_table_rows",
    "diagnostics_rows",
    "run_findings",
    "study_findings",
    "hull_girder_figure",
    "rao_figure",
    "deck_motion_figure",
    "saddle_time_history_figure",
    "deflection_moment_figure",
    "contact_timeline_figure",
    "run_figures",
    "study_surface_figure",
    "study_profile_figure",
    "compliance_map_figure",
    "study_figures",
    "ranking_rows",
    "render_html",
    "build_report_html",
    "plot_contact_timeline",
    "write_print_figures",
    "write_report",
    "add_report_subcommand",
]

REPORT_FILENAME = "report.html"
FIGURES_DIRNAME = "report_figures"
PDF_FILENAME = "report_figures.pdf"
PNG_DPI = 200
"""Resolution of the print figures [dpi]."""
TRUNCATION_LIMIT = 1e-2
"""Harmonic truncation indicator above which a nonlinear result is flagged (share of the
contact-force signal above harmonic H) [-]."""
TENSILE_NOTE_FRACTION = 1e-2
"""A regularised contact law's tensile force above this share of the largest saddle force is noted [-]."""

_COLORS = {"linear": "#1f77b4", "nonlinear": "#d62728"}
_FILL = {"linear": "rgba(31,119,180,0.18)", "nonlinear": "rgba(214,39,40,0.18)"}
_SADDLE_COLORS = ("#2ca02c", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf", "#ff7f0e")
_PLOTLY_CONFIG = {"displaylogo": False, "responsive": True, "toImageButtonOptions": {"format": "png", "scale": 2}}


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


# =============================================================================== helpers
def _go() -> Any:
    import plotly.graph_objects as go

    return go


def _subplots(**kwargs: Any) -> Any:
    from plotly.subplots import make_subplots

    return make_subplots(**kwargs)


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


def _style(fig: Any, title: str, height: int) -> Any:
    fig.update_layout(
        title=dict(text=title, x=0.01, xanchor="left"),
        height=height,
        template="plotly_white",
        margin=dict(l=70, r=30, t=70, b=60),
        legend=dict(orientation="h", yanchor="bottom", y=1.02, xanchor="right", x=1.0, font=dict(size=11)),
        hovermode="closest",
    )
    return fig


def _case_mapping(text: Any) -> dict[str, Any]:
    if not text:
        return {}
    try:
        data = json.loads(str(text))
    except (TypeError, ValueError):
        return {}
    return data if isinstance(data, dict) else {}


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


def _unit_of(key: str) -> str:
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
        {"key": k, "value": _format_value(v), "unit": _unit_of(k), "description": _description_of(k)}
        for k, v in flatten_case(case)
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
        One row per quantity of MODEL.md section 6, then ``contact preserved`` and ``converged``.
    """
    cols = [(lc, m) for lc in _labels(ds["load_case"]) for m in _labels(ds["model"])]
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


def diagnostics_rows(ds: xr.Dataset) -> tuple[list[str], list[list[str]]]:
    """Convergence diagnostics per (load case, model).

    Columns: load case, model, converged, residual norm [-], iterations, largest harmonic
    truncation indicator [-] (share of the contact-force signal above harmonic H), largest
    tensile force of the regularised contact law [kN], solver message.
    """
    header = ["load case", "model", "converged", "residual norm", "iterations", "truncation indicator", "tensile-force error [kN]", "solver message"]
    rows = []
    for lc in _labels(ds["load_case"]):
        for m in _labels(ds["model"]):
            sel = ds.sel(load_case=lc, model=m)

            def num(name: str, fmt: str, scale: float = 1.0, reduce: bool = False) -> str:
                if name not in sel:
                    return "-"
                vals = np.asarray(sel[name].values, dtype=float) * scale
                vals = vals[np.isfinite(vals)] if vals.ndim else (vals[None] if np.isfinite(vals) else np.array([]))
                return format(float(vals.max()), fmt) if vals.size else "-"

            rows.append(
                [
                    lc,
                    m,
                    ("yes" if bool(sel["converged"]) else "NO") if "converged" in sel else "-",
                    num("residual_norm", ".2e"),
                    str(int(sel["iterations"])) if "iterations" in sel else "-",
                    num("harmonic_truncation_indicator", ".2e"),
                    num("tensile_force_error_N", ".1f", 1e-3),
                    str(sel["solver_message"].values.item()) if "solver_message" in sel else "",
                ]
            )
    return header, rows


# =============================================================================== findings
def run_findings(ds: xr.Dataset) -> list[Finding]:
    """Diagnostics of a run that decide whether its numbers can be trusted.

    WARNING when: a solve did not converge; the harmonic truncation indicator exceeds
    :data:`TRUNCATION_LIMIT`; a solver message carries a warning (e.g. the quasi-static
    assumption, or excitation harmonics above H dropped); contact is lost while the linear
    (bilateral) model is used — its forces then include tension a saddle cannot carry.
    NOTE when the regularised contact law's tensile force exceeds
    :data:`TENSILE_NOTE_FRACTION` of the largest saddle force.
    """
    out: list[Finding] = []
    lcs, models = _labels(ds["load_case"]), _labels(ds["model"])
    for lc in lcs:
        for m in models:
            sel = ds.sel(load_case=lc, model=m)
            if "converged" in sel and not bool(sel["converged"]):
                res = float(sel["residual_norm"]) if "residual_norm" in sel else math.nan
                out.append(
                    Finding(
                        "WARNING",
                        f"{lc} {m}: the solver did NOT converge",
                        f"residual norm {res:.3e}. Its numbers (summary, figures) must not be trusted; "
                        "try more harmonics/time samples, the 'newton' solver or another contact law.",
                    )
                )
            if "harmonic_truncation_indicator" in sel:
                ind = np.asarray(sel["harmonic_truncation_indicator"].values, dtype=float)
                if np.any(ind > TRUNCATION_LIMIT):
                    j = int(np.nanargmax(ind))
                    out.append(
                        Finding(
                            "WARNING",
                            f"{lc} {m}: harmonic truncation indicator {np.nanmax(ind):.2e} > {TRUNCATION_LIMIT:g}",
                            f"at {_saddle_label(ds, j)}: a noticeable share of the contact force lies above harmonic "
                            f"H = {ds.attrs.get('harmonics', '?')}; increase solver.harmonics (and solver.time_samples) "
                            "until the maxima stop changing.",
                        )
                    )
            msg = str(sel["solver_message"].values.item()) if "solver_message" in sel else ""
            low = msg.lower()
            if "warning" in low or "quasi-static" in low or "quasi static" in low:
                title = "quasi-static assumption questionable" if "quasi" in low else "solver warning"
                out.append(Finding("WARNING", f"{lc} {m}: {title}", msg))
    if "contact_preserved" in ds and "linear" in models:
        lost = [lc for lc in lcs if not bool(ds["contact_preserved"].sel(load_case=lc, model="linear"))]
        if lost:
            out.append(
                Finding(
                    "WARNING",
                    f"contact lost while the linear model is used ({', '.join(lost)})",
                    "The linear (bilateral-saddle) model needs tension at a saddle over part of the period, which a real "
                    "saddle cannot carry: its forces, moments and stresses are not valid here. Use the nonlinear "
                    "(harmonic-balance) results.",
                )
            )
    if "tensile_force_error_N" in ds and "F_N" in ds:
        for lc in lcs:
            for m in models:
                t = float(ds["tensile_force_error_N"].sel(load_case=lc, model=m))
                f = float(ds["F_N"].sel(load_case=lc, model=m))
                if math.isfinite(t) and f > 0 and t > TENSILE_NOTE_FRACTION * f:
                    out.append(
                        Finding(
                            "NOTE",
                            f"{lc} {m}: the regularised contact law carries up to {t / 1e3:.0f} kN of tension",
                            f"{100 * t / f:.1f} % of the largest saddle force: the price of the smooth (tanh) contact law; "
                            "solver.contact_law=exact or softplus, or a larger solver.regularisation_per_m, removes it.",
                        )
                    )
    if not any(f.level == "WARNING" for f in out):
        out.insert(0, Finding("OK", "every solve converged; no diagnostic flags a result", ""))
    return out


def study_findings(sds: xr.Dataset) -> list[Finding]:
    """Diagnostics of a study: failed points, non-converged nonlinear points, linear validity."""
    out: list[Finding] = []
    keys = _study_keys(sds)
    n = int(np.prod([sds.sizes[k] for k in keys])) if keys else 1
    if "error" in sds:
        err = np.asarray(sds["error"].values).astype(str)
        bad = int(np.count_nonzero(err != ""))
        if bad:
            first = next(e for e in err.ravel() if e)
            out.append(
                Finding(
                    "WARNING",
                    f"{bad} of {n} study points failed to evaluate",
                    f"their cells are blank / marked x. First error: {first.splitlines()[0][:300]}",
                )
            )
    total = _total(sds)
    if "converged" in total and "nonlinear" in _labels(total["model"]):
        conv = np.asarray(total["converged"].sel(model="nonlinear").values).astype(bool)
        evaluated = (np.asarray(sds["error"].values).astype(str) == "") if "error" in sds else np.ones_like(conv)
        bad = int(np.count_nonzero(~conv & evaluated))
        if bad:
            out.append(
                Finding(
                    "WARNING",
                    f"the nonlinear solver did not converge at {bad} of {n} points",
                    "those points never count as compliant; inspect them with 'seafast run --set ...'.",
                )
            )
    if "contact_preserved" in total and "linear" in _labels(total["model"]):
        lost = int(np.count_nonzero(~np.asarray(total["contact_preserved"].sel(model="linear").values).astype(bool)))
        if lost:
            out.append(
                Finding(
                    "NOTE",
                    f"contact is lost at {lost} of {n} points: the linear model is not valid there",
                    "the linear surfaces are shown for comparison only; decisions use the nonlinear model.",
                )
            )
    if not any(f.level == "WARNING" for f in out):
        out.insert(0, Finding("OK", "every study point evaluated and converged", ""))
    return out


# =============================================================================== run figures
def hull_girder_figure(ds: xr.Dataset) -> Any | None:
    """Hull deflection [mm] (still water, hog, sag, wave envelope) and hull bending moment [MN m].

    Returns ``None`` when the dataset has no hull-girder variables (e.g. a deck-deflection table).
    """
    if "hull_x_m" not in ds.coords or "hull_still_water_deflection_m" not in ds:
        return None
    go = _go()
    x = ds["hull_x_m"].values
    sw = ds["hull_still_water_deflection_m"].values
    has_m = "hull_still_water_bending_moment_Nm" in ds
    fig = _subplots(rows=2 if has_m else 1, cols=1, shared_xaxes=True, vertical_spacing=0.08)
    fig.add_trace(go.Scatter(x=x, y=sw * 1e3, name="still water", line=dict(color="black", width=2), legendgroup="sw"), row=1, col=1)
    if "hull_wave_deflection_m" in ds:
        w = ds["hull_wave_deflection_m"].values
        fig.add_trace(go.Scatter(x=x, y=(sw + w.min(axis=0)) * 1e3, line=dict(width=0), showlegend=False, hoverinfo="skip"), row=1, col=1)
        fig.add_trace(
            go.Scatter(x=x, y=(sw + w.max(axis=0)) * 1e3, line=dict(width=0), fill="tonexty", fillcolor="rgba(128,128,128,0.2)",
                       name="still water + wave (envelope)", hoverinfo="skip"),
            row=1, col=1,
        )
        if has_m and "hull_wave_bending_moment_Nm" in ds:
            m = ds["hull_wave_bending_moment_Nm"].values
            mid = int(np.argmin(np.abs(x - 0.5 * (x[0] + x[-1]))))
            i_hog, i_sag = int(np.argmin(m[:, mid])), int(np.argmax(m[:, mid]))
            swm = ds["hull_still_water_bending_moment_Nm"].values
            for i, name, color in ((i_hog, "hog (crest amidships)", "#d62728"), (i_sag, "sag (trough amidships)", "#1f77b4")):
                fig.add_trace(go.Scatter(x=x, y=(sw + w[i]) * 1e3, name=name, legendgroup=name, line=dict(color=color)), row=1, col=1)
                fig.add_trace(
                    go.Scatter(x=x, y=(swm + m[i]) / 1e6, name=name, legendgroup=name, showlegend=False, line=dict(color=color)), row=2, col=1
                )
    if has_m:
        fig.add_trace(
            go.Scatter(x=x, y=ds["hull_still_water_bending_moment_Nm"].values / 1e6, name="still water", legendgroup="sw",
                       showlegend=False, line=dict(color="black", width=2)),
            row=2, col=1,
        )
        fig.update_yaxes(title_text="hull bending moment [MN m] (sagging +)", row=2, col=1)
    aft = _attr_float(ds, "cargo_aft_end_x_m")
    if math.isfinite(aft) and "x_cargo_m" in ds.coords:
        fore = aft + float(ds["x_cargo_m"].max())
        fig.add_vrect(x0=aft, x1=fore, fillcolor="orange", opacity=0.12, line_width=0, annotation_text="cargo", annotation_position="top left")
        if "saddle_x_m" in ds:
            xs = aft + ds["saddle_x_m"].values
            fig.add_trace(
                go.Scatter(x=xs, y=np.interp(xs, x, sw) * 1e3, mode="markers", name="saddles",
                           marker=dict(symbol="triangle-down", size=11, color="#2ca02c")),
                row=1, col=1,
            )
    fig.update_yaxes(title_text="hull deflection [mm] (up +)", row=1, col=1)
    fig.update_xaxes(title_text="x along the ship from the aft perpendicular [m]", row=2 if has_m else 1, col=1)
    return _style(fig, "Hull girder: deflection (chord through the ship's ends) and bending moment", 620 if has_m else 380)


def rao_figure(ds: xr.Dataset) -> Any | None:
    """Heave [m/m] and pitch [deg/m] RAOs, amplitude and phase [deg], wave frequency marked.

    Returns ``None`` without RAOs (``vessel.motions: none``).
    """
    if "rao_omega_rad_s" not in ds.coords or not _has(ds, "heave_rao_real", "heave_rao_imag", "pitch_rao_real", "pitch_rao_imag"):
        return None
    go = _go()
    w = ds["rao_omega_rad_s"].values
    fig = _subplots(rows=2, cols=2, shared_xaxes=True, vertical_spacing=0.1, horizontal_spacing=0.1,
                    subplot_titles=("heave amplitude", "pitch amplitude (bow up +)", "heave phase", "pitch phase"))
    for col, (name, scale, unit) in enumerate((("heave", 1.0, "m/m"), ("pitch", 180.0 / np.pi, "deg/m")), start=1):
        z = ds[f"{name}_rao_real"].values + 1j * ds[f"{name}_rao_imag"].values
        fig.add_trace(go.Scatter(x=w, y=np.abs(z) * scale, mode="lines+markers", name=f"{name} amplitude", line=dict(color="black"),
                                 hovertemplate=f"omega %{{x:.3f}} rad/s<br>%{{y:.4g}} {unit}<extra></extra>", showlegend=False), row=1, col=col)
        fig.add_trace(go.Scatter(x=w, y=np.degrees(np.angle(z)), mode="lines+markers", name=f"{name} phase", line=dict(color="gray"),
                                 hovertemplate="omega %{x:.3f} rad/s<br>%{y:.1f} deg<extra></extra>", showlegend=False), row=2, col=col)
        fig.update_yaxes(title_text=f"{name} RAO [{unit}]", row=1, col=col)
        fig.update_yaxes(title_text=f"{name} phase [deg]", row=2, col=col)
        fig.update_xaxes(title_text="wave frequency [rad/s]", row=2, col=col)
    omega = _attr_float(ds, "wave_frequency_rad_s")
    if math.isfinite(omega):
        for r in (1, 2):
            for c in (1, 2):
                fig.add_vline(x=omega, line=dict(color="#d62728", dash="dot"), row=r, col=c)
        fig.add_annotation(x=omega, y=1.0, xref="x", yref="paper", text=f"wave: {omega:.3f} rad/s", showarrow=False,
                           font=dict(color="#d62728"), yanchor="bottom")
    return _style(fig, "Rigid-body motions: heave and pitch RAOs (head seas)", 560)


def deck_motion_figure(ds: xr.Dataset) -> Any | None:
    """Deck deflection under each saddle over one wave period [mm] (the cargo's excitation)."""
    if "deck_deflection_m" not in ds:
        return None
    go = _go()
    fig = go.Figure()
    s = ds["period_fraction"].values
    deck = ds["deck_deflection_m"]
    lc = "dynamic" if "dynamic" in _labels(ds["load_case"]) else _labels(ds["load_case"])[-1]
    for j in range(ds.sizes["saddle"]):
        color = _SADDLE_COLORS[j % len(_SADDLE_COLORS)]
        fig.add_trace(go.Scatter(x=s, y=deck.sel(load_case=lc).isel(saddle=j).values * 1e3, name=_saddle_label(ds, j),
                                 line=dict(color=color), hovertemplate="t/T %{x:.3f}<br>%{y:.2f} mm<extra></extra>"))
        if "static" in _labels(ds["load_case"]):
            fig.add_trace(go.Scatter(x=s, y=deck.sel(load_case="static").isel(saddle=j).values * 1e3, name=f"still water, saddle {j}",
                                     line=dict(color=color, dash="dot"), showlegend=j == 0, legendgroup="sw", hoverinfo="skip"))
    fig.update_xaxes(title_text="period fraction t/T [-]")
    fig.update_yaxes(title_text="deck deflection under the saddle [mm] (up +)")
    return _style(fig, "Excitation: deck deflection under the saddles over one wave period", 440)


def saddle_time_history_figure(ds: xr.Dataset) -> Any:
    """Force [MN] and compression [mm] (negative = gap) of every saddle over one period, linear vs nonlinear."""
    go = _go()
    n = ds.sizes["saddle"]
    fig = _subplots(rows=2, cols=n, shared_xaxes=True, shared_yaxes="rows", vertical_spacing=0.1, horizontal_spacing=0.03,
                    subplot_titles=[_saddle_label(ds, j) for j in range(n)])
    s = ds["period_fraction"].values
    lc = "dynamic" if "dynamic" in _labels(ds["load_case"]) else _labels(ds["load_case"])[-1]
    for j in range(n):
        for m in _labels(ds["model"]):
            sel = ds.sel(load_case=lc, model=m).isel(saddle=j)
            c = _COLORS.get(m, "black")
            fig.add_trace(go.Scatter(x=s, y=sel["saddle_force_N"].values / 1e6, name=m, legendgroup=m, showlegend=j == 0, line=dict(color=c),
                                     hovertemplate=f"{m}<br>t/T %{{x:.3f}}<br>F %{{y:.3f}} MN<extra></extra>"), row=1, col=j + 1)
            fig.add_trace(go.Scatter(x=s, y=sel["saddle_compression_m"].values * 1e3, name=m, legendgroup=m, showlegend=False, line=dict(color=c),
                                     hovertemplate=f"{m}<br>t/T %{{x:.3f}}<br>compression %{{y:.2f}} mm<extra></extra>"), row=2, col=j + 1)
        fig.add_hline(y=0.0, line=dict(color="black", width=1), row=2, col=j + 1)
        fig.add_hline(y=0.0, line=dict(color="black", width=1), row=1, col=j + 1)
        fig.update_xaxes(title_text="t/T [-]", row=2, col=j + 1)
    fig.update_yaxes(title_text="saddle force [MN]", row=1, col=1)
    fig.update_yaxes(title_text="compression [mm] (negative = gap)", row=2, col=1)
    return _style(fig, f"Saddle force and compression/gap over one wave period ({lc}, total response)", 600)


def _envelope(fig: Any, x: np.ndarray, lo: np.ndarray, hi: np.ndarray, model: str, row: int, show: bool, unit: str) -> None:
    go = _go()
    fig.add_trace(go.Scatter(x=x, y=lo, line=dict(width=0.5, color=_COLORS.get(model, "gray")), legendgroup=f"{model}-env",
                             showlegend=False, hovertemplate=f"{model} dynamic min<br>x %{{x:.1f}} m<br>%{{y:.2f}} {unit}<extra></extra>"), row=row, col=1)
    fig.add_trace(go.Scatter(x=x, y=hi, line=dict(width=0.5, color=_COLORS.get(model, "gray")), fill="tonexty", fillcolor=_FILL.get(model, "rgba(0,0,0,0.1)"),
                             name=f"{model}, dynamic envelope", legendgroup=f"{model}-env", showlegend=show,
                             hovertemplate=f"{model} dynamic max<br>x %{{x:.1f}} m<br>%{{y:.2f}} {unit}<extra></extra>"), row=row, col=1)


def deflection_moment_figure(ds: xr.Dataset) -> Any:
    """Cargo deflection [mm] and bending moment [MN m] along the cargo: static lines and dynamic envelopes."""
    go = _go()
    fig = _subplots(rows=2, cols=1, shared_xaxes=True, vertical_spacing=0.08)
    lcs = _labels(ds["load_case"])
    xc, xm = ds["x_cargo_m"].values, ds["x_moment_m"].values
    for m in _labels(ds["model"]):
        c = _COLORS.get(m, "black")
        if "dynamic" in lcs:
            d = ds["cargo_deflection_m"].sel(load_case="dynamic", model=m).values * 1e3
            _envelope(fig, xc, d.min(axis=0), d.max(axis=0), m, 1, True, "mm")
            mo = ds["bending_moment_Nm"].sel(load_case="dynamic", model=m).values / 1e6
            _envelope(fig, xm, mo.min(axis=0), mo.max(axis=0), m, 2, False, "MN m")
        if "static" in lcs:
            st = ds["cargo_deflection_m"].sel(load_case="static", model=m).isel(period_fraction=0).values * 1e3
            fig.add_trace(go.Scatter(x=xc, y=st, name=f"{m}, static", legendgroup=f"{m}-st", line=dict(color=c, width=2.5),
                                     hovertemplate=f"{m} static<br>x %{{x:.1f}} m<br>%{{y:.2f}} mm<extra></extra>"), row=1, col=1)
            sm = ds["bending_moment_Nm"].sel(load_case="static", model=m).isel(period_fraction=0).values / 1e6
            fig.add_trace(go.Scatter(x=xm, y=sm, name=f"{m}, static", legendgroup=f"{m}-st", showlegend=False, line=dict(color=c, width=2.5),
                                     hovertemplate=f"{m} static<br>x %{{x:.1f}} m<br>%{{y:.2f}} MN m<extra></extra>"), row=2, col=1)
    if "saddle_x_m" in ds:
        for j, x in enumerate(ds["saddle_x_m"].values):
            fig.add_vline(x=float(x), line=dict(color="#2ca02c", dash="dot", width=1))
        fig.add_trace(go.Scatter(x=ds["saddle_x_m"].values, y=np.zeros(ds.sizes["saddle"]), mode="markers", name="saddles",
                                 marker=dict(symbol="triangle-up", size=11, color="#2ca02c"),
                                 text=[_saddle_label(ds, j) for j in range(ds.sizes["saddle"])], hovertemplate="%{text}<extra></extra>"), row=1, col=1)
    fig.update_yaxes(title_text="cargo deflection [mm] (up +)", row=1, col=1)
    fig.update_yaxes(title_text="bending moment [MN m] (sagging +)", row=2, col=1)
    fig.update_xaxes(title_text="x along the cargo from its aft end [m]", row=2, col=1)
    return _style(fig, "Cargo deflection (relative to the sea-fastening baseline) and bending moment: static and dynamic envelope", 700)


def contact_timeline_figure(ds: xr.Dataset) -> Any:
    """Contact state (saddle x period) of the dynamic response, one heatmap per model.

    For the linear (bilateral) model "detached" marks where the saddle would need tension.
    """
    go = _go()
    models = _labels(ds["model"])
    lc = "dynamic" if "dynamic" in _labels(ds["load_case"]) else _labels(ds["load_case"])[-1]
    fig = _subplots(rows=len(models), cols=1, shared_xaxes=True, vertical_spacing=0.12,
                    subplot_titles=[f"{m} model" + (" (detached = would need tension)" if m == "linear" else "") for m in models])
    s = ds["period_fraction"].values
    ylabels = [_saddle_label(ds, j) for j in range(ds.sizes["saddle"])]
    for i, m in enumerate(models, start=1):
        sel = ds.sel(load_case=lc, model=m)
        z = (sel["saddle_compression_m"].values > 0).astype(int).T if "saddle_compression_m" in sel else sel["contact_state"].values.T
        comp = sel["saddle_compression_m"].values.T * 1e3
        fig.add_trace(
            go.Heatmap(x=s, y=ylabels, z=z, zmin=0, zmax=1, colorscale=[[0, "#fdae61"], [0.5, "#fdae61"], [0.5, "#1a9850"], [1, "#1a9850"]],
                       showscale=i == 1, customdata=comp,
                       colorbar=dict(tickvals=[0.25, 0.75], ticktext=["detached", "in contact"], len=0.5, y=0.75, thickness=14),
                       hovertemplate="%{y}<br>t/T %{x:.3f}<br>compression %{customdata:.2f} mm<extra></extra>", xgap=0, ygap=2),
            row=i, col=1,
        )
        fig.update_yaxes(title_text="saddle", autorange="reversed", row=i, col=1)
    fig.update_xaxes(title_text="period fraction t/T [-]", row=len(models), col=1)
    return _style(fig, f"Contact state over one wave period ({lc})", 200 + 70 * ds.sizes["saddle"] * len(models))


def run_figures(ds: xr.Dataset) -> list[ReportFigure]:
    """Every interactive figure of a run dataset, in report order (vessel first)."""
    out: list[ReportFigure] = []
    for fid, title, builder, caption in (
        ("fig-hull-girder", "Hull girder", hull_girder_figure,
         "Still-water deflection and bending moment of the hull, with the wave's hog and sag extremes; the cargo span is shaded."),
        ("fig-raos", "Heave and pitch RAOs", rao_figure, "Amplitude and phase of the rigid-body RAOs; the case's wave frequency is the dotted line."),
        ("fig-deck-motion", "Deck deflection under the saddles", deck_motion_figure,
         "The prescribed deck displacement at each saddle over one period (solid) and in still water (dotted)."),
        ("fig-saddle-histories", "Saddle force and gap over the period", saddle_time_history_figure,
         "Total (static + wave) response. Negative compression is a gap: the nonlinear saddle lifts off and carries no force; "
         "the linear saddle would pull (negative force)."),
        ("fig-deflection-moment", "Deflection and bending-moment lines", deflection_moment_figure,
         "Thick lines: still water; shaded bands: range over one wave period of the total response."),
        ("fig-contact-timeline", "Contact-state timeline", contact_timeline_figure, "Green: saddle in contact; orange: detached."),
    ):
        try:
            fig = builder(ds)
        except KeyError:  # a dataset without the variables the figure needs
            fig = None
        if fig is not None:
            out.append(ReportFigure(fid, title, fig, caption))
    return out


# =============================================================================== study figures
def _study_keys(sds: xr.Dataset) -> list[str]:
    ref = "F_N" if "F_N" in sds else next(iter(sds.data_vars))
    return [d for d in sds[ref].dims if d not in ("load_case", "model")]


def _total(sds: xr.Dataset) -> xr.Dataset:
    if "load_case" not in sds.dims:
        return sds
    labels = _labels(sds["load_case"])
    return sds.sel(load_case="dynamic" if "dynamic" in labels else labels[-1])


def _is_log(sds: xr.Dataset, key: str) -> bool:
    return str(sds[key].attrs.get("scale", "")) == "log"


def _base(sds: xr.Dataset, key: str) -> float:
    try:
        return float(sds[key].attrs.get("base_value", math.nan))
    except (TypeError, ValueError):
        return math.nan


def _key_label(sds: xr.Dataset, key: str) -> str:
    unit = str(sds[key].attrs.get("units", "1"))
    return f"{key} [{'-' if unit in ('1', '') else unit}]"


def _edges(values: np.ndarray, log: bool) -> np.ndarray:
    v = np.asarray(values, dtype=float)
    if v.size == 1:
        return np.array([v[0] / 1.5, v[0] * 1.5]) if log else np.array([v[0] - 0.5, v[0] + 0.5])
    t = np.log(v) if log else v
    mid = 0.5 * (t[1:] + t[:-1])
    e = np.concatenate([[t[0] - (mid[0] - t[0])], mid, [t[-1] + (t[-1] - mid[-1])]])
    return np.exp(e) if log else e


def _study_view(sds: xr.Dataset, keep: int) -> tuple[xr.Dataset, list[str], dict[str, Any]]:
    """The study reduced to its first ``keep`` varying axes (others held at the base value).

    Returns the reduced dataset, its varying axis keys (outer first) and the held values.
    """
    keys = _study_keys(sds)
    varying = [k for k in keys if sds.sizes[k] > 1]
    held: dict[str, Any] = {}
    view = sds
    for k in keys:
        if k in varying[:keep]:
            continue
        coords = np.asarray(view[k].values)
        base = _base(view, k)
        idx = int(np.argmin(np.abs(coords.astype(float) - base))) if math.isfinite(base) and coords.min() <= base <= coords.max() else len(coords) // 2
        held[k] = coords[idx].item()
        view = view.isel({k: idx})
    return view, varying[:keep], held


def _axis_ticks(sds: xr.Dataset, key: str) -> dict[str, Any]:
    """Axis options for a study key: log type, and ticks at the values of a short integer axis."""
    values = np.asarray(sds[key].values)
    if _is_log(sds, key):
        return {"type": "log"}
    if values.dtype.kind in "iu" and values.size <= 15:
        return {"type": "linear", "tickmode": "array", "tickvals": values.tolist()}
    return {"type": "linear"}


def _bottom_legend(fig: Any, height: int) -> Any:
    fig.update_layout(legend=dict(orientation="h", yanchor="top", y=-0.2, xanchor="left", x=0.0), margin=dict(b=110), height=height)
    return fig


def _held_text(held: Mapping[str, Any]) -> str:
    return "" if not held else " (held: " + ", ".join(f"{k} = {v:g}" for k, v in held.items()) + ")"


_STUDY_QUANTITIES: tuple[tuple[str, str, float, str], ...] = (
    ("F_N", "max saddle force F", 1e-6, "MN"),
    ("M_b_Nm", "max bending moment M_b", 1e-6, "MN m"),
    ("sigma_b_Pa", "max bending stress sigma_b", 1e-6, "MPa"),
)


def _limits(sds: xr.Dataset) -> dict[str, float]:
    return {"F_N": _attr_float(sds, "max_saddle_force_N", 7e6), "sigma_b_Pa": _attr_float(sds, "max_bending_stress_Pa", 20e6)}


def study_surface_figure(sds: xr.Dataset, model: str = "nonlinear") -> Any | None:
    """Max force [MN], moment [MN m] and stress [MPa] of the total response over the two study axes.

    Heatmaps over the first two varying axes (others held at the base case); circles mark the
    points where contact is preserved at every saddle (nonlinear model: linear theory valid),
    red contour lines the design limits, a star the base case. ``None`` for studies with fewer
    than two varying axes or without ``model``.
    """
    view, axes, held = _study_view(sds, 2)
    if len(axes) < 2 or model not in _labels(sds["model"]):
        return None
    go = _go()
    ykey, xkey = axes[0], axes[1]
    total = _total(view).transpose(ykey, xkey, ...)
    x, y = view[xkey].values.astype(float), view[ykey].values.astype(float)
    xlog, ylog = _is_log(view, xkey), _is_log(view, ykey)
    xe, ye = _edges(x, xlog), _edges(y, ylog)
    ref_model = "nonlinear" if "nonlinear" in _labels(total["model"]) else model
    contact = np.asarray(total["contact_preserved"].sel(model=ref_model).values).astype(bool) if "contact_preserved" in total else None
    lim = _limits(sds)
    n = len(_STUDY_QUANTITIES)
    fig = _subplots(rows=1, cols=n, horizontal_spacing=0.09, subplot_titles=[f"{t} [{u}]" for _, t, _, u in _STUDY_QUANTITIES])
    X, Y = np.meshgrid(x, y)
    for i, (name, title, scale, unit) in enumerate(_STUDY_QUANTITIES, start=1):
        z = np.asarray(total[name].sel(model=model).values, dtype=float) * scale
        dom = fig.layout[f"xaxis{'' if i == 1 else i}"].domain
        fig.add_trace(
            go.Heatmap(x=xe, y=ye, z=z, colorscale="Viridis", colorbar=dict(x=dom[1] + 0.005, thickness=12, len=0.9, title=dict(text=unit, side="right")),
                       hovertemplate=f"{xkey} %{{x:.4g}}<br>{ykey} %{{y:.4g}}<br>{title} %{{z:.3f}} {unit}<extra>{model}</extra>"),
            row=1, col=i,
        )
        if name in lim and np.isfinite(z).any() and np.nanmin(z) < lim[name] * scale < np.nanmax(z):
            fig.add_trace(
                go.Contour(x=x, y=y, z=z, contours=dict(start=lim[name] * scale, end=lim[name] * scale, size=1, coloring="none",
                                                        showlabels=True, labelfont=dict(color="#d62728")),
                           line=dict(color="#d62728", width=2, dash="dash"), showscale=False, name="design limit",
                           legendgroup="limit", showlegend=i == 1, hoverinfo="skip"),
                row=1, col=i,
            )
        if contact is not None and contact.any():
            fig.add_trace(
                go.Scatter(x=X[contact], y=Y[contact], mode="markers", marker=dict(symbol="circle", size=8, color="white", line=dict(color="black", width=1)),
                           name="contact preserved (linear valid)", legendgroup="contact", showlegend=i == 1, hoverinfo="skip"),
                row=1, col=i,
            )
        bx, by = _base(view, xkey), _base(view, ykey)
        if math.isfinite(bx) and math.isfinite(by):
            fig.add_trace(
                go.Scatter(x=[bx], y=[by], mode="markers", marker=dict(symbol="star", size=16, color="white", line=dict(color="black", width=1.5)),
                           name="base case", legendgroup="base", showlegend=i == 1, hovertemplate="base case<extra></extra>"),
                row=1, col=i,
            )
        fig.update_xaxes(title_text=_key_label(view, xkey), **_axis_ticks(view, xkey), row=1, col=i)
        fig.update_yaxes(title_text=_key_label(view, ykey) if i == 1 else None, **_axis_ticks(view, ykey), row=1, col=i)
    _style(fig, f"Study {sds.attrs.get('study', '')}: {model} model, total (dynamic) response{_held_text(held)}", 560)
    return _bottom_legend(fig, 560)


def study_profile_figure(sds: xr.Dataset) -> Any | None:
    """Max force, moment and stress vs the single varying study axis, both models (1-D studies)."""
    view, axes, held = _study_view(sds, 1)
    keys = _study_keys(view)
    if not axes and not keys:
        return None
    key = axes[0] if axes else keys[0]
    go = _go()
    total = _total(view)
    x = view[key].values.astype(float)
    log = _is_log(view, key)
    lim = _limits(sds)
    fig = _subplots(rows=1, cols=3, horizontal_spacing=0.08, subplot_titles=[f"{t} [{u}]" for _, t, _, u in _STUDY_QUANTITIES])
    contact = np.asarray(total["contact_preserved"].sel(model="nonlinear").values).astype(bool) if "nonlinear" in _labels(total["model"]) else None
    for i, (name, title, scale, unit) in enumerate(_STUDY_QUANTITIES, start=1):
        for m in _labels(total["model"]):
            fig.add_trace(go.Scatter(x=x, y=np.asarray(total[name].sel(model=m).values, dtype=float) * scale, mode="lines+markers", name=m,
                                     legendgroup=m, showlegend=i == 1, line=dict(color=_COLORS.get(m, "black"), dash="dash" if m == "linear" else "solid"),
                                     hovertemplate=f"{key} %{{x:.4g}}<br>%{{y:.3f}} {unit}<extra>{m}</extra>"), row=1, col=i)
        if name in lim:
            fig.add_hline(y=lim[name] * scale, line=dict(color="#d62728", dash="dot"), row=1, col=i)
        if contact is not None and contact.any():
            yv = np.asarray(total[name].sel(model="nonlinear").values, dtype=float)[contact] * scale
            fig.add_trace(go.Scatter(x=x[contact], y=yv, mode="markers", marker=dict(symbol="circle-open", size=12, color="#1a9850", line=dict(width=2)),
                                     name="contact preserved (linear valid)", legendgroup="contact", showlegend=i == 1, hoverinfo="skip"), row=1, col=i)
        b = _base(view, key)
        if math.isfinite(b):
            fig.add_vline(x=b, line=dict(color="black", width=1), row=1, col=i)
        fig.update_xaxes(title_text=_key_label(view, key), **_axis_ticks(view, key), row=1, col=i)
    fig.update_yaxes(title_text="total (dynamic) response", row=1, col=1)
    _style(fig, f"Study {sds.attrs.get('study', '')}: total (dynamic) response; red dotted = design limit, black = base case{_held_text(held)}", 500)
    return _bottom_legend(fig, 500)


def compliance_map_figure(sds: xr.Dataset) -> Any | None:
    """Which model's verdict admits each point (F <= F_max and sigma_b <= sigma_max), over two axes (1-D: one row)."""
    keys = _study_keys(sds)
    if not keys:
        return None
    from seafast.studies.limits import DesignLimits, compliance

    view, axes, held = _study_view(sds, 2)
    if not axes:
        return None
    go = _go()
    comp = compliance(view, DesignLimits.from_attrs(sds.attrs))
    if len(axes) == 1:
        xkey, ykey = axes[0], None
    else:
        ykey, xkey = axes
    order = [k for k in (ykey, xkey) if k is not None]
    comp = comp.transpose(*order, ...)
    models = _labels(comp["model"])

    def verdict(m: str) -> np.ndarray:
        if m not in models:
            return np.zeros(comp["complies"].isel(model=0).shape, dtype=bool)
        return np.asarray(comp["complies"].sel(model=m).values).astype(bool)

    cat = verdict("linear").astype(int) + 2 * verdict("nonlinear").astype(int)
    names = ["complies with neither", "linear model only", "nonlinear model only", "both models"]
    colors = ["#d9d9d9", "#fdb863", "#80cdc1", "#1a9850"]
    x = view[xkey].values.astype(float)
    xe = _edges(x, _is_log(view, xkey))
    if ykey is None:
        cat = cat[None, :]
        ye, yv, ylabel = np.array([0.0, 1.0]), np.array([0.5]), ""
    else:
        yv = view[ykey].values.astype(float)
        ye, ylabel = _edges(yv, _is_log(view, ykey)), _key_label(view, ykey)
    scale = []
    for i, c in enumerate(colors):
        scale += [[i / 4, c], [(i + 1) / 4, c]]
    text = np.vectorize(lambda k: names[k])(cat)
    fig = go.Figure(
        go.Heatmap(x=xe, y=ye, z=cat, zmin=0, zmax=4, colorscale=scale, xgap=1, ygap=1, text=text,
                   colorbar=dict(tickvals=[0.5, 1.5, 2.5, 3.5], ticktext=names, thickness=14),
                   hovertemplate="%{x:.4g}, %{y:.4g}<br>%{text}<extra></extra>")
    )
    if "error" in view:
        err = np.asarray(view["error"].transpose(*order).values).astype(str) != ""
        if ykey is None:
            err = err[None, :]
        if err.any():
            yy, xx = np.nonzero(err)
            fig.add_trace(go.Scatter(x=x[xx], y=yv[yy], mode="markers", marker=dict(symbol="x", size=10, color="black"), name="evaluation failed"))
    if ykey is not None:
        bx, by = _base(view, xkey), _base(view, ykey)
        if math.isfinite(bx) and math.isfinite(by):
            fig.add_trace(go.Scatter(x=[bx], y=[by], mode="markers", name="base case",
                                     marker=dict(symbol="star", size=16, color="white", line=dict(color="black", width=1.5))))
    fig.update_xaxes(title_text=_key_label(view, xkey), **_axis_ticks(view, xkey))
    fig.update_yaxes(title_text=ylabel, showticklabels=ykey is not None, **(_axis_ticks(view, ykey) if ykey is not None else {}))
    lim = _limits(sds)
    _style(
        fig,
        f"Compliance: F <= {lim['F_N'] / 1e6:g} MN and sigma_b <= {lim['sigma_b_Pa'] / 1e6:g} MPa (total response){_held_text(held)}",
        500 if ykey is not None else 330,
    )
    return _bottom_legend(fig, 520 if ykey is not None else 350)


def study_figures(sds: xr.Dataset) -> list[ReportFigure]:
    """Interactive figures of a study: surfaces per model (>= 2 varying axes) or profiles (1 axis), and the compliance map."""
    out: list[ReportFigure] = []
    keys = _study_keys(sds)
    varying = [k for k in keys if sds.sizes[k] > 1]
    if len(varying) >= 2:
        for m in ("nonlinear", "linear"):
            fig = study_surface_figure(sds, m)
            if fig is not None:
                out.append(ReportFigure(f"fig-study-surface-{m}", f"Study surfaces, {m} model", fig,
                                        "Circles: contact preserved at every saddle over the whole period (nonlinear model), so the linear "
                                        "model is valid there; dashed red: design limit; star: base case."))
    elif varying or keys:
        fig = study_profile_figure(sds)
        if fig is not None:
            out.append(ReportFigure("fig-study-profiles", "Study profiles", fig,
                                    "Circles: contact preserved at every saddle (linear model valid); red dotted: design limit."))
    fig = compliance_map_figure(sds) if varying else None
    if fig is not None:
        out.append(ReportFigure("fig-compliance-map", "Compliance map", fig,
                                "Which model's verdict admits each arrangement; decisions use the nonlinear model."))
    return out


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


# =============================================================================== HTML
_CSS = """
body{font-family:-apple-system,Segoe UI,Helvetica,Arial,sans-serif;margin:0;color:#222;background:#fafafa}
header{background:#12355b;color:#fff;padding:18px 32px}header h1{margin:0;font-size:24px}header p{margin:4px 0 0;opacity:.85}
nav{background:#e8eef5;padding:8px 32px;font-size:14px;position:sticky;top:0;z-index:10;border-bottom:1px solid #c9d6e3}
nav a{margin-right:16px;color:#12355b;text-decoration:none}nav a:hover{text-decoration:underline}
main{padding:8px 32px 40px;max-width:1500px}section{margin-top:26px}h2{border-bottom:2px solid #12355b;padding-bottom:4px;color:#12355b}
table{border-collapse:collapse;font-size:13px;margin:8px 0;background:#fff}th,td{border:1px solid #ccd;padding:4px 8px;text-align:left;vertical-align:top}
th{background:#eef2f7}td.num{text-align:right;font-variant-numeric:tabular-nums}
.finding{border-left:8px solid;padding:10px 14px;margin:10px 0;border-radius:4px}
.finding.WARNING{background:#fdecea;border-color:#c62828}.finding.WARNING .lvl{color:#c62828}
.finding.NOTE{background:#fff8e1;border-color:#f9a825}.finding.NOTE .lvl{color:#8d6e00}
.finding.OK{background:#e8f5e9;border-color:#2e7d32}.finding.OK .lvl{color:#2e7d32}
.lvl{font-weight:800;letter-spacing:.05em;margin-right:8px}.figure{background:#fff;border:1px solid #dde;margin:14px 0;padding:6px}
.caption{font-size:13px;color:#555;margin:4px 8px 8px}details summary{cursor:pointer;color:#12355b}
.small{font-size:12px;color:#666}
"""


def _table(header: Sequence[str], rows: Sequence[Sequence[Any]], cls: str = "") -> str:
    def cell(v: Any) -> str:
        text = html.escape(str(v))
        numeric = isinstance(v, (int, float)) or (isinstance(v, str) and v.replace(".", "", 1).replace("-", "", 1).replace("e", "", 1).isdigit())
        return f'<td class="num">{text}</td>' if numeric else f"<td>{text}</td>"

    head = "".join(f"<th>{html.escape(str(h))}</th>" for h in header)
    body = "".join("<tr>" + "".join(cell(v) for v in r) + "</tr>" for r in rows)
    return f'<table class="{cls}"><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>'


def _findings_html(findings: Sequence[Finding]) -> str:
    return "".join(
        f'<div class="finding {f.level}"><span class="lvl">{html.escape(f.level)}</span><b>{html.escape(f.title)}</b>'
        + (f"<div>{html.escape(f.text)}</div>" if f.text else "")
        + "</div>"
        for f in findings
    )


def _figure_html(fig: ReportFigure, first: bool) -> str:
    div = fig.figure.to_html(full_html=False, include_plotlyjs=True if first else False, div_id=fig.id, config=_PLOTLY_CONFIG)
    return (
        f'<div class="figure" data-figure="{html.escape(fig.id)}"><h3>{html.escape(fig.title)}</h3>{div}'
        f'<p class="caption">{html.escape(fig.caption)}</p></div>'
    )


def render_html(title: str, subtitle: str, sections: Sequence[tuple[str, str, str]], figure_count: int) -> str:
    """Assemble the report page.

    Parameters
    ----------
    title, subtitle : str
        Page heading.
    sections : sequence of (id, heading, inner HTML)
        The sections in order; each gets a navigation link.
    figure_count : int
        Number of interactive figures (recorded in ``<meta name="seafast-figure-count">``).
    """
    nav = "".join(f'<a href="#{sid}">{html.escape(h)}</a>' for sid, h, _ in sections)
    body = "".join(f'<section id="{sid}"><h2>{html.escape(h)}</h2>{inner}</section>' for sid, h, inner in sections)
    return (
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
        f'<meta name="viewport" content="width=device-width, initial-scale=1"><meta name="seafast-figure-count" content="{figure_count}">'
        f"<title>{html.escape(title)}</title><style>{_CSS}</style></head><body>"
        f"<header><h1>{html.escape(title)}</h1><p>{html.escape(subtitle)}</p></header><nav>{nav}</nav><main>{body}</main></body></html>\n"
    )


def _inputs_section(case: Mapping[str, Any], heading_note: str = "") -> str:
    rows = input_rows(case)
    if not rows:
        return "<p>No case inputs recorded in the dataset.</p>"
    return (f"<p>{html.escape(heading_note)}</p>" if heading_note else "") + _table(
        ["key", "value", "unit", "meaning"], [[r["key"], r["value"], r["unit"], r["description"]] for r in rows]
    )


def _run_sections(ds: xr.Dataset, figs: list[ReportFigure], findings: list[Finding], first_fig: bool, files_note: str) -> tuple[list[tuple[str, str, str]], bool]:
    by_id = {f.id: f for f in figs}

    def figs_html(ids: Sequence[str]) -> str:
        nonlocal first_fig
        parts = []
        for i in ids:
            if i in by_id:
                parts.append(_figure_html(by_id[i], first_fig))
                first_fig = False
        return "".join(parts)

    case = _case_mapping(ds.attrs.get("case_json"))
    header, rows = summary_table_rows(ds)
    dheader, drows = diagnostics_rows(ds)
    omega = _attr_float(ds, "wave_frequency_rad_s")
    exc = html.escape(str(ds.attrs.get("excitation_source", "")))
    vessel_html = f"<p>Excitation: {exc}. Wave frequency {omega:.4f} rad/s (period {2 * math.pi / omega:.2f} s).</p>" if math.isfinite(omega) and omega > 0 else f"<p>Excitation: {exc}</p>"
    vessel_html += figs_html(["fig-hull-girder", "fig-raos", "fig-deck-motion"])
    if "fig-raos" not in by_id:
        vessel_html += '<p class="small">No rigid-body motions in this run (vessel.motions = none, or a deck-deflection table), so no RAO figure.</p>'
    summary_html = (
        _findings_html([f for f in findings if f.level == "WARNING"])
        + "<p>Maxima over the cargo, the saddles and one wave period; cargo deflection u_c relative to the sea-fastening baseline (deck line through the outermost saddles), rigid-body heave and pitch removed; "
        "<i>dynamic</i> = total response (still water included).</p>"
        + _table(header, rows)
        + files_note
    )
    sections = [
        ("run-summary", "Results summary", summary_html),
        ("run-diagnostics", "Convergence diagnostics", _findings_html(findings) + _table(dheader, drows)),
        ("run-inputs", "Inputs", _inputs_section(case, "The case as run (every key, defaults filled in; SI units).")),
        ("run-vessel", "Vessel excitation", vessel_html),
        ("run-saddles", "Saddles over the period", figs_html(["fig-saddle-histories", "fig-contact-timeline"])),
        ("run-lines", "Deflection and bending moment", figs_html(["fig-deflection-moment"])),
    ]
    return sections, first_fig


def _study_sections(sds: xr.Dataset, figs: list[ReportFigure], findings: list[Finding], first_fig: bool, ranking_csv: Path | None) -> tuple[list[tuple[str, str, str]], bool]:
    parts = []
    for f in figs:
        parts.append(_figure_html(f, first_fig))
        first_fig = False
    keys = _study_keys(sds)
    axes_rows = []
    for k in keys:
        v = np.asarray(sds[k].values)
        axes_rows.append([k, _unit_of(k), str(v.size), f"{v.min():.4g} .. {v.max():.4g}", str(sds[k].attrs.get("scale", "")), f"{_base(sds, k):.4g}"])
    header, rows = ranking_rows(sds, ranking_csv)
    show = rows[:40]

    def fmt(v: Any) -> str:
        if isinstance(v, bool):
            return "yes" if v else "no"
        if isinstance(v, float):
            return f"{v:.4g}"
        if isinstance(v, str):
            try:
                return f"{float(v):.4g}" if v not in ("true", "false") else ("yes" if v == "true" else "no")
            except ValueError:
                return v
        return str(v)

    ranking_html = (
        f"<p>{len(rows)} compliant arrangement(s), ranked by fewest saddles, then the larger margin (nonlinear model, total response)."
        + (f" The first {len(show)} are shown; see ranking.csv for all." if len(rows) > len(show) else "")
        + "</p>"
        + (_table(header, [[fmt(r.get(h)) for h in header] for r in show]) if rows else "<p><b>No arrangement of this study complies with the limits.</b></p>")
    )
    lim = _limits(sds)
    overview = (
        f"<p>{html.escape(str(sds.attrs.get('description', '')))}</p>"
        + _table(["axis (dotted key)", "unit", "values", "range", "scale", "base case"], axes_rows)
        + f"<p>Design limits: F &le; {lim['F_N'] / 1e6:g} MN, &sigma;<sub>b</sub> &le; {lim['sigma_b_Pa'] / 1e6:g} MPa.</p>"
    )
    base = _case_mapping(sds.attrs.get("base_case_json"))
    sections = [
        ("study-overview", "Study", overview + _findings_html(findings)),
        ("study-figures", "Study surfaces and compliance", "".join(parts) or "<p>Single-point study: no surfaces.</p>"),
        ("study-ranking", "Ranking of compliant arrangements", ranking_html),
        ("study-inputs", "Study base case", _inputs_section(base, "Every key of the base case the study varies from (SI units).")),
    ]
    return sections, first_fig


def build_report_html(
    run: xr.Dataset | None = None,
    study: xr.Dataset | None = None,
    *,
    title: str | None = None,
    ranking_csv: Path | None = None,
    files_note: str = "",
) -> tuple[str, list[ReportFigure], list[Finding]]:
    """The report page of a run and/or a study dataset (pure: no files written).

    Returns
    -------
    html : str
        The self-contained page (plotly.js inline once).
    figures : list of ReportFigure
        The interactive figures in page order.
    findings : list of Finding
        The diagnostics shown.
    """
    sections: list[tuple[str, str, str]] = []
    figures: list[ReportFigure] = []
    findings: list[Finding] = []
    first = True
    names = []
    if run is not None:
        rf = run_figures(run)
        fnd = run_findings(run)
        s, first = _run_sections(run, rf, fnd, first, files_note)
        sections += s
        figures += rf
        findings += fnd
        names.append(str(_case_mapping(run.attrs.get("case_json")).get("name", "run")))
    if study is not None:
        sf = study_figures(study)
        fnd = study_findings(study)
        s, first = _study_sections(study, sf, fnd, first, ranking_csv)
        sections += s
        figures += sf
        findings += fnd
        names.append(f"study {study.attrs.get('study', '')}")
    version = (run if run is not None else study).attrs.get("seafast_version", "") if (run is not None or study is not None) else ""
    stamp = datetime.now(timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    subtitle = f"seafast {version or ''} report, generated {stamp}. SI inputs; results in mm, MN, MN m, MPa."
    page = render_html(title or f"seafast report: {', '.join(names)}", subtitle, sections, len(figures))
    return page, figures, findings


# =============================================================================== print figures
@contextmanager
def _print_quality(pdf: Any | None, min_dpi: int) -> Iterator[list[str]]:
    """While active, every matplotlib ``Figure.savefig`` to a file uses at least ``min_dpi`` and
    the figure is also appended to ``pdf`` (a ``PdfPages``). Yields the list of saved paths.

    This lets the report reuse the figure functions of :mod:`seafast.output.plots` and
    :mod:`seafast.studies.figures` (which save and close their figures) unchanged.
    """
    from matplotlib.figure import Figure

    original = Figure.savefig
    saved: list[str] = []
    busy = [False]

    def savefig(self: Any, fname: Any, *args: Any, **kwargs: Any) -> Any:
        if busy[0] or kwargs.get("format") == "pdf":
            return original(self, fname, *args, **kwargs)
        dpi = kwargs.get("dpi")
        kwargs["dpi"] = max(float(dpi), min_dpi) if isinstance(dpi, (int, float)) else min_dpi
        result = original(self, fname, *args, **kwargs)
        saved.append(str(fname))
        if pdf is not None:
            busy[0] = True
            try:
                pdf.savefig(self, bbox_inches=kwargs.get("bbox_inches"))
            finally:
                busy[0] = False
        return result

    Figure.savefig = savefig  # type: ignore[method-assign]
    try:
        yield saved
    finally:
        Figure.savefig = original  # type: ignore[method-assign]


def plot_contact_timeline(ds: xr.Dataset, path: Path) -> Path:
    """Contact state (saddle x period fraction) of the dynamic response, per model (PNG)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import ListedColormap
    from matplotlib.patches import Patch

    models = _labels(ds["model"])
    lc = "dynamic" if "dynamic" in _labels(ds["load_case"]) else _labels(ds["load_case"])[-1]
    n = ds.sizes["saddle"]
    fig, axes = plt.subplots(len(models), 1, figsize=(9, 1.2 + 0.55 * n * len(models) + 0.6), squeeze=False, sharex=True)
    s = ds["period_fraction"].values
    ds_ = np.diff(s).mean() if s.size > 1 else 1.0
    xe = np.concatenate([s - ds_ / 2, [s[-1] + ds_ / 2]])
    cmap = ListedColormap(["#fdae61", "#1a9850"])
    for ax, m in zip(axes[:, 0], models):
        z = (ds["saddle_compression_m"].sel(load_case=lc, model=m).values > 0).astype(int).T
        ax.pcolormesh(xe, np.arange(n + 1) - 0.5, z, cmap=cmap, vmin=0, vmax=1, shading="flat")
        ax.set_yticks(range(n))
        ax.set_yticklabels([f"{j}: x = {float(ds['saddle_x_m'][j]):.1f} m" for j in range(n)], fontsize=8)
        ax.set_ylabel("saddle [-]")
        ax.set_title(f"{m} model" + (" (detached = would need tension)" if m == "linear" else ""), fontsize=10)
    axes[-1, 0].set_xlabel("period fraction t/T [-]")
    fig.legend(handles=[Patch(color="#1a9850", label="in contact"), Patch(color="#fdae61", label="detached")], loc="upper right", ncol=2, fontsize=8)
    fig.suptitle(f"Contact state over one wave period ({lc})", fontsize=11, x=0.02, ha="left")
    fig.tight_layout(rect=(0, 0, 1, 0.95))
    fig.savefig(path, dpi=PNG_DPI)
    plt.close(fig)
    return Path(path)


def _summary_page(pdf: Any, title: str, lines: Sequence[str]) -> None:
    import matplotlib.pyplot as plt

    fig = plt.figure(figsize=(11.69, 8.27))
    fig.text(0.05, 0.94, title, fontsize=16, weight="bold", va="top")
    fig.text(0.05, 0.88, "\n".join(lines), fontsize=8.5, family="monospace", va="top")
    pdf.savefig(fig)
    plt.close(fig)


def write_print_figures(run: xr.Dataset | None, study: xr.Dataset | None, fig_dir: Path, pdf_path: Path | None) -> list[Path]:
    """Print-quality PNGs (>= :data:`PNG_DPI` dpi) of the report's figures, and their PDF.

    Run figures reuse :mod:`seafast.output.plots`; study figures :mod:`seafast.studies.figures`.
    A figure that fails to draw is skipped (and named on stderr); the rest are written.
    """
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.backends.backend_pdf import PdfPages

    fig_dir.mkdir(parents=True, exist_ok=True)
    jobs: list[tuple[str, Any]] = []
    if run is not None:
        from seafast.output import plots

        if "hull_x_m" in run.coords:
            jobs.append(("hull_girder.png", plots.plot_hull_girder))
        if "rao_omega_rad_s" in run.coords:
            jobs.append(("raos.png", plots.plot_raos))
        jobs += [
            ("deflection.png", plots.plot_deflection),
            ("forces_moments.png", plots.plot_forces_and_moments),
            ("saddle_time_histories.png", plots.plot_saddle_time_histories),
            ("contact_timeline.png", plot_contact_timeline),
        ]
    paths: list[Path] = []
    pdf = PdfPages(pdf_path) if pdf_path is not None else None
    try:
        if pdf is not None:
            lines: list[str] = []
            if run is not None:
                header, rows = summary_table_rows(run)
                widths = [max(len(str(r[i])) for r in [header, *rows]) for i in range(len(header))]
                lines += ["maxima over the cargo, the saddles and one wave period (dynamic = total response)", ""]
                for r in [header, *rows]:
                    lines.append("  ".join(str(c).ljust(w) if i < 2 else str(c).rjust(w) for i, (c, w) in enumerate(zip(r, widths))))
                lines += ["", f"excitation: {run.attrs.get('excitation_source', '')}"]
                lines += [f"{f.level}: {f.title}" for f in run_findings(run)]
            if study is not None:
                lines += ["", f"study {study.attrs.get('study', '')}: {study.attrs.get('description', '')}"]
                lines += [f"{f.level}: {f.title}" for f in study_findings(study)]
            name = _case_mapping(run.attrs.get("case_json")).get("name", "") if run is not None else study.attrs.get("study", "") if study is not None else ""
            _summary_page(pdf, f"seafast report: {name}", lines)
        with _print_quality(pdf, PNG_DPI):
            for fname, fn in jobs:
                try:
                    paths.append(fn(run, fig_dir / fname))
                except Exception as exc:  # noqa: BLE001 - one bad figure must not lose the report
                    print(f"seafast: warning: print figure {fname} skipped ({type(exc).__name__}: {exc})", file=sys.stderr)
            if study is not None:
                try:
                    from seafast.studies.figures import plot_study

                    paths += list(plot_study(study, fig_dir))
                except Exception as exc:  # noqa: BLE001
                    print(f"seafast: warning: study print figures skipped ({type(exc).__name__}: {exc})", file=sys.stderr)
    finally:
        if pdf is not None:
            pdf.close()
    return paths


# =============================================================================== I/O edge
def _open(path: Path) -> xr.Dataset:
    try:
        with xr.open_dataset(path) as ds:
            return ds.load()
    except Exception as exc:  # noqa: BLE001 - any unreadable file is an input error
        raise ReportError(f"cannot read '{path}': {type(exc).__name__}: {exc}") from None


def write_report(directory: str | Path, output: str | Path | None = None, *, figures: bool = True) -> ReportOutputs:
    """Write the report of a run or study directory.

    Parameters
    ----------
    directory : str or Path
        Holds ``results.nc`` (run) and/or ``study.nc`` (study).
    output : str or Path, optional
        The HTML file (default ``DIR/report.html``). The print figures go next to it:
        ``report_figures/*.png`` and ``report_figures.pdf``.
    figures : bool
        Write the PNG/PDF print figures too.

    Raises
    ------
    ReportError
        If the directory is missing, holds neither file, or a file cannot be read.
    """
    d = Path(directory)
    if not d.exists():
        raise ReportError(f"directory '{d}' does not exist")
    if not d.is_dir():
        raise ReportError(f"'{d}' is not a directory; give the output directory of 'seafast run' or 'seafast study'")
    run_nc, study_nc = d / "results.nc", d / "study.nc"
    if not run_nc.is_file() and not study_nc.is_file():
        raise ReportError(f"'{d}' holds neither results.nc (from 'seafast run -o DIR') nor study.nc (from 'seafast study NAME -o DIR')")
    run = _open(run_nc) if run_nc.is_file() else None
    study = _open(study_nc) if study_nc.is_file() else None
    out = Path(output) if output is not None else d / REPORT_FILENAME
    out.parent.mkdir(parents=True, exist_ok=True)
    fig_dir, pdf_path = out.parent / FIGURES_DIRNAME, out.parent / PDF_FILENAME
    pngs: list[Path] = []
    if figures:
        pngs = write_print_figures(run, study, fig_dir, pdf_path)
    listed = "".join(f'<li><a href="{html.escape(p.relative_to(out.parent).as_posix())}">{html.escape(p.name)}</a></li>' for p in pngs if p.is_relative_to(out.parent))
    files_note = (
        f'<details><summary>Print figures ({len(pngs)} PNG at {PNG_DPI} dpi, and {PDF_FILENAME})</summary><ul>{listed}'
        f'<li><a href="{PDF_FILENAME}">{PDF_FILENAME}</a></li></ul></details>'
        if pngs
        else ""
    )
    page, figs, findings = build_report_html(run, study, ranking_csv=d / "ranking.csv", files_note=files_note)
    out.write_text(page, encoding="utf-8")
    return ReportOutputs(out, tuple(pngs), pdf_path if figures else None, tuple(f.id for f in figs), tuple(findings))


REPORT_EXAMPLES = """examples:
  seafast run -o out/base && seafast report out/base          # writes out/base/report.html
  seafast study saddles -o out/saddles && seafast report out/saddles
  seafast report out/base -o /tmp/base_report.html           # report elsewhere
  seafast report out/base --no-figures                        # HTML only, skip PNG/PDF

The HTML is self-contained (plotly.js inline): open it in any browser, no network needed.
Print figures: report_figures/*.png (200 dpi) and report_figures.pdf next to the HTML.
"""


def _cmd_report(args: argparse.Namespace) -> int:
    try:
        result = write_report(args.directory, args.output, figures=not args.no_figures)
    except ReportError as exc:
        print(f"seafast: error: {exc}", file=sys.stderr)
        return 2
    warnings = [f for f in result.findings if f.level == "WARNING"]
    for f in warnings:
        print(f"seafast: warning: {f.title}", file=sys.stderr)
    extra = f", {len(result.pngs)} PNG in {result.html.parent / FIGURES_DIRNAME} and {result.pdf}" if result.pdf else ""
    print(f"wrote {result.html} ({len(result.figure_ids)} interactive figures{extra})")
    return 0


def add_report_subcommand(subparsers: Any) -> argparse.ArgumentParser:
    """Register ``seafast report DIR [-o FILE] [--no-figures]`` on an argparse subparsers object.

    The handler (``args.handler(args)``) returns the exit code: 0 on success, 2 when DIR is
    missing or holds neither results.nc nor study.nc (one message on stderr, no traceback).
    """
    p = subparsers.add_parser(
        "report",
        help="HTML (and PNG/PDF) report of a run or study directory",
        description="Write one self-contained HTML report (interactive figures, tables, diagnostics) of a "
        "'seafast run' or 'seafast study' output directory, plus print-quality PNG and PDF figures.",
        epilog=REPORT_EXAMPLES,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("directory", metavar="DIR", help="output directory of 'seafast run' (results.nc) or 'seafast study' (study.nc)")
    p.add_argument("-o", "--output", metavar="FILE", default=None, help=f"HTML file to write (default: DIR/{REPORT_FILENAME})")
    p.add_argument("--no-figures", action="store_true", help="skip the PNG/PDF print figures")
    p.set_defaults(handler=_cmd_report)
    return p
