"""Study figures (matplotlib, Agg backend, PNG).

- 2-D studies: response surfaces (max saddle force, max bending moment, max bending stress of the
  total response) over the two study axes for each model, log axes where the study axis is log,
  the contact-preserved region hatched, the design limits drawn as contour lines, the base case
  marked; and a compliance map (which model's verdict admits each point).
- 1-D studies: the same quantities as lines.
- Studies with more than two axes: the surface over the first two axes with the other axes held at
  their base-case value (or the middle value when the base value is off the grid).

What is drawn is what was computed: one cell per study point, the contact-preserved cells
hatched and the design limits drawn along the cell edges between points within and beyond them
(nothing interpolated between saddle counts). Axis units are scaled to the data (a stiffness axis
in GN/m, ticks 0.01 ... 10) with plain-number ticks, and an axis of a few integers (saddle counts)
has its ticks at its values (:mod:`seafast.output.style`).
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import xarray as xr
from matplotlib.artist import Artist
from matplotlib.colors import ListedColormap
from matplotlib.patches import Patch, Rectangle

from seafast.output.style import MODEL_LINES, cell_boundary, legend_outside, plain_tick_labels, scaled_axis_label, value_ticks
from seafast.studies.limits import DesignLimits, compliance

__all__ = ["plot_study", "plot_surfaces", "plot_compliance_map", "plot_profiles", "study_slice"]

_QUANTITIES: tuple[tuple[str, str, float, str], ...] = (
    ("F_N", "max saddle force F", 1e-6, "MN"),
    ("M_b_Nm", "max bending moment M_b", 1e-6, "MN m"),
    ("sigma_b_Pa", "max bending stress sigma_b", 1e-6, "MPa"),
)


def _axis_keys(ds: xr.Dataset) -> list[str]:
    return [str(d) for d in ds["F_N"].dims if d not in ("load_case", "model")]


def _total(ds: xr.Dataset) -> xr.Dataset:
    labels = [str(v) for v in ds["load_case"].values] if "load_case" in ds.dims else []
    if not labels:
        return ds
    return ds.sel(load_case="dynamic" if "dynamic" in labels else labels[-1])


def _scaled(ds: xr.Dataset, key: str) -> tuple[np.ndarray, float, str]:
    """A study axis in its plotting unit: the scaled values, the factor applied and the axis label."""
    values = np.asarray(ds[key].values, dtype=float)
    factor, label = scaled_axis_label(key, values.tolist(), str(ds[key].attrs.get("units", "1")))
    return values * factor, factor, label


def _is_discrete(ds: xr.Dataset, key: str) -> bool:
    """A short axis of integers (saddle counts): ticks at its values."""
    values = np.asarray(ds[key].values)
    return values.size <= 15 and bool(np.all(np.isfinite(values.astype(float)))) and bool(np.all(values.astype(float) % 1 == 0))


def _is_log(ds: xr.Dataset, key: str) -> bool:
    return ds[key].attrs.get("scale") == "log"


def _base_value(ds: xr.Dataset, key: str) -> float:
    value = ds[key].attrs.get("base_value", math.nan)
    try:
        return float(value)
    except (TypeError, ValueError):
        return math.nan


def study_slice(ds: xr.Dataset, keep: int = 2) -> tuple[xr.Dataset, dict[str, Any]]:
    """Reduce a study to its first ``keep`` axes, holding the others at the base case.

    Returns
    -------
    sliced : xarray.Dataset
    held : dict
        The held axes and the values they are held at (SI units of the key).
    """
    held: dict[str, Any] = {}
    for key in _axis_keys(ds)[keep:]:
        coords = ds[key].values
        base = _base_value(ds, key)
        if math.isfinite(base) and coords.min() <= base <= coords.max():
            index = int(np.argmin(np.abs(coords.astype(float) - base)))
        else:
            index = len(coords) // 2
        held[key] = coords[index].item()
        ds = ds.isel({key: index})
    return ds, held


def _edges(values: np.ndarray, log: bool) -> np.ndarray:
    v = np.asarray(values, dtype=float)
    if len(v) == 1:
        return np.array([v[0] / 1.5, v[0] * 1.5]) if log else np.array([v[0] - 0.5, v[0] + 0.5])
    t = np.log(v) if log else v
    mid = 0.5 * (t[1:] + t[:-1])
    e = np.concatenate([[t[0] - (mid[0] - t[0])], mid, [t[-1] + (t[-1] - mid[-1])]])
    return np.exp(e) if log else e


def _setup_axis(ax: Any, which: str, ds: xr.Dataset, key: str) -> None:
    """Label, scale and ticks of the study axis ``key`` on ``ax``'s ``which`` ("x" or "y") axis."""
    values, _, label = _scaled(ds, key)
    axis = ax.xaxis if which == "x" else ax.yaxis
    axis.set_label_text(label)
    if _is_log(ds, key):
        (ax.set_xscale if which == "x" else ax.set_yscale)("log")
    if _is_discrete(ds, key):
        value_ticks(axis, values.tolist())
    else:
        plain_tick_labels(axis)


def _setup_axes(ax: Any, ds: xr.Dataset, xkey: str, ykey: str) -> None:
    _setup_axis(ax, "x", ds, xkey)
    _setup_axis(ax, "y", ds, ykey)


def _mark_base(ax: Any, ds: xr.Dataset, xkey: str, ykey: str) -> None:
    bx, by = _base_value(ds, xkey) * _scaled(ds, xkey)[1], _base_value(ds, ykey) * _scaled(ds, ykey)[1]
    if math.isfinite(bx) and math.isfinite(by):
        ax.plot([bx], [by], marker="*", markersize=14, color="white", markeredgecolor="black", linestyle="none", label="base case")


def _hatch_cells(ax: Any, xe: np.ndarray, ye: np.ndarray, mask: np.ndarray) -> None:
    """Hatch the cells where ``mask`` (rows along y) holds."""
    for i, j in zip(*np.nonzero(mask), strict=True):
        ax.add_patch(Rectangle((xe[j], ye[i]), xe[j + 1] - xe[j], ye[i + 1] - ye[i], fill=False, hatch="//", lw=0, edgecolor="black"))


def _title_suffix(held: dict[str, Any]) -> str:
    return "" if not held else " (" + ", ".join(f"{k} = {v:g}" for k, v in held.items()) + ")"


def plot_surfaces(ds: xr.Dataset, path: str | Path, model: str = "nonlinear", limits: DesignLimits | None = None) -> Path:
    """Response surfaces of one model over the first two study axes (PNG).

    Panels: max saddle force [MN], max bending moment [MN m], max bending stress [MPa] of the total
    (dynamic) response; hatched where contact is preserved at every saddle (nonlinear model);
    dashed lines at the design limits; star at the base case.
    """
    limits = limits or DesignLimits.from_attrs(ds.attrs)
    sliced, held = study_slice(ds, 2)
    xkey, ykey = _axis_keys(sliced)[1], _axis_keys(sliced)[0]
    total = _total(sliced).transpose(ykey, xkey, ...)
    x, y = _scaled(sliced, xkey)[0], _scaled(sliced, ykey)[0]
    xe, ye = _edges(x, _is_log(sliced, xkey)), _edges(y, _is_log(sliced, ykey))
    contact = total["contact_preserved"].sel(model="nonlinear" if "nonlinear" in total["model"] else model).values.astype(bool)
    limit_of = {"F_N": limits.max_saddle_force_N, "sigma_b_Pa": limits.max_bending_stress_Pa}
    fig, axes = plt.subplots(1, 3, figsize=(17, 4.8), constrained_layout=True)
    for ax, (name, title, scale, unit) in zip(axes, _QUANTITIES, strict=True):
        z = total[name].sel(model=model).values * scale
        mesh = ax.pcolormesh(xe, ye, np.ma.masked_invalid(z), shading="flat", cmap="viridis")
        fig.colorbar(mesh, ax=ax, label=f"{title} [{unit}]")
        _hatch_cells(ax, xe, ye, contact)
        ax.plot(*cell_boundary(xe, ye, contact), color="white", lw=1.0)
        if name in limit_of:
            beyond = np.nan_to_num(z, nan=-np.inf) > limit_of[name] * scale
            ax.plot(*cell_boundary(xe, ye, beyond), color="red", ls="--", lw=1.8)
        _setup_axes(ax, sliced, xkey, ykey)
        _mark_base(ax, sliced, xkey, ykey)
        ax.set_title(f"{title}, {model}")
    handles = [
        Patch(facecolor="none", edgecolor="black", hatch="//", label="contact preserved (linear valid)"),
        plt.Line2D([], [], color="red", linestyle="--", label="design limit"),
        plt.Line2D([], [], marker="*", color="white", markeredgecolor="black", linestyle="none", markersize=12, label="base case"),
    ]
    fig.legend(handles=handles, loc="lower center", ncol=3, bbox_to_anchor=(0.5, -0.08))
    fig.suptitle(f"study {ds.attrs.get('study', '')}: total (dynamic) response{_title_suffix(held)}")
    path = Path(path)
    fig.savefig(path, dpi=110, bbox_inches="tight")
    plt.close(fig)
    return path


def plot_compliance_map(ds: xr.Dataset, path: str | Path, limits: DesignLimits | None = None) -> Path:
    """Compliance map over the first two study axes (PNG): which model admits each point."""
    limits = limits or DesignLimits.from_attrs(ds.attrs)
    sliced, held = study_slice(ds, 2)
    comp = compliance(sliced, limits)
    keys = _axis_keys(sliced)
    xkey, ykey = keys[1], keys[0]
    comp = comp.transpose(ykey, xkey, ...)
    x, y = _scaled(sliced, xkey)[0], _scaled(sliced, ykey)[0]
    models = [str(m) for m in comp["model"].values]
    lin = comp["complies"].sel(model="linear").values if "linear" in models else np.zeros((len(y), len(x)), bool)
    non = comp["complies"].sel(model="nonlinear").values if "nonlinear" in models else np.zeros((len(y), len(x)), bool)
    category = lin.astype(int) + 2 * non.astype(int)  # 0 none, 1 linear only, 2 nonlinear only, 3 both
    colors = ["#d9d9d9", "#fdb863", "#80cdc1", "#1a9850"]
    names = ["complies with neither", "linear model only", "nonlinear model only", "both models"]
    fig, ax = plt.subplots(figsize=(7.5, 5.5), constrained_layout=True)
    ax.pcolormesh(
        _edges(x, _is_log(sliced, xkey)),
        _edges(y, _is_log(sliced, ykey)),
        category,
        shading="flat",
        cmap=ListedColormap(colors),
        vmin=-0.5,
        vmax=3.5,
        edgecolors="white",
        linewidth=0.3,
    )
    if "error" in sliced:
        failed = (sliced["error"] != "").broadcast_like(comp["complies"].isel(model=0)).transpose(ykey, xkey).values
    else:
        failed = np.zeros_like(category, bool)
    if failed.any():
        yy, xx = np.nonzero(failed)
        ax.plot(x[xx], y[yy], "kx", linestyle="none", label="evaluation failed")
    _setup_axes(ax, sliced, xkey, ykey)
    _mark_base(ax, sliced, xkey, ykey)
    handles: list[Artist] = [Patch(color=c, label=n) for c, n in zip(colors, names, strict=True)]
    handles += ax.get_legend_handles_labels()[0]
    ax.legend(handles=handles, loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize=8)
    ax.set_title(
        f"compliance: F <= {limits.max_saddle_force_N / 1e6:g} MN, sigma_b <= {limits.max_bending_stress_Pa / 1e6:g} MPa"
        f"{_title_suffix(held)}",
        fontsize=10,
    )
    path = Path(path)
    fig.savefig(path, dpi=110, bbox_inches="tight")
    plt.close(fig)
    return path


def plot_profiles(ds: xr.Dataset, path: str | Path, limits: DesignLimits | None = None) -> Path:
    """Line plots of a one-axis study (PNG): F, M_b, sigma_b of both models vs the study axis."""
    limits = limits or DesignLimits.from_attrs(ds.attrs)
    sliced, held = study_slice(ds, 1)
    key = _axis_keys(sliced)[0]
    total = _total(sliced)
    x, x_factor, _ = _scaled(sliced, key)
    contact = total["contact_preserved"].sel(model="nonlinear").values if "nonlinear" in total["model"] else None
    limit_of = {"F_N": limits.max_saddle_force_N, "sigma_b_Pa": limits.max_bending_stress_Pa}
    fig, axes = plt.subplots(1, 3, figsize=(16, 4.5), constrained_layout=True)
    xe = _edges(x, _is_log(sliced, key))
    for ax, (name, title, scale, unit) in zip(axes, _QUANTITIES, strict=True):
        for model in ("nonlinear", "linear"):
            if model in total["model"]:
                ax.plot(x, total[name].sel(model=model).values * scale, **MODEL_LINES[model], marker="o", markersize=4, label=model)
        if name in limit_of:
            ax.axhline(limit_of[name] * scale, color="red", linestyle=":", label="design limit")
        if contact is not None:
            for i, ok in enumerate(contact):
                if ok:
                    ax.axvspan(xe[i], xe[i + 1], color="tab:green", alpha=0.12, linewidth=0)
        base = _base_value(sliced, key) * x_factor
        if math.isfinite(base):
            ax.axvline(base, color="black", linewidth=0.8, label="base case")
        ax.set_ylabel(f"{title} [{unit}]")
        _setup_axis(ax, "x", sliced, key)
        ax.set_title(title)
    legend_outside(axes[-1])
    fig.suptitle(f"study {ds.attrs.get('study', '')}: total (dynamic) response; shaded: contact preserved{_title_suffix(held)}")
    path = Path(path)
    fig.savefig(path, dpi=110, bbox_inches="tight")
    plt.close(fig)
    return path


def plot_study(ds: xr.Dataset, directory: str | Path, limits: DesignLimits | None = None) -> list[Path]:
    """All figures of a study into ``directory``; returns the PNG paths.

    Files: ``surface_nonlinear.png``, ``surface_linear.png`` and ``compliance_map.png`` for
    studies with two or more axes (of at least two values each); ``profiles.png`` otherwise.
    """
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    limits = limits or DesignLimits.from_attrs(ds.attrs)
    keys = _axis_keys(ds)
    models = [str(m) for m in ds["model"].values]
    multi = [k for k in keys if ds.sizes[k] > 1]
    if len(multi) >= 2:
        reordered = ds.transpose(*multi, *[k for k in keys if k not in multi], "load_case", "model")
        paths = [plot_surfaces(reordered, directory / f"surface_{m}.png", m, limits) for m in ("nonlinear", "linear") if m in models]
        paths.append(plot_compliance_map(reordered, directory / "compliance_map.png", limits))
        return paths
    main = multi[0] if multi else keys[0]
    reordered = ds.transpose(main, *[k for k in keys if k != main], "load_case", "model")
    return [plot_profiles(reordered, directory / "profiles.png", limits)]
