"""The errors of the shared machinery: a run that cannot start as asked."""

from __future__ import annotations

from pathlib import Path
from typing import Any

__all__ = ["ParallelError", "ForeignStoreError"]


class ParallelError(ValueError):
    """A run cannot start as asked: invalid execution options, an unreachable scheduler, a store of another run.

    The message names the option or the directory, the value and what is allowed.
    """


class ForeignStoreError(ParallelError):
    """The output directory holds another run (another fingerprint).

    Attributes
    ----------
    path : Path
        The file that holds the other run (the manifest, or a record line of the records file).
    held : dict
        The manifest read from the directory (``{"fingerprint": ...}`` of the record line when a
        line disagrees; ``{}`` when the manifest cannot be read).
    fingerprint : str
        This run's fingerprint.
    """

    def __init__(self, message: str, path: Path, held: dict[str, Any], fingerprint: str) -> None:
        super().__init__(message)
        self.path = path
        self.held = held
        self.fingerprint = fingerprint
