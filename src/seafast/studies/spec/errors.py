"""The error of every study-file problem."""

from __future__ import annotations

from seafast.config.loader import CaseError

__all__ = ["StudyError"]


class StudyError(CaseError):
    """Invalid study input; the message names the field, the value and what is allowed."""
