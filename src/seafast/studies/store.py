"""The resumable point store of a study directory: one JSON line per finished point.

``DIR/study.json`` identifies the study (its fingerprint and a description of its points);
``DIR/points.jsonl`` holds one record per finished point, appended as results arrive. Only the
coordinating process writes. The store is generic: anything with a ``fingerprint()``, a
``size`` and a ``manifest()`` (:class:`StoredPoints`) can keep its points here (a parametric
grid, a set of Monte Carlo realisations).

Kill safety: every :meth:`PointStore.append` hands its records to the operating system in one
``write`` before it returns, so a process killed at any later moment (SIGKILL included) loses
nothing it appended; a write torn by the kill leaves a partial last line, which the next open
drops. Durability against a power cut (``fsync``) is batched: at most one ``fsync`` per
``fsync_interval_s`` seconds and one when the store closes, so a crash of the machine can lose
the last second of points (they are recomputed on resume), never corrupt the store.

A record holds each row's typed ``warnings`` (their values), so a resumed study restores the
warnings of the points computed before the interruption. A record without them (written by a
seafast that did not store warnings) is not trusted: its point is recomputed.
"""

from __future__ import annotations

import json
import logging
import os
import time
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Protocol

import numpy as np

from seafast.studies.messages import warning_values
from seafast.studies.spec import StudyError

__all__ = ["PointRecord", "PointStore", "StoredPoints", "stored_row"]

logger = logging.getLogger(__name__)


class StoredPoints(Protocol):
    """What a point store needs to know about the set of points it keeps."""

    @property
    def size(self) -> int:
        """Number of points (indices 0 .. size - 1)."""

    def fingerprint(self) -> str:
        """Identity of everything that determines the points' results."""

    def manifest(self) -> dict[str, Any]:
        """JSON-compatible description written to ``study.json`` (must hold ``name``)."""


def _plain(value: Any) -> Any:
    """A JSON-compatible Python scalar (numpy scalars unwrapped)."""
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, (bool, int, float, str)) or value is None:
        return value
    if isinstance(value, np.ndarray) and value.size == 1:
        return value.item()
    return str(value)


def stored_row(row: dict) -> dict:
    """An evaluator's row as stored: JSON-compatible scalars, and ``warnings`` as a list of values (always present)."""
    out = {k: _plain(v) for k, v in row.items() if k != "warnings"}
    out["warnings"] = warning_values(row.get("warnings"))
    return out


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
    messages : tuple of (str, int, str)
        The point's log records (logger name, level, text) when the study asked for them
        (:func:`seafast.studies.messages.point_log`); not stored.
    """

    index: int
    rows: tuple[dict, ...] = ()
    error: str = ""
    seconds: float = 0.0
    messages: tuple[tuple[str, int, str], ...] = ()

    def to_json(self, fingerprint: str) -> str:
        """One line of ``points.jsonl`` (no newline)."""
        return json.dumps(
            {"study": fingerprint, "index": self.index, "rows": list(self.rows), "error": self.error, "seconds": self.seconds},
            separators=(",", ":"),
            allow_nan=True,
        )

    @staticmethod
    def from_json(data: dict) -> PointRecord:
        """Inverse of :meth:`to_json` (already parsed)."""
        return PointRecord(int(data["index"]), tuple(data.get("rows") or ()), str(data.get("error") or ""), float(data.get("seconds", 0.0)))


class PointStore:
    """Append-only JSON-lines store of finished points in a study directory.

    Parameters
    ----------
    directory : Path
        The study's output directory (created if needed).
    grid : StoredPoints
        The points (e.g. a :class:`~seafast.studies.spec.StudyGrid`); a directory holding
        another set of points (other fingerprint) is refused.
    fsync_interval_s : float
        Least time between two ``fsync`` calls [s] (see the module docstring); 0 syncs every
        append.

    Raises
    ------
    StudyError
        If the directory holds a different study.
    """

    MANIFEST = "study.json"
    POINTS = "points.jsonl"

    def __init__(self, directory: Path, grid: StoredPoints, fsync_interval_s: float = 1.0) -> None:
        self.directory = Path(directory)
        self.fingerprint = grid.fingerprint()
        self.size = grid.size
        self.fsync_interval_s = float(fsync_interval_s)
        self.directory.mkdir(parents=True, exist_ok=True)
        self._check_manifest(grid.manifest())
        self.completed: dict[int, PointRecord] = self._read_points()
        self._handle = open(self.path, "ab")  # noqa: SIM115 - appended to until close() / __exit__
        self._last_sync = time.monotonic()
        self._unsynced = False

    @property
    def path(self) -> Path:
        """``DIR/points.jsonl``."""
        return self.directory / self.POINTS

    def _check_manifest(self, content: dict[str, Any]) -> None:
        manifest = self.directory / self.MANIFEST
        if manifest.exists():
            try:
                held = json.loads(manifest.read_text(encoding="utf-8"))
            except (OSError, ValueError):
                held = {}
            if held.get("fingerprint") != self.fingerprint:
                raise StudyError(
                    f"output directory '{self.directory}' holds a different study ('{held.get('name', '?')}', fingerprint "
                    f"{held.get('fingerprint', '?')}) from this '{content.get('name', '?')}' (fingerprint {self.fingerprint}; the "
                    "fingerprint covers the base case with its overrides, the axes and the derived keys); "
                    "allowed: the same study (to resume) or an empty directory; choose another -o DIR"
                )
            return
        tmp = manifest.with_suffix(".json.tmp")
        tmp.write_text(json.dumps({**content, "fingerprint": self.fingerprint}, indent=1), encoding="utf-8")
        os.replace(tmp, manifest)

    def _read_points(self) -> dict[int, PointRecord]:
        if not self.path.exists():
            return {}
        data = self.path.read_bytes()
        end = data.rfind(b"\n") + 1  # bytes after the last newline are a torn record
        completed: dict[int, PointRecord] = {}
        stale = 0
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
            if not (0 <= record.index < self.size):
                continue
            if not record.error and not all("warnings" in row for row in record.rows):
                stale += 1  # stored without its warnings: recomputed
                completed.pop(record.index, None)
                continue
            completed[record.index] = record
        if stale:
            logger.info("%d point(s) in %s were stored without their warnings; they are recomputed", stale, self.path)
        if end < len(data):
            logger.info("dropping a torn record at the end of %s", self.path)
            with open(self.path, "r+b") as fh:
                fh.truncate(end)
                fh.flush()
                os.fsync(fh.fileno())
        return completed

    def append(self, records: Iterable[PointRecord]) -> int:
        """Append records (one ``write``, kill-safe on return); returns how many were new."""
        fresh = [r for r in records if r.index not in self.completed]
        if not fresh:
            return 0
        payload = "".join(r.to_json(self.fingerprint) + "\n" for r in fresh).encode("utf-8")
        self._handle.write(payload)
        self._handle.flush()  # into the kernel: survives the death of this process
        self._unsynced = True
        if time.monotonic() - self._last_sync >= self.fsync_interval_s:
            self.sync()
        for r in fresh:
            self.completed[r.index] = r
        return len(fresh)

    def sync(self) -> None:
        """Make the appended records durable (``fsync``)."""
        if self._unsynced and not self._handle.closed:
            os.fsync(self._handle.fileno())
            self._unsynced = False
        self._last_sync = time.monotonic()

    def pending(self) -> list[int]:
        """Indices not yet in the store, ascending."""
        return [i for i in range(self.size) if i not in self.completed]

    def close(self) -> None:
        """Sync and close the append handle."""
        if not self._handle.closed:
            self.sync()
            self._handle.close()

    def __enter__(self) -> PointStore:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
