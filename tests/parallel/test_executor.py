"""The executor: serial = local processes (fork, forkserver, spawn) = Dask; forked workers start warm; every
worker runs one BLAS thread and exits with its parent; the start-method policy and the batch plan."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import textwrap
import threading
import time
from pathlib import Path

import pytest
from executor_tasks import blas_threads, pid_of_items, sleep_items, solve_items
from threadpoolctl import threadpool_limits

from seafast.parallel.errors import ParallelError
from seafast.parallel.executor import START_METHODS, ExecutionOptions, map_batches, plan_batches

HERE = Path(__file__).resolve().parent


def _flat(results) -> list:
    return sorted(item for batch in results for item in batch)


def test_serial_processes_and_dask_give_the_same_results():
    from distributed import LocalCluster

    batches = plan_batches(list(range(12)), 2, 3)
    serial = _flat(map_batches(solve_items, 7, batches, ExecutionOptions(workers=1)))
    assert [i for i, _ in serial] == list(range(12))
    for method in START_METHODS:
        local = _flat(map_batches(solve_items, 7, batches, ExecutionOptions(workers=2, start_method=method)))
        assert local == serial, method  # bit for bit: the same arithmetic on one BLAS thread
    with LocalCluster(processes=True, n_workers=2, threads_per_worker=1, host="127.0.0.1", dashboard_address=None) as cluster:
        dask = _flat(map_batches(solve_items, 7, batches, ExecutionOptions(scheduler=cluster.scheduler_address)))
    assert dask == serial


def test_forked_workers_start_after_the_first_item_ran_here():
    batches = plan_batches(list(range(8)), 2, 2)
    options = ExecutionOptions(workers=2, start_method="fork")
    results = list(map_batches(pid_of_items, None, batches, options))
    assert results[0] == [(0, os.getpid())]  # the first item, alone, in this process: its caches are warm when the workers fork
    others = [pid for batch in results[1:] for _, pid in batch]
    assert sorted(i for batch in results for i, _ in batch) == list(range(8))
    assert len(others) == 7 and os.getpid() not in others
    cold = _flat(map_batches(pid_of_items, None, batches, options, warm_up=False))
    assert os.getpid() not in [pid for _, pid in cold]


def test_a_single_batch_runs_in_this_process():
    for method in START_METHODS:
        results = _flat(map_batches(pid_of_items, None, [[3, 4]], ExecutionOptions(workers=2, start_method=method)))
        assert results == [(3, os.getpid()), (4, os.getpid())], method
    assert list(map_batches(pid_of_items, None, [[], []], ExecutionOptions(workers=2))) == []


@pytest.mark.skipif((os.cpu_count() or 1) < 2, reason="BLAS runs one thread on one core whatever is asked")
def test_every_back_end_runs_one_blas_thread(monkeypatch: pytest.MonkeyPatch):
    import scipy.linalg  # noqa: F401 - both BLAS libraries loaded here, so the limit below reaches them
    from distributed import LocalCluster

    monkeypatch.setenv("OPENBLAS_NUM_THREADS", "2")  # what a spawned worker or a Dask worker would start with
    batches = [[0], [1], [2], [3]]
    with threadpool_limits(limits=2, user_api="blas"):  # this process: two threads (a forked worker inherits them)
        for options in (ExecutionOptions(workers=1), *(ExecutionOptions(workers=2, start_method=m) for m in START_METHODS)):
            counts = {tuple(c) for batch in map_batches(blas_threads, None, batches, options) for _, c in batch}
            assert counts == {(1,)}, options
        assert {tuple(c) for _, c in blas_threads(None, [0])} == {(2,)}  # the probe sees two threads where they run
        with LocalCluster(processes=True, n_workers=1, threads_per_worker=1, host="127.0.0.1", dashboard_address=None) as cluster:
            on_dask = map_batches(blas_threads, None, batches, ExecutionOptions(scheduler=cluster.scheduler_address))
            counts = {tuple(c) for batch in on_dask for _, c in batch}
    assert counts == {(1,)}


def test_forkserver_workers_outlive_the_parent_watch_interval():
    # a forkserver's workers are children of the server, not of this process: they must watch the parent they
    # start with, or they exit at the watch's first tick (0.25 s) mid-run
    batches = [[0, 1, 2, 3], [4, 5, 6, 7]]
    results = _flat(map_batches(sleep_items, 0.1, batches, ExecutionOptions(workers=2, start_method="forkserver")))
    assert results == list(range(8))  # 4 x 0.1 s per task, beyond the 0.25 s tick


ORPHANS = textwrap.dedent(
    """
    import sys
    sys.path.insert(0, {here!r})
    from executor_tasks import record_pid_and_sleep
    from seafast.parallel.executor import ExecutionOptions, map_batches

    if __name__ == "__main__":
        options = ExecutionOptions(workers=2, start_method=sys.argv[2])
        for _ in map_batches(record_pid_and_sleep, sys.argv[1], [[0], [1], [2], [3]], options, warm_up=False):
            pass
    """
)


def _running(pid: int) -> bool:
    try:
        state = Path(f"/proc/{pid}/stat").read_text().split(")")[-1].split()[0]
    except OSError:
        return False
    return state != "Z"  # a zombie has exited (nobody reaped it yet)


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="reads /proc")
@pytest.mark.parametrize("method", ["fork", "forkserver"])
def test_workers_exit_when_the_coordinator_is_killed(tmp_path: Path, method: str):
    script = tmp_path / "coordinator.py"
    script.write_text(ORPHANS.format(here=str(HERE)), encoding="utf-8")
    pids = tmp_path / "pids"
    pids.mkdir()
    proc = subprocess.Popen([sys.executable, str(script), str(pids), method], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    deadline = time.monotonic() + 120
    while len(list(pids.iterdir())) < 2:
        assert proc.poll() is None, proc.communicate()
        assert time.monotonic() < deadline, "the workers did not start"
        time.sleep(0.05)
    workers = [int(p.name) for p in pids.iterdir()]
    assert all(_running(pid) for pid in workers)
    proc.send_signal(signal.SIGKILL)
    proc.wait(timeout=30)
    deadline = time.monotonic() + 30  # the watch ticks every 0.25 s
    while any(_running(pid) for pid in workers) and time.monotonic() < deadline:
        time.sleep(0.05)
    left = [pid for pid in workers if _running(pid)]
    for pid in left:  # do not leave them behind should the test fail
        os.kill(pid, signal.SIGKILL)
    assert left == [], "workers outlived their coordinator"


def test_start_method_is_fork_in_a_single_threaded_process_else_forkserver():
    probe = "from seafast.parallel.executor import ExecutionOptions; print(ExecutionOptions(workers=2).process_start_method())"
    fresh = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, timeout=120, check=True)
    assert fresh.stdout.strip() == ("fork" if sys.platform.startswith("linux") else "spawn")

    stop = threading.Event()
    thread = threading.Thread(target=stop.wait, daemon=True)
    thread.start()
    try:
        assert ExecutionOptions(workers=2).process_start_method() == "forkserver"  # POSIX
        assert ExecutionOptions(workers=2, start_method="spawn").process_start_method() == "spawn"
    finally:
        stop.set()
        thread.join()


def test_options_name_the_mode_and_refuse_an_unknown_start_method():
    assert ExecutionOptions(workers=1).mode() == "serial"
    assert ExecutionOptions(workers=3).mode() == "processes" and ExecutionOptions(workers=3).worker_count() == 3
    assert ExecutionOptions(workers=1, scheduler="tcp://host:8786").mode() == "dask"
    assert ExecutionOptions().worker_count() == (os.cpu_count() or 1)
    with pytest.raises(ParallelError, match=r"start_method = 'thread'; allowed: fork, forkserver, spawn or None"):
        ExecutionOptions(start_method="thread")


def test_an_unreachable_scheduler_is_a_clear_error():
    options = ExecutionOptions(scheduler="nope://host:8786")
    with pytest.raises(ParallelError, match="--scheduler nope://host:8786: cannot connect to a Dask scheduler"):
        list(map_batches(pid_of_items, None, [[0]], options))


def test_batches_cover_every_item_once():
    pending = list(range(1, 400, 2))
    for workers, size in ((1, None), (2, None), (8, None), (2, 7)):
        batches = plan_batches(pending, workers, size)
        assert [i for b in batches for i in b] == pending
        assert max(len(b) for b in batches) <= (size or 25)
    assert plan_batches([], 2) == []
    guided = [len(b) for b in plan_batches(list(range(400)), 2)]
    assert guided[0] == 25 and guided[-1] == 1 and guided == sorted(guided, reverse=True)  # the tail is fine-grained
    assert plan_batches([4, 9, 2], 2, 1) == [[4], [9], [2]]  # one item a task (the Monte Carlo's realisations)
