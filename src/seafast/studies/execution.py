"""Evaluating study points: evaluators, batches of points, and their run on the shared executor.

Every point is evaluated by an *evaluator* ``Callable[[Case], list[dict]]`` (default
:func:`seafast.analyses.run.evaluate_summary`, imported lazily) returning one row per load case and
model. Points travel to workers in batches (:func:`seafast.parallel.executor.plan_batches`);
:func:`evaluate_batches` yields each batch's :class:`~seafast.studies.store.PointRecord` list as
it completes, on the back-end the :class:`~seafast.parallel.executor.ExecutionOptions` select
(serial, local worker processes, Dask: :func:`seafast.parallel.executor.map_batches`, which
also pins each worker to one BLAS thread). A point whose evaluation raises is recorded with its
error text; a row's typed warnings are stored as their values, and the log records of a point
are captured, not printed (:mod:`seafast.studies.messages`).

The points can be anything with ``size`` and ``point_case(index)`` (:class:`PointSource`), e.g.
a :class:`~seafast.studies.spec.StudyGrid`. Forked local workers start after this process has
evaluated the study's first point, so they inherit the caches it warmed (vessel excitation,
hydrodynamic coefficients, cargo mesh).
"""

from __future__ import annotations

import importlib
import os
import time
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass
from typing import Any, Protocol

from seafast.config.schema import Case
from seafast.excitation.vessel import VesselCache
from seafast.model.cache import ModelCache
from seafast.parallel.executor import ExecutionOptions, error_text, map_batches
from seafast.studies.messages import point_log
from seafast.studies.spec import StudyError
from seafast.studies.store import PointRecord, stored_row

__all__ = [
    "Evaluator",
    "EVALUATOR_ENV",
    "PointSource",
    "default_evaluator",
    "resolve_evaluator",
    "evaluate_batch",
    "evaluate_batches",
]

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


_POINT_VESSELS = VesselCache()
"""The vessel excitations this process keeps for the study points it evaluates (with the hull forms and BEM
data behind them), shared with the evaluator while a batch runs (:meth:`VesselCache.shared`): a study over
the sea-fastening computes its vessel once per process, one over the cargo reads the BEM data once. A forked
worker inherits it warm from the coordinator's first point."""

_POINT_MODELS = ModelCache()
"""The cargo beams and Rayleigh fits this process keeps for the study points it evaluates, shared as
:data:`_POINT_VESSELS` is: along a stiffness axis the mesh is built once, along a pretension axis the fit too."""


def evaluate_batch(
    grid: PointSource,
    indices: Sequence[int],
    evaluator: Evaluator | str | None = None,
    keep_messages: bool = False,
) -> list[PointRecord]:
    """Evaluate a batch of points (in a worker, or in this process).

    Parameters
    ----------
    grid : PointSource
        The study (e.g. a :class:`~seafast.studies.spec.StudyGrid`).
    indices : sequence of int
        Flat point indices.
    evaluator : callable, str or None
        See :func:`resolve_evaluator`.
    keep_messages : bool
        Return each point's log records with its record (:func:`seafast.studies.messages.point_log`);
        False: they are dropped. Either way nothing is printed while a point runs.

    Returns
    -------
    list of PointRecord
        One per index, in order; a point that raised carries its error text. Each row holds
        ``warnings``, the list of its typed warnings' values (empty when none).
    """
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
                rows, error = (), error_text(exc)
        records.append(PointRecord(int(index), rows, error, time.perf_counter() - t0, tuple(messages)))
    return records


@dataclass(frozen=True)
class _StudyJob:
    """What every batch of a study shares: the points, the evaluator and whether to keep the points' messages."""

    grid: PointSource
    evaluator: Evaluator | str | None
    keep_messages: bool


def _evaluate_job(job: _StudyJob, indices: list[int]) -> list[PointRecord]:
    return evaluate_batch(job.grid, indices, job.evaluator, job.keep_messages)


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
        From :func:`seafast.parallel.executor.plan_batches`.
    evaluator : callable, str or None
        See :func:`resolve_evaluator`; must be picklable (a module-level function) for the
        spawned-process and Dask back-ends.
    execution : ExecutionOptions
        Serial, local processes or a Dask scheduler.
    keep_messages : bool
        Return each point's log records with its record (see :func:`evaluate_batch`).

    Raises
    ------
    seafast.parallel.errors.ParallelError
        If the Dask scheduler cannot be reached.
    """
    # a forkserver imports the numerics once (and a plug-in evaluator's module)
    preload = ["seafast.analyses.run"]
    if isinstance(evaluator, str) and ":" in evaluator:
        preload.append(evaluator.partition(":")[0])
    return map_batches(_evaluate_job, _StudyJob(grid, evaluator, keep_messages), batches, execution, preload=preload)
