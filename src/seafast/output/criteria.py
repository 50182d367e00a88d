"""The files and table of ``seafast criteria``: criteria.csv, criteria_motions.csv (docs/criteria.md, docs/interface.md).

criteria.csv: one row per load case and check (``saddle_force``, ``bending_stress``) of both branches, the default
criteria and the motion analysis: the spec's columns :data:`COLUMNS` (the check's own utilisation and verdict), then
:data:`EXTRA_COLUMNS` (``check``, ``limit``, ``outcome``, ``F_axial_N``, ``source``), then :data:`DESIGN_COLUMNS` (the
branch, the check in the design format, the friction credit). criteria_motions.csv: the motion analysis's most probable
maxima per heading (:data:`MOTION_COLUMNS`).
"""

from __future__ import annotations

import csv
from pathlib import Path

import yaml

from seafast.analyses.criteria.check import CriteriaCaseResult, CriteriaResult, Verdict
from seafast.analyses.criteria.design import DesignCheck
from seafast.analyses.criteria.motion_branch import CARGO_POINTS, MOTION_SOURCE, CriteriaAnalysis, HeadingCriteria, SeaStateCheck
from seafast.config.schema import Case
from seafast.solvers.transverse_statics import StaticsOutcome

__all__ = [
    "COLUMNS",
    "EXTRA_COLUMNS",
    "DESIGN_COLUMNS",
    "MOTION_COLUMNS",
    "criteria_rows",
    "motion_rows",
    "write_criteria_csv",
    "write_criteria_outputs",
    "format_criteria_table",
]

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

DESIGN_COLUMNS = (
    "branch",
    "design_format",
    "design_combination",
    "design_value",
    "design_resistance",
    "design_utilisation",
    "design_verdict",
    "friction_normal_N",
    "friction_capacity_N",
    "friction_credit",
    "F_axial_unresisted_N",
)
"""Then: the branch (``default_criteria``, ``motion_quasi_static``, ``motion_spectral``, ``motion_design_wave``); the
check in the design format (its format, governing combination, design value and resistance [N or Pa], utilisation and
verdict); the friction credit (the normal force [N], the friction that may be counted [N], whether it may, the axial
force friction does not hold [N])."""

MOTION_COLUMNS = (
    "heading_deg",
    "origin_x_m",
    "origin_z_m",
    "roll_deg",
    "roll_period_s",
    "pitch_deg",
    "pitch_period_s",
    "heave_acceleration_m_s2",
    *(f"a_{axis}_{point}_m_s2" for point in CARGO_POINTS for axis in "xyz"),
)
"""criteria_motions.csv: per heading the motions' reference (from the aft perpendicular, above the keel) [m] and the MPMs
of roll and pitch [deg] with their zero-crossing periods [s], of the heave acceleration [m/s^2] and of the accelerations
at the cargo's aft end, centre of gravity and fore end along the ship's x, y, z [m/s^2]."""


def _design_cells(design: DesignCheck | None) -> dict[str, object]:
    if design is None:
        return {}
    return {
        "design_format": design.design_format.value,
        "design_combination": design.combination,
        "design_value": design.value,
        "design_resistance": design.resistance,
        "design_utilisation": design.utilisation,
        "design_verdict": (Verdict.PASS if design.passed else Verdict.FAIL).value,
    }


def _friction_cells(item: CriteriaCaseResult) -> dict[str, object]:
    f = item.friction
    if f is None:
        return {}
    return {
        "friction_normal_N": f.normal_force_N,
        "friction_capacity_N": f.capacity_N,
        "friction_credit": "true" if f.counted else "false",
        "F_axial_unresisted_N": f.axial_unresisted_N,
    }


def _case_rows(item: CriteriaCaseResult, source: str, branch: str, limits: tuple[float, float]) -> list[dict[str, object]]:
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
    designs = (None, None) if item.design is None else item.design
    for k, (check, utilisation, limit) in enumerate(
        (("saddle_force", item.utilisation_force, limits[0]), ("bending_stress", item.utilisation_stress, limits[1]))
    ):
        verdict = Verdict.PASS if converged and utilisation <= 1.0 else Verdict.FAIL
        extra = {"check": check, "limit": limit, "outcome": item.outcome, "F_axial_N": item.axial_hold_force_N, "source": source}
        design = {"branch": branch, **_design_cells(designs[k]), **_friction_cells(item)}
        rows.append({**common, "utilisation": utilisation, "verdict": verdict.value, **extra, **design})
    return rows


def _sea_state_rows(item: SeaStateCheck, limits: tuple[float, float]) -> list[dict[str, object]]:
    common: dict[str, object] = {
        "load_case": item.name,
        "heading_deg": item.heading_deg,
        "F_N": item.F_N,
        "M_b_Nm": item.M_b_Nm,
        "sigma_b_Pa": item.sigma_b_Pa,
    }
    outcome = "converged" if item.converged else "not_converged"
    source = f"{MOTION_SOURCE}; {'linear spectral' if item.method == 'spectral' else 'nonlinear design-wave'} MPM as seafast seastate"
    rows = []
    for k, (check, utilisation, limit) in enumerate(
        (("saddle_force", item.utilisation_force, limits[0]), ("bending_stress", item.utilisation_stress, limits[1]))
    ):
        verdict = Verdict.PASS if item.converged and utilisation <= 1.0 else Verdict.FAIL
        extra = {"check": check, "limit": limit, "outcome": outcome, "source": source, "branch": f"motion_{item.method}"}
        rows.append({**common, "utilisation": utilisation, "verdict": verdict.value, **extra, **_design_cells(item.design[k])})
    return rows


def _as_analysis(result: CriteriaResult | CriteriaAnalysis) -> CriteriaAnalysis:
    return result if isinstance(result, CriteriaAnalysis) else CriteriaAnalysis(result, ())


def _heading_rows(h: HeadingCriteria, limits: tuple[float, float]) -> list[dict[str, object]]:
    source = f"{MOTION_SOURCE}; load case at the extreme of the governing response with the simultaneous motions"
    rows = [row for item in h.cases for row in _case_rows(item, source, "motion_quasi_static", limits)]
    return rows + [row for item in h.sea_state for row in _sea_state_rows(item, limits)]


def criteria_rows(result: CriteriaResult | CriteriaAnalysis) -> list[dict[str, object]]:
    """The rows of criteria.csv: two per load case (saddle force, bending stress), the default criteria's then each
    heading's motion-analysis cases and sea-state maxima."""
    analysis = _as_analysis(result)
    d = analysis.default
    limits = (d.max_saddle_force_N, d.max_bending_stress_Pa)
    rows = [row for item in d.cases for row in _case_rows(item, d.criteria.source, "default_criteria", limits)]
    return rows + [row for h in analysis.headings for row in _heading_rows(h, limits)]


def motion_rows(analysis: CriteriaAnalysis) -> list[dict[str, object]]:
    """The rows of criteria_motions.csv: one per heading."""
    out = []
    for h in analysis.headings:
        m = h.maxima
        row: dict[str, object] = {
            "heading_deg": h.heading_deg,
            "origin_x_m": h.origin.x_m,
            "origin_z_m": h.origin.z_above_keel_m,
            "roll_deg": m.roll_deg,
            "roll_period_s": m.roll_period_s,
            "pitch_deg": m.pitch_deg,
            "pitch_period_s": m.pitch_period_s,
            "heave_acceleration_m_s2": m.heave_acceleration_m_s2,
        }
        for i, point in enumerate(CARGO_POINTS):
            for k, axis in enumerate("xyz"):
                row[f"a_{axis}_{point}_m_s2"] = float(m.cargo_acceleration_m_s2[i, k])
        out.append(row)
    return out


def _write_csv(path: Path, columns: tuple[str, ...], rows: list[dict[str, object]]) -> Path:
    with path.open("w", newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=list(columns))
        writer.writeheader()
        for row in rows:
            writer.writerow({k: (f"{v + 0.0:.9g}" if isinstance(v, float) else v) for k, v in row.items()})
    return path


def write_criteria_csv(result: CriteriaResult | CriteriaAnalysis, directory: str | Path) -> Path:
    """Write ``directory/criteria.csv`` (the directory is made) and return its path."""
    out = Path(directory)
    out.mkdir(parents=True, exist_ok=True)
    return _write_csv(out / "criteria.csv", (*COLUMNS, *EXTRA_COLUMNS, *DESIGN_COLUMNS), criteria_rows(result))


def write_criteria_outputs(result: CriteriaResult | CriteriaAnalysis, case: Case, directory: str | Path) -> dict[str, Path]:
    """Write criteria.csv, criteria_motions.csv (with the motion branch) and case.yaml (the case as checked) to
    ``directory``; return their paths."""
    analysis = _as_analysis(result)
    paths = {"criteria": write_criteria_csv(analysis, directory)}
    if analysis.headings:
        paths["motions"] = _write_csv(Path(directory) / "criteria_motions.csv", MOTION_COLUMNS, motion_rows(analysis))
    paths["case"] = Path(directory) / "case.yaml"
    paths["case"].write_text(
        "# the case as checked (all defaults filled in)\n" + yaml.safe_dump(case.model_dump(mode="json"), sort_keys=False), encoding="utf-8"
    )
    return paths


def _case_line(item: CriteriaCaseResult) -> str:
    st = item.statics
    design = "" if item.design is None else f" {max(d.utilisation for d in item.design):6.3f}"
    friction = "" if item.friction is None else f" {item.friction.capacity_N / 1e6:7.3f}"
    return (
        f"{item.load_case.name:<26} {item.apparent_gravity_cog_m_s2[1]:9.3f} {item.apparent_gravity_cog_m_s2[2]:9.3f} "
        f"{item.saddle_force_N / 1e6:7.3f} {st.pad_force_N.max(initial=0.0) / 1e6:7.3f} "
        f"{st.stopper_force_N.max(initial=0.0) / 1e6:7.3f} {st.lashing_tension_N.max(initial=0.0) / 1e3:8.1f} "
        f"{item.bending_stress_Pa / 1e6:9.2f} {item.utilisation:6.3f}{design}{friction} {item.verdict.value}"
        + ("" if item.outcome == StaticsOutcome.CONVERGED.value else f" ({item.outcome})")
    )


def _sea_state_line(item: SeaStateCheck) -> str:
    design = f" {max(d.utilisation for d in item.design):6.3f}"
    return (
        f"{item.name:<26} {'':>9} {'':>9} {item.F_N / 1e6:7.3f} {'':>7} {'':>7} {'':>8} {item.sigma_b_Pa / 1e6:9.2f} "
        f"{item.utilisation:6.3f}{design} {'':>7} {item.verdict.value}" + ("" if item.converged else " (not converged)")
    )


def _heading_lines(h: HeadingCriteria) -> list[str]:
    m = h.maxima
    a = m.cargo_acceleration_m_s2
    title = (
        f"motion analysis, heading {h.heading_deg:g} deg: MPM roll {m.roll_deg:.2f} deg (Tz {m.roll_period_s:.2f} s), pitch "
        f"{m.pitch_deg:.2f} deg (Tz {m.pitch_period_s:.2f} s), heave {m.heave_acceleration_m_s2:.3f} m/s2; at the cargo's CoG "
        f"a_x {a[1, 0]:.3f}, a_y {a[1, 1]:.3f}, a_z {a[1, 2]:.3f} m/s2 (ends: a_z {a[0, 2]:.3f} aft, {a[2, 2]:.3f} fore)"
    )
    return [title] + [_case_line(c) for c in h.cases] + [_sea_state_line(s) for s in h.sea_state]


def format_criteria_table(result: CriteriaResult | CriteriaAnalysis) -> str:
    """A plain-text table of the load cases of both branches for the terminal, naming the governing case.

    ``util`` is the largest plain utilisation (value over the case's limit), ``design`` the largest in the design format,
    ``fric MN`` the friction that may be counted.
    """
    analysis = _as_analysis(result)
    d = analysis.default
    c = d.criteria
    fmt = None if not d.cases or d.cases[0].design is None else d.cases[0].design[0].design_format.value
    title = (
        f"default motion criteria: {c.source}: roll {c.roll_deg:g} deg / {c.roll_period_s:g} s, "
        f"pitch {c.pitch_deg:g} deg / {c.pitch_period_s:g} s, heave {c.heave_acceleration_g:g} g"
        + ("" if fmt is None else f"; design format {fmt}")
    )
    extra = "" if fmt is None else f" {'design':>6} {'fric MN':>7}"
    header = (
        f"{'load case':<26} {'a_y m/s2':>9} {'a_z m/s2':>9} {'F MN':>7} {'pad MN':>7} {'stop MN':>7} {'lash kN':>8} "
        f"{'sigma MPa':>9} {'util':>6}{extra} verdict"
    )
    lines = [title, header, *(_case_line(item) for item in d.cases)]
    for h in analysis.headings:
        lines += _heading_lines(h)
    name, u = analysis.governing
    branch = "the motion analysis" if name.startswith("motion_") else "the default criteria"
    lines.append(f"governing: {name} (utilisation {u:.3f}, {branch}); overall {analysis.verdict.value}")
    return "\n".join(lines)
