"""The files and table of ``seafast criteria``: criteria.csv (docs/criteria.md, docs/interface.md).

One row per load case and check (``saddle_force``, ``bending_stress``): the spec's columns
:data:`COLUMNS` (the check's own utilisation and verdict), then ``check``, ``limit``, ``outcome``,
``F_axial_N`` and ``source`` (the standard's clause).
"""

from __future__ import annotations

import csv
from pathlib import Path

import yaml

from seafast.analyses.criteria.check import CriteriaCaseResult, CriteriaResult, Verdict
from seafast.config.schema import Case
from seafast.solvers.transverse_statics import StaticsOutcome

__all__ = ["COLUMNS", "EXTRA_COLUMNS", "criteria_rows", "write_criteria_csv", "write_criteria_outputs", "format_criteria_table"]

COLUMNS = (
    "load_case",
    "heading_deg",
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
)
"""The spec's columns of criteria.csv."""

EXTRA_COLUMNS = ("check", "limit", "outcome", "F_axial_N", "source")
"""seafast's columns after them: the check, its limit [N or Pa], the statics' outcome, the axial hold [N], the clause."""


def _case_rows(result: CriteriaResult, item: CriteriaCaseResult) -> list[dict[str, object]]:
    lc, st = item.load_case, item.statics
    common: dict[str, object] = {
        "load_case": lc.name,
        "heading_deg": lc.heading_deg,
        "roll_deg": lc.roll_deg,
        "pitch_deg": lc.pitch_deg,
        "heave_acceleration_m_s2": lc.heave_acceleration_m_s2,
        "period_s": lc.period_s,
        "a_x_m_s2": float(item.apparent_gravity_cog_m_s2[0]),
        "a_y_m_s2": float(item.apparent_gravity_cog_m_s2[1]),
        "a_z_m_s2": float(item.apparent_gravity_cog_m_s2[2]),
        "F_N": item.saddle_force_N,
        "F_pad_N": float(st.pad_force_N.max(initial=0.0)),
        "F_stopper_N": float(st.stopper_force_N.max(initial=0.0)),
        "lashing_tension_max_N": float(st.lashing_tension_N.max(initial=0.0)),
        "M_b_Nm": item.bending_moment_Nm,
        "sigma_b_Pa": item.bending_stress_Pa,
    }
    converged = item.outcome == StaticsOutcome.CONVERGED.value
    rows = []
    for check, utilisation, limit in (
        ("saddle_force", item.utilisation_force, result.max_saddle_force_N),
        ("bending_stress", item.utilisation_stress, result.max_bending_stress_Pa),
    ):
        verdict = Verdict.PASS if converged and utilisation <= 1.0 else Verdict.FAIL
        extra = {
            "check": check,
            "limit": limit,
            "outcome": item.outcome,
            "F_axial_N": item.axial_hold_force_N,
            "source": result.criteria.source,
        }
        rows.append({**common, "utilisation": utilisation, "verdict": verdict.value, **extra})
    return rows


def criteria_rows(result: CriteriaResult) -> list[dict[str, object]]:
    """The rows of criteria.csv: two per load case (saddle force, bending stress)."""
    return [row for item in result.cases for row in _case_rows(result, item)]


def write_criteria_csv(result: CriteriaResult, directory: str | Path) -> Path:
    """Write ``directory/criteria.csv`` (the directory is made) and return its path."""
    out = Path(directory)
    out.mkdir(parents=True, exist_ok=True)
    path = out / "criteria.csv"
    with path.open("w", newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=[*COLUMNS, *EXTRA_COLUMNS])
        writer.writeheader()
        for row in criteria_rows(result):
            writer.writerow({k: (f"{v + 0.0:.9g}" if isinstance(v, float) else v) for k, v in row.items()})
    return path


def write_criteria_outputs(result: CriteriaResult, case: Case, directory: str | Path) -> dict[str, Path]:
    """Write criteria.csv and case.yaml (the case as checked) to ``directory``; return their paths."""
    paths = {"criteria": write_criteria_csv(result, directory)}
    paths["case"] = Path(directory) / "case.yaml"
    paths["case"].write_text(
        "# the case as checked (all defaults filled in)\n" + yaml.safe_dump(case.model_dump(mode="json"), sort_keys=False), encoding="utf-8"
    )
    return paths


def format_criteria_table(result: CriteriaResult) -> str:
    """A plain-text table of the load cases for the terminal, naming the governing case."""
    c = result.criteria
    title = (
        f"default motion criteria: {c.source}: roll {c.roll_deg:g} deg / {c.roll_period_s:g} s, "
        f"pitch {c.pitch_deg:g} deg / {c.pitch_period_s:g} s, heave {c.heave_acceleration_g:g} g"
    )
    header = (
        f"{'load case':<20} {'a_y m/s2':>9} {'a_z m/s2':>9} {'F MN':>7} {'pad MN':>7} {'stop MN':>7} {'lash kN':>8} "
        f"{'sigma MPa':>9} {'util':>6} verdict"
    )
    lines = [title, header]
    for item in result.cases:
        st = item.statics
        lines.append(
            f"{item.load_case.name:<20} {item.apparent_gravity_cog_m_s2[1]:9.3f} {item.apparent_gravity_cog_m_s2[2]:9.3f} "
            f"{item.saddle_force_N / 1e6:7.3f} {st.pad_force_N.max(initial=0.0) / 1e6:7.3f} "
            f"{st.stopper_force_N.max(initial=0.0) / 1e6:7.3f} {st.lashing_tension_N.max(initial=0.0) / 1e3:8.1f} "
            f"{item.bending_stress_Pa / 1e6:9.2f} {item.utilisation:6.3f} {item.verdict.value}"
            + ("" if item.outcome == StaticsOutcome.CONVERGED.value else f" ({item.outcome})")
        )
    g = result.governing
    lines.append(f"governing: {g.load_case.name} (utilisation {g.utilisation:.3f}); overall {result.verdict.value}")
    return "\n".join(lines)
