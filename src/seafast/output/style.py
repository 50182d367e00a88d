"""Figure conventions shared by every PNG and interactive figure of the package.

* Series that can coincide stay visible: the nonlinear model is drawn as a thick solid line
  underneath, the linear one as a thinner dashed line on top (:data:`MODEL_LINES`); where they
  agree both are seen.
* Axis units follow the data: :func:`scaled_unit` picks the SI prefix (mm or µm, MN or GN/m, ...)
  that puts the largest value between 1 and 1000, the data are multiplied by its factor and the
  tick labels are plain numbers in the unit the axis label names (:func:`plain_tick_labels`);
  never an SI letter on a tick ("200µ" on an axis labelled mm) and never a log-axis "1B".
* Legends stand outside the axes (:func:`legend_outside`), so they cover no data.
* A PNG is laid out tightly and rendered once (:func:`save_png`).

matplotlib is imported inside the functions that draw; the unit scaling is plain Python, used
by the plotly figures too.
"""

from __future__ import annotations

import math
import zlib
from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import Any

__all__ = [
    "MODEL_LINES",
    "MODEL_COLORS",
    "scaled_unit",
    "scaled_axis_label",
    "legend_outside",
    "plain_tick_labels",
    "value_ticks",
    "cell_boundary",
    "save_png",
    "PNG_COMPRESS_LEVEL",
    "PNG_COMPRESS_STRATEGY",
]

PNG_COMPRESS_LEVEL = 1
"""zlib level of the PNG files [-]: lossless at every level (the same pixels); 1 encodes a run's
figure (2400 x 1500 pixels) in about 0.7 of the time of Pillow's default 6, for a file a fifth to
a third larger (about 300 kB)."""

PNG_COMPRESS_STRATEGY = zlib.Z_RLE
"""zlib strategy of the PNG files: run-length matches only, lossless like every strategy (the
same pixels). A figure is mostly runs of one colour: at level 1 a run's figure encodes in about
0.6 of the time of the default strategy, the seven files of a run as large in total (each
within 20 %)."""

# matplotlib line keywords per model: the thick solid nonlinear line under the thin dashed linear one
MODEL_LINES: dict[str, dict[str, Any]] = {
    "nonlinear": {"color": "tab:red", "ls": "-", "lw": 2.4, "zorder": 2},
    "linear": {"color": "tab:blue", "ls": "--", "lw": 1.3, "zorder": 3},
}
MODEL_COLORS = {m: str(style["color"]) for m, style in MODEL_LINES.items()}

# units that take an SI prefix on their leading symbol, and the prefixes each may take (largest first)
_PREFIXES: dict[str, tuple[tuple[str, float], ...]] = {
    "m": (("", 1.0), ("m", 1e-3), ("µ", 1e-6)),
    "N": (("G", 1e9), ("M", 1e6), ("k", 1e3), ("", 1.0)),
    "Pa": (("G", 1e9), ("M", 1e6), ("k", 1e3), ("", 1.0)),
}
_COMPOUND = {"N/m": "N", "N m": "N", "Nm": "N", "N s/m": "N"}


def scaled_unit(values: Iterable[float] | float, unit: str) -> tuple[float, str]:
    """The factor and unit label that put the largest finite ``|values|`` in [1, 1000).

    Parameters
    ----------
    values : float or iterable of float
        The data in ``unit`` (SI).
    unit : str
        SI unit of the data: ``m``, ``N``, ``Pa`` or a compound with a leading ``N`` (``N/m``,
        ``N m``); any other unit (``1``, ``s``, ``rad/s``, ``kg``, ``m/m``) is returned unscaled.

    Returns
    -------
    factor : float
        Multiply the data by it (``1e3`` for m -> mm).
    label : str
        The unit of the scaled data (``mm``, ``µm``, ``GN/m``, ``MN m``, ``MPa``).

    Examples
    --------
    >>> scaled_unit([2.2e-7, -1e-7], "m")
    (1000000.0, 'µm')
    >>> scaled_unit([1.1e7, 1.1e10], "N/m")
    (1e-09, 'GN/m')
    """
    base = _COMPOUND.get(unit, unit)
    prefixes = _PREFIXES.get(base)
    if prefixes is None:
        return 1.0, unit
    finite = [abs(float(v)) for v in ([values] if isinstance(values, (int, float)) else values) if math.isfinite(float(v))]
    largest = max(finite, default=0.0)
    if largest == 0.0:
        return 1.0, unit
    symbol, size = next(((s, p) for s, p in prefixes if largest / p >= 1.0), prefixes[-1])
    rest = unit[len(base) :]
    return 1.0 / size, f"{symbol}{base}{rest}"


def scaled_axis_label(name: str, values: Iterable[float], unit: str) -> tuple[float, str]:
    """The factor for ``values`` (SI ``unit``) and the axis label ``name [unit]`` after scaling.

    A dimensionless unit (``1`` or empty) reads ``[-]``; see :func:`scaled_unit`.
    """
    if unit in ("1", ""):
        return 1.0, f"{name} [-]"
    factor, shown = scaled_unit(values, unit)
    return factor, f"{name} [{shown}]"


def legend_outside(ax: Any, handles: Sequence[Any] | None = None, labels: Sequence[str] | None = None, **kwargs: Any) -> Any:
    """A legend to the right of ``ax``, outside its data area (``tight_layout`` makes room for it)."""
    options: dict[str, Any] = {"loc": "upper left", "bbox_to_anchor": (1.02, 1.0), "borderaxespad": 0.0, "fontsize": 8}
    options.update(kwargs)
    if handles is not None:
        return ax.legend(handles, labels if labels is not None else [h.get_label() for h in handles], **options)
    return ax.legend(**options)


def plain_tick_labels(axis: Any) -> None:
    """Tick labels of a matplotlib ``axis`` as plain numbers (no offset, no exponent, no mathtext).

    On a log axis the major ticks read ``0.01``, ``0.1``, ``1``, ``10`` and the minor ones are
    unlabelled; use it after the data were scaled with :func:`scaled_unit`.
    """
    from matplotlib.ticker import FuncFormatter, NullFormatter, ScalarFormatter

    if axis.get_scale() == "log":
        axis.set_major_formatter(FuncFormatter(lambda v, _pos: f"{v:g}"))
        axis.set_minor_formatter(NullFormatter())
        return
    formatter = ScalarFormatter(useOffset=False, useMathText=False)
    formatter.set_scientific(False)
    axis.set_major_formatter(formatter)


def value_ticks(axis: Any, values: Sequence[float]) -> None:
    """Ticks exactly at the computed ``values`` of a discrete axis (saddle counts: 2, 3, 4, not 2.5)."""
    axis.set_ticks(list(values), [f"{v:g}" for v in values])
    axis.set_ticks([], minor=True)


def cell_boundary(x_edges: Any, y_edges: Any, inside: Any) -> tuple[list[float | None], list[float | None]]:
    """The cell edges between ``inside`` (rows along y, columns along x) and the other cells.

    ``x_edges`` and ``y_edges`` are the cell edges (sequences or arrays, one longer than the
    number of columns and rows of ``inside``).

    Returns the x and y of line segments separated by ``None`` (plotly and matplotlib both draw
    them as one broken line): the boundary of a region on a grid of computed points, drawn on the
    cell edges instead of interpolated between points.
    """
    rows, cols = len(y_edges) - 1, len(x_edges) - 1
    xs: list[float | None] = []
    ys: list[float | None] = []

    def cell(i: int, j: int) -> bool:
        return 0 <= i < rows and 0 <= j < cols and bool(inside[i][j])

    for i in range(rows + 1):
        for j in range(cols):
            if cell(i - 1, j) != cell(i, j) and (0 < i < rows):
                xs += [float(x_edges[j]), float(x_edges[j + 1]), None]
                ys += [float(y_edges[i]), float(y_edges[i]), None]
    for j in range(cols + 1):
        for i in range(rows):
            if cell(i, j - 1) != cell(i, j) and (0 < j < cols):
                xs += [float(x_edges[j]), float(x_edges[j]), None]
                ys += [float(y_edges[i]), float(y_edges[i + 1]), None]
    return xs, ys


def save_png(fig: Any, path: str | Path, dpi: float, rect: tuple[float, float, float, float] | None = None) -> Path:
    """Lay ``fig`` out tightly, write it to ``path`` at ``dpi`` and close it; return the path.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure, drawn.
    path : str or Path
        The file; a ``.png`` name is written with :data:`PNG_COMPRESS_LEVEL` and
        :data:`PNG_COMPRESS_STRATEGY`, any other suffix in its own format.
    dpi : float
        Resolution [dots per inch].
    rect : tuple of float, optional
        ``(left, bottom, right, top)`` in figure fractions [-] the tight layout fits the axes into.

    Notes
    -----
    After ``tight_layout`` the figure keeps a placeholder layout engine, and ``savefig`` then
    draws it once more before the rendering that is written; the layout is done, so the engine is
    dropped and the figure is drawn once (the same pixels).
    """
    import matplotlib.pyplot as plt

    fig.tight_layout(rect=rect)
    fig.set_layout_engine(None)
    target = Path(path)
    options: dict[str, Any] = (
        {"pil_kwargs": {"compress_level": PNG_COMPRESS_LEVEL, "compress_type": PNG_COMPRESS_STRATEGY}}
        if target.suffix.lower() == ".png"
        else {}
    )
    fig.savefig(target, dpi=dpi, **options)
    plt.close(fig)
    return target
