"""PNG figures of a sea state (matplotlib, SI units on every axis label, engineering scaling).

* ``seastate_spectrum.png``: the wave spectrum and the response spectra of the governing saddle
  force and bending moment (normalised to their peaks).
* ``seastate_transfer_functions.png``: |transfer function| of the saddle forces, the bending
  moment where it is largest, the deck deflection under the saddles, heave and pitch.
* ``seastate_realisation.png``: one Monte Carlo realisation's saddle forces over time with
  lift-off marked (when the Monte Carlo engine ran).
* ``seastate_maxima.png``: the distribution of the per-realisation maxima with the Gumbel fit
  (when the Monte Carlo engine ran).

Figures are built from the seastate.nc Dataset (and the Monte Carlo result for the two last).
Legends stand outside the axes and curves that coincide keep distinct styles
(:mod:`seafast.output.style`).
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
import xarray as xr

from seafast.output.style import legend_outside, save_png

if TYPE_CHECKING:  # imported by the engine's caller when it ran
    from seafast.analyses.seastate.monte_carlo import MonteCarloResult

__all__ = ["write_seastate_figures", "FIGURE_DPI"]

FIGURE_DPI = 200  # print quality, as the report's figures


def _abs(ds: xr.Dataset, name: str) -> np.ndarray:
    return np.hypot(ds[f"{name}_real"].values, ds[f"{name}_imag"].values)


def _governing(ds: xr.Dataset) -> tuple[int, int]:
    """Index of the saddle with the largest total force and of the x with the largest total moment."""
    s = int(np.argmax(ds["still_water_saddle_force_N"].values + ds["saddle_force_mpm_dynamic_N"].values))
    x = int(np.argmax(np.abs(ds["still_water_bending_moment_Nm"].values) + ds["bending_moment_mpm_dynamic_Nm"].values))
    return s, x


def _spectrum_figure(ds: xr.Dataset, path: Path) -> Path:
    import matplotlib.pyplot as plt

    w = ds["omega_rad_s"].values
    s, x = _governing(ds)
    fig, ax = plt.subplots(figsize=(11, 4.8))
    ax.plot(w, ds["wave_spectrum_m2_s_per_rad"].values, "k-", lw=2, label="wave spectrum")
    ax.set_xlabel("wave frequency ω [rad/s]")
    ax.set_ylabel("wave spectral density S(ω) [m² s/rad]")
    ax2 = ax.twinx()
    # the two normalised response spectra nearly coincide: a wide light line under a thin dashed one
    wide: dict[str, Any] = {"color": "C0", "lw": 4, "alpha": 0.45}
    thin: dict[str, Any] = {"color": "C3", "lw": 1.2, "ls": "--"}
    for name, idx, label, style in (
        ("saddle_force_spectrum_N2_s_per_rad", {"saddle": s}, f"saddle force, saddle {s}", wide),
        ("bending_moment_spectrum_Nm2_s_per_rad", {"x_moment_m": x}, f"bending moment, x = {float(ds['x_moment_m'][x]):.1f} m", thin),
    ):
        r = ds[name].isel(idx).values
        ax2.plot(w, r / max(float(r.max()), 1e-300), **style, label=f"response: {label}")
    ax2.set_ylabel("response spectrum / its peak [-]")
    ax2.set_ylim(0, 1.05)
    lines = ax.get_legend_handles_labels()[0] + ax2.get_legend_handles_labels()[0]
    labels = ax.get_legend_handles_labels()[1] + ax2.get_legend_handles_labels()[1]
    legend_outside(ax2, lines, labels, bbox_to_anchor=(1.1, 1.0))
    ax.set_xlim(0, float(w[-1]))
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3)
    ax.set_title(f"Sea state: {ds.attrs.get('spectrum', '')}, duration {float(ds.attrs.get('duration_s', np.nan)) / 3600:g} h")
    return save_png(fig, path, FIGURE_DPI)


def _transfer_figure(ds: xr.Dataset, path: Path) -> Path:
    import matplotlib.pyplot as plt

    w = ds["omega_rad_s"].values
    _, x = _governing(ds)
    fig, axes = plt.subplots(2, 2, figsize=(13, 7), sharex=True)
    force = _abs(ds, "saddle_force_transfer_N_per_m")
    deck = _abs(ds, "deck_deflection_transfer_m_per_m")
    for i in range(force.shape[1]):
        # saddles with mirror-image responses coincide: each a line style of its own, later ones thinner
        style: dict[str, Any] = {"ls": ("-", "--", "-.", ":")[i % 4], "lw": max(2.4 - 0.5 * i, 0.8), "color": f"C{i}"}
        axes[0, 0].plot(w, force[:, i] / 1e6, **style, label=f"saddle {i} (x = {float(ds['saddle_x_m'][i]):.1f} m)")
        axes[1, 0].plot(w, deck[:, i] * 1e3, **style, label=f"saddle {i}")
    axes[0, 0].set_ylabel("|saddle force| [MN per m of wave]")
    axes[1, 0].set_ylabel("|hull deck deflection| [mm per m of wave]")
    moment = _abs(ds, "bending_moment_transfer_Nm_per_m")[:, x]
    axes[0, 1].plot(w, moment / 1e6, "C3", label=f"x = {float(ds['x_moment_m'][x]):.1f} m (largest total)")
    axes[0, 1].set_ylabel("|bending moment| [MN m per m of wave]")
    k = w**2 / 9.81
    axes[1, 1].plot(w, _abs(ds, "heave_transfer_m_per_m"), "k", label="heave [m/m]")
    axes[1, 1].plot(w, _abs(ds, "pitch_transfer_rad_per_m") / k, "C2", label="pitch / k [-]")
    axes[1, 1].set_ylabel("|heave| [m/m], |pitch| / k [-]")
    for ax in axes.ravel():
        ax.grid(alpha=0.3)
        ax.set_xlim(0, float(w[-1]))
    for ax in axes[:, 0]:  # the saddle legends, between the columns
        legend_outside(ax, fontsize=7)
    for ax in axes[:, 1]:
        legend_outside(ax, fontsize=7)
    for ax in axes[1]:
        ax.set_xlabel("wave frequency ω [rad/s]")
    fig.suptitle("Transfer functions per metre of wave amplitude (linear model, head seas)")
    return save_png(fig, path, FIGURE_DPI)


def _realisation_figure(example: Any, path: Path) -> Path:
    """``example``: the engine's ``RealisationTimeSeries`` (time_s, wave_elevation_m, linear/nonlinear_saddle_force_N, saddle_lifted).

    Top: the wave; middle: the whole record; bottom: 90 s around the lift-off nearest the largest
    linear force (or around the largest force when no saddle lifts), where the models part.
    """
    import matplotlib.pyplot as plt

    t = np.asarray(example.time_s, dtype=float)
    nonlinear = np.asarray(example.nonlinear_saddle_force_N, dtype=float)
    linear = np.asarray(example.linear_saddle_force_N, dtype=float)
    lifted = np.asarray(example.saddle_lifted, dtype=bool)
    peak = int(np.argmax(linear.max(axis=1)))
    lift_times = np.flatnonzero(lifted.any(axis=1))
    centre = t[lift_times[np.argmin(np.abs(lift_times - peak))]] if lift_times.size else t[int(np.argmax(nonlinear.max(axis=1)))]
    zoom = (t >= centre - 45.0) & (t <= centre + 45.0)
    fig, (ax0, ax1, ax2) = plt.subplots(3, 1, figsize=(13, 8.5), gridspec_kw={"height_ratios": [1, 2, 2]})
    ax0.plot(t, np.asarray(example.wave_elevation_m, dtype=float), "k", lw=0.4)
    ax0.set_ylabel("wave at midship ζ [m]")
    for ax, sel in ((ax1, slice(None)), (ax2, zoom)):
        for i in range(nonlinear.shape[1]):
            colour = f"C{i}"
            # where the models agree the thin dashed linear line lies on the wider nonlinear one
            ax.plot(t[sel], nonlinear[sel, i] / 1e6, color=colour, lw=1.4, zorder=2, label=f"saddle {i}, nonlinear")
            ax.plot(
                t[sel], linear[sel, i] / 1e6, color="k", lw=0.6, ls="--", zorder=3, label="linear model (each saddle)" if i == 0 else None
            )
            mark = lifted[sel, i]
            if np.any(mark):
                ax.plot(t[sel][mark], np.zeros(int(mark.sum())), "|", color=colour, ms=12, mew=1.5, label=f"saddle {i} lifted off")
        ax.axhline(0.0, color="k", lw=0.6)
        ax.set_ylabel("saddle force F [MN]")
    ax1.axvspan(centre - 45.0, centre + 45.0, color="0.85", zorder=0)
    ax2.set_xlabel("time t [s]")
    ax2.set_title(f"t = {centre - 45:.0f} to {centre + 45:.0f} s (shaded above)", fontsize=9)
    legend_outside(ax2, fontsize=7)
    for ax in (ax0, ax1, ax2):
        ax.grid(alpha=0.3)
    fig.suptitle(
        f"Realisation {getattr(example, 'index', '')}: saddle forces (nonlinear solid, linear dashed black), lift-off marked | on F = 0"
    )
    return save_png(fig, path, FIGURE_DPI)


def _maxima_figure(monte_carlo: Any, ds: xr.Dataset, path: Path) -> Path:
    import matplotlib.pyplot as plt
    from scipy.stats import gumbel_r

    from seafast.analyses.seastate.extremes import gumbel_fit  # the engine's fit: its mode is the MPM reported

    fig, axes = plt.subplots(2, 1, figsize=(10, 8))
    for ax, q, scale, unit in ((axes[0], "F_N", 1e-6, "MN"), (axes[1], "M_b_Nm", 1e-6, "MN m")):
        for stats, colour, marker in ((monte_carlo.linear, "C0", "o"), (monte_carlo.nonlinear, "C3", "x")):
            m = np.sort(np.asarray(stats.maxima[q], dtype=float))
            m = m[np.isfinite(m)]
            if m.size == 0:
                continue
            p = (np.arange(1, m.size + 1) - 0.44) / (m.size + 0.12)  # Gringorten plotting positions
            face = "none" if marker == "o" else colour
            ax.plot(m * scale, p, marker, color=colour, mfc=face, ms=6, ls="none", label=f"{stats.model}: maxima of {m.size} realisations")
            if m.size >= 3 and np.ptp(m) > 0 and np.all(m > 0):
                mode, beta = (float(v) for v in gumbel_fit(m))
                xx = np.linspace(m.min() - 0.3 * np.ptp(m), m.max() + 0.3 * np.ptp(m), 200)
                ax.plot(xx * scale, gumbel_r.cdf(xx, mode, beta), "-", color=colour, lw=1, label=f"{stats.model}: Gumbel fit")
            ax.axvline(float(stats.mpm[q]) * scale, color=colour, ls=":", lw=1)
        spectral = float(ds[q].sel(model="linear", estimate_method="spectral"))
        ax.axvline(spectral * scale, color="k", ls="--", lw=1, label="linear spectral MPM")
        ax.set_xlabel(f"{'saddle force F' if q == 'F_N' else 'bending moment M_b'} maximum over the duration [{unit}]")
        ax.set_ylabel("non-exceedance probability [-]")
        ax.grid(alpha=0.3)
        legend_outside(ax, fontsize=7)
    fig.suptitle("Distribution of the maxima (MPM: dotted = Gumbel mode, dashed = spectral)")
    return save_png(fig, path, FIGURE_DPI)


def write_seastate_figures(ds: xr.Dataset, out_dir: str | Path, monte_carlo: MonteCarloResult | None = None) -> list[Path]:
    """Write the sea-state PNGs into ``out_dir``; the Monte Carlo ones only when it ran."""
    import matplotlib

    matplotlib.use("Agg")
    out = Path(out_dir)
    paths = [_spectrum_figure(ds, out / "seastate_spectrum.png"), _transfer_figure(ds, out / "seastate_transfer_functions.png")]
    if monte_carlo is not None:
        if getattr(monte_carlo, "example", None) is not None:
            paths.append(_realisation_figure(monte_carlo.example, out / "seastate_realisation.png"))
        paths.append(_maxima_figure(monte_carlo, ds, out / "seastate_maxima.png"))
    return paths
