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
  over the saddles and the period [m]: the motion across the pads' tangent at bottom dead centre. Without friction
  the pads are frictionless, so it is the motion the pads' normals allow, not a slip against friction.

With ``seafastening.friction_coefficient`` set, the nonlinear rows are solved on frictional pads
(:class:`~seafast.solvers.pad_tangential.FrictionalCradleResponse`) and:

* ``transverse_slip_m`` of a nonlinear row is the largest slip of a pad: its slider's largest displacement from its
  position at rest ``|w - w_rest|`` (circumferential and axial together) over the pads and the period [m];
* ``pad_friction_utilisation`` (:data:`FRICTION_SUMMARY_COLUMNS`, after the five) is the largest ``|f| / (mu F_n)``
  over the pads and the period [-]: 1 where a pad slips. A linear row has no friction: its slip keeps the
  definition above and its utilisation is NaN.

A linear row keeps the pads and lashing wires bilateral and the side stoppers open, as at rest (a bilateral
stopper with a gap would pull the cargo across its gap): its pad force ``k s`` goes negative where the pad would
pull (tension in a pad, flagged by the validity lines, :mod:`seafast.results.validity`), its wire tension negative
where a wire would push. Units: SI.

Size: over 400 lines because the rows' summary fields, their ``results.nc`` variables with and without friction and
their grid over one or several wave periods (a subharmonic) are one schema, read together.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np
import xarray as xr
from numpy.typing import NDArray

from seafast.fourier import period_fraction
from seafast.model.pad_friction import TANGENTIAL_DIRECTIONS
from seafast.results.dataset import LOAD_CASES, MODELS
from seafast.results.labelled import labelled_variable
from seafast.solvers.cradle_hbm import CradleResponse
from seafast.solvers.outcome import SolverOutcome
from seafast.solvers.pad_tangential import FrictionalCradleResponse

__all__ = [
    "CRADLE_SUMMARY_COLUMNS",
    "FRICTION_SUMMARY_COLUMNS",
    "CRADLE_FIELD_LONG_NAMES",
    "CRADLE_ERROR_OUTCOME",
    "CradleRow",
    "CradleLayout",
    "CradleRows",
    "failed_cradle_summary",
]

CRADLE_SUMMARY_COLUMNS = ("F_pad_N", "F_stopper_N", "lashing_tension_max_N", "lashing_tension_min_N", "transverse_slip_m")
"""The columns ``summary.csv`` gains off head seas, right after ``converged``."""

FRICTION_SUMMARY_COLUMNS = ("pad_friction_utilisation",)
"""The column ``summary.csv`` gains after :data:`CRADLE_SUMMARY_COLUMNS` when the pads carry friction."""

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
    "pad_friction_utilisation": "largest pad friction utilisation |f| / (mu F_n) (frictional pads; NaN in a linear row)",
    "cradle_message": "the frictional cradle solve's account (why it did not converge)",
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
    bilateral pads and wires (signed; the stoppers open, 0) in a linear row (module docstring). ``friction`` is the
    solve on frictional pads the row came from (its ``cradle`` is ``response``), None on frictionless pads.
    """

    response: CradleResponse
    linear: bool
    friction: FrictionalCradleResponse | None = None

    @property
    def converged(self) -> bool:
        return bool(self.response.converged)

    def transverse_slip_m(self, layout: CradleLayout) -> float:
        """On frictional pads the largest slider displacement from rest over the pads and the period [m]; else the
        largest |v| of the cargo's axis at a saddle over the period [m] (relative to the deck)."""
        if self.friction is not None:
            return float(np.max(self.friction.max_slip_m, initial=0.0))
        return float(np.max(np.abs(self.response.cargo_displacement_m[:, layout.lateral_dof]), initial=0.0))

    def friction_utilisation(self) -> float:
        """The largest ``|f| / (mu F_n)`` over the pads and the period [-]; NaN without friction."""
        if self.friction is None:
            return float("nan")
        return float(np.max(self.friction.friction_utilisation, initial=0.0))

    def summary_fields(self, layout: CradleLayout) -> dict[str, Any]:
        """The row's :data:`CRADLE_SUMMARY_COLUMNS` and what the validity lines and the CLI read.

        Beside the five columns: ``pad_force_min_N`` (the least pad force [N]; negative in a linear row where a pad
        would pull), ``stopper_overclosure_m`` (how far a linear row's cargo passes a stopper it leaves open [m];
        0 in a nonlinear row), ``cradle_converged``, ``cradle_outcome``, ``cradle_residual`` and ``cradle_period_multiple``
        (the wave periods the row's response repeats after: 1, or 2 to 6 for a subharmonic); on frictional pads
        also ``pad_friction_utilisation`` and ``cradle_message`` (the solver's account, with why it did not converge).
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
            "cradle_period_multiple": int(r.period_multiple),
        } | ({} if self.friction is None else {"pad_friction_utilisation": self.friction_utilisation(), "cradle_message": self._message()})

    def _message(self) -> str:
        """The solver's message; on frictional pads that did not converge with a pad lifting off, why."""
        r = self.response
        lifts = bool(np.any(r.open_fraction[: r.pad_count] > 0.0))
        if self.converged or not lifts:
            return r.message
        why = (
            "; a pad lifts off: neither the frictional harmonic balance nor the time march of the frictional cargo reached a "
            "periodic state within its tolerances (docs/transverse.md#8-friction-at-the-pads)"
        )
        return r.message + why


@dataclass(frozen=True)
class CradleRows:
    """The four rows of the cargo on its cradles, on one time grid, with the layout of their elements."""

    rows: Mapping[tuple[str, str], CradleRow]
    layout: CradleLayout

    @property
    def converged(self) -> bool:
        return all(row.converged for row in self.rows.values())

    @property
    def period_multiple(self) -> int:
        """The wave periods the rows' grid spans (1; 2 to 6 where the dynamic nonlinear row is a subharmonic)."""
        return max(int(row.response.period_multiple) for row in self.rows.values())

    def warning_lines(self) -> list[str]:
        """One line per row whose solve converged on a response repeating only every several wave periods (a
        subharmonic: ``CONVERGED_SUBHARMONIC``), for the CLI."""
        return [
            f"{lc} {m}: the cargo on its cradles repeats every {row.response.period_multiple} wave periods, not every one "
            f"(a subharmonic: the response at the wave's period is unstable); its maxima are over the "
            f"{row.response.period_multiple} periods (results.nc: cradle_period_fraction is t over them)"
            for (lc, m), row in self.rows.items()
            if row.response.outcome is SolverOutcome.CONVERGED_SUBHARMONIC
        ]

    @property
    def has_friction(self) -> bool:
        """Whether the nonlinear rows were solved on frictional pads."""
        return any(row.friction is not None for row in self.rows.values())

    @property
    def summary_column_names(self) -> tuple[str, ...]:
        """The columns these rows add to ``summary.csv``: the five, and the friction's with friction."""
        return CRADLE_SUMMARY_COLUMNS + (FRICTION_SUMMARY_COLUMNS if self.has_friction else ())

    def fields(self, load_case: str, model: str) -> dict[str, Any]:
        """The summary fields of one row (:meth:`CradleRow.summary_fields`); with friction every row has
        ``pad_friction_utilisation`` (NaN in a row without friction)."""
        row = self.rows[(load_case, model)]
        extra = {"pad_friction_utilisation": row.friction_utilisation()} if self.has_friction else {}
        return row.summary_fields(self.layout) | extra

    def extend_summary(self, rows: list[dict[str, Any]]) -> list[dict[str, Any]]:
        """Summary rows with each row's cradle fields; a row is converged when its cradle solve is too."""
        out = [{**r, **self.fields(r["load_case"], r["model"])} for r in rows]
        return [{**r, "converged": bool(r["converged"] and r["cradle_converged"])} for r in out]

    def merged_into(self, ds: xr.Dataset) -> xr.Dataset:
        """``ds`` (a run's Dataset) with the cradle variables (:meth:`to_dataset`) and the pads' angle attribute; its
        ``converged`` false where the row's cradle solve did not converge (as the summary's)."""
        cradle = self.to_dataset()
        out = xr.merge([ds, cradle], compat="no_conflicts", join="outer", combine_attrs="override")
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
                    f"{self._description(name, description)} (as in summary.csv)",
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
        if self.has_friction:
            data |= self._friction_variables(N)
        coords = self._coordinates(N)
        attrs = {"saddle_contact_angle_deg": lay.contact_angle_deg, "cradle_period_multiple": self.period_multiple}
        return xr.Dataset(data, coords=coords, attrs=attrs)

    def _coordinates(self, N: int) -> dict[str, xr.Variable]:
        """The cradle variables' coordinates on ``N`` samples of the rows' period (P wave periods, P the
        :attr:`period_multiple`)."""
        lay = self.layout
        P = self.period_multiple
        over = "time over the wave period t/T" if P == 1 else f"time over {P} wave periods t/({P} T) (a subharmonic)"
        return {
            "cradle_period_fraction": labelled_variable(("cradle_period_fraction",), period_fraction(N), over, "1"),
            "pad_side": labelled_variable(("pad_side",), np.array(SIDES), "the pad's side of bottom dead centre", "1"),
            **(
                {
                    "pad_direction": labelled_variable(
                        ("pad_direction",), np.array(TANGENTIAL_DIRECTIONS), "the pad's tangential direction", "1"
                    )
                }
                if self.has_friction
                else {}
            ),
            "cradle_tube_radius_m": labelled_variable(("saddle",), lay.tube_radius_m, "cargo outer radius at the saddle", "m"),
            "stopper_x_m": labelled_variable(("stopper",), lay.stopper_x_m, "side stopper position along the cargo", "m"),
            "stopper_side": labelled_variable(("stopper",), np.array(lay.stopper_side, dtype=str), "side stopper's side", "1"),
            "stopper_gap_m": labelled_variable(("stopper",), lay.stopper_gap_m, "side stopper's gap to the cargo at rest", "m"),
            "lashing_saddle": labelled_variable(("lashing",), lay.lashing_saddle, "the lashing wire's saddle (index)", "1"),
            "lashing_direction": labelled_variable(
                ("lashing", "xyz"), lay.lashing_direction.reshape(-1, 3), "unit direction of the wire from its lug to its anchor", "1"
            ),
        }

    def _description(self, name: str, description: str) -> str:
        """A summary variable's long name; the slip's says what it is on frictional pads."""
        if name != "transverse_slip_m" or not self.has_friction:
            return description
        return "nonlinear rows: largest pad slider displacement from rest; linear rows: " + description

    def _friction_variables(self, N: int) -> dict[str, xr.Variable]:
        """The pads' friction in ``results.nc`` (rows without friction NaN): per-pad histories and maxima, and the
        summary's ``pad_friction_utilisation``."""
        n_s = self.layout.saddle_x_m.size
        nan = np.full((N, n_s, 2, 2), np.nan)

        def stack(get: Any) -> NDArray[np.float64]:
            return np.array([[get(self.rows[(lc, m)].friction) for m in MODELS] for lc in LOAD_CASES])

        force = stack(lambda f: nan if f is None else f.friction_force_N.reshape(N, n_s, 2, 2))
        slip = stack(lambda f: nan if f is None else f.slip_m.reshape(N, n_s, 2, 2))
        use = stack(lambda f: nan[..., 0] if f is None else f.friction_utilisation.reshape(N, n_s, 2))
        rows = ("load_case", "model")
        history = rows + ("cradle_period_fraction", "saddle", "pad_side")
        per_pad = rows + ("saddle", "pad_side")
        return {
            "pad_friction_force_N": labelled_variable(
                history + ("pad_direction",),
                force,
                "pad friction force resisting the pad's motion (circumferential to port +, axial forward +); on the cargo the opposite",
                "N",
            ),
            "pad_slip_m": labelled_variable(
                history + ("pad_direction",), slip, "pad slider's displacement from its position at rest (circumferential, axial)", "m"
            ),
            "pad_friction_utilisation_history": labelled_variable(
                history, use, "pad friction force over its limit |f| / (mu F_n) (1 in slip, 0 where the pad is open)", "1"
            ),
            "pad_friction_utilisation_max": labelled_variable(
                per_pad, use.max(axis=2), "largest friction utilisation of the pad over the period", "1"
            ),
            "pad_slip_max_m": labelled_variable(
                per_pad, np.hypot(slip[..., 0], slip[..., 1]).max(axis=2), "largest slider displacement of the pad from rest", "m"
            ),
            "pad_friction_utilisation": labelled_variable(
                rows,
                [[self.rows[(lc, m)].friction_utilisation() for m in MODELS] for lc in LOAD_CASES],
                "largest pad friction utilisation (as in summary.csv; NaN without friction)",
                "1",
            ),
        }


def failed_cradle_summary(rows: list[dict[str, Any]], reason: str) -> list[dict[str, Any]]:
    """Summary rows whose cradle solve raised: the vertical plane kept, the cradle's maxima unknown (None).

    Each row gains the fields :meth:`CradleRow.summary_fields` gives (numbers None), ``cradle_converged`` and
    ``converged`` false, ``cradle_outcome`` :data:`CRADLE_ERROR_OUTCOME` and ``cradle_error`` the ``reason``.
    """
    unknown = dict.fromkeys((*CRADLE_SUMMARY_COLUMNS, "pad_force_min_N", "stopper_overclosure_m"))
    failed = {**unknown, "cradle_converged": False, "cradle_outcome": CRADLE_ERROR_OUTCOME, "cradle_residual": None}
    return [{**row, **failed, "cradle_error": reason, "converged": False} for row in rows]
