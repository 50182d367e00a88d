"""Shared timing helper of the benchmark scripts (run as ``python benchmarks/<name>.py``)."""

from __future__ import annotations

import time
from collections.abc import Callable
from typing import Any

import numpy as np


def timed(fn: Callable[[], Any], repeats: int, clock: Callable[[], float] = time.perf_counter) -> tuple[Any, float]:
    """Call ``fn`` ``repeats`` times; return its last result and the median time [ms].

    ``clock``: wall time by default; ``time.process_time`` gives the process's CPU time, which a machine
    shared with other jobs inflates far less (for single-threaded work).
    """
    out, times = None, []
    for _ in range(repeats):
        t0 = clock()
        out = fn()
        times.append(clock() - t0)
    return out, 1e3 * float(np.median(times))
