"""The Monte Carlo statistics of the cargo on its cradles off head seas: most probable extremes over the realisations.

From the ``cradle`` part of each realisation's record (:func:`~seafast.analyses.seastate.cradle_realisation.evaluate_cradle_realisation`,
stored by :mod:`seafast.analyses.seastate.monte_carlo`): per model (linear, nonlinear) and quantity the extremes per
realisation, the most probable extreme over the duration by the vertical quantities' estimator
(:func:`~seafast.analyses.seastate.extremes.most_probable_maximum`: the mode of a Gumbel fit, the 1/e quantile where some
maxima are not positive) with its bootstrap interval; the lashing minimum's as the most probable maximum of its
negative, negated (the 1 - 1/e quantile of the minima where the Gumbel does not apply, e.g. slack wires at 0). And
seastate.nc's ``mc_cradle_*`` variables. Units: SI.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from seafast.analyses.seastate.cradle_friction_realisation import FRICTION_QUANTITIES
from seafast.analyses.seastate.cradle_realisation import CRADLE_QUANTITIES, FRACTIONS
from seafast.analyses.seastate.extremes import most_probable_maximum

__all__ = ["CradleStatistics", "cradle_statistics", "cradle_statistics_variables"]

_UNITS = {
    "F_pad_N": "N",
    "F_stopper_N": "N",
    "lashing_tension_max_N": "N",
    "lashing_tension_min_N": "N",
    "transverse_slip_m": "m",
    "pad_friction_utilisation": "1",
    "pad_slip_m": "m",
}
_LONG = {
    "F_pad_N": "largest pad force over the saddles, sides and the duration (still water included)",
    "F_stopper_N": "largest side-stopper force over the duration (linear: k max(s, 0) of the linear motion across)",
    "lashing_tension_max_N": "largest lashing-wire tension over the duration (still water included)",
    "lashing_tension_min_N": "least lashing-wire tension over the duration (linear: negative where the wire would push)",
    "transverse_slip_m": "largest lateral displacement of the cargo relative to the deck at a saddle over the duration",
    "pad_friction_utilisation": "largest pad friction utilisation |f| / (mu F_n) over the duration (frictional pads)",
    "pad_slip_m": "largest slip of a pad from rest |w - w_rest| over the duration (frictional pads)",
}


@dataclass(frozen=True)
class CradleStatistics:
    """The cradle quantities' statistics of one model over the realisations.

    Attributes
    ----------
    model
        ``linear`` (pads and lashings bilateral, stoppers open) or ``nonlinear`` (exact contact).
    extremes
        Per :data:`CRADLE_QUANTITIES` and :data:`FRACTIONS`, per realisation (n_r,) [N, m, -]; NaN where failed.
    mpm, mpm_interval, mpm_method
        Per :data:`CRADLE_QUANTITIES` the most probable extreme over the duration
        (:func:`~seafast.analyses.seastate.extremes.most_probable_maximum`; the lashing minimum's as the most
        probable maximum of its negative, negated: the 1 - 1/e quantile of the minima), its bootstrap interval and
        estimator.
    converged
        Every realisation was evaluated and every step's contact problem solved exactly.
    """

    model: str
    extremes: Mapping[str, NDArray[np.float64]]
    mpm: Mapping[str, float]
    mpm_interval: Mapping[str, tuple[float, float]]
    mpm_method: Mapping[str, str]
    converged: bool


def cradle_statistics(model: str, records: Sequence[Mapping[str, Any]], seed: int) -> CradleStatistics:
    """The ``model`` statistics of the realisation records' ``cradle`` parts (:func:`evaluate_cradle_realisation`);
    on frictional pads the nonlinear model's :data:`FRICTION_QUANTITIES` too, each a most probable maximum."""
    parts = [r.get("cradle") if "error" not in r else None for r in records]
    frictional = tuple(q for q in FRICTION_QUANTITIES if any(p is not None and q in p[model] for p in parts))
    extremes = {q: np.array([np.nan if p is None else p[model][q] for p in parts]) for q in CRADLE_QUANTITIES + FRACTIONS + frictional}
    mpm, interval, method = {}, {}, {}
    for i, q in enumerate(CRADLE_QUANTITIES + frictional):
        least = q == "lashing_tension_min_N"
        e = most_probable_maximum(-extremes[q] if least else extremes[q], seed=seed + 100 + i)
        mpm[q] = -e.value if least else e.value
        interval[q] = (-e.interval[1], -e.interval[0]) if least else e.interval
        method[q] = e.method
    converged = all(p is not None and bool(p.get("solved", True)) for p in parts)
    return CradleStatistics(model, extremes, mpm, interval, method, converged)


def cradle_statistics_variables(statistics: Sequence[CradleStatistics]) -> dict[str, Any]:
    """seastate.nc's ``mc_cradle_*`` variables (dimensions ``model``, ``realisation``) of both models' statistics."""
    out: dict[str, Any] = {}
    frictional = tuple(q for q in FRICTION_QUANTITIES if all(q in s.mpm for s in statistics))
    for q in CRADLE_QUANTITIES + frictional:
        u, ln = _UNITS[q], _LONG[q]
        out[f"mc_cradle_{q}"] = (
            ("model", "realisation"),
            np.stack([s.extremes[q] for s in statistics]),
            {"units": u, "long_name": f"{ln}, per realisation"},
        )
        out[f"mc_cradle_mpm_{q}"] = (
            ("model",),
            np.array([s.mpm[q] for s in statistics]),
            {"units": u, "long_name": f"most probable extreme: {ln}", "method": ", ".join(s.mpm_method[q] for s in statistics)},
        )
        for bound, k in (("low", 0), ("high", 1)):
            out[f"mc_cradle_mpm_{bound}_{q}"] = (
                ("model",),
                np.array([s.mpm_interval[q][k] for s in statistics]),
                {"units": u, "long_name": f"{bound} bound of the bootstrap interval of the most probable extreme of {q}"},
            )
    for q, what in zip(FRACTIONS, ("a pad is lifted", "a lashing is slack"), strict=True):
        out[f"mc_cradle_{q}"] = (
            ("model", "realisation"),
            np.stack([s.extremes[q] for s in statistics]),
            {"units": "1", "long_name": f"largest fraction of the duration {what} (linear: its engagement below 0)"},
        )
    return out
