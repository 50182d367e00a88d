"""Compare two runs of the same study (e.g. before and after a change): same content to tolerance?

Usage::

    python benchmarks/compare_studies.py OLD_DIR NEW_DIR [--rtol 1e-8]

Checks that ``study.csv`` has the same columns and rows (axis values, load case, model), and per
numeric column reports the largest difference relative to the column's largest magnitude;
columns only NEW has (e.g. ``warnings``, added after OLD was run) are listed, not judged, and
the columns both have are compared; a column OLD has and NEW lacks is a difference;
boolean columns (``converged``, ``contact_preserved``) and ``error`` must match exactly;
``ranking.csv`` and ``compliance.csv`` are compared the same way when both runs have them.
``iterations`` and ``residual_norm`` are solver diagnostics and are reported, not judged. The
last line is ``key=value`` pairs; the exit code is 1 when a judged column differs beyond
``--rtol``.
"""

from __future__ import annotations

import argparse
import csv
import math
import sys
from pathlib import Path

DIAGNOSTICS = ("iterations", "residual_norm", "eval_seconds")


def _read(path: Path) -> tuple[list[str], list[list[str]]]:
    with open(path, newline="", encoding="utf-8") as fh:
        rows = list(csv.reader(fh))
    return rows[0], rows[1:]


def _number(text: str) -> float | None:
    try:
        return float(text)
    except ValueError:
        return None


def compare_table(old: Path, new: Path, rtol: float) -> tuple[bool, dict[str, float], list[str]]:
    """(same within rtol, largest relative difference per numeric column, problems)."""
    h_old, r_old = _read(old)
    h_new, r_new = _read(new)
    problems: list[str] = []
    missing = [c for c in h_old if c not in h_new]
    if missing or [c for c in h_new if c in h_old] != h_old:
        return False, {}, [f"{new.name}: columns differ: {h_old} vs {h_new}"]
    added = [c for c in h_new if c not in h_old]
    if added:
        print(f"  {new.name}: columns only in {new.parent.name}: {', '.join(added)} (not judged)")
    if len(r_old) != len(r_new):
        return False, {}, [f"{new.name}: {len(r_old)} rows vs {len(r_new)}"]
    worst: dict[str, float] = {}
    for j, name in enumerate(h_old):
        k = h_new.index(name)
        a = [row[j] for row in r_old]
        b = [row[k] for row in r_new]
        xa, xb = [_number(v) for v in a], [_number(v) for v in b]
        numeric = (
            all(v is not None or t == "" for v, t in zip(xa, a, strict=True))
            and any(v is not None for v in xa)
            and not all(t in ("true", "false") for t in a)
        )
        if not numeric:
            mismatches = sum(1 for u, v in zip(a, b, strict=True) if u != v)
            if mismatches and name not in DIAGNOSTICS:
                problems.append(f"{new.name}: column {name}: {mismatches} of {len(a)} cells differ")
            continue
        scale = max((abs(v) for v in xa if v is not None and math.isfinite(v)), default=0.0) or 1.0
        diff = 0.0
        for u, v, tu, tv in zip(xa, xb, a, b, strict=True):
            if (u is None) != (v is None) or (tu == "") != (tv == ""):
                diff = math.inf
                break
            if u is not None and v is not None:
                diff = max(diff, abs(u - v) / scale)
        worst[name] = diff
        if diff > rtol and name not in DIAGNOSTICS:
            problems.append(f"{new.name}: column {name}: largest difference {diff:.2e} of the column's scale (rtol {rtol:g})")
    return not problems, worst, problems


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("old", type=Path)
    parser.add_argument("new", type=Path)
    parser.add_argument("--rtol", type=float, default=1e-8, help="largest judged difference relative to a column's scale")
    args = parser.parse_args(argv)
    ok = True
    largest = 0.0
    for name in ("study.csv", "compliance.csv", "ranking.csv"):
        old, new = args.old / name, args.new / name
        if not (old.exists() and new.exists()):
            continue
        same, worst, problems = compare_table(old, new, args.rtol)
        ok &= same
        judged = {k: v for k, v in worst.items() if k not in DIAGNOSTICS}
        largest = max([largest, *judged.values()])
        detail = ", ".join(f"{k} {v:.1e}" for k, v in judged.items() if v > 0) or "all equal"
        print(f"{name}: {'same' if same else 'DIFFERENT'} ({detail})")
        for p in problems:
            print("  " + p)
    print(f"same_content={'true' if ok else 'false'} largest_relative_difference={largest:.3g} rtol={args.rtol:g}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
