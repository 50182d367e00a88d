"""Two-way coupling in ``results.nc``: each row's coupling outcome.

Present only after a ``vessel.coupling: two_way`` run. Coupling outcome, per ``(load_case, model)``: ``coupling_converged``, ``coupling_outcome`` (a
:class:`~seafast.excitation.coupling_status.CouplingOutcome` value), ``coupling_residual_m``,
``coupling_tolerance_m``, ``coupling_deck_motion_scale_m``, ``coupling_iterations``,
``coupling_mean_deck_change_m`` (per saddle) and ``coupling_message`` (for people).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import Any

import numpy as np
import xarray as xr
from numpy.typing import DTypeLike

from seafast.excitation.coupling_status import CouplingStatus
from seafast.results.dataset import LOAD_CASES, MODELS

__all__ = ["coupling_dataset", "coupling_summary_fields"]

def _row_array(
    statuses: Mapping[tuple[str, str], CouplingStatus], get: Callable[[CouplingStatus], Any], fill: Any, dtype: DTypeLike
) -> np.ndarray:
    """One field of every row's status, shape (load_case, model); ``fill`` where a row has none."""
    out = np.full((len(LOAD_CASES), len(MODELS)), fill, dtype=dtype)
    for i, lc in enumerate(LOAD_CASES):
        for j, mdl in enumerate(MODELS):
            if (lc, mdl) in statuses:
                out[i, j] = get(statuses[(lc, mdl)])
    return out


def coupling_dataset(statuses: Mapping[tuple[str, str], CouplingStatus]) -> xr.Dataset:
    """The coupling variables of ``results.nc`` (see the module docstring).

    Parameters
    ----------
    statuses
        The coupling outcome of each ``(load_case, model)`` row.
    """
    rows = ("load_case", "model")
    data: dict[str, tuple] = {}
    if statuses:
        n_s = max(len(s.mean_deck_change_m) for s in statuses.values())
        change = np.full((len(LOAD_CASES), len(MODELS), n_s), np.nan)
        for i, lc in enumerate(LOAD_CASES):
            for j, mdl in enumerate(MODELS):
                if (lc, mdl) in statuses:
                    change[i, j] = statuses[(lc, mdl)].mean_deck_change_m
        data.update(
            coupling_converged=(
                rows,
                _row_array(statuses, lambda s: s.converged, 0, np.int8),
                {"long_name": "two-way hull-cargo coupling converged (1) or not (0)", "units": "1"},
            ),
            coupling_outcome=(
                rows,
                _row_array(statuses, lambda s: s.outcome.value, "", object).astype(str),
                {"long_name": "how the coupling iteration ended: converged, iteration_limit, stalled or not_finite"},
            ),
            coupling_residual_m=(
                rows,
                _row_array(statuses, lambda s: s.residual_m, np.nan, float),
                {
                    "long_name": "coupling residual: largest mismatch of the deck under the saddles (slopes times half the cargo length)",
                    "units": "m",
                },
            ),
            coupling_tolerance_m=(
                rows,
                _row_array(statuses, lambda s: s.tolerance_m, np.nan, float),
                {"long_name": "coupling tolerance: relative tolerance times the deck-motion scale", "units": "m"},
            ),
            coupling_deck_motion_scale_m=(
                rows,
                _row_array(statuses, lambda s: s.deck_motion_scale_m, np.nan, float),
                {"long_name": "deck-motion scale: largest one-way deck harmonic under the saddles", "units": "m"},
            ),
            coupling_iterations=(
                rows,
                _row_array(statuses, lambda s: s.iterations, -1, np.int64),
                {"long_name": "coupling quasi-Newton steps", "units": "1"},
            ),
            coupling_mean_deck_change_m=(
                (*rows, "saddle"),
                change,
                {"long_name": "period-mean deck deflection change under each saddle, two-way minus one-way (up +)", "units": "m"},
            ),
            coupling_message=(
                rows,
                _row_array(statuses, lambda s: s.message, "", object).astype(str),
                {"long_name": "coupling outcome in words (for people; read the coupling_* values)"},
            ),
        )
    return xr.Dataset(data, coords={"load_case": list(LOAD_CASES), "model": list(MODELS)} if statuses else {})


def coupling_summary_fields(status: CouplingStatus) -> dict[str, object]:
    """The coupling's diagnostics added to a summary row of a two-way run (and so to studies)."""
    return {
        "coupling_converged": status.converged,
        "coupling_residual_m": status.residual_m,
        "coupling_tolerance_m": status.tolerance_m,
        "coupling_iterations": status.iterations,
    }
