"""The design-criteria section of ``seafast report DIR``: the clause-by-clause table from criteria.csv."""

from __future__ import annotations

import csv
import re

import pytest

from seafast.analyses.criteria.check import criteria_check
from seafast.config import load_case
from seafast.output.criteria import write_criteria_outputs
from seafast.output.report import write_report
from seafast.output.report.common import ReportError
from seafast.output.report.criteria import CRITERIA_TABLE_HEADER, criteria_table_rows, read_criteria_csv


def _section(page: str) -> str:
    start = page.index("Design criteria: default motion criteria")
    return page[start:]


def test_the_report_holds_one_row_per_case_and_check_with_its_computation(tmp_path):
    case = load_case()
    write_criteria_outputs(criteria_check(case), case, tmp_path)
    out = write_report(tmp_path, figures=False)
    page = out.html.read_text(encoding="utf-8")
    section = _section(page)
    for name in CRITERIA_TABLE_HEADER:
        assert f"<th>{name}</th>" in section
    rows = read_criteria_csv(tmp_path / "criteria.csv")
    table = criteria_table_rows(rows)
    assert len(table) == 16 == section.count("<tr>") - 1
    for row, shown in zip(rows, table, strict=True):
        assert "0030/ND" in shown[0] and row["load_case"] == shown[1]
        value = float(row["F_N"]) / 1e6 if row["check"] == "saddle_force" else float(row["sigma_b_Pa"]) / 1e6
        assert float(shown[2].split()[0]) == pytest.approx(value, abs=5e-4)
        assert shown[5] == row["verdict"] and float(shown[4]) == pytest.approx(float(row["utilisation"]), abs=5e-4)
        # the computation names the apparent gravity's numbers of the row
        assert f"{float(row['a_y_m_s2']):.3f}" in shown[6] and f"{float(row['a_z_m_s2']):.3f}" in shown[6]
    assert "Every default motion criterion passes" in section
    assert re.search(r"largest utilisation 0\.93\d \(pitch-12\.5_heave\+", section)


def test_a_failed_check_is_a_warning_naming_its_case(tmp_path):
    case = load_case(overrides={"seafastening.saddle_contact_angle_deg": 20.0})
    write_criteria_outputs(criteria_check(case), case, tmp_path)
    out = write_report(tmp_path, figures=False)
    warnings = [f for f in out.findings if f.level == "WARNING"]
    assert warnings and all("fails" in f.title for f in warnings)
    assert any("roll" in f.title and "small displacements" in f.text for f in warnings)


def test_a_criteria_csv_without_its_columns_is_refused(tmp_path):
    path = tmp_path / "criteria.csv"
    with path.open("w", newline="") as handle:
        csv.writer(handle).writerows([["load_case", "F_N"], ["roll+20_heave+", "1"]])
    with pytest.raises(ReportError, match=r"lacks .*utilisation"):
        read_criteria_csv(path)
