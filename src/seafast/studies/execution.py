"""Evaluating study points: evaluators, batches, and the serial / local-process / Dask back-ends.

Every point is evaluated by an *evaluator* ``Callable[[Case], list[dict]]`` (default
:func:`seafast.analyses.run.evaluate_summary`, imported lazily) returning one row per load case and
model. Points travel to workers in batches (:func:`plan_batches`); :func:`evaluate_batches`
yields each batch's :class:`~seafast.studies.store.PointRecord` list as it completes, whatever
the back-end. A point whose evaluation raises is recorded with its error text; a row's typed
warnings are stored as their values, and the log records of a point are captured, not printed
(:mod:`seafast.studies.messages`).

The back-ends are generic: they need an object with ``size`` and ``point_case(index)``
(:class:`PointSource`), e.g. a :class:`~seafast.studies.spec.StudyGrid`.

Local processes start by ``fork`` on Linux when this process runs no other Python thread: the
workers then inherit the imported modules and the caches the coordinating process warmed on
its first point (the vessel excitation and BEM data of its ``VesselCache``, the cargo mesh), so a worker costs
milliseconds to start instead of a fresh interpreter's imports (about a second of CPU each).
Otherwise (another thread runs here, e.g. after a Dask client; not Linux) they fork from a
``forkserver`` that imported the numerics once, or are spawned where there is none; any of the
three can be asked for (``ExecutionOptions.start_method``).
"""

from __future__ import annotations

import concurrent.futures as cf
import importlib
import logging
import math
import multiprocessing
import os
import sys
import threading
import time
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass
from typing import Any, Protocol

from seafast.config.schema import Case
from seafast.excitation.vessel import VesselCache
from seafast.model.cache import ModelCache
from seafast.studies.messages import point_log
from seafast.studies.spec import StudyError
from seafast.studies.store import PointRecord, stored_row

__all__ = [
    "Evaluator",
    "EVALUATOR_ENV",
    "PointSource",
    "ExecutionOptions",
    "default_evaluator",
    "resolve_evaluator",
    "evaluate_batch",
    "plan_batches",
    "evaluate_batches",
]

logger = logging.getLogger(__name__)

Evaluator = Callable[[Case], list[dict]]

#: Environment variable naming an alternative evaluator as ``module:function`` (testing, plug-ins).
EVALUATOR_ENV = "SEAFAST_STUDY_EVALUATOR"


class PointSource(Protocol):
    """What the back-ends need of a set of points."""

    @property
    def size(self) -> int:
        """Number of points."""

    def point_case(self, index: int) -> Case:
        """The validated case of point ``index`` (raises for an invalid combination)."""


# --------------------------------------------------------------------------- evaluators
def default_evaluator(case: Case) -> list[dict]:
    """Evaluate one case with :func:`seafast.analyses.run.evaluate_summary` (imported on first use)."""
    from seafast.analyses.run import evaluate_summary

    return evaluate_summary(case)


def resolve_evaluator(evaluator: Evaluator | str | None) -> Evaluator:
    """The evaluator callable.

    Parameters
    ----------
    evaluator : callable, str or None
        A callable; ``"module:function"``; or None for the ``SEAFAST_STUDY_EVALUATOR``
        environment variable when set, else :func:`default_evaluator`.
    """
    if callable(evaluator):
        return evaluator
    ref = evaluator if evaluator is not None else os.environ.get(EVALUATOR_ENV)
    if not ref:
        return default_evaluator
    module_name, _, attr = ref.partition(":")
    if not attr:
        raise StudyError(f"evaluator {ref!r}: expected 'module:function'")
    try:
        target: Any = importlib.import_module(module_name)
        for part in attr.split("."):
            target = getattr(target, part)
    except (ImportError, AttributeError) as exc:
        raise StudyError(f"evaluator {ref!r} cannot be imported: {exc}") from None
    if not callable(target):
        raise StudyError(f"evaluator {ref!r} is not callable")
    return target


_worker_ready = False

_POINT_VESSELS = VesselCache()
"""The vessel excitations this process keeps for the study points it evaluates (with the hull forms and BEM
data behind them), shared with the evaluator while a batch runs (:meth:`VesselCache.shared`): a study over
the sea-fastening computes its vessel once per process, one over the cargo reads the BEM data once. A forked
worker inherits it warm from the coordinator's first point."""

_POINT_MODELS = ModelCache()
"""The cargo beams and Rayleigh fits this process keeps for the study points it evaluates, shared as
:data:`_POINT_VESSELS` is: along a stiffness axis the mesh is built once, along a pretension axis the fit too."""


def _prepare_worker() -> None:
    """Once per worker process: one BLAS/OpenMP thread (the parallelism is across points)."""
    global _worker_ready  # noqa: PLW0603 - per-process state: a worker pins its threads once
    if _worker_ready:
        return
    for var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "NUMEXPR_NUM_THREADS"):
        os.environ[var] = "1"
    try:
        from threadpoolctl import threadpool_limits

        threadpool_limits(limits=1)
    except Exception:  # noqa: BLE001  # pragma: no cover - pinning is an optimisation; a library threadpoolctl cannot inspect must not stop a worker
        pass
    _worker_ready = True


def _exit_with_parent(parent_pid: int, interval_s: float = 0.25) -> None:
    """Exit this worker when its parent process is gone (e.g. the study was killed with SIGKILL)."""

    def watch() -> None:
        while True:
            time.sleep(interval_s)
            if os.getppid() != parent_pid:
                os._exit(1)

    threading.Thread(target=watch, name="seafast-parent-watch", daemon=True).start()


def _init_process_worker(coordinator_pid: int) -> None:
    """Initializer of local worker processes: one BLAS thread; exit with the coordinator.

    A forked or spawned worker's parent is the coordinating process; a forkserver's worker's is
    the server, which exits when the coordinator does. Either way the worker watches the parent
    it starts with.
    """
    global _worker_ready  # noqa: PLW0603 - per-process state, reset in a forked worker
    _worker_ready = False  # a forked worker re-pins its own BLAS
    _prepare_worker()
    parent = os.getppid()
    if parent == 1 and coordinator_pid != 1:
        os._exit(1)  # orphaned before it started
    _exit_with_parent(parent)


def evaluate_batch(
    grid: PointSource,
    indices: Sequence[int],
    evaluator: Evaluator | str | None = None,
    pin_threads: bool = True,
    keep_messages: bool = False,
) -> list[PointRecord]:
    """Evaluate a batch of points (runs in a worker).

    Parameters
    ----------
    grid : PointSource
        The study (e.g. a :class:`~seafast.studies.spec.StudyGrid`).
    indices : sequence of int
        Flat point indices.
    evaluator : callable, str or None
        See :func:`resolve_evaluator`.
    pin_threads : bool
        Limit BLAS/OpenMP to one thread in this process (workers; not the serial runner).
    keep_messages : bool
        Return each point's log records with its record (:func:`seafast.studies.messages.point_log`);
        False: they are dropped. Either way nothing is printed while a point runs.

    Returns
    -------
    list of PointRecord
        One per index, in order; a point that raised carries its error text. Each row holds
        ``warnings``, the list of its typed warnings' values (empty when none).
    """
    if pin_threads:
        _prepare_worker()
    func = resolve_evaluator(evaluator)
    records = []
    for index in indices:
        t0 = time.perf_counter()
        with point_log(keep_messages) as messages, _POINT_VESSELS.shared(), _POINT_MODELS.shared():
            try:
                case = grid.point_case(int(index))
                rows = tuple(stored_row(row) for row in func(case))
                error = ""
            except Exception as exc:  # noqa: BLE001 - any failure of one point is recorded, the study goes on
                text = " ".join(str(exc).split()) or "(no message)"
                rows, error = (), f"{type(exc).__name__}: {text}"
        records.append(PointRecord(int(index), rows, error, time.perf_counter() - t0, tuple(messages)))
    return records


def plan_batches(pending: Sequence[int], workers: int, batch_size: int | None = None) -> list[list[int]]:
    """Split pending point indices into batches (tasks).

    Parameters
    ----------
    pending : sequence of int
        Indices still to evaluate.
    workers : int
        Parallel workers. By default the batches shrink as the work runs out (guided
        scheduling): each holds a quarter of the points left per worker, 1..25 of them, so
        the workers finish together instead of one waiting for another's last large batch.
    batch_size : int, optional
        Points per batch (overrides the default).
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


# --------------------------------------------------------------------------- execution options
START_METHODS: tuple[str, ...] = ("fork", "forkserver", "spawn")


@dataclass(frozen=True)
class ExecutionOptions:
    """How to run a study.

    Attributes
    ----------
    workers : int or None
        Local worker processes; None = all cores; 1 = serial in this process.
    scheduler : str or None
        Address of a Dask distributed scheduler (``tcp://host:port``); overrides ``workers``.
    batch_size : int or None
        Points per task; None = about four tasks per worker, at most 25 points each.
    progress : bool
        Show progress on stderr (:func:`seafast.progress.progress`: a bar on a terminal, else a
        plain line every few per cent).
    start_method : str or None
        How local worker processes start: ``fork``, ``forkserver`` or ``spawn``; None = ``fork``
        on Linux when this process runs no other Python thread, else ``forkserver`` where
        available, else ``spawn``.
    """

    workers: int | None = None
    scheduler: str | None = None
    batch_size: int | None = None
    progress: bool = True
    start_method: str | None = None

    def __post_init__(self) -> None:
        if self.start_method is not None and self.start_method not in START_METHODS:
            raise StudyError(f"start_method = {self.start_method!r}; allowed: {', '.join(START_METHODS)} or None (automatic)")

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


# --------------------------------------------------------------------------- back-ends
def _iter_serial(
    grid: PointSource, batches: list[list[int]], evaluator: Evaluator | str | None, keep: bool = False
) -> Iterator[list[PointRecord]]:
    from threadpoolctl import threadpool_limits

    # One BLAS thread here too: the model's matrices are small, and threading them is slower.
    with threadpool_limits(limits=1):
        for batch in batches:
            yield evaluate_batch(grid, batch, evaluator, pin_threads=False, keep_messages=keep)


def _iter_processes(
    grid: PointSource, batches: list[list[int]], evaluator: Evaluator | str | None, workers: int, start_method: str, keep: bool = False
) -> Iterator[list[PointRecord]]:
    if start_method == "fork" and batches and batches[0]:
        # the first point here, before forking: the workers inherit its imports and warm caches
        first, rest = batches[0][:1], batches[0][1:]
        # unpacked, not next(): the generator runs to its end and leaves its thread limit
        (records,) = _iter_serial(grid, [first], evaluator, keep)
        yield records
        batches = ([rest] if rest else []) + batches[1:]
        if not batches:
            return
    context = multiprocessing.get_context(start_method)
    if start_method == "forkserver":
        # the server imports the numerics once; each worker forks from it (no per-worker imports)
        preload = ["seafast.analyses.run", "seafast.studies.execution"]
        if isinstance(evaluator, str) and ":" in evaluator:
            preload.append(evaluator.partition(":")[0])
        context.set_forkserver_preload(preload)
    executor = cf.ProcessPoolExecutor(
        max_workers=min(workers, len(batches)), mp_context=context, initializer=_init_process_worker, initargs=(os.getpid(),)
    )
    try:
        futures = [executor.submit(evaluate_batch, grid, batch, evaluator, True, keep) for batch in batches]
        for future in cf.as_completed(futures):
            yield future.result()
    finally:
        executor.shutdown(wait=True, cancel_futures=True)


def _iter_dask(
    grid: PointSource, batches: list[list[int]], evaluator: Evaluator | str | None, address: str, keep: bool = False
) -> Iterator[list[PointRecord]]:
    from distributed import Client, as_completed

    try:
        client = Client(address, timeout="20s", set_as_default=False)
    except (OSError, TimeoutError, ValueError) as exc:
        raise StudyError(f"--scheduler {address}: cannot connect to a Dask scheduler ({exc})") from None
    try:
        grid_future = client.scatter(grid, broadcast=True, hash=False)
        futures = [client.submit(evaluate_batch, grid_future, batch, evaluator, True, keep, pure=False) for batch in batches]
        for future in as_completed(futures, loop=client.loop):
            yield future.result()
    finally:
        client.close()


def evaluate_batches(
    grid: PointSource,
    batches: list[list[int]],
    evaluator: Evaluator | str | None,
    execution: ExecutionOptions,
    keep_messages: bool = False,
) -> Iterator[list[PointRecord]]:
    """Evaluate batches on the back-end ``execution`` selects; yields each batch's records as it completes.

    Parameters
    ----------
    grid : PointSource
        The points.
    batches : list of list of int
        From :func:`plan_batches`.
    evaluator : callable, str or None
        See :func:`resolve_evaluator`; must be picklable (a module-level function) for the
        spawned-process and Dask back-ends.
    execution : ExecutionOptions
        Serial, local processes or a Dask scheduler.
    keep_messages : bool
        Return each point's log records with its record (see :func:`evaluate_batch`).

    Raises
    ------
    StudyError
        If the Dask scheduler cannot be reached.
    """
    if not batches:
        return iter(())
    mode = execution.mode()
    if mode == "dask":
        assert execution.scheduler is not None
        return _iter_dask(grid, batches, evaluator, execution.scheduler, keep_messages)
    if mode == "processes":
        method = execution.process_start_method()
        logger.debug("local worker processes start by %s", method)
        return _iter_processes(grid, batches, evaluator, execution.worker_count(), method, keep_messages)
    return _iter_serial(grid, batches, evaluator, keep_messages)
