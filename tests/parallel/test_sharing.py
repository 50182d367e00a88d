"""Work shared with forked helper processes: the same results as one process, and no error lost."""

from __future__ import annotations

import multiprocessing
import os
import signal

import pytest

from seafast.parallel import sharing
from seafast.parallel.sharing import HelperPool, RemoteTraceback, helper_count, share_work

fork_only = pytest.mark.skipif("fork" not in multiprocessing.get_all_start_methods(), reason="needs fork")

PARENT = os.getpid()


def _helper_event():
    """An event a forked helper sets, for this process to wait on (no race: the helper has taken an item)."""
    return multiprocessing.get_context("fork").Event()


@fork_only
def test_helpers_return_every_result_in_the_order_of_the_items_and_share_the_work():
    taken, log = _helper_event(), []

    def square_with_pid(x: int) -> tuple[int, int]:
        if os.getpid() != PARENT:
            taken.set()
        return x * x, os.getpid()

    def first() -> None:
        log.append("first")
        taken.wait(60)  # a helper has taken an item by then

    out = share_work(list(range(40)), square_with_pid, first=first, helpers=2)
    assert [value for value, _ in out] == [x * x for x in range(40)]
    assert log == ["first"]  # first runs once, here
    assert {pid for _, pid in out} - {PARENT}


def test_without_helpers_everything_runs_here_first_then_the_items_in_order():
    log: list[object] = []
    out = share_work([3, 1, 2], lambda x: log.append(x) or x + 1, first=lambda: log.append("first"), helpers=0)
    assert out == [4, 2, 3] and log == ["first", 3, 1, 2]


@fork_only
def test_an_error_in_a_helper_is_raised_here_with_its_type_message_and_traceback():
    taken = _helper_event()

    def fail_in_helper(x: int) -> int:
        if os.getpid() != PARENT:
            taken.set()
            raise ValueError(f"item {x} is wrong")
        return x

    with pytest.raises(ValueError, match=r"item \d is wrong") as info:
        share_work(list(range(6)), fail_in_helper, first=lambda: taken.wait(60), helpers=1)
    assert isinstance(info.value.__cause__, RemoteTraceback)
    assert "fail_in_helper" in str(info.value.__cause__)


@fork_only
def test_a_helper_killed_without_a_word_is_an_error_naming_its_exit_code():
    taken = _helper_event()

    def die_in_helper(x: int) -> int:
        if os.getpid() != PARENT:
            taken.set()
            os.kill(os.getpid(), signal.SIGKILL)
        return x

    with pytest.raises(RuntimeError, match="exit code -9"):
        share_work([1, 2, 3], die_in_helper, first=lambda: taken.wait(60), helpers=1)


@fork_only
def test_an_error_here_stops_the_helpers_and_is_raised():
    def boom() -> None:
        raise OSError("disk full")

    with pytest.raises(OSError, match="disk full"):
        share_work([1, 2, 3], lambda x: x, first=boom, helpers=1)


def test_one_helper_per_further_idle_core_none_for_one_item_or_a_running_thread(monkeypatch):
    assert helper_count(1) == 0
    forks = "fork" in multiprocessing.get_all_start_methods()
    monkeypatch.setattr(sharing.threading, "active_count", lambda: 1)  # whatever threads earlier tests left
    monkeypatch.setattr(sharing.os, "sched_getaffinity", lambda _pid: {0, 1, 2, 3}, raising=False)
    monkeypatch.setattr(sharing.os, "cpu_count", lambda: 4)
    monkeypatch.setattr(sharing, "busy_cores", lambda: 0)
    assert helper_count(8) == (3 if forks else 0)
    assert helper_count(2) == (1 if forks else 0)
    monkeypatch.setattr(sharing, "busy_cores", lambda: 2)  # two cores taken by others: one idle besides this process's
    assert helper_count(8) == (1 if forks else 0)
    monkeypatch.setattr(sharing, "busy_cores", lambda: 5)
    assert helper_count(8) == 0
    monkeypatch.setattr(sharing, "busy_cores", lambda: 0)
    monkeypatch.setattr(sharing.threading, "active_count", lambda: 2)
    assert helper_count(8) == 0


def test_busy_cores_reads_the_processes_running_now_less_this_one(monkeypatch, tmp_path):
    real_path = sharing.Path
    loadavg = tmp_path / "loadavg"
    loadavg.write_text("7.77 8.07 7.54 9/139 21737\n")
    monkeypatch.setattr(sharing, "Path", lambda p: loadavg if p == "/proc/loadavg" else real_path(p))
    assert sharing.busy_cores() == 8
    loadavg.write_text("0.10 0.20 0.30 1/139 21737\n")
    assert sharing.busy_cores() == 0
    loadavg.unlink()  # no /proc: the load average, rounded
    monkeypatch.setattr(sharing.os, "getloadavg", lambda: (2.6, 1.0, 1.0), raising=False)
    assert sharing.busy_cores() == 3


@fork_only
def test_a_pool_started_ahead_warms_up_then_takes_the_work_pickled():
    with HelperPool(1, warm=_warm_marker).start() as pool:
        out = pool.share(list(range(12)), _square_and_warm_pid, first=_wait_for_helper_result)
    assert [value for value, _ in out] == [x * x for x in range(12)]
    assert {warmed for _, warmed in out} <= {PARENT, "warmed"}
    assert pool.share([5, 6], _square_and_warm_pid) == [(25, PARENT), (36, PARENT)]  # a second piece of work: here


@fork_only
def test_a_pool_started_ahead_and_left_unused_stops_its_helpers():
    pool = HelperPool(1, warm=_warm_marker).start()
    assert len(multiprocessing.active_children()) == 1
    pool.close()
    assert multiprocessing.active_children() == []


@fork_only
def test_an_error_while_warming_up_is_raised_here():
    with pytest.raises(ImportError, match="no such figure library"), HelperPool(1, warm=_warm_fails).start() as pool:
        pool.share([1, 2, 3], _square_and_warm_pid)


_WARMED: list[str] = []


def _warm_marker() -> None:
    _WARMED.append("warmed")


def _warm_fails() -> None:
    raise ImportError("no such figure library")


def _square_and_warm_pid(x: int) -> tuple[int, object]:
    return x * x, (_WARMED[-1] if os.getpid() != PARENT and _WARMED else PARENT)


def _wait_for_helper_result() -> None:
    import time

    time.sleep(0.2)
