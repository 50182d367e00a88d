"""Summary tables: the CSV contract of docs/interface.md#51-summarycsv and a terminal rendering."""

from __future__ import annotations

import csv
import io
from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import Any

from seafast.results.dataset import SUMMARY_COLUMNS

__all__ = ["write_summary_csv", "summary_csv_text", "format_summary_table", "format_axial_table", "format_cradle_table", "text_table"]


def _cell(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return repr(value)
    return str(value)


def summary_csv_text(rows: Iterable[dict[str, Any]], columns: Sequence[str] = SUMMARY_COLUMNS) -> str:
    """CSV text with exactly ``columns`` (SI units; booleans as true/false)."""
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(columns)
    for r in rows:
        w.writerow([_cell(r[c]) for c in columns])
    return buf.getvalue()


def write_summary_csv(rows: Iterable[dict[str, Any]], path: str | Path, columns: Sequence[str] | None = None) -> Path:
    """Write ``summary.csv`` (docs/interface.md#51-summarycsv columns, or ``columns``, e.g. with the axial ones) and return its path."""
    p = Path(path)
    p.write_text(summary_csv_text(rows, columns or SUMMARY_COLUMNS), encoding="utf-8")
    return p


def _not_converged(row: dict[str, Any]) -> str:
    """Why a row is flagged: the two-way coupling's residual when it failed, else the cargo solver's."""
    if row.get("coupling_converged") is False:
        return f"NO (coupling residual {row['coupling_residual_m']:.2e} m)"
    if row.get("cradle_converged") is False:
        return f"NO (cradle residual {row['cradle_residual']:.2e})"
    return f"NO (residual {row.get('residual_norm', float('nan')):.2e})"


def format_axial_table(rows: Sequence[dict[str, Any]]) -> str:
    """The axial columns of the summary rows in engineering units (mm, kN)."""
    head = ("load case", "model", "slip [mm]", "friction utilisation", "axial force [kN]", "mu_crit [-]", "converged")
    lines = [
        (
            r["load_case"],
            r["model"],
            f"{r['slip_m'] * 1e3:.2f}",
            f"{r['friction_utilisation']:.3f}",
            f"{r['axial_force_N'] / 1e3:.1f}",
            f"{r['critical_friction_coefficient']:.4f}",
            "yes" if r.get("axial_converged", True) else "NO",
        )
        for r in rows
    ]
    return text_table(head, lines, "axial sliding (per period; slides where utilisation = 1)")


def format_cradle_table(rows: Sequence[dict[str, Any]]) -> str:
    """The cradle columns of the summary rows (off head seas) in engineering units (MN, kN, mm); with pad friction its
    utilisation (nan in a linear row) and the slip the pads' (docs/interface.md#51-summarycsv)."""
    friction = any("pad_friction_utilisation" in r for r in rows)
    head: tuple[str, ...] = ("load case", "model", "pad [MN]", "least pad [MN]", "stopper [MN]", "lashing max [kN]", "lashing min [kN]")
    head += ("slip [mm]",) + (("pad friction util.",) if friction else ())
    lines = [
        (
            r["load_case"],
            r["model"],
            f"{r['F_pad_N'] / 1e6:.3f}",
            f"{r['pad_force_min_N'] / 1e6:.3f}",
            f"{r['F_stopper_N'] / 1e6:.3f}",
            f"{r['lashing_tension_max_N'] / 1e3:.1f}",
            f"{r['lashing_tension_min_N'] / 1e3:.1f}",
            f"{r['transverse_slip_m'] * 1e3:.2f}",
        )
        + ((f"{r['pad_friction_utilisation']:.3f}",) if friction else ())
        for r in rows
    ]
    return text_table(head, lines, "the cargo on its cradles (pads, side stoppers, lashing wires; a linear pad below 0 would pull)")


def format_summary_table(rows: Sequence[dict[str, Any]], title: str = "") -> str:
    """Human-readable table in engineering units (mm, MN, MN m, MPa).

    A ``valid`` column is added when a row lies outside the model's small-displacement validity
    (``within_validity`` False, :mod:`seafast.results.validity`).
    """
    head: tuple[str, ...] = ("load case", "model", "u_c [mm]", "u_s [mm]", "u_d [mm]", "F [MN]", "M_b [MNm]", "sigma_b [MPa]", "contact")
    head += ("converged",)
    show_validity = any(not r.get("within_validity", True) for r in rows)
    if show_validity:
        head += ("valid",)
    lines = []
    for r in rows:
        line: tuple[str, ...] = (
            r["load_case"],
            r["model"],
            f"{r['u_c_m'] * 1e3:.2f}",
            f"{r['u_s_m'] * 1e3:.2f}",
            f"{r['u_d_m'] * 1e3:.2f}",
            f"{r['F_N'] / 1e6:.3f}",
            f"{r['M_b_Nm'] / 1e6:.2f}",
            f"{r['sigma_b_Pa'] / 1e6:.2f}",
            "kept" if r.get("contact_preserved", True) else "LOST",
            "yes" if r["converged"] else _not_converged(r),
        )
        if show_validity:
            line += ("yes" if r.get("within_validity", True) else "NO",)
        lines.append(line)
    return text_table(head, lines, title)


def text_table(head: Sequence[str], lines: Sequence[Sequence[str]], title: str = "", label_columns: int = 2) -> str:
    """A plain-text table: an optional title line, the heading, a rule of dashes, the lines; each column as wide as
    its widest cell, the first ``label_columns`` left-aligned and the rest (numbers) right-aligned, two spaces apart."""
    widths = [max(len(h), *(len(line[i]) for line in lines)) if lines else len(h) for i, h in enumerate(head)]

    def row(cells: Sequence[str]) -> str:
        return "  ".join(c.ljust(w) if i < label_columns else c.rjust(w) for i, (c, w) in enumerate(zip(cells, widths, strict=True)))

    return "\n".join(([title] if title else []) + [row(head), row(["-" * w for w in widths])] + [row(line) for line in lines])
