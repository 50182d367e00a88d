"""The HTML page of the report: template (embedded CSS), tables, findings and figure blocks.

The page is self-contained: plotly.js is embedded inline once (with the first figure), so the
file opens without a network. :func:`build_report_html` is pure (no files written).
"""

from __future__ import annotations

import html
import math
from collections.abc import Mapping, Sequence
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

import numpy as np
import xarray as xr

from seafast.output.report.common import (
    Finding,
    ReportFigure,
    attr_float,
    base_value,
    case_mapping,
    design_limits,
    findings_html,
    study_keys,
)
from seafast.output.report.findings import run_findings, study_findings
from seafast.output.report.run_figures import run_figures
from seafast.output.report.study_figures import study_figures
from seafast.output.report.tables import coupling_rows, diagnostics_rows, display_unit, input_rows, ranking_rows, summary_table_rows

__all__ = ["render_html", "build_report_html"]

_PLOTLY_CONFIG = {"displaylogo": False, "responsive": True, "toImageButtonOptions": {"format": "png", "scale": 2}}


# =============================================================================== HTML
_CSS = """
body{font-family:-apple-system,Segoe UI,Helvetica,Arial,sans-serif;margin:0;color:#222;background:#fafafa}
header{background:#12355b;color:#fff;padding:18px 32px}header h1{margin:0;font-size:24px}header p{margin:4px 0 0;opacity:.85}
nav{background:#e8eef5;padding:8px 32px;font-size:14px;position:sticky;top:0;z-index:10;border-bottom:1px solid #c9d6e3}
nav a{margin-right:16px;color:#12355b;text-decoration:none}nav a:hover{text-decoration:underline}
main{padding:8px 32px 40px;max-width:1500px}section{margin-top:26px}h2{border-bottom:2px solid #12355b;padding-bottom:4px;color:#12355b}
table{border-collapse:collapse;font-size:13px;margin:8px 0;background:#fff}
th,td{border:1px solid #ccd;padding:4px 8px;text-align:left;vertical-align:top}
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
        numeric = isinstance(v, (int, float)) or (
            isinstance(v, str) and v.replace(".", "", 1).replace("-", "", 1).replace("e", "", 1).isdigit()
        )
        return f'<td class="num">{text}</td>' if numeric else f"<td>{text}</td>"

    head = "".join(f"<th>{html.escape(str(h))}</th>" for h in header)
    body = "".join("<tr>" + "".join(cell(v) for v in r) + "</tr>" for r in rows)
    return f'<table class="{cls}"><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>'


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
        '<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8">'
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


def _run_sections(
    ds: xr.Dataset, figs: list[ReportFigure], findings: list[Finding], first_fig: bool, files_note: str
) -> tuple[list[tuple[str, str, str]], bool]:
    by_id = {f.id: f for f in figs}

    def figs_html(ids: Sequence[str]) -> str:
        nonlocal first_fig
        parts = []
        for i in ids:
            if i in by_id:
                parts.append(_figure_html(by_id[i], first_fig))
                first_fig = False
        return "".join(parts)

    case = case_mapping(ds.attrs.get("case_json"))
    header, rows = summary_table_rows(ds)
    dheader, drows = diagnostics_rows(ds)
    omega = attr_float(ds, "wave_frequency_rad_s")
    exc = html.escape(str(ds.attrs.get("excitation_source", "")))
    vessel_html = (
        f"<p>Excitation: {exc}. Wave frequency {omega:.4f} rad/s (period {2 * math.pi / omega:.2f} s).</p>"
        if math.isfinite(omega) and omega > 0
        else f"<p>Excitation: {exc}</p>"
    )
    if "coupling_converged" in ds:
        vessel_html += (
            "<p>Hull-cargo coupling (vessel.coupling = two_way): the deck of each row iterated with the hull girder. "
            "The hull girder figure shows the one-way hull (the cargo as a spread weight) and the two-way coupled one "
            "(under the nonlinear model's saddle forces).</p>" + _table(*coupling_rows(ds))
        )
    vessel_html += figs_html(["fig-hull-girder", "fig-raos", "fig-deck-motion"])
    if "fig-raos" not in by_id:
        vessel_html += (
            '<p class="small">No rigid-body motions in this run (vessel.motions = none, or a deck-deflection table), so no RAO figure.</p>'
        )
    summary_html = (
        findings_html([f for f in findings if f.level == "WARNING"])
        + "<p>Maxima over the cargo, the saddles and one wave period; cargo deflection u_c relative to the sea-fastening baseline "
        "(deck line through the outermost saddles), rigid-body heave and pitch removed; "
        "<i>dynamic</i> = total response (still water included).</p>" + _table(header, rows) + files_note
    )
    sections = [
        ("run-summary", "Results summary", summary_html),
        ("run-diagnostics", "Convergence diagnostics", findings_html(findings) + _table(dheader, drows)),
        ("run-inputs", "Inputs", _inputs_section(case, "The case as run (every key, defaults filled in; SI units).")),
        ("run-vessel", "Vessel excitation", vessel_html),
        ("run-saddles", "Saddles over the period", figs_html(["fig-saddle-histories", "fig-contact-timeline"])),
        ("run-lines", "Deflection and bending moment", figs_html(["fig-deflection-moment"])),
    ]
    if "slip_m" in ds:
        sections.append(("run-axial", "Axial sliding", _axial_html(ds) + figs_html(["fig-stick-slip"])))
    return sections, first_fig


def _axial_html(ds: xr.Dataset) -> str:
    """The axial analysis's table (docs/axial.md): slip, utilisation, lashing/stopper force, critical coefficient."""
    rows = []
    for lc in [str(v) for v in ds["load_case"].values]:  # plain xarray: no report helper needed
        for m in [str(v) for v in ds["model"].values]:
            sel = ds.sel(load_case=lc, model=m)
            rows.append(
                [
                    lc,
                    m,
                    f"{float(sel['slip_m']) * 1e3:.2f}",
                    f"{float(sel['friction_utilisation']):.3f}",
                    f"{float(sel['axial_force_N']) / 1e3:.1f}",
                    f"{float(sel['critical_friction_coefficient']):.4f}",
                    "yes" if int(sel["axial_converged"]) else "NO",
                ]
            )
    mu = ", ".join(f"{v:.3g}" for v in np.asarray(ds["friction_coefficient"].values)) if "friction_coefficient" in ds else "?"
    return (
        f"<p>Coulomb friction at the saddles (coefficients {html.escape(mu)}) with each model's own saddle contact forces, "
        f"lashings {float(ds.attrs.get('axial_lashing_stiffness_N_per_m', math.nan)) / 1e3:.1f} kN/m axially; axial load amplitude "
        f"{float(ds.attrs.get('axial_load_amplitude_N', math.nan)) / 1e3:.0f} kN (surge, pitch inertia, gravity). "
        "Utilisation 1 = the cargo slides; it slides whenever the friction coefficient is below the critical one.</p>"
        + _table(
            [
                "load case",
                "model",
                "slip per period [mm]",
                "friction utilisation [-]",
                "lashing + stopper force [kN]",
                "critical friction coefficient [-]",
                "converged",
            ],
            rows,
        )
    )


def _study_sections(
    sds: xr.Dataset, figs: list[ReportFigure], findings: list[Finding], first_fig: bool, ranking_csv: Path | None
) -> tuple[list[tuple[str, str, str]], bool]:
    parts = []
    for f in figs:
        parts.append(_figure_html(f, first_fig))
        first_fig = False
    keys = study_keys(sds)
    axes_rows = []
    for k in keys:
        v = np.asarray(sds[k].values)
        axes_rows.append(
            [
                k,
                display_unit(k),
                str(v.size),
                f"{v.min():.4g} .. {v.max():.4g}",
                str(sds[k].attrs.get("scale", "")),
                f"{base_value(sds, k):.4g}",
            ]
        )
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
        + (
            _table(header, [[fmt(r.get(h)) for h in header] for r in show])
            if rows
            else "<p><b>No arrangement of this study complies with the limits.</b></p>"
        )
    )
    lim = design_limits(sds)
    overview = (
        f"<p>{html.escape(str(sds.attrs.get('description', '')))}</p>"
        + _table(["axis (dotted key)", "unit", "values", "range", "scale", "base case"], axes_rows)
        + f"<p>Design limits: F &le; {lim['F_N'] / 1e6:g} MN, &sigma;<sub>b</sub> &le; {lim['sigma_b_Pa'] / 1e6:g} MPa.</p>"
    )
    base = case_mapping(sds.attrs.get("base_case_json"))
    sections = [
        ("study-overview", "Study", overview + findings_html(findings)),
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
    seastate: xr.Dataset | None = None,
    operability: xr.Dataset | None = None,
    criteria: list[dict[str, str]] | None = None,
) -> tuple[str, list[ReportFigure], list[Finding]]:
    """The report page of a run and/or a study dataset (pure: no files written).

    ``criteria``: the rows of a ``seafast criteria`` criteria.csv (the design-criteria section).

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
        names.append(str(case_mapping(run.attrs.get("case_json")).get("name", "run")))
    if study is not None:
        sf = study_figures(study)
        fnd = study_findings(study)
        s, first = _study_sections(study, sf, fnd, first, ranking_csv)
        sections += s
        figures += sf
        findings += fnd
        names.append(f"study {study.attrs.get('study', '')}")
    if seastate is not None:
        from seafast.output.report.seastate import seastate_report_sections

        s, sfigs, sfnd, first = seastate_report_sections(seastate, first)
        sections += s
        figures += sfigs
        findings += sfnd
        names.append(f"sea state {seastate.attrs.get('title', '').removeprefix('seafast sea state: ')}")
    if operability is not None:
        from seafast.output.report.operability import operability_report_sections

        s, ofigs, ofnd, first = operability_report_sections(operability, first)
        sections += s
        figures += ofigs
        findings += ofnd
        names.append(f"operability {operability.attrs.get('title', '').removeprefix('seafast operability: ')}")
    if criteria is not None:
        from seafast.output.report.criteria import criteria_report_sections

        s, cfnd = criteria_report_sections(criteria)
        sections += s
        findings += cfnd
        names.append("design criteria")
    sources = [d for d in (run, study, seastate, operability) if d is not None]
    version = sources[0].attrs.get("seafast_version", "") if sources else ""
    stamp = datetime.now(UTC).strftime("%Y-%m-%d %H:%M UTC")
    subtitle = f"seafast {version or ''} report, generated {stamp}. SI inputs; results in mm, MN, MN m, MPa."
    page = render_html(title or f"seafast report: {', '.join(names)}", subtitle, sections, len(figures))
    return page, figures, findings
