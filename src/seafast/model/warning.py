"""Typed warnings about the model itself (not about a solve), as :class:`ModelWarning` values.

A solver's warnings are :class:`~seafast.solvers.outcome.SolverWarning` values on its response;
a model's are on the model (:attr:`seafast.model.structure.StructuralModel.warnings`). Both reach
the summary rows (``warnings``) and a study's ``study.csv`` / ``study.nc``; nothing decides
anything from a message's text. The values (``"rayleigh_fallback"``) are what the files store.
"""

from __future__ import annotations

from enum import Enum

__all__ = ["ModelWarning"]


class ModelWarning(Enum):
    """A model whose results need a second look.

    ``RAYLEIGH_FALLBACK``
        Rayleigh damping cannot give both of the first two modes (cargo on bilateral saddles, deck
        fixed) ``model.damping_ratio`` with non-negative, moderate coefficients; the fallback
        (:func:`seafast.model.damping.fit_rayleigh_to_modes`) realises a ratio more than
        :data:`seafast.model.damping.RAYLEIGH_FALLBACK_TOLERANCE` (10 %) off the requested one in
        one of them. It changes the dynamic rows only (still water has no velocity).
    """

    RAYLEIGH_FALLBACK = "rayleigh_fallback"

    @property
    def dynamic_only(self) -> bool:
        """Whether it concerns the motion only (the static rows, still water, are not affected)."""
        return self is ModelWarning.RAYLEIGH_FALLBACK

    @property
    def description(self) -> str:
        """One line for people (CLI, report)."""
        return _DESCRIPTIONS[self]


_DESCRIPTIONS = {
    ModelWarning.RAYLEIGH_FALLBACK: "Rayleigh damping cannot give the first two modes model.damping_ratio; the fallback "
    "realises a ratio more than 10 % off in one of them (dynamic rows)",
}
