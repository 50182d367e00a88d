"""A study's typed warnings per row (study.csv, study.nc, the store), counted once per kind; point messages named."""

from __future__ import annotations

import csv
import json
import logging
import re
import threading
from pathlib import Path

import pytest
import xarray as xr

from seafast.cli import main
from seafast.parallel.executor import ExecutionOptions
from seafast.studies.execution import evaluate_batch
from seafast.studies.messages import WARNING_KINDS, point_log, replay_point_messages
from seafast.studies.runner import run_study
from seafast.studies.store import point_store
from study_fakes import fake_warnings

FAKE = "study_fakes:fake_evaluate"
SERIAL = ExecutionOptions(workers=1, progress=False)
KEYS = ("seafastening.saddle_count", "seafastening.saddle_stiffness_N_per_m")


def _expected(small_grid, index: int, load_case: str, model: str) -> list[str]:
    case = small_grid.point_case(index)
    return [w.value for w in fake_warnings(case.seafastening.saddle_count, case.seafastening.saddle_stiffness_N_per_m, load_case, model)]


def test_each_rows_typed_warnings_reach_study_csv_and_study_nc(small_grid, tmp_path: Path):
    run = run_study(small_grid, tmp_path, evaluator=FAKE, execution=SERIAL)
    with open(tmp_path / "study.csv", newline="") as fh:
        rows = list(csv.DictReader(fh))
    assert len(rows) == 4 * small_grid.size
    for i, row in enumerate(rows):
        expected = _expected(small_grid, i // 4, row["load_case"], row["model"])
        assert row["warnings"] == ";".join(expected), (i, row)
    # 4 points lift off stiffly (4 and 5 saddles at 1.1e9 and 1.1e10 N/m), 4 are the softest (1.1e7 N/m)
    assert sum(1 for r in rows if "too_few_harmonics" in r["warnings"]) == 4
    assert sum(1 for r in rows if "rayleigh_fallback" in r["warnings"]) == 8  # both dynamic rows of 4 points
    assert run.warning_points == {"too_few_harmonics": 4, "rayleigh_fallback": 4}

    ds = xr.load_dataset(tmp_path / "study.nc")
    flag = ds["warning_flag"]
    assert flag.dims == (*KEYS, "load_case", "model", "warning") and flag.dtype == bool
    assert ds["warning"].values.tolist() == list(WARNING_KINDS)
    assert flag.attrs["units"] == "1" and "warning" in flag.attrs["long_name"]
    assert ds["warning"].attrs["units"] == "1" and "long_name" in ds["warning"].attrs
    stiff = flag.sel({KEYS[0]: [4, 5], KEYS[1]: [1.1e9, 1.1e10]}, method="nearest")
    assert bool(stiff.sel(load_case="dynamic", model="nonlinear", warning="too_few_harmonics").all())
    assert int(flag.sel(warning="too_few_harmonics").sum()) == 4
    assert not bool(flag.sel(load_case="static").any())  # still water: no damping, no harmonics
    soft = flag.isel({KEYS[1]: 0}).sel(load_case="dynamic", warning="rayleigh_fallback")
    assert bool(soft.all()) and int(flag.sel(warning="rayleigh_fallback").sum()) == 8
    assert not bool(flag.sel(warning=["harmonics_above_h_ignored", "quasi_statics_questionable"]).any())


def test_a_resumed_study_restores_the_warnings_of_the_points_stored_before(small_grid, tmp_path: Path):
    evaluated: list[int] = []

    def counting(case):
        from study_fakes import fake_evaluate

        evaluated.append(case.seafastening.saddle_count)
        return fake_evaluate(case)

    with point_store(tmp_path / "resumed", small_grid) as store:  # the run before the interruption
        store.append(evaluate_batch(small_grid, [0, 4, 10, 11, 15], FAKE))
    resumed = run_study(small_grid, tmp_path / "resumed", evaluator=counting, execution=SERIAL)
    assert resumed.reused == 5 and len(evaluated) == small_grid.size - 5
    reference = run_study(small_grid, tmp_path / "reference", evaluator=FAKE, execution=SERIAL)
    # the stored points carried 2 of the 4 too_few_harmonics (10, 11) and 2 of the 4 fallbacks (0, 4)
    assert resumed.warning_points == reference.warning_points == {"too_few_harmonics": 4, "rayleigh_fallback": 4}
    xr.testing.assert_identical(resumed.dataset["warning_flag"], reference.dataset["warning_flag"])
    assert (tmp_path / "resumed" / "study.csv").read_text() == (tmp_path / "reference" / "study.csv").read_text()


def test_a_point_stored_without_its_warnings_is_recomputed(small_grid, tmp_path: Path):
    with point_store(tmp_path, small_grid) as store:
        store.append(evaluate_batch(small_grid, [0, 1], FAKE))
    lines = (tmp_path / "points.jsonl").read_text().splitlines()
    old = json.loads(lines[0])
    for row in old["rows"]:
        del row["warnings"]  # as a store written before warnings were stored
    (tmp_path / "points.jsonl").write_text(json.dumps(old) + "\n" + lines[1] + "\n")
    with point_store(tmp_path, small_grid) as store:
        assert sorted(store.completed) == [1] and store.rejected == 1
    run = run_study(small_grid, tmp_path, evaluator=FAKE, execution=SERIAL)
    assert run.reused == 1 and run.computed == small_grid.size - 1
    assert bool(run.dataset["warning_flag"].isel({KEYS[0]: 0, KEYS[1]: 0}).sel(load_case="dynamic", warning="rayleigh_fallback").all())


def _study_command(tmp_path: Path, out: str, *extra: str) -> list[str]:
    # serial: worker processes would not see the evaluator's environment variable when they fork from a
    # forkserver another test started (the forked workers are tested through run_study below)
    return ["study", str(tmp_path / "small.yaml"), "-o", str(tmp_path / out), "--workers", "1", "--no-figures", *extra]


@pytest.fixture
def fake_study(small_study_file: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    monkeypatch.setenv("SEAFAST_STUDY_EVALUATOR", FAKE)
    return small_study_file.parent


def test_the_command_prints_one_count_per_warning_kind_and_no_point_messages(fake_study: Path, capsys):
    assert main(_study_command(fake_study, "out")) == 0
    err = capsys.readouterr().err
    assert "fake solver" not in err  # neither the notes nor the warnings of the points
    counts = [line for line in err.splitlines() if " of 16 points: " in line]
    too_few = (
        "seafast: warning: 4 of 16 points: too_few_harmonics (see the warnings column of study.csv): "
        "too few harmonics: the peak forces may move by more than solver.truncation_tolerance "
        "(leave solver.harmonics unset, or raise it / solver.max_harmonics)"
    )
    fallback = (
        "seafast: warning: 4 of 16 points: rayleigh_fallback (see the warnings column of study.csv): "
        "Rayleigh damping cannot give the first two modes model.damping_ratio; the fallback realises a ratio "
        "more than 10 % off in one of them (dynamic rows)"
    )
    assert counts == [too_few, fallback]
    # resumed: nothing recomputed, the same counts from the store
    assert main(_study_command(fake_study, "out")) == 0
    again = capsys.readouterr().err
    assert [line for line in again.splitlines() if " of 16 points: " in line] == counts
    assert "16 points: 0 computed, 16 reused" in again


def test_verbose_prints_each_points_messages_naming_the_point(fake_study: Path, capsys):
    assert main(["-v", *_study_command(fake_study, "verbose")]) == 0
    err = capsys.readouterr().err.splitlines()
    notes = [line for line in err if "fake solver:" in line]
    assert len(notes) == 16 + 4  # a note per point, a warning per stiff lift-off point
    # point 10 = (4 saddles, 1.1e9 N/m); its warning keeps its level and logger, prefixed with the point
    assert (
        "seafast: warning: point 10 (seafastening.saddle_count=4, seafastening.saddle_stiffness_N_per_m=1.1e+09): "
        "fake solver: H = 16 leaves 4 saddles at 1.1e+09 N/m unsettled"
    ) in err
    for line in notes:
        match = re.search(r"point (\d+) \(seafastening.saddle_count=(\d), seafastening.saddle_stiffness_N_per_m=([\d.e+]+)\): fake", line)
        assert match, line
        index, count, stiffness = int(match[1]), int(match[2]), float(match[3])
        assert (count, stiffness) == (2 + index // 4, pytest.approx(1.1e7 * 10.0 ** (index % 4), rel=1e-6))
        assert f"{count} saddles at {stiffness:g} N/m" in line  # the message is the point's own


@pytest.mark.parametrize("level", [logging.INFO, logging.DEBUG], ids=["default", "verbose"])
def test_forked_workers_print_no_point_message_and_verbose_ones_come_back_named(small_grid, tmp_path: Path, capsys, level: int):
    """Forked workers inherit the command's stderr handler: without the capture they would print every note."""
    from seafast.cli.console import command_logging

    options = ExecutionOptions(workers=2, batch_size=3, progress=False, start_method="fork")
    with command_logging(level):
        run = run_study(small_grid, tmp_path, evaluator=FAKE, execution=options)
    assert run.computed == small_grid.size and run.warning_points == {"too_few_harmonics": 4, "rayleigh_fallback": 4}
    notes = [line for line in capsys.readouterr().err.splitlines() if "fake solver:" in line]
    if level == logging.INFO:
        assert notes == []
    else:  # every point's note and warning, each named, in this process (whichever worker ran the point)
        assert len(notes) == 16 + 4 and all(re.search(r"point \d+ \(seafastening.saddle_count=\d, ", line) for line in notes)
        assert sum(line.startswith("seafast: warning: point ") for line in notes) == 4


def test_point_log_captures_per_thread_and_restores_the_package_logger():
    package = logging.getLogger("seafast")
    before = (list(package.handlers), package.propagate, package.level)
    note = logging.getLogger("seafast.tests.threads")
    barrier = threading.Barrier(3)
    captured: dict[str, list] = {}
    seen: list[str] = []

    class Collect(logging.Handler):
        def emit(self, record: logging.LogRecord) -> None:
            seen.append(record.getMessage())

    collect = Collect()
    package.addHandler(collect)
    package.setLevel(logging.INFO)

    def point(name: str, keep: bool) -> None:
        with point_log(keep) as messages:
            barrier.wait()  # every thread inside its capture at once
            note.info("%s evaluates", name)
            note.debug("%s detail", name)
            barrier.wait()
        captured[name] = list(messages)

    def bystander() -> None:
        barrier.wait()
        note.info("bystander logs")  # a thread evaluating no point: handled as before
        note.debug("bystander detail")  # below the package logger's own level: not handled
        barrier.wait()

    threads = [threading.Thread(target=point, args=("a", True)), threading.Thread(target=point, args=("b", False))]
    threads.append(threading.Thread(target=bystander))
    try:
        for t in threads:
            t.start()
        for t in threads:
            t.join(timeout=30)
        name = "seafast.tests.threads"
        assert captured["a"] == [(name, logging.INFO, "a evaluates"), (name, logging.DEBUG, "a detail")]
        assert captured["b"] == []
        assert seen == ["bystander logs"]
        assert (package.handlers, package.propagate, package.level) == ([*before[0], collect], before[1], logging.INFO)
        replay_point_messages("point 3 (x=1)", captured["a"])
        assert seen[-1] == "point 3 (x=1): a evaluates"  # the debug line stays below the level
    finally:
        package.removeHandler(collect)
        package.setLevel(before[2])


def test_the_command_shows_progress_lines_off_a_terminal(fake_study: Path, capsys, monkeypatch: pytest.MonkeyPatch):
    import seafast.parallel.progress

    monkeypatch.setattr(seafast.parallel.progress, "PROGRESS_MIN_INTERVAL_S", 0.0)  # the test's points take milliseconds
    command = ["study", str(fake_study / "small.yaml"), "--workers", "1", "--batch-size", "1", "--no-figures"]
    assert main([*command, "-o", str(fake_study / "plain")]) == 0
    lines = [line for line in capsys.readouterr().err.splitlines() if line.startswith("study small: ")]
    assert len(lines) == 16  # 5 % of 16 points is one point
    assert re.fullmatch(r"study small: 8/16 points \(50 %\), \d+ s elapsed, ~\d+ s left", lines[7])
    assert re.fullmatch(r"study small: 16/16 points \(100 %\), \d+ s elapsed", lines[-1])
    assert main([*command, "-o", str(fake_study / "quiet"), "-q"]) == 0
    assert "study small: " not in capsys.readouterr().err
