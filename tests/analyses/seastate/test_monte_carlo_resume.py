"""Resumable execution: a Monte Carlo run killed with SIGKILL mid-run resumes, losing and repeating nothing;
Dask gives the serial records."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import numpy as np

import seafast
from seafast.analyses.seastate.monte_carlo import STORE_DIRECTORY, build_plan
from seafast.analyses.seastate.realisation import evaluate_realisation
from seafast.parallel.store import DICT_RECORDS

OVERRIDES = {"sea_state.significant_height_m": 3.0, "sea_state.duration_s": 900.0, "sea_state.realisations": 12}

SCRIPT = textwrap.dedent(
    f"""
    import json, sys
    import seafast
    from seafast.analyses.seastate.monte_carlo import run_monte_carlo

    def main():
        case = seafast.load_case(None, {OVERRIDES!r})
        result = run_monte_carlo(case, sys.argv[1], workers=2, progress=False)
        print(json.dumps({{"reused": result.reused, "converged": result.nonlinear.converged}}))

    if __name__ == "__main__":
        main()
    """
)


def _stored(out: Path) -> list[int]:
    path = out / STORE_DIRECTORY / DICT_RECORDS.records
    if not path.exists():
        return []
    return [json.loads(line)["index"] for line in path.read_bytes().split(b"\n")[:-1]]


def test_sigkill_then_resume_loses_and_repeats_nothing(tmp_path: Path):
    script = tmp_path / "run_mc.py"
    script.write_text(SCRIPT, encoding="utf-8")
    out = tmp_path / "out"
    env = {**os.environ, "OMP_NUM_THREADS": "1", "OPENBLAS_NUM_THREADS": "1"}
    proc = subprocess.Popen([sys.executable, str(script), str(out)], env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    deadline = time.monotonic() + 240
    while len(_stored(out)) < 3:
        assert proc.poll() is None, proc.communicate()
        assert time.monotonic() < deadline, "the run did not start"
        time.sleep(0.02)
    proc.send_signal(signal.SIGKILL)
    proc.wait(timeout=30)
    time.sleep(0.5)  # orphaned workers notice their parent is gone and exit
    after_kill = _stored(out)
    assert 3 <= len(after_kill) < 12, "kill came too late to test a resume"

    done = subprocess.run([sys.executable, str(script), str(out)], env=env, capture_output=True, text=True, timeout=600, check=False)
    assert done.returncode == 0, done.stderr
    summary = json.loads(done.stdout.strip().splitlines()[-1])
    assert summary["converged"]
    stored = _stored(out)
    assert sorted(stored) == list(range(12))  # nothing lost, nothing duplicated
    assert stored[: len(after_kill)] == after_kill  # the first run's records kept as written
    assert summary["reused"] == len(after_kill)  # finished realisations were not recomputed

    # the stored records equal an uninterrupted in-process evaluation
    plan = build_plan(seafast.load_case(None, OVERRIDES))
    lines = {
        json.loads(line)["index"]: json.loads(line)["record"]
        for line in (out / STORE_DIRECTORY / DICT_RECORDS.records).read_text().splitlines()
    }
    for index in (after_kill[0], stored[-1]):
        record, _ = evaluate_realisation(plan, index)
        for model in ("linear", "nonlinear"):
            assert lines[index][model] == record[model]


def test_dask_scheduler_gives_the_serial_records(tmp_path: Path):
    from distributed import LocalCluster

    from seafast.analyses.seastate.monte_carlo import run_monte_carlo

    case = seafast.load_case(None, {"sea_state.significant_height_m": 3.0, "sea_state.duration_s": 600.0, "sea_state.realisations": 3})
    serial = run_monte_carlo(case, tmp_path / "serial", workers=1, progress=False)
    with LocalCluster(processes=True, n_workers=1, threads_per_worker=1, host="127.0.0.1", dashboard_address=None) as cluster:
        dask = run_monte_carlo(case, tmp_path / "dask", scheduler=cluster.scheduler_address, progress=False)
    for model in ("linear", "nonlinear"):
        for q, values in getattr(serial, model).maxima.items():
            assert np.array_equal(values, getattr(dask, model).maxima[q]), (model, q)
