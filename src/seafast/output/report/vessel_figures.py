"""Interactive (plotly) figures of a run's vessel side: the hull girder, the rigid-body RAOs, the deck under the saddles.

Every builder is a pure function ``Dataset -> plotly Figure`` (``None`` when the dataset lacks
what the figure needs); :func:`~seafast.output.report.run_figures.run_figures` collects them in
report order.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import xarray as xr

from seafast.output.report.common import attr_float, coord_labels, has_variables, rao_curves, saddle_label, total_load_case
from seafast.output.report.plotly_style import plotly_go, style_figure, subplots

__all__ = ["hull_girder_figure", "rao_figure", "deck_motion_figure"]

_SADDLE_COLORS = ("#2ca02c", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf", "#ff7f0e")


def hull_girder_figure(ds: xr.Dataset) -> Any | None:
    """Hull deflection [mm] (still water, hog, sag, wave envelope) and hull bending moment [MN m].

    Returns ``None`` when the dataset has no hull-girder variables (e.g. a deck-deflection table).
    """
    if "hull_x_m" not in ds.coords or "hull_still_water_deflection_m" not in ds:
        return None
    go = plotly_go()
    x = ds["hull_x_m"].values
    sw = ds["hull_still_water_deflection_m"].values
    has_m = "hull_still_water_bending_moment_Nm" in ds
    coupled = "hull_still_water_deflection_coupled_m" in ds
    tag = ", one-way" if coupled else ""
    fig = subplots(rows=2 if has_m else 1, cols=1, shared_xaxes=True, vertical_spacing=0.08)
    fig.add_trace(go.Scatter(x=x, y=sw * 1e3, name=f"still water{tag}", line=dict(color="black", width=2), legendgroup="sw"), row=1, col=1)
    if "hull_wave_deflection_m" in ds:
        w = ds["hull_wave_deflection_m"].values
        fig.add_trace(go.Scatter(x=x, y=(sw + w.min(axis=0)) * 1e3, line=dict(width=0), showlegend=False, hoverinfo="skip"), row=1, col=1)
        fig.add_trace(
            go.Scatter(
                x=x,
                y=(sw + w.max(axis=0)) * 1e3,
                line=dict(width=0),
                fill="tonexty",
                fillcolor="rgba(128,128,128,0.2)",
                name="still water + wave (envelope)",
                hoverinfo="skip",
            ),
            row=1,
            col=1,
        )
        if has_m and "hull_wave_bending_moment_Nm" in ds:
            m = ds["hull_wave_bending_moment_Nm"].values
            mid = int(np.argmin(np.abs(x - 0.5 * (x[0] + x[-1]))))
            i_hog, i_sag = int(np.argmin(m[:, mid])), int(np.argmax(m[:, mid]))
            swm = ds["hull_still_water_bending_moment_Nm"].values
            for i, name, color in ((i_hog, f"hog (crest amidships){tag}", "#d62728"), (i_sag, f"sag (trough amidships){tag}", "#1f77b4")):
                fig.add_trace(go.Scatter(x=x, y=(sw + w[i]) * 1e3, name=name, legendgroup=name, line=dict(color=color)), row=1, col=1)
                fig.add_trace(
                    go.Scatter(x=x, y=(swm + m[i]) / 1e6, name=name, legendgroup=name, showlegend=False, line=dict(color=color)),
                    row=2,
                    col=1,
                )
    if has_m:
        fig.add_trace(
            go.Scatter(
                x=x,
                y=ds["hull_still_water_bending_moment_Nm"].values / 1e6,
                name="still water",
                legendgroup="sw",
                showlegend=False,
                line=dict(color="black", width=2),
            ),
            row=2,
            col=1,
        )
        fig.update_yaxes(title_text="hull bending moment [MN m] (sagging +)", row=2, col=1)
    if coupled:
        _add_coupled_hull_traces(fig, ds, has_m)
    aft = attr_float(ds, "cargo_aft_end_x_m")
    if math.isfinite(aft) and "x_cargo_m" in ds.coords:
        fore = aft + float(ds["x_cargo_m"].max())
        fig.add_vrect(
            x0=aft, x1=fore, fillcolor="orange", opacity=0.12, line_width=0, annotation_text="cargo", annotation_position="top left"
        )
        if "saddle_x_m" in ds:
            xs = aft + ds["saddle_x_m"].values
            fig.add_trace(
                go.Scatter(
                    x=xs,
                    y=np.interp(xs, x, sw) * 1e3,
                    mode="markers",
                    name="saddles",
                    marker=dict(symbol="triangle-down", size=11, color="#2ca02c"),
                ),
                row=1,
                col=1,
            )
    fig.update_yaxes(title_text="hull deflection [mm] (up +)", row=1, col=1)
    fig.update_xaxes(title_text="x along the ship from the aft perpendicular [m]", row=2 if has_m else 1, col=1)
    return style_figure(fig, "Hull girder: deflection (chord through the ship's ends) and bending moment", 620 if has_m else 380)


def _add_coupled_hull_traces(fig: Any, ds: xr.Dataset, has_m: bool) -> None:
    """The two-way coupled hull (dashed): still water, and hog and sag where the wave fields exist."""
    go = plotly_go()
    x = ds["hull_x_m"].values
    sw = ds["hull_still_water_deflection_coupled_m"].values
    swm = ds["hull_still_water_bending_moment_coupled_Nm"].values if "hull_still_water_bending_moment_coupled_Nm" in ds else None
    lines = [("still water, two-way coupled", "black", sw, swm)]
    if "hull_wave_deflection_coupled_m" in ds and swm is not None and "hull_wave_bending_moment_coupled_Nm" in ds:
        w, m = ds["hull_wave_deflection_coupled_m"].values, ds["hull_wave_bending_moment_coupled_Nm"].values
        mid = int(np.argmin(np.abs(x - 0.5 * (x[0] + x[-1]))))
        i_hog, i_sag = int(np.argmin(m[:, mid])), int(np.argmax(m[:, mid]))
        lines += [
            ("hog, two-way coupled", "#d62728", sw + w[i_hog], swm + m[i_hog]),
            ("sag, two-way coupled", "#1f77b4", sw + w[i_sag], swm + m[i_sag]),
        ]
    for name, color, z, moment in lines:
        style = dict(color=color, dash="dash", width=2 if color == "black" else 1.5)
        fig.add_trace(go.Scatter(x=x, y=z * 1e3, name=name, legendgroup=name, line=style), row=1, col=1)
        if has_m and moment is not None:
            fig.add_trace(go.Scatter(x=x, y=moment / 1e6, name=name, legendgroup=name, showlegend=False, line=style), row=2, col=1)


def rao_figure(ds: xr.Dataset) -> Any | None:
    """Heave [m/m] and pitch [deg/m] RAOs, amplitude and phase [deg], wave frequency marked.

    Returns ``None`` without RAOs (``vessel.motions: none``).
    """
    head = has_variables(ds, "heave_rao_real", "heave_rao_imag", "pitch_rao_real", "pitch_rao_imag")
    if "rao_omega_rad_s" not in ds.coords or not (head or has_variables(ds, "roll_rao6_real", "roll_rao6_imag")):
        return None
    go = plotly_go()
    w = ds["rao_omega_rad_s"].values
    dofs, curves, where = rao_curves(ds)
    extra = {"pitch": " (bow up +)", "surge": " (forward +)", "roll": " (starboard down +)"}
    fig = subplots(
        rows=2,
        cols=len(dofs),
        shared_xaxes=True,
        vertical_spacing=0.1,
        horizontal_spacing=0.08,
        subplot_titles=[f"{n} amplitude{extra.get(n, '')}" for n, _, _ in dofs] + [f"{n} phase" for n, _, _ in dofs],
    )
    for col, (name, scale, unit) in enumerate(dofs, start=1):
        z = curves[name]
        fig.add_trace(
            go.Scatter(
                x=w,
                y=np.abs(z) * scale,
                mode="lines+markers",
                name=f"{name} amplitude",
                line=dict(color="black"),
                hovertemplate=f"omega %{{x:.3f}} rad/s<br>%{{y:.4g}} {unit}<extra></extra>",
                showlegend=False,
            ),
            row=1,
            col=col,
        )
        fig.add_trace(
            go.Scatter(
                x=w,
                y=np.degrees(np.angle(z)),
                mode="lines+markers",
                name=f"{name} phase",
                line=dict(color="gray"),
                hovertemplate="omega %{x:.3f} rad/s<br>%{y:.1f} deg<extra></extra>",
                showlegend=False,
            ),
            row=2,
            col=col,
        )
        fig.update_yaxes(title_text=f"{name} RAO [{unit}]", row=1, col=col)
        fig.update_yaxes(title_text=f"{name} phase [deg]", row=2, col=col)
        fig.update_xaxes(title_text="wave frequency [rad/s]", row=2, col=col)
    omega = attr_float(ds, "wave_frequency_rad_s")
    if math.isfinite(omega):
        for r in (1, 2):
            for c in range(1, len(dofs) + 1):
                fig.add_vline(x=omega, line=dict(color="#d62728", dash="dot"), row=r, col=c)
        # named in the legend (beside the plot), not by a label that would sit on a subplot title
        fig.add_trace(
            go.Scatter(
                x=[None], y=[None], mode="lines", line=dict(color="#d62728", dash="dot"), name=f"the case's wave, {omega:.3f} rad/s"
            ),
            row=1,
            col=1,
        )
    names = " and ".join(n for n, _, _ in dofs) if len(dofs) == 2 else ", ".join(n for n, _, _ in dofs[:-1]) + f" and {dofs[-1][0]}"
    return style_figure(fig, f"Rigid-body motions: {names} RAOs ({where})", 560)


def deck_motion_figure(ds: xr.Dataset) -> Any | None:
    """Deck deflection under each saddle over one wave period [mm] (the cargo's excitation)."""
    if "deck_deflection_m" not in ds:
        return None
    go = plotly_go()
    fig = go.Figure()
    s = ds["period_fraction"].values
    deck = ds["deck_deflection_m"]
    lc = total_load_case(ds)
    for j in range(ds.sizes["saddle"]):
        color = _SADDLE_COLORS[j % len(_SADDLE_COLORS)]
        fig.add_trace(
            go.Scatter(
                x=s,
                y=deck.sel(load_case=lc).isel(saddle=j).values * 1e3,
                name=saddle_label(ds, j),
                line=dict(color=color),
                hovertemplate="t/T %{x:.3f}<br>%{y:.2f} mm<extra></extra>",
            )
        )
        if "static" in coord_labels(ds["load_case"]):
            fig.add_trace(
                go.Scatter(
                    x=s,
                    y=deck.sel(load_case="static").isel(saddle=j).values * 1e3,
                    name=f"still water, saddle {j}",
                    line=dict(color=color, dash="dot"),
                    showlegend=j == 0,
                    legendgroup="sw",
                    hoverinfo="skip",
                )
            )
    fig.update_xaxes(title_text="period fraction t/T [-]")
    fig.update_yaxes(title_text="deck deflection under the saddle [mm] (up +)")
    return style_figure(fig, "Excitation: deck deflection under the saddles over one wave period", 440)
