"""Two-way coupling in ``results.nc``: each row's coupling outcome and the coupled hull girder.

Present only after a ``vessel.coupling: two_way`` run. The one-way hull variables
(``hull_still_water_deflection_m``, ``hull_still_water_bending_moment_Nm``,
``hull_still_water_shear_force_N``, ``hull_wave_deflection_m``, ``hull_wave_bending_moment_Nm``)
keep their names, grid and values and carry ``hull_coupling = "one_way"``; the coupled hull is
in the same variables with ``_coupled`` before the unit (``hull_still_water_deflection_coupled_m``
...), on the same ``hull_x_m`` and ``hull_period_fraction``, with ``hull_coupling = "two_way"``.

Coupling outcome, per ``(load_case, model)``: ``coupling_converged``, ``coupling_outcome`` (a
:class:`~seafast.coupling.status.CouplingOutcome` value), ``coupling_residual_m``,
``coupling_tolerance_m``, ``coupling_deck_motion_scale_m``, ``coupling_iterations``,
``coupling_mean_deck_change_m`` (per saddle) and ``coupling_message`` (for people).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import Any

import numpy as np
import xarray as xr
from numpy.typing import DTypeLike, NDArray

from seafast.coupling.hull import CoupledHull
from seafast.coupling.status import CouplingStatus
from seafast.results.dataset import LOAD_CASES, MODELS

__all__ = ["COUPLED_HULL_VARIABLES", "coupling_dataset", "coupling_summary_fields"]

COUPLED_HULL_VARIABLES = {
    "hull_still_water_deflection_coupled_m": "hull_still_water_deflection_m",
    "hull_still_water_bending_moment_coupled_Nm": "hull_still_water_bending_moment_Nm",
    "hull_still_water_shear_force_coupled_N": "hull_still_water_shear_force_N",
    "hull_wave_deflection_coupled_m": "hull_wave_deflection_m",
    "hull_wave_bending_moment_coupled_Nm": "hull_wave_bending_moment_Nm",
}
"""Each coupled hull variable and the one-way variable it pairs with."""

_UNDER = "under the two-way coupled cargo (the nonlinear model's deck forces at the saddles in place of its spread weight)"


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


def _outcome_variables(statuses: Mapping[tuple[str, str], CouplingStatus]) -> dict[str, tuple]:
    """Each row's coupling outcome over ``(load_case, model)`` (``coupling_mean_deck_change_m`` also per saddle)."""
    rows = ("load_case", "model")
    n_s = max(len(s.mean_deck_change_m) for s in statuses.values())
    change = np.full((len(LOAD_CASES), len(MODELS), n_s), np.nan)
    for i, lc in enumerate(LOAD_CASES):
        for j, mdl in enumerate(MODELS):
            if (lc, mdl) in statuses:
                change[i, j] = statuses[(lc, mdl)].mean_deck_change_m
    return dict(
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


_HULL_ATTRS = {"hull_coupling": "two_way"}


def _coupled_still_water_variables(hull: CoupledHull) -> dict[str, tuple]:
    """The coupled hull's still-water deflection, bending moment and shear force over ``hull_x_m``."""
    x = ("hull_x_m",)
    return dict(
        hull_still_water_deflection_coupled_m=(
            x,
            hull.still_water_deflection_m,
            {"long_name": f"still-water hull deflection (chord through AP and FP, up +), {_UNDER}", "units": "m", **_HULL_ATTRS},
        ),
        hull_still_water_bending_moment_coupled_Nm=(
            x,
            hull.still_water_bending_moment_Nm,
            {"long_name": f"still-water hull bending moment (sagging +), {_UNDER}", "units": "N m", **_HULL_ATTRS},
        ),
        hull_still_water_shear_force_coupled_N=(
            x,
            hull.still_water_shear_force_N,
            {"long_name": f"still-water hull shear force (V = dM/dx), {_UNDER}", "units": "N", **_HULL_ATTRS},
        ),
    )


def _coupled_wave_variables(wave_deflection_m: NDArray, wave_bending_moment_Nm: NDArray) -> dict[str, tuple]:
    """The coupled hull's wave-induced deflection [m] and bending moment [N m] over ``(hull_period_fraction, hull_x_m)``."""
    t = ("hull_period_fraction", "hull_x_m")
    return dict(
        hull_wave_deflection_coupled_m=(
            t,
            wave_deflection_m,
            {
                "long_name": f"wave-induced hull deflection (coupled total minus coupled still water), {_UNDER}",
                "units": "m",
                **_HULL_ATTRS,
            },
        ),
        hull_wave_bending_moment_coupled_Nm=(
            t,
            wave_bending_moment_Nm,
            {
                "long_name": f"wave-induced hull bending moment (sagging +; coupled total minus coupled still water), {_UNDER}",
                "units": "N m",
                **_HULL_ATTRS,
            },
        ),
    )


def coupling_dataset(statuses: Mapping[tuple[str, str], CouplingStatus], hull: CoupledHull | None) -> xr.Dataset:
    """The coupling variables of ``results.nc`` (see the module docstring).

    Parameters
    ----------
    statuses
        The coupling outcome of each ``(load_case, model)`` row.
    hull
        The coupled hull girder (``None`` when it was not computed).
    """
    data: dict[str, tuple] = _outcome_variables(statuses) if statuses else {}
    coords: dict[str, tuple] = {}
    if hull is not None:
        data.update(_coupled_still_water_variables(hull))
        if hull.wave_deflection_m is not None and hull.wave_bending_moment_Nm is not None:
            coords["hull_period_fraction"] = (
                "hull_period_fraction",
                hull.period_fraction,
                {"long_name": "t/T of the hull wave balance", "units": "1"},
            )
            data.update(_coupled_wave_variables(hull.wave_deflection_m, hull.wave_bending_moment_Nm))
        coords["hull_x_m"] = ("hull_x_m", hull.x_m, {"long_name": "x along the ship from the aft perpendicular", "units": "m"})
    return xr.Dataset(data, coords={**coords, "load_case": list(LOAD_CASES), "model": list(MODELS)} if statuses else coords)


def coupling_summary_fields(status: CouplingStatus) -> dict[str, object]:
    """The coupling's diagnostics added to a summary row of a two-way run (and so to studies)."""
    return {
        "coupling_converged": status.converged,
        "coupling_residual_m": status.residual_m,
        "coupling_tolerance_m": status.tolerance_m,
        "coupling_iterations": status.iterations,
    }
