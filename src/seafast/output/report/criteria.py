"""The design-criteria section of ``seafast report DIR`` (a ``seafast criteria`` directory: criteria.csv).

A clause-by-clause table: for each load case and check of both branches (the default criteria, the motion analysis
per heading), the requirement (the standard's clause or the motion analysis, and the case), the value, the limit, the
utilisation, pass or fail, the computation behind the number (with the friction credit) and the check in the design
format (docs/criteria.md).
"""

from __future__ import annotations

import csv
import html
from pathlib import Path

from seafast.output.report.common import Finding, ReportError, findings_html, plain_table_html

__all__ = ["CRITERIA_TABLE_HEADER", "read_criteria_csv", "criteria_table_rows", "criteria_findings", "criteria_report_sections"]

CRITERIA_TABLE_HEADER = ("requirement", "load case", "value", "limit", "utilisation", "pass/fail", "computation", "design format")

_NEEDED = (
    "load_case",
    "roll_deg",
    "pitch_deg",
    "heave_acceleration_m_s2",
    "period_s",
    "a_x_m_s2",
    "a_y_m_s2",
    "a_z_m_s2",
    "F_N",
    "F_pad_N",
    "F_stopper_N",
    "lashing_tension_max_N",
    "M_b_Nm",
    "sigma_b_Pa",
    "utilisation",
    "verdict",
    "check",
    "limit",
    "outcome",
    "source",
)


def read_criteria_csv(path: str | Path) -> list[dict[str, str]]:
    """The rows of a ``seafast criteria`` criteria.csv (text cells).

    Raises
    ------
    ReportError
        If the file cannot be read or lacks a column the section needs.
    """
    try:
        with Path(path).open(newline="", encoding="utf-8") as handle:
            reader = csv.DictReader(handle)
            rows = list(reader)
            columns = set(reader.fieldnames or ())
    except OSError as exc:
        raise ReportError(f"cannot read '{path}': {exc}") from None
    missing = [c for c in _NEEDED if c not in columns]
    if missing:
        raise ReportError(f"'{path}' lacks {', '.join(missing)}: write it again with this version's 'seafast criteria'")
    return rows


def _friction(row: dict[str, str]) -> str:
    if not row.get("friction_credit"):
        return ""
    if row["friction_credit"] == "true":
        return (
            f"; friction may be counted: mu N = {float(row['friction_capacity_N']) / 1e6:.3f} MN (N = "
            f"{float(row['friction_normal_N']) / 1e6:.3f} MN), axial force left to the end stops "
            f"{float(row['F_axial_unresisted_N']) / 1e6:.3f} MN"
        )
    return f"; no friction counted, axial force left to the end stops {float(row['F_axial_unresisted_N']) / 1e6:.3f} MN"


def _sea_state_computation(row: dict[str, str]) -> str:
    what = "linear spectral" if row.get("branch") == "motion_spectral" else "nonlinear design-wave"
    return (
        f"{what} most probable maximum of the sea state at heading {float(row['heading_deg']):g} deg, still water included, "
        f"as seafast seastate (vertical plane: F = {float(row['F_N']) / 1e6:.3f} MN, M_b = {float(row['M_b_Nm']) / 1e6:.2f} MN m); "
        "utilisation = value / limit"
    )


def _computation(row: dict[str, str]) -> str:
    """The computation behind a row's value, with its numbers."""
    if not row["roll_deg"]:
        return _sea_state_computation(row)
    a = tuple(float(row[k]) for k in ("a_x_m_s2", "a_y_m_s2", "a_z_m_s2"))
    if row.get("branch", "default_criteria") == "default_criteria":
        angle = f"roll {float(row['roll_deg']):g} deg" if float(row["roll_deg"]) != 0.0 else f"pitch {float(row['pitch_deg']):g} deg"
        motion = f"{angle} over {float(row['period_s']):g} s, alpha = angle (2 pi / T)^2"
    else:
        motion = (
            f"heading {float(row['heading_deg']):g} deg, roll {float(row['roll_deg']):.2f} deg, pitch {float(row['pitch_deg']):.2f} "
            f"deg at the governing response's MPM (Tz {float(row['period_s']):.2f} s), the rest simultaneous"
        )
    field = (
        f"apparent gravity at the CoG g_app = g(-sin theta, -cos theta sin phi, -cos theta cos phi) - alpha x r - a_0 "
        f"= ({a[0]:.3f}, {a[1]:.3f}, {a[2]:.3f}) m/s2 ({motion}, "
        f"heave {float(row['heave_acceleration_m_s2']):+.3f} m/s2); mass x g_app on the cargo, solved exactly on pads, stoppers "
        f"and lashings (largest pad {float(row['F_pad_N']) / 1e6:.3f} MN, stopper {float(row['F_stopper_N']) / 1e6:.3f} MN, "
        f"lashing {float(row['lashing_tension_max_N']) / 1e3:.1f} kN; outcome {row['outcome']})"
    )
    if row["check"] == "saddle_force":
        return f"{field}; F = the largest saddle's vertical pad push; utilisation = F / limit{_friction(row)}"
    return (
        f"{field}; M_b = max over the cargo of sqrt(M_vertical^2 + M_lateral^2) = {float(row['M_b_Nm']) / 1e6:.2f} MN m, "
        "sigma_b = M_b / (I / (D / 2)); utilisation = sigma_b / limit"
    )


def _design(row: dict[str, str]) -> str:
    if not row.get("design_format"):
        return ""
    unit, scale = ("MN", 1e6) if row["check"] == "saddle_force" else ("MPa", 1e6)
    return (
        f"{row['design_format']} ({row['design_combination']}): {float(row['design_value']) / scale:.3f} / "
        f"{float(row['design_resistance']) / scale:.3f} {unit} = {float(row['design_utilisation']):.3f}, {row['design_verdict']}"
    )


def criteria_table_rows(rows: list[dict[str, str]]) -> list[tuple[str, ...]]:
    """The clause-by-clause table's rows: requirement, load case, value, limit, utilisation, pass/fail, computation."""
    out: list[tuple[str, ...]] = []
    for row in rows:
        force = row["check"] == "saddle_force"
        what = "saddle force F" if force else "bending stress sigma_b"
        value = float(row["F_N"] if force else row["sigma_b_Pa"]) / 1e6
        unit = "MN" if force else "MPa"
        out.append(
            (
                f"{row['source']}: {what}",
                row["load_case"],
                f"{value:.3f} {unit}",
                f"{float(row['limit']) / 1e6:g} {unit}",
                f"{float(row['utilisation']):.3f}",
                row["verdict"],
                _computation(row),
                _design(row),
            )
        )
    return out


def criteria_findings(rows: list[dict[str, str]]) -> list[Finding]:
    """WARNING for each failed check (naming its case and why), else one OK."""
    failed = [r for r in rows if r["verdict"] != "pass" or r.get("design_verdict", "pass") != "pass"]
    if not failed:
        worst = max(rows, key=lambda r: float(r["utilisation"]))
        return [
            Finding(
                "OK",
                "Every default motion criterion passes"
                if all(r.get("branch", "default_criteria") == "default_criteria" for r in rows)
                else "Every check of both branches passes",
                f"largest utilisation {float(worst['utilisation']):.3f} ({worst['load_case']}, {worst['check']})",
            )
        ]
    return [
        Finding(
            "WARNING",
            f"{r['load_case']}: {r['check']} fails",
            f"utilisation {float(r['utilisation']):.3f}"
            + (f", {r['design_format']} {float(r['design_utilisation']):.3f}" if r.get("design_format") else "")
            + f"; statics {r['outcome']}"
            + (
                ""
                if r["outcome"] == "converged"
                else " (the cradles do not hold the cargo within small displacements: add side stoppers or check the contact angle)"
            ),
        )
        for r in failed
    ]


def criteria_report_sections(rows: list[dict[str, str]]) -> tuple[list[tuple[str, str, str]], list[Finding]]:
    """The design-criteria section (id, heading, inner HTML) and its findings."""
    if not rows:
        raise ReportError("criteria.csv has no rows: write it again with 'seafast criteria'")
    findings = criteria_findings(rows)
    motion = [r for r in rows if r.get("branch", "default_criteria") != "default_criteria"]
    headings = sorted({float(r["heading_deg"]) for r in motion})
    governing = max(rows, key=lambda r: float(r["utilisation"]))
    body = (
        f"<p>The standard's default motion criteria ({html.escape(rows[0]['source'])}) as quasi-static load cases, roll and "
        "pitch about axes through the centre of flotation at the waterline, each solved exactly on the saddle pads, side "
        "stoppers and lashings (docs/criteria.md).</p>"
        + (
            ""
            if not motion
            else f"<p>Beside them, the motion analysis of the case's sea state at {', '.join(f'{h:g}' for h in headings)} deg: "
            "load cases at the most probable maximum of roll, pitch and the vertical acceleration at the cargo's centre of "
            "gravity with the simultaneous motions, solved the same way, and the vertical-plane maxima of seafast seastate. "
            f"Governing over both branches: {html.escape(governing['load_case'])} ({governing['check']}, utilisation "
            f"{float(governing['utilisation']):.3f}).</p>"
        )
        + findings_html(findings)
        + plain_table_html(CRITERIA_TABLE_HEADER, criteria_table_rows(rows))
    )
    return [("criteria", "Design criteria: default motion criteria", body)], findings
