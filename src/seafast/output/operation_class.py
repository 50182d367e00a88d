"""The operation class in the files and terminal of ``seafast operability`` and ``seafast criteria``.

* Weather-restricted: operability.csv gains :data:`ROUTING_COLUMNS` after its own (alpha and the
  weather-routing limit OP_WF = alpha OP_LIM, linear and nonlinear; empty where alpha has no value);
  ``seafast criteria`` writes operation.csv (:data:`OPERATION_COLUMNS`: alpha and OP_WF at the table's design
  wave heights).
* Unrestricted: route.csv (:data:`ROUTE_COLUMNS`), one row per route leg: its design sea state and, from
  ``seafast operability``, its check against the allowable Hs (empty in ``seafast criteria``).

docs/criteria.md section 12 and docs/interface.md.
"""

from __future__ import annotations

import csv
import io
import math
from collections.abc import Sequence
from pathlib import Path

import numpy as np

from seafast.analyses.criteria.alpha_factor import DESIGN_HS_COLUMNS_M, WeatherRestriction
from seafast.analyses.criteria.operation_class import AllowableTable, OperationPlan, RouteCheck, WeatherRoutingLimits
from seafast.analyses.criteria.route_extremes import RouteDesignSeaState
from seafast.analyses.operability.allowable import OperabilityResult
from seafast.analyses.operability.headings import HeadingOperabilityResult
from seafast.output.operability import operability_cell
from seafast.output.tables import text_table

__all__ = [
    "ROUTING_COLUMNS",
    "ROUTE_COLUMNS",
    "OPERATION_COLUMNS",
    "allowable_table_of",
    "append_routing_columns",
    "route_csv_text",
    "operation_csv_text",
    "format_routing_table",
    "format_route_table",
    "operation_summary",
    "write_operation_class",
]

ROUTING_COLUMNS = ("alpha_linear", "hs_forecast_limit_linear_m", "alpha_nonlinear", "hs_forecast_limit_nonlinear_m")
"""operability.csv's columns of a weather-restricted operation, after its own."""

ROUTE_COLUMNS = (
    "sector",
    "season",
    "design_hs_m",
    "tp_min_s",
    "tp_max_s",
    "method",
    "sea_states",
    "weibull_shape",
    "weibull_location_m",
    "weibull_scale_m",
    "source",
    "hs_allowable_linear_m",
    "hs_allowable_nonlinear_m",
    "governing_peak_period_s",
    "governing_heading_deg",
    "utilisation_linear",
    "utilisation_nonlinear",
    "verdict",
)
"""route.csv: one row per route leg (an unrestricted operation)."""

OPERATION_COLUMNS = (
    "operation_class",
    "planned_operation_period_h",
    "contingency_h",
    "reference_period_h",
    "forecast_level",
    "alpha_table",
    "hs_operational_limit_m",
    "alpha",
    "hs_forecast_limit_m",
)
"""operation.csv of ``seafast criteria`` (weather-restricted): one row per design wave height of the alpha table."""


def allowable_table_of(result: OperabilityResult | HeadingOperabilityResult) -> AllowableTable:
    """The allowable Hs as flat rows, in the order of operability.csv's rows (heading, then peak period).

    Without headings the heading is the case's sea state's (``sea_state.heading_deg``).
    """
    if isinstance(result, OperabilityResult):
        items = [(float(result.case.sea_state.heading_deg), p) for p in result.points]
    else:
        items = [(h.heading_deg, p) for h in result.headings for p in h.result.points]
    return AllowableTable.of(
        [h for h, _ in items],
        [p.peak_period_s for _, p in items],
        [p.hs_allowable_linear_m for _, p in items],
        [p.hs_allowable_nonlinear_m for _, p in items],
    )


def append_routing_columns(operability_csv: Path, limits: WeatherRoutingLimits) -> None:
    """Add :data:`ROUTING_COLUMNS` to a written operability.csv whose rows are ``limits.table``'s."""
    rows = list(csv.reader(io.StringIO(operability_csv.read_text(encoding="utf-8"))))
    header, body = rows[0], rows[1:]
    tp_col = header.index("peak_period_s")
    if len(body) != limits.table.peak_period_s.size or any(
        float(r[tp_col]) != t for r, t in zip(body, limits.table.peak_period_s, strict=True)
    ):
        raise ValueError(f"{operability_csv}: its rows are not those of the weather-routing limits")
    columns = (limits.alpha_linear, limits.hs_forecast_limit_linear_m, limits.alpha_nonlinear, limits.hs_forecast_limit_nonlinear_m)
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow([*header, *ROUTING_COLUMNS])
    for i, r in enumerate(body):
        w.writerow([*r, *(operability_cell(float(c[i])) for c in columns)])
    operability_csv.write_text(buf.getvalue(), encoding="utf-8")


def _route_row(state: RouteDesignSeaState, check: RouteCheck | None) -> dict[str, object]:
    fit = state.fit
    row: dict[str, object] = {
        "sector": state.sector,
        "season": state.season,
        "design_hs_m": state.design_hs_m,
        "tp_min_s": state.tp_min_s,
        "tp_max_s": state.tp_max_s,
        "method": state.method.value,
        "sea_states": state.sea_states,
        "weibull_shape": fit.shape if fit else None,
        "weibull_location_m": fit.location_m if fit else None,
        "weibull_scale_m": fit.scale_m if fit else None,
        "source": state.source,
    }
    if check is not None:
        row |= {
            "hs_allowable_linear_m": check.hs_allowable_linear_m,
            "hs_allowable_nonlinear_m": check.hs_allowable_nonlinear_m,
            "governing_peak_period_s": check.governing_peak_period_s,
            "governing_heading_deg": check.governing_heading_deg,
            "utilisation_linear": check.utilisation_linear,
            "utilisation_nonlinear": check.utilisation_nonlinear,
            "verdict": check.verdict.value,
        }
    return row


def route_csv_text(states: Sequence[RouteDesignSeaState], checks: Sequence[RouteCheck] | None = None) -> str:
    """route.csv text: each leg's design sea state, and its check when given (else those cells empty)."""
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(ROUTE_COLUMNS)
    for i, s in enumerate(states):
        row = _route_row(s, checks[i] if checks is not None else None)
        w.writerow([operability_cell(row.get(c)) for c in ROUTE_COLUMNS])
    return buf.getvalue()


def operation_csv_text(restriction: WeatherRestriction) -> str:
    """operation.csv text: alpha and OP_WF at each design wave height of the restriction's alpha table."""
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(OPERATION_COLUMNS)
    hs = np.array(DESIGN_HS_COLUMNS_M)
    alpha = restriction.alpha(hs)
    for h, a in zip(hs, alpha, strict=True):
        cells = (
            "weather_restricted",
            restriction.planned_operation_period_h,
            restriction.contingency_h,
            restriction.reference_period_h,
            restriction.forecast_level.value,
            restriction.table.name,
            float(h),
            float(a),
            float(a * h),
        )
        w.writerow([operability_cell(c) for c in cells])
    return buf.getvalue()


def _fmt(x: float, spec: str = ".2f") -> str:
    return "-" if not math.isfinite(x) else format(x, spec)


def operation_summary(plan: OperationPlan) -> str:
    """One line: the operation class and what it rests on."""
    r = plan.restriction
    if r is not None:
        return (
            f"operation class: weather-restricted, T_POP {r.planned_operation_period_h:g} h, T_C {r.contingency_h:g} h, "
            f"T_R {r.reference_period_h:g} h, forecast {r.forecast_level.value} ({r.table.name})"
        )
    years = plan.operation.return_period_years
    return f"operation class: unrestricted, {len(plan.route)} route leg(s), {years:g}-year monthly extreme Hs per sector and season"


def format_routing_table(limits: WeatherRoutingLimits) -> str:
    """Terminal table of the weather-routing limit: per peak period the smallest nonlinear OP_WF over the headings."""
    t = limits.table
    lines = []
    for tp in np.unique(t.peak_period_s):
        rows = np.flatnonzero(t.peak_period_s == tp)
        wf = limits.hs_forecast_limit_nonlinear_m[rows]
        i = rows[int(np.nanargmin(wf))] if np.isfinite(wf).any() else rows[0]
        heading = f"{t.heading_deg[i]:g}"
        lines.append(
            [
                f"{tp:g}",
                heading,
                _fmt(t.hs_allowable_nonlinear_m[i]),
                _fmt(limits.alpha_nonlinear[i], ".3f"),
                _fmt(limits.hs_forecast_limit_nonlinear_m[i]),
                _fmt(limits.hs_forecast_limit_linear_m[i]),
            ]
        )
    head = ["Tp [s]", "heading [deg]", "OP_LIM nonlin [m]", "alpha", "OP_WF nonlin [m]", "OP_WF lin [m]"]
    title = "weather-routing limit OP_WF = alpha OP_LIM (the forecast Hs must stay below it; '-': alpha not defined below 1 m)"
    return title + "\n" + text_table(head, lines, label_columns=0)


def format_route_table(checks: Sequence[RouteCheck]) -> str:
    """Terminal table of the route legs' design sea states and their checks."""
    lines = [
        [
            f"{c.sea_state.sector}, {c.sea_state.season}",
            _fmt(c.sea_state.design_hs_m),
            f"{c.sea_state.tp_min_s:.1f}-{c.sea_state.tp_max_s:.1f}",
            c.sea_state.method.value,
            _fmt(c.hs_allowable_nonlinear_m),
            _fmt(c.governing_peak_period_s, "g"),
            _fmt(c.utilisation_nonlinear, ".3f"),
            c.verdict.value,
        ]
        for c in checks
    ]
    head = ["leg", "design Hs [m]", "Tp range [s]", "method", "allowable Hs [m]", "at Tp [s]", "utilisation", "verdict"]
    return "route design sea states (10-year monthly extremes) against the allowable Hs (nonlinear)\n" + text_table(
        head, lines, label_columns=0
    )


def write_operation_class(plan: OperationPlan, out_dir: str | Path) -> tuple[Path, str]:
    """``seafast criteria``'s file of the operation class (operation.csv or route.csv) and its terminal text."""
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    r = plan.restriction
    if r is not None:
        path = out / "operation.csv"
        path.write_text(operation_csv_text(r), encoding="utf-8")
        hs = np.array(DESIGN_HS_COLUMNS_M)
        lines = [[f"{h:g}", _fmt(a, ".3f"), _fmt(a * h)] for h, a in zip(hs, r.alpha(hs), strict=True)]
        table = text_table(["OP_LIM [m]", "alpha", "OP_WF [m]"], lines, label_columns=0)
        note = "OP_LIM per peak period and heading: seafast operability (operability.csv's hs_forecast_limit_* columns)"
        return path, f"{operation_summary(plan)}\n{table}\n{note}"
    path = out / "route.csv"
    path.write_text(route_csv_text(plan.route), encoding="utf-8")
    lines = [
        [f"{s.sector}, {s.season}", _fmt(s.design_hs_m), f"{s.tp_min_s:.1f}-{s.tp_max_s:.1f}", s.method.value, s.source] for s in plan.route
    ]
    table = text_table(["leg", "design Hs [m]", "Tp range [s]", "method", "source"], lines, label_columns=0)
    return path, f"{operation_summary(plan)}\n{table}\nchecked against the allowable Hs by seafast operability (route.csv)"
