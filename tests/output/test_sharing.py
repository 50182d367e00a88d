"""Work shared with forked helper processes: the same results as one process, and no error lost."""

from __future__ import annotations

import multiprocessing
import os
import signal

import pytest

from seafast.output import sharing
from seafast.output.sharing import RemoteTraceback, helper_count, share_work

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


def test_no_helper_for_one_item_one_core_or_a_running_thread(monkeypatch):
    assert helper_count(1) == 0
    monkeypatch.setattr(sharing.os, "sched_getaffinity", lambda _pid: {0}, raising=False)
    monkeypatch.setattr(sharing.os, "cpu_count", lambda: 1)
    assert helper_count(8) == 0
    monkeypatch.setattr(sharing.os, "sched_getaffinity", lambda _pid: {0, 1, 2, 3}, raising=False)
    monkeypatch.setattr(sharing.os, "cpu_count", lambda: 4)
    assert helper_count(8) == (3 if "fork" in multiprocessing.get_all_start_methods() else 0)
    assert helper_count(2) in (0, 1)
    monkeypatch.setattr(sharing.threading, "active_count", lambda: 2)
    assert helper_count(8) == 0
