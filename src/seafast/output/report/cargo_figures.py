"""Interactive (plotly) figures of a run's cargo response: saddle histories, deflection and moment lines, contact states.

Linear and nonlinear models side by side. Every builder is a pure function
``Dataset -> plotly Figure``; :func:`~seafast.output.report.run_figures.run_figures` collects
them in report order.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import xarray as xr

from seafast.output.report.common import coord_labels, saddle_label, total_load_case
from seafast.output.report.plotly_style import model_line, model_order, plotly_go, style_figure, subplots

__all__ = ["saddle_time_history_figure", "deflection_moment_figure", "contact_timeline_figure"]

_FILL = {"linear": "rgba(31,119,180,0.18)", "nonlinear": "rgba(214,39,40,0.18)"}


def saddle_time_history_figure(ds: xr.Dataset) -> Any:
    """Force [MN] and compression [mm] (negative = gap) of every saddle over one period, linear vs nonlinear."""
    go = plotly_go()
    n = ds.sizes["saddle"]
    fig = subplots(
        rows=2,
        cols=n,
        shared_xaxes=True,
        shared_yaxes="rows",
        vertical_spacing=0.1,
        horizontal_spacing=0.03,
        subplot_titles=[saddle_label(ds, j) for j in range(n)],
    )
    s = ds["period_fraction"].values
    lc = total_load_case(ds)
    for j in range(n):
        for m in model_order(coord_labels(ds["model"])):
            sel = ds.sel(load_case=lc, model=m).isel(saddle=j)
            fig.add_trace(
                go.Scatter(
                    x=s,
                    y=sel["saddle_force_N"].values / 1e6,
                    name=m,
                    legendgroup=m,
                    showlegend=j == 0,
                    line=model_line(m),
                    hovertemplate=f"{m}<br>t/T %{{x:.3f}}<br>F %{{y:.3f}} MN<extra></extra>",
                ),
                row=1,
                col=j + 1,
            )
            fig.add_trace(
                go.Scatter(
                    x=s,
                    y=sel["saddle_compression_m"].values * 1e3,
                    name=m,
                    legendgroup=m,
                    showlegend=False,
                    line=model_line(m),
                    hovertemplate=f"{m}<br>t/T %{{x:.3f}}<br>compression %{{y:.2f}} mm<extra></extra>",
                ),
                row=2,
                col=j + 1,
            )
        fig.add_hline(y=0.0, line=dict(color="black", width=1), row=2, col=j + 1)
        fig.add_hline(y=0.0, line=dict(color="black", width=1), row=1, col=j + 1)
        fig.update_xaxes(title_text="t/T [-]", row=2, col=j + 1)
    fig.update_yaxes(title_text="saddle force [MN]", row=1, col=1)
    fig.update_yaxes(title_text="compression [mm] (negative = gap)", row=2, col=1)
    return style_figure(fig, f"Saddle force and compression/gap over one wave period ({lc}, total response)", 600)


def _envelope(fig: Any, x: np.ndarray, lo: np.ndarray, hi: np.ndarray, model: str, row: int, show: bool, unit: str) -> None:
    go = plotly_go()
    fig.add_trace(
        go.Scatter(
            x=x,
            y=lo,
            line=dict(model_line(model), width=0.8),
            legendgroup=f"{model}-env",
            showlegend=False,
            hovertemplate=f"{model} dynamic min<br>x %{{x:.1f}} m<br>%{{y:.2f}} {unit}<extra></extra>",
        ),
        row=row,
        col=1,
    )
    fig.add_trace(
        go.Scatter(
            x=x,
            y=hi,
            line=dict(model_line(model), width=0.8),
            fill="tonexty",
            fillcolor=_FILL.get(model, "rgba(0,0,0,0.1)"),
            name=f"{model}, dynamic envelope",
            legendgroup=f"{model}-env",
            showlegend=show,
            hovertemplate=f"{model} dynamic max<br>x %{{x:.1f}} m<br>%{{y:.2f}} {unit}<extra></extra>",
        ),
        row=row,
        col=1,
    )


def deflection_moment_figure(ds: xr.Dataset) -> Any:
    """Cargo deflection [mm] and bending moment [MN m] along the cargo: static lines and dynamic envelopes."""
    go = plotly_go()
    fig = subplots(rows=2, cols=1, shared_xaxes=True, vertical_spacing=0.08)
    lcs = coord_labels(ds["load_case"])
    xc, xm = ds["x_cargo_m"].values, ds["x_moment_m"].values
    for m in model_order(coord_labels(ds["model"])):
        if "dynamic" in lcs:
            d = ds["cargo_deflection_m"].sel(load_case="dynamic", model=m).values * 1e3
            _envelope(fig, xc, d.min(axis=0), d.max(axis=0), m, 1, True, "mm")
            mo = ds["bending_moment_Nm"].sel(load_case="dynamic", model=m).values / 1e6
            _envelope(fig, xm, mo.min(axis=0), mo.max(axis=0), m, 2, False, "MN m")
        if "static" in lcs:
            st = ds["cargo_deflection_m"].sel(load_case="static", model=m).isel(period_fraction=0).values * 1e3
            fig.add_trace(
                go.Scatter(
                    x=xc,
                    y=st,
                    name=f"{m}, static",
                    legendgroup=f"{m}-st",
                    line=model_line(m),
                    hovertemplate=f"{m} static<br>x %{{x:.1f}} m<br>%{{y:.2f}} mm<extra></extra>",
                ),
                row=1,
                col=1,
            )
            sm = ds["bending_moment_Nm"].sel(load_case="static", model=m).isel(period_fraction=0).values / 1e6
            fig.add_trace(
                go.Scatter(
                    x=xm,
                    y=sm,
                    name=f"{m}, static",
                    legendgroup=f"{m}-st",
                    showlegend=False,
                    line=model_line(m),
                    hovertemplate=f"{m} static<br>x %{{x:.1f}} m<br>%{{y:.2f}} MN m<extra></extra>",
                ),
                row=2,
                col=1,
            )
    if "saddle_x_m" in ds:
        for x in ds["saddle_x_m"].values:
            fig.add_vline(x=float(x), line=dict(color="#2ca02c", dash="dot", width=1))
        fig.add_trace(
            go.Scatter(
                x=ds["saddle_x_m"].values,
                y=np.zeros(ds.sizes["saddle"]),
                mode="markers",
                name="saddles",
                marker=dict(symbol="triangle-up", size=11, color="#2ca02c"),
                text=[saddle_label(ds, j) for j in range(ds.sizes["saddle"])],
                hovertemplate="%{text}<extra></extra>",
            ),
            row=1,
            col=1,
        )
    fig.update_yaxes(title_text="cargo deflection [mm] (up +)", row=1, col=1)
    fig.update_yaxes(title_text="bending moment [MN m] (sagging +)", row=2, col=1)
    fig.update_xaxes(title_text="x along the cargo from its aft end [m]", row=2, col=1)
    return style_figure(
        fig, "Cargo deflection (relative to the sea-fastening baseline) and bending moment: static and dynamic envelope", 700
    )


def contact_timeline_figure(ds: xr.Dataset) -> Any:
    """Contact state (saddle x period) of the dynamic response, one heatmap per model.

    For the linear (bilateral) model "detached" marks where the saddle would need tension.
    """
    go = plotly_go()
    models = coord_labels(ds["model"])
    lc = total_load_case(ds)
    fig = subplots(
        rows=len(models),
        cols=1,
        shared_xaxes=True,
        vertical_spacing=0.12,
        subplot_titles=[f"{m} model" + (" (detached = would need tension)" if m == "linear" else "") for m in models],
    )
    s = ds["period_fraction"].values
    ylabels = [saddle_label(ds, j) for j in range(ds.sizes["saddle"])]
    for i, m in enumerate(models, start=1):
        sel = ds.sel(load_case=lc, model=m)
        z = (sel["saddle_compression_m"].values > 0).astype(int).T if "saddle_compression_m" in sel else sel["contact_state"].values.T
        comp = sel["saddle_compression_m"].values.T * 1e3
        fig.add_trace(
            go.Heatmap(
                x=s,
                y=ylabels,
                z=z,
                zmin=0,
                zmax=1,
                colorscale=[[0, "#fdae61"], [0.5, "#fdae61"], [0.5, "#1a9850"], [1, "#1a9850"]],
                showscale=i == 1,
                customdata=comp,
                colorbar=dict(tickvals=[0.25, 0.75], ticktext=["detached", "in contact"], len=0.5, y=0.75, thickness=14),
                hovertemplate="%{y}<br>t/T %{x:.3f}<br>compression %{customdata:.2f} mm<extra></extra>",
                xgap=0,
                ygap=2,
            ),
            row=i,
            col=1,
        )
        fig.update_yaxes(title_text="saddle", autorange="reversed", row=i, col=1)
    fig.update_xaxes(title_text="period fraction t/T [-]", row=len(models), col=1)
    return style_figure(fig, f"Contact state over one wave period ({lc})", 200 + 70 * ds.sizes["saddle"] * len(models))
