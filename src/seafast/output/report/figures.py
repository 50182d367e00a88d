"""Interactive (plotly) figures of a run, and the plotly styling shared with the study figures.

Every builder is a pure function ``Dataset -> plotly Figure`` (``None`` when the dataset lacks
what the figure needs); :func:`run_figures` collects them in report order.

Size: over 400 lines as ruff formats it (one keyword argument a line in a call that does not fit on
one line; about 340 lines before): the plotly calls carry many style keywords; each figure is a
short function of the dataset, and they share the styling above.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import xarray as xr

from seafast.output.report.common import ReportFigure, attr_float, coord_labels, has_variables, saddle_label, total_load_case
from seafast.output.style import scaled_unit

__all__ = [
    "hull_girder_figure",
    "rao_figure",
    "deck_motion_figure",
    "saddle_time_history_figure",
    "deflection_moment_figure",
    "contact_timeline_figure",
    "stick_slip_figure",
    "run_figures",
    "MODEL_COLORS",
    "model_line",
    "model_order",
    "plotly_go",
    "subplots",
    "style_figure",
]

MODEL_COLORS = {"linear": "#1f77b4", "nonlinear": "#d62728"}
# where the models agree both stay visible: a thick solid nonlinear line under a thin dashed linear one
_MODEL_LINES: dict[str, dict[str, Any]] = {
    "nonlinear": {"color": MODEL_COLORS["nonlinear"], "width": 3.2},
    "linear": {"color": MODEL_COLORS["linear"], "width": 1.6, "dash": "dash"},
}
_FILL = {"linear": "rgba(31,119,180,0.18)", "nonlinear": "rgba(214,39,40,0.18)"}
_SADDLE_COLORS = ("#2ca02c", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf", "#ff7f0e")


# =============================================================================== plotly helpers
def plotly_go() -> Any:
    """``plotly.graph_objects``, imported on first use (plotly is slow to import)."""
    import plotly.graph_objects as go

    return go


def subplots(**kwargs: Any) -> Any:
    """``plotly.subplots.make_subplots(**kwargs)``, imported on first use."""
    from plotly.subplots import make_subplots

    return make_subplots(**kwargs)


def model_line(model: str) -> dict[str, Any]:
    """The plotly ``line`` of a model's trace (:data:`MODEL_COLORS`; linear dashed and thinner)."""
    return dict(_MODEL_LINES.get(model, {"color": "black"}))


def model_order(models: list[str]) -> list[str]:
    """The models in drawing order: nonlinear first, so the thin dashed linear trace lies on top."""
    return sorted(models, key=lambda m: 0 if m == "nonlinear" else 1)


def style_figure(fig: Any, title: str, height: int) -> Any:
    """The report's common layout; ``height`` in pixels.

    The legend stands to the right of the plot area (plotly widens the right margin for it), so
    it covers neither data nor titles; axis ticks never use SI letters ("200µ", "1B"): numbers in
    the unit of the axis title, with a power of ten where one is needed.
    """
    fig.update_layout(
        title=dict(text=title, x=0.01, xanchor="left"),
        height=height,
        template="plotly_white",
        margin=dict(l=70, r=30, t=70, b=60),
        legend=dict(font=dict(size=11), tracegroupgap=2),
        hovermode="closest",
    )
    for each in (fig.for_each_xaxis, fig.for_each_yaxis):  # an axis that chose its own format keeps it
        each(lambda axis: axis.update(exponentformat="power") if axis.exponentformat is None else None)
    return fig


# =============================================================================== run figures
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
    if "rao_omega_rad_s" not in ds.coords or not has_variables(ds, "heave_rao_real", "heave_rao_imag", "pitch_rao_real", "pitch_rao_imag"):
        return None
    go = plotly_go()
    w = ds["rao_omega_rad_s"].values
    dofs = [("heave", 1.0, "m/m"), ("pitch", 180.0 / np.pi, "deg/m")]
    if "surge_rao_real" in ds and "surge_rao_imag" in ds:
        dofs.insert(0, ("surge", 1.0, "m/m"))
    extra = {"pitch": " (bow up +)", "surge": " (forward +)"}
    fig = subplots(
        rows=2,
        cols=len(dofs),
        shared_xaxes=True,
        vertical_spacing=0.1,
        horizontal_spacing=0.08,
        subplot_titles=[f"{n} amplitude{extra.get(n, '')}" for n, _, _ in dofs] + [f"{n} phase" for n, _, _ in dofs],
    )
    for col, (name, scale, unit) in enumerate(dofs, start=1):
        z = ds[f"{name}_rao_real"].values + 1j * ds[f"{name}_rao_imag"].values
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
    names = " and ".join(n for n, _, _ in dofs) if len(dofs) == 2 else "surge, heave and pitch"
    return style_figure(fig, f"Rigid-body motions: {names} RAOs (head seas)", 560)


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


def run_figures(ds: xr.Dataset) -> list[ReportFigure]:
    """Every interactive figure of a run dataset, in report order (vessel first)."""
    out: list[ReportFigure] = []
    for fid, title, builder, caption in (
        (
            "fig-hull-girder",
            "Hull girder",
            hull_girder_figure,
            (
                "Still-water deflection and bending moment of the hull, with the wave's hog and sag extremes; the cargo span is shaded. "
                "After a two-way run, dashed: the hull under the coupled cargo."
            ),
        ),
        (
            "fig-raos",
            "Rigid-body RAOs",
            rao_figure,
            (
                "Amplitude and phase of the rigid-body RAOs (surge when the hydrodynamic data hold it, "
                "heave, pitch); the case's wave frequency is the dotted line."
            ),
        ),
        (
            "fig-deck-motion",
            "Deck deflection under the saddles",
            deck_motion_figure,
            "The prescribed deck displacement at each saddle over one period (solid) and in still water (dotted).",
        ),
        (
            "fig-saddle-histories",
            "Saddle force and gap over the period",
            saddle_time_history_figure,
            (
                "Total (static + wave) response. Negative compression is a gap: the nonlinear saddle lifts off and carries no force; "
                "the linear saddle would pull (negative force)."
            ),
        ),
        (
            "fig-deflection-moment",
            "Deflection and bending-moment lines",
            deflection_moment_figure,
            "Thick lines: still water; shaded bands: range over one wave period of the total response.",
        ),
        ("fig-contact-timeline", "Contact-state timeline", contact_timeline_figure, "Green: saddle in contact; orange: detached."),
        (
            "fig-stick-slip",
            "Axial stick-slip",
            stick_slip_figure,
            (
                "Axial displacement of the cargo relative to the deck, and the friction force against the friction available "
                "(sum of mu N over the saddles, from each model's own contact forces); where the friction reaches it, the cargo slides."
            ),
        ),
    ):
        try:
            fig = builder(ds)
        except KeyError:  # a dataset without the variables the figure needs
            fig = None
        if fig is not None:
            out.append(ReportFigure(fid, title, fig, caption))
    return out
