"""The ``seafast report DIR [-o FILE] [--no-figures]`` subcommand."""

from __future__ import annotations

import argparse
import sys
from typing import Any

from seafast.output.report.common import REPORT_FILENAME

__all__ = ["REPORT_EXAMPLES", "add_report_subcommand"]

REPORT_EXAMPLES = """examples:
  seafast run -o out/base && seafast report out/base          # writes out/base/report.html
  seafast study saddles -o out/saddles && seafast report out/saddles
  seafast report out/base -o /tmp/base_report.html           # report elsewhere
  seafast report out/base --no-figures                        # HTML only, skip PNG/PDF

The HTML is self-contained (plotly.js inline): open it in any browser, no network needed.
Print figures: report_figures/*.png (200 dpi) and report_figures.pdf next to the HTML.
"""


def _cmd_report(args: argparse.Namespace) -> int:
    from seafast.output.report.common import FIGURES_DIRNAME, ReportError
    from seafast.output.report.write import write_report

    try:
        result = write_report(args.directory, args.output, figures=not args.no_figures)
    except ReportError as exc:
        print(f"seafast: error: {exc}", file=sys.stderr)
        return 2
    warnings = [f for f in result.findings if f.level == "WARNING"]
    for f in warnings:
        print(f"seafast: warning: {f.title}", file=sys.stderr)
    extra = f", {len(result.pngs)} PNG in {result.html.parent / FIGURES_DIRNAME} and {result.pdf}" if result.pdf else ""
    print(f"wrote {result.html} ({len(result.figure_ids)} interactive figures{extra})")
    return 0


def add_report_subcommand(subparsers: Any) -> argparse.ArgumentParser:
    """Register ``seafast report DIR [-o FILE] [--no-figures]`` on an argparse subparsers object.

    The handler (``args.handler(args)``) returns the exit code: 0 on success, 2 when DIR is
    missing or holds neither results.nc nor study.nc (one message on stderr, no traceback).
    """
    p = subparsers.add_parser(
        "report",
        help="HTML (and PNG/PDF) report of a run or study directory",
        description="Write one self-contained HTML report (interactive figures, tables, diagnostics) of a "
        "'seafast run' or 'seafast study' output directory, plus print-quality PNG and PDF figures.",
        epilog=REPORT_EXAMPLES,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument(
        "directory",
        metavar="DIR",
        help="output directory of 'seafast run' (results.nc), 'seafast study' (study.nc), 'seafast seastate', "
        "'seafast operability' or 'seafast criteria' (criteria.csv)",
    )
    p.add_argument("-o", "--output", metavar="FILE", default=None, help=f"HTML file to write (default: DIR/{REPORT_FILENAME})")
    p.add_argument("--no-figures", action="store_true", help="skip the PNG/PDF print figures")
    p.set_defaults(handler=_cmd_report)
    return p
