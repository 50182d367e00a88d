"""Running batches of independent tasks: serially, on local worker processes or on a Dask scheduler.

:func:`map_batches` evaluates ``task(shared, batch)`` for each batch of task indices
(:func:`plan_batches`) and yields each batch's result as it completes, whatever the back-end
(:class:`ExecutionOptions`). ``shared`` (a study grid and its evaluator, a Monte Carlo plan)
reaches each worker once, not with every batch. The task is the caller's: it records a failure
of one of its items in its result (:func:`error_text`), so one failure does not stop the run;
an exception that escapes it does.

* **serial**: in this process, with one BLAS thread (:func:`seafast.parallel.threads.one_blas_thread`).
* **local worker processes**: a process pool; each worker pins itself to one thread
  (:func:`seafast.parallel.threads.pin_worker_threads`) and exits within a quarter of a second
  of the coordinating process (this one) being gone: a coordinator killed with SIGKILL leaves no
  orphan computing. On Linux, when
  this process runs no other Python thread, the workers *fork*: they inherit the imported modules
  and every cache this process warmed, and with ``warm_up`` the first item of the first batch
  runs here before they fork, so those caches are warm (a worker costs milliseconds to start
  instead of a fresh interpreter's imports, about a second of CPU). Otherwise (another thread
  runs here, e.g. after a Dask client; not Linux) they fork from a ``forkserver`` that imported
  the task's module once, or are spawned where there is none; any of the three can be asked for
  (``ExecutionOptions.start_method``). A single batch runs in this process.
* **Dask**: the tasks go to a distributed scheduler (``tcp://host:port``); ``shared`` is
  scattered to every worker once, and each task pins its worker's threads first.

The task must be a module-level function and ``shared`` picklable for the spawned, forkserver
and Dask back-ends.
"""

from __future__ import annotations

import concurrent.futures as cf
import logging
import math
import multiprocessing
import os
import sys
import threading
import time
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass
from typing import Any, TypeVar

from seafast.parallel.errors import ParallelError
from seafast.parallel.threads import one_blas_thread, pin_worker_threads

__all__ = ["START_METHODS", "ExecutionOptions", "plan_batches", "map_batches", "error_text"]

logger = logging.getLogger(__name__)

S = TypeVar("S")
R = TypeVar("R")

Task = Callable[[S, list[int]], R]

START_METHODS: tuple[str, ...] = ("fork", "forkserver", "spawn")
"""How local worker processes can start."""


@dataclass(frozen=True)
class ExecutionOptions:
    """Where and how a run's tasks are evaluated.

    Attributes
    ----------
    workers : int or None
        Local worker processes; None = all cores; 1 = serial in this process.
    scheduler : str or None
        Address of a Dask distributed scheduler (``tcp://host:port``); overrides ``workers``.
    batch_size : int or None
        Items per task; None = the caller's plan (a study: about four tasks per worker, at most
        25 points each, :func:`plan_batches`; a Monte Carlo run: one realisation per task).
    progress : bool
        Show progress on stderr (:func:`seafast.parallel.progress.progress`: a bar on a terminal,
        else a plain line every few per cent).
    start_method : str or None
        How local worker processes start: ``fork``, ``forkserver`` or ``spawn``; None = ``fork``
        on Linux when this process runs no other Python thread, else ``forkserver`` where
        available, else ``spawn``.

    Raises
    ------
    ParallelError
        If ``start_method`` is none of :data:`START_METHODS`.
    """

    workers: int | None = None
    scheduler: str | None = None
    batch_size: int | None = None
    progress: bool = True
    start_method: str | None = None

    def __post_init__(self) -> None:
        if self.start_method is not None and self.start_method not in START_METHODS:
            raise ParallelError(f"start_method = {self.start_method!r}; allowed: {', '.join(START_METHODS)} or None (automatic)")

    def worker_count(self) -> int:
        """Number of local workers."""
        return max(1, self.workers if self.workers is not None else (os.cpu_count() or 1))

    def mode(self) -> str:
        """``'dask'``, ``'processes'`` or ``'serial'``."""
        if self.scheduler:
            return "dask"
        return "serial" if self.worker_count() == 1 else "processes"

    def process_start_method(self) -> str:
        """The start method local worker processes will use (see ``start_method``)."""
        if self.start_method is not None:
            return self.start_method
        methods = multiprocessing.get_all_start_methods()
        if sys.platform.startswith("linux") and "fork" in methods and threading.active_count() == 1:
            return "fork"
        return "forkserver" if "forkserver" in methods else "spawn"


def plan_batches(pending: Sequence[int], workers: int, batch_size: int | None = None) -> list[list[int]]:
    """Split pending task indices into batches.

    Parameters
    ----------
    pending : sequence of int
        Indices still to evaluate.
    workers : int
        Parallel workers. By default the batches shrink as the work runs out (guided
        scheduling): each holds a quarter of the items left per worker, 1..25 of them, so
        the workers finish together instead of one waiting for another's last large batch.
    batch_size : int, optional
        Items per batch (overrides the default).
    """
    if not pending:
        return []
    if batch_size:
        return [list(pending[i : i + batch_size]) for i in range(0, len(pending), batch_size)]
    batches, start = [], 0
    while start < len(pending):
        size = max(1, min(25, math.ceil((len(pending) - start) / (4 * max(1, workers)))))
        batches.append(list(pending[start : start + size]))
        start += size
    return batches


def error_text(exc: BaseException) -> str:
    """``Type: message`` on one line (``(no message)`` for an empty one): how a failed item is recorded."""
    text = " ".join(str(exc).split()) or "(no message)"
    return f"{type(exc).__name__}: {text}"


# --------------------------------------------------------------------------- worker processes
_shared: dict[str, Any] = {}  # per worker process: the run's shared argument (set by the initialiser)


def _gone(pid: int) -> bool:
    """Whether process ``pid`` has exited (a zombie, dead but not reaped yet, has)."""
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return True
    except PermissionError:
        return False  # it exists (another user's)
    try:
        with open(f"/proc/{pid}/stat", "rb") as fh:
            return fh.read().rsplit(b")", 1)[-1].split()[0] == b"Z"
    except (OSError, IndexError):
        return False  # no /proc (not Linux): os.kill found it


def _exit_with_coordinator(coordinator_pid: int, interval_s: float = 0.25) -> None:
    """Exit this worker when the coordinating process, or the parent it started from, is gone.

    A forked or spawned worker's parent is the coordinator, and a dead parent shows at once as
    another parent. A forkserver's worker's parent is the server, which outlives a coordinator
    killed with SIGKILL (every worker it forked holds the coordinator's end of the pipe whose
    closing would stop it): such a worker watches the coordinator's process id too.
    """
    parent = os.getppid()

    def watch() -> None:
        while True:
            time.sleep(interval_s)
            if os.getppid() != parent or _gone(coordinator_pid):
                os._exit(1)

    threading.Thread(target=watch, name="seafast-coordinator-watch", daemon=True).start()


def _init_worker(coordinator_pid: int, shared: Any) -> None:
    """Initialiser of a local worker process: one thread, the shared argument kept, exit with the coordinator."""
    pin_worker_threads()
    _shared["value"] = shared
    if _gone(coordinator_pid):
        os._exit(1)  # orphaned before it started
    _exit_with_coordinator(coordinator_pid)


def _run_in_worker(task: Task[Any, R], batch: list[int]) -> R:
    return task(_shared["value"], batch)


def _run_on_dask(task: Task[S, R], shared: S, batch: list[int]) -> R:
    pin_worker_threads()
    return task(shared, batch)


# --------------------------------------------------------------------------- back-ends
def _serial(task: Task[S, R], shared: S, batches: list[list[int]]) -> Iterator[R]:
    with one_blas_thread():  # the model's matrices are small: threading them is slower
        for batch in batches:
            yield task(shared, batch)


def _processes(
    task: Task[S, R], shared: S, batches: list[list[int]], workers: int, method: str, warm_up: bool, preload: Sequence[str]
) -> Iterator[R]:
    if method == "fork" and warm_up and batches[0]:
        # the first item here, before forking: the workers inherit its imports and warm caches
        first, rest = batches[0][:1], batches[0][1:]
        with one_blas_thread():
            result = task(shared, first)
        yield result
        batches = ([rest] if rest else []) + batches[1:]
    if len(batches) <= 1:
        yield from _serial(task, shared, batches)
        return
    context = multiprocessing.get_context(method)
    if method == "forkserver":
        # the server imports these once; each worker forks from it (no per-worker imports)
        context.set_forkserver_preload(list(dict.fromkeys([__name__, task.__module__, *preload])))
    executor = cf.ProcessPoolExecutor(
        max_workers=min(workers, len(batches)), mp_context=context, initializer=_init_worker, initargs=(os.getpid(), shared)
    )
    try:
        futures = [executor.submit(_run_in_worker, task, batch) for batch in batches]
        for future in cf.as_completed(futures):
            yield future.result()
    finally:
        executor.shutdown(wait=True, cancel_futures=True)


def _dask(task: Task[S, R], shared: S, batches: list[list[int]], address: str) -> Iterator[R]:
    from distributed import Client, as_completed

    try:
        client = Client(address, timeout="20s", set_as_default=False)
    except (OSError, TimeoutError, ValueError) as exc:
        raise ParallelError(f"--scheduler {address}: cannot connect to a Dask scheduler ({exc})") from None
    try:
        shared_future = client.scatter(shared, broadcast=True, hash=False)
        futures = [client.submit(_run_on_dask, task, shared_future, batch, pure=False) for batch in batches]
        for future in as_completed(futures, loop=client.loop):
            yield future.result()
    finally:
        client.close()


def map_batches(
    task: Task[S, R],
    shared: S,
    batches: Sequence[Sequence[int]],
    execution: ExecutionOptions,
    *,
    warm_up: bool = True,
    preload: Sequence[str] = (),
) -> Iterator[R]:
    """Evaluate ``task(shared, batch)`` for every batch on the back-end ``execution`` selects; yield each result as it completes.

    Parameters
    ----------
    task : callable
        ``task(shared, indices) -> result``; a module-level function for the spawned, forkserver
        and Dask back-ends. It records its items' failures in its result (:func:`error_text`).
    shared : object
        The argument every batch shares (picklable, except for the serial and forked back-ends).
    batches : sequence of sequence of int
        Task indices per batch (:func:`plan_batches`); the order of the results is the order in
        which the batches complete.
    execution : ExecutionOptions
        Serial, local processes or a Dask scheduler.
    warm_up : bool
        Forked workers: run the first item here first, so that the workers inherit its warm caches.
    preload : sequence of str
        Modules a forkserver imports once besides this one and the task's (e.g. the numerics the
        task imports lazily).

    Raises
    ------
    ParallelError
        If the Dask scheduler cannot be reached.
    """
    plan = [list(map(int, batch)) for batch in batches if len(batch)]
    if not plan:
        return iter(())
    mode = execution.mode()
    if mode == "dask":
        assert execution.scheduler is not None
        return _dask(task, shared, plan, execution.scheduler)
    if mode == "processes":
        method = execution.process_start_method()
        logger.debug("local worker processes start by %s", method)
        return _processes(task, shared, plan, execution.worker_count(), method, warm_up, preload)
    return _serial(task, shared, plan)
