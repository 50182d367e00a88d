"""A study's points in the shared resumable store: one JSON line per finished point.

``DIR/study.json`` identifies the study (its fingerprint and a description of its points);
``DIR/points.jsonl`` holds one record per finished point (its rows, error text and wall time),
appended as results arrive. The store itself, with its kill safety, batched ``fsync`` and
refusal of another run's directory, is :class:`seafast.parallel.store.RecordStore`; this module
says how a study's points are laid out in it (:data:`STUDY_MANIFEST`, :data:`POINTS_FILE`,
:func:`point_store`). Anything with a ``fingerprint()``, a ``size`` and a ``manifest()``
(:class:`StoredPoints`) can keep its points here.

A record holds each row's typed ``warnings`` (their values), so a resumed study restores the
warnings of the points computed before the interruption. A record without them (written by a
seafast that did not store warnings) is not trusted: its point is recomputed. So is a record of a
point off head seas without the cargo on its cradles (``cradle_converged`` in its rows), written by a
seafast whose studies recorded the vertical plane alone, when the store is told which points solve
the cradles (``cradle_points``).
"""

from __future__ import annotations

import logging
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Protocol

import numpy as np

from seafast.parallel.errors import ForeignStoreError
from seafast.parallel.store import RecordStore, StoreLayout
from seafast.studies.messages import warning_values
from seafast.studies.spec import StudyError

__all__ = ["STUDY_MANIFEST", "POINTS_FILE", "PointRecord", "StoredPoints", "point_store", "stored_row"]

logger = logging.getLogger(__name__)

STUDY_MANIFEST = "study.json"
"""The study's manifest in its directory (fingerprint, name, axes)."""

POINTS_FILE = "points.jsonl"
"""The study's records file in its directory (one JSON line per finished point)."""


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

    def fields(self) -> dict[str, Any]:
        """What a line of ``points.jsonl`` holds besides the study's fingerprint and the index."""
        return {"rows": list(self.rows), "error": self.error, "seconds": self.seconds}

    @staticmethod
    def from_json(data: dict) -> PointRecord:
        """A record from a parsed line of ``points.jsonl``."""
        return PointRecord(int(data["index"]), tuple(data.get("rows") or ()), str(data.get("error") or ""), float(data.get("seconds", 0.0)))


def _point_index(record: PointRecord) -> int:
    return record.index


def _point_fields(record: PointRecord) -> dict[str, Any]:
    return record.fields()


CRADLE_MARKER = "cradle_converged"
"""The row key every row of a point off head seas holds (its cradle solve's outcome, failed or not)."""


@dataclass(frozen=True)
class _PointDecoder:
    """A stored line back to a point of a study of ``size`` points; None for a point stored without its warnings,
    or (``cradle_points``) off head seas without the cargo on its cradles."""

    size: int
    cradle_points: Callable[[int], bool] | None = None

    def __call__(self, line: dict[str, Any]) -> PointRecord | None:
        record = PointRecord.from_json(line)
        if not (0 <= record.index < self.size):
            return None
        if not record.error and not all("warnings" in row for row in record.rows):
            return None  # stored without its warnings: recomputed
        if record.error or self.cradle_points is None or all(CRADLE_MARKER in row for row in record.rows):
            return record
        return None if self.cradle_points(record.index) else record  # the vertical plane alone: recomputed


def point_store(
    directory: str | Path,
    grid: StoredPoints,
    *,
    fsync_interval_s: float = 1.0,
    cradle_points: Callable[[int], bool] | None = None,
) -> RecordStore[PointRecord]:
    """The resumable store of a study's points in ``directory`` (``study.json``, ``points.jsonl``).

    Parameters
    ----------
    directory : str or Path
        The study's output directory (created if needed).
    grid : StoredPoints
        The points (e.g. a :class:`~seafast.studies.spec.StudyGrid`); a directory holding
        another set of points (other fingerprint) is refused.
    fsync_interval_s : float
        Least time between two ``fsync`` calls [s] (:class:`~seafast.parallel.store.RecordStore`);
        0 syncs every append.
    cradle_points : callable, optional
        Whether point ``index`` records the cargo on its cradles (its heading is not head seas and the
        evaluator is the default or the sea-state one); a stored point for which it is true but whose rows lack
        them is recomputed. None: no such check (a plug-in evaluator).

    Raises
    ------
    StudyError
        If the directory holds a different study.
    """
    manifest = grid.manifest()
    fingerprint = grid.fingerprint()
    layout = StoreLayout(STUDY_MANIFEST, POINTS_FILE, "study", _point_index, _point_fields, _PointDecoder(grid.size, cradle_points))
    try:
        store = RecordStore(directory, fingerprint, manifest, layout, fsync_interval_s=fsync_interval_s)
    except ForeignStoreError as exc:
        if exc.path.name != STUDY_MANIFEST:
            raise StudyError(
                f"'{exc.path}' holds points of another study (fingerprint {exc.held.get('fingerprint')}, "
                f"this study {fingerprint}); choose another -o DIR"
            ) from None
        raise StudyError(
            f"output directory '{directory}' holds a different study ('{exc.held.get('name', '?')}', fingerprint "
            f"{exc.held.get('fingerprint', '?')}) from this '{manifest.get('name', '?')}' (fingerprint {fingerprint}; the "
            "fingerprint covers the base case with its overrides, the axes and the derived keys); "
            "allowed: the same study (to resume) or an empty directory; choose another -o DIR"
        ) from None
    if store.rejected:
        logger.info(
            "%d point(s) in %s were stored without their warnings or, off head seas, without the cargo on its cradles; they are recomputed",
            store.rejected,
            store.path,
        )
    return store
