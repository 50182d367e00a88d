"""The cargo across the ship in a run off head seas: its rows on the cradles, their summary columns and variables.

A run at a heading other than 180 deg also solves the 3-D cargo on its cradles, side stoppers and lashings
(docs/transverse.md#9-in-seafast-run) in the four rows of the vertical plane: ``static`` (still water) and
``dynamic`` (the wave, still water included), ``linear`` and ``nonlinear``. This module holds those rows
(:class:`CradleRow`, :class:`CradleRows`), the five columns they add to ``summary.csv``
(:data:`CRADLE_SUMMARY_COLUMNS`) and their labelled variables in ``results.nc`` (:meth:`CradleRows.to_dataset`).

* ``F_pad_N``: the largest pad force over the pads and the period [N];
* ``F_stopper_N``: the largest side-stopper force [N] (0 without stoppers);
* ``lashing_tension_max_N``, ``lashing_tension_min_N``: the largest and least lashing-wire tension [N] (0 without
  lashing wires);
* ``transverse_slip_m``: the largest lateral displacement of the cargo's axis at a saddle, relative to the deck,
  over the saddles and the period [m]: the motion across the pads' tangent at bottom dead centre. The pads are
  frictionless in this model, so it is the motion the pads' normals allow, not a slip against friction.

A linear row keeps the pads and lashing wires bilateral and the side stoppers open, as at rest (a bilateral
stopper with a gap would pull the cargo across its gap): its pad force ``k s`` goes negative where the pad would
pull (tension in a pad, flagged by the validity lines, :mod:`seafast.results.validity`), its wire tension negative
where a wire would push. Units: SI.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np
import xarray as xr
from numpy.typing import NDArray

from seafast.fourier import period_fraction
from seafast.results.dataset import LOAD_CASES, MODELS
from seafast.results.labelled import labelled_variable
from seafast.solvers.cradle_hbm import CradleResponse

__all__ = [
    "CRADLE_SUMMARY_COLUMNS",
    "CRADLE_FIELD_LONG_NAMES",
    "CRADLE_ERROR_OUTCOME",
    "CradleRow",
    "CradleLayout",
    "CradleRows",
    "failed_cradle_summary",
]

CRADLE_SUMMARY_COLUMNS = ("F_pad_N", "F_stopper_N", "lashing_tension_max_N", "lashing_tension_min_N", "transverse_slip_m")
"""The columns ``summary.csv`` gains off head seas, right after ``converged``."""

SIDES = ("port", "starboard")

_SUMMARY_VARIABLES = (
    ("F_pad_N", "largest cradle pad force", "N"),
    ("F_stopper_N", "largest side-stopper force", "N"),
    ("lashing_tension_max_N", "largest lashing-wire tension", "N"),
    ("lashing_tension_min_N", "least lashing-wire tension", "N"),
    ("transverse_slip_m", "largest lateral displacement of the cargo's axis at a saddle relative to the deck", "m"),
)

CRADLE_ERROR_OUTCOME = "error"
"""``cradle_outcome`` of a row whose cradle solve raised (the reason in ``cradle_error``; :func:`failed_cradle_summary`)."""

CRADLE_FIELD_LONG_NAMES: dict[str, str] = {
    **{name: description for name, description, _ in _SUMMARY_VARIABLES},
    "pad_force_min_N": "least cradle pad force (negative in a linear row where a pad would pull)",
    "stopper_overclosure_m": "how far a linear row's cargo passes a side stopper it leaves open",
    "cradle_converged": "the cargo's solve on its cradles converged",
    "cradle_outcome": "outcome of the cradle solve (SolverOutcome value, or error)",
    "cradle_residual": "largest residual of the cradle solve relative to its scale",
    "cradle_error": "why the cradle solve raised (empty when it did not)",
}
"""The long name of every field a row's cradle solve adds to a summary row (what a study's ``study.nc`` labels them)."""


@dataclass(frozen=True)
class CradleLayout:
    """Where the cradles' elements are: what the rows' element columns mean.

    Attributes
    ----------
    saddle_x_m, tube_radius_m
        Each saddle's position along the cargo and the tube's outer radius there [m], (n_s,).
    contact_angle_deg
        The pads' half-angle from bottom dead centre [deg].
    lateral_dof
        The cargo's lateral DOF ``v`` at each saddle's node (:mod:`seafast.model.cargo3d`'s order), (n_s,).
    stopper_x_m, stopper_side, stopper_gap_m
        Each side stopper's position [m], side (``port``/``starboard``) and gap [m].
    lashing_saddle, lashing_direction
        Each lashing wire's saddle (index) and unit direction from its cargo point to its deck anchor (x, y, z).
    """

    saddle_x_m: NDArray[np.float64]
    tube_radius_m: NDArray[np.float64]
    contact_angle_deg: float
    lateral_dof: NDArray[np.intp]
    stopper_x_m: NDArray[np.float64]
    stopper_side: tuple[str, ...]
    stopper_gap_m: NDArray[np.float64]
    lashing_saddle: NDArray[np.intp]
    lashing_direction: NDArray[np.float64]


@dataclass(frozen=True)
class CradleRow:
    """One (load case, model) row of the cargo on its cradles.

    ``response.element_force_N`` is the nonlinear law's ``k max(s, 0)`` in a nonlinear row, and ``k s`` of the
    bilateral pads and wires (signed; the stoppers open, 0) in a linear row (module docstring).
    """

    response: CradleResponse
    linear: bool

    @property
    def converged(self) -> bool:
        return bool(self.response.converged)

    def transverse_slip_m(self, layout: CradleLayout) -> float:
        """The largest |v| of the cargo's axis at a saddle over the period [m] (relative to the deck)."""
        return float(np.max(np.abs(self.response.cargo_displacement_m[:, layout.lateral_dof]), initial=0.0))

    def summary_fields(self, layout: CradleLayout) -> dict[str, Any]:
        """The row's :data:`CRADLE_SUMMARY_COLUMNS` and what the validity lines and the CLI read.

        Beside the five columns: ``pad_force_min_N`` (the least pad force [N]; negative in a linear row where a pad
        would pull), ``stopper_overclosure_m`` (how far a linear row's cargo passes a stopper it leaves open [m];
        0 in a nonlinear row), ``cradle_converged``, ``cradle_outcome`` and ``cradle_residual``.
        """
        r = self.response
        pads, stoppers, wires = r.pad_force_N.reshape(r.time_s.size, -1), r.stopper_force_N, r.lashing_tension_N
        overclosure = r.engagement_m[:, r.pad_count : r.pad_count + r.stopper_count] if self.linear else np.zeros((1, 0))
        return {
            "F_pad_N": float(np.max(pads, initial=0.0)),
            "F_stopper_N": float(np.max(stoppers, initial=0.0)),
            "lashing_tension_max_N": float(np.max(wires)) if wires.size else 0.0,
            "lashing_tension_min_N": float(np.min(wires)) if wires.size else 0.0,
            "transverse_slip_m": self.transverse_slip_m(layout),
            "pad_force_min_N": float(np.min(pads)) if pads.size else 0.0,
            "stopper_overclosure_m": float(np.max(overclosure, initial=0.0)),
            "cradle_converged": self.converged,
            "cradle_outcome": r.outcome.value,
            "cradle_residual": float(r.residual),
        }


@dataclass(frozen=True)
class CradleRows:
    """The four rows of the cargo on its cradles, on one time grid, with the layout of their elements."""

    rows: Mapping[tuple[str, str], CradleRow]
    layout: CradleLayout

    @property
    def converged(self) -> bool:
        return all(row.converged for row in self.rows.values())

    def fields(self, load_case: str, model: str) -> dict[str, Any]:
        """The summary fields of one row (:meth:`CradleRow.summary_fields`)."""
        return self.rows[(load_case, model)].summary_fields(self.layout)

    def extend_summary(self, rows: list[dict[str, Any]]) -> list[dict[str, Any]]:
        """Summary rows with each row's cradle fields; a row is converged when its cradle solve is too."""
        out = [{**r, **self.fields(r["load_case"], r["model"])} for r in rows]
        return [{**r, "converged": bool(r["converged"] and r["cradle_converged"])} for r in out]

    def merged_into(self, ds: xr.Dataset) -> xr.Dataset:
        """``ds`` (a run's Dataset) with the cradle variables (:meth:`to_dataset`) and the pads' angle attribute; its
        ``converged`` false where the row's cradle solve did not converge (as the summary's)."""
        cradle = self.to_dataset()
        out = xr.merge([ds, cradle], combine_attrs="override")
        out.attrs.update(cradle.attrs)
        if "converged" in out:
            ok = np.array([[self.rows[(lc, m)].converged for m in MODELS] for lc in LOAD_CASES])
            out["converged"] = out["converged"].copy(data=out["converged"].values & ok)
        return out

    def to_dataset(self) -> xr.Dataset:
        """The rows' labelled variables for ``results.nc`` (``cradle_*`` dimensions; see docs/interface.md)."""
        first = self.rows[(LOAD_CASES[0], MODELS[0])].response
        N = first.time_s.size
        grid = [[self.rows[(lc, m)].response for m in MODELS] for lc in LOAD_CASES]

        def stack(get: Any) -> NDArray[np.float64]:
            return np.array([[get(r) for r in line] for line in grid])

        lay = self.layout
        pad_dims = ("load_case", "model", "cradle_period_fraction", "saddle", "pad_side")
        row_dims = ("load_case", "model")
        per_pad = row_dims + ("saddle", "pad_side")
        pads = stack(lambda r: r.pad_force_N)
        pad_open = stack(lambda r: r.open_fraction[: r.pad_count].reshape(-1, 2))
        stopper_open = stack(lambda r: r.open_fraction[r.pad_count : r.pad_count + r.stopper_count])
        wire_slack = stack(lambda r: r.open_fraction[r.pad_count + r.stopper_count :])
        lateral = stack(lambda r: r.cargo_displacement_m[:, lay.lateral_dof])
        data = {
            "pad_force_N": labelled_variable(
                pad_dims, pads, "pad normal force on the cargo (linear rows: k s, negative where the pad would pull)", "N"
            ),
            "pad_force_max_N": labelled_variable(per_pad, pads.max(axis=2), "largest pad force over the period", "N"),
            "pad_force_min_N": labelled_variable(per_pad, pads.min(axis=2), "least pad force over the period", "N"),
            "pad_open_fraction": labelled_variable(
                per_pad,
                pad_open,
                "fraction of the period the pad is lifted off (linear rows: would pull)",
                "1",
            ),
            "stopper_force_N": labelled_variable(
                row_dims + ("cradle_period_fraction", "stopper"), stack(lambda r: r.stopper_force_N), "side-stopper force on the cargo", "N"
            ),
            "stopper_open_fraction": labelled_variable(
                row_dims + ("stopper",), stopper_open, "fraction of the period the side stopper is clear of the cargo", "1"
            ),
            "lashing_tension_N": labelled_variable(
                row_dims + ("cradle_period_fraction", "lashing"),
                stack(lambda r: r.lashing_tension_N),
                "lashing-wire tension (linear rows: negative where the wire would push)",
                "N",
            ),
            "lashing_slack_fraction": labelled_variable(
                row_dims + ("lashing",), wire_slack, "fraction of the period the lashing wire is slack", "1"
            ),
            "cargo_lateral_displacement_m": labelled_variable(
                row_dims + ("cradle_period_fraction", "saddle"),
                lateral,
                "lateral displacement of the cargo's axis at the saddle relative to the deck, to port positive",
                "m",
            ),
            "stopper_force_max_N": labelled_variable(
                row_dims + ("stopper",), stack(lambda r: r.stopper_force_N.max(axis=0)), "largest side-stopper force", "N"
            ),
            "lashing_wire_tension_max_N": labelled_variable(
                row_dims + ("lashing",), stack(lambda r: r.lashing_tension_N.max(axis=0)), "largest lashing-wire tension", "N"
            ),
            "lashing_wire_tension_min_N": labelled_variable(
                row_dims + ("lashing",), stack(lambda r: r.lashing_tension_N.min(axis=0)), "least lashing-wire tension", "N"
            ),
            **{
                name: labelled_variable(
                    row_dims,
                    [[self.fields(lc, m)[name] for m in MODELS] for lc in LOAD_CASES],
                    f"{description} (as in summary.csv)",
                    unit,
                )
                for name, description, unit in _SUMMARY_VARIABLES
            },
            "cradle_solver_outcome": labelled_variable(
                row_dims, stack(lambda r: r.outcome.value).astype(str), "outcome of the cradle solve (SolverOutcome value)", "1"
            ),
            "cradle_residual": labelled_variable(
                row_dims, stack(lambda r: r.residual), "largest residual of the cradle solve relative to its scale", "1"
            ),
        }
        coords = {
            "cradle_period_fraction": labelled_variable(
                ("cradle_period_fraction",), period_fraction(N), "time over the wave period t/T", "1"
            ),
            "pad_side": labelled_variable(("pad_side",), np.array(SIDES), "the pad's side of bottom dead centre", "1"),
            "cradle_tube_radius_m": labelled_variable(("saddle",), lay.tube_radius_m, "cargo outer radius at the saddle", "m"),
            "stopper_x_m": labelled_variable(("stopper",), lay.stopper_x_m, "side stopper position along the cargo", "m"),
            "stopper_side": labelled_variable(("stopper",), np.array(lay.stopper_side, dtype=str), "side stopper's side", "1"),
            "stopper_gap_m": labelled_variable(("stopper",), lay.stopper_gap_m, "side stopper's gap to the cargo at rest", "m"),
            "lashing_saddle": labelled_variable(("lashing",), lay.lashing_saddle, "the lashing wire's saddle (index)", "1"),
            "lashing_direction": labelled_variable(
                ("lashing", "xyz"), lay.lashing_direction.reshape(-1, 3), "unit direction of the wire from its lug to its anchor", "1"
            ),
        }
        attrs = {"saddle_contact_angle_deg": lay.contact_angle_deg}
        return xr.Dataset(data, coords=coords, attrs=attrs)


def failed_cradle_summary(rows: list[dict[str, Any]], reason: str) -> list[dict[str, Any]]:
    """Summary rows whose cradle solve raised: the vertical plane kept, the cradle's maxima unknown (None).

    Each row gains the fields :meth:`CradleRow.summary_fields` gives (numbers None), ``cradle_converged`` and
    ``converged`` false, ``cradle_outcome`` :data:`CRADLE_ERROR_OUTCOME` and ``cradle_error`` the ``reason``.
    """
    unknown = dict.fromkeys((*CRADLE_SUMMARY_COLUMNS, "pad_force_min_N", "stopper_overclosure_m"))
    failed = {**unknown, "cradle_converged": False, "cradle_outcome": CRADLE_ERROR_OUTCOME, "cradle_residual": None}
    return [{**row, **failed, "cradle_error": reason, "converged": False} for row in rows]
