"""The limits operability judges the sea states by: their names, the case's values, one limit's linear allowable Hs.

In the vertical plane (every heading) the saddle force ``limits.max_saddle_force_N`` and the bending stress
``limits.max_bending_stress_Pa``; off head seas also the cargo on its cradles, each cradle limit that is set
(:data:`CRADLE_LIMITS`; None: not checked): the largest pad force, lashing-wire tension and lateral displacement of
the cargo at a saddle (the columns of ``seafast seastate`` off head seas, :mod:`seafast.analyses.seastate.cradle_extremes`).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from seafast.config.schema import Case

__all__ = ["GOVERNING", "CRADLE_LIMITS", "VERTICAL_LIMITS", "cradle_limits", "vertical_limits", "linear_limit_hs"]

VERTICAL_LIMITS: tuple[tuple[str, str, str], ...] = (
    ("saddle_force", "max_saddle_force_N", "F_N"),
    ("bending_stress", "max_bending_stress_Pa", "sigma_b_Pa"),
)
"""(governing name, ``limits`` key, seastate.csv column) of the vertical plane's limits, judged at every heading."""

CRADLE_LIMITS: tuple[tuple[str, str, str], ...] = (
    ("pad_force", "max_pad_force_N", "F_pad_N"),
    ("lashing_tension", "max_lashing_tension_N", "lashing_tension_max_N"),
    ("transverse_slip", "max_transverse_slip_m", "transverse_slip_m"),
)
"""(governing name, ``limits`` key, seastate.csv column) of the optional cradle limits, judged off head seas."""

GOVERNING: tuple[str, ...] = (
    *(name for name, _, _ in VERTICAL_LIMITS),
    *(name for name, _, _ in CRADLE_LIMITS),
    "steepness",
    "not_converged",
)
"""Values of the governing_* columns: the limit reached first; ``steepness`` when none is reached up to the steepest
sea state at that Tp; ``not_converged`` when a nonlinear solve failed."""


def vertical_limits(case: Case) -> dict[str, float]:
    """Governing name -> the case's limit [N or Pa] of the vertical plane (saddle force, bending stress), in order."""
    return {name: float(getattr(case.limits, key)) for name, key, _ in VERTICAL_LIMITS}


def cradle_limits(case: Case) -> dict[str, float]:
    """Governing name -> the case's limit [N or m] of each cradle limit that is set (in :data:`CRADLE_LIMITS`' order)."""
    return {name: float(v) for name, key, _ in CRADLE_LIMITS if (v := getattr(case.limits, key)) is not None}


def linear_limit_hs(static: NDArray[np.float64], per_hs: NDArray[np.float64], limit: float) -> float:
    """Smallest Hs [m] with ``max(static + Hs per_hs) = limit`` over the locations.

    ``static``: the still-water values, ``per_hs``: the linear MPMs per metre of Hs (one per location). 0 when the
    still water alone reaches the limit somewhere; inf when it is never reached (no location, or none that grows).
    """
    static, per_hs = np.asarray(static, dtype=float), np.asarray(per_hs, dtype=float)
    if static.size == 0:
        return math.inf
    if np.any(static >= limit):
        return 0.0
    with np.errstate(divide="ignore"):
        hs = np.where(per_hs > 0, (limit - static) / np.where(per_hs > 0, per_hs, 1.0), np.inf)
    return float(np.min(hs))
