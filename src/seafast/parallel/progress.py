"""Progress of a long run of independent items (study points, Monte Carlo realisations) on stderr.

One helper for every such run (:func:`progress`): on a terminal a tqdm bar (no monitor thread:
the bar is updated as results arrive, and local workers may be forked from this process, which is
only safe while it runs a single thread); otherwise (a log file, a pipe, a CI job) a plain line
every :data:`PROGRESS_STEP_PERCENT` per cent of the items, at most one per
:data:`PROGRESS_MIN_INTERVAL_S` seconds, e.g.::

    study saddles: 30/120 points (25 %), 14 s elapsed, ~42 s left

logged at INFO on ``seafast.parallel.progress`` (``seafast`` prints it on stderr; ``-q`` hides it; a
library caller sees it when it configures logging). The time left is the rate of this run's
items so far (items found finished before it, e.g. a resumed study's, do not count) times the
items left.
"""

from __future__ import annotations

import logging
import math
import sys
import time
from collections.abc import Callable
from typing import Any, Protocol

__all__ = ["Progress", "PlainProgress", "progress", "format_duration", "PROGRESS_STEP_PERCENT", "PROGRESS_MIN_INTERVAL_S"]

logger = logging.getLogger(__name__)

PROGRESS_STEP_PERCENT = 5.0
"""A plain progress line is due each time this many per cent of the items more are done."""

PROGRESS_MIN_INTERVAL_S = 2.0
"""Least time between two plain progress lines [s] (a fast run prints few)."""


class Progress(Protocol):
    """What a run reports its progress to."""

    def update(self, n: int = 1) -> Any:
        """``n`` more items are done."""

    def close(self) -> None:
        """The run is over (or interrupted)."""


def format_duration(seconds: float) -> str:
    """``14 s``, ``3.2 min`` or ``1.5 h`` (whole seconds below 100 s)."""
    if not math.isfinite(seconds):
        return "?"
    if seconds < 100.0:
        return f"{seconds:.0f} s"
    if seconds < 6000.0:
        return f"{seconds / 60.0:.1f} min"
    return f"{seconds / 3600.0:.1f} h"


class PlainProgress:
    """Plain progress lines (see the module docstring).

    Parameters
    ----------
    total : int
        Items in the run.
    initial : int
        Items already done when it starts (e.g. found in a resumable store).
    label : str
        What runs (``study saddles``).
    unit : str
        The items' name, plural (``points``).
    step_percent : float, optional
        A line is due each time this many per cent more are done [%]; default
        :data:`PROGRESS_STEP_PERCENT`.
    min_interval_s : float, optional
        Least time between two lines [s]; default :data:`PROGRESS_MIN_INTERVAL_S`.
    clock : callable
        Monotonic time [s] (tests pass their own).
    """

    def __init__(
        self,
        total: int,
        initial: int = 0,
        label: str = "",
        unit: str = "items",
        *,
        step_percent: float | None = None,
        min_interval_s: float | None = None,
        clock: Callable[[], float] = time.monotonic,
    ) -> None:
        self.total, self.initial, self.done = int(total), int(initial), int(initial)
        self.label, self.unit = label, unit
        step = PROGRESS_STEP_PERCENT if step_percent is None else step_percent
        self.step = max(1, math.ceil(self.total * step / 100.0))
        self.min_interval_s = float(PROGRESS_MIN_INTERVAL_S if min_interval_s is None else min_interval_s)
        self._clock = clock
        self._start = self._last_time = clock()
        self._next = (self.done // self.step + 1) * self.step
        self._printed = self.done
        self.lines: list[str] = []

    def line(self) -> str:
        """The current state as one line."""
        elapsed = self._clock() - self._start
        percent = 100.0 * self.done / self.total if self.total else 100.0
        text = f"{self.label}: {self.done}/{self.total} {self.unit} ({percent:.0f} %), {format_duration(elapsed)} elapsed"
        computed = self.done - self.initial
        if 0 < computed and self.done < self.total:
            text += f", ~{format_duration(elapsed / computed * (self.total - self.done))} left"
        return text

    def _emit(self) -> None:
        text = self.line()
        self.lines.append(text)
        logger.info("%s", text)
        self._printed, self._last_time = self.done, self._clock()

    def update(self, n: int = 1) -> None:
        """``n`` more items are done; a line when a step is crossed and the interval has passed."""
        self.done = min(self.total, self.done + int(n))
        if self.done >= self._next and self._clock() - self._last_time >= self.min_interval_s:
            self._emit()
            self._next = (self.done // self.step + 1) * self.step

    def close(self) -> None:
        """A last line with the final count, when an earlier line left it behind."""
        if self.lines and self._printed < self.done:
            self._emit()


def _tqdm_bar(total: int, initial: int, label: str, unit: str) -> Progress:
    from tqdm import tqdm

    class _Bar(tqdm):
        monitor_interval = 0  # no monitor thread (see the module docstring)

    bar: Progress = _Bar(total=total, initial=initial, file=sys.stderr, unit=unit, desc=label, dynamic_ncols=True)
    return bar


class _Off:
    def update(self, n: int = 1) -> None:
        pass

    def close(self) -> None:
        pass


def progress(total: int, initial: int = 0, *, label: str, unit: str, enabled: bool = True) -> Progress:
    """The progress of a run: a tqdm bar when stderr is a terminal, else :class:`PlainProgress` lines.

    Parameters
    ----------
    total, initial : int
        Items in the run; items done before it starts.
    label : str
        What runs, e.g. ``study saddles`` or ``Monte Carlo base``.
    unit : str
        The items' name, plural: ``points``, ``realisations``.
    enabled : bool
        False: report nothing.
    """
    if not enabled:
        return _Off()
    if hasattr(sys.stderr, "isatty") and sys.stderr.isatty():
        return _tqdm_bar(total, initial, label, unit)
    return PlainProgress(total, initial, label, unit)
