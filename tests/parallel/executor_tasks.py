"""Module-level tasks for the executor tests (importable by worker processes)."""

from __future__ import annotations

import os
import time
from pathlib import Path

import numpy as np


def solve_items(seed: int, indices: list[int]) -> list[tuple[int, list[float]]]:
    """Per index, the solution of a 60 x 60 system drawn from ``seed + index`` (a pure function of the two)."""
    out = []
    for index in indices:
        rng = np.random.default_rng(seed + index)
        a = rng.standard_normal((60, 60)) + 60.0 * np.eye(60)
        b = rng.standard_normal(60)
        out.append((index, np.linalg.solve(a, a @ a @ b).tolist()))
    return out


def pid_of_items(_shared: object, indices: list[int]) -> list[tuple[int, int]]:
    """Each index with the id of the process that ran it."""
    return [(int(i), os.getpid()) for i in indices]


def blas_threads(_shared: object, indices: list[int]) -> list[tuple[int, list[int]]]:
    """Each index with the thread counts of the BLAS libraries loaded where it ran (numpy's and scipy's loaded first)."""
    import scipy.linalg  # noqa: F401 - load scipy's BLAS too
    from threadpoolctl import threadpool_info

    counts = sorted({int(info["num_threads"]) for info in threadpool_info() if info["user_api"] == "blas"})
    return [(int(i), counts) for i in indices]


def sleep_items(seconds: float, indices: list[int]) -> list[int]:
    """Sleep ``seconds`` per index (a task longer than the parent watch's tick)."""
    for _ in indices:
        time.sleep(seconds)
    return list(indices)


def record_pid_and_sleep(directory: str, indices: list[int]) -> list[int]:
    """Write this process's id to ``directory/<pid>`` and sleep a long time (a worker to be orphaned)."""
    Path(directory, str(os.getpid())).write_text("", encoding="utf-8")
    time.sleep(120.0)
    return list(indices)
