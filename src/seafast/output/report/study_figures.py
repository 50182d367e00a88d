"""Interactive (plotly) figures of a study: response surfaces or profiles, and the compliance map.

Every builder is a pure function ``Dataset -> plotly Figure`` (``None`` when the study has too
few varying axes); :func:`study_figures` collects them in report order. A study axis is drawn in
the unit that suits its values (a saddle stiffness in GN/m, ticks 0.01 ... 10, never "1B"), one
cell per computed point, the design limits along the cell edges between points within and beyond
them (nothing interpolated between saddle counts).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np
import xarray as xr

from seafast.output.report.common import ReportFigure, base_value, coord_labels, design_limits, study_keys, total_response
from seafast.output.report.plotly_style import model_line, model_order, plotly_go, style_figure, subplots
from seafast.output.style import cell_boundary, scaled_axis_label

__all__ = ["study_surface_figure", "study_profile_figure", "compliance_map_figure", "study_figures"]


# =============================================================================== study axes
def _is_log(sds: xr.Dataset, key: str) -> bool:
    return str(sds[key].attrs.get("scale", "")) == "log"


def _axis(sds: xr.Dataset, key: str) -> tuple[np.ndarray, float, str]:
    """A study axis in its plotting unit: the scaled values, the factor applied, the axis title."""
    values = np.asarray(sds[key].values, dtype=float)
    factor, label = scaled_axis_label(key, values.tolist(), str(sds[key].attrs.get("units", "1")))
    return values * factor, factor, label


def _unit(label: str) -> str:
    return label.rsplit("[", 1)[-1].rstrip("]")


def _edges(values: np.ndarray, log: bool) -> np.ndarray:
    v = np.asarray(values, dtype=float)
    if v.size == 1:
        return np.array([v[0] / 1.5, v[0] * 1.5]) if log else np.array([v[0] - 0.5, v[0] + 0.5])
    t = np.log(v) if log else v
    mid = 0.5 * (t[1:] + t[:-1])
    e = np.concatenate([[t[0] - (mid[0] - t[0])], mid, [t[-1] + (t[-1] - mid[-1])]])
    return np.exp(e) if log else e


def _study_view(sds: xr.Dataset, keep: int) -> tuple[xr.Dataset, list[str], dict[str, Any]]:
    """The study reduced to its first ``keep`` varying axes (others held at the base value).

    Returns the reduced dataset, its varying axis keys (outer first) and the held values.
    """
    keys = study_keys(sds)
    varying = [k for k in keys if sds.sizes[k] > 1]
    held: dict[str, Any] = {}
    view = sds
    for k in keys:
        if k in varying[:keep]:
            continue
        coords = np.asarray(view[k].values)
        base = base_value(view, k)
        idx = (
            int(np.argmin(np.abs(coords.astype(float) - base)))
            if math.isfinite(base) and coords.min() <= base <= coords.max()
            else len(coords) // 2
        )
        held[k] = coords[idx].item()
        view = view.isel({k: idx})
    return view, varying[:keep], held


def _axis_ticks(sds: xr.Dataset, key: str) -> dict[str, Any]:
    """Axis options for a study key: log type, and ticks at the values of a short integer axis."""
    values = np.asarray(sds[key].values)
    if _is_log(sds, key):  # decades only, as plain numbers of the scaled unit (0.01, 0.1, 1, 10)
        return {"type": "log", "dtick": 1, "exponentformat": "none"}
    if values.dtype.kind in "iu" and values.size <= 15:
        return {"type": "linear", "tickmode": "array", "tickvals": _axis(sds, key)[0].tolist()}
    return {"type": "linear"}


def _bottom_legend(fig: Any, height: int) -> Any:
    fig.update_layout(legend=dict(orientation="h", yanchor="top", y=-0.2, xanchor="left", x=0.0), margin=dict(b=110), height=height)
    return fig


def _held_text(held: Mapping[str, Any]) -> str:
    return "" if not held else " (held: " + ", ".join(f"{k} = {v:g}" for k, v in held.items()) + ")"


_STUDY_QUANTITIES: tuple[tuple[str, str, float, str], ...] = (
    ("F_N", "max saddle force F", 1e-6, "MN"),
    ("M_b_Nm", "max bending moment M_b", 1e-6, "MN m"),
    ("sigma_b_Pa", "max bending stress sigma_b", 1e-6, "MPa"),
)


def study_surface_figure(sds: xr.Dataset, model: str = "nonlinear") -> Any | None:
    """Max force [MN], moment [MN m] and stress [MPa] of the total response over the two study axes.

    Heatmaps over the first two varying axes (others held at the base case); circles mark the
    points where contact is preserved at every saddle (nonlinear model: linear theory valid),
    red contour lines the design limits, a star the base case. ``None`` for studies with fewer
    than two varying axes or without ``model``.
    """
    view, axes, held = _study_view(sds, 2)
    if len(axes) < 2 or model not in coord_labels(sds["model"]):
        return None
    go = plotly_go()
    ykey, xkey = axes[0], axes[1]
    total = total_response(view).transpose(ykey, xkey, ...)
    (x, fx, xlabel), (y, fy, ylabel) = _axis(view, xkey), _axis(view, ykey)
    xlog, ylog = _is_log(view, xkey), _is_log(view, ykey)
    xe, ye = _edges(x, xlog), _edges(y, ylog)
    ref_model = "nonlinear" if "nonlinear" in coord_labels(total["model"]) else model
    contact = np.asarray(total["contact_preserved"].sel(model=ref_model).values).astype(bool) if "contact_preserved" in total else None
    lim = design_limits(sds)
    n = len(_STUDY_QUANTITIES)
    fig = subplots(rows=1, cols=n, horizontal_spacing=0.09, subplot_titles=[f"{t} [{u}]" for _, t, _, u in _STUDY_QUANTITIES])
    X, Y = np.meshgrid(x, y)
    for i, (name, title, scale, unit) in enumerate(_STUDY_QUANTITIES, start=1):
        z = np.asarray(total[name].sel(model=model).values, dtype=float) * scale
        dom = fig.layout[f"xaxis{'' if i == 1 else i}"].domain
        fig.add_trace(
            go.Heatmap(
                x=xe,
                y=ye,
                z=z,
                colorscale="Viridis",
                colorbar=dict(x=dom[1] + 0.005, thickness=12, len=0.9, title=dict(text=unit, side="right")),
                hovertemplate=(
                    f"{xkey} %{{x:.4g}} {_unit(xlabel)}<br>{ykey} %{{y:.4g}} {_unit(ylabel)}<br>{title} %{{z:.3f}} {unit}"
                    f"<extra>{model}</extra>"
                ),
            ),
            row=1,
            col=i,
        )
        if name in lim:
            bx_, by_ = cell_boundary(xe, ye, np.nan_to_num(z, nan=-np.inf) > lim[name] * scale)
            if bx_:
                fig.add_trace(
                    go.Scatter(
                        x=bx_,
                        y=by_,
                        mode="lines",
                        line=dict(color="#d62728", width=2.5, dash="dash"),
                        name="design limit (between the points within and beyond)",
                        legendgroup="limit",
                        showlegend=i == 1,
                        hoverinfo="skip",
                    ),
                    row=1,
                    col=i,
                )
        if contact is not None and contact.any():
            fig.add_trace(
                go.Scatter(
                    x=X[contact],
                    y=Y[contact],
                    mode="markers",
                    marker=dict(symbol="circle", size=8, color="white", line=dict(color="black", width=1)),
                    name="contact preserved (linear valid)",
                    legendgroup="contact",
                    showlegend=i == 1,
                    hoverinfo="skip",
                ),
                row=1,
                col=i,
            )
        bx, by = base_value(view, xkey) * fx, base_value(view, ykey) * fy
        if math.isfinite(bx) and math.isfinite(by):
            fig.add_trace(
                go.Scatter(
                    x=[bx],
                    y=[by],
                    mode="markers",
                    marker=dict(symbol="star", size=16, color="white", line=dict(color="black", width=1.5)),
                    name="base case",
                    legendgroup="base",
                    showlegend=i == 1,
                    hovertemplate="base case<extra></extra>",
                ),
                row=1,
                col=i,
            )
        fig.update_xaxes(title_text=xlabel, **_axis_ticks(view, xkey), row=1, col=i)
        fig.update_yaxes(title_text=ylabel if i == 1 else None, **_axis_ticks(view, ykey), row=1, col=i)
    style_figure(fig, f"Study {sds.attrs.get('study', '')}: {model} model, total (dynamic) response{_held_text(held)}", 560)
    return _bottom_legend(fig, 560)


def study_profile_figure(sds: xr.Dataset) -> Any | None:
    """Max force, moment and stress vs the single varying study axis, both models (1-D studies)."""
    view, axes, held = _study_view(sds, 1)
    keys = study_keys(view)
    if not axes and not keys:
        return None
    key = axes[0] if axes else keys[0]
    go = plotly_go()
    total = total_response(view)
    x, fx, xlabel = _axis(view, key)
    lim = design_limits(sds)
    fig = subplots(rows=1, cols=3, horizontal_spacing=0.08, subplot_titles=[f"{t} [{u}]" for _, t, _, u in _STUDY_QUANTITIES])
    contact = (
        np.asarray(total["contact_preserved"].sel(model="nonlinear").values).astype(bool)
        if "nonlinear" in coord_labels(total["model"])
        else None
    )
    for i, (name, _title, scale, unit) in enumerate(_STUDY_QUANTITIES, start=1):
        for m in model_order(coord_labels(total["model"])):
            fig.add_trace(
                go.Scatter(
                    x=x,
                    y=np.asarray(total[name].sel(model=m).values, dtype=float) * scale,
                    mode="lines+markers",
                    name=m,
                    legendgroup=m,
                    showlegend=i == 1,
                    line=model_line(m),
                    hovertemplate=f"{key} %{{x:.4g}} {_unit(xlabel)}<br>%{{y:.3f}} {unit}<extra>{m}</extra>",
                ),
                row=1,
                col=i,
            )
        if name in lim:
            fig.add_hline(y=lim[name] * scale, line=dict(color="#d62728", dash="dot"), row=1, col=i)
        if contact is not None and contact.any():
            yv = np.asarray(total[name].sel(model="nonlinear").values, dtype=float)[contact] * scale
            fig.add_trace(
                go.Scatter(
                    x=x[contact],
                    y=yv,
                    mode="markers",
                    marker=dict(symbol="circle-open", size=12, color="#1a9850", line=dict(width=2)),
                    name="contact preserved (linear valid)",
                    legendgroup="contact",
                    showlegend=i == 1,
                    hoverinfo="skip",
                ),
                row=1,
                col=i,
            )
        b = base_value(view, key) * fx
        if math.isfinite(b):
            fig.add_vline(x=b, line=dict(color="black", width=1), row=1, col=i)
        fig.update_xaxes(title_text=xlabel, **_axis_ticks(view, key), row=1, col=i)
    fig.update_yaxes(title_text="total (dynamic) response", row=1, col=1)
    style_figure(
        fig,
        f"Study {sds.attrs.get('study', '')}: total (dynamic) response; red dotted = design limit, black = base case{_held_text(held)}",
        500,
    )
    return _bottom_legend(fig, 500)


def compliance_map_figure(sds: xr.Dataset) -> Any | None:
    """Which model's verdict admits each point (F <= F_max and sigma_b <= sigma_max), over two axes (1-D: one row)."""
    keys = study_keys(sds)
    if not keys:
        return None
    from seafast.studies.limits import DesignLimits, compliance

    view, axes, held = _study_view(sds, 2)
    if not axes:
        return None
    go = plotly_go()
    comp = compliance(view, DesignLimits.from_attrs(sds.attrs))
    if len(axes) == 1:
        xkey, ykey = axes[0], None
    else:
        ykey, xkey = axes
    order = [k for k in (ykey, xkey) if k is not None]
    comp = comp.transpose(*order, ...)
    models = coord_labels(comp["model"])

    def verdict(m: str) -> np.ndarray:
        if m not in models:
            return np.zeros(comp["complies"].isel(model=0).shape, dtype=bool)
        return np.asarray(comp["complies"].sel(model=m).values).astype(bool)

    cat = verdict("linear").astype(int) + 2 * verdict("nonlinear").astype(int)
    names = ["complies with neither", "linear model only", "nonlinear model only", "both models"]
    colors = ["#d9d9d9", "#fdb863", "#80cdc1", "#1a9850"]
    x, fx, xlabel = _axis(view, xkey)
    xe = _edges(x, _is_log(view, xkey))
    fy = 1.0
    if ykey is None:
        cat = cat[None, :]
        ye, yv, ylabel = np.array([0.0, 1.0]), np.array([0.5]), ""
    else:
        yv, fy, ylabel = _axis(view, ykey)
        ye = _edges(yv, _is_log(view, ykey))
    scale = []
    for i, c in enumerate(colors):
        scale += [[i / 4, c], [(i + 1) / 4, c]]
    text = np.vectorize(lambda k: names[k])(cat)
    fig = go.Figure(
        go.Heatmap(
            x=xe,
            y=ye,
            z=cat,
            zmin=0,
            zmax=4,
            colorscale=scale,
            xgap=1,
            ygap=1,
            text=text,
            colorbar=dict(tickvals=[0.5, 1.5, 2.5, 3.5], ticktext=names, thickness=14),
            hovertemplate=f"%{{x:.4g}} {_unit(xlabel)}, %{{y:.4g}} {_unit(ylabel) if ykey else ''}<br>%{{text}}<extra></extra>",
        )
    )
    if "error" in view:
        err = np.asarray(view["error"].transpose(*order).values).astype(str) != ""
        if ykey is None:
            err = err[None, :]
        if err.any():
            yy, xx = np.nonzero(err)
            fig.add_trace(
                go.Scatter(x=x[xx], y=yv[yy], mode="markers", marker=dict(symbol="x", size=10, color="black"), name="evaluation failed")
            )
    if ykey is not None:
        bx, by = base_value(view, xkey) * fx, base_value(view, ykey) * fy
        if math.isfinite(bx) and math.isfinite(by):
            fig.add_trace(
                go.Scatter(
                    x=[bx],
                    y=[by],
                    mode="markers",
                    name="base case",
                    marker=dict(symbol="star", size=16, color="white", line=dict(color="black", width=1.5)),
                )
            )
    fig.update_xaxes(title_text=xlabel, **_axis_ticks(view, xkey))
    fig.update_yaxes(title_text=ylabel, showticklabels=ykey is not None, **(_axis_ticks(view, ykey) if ykey is not None else {}))
    lim = design_limits(sds)
    style_figure(
        fig,
        f"Compliance: F <= {lim['F_N'] / 1e6:g} MN and sigma_b <= {lim['sigma_b_Pa'] / 1e6:g} MPa (total response){_held_text(held)}",
        500 if ykey is not None else 330,
    )
    return _bottom_legend(fig, 520 if ykey is not None else 350)


def study_figures(sds: xr.Dataset) -> list[ReportFigure]:
    """Interactive figures of a study: surfaces per model (>= 2 varying axes) or profiles (1 axis), and the compliance map."""
    out: list[ReportFigure] = []
    keys = study_keys(sds)
    varying = [k for k in keys if sds.sizes[k] > 1]
    if len(varying) >= 2:
        for m in ("nonlinear", "linear"):
            fig = study_surface_figure(sds, m)
            if fig is not None:
                out.append(
                    ReportFigure(
                        f"fig-study-surface-{m}",
                        f"Study surfaces, {m} model",
                        fig,
                        "Circles: contact preserved at every saddle over the whole period (nonlinear model), so the linear "
                        "model is valid there; dashed red: design limit; star: base case.",
                    )
                )
    elif varying or keys:
        fig = study_profile_figure(sds)
        if fig is not None:
            out.append(
                ReportFigure(
                    "fig-study-profiles",
                    "Study profiles",
                    fig,
                    "Circles: contact preserved at every saddle (linear model valid); red dotted: design limit.",
                )
            )
    fig = compliance_map_figure(sds) if varying else None
    if fig is not None:
        out.append(
            ReportFigure(
                "fig-compliance-map",
                "Compliance map",
                fig,
                "Which model's verdict admits each arrangement; decisions use the nonlinear model.",
            )
        )
    return out
