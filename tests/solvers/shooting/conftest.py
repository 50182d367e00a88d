"""The shooting tests share the solver tests' cases (``tests/solvers/solver_cases.py``): their folder is importable."""

from __future__ import annotations

import sys
from pathlib import Path

_SOLVERS = str(Path(__file__).resolve().parents[1])
if _SOLVERS not in sys.path:
    sys.path.insert(0, _SOLVERS)
