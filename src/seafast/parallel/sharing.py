"""Sharing a command's output work with forked helper processes: the figures drawn beside results.nc.

:func:`share_work` runs ``first()`` (writing results.nc) in this process while forked helpers
take ``work(item)`` (drawing a figure) from a shared list; this process takes items too once
``first`` is done. Each item is taken once, by whichever process is free, so the processes end
together whatever the items cost. Only each item's result (a path) comes back.

The helpers are forked either when the work is known (they inherit the data and every module
loaded; nothing is pickled on the way in), or ahead of it (:class:`HelperPool` started early,
``seafast run`` does so before it solves): each then runs its ``warm`` callable at once
(importing matplotlib, loading the fonts) while this process computes, and receives the work
pickled (a module-level function or a :func:`functools.partial` of one, and its data) when it is
known.

Errors are never lost: an exception raised by ``work`` (or ``warm``) in a helper is raised again
in this process (its type and message kept where it pickles, the helper's traceback as its
cause); a helper that dies without a word (killed, a crash) is an error naming its exit code. An
error here stops the helpers.

Where a process cannot fork (not POSIX), another Python thread runs here (forking a threaded
process can deadlock), or no core is idle (:func:`helper_count`), everything runs here, one item
after the other: the same results.
"""

from __future__ import annotations

import contextlib
import gc
import multiprocessing
import os
import sys
import threading
import traceback
from collections.abc import Callable, Sequence
from pathlib import Path
from types import TracebackType
from typing import Any, TypeVar

__all__ = ["RemoteTraceback", "HelperPool", "busy_cores", "helper_count", "share_work"]

T = TypeVar("T")
R = TypeVar("R")


class RemoteTraceback(Exception):
    """The traceback of an exception raised in a helper process (the cause of the one raised here)."""

    def __str__(self) -> str:
        return str(self.args[0]) if self.args else ""


def busy_cores() -> int:
    """Processes other than this one running or ready to run now (Linux's ``/proc/loadavg``), else the load average.

    Where ``/proc/loadavg`` is missing, the 1-minute load average rounded; 0 where neither is known.
    """
    try:
        running = Path("/proc/loadavg").read_text(encoding="ascii").split()[3].split("/")[0]
        return max(int(running) - 1, 0)
    except (OSError, IndexError, ValueError):
        pass
    return round(os.getloadavg()[0]) if hasattr(os, "getloadavg") else 0


def helper_count(items: int) -> int:
    """How many helper processes to fork for ``items`` items: one per further idle core, none where forking is unsafe.

    Idle cores: this process's cores less one (its own) and less those other processes are
    using now (:func:`busy_cores`). A helper on a busy machine gets no core of its own: it would
    only add its start-up (its imports) to the work, so there is none then and everything runs
    here.
    """
    if items < 2 or "fork" not in multiprocessing.get_all_start_methods() or threading.active_count() > 1:
        return 0
    cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1)
    return max(0, min(cores - 1 - busy_cores(), items - 1))


def _take(counter: Any, total: int) -> int | None:
    """The next item's index from the shared ``counter``, or None when all are taken."""
    with counter.get_lock():
        index = int(counter.value)
        if index >= total:
            return None
        counter.value = index + 1
    return index


def _stop_taking(counter: Any) -> None:
    """No process takes another item (an error stops the work)."""
    with counter.get_lock():
        counter.value = sys.maxsize >> 33  # beyond any list of items


def _helper(
    counter: Any, jobs: Any, conn: Any, warm: Callable[[], object] | None, job: tuple[Sequence[Any], Callable[[Any], Any]] | None
) -> None:
    """A helper: warm up and wait for its job (unless it came with it), take items, send ``("ok", index, result)``.

    On an error: send it, and stop every process taking items.
    """
    try:
        if job is None:
            if warm is not None:
                warm()
            job = jobs.recv()
            if job is None:  # the pool closed without work
                return
        items, work = job
        while (index := _take(counter, len(items))) is not None:
            conn.send(("ok", index, work(items[index])))
    except BaseException as exc:  # noqa: BLE001 - every error goes back to the parent, none is lost
        _stop_taking(counter)
        text = "".join(traceback.format_exception(exc))
        try:
            conn.send(("error", exc, text))
        except OSError:  # the parent is gone (killed): nobody to tell
            pass
        except Exception:  # noqa: BLE001 - an exception that does not pickle goes back as its text
            with contextlib.suppress(OSError):
                conn.send(("error", None, text))
    finally:
        conn.close()
        jobs.close()


class HelperPool:
    """Helper processes for one shared piece of work (:meth:`share`), forked at :meth:`start` or when the work comes.

    Parameters
    ----------
    count : int
        Helper processes (0: :meth:`share` runs everything here).
    warm : callable, optional
        What an early helper runs while it waits for its work (imports, caches); module-level.

    A pool serves one piece of work: after :meth:`share` (or :meth:`close`) a further share
    runs in this process. A context manager: leaving it stops helpers that got no work.

    A helper forked ahead receives the work once it is warm: :meth:`share` waits for that
    before it runs ``first`` (``seafast run`` starts the pool before it loads the solvers, and
    the helper is warm long before the Dataset exists).
    """

    def __init__(self, count: int, warm: Callable[[], object] | None = None) -> None:
        self.count = count
        self.warm = warm
        self._context = multiprocessing.get_context("fork") if count > 0 else None
        self._counter: Any = None
        self._helpers: list[tuple[Any, Any, Any]] = []  # (process, its results' reading end, its job's writing end)
        self._early = False

    def _fork(self, job: tuple[Sequence[Any], Callable[[Any], Any]] | None) -> None:
        """Fork the helpers (each with ``job``, or to wait for it), what they inherit frozen out of the garbage collector."""
        assert self._context is not None
        self._counter = self._context.Value("i", 0)
        sys.stdout.flush()
        sys.stderr.flush()
        # frozen, the inherited objects are not touched by the helpers' garbage collector: no
        # copy-on-write of their pages (Python's gc.freeze documentation); thawed here after,
        # unless something had frozen objects before (then nothing is frozen or thawed here)
        thaw = gc.get_freeze_count() == 0
        if thaw:
            gc.freeze()
        try:
            for _ in range(self.count):
                job_in, job_out = self._context.Pipe(duplex=False)
                results_in, results_out = self._context.Pipe(duplex=False)
                process = self._context.Process(target=_helper, args=(self._counter, job_in, results_out, self.warm, job), daemon=True)
                process.start()
                job_in.close()
                results_out.close()  # the helper holds the only writing end: its exit ends the messages
                self._helpers.append((process, results_in, job_out))
        finally:
            if thaw:
                gc.unfreeze()

    def start(self) -> HelperPool:
        """Fork the helpers now: they run ``warm`` and wait for :meth:`share`'s work."""
        if self.count > 0 and not self._helpers:
            self._fork(None)
            self._early = True
        return self

    def share(self, items: Sequence[T], work: Callable[[T], R], first: Callable[[], object] | None = None) -> list[R]:
        """``[work(item) for item in items]``, shared with the helpers while this process runs ``first()`` (see :func:`share_work`)."""
        if self.count == 0:
            if first is not None:
                first()
            return [work(item) for item in items]
        results: dict[int, R] = {}
        try:
            if self._early:
                for _, _, jobs in self._helpers:
                    try:
                        jobs.send((items, work))  # the work pickled: the helpers were forked before it existed
                    except OSError:  # the helper ended (its warm-up failed): its message, read below, says why
                        pass
            else:
                self._fork((items, work))
            if first is not None:
                first()
            while (index := _take(self._counter, len(items))) is not None:
                results[index] = work(items[index])
        except BaseException:
            self.close()
            raise
        self.count = 0  # a pool serves one piece of work: another share runs here
        self._collect(results)
        return [results[i] for i in range(len(items))]

    def _collect(self, results: dict[int, Any]) -> None:
        """Read every helper's messages until it closes its end, join it; raise the first error a helper reported."""
        failure: BaseException | None = None
        helpers, self._helpers = self._helpers, []
        for process, conn, jobs in helpers:
            jobs.close()
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
                failure = RuntimeError(f"a helper process ended with exit code {process.exitcode} and no result")
        if failure is not None:
            raise failure

    def close(self) -> None:
        """Stop the helpers still running (no work for them, or an error here); a no-op after :meth:`share`."""
        if self._counter is not None:
            _stop_taking(self._counter)
        self.count = 0
        helpers, self._helpers = self._helpers, []
        for process, conn, jobs in helpers:
            process.terminate()
            process.join()
            conn.close()
            jobs.close()

    def __enter__(self) -> HelperPool:
        return self

    def __exit__(self, kind: type[BaseException] | None, value: BaseException | None, tb: TracebackType | None) -> None:
        self.close()


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
    with HelperPool(count) as pool:
        return pool.share(items, work, first)
