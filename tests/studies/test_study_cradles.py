"""Studies off head seas record the cargo on its cradles (docs/studies.md, the cargo on its cradles)."""

from __future__ import annotations

import csv
import math
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from seafast.analyses.run import run_case
from seafast.config.schema import Case
from seafast.parallel.executor import ExecutionOptions
from seafast.results.cradle import CRADLE_SUMMARY_COLUMNS
from seafast.studies.assembly import CORE_COLUMNS
from seafast.studies.runner import run_study
from seafast.studies.spec import build_grid, load_study_spec

SERIAL = ExecutionOptions(workers=1, progress=False)
OK_WIRE_N_PER_M, STIFF_WIRE_N_PER_M = 37500.0, 1.0e10  # the base case's wires; wires stiffer than the saddles (no pads left)

# two headings (beam and head seas) by two lashing stiffnesses: the stiff wires leave the pads no stiffness, so the
# cradle solve raises at 90 deg (the vertical plane alone at 180 deg does not build the cradles)
MIXED = f"""\
name: cradles
set:
  solver.harmonics: 16
axes:
  - key: wave.heading_deg
    values: [90.0, 180.0]
  - key: seafastening.lashing.stiffness_N_per_m
    values: [{OK_WIRE_N_PER_M}, {STIFF_WIRE_N_PER_M}]
"""

HEAD_SEAS = """\
name: head
set:
  solver.harmonics: 16
axes:
  - key: seafastening.saddle_stiffness_N_per_m
    values: [1.1e+9, 2.0e+9]
"""


def vertical_plane(case: Case) -> list[dict]:
    """What a study point recorded before the cradles: the vertical plane at every heading."""
    return run_case(case, cradles=False).summary


def _grid(tmp_path: Path, text: str):
    path = tmp_path / "study.yaml"
    path.write_text(text, encoding="utf-8")
    spec, directory = load_study_spec(path)
    return build_grid(spec, directory)


def _csv(path: Path) -> list[dict[str, str]]:
    with open(path, newline="", encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


@pytest.fixture(scope="module")
def mixed(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("mixed")
    grid = _grid(tmp, MIXED)
    return grid, run_study(grid, tmp / "out", execution=SERIAL)


def test_points_off_head_seas_record_the_run_s_cradle_columns(mixed):
    """At 90 deg every row holds the five columns, each the value `seafast run` gives the point (repr exact in
    study.csv, exact in study.nc); at 180 deg, in a study that mixes headings, they are empty / NaN."""
    grid, run = mixed
    header = run.files["csv"].read_text(encoding="utf-8").splitlines()[0].split(",")
    start = header.index(CORE_COLUMNS[-1]) + 1
    assert tuple(header[start : start + 5]) == CRADLE_SUMMARY_COLUMNS  # right after contact_preserved
    rows = _csv(run.files["csv"])
    ds = run.dataset
    expected = {(r["load_case"], r["model"]): r for r in run_case(grid.point_case(0)).summary}  # 90 deg, the base wires
    for row in rows:
        at_90 = float(row["wave.heading_deg"]) == 90.0 and float(row["seafastening.lashing.stiffness_N_per_m"]) == OK_WIRE_N_PER_M
        if not at_90:
            continue
        want = expected[(row["load_case"], row["model"])]
        sel = ds.sel({"wave.heading_deg": 90.0, "seafastening.lashing.stiffness_N_per_m": OK_WIRE_N_PER_M}).sel(
            load_case=row["load_case"], model=row["model"]
        )
        for key in CRADLE_SUMMARY_COLUMNS:
            assert float(row[key]) == want[key] == float(sel[key]), key
        assert row["cradle_outcome"] == want["cradle_outcome"] == "converged" and row["converged"] == "true"
    head = [r for r in rows if float(r["wave.heading_deg"]) == 180.0]
    assert len(head) == 8 and all(r[k] == "" for r in head for k in (*CRADLE_SUMMARY_COLUMNS, "cradle_outcome"))
    assert np.isnan(ds["F_pad_N"].sel({"wave.heading_deg": 180.0}).values).all()
    # the physics the columns carry: still water is the same at every heading, the wave moves the cargo across
    beam = ds.sel({"wave.heading_deg": 90.0, "seafastening.lashing.stiffness_N_per_m": OK_WIRE_N_PER_M})
    static, dynamic = beam.sel(load_case="static"), beam.sel(load_case="dynamic")
    assert (static["transverse_slip_m"] < 1e-9).all() and (dynamic["transverse_slip_m"] > 1e-4).all()
    assert (dynamic["F_pad_N"] > static["F_pad_N"]).all() and (static["F_pad_N"] > 1e6).all()


def test_the_columns_are_labelled_in_study_nc(mixed):
    _, run = mixed
    on_disk = xr.load_dataset(run.files["netcdf"])
    units = {"F_pad_N": "N", "F_stopper_N": "N", "lashing_tension_max_N": "N", "lashing_tension_min_N": "N", "transverse_slip_m": "m"}
    for key, unit in units.items():
        assert on_disk[key].attrs["units"] == unit and on_disk[key].attrs["long_name"] != key
        assert on_disk[key].dims == ("wave.heading_deg", "seafastening.lashing.stiffness_N_per_m", "load_case", "model")
    assert "pad force" in on_disk["F_pad_N"].attrs["long_name"]


def test_a_point_whose_cradle_solve_fails_keeps_its_vertical_plane_and_its_reason(mixed):
    grid, run = mixed
    assert run.failed == 0 and run.computed == 4  # the study went on
    rows = [
        r
        for r in _csv(run.files["csv"])
        if float(r["wave.heading_deg"]) == 90.0 and float(r["seafastening.lashing.stiffness_N_per_m"]) == STIFF_WIRE_N_PER_M
    ]
    vertical = {(r["load_case"], r["model"]): r for r in vertical_plane(grid.point_case(1))}
    assert len(rows) == 4
    for row in rows:
        assert row["converged"] == "false" and row["cradle_converged"] == "false" and row["cradle_outcome"] == "error"
        assert "seafastening.saddle_stiffness_N_per_m" in row["cradle_error"] and "lashing" in row["cradle_error"]
        assert all(row[k] == "" for k in CRADLE_SUMMARY_COLUMNS)
        assert float(row["F_N"]) == vertical[(row["load_case"], row["model"])]["F_N"]  # the vertical plane kept
        assert row["error"] == ""


def test_a_head_seas_study_writes_today_s_files(tmp_path: Path):
    """Head seas: study.csv byte for byte, and study.nc's variables, as a study of the vertical plane alone."""
    grid = _grid(tmp_path, HEAD_SEAS)
    now = run_study(grid, tmp_path / "now", execution=SERIAL)
    before = run_study(grid, tmp_path / "before", evaluator=vertical_plane, execution=SERIAL)
    assert now.files["csv"].read_bytes() == before.files["csv"].read_bytes()
    assert not any(k in now.dataset for k in (*CRADLE_SUMMARY_COLUMNS, "cradle_converged"))
    disk = [xr.load_dataset(r.files["netcdf"]).drop_vars("eval_seconds") for r in (now, before)]
    xr.testing.assert_identical(disk[0], disk[1])


def test_a_store_of_the_vertical_plane_resumes_with_the_cradles(mixed, tmp_path: Path):
    """A store written when studies recorded the vertical plane alone: its points at 90 deg are recomputed with
    the cradles, those at 180 deg reused; the files are a fresh study's."""
    grid, fresh = mixed
    out = tmp_path / "old"
    old = run_study(grid, out, evaluator=vertical_plane, execution=SERIAL)
    assert "F_pad_N" not in old.dataset
    resumed = run_study(grid, out, execution=SERIAL)
    assert (resumed.reused, resumed.computed) == (2, 2)
    assert resumed.files["csv"].read_bytes() == fresh.files["csv"].read_bytes()
    again = run_study(grid, out, execution=SERIAL)
    assert (again.reused, again.computed) == (4, 0)
    assert not math.isnan(float(again.dataset["F_pad_N"].isel({"wave.heading_deg": 0}).max()))
