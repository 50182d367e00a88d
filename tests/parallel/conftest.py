"""Shared set-up of the machinery tests: worker processes import the tasks of ``executor_tasks`` from here."""

from __future__ import annotations

import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
if str(HERE) not in sys.path:  # spawned and forkserver workers, and Dask workers, import the tasks by module name
    sys.path.insert(0, str(HERE))
