"""The polar operability chart over headings (operability.png of ``seafast operability --headings``).

Allowable Hs [m] radially against the wave heading: 180 deg (head seas, waves from ahead) at the
top, the bow; 90 deg (beam seas, waves from starboard) on the right; 0 deg (following seas) at the
bottom; one curve per peak period. Reads only the dataset (operability.nc over ``heading_deg``).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import xarray as xr

__all__ = ["polar_curves", "plot_heading_operability"]


def polar_curves(heading_deg: np.ndarray, hs_m: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Headings [rad] in increasing order and the rows of ``hs_m`` with them; the first repeated at the end (+2 pi)
    when the headings go round the circle evenly (the gap across 0 deg no wider than the others): a closed curve."""
    order = np.argsort(heading_deg % 360.0)
    h, rows = heading_deg[order] % 360.0, hs_m[order, ...]
    if h.size > 2 and 360.0 - h[-1] + h[0] <= np.max(np.diff(h)) + 1e-9:
        h, rows = np.append(h, h[0] + 360.0), np.concatenate([rows, rows[:1]], axis=0)
    return np.deg2rad(h), rows


def plot_heading_operability(ds: xr.Dataset, path: str | Path) -> Path:
    """Polar chart (PNG, 200 dpi): nonlinear allowable Hs [m] against heading, one curve per Tp; 180 deg at the top."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from seafast.output.style import legend_outside, save_png

    theta, hs = polar_curves(ds["heading_deg"].values, ds["hs_allowable_nonlinear_m"].values)
    tps = ds["peak_period_s"].values
    fig = plt.figure(figsize=(10.0, 7.5))
    ax: Any = fig.add_subplot(projection="polar")  # a PolarAxes
    ax.set_theta_zero_location("S")  # 0 (following seas, waves from astern) at the bottom, 180 (head seas) at the top
    ax.set_theta_direction(1)  # counter-clockwise: 90 (waves from starboard) on the right
    cmap = plt.get_cmap("viridis")
    span = max(float(tps.max() - tps.min()), 1e-9)
    for j, tp in enumerate(tps):
        ax.plot(theta, hs[:, j], color=cmap((tp - tps.min()) / span), lw=1.0, marker=".", ms=3)
    envelope = np.min(np.where(np.isnan(hs), np.inf, hs), axis=1)
    envelope[np.isinf(envelope)] = np.nan
    ax.plot(theta, envelope, color="black", lw=2.5, marker="o", ms=4, label="smallest over Tp")
    if "governing_heading_nonlinear_deg" in ds.attrs:
        heading, tp = float(ds.attrs["governing_heading_nonlinear_deg"]), float(ds.attrs["governing_peak_period_nonlinear_s"])
        star = ([np.deg2rad(heading)], [float(ds.attrs["governing_hs_allowable_nonlinear_m"])])
        ax.plot(*star, "r*", ms=14, label=f"governing: {heading:g} deg, Tp {tp:g} s")
    names = {0: " following", 90: " beam (stbd)", 180: " head", 270: " beam (port)"}
    ax.set_thetagrids(range(0, 360, 30), [f"{a}{names.get(a, '')}" for a in range(0, 360, 30)])
    ax.set_rlim(0.0, 1.1 * max(float(np.nanmax(hs)) if np.isfinite(hs).any() else 0.1, 0.1))
    sm = plt.cm.ScalarMappable(cmap=cmap, norm=matplotlib.colors.Normalize(float(tps.min()), float(tps.min()) + span))
    fig.colorbar(sm, ax=ax, pad=0.12, shrink=0.7, label="peak period Tp [s]")
    ax.set_title(
        f"{ds.attrs.get('title', '').removeprefix('seafast operability: ')}: allowable Hs [m] (nonlinear, radial) against "
        "wave heading [deg]\n180 = head seas at the top (bow), 90 = beam seas from starboard on the right",
        fontsize=9,
        pad=24,
    )
    legend_outside(ax, loc="upper right", bbox_to_anchor=(0.0, 1.0))
    return save_png(fig, path, 200)
