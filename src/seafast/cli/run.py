"""``seafast run``: one case end to end, its summary table, its files, and what a user must know about it."""

from __future__ import annotations

import argparse
import logging
import sys
import time
from typing import TYPE_CHECKING, Any

import seafast
from seafast.cli.common import EXIT_NOT_CONVERGED, EXIT_OK, EXIT_OUTSIDE_VALIDITY, add_case_options, error

if TYPE_CHECKING:
    from seafast.analyses.run import CaseResult

__all__ = ["add_run_subcommand", "RUN_EXAMPLES"]

logger = logging.getLogger("seafast.cli")

RUN_EXAMPLES = """examples:
  seafast run                                   # the built-in base case
  seafast run case.yaml -o results/             # a case file
  seafast run --set seafastening.saddle_count=4 --set wave.amplitude_m=2
  seafast run case.yaml --set solver.harmonics=32      # a fixed H instead of the adaptive choice
  seafast run --preset source                   # the source's method (tanh, H = 5, N = 128, Powell)
"""


def add_run_subcommand(subparsers: Any) -> argparse.ArgumentParser:
    """``seafast run``."""
    run = subparsers.add_parser(
        "run",
        help="run a case (default: the built-in base case)",
        epilog=RUN_EXAMPLES,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    run.add_argument("case", nargs="?", help="case file (YAML); omit for the built-in base case")
    run.add_argument("-o", "--output", default="seafast-output", help="output directory (default: %(default)s)")
    add_case_options(run)
    run.add_argument("--no-plots", action="store_true", help="skip the PNG figures")
    run.add_argument("-q", "--quiet", action="store_true", help="print only warnings and errors")
    run.set_defaults(handler=_cmd_run)
    return run


def _cmd_run(args: argparse.Namespace) -> int:
    from seafast.config import CaseError, load_case, parse_overrides
    from seafast.output.case_figures import figure_helpers
    from seafast.output.files import no_dask_lookup

    try:
        overrides = parse_overrides(args.overrides)
        if args.no_plots:
            overrides["outputs.plots"] = False
        case = load_case(args.case, overrides)
    except CaseError as exc:
        return error(str(exc))
    source = f"from {args.case}" if args.case else "(built-in base case)"
    logger.info("seafast %s: running '%s' %s", seafast.__version__, case.name, source)
    t0 = time.perf_counter()
    # a run makes no Dask collection: xarray need not import Dask to tell; the figures' helpers
    # are forked first, before the numerical stack loads here, and load matplotlib meanwhile
    with no_dask_lookup(), figure_helpers(case.outputs.plots) as helpers:
        from seafast.analyses.run import run_case
        from seafast.output.files import write_run_outputs

        try:
            result = run_case(case, progress=logger.info)
        except (CaseError, ValueError) as exc:
            return error(str(exc))
        rows = result.summary
        if not args.quiet:
            # the table as soon as the rows are known: results.nc and the figures take longer than the solves
            _print_tables(result, rows)
        logger.info("writing the results to %s", args.output)
        paths = write_run_outputs(result, args.output, helpers=helpers)
    if not args.quiet:
        print(f"wrote {', '.join(str(p) for p in paths.values())} ({time.perf_counter() - t0:.1f} s)")
    if result.axial is not None:
        for line in result.axial.warning_lines():
            print(f"seafast: warning: {line}", file=sys.stderr)
    if result.cradle is not None:
        for line in result.cradle.warning_lines():
            print(f"seafast: warning: {line}", file=sys.stderr)
    orbit = result.rows.nonlinear_dynamic.orbit
    if orbit is not None and orbit.same_as_start is False:
        print(
            f"seafast: warning: dynamic nonlinear: the time-domain reference started on the {orbit.start_method} solution's "
            f"orbit and settled on ANOTHER periodic state (RMS saddle-force distance {orbit.distance_from_start:.2e} > "
            f"{orbit.orbit_tolerance:g}): that orbit is unstable or not unique; the numbers are the orbit reached",
            file=sys.stderr,
        )
    for line in result.impact.warning_lines():
        print(f"seafast: warning: dynamic nonlinear: {line}", file=sys.stderr)
    bad = [r for r in rows if not r["converged"]]
    for r in bad:
        coupling = result.coupling.get((r["load_case"], r["model"]))
        if coupling is not None and not coupling.converged:
            why = (
                f"two-way coupling {coupling.outcome.value.replace('_', ' ')}: coupling residual {coupling.residual_m:.2e} m "
                f"> tolerance {coupling.tolerance_m:.2e} m after {coupling.iterations} step(s)"
            )
        elif r.get("cradle_converged") is False:
            why = (
                f"the cargo on its cradles: {r['cradle_outcome'].replace('_', ' ')}, residual {r['cradle_residual']:.3e}: "
                f"{r.get('cradle_message', '')}"
            )
        else:
            from seafast.results.dataset import LOAD_CASES, MODELS
            from seafast.results.impact import fixed_harmonics_reason

            outcome = result.arrays.solver_outcome[LOAD_CASES.index(r["load_case"]), MODELS.index(r["model"])]
            why = f"{outcome.replace('_', ' ')}, residual {r['residual_norm']:.3e}"
            reason = fixed_harmonics_reason(result.case, result.model, result.excitation.omega_rad_s)
            why += f"; {reason}" if reason is not None and r["load_case"] == "dynamic" else ""
        print(
            f"seafast: warning: {r['load_case']} {r['model']} solution did NOT converge ({why}); "
            "its numbers are flagged converged=false in summary.csv and must not be trusted",
            file=sys.stderr,
        )
    if bad:
        return EXIT_NOT_CONVERGED
    beyond = _warn_validity(result)
    # a peak saddle force that is an elastic impact (warned above) is a result beyond the model's validity too
    return EXIT_OUTSIDE_VALIDITY if beyond or result.impact.flagged else EXIT_OK


def _print_tables(result: CaseResult, rows: list[dict[str, Any]]) -> None:
    """Print the summary table (and the axial one), the excitation and the coupling outcomes on stdout, flushed."""
    from seafast.output.tables import format_axial_table, format_cradle_table, format_summary_table

    print(format_summary_table(rows, title=f"{result.case.name}: maxima over the cargo, the saddles and one wave period"))
    if result.cradle is not None:
        print(format_cradle_table(rows))
    if result.axial is not None:
        print(format_axial_table(rows))
    print(f"excitation: {result.excitation.source}")
    for status in result.coupling.values():
        print(status.message)
    sys.stdout.flush()  # a pipe or a file buffers stdout: the table must not wait for the files


def _warn_validity(result: CaseResult) -> bool:
    """Warn (stderr) about each row beyond the model's validity, with the likely cause; whether there was one."""
    from seafast.results.validity import likely_cause

    issues = result.validity
    rows = dict.fromkeys((i.load_case, i.model) for i in issues)
    for load_case, model in rows:
        what = "; ".join(
            f"{i.quantity} {i.value:.4g} {i.unit} > {i.allowed:.3g} {i.unit}"
            for i in issues
            if (i.load_case, i.model) == (load_case, model)
        )
        print(
            f"seafast: warning: {load_case} {model}: results beyond the model's small-displacement validity ({what}); "
            "written, flagged within_validity=false in results.nc, and not a valid answer",
            file=sys.stderr,
        )
    cause = likely_cause(result.case, issues)
    if cause is not None:
        print(f"seafast: warning: {cause}", file=sys.stderr)
    return bool(issues)
