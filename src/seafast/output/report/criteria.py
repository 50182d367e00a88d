"""The design-criteria section of ``seafast report DIR`` (a ``seafast criteria`` directory: criteria.csv).

A clause-by-clause table: for each load case and check, the requirement (the standard's clause and the
case), the value, the limit, the utilisation, pass or fail, and the computation behind the number
(docs/criteria.md).
"""

from __future__ import annotations

import csv
import html
from pathlib import Path

from seafast.output.report.common import Finding, ReportError, findings_html, plain_table_html

__all__ = ["CRITERIA_TABLE_HEADER", "read_criteria_csv", "criteria_table_rows", "criteria_findings", "criteria_report_sections"]

CRITERIA_TABLE_HEADER = ("requirement", "load case", "value", "limit", "utilisation", "pass/fail", "computation")

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


def _computation(row: dict[str, str]) -> str:
    """The computation behind a row's value, with its numbers."""
    a = tuple(float(row[k]) for k in ("a_x_m_s2", "a_y_m_s2", "a_z_m_s2"))
    angle = f"roll {float(row['roll_deg']):g} deg" if float(row["roll_deg"]) != 0.0 else f"pitch {float(row['pitch_deg']):g} deg"
    field = (
        f"apparent gravity at the CoG g_app = g(-sin theta, -cos theta sin phi, -cos theta cos phi) - alpha x r - a_h "
        f"= ({a[0]:.3f}, {a[1]:.3f}, {a[2]:.3f}) m/s2 ({angle} over {float(row['period_s']):g} s, alpha = angle (2 pi / T)^2, "
        f"heave {float(row['heave_acceleration_m_s2']):+.3f} m/s2); mass x g_app on the cargo, solved exactly on pads, stoppers "
        f"and lashings (largest pad {float(row['F_pad_N']) / 1e6:.3f} MN, stopper {float(row['F_stopper_N']) / 1e6:.3f} MN, "
        f"lashing {float(row['lashing_tension_max_N']) / 1e3:.1f} kN; outcome {row['outcome']})"
    )
    if row["check"] == "saddle_force":
        return f"{field}; F = the largest saddle's vertical pad push; utilisation = F / limit"
    return (
        f"{field}; M_b = max over the cargo of sqrt(M_vertical^2 + M_lateral^2) = {float(row['M_b_Nm']) / 1e6:.2f} MN m, "
        "sigma_b = M_b / (I / (D / 2)); utilisation = sigma_b / limit"
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
            )
        )
    return out


def criteria_findings(rows: list[dict[str, str]]) -> list[Finding]:
    """WARNING for each failed check (naming its case and why), else one OK."""
    failed = [r for r in rows if r["verdict"] != "pass"]
    if not failed:
        worst = max(rows, key=lambda r: float(r["utilisation"]))
        return [
            Finding(
                "OK",
                "Every default motion criterion passes",
                f"largest utilisation {float(worst['utilisation']):.3f} ({worst['load_case']}, {worst['check']})",
            )
        ]
    return [
        Finding(
            "WARNING",
            f"{r['load_case']}: {r['check']} fails",
            f"utilisation {float(r['utilisation']):.3f}; statics {r['outcome']}"
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
    body = (
        f"<p>The standard's default motion criteria ({html.escape(rows[0]['source'])}) as quasi-static load cases, roll and "
        "pitch about axes through the centre of flotation at the waterline, each solved exactly on the saddle pads, side "
        "stoppers and lashings (docs/criteria.md).</p>"
        + findings_html(findings)
        + plain_table_html(CRITERIA_TABLE_HEADER, criteria_table_rows(rows))
    )
    return [("criteria", "Design criteria: default motion criteria", body)], findings
