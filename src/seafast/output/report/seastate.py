"""The sea-state section of ``seafast report DIR`` (a ``seafast seastate`` directory: seastate.nc).

Pure functions ``Dataset -> (sections, figures, findings)``; the page assembly and the files
stay in :mod:`~seafast.output.report.html` and :mod:`~seafast.output.report.write`.
"""

from __future__ import annotations

import html
import json
import math
from typing import Any

import numpy as np
import xarray as xr

from seafast.output.report.common import Finding, ReportError, ReportFigure, findings_html, plain_table_html

__all__ = [
    "seastate_findings",
    "seastate_figures",
    "seastate_report_sections",
    "seastate_table_header",
    "SEASTATE_TABLE_HEADER",
    "CRADLE_TABLE_HEADER",
]

SEASTATE_TABLE_HEADER = ("model", "method", "F [MN]", "M_b [MN m]", "sigma_b [MPa]", "u_s [mm]", "u_d [mm]", "uplift [1/h]", "converged")
_SCALE = (("F_N", 1e-6, 3), ("M_b_Nm", 1e-6, 2), ("sigma_b_Pa", 1e-6, 2), ("u_s_m", 1e3, 2), ("u_d_m", 1e3, 2), ("uplift_per_hour", 1.0, 2))
_CRADLE_SCALE = (
    ("F_pad_N", 1e-6, 3),
    ("F_stopper_N", 1e-6, 3),
    ("lashing_tension_max_N", 1e-3, 2),
    ("lashing_tension_min_N", 1e-3, 2),
    ("transverse_slip_m", 1e3, 2),
)
"""seastate.csv's cradle columns (off head seas) in the table: variable, scale to the head's unit, digits."""
CRADLE_TABLE_HEADER = ("F_pad [MN]", "F_stopper [MN]", "T_max [kN]", "T_min [kN]", "slip [mm]")
"""The cradle columns' heads, after ``converged``: pad force, stopper force, lashing tension max and min, transverse slip."""
_CRADLE_LIMITS = (
    ("F_pad_N", "max_pad_force_N", "pad force", "MN", 1e-6),
    ("lashing_tension_max_N", "max_lashing_tension_N", "lashing tension", "kN", 1e-3),
    ("transverse_slip_m", "max_transverse_slip_m", "transverse slip", "mm", 1e3),
)
_PLOTLY_CONFIG = {"displaylogo": False, "responsive": True}


def _value(ds: xr.Dataset, name: str, model: str, method: str) -> float:
    return float(ds[name].sel({"model": model, "estimate_method": method}).values)


def _methods(ds: xr.Dataset) -> tuple[tuple[str, str], ...]:
    """The (model, method) rows the dataset holds (seastate.nc files written before the design waves have three)."""
    rows = (("linear", "spectral"), ("linear", "monte_carlo"), ("nonlinear", "monte_carlo"), ("nonlinear", "design_wave"))
    methods = [str(m) for m in ds["estimate_method"].values]
    return tuple(r for r in rows if r[1] in methods)


def _has_cradles(ds: xr.Dataset) -> bool:
    """Whether seastate.nc carries the cradle columns (a sea state off head seas)."""
    return all(name in ds for name, _, _ in _CRADLE_SCALE)


def seastate_table_header(ds: xr.Dataset) -> tuple[str, ...]:
    """The table's heads: :data:`SEASTATE_TABLE_HEADER`, and :data:`CRADLE_TABLE_HEADER` when the file has the cradle columns."""
    return SEASTATE_TABLE_HEADER + (CRADLE_TABLE_HEADER if _has_cradles(ds) else ())


def _rows(ds: xr.Dataset) -> list[list[str]]:
    out = []
    cradle = _CRADLE_SCALE if _has_cradles(ds) else ()
    for model, method in _methods(ds):
        row = [model, method]
        for name, scale, digits in _SCALE:
            v = _value(ds, name, model, method)
            row.append(f"{v * scale:.{digits}f}" if math.isfinite(v) else "not computed")
        c = int(ds["converged"].sel({"model": model, "estimate_method": method}).values)
        row.append({1: "yes", 0: "NO", -1: "-"}[c])
        for name, scale, digits in cradle:
            v = _value(ds, name, model, method)
            row.append(f"{v * scale:.{digits}f}" if math.isfinite(v) else "not computed")
        out.append(row)
    return out


def _case_limits(ds: xr.Dataset) -> dict[str, Any]:
    """The case's ``limits`` section recorded in seastate.nc (``case_json``), or {}."""
    try:
        limits = json.loads(str(ds.attrs.get("case_json", "{}"))).get("limits", {})
    except (ValueError, AttributeError):
        return {}
    return limits if isinstance(limits, dict) else {}


def _cradle_limit_findings(ds: xr.Dataset) -> list[Finding]:
    """A WARNING per cradle column above its limit (``limits.max_pad_force_N`` etc., when set) in a row judged on."""
    if not _has_cradles(ds):
        return []
    limits, out = _case_limits(ds), []
    for name, key, label, unit, scale in _CRADLE_LIMITS:
        limit = limits.get(key)
        if limit is None:
            continue
        for model, method in (r for r in _methods(ds) if r[1] != "monte_carlo"):
            v = _value(ds, name, model, method)
            if math.isfinite(v) and v > float(limit):
                out.append(
                    Finding(
                        "WARNING",
                        f"{model} {method}: MPM {label} {v * scale:.2f} {unit} exceeds the limit {float(limit) * scale:g} {unit}",
                        f"limits.{key} of the case (the cargo on its cradles).",
                    )
                )
    return out


def _heading_text(ds: xr.Dataset) -> str:
    """``head seas``, or the sea state's heading off head seas (seastate.nc's ``sea_state_heading_deg``)."""
    heading = float(ds.attrs.get("sea_state_heading_deg", 180.0))
    return "head seas" if heading == 180.0 else f"heading {heading:g} deg (180 = head seas, 90 = beam seas)"


def seastate_findings(ds: xr.Dataset) -> list[Finding]:
    """WARNING / NOTE / OK statements on a sea-state result."""
    out: list[Finding] = []
    hours = float(ds.attrs.get("duration_s", 10800.0)) / 3600.0
    events = _value(ds, "uplift_per_hour", "linear", "spectral") * hours
    if events >= 1.0:
        out.append(
            Finding(
                "WARNING",
                f"The linear model predicts {events:.1f} uplift events in {hours:g} h: saddles lift off",
                "The linear spectral extremes assume saddles that pull; with lift-off they are not to be trusted. "
                "Use the nonlinear rows (design waves, Monte Carlo).",
            )
        )
    elif events >= 0.01:
        out.append(
            Finding(
                "NOTE",
                f"Lift-off is possible: {events:.2f} expected uplift events in {hours:g} h (linear, Rice)",
                "Compare with the nonlinear rows (design waves, Monte Carlo).",
            )
        )
    else:
        out.append(Finding("OK", f"No lift-off expected ({events:.1e} uplift events in {hours:g} h): the linear extremes hold", ""))
    limits = {
        "F_N": float(ds.attrs.get("max_saddle_force_N", math.nan)),
        "sigma_b_Pa": float(ds.attrs.get("max_bending_stress_Pa", math.nan)),
    }
    for model, method in [r for r in _methods(ds) if r[1] != "monte_carlo" or r[0] == "nonlinear"]:
        for name, label, unit, scale in (("F_N", "saddle force", "MN", 1e-6), ("sigma_b_Pa", "bending stress", "MPa", 1e-6)):
            v = _value(ds, name, model, method)
            if math.isfinite(v) and math.isfinite(limits[name]) and v > limits[name]:
                out.append(
                    Finding(
                        "WARNING",
                        f"{model} {method}: MPM {label} {v * scale:.2f} {unit} exceeds the limit {limits[name] * scale:g} {unit}",
                        "limits.* keys of the case.",
                    )
                )
    out += _cradle_limit_findings(ds)
    for model, method in _methods(ds):
        if int(ds["converged"].sel({"model": model, "estimate_method": method}).values) == 0:
            what = "A design wave's harmonic balance" if method == "design_wave" else "A Monte Carlo realisation"
            out.append(Finding("WARNING", f"{what} did not converge ({model}, {method})", "Its row is flagged converged = NO."))
    if not math.isfinite(_value(ds, "F_N", "nonlinear", "monte_carlo")):
        out.append(
            Finding("NOTE", "The nonlinear Monte Carlo reference was not computed", "Run seafast seastate without --no-monte-carlo.")
        )
    return out


def _abs(ds: xr.Dataset, name: str) -> np.ndarray:
    return np.hypot(ds[f"{name}_real"].values, ds[f"{name}_imag"].values)


def _spectrum_figure(ds: xr.Dataset, s: int, x: int) -> Any:
    """The wave spectrum and the normalised response spectra of saddle ``s``'s force and the moment at ``x_moment_m[x]``."""
    import plotly.graph_objects as go
    from plotly.subplots import make_subplots

    w = ds["omega_rad_s"].values
    spec = make_subplots(specs=[[{"secondary_y": True}]])
    spec.add_trace(go.Scatter(x=w, y=ds["wave_spectrum_m2_s_per_rad"].values, name="wave S(ω)", line={"color": "black"}))
    # the two normalised response spectra nearly coincide: a wide light line under a thin dashed one
    for name, idx, label, line in (
        ("saddle_force_spectrum_N2_s_per_rad", {"saddle": s}, f"saddle force, saddle {s}", {"color": "rgba(31,119,180,0.45)", "width": 6}),
        (
            "bending_moment_spectrum_Nm2_s_per_rad",
            {"x_moment_m": x},
            f"bending moment at x = {float(ds['x_moment_m'][x]):.1f} m",
            {"color": "#d62728", "width": 1.5, "dash": "dash"},
        ),
    ):
        r = ds[name].isel(idx).values
        spec.add_trace(go.Scatter(x=w, y=r / max(float(r.max()), 1e-300), name=f"response: {label}", line=line), secondary_y=True)
    spec.update_xaxes(title_text="wave frequency ω [rad/s]")
    spec.update_yaxes(title_text="wave spectral density S [m² s/rad]", rangemode="tozero", secondary_y=False)
    spec.update_yaxes(title_text="response spectrum / its peak [-]", range=[0, 1.05], dtick=0.2, secondary_y=True)
    # the right-hand axis carries the response scale: the legend goes below the plot, clear of it
    spec.update_layout(
        height=460,
        template="plotly_white",
        title=str(ds.attrs.get("spectrum", "")),
        legend={"orientation": "h", "yref": "container", "y": 0.0, "yanchor": "bottom", "x": 0.0},
        margin={"b": 110},
    )
    return spec


def seastate_figures(ds: xr.Dataset) -> list[ReportFigure]:
    """Interactive figures: spectra, transfer functions."""
    import plotly.graph_objects as go
    from plotly.subplots import make_subplots

    w = ds["omega_rad_s"].values
    s = int(np.argmax(ds["still_water_saddle_force_N"].values + ds["saddle_force_mpm_dynamic_N"].values))
    x = int(np.argmax(np.abs(ds["still_water_bending_moment_Nm"].values) + ds["bending_moment_mpm_dynamic_Nm"].values))
    spec = _spectrum_figure(ds, s, x)
    tf = make_subplots(rows=1, cols=2, subplot_titles=("saddle forces", "bending moment (largest total)"))
    force = _abs(ds, "saddle_force_transfer_N_per_m")
    for i in range(force.shape[1]):  # mirror-image saddles coincide: a dash and width of their own
        line = {"dash": ("solid", "dash", "dashdot", "dot")[i % 4], "width": max(3.0 - 0.7 * i, 1.0)}
        tf.add_trace(go.Scatter(x=w, y=force[:, i] / 1e6, name=f"saddle {i}", line=line), row=1, col=1)
    tf.add_trace(
        go.Scatter(x=w, y=_abs(ds, "bending_moment_transfer_Nm_per_m")[:, x] / 1e6, name=f"M at x = {float(ds['x_moment_m'][x]):.1f} m"),
        row=1,
        col=2,
    )
    tf.update_xaxes(title_text="wave frequency ω [rad/s]")
    tf.update_yaxes(title_text="|F| [MN per m of wave]", row=1, col=1)
    tf.update_yaxes(title_text="|M_b| [MN m per m of wave]", row=1, col=2)
    tf.update_layout(height=420, template="plotly_white")
    figures = [
        ReportFigure(
            "fig-seastate-spectrum",
            "Wave and response spectra",
            spec,
            "The wave spectrum and the response spectra of the governing saddle force and bending moment (normalised).",
        ),
        ReportFigure(
            "fig-seastate-transfer",
            "Transfer functions",
            tf,
            f"Magnitude of the linear transfer functions per metre of wave amplitude ({_heading_text(ds)}).",
        ),
    ]
    if "mc_F_N" in ds:
        figures.append(_maxima_figure(ds))
    if "mc_example_saddle_force_N" in ds:
        figures.append(_example_figure(ds))
    return figures


def _maxima_figure(ds: xr.Dataset) -> ReportFigure:
    import plotly.graph_objects as go
    from plotly.subplots import make_subplots

    fig = make_subplots(rows=1, cols=2, subplot_titles=("saddle force F", "bending moment M_b"))
    colours = {"linear": "#1f77b4", "nonlinear": "#d62728"}
    for col, q in ((1, "F_N"), (2, "M_b_Nm")):
        # where the two models' maxima coincide: an open circle around a cross
        markers = {"linear": {"symbol": "circle-open", "size": 11}, "nonlinear": {"symbol": "x-thin-open", "size": 8}}
        for model in ("linear", "nonlinear"):
            m = np.sort(ds[f"mc_{q}"].sel(model=model).values.astype(float))
            m = m[np.isfinite(m)]
            p = (np.arange(1, m.size + 1) - 0.44) / (m.size + 0.12)
            fig.add_trace(
                go.Scatter(
                    x=m / 1e6,
                    y=p,
                    mode="markers",
                    name=f"{model}: per-realisation maxima",
                    marker={"color": colours[model], "line": {"width": 2, "color": colours[model]}, **markers[model]},
                    showlegend=col == 1,
                ),
                row=1,
                col=col,
            )
            mpm = float(ds[f"mc_mpm_{q}"].sel(model=model))
            fig.add_vline(x=mpm / 1e6, line={"color": colours[model], "dash": "dot"}, row=1, col=col)
        fig.add_vline(x=_value(ds, q, "linear", "spectral") / 1e6, line={"color": "black", "dash": "dash"}, row=1, col=col)
    fig.update_xaxes(title_text="F [MN]", row=1, col=1)
    fig.update_xaxes(title_text="M_b [MN m]", row=1, col=2)
    fig.update_yaxes(title_text="non-exceedance probability [-]")
    fig.update_layout(height=420, template="plotly_white")
    return ReportFigure(
        "fig-seastate-maxima",
        "Distribution of the maxima",
        fig,
        "Per-realisation maxima over the duration (Gringorten plotting positions); dotted: Monte Carlo MPM "
        "(Gumbel mode) per model, dashed: linear spectral MPM.",
    )


def _example_figure(ds: xr.Dataset) -> ReportFigure:
    import plotly.graph_objects as go

    # 300 s around the lift-off nearest the largest linear force: whole cycles stay readable and the
    # page small (the full record is in seastate.nc and seastate_realisation.png)
    t_all = ds["mc_example_time_s"].values
    lifted_all = ds["mc_example_saddle_lifted"].values.astype(bool)
    peak = int(np.argmax(ds["mc_example_saddle_force_N"].sel(model="linear").values.max(axis=1)))
    lifts = np.flatnonzero(lifted_all.any(axis=1))
    centre = t_all[lifts[np.argmin(np.abs(lifts - peak))]] if lifts.size else t_all[peak]
    window = (t_all >= centre - 150.0) & (t_all <= centre + 150.0)
    t, lifted = t_all[window], lifted_all[window]
    fig = go.Figure()
    for i in range(ds.sizes["saddle"]):
        colour = f"hsl({(i * 110) % 360},60%,45%)"
        # nonlinear wide and solid underneath, linear thin and dashed black on top: both seen where they agree
        for model, line in (("nonlinear", {"color": colour, "width": 2.5}), ("linear", {"color": "black", "dash": "dash", "width": 1})):
            f = ds["mc_example_saddle_force_N"].sel(model=model).isel(saddle=i).values[window] / 1e6
            fig.add_trace(go.Scattergl(x=t, y=f, mode="lines", name=f"saddle {i}, {model}", line=line))
        if lifted[:, i].any():
            fig.add_trace(
                go.Scattergl(
                    x=t[lifted[:, i]],
                    y=np.zeros(int(lifted[:, i].sum())),
                    mode="markers",
                    name=f"saddle {i} lifted off",
                    marker={"symbol": "line-ns-open", "size": 10, "color": colour},
                )
            )
    fig.update_xaxes(title_text="time t [s]")
    fig.update_yaxes(title_text="saddle force F [MN]")
    fig.update_layout(height=450, template="plotly_white")
    return ReportFigure(
        "fig-seastate-realisation",
        f"One realisation ({ds['mc_example_time_s'].attrs.get('long_name', '')})",
        fig,
        "Saddle forces, nonlinear (solid, per saddle colour) and linear (dashed black), over 300 s around the lift-off nearest the largest "
        "linear force; lift-off marked on F = 0 (the whole record: seastate.nc, seastate_realisation.png).",
    )


_CRADLE_NOTE = (
    "<p>Off head seas the cargo on its cradles (docs/seastate.md): the largest pad force F_pad, side-stopper force "
    "F_stopper, lashing-wire tension T_max and T_min, and lateral displacement of the cargo at a saddle (slip), most "
    "probable maxima (T_min: minimum) with still water; the Monte Carlo rows stay in the vertical plane (not computed).</p>"
)


def seastate_report_sections(
    ds: xr.Dataset, first_figure: bool
) -> tuple[list[tuple[str, str, str]], list[ReportFigure], list[Finding], bool]:
    """The sea-state sections (id, heading, inner HTML), their figures and findings.

    ``first_figure``: whether plotly.js still has to be embedded (with this section's first
    figure); returned updated.
    """
    needed = ("wave_spectrum_m2_s_per_rad", "saddle_force_transfer_N_per_m_real", "F_N", "converged", "still_water_saddle_force_N")
    missing = [n for n in needed if n not in ds] + [d for d in ("model", "estimate_method") if d not in ds.dims]
    if missing:
        raise ReportError(f"seastate.nc lacks {', '.join(missing)}: write it again with this version's 'seafast seastate'")
    figs = seastate_figures(ds)
    findings = seastate_findings(ds)
    parts = []
    for f in figs:
        div = f.figure.to_html(full_html=False, include_plotlyjs=True if first_figure else False, div_id=f.id, config=_PLOTLY_CONFIG)
        first_figure = False
        parts.append(
            f'<div class="figure" data-figure="{html.escape(f.id)}"><h3>{html.escape(f.title)}</h3>{div}'
            f'<p class="caption">{html.escape(f.caption)}</p></div>'
        )
    hs, tp = float(ds.attrs.get("significant_height_m", math.nan)), float(ds.attrs.get("peak_period_s", math.nan))
    summary = (
        f"<p>{html.escape(str(ds.attrs.get('spectrum', '')))}: Hs = {hs:g} m, Tp = {tp:.3g} s, {_heading_text(ds)}; most probable "
        f"maxima over {float(ds.attrs.get('duration_s', math.nan)) / 3600:g} h, still water included "
        "(linear spectral: Rayleigh; design waves: harmonic balance of the regular waves whose linear response is the "
        "linear MPM, docs/operability.md; Monte Carlo: mode of the Gumbel fit to the per-realisation maxima).</p>"
        + findings_html(findings)
        + (_CRADLE_NOTE if _has_cradles(ds) else "")
        + plain_table_html(seastate_table_header(ds), _rows(ds))
    )
    sections = [("seastate-summary", "Sea state: extremes", summary), ("seastate-figures", "Sea state: figures", "".join(parts))]
    return sections, figs, findings, first_figure
