"""``seafast study``: run a built-in or file-defined parametric study.

Usage::

    seafast study NAME|FILE [-o DIR] [--set KEY=VALUE ...] [--workers N | --scheduler ADDRESS]
                  [--batch-size N] [--no-progress] [--no-figures] [-q]

Writes ``DIR/study.nc``, ``DIR/study.csv``, ``DIR/compliance.csv``, ``DIR/ranking.csv`` and PNG
figures; ``DIR/points.jsonl`` is the resumable store (rerun the same command after an
interruption). Exit code 0 on success, 2 on invalid input (one message on stderr).
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from seafast.cli.common import EXIT_INTERRUPTED, EXIT_OK, add_set_option, error

__all__ = ["add_study_subcommand", "build_study_parser", "cmd_study", "main"]


STUDY_EXAMPLES = """built-in studies: saddles, lashing, cargo, cargo-saddles-8m, cargo-saddles-12m

examples:
  seafast study saddles -o out/saddles                 # all cores
  seafast study lashing --workers 1                    # serial
  seafast study my_study.yaml --set wave.amplitude_m=2 # a study file, base case overridden
  seafast study cargo --scheduler tcp://10.0.0.5:8786  # a Dask cluster
  seafast study saddles --response sea_state            # ranked by the nonlinear MPM in the base case's sea state
An interrupted study resumes when the same command is run again (finished points are kept).

study file (YAML):
  name: my-study
  base: my_case.yaml            # optional; default the built-in base case
  set: {wave.amplitude_m: 2.5}  # optional overrides of the base case
  axes:
    - {key: seafastening.saddle_count, values: [2, 3, 4]}
    - {key: seafastening.saddle_stiffness_N_per_m, start: 1.1e7, stop: 1.1e10, num: 20, scale: log}
  derived: {cargo.wall_thickness_m: cargo.diameter_m / 110}   # optional
  limits: {max_saddle_force_N: 7.0e6, max_bending_stress_Pa: 20.0e6}
  response: sea_state           # optional: judge points on their sea state's MPMs (default when an axis is sea_state.*)
"""


def _configure(parser: argparse.ArgumentParser) -> argparse.ArgumentParser:
    parser.add_argument("study", metavar="NAME|FILE", help="built-in study name or study file (YAML)")
    parser.add_argument("-o", "--output", default=None, help="output directory (default: study-NAME)")
    add_set_option(parser, "wave.amplitude_m=2", "a key of the study's base case")
    where = parser.add_mutually_exclusive_group()
    where.add_argument("--workers", type=int, default=None, metavar="N", help="local worker processes (default: all cores; 1 = serial)")
    where.add_argument("--scheduler", default=None, metavar="ADDRESS", help="Dask distributed scheduler address, e.g. tcp://host:8786")
    parser.add_argument("--batch-size", type=int, default=None, metavar="N", help="points per task (default: automatic, at most 25)")
    parser.add_argument(
        "--response",
        choices=("regular_wave", "sea_state"),
        default=None,
        help="judge points on the regular wave (seafast run) or on their sea state's most probable maxima "
        "(linear spectral, nonlinear design waves); overrides the study file's response",
    )
    parser.add_argument(
        "--no-progress", action="store_true", help="no progress (a bar on a terminal, else a line every few per cent; also off with -q)"
    )
    parser.add_argument("--no-figures", action="store_true", help="skip the PNG figures")
    parser.add_argument("-q", "--quiet", action="store_true", help="print only warnings and errors")
    parser.set_defaults(handler=cmd_study)
    return parser


def add_study_subcommand(subparsers: Any) -> argparse.ArgumentParser:
    """Register ``study`` on an argparse sub-parsers object; returns the sub-parser."""
    parser = subparsers.add_parser(
        "study",
        help="run a parametric study (built-in NAME or a study FILE) and check design limits",
        description="Run a parametric study over case keys, check the design limits and rank compliant arrangements.",
        epilog=STUDY_EXAMPLES,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    return _configure(parser)


def build_study_parser() -> argparse.ArgumentParser:
    """A stand-alone parser for ``python -m seafast.cli.study``."""
    parser = argparse.ArgumentParser(
        prog="seafast study",
        description="Run a parametric study over case keys, check the design limits and rank compliant arrangements.",
        epilog=STUDY_EXAMPLES,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    return _configure(parser)


def cmd_study(args: argparse.Namespace) -> int:
    """Handler of ``seafast study``; returns the exit code."""
    from seafast.config.loader import CaseError, parse_overrides
    from seafast.parallel.executor import ExecutionOptions
    from seafast.studies.limits import (
        COMPLIANCE_COLUMNS,
        RANKING_COLUMNS,
        DesignLimits,
        compliance_rows,
        format_table,
        rank_compliant,
        write_rows_csv,
    )
    from seafast.studies.runner import run_study
    from seafast.studies.spec import build_grid, load_study_spec, study_spec_from_mapping

    say = (lambda *a: None) if args.quiet else (lambda *a: print(*a, file=sys.stderr))
    if args.workers is not None and args.workers < 1:
        return error(f"--workers {args.workers}: allowed: 1 (serial) or more processes")
    if args.batch_size is not None and args.batch_size < 1:
        return error(f"--batch-size {args.batch_size}: allowed: 1 or more points per task")
    try:
        overrides = parse_overrides(args.overrides)
        spec, directory = load_study_spec(args.study)
        if args.response is not None and args.response != spec.response:
            spec = study_spec_from_mapping(
                {**spec.model_dump(mode="json", exclude_none=True), "response": args.response}, f"'{args.study}'"
            )
        grid = build_grid(spec, directory, overrides)
    except CaseError as exc:
        return error(str(exc))
    out = Path(args.output or f"study-{spec.name}")
    execution = ExecutionOptions(args.workers, args.scheduler, args.batch_size, progress=not (args.no_progress or args.quiet))
    where = {"serial": "serially", "processes": f"on {execution.worker_count()} local processes", "dask": f"on Dask at {args.scheduler}"}
    say(f"study '{spec.name}': {grid.size} points over {' x '.join(grid.keys)} {where[execution.mode()]} -> {out}")
    try:
        run = run_study(grid, out, execution=execution)
    except CaseError as exc:
        return error(str(exc))
    except KeyboardInterrupt:
        print(f"seafast: interrupted; finished points are kept in {out}; rerun the same command to resume", file=sys.stderr)
        return EXIT_INTERRUPTED
    limits = DesignLimits.from_spec(spec.limits)
    comp_rows = compliance_rows(run.dataset, limits)
    ranking = rank_compliant(run.dataset, limits)
    keys = list(grid.keys)
    write_rows_csv(out / "compliance.csv", comp_rows, [*keys, *COMPLIANCE_COLUMNS])
    ranking_columns = ["rank", "saddle_count", *[k for k in keys if k != "seafastening.saddle_count"], *RANKING_COLUMNS[2:]]
    write_rows_csv(out / "ranking.csv", ranking, ranking_columns)
    figures = []
    if not args.no_figures:
        from seafast.output.study_plots import plot_study

        # the figures lay out the study's axes, load case and model; the warning flags are not drawn
        figures = plot_study(run.dataset.drop_dims("warning", errors="ignore"), out, limits)
    say(
        f"{run.points} points: {run.computed} computed, {run.reused} reused from {run.files['store']}, "
        f"{run.failed} failed; {run.seconds:.1f} s ({run.points_per_second:.1f} points/s)"
    )
    if run.failed:
        first = next(str(e) for e in run.dataset["error"].values.ravel() if str(e))
        print(f"seafast: warning: {run.failed} point(s) failed (error recorded per point in study.csv); first: {first}", file=sys.stderr)
    if "nonlinear" in run.dataset["model"]:
        evaluated = run.dataset["error"] == ""
        diverged = ~run.dataset["converged"].sel(model="nonlinear").all("load_case") & evaluated
        if int(diverged.sum()):
            say(
                f"note: at {int(diverged.sum())} point(s) the nonlinear solver did not converge "
                "(converged=false in study.csv; such points never count as compliant)"
            )
    if not args.quiet:
        compliant = sum(1 for r in comp_rows if r.get("complies_nonlinear"))
        print(
            f"study {spec.name}: {compliant} of {len(comp_rows)} points comply with F <= {limits.max_saddle_force_N / 1e6:g} MN "
            f"and sigma_b <= {limits.max_bending_stress_Pa / 1e6:g} MPa"
            + "".join(f", {column} <= {value:g}" for column, value in limits.cradle_limits().items())
            + " (nonlinear model, total response); "
            f"linear model: {sum(1 for r in comp_rows if r.get('complies_linear'))}"
        )
        print("compliant arrangements, fewest saddles first, then largest margin:")
        print(format_table(ranking, ranking_columns, max_rows=15))
        written = [run.files["netcdf"], run.files["csv"], out / "compliance.csv", out / "ranking.csv", *figures]
        print("wrote " + ", ".join(str(p) for p in written))
    return EXIT_OK


def main(argv: Sequence[str] | None = None) -> int:
    """``python -m seafast.cli.study``: the ``seafast study`` command on its own (messages as ``seafast study``'s)."""
    import logging

    from seafast.cli.console import command_logging

    args = build_study_parser().parse_args(argv)
    with command_logging(logging.WARNING if args.quiet else logging.INFO):
        return int(args.handler(args))


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
