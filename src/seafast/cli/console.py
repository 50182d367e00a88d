"""How a command prints the package's messages: its log records on stderr for the command's duration.

``seafast`` (:func:`seafast.cli.command.main`) and ``python -m seafast.cli.study`` route the records
of the ``seafast.*`` loggers to stderr while the command runs (:func:`command_logging`):
progress at INFO as plain lines, warnings and errors as ``seafast: warning: ...``, debug lines
with their logger's name (:class:`CliFormatter`).
"""

from __future__ import annotations

import logging
import sys
from collections.abc import Iterator
from contextlib import contextmanager

__all__ = ["CliFormatter", "command_logging"]


class CliFormatter(logging.Formatter):
    """Progress as plain lines; warnings and errors as ``seafast: warning: ...``; debug with its logger."""

    def format(self, record: logging.LogRecord) -> str:
        message = record.getMessage()
        if record.levelno >= logging.WARNING:
            return f"seafast: {record.levelname.lower()}: {message}"
        if record.levelno < logging.INFO:
            return f"seafast: debug: {record.name}: {message}"
        return message


@contextmanager
def command_logging(level: int) -> Iterator[None]:
    """The ``seafast`` logger's records at ``level`` and up go to stderr inside the block, and only there.

    The handler is removed and the logger's level and propagation restored on exit, so the
    command can run again (tests, scripts) without a handler on a stale stream.
    """
    package_logger = logging.getLogger("seafast")
    handler = logging.StreamHandler(sys.stderr)
    handler.setFormatter(CliFormatter())
    saved = package_logger.level, package_logger.propagate
    package_logger.addHandler(handler)
    package_logger.setLevel(level)
    package_logger.propagate = False
    try:
        yield
    finally:
        package_logger.removeHandler(handler)
        package_logger.setLevel(saved[0])
        package_logger.propagate = saved[1]
