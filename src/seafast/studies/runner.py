"""Running a study: batched evaluation (serial, local processes or Dask) into a resumable store.

The pieces live by concern: :mod:`seafast.studies.execution` (evaluators and their batches on
the shared executor, :mod:`seafast.parallel.executor`), :mod:`seafast.studies.store` (the
study's points in the shared resumable store, :mod:`seafast.parallel.store`) and
:mod:`seafast.studies.assembly` (``study.nc`` and ``study.csv``); this module drives them.

Points are sent to workers in batches; as each batch completes, its records are appended to
``DIR/points.jsonl`` (one JSON object per point, keyed by the point index and the study
fingerprint). A study killed at any moment resumes on the same command: the store is read back
(a torn last line is dropped), finished points are skipped, and ``DIR/study.nc`` /
``DIR/study.csv`` are assembled from the store when every point is done. A directory holding a
different study is refused. A point whose evaluation raises is recorded with its error text;
the study goes on.

Every point is a pure function of its case: the default evaluator starts each nonlinear solve
from the point's own predictor, never from a neighbour's solution, so the results do not depend
on the back-end, the batch plan, the number of workers or a resume (bit for bit on one machine).

Messages: progress through :func:`seafast.parallel.progress.progress` (a bar on a terminal, else a plain
line every few per cent); a point's log records are not printed as it runs, but logged again here
naming the point (index and overrides) when this process logs at DEBUG (``seafast -v study``);
at the end one warning per typed warning kind with the number of points that raised it
(:mod:`seafast.studies.messages`).
"""

from __future__ import annotations

import logging
import time
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path

import xarray as xr

from seafast.config.schema import HEAD_SEAS_DEG
from seafast.parallel.errors import ParallelError
from seafast.parallel.executor import ExecutionOptions, plan_batches
from seafast.parallel.progress import progress
from seafast.studies.assembly import assemble_dataset, write_study_csv, write_study_netcdf
from seafast.studies.execution import Evaluator, default_evaluator, evaluate_batches, resolve_evaluator
from seafast.studies.messages import point_label, points_with_warning, replay_point_messages, warning_count_lines
from seafast.studies.spec import StudyError, StudyGrid
from seafast.studies.store import POINTS_FILE, PointRecord, point_store

logger = logging.getLogger(__name__)

SEA_STATE_EVALUATOR = "seafast.analyses.seastate.study:evaluate_sea_state"
"""The evaluator of studies judged on their sea state (``response: sea_state``)."""

__all__ = ["StudyRun", "run_study", "SEA_STATE_EVALUATOR"]


# --------------------------------------------------------------------------- the driver
@dataclass(frozen=True)
class StudyRun:
    """What :func:`run_study` did.

    Attributes
    ----------
    dataset : xarray.Dataset
        The assembled results (see :func:`assemble_dataset`).
    directory : Path
        Output directory.
    points : int
        Points in the study.
    reused : int
        Points found finished in the store (not recomputed).
    computed : int
        Points evaluated by this run.
    failed : int
        Points recorded with an error.
    seconds : float
        Wall time of this run [s].
    mode : str
        ``serial``, ``processes`` or ``dask``.
    workers : int
        Local processes that evaluated points: 1 serial, the worker count with local processes,
        0 on Dask (the cluster's size is the scheduler's business).
    files : dict
        Written files by role (``netcdf``, ``csv``, ``store``).
    warning_points : dict
        Per typed warning value raised: the number of points that raised it in some row (all
        points of the study, those reused from the store included).
    """

    dataset: xr.Dataset
    directory: Path
    points: int
    reused: int
    computed: int
    failed: int
    seconds: float
    mode: str
    files: dict[str, Path] = field(default_factory=dict)
    workers: int = 1
    warning_points: dict[str, int] = field(default_factory=dict)

    @property
    def points_per_second(self) -> float:
        """Evaluated points per second of wall time in this run."""
        return self.computed / self.seconds if self.seconds > 0 else float("nan")


HEADING_KEY = "wave.heading_deg"
SEA_STATE_HEADING_KEY = "sea_state.heading_deg"


@dataclass(frozen=True)
class _OffHeadSeas:
    """Whether a point of ``grid`` lies off head seas (its ``key``, the regular wave's or the sea state's heading):
    the default and the sea-state evaluators record its cargo on its cradles there."""

    grid: StudyGrid
    key: str = HEADING_KEY

    def __call__(self, index: int) -> bool:
        try:
            heading = self.grid.point_overrides(index).get(self.key, self.grid.base_value(self.key))
            return float(heading) != HEAD_SEAS_DEG
        except Exception:  # noqa: BLE001 - an invalid point: its record holds its error
            return False


def _cradle_points(grid: StudyGrid, evaluator: Evaluator | str | None) -> _OffHeadSeas | None:
    """Which points the evaluator records with the cargo on its cradles (a stored point of them without: recomputed);
    None for a plug-in evaluator (no cradles)."""
    resolved = resolve_evaluator(evaluator)
    if resolved is default_evaluator:
        return _OffHeadSeas(grid)
    if resolved is resolve_evaluator(SEA_STATE_EVALUATOR):
        return _OffHeadSeas(grid, SEA_STATE_HEADING_KEY)
    return None


def _replay(grid: StudyGrid, records: list[PointRecord]) -> None:
    """Log the captured messages of freshly computed points again, each naming its point."""
    for record in records:
        if record.messages:
            try:
                label = point_label(record.index, grid.point_overrides(record.index))
            except Exception:  # noqa: BLE001 - an invalid point's overrides: its index still names it
                label = f"point {record.index}"
            replay_point_messages(label, record.messages)


def run_study(
    grid: StudyGrid,
    directory: str | Path,
    *,
    evaluator: Evaluator | str | None = None,
    execution: ExecutionOptions = ExecutionOptions(),
) -> StudyRun:
    """Run (or resume) a study and write ``study.nc`` and ``study.csv``.

    Parameters
    ----------
    grid : StudyGrid
        The study (:func:`seafast.studies.spec.build_grid`).
    directory : str or Path
        Output directory; holds the resumable store ``points.jsonl``.
    evaluator : callable, str or None
        Per-point evaluator (see :func:`resolve_evaluator`); must be picklable (a module-level
        function) for the process and Dask back-ends. None: the sea-state evaluator
        (:data:`SEA_STATE_EVALUATOR`) for a study judged on its sea state, else the default.
    execution : ExecutionOptions
        Serial, local processes (default, all cores) or a Dask scheduler address.

    Returns
    -------
    StudyRun

    Raises
    ------
    StudyError
        If the directory holds a different study, or the scheduler cannot be reached.
    """
    t0 = time.perf_counter()
    out = Path(directory)
    if evaluator is None and grid.spec.evaluates_sea_state:
        evaluator = SEA_STATE_EVALUATOR
    if isinstance(evaluator, str):
        resolve_evaluator(evaluator)  # fail early on a bad reference
    try:
        with point_store(out, grid, cradle_points=_cradle_points(grid, evaluator)) as store:
            reused = len(store.completed)
            pending = store.pending(grid.size)
            mode = execution.mode()
            workers = execution.worker_count() if mode == "processes" else 1
            batches = plan_batches(pending, workers if mode != "dask" else max(2, workers), execution.batch_size)
            computed = 0
            logger.info(
                "study '%s': %d points, %d already stored in %s, %d to compute (%s)",
                grid.spec.name,
                grid.size,
                reused,
                out,
                len(pending),
                mode,
            )
            keep = logging.getLogger("seafast").isEnabledFor(logging.DEBUG)  # point messages wanted (seafast -v)
            stream: Iterator[list[PointRecord]] = evaluate_batches(grid, batches, evaluator, execution, keep)
            bar = progress(grid.size, reused, label=f"study {grid.spec.name}", unit="points", enabled=execution.progress and bool(pending))
            try:
                for batch in stream:
                    added = store.append(batch)
                    computed += added
                    _replay(grid, batch)
                    bar.update(added)
            finally:
                bar.close()
            records = dict(sorted(store.completed.items()))
    except ParallelError as exc:  # e.g. an unreachable scheduler: a study's error, as its other input errors
        raise StudyError(str(exc)) from None
    dataset = assemble_dataset(grid, records)
    files = {
        "netcdf": write_study_netcdf(out / "study.nc", dataset),
        "csv": write_study_csv(out / "study.csv", grid, records),
        "store": out / POINTS_FILE,
    }
    failed = sum(1 for r in records.values() if r.error)
    logger.info("study '%s': %d computed, %d failed, %.1f s", grid.spec.name, computed, failed, time.perf_counter() - t0)
    counts = points_with_warning(records.values())
    for line in warning_count_lines(counts, grid.size):
        logger.warning("%s", line)
    return StudyRun(
        dataset, out, grid.size, reused, computed, failed, time.perf_counter() - t0, mode, files, 0 if mode == "dask" else workers, counts
    )
