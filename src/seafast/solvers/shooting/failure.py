"""Why an exact-event shooting solve did not converge: a typed reason, recorded in the response's ``options``.

A :class:`~seafast.solvers.periodic.PeriodicResponse` of :func:`~seafast.solvers.shooting.solve_shooting` that is
not converged carries ``options["failure"]``, a :class:`ShootingFailure` (a ``str`` enum: it serialises as its
value); :func:`shooting_failure` reads it back typed. The message says the same for people, with its numbers.
"""

from __future__ import annotations

from enum import StrEnum

from seafast.solvers.periodic import PeriodicResponse

__all__ = ["FAILURE_KEY", "ShootingFailure", "shooting_failure"]

FAILURE_KEY = "failure"
"""The ``options`` key of the reason (absent when the solve converged)."""


class ShootingFailure(StrEnum):
    """Why a shooting solve did not converge.

    ``NOT_PERIODIC``
        Newton's method on the periodic state stopped above ``tolerance`` (the residual is reported).
    ``UNSTABLE_ORBIT``
        The periodic orbit found has a Floquet multiplier above 1: the physical motion does not stay on it.
    ``TOO_MANY_EVENTS``
        More contact events in one period than ``max_events`` (a chattering contact).
    ``SINGULAR_STATE``
        A contact state has no stiffness against a rigid-body motion (every support lifted, no lashing).
    ``CUTOFF_NOT_SETTLED``
        Stiff saddles: the peak forces still moved by more than the modal tolerance after the most doublings of
        the modal cutoff allowed.
    ``IMPACTS_UNRESOLVED``
        Stiff saddles: the finest event grid allowed still misses more than ``peak_tolerance`` of a peak force
        (impacts shorter than its samples resolve).
    """

    NOT_PERIODIC = "not_periodic"
    UNSTABLE_ORBIT = "unstable_orbit"
    TOO_MANY_EVENTS = "too_many_events"
    SINGULAR_STATE = "singular_state"
    CUTOFF_NOT_SETTLED = "cutoff_not_settled"
    IMPACTS_UNRESOLVED = "impacts_unresolved"


def shooting_failure(response: PeriodicResponse) -> ShootingFailure | None:
    """The reason a shooting response did not converge (None: it converged, or it is not a shooting response)."""
    value = response.options.get(FAILURE_KEY)
    return ShootingFailure(value) if isinstance(value, str) and not response.converged else None
