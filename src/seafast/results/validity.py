"""Where the model's answers stop being answers: the small-displacement validity of a case's results.

The cargo model is linear beam theory on springs at fixed contact points, with small displacements and
rotations. A result far outside that (a saddle compressed by metres because its stiffness was typed in the
wrong unit) is still a solution of the equations, and a converged one, but not a description of a monopile on
its saddles. Each row of a run is checked against three lines, drawn here once:

* **displacement**: the largest saddle compression and cargo deflection at most a quarter of the cargo's
  outer diameter (:data:`DISPLACEMENT_SHARE_OF_DIAMETER`). A saddle is a cradle whose contact is a fraction
  of the diameter deep; a cargo moved by more than that against the deck has left, or gone through, its
  saddles, and fixed contact points with linear springs do not describe it;
* **rotation**: the cargo's largest slope at most 0.1 rad (:data:`MAX_ROTATION_RAD`), where the small-angle
  kinematics (sin, tan and 1 - cos against the angle) are within 0.5 %;
* **lift-off gap**: at most 0.1 m (:data:`DEFAULT_MAX_GAP_M`, the line the
  frequency sweeps draw): a monopile lifted further has left the sea-fastening's design state.

Off head seas, where a run also solves the cargo on its cradles (:mod:`seafast.results.cradle`), two more lines
for its linear rows (pads and lashing wires bilateral, side stoppers open):

* **pad tension**: the least pad force at least 0: a linear pad with a negative force pulls the cargo, which a
  pad cannot (the nonlinear row lifts it off);
* **stopper passed**: the cargo does not pass a side stopper the linear row leaves open.

The numbers of a row beyond a line are written (nothing computed is lost) and flagged: ``within_validity``
in ``results.nc``, a warning with a suggestion of what was probably meant, exit code 4 on the command line.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from enum import StrEnum
from typing import Any

import numpy as np

from seafast.config.schema import BASE_SADDLE_STIFFNESS_N_PER_M, Case
from seafast.model.structure import StructuralModel
from seafast.results.dataset import LOAD_CASES, MODELS

__all__ = [
    "DISPLACEMENT_SHARE_OF_DIAMETER",
    "MAX_ROTATION_RAD",
    "DEFAULT_MAX_GAP_M",
    "ValidityLimit",
    "ValidityIssue",
    "validity_issues",
    "within_validity",
    "with_validity",
    "likely_cause",
    "cargo_diameter_m",
]

DISPLACEMENT_SHARE_OF_DIAMETER = 0.25
"""Largest saddle compression and cargo deflection, as a share of the cargo's outer diameter [-]."""

MAX_ROTATION_RAD = 0.1
"""Largest cargo slope [rad]: sin, tan and 1 - cos are within 0.5 % of their small-angle forms."""

DEFAULT_MAX_GAP_M = 0.1
"""Largest detachment gap [m] inside the meaningful range (also the frequency sweeps', ``docs/sweeps.md``): a
monopile lifted 10 cm off its saddles has left the sea-fastening's design state; the model's linear lashings,
fixed saddle positions and undamped re-contact no longer describe what happens next."""


class ValidityLimit(StrEnum):
    """Which line of the model's small-displacement validity a result is beyond."""

    DISPLACEMENT = "displacement_beyond_quarter_diameter"
    """A saddle compression or the cargo deflection exceeds a quarter of the cargo's diameter."""
    ROTATION = "rotation_beyond_small_angle"
    """The cargo's slope exceeds :data:`MAX_ROTATION_RAD`."""
    LIFT_OFF_GAP = "lift_off_gap_beyond_meaningful_range"
    """A saddle's lift-off gap exceeds :data:`DEFAULT_MAX_GAP_M`."""
    PAD_TENSION = "pad_in_tension"
    """A linear row's cradle pad carries tension (a negative force): the bilateral pad pulls the cargo."""
    STOPPER_PASSED = "side_stopper_passed"
    """A linear row's cargo moves past a side stopper's gap (the linear model leaves the stoppers open)."""

    @property
    def description(self) -> str:
        """One line for people (CLI, study counts, report)."""
        return {
            ValidityLimit.DISPLACEMENT: "a saddle compression or the cargo deflection exceeds a quarter of the cargo's diameter: "
            "not a valid answer (check the units of the stiffnesses)",
            ValidityLimit.ROTATION: "the cargo's slope exceeds 0.1 rad: beyond the small-angle kinematics, not a valid answer",
            ValidityLimit.LIFT_OFF_GAP: "a saddle lifts off by more than 0.1 m: the cargo has left the sea-fastening's design "
            "state, not a valid answer",
            ValidityLimit.PAD_TENSION: "a linear cradle pad carries tension, which a pad cannot: the linear row is not a valid "
            "answer (the nonlinear row lifts the pad off)",
            ValidityLimit.STOPPER_PASSED: "the linear row's cargo moves past a side stopper it leaves open: not a valid answer "
            "(the nonlinear row engages the stopper)",
        }[self]


@dataclass(frozen=True)
class ValidityIssue:
    """One row's result beyond one line: the quantity, its value and the largest value allowed (SI units)."""

    load_case: str
    model: str
    limit: ValidityLimit
    quantity: str
    value: float
    allowed: float
    unit: str

    @property
    def message(self) -> str:
        """One line for people: the row, the quantity, the value and the line."""
        validity = (
            "linear cradle model's validity"
            if self.limit in (ValidityLimit.PAD_TENSION, ValidityLimit.STOPPER_PASSED)
            else "model's small-displacement validity"
        )
        return (
            f"{self.load_case} {self.model}: {self.quantity} {self.value:.4g} {self.unit} is beyond the {validity} "
            f"(at most {self.allowed:.3g} {self.unit}); the row's numbers are not a valid answer"
        )


def validity_issues(rows: Sequence[Mapping[str, Any]], diameter_m: float) -> tuple[ValidityIssue, ...]:
    """Every (row, line) where a case's summary rows leave the model's validity (empty: all rows valid).

    Parameters
    ----------
    rows
        Summary rows (``load_case``, ``model``, ``u_c_m``, ``u_s_m``, ``u_d_m``, ``cargo_slope_rad``; off head seas
        also ``pad_force_min_N`` and ``stopper_overclosure_m``), as :attr:`seafast.analyses.run.CaseResult.summary`
        and :func:`seafast.results.summary.summary_rows` give them.
    diameter_m
        The cargo's largest outer diameter [m].
    """
    displacement_allowed = DISPLACEMENT_SHARE_OF_DIAMETER * float(diameter_m)
    issues: list[ValidityIssue] = []
    for row in rows:
        checks: list[tuple[ValidityLimit, str, Any, float, str]] = [
            (ValidityLimit.DISPLACEMENT, "saddle compression", row["u_s_m"], displacement_allowed, "m"),
            (ValidityLimit.DISPLACEMENT, "cargo deflection", row["u_c_m"], displacement_allowed, "m"),
            (ValidityLimit.ROTATION, "cargo slope", row["cargo_slope_rad"], MAX_ROTATION_RAD, "rad"),
            (ValidityLimit.LIFT_OFF_GAP, "lift-off gap", row["u_d_m"], DEFAULT_MAX_GAP_M, "m"),
        ]
        if "pad_force_min_N" in row:  # the cargo on its cradles (off head seas): a pad cannot pull, a stopper is not passed
            checks += [
                (ValidityLimit.PAD_TENSION, "pad tension", -float(row["pad_force_min_N"]), 0.0, "N"),
                (ValidityLimit.STOPPER_PASSED, "side stopper overclosure", row["stopper_overclosure_m"], 0.0, "m"),
            ]
        for limit, quantity, value, allowed, unit in checks:
            if not math.isfinite(float(value)) or float(value) > allowed:
                issues.append(ValidityIssue(str(row["load_case"]), str(row["model"]), limit, quantity, float(value), allowed, unit))
    return tuple(issues)


def within_validity(issues: Sequence[ValidityIssue]) -> np.ndarray:
    """(load_case, model) booleans: True where no line is crossed."""
    ok = np.ones((len(LOAD_CASES), len(MODELS)), dtype=bool)
    for issue in issues:
        ok[LOAD_CASES.index(issue.load_case), MODELS.index(issue.model)] = False
    return ok


def with_validity(rows: Sequence[Mapping[str, Any]], diameter_m: float) -> list[dict[str, Any]]:
    """The rows with ``within_validity`` (bool) set on each, False where the row crosses a line, and the
    lines crossed appended to the row's typed ``warnings`` (as :class:`ValidityLimit` members, each once)."""
    issues = validity_issues(rows, diameter_m)
    out = []
    for row in rows:
        crossed = {i.limit for i in issues if (i.load_case, i.model) == (row["load_case"], row["model"])}
        warnings = (*row.get("warnings", ()), *(limit for limit in ValidityLimit if limit in crossed))
        out.append({**row, "within_validity": not crossed, "warnings": warnings})
    return out


def likely_cause(case: Case, issues: Sequence[ValidityIssue]) -> str | None:
    """What was probably meant, when an input in the wrong unit explains the issues (else a generic hint).

    A saddle stiffness far below any real saddle's (steel saddles with timber or rubber pads: 1e8 to 1e10
    N/m) is the usual cause of metres of compression: its value read as kN/m, MN/m or GN/m is suggested.
    """
    if not issues:
        return None
    if all(i.limit in (ValidityLimit.PAD_TENSION, ValidityLimit.STOPPER_PASSED) for i in issues):
        return "a linear row's cradle pad pulls or its cargo passes a side stopper: the nonlinear rows hold the answer"
    stiffnesses = np.asarray(case.saddle_stiffnesses_N_per_m(), dtype=float)
    soft = float(np.min(stiffnesses))
    if any(i.limit is ValidityLimit.DISPLACEMENT for i in issues) and soft < 1e6:
        readings = ", ".join(f"{soft:g} {unit} = {soft * factor:.3g} N/m" for unit, factor in (("MN/m", 1e6), ("GN/m", 1e9)))
        return (
            f"seafastening.saddle_stiffness_N_per_m = {soft:g} N/m is far below a real saddle's stiffness (1e8 to 1e10 "
            f"N/m; the base case {BASE_SADDLE_STIFFNESS_N_PER_M:.3g} N/m): was it meant in another unit ({readings})?"
        )
    return "check the units of the case's stiffnesses (N/m), loads (N) and lengths (m) against the quantities they describe"


def cargo_diameter_m(model: StructuralModel) -> float:
    """The cargo's largest outer diameter [m] (the scale of the displacement line)."""
    return float(np.max(model.cargo.element_outer_diameter_m))
