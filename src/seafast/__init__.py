"""seafast: sea-fastening response of long cargo (monopiles) on heavy-lift vessels.

Linear and nonlinear (harmonic balance with unilateral saddles) response of the cargo to the
vessel's hull-girder deflection and rigid-body motions in regular waves.

Scripting::

    import seafast
    case = seafast.load_case("my_case.yaml", {"seafastening.saddle_count": 4})
    result = seafast.run_case(case)
    result.summary            # rows of summary.csv
    result.dataset            # everything, labelled (xarray)

The package imports its numerical stack lazily, so ``seafast.cli`` can pin BLAS threads first.
Modules log to ``logging.getLogger(__name__)`` (the ``seafast`` hierarchy): solver paths and
fallbacks at DEBUG/INFO, BEM cache misses and study progress at INFO, typed solver warnings at
WARNING.
"""

from __future__ import annotations

import logging
from typing import Any

__version__ = "0.1.0"

# A library logs and lets the application decide what to show: nothing, unless it configures
# logging (the ``seafast`` command does, see :func:`seafast.cli.command.main`).
logging.getLogger(__name__).addHandler(logging.NullHandler())

__all__ = ["__version__", "load_case", "run_case", "Case", "CaseError", "CaseResult"]

_LAZY = {
    "load_case": "seafast.config",
    "Case": "seafast.config",
    "CaseError": "seafast.config",
    "run_case": "seafast.analyses.run",
    "CaseResult": "seafast.analyses.run",
}


def __getattr__(name: str) -> Any:
    if name in _LAZY:
        import importlib

        return getattr(importlib.import_module(_LAZY[name]), name)
    raise AttributeError(f"module 'seafast' has no attribute {name!r}")
