"""``seafast criteria``: criteria.csv's columns and rows, and bad input refused with exit 2 naming the key."""

from __future__ import annotations

import csv

import pytest

from seafast.cli import main
from seafast.output.criteria import COLUMNS, DESIGN_COLUMNS, EXTRA_COLUMNS

SPEC_COLUMNS = (
    "load_case,heading_deg,roll_deg,pitch_deg,heave_acceleration_m_s2,period_s,a_x_m_s2,a_y_m_s2,a_z_m_s2,F_N,F_pad_N,"
    "F_stopper_N,lashing_tension_max_N,M_b_Nm,sigma_b_Pa,utilisation,verdict"
)


def test_criteria_writes_the_spec_columns_one_row_per_case_and_check(tmp_path, capsys):
    assert ",".join(COLUMNS) == SPEC_COLUMNS
    assert main(["criteria", "-o", str(tmp_path)]) == 0
    with (tmp_path / "criteria.csv").open() as handle:
        reader = csv.DictReader(handle)
        assert tuple(reader.fieldnames or ()) == (*COLUMNS, *EXTRA_COLUMNS, *DESIGN_COLUMNS)
        rows = list(reader)
    assert len(rows) == 16 and {r["check"] for r in rows} == {"saddle_force", "bending_stress"}
    assert len({r["load_case"] for r in rows}) == 8
    for r in rows:
        limit = float(r["limit"])
        value = float(r["F_N"]) if r["check"] == "saddle_force" else float(r["sigma_b_Pa"])
        assert float(r["utilisation"]) == pytest.approx(value / limit, rel=1e-8)
        assert r["verdict"] == ("pass" if float(r["utilisation"]) <= 1 else "fail") and r["outcome"] == "converged"
        assert float(r["a_z_m_s2"]) < 0.0  # the apparent gravity points down
    out = capsys.readouterr().out
    assert "governing:" in out and "0030/ND" in out
    assert (tmp_path / "case.yaml").exists()


@pytest.mark.parametrize(
    ("override", "expect"),
    [
        ("seafastening.saddle_contact_angle_deg=95", "seafastening.saddle_contact_angle_deg"),
        ("seafastening.saddle_contact_angle_deg=0", "seafastening.saddle_contact_angle_deg"),
        ("seafastening.side_stopper.gap_m=0.02", "stiffness_N_per_m"),
        ("seafastening.side_stopper.stiffness_N_per_m=-1", "seafastening.side_stopper.stiffness_N_per_m"),
        ("seafastening.saddle_stiffness_N_per_m=1000", "seafastening.saddle_stiffness_N_per_m"),  # below the wires' k_l sin^2
        ("criteria.design.format=lfd", "criteria.design.format"),
        ("criteria.design.material_factor=0.9", "criteria.design.material_factor"),
        ("criteria.friction.contact=steel_on_ice", "criteria.friction.contact"),
        ("criteria.motion_analysis.headings_deg=[90,90]", "criteria.motion_analysis.headings_deg"),
    ],
)
def test_bad_input_exits_2_naming_the_key(tmp_path, capsys, override, expect):
    assert main(["criteria", "-o", str(tmp_path), "--set", override]) == 2
    err = capsys.readouterr().err
    assert expect in err and "Traceback" not in err
    assert not (tmp_path / "criteria.csv").exists()


def test_bad_headings_exit_2_naming_the_option(tmp_path, capsys):
    assert main(["criteria", "-o", str(tmp_path), "--headings", "90:400:45"]) == 2
    err = capsys.readouterr().err
    assert "--headings" in err and "Traceback" not in err
    assert not (tmp_path / "criteria.csv").exists()


def test_lrfd_rows_carry_the_governing_combination_and_the_friction_credit(tmp_path, capsys):
    overrides = ["criteria.design.format=lrfd", "criteria.friction.contact=steel_on_timber", "seafastening.friction_coefficient=0.2"]
    assert main(["criteria", "-o", str(tmp_path), *(a for o in overrides for a in ("--set", o))]) == 0
    with (tmp_path / "criteria.csv").open() as handle:
        rows = list(csv.DictReader(handle))
    assert len(rows) == 16 and {r["branch"] for r in rows} == {"default_criteria"}
    for r in rows:
        assert r["design_format"] == "lrfd" and r["design_combination"] in ("uls_a", "uls_b")
        resistance = 7e6 if r["check"] == "saddle_force" else 355e6 / 1.15
        assert float(r["design_resistance"]) == pytest.approx(resistance, rel=1e-8)
        if r["design_utilisation"] != "inf":
            assert float(r["design_utilisation"]) == pytest.approx(float(r["design_value"]) / resistance, rel=1e-8)
        assert r["friction_credit"] == "true"
        assert float(r["friction_capacity_N"]) == pytest.approx(0.2 * float(r["friction_normal_N"]), rel=1e-8)
    out = capsys.readouterr().out
    assert "design format lrfd" in out and "governing:" in out
