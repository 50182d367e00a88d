"""A study's per-point warnings and messages: the warning kinds, a point's log, the count per kind.

**Warnings** are typed values. Every row an evaluator returns may carry ``warnings``: a sequence
of :class:`~seafast.solvers.outcome.SolverWarning` and :class:`~seafast.model.warning.ModelWarning`
members (the default evaluator's rows do: :func:`seafast.results.dataset.row_warnings`), or
their string values. The study stores their values per row (``points.jsonl``, ``study.csv``
column ``warnings``, ``study.nc`` ``warning_flag``), and at the end logs one line per kind with
the number of points that raised it (:func:`warning_count_lines`). Nothing is read from a
message's text.

**Messages.** While a point is evaluated, the records of the ``seafast`` loggers are captured
instead of handled (:func:`point_log`): a study of a hundred points would otherwise print their
solver notes one by one, nameless, from whichever process ran them. When the coordinating
process asks for them (it logs at DEBUG: ``seafast -v study``) they travel back with the point's
record and are logged again there, each naming its point (:func:`replay_point_messages`);
otherwise they are dropped. The capture is per thread (a Dask worker may run several points at
once); records logged meanwhile by a thread that evaluates no point are handled as before.
"""

from __future__ import annotations

import logging
import threading
from collections.abc import Iterable, Iterator, Mapping
from contextlib import contextmanager
from dataclasses import dataclass, field
from enum import Enum
from typing import Any

from seafast.model.warning import ModelWarning
from seafast.results.validity import ValidityLimit
from seafast.solvers.outcome import SolverWarning

__all__ = [
    "WARNING_KINDS",
    "PointMessage",
    "warning_values",
    "describe_warning",
    "warning_kinds",
    "points_with_warning",
    "warning_count_lines",
    "point_label",
    "point_log",
    "replay_point_messages",
]

WARNING_KINDS: tuple[str, ...] = tuple(w.value for e in (SolverWarning, ModelWarning, ValidityLimit) for w in e)
"""Every typed warning a point of the default evaluator can raise, in the order study.nc lists them."""

_DESCRIPTIONS: dict[str, str] = {w.value: w.description for e in (SolverWarning, ModelWarning, ValidityLimit) for w in e}

PointMessage = tuple[str, int, str]
"""A captured log record: (logger name, level number, message text)."""


def warning_values(value: Any) -> list[str]:
    """The warning values of a row's ``warnings`` (enum members, strings or a ``;``-joined string; None: none)."""
    if value is None:
        return []
    items = value.split(";") if isinstance(value, str) else list(value)
    out: list[str] = []
    for item in items:
        text = str(item.value if isinstance(item, Enum) else item).strip()
        if text and text not in out:
            out.append(text)
    return out


def describe_warning(kind: str) -> str:
    """One line for people about a warning value ('' for a kind seafast does not define)."""
    return _DESCRIPTIONS.get(kind, "")


def _rows(records: Iterable[Any]) -> Iterator[dict]:
    for record in records:
        yield from record.rows


def warning_kinds(records: Iterable[Any]) -> list[str]:
    """:data:`WARNING_KINDS`, then any other value the records' rows carry (a plug-in evaluator's), in order seen."""
    kinds = list(WARNING_KINDS)
    for row in _rows(records):
        kinds += [w for w in warning_values(row.get("warnings")) if w not in kinds]
    return kinds


def points_with_warning(records: Iterable[Any]) -> dict[str, int]:
    """Per warning value raised anywhere: how many points raised it in some row (kinds in :func:`warning_kinds` order)."""
    records = list(records)
    counts: dict[str, int] = {}
    for record in records:
        for kind in {w for row in record.rows for w in warning_values(row.get("warnings"))}:
            counts[kind] = counts.get(kind, 0) + 1
    return {k: counts[k] for k in warning_kinds(records) if k in counts}


def warning_count_lines(counts: Mapping[str, int], points: int) -> list[str]:
    """One line per warning kind: ``12 of 120 points: too_few_harmonics (see the warnings column of study.csv): ...``."""
    lines = []
    for kind, n in counts.items():
        what = describe_warning(kind)
        lines.append(f"{n} of {points} points: {kind} (see the warnings column of study.csv)" + (f": {what}" if what else ""))
    return lines


def point_label(index: int, overrides: Mapping[str, Any]) -> str:
    """``point 17 (seafastening.saddle_count=7, seafastening.saddle_stiffness_N_per_m=1.1e+10)``."""
    values = ", ".join(f"{k}={v:.6g}" if isinstance(v, float) else f"{k}={v}" for k, v in overrides.items())
    return f"point {index} ({values})"


# --------------------------------------------------------------------------- capture
_PACKAGE = "seafast"


@dataclass
class _Sink:
    keep: bool
    messages: list[PointMessage] = field(default_factory=list)


@dataclass
class _Installed:
    handlers: list[logging.Handler]
    propagate: bool
    level: int
    keeping: int = 0
    users: int = 0


_local = threading.local()
_lock = threading.Lock()
_state: list[_Installed] = []  # the package logger's own set-up while a capture is installed (at most one)


class _Router(logging.Handler):
    """On the package logger while points are evaluated: a capturing thread's records go to its sink."""

    def emit(self, record: logging.LogRecord) -> None:
        sink: _Sink | None = getattr(_local, "sink", None)
        if sink is not None:
            if sink.keep:
                sink.messages.append((record.name, record.levelno, record.getMessage()))
            return
        saved = _state[0] if _state else None
        if saved is None or record.levelno < (saved.level or logging.getLogger().getEffectiveLevel()):
            return
        for handler in saved.handlers:
            if record.levelno >= handler.level:
                handler.handle(record)
        if saved.propagate:
            logging.getLogger().handle(record)


_ROUTER = _Router()


def _install(keep: bool) -> None:
    package = logging.getLogger(_PACKAGE)
    with _lock:
        if not _state:
            _state.append(_Installed(list(package.handlers), package.propagate, package.level))
            package.handlers = [_ROUTER]
            package.propagate = False
        installed = _state[0]
        installed.users += 1
        if keep:
            installed.keeping += 1
            package.setLevel(logging.DEBUG)


def _uninstall(keep: bool) -> None:
    package = logging.getLogger(_PACKAGE)
    with _lock:
        installed = _state[0]
        installed.users -= 1
        if keep:
            installed.keeping -= 1
            if not installed.keeping:
                package.setLevel(installed.level)
        if not installed.users:
            package.handlers = installed.handlers
            package.propagate = installed.propagate
            package.setLevel(installed.level)
            _state.clear()


@contextmanager
def point_log(keep: bool) -> Iterator[list[PointMessage]]:
    """Capture the ``seafast`` log records this thread emits while one point is evaluated.

    Parameters
    ----------
    keep : bool
        Keep every record (DEBUG and up) in the yielded list; False: drop them.

    Yields
    ------
    list of PointMessage
        The captured records (filled as the point runs; empty when ``keep`` is False).
    """
    sink = _Sink(keep)
    previous = getattr(_local, "sink", None)
    _install(keep)
    _local.sink = sink
    try:
        yield sink.messages
    finally:
        _local.sink = previous
        _uninstall(keep)


def replay_point_messages(label: str, messages: Iterable[PointMessage]) -> None:
    """Log a point's captured messages again in this process, each prefixed with the point's ``label``.

    Each record keeps its logger and level (a warning prints as ``seafast: warning: point 17 (...): ...``).
    """
    for name, level, text in messages:
        target = logging.getLogger(name)
        if target.isEnabledFor(level):
            target.handle(
                logging.makeLogRecord({"name": name, "levelno": level, "levelname": logging.getLevelName(level), "msg": f"{label}: {text}"})
            )
