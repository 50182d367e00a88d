"""The operability section of ``seafast report DIR`` for an analysis over headings (operability.nc with ``heading_deg``).

Pure functions ``Dataset -> (sections, figures, findings)``, as :mod:`~seafast.output.report.operability`
for one heading: the governing heading named, a polar chart (180 deg = head seas at the top, the
bow; 90 deg = beam seas from starboard on the right) and the table of allowable Hs per peak period
and heading.
"""

from __future__ import annotations

import html
import math

import numpy as np
import xarray as xr

from seafast.output.report.common import Finding, ReportFigure, findings_html, plain_table_html
from seafast.output.report.operability_limits import cradle_governing_finding, limits_html

__all__ = ["heading_operability_findings", "heading_operability_figure", "heading_operability_report_sections"]

_PLOTLY_CONFIG = {"displaylogo": False, "responsive": True}
POLAR_CAPTION = (
    "Largest Hs [m] (radial) within the limits (saddle force, bending stress; off head seas the cradle limits set), "
    "nonlinear design-wave estimate, against "
    "the wave heading [deg]: 180 deg (head seas, waves from ahead) at the top, the bow; 90 deg (beam seas, waves from "
    "starboard) on the right; 0 deg (following seas) at the bottom. One curve per peak period; in black the smallest "
    "over the peak periods; the star marks the governing heading."
)


def _m(value: float) -> str:
    return f"{value:.2f}" if math.isfinite(value) else "-"


def _governing_finding(ds: xr.Dataset, model: str) -> Finding:
    key = f"governing_heading_{model}_deg"
    if key not in ds.attrs:
        return Finding("WARNING", f"No heading has an allowable Hs ({model})", "Every heading failed or did not converge.")
    a = ds.attrs
    return Finding(
        "NOTE",
        f"Governing heading ({model}): {float(a[key]):g} deg at Tp {float(a[f'governing_peak_period_{model}_s']):g} s, "
        f"allowable Hs {float(a[f'governing_hs_allowable_{model}_m']):.2f} m ({a[f'governing_limit_{model}']} governs)",
        "The heading of the smallest allowable Hs over every heading and peak period analysed.",
    )


def heading_operability_findings(ds: xr.Dataset) -> list[Finding]:
    """The governing heading (nonlinear and linear), failed headings and searches that did not converge."""
    out = [_governing_finding(ds, "nonlinear"), _governing_finding(ds, "linear")]
    headings = ds["heading_deg"].values
    failed = [(float(h), str(e)) for h, e in zip(headings, ds["heading_error"].values, strict=True) if str(e)]
    if failed:
        out.insert(
            0,
            Finding(
                "WARNING",
                f"The analysis failed at heading {', '.join(f'{h:g}' for h, _ in failed)} deg",
                "Its allowable Hs are empty and it takes no part in the governing heading: " + "; ".join(e for _, e in failed),
            ),
        )
    headings_tp = [f"{float(h):g} deg Tp {float(t):g} s" for h in headings for t in ds["peak_period_s"].values]
    for model in ("nonlinear", "linear"):
        note = cradle_governing_finding(ds[f"governing_{model}"].values, headings_tp, model)
        if note is not None:
            out.append(note)
            break
    gov = ds["governing_nonlinear"].values
    stuck = [float(h) for i, h in enumerate(headings) if any(str(g) == "not_converged" for g in gov[i])]
    if stuck:
        out.insert(
            0,
            Finding(
                "WARNING",
                f"The nonlinear search did not converge at some peak periods of heading {', '.join(f'{h:g}' for h in stuck)} deg",
                "Those allowable Hs are empty and take no part in the governing heading; the linear ones stand alone there.",
            ),
        )
    return out


def heading_operability_figure(ds: xr.Dataset) -> ReportFigure:
    """Polar chart: nonlinear allowable Hs against heading, one curve per Tp, the smallest over Tp, the governing heading."""
    import plotly.graph_objects as go
    from plotly.colors import sample_colorscale

    from seafast.output.operability_polar import polar_curves

    theta, hs = polar_curves(ds["heading_deg"].values, ds["hs_allowable_nonlinear_m"].values)
    heading = np.rad2deg(theta)
    tps = ds["peak_period_s"].values.astype(float)
    colours = sample_colorscale("Viridis", list((tps - tps.min()) / max(float(np.ptp(tps)), 1e-9)))
    fig = go.Figure()
    for j, tp in enumerate(tps):
        fig.add_trace(
            go.Scatterpolar(r=hs[:, j], theta=heading, mode="lines+markers", name=f"Tp {tp:g} s", line={"width": 1, "color": colours[j]})
        )
    envelope = np.min(np.where(np.isnan(hs), np.inf, hs), axis=1)
    envelope[np.isinf(envelope)] = np.nan
    fig.add_trace(go.Scatterpolar(r=envelope, theta=heading, mode="lines", name="smallest over Tp", line={"color": "black", "width": 3}))
    if "governing_heading_nonlinear_deg" in ds.attrs:
        fig.add_trace(
            go.Scatterpolar(
                r=[float(ds.attrs["governing_hs_allowable_nonlinear_m"])],
                theta=[float(ds.attrs["governing_heading_nonlinear_deg"])],
                mode="markers",
                name="governing heading",
                marker={"symbol": "star", "size": 16, "color": "#d62728"},
            )
        )
    fig.update_layout(
        height=560,
        template="plotly_white",
        polar={
            "angularaxis": {"rotation": -90, "direction": "counterclockwise", "dtick": 30, "ticksuffix": " deg"},
            "radialaxis": {"title": {"text": "allowable Hs [m]"}, "rangemode": "tozero"},
        },
    )
    return ReportFigure("fig-operability-headings", "Allowable sea states per heading", fig, POLAR_CAPTION)


def _table(ds: xr.Dataset) -> tuple[list[str], list[list[str]]]:
    headings = [float(h) for h in ds["heading_deg"].values]
    header = ["Tp [s]", *(f"{h:g} deg [m]" for h in headings), "governing heading [deg]", "limit"]
    rows = []
    for j, tp in enumerate(ds["peak_period_s"].values):
        gh = float(ds["governing_heading_nonlinear_deg"].values[j])
        cells = [f"{float(tp):g}", *(_m(float(ds["hs_allowable_nonlinear_m"].values[i, j])) for i in range(len(headings)))]
        rows.append(cells + [f"{gh:g}" if math.isfinite(gh) else "-", str(ds["governing_limit_nonlinear"].values[j]) or "-"])
    return header, rows


def heading_operability_report_sections(
    ds: xr.Dataset, first_figure: bool
) -> tuple[list[tuple[str, str, str]], list[ReportFigure], list[Finding], bool]:
    """The operability section over headings (id, heading, inner HTML), its polar figure and findings."""
    fig = heading_operability_figure(ds)
    findings = heading_operability_findings(ds)
    div = fig.figure.to_html(full_html=False, include_plotlyjs=True if first_figure else False, div_id=fig.id, config=_PLOTLY_CONFIG)
    header, rows = _table(ds)
    body = (
        f"<p>{limits_html(ds)}; most "
        f"probable maxima over {float(ds.attrs.get('duration_s', math.nan)) / 3600:g} h, still water included; "
        f"{html.escape(str(ds.attrs.get('spectrum', '')))} spectrum (&gamma; = {float(ds.attrs.get('peak_enhancement', math.nan)):g}) "
        "at each heading (180 deg = head seas, 90 deg = beam seas from starboard). Nonlinear: design waves solved by harmonic "
        "balance (docs/operability.md).</p>"
        + findings_html(findings)
        + f'<div class="figure" data-figure="{html.escape(fig.id)}"><h3>{html.escape(fig.title)}</h3>{div}'
        f'<p class="caption">{html.escape(fig.caption)}</p></div>'
        + "<p>Allowable Hs, nonlinear [m], per peak period and heading; the governing heading is that of the smallest.</p>"
        + plain_table_html(tuple(header), rows)
    )
    return [("operability", "Operability: allowable sea states per heading", body)], [fig], findings, False
