"""Which figures of one case a run's Dataset supports, and drawing one of them by its file name.

Imports no matplotlib: ``seafast run`` plans its figures (:func:`case_figure_names`) before any
process loads it, and each process that draws (:func:`draw_case_figure`) loads it itself; a
helper forked ahead (:func:`figure_helpers`) loads it while the run is solved
(:func:`warm_figures`).
"""

from __future__ import annotations

import io
from pathlib import Path
from typing import Any

from seafast.parallel.sharing import HelperPool, helper_count

__all__ = ["CASE_FIGURES", "case_figure_names", "draw_case_figure", "write_case_figures", "warm_figures", "figure_helpers"]

CASE_FIGURES: tuple[tuple[str, str, str | None, float], ...] = (
    ("deflection", "plot_deflection", None, 1.0),
    ("forces_moments", "plot_forces_and_moments", None, 0.8),
    ("saddle_time_histories", "plot_saddle_time_histories", None, 1.0),
    ("saddle_surfaces", "plot_saddle_surfaces", None, 0.6),
    ("aft_most_loaded_saddle", "plot_aft_picture", None, 0.55),
    ("hull_girder", "plot_hull_girder", "hull_x_m", 0.65),
    ("raos", "plot_raos", "rao_omega_rad_s", 1.1),
    ("stick_slip", "plot_stick_slip", "friction_force_N", 0.8),
    ("cradle_sections", "seafast.output.cradle_sections:plot_cradle_sections", "pad_force_max_N", 0.5),
)
"""Each figure of a case: its file name (without ``.png``), its function in
:mod:`seafast.output.plots` (or ``module:function`` elsewhere), the variable of the Dataset it needs (None: every run has what it
needs) and its drawing time relative to ``deflection`` [-] (measured; it orders the shared work,
costliest first). The order is the report's."""


def case_figure_names(ds: Any) -> list[str]:
    """The file names (without ``.png``) of the figures ``ds`` (a run's Dataset) supports, in the report's order."""
    return [name for name, _, needs, _ in CASE_FIGURES if needs is None or needs in ds]


def draw_case_figure(ds: Any, name: str, out_dir: str | Path) -> Path:
    """Draw the figure ``name`` (a name of :data:`CASE_FIGURES`) of ``ds`` into ``out_dir/name.png``; return its path."""
    import importlib

    from seafast.output import plots

    module_name, _, function = {n: f for n, f, _, _ in CASE_FIGURES}[name].rpartition(":")
    module = importlib.import_module(module_name) if module_name else plots
    path: Path = getattr(module, function)(ds, Path(out_dir) / f"{name}.png")
    return path


def write_case_figures(ds: Any, out_dir: str | Path) -> list[Path]:
    """Write every figure ``ds`` (a run's Dataset) supports into ``out_dir``, one after the other; return the paths.

    ``seafast run`` draws the same ones, shared among processes
    (:func:`seafast.output.files.write_run_outputs`).
    """
    return [draw_case_figure(ds, name, out_dir) for name in case_figure_names(ds)]


def warm_figures() -> None:
    """Load what drawing a figure needs (matplotlib with Agg, :mod:`seafast.output.plots`, the font, the PNG encoder)."""
    import matplotlib.pyplot as plt

    from seafast.output import plots
    from seafast.output.style import PNG_COMPRESS_LEVEL, PNG_COMPRESS_STRATEGY

    fig, ax = plt.subplots(figsize=(2.0, 1.5))
    ax.plot([0.0, 1.0], [0.0, 1.0], label="x")
    ax.set_xlabel("x [m]")
    ax.set_title("warm-up")
    ax.legend()
    fig.tight_layout()
    pil_kwargs = {"compress_level": PNG_COMPRESS_LEVEL, "compress_type": PNG_COMPRESS_STRATEGY}
    fig.savefig(io.BytesIO(), format="png", dpi=plots.DPI, pil_kwargs=pil_kwargs)
    plt.close(fig)


def figure_helpers(draws: bool = True) -> HelperPool:
    """Helpers for a run's figures, forked now (one per further core) to load matplotlib while the run is solved.

    ``draws`` False (no figures): an empty pool. Use as a context manager around the run and
    :func:`seafast.output.files.write_run_outputs` (``helpers=``): leaving it stops helpers that
    got no figure.
    """
    return HelperPool(helper_count(len(CASE_FIGURES)) if draws else 0, warm=warm_figures).start()
