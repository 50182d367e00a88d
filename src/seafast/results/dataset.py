"""Labelled results of one case: an xarray Dataset with named dimensions and units.

Dimensions: ``load_case`` (static, dynamic), ``model`` (linear, nonlinear), ``period_fraction``
(t / T over one wave period), ``saddle``, ``x_cargo_m`` (cargo nodes), ``x_moment_m``
(bending-moment sample points; element ends appear twice so jumps show), ``solver_warning``
(the :class:`~seafast.solvers.outcome.SolverWarning` values; ``solver_warning_flag`` is 1 where
a row raised one).
``dynamic`` is the total response (still water included). ``solver_outcome`` holds each row's
:class:`~seafast.solvers.outcome.SolverOutcome` value (``SolverOutcome(value)`` reads it back).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np
import xarray as xr

from seafast.excitation.harmonic import HarmonicExcitation
from seafast.fourier import harmonics_to_time, period_fraction
from seafast.model.structure import StructuralModel
from seafast.model.warning import ModelWarning
from seafast.results.labelled import labelled_variable as _var
from seafast.results.timeseries import PeriodTimeSeries, moment_lines
from seafast.solvers.outcome import SolverOutcome, SolverWarning

__all__ = [
    "LOAD_CASES",
    "MODELS",
    "SUMMARY_COLUMNS",
    "SOLVER_OUTCOMES",
    "SOLVER_WARNINGS",
    "CaseArrays",
    "case_arrays",
    "build_case_dataset",
    "summary_rows_from_arrays",
    "largest_slope_rad",
    "seafastening_baseline",
    "RowWarning",
    "row_warnings",
]

SOLVER_OUTCOMES = tuple(o.value for o in SolverOutcome if o is not SolverOutcome.CONVERGED_BY_TIME_MARCH)
"""The outcomes ``solver_outcome``'s ``long_name`` lists (the time march's is the frictional cradle row's alone:
``cradle_solver_outcome``)."""
SOLVER_WARNINGS = tuple(w.value for w in SolverWarning)
LOAD_CASES = ("static", "dynamic")
MODELS = ("linear", "nonlinear")
SUMMARY_COLUMNS = ("load_case", "model", "u_c_m", "u_s_m", "u_d_m", "F_N", "M_b_Nm", "sigma_b_Pa", "converged")

RowWarning = SolverWarning | ModelWarning
"""A typed warning of a summary row: its solve's or its model's."""


def row_warnings(
    load_case: str, solver_warnings: Iterable[SolverWarning], model_warnings: Iterable[ModelWarning]
) -> tuple[RowWarning, ...]:
    """A summary row's typed warnings (its ``warnings``): its solve's, then the model's that bear on the row.

    A model warning bears on every row unless it concerns the motion only
    (:attr:`ModelWarning.dynamic_only`, e.g. the damping fit), which leaves the ``static`` rows.
    Each warning once, in its enum's order (so that every route to a row lists them alike).
    """
    solver, model = set(solver_warnings), set(model_warnings)
    bearing = [w for w in ModelWarning if w in model and (load_case != "static" or not w.dynamic_only)]
    return (*[w for w in SolverWarning if w in solver], *bearing)


_SUMMARY_ATTRS = {
    "u_c_m": ("maximum cargo deflection relative to the sea-fastening baseline (rigid-body motion removed)", "m"),
    "u_s_m": ("maximum saddle compression", "m"),
    "u_d_m": ("maximum saddle detachment (gap); 0 for the linear model", "m"),
    "F_N": ("maximum saddle normal force", "N"),
    "M_b_Nm": ("maximum absolute bending moment in the cargo", "N m"),
    "sigma_b_Pa": ("maximum absolute bending stress in the cargo, M_b (D/2) / I", "Pa"),
    "converged": ("solver converged", "1"),
    "contact_preserved": ("every saddle in contact over the whole period (linear theory valid)", "1"),
}


def seafastening_baseline(model: StructuralModel, excitation: HarmonicExcitation, deck_z: np.ndarray) -> np.ndarray:
    """Straight line through the deck points under the outermost saddles, at every cargo node [m].

    ``deck_z`` (N, n_s) are the deck deflections of one row, ``excitation`` that row's
    excitation; returns (N, n_nodes).

    The frame in which the cargo's own deflection is reported: it moves with the deck at the
    sea-fastening, so the hull girder's deflection elsewhere along the ship (tens of mm
    relative to the ship's end chord) does not swamp the cargo's millimetres. With a single
    saddle the line has the deck slope under it.
    """
    x = model.cargo.node_x_m
    xs = model.saddle_x_m
    if xs.size >= 2:
        slope = (deck_z[..., -1] - deck_z[..., 0]) / (xs[-1] - xs[0])
    else:
        theta = excitation.deck_displacement[:, model.saddle_deck_dof + 1]
        slope = harmonics_to_time(theta, deck_z.shape[-2])[:, 0]
    return deck_z[..., :1] + slope[..., None] * (x - xs[0])


@dataclass(frozen=True)
class CaseArrays:
    """The numbers of one case as plain arrays, axes (load_case, model, period_fraction, ...)."""

    period_fraction: np.ndarray
    x_moment_m: np.ndarray
    cargo_deflection_m: np.ndarray  # relative to the sea-fastening baseline
    cargo_deflection_vessel_frame_m: np.ndarray
    saddle_compression_m: np.ndarray
    saddle_gap_m: np.ndarray
    saddle_force_N: np.ndarray
    bending_moment_Nm: np.ndarray
    bending_stress_Pa: np.ndarray
    deck_deflection_m: np.ndarray  # (load_case, model, period_fraction, saddle)
    deck_rise_m: np.ndarray
    converged: np.ndarray  # (load_case, model)
    residual_norm: np.ndarray
    iterations: np.ndarray
    solver_message: np.ndarray
    harmonic_truncation_indicator: np.ndarray  # (load_case, model, saddle)
    truncation_error: np.ndarray  # (load_case, model, saddle): estimated peak-force error from the harmonics left out
    tensile_force_error_N: np.ndarray
    solver_outcome: np.ndarray  # (load_case, model): SolverOutcome values
    solver_warning: np.ndarray  # (load_case, model, solver_warning): bool, one per SolverWarning

    def maxima(self) -> dict[str, np.ndarray]:
        """Summary quantities (docs/conventions.md#8-summary-quantities), each of shape (load_case, model)."""
        return {
            "u_c_m": np.abs(self.cargo_deflection_m).max(axis=(2, 3)),
            "u_s_m": np.maximum(self.saddle_compression_m.max(axis=(2, 3)), 0.0),
            "u_d_m": self.saddle_gap_m.max(axis=(2, 3)),
            "F_N": self.saddle_force_N.max(axis=(2, 3)),
            "M_b_Nm": np.abs(self.bending_moment_Nm).max(axis=(2, 3)),
            "sigma_b_Pa": np.abs(self.bending_stress_Pa).max(axis=(2, 3)),
            "contact_preserved": (self.saddle_compression_m > 0.0).all(axis=(2, 3)),
        }


def case_arrays(
    model: StructuralModel,
    excitation: HarmonicExcitation,
    series: Mapping[tuple[str, str], PeriodTimeSeries],
    time_samples: int,
    excitations: Mapping[tuple[str, str], HarmonicExcitation] | None = None,
) -> CaseArrays:
    """Collect the four responses keyed by (load_case, model) into arrays, with moment lines.

    ``excitations`` gives the excitation of each (load_case, model) when they differ (two-way
    hull-cargo coupling); by default every row has ``excitation`` (its static part for the
    static load case).
    """
    nodes = model.cargo.node_x_m
    n_s = model.saddle_count
    disp = np.zeros((2, 2, time_samples, nodes.size))
    comp = np.zeros((2, 2, time_samples, n_s))
    force = np.zeros_like(comp)
    moments, stresses = [], []
    x_moment = np.zeros(0)
    converged = np.zeros((2, 2), dtype=bool)
    residual = np.full((2, 2), np.nan)
    iterations = np.zeros((2, 2), dtype=int)
    truncation = np.full((2, 2, n_s), np.nan)
    truncation_error = np.full((2, 2, n_s), np.nan)
    tensile = np.full((2, 2), np.nan)
    messages = np.empty((2, 2), dtype=object)
    outcomes = np.empty((2, 2), dtype=object)
    flags = np.zeros((2, 2, len(SOLVER_WARNINGS)), dtype=bool)
    deck_all = np.zeros((2, 2, time_samples, n_s))
    baseline = np.zeros((2, 2, time_samples, nodes.size))
    for i, lc in enumerate(LOAD_CASES):
        for j, mdl in enumerate(MODELS):
            exc = (excitations or {}).get((lc, mdl), excitation)
            exc = exc.static_part() if lc == "static" else exc
            deck_all[i, j] = harmonics_to_time(exc.deck_displacement[:, model.saddle_deck_dof], time_samples)
            baseline[i, j] = seafastening_baseline(model, exc, deck_all[i, j])
            ts = series[(lc, mdl)]
            disp[i, j] = ts.cargo_displacement_m[:, 0::2]
            comp[i, j] = ts.saddle_compression_m
            force[i, j] = ts.saddle_force_N
            x_moment, m, sig = moment_lines(model, ts, exc)
            moments.append(m)
            stresses.append(sig)
            converged[i, j] = ts.converged
            residual[i, j] = ts.diagnostics.get("residual_norm", np.nan)
            iterations[i, j] = ts.diagnostics.get("iterations", 0)
            messages[i, j] = ts.diagnostics.get("message", "")
            outcomes[i, j] = ts.outcome.value
            flags[i, j] = [w in ts.warnings for w in SolverWarning]
            if "harmonic_truncation_indicator" in ts.diagnostics:
                truncation[i, j] = np.broadcast_to(ts.diagnostics["harmonic_truncation_indicator"], (n_s,))
            if "truncation_error" in ts.diagnostics:
                truncation_error[i, j] = np.broadcast_to(ts.diagnostics["truncation_error"], (n_s,))
            if "tensile_force_error_N" in ts.diagnostics:
                tensile[i, j] = float(np.max(ts.diagnostics["tensile_force_error_N"]))
    is_nonlinear = (np.array(MODELS) == "nonlinear")[None, :, None, None]
    return CaseArrays(
        period_fraction=period_fraction(time_samples),
        x_moment_m=x_moment,
        cargo_deflection_m=disp - baseline,
        cargo_deflection_vessel_frame_m=disp,
        saddle_compression_m=comp,
        saddle_gap_m=np.where(is_nonlinear, np.maximum(-comp, 0.0), 0.0),
        saddle_force_N=force,
        bending_moment_Nm=np.stack(moments).reshape(2, 2, time_samples, -1),
        bending_stress_Pa=np.stack(stresses).reshape(2, 2, time_samples, -1),
        deck_deflection_m=deck_all,
        deck_rise_m=deck_all - baseline[..., model.saddle_node],
        converged=converged,
        residual_norm=residual,
        iterations=iterations,
        solver_message=messages.astype(str),
        harmonic_truncation_indicator=truncation,
        truncation_error=truncation_error,
        tensile_force_error_N=tensile,
        solver_outcome=outcomes.astype(str),
        solver_warning=flags,
    )


def largest_slope_rad(deflection_m: np.ndarray, x_m: np.ndarray) -> np.ndarray:
    """Largest |dz/dx| over the last two axes (time, node) of a deflection (..., n_t, n_x) at nodes ``x_m`` [rad]."""
    slope = np.diff(np.asarray(deflection_m, dtype=float), axis=-1) / np.diff(np.asarray(x_m, dtype=float))
    return np.asarray(np.abs(slope).max(axis=(-2, -1)), dtype=float)


def summary_rows_from_arrays(
    arrays: CaseArrays, cargo_x_m: np.ndarray, model_warnings: Iterable[ModelWarning] = ()
) -> list[dict[str, Any]]:
    """The summary table rows straight from the arrays (no Dataset needed: fast for studies).

    ``cargo_x_m``: the cargo's node positions [m], for ``cargo_slope_rad`` (the largest slope of the cargo's
    deflection relative to the vessel's rigid-body frame, which the validity check reads). Each row's
    ``warnings`` (:func:`row_warnings`) are its solver warnings (``arrays.solver_warning``) and the given model
    warnings that bear on it.
    """
    mx = arrays.maxima()
    slope = largest_slope_rad(arrays.cargo_deflection_vessel_frame_m, cargo_x_m)
    model_warnings = tuple(model_warnings)
    rows = []
    for i, lc in enumerate(LOAD_CASES):
        for j, mdl in enumerate(MODELS):
            row: dict[str, Any] = {"load_case": lc, "model": mdl}
            for name in ("u_c_m", "u_s_m", "u_d_m", "F_N", "M_b_Nm", "sigma_b_Pa"):
                row[name] = float(mx[name][i, j])
            row["cargo_slope_rad"] = float(slope[i, j])
            row["converged"] = bool(arrays.converged[i, j])
            row["contact_preserved"] = bool(mx["contact_preserved"][i, j])
            row["residual_norm"] = float(arrays.residual_norm[i, j])
            row["iterations"] = int(arrays.iterations[i, j])
            raised = [w for w, flag in zip(SolverWarning, arrays.solver_warning[i, j], strict=True) if flag]
            row["warnings"] = row_warnings(lc, raised, model_warnings)
            rows.append(row)
    return rows


def build_case_dataset(arrays: CaseArrays, model: StructuralModel, attrs: Mapping[str, Any] | None = None) -> xr.Dataset:
    """The case Dataset (what ``results.nc`` holds) from the case arrays."""
    a = arrays
    data_vars = {**_period_variables(a), **_row_variables(a, model)}
    for name, values in a.maxima().items():
        data_vars[name] = _var(("load_case", "model"), values.astype(np.int8) if values.dtype == bool else values, *_SUMMARY_ATTRS[name])
    return xr.Dataset(
        data_vars,
        coords={
            "load_case": list(LOAD_CASES),
            "model": list(MODELS),
            "period_fraction": _var(("period_fraction",), a.period_fraction, "time over wave period t/T", "1"),
            "saddle": np.arange(model.saddle_count),
            "x_cargo_m": _var(("x_cargo_m",), model.cargo.node_x_m, "position along the cargo from its aft end", "m"),
            "x_moment_m": _var(("x_moment_m",), a.x_moment_m, "position along the cargo from its aft end", "m"),
            "solver_warning": _var(("solver_warning",), list(SOLVER_WARNINGS), "solver warning (SolverWarning value)", "1"),
        },
        attrs=dict(attrs or {}),
    )


def _period_variables(a: CaseArrays) -> dict[str, xr.Variable]:
    """The responses over the period: deflections, saddle compressions and forces, moments, stresses, the deck."""
    dims4 = ("load_case", "model", "period_fraction")
    return {
        "cargo_deflection_m": _var(
            dims4 + ("x_cargo_m",),
            a.cargo_deflection_m,
            "cargo deflection relative to the sea-fastening baseline (line through the deck under the outermost saddles), up positive",
            "m",
        ),
        "cargo_deflection_vessel_frame_m": _var(
            dims4 + ("x_cargo_m",),
            a.cargo_deflection_vessel_frame_m,
            "cargo deflection relative to the vessel's rigid-body frame (hull chord AP-FP), up positive",
            "m",
        ),
        "saddle_compression_m": _var(
            dims4 + ("saddle",), a.saddle_compression_m, "saddle compression delta = z_deck - z_cargo (negative = gap)", "m"
        ),
        "saddle_gap_m": _var(dims4 + ("saddle",), a.saddle_gap_m, "saddle detachment (gap), nonlinear model", "m"),
        "saddle_force_N": _var(dims4 + ("saddle",), a.saddle_force_N, "saddle normal force on the cargo (up positive)", "N"),
        "contact_state": _var(
            dims4 + ("saddle",), (a.saddle_compression_m > 0).astype(np.int8), "saddle in contact (1) or detached (0)", "1"
        ),
        "bending_moment_Nm": _var(dims4 + ("x_moment_m",), a.bending_moment_Nm, "cargo bending moment (sagging positive)", "N m"),
        "bending_stress_Pa": _var(
            dims4 + ("x_moment_m",), a.bending_stress_Pa, "cargo bending stress at the outer fibre, bottom (tension positive)", "Pa"
        ),
        # the deck the nonlinear (physical) cargo stands on, in the layout of one-way results;
        # with two-way coupling each model has its own deck: the *_per_model_m variables
        "deck_deflection_m": _var(
            ("load_case", "period_fraction", "saddle"),
            a.deck_deflection_m[:, 1],
            "deck deflection under each saddle (hull elastic deflection, up positive), under the nonlinear model's cargo",
            "m",
        ),
        "deck_rise_m": _var(
            ("load_case", "period_fraction", "saddle"),
            a.deck_rise_m[:, 1],
            "deck deflection under each saddle relative to the sea-fastening baseline (up positive), under the nonlinear model's cargo",
            "m",
        ),
        "deck_deflection_per_model_m": _var(
            dims4 + ("saddle",),
            a.deck_deflection_m,
            "deck deflection under each saddle per model (differs between models only with two-way coupling), up positive",
            "m",
        ),
        "deck_rise_per_model_m": _var(
            dims4 + ("saddle",),
            a.deck_rise_m,
            "deck deflection under each saddle relative to the sea-fastening baseline, per model (up positive)",
            "m",
        ),
    }


def _row_variables(a: CaseArrays, model: StructuralModel) -> dict[str, xr.Variable]:
    """The saddles' properties, and each row's solver diagnostics, outcome and typed warnings."""
    return {
        "saddle_stiffness_N_per_m": _var(("saddle",), model.saddle_stiffness_N_per_m, "saddle compression stiffness", "N/m"),
        "saddle_lashed": _var(("saddle",), np.asarray(model.seafastening.lashed).astype(np.int8), "saddle carries lashings", "1"),
        "saddle_x_m": _var(("saddle",), model.saddle_x_m, "saddle position along the cargo from its aft end", "m"),
        "residual_norm": _var(("load_case", "model"), a.residual_norm, "nonlinear solver residual norm", "1"),
        "iterations": _var(("load_case", "model"), a.iterations, "nonlinear solver iterations", "1"),
        "solver_message": xr.Variable(("load_case", "model"), a.solver_message, {"long_name": "solver message"}),
        "harmonic_truncation_indicator": _var(
            ("load_case", "model", "saddle"), a.harmonic_truncation_indicator, "share of the contact-force signal above harmonic H", "1"
        ),
        "truncation_error": _var(
            ("load_case", "model", "saddle"),
            a.truncation_error,
            "estimated error of each saddle's peak force from the harmonics above H (exact-event shooting: the part of"
            " the continuous peak its sample grid misses), over the saddle's force scale (NaN where the solver gives none;"
            " compare solver.truncation_tolerance)",
            "1",
        ),
        "tensile_force_error_N": _var(
            ("load_case", "model"), a.tensile_force_error_N, "largest tensile force of the regularised contact law", "N"
        ),
        "converged": _var(("load_case", "model"), a.converged.astype(np.int8), *_SUMMARY_ATTRS["converged"]),
        "solver_outcome": xr.Variable(
            ("load_case", "model"),
            a.solver_outcome,
            {"long_name": "how the solve ended (" + ", ".join(SOLVER_OUTCOMES) + ")", "units": "1"},
        ),
        "solver_warning_flag": _var(
            ("load_case", "model", "solver_warning"),
            a.solver_warning.astype(np.int8),
            "typed solver warning raised (1) or not (0), one per solver_warning",
            "1",
        ),
    }
