"""A study killed with SIGKILL mid-run resumes on the same command, losing and repeating nothing."""

from __future__ import annotations

import csv
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

from seafast.studies.spec import build_grid, load_study_spec

HERE = Path(__file__).resolve().parent
STUDY = """\
name: killable
axes:
  - key: seafastening.saddle_count
    values: [2, 3, 4]
  - key: seafastening.saddle_stiffness_N_per_m
    start: 1.1e+7
    stop: 1.1e+10
    num: 12
    scale: log
"""


def _command(study: Path, out: Path, workers: int = 2) -> list[str]:
    return [
        sys.executable,
        "-m",
        "seafast.cli.study",
        str(study),
        "-o",
        str(out),
        "--workers",
        str(workers),
        "--batch-size",
        "2",
        "--no-progress",
        "--no-figures",
        "-q",
    ]


def _env(log: Path, sleep_s: float) -> dict[str, str]:
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join([str(HERE), env.get("PYTHONPATH", "")])
    env["SEAFAST_STUDY_EVALUATOR"] = "study_fakes:fake_evaluate"
    env["SEAFAST_FAKE_EVAL_LOG"] = str(log)
    env["SEAFAST_FAKE_EVAL_SLEEP_S"] = str(sleep_s)
    return env


def _stored_indices(out: Path) -> list[int]:
    path = out / "points.jsonl"
    if not path.exists():
        return []
    indices = []
    for line in path.read_bytes().split(b"\n")[:-1]:
        indices.append(json.loads(line)["index"])
    return indices


def _evaluated_keys(log: Path) -> list[str]:
    if not log.exists():
        return []
    return [line.split(" ", 1)[1] for line in log.read_text().splitlines()]


def _key_of(grid, index: int) -> str:
    case = grid.point_case(index)
    return f"{case.seafastening.saddle_count} {case.seafastening.saddle_stiffness_N_per_m!r}"


def test_sigkill_then_resume_equals_an_uninterrupted_run(tmp_path: Path):
    study = tmp_path / "killable.yaml"
    study.write_text(STUDY, encoding="utf-8")
    grid = build_grid(*load_study_spec(study))
    out = tmp_path / "out"
    first_log, second_log = tmp_path / "first.log", tmp_path / "second.log"

    proc = subprocess.Popen(_command(study, out), env=_env(first_log, 0.08), stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    deadline = time.monotonic() + 60
    while len(_stored_indices(out)) < 8:
        assert proc.poll() is None, proc.communicate()
        assert time.monotonic() < deadline, "the study did not start"
        time.sleep(0.02)
    proc.send_signal(signal.SIGKILL)
    proc.wait(timeout=30)
    time.sleep(0.3)  # let orphaned workers notice and exit
    stored_after_kill = _stored_indices(out)
    assert 8 <= len(stored_after_kill) < grid.size, "kill came too late to test a resume"
    assert not (out / "study.csv").exists()

    done = subprocess.run(_command(study, out), env=_env(second_log, 0.0), capture_output=True, text=True, timeout=120, check=False)
    assert done.returncode == 0, done.stderr

    stored = _stored_indices(out)
    assert sorted(stored) == list(range(grid.size))  # nothing lost, nothing duplicated
    resumed_keys = sorted(_evaluated_keys(second_log))
    expected_keys = sorted(_key_of(grid, i) for i in range(grid.size) if i not in set(stored_after_kill))
    assert resumed_keys == expected_keys  # finished points were not recomputed

    reference = tmp_path / "reference"
    ref = subprocess.run(
        _command(study, reference, workers=1),
        env=_env(tmp_path / "ref.log", 0.0),
        capture_output=True,
        text=True,
        timeout=120,
        check=False,  # the return code is asserted with the run's messages
    )
    assert ref.returncode == 0, ref.stderr
    assert (out / "study.csv").read_text() == (reference / "study.csv").read_text()
    # ... warnings included: the points stored before the kill keep theirs (fake: 12 soft points, 4 stiff ones)
    with open(out / "study.csv", newline="") as fh:
        rows = list(csv.DictReader(fh))
    warned = {int(i) // 4 for i, r in enumerate(rows) if r["warnings"]}
    assert len(warned) == 16 and warned & set(stored_after_kill), "no stored point carried a warning"
    assert (out / "compliance.csv").read_text() == (reference / "compliance.csv").read_text()
    assert (out / "ranking.csv").read_text() == (reference / "ranking.csv").read_text()
