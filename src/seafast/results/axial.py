"""The axial sliding analysis' record of one case: per (load_case, model) row, arrays, summary columns, Dataset.

:class:`AxialCaseArrays` is what :func:`seafast.analyses.axial.run_axial_analysis` fills
(docs/axial.md): each row's axial motion and forces over the period, its row values, its typed
warnings (:class:`~seafast.solvers.axial.AxialWarning`: ``friction_carries_load`` where the friction
carries more of the axial load than the lashings and stoppers, with what the lashings and
stoppers alone would do, ``frictionless_axial_force_N``, docs/axial.md#friction-credit), the
columns ``summary.csv`` gains and the variables of ``results.nc``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import xarray as xr

from seafast.results.dataset import LOAD_CASES, MODELS
from seafast.solvers.axial import AxialWarning

__all__ = ["AXIAL_SUMMARY_COLUMNS", "AXIAL_WARNINGS", "TIME_VARIABLES", "ROW_VARIABLES", "AxialCaseArrays"]

#: Columns ``summary.csv`` gains (after ``converged``) when the axial analysis runs.
AXIAL_SUMMARY_COLUMNS = ("slip_m", "friction_utilisation", "axial_force_N", "axial_warnings")

#: The typed axial warnings, in the order of the ``axial_warning`` coordinate of ``results.nc``.
AXIAL_WARNINGS = tuple(w.value for w in AxialWarning)

TIME_VARIABLES: dict[str, tuple[str, str]] = {
    "axial_displacement_m": ("cargo axial displacement relative to the deck (forward +)", "m"),
    "axial_velocity_m_per_s": ("cargo axial velocity relative to the deck (forward +)", "m/s"),
    "friction_force_N": ("friction force of all saddles on the cargo (forward +)", "N"),
    "friction_capacity_N": ("friction available, sum of mu_i max(N_i, 0) over the saddles", "N"),
    "lashing_axial_force_N": ("axial force of the lashings on the cargo (forward +)", "N"),
    "stopper_force_N": ("axial force of the end stoppers on the cargo (forward +)", "N"),
    "axial_load_N": ("axial inertia and gravity load on the cargo in the ship's frame (forward +)", "N"),
}
ROW_VARIABLES: dict[str, tuple[str, str]] = {
    "slip_m": ("sliding distance of the cargo per period (0 when stuck)", "m"),
    "friction_utilisation": ("friction force over friction available, maximum over the period (1 = slides)", "1"),
    "axial_force_N": ("largest axial force of the lashings and stoppers on the cargo", "N"),
    "critical_friction_coefficient": ("uniform friction coefficient below which the cargo starts to slide", "1"),
    "friction_moment_saddle_force_change_N": (
        (
            "estimated change of the saddle forces by the friction's moment "
            "(friction at the contact line, D/2 below the axis; quasi-static, bilateral saddles)"
        ),
        "N",
    ),
    "frictionless_axial_force_N": (
        "largest axial force of the lashings and stoppers without friction (what they alone would carry; inf: nothing restrains)",
        "N",
    ),
    "frictionless_axial_displacement_m": ("largest axial displacement of the cargo without friction (inf: nothing restrains it)", "m"),
    "axial_residual_norm": ("axial solver residual (HBM: relative; time domain: last period change)", "1"),
    "axial_residual_drift_m": (
        "time domain: estimated distance of the state it stopped at from the periodic state (0 for the HBM)",
        "m",
    ),
    "axial_iterations": ("axial solver iterations (HBM: Newton; time domain: periods)", "1"),
}


@dataclass(frozen=True)
class AxialCaseArrays:
    """The axial numbers of one case, axes (load_case, model, period_fraction[, saddle])."""

    period_fraction: np.ndarray
    time: dict[str, np.ndarray]  # TIME_VARIABLES, each (2, 2, N)
    friction_force_per_saddle_N: np.ndarray  # (2, 2, N, n_s)
    normal_force_N: np.ndarray  # (2, 2, N, n_s), max(N, 0)
    sliding: np.ndarray  # (2, 2, N) bool
    rows: dict[str, np.ndarray]  # ROW_VARIABLES, each (2, 2)
    converged: np.ndarray  # (2, 2) bool
    messages: np.ndarray  # (2, 2) str
    friction_coefficient: np.ndarray  # (n_s,)
    attrs: dict[str, Any] = field(default_factory=dict)
    warnings: np.ndarray = field(default_factory=lambda: np.zeros((2, 2, len(AXIAL_WARNINGS)), dtype=bool))  # (2, 2, n_w)

    def row_warnings(self, load_case: str, model: str) -> tuple[AxialWarning, ...]:
        """The typed warnings of one row."""
        flags = self.warnings[LOAD_CASES.index(load_case), MODELS.index(model)]
        return tuple(w for w, on in zip(AxialWarning, flags, strict=True) if on)

    def warning_lines(self) -> list[str]:
        """One line per row and warning, for people (the CLI prints them on stderr)."""
        out = []
        for i, lc in enumerate(LOAD_CASES):
            for j, m in enumerate(MODELS):
                for w in self.row_warnings(lc, m):
                    out.append(f"{lc} {m}: {w.value}: {self._explain(w, i, j)}")
        return out

    def _explain(self, warning: AxialWarning, i: int, j: int) -> str:
        friction = float(np.max(np.abs(self.time["friction_force_N"][i, j])))
        held = float(self.rows["axial_force_N"][i, j])
        alone, moves = float(self.rows["frictionless_axial_force_N"][i, j]), float(self.rows["frictionless_axial_displacement_m"][i, j])
        without = (
            "nothing else restrains the cargo axially"
            if math.isinf(moves)
            else f"without friction the lashings and stoppers alone would let it move {moves:.3g} m and carry {alone / 1e3:.1f} kN"
        )
        return (
            f"the friction carries up to {friction / 1e3:.1f} kN of the axial load, the lashings and stoppers {held / 1e3:.1f} kN; "
            f"{without}. Check that this friction may be credited (contact materials, vertical acceleration; "
            "docs/axial.md#friction-credit)"
        )

    def summary_columns(self, load_case: str, model: str) -> dict[str, Any]:
        """The axial columns of one summary row (plus ``critical_friction_coefficient`` and ``axial_converged``)."""
        i, j = LOAD_CASES.index(load_case), MODELS.index(model)
        names = (*AXIAL_SUMMARY_COLUMNS[:-1], "critical_friction_coefficient")
        out: dict[str, Any] = {name: float(self.rows[name][i, j]) for name in names}
        out["axial_warnings"] = ";".join(w.value for w in self.row_warnings(load_case, model))
        out["axial_converged"] = bool(self.converged[i, j])
        return out

    @property
    def summary_column_names(self) -> tuple[str, ...]:
        """The columns ``summary.csv`` gains: :data:`AXIAL_SUMMARY_COLUMNS`."""
        return AXIAL_SUMMARY_COLUMNS

    def extend_summary(self, rows: list[dict[str, Any]]) -> list[dict[str, Any]]:
        """The summary rows with the axial columns added; ``converged`` then includes the axial solve."""
        for row in rows:
            row.update(self.summary_columns(row["load_case"], row["model"]))
            row["converged"] = bool(row["converged"] and row["axial_converged"])
        return rows

    def merged_into(self, ds: xr.Dataset) -> xr.Dataset:
        """``ds`` (the case's results) with the axial variables and attributes merged in."""
        axial = self.to_dataset()
        out = xr.merge([ds, axial], compat="no_conflicts", join="outer", combine_attrs="override")
        out.attrs.update(ds.attrs)
        out.attrs.update(axial.attrs)
        return out

    def to_dataset(self) -> xr.Dataset:
        """The axial variables of ``results.nc`` (units and long names on every one)."""
        dims3 = ("load_case", "model", "period_fraction")
        data: dict[str, Any] = {
            name: xr.Variable(dims3, self.time[name], {"long_name": ln, "units": u}) for name, (ln, u) in TIME_VARIABLES.items()
        }
        data["friction_force_per_saddle_N"] = xr.Variable(
            dims3 + ("saddle",),
            self.friction_force_per_saddle_N,
            {"long_name": "friction force of each saddle on the cargo (forward +; shares mu_i N_i / sum mu_j N_j)", "units": "N"},
        )
        data["friction_normal_force_N"] = xr.Variable(
            dims3 + ("saddle",), self.normal_force_N, {"long_name": "saddle contact force the friction acts with, max(N, 0)", "units": "N"}
        )
        data["sliding"] = xr.Variable(dims3, self.sliding.astype(np.int8), {"long_name": "cargo sliding (1) or stuck (0)", "units": "1"})
        for name, (ln, u) in ROW_VARIABLES.items():
            data[name] = xr.Variable(("load_case", "model"), self.rows[name], {"long_name": ln, "units": u})
        data["axial_converged"] = xr.Variable(
            ("load_case", "model"), self.converged.astype(np.int8), {"long_name": "axial solver converged", "units": "1"}
        )
        data["axial_solver_message"] = xr.Variable(
            ("load_case", "model"), self.messages.astype(str), {"long_name": "axial solver message", "units": "1"}
        )
        data["friction_coefficient"] = xr.Variable(
            ("saddle",), self.friction_coefficient, {"long_name": "Coulomb friction coefficient of each saddle", "units": "1"}
        )
        data["axial_warning_flag"] = xr.Variable(
            ("load_case", "model", "axial_warning"),
            self.warnings.astype(np.int8),
            {"long_name": "typed axial warning raised (1) or not (0), one per axial_warning", "units": "1"},
        )
        label = {"long_name": "axial warning (AxialWarning value)", "units": "1"}
        coords = {"axial_warning": ("axial_warning", list(AXIAL_WARNINGS), label)}
        return xr.Dataset(data, coords=coords, attrs=self.attrs)
