"""The small-displacement validity of a run's results: where the lines are, and what a user is told.

A saddle stiffness typed as 1.1 (N/m) instead of 1.1e9 gives a converged solution with the cargo 889 m
below its deck: a solution of the equations, not of a monopile on saddles. Such rows are written and
flagged (``within_validity``), the command exits 4 and suggests the unit that was probably meant; the base
case and the extreme-but-real soft-saddle cases of the test suite stay valid.
"""

from __future__ import annotations

import csv

import xarray as xr

from seafast.analyses.run import evaluate_summary, run_case
from seafast.cli import EXIT_OUTSIDE_VALIDITY, main
from seafast.config import load_case
from seafast.output.report.findings import run_findings
from seafast.results.dataset import SUMMARY_COLUMNS
from seafast.results.validity import (
    DEFAULT_MAX_GAP_M,
    DISPLACEMENT_SHARE_OF_DIAMETER,
    MAX_ROTATION_RAD,
    ValidityLimit,
    likely_cause,
    validity_issues,
    with_validity,
)

FAST = ["--no-plots", "--set", "model.element_length_m=4.0"]


def _row(**values: float) -> dict:
    row = {"load_case": "dynamic", "model": "nonlinear", "u_c_m": 0.01, "u_s_m": 0.01, "u_d_m": 0.0, "cargo_slope_rad": 1e-3}
    row.update(values)
    return row


def test_each_line_is_drawn_where_the_docs_say():
    diameter = 8.0
    at = DISPLACEMENT_SHARE_OF_DIAMETER * diameter  # 2 m for an 8 m pile
    assert at == 2.0
    cases = {
        "u_s_m": (at, ValidityLimit.DISPLACEMENT),
        "u_c_m": (at, ValidityLimit.DISPLACEMENT),
        "cargo_slope_rad": (MAX_ROTATION_RAD, ValidityLimit.ROTATION),
        "u_d_m": (DEFAULT_MAX_GAP_M, ValidityLimit.LIFT_OFF_GAP),
    }
    for key, (limit_value, limit) in cases.items():
        assert validity_issues([_row(**{key: limit_value})], diameter) == ()  # on the line: valid
        (issue,) = validity_issues([_row(**{key: 1.01 * limit_value})], diameter)
        assert issue.limit is limit and issue.allowed == limit_value and issue.value == 1.01 * limit_value
        assert "beyond the model's small-displacement validity" in issue.message
    (nan,) = validity_issues([_row(u_s_m=float("nan"))], diameter)  # a non-number is never a valid answer
    assert nan.limit is ValidityLimit.DISPLACEMENT
    rows = with_validity([_row(), {**_row(u_d_m=0.2), "load_case": "static"}], diameter)
    assert [r["within_validity"] for r in rows] == [True, False]


def test_a_saddle_stiffness_in_the_wrong_unit_is_flagged_with_what_was_meant(tmp_path, capsys):
    out = tmp_path / "slip"
    code = main(["run", "-o", str(out), *FAST, "--set", "seafastening.saddle_stiffness_N_per_m=1.1"])
    err = capsys.readouterr().err
    assert code == EXIT_OUTSIDE_VALIDITY == 4
    assert "beyond the model's small-displacement validity (saddle compression 8" in err
    assert "1.1 GN/m = 1.1e+09 N/m" in err
    assert "Traceback" not in err
    with xr.open_dataset(out / "results.nc") as ds:
        assert not ds["within_validity"].values.any()
        assert ds["within_validity"].attrs["units"] == "1"
        findings = [f for f in run_findings(ds) if "small-displacement validity" in f.title]
        assert len(findings) == 4 and all(f.level == "WARNING" for f in findings)
    header = (out / "summary.csv").read_text(encoding="utf-8").splitlines()[0]
    assert header == ",".join(SUMMARY_COLUMNS)  # the contract's columns, unchanged


def test_the_base_case_and_the_soft_saddles_of_the_studies_are_valid():
    base = run_case(load_case())
    assert base.validity == () and all(r["within_validity"] for r in base.summary)
    assert bool(base.dataset["within_validity"].all())
    # the saddle study's softest corner (two saddles at 1 % of the base stiffness): 0.57 m of compression, an
    # extreme arrangement but a description of one (a quarter of the 8 m diameter is 2 m)
    soft = run_case(load_case(overrides={"seafastening.saddle_count": 2, "seafastening.saddle_stiffness_N_per_m": 1.1e7}))
    assert 0.5 < max(r["u_s_m"] for r in soft.summary) < 2.0 and soft.validity == ()


def test_the_likely_cause_names_the_stiffness_only_when_it_explains_the_issue():
    soft = load_case(overrides={"seafastening.saddle_stiffness_N_per_m": 1.1})
    (issue,) = validity_issues([_row(u_s_m=889.0)], 8.0)
    assert "1.1 MN/m = 1.1e+06 N/m" in (likely_cause(soft, (issue,)) or "")
    (gap,) = validity_issues([_row(u_d_m=0.3)], 8.0)
    assert "saddle_stiffness" not in (likely_cause(load_case(), (gap,)) or "")
    assert likely_cause(soft, ()) is None


def test_a_study_records_the_rows_beyond_validity_as_typed_warnings(tmp_path, capsys):
    """Both routes to a row (the run's and a study point's short path) mark it, and a study stores the line
    crossed in its warnings column and counts it once at the end."""
    slip = load_case(overrides={"seafastening.saddle_stiffness_N_per_m": 1.1, "model.element_length_m": 4.0})
    rows = evaluate_summary(slip)
    assert not any(r["within_validity"] for r in rows)
    assert all(ValidityLimit.DISPLACEMENT in r["warnings"] for r in rows)
    assert [r["warnings"] for r in rows] == [r["warnings"] for r in run_case(slip).summary]
    spec = tmp_path / "slip.yaml"
    spec.write_text(
        "name: slip\naxes:\n  - key: seafastening.saddle_stiffness_N_per_m\n    values: [1.1, 1.1e9]\n"
        "set:\n  model.element_length_m: 4.0\n  solver.harmonics: 16\n",
        encoding="utf-8",
    )
    assert main(["study", str(spec), "-o", str(tmp_path / "out"), "--workers", "1"]) == 0
    err = capsys.readouterr().err
    assert "1 of 2 points: displacement_beyond_quarter_diameter" in err
    with open(tmp_path / "out" / "study.csv", newline="", encoding="utf-8") as fh:
        study = list(csv.DictReader(fh))
    flagged = {r["seafastening.saddle_stiffness_N_per_m"] for r in study if "displacement_beyond_quarter_diameter" in r["warnings"]}
    assert flagged == {"1.1"}
