"""A resumable store of independent tasks' results, and the local/Dask execution that feeds it.

Why not ``studies/runner.py``'s ``PointStore``: it is bound to a study grid (its manifest holds
the grid's axes); this is the same design for any indexed tasks (Monte Carlo realisations):
``DIR/manifest.json`` identifies the run by a fingerprint, ``DIR/records.jsonl`` holds one JSON
object per finished task, appended, flushed and fsync'ed as each task finishes. A run killed at
any moment resumes: the store is read back (a torn last line is dropped and truncated), finished
tasks are skipped, nothing is duplicated. A directory holding another run is refused.

Execution back-ends: serial in this process, local worker processes (spawned, one BLAS thread
each, exiting with their parent), or a Dask distributed scheduler. The task function and its
shared argument must be picklable.
"""

from __future__ import annotations

import concurrent.futures as cf
import json
import multiprocessing
import os
import threading
import time
from collections.abc import Callable, Iterable, Iterator
from pathlib import Path
from typing import Any

__all__ = ["StoreError", "TaskStore", "run_tasks"]


class StoreError(ValueError):
    """The output directory holds another run, or a scheduler cannot be reached."""


class TaskStore:
    """Append-only JSON-lines store of finished tasks (records with an integer ``index``).

    Parameters
    ----------
    directory
        Where ``manifest.json`` and ``records.jsonl`` live (created if needed).
    fingerprint
        Identifies the run; a directory with another fingerprint is refused.
    manifest
        What the manifest records besides the fingerprint (JSON-serialisable).
    """

    MANIFEST = "manifest.json"
    RECORDS = "records.jsonl"

    def __init__(self, directory: str | Path, fingerprint: str, manifest: dict[str, Any]) -> None:
        self.directory = Path(directory)
        self.fingerprint = str(fingerprint)
        self.directory.mkdir(parents=True, exist_ok=True)
        self._check_manifest(manifest)
        self.completed: dict[int, dict[str, Any]] = self._read()
        self._handle = open(self.path, "ab")  # noqa: SIM115 - appended to until close() / __exit__

    @property
    def path(self) -> Path:
        """``DIR/records.jsonl``."""
        return self.directory / self.RECORDS

    def _check_manifest(self, manifest: dict[str, Any]) -> None:
        path = self.directory / self.MANIFEST
        if path.exists():
            try:
                held = json.loads(path.read_text(encoding="utf-8"))
            except (OSError, ValueError):
                held = {}
            if held.get("fingerprint") != self.fingerprint:
                raise StoreError(
                    f"output directory '{self.directory}' holds another run (fingerprint {held.get('fingerprint', '?')}, "
                    f"this run {self.fingerprint}); allowed: the same run (to resume) or an empty directory; choose another -o DIR"
                )
            return
        tmp = path.with_suffix(".json.tmp")
        tmp.write_text(json.dumps({"fingerprint": self.fingerprint, **manifest}, indent=1), encoding="utf-8")
        os.replace(tmp, path)

    def _read(self) -> dict[int, dict[str, Any]]:
        if not self.path.exists():
            return {}
        data = self.path.read_bytes()
        end = data.rfind(b"\n") + 1  # bytes after the last newline are a torn record
        completed: dict[int, dict[str, Any]] = {}
        for line in data[:end].splitlines():
            try:
                raw = json.loads(line)
            except ValueError:
                continue  # a damaged record: its task is recomputed
            if raw.get("run") != self.fingerprint:
                raise StoreError(f"'{self.path}' holds records of another run (fingerprint {raw.get('run')}); choose another -o DIR")
            completed.setdefault(int(raw["index"]), raw["record"])
        if end < len(data):
            with open(self.path, "r+b") as fh:
                fh.truncate(end)
                fh.flush()
                os.fsync(fh.fileno())
        return completed

    def append(self, records: Iterable[dict[str, Any]]) -> int:
        """Append records durably (one write, flush, fsync); returns how many were new."""
        fresh = [r for r in records if int(r["index"]) not in self.completed]
        if not fresh:
            return 0
        payload = "".join(
            json.dumps({"run": self.fingerprint, "index": int(r["index"]), "record": r}, separators=(",", ":")) + "\n" for r in fresh
        ).encode("utf-8")
        self._handle.write(payload)
        self._handle.flush()
        os.fsync(self._handle.fileno())
        for r in fresh:
            self.completed[int(r["index"])] = r
        return len(fresh)

    def pending(self, count: int) -> list[int]:
        """Indices 0 .. count-1 not yet stored."""
        return [i for i in range(count) if i not in self.completed]

    def close(self) -> None:
        self._handle.close()

    def __enter__(self) -> TaskStore:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


# ---------------------------------------------------------------------------- execution
_shared: dict[str, Any] = {}


def _pin_threads() -> None:
    for var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "NUMEXPR_NUM_THREADS"):
        os.environ[var] = "1"
    from threadpoolctl import threadpool_limits

    threadpool_limits(limits=1)


def _init_worker(parent_pid: int, shared: Any) -> None:
    """Local worker: one BLAS thread, the shared argument kept, exit when the parent is gone."""
    _pin_threads()
    _shared["value"] = shared

    def watch() -> None:
        while True:
            time.sleep(0.25)
            if os.getppid() != parent_pid:
                os._exit(1)

    threading.Thread(target=watch, name="seafast-parent-watch", daemon=True).start()


def _call_with_shared(task: Callable[[Any, int], dict[str, Any]], index: int) -> dict[str, Any]:
    return _guarded(task, _shared["value"], index)


def _guarded(task: Callable[[Any, int], dict[str, Any]], shared: Any, index: int) -> dict[str, Any]:
    """Run one task; a failure becomes a record with its error text (the run goes on)."""
    t0 = time.perf_counter()
    try:
        return task(shared, index)
    except Exception as exc:  # noqa: BLE001 - any failure of one task is recorded
        text = " ".join(str(exc).split()) or "(no message)"
        return {"index": int(index), "error": f"{type(exc).__name__}: {text}", "seconds": time.perf_counter() - t0}


def _dask_task(task: Callable[[Any, int], dict[str, Any]], shared: Any, index: int) -> dict[str, Any]:
    _pin_threads()
    return _guarded(task, shared, index)


def run_tasks(
    task: Callable[[Any, int], dict[str, Any]],
    shared: Any,
    indices: list[int],
    *,
    workers: int | None = None,
    scheduler: str | None = None,
) -> Iterator[dict[str, Any]]:
    """Evaluate ``task(shared, i)`` for each index, yielding records as they finish.

    Parameters
    ----------
    task
        Module-level function returning a JSON-serialisable record with ``index``.
    shared
        The argument every task shares (sent once per worker).
    indices
        Task indices.
    workers
        Local processes (None = all cores; 1 = serial in this process).
    scheduler
        Dask scheduler address (``tcp://host:port``); overrides ``workers``.

    Raises
    ------
    StoreError
        If the scheduler cannot be reached.
    """
    if not indices:
        return
    if scheduler:
        from distributed import Client, as_completed

        try:
            client = Client(scheduler, timeout="20s", set_as_default=False)
        except (OSError, TimeoutError, ValueError) as exc:
            raise StoreError(f"--scheduler {scheduler}: cannot connect to a Dask scheduler ({exc})") from None
        try:
            shared_future = client.scatter(shared, broadcast=True, hash=False)
            futures: list[Any] = [client.submit(_dask_task, task, shared_future, i, pure=False) for i in indices]
            for future in as_completed(futures, loop=client.loop):
                yield future.result()
        finally:
            client.close()
        return
    n = max(1, workers if workers is not None else (os.cpu_count() or 1))
    if n == 1 or len(indices) == 1:
        from threadpoolctl import threadpool_limits

        with threadpool_limits(limits=1):
            for i in indices:
                yield _guarded(task, shared, i)
        return
    context = multiprocessing.get_context("spawn")
    executor = cf.ProcessPoolExecutor(
        max_workers=min(n, len(indices)), mp_context=context, initializer=_init_worker, initargs=(os.getpid(), shared)
    )
    try:
        local = [executor.submit(_call_with_shared, task, i) for i in indices]
        for future in cf.as_completed(local):
            yield future.result()
    finally:
        executor.shutdown(wait=True, cancel_futures=True)
