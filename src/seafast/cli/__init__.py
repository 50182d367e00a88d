"""The ``seafast`` command line, one module per command (:mod:`seafast.cli.command` builds the parser and runs it)."""

from __future__ import annotations

from seafast.cli.command import build_parser, main
from seafast.cli.common import EXIT_INVALID_INPUT, EXIT_NOT_CONVERGED, EXIT_OK, EXIT_OUTSIDE_VALIDITY

__all__ = ["main", "build_parser", "EXIT_OK", "EXIT_INVALID_INPUT", "EXIT_NOT_CONVERGED", "EXIT_OUTSIDE_VALIDITY"]
