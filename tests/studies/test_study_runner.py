"""Study execution: back-ends agree, failures are recorded, the store resumes, outputs follow docs/interface.md."""

from __future__ import annotations

import csv
import json
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from seafast.parallel.executor import ExecutionOptions
from seafast.studies.assembly import CORE_COLUMNS
from seafast.studies.execution import evaluate_batch
from seafast.studies.runner import run_study
from seafast.studies.spec import StudyError, build_grid, load_study_spec
from seafast.studies.store import point_store

FAKE = "study_fakes:fake_evaluate"
FAILING = "study_fakes:failing_evaluate"


def _results(ds: xr.Dataset) -> xr.Dataset:
    return ds.drop_vars("eval_seconds")


def test_serial_processes_and_dask_agree(small_grid, tmp_path: Path):
    from distributed import LocalCluster

    serial = run_study(small_grid, tmp_path / "serial", evaluator=FAKE, execution=ExecutionOptions(workers=1, progress=False))
    processes = run_study(
        small_grid, tmp_path / "processes", evaluator=FAKE, execution=ExecutionOptions(workers=2, batch_size=3, progress=False)
    )
    with LocalCluster(processes=True, n_workers=2, threads_per_worker=1, host="127.0.0.1", dashboard_address=None) as cluster:
        dask = run_study(
            small_grid, tmp_path / "dask", evaluator=FAKE, execution=ExecutionOptions(scheduler=cluster.scheduler_address, progress=False)
        )
    assert (serial.mode, processes.mode, dask.mode) == ("serial", "processes", "dask")
    assert serial.computed == processes.computed == dask.computed == small_grid.size
    xr.testing.assert_identical(_results(serial.dataset), _results(processes.dataset))
    xr.testing.assert_identical(_results(serial.dataset), _results(dask.dataset))
    on_disk = [xr.load_dataset(tmp_path / d / "study.nc") for d in ("serial", "processes", "dask")]
    xr.testing.assert_identical(_results(on_disk[0]), _results(on_disk[1]))
    xr.testing.assert_identical(_results(on_disk[0]), _results(on_disk[2]))
    texts = [(tmp_path / d / "study.csv").read_text() for d in ("serial", "processes", "dask")]
    assert texts[0] == texts[1] == texts[2]
    for method in ("spawn", "forkserver"):
        other = run_study(
            small_grid,
            tmp_path / method,
            evaluator=FAKE,
            execution=ExecutionOptions(workers=2, batch_size=5, progress=False, start_method=method),
        )
        xr.testing.assert_identical(_results(serial.dataset), _results(other.dataset))
        assert (tmp_path / method / "study.csv").read_text() == texts[0]


def test_dataset_layout_and_attributes(small_grid, tmp_path: Path):
    run = run_study(small_grid, tmp_path, evaluator=FAKE, execution=ExecutionOptions(workers=1, progress=False))
    ds = xr.load_dataset(tmp_path / "study.nc")
    assert ds["F_N"].dims == ("seafastening.saddle_count", "seafastening.saddle_stiffness_N_per_m", "load_case", "model")
    assert ds["load_case"].values.tolist() == ["static", "dynamic"]
    assert ds["model"].values.tolist() == ["linear", "nonlinear"]
    assert ds["F_N"].attrs["units"] == "N" and ds["sigma_b_Pa"].attrs["units"] == "Pa" and ds["M_b_Nm"].attrs["units"] == "N m"
    assert ds["seafastening.saddle_stiffness_N_per_m"].attrs["units"] == "N/m"
    assert ds["seafastening.saddle_stiffness_N_per_m"].attrs["scale"] == "log"
    assert ds["seafastening.saddle_count"].attrs["base_value"] == 3
    for name in ("u_c_m", "u_s_m", "u_d_m", "F_N", "M_b_Nm", "sigma_b_Pa", "converged", "contact_preserved", "residual_norm", "iterations"):
        assert "long_name" in ds[name].attrs and "units" in ds[name].attrs
    assert ds["contact_preserved"].dtype == bool
    point = ds.sel({"seafastening.saddle_count": 3}).isel({"seafastening.saddle_stiffness_N_per_m": 1})
    case = small_grid.point_case(5)
    from study_fakes import fake_evaluate

    expected = {(r["load_case"], r["model"]): r for r in fake_evaluate(case)}
    assert float(point["F_N"].sel(load_case="dynamic", model="nonlinear")) == expected[("dynamic", "nonlinear")]["F_N"]
    assert run.points_per_second > 0


def test_csv_columns_follow_the_interface(small_grid, tmp_path: Path):
    run_study(small_grid, tmp_path, evaluator=FAKE, execution=ExecutionOptions(workers=1, progress=False))
    with open(tmp_path / "study.csv", newline="") as fh:
        rows = list(csv.reader(fh))
    header = rows[0]
    keys = ["seafastening.saddle_count", "seafastening.saddle_stiffness_N_per_m"]
    fixed = "load_case,model,u_c_m,u_s_m,u_d_m,F_N,M_b_Nm,sigma_b_Pa,converged".split(",")
    assert header[:2] == keys
    assert header[2:11] == fixed
    assert header[11] == "contact_preserved"
    assert header[12:] == ["residual_norm", "iterations", "warnings", "error"]
    assert tuple(header[2:12]) == CORE_COLUMNS
    assert len(rows) - 1 == small_grid.size * 4  # one row per point, load case and model
    assert {r[11] for r in rows[1:]} == {"true", "false"}
    first = rows[1]
    assert first[:4] == ["2", "11000000.0", "static", "linear"]


def test_failing_point_is_recorded_and_the_others_complete(small_grid, tmp_path: Path):
    run = run_study(small_grid, tmp_path, evaluator=FAILING, execution=ExecutionOptions(workers=2, progress=False))
    ds = run.dataset
    errors = ds["error"]
    five = errors.sel({"seafastening.saddle_count": 5}).values
    assert all(e.startswith("RuntimeError: solver diverged for 5 saddles") for e in five)
    assert "\n" not in five[0]
    assert (errors.sel({"seafastening.saddle_count": [2, 3, 4]}) == "").all()
    assert np.isnan(ds["F_N"].sel({"seafastening.saddle_count": 5})).all()
    assert np.isfinite(ds["F_N"].sel({"seafastening.saddle_count": [2, 3, 4]})).all()
    assert run.failed == 4 and ds.attrs["failed_points"] == 4
    text = (tmp_path / "study.csv").read_text()
    assert text.count("RuntimeError: solver diverged") == 4 * 4


def test_not_converged_is_recorded_not_an_error(tmp_path: Path):
    spec, directory = load_study_spec("saddles")
    grid = build_grid(spec, directory)
    records = evaluate_batch(grid, [80], FAILING)  # 6 saddles
    assert records[0].error == ""
    assert [r["converged"] for r in records[0].rows if r["model"] == "nonlinear"] == [False, False]


def test_invalid_point_combination_is_an_error_record():
    spec_text = {"name": "t", "axes": [{"key": "cargo.wall_thickness_m", "values": [0.05, 5.0]}]}
    from seafast.studies.spec import study_spec_from_mapping

    grid = build_grid(study_spec_from_mapping(spec_text))
    ok, bad = evaluate_batch(grid, [0, 1], FAKE)
    assert ok.error == "" and len(ok.rows) == 4
    assert bad.error.startswith("CaseError:") and "wall_thickness_m" in bad.error and bad.rows == ()


def test_resume_skips_finished_points_and_drops_a_torn_line(small_grid, tmp_path: Path, monkeypatch):
    calls: list[int] = []

    def counting(case):
        from study_fakes import fake_evaluate

        calls.append(1)
        return fake_evaluate(case)

    with point_store(tmp_path, small_grid) as store:
        store.append(evaluate_batch(small_grid, list(range(7)), FAKE))
    with open(tmp_path / "points.jsonl", "ab") as fh:
        fh.write(b'{"study": "' + small_grid.fingerprint().encode() + b'", "index": 7, "rows": [{"load_')
    run = run_study(small_grid, tmp_path, evaluator=counting, execution=ExecutionOptions(workers=1, progress=False))
    assert run.reused == 7 and run.computed == small_grid.size - 7 and len(calls) == small_grid.size - 7
    lines = (tmp_path / "points.jsonl").read_text().splitlines()
    indices = [json.loads(line)["index"] for line in lines]
    assert sorted(indices) == list(range(small_grid.size))  # none lost, none duplicated, torn line gone
    reference = run_study(small_grid, tmp_path / "ref", evaluator=FAKE, execution=ExecutionOptions(workers=1, progress=False))
    xr.testing.assert_identical(_results(run.dataset), _results(reference.dataset))
    again = run_study(small_grid, tmp_path, evaluator=counting, execution=ExecutionOptions(workers=1, progress=False))
    assert again.computed == 0 and again.reused == small_grid.size


def test_directory_of_another_study_is_refused(small_grid, tmp_path: Path):
    run_study(small_grid, tmp_path, evaluator=FAKE, execution=ExecutionOptions(workers=1, progress=False))
    other = build_grid(small_grid.spec, None, {"wave.amplitude_m": 1.0})
    with pytest.raises(StudyError, match="different study"):
        run_study(other, tmp_path, evaluator=FAKE, execution=ExecutionOptions(workers=1, progress=False))


def test_the_store_keeps_its_format_and_resumes_a_directory_written_before(small_grid, tmp_path: Path):
    first = run_study(small_grid, tmp_path / "now", evaluator=FAKE, execution=ExecutionOptions(workers=1, progress=False))
    lines = (tmp_path / "now" / "points.jsonl").read_text().splitlines()
    fingerprint = small_grid.fingerprint()
    assert [list(json.loads(line)) for line in lines] == [["study", "index", "rows", "error", "seconds"]] * small_grid.size
    assert lines[0].startswith('{"study":"' + fingerprint + '","index":0,"rows":[{"load_case":"static","model":"linear",')
    # a directory as an earlier seafast wrote it: the manifest's fingerprint after the description
    old = tmp_path / "old"
    old.mkdir()
    (old / "study.json").write_text(json.dumps({**small_grid.manifest(), "fingerprint": fingerprint}, indent=1))
    (old / "points.jsonl").write_text("\n".join(lines) + "\n")
    resumed = run_study(small_grid, old, evaluator=FAKE, execution=ExecutionOptions(workers=1, progress=False))
    assert resumed.reused == small_grid.size and resumed.computed == 0
    assert (old / "study.csv").read_text() == (tmp_path / "now" / "study.csv").read_text()
    xr.testing.assert_identical(_results(resumed.dataset), _results(first.dataset))


def test_an_unreachable_scheduler_is_a_study_error(small_grid, tmp_path: Path):
    with pytest.raises(StudyError, match="--scheduler nope://host:8786: cannot connect to a Dask scheduler"):
        run_study(small_grid, tmp_path, evaluator=FAKE, execution=ExecutionOptions(scheduler="nope://host:8786", progress=False))


def test_real_points_do_not_depend_on_the_back_end_or_the_evaluation_order(tmp_path: Path):
    # each point is a pure function of its case (no warm start from a neighbour; caches hold
    # inputs, not solutions): serial, forked workers in another order, and a resume after a
    # partial run give the same bytes in study.csv
    from seafast.studies.spec import study_spec_from_mapping

    spec = study_spec_from_mapping(
        {
            "name": "order",
            "axes": [
                {"key": "seafastening.saddle_count", "values": [2, 3]},
                {"key": "seafastening.saddle_stiffness_N_per_m", "values": [1.1e7, 1.786154413e9, 1.1e10]},
            ],
        }
    )
    grid = build_grid(spec)
    serial = run_study(grid, tmp_path / "serial", execution=ExecutionOptions(workers=1, progress=False))
    assert serial.failed == 0
    run_study(grid, tmp_path / "forked", execution=ExecutionOptions(workers=2, batch_size=1, progress=False))
    with point_store(tmp_path / "resumed", grid) as store:  # a partial run, points in reverse order
        store.append(evaluate_batch(grid, [5, 3, 1]))
    resumed = run_study(grid, tmp_path / "resumed", execution=ExecutionOptions(workers=1, progress=False))
    assert resumed.reused == 3 and resumed.computed == 3
    text = (tmp_path / "serial" / "study.csv").read_text()
    assert (tmp_path / "forked" / "study.csv").read_text() == text
    assert (tmp_path / "resumed" / "study.csv").read_text() == text
    assert float(serial.dataset["F_N"].sel(load_case="dynamic", model="nonlinear").max()) > 5e6  # real forces


def test_a_study_process_shares_one_vessel_cache_with_the_points_it_evaluates(small_grid):
    """The evaluator finds the process's vessel cache (so the pipeline's and the sea-state analysis'
    ``vessel_excitation(case)`` reuse one vessel across points), the same in every batch; outside a batch
    nothing is shared."""
    from seafast.excitation.vessel import VesselCache, shared_vessel_cache
    from seafast.model.cache import ModelCache, shared_model_cache
    from study_fakes import fake_evaluate

    seen, models = [], []

    def evaluate(case):
        seen.append(shared_vessel_cache())
        models.append(shared_model_cache())
        return fake_evaluate(case)

    evaluate_batch(small_grid, [0, 1], evaluate)
    evaluate_batch(small_grid, [2], evaluate)
    assert len(seen) == 3 and isinstance(seen[0], VesselCache) and all(cache is seen[0] for cache in seen)
    assert isinstance(models[0], ModelCache) and all(cache is models[0] for cache in models)  # the cargo meshes too
    assert shared_vessel_cache() is None and shared_model_cache() is None
