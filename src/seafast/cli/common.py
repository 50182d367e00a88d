"""What every ``seafast`` command shares: the exit codes, the error line, the case options.

Exit codes: 0 success; 2 invalid input (one clear message on stderr, no traceback); 3 the case
ran but a nonlinear solve did not converge (results are still written, flagged); 4 the case ran
and converged, but a result lies outside the model's small-displacement validity (results
written, flagged ``within_validity = false`` in results.nc; :mod:`seafast.results.validity`), or its peak
saddle force is an elastic impact (``F_within_validity = false``; :mod:`seafast.results.impact`);
130 a study interrupted (its finished points kept).
"""

from __future__ import annotations

import argparse
import sys

__all__ = [
    "EXIT_OK",
    "EXIT_INVALID_INPUT",
    "EXIT_NOT_CONVERGED",
    "EXIT_OUTSIDE_VALIDITY",
    "EXIT_INTERRUPTED",
    "error",
    "add_case_options",
    "add_set_option",
]

EXIT_OK = 0
EXIT_INVALID_INPUT = 2
EXIT_NOT_CONVERGED = 3
EXIT_OUTSIDE_VALIDITY = 4
EXIT_INTERRUPTED = 130


def error(message: str) -> int:
    """Print ``seafast: error: MESSAGE`` on stderr; the invalid-input exit code."""
    print(f"seafast: error: {message}", file=sys.stderr)
    return EXIT_INVALID_INPUT


class PresetAction(argparse.Action):
    """``--preset NAME`` is ``--set solver.preset=NAME``."""

    def __call__(
        self, parser: argparse.ArgumentParser, namespace: argparse.Namespace, values: object, option_string: str | None = None
    ) -> None:
        overrides = list(getattr(namespace, "overrides", None) or [])
        overrides.append(f"solver.preset={values}")
        namespace.overrides = overrides


def add_set_option(p: argparse.ArgumentParser, example: str, what: str = "a case key") -> None:
    """``--set KEY=VALUE`` (repeatable; ``args.overrides``), as every command that takes a case has it.

    ``example``: a dotted ``KEY=VALUE`` the command's users would set; ``what``: what a key names.
    """
    p.add_argument(
        "--set",
        dest="overrides",
        action="append",
        default=[],
        metavar="KEY=VALUE",
        help=f"override {what} (dotted, e.g. {example}); repeatable; VALUE is read as YAML",
    )


def add_case_options(p: argparse.ArgumentParser) -> None:
    """``--set KEY=VALUE`` (:func:`add_set_option`) and ``--preset NAME``, for the commands that solve the cargo's dynamics."""
    add_set_option(p, "cargo.length_m=90")
    p.add_argument(
        "--preset",
        action=PresetAction,
        choices=("default", "source"),
        help="solver preset: 'source' = the source's method (tanh law, kappa 1000 1/m, H = 5, N = 128, Powell's hybrid "
        "method) for the solver keys the case leaves unset; same as --set solver.preset=source",
    )
