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
from seafast.studies.assembly import CORE_COLUMNS, assemble_dataset
from seafast.studies.limits import DesignLimits, compliance
from seafast.studies.runner import run_study
from seafast.studies.spec import StudyError, build_grid, load_study_spec

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


def test_cradle_limits_judge_the_points_off_head_seas(mixed):
    """A pad-force limit between the beam sea's still-water and wave pad forces fails the point at 90 deg (its
    margin 1 - F_pad / limit), leaves those at 180 deg as they were, and a point whose cradle solve raised never
    complies; a limit above every pad force changes no verdict."""
    _, run = mixed
    ds = run.dataset
    plain = compliance(ds, DesignLimits())
    beam = {"wave.heading_deg": 90.0, "seafastening.lashing.stiffness_N_per_m": OK_WIRE_N_PER_M}
    wave_pad = float(ds["F_pad_N"].sel(beam).sel(load_case="dynamic", model="nonlinear"))
    still_pad = float(ds["F_pad_N"].sel(beam).sel(load_case="static", model="nonlinear"))
    assert 1.1 * still_pad < wave_pad  # the wave adds to the pads' still-water force: a limit fits between
    limit = 0.5 * (still_pad + wave_pad)
    judged = compliance(ds, DesignLimits(max_pad_force_N=limit))
    nl = judged.sel(model="nonlinear")
    assert float(nl["margin_F_pad_N"].sel(beam)) == pytest.approx(1.0 - wave_pad / limit, rel=1e-12)
    assert float(nl["margin"].sel(beam)) == pytest.approx(1.0 - wave_pad / limit, rel=1e-12)  # the smallest margin
    assert bool(plain["complies"].sel(beam).sel(model="nonlinear")) and not bool(nl["complies"].sel(beam))
    head = {"wave.heading_deg": 180.0}
    xr.testing.assert_equal(judged["complies"].sel(head), plain["complies"].sel(head))
    assert np.isnan(judged["margin_F_pad_N"].sel(head).values).all()
    failed = {"wave.heading_deg": 90.0, "seafastening.lashing.stiffness_N_per_m": STIFF_WIRE_N_PER_M}
    assert not judged["complies"].sel(failed).any()  # the linear row too: its cradle solve raised
    above = compliance(ds, DesignLimits(max_pad_force_N=2.0 * wave_pad, max_transverse_slip_m=1.0, max_lashing_tension_N=1e9))
    beam_and_head = above["complies"].sel({"seafastening.lashing.stiffness_N_per_m": OK_WIRE_N_PER_M})
    xr.testing.assert_equal(beam_and_head, plain["complies"].sel({"seafastening.lashing.stiffness_N_per_m": OK_WIRE_N_PER_M}))


def test_cradle_limits_in_the_study_file(tmp_path: Path):
    text = MIXED + "limits:\n  max_pad_force_N: 6.0e+6\n  max_transverse_slip_m: 0.01\n"
    grid = _grid(tmp_path, text)
    limits = DesignLimits.from_spec(grid.spec.limits)
    assert (limits.max_pad_force_N, limits.max_lashing_tension_N, limits.max_transverse_slip_m) == (6.0e6, None, 0.01)
    attrs = assemble_dataset(grid, {}).attrs
    assert attrs["max_pad_force_N"] == 6.0e6 and "max_lashing_tension_N" not in attrs
    assert DesignLimits.from_attrs(attrs) == limits
    bad = MIXED + "limits:\n  max_lashing_tension_N: -2.0e+5\n"
    with pytest.raises(StudyError, match=r"limits\.max_lashing_tension_N = -200000\.0: .*greater than 0"):
        _grid(tmp_path, bad)
    with pytest.raises(StudyError, match=r"allowed: .*max_pad_force_N"):
        _grid(tmp_path, MIXED + "limits:\n  max_pad_N: 1.0\n")
