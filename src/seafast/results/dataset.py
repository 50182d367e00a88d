"""Labelled results of one case: an xarray Dataset with named dimensions and units.

Dimensions: ``load_case`` (static, dynamic), ``model`` (linear, nonlinear), ``period_fraction``
(t / T over one wave period), ``saddle``, ``x_cargo_m`` (cargo nodes), ``x_moment_m``
(bending-moment sample points; element ends appear twice so jumps show).
``dynamic`` is the total response (still water included).
"""

from __future__ import annotations

from typing import Any, Mapping

import numpy as np
import xarray as xr

from seafast.excitation.harmonic import HarmonicExcitation
from seafast.model.structure import StructuralModel
from seafast.results.timeseries import PeriodTimeSeries, harmonics_to_time, moment_lines, period_grid

__all__ = ["LOAD_CASES", "MODELS", "SUMMARY_COLUMNS", "build_case_dataset", "summary_rows"]

LOAD_CASES = ("static", "dynamic")
MODELS = ("linear", "nonlinear")
SUMMARY_COLUMNS = ("load_case", "model", "u_c_m", "u_s_m", "u_d_m", "F_N", "M_b_Nm", "sigma_b_Pa", "converged")

_SUMMARY_ATTRS = {
    "u_c_m": ("maximum cargo deflection relative to the vessel's rigid-body frame", "m"),
    "u_s_m": ("maximum saddle compression", "m"),
    "u_d_m": ("maximum saddle detachment (gap); 0 for the linear model", "m"),
    "F_N": ("maximum saddle normal force", "N"),
    "M_b_Nm": ("maximum absolute bending moment in the cargo", "N m"),
    "sigma_b_Pa": ("maximum absolute bending stress in the cargo, M_b (D/2) / I", "Pa"),
    "converged": ("solver converged", "1"),
    "contact_preserved": ("every saddle in contact over the whole period (linear theory valid)", "1"),
}


def _var(dims: tuple[str, ...], data: Any, long_name: str, units: str) -> xr.Variable:
    return xr.Variable(dims, np.asarray(data), {"long_name": long_name, "units": units})


def _seafastening_baseline(model: StructuralModel, excitation: HarmonicExcitation, deck_z: np.ndarray) -> np.ndarray:
    """Straight line through the deck points under the outermost saddles, at every cargo node [m].

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
        n_t = deck_z.shape[-2]
        th_dyn = harmonics_to_time(theta, n_t)[:, 0]
        slope = np.stack([np.full(n_t, np.real(theta[0, 0])), th_dyn])
    return deck_z[..., :1] + slope[..., None] * (x - xs[0])


def build_case_dataset(
    model: StructuralModel,
    excitation: HarmonicExcitation,
    series: Mapping[tuple[str, str], PeriodTimeSeries],
    time_samples: int,
    attrs: Mapping[str, Any] | None = None,
) -> xr.Dataset:
    """Assemble the case Dataset from the four responses keyed by (load_case, model)."""
    s = period_grid(time_samples)
    nodes = model.cargo.node_x_m
    disp = np.zeros((2, 2, time_samples, nodes.size))
    comp = np.zeros((2, 2, time_samples, model.saddle_count))
    force = np.zeros_like(comp)
    moments = []
    stresses = []
    x_moment = None
    converged = np.zeros((2, 2), dtype=bool)
    residual = np.full((2, 2), np.nan)
    iterations = np.zeros((2, 2), dtype=int)
    truncation = np.full((2, 2, model.saddle_count), np.nan)
    tensile = np.full((2, 2), np.nan)
    messages = np.empty((2, 2), dtype=object)
    for i, lc in enumerate(LOAD_CASES):
        exc = excitation.static_part() if lc == "static" else excitation
        for j, mdl in enumerate(MODELS):
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
            if "harmonic_truncation_indicator" in ts.diagnostics:
                truncation[i, j] = np.broadcast_to(ts.diagnostics["harmonic_truncation_indicator"], (model.saddle_count,))
            if "tensile_force_error_N" in ts.diagnostics:
                tensile[i, j] = float(np.max(ts.diagnostics["tensile_force_error_N"]))
    moment = np.stack(moments).reshape(2, 2, time_samples, -1)
    stress = np.stack(stresses).reshape(2, 2, time_samples, -1)
    contact = comp > 0.0
    gap = np.where(np.array(MODELS)[None, :, None, None] == "nonlinear", np.maximum(-comp, 0.0), 0.0)

    dims4 = ("load_case", "model", "period_fraction")
    deck_static = np.real(excitation.deck_displacement[0, model.saddle_deck_dof])
    deck_total = harmonics_to_time(excitation.deck_displacement[:, model.saddle_deck_dof], time_samples)
    deck_all = np.stack([np.broadcast_to(deck_static, deck_total.shape), deck_total])  # (load_case, N, n_s)
    baseline = _seafastening_baseline(model, excitation, deck_all)  # (load_case, N, n_x)
    data_vars = {
        "cargo_deflection_m": _var(
            dims4 + ("x_cargo_m",),
            disp - baseline[:, None],
            "cargo deflection relative to the sea-fastening baseline (line through the deck under the outermost saddles), up positive",
            "m",
        ),
        "cargo_deflection_vessel_frame_m": _var(
            dims4 + ("x_cargo_m",), disp, "cargo deflection relative to the vessel's rigid-body frame (hull chord AP-FP), up positive", "m"
        ),
        "saddle_compression_m": _var(dims4 + ("saddle",), comp, "saddle compression delta = z_deck - z_cargo (negative = gap)", "m"),
        "saddle_gap_m": _var(dims4 + ("saddle",), gap, "saddle detachment (gap), nonlinear model", "m"),
        "saddle_force_N": _var(dims4 + ("saddle",), force, "saddle normal force on the cargo (up positive)", "N"),
        "contact_state": _var(dims4 + ("saddle",), contact.astype(np.int8), "saddle in contact (1) or detached (0)", "1"),
        "bending_moment_Nm": _var(dims4 + ("x_moment_m",), moment, "cargo bending moment (sagging positive)", "N m"),
        "bending_stress_Pa": _var(dims4 + ("x_moment_m",), stress, "cargo bending stress at the outer fibre, bottom (tension positive)", "Pa"),
        "deck_deflection_m": _var(
            ("load_case", "period_fraction", "saddle"),
            deck_all,
            "deck deflection under each saddle (hull elastic deflection, up positive)",
            "m",
        ),
        "saddle_stiffness_N_per_m": _var(("saddle",), model.saddle_stiffness_N_per_m, "saddle compression stiffness", "N/m"),
        "saddle_lashed": _var(("saddle",), np.asarray(model.seafastening.lashed).astype(np.int8), "saddle carries lashings", "1"),
        "saddle_x_m": _var(("saddle",), model.saddle_x_m, "saddle position along the cargo from its aft end", "m"),
        "residual_norm": _var(("load_case", "model"), residual, "nonlinear solver residual norm", "1"),
        "iterations": _var(("load_case", "model"), iterations, "nonlinear solver iterations", "1"),
        "solver_message": xr.Variable(("load_case", "model"), messages.astype(str), {"long_name": "solver message"}),
        "harmonic_truncation_indicator": _var(
            ("load_case", "model", "saddle"), truncation, "share of the contact-force signal above harmonic H", "1"
        ),
        "tensile_force_error_N": _var(("load_case", "model"), tensile, "largest tensile force of the regularised contact law", "N"),
    }
    ds = xr.Dataset(
        data_vars,
        coords={
            "load_case": list(LOAD_CASES),
            "model": list(MODELS),
            "period_fraction": _var(("period_fraction",), s, "time over wave period t/T", "1"),
            "saddle": np.arange(model.saddle_count),
            "x_cargo_m": _var(("x_cargo_m",), nodes, "position along the cargo from its aft end", "m"),
            "x_moment_m": _var(("x_moment_m",), x_moment, "position along the cargo from its aft end", "m"),
        },
        attrs=dict(attrs or {}),
    )
    # maxima over the cargo, saddles and the period (MODEL.md section 6)
    def over(v: str, dims: tuple[str, ...]) -> xr.DataArray:
        return np.abs(ds[v]).max(dims)

    ds["u_c_m"] = over("cargo_deflection_m", ("period_fraction", "x_cargo_m"))
    ds["u_s_m"] = ds["saddle_compression_m"].max(("period_fraction", "saddle")).clip(min=0.0)
    ds["u_d_m"] = ds["saddle_gap_m"].max(("period_fraction", "saddle"))
    ds["F_N"] = ds["saddle_force_N"].max(("period_fraction", "saddle"))
    ds["M_b_Nm"] = over("bending_moment_Nm", ("period_fraction", "x_moment_m"))
    ds["sigma_b_Pa"] = over("bending_stress_Pa", ("period_fraction", "x_moment_m"))
    ds["converged"] = xr.DataArray(converged.astype(np.int8), dims=("load_case", "model"))
    ds["contact_preserved"] = (ds["saddle_compression_m"] > 0).all(("period_fraction", "saddle")).astype(np.int8)
    for name, (long_name, units) in _SUMMARY_ATTRS.items():
        ds[name].attrs.update(long_name=long_name, units=units)
    return ds


def summary_rows(ds: xr.Dataset) -> list[dict[str, Any]]:
    """The summary table: one row per (load_case, model), INTERFACE.md columns + contact_preserved."""
    rows = []
    for lc in LOAD_CASES:
        for mdl in MODELS:
            sel = ds.sel(load_case=lc, model=mdl)
            rows.append(
                {
                    "load_case": lc,
                    "model": mdl,
                    "u_c_m": float(sel["u_c_m"]),
                    "u_s_m": float(sel["u_s_m"]),
                    "u_d_m": float(sel["u_d_m"]),
                    "F_N": float(sel["F_N"]),
                    "M_b_Nm": float(sel["M_b_Nm"]),
                    "sigma_b_Pa": float(sel["sigma_b_Pa"]),
                    "converged": bool(sel["converged"]),
                    "contact_preserved": bool(sel["contact_preserved"]),
                    "residual_norm": float(sel["residual_norm"]),
                    "iterations": int(sel["iterations"]),
                }
            )
    return rows
