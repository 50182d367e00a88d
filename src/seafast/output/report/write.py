"""The I/O edge of the report: read a run/study directory, write the HTML and print figures."""

from __future__ import annotations

import html
from pathlib import Path

import xarray as xr

from seafast.output.report.common import FIGURES_DIRNAME, PDF_FILENAME, PNG_DPI, REPORT_FILENAME, ReportError, ReportOutputs
from seafast.output.report.criteria import read_criteria_csv
from seafast.output.report.html import build_report_html
from seafast.output.report.print_figures import write_print_figures

__all__ = ["write_report"]


def _open(path: Path) -> xr.Dataset:
    try:
        with xr.open_dataset(path) as ds:
            return ds.load()
    except Exception as exc:  # noqa: BLE001 - any unreadable file is an input error
        raise ReportError(f"cannot read '{path}': {type(exc).__name__}: {exc}") from None


def write_report(directory: str | Path, output: str | Path | None = None, *, figures: bool = True) -> ReportOutputs:
    """Write the report of a run or study directory.

    Parameters
    ----------
    directory : str or Path
        Holds ``results.nc`` (run), ``study.nc`` (study), ``seastate.nc`` (sea state) and/or
        ``operability.nc`` (operability) and/or ``criteria.csv`` (design criteria).
    output : str or Path, optional
        The HTML file (default ``DIR/report.html``). The print figures go next to it:
        ``report_figures/*.png`` and ``report_figures.pdf``.
    figures : bool
        Write the PNG/PDF print figures too.

    Raises
    ------
    ReportError
        If the directory is missing, holds neither file, or a file cannot be read.
    """
    d = Path(directory)
    if not d.exists():
        raise ReportError(f"directory '{d}' does not exist")
    if not d.is_dir():
        raise ReportError(f"'{d}' is not a directory; give the output directory of 'seafast run' or 'seafast study'")
    run_nc, study_nc, seastate_nc, operability_nc = d / "results.nc", d / "study.nc", d / "seastate.nc", d / "operability.nc"
    criteria_csv = d / "criteria.csv"
    if not any(p.is_file() for p in (run_nc, study_nc, seastate_nc, operability_nc, criteria_csv)):
        raise ReportError(
            f"'{d}' holds neither results.nc (from 'seafast run -o DIR'), study.nc (from 'seafast study NAME -o DIR'), "
            "seastate.nc (from 'seafast seastate -o DIR'), operability.nc (from 'seafast operability --tp ... -o DIR') "
            "nor criteria.csv (from 'seafast criteria -o DIR')"
        )
    run = _open(run_nc) if run_nc.is_file() else None
    study = _open(study_nc) if study_nc.is_file() else None
    seastate = _open(seastate_nc) if seastate_nc.is_file() else None
    operability = _open(operability_nc) if operability_nc.is_file() else None
    criteria = read_criteria_csv(criteria_csv) if criteria_csv.is_file() else None
    out = Path(output) if output is not None else d / REPORT_FILENAME
    out.parent.mkdir(parents=True, exist_ok=True)
    fig_dir, pdf_path = out.parent / FIGURES_DIRNAME, out.parent / PDF_FILENAME
    pngs: list[Path] = []
    if figures:
        pngs = write_print_figures(run, study, fig_dir, pdf_path)
        if seastate is not None:
            from seafast.output.seastate_plots import write_seastate_figures

            fig_dir.mkdir(parents=True, exist_ok=True)
            pngs = list(pngs) + write_seastate_figures(seastate, fig_dir)
        if operability is not None:
            from seafast.output.operability import plot_operability

            fig_dir.mkdir(parents=True, exist_ok=True)
            pngs = list(pngs) + [plot_operability(operability, fig_dir / "operability.png")]
    listed = "".join(
        f'<li><a href="{html.escape(p.relative_to(out.parent).as_posix())}">{html.escape(p.name)}</a></li>'
        for p in pngs
        if p.is_relative_to(out.parent)
    )
    files_note = (
        f"<details><summary>Print figures ({len(pngs)} PNG at {PNG_DPI} dpi, and {PDF_FILENAME})</summary><ul>{listed}"
        f'<li><a href="{PDF_FILENAME}">{PDF_FILENAME}</a></li></ul></details>'
        if pngs
        else ""
    )
    page, figs, findings = build_report_html(
        run, study, ranking_csv=d / "ranking.csv", files_note=files_note, seastate=seastate, operability=operability, criteria=criteria
    )
    out.write_text(page, encoding="utf-8")
    return ReportOutputs(out, tuple(pngs), pdf_path if figures else None, tuple(f.id for f in figs), tuple(findings))
