"""Study figures (matplotlib, Agg backend, PNG).

- 2-D studies: response surfaces (max saddle force, max bending moment, max bending stress of the
  total response) over the two study axes for each model, log axes where the study axis is log,
  the contact-preserved region hatched, the design limits drawn as contour lines, the base case
  marked; and a compliance map (which model's verdict admits each point).
- 1-D studies: the same quantities as lines.
- Studies with more than two axes: the surface over the first two axes with the other axes held at
  their base-case value (or the middle value when the base value is off the grid).
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
from matplotlib.patches import Patch

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


def _label(ds: xr.Dataset, key: str) -> str:
    unit = ds[key].attrs.get("units", "1")
    return f"{key} [{'-' if unit in ('1', '') else unit}]"


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


def _setup_axes(ax: Any, ds: xr.Dataset, xkey: str, ykey: str) -> None:
    ax.set_xlabel(_label(ds, xkey))
    ax.set_ylabel(_label(ds, ykey))
    if _is_log(ds, xkey):
        ax.set_xscale("log")
    if _is_log(ds, ykey):
        ax.set_yscale("log")


def _mark_base(ax: Any, ds: xr.Dataset, xkey: str, ykey: str) -> None:
    bx, by = _base_value(ds, xkey), _base_value(ds, ykey)
    if math.isfinite(bx) and math.isfinite(by):
        ax.plot([bx], [by], marker="*", markersize=14, color="white", markeredgecolor="black", linestyle="none", label="base case")


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
    total = _total(sliced)
    x, y = sliced[xkey].values.astype(float), sliced[ykey].values.astype(float)
    xe, ye = _edges(x, _is_log(sliced, xkey)), _edges(y, _is_log(sliced, ykey))
    contact = total["contact_preserved"].sel(model="nonlinear" if "nonlinear" in total["model"] else model).values.astype(float)
    limit_of = {"F_N": limits.max_saddle_force_N, "sigma_b_Pa": limits.max_bending_stress_Pa}
    fig, axes = plt.subplots(1, 3, figsize=(17, 4.8), constrained_layout=True)
    for ax, (name, title, scale, unit) in zip(axes, _QUANTITIES, strict=True):
        z = total[name].sel(model=model).values * scale
        mesh = ax.pcolormesh(xe, ye, np.ma.masked_invalid(z), shading="flat", cmap="viridis")
        fig.colorbar(mesh, ax=ax, label=f"{title} [{unit}]")
        if len(x) > 1 and len(y) > 1:
            if np.any(contact > 0.5):
                ax.contourf(x, y, contact, levels=[0.5, 1.5], colors="none", hatches=["//"])
                ax.contour(x, y, contact, levels=[0.5], colors="white", linewidths=1.0)
            if name in limit_of and np.nanmin(z) < limit_of[name] * scale < np.nanmax(z):
                ax.contour(x, y, z, levels=[limit_of[name] * scale], colors="red", linestyles="--", linewidths=1.5)
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
    x, y = sliced[xkey].values.astype(float), sliced[ykey].values.astype(float)
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
    x = sliced[key].values.astype(float)
    contact = total["contact_preserved"].sel(model="nonlinear").values if "nonlinear" in total["model"] else None
    limit_of = {"F_N": limits.max_saddle_force_N, "sigma_b_Pa": limits.max_bending_stress_Pa}
    fig, axes = plt.subplots(1, 3, figsize=(16, 4.5), constrained_layout=True)
    xe = _edges(x, _is_log(sliced, key))
    for ax, (name, title, scale, unit) in zip(axes, _QUANTITIES, strict=True):
        for model, style in (("linear", "--"), ("nonlinear", "-")):
            if model in total["model"]:
                ax.plot(x, total[name].sel(model=model).values * scale, style, marker="o", markersize=3, label=model)
        if name in limit_of:
            ax.axhline(limit_of[name] * scale, color="red", linestyle=":", label="design limit")
        if contact is not None:
            for i, ok in enumerate(contact):
                if ok:
                    ax.axvspan(xe[i], xe[i + 1], color="tab:green", alpha=0.12, linewidth=0)
        base = _base_value(sliced, key)
        if math.isfinite(base):
            ax.axvline(base, color="black", linewidth=0.8, label="base case")
        ax.set_xlabel(_label(sliced, key))
        ax.set_ylabel(f"{title} [{unit}]")
        if _is_log(sliced, key):
            ax.set_xscale("log")
        ax.set_title(title)
        ax.legend(fontsize=8)
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
