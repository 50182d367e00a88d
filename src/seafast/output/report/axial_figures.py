"""Interactive (plotly) figure of a run's axial analysis: stick-slip of the cargo on its saddles over one period.

Present only when the case sets ``seafastening.friction_coefficient``;
:func:`~seafast.output.report.run_figures.run_figures` places it last.
"""

from __future__ import annotations

from typing import Any

import xarray as xr

from seafast.output.report.plotly_style import model_line, model_order, plotly_go, style_figure, subplots
from seafast.output.style import scaled_unit

__all__ = ["stick_slip_figure"]


def stick_slip_figure(ds: xr.Dataset) -> Any | None:
    """Axial stick-slip over one period: displacement (mm, or µm while the cargo sticks) and friction against its capacity [MN].

    Returns ``None`` without the axial analysis (``seafastening.friction_coefficient`` not set).
    """
    if "friction_force_N" not in ds:
        return None
    go = plotly_go()
    lc = "dynamic" if "dynamic" in [str(v) for v in ds["load_case"].values] else str(ds["load_case"].values[-1])
    models = model_order([str(v) for v in ds["model"].values])
    s = ds["period_fraction"].values
    u_factor, u_unit = scaled_unit(ds["axial_displacement_m"].sel(load_case=lc).values.ravel(), "m")
    fig = subplots(rows=2, cols=1, shared_xaxes=True, vertical_spacing=0.08)
    for m in models:
        sel = ds.sel(load_case=lc, model=m)
        line = model_line(m)
        fig.add_trace(
            go.Scatter(
                x=s,
                y=sel["axial_displacement_m"].values * u_factor,
                name=f"{m}: slip {float(sel['slip_m']) * 1e3:.3g} mm per period",
                line=line,
                hovertemplate=f"{m}<br>t/T %{{x:.3f}}<br>u %{{y:.3g}} {u_unit}<extra></extra>",
            ),
            row=1,
            col=1,
        )
        fig.add_trace(
            go.Scatter(
                x=s,
                y=-sel["friction_force_N"].values / 1e6,
                name=f"{m}: friction (resisting u)",
                line=line,
                hovertemplate=f"{m}<br>t/T %{{x:.3f}}<br>%{{y:.3f}} MN<extra></extra>",
            ),
            row=2,
            col=1,
        )
        cap = sel["friction_capacity_N"].values / 1e6
        for sign, show in ((1, True), (-1, False)):
            fig.add_trace(
                go.Scatter(
                    x=s,
                    y=sign * cap,
                    name=f"{m}: friction available (±)",
                    legendgroup=f"{m}-cap",
                    showlegend=show,
                    line=dict(color=line["color"], dash="dot", width=1),
                    hoverinfo="skip",
                ),
                row=2,
                col=1,
            )
    # while the cargo sticks the friction equals the load: the load thin, on top of both
    fig.add_trace(
        go.Scatter(
            x=s,
            y=ds["axial_load_N"].sel(load_case=lc, model=models[0]).values / 1e6,
            name="axial load F(t)",
            line=dict(color="black", width=1),
            hovertemplate="t/T %{x:.3f}<br>F %{y:.3f} MN<extra></extra>",
        ),
        row=2,
        col=1,
    )
    fig.update_yaxes(title_text=f"axial displacement u [{u_unit}] (forward +)", row=1, col=1)
    fig.update_yaxes(title_text="axial force [MN] (forward +)", row=2, col=1)
    fig.update_xaxes(title_text="period fraction t/T [-]", row=2, col=1)
    return style_figure(fig, f"Axial stick-slip over one wave period ({lc})", 620)
