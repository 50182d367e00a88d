"""Print-quality figures of the report: PNGs (matplotlib, >= PNG_DPI dpi) and their PDF.

The run figures reuse :mod:`seafast.output.plots`, the study figures
:mod:`seafast.output.study_plots`; :func:`_print_quality` raises their resolution and collects
them into the PDF without changing those modules.
"""

from __future__ import annotations

import logging
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from pathlib import Path
from typing import Any

import numpy as np
import xarray as xr

from seafast.output.report.common import PNG_DPI, case_mapping, coord_labels, total_load_case
from seafast.output.report.findings import run_findings, study_findings
from seafast.output.report.tables import summary_table_rows

__all__ = ["plot_contact_timeline", "write_print_figures"]

logger = logging.getLogger(__name__)


@contextmanager
def _print_quality(pdf: Any | None, min_dpi: int) -> Iterator[list[str]]:
    """While active, every matplotlib ``Figure.savefig`` to a file uses at least ``min_dpi`` and
    the figure is also appended to ``pdf`` (a ``PdfPages``). Yields the list of saved paths.

    This lets the report reuse the figure functions of :mod:`seafast.output.plots` and
    :mod:`seafast.output.study_plots` (which save and close their figures) unchanged.
    """
    from matplotlib.figure import Figure

    original = Figure.savefig
    saved: list[str] = []
    busy = [False]

    def savefig(self: Any, fname: Any, *args: Any, **kwargs: Any) -> Any:
        if busy[0] or kwargs.get("format") == "pdf":
            return original(self, fname, *args, **kwargs)
        dpi = kwargs.get("dpi")
        kwargs["dpi"] = max(float(dpi), min_dpi) if isinstance(dpi, (int, float)) else min_dpi
        result = original(self, fname, *args, **kwargs)
        saved.append(str(fname))
        if pdf is not None:
            busy[0] = True
            try:
                pdf.savefig(self, bbox_inches=kwargs.get("bbox_inches"))
            finally:
                busy[0] = False
        return result

    Figure.savefig = savefig  # type: ignore[method-assign]  # patched on purpose, for the with-block only
    try:
        yield saved
    finally:
        Figure.savefig = original  # type: ignore[method-assign]  # restored


def plot_contact_timeline(ds: xr.Dataset, path: Path) -> Path:
    """Contact state (saddle x period fraction) of the dynamic response, per model (PNG)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import ListedColormap
    from matplotlib.patches import Patch

    models = coord_labels(ds["model"])
    lc = total_load_case(ds)
    n = ds.sizes["saddle"]
    fig, axes = plt.subplots(len(models), 1, figsize=(9, 1.2 + 0.55 * n * len(models) + 0.6), squeeze=False, sharex=True)
    s = ds["period_fraction"].values
    ds_ = np.diff(s).mean() if s.size > 1 else 1.0
    xe = np.concatenate([s - ds_ / 2, [s[-1] + ds_ / 2]])
    cmap = ListedColormap(["#fdae61", "#1a9850"])
    for ax, m in zip(axes[:, 0], models, strict=True):
        z = (ds["saddle_compression_m"].sel(load_case=lc, model=m).values > 0).astype(int).T
        ax.pcolormesh(xe, np.arange(n + 1) - 0.5, z, cmap=cmap, vmin=0, vmax=1, shading="flat")
        ax.set_yticks(range(n))
        ax.set_yticklabels([f"{j}: x = {float(ds['saddle_x_m'][j]):.1f} m" for j in range(n)], fontsize=8)
        ax.set_ylabel("saddle [-]")
        ax.set_title(f"{m} model" + (" (detached = would need tension)" if m == "linear" else ""), fontsize=10)
    axes[-1, 0].set_xlabel("period fraction t/T [-]")
    fig.legend(
        handles=[Patch(color="#1a9850", label="in contact"), Patch(color="#fdae61", label="detached")],
        loc="upper right",
        ncol=2,
        fontsize=8,
    )
    fig.suptitle(f"Contact state over one wave period ({lc})", fontsize=11, x=0.02, ha="left")
    fig.tight_layout(rect=(0, 0, 1, 0.95))
    fig.savefig(path, dpi=PNG_DPI)
    plt.close(fig)
    return Path(path)


def _summary_page(pdf: Any, title: str, lines: Sequence[str]) -> None:
    import matplotlib.pyplot as plt

    fig = plt.figure(figsize=(11.69, 8.27))
    fig.text(0.05, 0.94, title, fontsize=16, weight="bold", va="top")
    fig.text(0.05, 0.88, "\n".join(lines), fontsize=8.5, family="monospace", va="top")
    pdf.savefig(fig)
    plt.close(fig)


def write_print_figures(run: xr.Dataset | None, study: xr.Dataset | None, fig_dir: Path, pdf_path: Path | None) -> list[Path]:
    """Print-quality PNGs (>= :data:`PNG_DPI` dpi) of the report's figures, and their PDF.

    Run figures reuse :mod:`seafast.output.plots`; study figures :mod:`seafast.output.study_plots`.
    A figure that fails to draw is skipped (and named on stderr); the rest are written.
    """
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.backends.backend_pdf import PdfPages

    fig_dir.mkdir(parents=True, exist_ok=True)
    jobs: list[tuple[str, Any]] = []
    if run is not None:
        from seafast.output import plots

        if "hull_x_m" in run.coords:
            jobs.append(("hull_girder.png", plots.plot_hull_girder))
        if "rao_omega_rad_s" in run.coords:
            jobs.append(("raos.png", plots.plot_raos))
        jobs += [
            ("deflection.png", plots.plot_deflection),
            ("forces_moments.png", plots.plot_forces_and_moments),
            ("saddle_time_histories.png", plots.plot_saddle_time_histories),
            ("contact_timeline.png", plot_contact_timeline),
        ]
        if "friction_force_N" in run:
            jobs.append(("stick_slip.png", plots.plot_stick_slip))
        if "pad_force_max_N" in run:  # off head seas: the cargo in its cradles
            from seafast.output.cradle_sections import plot_cradle_sections

            jobs.append(("cradle_sections.png", plot_cradle_sections))
    paths: list[Path] = []
    pdf = PdfPages(pdf_path) if pdf_path is not None else None
    try:
        if pdf is not None:
            lines: list[str] = []
            if run is not None:
                header, rows = summary_table_rows(run)
                widths = [max(len(str(r[i])) for r in [header, *rows]) for i in range(len(header))]
                lines += ["maxima over the cargo, the saddles and one wave period (dynamic = total response)", ""]
                for r in [header, *rows]:
                    lines.append(
                        "  ".join(str(c).ljust(w) if i < 2 else str(c).rjust(w) for i, (c, w) in enumerate(zip(r, widths, strict=True)))
                    )
                lines += ["", f"excitation: {run.attrs.get('excitation_source', '')}"]
                lines += [f"{f.level}: {f.title}" for f in run_findings(run)]
            if study is not None:
                lines += ["", f"study {study.attrs.get('study', '')}: {study.attrs.get('description', '')}"]
                lines += [f"{f.level}: {f.title}" for f in study_findings(study)]
            name = (
                case_mapping(run.attrs.get("case_json")).get("name", "")
                if run is not None
                else study.attrs.get("study", "")
                if study is not None
                else ""
            )
            _summary_page(pdf, f"seafast report: {name}", lines)
        with _print_quality(pdf, PNG_DPI):
            for fname, fn in jobs:
                try:
                    paths.append(fn(run, fig_dir / fname))
                except Exception as exc:  # noqa: BLE001 - one bad figure must not lose the report
                    logger.warning("print figure %s skipped (%s: %s)", fname, type(exc).__name__, exc)
            if study is not None:
                try:
                    from seafast.output.study_plots import plot_study

                    # the figures lay out the study's axes, load case and model; the warning flags are not drawn
                    paths += list(plot_study(study.drop_dims("warning", errors="ignore"), fig_dir))
                except Exception as exc:  # noqa: BLE001 - one bad figure must not lose the report
                    logger.warning("study print figures skipped (%s: %s)", type(exc).__name__, exc)
    finally:
        if pdf is not None:
            pdf.close()
    return paths
