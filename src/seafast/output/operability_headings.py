"""What ``seafast operability --headings`` writes: operability.csv and .nc over headings, the polar chart, the table.

``operability.csv`` has ``heading_deg`` then exactly the columns of :data:`~seafast.output.operability.OPERABILITY_COLUMNS`
(and, when the case sets a cradle limit, the cradle limits' columns after them: their cells empty at head seas,
where no cradle is solved), one row per heading and peak period (headings in the order given, peak periods within each);
empty cell = not found; a heading whose analysis failed has governing ``failed`` and empty Hs.
``operability.nc`` holds every variable of the single-heading file over the dimensions
``(heading_deg, peak_period_s)``, each heading's error (``heading_error``) and per peak period the
smallest allowable Hs over the headings and its heading (``governing_heading_*_deg``) and limit;
the overall governing heading in the global attributes. The chart is polar
(:mod:`~seafast.output.operability_polar`).
"""

from __future__ import annotations

import csv
import io
import math
from pathlib import Path

import numpy as np
import xarray as xr
import yaml

from seafast.analyses.operability.headings import AllowableModel, GoverningHeading, HeadingOperabilityResult
from seafast.output.operability import OPERABILITY_COLUMNS, operability_cell, operability_columns, operability_dataset
from seafast.output.operability_polar import plot_heading_operability
from seafast.results.labelled import labelled_variable

__all__ = [
    "HEADING_OPERABILITY_COLUMNS",
    "HEADING_LONG_NAME",
    "heading_operability_csv_text",
    "heading_operability_dataset",
    "format_heading_table",
    "governing_heading_text",
    "write_heading_operability_outputs",
]

HEADING_OPERABILITY_COLUMNS = ("heading_deg", *OPERABILITY_COLUMNS)
"""Columns of operability.csv with ``--headings`` (the scriptable contract)."""

HEADING_LONG_NAME = (
    "wave heading beta: direction the waves travel from the ship's x axis (forward) towards y (port); "
    "180 = head seas, 90 = beam seas (waves from starboard), 0 = following seas"
)


def heading_operability_csv_text(result: HeadingOperabilityResult) -> str:
    """operability.csv text with the leading ``heading_deg`` column (SI units and degrees; empty cell = not found)."""
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    columns = ("heading_deg", *operability_columns(result.case))
    w.writerow(columns)
    for h in result.headings:
        for p in h.result.points:
            row = {"heading_deg": float(h.heading_deg), **p.row(), **p.cradle_row()}
            w.writerow([operability_cell(row[c]) for c in columns])
    return buf.getvalue()


def _governing_variables(result: HeadingOperabilityResult) -> dict[str, xr.Variable]:
    """Per peak period and model: the smallest allowable Hs over the headings, its heading and its limit."""
    d = ("peak_period_s",)
    out: dict[str, xr.Variable] = {}
    for model in AllowableModel:
        per_tp = result.governing_per_peak_period(model)
        out[f"governing_heading_{model}_deg"] = labelled_variable(
            d,
            [math.nan if g is None else g.heading_deg for g in per_tp],
            f"heading of the smallest allowable Hs, {model} (NaN: none)",
            "degree",
        )
        out[f"hs_allowable_{model}_all_headings_m"] = labelled_variable(
            d, [math.nan if g is None else g.hs_allowable_m for g in per_tp], f"smallest allowable Hs over the headings, {model}", "m"
        )
        out[f"governing_limit_{model}"] = xr.Variable(
            d,
            np.array(["" if g is None else g.governing for g in per_tp], dtype=str),
            {"long_name": f"limit reached first at the governing heading, {model} (empty: none)", "units": "1"},
        )
    return out


def heading_operability_dataset(result: HeadingOperabilityResult) -> xr.Dataset:
    """The content of operability.nc with headings (see the module docstring)."""
    per_heading = [operability_dataset(h.result) for h in result.headings]
    heading = labelled_variable(("heading_deg",), [float(h) for h in result.headings_deg], HEADING_LONG_NAME, "degree")
    ds = xr.concat(per_heading, dim="heading_deg", combine_attrs="override").assign_coords(heading_deg=heading)
    ds["heading_error"] = xr.Variable(
        ("heading_deg",),
        np.array([h.error or "" for h in result.headings], dtype=str),
        {"long_name": "the error of a heading whose analysis failed (empty: it ran)", "units": "1"},
    )
    ds = ds.assign(_governing_variables(result))
    attrs = dict(ds.attrs)
    attrs["title"] = f"seafast operability: {result.case.name}"
    attrs["case_json"] = result.case.model_dump_json()
    attrs["conventions"] = "MPMs over duration_s, still water included; wave heading per heading_deg (180 = head seas); Hs = 4 sqrt(m0)"
    for model in AllowableModel:
        g = result.governing_heading(model)
        if g is not None:
            attrs[f"governing_heading_{model}_deg"] = g.heading_deg
            attrs[f"governing_peak_period_{model}_s"] = g.peak_period_s
            attrs[f"governing_hs_allowable_{model}_m"] = g.hs_allowable_m
            attrs[f"governing_limit_{model}"] = g.governing
    ds.attrs = attrs
    return ds


def governing_heading_text(governing: GoverningHeading | None, model: AllowableModel) -> str:
    """One line naming the governing heading, its peak period, allowable Hs and limit."""
    if governing is None:
        return f"governing heading ({model}): none (no heading has an allowable Hs)"
    g = governing
    return (
        f"governing heading ({model}): {g.heading_deg:g} deg at Tp {g.peak_period_s:g} s, allowable Hs {g.hs_allowable_m:.2f} m "
        f"({g.governing} governs)"
    )


def format_heading_table(result: HeadingOperabilityResult, model: AllowableModel = AllowableModel.NONLINEAR) -> str:
    """Terminal table: allowable Hs [m] per peak period (rows) and heading (columns), the governing heading and limit."""
    head = ["Tp [s]", *(f"{h:g} deg" for h in result.headings_deg), "governing [deg]", "limit"]
    lines = []
    for i, g in enumerate(result.governing_per_peak_period(model)):
        cells = [f"{result.peak_periods_s[i]:g}"]
        for h in result.headings:
            p = h.result.points[i]
            hs = p.hs_allowable_linear_m if model is AllowableModel.LINEAR else p.hs_allowable_nonlinear_m
            cells.append(f"{hs:.2f}" if math.isfinite(hs) else ("failed" if h.failed else "-"))
        cells += ["-", "-"] if g is None else [f"{g.heading_deg:g}", g.governing]
        lines.append(cells)
    widths = [max(len(c), *(len(r[i]) for r in lines)) for i, c in enumerate(head)]

    def fmt(cells: list[str]) -> str:
        return "  ".join(c.ljust(w) if i == len(head) - 1 else c.rjust(w) for i, (c, w) in enumerate(zip(cells, widths, strict=True)))

    title = f"allowable Hs [m], {model}, per peak period and heading (180 deg = head seas, 90 = beam seas)"
    return "\n".join([title, fmt(head), fmt(["-" * w for w in widths])] + [fmt(r) for r in lines])


def write_heading_operability_outputs(result: HeadingOperabilityResult, out_dir: str | Path, *, plots: bool = True) -> dict[str, Path]:
    """Write operability.csv, operability.nc, case.yaml and operability.png (polar) for an analysis over headings."""
    from seafast.output.files import write_netcdf

    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    paths: dict[str, Path] = {}
    (out / "operability.csv").write_text(heading_operability_csv_text(result), encoding="utf-8")
    paths["operability_csv"] = out / "operability.csv"
    (out / "case.yaml").write_text(
        "# the case as run (all defaults filled in; the sea state's heading is each of heading_deg in operability.csv)\n"
        + yaml.safe_dump(result.case.model_dump(mode="json"), sort_keys=False),
        encoding="utf-8",
    )
    paths["case"] = out / "case.yaml"
    ds = heading_operability_dataset(result)
    nc = out / "operability.nc"
    if nc.exists():
        nc.unlink()
    paths["operability_nc"] = write_netcdf(ds, nc)
    if plots:
        paths["operability_png"] = plot_heading_operability(ds, out / "operability.png")
    return paths
