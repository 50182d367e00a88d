"""Exact-event shooting on the piecewise-linear contact problem: the periodic response whatever the ringing.

:mod:`~seafast.solvers.shooting.states` (each contact state's closed-form dynamics),
:mod:`~seafast.solvers.shooting.period` (one period with exact events and its monodromy matrix),
:mod:`~seafast.solvers.shooting.solve` (Newton on the periodic state, :func:`solve_shooting`),
:mod:`~seafast.solvers.shooting.options` (:class:`ShootingOptions`).
"""

from seafast.solvers.shooting.options import ShootingOptions
from seafast.solvers.shooting.solve import event_samples, solve_shooting

__all__ = ["ShootingOptions", "event_samples", "solve_shooting"]
