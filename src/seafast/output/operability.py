"""What ``seafast operability`` writes: operability.csv, operability.nc, operability.png, scatter.csv.

``operability.csv`` has exactly :data:`OPERABILITY_COLUMNS`, one row per peak period; an Hs that
could not be found (the nonlinear search did not converge, or no lift-off below the limiting
steepness for the uplift onset) is an empty cell. When the case sets a cradle limit
(``limits.max_pad_force_N``, ``limits.max_lashing_tension_N``, ``limits.max_transverse_slip_m``) it has
:data:`~seafast.analyses.operability.allowable.CRADLE_OPERABILITY_COLUMNS` after them (each cradle limit's Hs alone;
empty where not checked: the limit unset or head seas, not reached below the steepness limit, or not searched).
``operability.nc`` holds the same and the diagnostics of each search (per limit, steepness cap, convergence, evaluations), ``units`` and
``long_name`` on every variable; with a scatter diagram also its cells and the shares within the
limits. The chart plots Hs against Tp: both allowable curves, the uplift onset and the limiting
steepness (and the scatter cells).
"""

from __future__ import annotations

import csv
import io
import math
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np
import xarray as xr
import yaml

import seafast
from seafast.analyses.operability.allowable import CRADLE_OPERABILITY_COLUMNS, OperabilityResult
from seafast.analyses.operability.limits import CRADLE_LIMITS, GOVERNING, cradle_limits
from seafast.analyses.operability.scatter import ScatterAssessment
from seafast.config.schema import Case
from seafast.results.labelled import labelled_variable as _var

__all__ = [
    "OPERABILITY_COLUMNS",
    "SCATTER_RESULT_COLUMNS",
    "operability_columns",
    "operability_cell",
    "operability_csv_text",
    "operability_dataset",
    "write_operability_outputs",
    "format_operability_table",
    "plot_operability",
]

OPERABILITY_COLUMNS = (
    "peak_period_s",
    "hs_allowable_linear_m",
    "hs_allowable_nonlinear_m",
    "hs_uplift_onset_m",
    "governing_linear",
    "governing_nonlinear",
)
"""Columns of operability.csv (the scriptable contract)."""

SCATTER_RESULT_COLUMNS = ("significant_height_m", "peak_period_s", "occurrence", "within_limits_linear", "within_limits_nonlinear")
"""Columns of scatter.csv (one row per cell of the user's scatter diagram; occurrence normalised)."""


def operability_cell(value: Any) -> str:
    """One cell of operability.csv and scatter.csv: empty for None or a non-finite number, true/false, floats in full."""
    if value is None:
        return ""
    if isinstance(value, (bool, np.bool_)):
        return "true" if value else "false"
    if isinstance(value, (float, np.floating)):
        return "" if not math.isfinite(float(value)) else repr(float(value))
    return str(value)


def operability_columns(case: Case) -> tuple[str, ...]:
    """operability.csv's columns: :data:`OPERABILITY_COLUMNS`, and the cradle limits' when the case sets one."""
    return OPERABILITY_COLUMNS + (CRADLE_OPERABILITY_COLUMNS if cradle_limits(case) else ())


def operability_csv_text(result: OperabilityResult) -> str:
    """operability.csv text (SI units; empty cell = not found)."""
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    columns = operability_columns(result.case)
    w.writerow(columns)
    for p in result.points:
        row = p.row() | p.cradle_row()
        w.writerow([operability_cell(row[c]) for c in columns])
    return buf.getvalue()


def _point_variables(result: OperabilityResult) -> dict[str, xr.Variable]:
    """The allowable Hs of each peak period and the diagnostics of its searches (dimension ``peak_period_s``)."""
    P = result.points
    d = ("peak_period_s",)
    return {
        "hs_allowable_linear_m": _var(d, [p.hs_allowable_linear_m for p in P], "largest Hs within both limits, linear spectral MPMs", "m"),
        "hs_allowable_nonlinear_m": _var(
            d,
            [p.hs_allowable_nonlinear_m for p in P],
            "largest Hs within both limits, nonlinear design-wave MPMs (NaN: not converged)",
            "m",
        ),
        "hs_uplift_onset_m": _var(
            d,
            [p.hs_uplift_onset_m for p in P],
            "Hs at which the MPM compression of a saddle reaches its still-water compression (NaN: beyond the limiting steepness)",
            "m",
        ),
        "governing_linear": xr.Variable(
            d,
            np.array([p.governing_linear for p in P], dtype=str),
            {"long_name": f"limit reached first, linear: {', '.join(GOVERNING[:-1])}", "units": "1"},
        ),
        "governing_nonlinear": xr.Variable(
            d,
            np.array([p.governing_nonlinear for p in P], dtype=str),
            {"long_name": f"limit reached first, nonlinear: {', '.join(GOVERNING)}", "units": "1"},
        ),
        "hs_max_steepness_m": _var(
            d,
            [p.hs_max_steepness_m for p in P],
            "steepest sea state at this Tp (DNV-RP-C205 limiting steepness): the cap of the search",
            "m",
        ),
        "hs_force_linear_m": _var(
            d, [p.hs_force_linear_m for p in P], "Hs at which the linear MPM saddle force reaches its limit (inf: never)", "m"
        ),
        "hs_stress_linear_m": _var(
            d, [p.hs_stress_linear_m for p in P], "Hs at which the linear MPM bending stress reaches its limit (inf: never)", "m"
        ),
        "hs_force_nonlinear_m": _var(
            d,
            [p.hs_force_nonlinear_m for p in P],
            "Hs at which the nonlinear design-wave saddle force reaches its limit "
            "(inf: not below the steepness cap; NaN: the other limit is reached first, or not converged)",
            "m",
        ),
        "hs_stress_nonlinear_m": _var(
            d,
            [p.hs_stress_nonlinear_m for p in P],
            "Hs at which the nonlinear design-wave bending stress reaches its limit "
            "(inf: not below the steepness cap; NaN: the other limit is reached first, or not converged)",
            "m",
        ),
        "converged": _var(
            d,
            np.array([p.converged for p in P], dtype=np.int8),
            "every harmonic-balance solve of the nonlinear search converged (1) or not (0)",
            "1",
        ),
        "evaluations": _var(d, [p.evaluations for p in P], "design-wave evaluations of the nonlinear search", "1"),
        **(_cradle_point_variables(result) if cradle_limits(result.case) else {}),
    }


_CRADLE_LIMIT_TEXT = {
    "pad_force": "pad force",
    "lashing_tension": "largest lashing-wire tension",
    "transverse_slip": "lateral displacement of the cargo at a saddle",
}


def _cradle_point_variables(result: OperabilityResult) -> dict[str, xr.Variable]:
    """Each cradle limit's Hs alone, linear and nonlinear (dimension ``peak_period_s``; written when one is set)."""
    d = ("peak_period_s",)
    out: dict[str, xr.Variable] = {}
    for model, source in (("linear", "linear spectral MPM"), ("nonlinear", "nonlinear design-wave")):
        for name, text in _CRADLE_LIMIT_TEXT.items():
            key = f"hs_{name}_{model}_m"
            out[key] = _var(
                d,
                [getattr(p, key) for p in result.points],
                f"Hs at which the {source} {text} reaches its limit (inf: never; NaN: not checked (limit unset, head seas)"
                + (", not searched or not converged)" if model == "nonlinear" else ")"),
                "m",
            )
    return out


def _operability_attrs(result: OperabilityResult) -> dict[str, Any]:
    """The global attributes of operability.nc: the sea state's shape, the limits, the search settings and the case."""
    case = result.case
    return {
        "title": f"seafast operability: {case.name}",
        "seafast_version": seafast.__version__,
        "spectrum": case.sea_state.spectrum,
        "peak_enhancement": case.sea_state.peak_enhancement,
        "duration_s": case.sea_state.duration_s,
        "max_saddle_force_N": case.limits.max_saddle_force_N,
        "max_bending_stress_Pa": case.limits.max_bending_stress_Pa,
        **{key: v for _, key, _ in CRADLE_LIMITS if (v := getattr(case.limits, key)) is not None},
        # the design waves' solve: their converged periodic answer (the default) or a fixed H
        "design_wave_harmonics": "converged" if result.settings.design_wave.harmonics is None else result.settings.design_wave.harmonics,
        "design_wave_band_fraction": result.settings.design_wave.band_fraction,
        "design_wave_band_points": result.settings.design_wave.band_points,
        "hs_tolerance_m": result.settings.hs_tolerance_m,
        "case_json": case.model_dump_json(),
        "conventions": f"MPMs over duration_s, still water included; {_heading_words(case)}; Hs = 4 sqrt(m0)",
    }


def _heading_words(case: Case) -> str:
    """``head seas`` or ``heading B deg (180 = head seas)``: the sea state's heading as the file's conventions say it."""
    heading = float(case.sea_state.heading_deg)
    return "head seas" if heading == 180.0 else f"heading {heading:g} deg (180 = head seas, 90 = beam seas)"


def _scatter_variables(scatter: ScatterAssessment) -> dict[str, xr.Variable]:
    """The scatter diagram's cells and whether each lies within the limits (dimension ``scatter_cell``)."""
    c = ("scatter_cell",)
    dg = scatter.diagram
    return {
        "scatter_significant_height_m": _var(c, dg.significant_height_m, "scatter cell significant wave height", "m"),
        "scatter_peak_period_s": _var(c, dg.peak_period_s, "scatter cell peak period", "s"),
        "scatter_occurrence": _var(c, dg.occurrence, "scatter cell occurrence, normalised to sum 1", "1"),
        "scatter_within_limits_linear": _var(
            c, scatter.within_linear.astype(np.int8), "cell within the limits, linear (1) or not (0)", "1"
        ),
        "scatter_within_limits_nonlinear": _var(
            c, scatter.within_nonlinear.astype(np.int8), "cell within the limits, nonlinear (1) or not (0)", "1"
        ),
    }


def operability_dataset(result: OperabilityResult, scatter: ScatterAssessment | None = None) -> xr.Dataset:
    """The content of operability.nc (see the module docstring)."""
    v = _point_variables(result)
    coords: dict[str, Any] = {
        "peak_period_s": _var(("peak_period_s",), [p.peak_period_s for p in result.points], "spectral peak period Tp", "s")
    }
    attrs = _operability_attrs(result)
    if scatter is not None:
        v.update(_scatter_variables(scatter))
        dg = scatter.diagram
        coords["scatter_cell"] = _var(("scatter_cell",), np.arange(dg.occurrence.size), "scatter diagram cell index", "1")
        attrs.update(
            scatter_source=dg.source,
            share_within_limits_linear=scatter.share_within_linear,
            share_within_limits_nonlinear=scatter.share_within_nonlinear,
        )
    return xr.Dataset(v, coords=coords, attrs=attrs)


def format_operability_table(result: OperabilityResult) -> str:
    """Terminal table (Hs in m)."""
    head = ("Tp [s]", "Hs lin [m]", "Hs nonlin [m]", "uplift Hs [m]", "governing (lin)", "governing (nonlin)")
    lines = []
    for p in result.points:

        def m(x: float) -> str:
            return "-" if not math.isfinite(x) else f"{x:.2f}"

        lines.append(
            [
                f"{p.peak_period_s:g}",
                m(p.hs_allowable_linear_m),
                m(p.hs_allowable_nonlinear_m),
                m(p.hs_uplift_onset_m),
                p.governing_linear,
                p.governing_nonlinear,
            ]
        )
    widths = [max(len(h), *(len(r[i]) for r in lines)) for i, h in enumerate(head)]

    def fmt(cells: Sequence[str]) -> str:
        return "  ".join(c.rjust(w) if i < 4 else c.ljust(w) for i, (c, w) in enumerate(zip(cells, widths, strict=True)))

    return "\n".join([fmt(head), fmt(["-" * w for w in widths])] + [fmt(r) for r in lines])


def plot_operability(ds: xr.Dataset, path: str | Path) -> Path:
    """The operability chart (PNG, 200 dpi): allowable Hs against Tp, uplift onset, steepness limit, scatter cells.

    Over headings (a ``heading_deg`` dimension) the polar chart of
    :func:`~seafast.output.operability_polar.plot_heading_operability`.
    """
    if "heading_deg" in ds.dims:
        from seafast.output.operability_polar import plot_heading_operability

        return plot_heading_operability(ds, path)
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from seafast.output.style import legend_outside, save_png

    tp = ds["peak_period_s"].values
    fig, ax = plt.subplots(figsize=(11.0, 5.0))
    ax.plot(tp, ds["hs_max_steepness_m"].values, color="0.6", lw=1.0, ls=":", label="limiting steepness (DNV-RP-C205)")
    ax.plot(tp, ds["hs_allowable_nonlinear_m"].values, color="tab:red", lw=2.5, marker=".", label="allowable Hs, nonlinear (design waves)")
    ax.plot(
        tp, ds["hs_allowable_linear_m"].values, color="tab:blue", lw=1.5, ls="--", marker=".", label="allowable Hs, linear (spectral MPM)"
    )
    ax.plot(tp, ds["hs_uplift_onset_m"].values, color="tab:green", lw=1.5, ls="-.", label="uplift onset (a saddle lifts off)")
    if "scatter_occurrence" in ds:
        occ = ds["scatter_occurrence"].values
        within = ds["scatter_within_limits_nonlinear"].values.astype(bool)
        size = 10.0 + 400.0 * occ / max(float(occ.max()), 1e-300)
        for sel, colour, label in (
            (within, "tab:green", "scatter: within limits (nonlinear)"),
            (~within, "tab:gray", "scatter: not within"),
        ):
            ax.scatter(
                ds["scatter_peak_period_s"].values[sel],
                ds["scatter_significant_height_m"].values[sel],
                s=size[sel],
                facecolors="none",
                edgecolors=colour,
                label=label,
            )
    top = np.nanmax(
        np.concatenate(
            [
                ds["hs_allowable_linear_m"].values,
                ds["hs_allowable_nonlinear_m"].values,
                np.nan_to_num(ds["hs_uplift_onset_m"].values, nan=0.0),
            ]
        )
    )
    ax.set_ylim(0.0, 1.15 * max(top, 0.1))
    ax.set_xlabel("peak period Tp [s]")
    ax.set_ylabel("significant wave height Hs [m]")
    f, s = float(ds.attrs["max_saddle_force_N"]), float(ds.attrs["max_bending_stress_Pa"])
    ax.set_title(
        f"{ds.attrs.get('title', '').removeprefix('seafast operability: ')}: F <= {f / 1e6:g} MN, "
        f"sigma_b <= {s / 1e6:g} MPa, MPM over {float(ds.attrs['duration_s']) / 3600:g} h",
        fontsize=10,
    )
    ax.grid(True, alpha=0.3)
    legend_outside(ax)
    return save_png(fig, path, 200)


def write_operability_outputs(
    result: OperabilityResult, out_dir: str | Path, *, scatter: ScatterAssessment | None = None, plots: bool = True
) -> dict[str, Path]:
    """Write operability.csv, operability.nc, case.yaml, operability.png and (with a scatter diagram) scatter.csv."""
    from seafast.output.files import write_netcdf

    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    paths: dict[str, Path] = {}
    (out / "operability.csv").write_text(operability_csv_text(result), encoding="utf-8")
    paths["operability_csv"] = out / "operability.csv"
    (out / "case.yaml").write_text(
        "# the case as run (all defaults filled in)\n" + yaml.safe_dump(result.case.model_dump(mode="json"), sort_keys=False),
        encoding="utf-8",
    )
    paths["case"] = out / "case.yaml"
    ds = operability_dataset(result, scatter)
    nc = out / "operability.nc"
    if nc.exists():
        nc.unlink()
    paths["operability_nc"] = write_netcdf(ds, nc)
    if scatter is not None:
        buf = io.StringIO()
        w = csv.writer(buf, lineterminator="\n")
        w.writerow(SCATTER_RESULT_COLUMNS)
        dg = scatter.diagram
        for i in range(dg.occurrence.size):
            w.writerow(
                [
                    operability_cell(float(dg.significant_height_m[i])),
                    operability_cell(float(dg.peak_period_s[i])),
                    operability_cell(float(dg.occurrence[i])),
                    operability_cell(bool(scatter.within_linear[i])),
                    operability_cell(bool(scatter.within_nonlinear[i])),
                ]
            )
        (out / "scatter.csv").write_text(buf.getvalue(), encoding="utf-8")
        paths["scatter_csv"] = out / "scatter.csv"
    if plots:
        paths["operability_png"] = plot_operability(ds, out / "operability.png")
    return paths
