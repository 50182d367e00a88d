"""The ``seafast`` command: the parser of every subcommand, and :func:`main`.

One module per command (:mod:`~seafast.cli.run`, :mod:`~seafast.cli.case_file` for ``init`` and
``schema``, :mod:`~seafast.cli.sweep`, :mod:`~seafast.cli.study`, :mod:`~seafast.cli.seastate`,
:mod:`~seafast.cli.operability`, :mod:`~seafast.cli.report`); each defines its subparser and its
handler, which imports the numerical stack it needs when it runs (``seafast --help`` loads none of it).
Exit codes: :mod:`seafast.cli.common`.

Messages: :func:`main` routes the package's logging (``seafast.*`` loggers) to stderr for the
duration of the command (:func:`seafast.cli.console.command_logging`): progress at INFO (shown by
default), warnings as ``seafast: warning: ...``; ``-v/--verbose`` adds DEBUG (solver paths, cache
hits), ``-q/--quiet`` keeps warnings and errors only (``seafast run -q`` and ``seafast study -q``
as well).
"""

from __future__ import annotations

import argparse
import gc
import logging
import sys
from collections.abc import Sequence

from seafast.parallel.threads import default_to_one_thread, one_blas_thread

# Small dense solves are fastest on one BLAS thread on few cores; OpenBLAS reads the variables
# when it is loaded, so they are set before numpy/scipy load (worker processes inherit them). An
# explicit user setting wins.
default_to_one_thread()

# the command modules import the numerical stack in their handlers only: after the thread settings above
import seafast  # noqa: E402
from seafast.cli.case_file import add_init_subcommand, add_schema_subcommand  # noqa: E402
from seafast.cli.common import EXIT_OK  # noqa: E402
from seafast.cli.console import command_logging  # noqa: E402
from seafast.cli.criteria import add_criteria_subcommand  # noqa: E402
from seafast.cli.operability import add_operability_subcommand  # noqa: E402
from seafast.cli.report import add_report_subcommand  # noqa: E402
from seafast.cli.run import add_run_subcommand  # noqa: E402
from seafast.cli.seastate import add_seastate_subcommand  # noqa: E402
from seafast.cli.study import add_study_subcommand  # noqa: E402
from seafast.cli.sweep import add_sweep_subcommand  # noqa: E402

__all__ = ["main", "build_parser"]


def build_parser() -> argparse.ArgumentParser:
    """The ``seafast`` parser with every subcommand (nothing of the numerical stack is imported)."""
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

    for add in (
        add_run_subcommand,
        add_init_subcommand,
        add_schema_subcommand,
        add_sweep_subcommand,
        add_study_subcommand,
        add_seastate_subcommand,
        add_operability_subcommand,
        add_criteria_subcommand,
        add_report_subcommand,
    ):
        add(sub)
    return parser


def _log_level(args: argparse.Namespace) -> int:
    """DEBUG with --verbose, WARNING with a -q (global or the command's), else INFO."""
    if args.global_quiet or getattr(args, "quiet", False):
        return logging.WARNING
    return logging.DEBUG if args.verbose else logging.INFO


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of the ``seafast`` command; returns the exit code.

    ``argv`` None (the ``seafast`` script: the process's own command line, which ends when main
    returns): the objects left are then frozen out of the garbage collector (``gc.freeze``), so
    that the interpreter's shutdown does not walk them all (after a run it took 0.8 s, frozen
    0.08 s). A list of arguments (tests, scripts) leaves the collector as it was.
    """
    parser = build_parser()
    args = parser.parse_args(argv)  # --help and --version exit here, before numpy/scipy load
    if not getattr(args, "handler", None):
        parser.print_help()
        return EXIT_OK
    if args.global_quiet and hasattr(args, "quiet"):
        args.quiet = True  # the command's own quiet mode (no tables) follows the global one
    # the package's log records go to stderr for this command only (main can be called again,
    # e.g. by tests or scripts, and must not leave a handler on a stale stream)
    with command_logging(_log_level(args)):
        # seafast's dense solves are small (~100-5000 unknowns): one BLAS thread is fastest on
        # few cores, and leaves the cores to study workers (the BEM step lifts this limit for itself).
        with one_blas_thread():
            code = int(args.handler(args))
    if argv is None:
        gc.freeze()
    return code


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
