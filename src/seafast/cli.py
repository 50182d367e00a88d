"""The ``seafast`` command line: run, init, schema, study, report.

Exit codes: 0 success; 2 invalid input (one clear message on stderr, no traceback); 3 the
case ran but the nonlinear solver did not converge (results are still written, flagged); 4 the
case ran and converged, but a result lies outside the model's small-displacement validity
(results written, flagged ``within_validity = false`` in results.nc; :mod:`seafast.results.validity`).

Messages: :func:`main` routes the package's logging (``seafast.*`` loggers) to stderr for the
duration of the command (:func:`seafast.console.command_logging`): progress at INFO (shown by
default), warnings as ``seafast: warning: ...``; ``-v/--verbose`` adds DEBUG (solver paths, cache
hits), ``-q/--quiet`` keeps warnings and errors only (``seafast run -q`` and ``seafast study -q``
as well).
"""

from __future__ import annotations

import argparse
import json
import logging
import math
import os
import sys
import time
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

# Small dense solves are fastest on one BLAS thread on few cores; OpenBLAS reads this when it is
# loaded, so set it before numpy/scipy load (study worker processes inherit it). An explicit
# user setting wins.
for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")


import seafast  # noqa: E402 - after the thread settings above, like numpy
from seafast.console import command_logging  # noqa: E402 - after the thread settings above

if TYPE_CHECKING:
    from seafast.pipeline import CaseResult

__all__ = ["main", "build_parser"]

logger = logging.getLogger(__name__)

EXIT_OK = 0
EXIT_INVALID_INPUT = 2
EXIT_NOT_CONVERGED = 3
EXIT_OUTSIDE_VALIDITY = 4

RUN_EXAMPLES = """examples:
  seafast run                                   # the built-in base case
  seafast run case.yaml -o results/             # a case file
  seafast run --set seafastening.saddle_count=4 --set wave.amplitude_m=2
  seafast run case.yaml --set solver.harmonics=32      # a fixed H instead of the adaptive choice
  seafast run --preset source                   # the source's method (tanh, H = 5, N = 128, Powell)
"""


class _PresetAction(argparse.Action):
    """``--preset NAME`` is ``--set solver.preset=NAME``."""

    def __call__(
        self, parser: argparse.ArgumentParser, namespace: argparse.Namespace, values: object, option_string: str | None = None
    ) -> None:
        overrides = list(getattr(namespace, "overrides", None) or [])
        overrides.append(f"solver.preset={values}")
        namespace.overrides = overrides


def _add_set(p: argparse.ArgumentParser) -> None:
    p.add_argument(
        "--set",
        dest="overrides",
        action="append",
        default=[],
        metavar="KEY=VALUE",
        help="override a case key (dotted, e.g. cargo.length_m=90); repeatable; VALUE is read as YAML",
    )
    p.add_argument(
        "--preset",
        action=_PresetAction,
        choices=("default", "source"),
        help="solver preset: 'source' = the source's method (tanh law, kappa 1000 1/m, H = 5, N = 128, Powell's hybrid "
        "method) for the solver keys the case leaves unset; same as --set solver.preset=source",
    )


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="seafast",
        description="Sea-fastening response of monopiles on heavy-lift vessels: linear and harmonic-balance "
        "(unilateral saddle) analysis of the cargo under hull-girder deflection and ship motions.",
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog="Run 'seafast COMMAND --help' for a command's options and examples.",
    )
    parser.add_argument("--version", action="version", version=f"seafast {seafast.__version__}")
    verbosity = parser.add_mutually_exclusive_group()
    verbosity.add_argument("-v", "--verbose", action="store_true", help="also print debug messages (solver paths, fallbacks, cache hits)")
    verbosity.add_argument("-q", "--quiet", dest="global_quiet", action="store_true", help="print only warnings and errors")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")

    run = sub.add_parser(
        "run",
        help="run a case (default: the built-in base case)",
        epilog=RUN_EXAMPLES,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    run.add_argument("case", nargs="?", help="case file (YAML); omit for the built-in base case")
    run.add_argument("-o", "--output", default="seafast-output", help="output directory (default: %(default)s)")
    _add_set(run)
    run.add_argument("--no-plots", action="store_true", help="skip the PNG figures")
    run.add_argument("-q", "--quiet", action="store_true", help="print only warnings and errors")
    run.set_defaults(handler=_cmd_run)

    init = sub.add_parser(
        "init",
        help="write the base case as an editable, commented YAML file",
        epilog="example:\n  seafast init my_case.yaml && seafast run my_case.yaml",
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    init.add_argument("file", help="path of the case file to write")
    init.add_argument("--force", action="store_true", help="overwrite an existing file")
    init.set_defaults(handler=_cmd_init)

    schema = sub.add_parser(
        "schema",
        help="print the JSON Schema of the case format",
        epilog="example:\n  seafast schema > seafast-case.schema.json",
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    schema.set_defaults(handler=_cmd_schema)

    sweep = sub.add_parser(
        "sweep",
        help="nonlinear frequency response by pseudo-arclength continuation (structural, or --wave: the case's wave amplitude)",
        epilog="examples:\n  seafast sweep --omega-min 0.2 --omega-max 2.0            # wave frequencies: quasi-static?\n"
        "  seafast sweep --set seafastening.saddle_stiffness_N_per_m=1.1e7 --omega-min 0.5 --omega-max 12  # through resonance\n"
        "  seafast sweep --wave --omega-min 0.2 --omega-max 1.8     # nonlinear RAOs of saddle force and bending moment",
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    sweep.add_argument("case", nargs="?", help="case file (YAML); omit for the built-in base case")
    sweep.add_argument("-o", "--output", default="seafast-sweep", help="output directory (default: %(default)s)")
    sweep.add_argument("--omega-min", type=float, default=0.2, help="start frequency [rad/s] (default: %(default)s)")
    sweep.add_argument("--omega-max", type=float, default=2.0, help="end frequency [rad/s] (default: %(default)s)")
    sweep.add_argument(
        "--wave",
        action="store_true",
        help=(
            "wave sweep: at each frequency a wave of the case's amplitude (its hull deflection and RAOs) instead of the case's motions held"
        ),
    )
    sweep.add_argument(
        "--max-gap-m",
        type=float,
        default=None,
        metavar="GAP",
        help="largest detachment gap inside the physically meaningful range [m] (default: 0.1); points beyond are flagged valid=false",
    )
    sweep.add_argument(
        "--follow-beyond-range",
        action="store_true",
        help=(
            "structural sweep: go on past the frequency where the held deck motion accelerates the deck faster than g (default: stop there)"
        ),
    )
    sweep.add_argument("--no-plots", action="store_true", help="skip frequency_response.png")
    _add_set(sweep)
    sweep.set_defaults(handler=_cmd_sweep)

    # the study, sea-state, operability and report commands are defined in their own packages
    from seafast.operability.cli import add_operability_subcommand
    from seafast.output.report.cli import add_report_subcommand
    from seafast.seastate.cli import add_seastate_subcommand
    from seafast.studies.cli import add_study_subcommand

    add_study_subcommand(sub)
    add_seastate_subcommand(sub)
    add_operability_subcommand(sub)
    add_report_subcommand(sub)
    return parser


def _error(message: str) -> int:
    print(f"seafast: error: {message}", file=sys.stderr)
    return EXIT_INVALID_INPUT


def _cmd_run(args: argparse.Namespace) -> int:
    from seafast.config import CaseError, load_case, parse_overrides
    from seafast.output.files import write_run_outputs
    from seafast.output.tables import format_summary_table
    from seafast.pipeline import run_case
    from seafast.results.dataset import LOAD_CASES, MODELS

    try:
        overrides = parse_overrides(args.overrides)
        if args.no_plots:
            overrides["outputs.plots"] = False
        case = load_case(args.case, overrides)
    except CaseError as exc:
        return _error(str(exc))
    source = f"from {args.case}" if args.case else "(built-in base case)"
    logger.info("seafast %s: running '%s' %s", seafast.__version__, case.name, source)
    t0 = time.perf_counter()
    try:
        result = run_case(case, progress=logger.info)
    except (CaseError, ValueError) as exc:
        return _error(str(exc))
    paths = write_run_outputs(result, args.output)
    rows = result.summary
    if not args.quiet:
        print(format_summary_table(rows, title=f"{case.name}: maxima over the cargo, the saddles and one wave period"))
        if result.axial is not None:
            from seafast.output.tables import format_axial_table

            print(format_axial_table(rows))
        print(f"excitation: {result.excitation.source}")
        for status in result.coupling.values():
            print(status.message)
        print(f"wrote {', '.join(str(p) for p in paths.values())} ({time.perf_counter() - t0:.1f} s)")
    if result.axial is not None:
        for line in result.axial.warning_lines():
            print(f"seafast: warning: {line}", file=sys.stderr)
    orbit = getattr(result.responses.get("nonlinear_dynamic"), "orbit", None)
    if orbit is not None and orbit.same_as_start is False:
        print(
            f"seafast: warning: dynamic nonlinear: the time-domain reference started on the {orbit.start_method} solution's "
            f"orbit and settled on ANOTHER periodic state (RMS saddle-force distance {orbit.distance_from_start:.2e} > "
            f"{orbit.orbit_tolerance:g}): that orbit is unstable or not unique; the numbers are the orbit reached",
            file=sys.stderr,
        )
    bad = [r for r in rows if not r["converged"]]
    for r in bad:
        coupling = result.coupling.get((r["load_case"], r["model"]))
        if coupling is not None and not coupling.converged:
            why = (
                f"two-way coupling {coupling.outcome.value.replace('_', ' ')}: coupling residual {coupling.residual_m:.2e} m "
                f"> tolerance {coupling.tolerance_m:.2e} m after {coupling.iterations} step(s)"
            )
        else:
            outcome = result.arrays.solver_outcome[LOAD_CASES.index(r["load_case"]), MODELS.index(r["model"])]
            why = f"{outcome.replace('_', ' ')}, residual {r['residual_norm']:.3e}"
        print(
            f"seafast: warning: {r['load_case']} {r['model']} solution did NOT converge ({why}); "
            "its numbers are flagged converged=false in summary.csv and must not be trusted",
            file=sys.stderr,
        )
    if bad:
        return EXIT_NOT_CONVERGED
    return EXIT_OUTSIDE_VALIDITY if _warn_validity(result) else EXIT_OK


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


def _cmd_sweep(args: argparse.Namespace) -> int:
    from seafast.config import CaseError, load_case, parse_overrides
    from seafast.output.sweep import fold_warning, format_sweep_summary, range_warning, truncation_warning, write_sweep_outputs
    from seafast.sweeps import SweepKind, frequency_sweep

    if not all(map(math.isfinite, (args.omega_min, args.omega_max))) or not (0 < args.omega_min < args.omega_max):
        return _error(f"--omega-min = {args.omega_min}, --omega-max = {args.omega_max}: need 0 < omega-min < omega-max (rad/s)")
    if args.max_gap_m is not None and not (math.isfinite(args.max_gap_m) and args.max_gap_m > 0):
        return _error(f"--max-gap-m = {args.max_gap_m}: need a finite gap > 0 (m)")
    kind = SweepKind.WAVE if args.wave else SweepKind.STRUCTURAL
    try:
        case = load_case(args.case, parse_overrides(args.overrides))
        if kind is SweepKind.WAVE and not case.wave.amplitude_m > 0:
            return _error(f"wave.amplitude_m = {case.wave.amplitude_m}: the wave sweep needs a wave amplitude > 0 (m)")
        result = frequency_sweep(
            case, args.omega_min, args.omega_max, kind=kind, max_gap_m=args.max_gap_m, follow_beyond_range=args.follow_beyond_range
        )
    except (CaseError, ValueError) as exc:
        return _error(str(exc))
    paths = write_sweep_outputs(result, args.output, plots=not args.no_plots)
    if not args.global_quiet:
        w1 = float(result.model.natural_frequencies_rad_s(True, 1)[0])
        for line in format_sweep_summary(result):
            print(line)
        print(f"first natural frequency on bilateral saddles {w1:.3g} rad/s; wrote {', '.join(str(p) for p in paths)}")
    for warning in (range_warning(result), truncation_warning(result), fold_warning(result)):
        if warning is not None:
            print(f"seafast: warning: {warning}", file=sys.stderr)
    if not result.converged:
        print("seafast: warning: some branch points did NOT converge (converged=false in frequency_response.csv)", file=sys.stderr)
    return EXIT_OK if result.converged else EXIT_NOT_CONVERGED


def _cmd_init(args: argparse.Namespace) -> int:
    from seafast.config import base_case_text

    path = Path(args.file)
    if path.exists() and not args.force:
        return _error(f"'{path}' exists; use --force to overwrite it")
    try:
        path.write_text(base_case_text(), encoding="utf-8")
    except OSError as exc:
        return _error(f"cannot write '{path}': {exc.strerror}")
    print(f"wrote {path}: the base case; edit it and run 'seafast run {path}'")
    return EXIT_OK


def _cmd_schema(args: argparse.Namespace) -> int:
    from seafast.config import case_json_schema

    print(json.dumps(case_json_schema(), indent=2))
    return EXIT_OK


def _log_level(args: argparse.Namespace) -> int:
    """DEBUG with --verbose, WARNING with a -q (global or the command's), else INFO."""
    if args.global_quiet or getattr(args, "quiet", False):
        return logging.WARNING
    return logging.DEBUG if args.verbose else logging.INFO


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of the ``seafast`` command; returns the exit code."""
    parser = build_parser()
    args = parser.parse_args(argv)  # --help and --version exit here, before numpy/scipy load
    if not getattr(args, "handler", None):
        parser.print_help()
        return EXIT_OK
    import scipy.linalg  # noqa: F401 - load scipy's BLAS now so the limit below reaches it
    from threadpoolctl import threadpool_limits

    if args.global_quiet and hasattr(args, "quiet"):
        args.quiet = True  # the command's own quiet mode (no tables) follows the global one
    # the package's log records go to stderr for this command only (main can be called again,
    # e.g. by tests or scripts, and must not leave a handler on a stale stream)
    with command_logging(_log_level(args)):
        # seafast's dense solves are small (~100-5000 unknowns): one BLAS thread is fastest on
        # few cores, and leaves the cores to study workers (the BEM step lifts this limit for itself).
        with threadpool_limits(limits=1, user_api="blas"):
            return int(args.handler(args))


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
