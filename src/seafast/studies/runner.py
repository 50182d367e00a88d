"""Running a study: batched evaluation (serial, local processes or Dask) into a resumable store.

Every point is evaluated by an *evaluator* ``Callable[[Case], list[dict]]`` (default
:func:`seafast.pipeline.evaluate_summary`, imported lazily) returning one row per load case
(``static``, ``dynamic``) and model (``linear``, ``nonlinear``). Points are sent to workers in
batches; as each batch completes, its records are appended to ``DIR/points.jsonl`` (one JSON
object per point, keyed by the point index and the study fingerprint) and fsync'ed. A study killed
at any moment resumes on the same command: the store is read back (a torn last line is dropped),
finished points are skipped, and ``DIR/study.nc`` / ``DIR/study.csv`` are assembled from the store
when every point is done. A directory holding a different study is refused.

A point whose evaluation raises is recorded with its error text; the study goes on.
"""

from __future__ import annotations

import concurrent.futures as cf
import csv
import importlib
import json
import logging
import math
import multiprocessing
import os
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, Iterable, Iterator, Sequence

import numpy as np
import xarray as xr

from seafast.config.schema import Case
from seafast.studies.spec import StudyError, StudyGrid, units_of_key

__all__ = [
    "Evaluator",
    "ExecutionOptions",
    "PointRecord",
    "PointStore",
    "StudyRun",
    "CORE_COLUMNS",
    "LOAD_CASES",
    "MODELS",
    "EVALUATOR_ENV",
    "default_evaluator",
    "resolve_evaluator",
    "evaluate_batch",
    "plan_batches",
    "run_study",
    "assemble_dataset",
    "study_rows",
    "write_study_csv",
    "write_study_netcdf",
]

logger = logging.getLogger(__name__)

Evaluator = Callable[[Case], list[dict]]

#: Environment variable naming an alternative evaluator as ``module:function`` (testing, plug-ins).
EVALUATOR_ENV = "SEAFAST_STUDY_EVALUATOR"

LOAD_CASES: tuple[str, ...] = ("static", "dynamic")
MODELS: tuple[str, ...] = ("linear", "nonlinear")

#: Columns of ``study.csv`` after the study's dotted keys (INTERFACE.md).
CORE_COLUMNS: tuple[str, ...] = (
    "load_case",
    "model",
    "u_c_m",
    "u_s_m",
    "u_d_m",
    "F_N",
    "M_b_Nm",
    "sigma_b_Pa",
    "converged",
    "contact_preserved",
)
_FLOAT_RESULTS: tuple[str, ...] = ("u_c_m", "u_s_m", "u_d_m", "F_N", "M_b_Nm", "sigma_b_Pa")
_BOOL_RESULTS: tuple[str, ...] = ("converged", "contact_preserved")
_LONG_NAMES: dict[str, str] = {
    "u_c_m": "maximum cargo deflection u_c",
    "u_s_m": "maximum saddle compression u_s",
    "u_d_m": "maximum detachment (gap) u_d (nonlinear model only)",
    "F_N": "maximum saddle normal force F",
    "M_b_Nm": "maximum cargo bending moment M_b",
    "sigma_b_Pa": "maximum cargo bending stress sigma_b = M_b (D/2) / I",
    "converged": "nonlinear solver converged",
    "contact_preserved": "contact preserved at every saddle over the whole period (linear model valid)",
    "residual_norm": "final residual norm of the nonlinear solver",
    "iterations": "nonlinear solver iterations",
    "error": "error text of a point whose evaluation failed (empty when it succeeded)",
    "eval_seconds": "wall time to evaluate the point",
}


# --------------------------------------------------------------------------- evaluators
def default_evaluator(case: Case) -> list[dict]:
    """Evaluate one case with :func:`seafast.pipeline.evaluate_summary` (imported on first use)."""
    from seafast.pipeline import evaluate_summary

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


# --------------------------------------------------------------------------- per-point work
@dataclass(frozen=True)
class PointRecord:
    """The outcome of one study point.

    Attributes
    ----------
    index : int
        Flat (C-order) index of the point in the grid.
    rows : tuple of dict
        The evaluator's rows (empty when the point failed).
    error : str
        Error text, empty when the evaluation succeeded.
    seconds : float
        Wall time of the evaluation [s].
    """

    index: int
    rows: tuple[dict, ...] = ()
    error: str = ""
    seconds: float = 0.0

    def to_json(self, fingerprint: str) -> str:
        """One line of ``points.jsonl`` (no newline)."""
        return json.dumps(
            {"study": fingerprint, "index": self.index, "rows": list(self.rows), "error": self.error, "seconds": self.seconds},
            separators=(",", ":"),
            allow_nan=True,
        )

    @staticmethod
    def from_json(data: dict) -> "PointRecord":
        """Inverse of :meth:`to_json` (already parsed)."""
        return PointRecord(int(data["index"]), tuple(data.get("rows") or ()), str(data.get("error") or ""), float(data.get("seconds", 0.0)))


def _plain(value: Any) -> Any:
    """A JSON-compatible Python scalar (numpy scalars unwrapped)."""
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, (bool, int, float, str)) or value is None:
        return value
    if isinstance(value, np.ndarray) and value.size == 1:
        return value.item()
    return str(value)


_worker_ready = False


def _prepare_worker() -> None:
    """Once per worker process: one BLAS/OpenMP thread (the parallelism is across points)."""
    global _worker_ready
    if _worker_ready:
        return
    for var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "NUMEXPR_NUM_THREADS"):
        os.environ[var] = "1"
    try:
        from threadpoolctl import threadpool_limits

        threadpool_limits(limits=1)
    except Exception:  # pragma: no cover - threadpoolctl is a dependency; be lenient anyway
        pass
    _worker_ready = True


def _exit_with_parent(parent_pid: int, interval_s: float = 0.25) -> None:
    """Exit this worker when its parent is gone (e.g. the study was killed with SIGKILL)."""
    import threading

    def watch() -> None:
        while True:
            time.sleep(interval_s)
            if os.getppid() != parent_pid:
                os._exit(1)

    threading.Thread(target=watch, name="seafast-parent-watch", daemon=True).start()


def _init_process_worker(parent_pid: int) -> None:
    """Initializer of local worker processes: one BLAS thread; exit with the parent."""
    _prepare_worker()
    _exit_with_parent(parent_pid)


def evaluate_batch(grid: StudyGrid, indices: Sequence[int], evaluator: Evaluator | str | None = None, pin_threads: bool = True) -> list[PointRecord]:
    """Evaluate a batch of points (runs in a worker).

    Parameters
    ----------
    grid : StudyGrid
        The study.
    indices : sequence of int
        Flat point indices.
    evaluator : callable, str or None
        See :func:`resolve_evaluator`.
    pin_threads : bool
        Limit BLAS/OpenMP to one thread in this process (workers; not the serial runner).

    Returns
    -------
    list of PointRecord
        One per index, in order; a point that raised carries its error text.
    """
    if pin_threads:
        _prepare_worker()
    func = resolve_evaluator(evaluator)
    records = []
    for index in indices:
        t0 = time.perf_counter()
        try:
            case = grid.point_case(int(index))
            rows = tuple({k: _plain(v) for k, v in row.items()} for row in func(case))
            records.append(PointRecord(int(index), rows, "", time.perf_counter() - t0))
        except Exception as exc:  # noqa: BLE001 - any failure of one point is recorded, the study goes on
            text = " ".join(str(exc).split()) or "(no message)"
            records.append(PointRecord(int(index), (), f"{type(exc).__name__}: {text}", time.perf_counter() - t0))
    return records


def plan_batches(pending: Sequence[int], workers: int, batch_size: int | None = None) -> list[list[int]]:
    """Split pending point indices into batches (tasks).

    Parameters
    ----------
    pending : sequence of int
        Indices still to evaluate.
    workers : int
        Parallel workers; by default about four batches per worker, 1..25 points each.
    batch_size : int, optional
        Points per batch (overrides the default).
    """
    if not pending:
        return []
    size = batch_size or max(1, min(25, math.ceil(len(pending) / (4 * max(1, workers)))))
    return [list(pending[i : i + size]) for i in range(0, len(pending), size)]


# --------------------------------------------------------------------------- the store
class PointStore:
    """Append-only JSON-lines store of finished points in a study directory.

    ``DIR/study.json`` identifies the study (name, fingerprint, grid); ``DIR/points.jsonl`` holds
    one record per finished point. Only the coordinating process writes.

    Parameters
    ----------
    directory : Path
        The study's output directory (created if needed).
    grid : StudyGrid
        The study; a directory holding another study (other fingerprint) is refused.

    Raises
    ------
    StudyError
        If the directory holds a different study.
    """

    MANIFEST = "study.json"
    POINTS = "points.jsonl"

    def __init__(self, directory: Path, grid: StudyGrid) -> None:
        self.directory = Path(directory)
        self.fingerprint = grid.fingerprint()
        self.size = grid.size
        self.directory.mkdir(parents=True, exist_ok=True)
        self._check_manifest(grid)
        self.completed: dict[int, PointRecord] = self._read_points()
        self._handle = open(self.path, "ab")

    @property
    def path(self) -> Path:
        """``DIR/points.jsonl``."""
        return self.directory / self.POINTS

    def _check_manifest(self, grid: StudyGrid) -> None:
        manifest = self.directory / self.MANIFEST
        if manifest.exists():
            try:
                held = json.loads(manifest.read_text(encoding="utf-8"))
            except (OSError, ValueError):
                held = {}
            if held.get("fingerprint") != self.fingerprint:
                raise StudyError(
                    f"output directory '{self.directory}' holds a different study ('{held.get('name', '?')}', fingerprint "
                    f"{held.get('fingerprint', '?')}) from this '{grid.spec.name}' (fingerprint {self.fingerprint}; the "
                    "fingerprint covers the base case with its overrides, the axes and the derived keys); "
                    "allowed: the same study (to resume) or an empty directory; choose another -o DIR"
                )
            return
        content = {
            "name": grid.spec.name,
            "fingerprint": self.fingerprint,
            "shape": list(grid.shape),
            "axes": {k: c.tolist() for k, c in zip(grid.keys, grid.coordinates)},
            "spec": grid.spec.model_dump(mode="json"),
        }
        tmp = manifest.with_suffix(".json.tmp")
        tmp.write_text(json.dumps(content, indent=1), encoding="utf-8")
        os.replace(tmp, manifest)

    def _read_points(self) -> dict[int, PointRecord]:
        if not self.path.exists():
            return {}
        data = self.path.read_bytes()
        end = data.rfind(b"\n") + 1  # bytes after the last newline are a torn record
        completed: dict[int, PointRecord] = {}
        for line in data[:end].splitlines():
            if not line.strip():
                continue
            try:
                raw = json.loads(line)
            except ValueError:
                continue  # a damaged record: its point is recomputed
            if raw.get("study") != self.fingerprint:
                raise StudyError(
                    f"'{self.path}' holds points of another study (fingerprint {raw.get('study')}, "
                    f"this study {self.fingerprint}); choose another -o DIR"
                )
            record = PointRecord.from_json(raw)
            if 0 <= record.index < self.size:
                completed[record.index] = record
        if end < len(data):
            with open(self.path, "r+b") as fh:
                fh.truncate(end)
                fh.flush()
                os.fsync(fh.fileno())
        return completed

    def append(self, records: Iterable[PointRecord]) -> int:
        """Append records durably (one write, flush, fsync); returns how many were new."""
        fresh = [r for r in records if r.index not in self.completed]
        if not fresh:
            return 0
        payload = "".join(r.to_json(self.fingerprint) + "\n" for r in fresh).encode("utf-8")
        self._handle.write(payload)
        self._handle.flush()
        os.fsync(self._handle.fileno())
        for r in fresh:
            self.completed[r.index] = r
        return len(fresh)

    def pending(self) -> list[int]:
        """Indices not yet in the store, ascending."""
        return [i for i in range(self.size) if i not in self.completed]

    def close(self) -> None:
        """Close the append handle."""
        self._handle.close()

    def __enter__(self) -> "PointStore":
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


# --------------------------------------------------------------------------- execution back-ends
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
        Show a progress bar on stderr (only when stderr is a terminal).
    """

    workers: int | None = None
    scheduler: str | None = None
    batch_size: int | None = None
    progress: bool = True

    def worker_count(self) -> int:
        """Number of local workers."""
        return max(1, self.workers if self.workers is not None else (os.cpu_count() or 1))

    def mode(self) -> str:
        """``'dask'``, ``'processes'`` or ``'serial'``."""
        if self.scheduler:
            return "dask"
        return "serial" if self.worker_count() == 1 else "processes"


def _iter_serial(grid: StudyGrid, batches: list[list[int]], evaluator: Evaluator | str | None) -> Iterator[list[PointRecord]]:
    from threadpoolctl import threadpool_limits

    # One BLAS thread here too: the model's matrices are small, and threading them is slower.
    with threadpool_limits(limits=1):
        for batch in batches:
            yield evaluate_batch(grid, batch, evaluator, pin_threads=False)


def _iter_processes(grid: StudyGrid, batches: list[list[int]], evaluator: Evaluator | str | None, workers: int) -> Iterator[list[PointRecord]]:
    context = multiprocessing.get_context("spawn")
    executor = cf.ProcessPoolExecutor(
        max_workers=min(workers, len(batches)), mp_context=context, initializer=_init_process_worker, initargs=(os.getpid(),)
    )
    try:
        futures = [executor.submit(evaluate_batch, grid, batch, evaluator) for batch in batches]
        for future in cf.as_completed(futures):
            yield future.result()
    finally:
        executor.shutdown(wait=True, cancel_futures=True)


def _iter_dask(grid: StudyGrid, batches: list[list[int]], evaluator: Evaluator | str | None, address: str) -> Iterator[list[PointRecord]]:
    from distributed import Client, as_completed

    try:
        client = Client(address, timeout="20s", set_as_default=False)
    except (OSError, TimeoutError, ValueError) as exc:
        raise StudyError(f"--scheduler {address}: cannot connect to a Dask scheduler ({exc})") from None
    try:
        grid_future = client.scatter(grid, broadcast=True, hash=False)
        futures = [client.submit(evaluate_batch, grid_future, batch, evaluator, pure=False) for batch in batches]
        for future in as_completed(futures, loop=client.loop):
            yield future.result()
    finally:
        client.close()


# --------------------------------------------------------------------------- assembly
def _axis_columns(grid: StudyGrid) -> list[str]:
    return list(grid.keys)


def _labels(records: Iterable[PointRecord], key: str, canonical: tuple[str, ...]) -> list[str]:
    seen = list(canonical)
    for r in records:
        for row in r.rows:
            v = row.get(key)
            if isinstance(v, str) and v not in seen:
                seen.append(v)
    return seen


def _extra_keys(records: Iterable[PointRecord]) -> list[str]:
    core = set(CORE_COLUMNS)
    extras: list[str] = []
    for r in records:
        for row in r.rows:
            for k in row:
                if k not in core and k not in extras:
                    extras.append(k)
    return extras


def _derived_values(grid: StudyGrid) -> dict[str, np.ndarray]:
    """Per-point values of the derived keys, over the study dimensions."""
    out: dict[str, np.ndarray] = {}
    if not grid.spec.derived:
        return out
    arrays = {k: np.full(grid.size, np.nan) for k in grid.spec.derived}
    for i in range(grid.size):
        try:
            overrides = grid.point_overrides(i)
        except Exception:  # noqa: BLE001 - the point's own record carries the error
            continue
        for k in arrays:
            arrays[k][i] = float(overrides[k])
    for k, a in arrays.items():
        out[k] = a.reshape(grid.shape)
    return out


def assemble_dataset(grid: StudyGrid, records: dict[int, PointRecord]) -> xr.Dataset:
    """The study's labelled results.

    Parameters
    ----------
    grid : StudyGrid
        The study.
    records : dict of int to PointRecord
        Finished points by flat index (missing points are left NaN with error ``"not evaluated"``).

    Returns
    -------
    xarray.Dataset
        Dimensions: the axis keys (dotted names), ``load_case`` (static, dynamic) and ``model``
        (linear, nonlinear). Variables ``u_c_m, u_s_m, u_d_m, F_N, M_b_Nm, sigma_b_Pa`` (float,
        NaN where missing), ``converged`` and ``contact_preserved`` (bool, False where missing),
        numeric diagnostics (e.g. ``residual_norm``, ``iterations``), ``error`` (str per point)
        and ``eval_seconds``; each with ``units`` and ``long_name``.
    """
    values = list(records.values())
    load_cases = _labels(values, "load_case", LOAD_CASES)
    models = _labels(values, "model", MODELS)
    extras = _extra_keys(values)
    numeric_extras = [
        k for k in extras if all(isinstance(row.get(k), (int, float, bool)) or row.get(k) is None for r in values for row in r.rows)
    ]
    text_extras = [k for k in extras if k not in numeric_extras]
    n, nl, nm = grid.size, len(load_cases), len(models)
    floats = {k: np.full((n, nl, nm), np.nan) for k in (*_FLOAT_RESULTS, *numeric_extras)}
    bools = {k: np.zeros((n, nl, nm), dtype=bool) for k in _BOOL_RESULTS}
    texts = {k: np.full((n, nl, nm), "", dtype=object) for k in text_extras}
    error = np.full(n, "not evaluated", dtype=object)
    seconds = np.full(n, np.nan)
    lc_index = {v: i for i, v in enumerate(load_cases)}
    m_index = {v: i for i, v in enumerate(models)}
    for index, record in records.items():
        error[index] = record.error
        seconds[index] = record.seconds
        for row in record.rows:
            li, mi = lc_index.get(row.get("load_case")), m_index.get(row.get("model"))
            if li is None or mi is None:
                continue
            for k, a in floats.items():
                v = row.get(k)
                if isinstance(v, (int, float)) and v is not None:
                    a[index, li, mi] = float(v)
            for k, a in bools.items():
                a[index, li, mi] = bool(row.get(k, False))
            for k, a in texts.items():
                a[index, li, mi] = "" if row.get(k) is None else str(row.get(k))
    dims = (*grid.keys, "load_case", "model")
    shape = (*grid.shape, nl, nm)
    data_vars: dict[str, Any] = {}
    for k, a in floats.items():
        data_vars[k] = (dims, a.reshape(shape), {"units": units_of_key(k), "long_name": _LONG_NAMES.get(k, k)})
    for k, a in bools.items():
        data_vars[k] = (dims, a.reshape(shape), {"units": "1", "long_name": _LONG_NAMES[k]})
    for k, a in texts.items():
        data_vars[k] = (dims, a.reshape(shape).astype(str), {"units": "1", "long_name": k})
    data_vars["error"] = (grid.keys, error.reshape(grid.shape).astype(str), {"units": "1", "long_name": _LONG_NAMES["error"]})
    data_vars["eval_seconds"] = (grid.keys, seconds.reshape(grid.shape), {"units": "s", "long_name": _LONG_NAMES["eval_seconds"]})
    coords: dict[str, Any] = {}
    for axis, key, c in zip(grid.spec.axes, grid.keys, grid.coordinates):
        try:
            base_value = float(grid.base_value(key))
        except (StudyError, TypeError, ValueError):
            base_value = float("nan")
        coords[key] = (key, c, {"units": units_of_key(key), "long_name": key, "scale": axis.scale, "base_value": base_value})
    for key, a in _derived_values(grid).items():
        coords[key] = (grid.keys, a, {"units": units_of_key(key), "long_name": f"{key} = {grid.spec.derived[key]}"})
    coords["load_case"] = ("load_case", np.array(load_cases, dtype=str), {"long_name": "load case (dynamic = total response)"})
    coords["model"] = ("model", np.array(models, dtype=str), {"long_name": "response model"})
    base_counts = "seafastening.saddle_count" not in grid.keys
    attrs = {
        "study": grid.spec.name,
        "description": grid.spec.description,
        "fingerprint": grid.fingerprint(),
        "axes": " ".join(grid.keys),
        "study_spec_json": json.dumps(grid.spec.model_dump(mode="json")),
        "base_case_json": json.dumps(grid.base),
        "max_saddle_force_N": grid.spec.limits.max_saddle_force_N,
        "max_bending_stress_Pa": grid.spec.limits.max_bending_stress_Pa,
        "points": grid.size,
        "failed_points": int(sum(1 for r in records.values() if r.error)),
    }
    if base_counts:
        attrs["saddle_count"] = int(grid.base["seafastening"]["saddle_count"])
    return xr.Dataset(data_vars, coords=coords, attrs=attrs)


def _csv_value(value: Any) -> Any:
    if value is None:
        return ""
    if isinstance(value, float) and math.isnan(value):
        return ""
    return value


def study_rows(grid: StudyGrid, records: dict[int, PointRecord]) -> tuple[list[str], list[list[Any]]]:
    """Header and rows of ``study.csv``: one row per point, load case and model.

    Columns: the study's dotted keys, then ``load_case, model, u_c_m, u_s_m, u_d_m, F_N,
    M_b_Nm, sigma_b_Pa, converged, contact_preserved``, then the evaluator's diagnostics, the
    derived keys and ``error``. A failed point has empty result cells and its error text.
    """
    values = list(records.values())
    load_cases = _labels(values, "load_case", LOAD_CASES)
    models = _labels(values, "model", MODELS)
    extras = _extra_keys(values)
    derived = list(grid.spec.derived)
    header = [*_axis_columns(grid), *CORE_COLUMNS, *extras, *derived, "error"]
    derived_values = _derived_values(grid)
    rows: list[list[Any]] = []
    for index in range(grid.size):
        point = grid.point_values(index)
        record = records.get(index, PointRecord(index, (), "not evaluated"))
        by_label = {(r.get("load_case"), r.get("model")): r for r in record.rows}
        multi = np.unravel_index(index, grid.shape)
        dvals = [_csv_value(float(derived_values[k][multi])) for k in derived]
        for lc in load_cases:
            for m in models:
                row = by_label.get((lc, m), {})
                cells: list[Any] = [point[k] for k in grid.keys]
                cells += [lc, m]
                cells += [_csv_value(row.get(k)) for k in CORE_COLUMNS[2:]]
                cells += [_csv_value(row.get(k)) for k in extras]
                cells += dvals
                cells.append(record.error)
                rows.append(cells)
    return header, rows


def _csv_text(value: Any) -> Any:
    """CSV cell text: booleans as true/false (as summary.csv), floats round-trip exact."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return repr(value)
    return value


def _atomic_path(path: Path) -> Path:
    return path.with_name(path.name + ".tmp")


def write_study_csv(path: Path, grid: StudyGrid, records: dict[int, PointRecord]) -> Path:
    """Write ``study.csv`` atomically; returns its path."""
    header, rows = study_rows(grid, records)
    tmp = _atomic_path(path)
    with open(tmp, "w", newline="", encoding="utf-8") as fh:
        writer = csv.writer(fh, lineterminator="\n")
        writer.writerow(header)
        for row in rows:
            writer.writerow([_csv_text(v) for v in row])
    os.replace(tmp, path)
    return path


def write_study_netcdf(path: Path, dataset: xr.Dataset) -> Path:
    """Write ``study.nc`` atomically; returns its path."""
    tmp = _atomic_path(path)
    dataset.to_netcdf(tmp)
    os.replace(tmp, path)
    return path


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
    files : dict
        Written files by role (``netcdf``, ``csv``, ``store``).
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

    @property
    def points_per_second(self) -> float:
        """Evaluated points per second of wall time in this run."""
        return self.computed / self.seconds if self.seconds > 0 else float("nan")


def _progress_bar(total: int, initial: int, enabled: bool, label: str) -> Any:
    from tqdm import tqdm

    show = enabled and hasattr(sys.stderr, "isatty") and sys.stderr.isatty()
    return tqdm(total=total, initial=initial, disable=not show, file=sys.stderr, unit="pt", desc=label, dynamic_ncols=True)


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
        function) for the process and Dask back-ends.
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
    if isinstance(evaluator, str):
        resolve_evaluator(evaluator)  # fail early on a bad reference
    with PointStore(out, grid) as store:
        reused = len(store.completed)
        pending = store.pending()
        mode = execution.mode()
        workers = execution.worker_count() if mode == "processes" else 1
        batches = plan_batches(pending, workers if mode != "dask" else max(2, workers), execution.batch_size)
        computed = 0
        logger.info(
            "study '%s': %d points, %d already stored in %s, %d to compute (%s)", grid.spec.name, grid.size, reused, out, len(pending), mode
        )
        bar = _progress_bar(grid.size, reused, execution.progress, grid.spec.name)
        try:
            if not batches:
                stream: Iterator[list[PointRecord]] = iter(())
            elif mode == "dask":
                assert execution.scheduler is not None
                stream = _iter_dask(grid, batches, evaluator, execution.scheduler)
            elif mode == "processes":
                stream = _iter_processes(grid, batches, evaluator, workers)
            else:
                stream = _iter_serial(grid, batches, evaluator)
            for records in stream:
                added = store.append(records)
                computed += added
                bar.update(added)
        finally:
            bar.close()
        records = dict(sorted(store.completed.items()))
    dataset = assemble_dataset(grid, records)
    files = {
        "netcdf": write_study_netcdf(out / "study.nc", dataset),
        "csv": write_study_csv(out / "study.csv", grid, records),
        "store": out / PointStore.POINTS,
    }
    failed = sum(1 for r in records.values() if r.error)
    logger.info("study '%s': %d computed, %d failed, %.1f s", grid.spec.name, computed, failed, time.perf_counter() - t0)
    return StudyRun(dataset, out, grid.size, reused, computed, failed, time.perf_counter() - t0, mode, files)
