"""The cross-section of the cargo in each of its cradles, off head seas (matplotlib, PNG).

One panel per saddle, looking forward (port on the left): the tube's circle, its two pads at +-alpha from bottom
dead centre with the peak and least force of the wave's nonlinear row and the share of the period each is lifted
off, the side stoppers with their gap and peak force, and the lashing wires (in the ship's vertical-longitudinal
plane, so seen end-on below the axis) with their largest and least tension. Reads the run's Dataset (the
variables of :mod:`seafast.results.cradle`, present only off head seas).
"""

from __future__ import annotations

import math
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import xarray as xr

from seafast.output.style import save_png

__all__ = ["plot_cradle_sections"]

DPI = 200


def _pads(ax: plt.Axes, sel: xr.Dataset, j: int, radius: float, alpha: float) -> None:
    """The two pads of saddle ``j``: blocks on the circle at +-alpha, each with its forces [MN] and lifted share."""
    for side_index, side in enumerate(("port", "starboard")):
        y = (1.0 if side == "port" else -1.0) * radius * math.sin(alpha)
        z = -radius * math.cos(alpha)
        normal = np.array([y, z]) / radius
        block = np.array([[y, z], [y, z]]) + np.outer([0.0, 0.12 * radius], normal)
        ax.plot(block[:, 0], block[:, 1], color="tab:brown", lw=7, solid_capstyle="butt")
        peak = float(sel["pad_force_max_N"].isel(saddle=j, pad_side=side_index)) / 1e6
        least = float(sel["pad_force_min_N"].isel(saddle=j, pad_side=side_index)) / 1e6
        lifted = 100.0 * float(sel["pad_open_fraction"].isel(saddle=j, pad_side=side_index))
        ax.annotate(
            f"{side} pad\nmax {peak:.2f} MN\nmin {least:.2f} MN\nlifted {lifted:.0f} %",
            (y, z),
            xytext=(1.55 * y, z - 0.45 * radius),
            fontsize=7,
            ha="center",
            va="top",
            arrowprops={"arrowstyle": "-", "color": "0.5", "lw": 0.6},
        )


def _stoppers(ax: plt.Axes, ds: xr.Dataset, sel: xr.Dataset, x_m: float, radius: float) -> None:
    """The side stoppers at the saddle's x: bars beyond the gap, each with its peak force [MN]."""
    if "stopper" not in ds.dims:
        return
    for k in np.flatnonzero(np.isclose(ds["stopper_x_m"].values, x_m)):
        sign = 1.0 if str(ds["stopper_side"].values[k]) == "port" else -1.0
        y = sign * (radius + float(ds["stopper_gap_m"].values[k]))
        ax.plot([y, y + sign * 0.08 * radius], [0.0, 0.0], color="tab:purple", lw=6, solid_capstyle="butt")
        peak = float(sel["stopper_force_N"].isel(stopper=k).max()) / 1e6
        ax.text(y + sign * 0.1 * radius, 0.12 * radius, f"stopper\nmax {peak:.2f} MN", fontsize=7, ha="center", va="bottom")


def _lashings(ax: plt.Axes, ds: xr.Dataset, sel: xr.Dataset, j: int, radius: float) -> None:
    """The lashing wires of saddle ``j`` (fore and aft, seen end-on): their largest and least tension [kN]."""
    if "lashing" not in ds.dims:
        return
    wires = np.flatnonzero(ds["lashing_saddle"].values == j)
    if wires.size == 0:
        return
    tension = sel["lashing_tension_N"].isel(lashing=wires).values / 1e3
    for w in wires:
        d = ds["lashing_direction"].values[w]
        ax.plot([0.0, 1.3 * radius * d[1]], [0.0, 1.3 * radius * d[2]], "--", color="tab:blue", lw=1.2)
    ax.text(
        -0.08 * radius,  # beside the wires (the y axis runs to port on the left)
        -0.55 * radius,
        f"{wires.size} lashing wire(s)\nmax {tension.max():.1f} kN\nmin {tension.min():.1f} kN",
        fontsize=7,
        color="tab:blue",
    )


def plot_cradle_sections(ds: xr.Dataset, path: Path) -> Path:
    """One cross-section per saddle with its pads, stoppers and lashings and their forces (module docstring)."""
    sel = ds.sel(load_case="dynamic", model="nonlinear")  # the wave's nonlinear response, still water included
    n = int(ds.sizes["saddle"])
    columns = min(n, 4)
    rows = math.ceil(n / columns)
    fig, axes = plt.subplots(rows, columns, figsize=(3.6 * columns, 4.6 * rows), squeeze=False)
    alpha = math.radians(float(ds.attrs["saddle_contact_angle_deg"]))
    for j, ax in enumerate(axes.ravel()):
        if j >= n:
            ax.set_axis_off()
            continue
        radius = float(ds["cradle_tube_radius_m"].values[j])
        x_m = float(ds["saddle_x_m"].values[j])
        circle = np.linspace(0.0, 2.0 * np.pi, 181)
        ax.plot(radius * np.cos(circle), radius * np.sin(circle), color="k", lw=1.2)
        ax.plot([-1.6 * radius, 1.6 * radius], [-1.25 * radius] * 2, color="0.4", lw=2)
        _pads(ax, sel, j, radius, alpha)
        _stoppers(ax, ds, sel, x_m, radius)
        _lashings(ax, ds, sel, j, radius)
        ax.set_aspect("equal")
        ax.set_xlim(1.9 * radius, -1.9 * radius)  # looking forward: port (y > 0) on the left
        ax.set_ylim(-2.3 * radius, 1.5 * radius)
        ax.set_title(f"saddle {j}, x = {x_m:.1f} m (alpha = {math.degrees(alpha):.0f} deg)", fontsize=9)
        ax.set_xlabel("y, to port [m]")
        ax.set_ylabel("z, up [m]")
        ax.grid(alpha=0.25)
    fig.suptitle("The cargo in its cradles, looking forward: dynamic nonlinear row (still water + wave)", fontsize=10)
    return save_png(fig, path, DPI, rect=(0.0, 0.03, 1.0, 0.94))
