"""Typed warnings about the model itself (not about a solve), as :class:`ModelWarning` values.

A solver's warnings are :class:`~seafast.solvers.outcome.SolverWarning` values on its response;
a model's are on the model (:attr:`seafast.model.structure.StructuralModel.warnings`), or, for a result the
model cannot give although the solve converged (``SADDLE_FORCE_ELASTIC_IMPACT``), on the row the run reads it
from (:mod:`seafast.results.impact`). Both reach
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
    ``SADDLE_FORCE_ELASTIC_IMPACT``
        The dynamic nonlinear row's peak saddle force is an elastic impact at a re-contact (near-rigid saddles):
        its impact estimate ``v G(k)`` (the re-contact's approach velocity times the beam's impact force per unit
        velocity) exceeds :data:`seafast.results.impact.IMPACT_RATIO_LIMIT` times the force the saddle carries with
        its contact kept, and the peak then grows with the saddle stiffness ``k`` (the force is no answer; the
        bending moment and the displacements remain valid). Raised from the solution
        (:func:`seafast.results.impact.impact_check`), not by the model.
    """

    RAYLEIGH_FALLBACK = "rayleigh_fallback"
    SADDLE_FORCE_ELASTIC_IMPACT = "saddle_force_elastic_impact"

    @property
    def dynamic_only(self) -> bool:
        """Whether it concerns the motion only (the static rows, still water, are not affected)."""
        return self in (ModelWarning.RAYLEIGH_FALLBACK, ModelWarning.SADDLE_FORCE_ELASTIC_IMPACT)

    @property
    def description(self) -> str:
        """One line for people (CLI, report)."""
        return _DESCRIPTIONS[self]


_DESCRIPTIONS = {
    ModelWarning.RAYLEIGH_FALLBACK: "Rayleigh damping cannot give the first two modes model.damping_ratio; the fallback "
    "realises a ratio more than 10 % off in one of them (dynamic rows)",
    ModelWarning.SADDLE_FORCE_ELASTIC_IMPACT: "the peak saddle force is an elastic impact at a re-contact (near-rigid "
    "saddles): it grows with the saddle stiffness, not an answer (use a measured saddle stiffness, a mesh study); "
    "the bending moment and the displacements remain valid",
}
