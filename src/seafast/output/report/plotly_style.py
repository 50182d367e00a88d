"""The plotly styling every interactive figure of the report shares: model lines, layout, lazy imports.

plotly is imported on first use (:func:`plotly_go`, :func:`subplots`): it is slow to import,
and the command line's parser must not load it.
"""

from __future__ import annotations

from typing import Any

__all__ = ["MODEL_COLORS", "model_line", "model_order", "plotly_go", "subplots", "style_figure"]

MODEL_COLORS = {"linear": "#1f77b4", "nonlinear": "#d62728"}
# where the models agree both stay visible: a thick solid nonlinear line under a thin dashed linear one
_MODEL_LINES: dict[str, dict[str, Any]] = {
    "nonlinear": {"color": MODEL_COLORS["nonlinear"], "width": 3.2},
    "linear": {"color": MODEL_COLORS["linear"], "width": 1.6, "dash": "dash"},
}


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
