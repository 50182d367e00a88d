"""Exact-event shooting on the piecewise-linear contact problem: the periodic response whatever the ringing.

:mod:`~seafast.solvers.shooting.states` (each contact state's closed-form dynamics),
:mod:`~seafast.solvers.shooting.period` (one period with exact events and its monodromy matrix),
:mod:`~seafast.solvers.shooting.solve` (Newton on the periodic state, :func:`solve_shooting`),
:mod:`~seafast.solvers.shooting.options` (:class:`ShootingOptions`),
:mod:`~seafast.solvers.shooting.failure` (:class:`ShootingFailure`: why a solve did not converge).
"""

from seafast.solvers.shooting.failure import ShootingFailure, shooting_failure
from seafast.solvers.shooting.options import ShootingOptions
from seafast.solvers.shooting.solve import event_samples, solve_shooting

__all__ = ["ShootingFailure", "ShootingOptions", "event_samples", "shooting_failure", "solve_shooting"]
