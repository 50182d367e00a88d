"""The outcome of a two-way hull-cargo coupling, as values (:func:`seafast.coupling.deck_iteration.couple_deck`).

A record per coupled row that the pipeline, the CLI and the report read field by field; the
one-line message is derived from the fields for people and never parsed. Kept apart from the
numerics so that output code can use the types without importing the solver.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum

__all__ = ["CouplingOutcome", "CouplingStatus"]


class CouplingOutcome(Enum):
    """How a two-way coupling iteration ended."""

    CONVERGED = "converged"
    """The residual is within the tolerance."""
    ITERATION_LIMIT = "iteration_limit"
    """``max_iterations`` quasi-Newton steps without reaching the tolerance."""
    STALLED = "stalled"
    """No step reduced the residual, even from the model's own (finite-difference) Jacobian."""
    NOT_FINITE = "not_finite"
    """The residual is not finite (the cargo solve failed)."""


@dataclass(frozen=True)
class CouplingStatus:
    """The outcome of one two-way coupling (one row: load case and model), as values.

    Attributes
    ----------
    outcome
        How the iteration ended (:class:`CouplingOutcome`).
    iterations
        Quasi-Newton steps taken.
    residual_m
        The coupling's own residual [m]: the largest mismatch, over the coupled harmonics and
        the sea-fastening points, between the deck the cargo stood on and the deck the hull
        gives under the cargo's forces; deflections in m, slopes [rad] times the lever arm
        ``lever_arm_m`` (half the cargo length).
    tolerance_m
        ``relative_tolerance * deck_motion_scale_m`` [m].
    deck_motion_scale_m
        The largest one-way deck harmonic under the sea-fastening [m] (deflection amplitude, or
        slope amplitude times ``lever_arm_m``), relative to the hull's end chord as the deck
        excitation is; at least 1 um.
    relative_tolerance
        The tolerance relative to ``deck_motion_scale_m`` [-].
    lever_arm_m
        Length that turns a slope mismatch into metres [m].
    harmonic_count
        K: harmonics 0 .. K-1 of the deck coupled (1: still water only).
    mean_deck_change_m
        Period-mean deck deflection change under each sea-fastening point, two-way minus
        one-way [m] (up +), shape (n_s,).
    label
        Which row, for messages (e.g. ``"static, nonlinear"``).
    """

    outcome: CouplingOutcome
    iterations: int
    residual_m: float
    tolerance_m: float
    deck_motion_scale_m: float
    relative_tolerance: float
    lever_arm_m: float
    harmonic_count: int
    mean_deck_change_m: tuple[float, ...]
    label: str = ""

    @property
    def converged(self) -> bool:
        """Whether the coupling reached its tolerance."""
        return self.outcome is CouplingOutcome.CONVERGED

    @property
    def message(self) -> str:
        """One line for people (code reads the fields, never this text)."""
        what = "still-water" if self.harmonic_count == 1 else f"harmonics 0..{self.harmonic_count - 1}"
        state = "converged" if self.converged else f"NOT converged ({self.outcome.value.replace('_', ' ')})"
        return (
            f"two-way coupling{(' (' + self.label + ')') if self.label else ''} of the deck, {what}: {state} in "
            f"{self.iterations} quasi-Newton step(s), residual {self.residual_m:.1e} m (tolerance {self.tolerance_m:.1e} m "
            f"= {self.relative_tolerance:g} of the deck motion {1e3 * self.deck_motion_scale_m:.1f} mm); mean deck change "
            f"at the saddles {', '.join(f'{1e3 * d:+.2f}' for d in self.mean_deck_change_m)} mm"
        )
