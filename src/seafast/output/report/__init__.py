"""``seafast report DIR``: one self-contained HTML report of a run or study directory.

The report holds interactive plotly figures (plotly.js embedded inline once, so the file opens
without a network), tables in engineering units (mm, MN, MN m, MPa) and clearly visible WARNING
boxes where a result should not be trusted. The same figures are written at print quality as
PNG (matplotlib, at least :data:`PNG_DPI` dpi, units on every axis) into ``report_figures/``
next to the HTML, and collected into ``report_figures.pdf``.

Inputs
------
* A run directory (``seafast run -o DIR``): ``results.nc`` (required), ``summary.csv``,
  ``case.yaml``.
* A study directory (``seafast study NAME -o DIR``): ``study.nc`` (required), ``ranking.csv``
  (read when present, else the ranking is computed from ``study.nc``), ``compliance.csv``.

Design: every figure and table is a pure function ``Dataset -> plotly Figure / rows``; reading
files and writing the report happen only in :func:`write_report` and the command handler.
The print (PNG/PDF) figures reuse :mod:`seafast.output.plots` (run) and
:mod:`seafast.output.study_plots` (study).

Modules
-------
* :mod:`~seafast.output.report.common`: file names, result types (:class:`ReportError`,
  :class:`Finding`, :class:`ReportFigure`, :class:`ReportOutputs`) and dataset accessors.
* :mod:`~seafast.output.report.tables`: inputs (the flattened case), summary, diagnostics and
  ranking rows.
* :mod:`~seafast.output.report.findings`: WARNING/NOTE/OK diagnostics of runs and studies.
* :mod:`~seafast.output.report.plotly_style`: the plotly styling all interactive figures share.
* :mod:`~seafast.output.report.vessel_figures`: plotly figures of a run's vessel side (hull girder,
  RAOs, deck motion).
* :mod:`~seafast.output.report.cargo_figures`: plotly figures of a run's cargo response (saddles,
  deflection and moment lines, contact states).
* :mod:`~seafast.output.report.axial_figures`: the plotly stick-slip figure of a run's axial analysis.
* :mod:`~seafast.output.report.run_figures`: a run's interactive figures in report order.
* :mod:`~seafast.output.report.study_figures`: plotly figures of a study.
* :mod:`~seafast.output.report.html`: the page template and :func:`build_report_html`.
* :mod:`~seafast.output.report.print_figures`: matplotlib PNG/PDF print figures.
* :mod:`~seafast.output.report.write`: :func:`write_report` (reads the directory, writes the
  page and the print figures).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from seafast.lazy import lazy_exports

if TYPE_CHECKING:
    from seafast.output.report.axial_figures import stick_slip_figure
    from seafast.output.report.cargo_figures import contact_timeline_figure, deflection_moment_figure, saddle_time_history_figure
    from seafast.output.report.common import (
        FIGURES_DIRNAME,
        PDF_FILENAME,
        PNG_DPI,
        REPORT_FILENAME,
        Finding,
        ReportError,
        ReportFigure,
        ReportOutputs,
    )
    from seafast.output.report.findings import TENSILE_NOTE_FRACTION, TRUNCATION_LIMIT, run_findings, study_findings
    from seafast.output.report.html import build_report_html, render_html
    from seafast.output.report.print_figures import plot_contact_timeline, write_print_figures
    from seafast.output.report.run_figures import run_figures
    from seafast.output.report.study_figures import compliance_map_figure, study_figures, study_profile_figure, study_surface_figure
    from seafast.output.report.tables import diagnostics_rows, flatten_case, input_rows, ranking_rows, summary_table_rows
    from seafast.output.report.vessel_figures import deck_motion_figure, hull_girder_figure, rao_figure
    from seafast.output.report.write import write_report

# imported on first use (seafast.lazy): the command line's parser imports the report's
# subcommand without loading xarray, plotly or matplotlib
EXPORTS = {
    "seafast.output.report.axial_figures": ("stick_slip_figure",),
    "seafast.output.report.cargo_figures": ("contact_timeline_figure", "deflection_moment_figure", "saddle_time_history_figure"),
    "seafast.output.report.common": (
        "FIGURES_DIRNAME",
        "PDF_FILENAME",
        "PNG_DPI",
        "REPORT_FILENAME",
        "Finding",
        "ReportError",
        "ReportFigure",
        "ReportOutputs",
    ),
    "seafast.output.report.findings": ("TENSILE_NOTE_FRACTION", "TRUNCATION_LIMIT", "run_findings", "study_findings"),
    "seafast.output.report.html": ("build_report_html", "render_html"),
    "seafast.output.report.print_figures": ("plot_contact_timeline", "write_print_figures"),
    "seafast.output.report.run_figures": ("run_figures",),
    "seafast.output.report.study_figures": ("compliance_map_figure", "study_figures", "study_profile_figure", "study_surface_figure"),
    "seafast.output.report.tables": ("diagnostics_rows", "flatten_case", "input_rows", "ranking_rows", "summary_table_rows"),
    "seafast.output.report.vessel_figures": ("deck_motion_figure", "hull_girder_figure", "rao_figure"),
    "seafast.output.report.write": ("write_report",),
}
__all__ = [
    "stick_slip_figure",
    "contact_timeline_figure",
    "deflection_moment_figure",
    "saddle_time_history_figure",
    "FIGURES_DIRNAME",
    "PDF_FILENAME",
    "PNG_DPI",
    "REPORT_FILENAME",
    "Finding",
    "ReportError",
    "ReportFigure",
    "ReportOutputs",
    "TENSILE_NOTE_FRACTION",
    "TRUNCATION_LIMIT",
    "run_findings",
    "study_findings",
    "build_report_html",
    "render_html",
    "plot_contact_timeline",
    "write_print_figures",
    "run_figures",
    "compliance_map_figure",
    "study_figures",
    "study_profile_figure",
    "study_surface_figure",
    "diagnostics_rows",
    "flatten_case",
    "input_rows",
    "ranking_rows",
    "summary_table_rows",
    "deck_motion_figure",
    "hull_girder_figure",
    "rao_figure",
    "write_report",
]
lazy_exports(__name__, EXPORTS)
