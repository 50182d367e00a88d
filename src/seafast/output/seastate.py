"""What ``seafast seastate`` writes: seastate.csv, seastate.nc and the sea-state figures.

``seastate.csv`` has exactly :data:`~seafast.analyses.seastate.spectral.SEASTATE_COLUMNS`, one row per
(model, method): (linear, spectral), (linear, monte_carlo), (nonlinear, monte_carlo), (nonlinear,
design_wave). A row whose method was not run has empty cells (read as NaN), never made-up numbers.
Off head seas the cradle columns follow ``converged`` (:mod:`seafast.output.seastate_cradle`); head seas: today's file.

``seastate.nc`` holds the spectrum, the transfer functions (real and imaginary parts, per metre
of wave amplitude), the response spectra and spectral statistics, the table of seastate.csv as
variables over (model, estimate_method), the design waves and their nonlinear maxima (dimension
``design_wave``), and the Monte Carlo engine's per-realisation data when it ran;
``units`` and ``long_name`` on every variable.
"""

from __future__ import annotations

import csv
import io
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
import xarray as xr
import yaml

import seafast
from seafast.analyses.seastate.cradle_design_wave import CradleSeaState
from seafast.analyses.seastate.design_wave import DesignWaveExtremes
from seafast.analyses.seastate.spectral import SEASTATE_COLUMNS, SpectralAnalysis
from seafast.analyses.seastate.wave_maxima import SADDLE_QUANTITIES
from seafast.output.seastate_cradle import (
    CRADLE_TABLE_HEAD,
    cradle_coords,
    cradle_table_cells,
    cradle_table_head,
    cradle_table_variables,
    cradle_variables,
    seastate_columns,
)
from seafast.output.tables import text_table
from seafast.results.labelled import labelled_variable as _var

if TYPE_CHECKING:  # the Monte Carlo engine (half a second to import) only when it runs: --no-monte-carlo needs none of it
    from seafast.analyses.seastate.monte_carlo import MonteCarloResult, MonteCarloStatistics

__all__ = [
    "ROWS",
    "QUANTITIES",
    "not_computed_row",
    "monte_carlo_row",
    "seastate_csv_text",
    "seastate_dataset",
    "write_seastate_outputs",
    "format_seastate_table",
]

ROWS = (("linear", "spectral"), ("linear", "monte_carlo"), ("nonlinear", "monte_carlo"), ("nonlinear", "design_wave"))
"""The (model, method) rows of seastate.csv, in order."""

QUANTITIES = {
    "F_N": ("most probable maximum saddle force over the duration, still water included", "N"),
    "M_b_Nm": ("most probable maximum absolute cargo bending moment over the duration, still water included", "N m"),
    "sigma_b_Pa": ("most probable maximum absolute cargo bending stress over the duration, still water included", "Pa"),
    "u_s_m": ("most probable maximum saddle compression over the duration, still water included", "m"),
    "u_d_m": ("most probable maximum saddle detachment (gap); 0 for the linear model (bilateral saddles)", "m"),
    "uplift_per_hour": ("expected uplift events per hour (downward zero crossings of a saddle's compression), all saddles", "1/h"),
}

_DESIGN_WAVE_MAXIMA = {
    "F_N": "largest saddle force",
    "M_b_Nm": "largest absolute cargo bending moment",
    "sigma_b_Pa": "largest absolute cargo bending stress",
    "u_s_m": "largest saddle compression",
    "u_d_m": "largest saddle detachment (gap)",
}


def not_computed_row(model: str, method: str) -> dict[str, Any]:
    """A row of a method that did not run: empty cells."""
    return {"model": model, "method": method, **dict.fromkeys(QUANTITIES), "converged": None}


def monte_carlo_row(statistics: MonteCarloStatistics) -> dict[str, Any]:
    """The row of one model's Monte Carlo statistics (``MonteCarloStatistics``)."""
    row: dict[str, Any] = {"model": statistics.model, "method": "monte_carlo"}
    for q in ("F_N", "M_b_Nm", "sigma_b_Pa", "u_s_m", "u_d_m"):
        row[q] = float(statistics.mpm[q])
    row["uplift_per_hour"] = float(statistics.uplift_per_hour)
    row["converged"] = bool(statistics.converged)
    return row


def _cell(value: Any) -> str:
    if value is None:
        return ""
    if isinstance(value, (bool, np.bool_)):
        return "true" if value else "false"
    if isinstance(value, float):
        return repr(value)
    return str(value)


def seastate_csv_text(rows: Sequence[Mapping[str, Any]]) -> str:
    """seastate.csv text (SI units; booleans true/false; empty = not computed) with :func:`seastate_columns`."""
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    columns = seastate_columns(rows)
    w.writerow(columns)
    for r in rows:
        w.writerow([_cell(r.get(c)) for c in columns])
    return buf.getvalue()


def format_seastate_table(rows: Sequence[Mapping[str, Any]], title: str = "") -> str:
    """Terminal table in engineering units (MN, MN m, MPa, mm; off head seas the cradle columns in MN, kN, mm)."""
    head: tuple[str, ...] = ("model", "method", "F [MN]", "M_b [MNm]", "sigma_b [MPa]", "u_s [mm]", "u_d [mm]", "uplift [1/h]", "converged")
    scale = {"F_N": 1e-6, "M_b_Nm": 1e-6, "sigma_b_Pa": 1e-6, "u_s_m": 1e3, "u_d_m": 1e3, "uplift_per_hour": 1.0}
    cradle = len(seastate_columns(rows)) > len(SEASTATE_COLUMNS)
    head += cradle_table_head(rows) if cradle else ()
    friction = len(cradle_table_head(rows)) > len(CRADLE_TABLE_HEAD)
    lines = []
    for r in rows:
        cells = [str(r["model"]), str(r["method"])]
        for q, s in scale.items():
            cells.append("not computed" if r[q] is None else f"{r[q] * s:.{2 if q != 'F_N' else 3}f}")
        cells.append("-" if r["converged"] is None else ("yes" if r["converged"] else "NO"))
        cells += cradle_table_cells(r, friction) if cradle else []
        lines.append(cells)
    return text_table(head, lines, title)


def _complex(out: dict[str, xr.Variable], name: str, dims: tuple[str, ...], data: Any, long_name: str, units: str) -> None:
    for part, fn in (("real", np.real), ("imag", np.imag)):
        out[f"{name}_{part}"] = _var(dims, fn(data), f"{long_name}, {'real' if part == 'real' else 'imaginary'} part", units)


def _design_wave_variables(design: Any) -> dict[str, xr.Variable]:
    """The design waves (dimension ``design_wave``) and their nonlinear maxima."""
    d = ("design_wave",)
    waves, sols = design.waves, design.solutions
    v = {
        "design_wave_quantity": xr.Variable(
            d,
            np.array([w.quantity for w in waves], dtype=str),
            {"long_name": "quantity the design wave is designed for (seastate.csv column)", "units": "1"},
        ),
        "design_wave_role": xr.Variable(
            d,
            np.array([w.role for w in waves], dtype=str),
            {"long_name": "where in the response spectrum: peak, band_low, band_high (ends of the half-peak band) or band", "units": "1"},
        ),
        "design_wave_location": _var(
            d,
            [w.location for w in waves],
            "location the wave is designed for and read at: saddle index (F_N, u_s_m, u_d_m) or x_moment_m index (M_b_Nm, sigma_b_Pa)",
            "1",
        ),
        "design_wave_omega_rad_s": _var(d, [w.omega_rad_s for w in waves], "design wave frequency", "rad/s"),
        "design_wave_amplitude_m": _var(
            d, [w.amplitude_m for w in waves], "design wave amplitude (linear response = linear spectral MPM)", "m"
        ),
        "design_wave_heading_deg": _var(
            d,
            [w.heading_deg for w in waves],
            "design wave heading (180 = head seas; in a spread sea the direction whose transfer function is largest)",
            "deg",
        ),
        "design_wave_converged": _var(
            d, np.array([s.converged for s in sols], dtype=np.int8), "harmonic balance converged (1) or not (0)", "1"
        ),
        "design_wave_harmonics": _var(d, [s.harmonics for s in sols], "harmonics H of the harmonic balance that solved the wave", "1"),
    }
    saddle_wave = np.array([w.quantity in SADDLE_QUANTITIES for w in waves], dtype=bool)
    read = design.read
    v["design_wave_read_locations"] = _var(
        d, [r.size for r in read], "number of locations the wave is read at for its quantity (saddle: 1; moment points)", "1"
    )
    for q, what in _DESIGN_WAVE_MAXIMA.items():
        v[f"design_wave_{q}"] = _var(
            d,
            [s.maxima[q] for s in sols],
            f"{what} over the cargo and the design wave's period (nonlinear, still water included)",
            QUANTITIES[q][1],
        )
        # what the design-wave row reads: each wave where it is read (its saddle; for a moment wave the
        # moment points where it is at most an MPM wave); NaN for a quantity of the other kind
        same_kind = saddle_wave == (q in SADDLE_QUANTITIES)
        v[f"design_wave_{q}_read"] = _var(
            d,
            [s.maximum_at(q, r) if k else np.nan for s, r, k in zip(sols, read, same_kind, strict=True)],
            f"{what} where the design wave is read, over its period (nonlinear, still water included; NaN: other kind of location)",
            QUANTITIES[q][1],
        )
    return v


_MODELS = ("linear", "nonlinear")
_METHODS = ("spectral", "monte_carlo", "design_wave")


def _transfer_variables(analysis: SpectralAnalysis) -> dict[str, xr.Variable]:
    """The wave spectrum, the grid's geometry and the transfer functions (real and imaginary parts)."""
    sp, tf = analysis.spectrum, analysis.transfer
    w, s, x = ("omega_rad_s",), ("omega_rad_s", "saddle"), ("omega_rad_s", "x_moment_m")
    per = "per metre of wave amplitude"
    v: dict[str, xr.Variable] = {
        "wave_spectrum_m2_s_per_rad": _var(w, sp.density_m2_s_per_rad, "wave spectral density S(omega), one-sided", "m2 s/rad"),
        "hull_emergence_amplitude_m": _var(
            w, tf.hull_emergence_amplitude_m, "regular-wave amplitude at which a hull section emerges (hull response linear below)", "m"
        ),
        "saddle_x_m": _var(("saddle",), analysis.model.saddle_x_m, "saddle position along the cargo from its aft end", "m"),
        "bending_section_modulus_m3": _var(("x_moment_m",), tf.bending_section_modulus_m3, "cargo section modulus I / (D/2)", "m3"),
    }
    _complex(v, "heave_transfer_m_per_m", w, tf.heave_m, f"heave at the pitch reference {per}", "m/m")
    _complex(v, "pitch_transfer_rad_per_m", w, tf.pitch_rad, f"pitch dz/dx, bow up, {per}", "rad/m")
    if tf.roll_rad is not None:  # the six-DOF motions (off head seas, or a short-crested sea): the mean heading's roll
        _complex(v, "roll_transfer_rad_per_m", w, tf.roll_rad, f"roll about the CoG, starboard down +, at the mean heading, {per}", "rad/m")
    _complex(
        v,
        "deck_deflection_transfer_m_per_m",
        s,
        tf.deck_displacement[:, 0::2],
        f"hull elastic deck deflection under each saddle {per}",
        "m/m",
    )
    _complex(
        v, "deck_slope_transfer_rad_per_m", s, tf.deck_displacement[:, 1::2], f"hull elastic deck slope under each saddle {per}", "rad/m"
    )
    _complex(v, "saddle_compression_transfer_m_per_m", s, tf.saddle_compression_m, f"saddle compression (linear model) {per}", "m/m")
    _complex(v, "saddle_force_transfer_N_per_m", s, tf.saddle_force_N, f"saddle force, compression-only part (linear model) {per}", "N/m")
    _complex(
        v, "bending_moment_transfer_Nm_per_m", x, tf.bending_moment_Nm, f"cargo bending moment, sagging + (linear model) {per}", "N m/m"
    )
    return v


def _spectral_variables(analysis: SpectralAnalysis) -> dict[str, xr.Variable]:
    """The response spectra and their statistics, the still-water state and the uplift rate (linear)."""
    e = analysis.extremes
    v: dict[str, xr.Variable] = {}
    for key, stats, unit, tag, spectrum_unit, label in (
        ("saddle_force", e.saddle_force, "N", "N", "N2 s/rad", "saddle force"),
        ("saddle_compression", e.saddle_compression, "m", "m", "m2 s/rad", "saddle compression"),
        ("bending_moment", e.bending_moment, "N m", "Nm", "N2 m2 s/rad", "cargo bending moment"),
        ("bending_stress", e.bending_stress, "Pa", "Pa", "Pa2 s/rad", "cargo bending stress"),
    ):
        dims = ("saddle",) if key.startswith("saddle") else ("x_moment_m",)
        v[f"{key}_spectrum_{tag}2_s_per_rad"] = _var(
            ("omega_rad_s",) + dims, stats.spectrum, f"response spectrum of the {label} (linear)", spectrum_unit
        )
        v[f"{key}_std_{tag}"] = _var(dims, stats.sigma, f"standard deviation of the {label} (linear, spectral)", unit)
        v[f"{key}_zero_crossing_period_s"] = _var(
            dims, stats.zero_crossing_period_s, f"mean zero-crossing period of the {label} (linear, spectral)", "s"
        )
        v[f"{key}_mpm_dynamic_{tag}"] = _var(
            dims, stats.mpm, f"Rayleigh most probable maximum of the dynamic {label} over the duration (linear)", unit
        )
    sw = e.still_water
    v["still_water_saddle_force_N"] = _var(("saddle",), sw.saddle_force_N, "still-water saddle force (linear)", "N")
    v["still_water_saddle_compression_m"] = _var(("saddle",), sw.saddle_compression_m, "still-water saddle compression (linear)", "m")
    v["still_water_bending_moment_Nm"] = _var(
        ("x_moment_m",), sw.bending_moment_Nm, "still-water cargo bending moment, sagging + (linear)", "N m"
    )
    v["still_water_bending_stress_Pa"] = _var(("x_moment_m",), sw.bending_stress_Pa, "still-water cargo bending stress (linear)", "Pa")
    v["uplift_per_hour_per_saddle"] = _var(
        ("saddle",),
        e.uplift_per_hour_per_saddle,
        "expected downward zero crossings of the saddle compression per hour (linear, Rice)",
        "1/h",
    )
    return v


def _table_variables(rows: Sequence[Mapping[str, Any]]) -> dict[str, xr.Variable]:
    """The table of seastate.csv over (model, estimate_method): NaN, and converged -1, where not computed."""
    models, methods = list(_MODELS), list(_METHODS)
    v: dict[str, xr.Variable] = {}
    for q, (long_name, unit) in QUANTITIES.items():
        table = np.full((2, 3), np.nan)
        for r in rows:
            if r[q] is not None:
                table[models.index(r["model"]), methods.index(r["method"])] = r[q]
        v[q] = _var(("model", "estimate_method"), table, long_name + " (NaN: not computed)", unit)
    v.update(cradle_table_variables(rows, models, methods))
    conv = np.full((2, 3), -1, dtype=np.int8)
    for r in rows:
        if r["converged"] is not None:
            conv[models.index(r["model"]), methods.index(r["method"])] = int(bool(r["converged"]))
    v["converged"] = _var(("model", "estimate_method"), conv, "all solves converged (1), not (0), not computed (-1)", "1")
    return v


def _seastate_coords(analysis: SpectralAnalysis, design: Any) -> dict[str, xr.Variable]:
    """The coordinates of seastate.nc (``design_wave`` when the design waves were computed)."""
    tf = analysis.transfer
    coords = {
        "omega_rad_s": _var(("omega_rad_s",), analysis.spectrum.omega_rad_s, "wave angular frequency (sea-state grid)", "rad/s"),
        "saddle": _var(("saddle",), np.arange(analysis.model.saddle_count), "saddle index, aft to fore", "1"),
        "x_moment_m": _var(("x_moment_m",), tf.bending_moment_x_m, "position along the cargo from its aft end", "m"),
        "model": xr.Variable(("model",), list(_MODELS), {"long_name": "cargo model (linear: bilateral saddles)", "units": "1"}),
        # not "method": xarray's .sel(method=...) is taken
        "estimate_method": xr.Variable(
            ("estimate_method",), list(_METHODS), {"long_name": "method of the extremes (seastate.csv column 'method')", "units": "1"}
        ),
    }
    if design is not None:
        coords["design_wave"] = _var(("design_wave",), np.arange(len(design.waves)), "design wave index", "1")
    return coords


def _seastate_attrs(analysis: SpectralAnalysis) -> dict[str, Any]:
    """The global attributes of seastate.nc: the sea state, the limits, the case and the conventions."""
    sp, case = analysis.spectrum, analysis.case
    directional = {} if analysis.directional is None else analysis.directional.attributes()
    return {
        **directional,
        "title": f"seafast sea state: {case.name}",
        "seafast_version": seafast.__version__,
        "spectrum": sp.description,
        "significant_height_m": sp.significant_height_m,
        "peak_period_s": sp.peak_period_s,
        "duration_s": case.sea_state.duration_s,
        "variance_outside_grid_m2": sp.variance_outside_grid_m2,
        "max_saddle_force_N": case.limits.max_saddle_force_N,
        "max_bending_stress_Pa": case.limits.max_bending_stress_Pa,
        "pitch_reference_x_m": analysis.transfer.pitch_reference_x_m,
        "case_json": case.model_dump_json(),
        "conventions": "x(t) = Re(X exp(i omega t)) per metre of wave amplitude, wave zeta = zeta_a cos(omega t) amidships "
        "(head seas); z up; sagging moment +; saddle compression + when compressed; maxima are most probable maxima "
        "over duration_s, still water included",
    }


def seastate_dataset(
    analysis: SpectralAnalysis,
    rows: Sequence[Mapping[str, Any]],
    monte_carlo: xr.Dataset | None = None,
    design: DesignWaveExtremes | None = None,
    cradle: CradleSeaState | None = None,
) -> xr.Dataset:
    """The content of seastate.nc (module docstring); ``design``, ``cradle``: the design waves, the cradles, if computed."""
    v = _transfer_variables(analysis)
    v.update(_spectral_variables(analysis))
    v.update(_table_variables(rows))
    if design is not None:
        v.update(_design_wave_variables(design))
    coords = _seastate_coords(analysis, design)
    if cradle is not None:
        v, coords = {**v, **cradle_variables(cradle)}, {**coords, **cradle_coords(cradle)}
    ds = xr.Dataset(v, coords=coords, attrs=_seastate_attrs(analysis))
    if monte_carlo is not None:
        ds = xr.merge([ds, monte_carlo], compat="no_conflicts", join="outer", combine_attrs="override")
        ds.attrs.update(monte_carlo.attrs)
        ds.attrs["title"] = f"seafast sea state: {analysis.case.name}"
    return ds


def write_seastate_outputs(
    analysis: SpectralAnalysis,
    rows: Sequence[Mapping[str, Any]],
    out_dir: str | Path,
    *,
    monte_carlo: MonteCarloResult | None = None,
    plots: bool = True,
    design: DesignWaveExtremes | None = None,
    cradle: CradleSeaState | None = None,
) -> dict[str, Path]:
    """Write seastate.csv, seastate.nc, case.yaml and (``plots``) the PNG figures; return their paths.

    ``design``: the :class:`~seafast.analyses.seastate.design_wave.DesignWaveExtremes` (its waves go to seastate.nc);
    ``cradle``: the cradle quantities off head seas (:class:`~seafast.analyses.seastate.cradle_extremes.CradleSeaState`).
    """
    from seafast.output.files import write_netcdf

    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    paths: dict[str, Path] = {}
    (out / "seastate.csv").write_text(seastate_csv_text(rows), encoding="utf-8")
    paths["seastate_csv"] = out / "seastate.csv"
    (out / "case.yaml").write_text(
        "# the case as run (all defaults filled in)\n" + yaml.safe_dump(analysis.case.model_dump(mode="json"), sort_keys=False),
        encoding="utf-8",
    )
    paths["case"] = out / "case.yaml"
    mc_ds = monte_carlo.to_dataset() if monte_carlo is not None else None
    ds = seastate_dataset(analysis, rows, mc_ds, design, cradle)
    nc = out / "seastate.nc"
    if nc.exists():
        nc.unlink()
    paths["seastate_nc"] = write_netcdf(ds, nc)
    if plots:
        from seafast.output.seastate_plots import write_seastate_figures

        for p in write_seastate_figures(ds, out, monte_carlo):
            paths[p.stem] = p
    return paths
