"""Report-ready figures of one case (matplotlib, PNG). Every axis carries its unit.

All functions take the case Dataset written as ``results.nc`` (so they also work on a file
read back later) and return the path written. The conventions of :mod:`seafast.output.style`
hold: the linear model dashed over the nonlinear one, legends outside the axes, axis units
scaled to the data with plain-number ticks.
"""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import xarray as xr

from seafast.fourier import harmonics_up_to
from seafast.output.report.common import rao_curves
from seafast.output.style import MODEL_LINES, legend_outside, plain_tick_labels, save_png, scaled_unit

__all__ = [
    "plot_deflection",
    "plot_forces_and_moments",
    "plot_saddle_time_histories",
    "plot_saddle_surfaces",
    "plot_aft_picture",
    "plot_hull_girder",
    "plot_raos",
    "plot_stick_slip",
]

_MODELS = ("nonlinear", "linear")  # drawing order: the thin dashed linear line on top
DPI = 200


def _save(fig: plt.Figure, path: Path) -> Path:
    return save_png(fig, path, DPI)


def plot_deflection(ds: xr.Dataset, path: Path) -> Path:
    """Ship deck, saddles and cargo deflection (static and dynamic envelope)."""
    has_hull = "hull_x_m" in ds.coords
    fig, axes = plt.subplots(2 if has_hull else 1, 1, figsize=(12, 7.5 if has_hull else 4), squeeze=False)
    axes = axes[:, 0]
    ax_c = axes[-1]
    aft = float(ds.attrs.get("cargo_aft_end_x_m", 0.0))
    if has_hull:
        ax = axes[0]
        x = ds["hull_x_m"].values
        sw = ds["hull_still_water_deflection_m"].values * 1e3
        one_way = ", one-way" if "hull_still_water_deflection_coupled_m" in ds else ""
        ax.plot(x, sw, "k", label=f"still water{one_way}")
        if "hull_wave_deflection_m" in ds:
            w = ds["hull_wave_deflection_m"].values * 1e3
            ax.fill_between(x, sw + w.min(axis=0), sw + w.max(axis=0), color="0.8", label=f"still water + wave (envelope){one_way}")
        xs = aft + ds["saddle_x_m"].values
        ax.plot(xs, np.interp(xs, x, sw), "v", color="tab:green", ms=9, label="saddles")
        if "hull_still_water_deflection_coupled_m" in ds:
            ax.plot(
                x, ds["hull_still_water_deflection_coupled_m"].values * 1e3, "--", color="tab:purple", label="still water, two-way coupled"
            )
        if ds.attrs.get("hull_cargo_coupling") and "deck_deflection_m" in ds:
            # where the coupled deck the cargo stood on sits in still water
            coupled_deck = ds["deck_deflection_m"].sel(load_case="static")  # under the nonlinear model's cargo
            ax.plot(
                xs,
                coupled_deck.isel(period_fraction=0).values * 1e3,
                "o",
                mfc="none",
                color="tab:purple",
                ms=9,
                label="deck under the saddles, two-way coupled (still water)",
            )
        ax.axvspan(aft, aft + float(ds["x_cargo_m"].max()), color="tab:orange", alpha=0.15, label="cargo")
        ax.set_xlabel("x along the ship from the aft perpendicular [m]")
        ax.set_ylabel("hull deflection [mm]")
        ax.set_title(
            "Hull deflection (relative to the chord through the ship's ends)"
            + ("; black and grey: one-way" if ds.attrs.get("hull_cargo_coupling") else "")
        )
        legend_outside(ax)
        ax.grid(alpha=0.3)
    xc = ds["x_cargo_m"].values
    for mdl in _MODELS:
        style = MODEL_LINES[mdl]
        st = ds["cargo_deflection_m"].sel(load_case="static", model=mdl).isel(period_fraction=0).values * 1e3
        ax_c.plot(xc, st, **style, label=f"{mdl}, static")
        dyn = ds["cargo_deflection_m"].sel(load_case="dynamic", model=mdl).values * 1e3
        _envelope(ax_c, xc, dyn, mdl)
    deck = ds["deck_rise_m"].sel(load_case="static").isel(period_fraction=0).values * 1e3
    ax_c.plot(ds["saddle_x_m"].values, deck, "^", color="tab:green", ms=9, zorder=4, label="deck under saddles (static)")
    ax_c.set_xlabel("x along the cargo from its aft end [m]")
    ax_c.set_ylabel("deflection [mm]")
    ax_c.set_title("Cargo deflection relative to the sea-fastening baseline\n(deck line through the outer saddles)")
    legend_outside(ax_c)
    ax_c.grid(alpha=0.3)
    return _save(fig, path)


def _envelope(ax: plt.Axes, x: np.ndarray, values: np.ndarray, model: str) -> None:
    """The min-max envelope over the period of one model: a light fill with its edges in the model's line style."""
    style = MODEL_LINES[model]
    lo, hi = values.min(axis=0), values.max(axis=0)
    ax.fill_between(x, lo, hi, color=style["color"], alpha=0.12, lw=0, label=f"{model}, dynamic envelope")
    for edge in (lo, hi):
        ax.plot(x, edge, color=style["color"], ls=style["ls"], lw=0.9, zorder=style["zorder"])


def plot_forces_and_moments(ds: xr.Dataset, path: Path) -> Path:
    """Saddle forces (static and dynamic range) and bending-moment lines along the cargo."""
    fig, (ax_f, ax_m) = plt.subplots(2, 1, figsize=(12, 7.5))
    xs = ds["saddle_x_m"].values
    width = 0.015 * float(ds["x_cargo_m"].max())
    for i, mdl in enumerate(("linear", "nonlinear")):
        c = MODEL_LINES[mdl]["color"]
        off = (i - 0.5) * width
        st = ds["saddle_force_N"].sel(load_case="static", model=mdl).isel(period_fraction=0).values / 1e6
        dyn = ds["saddle_force_N"].sel(load_case="dynamic", model=mdl).values / 1e6
        ax_f.bar(xs + off, st, width=width, color=c, alpha=0.6, label=f"{mdl}, static")
        ax_f.errorbar(
            xs + off, st, yerr=[st - dyn.min(axis=0), dyn.max(axis=0) - st], fmt="none", ecolor=c, capsize=4, label=f"{mdl}, dynamic range"
        )
    ax_f.axhline(0.0, color="k", lw=0.8)
    ax_f.set_xlabel("saddle position along the cargo [m]")
    ax_f.set_ylabel("saddle force [MN]")
    ax_f.set_title("Saddle normal forces (negative = tension, impossible for a real saddle)")
    legend_outside(ax_f)
    ax_f.grid(alpha=0.3)
    xm = ds["x_moment_m"].values
    for mdl in _MODELS:
        st = ds["bending_moment_Nm"].sel(load_case="static", model=mdl).isel(period_fraction=0).values / 1e6
        dyn = ds["bending_moment_Nm"].sel(load_case="dynamic", model=mdl).values / 1e6
        ax_m.plot(xm, st, **MODEL_LINES[mdl], label=f"{mdl}, static")
        _envelope(ax_m, xm, dyn, mdl)
    for x in xs:
        ax_m.axvline(x, color="tab:green", lw=0.8, ls=":")
    ax_m.set_xlabel("x along the cargo from its aft end [m]")
    ax_m.set_ylabel("bending moment [MN m] (sagging +)")
    ax_m.set_title("Cargo bending moment (dotted green: saddles)")
    legend_outside(ax_m)
    ax_m.grid(alpha=0.3)
    return _save(fig, path)


def plot_saddle_time_histories(ds: xr.Dataset, path: Path) -> Path:
    """Force and compression/gap of every saddle over one period, linear vs nonlinear."""
    n = ds.sizes["saddle"]
    fig, axes = plt.subplots(2, n, figsize=(3.2 * n + 2.2, 5.5), squeeze=False, sharex=True)
    s = ds["period_fraction"].values
    for j in range(n):
        for mdl in _MODELS:
            sel = ds.sel(load_case="dynamic", model=mdl, saddle=j)
            axes[0, j].plot(s, sel["saddle_force_N"].values / 1e6, **MODEL_LINES[mdl], label=mdl)
            axes[1, j].plot(s, sel["saddle_compression_m"].values * 1e3, **MODEL_LINES[mdl], label=mdl)
        axes[0, j].set_title(f"saddle {j} at x = {float(ds['saddle_x_m'][j]):.1f} m")
        axes[1, j].axhline(0.0, color="k", lw=0.8)
        axes[1, j].set_xlabel("period fraction t/T [-]")
        for ax in axes[:, j]:
            ax.grid(alpha=0.3)
    axes[0, 0].set_ylabel("saddle force [MN]")
    axes[1, 0].set_ylabel("compression [mm] (negative = gap)")
    legend_outside(axes[0, -1])
    return _save(fig, path)


def plot_saddle_surfaces(ds: xr.Dataset, path: Path) -> Path:
    """Nonlinear saddle force and compression over saddle x period fraction, as heat maps.

    One column per saddle (what is computed; nothing is interpolated between saddles), the
    period fraction upwards, colour bars in MN and mm; the compression's colour scale is centred
    on 0 (red: gap, the saddle lifted off). The file keeps its name, ``saddle_surfaces.png``.
    """
    from matplotlib.colors import TwoSlopeNorm

    sel = ds.sel(load_case="dynamic", model="nonlinear")
    s = ds["period_fraction"].values
    n = ds.sizes["saddle"]
    step = float(np.diff(s).mean()) if s.size > 1 else 1.0
    s_edges = np.concatenate([s - step / 2, [s[-1] + step / 2]])
    j_edges = np.arange(n + 1) - 0.5
    fig, axes = plt.subplots(1, 2, figsize=(12, 5))
    panels = (
        ("saddle_force_N", 1e-6, "saddle force [MN]", "viridis", False),
        ("saddle_compression_m", 1e3, "compression [mm] (negative = gap)", "RdBu", True),
    )
    for ax, (var, scale, label, cmap, centred) in zip(axes, panels, strict=True):
        z = sel[var].transpose("period_fraction", "saddle").values * scale
        norm = None
        if centred:
            reach = max(float(np.abs(z).max()), 1e-12)
            norm = TwoSlopeNorm(0.0, vmin=min(float(z.min()), -1e-3 * reach), vmax=max(float(z.max()), 1e-3 * reach))
        mesh = ax.pcolormesh(j_edges, s_edges, z, cmap=cmap, norm=norm, shading="flat")
        fig.colorbar(mesh, ax=ax, label=label)
        ax.set_xticks(range(n), [f"{j}\nx = {float(ds['saddle_x_m'][j]):.1f} m" for j in range(n)])
        ax.set_xlabel("saddle [-] (x along the cargo)")
        ax.set_ylabel("period fraction t/T [-]")
        ax.set_title(f"nonlinear {label.split(' [')[0]}, dynamic")
    return _save(fig, path)


def plot_aft_picture(ds: xr.Dataset, path: Path) -> Path:
    """The AFT picture for the most loaded saddle: compression, time-domain force, H-harmonic force."""
    sel = ds.sel(load_case="dynamic", model="nonlinear")
    j = int(np.argmax(sel["saddle_force_N"].max("period_fraction").values))
    s = sel["period_fraction"].values
    comp = sel["saddle_compression_m"].isel(saddle=j).values
    force = sel["saddle_force_N"].isel(saddle=j).values
    H = int(ds.attrs.get("harmonics", 5))
    recon = harmonics_up_to(force, H)
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(11, 6), sharex=True)
    ax1.plot(s, comp * 1e3, "k.-", ms=3)
    ax1.axhline(0.0, color="0.5", lw=0.8)
    ax1.set_ylabel("compression delta(t) [mm]")
    ax1.set_title(f"AFT, saddle {j} (x = {float(ds['saddle_x_m'][j]):.1f} m): harmonics -> time samples -> contact law -> harmonics")
    ax2.plot(s, recon / 1e6, "-", color="tab:blue", lw=3, alpha=0.45, zorder=2, label=f"reconstruction from H = {H} harmonics")
    ax2.plot(s, force / 1e6, ".", color="tab:red", ms=2.5, zorder=3, label=f"contact force f(delta(t_n)) at the {s.size} time samples")
    ax2.set_xlabel("period fraction t/T [-]")
    ax2.set_ylabel("saddle force [MN]")
    legend_outside(ax2)
    for ax in (ax1, ax2):
        ax.grid(alpha=0.3)
    return _save(fig, path)


def _hull_lines(ds: xr.Dataset, suffix: str) -> dict[str, np.ndarray] | None:
    """Still-water and hog/sag hull lines [mm, MN m] of one coupling (``suffix`` "" or "_coupled")."""
    names = {
        k: f"hull_{k}{suffix}_{u}"
        for k, u in (
            ("still_water_deflection", "m"),
            ("still_water_bending_moment", "Nm"),
            ("wave_deflection", "m"),
            ("wave_bending_moment", "Nm"),
        )
    }
    if names["still_water_deflection"] not in ds or names["still_water_bending_moment"] not in ds:
        return None
    x = ds["hull_x_m"].values
    sw, swm = ds[names["still_water_deflection"]].values, ds[names["still_water_bending_moment"]].values
    out = {"sw_mm": sw * 1e3, "sw_MNm": swm / 1e6}
    if names["wave_deflection"] in ds and names["wave_bending_moment"] in ds:
        w, m = ds[names["wave_deflection"]].values, ds[names["wave_bending_moment"]].values
        mid = np.argmin(np.abs(x - 0.5 * x[-1]))
        i_hog, i_sag = int(np.argmin(m[:, mid])), int(np.argmax(m[:, mid]))
        out.update(
            hog_mm=(sw + w[i_hog]) * 1e3, sag_mm=(sw + w[i_sag]) * 1e3, hog_MNm=(swm + m[i_hog]) / 1e6, sag_MNm=(swm + m[i_sag]) / 1e6
        )
    return out


def plot_hull_girder(ds: xr.Dataset, path: Path) -> Path:
    """Hull deflection (still water, hog, sag) and hull bending moment along the ship.

    After a two-way run both hulls are drawn, labelled: one-way (the cargo as a spread weight,
    solid) and two-way coupled (dashed).
    """
    x = ds["hull_x_m"].values
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(12, 7.5), sharex=True)
    coupled = _hull_lines(ds, "_coupled")
    variants = [("", "-", " (one-way)" if coupled else "")]
    if coupled:
        variants.append(("_coupled", "--", " (two-way coupled)"))
    for suffix, style, tag in variants:
        lines = _hull_lines(ds, suffix)
        if lines is None:
            continue
        ax1.plot(x, lines["sw_mm"], "k", ls=style, label=f"still water{tag}")
        ax2.plot(x, lines["sw_MNm"], "k", ls=style, label=f"still water{tag}")
        if "hog_mm" in lines:
            ax1.plot(x, lines["hog_mm"], "tab:red", ls=style, label=f"hog (crest amidships){tag}")
            ax1.plot(x, lines["sag_mm"], "tab:blue", ls=style, label=f"sag (trough amidships){tag}")
            ax2.plot(x, lines["hog_MNm"], "tab:red", ls=style, label=f"hog{tag}")
            ax2.plot(x, lines["sag_MNm"], "tab:blue", ls=style, label=f"sag{tag}")
    aft = float(ds.attrs.get("cargo_aft_end_x_m", np.nan))
    if np.isfinite(aft):
        for ax in (ax1, ax2):
            ax.axvspan(aft, aft + float(ds["x_cargo_m"].max()), color="tab:orange", alpha=0.15)
    ax1.set_ylabel("hull deflection [mm]")
    ax2.set_ylabel("hull bending moment [MN m] (sagging +)")
    ax2.set_xlabel("x along the ship from the aft perpendicular [m]")
    for ax in (ax1, ax2):
        legend_outside(ax, fontsize=7 if coupled else 8)
        ax.grid(alpha=0.3)
    ax1.set_title("Hull girder: one-way (solid) and two-way coupled (dashed)" if coupled else "Hull girder")
    return _save(fig, path)


def plot_raos(ds: xr.Dataset, path: Path) -> Path:
    """Heave, pitch (and surge, when present) RAOs in head seas, or heave, roll and pitch at the case's heading (amplitude and
    phase), the case's wave frequency marked."""
    w = ds["rao_omega_rad_s"].values
    dofs, curves, where = rao_curves(ds)
    fig, axes = plt.subplots(2, len(dofs), figsize=(4.5 * len(dofs), 6.4), sharex=True, squeeze=False)
    omega = float(ds.attrs.get("wave_frequency_rad_s", np.nan))
    for col, (name, scale, unit) in enumerate(dofs):
        z = curves[name]
        axes[0, col].plot(w, np.abs(z) * scale, "k.-")
        axes[0, col].set_ylabel(f"{name} RAO [{unit}]")
        axes[1, col].plot(w, np.degrees(np.angle(z)), "k.-")
        axes[1, col].set_ylabel(f"{name} phase [deg]")
        axes[1, col].set_xlabel("wave frequency [rad/s]")
        for ax in axes[:, col]:
            if np.isfinite(omega):
                ax.axvline(omega, color="tab:red", ls=":")
            ax.grid(alpha=0.3)
    titles = {
        "surge": f"Surge (forward positive, {where})",
        "heave": f"Heave ({where})",
        "pitch": f"Pitch (bow up positive, {where})",
        "roll": f"Roll (starboard down positive, {where})",
    }
    for col, (name, _, _) in enumerate(dofs):
        axes[0, col].set_title(titles[name])
    if np.isfinite(omega):  # said once, above the panels: no label inside an axes can cover a title or data
        fig.suptitle(f"Rigid-body motion RAOs; red dotted: the case's wave, {omega:.3f} rad/s", fontsize=11)
    return _save(fig, path)


def plot_stick_slip(ds: xr.Dataset, path: Path) -> Path:
    """Axial stick-slip over one period: displacement, friction against its capacity, sliding phases.

    The displacement axis takes the unit that suits the data (mm, or µm while the cargo sticks:
    the elastic creep of a stuck cargo is a fraction of a micrometre), with plain-number ticks.
    """
    s = ds["period_fraction"].values
    fig, (ax_u, ax_f) = plt.subplots(2, 1, figsize=(12, 7), sharex=True)
    u_factor, u_unit = scaled_unit(ds["axial_displacement_m"].sel(load_case="dynamic").values.ravel(), "m")
    for mdl in _MODELS:
        sel = ds.sel(load_case="dynamic", model=mdl)
        style = MODEL_LINES[mdl]
        slip = float(sel["slip_m"])
        ax_u.plot(s, sel["axial_displacement_m"].values * u_factor, **style, label=f"{mdl}: slip {slip * 1e3:.3g} mm per period")
        ax_f.plot(s, -sel["friction_force_N"].values / 1e6, **style, label=f"{mdl}: friction force (resisting u)")
        cap = sel["friction_capacity_N"].values / 1e6
        ax_f.plot(s, cap, color=style["color"], ls=":", lw=1.0, zorder=1, label=f"{mdl}: friction available (±)")
        ax_f.plot(s, -cap, color=style["color"], ls=":", lw=1.0, zorder=1)
        sliding = sel["sliding"].values.astype(bool)
        if sliding.any():
            ax_u.fill_between(s, 0, 1, where=sliding, transform=ax_u.get_xaxis_transform(), color=style["color"], alpha=0.08, lw=0)
    load = ds["axial_load_N"].sel(load_case="dynamic", model="nonlinear").values / 1e6
    # where the cargo sticks the friction equals the load: the load as a thin line on top of both
    ax_f.plot(s, load, color="k", lw=0.8, zorder=4, label="axial load F(t) (inertia + gravity)")
    ax_u.axhline(0.0, color="k", lw=0.8)
    ax_u.set_ylabel(f"axial displacement u [{u_unit}] (forward +)")
    ax_u.set_title("Axial stick-slip of the cargo (shaded: sliding)")
    plain_tick_labels(ax_u.yaxis)
    legend_outside(ax_u)
    ax_f.set_xlabel("period fraction t/T [-]")
    ax_f.set_ylabel("axial force [MN] (forward +)")
    plain_tick_labels(ax_f.yaxis)
    legend_outside(ax_f)
    for ax in (ax_u, ax_f):
        ax.grid(alpha=0.3)
    return _save(fig, path)
