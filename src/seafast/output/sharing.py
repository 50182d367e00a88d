"""Sharing a command's output work with forked helper processes: the figures drawn beside results.nc.

:func:`share_work` runs ``first()`` (writing results.nc) in this process while forked helpers
take ``work(item)`` (drawing a figure) from a shared list; this process joins them once
``first`` is done. Each item is taken once, by whichever process is free, so the processes end
together whatever the items cost. The helpers are forked, after the data are known: they
inherit the run's results and every module loaded, and nothing is pickled on the way in; only
each item's result (a path) comes back.

Errors are never lost: an exception raised by ``work`` in a helper is raised again in this
process (its type and message kept where it pickles, the helper's traceback as its cause); a
helper that dies without a word (killed, a crash) is an error naming its exit code. An error
here stops the helpers.

Where a process cannot fork (not POSIX), another Python thread runs here (forking a threaded
process can deadlock), or one core is all there is, everything runs here, one item after the
other: the same results.
"""

from __future__ import annotations

import gc
import multiprocessing
import os
import sys
import threading
import traceback
from collections.abc import Callable, Sequence
from typing import Any, TypeVar

__all__ = ["RemoteTraceback", "helper_count", "share_work"]

T = TypeVar("T")
R = TypeVar("R")


class RemoteTraceback(Exception):
    """The traceback of an exception raised in a helper process (the cause of the one raised here)."""

    def __str__(self) -> str:
        return str(self.args[0]) if self.args else ""


def helper_count(items: int) -> int:
    """How many helper processes to fork for ``items`` items: one per further core, none where forking is unsafe."""
    if items < 2 or "fork" not in multiprocessing.get_all_start_methods() or threading.active_count() > 1:
        return 0
    cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1)
    return max(0, min(cores - 1, items - 1))


def _take(counter: Any, total: int) -> int | None:
    """The next item's index from the shared ``counter``, or None when all are taken."""
    with counter.get_lock():
        index = int(counter.value)
        if index >= total:
            return None
        counter.value = index + 1
    return index


def _helper(items: Sequence[T], work: Callable[[T], R], counter: Any, conn: Any) -> None:
    """A helper's loop: take items, send ``("ok", index, result)``; on an error send it and stop every process taking."""
    try:
        while (index := _take(counter, len(items))) is not None:
            conn.send(("ok", index, work(items[index])))
    except BaseException as exc:  # noqa: BLE001 - every error goes back to the parent, none is lost
        with counter.get_lock():
            counter.value = len(items)
        text = "".join(traceback.format_exception(exc))
        try:
            conn.send(("error", exc, text))
        except Exception:  # noqa: BLE001 - an exception that does not pickle goes back as its text
            conn.send(("error", None, text))
    finally:
        conn.close()


def _collect(helpers: list[tuple[Any, Any]], results: dict[int, Any]) -> None:
    """Read every helper's messages until it closes its end, join it; raise the first error a helper reported."""
    failure: BaseException | None = None
    for process, conn in helpers:
        try:
            while True:
                kind, *payload = conn.recv()
                if kind == "ok":
                    results[payload[0]] = payload[1]
                elif failure is None:
                    exc, text = payload
                    failure = exc if isinstance(exc, BaseException) else RuntimeError(f"a helper process failed:\n{text}")
                    failure.__cause__ = RemoteTraceback(text)
        except EOFError:
            pass
        finally:
            conn.close()
        process.join()
        if process.exitcode != 0 and failure is None:
            failure = RuntimeError(f"a helper process drawing the figures ended with exit code {process.exitcode} and no result")
    if failure is not None:
        raise failure


def share_work(
    items: Sequence[T], work: Callable[[T], R], first: Callable[[], object] | None = None, helpers: int | None = None
) -> list[R]:
    """``[work(item) for item in items]``, shared with forked helpers while this process runs ``first()``.

    Parameters
    ----------
    items : sequence
        The work, in the order it is taken (the costliest first balances the processes best).
    work : callable
        Called once per item, in this process or a helper; its result must pickle.
    first : callable, optional
        Run in this process before it takes items (the helpers start at once).
    helpers : int, optional
        Helper processes to fork; default :func:`helper_count` (0: everything here, in order).

    Returns
    -------
    list
        ``work(item)`` for each item, in the order of ``items``.

    Raises
    ------
    BaseException
        The first error of ``first``, of ``work`` here, or of ``work`` in a helper (re-raised
        here, the helper's traceback as its ``__cause__``); :class:`RuntimeError` when a helper
        ended without a result (killed or crashed).
    """
    count = helper_count(len(items)) if helpers is None else helpers
    if count == 0:
        if first is not None:
            first()
        return [work(item) for item in items]
    context = multiprocessing.get_context("fork")
    counter = context.Value("i", 0)
    started: list[tuple[Any, Any]] = []
    results: dict[int, R] = {}
    sys.stdout.flush()
    sys.stderr.flush()
    # what the helpers inherit is frozen out of their garbage collector, which then touches none
    # of it: no copy-on-write of those pages (Python's gc.freeze documentation); thawed here after
    # (where something had frozen objects before, nothing is frozen or thawed here)
    thaw = gc.get_freeze_count() == 0
    if thaw:
        gc.freeze()
    try:
        for _ in range(count):
            receive, send = context.Pipe(duplex=False)
            process = context.Process(target=_helper, args=(items, work, counter, send), daemon=True)
            process.start()
            send.close()  # the helper holds the only writing end: its exit ends the messages
            started.append((process, receive))
        if thaw:
            gc.unfreeze()
            thaw = False
        if first is not None:
            first()
        while (index := _take(counter, len(items))) is not None:
            results[index] = work(items[index])
    except BaseException:
        if thaw:
            gc.unfreeze()
        with counter.get_lock():
            counter.value = len(items)
        for process, conn in started:
            process.terminate()
            process.join()
            conn.close()
        raise
    _collect(started, results)
    return [results[i] for i in range(len(items))]
