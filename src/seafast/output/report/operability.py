"""The operability section of ``seafast report DIR`` (a ``seafast operability`` directory: operability.nc).

Pure functions ``Dataset -> (sections, figures, findings)``; the page assembly and the files stay
in :mod:`~seafast.output.report.html` and :mod:`~seafast.output.report.write`.
"""

from __future__ import annotations

import html
import json
import math

import numpy as np
import xarray as xr

from seafast.output.report.common import Finding, ReportError, ReportFigure, findings_html, plain_table_html
from seafast.output.report.operability_limits import cradle_governing_finding, limits_html

__all__ = [
    "operability_findings",
    "operability_figure",
    "operability_report_sections",
    "OPERABILITY_TABLE_HEADER",
]

OPERABILITY_TABLE_HEADER = (
    "Tp [s]",
    "allowable Hs, linear [m]",
    "allowable Hs, nonlinear [m]",
    "uplift onset Hs [m]",
    "governing (linear)",
    "governing (nonlinear)",
    "steepest Hs [m]",
)
_PLOTLY_CONFIG = {"displaylogo": False, "responsive": True}


def _m(value: float) -> str:
    return f"{value:.2f}" if math.isfinite(value) else "-"


def _rows(ds: xr.Dataset) -> list[list[str]]:
    out = []
    for i, tp in enumerate(ds["peak_period_s"].values):
        out.append(
            [
                f"{float(tp):g}",
                _m(float(ds["hs_allowable_linear_m"].values[i])),
                _m(float(ds["hs_allowable_nonlinear_m"].values[i])),
                _m(float(ds["hs_uplift_onset_m"].values[i])),
                str(ds["governing_linear"].values[i]),
                str(ds["governing_nonlinear"].values[i]),
                _m(float(ds["hs_max_steepness_m"].values[i])),
            ]
        )
    return out


def _heading_text(ds: xr.Dataset) -> str:
    """The analysed heading of a single-heading operability.nc (from its case), as words."""
    try:
        heading = float(json.loads(str(ds.attrs.get("case_json", "{}")))["sea_state"]["heading_deg"])
    except (ValueError, KeyError, TypeError):
        return "head seas"
    return "head seas" if heading == 180.0 else f"heading {heading:g} deg (180 = head seas, 90 = beam seas)"


def operability_findings(ds: xr.Dataset) -> list[Finding]:
    """WARNING / NOTE / OK statements on an operability result."""
    out: list[Finding] = []
    tp = ds["peak_period_s"].values
    lin, onset = (ds[n].values.astype(float) for n in ("hs_allowable_linear_m", "hs_uplift_onset_m"))
    failed = [float(t) for t, g in zip(tp, ds["governing_nonlinear"].values, strict=True) if str(g) == "not_converged"]
    if failed:
        out.append(
            Finding(
                "WARNING",
                f"The nonlinear search did not converge at Tp = {', '.join(f'{t:g}' for t in failed)} s",
                "Its allowable Hs is left empty; the linear one stands alone there.",
            )
        )
    lifted = [float(t) for t, h, u in zip(tp, lin, onset, strict=True) if math.isfinite(u) and u < h]
    if lifted:
        out.append(
            Finding(
                "NOTE",
                f"Saddles lift off below the linear allowable Hs at {len(lifted)} peak period(s) ({min(lifted):g}-{max(lifted):g} s)",
                "There the linear answer assumes saddles that pull; the nonlinear (design-wave) curve is the one to use.",
            )
        )
    else:
        out.append(Finding("OK", "No saddle lifts off below the allowable Hs: the linear and nonlinear curves agree", ""))
    tps = [f"Tp {float(t):g} s" for t in tp]
    for model in ("nonlinear", "linear"):
        note = cradle_governing_finding(ds[f"governing_{model}"].values, tps, model)
        if note is not None:
            out.append(note)
            break
    if "share_within_limits_nonlinear" in ds.attrs:
        out.append(
            Finding(
                "NOTE",
                f"Scatter diagram {ds.attrs.get('scatter_source', '')}: within the limits "
                f"{float(ds.attrs['share_within_limits_linear']):.1%} of the time (linear), "
                f"{float(ds.attrs['share_within_limits_nonlinear']):.1%} (nonlinear)",
                "",
            )
        )
    return out


def operability_figure(ds: xr.Dataset) -> ReportFigure:
    """Allowable Hs against Tp (both models), uplift onset, limiting steepness, scatter cells."""
    import plotly.graph_objects as go

    tp = ds["peak_period_s"].values
    fig = go.Figure()
    fig.add_trace(go.Scatter(x=tp, y=ds["hs_max_steepness_m"].values, name="limiting steepness", line={"color": "gray", "dash": "dot"}))
    fig.add_trace(
        go.Scatter(
            x=tp,
            y=ds["hs_allowable_nonlinear_m"].values,
            name="allowable Hs, nonlinear (design waves)",
            mode="lines+markers",
            line={"color": "#d62728", "width": 3},
        )
    )
    fig.add_trace(
        go.Scatter(
            x=tp,
            y=ds["hs_allowable_linear_m"].values,
            name="allowable Hs, linear (spectral MPM)",
            mode="lines+markers",
            line={"color": "#1f77b4", "dash": "dash"},
        )
    )
    fig.add_trace(go.Scatter(x=tp, y=ds["hs_uplift_onset_m"].values, name="uplift onset", line={"color": "#2ca02c", "dash": "dashdot"}))
    if "scatter_occurrence" in ds:
        occ = ds["scatter_occurrence"].values
        within = ds["scatter_within_limits_nonlinear"].values.astype(bool)
        size = 6.0 + 30.0 * np.sqrt(occ / max(float(occ.max()), 1e-300))
        for sel, colour, label in ((within, "#2ca02c", "scatter: within limits (nonlinear)"), (~within, "gray", "scatter: not within")):
            fig.add_trace(
                go.Scatter(
                    x=ds["scatter_peak_period_s"].values[sel],
                    y=ds["scatter_significant_height_m"].values[sel],
                    mode="markers",
                    name=label,
                    marker={"size": size[sel], "color": colour, "symbol": "circle-open"},
                )
            )
    top = np.nanmax(
        np.concatenate(
            [
                ds["hs_allowable_linear_m"].values,
                ds["hs_allowable_nonlinear_m"].values,
                np.nan_to_num(ds["hs_uplift_onset_m"].values, nan=0.0),
            ]
        )
    )
    fig.update_xaxes(title_text="peak period Tp [s]")
    fig.update_yaxes(title_text="significant wave height Hs [m]", range=[0.0, 1.15 * max(float(top), 0.1)])
    fig.update_layout(height=480, template="plotly_white")
    return ReportFigure(
        "fig-operability",
        "Allowable sea states",
        fig,
        "Largest Hs per peak period within the saddle-force and bending-stress limits (off head seas also the cradle "
        "limits set; most probable maxima over "
        "the duration, still water included): linear spectral and nonlinear design-wave estimates; the Hs at "
        "which a saddle first lifts off; the steepest sea state (DNV-RP-C205).",
    )


def operability_report_sections(
    ds: xr.Dataset, first_figure: bool
) -> tuple[list[tuple[str, str, str]], list[ReportFigure], list[Finding], bool]:
    """The operability section (id, heading, inner HTML), its figure and findings.

    ``first_figure``: whether plotly.js still has to be embedded; returned updated. An operability.nc over
    headings (a ``heading_deg`` dimension) gets its own section (:mod:`~seafast.output.report.operability_headings`).
    """
    if "heading_deg" in ds.dims:
        from seafast.output.report.operability_headings import heading_operability_report_sections

        return heading_operability_report_sections(ds, first_figure)
    needed = (
        "hs_allowable_linear_m",
        "hs_allowable_nonlinear_m",
        "hs_uplift_onset_m",
        "governing_linear",
        "governing_nonlinear",
        "hs_max_steepness_m",
    )
    missing = [n for n in needed if n not in ds]
    if missing:
        raise ReportError(f"operability.nc lacks {', '.join(missing)}: write it again with this version's 'seafast operability'")
    fig = operability_figure(ds)
    findings = operability_findings(ds)
    div = fig.figure.to_html(full_html=False, include_plotlyjs=True if first_figure else False, div_id=fig.id, config=_PLOTLY_CONFIG)
    body = (
        f"<p>{limits_html(ds)}; most "
        f"probable maxima over {float(ds.attrs.get('duration_s', math.nan)) / 3600:g} h, still water included; "
        f"{html.escape(str(ds.attrs.get('spectrum', '')))} spectrum (&gamma; = {float(ds.attrs.get('peak_enhancement', math.nan)):g}), "
        f"{_heading_text(ds)}. Nonlinear: design waves solved by harmonic balance (docs/operability.md).</p>"
        + findings_html(findings)
        + f'<div class="figure" data-figure="{html.escape(fig.id)}"><h3>{html.escape(fig.title)}</h3>{div}'
        f'<p class="caption">{html.escape(fig.caption)}</p></div>' + plain_table_html(OPERABILITY_TABLE_HEADER, _rows(ds))
    )
    return [("operability", "Operability: allowable sea states", body)], [fig], findings, False
