"""Sea-state studies off head seas record the cargo on its cradles as ``seafast seastate --no-monte-carlo`` does
(docs/studies.md section 7): the linear row the linear spectral MPMs, the nonlinear row the cradle design waves."""

from __future__ import annotations

import csv
import json
import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

import seafast
from seafast.analyses.seastate import study as sea_state_study
from seafast.analyses.seastate.study import evaluate_sea_state
from seafast.cli import main
from seafast.parallel.executor import ExecutionOptions
from seafast.results.cradle import CRADLE_SUMMARY_COLUMNS
from seafast.studies.assembly import CORE_COLUMNS
from seafast.studies.limits import DesignLimits, compliance
from seafast.studies.runner import run_study
from seafast.studies.spec import build_grid, study_spec_from_mapping

SERIAL = ExecutionOptions(workers=1, progress=False)
ANGLES_DEG = (35.0, 50.0)
BEAM = {"sea_state.heading_deg": 90.0, "sea_state.significant_height_m": 3.0}
ANGLE_KEY = "seafastening.saddle_contact_angle_deg"
STIFF_WIRE = {"seafastening.lashing.stiffness_N_per_m": 1.0e10}  # wires stiffer than the saddles: the cradles cannot be held
VERTICAL_KEYS = [*CORE_COLUMNS, "uplift_per_hour", "warnings"]  # a sea-state study's rows in head seas


def _study(name: str, axes: list[dict], base: dict, limits: dict | None = None):
    spec = {"name": name, "axes": axes, "response": "sea_state", "set": base}
    return build_grid(study_spec_from_mapping(spec | ({"limits": limits} if limits else {})))


def _csv(path: Path) -> list[dict[str, str]]:
    with open(path, newline="", encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


def _seastate_csv(tmp_path: Path, overrides: dict) -> dict[str, dict[str, str]]:
    """``seafast seastate --no-monte-carlo``'s seastate.csv rows by method (spectral, design_wave)."""
    out = tmp_path / f"seastate-{len(list(tmp_path.iterdir()))}"
    sets = [a for k, v in overrides.items() for a in ("--set", f"{k}={v}")]
    assert main(["seastate", "--no-monte-carlo", "--no-plots", "-q", "-o", str(out), *sets]) in (0, 3)
    return {r["method"]: r for r in _csv(out / "seastate.csv")}


def test_beam_seas_study_records_seafast_seastates_cradle_columns_and_judges_a_cradle_limit(tmp_path):
    grid = _study("beam", [{"key": ANGLE_KEY, "values": list(ANGLES_DEG)}], BEAM)
    run = run_study(grid, tmp_path / "study", execution=SERIAL)
    assert run.failed == 0
    rows = _csv(tmp_path / "study" / "study.csv")
    header = list(rows[0])
    at = header.index("contact_preserved") + 1
    assert header[at : at + 5] == list(CRADLE_SUMMARY_COLUMNS)  # placed as in a regular-wave study
    ds = run.dataset.sel(load_case="sea_state")
    for angle in ANGLES_DEG:
        reference = _seastate_csv(tmp_path, {**BEAM, ANGLE_KEY: angle})
        for model, method in (("linear", "spectral"), ("nonlinear", "design_wave")):
            row = next(r for r in rows if float(r[ANGLE_KEY]) == angle and r["model"] == model)
            ref = reference[method]
            for column in CRADLE_SUMMARY_COLUMNS + ("F_N", "sigma_b_Pa"):
                expected = float(ref[column])
                assert float(row[column]) == pytest.approx(expected, rel=1e-9, abs=1e-15), (angle, model, column)
                assert float(ds[column].sel({ANGLE_KEY: angle, "model": model})) == pytest.approx(expected, rel=1e-9, abs=1e-15)
            assert row["converged"] == ref["converged"] == "true", (angle, model)
    # the pads carry the cargo: a larger angle takes more pad force (the wedge), a smaller one lets it slip further
    nonlinear = ds.sel(model="nonlinear")
    f_pad, slip = nonlinear["F_pad_N"].values, nonlinear["transverse_slip_m"].values
    assert f_pad[0] < f_pad[1] and slip[0] > slip[1]
    # the cradle limit judged on the nonlinear row: between the two pad forces, only the first angle complies
    limit = float(np.mean(f_pad))
    loose = DesignLimits(1e9, 1e12)
    judged = compliance(run.dataset, replace(loose, max_pad_force_N=limit)).sel(model="nonlinear")
    assert judged["complies"].values.tolist() == [True, False]
    np.testing.assert_allclose(judged["margin_F_pad_N"].values, 1.0 - f_pad / limit, rtol=1e-12)
    assert compliance(run.dataset, replace(loose, max_pad_force_N=2.0 * limit)).sel(model="nonlinear")["complies"].all()


def test_head_seas_rows_are_the_vertical_plane_alone(tmp_path):
    rows = evaluate_sea_state(seafast.load_case(None, {"sea_state.significant_height_m": 3.0}))
    assert [list(r) for r in rows] == [VERTICAL_KEYS, VERTICAL_KEYS]
    grid = _study("head", [{"key": ANGLE_KEY, "values": [40.0]}], {"sea_state.significant_height_m": 3.0})
    run_study(grid, tmp_path, execution=SERIAL)
    header = list(_csv(tmp_path / "study.csv")[0])
    assert header == [ANGLE_KEY, *CORE_COLUMNS, "uplift_per_hour", "warnings", "error"]


def test_a_cradle_part_that_raises_keeps_the_point(tmp_path):
    grid = _study("stiff", [{"key": ANGLE_KEY, "values": [40.0]}], BEAM | STIFF_WIRE, {"max_pad_force_N": 1.0e8})
    run = run_study(grid, tmp_path, execution=SERIAL)
    assert run.failed == 0
    rows = _csv(tmp_path / "study.csv")
    assert len(rows) == 2 and all(r["error"] == "" for r in rows)
    for r in rows:
        assert all(r[c] == "" for c in CRADLE_SUMMARY_COLUMNS)  # unknown, not zero
        assert r["converged"] == "false" and r["cradle_outcome"] == "error"
        assert r["cradle_error"].startswith("the cargo on its cradles: ")
        assert float(r["F_N"]) > 0.0  # the vertical plane kept
    vertical = evaluate_sea_state(seafast.load_case(None, {**BEAM, **STIFF_WIRE, ANGLE_KEY: 40.0}))
    assert float(rows[1]["F_N"]) == vertical[1]["F_N"]
    assert not bool(compliance(run.dataset).sel(model="nonlinear")["complies"].any())  # a raised cradle does not comply


def test_a_design_wave_that_did_not_converge_flags_the_nonlinear_row(monkeypatch):
    real = sea_state_study.cradle_sea_state

    def unconverged(analysis):
        cradle = real(analysis)
        assert cradle.design is not None
        return replace(cradle, design=replace(cradle.design, converged=False, residual=3.5e-4))

    monkeypatch.setattr(sea_state_study, "cradle_sea_state", unconverged)
    linear, nonlinear = evaluate_sea_state(seafast.load_case(None, {**BEAM, ANGLE_KEY: 40.0}))
    assert linear["converged"] and linear["cradle_converged"] and linear["cradle_message"] == ""
    assert nonlinear["converged"] is False and nonlinear["cradle_converged"] is False
    assert nonlinear["cradle_residual"] == 3.5e-4 and "did not converge (largest residual 0.00035)" in nonlinear["cradle_message"]
    assert math.isfinite(nonlinear["F_pad_N"])  # the estimate kept, flagged


def test_frictional_pads_add_seafast_seastates_friction_columns(tmp_path):
    base = {**BEAM, "seafastening.friction_coefficient": 0.8}
    grid = _study("friction", [{"key": ANGLE_KEY, "values": [35.0]}], base)
    run_study(grid, tmp_path / "study", execution=SERIAL)
    rows = _csv(tmp_path / "study" / "study.csv")
    header = list(rows[0])
    at = header.index("contact_preserved") + 1
    assert header[at : at + 7] == [*CRADLE_SUMMARY_COLUMNS, "pad_friction_utilisation", "pad_slip_m"]  # as seastate.csv
    reference = _seastate_csv(tmp_path, {**base, ANGLE_KEY: 35.0})
    linear, nonlinear = (next(r for r in rows if r["model"] == m) for m in ("linear", "nonlinear"))
    for column in (*CRADLE_SUMMARY_COLUMNS, "pad_friction_utilisation", "pad_slip_m"):
        assert linear[column] == reference["spectral"][column]  # the linear pads frictionless: no friction columns
        assert float(nonlinear[column]) == pytest.approx(float(reference["design_wave"][column]), rel=1e-9, abs=1e-15), column
    assert linear["pad_friction_utilisation"] == "" and 0.0 < float(nonlinear["pad_friction_utilisation"]) <= 1.0 + 1e-9
    assert nonlinear["converged"] == reference["design_wave"]["converged"]


def test_a_point_stored_without_its_cradles_is_recomputed(tmp_path):
    grid = _study("resume", [{"key": ANGLE_KEY, "values": [40.0]}], BEAM)
    first = run_study(grid, tmp_path, execution=SERIAL)
    store = tmp_path / "points.jsonl"
    lines = store.read_text(encoding="utf-8").splitlines()
    cradle_keys = {*CRADLE_SUMMARY_COLUMNS, "cradle_converged", "cradle_residual", "cradle_message"}
    stripped = []
    for line in lines:
        data = json.loads(line)
        if "rows" in data:
            data["rows"] = [{k: v for k, v in row.items() if k not in cradle_keys} for row in data["rows"]]
        stripped.append(json.dumps(data))
    store.write_text("\n".join(stripped) + "\n", encoding="utf-8")
    again = run_study(grid, tmp_path, execution=SERIAL)
    assert (first.computed, again.reused, again.computed) == (1, 0, 1)
    assert float(again.dataset["F_pad_N"].sel(model="nonlinear").squeeze()) == float(
        first.dataset["F_pad_N"].sel(model="nonlinear").squeeze()
    )
