"""The resumable store of a run's finished tasks: a manifest and one JSON line per record, appended.

A run of independent indexed tasks (a study's points, a Monte Carlo run's realisations) keeps
its results in a directory: the *manifest* (a JSON file) identifies the run by a fingerprint,
and the *records file* holds one JSON object per finished task, appended as results arrive::

    {"<fingerprint key>": "<fingerprint>", "index": 7, ...the record's fields...}

Only the coordinating process writes. How a kind of record is laid out (the two file names, the
fingerprint key, the record's fields) is a :class:`StoreLayout`; :data:`DICT_RECORDS` keeps
plain dictionaries (``manifest.json``, ``records.jsonl``, each record under ``"record"``).

* **Resumable.** Opening a directory reads its records back: the finished tasks are
  :attr:`RecordStore.completed`, :meth:`RecordStore.pending` lists the others, and a record
  already stored is never appended again. For each index the first record the layout accepts
  counts; one it does not accept (its ``decode`` returns None, e.g. a record written by a seafast
  that stored less) is counted in :attr:`RecordStore.rejected` and its task is recomputed.
* **Kill-safe.** :meth:`RecordStore.append` hands its records to the operating system in one
  ``write`` before it returns, so a process killed at any later moment (SIGKILL included) loses
  nothing it appended; a write torn by the kill leaves a partial last line, which the next open
  drops (and truncates). A damaged line elsewhere is skipped: its task is recomputed.
* **Durable in batches.** ``fsync`` at most once per ``fsync_interval_s`` seconds and once when
  the store closes: a crash of the machine can lose the last second of records (recomputed on
  resume), never corrupt the store.
* **One run per directory.** A directory whose manifest, or any of whose record lines, holds
  another fingerprint is refused (:class:`~seafast.parallel.errors.ForeignStoreError`).
"""

from __future__ import annotations

import json
import logging
import os
import time
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Generic, TypeVar

from seafast.parallel.errors import ForeignStoreError

__all__ = ["StoreLayout", "DICT_RECORDS", "RecordStore"]

logger = logging.getLogger(__name__)

R = TypeVar("R")


@dataclass(frozen=True)
class StoreLayout(Generic[R]):
    """How records of type ``R`` are laid out in a store's directory.

    Attributes
    ----------
    manifest : str
        File name of the manifest (``manifest.json``).
    records : str
        File name of the records, one JSON object a line (``records.jsonl``).
    fingerprint_key : str
        The key of every line that holds the run's fingerprint (``run``).
    index : callable
        A record's task index (0, 1, ...).
    encode : callable
        A record's fields as a JSON-compatible mapping (written after the fingerprint key and
        ``index``; neither of the two keys).
    decode : callable
        A parsed line back to a record, or None for a record that is not trusted (its task is
        recomputed).
    """

    manifest: str
    records: str
    fingerprint_key: str
    index: Callable[[R], int]
    encode: Callable[[R], Mapping[str, Any]]
    decode: Callable[[dict[str, Any]], R | None]


def _dict_index(record: dict[str, Any]) -> int:
    return int(record["index"])


def _dict_encode(record: dict[str, Any]) -> dict[str, Any]:
    return {"record": record}


def _dict_decode(line: dict[str, Any]) -> dict[str, Any] | None:
    record = line.get("record")
    return record if isinstance(record, dict) else None


DICT_RECORDS: StoreLayout[dict[str, Any]] = StoreLayout(
    manifest="manifest.json", records="records.jsonl", fingerprint_key="run", index=_dict_index, encode=_dict_encode, decode=_dict_decode
)
"""Plain dictionaries with an integer ``"index"``, each stored under ``"record"`` (the Monte Carlo's realisations)."""


class RecordStore(Generic[R]):
    """Append-only JSON-lines store of a run's finished tasks (see the module docstring).

    Parameters
    ----------
    directory : Path
        Where the manifest and the records file live (created if needed).
    fingerprint : str
        Identity of everything that determines the records; a directory holding another is refused.
    manifest : mapping
        What the manifest records besides the fingerprint (JSON-compatible); written when the
        directory holds no manifest yet.
    layout : StoreLayout
        File names, fingerprint key and the records' encoding.
    fsync_interval_s : float
        Least time between two ``fsync`` calls [s]; 0 syncs every append.

    Raises
    ------
    ForeignStoreError
        If the directory holds another run.
    """

    def __init__(
        self,
        directory: str | Path,
        fingerprint: str,
        manifest: Mapping[str, Any],
        layout: StoreLayout[R],
        *,
        fsync_interval_s: float = 1.0,
    ) -> None:
        self.directory = Path(directory)
        self.fingerprint = str(fingerprint)
        self.layout = layout
        self.fsync_interval_s = float(fsync_interval_s)
        self.rejected = 0
        self.directory.mkdir(parents=True, exist_ok=True)
        self._check_manifest(manifest)
        self.completed: dict[int, R] = self._read()
        self._handle = open(self.path, "ab")  # noqa: SIM115 - appended to until close() / __exit__
        self._last_sync = time.monotonic()
        self._unsynced = False

    @property
    def path(self) -> Path:
        """The records file."""
        return self.directory / self.layout.records

    @property
    def manifest_path(self) -> Path:
        """The manifest."""
        return self.directory / self.layout.manifest

    def _check_manifest(self, content: Mapping[str, Any]) -> None:
        path = self.manifest_path
        if path.exists():
            try:
                held = json.loads(path.read_text(encoding="utf-8"))
            except (OSError, ValueError):
                held = {}
            if not isinstance(held, dict) or held.get("fingerprint") != self.fingerprint:
                held = held if isinstance(held, dict) else {}
                raise ForeignStoreError(
                    f"output directory '{self.directory}' holds another run (fingerprint {held.get('fingerprint', '?')}, "
                    f"this run {self.fingerprint}); allowed: the same run (to resume) or an empty directory; choose another -o DIR",
                    path,
                    held,
                    self.fingerprint,
                )
            return
        tmp = path.with_name(path.name + ".tmp")
        tmp.write_text(json.dumps({"fingerprint": self.fingerprint, **content}, indent=1), encoding="utf-8")
        os.replace(tmp, path)

    def _read(self) -> dict[int, R]:
        if not self.path.exists():
            return {}
        data = self.path.read_bytes()
        end = data.rfind(b"\n") + 1  # bytes after the last newline are a torn record
        completed: dict[int, R] = {}
        for line in data[:end].splitlines():
            try:
                raw = json.loads(line)
                index = int(raw["index"])
            except (ValueError, TypeError, KeyError):
                continue  # a blank or damaged line: its task is recomputed
            held = raw.get(self.layout.fingerprint_key)
            if held != self.fingerprint:
                raise ForeignStoreError(
                    f"'{self.path}' holds records of another run (fingerprint {held}, this run {self.fingerprint}); choose another -o DIR",
                    self.path,
                    {"fingerprint": held},
                    self.fingerprint,
                )
            if index in completed:
                continue
            record = self.layout.decode(raw)
            if record is None:
                self.rejected += 1
                continue
            completed[index] = record
        if end < len(data):
            logger.info("dropping a torn record at the end of %s", self.path)
            with open(self.path, "r+b") as fh:
                fh.truncate(end)
                fh.flush()
                os.fsync(fh.fileno())
        return completed

    def append(self, records: Iterable[R]) -> int:
        """Append the records not stored yet (one ``write``: kill-safe on return); returns how many were new."""
        fresh: dict[int, R] = {}
        for record in records:
            index = int(self.layout.index(record))
            if index not in self.completed:
                fresh.setdefault(index, record)
        if not fresh:
            return 0
        key = self.layout.fingerprint_key
        lines = (
            json.dumps({key: self.fingerprint, "index": i, **self.layout.encode(r)}, separators=(",", ":"), allow_nan=True) + "\n"
            for i, r in fresh.items()
        )
        self._handle.write("".join(lines).encode("utf-8"))
        self._handle.flush()  # into the kernel: survives the death of this process
        self._unsynced = True
        if time.monotonic() - self._last_sync >= self.fsync_interval_s:
            self.sync()
        self.completed.update(fresh)
        return len(fresh)

    def sync(self) -> None:
        """Make the appended records durable (``fsync``)."""
        if self._unsynced and not self._handle.closed:
            os.fsync(self._handle.fileno())
            self._unsynced = False
        self._last_sync = time.monotonic()

    def pending(self, count: int) -> list[int]:
        """Indices ``0 .. count - 1`` not yet stored, ascending."""
        return [i for i in range(count) if i not in self.completed]

    def close(self) -> None:
        """Sync and close the append handle."""
        if not self._handle.closed:
            self.sync()
            self._handle.close()

    def __enter__(self) -> RecordStore[R]:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
