"""Windows of the 3-D cargo's correction system marched along a given record of linear engagements.

The march of :mod:`seafast.solvers.cradle_march` (the same :class:`~seafast.solvers.cradle_march.CradleStepper` and
the arithmetic of :func:`~seafast.solvers.cradle_march.march_step`, compiled over blocks of steps in
:mod:`seafast.solvers.cradle_kernels`: Newmark's average acceleration, the exact contact per step) driven
not by a periodic linear solution but by any record ``s_lin(t)`` of every element's linear engagement, e.g. a
random sea's (:mod:`seafast.analyses.seastate.cradle_realisation`). The linear system is the cargo with the elements
``included`` bilateral (the pads and lashings) and the others open (the side stoppers), so the nonlinear response
is ``q = q_lin + q_c`` with ``q_c`` the response to the correction ``c`` (the tension of a bilateral pad or lashing
removed, the force of a closed stopper added)::

    M q_c'' + D q_c' + K_lin q_c = -A^T c,   s = s_lin(t) + A q_c,
    c = k max(-s, 0) (included),   c = k max(s, 0) (open in the linear system).

:func:`march_cradle_window` starts at rest (``q_c = 0``, exact where every element was in its linear state long
enough for the previous correction to have died out) or quasi-statically, marches fine steps while the caller's
trigger says some element may change state, and stops at a coarse sample where none is corrected, the trigger is
off and the free vibration left is below a tolerance (``sum_r max_i |(A Phi)_ir| sqrt(eta_r^2 + (eta_r'/omega_r)^2)``,
a bound on the engagement it can still cause) [m]. Outside windows ``q_c = 0`` exactly.

Units: engagements [m]; forces [N]; time [s].
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from seafast.solvers.cradle_kernels import march_block
from seafast.solvers.cradle_march import CradleStepper, contact_correction_N

__all__ = ["CradleWindow", "march_cradle_window", "quasi_static_state"]

CHUNK_SAMPLES = 16
"""Coarse intervals of the linear record asked for at a time."""


@dataclass(frozen=True)
class CradleWindow:
    """What one window found over its fine steps ``start + 1 .. end``.

    Attributes
    ----------
    end
        The last fine step marched.
    max_force_N, min_force_N
        (m,) every element's largest and least force ``k max(s, 0)`` over the window [N].
    max_abs_output
        (p,) the largest ``|y_lin + y_c|`` of the stepper's outputs [m, rad] (empty without outputs).
    corrected_steps
        (m,) steps each element spent corrected (a pad lifted, a lashing slack, a stopper closed).
    solved
        Every step's contact problem was solved exactly (its complementarity conditions hold to round-off).
    """

    end: int
    max_force_N: NDArray[np.float64]
    min_force_N: NDArray[np.float64]
    max_abs_output: NDArray[np.float64]
    corrected_steps: NDArray[np.int64]
    solved: bool


def quasi_static_state(stepper: CradleStepper, s_lin: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.bool_]]:
    """The correction at rest under the linear engagements ``s_lin`` (m,): the state (eta, 0, 0) and corrected set.

    The static receptance ``A Phi Omega^-2 Phi^T A^T + A R A^T`` (the step's residual part unchanged).
    """
    assert stepper.modal_stiffness is not None
    E, w2 = stepper.engagement_modes, stepper.modal_stiffness
    G0 = E @ (E.T / w2[:, None]) + (stepper.receptance - E @ stepper.flexibility)
    c, chosen = contact_correction_N(0.5 * (G0 + G0.T), stepper.stiffness_N_per_m, s_lin, np.zeros(s_lin.size, dtype=bool), stepper.sign)
    r = w2.size
    x = np.zeros(3 * r)
    x[:r] = -(E.T @ c) / w2
    return x, chosen


def _c(a: NDArray[np.float64]) -> NDArray[np.float64]:
    return np.ascontiguousarray(a, dtype=np.float64)


def march_cradle_window(
    stepper: CradleStepper,
    linear_at: Callable[[int, int], NDArray[np.float64]],
    trigger: NDArray[np.bool_],
    ratio: int,
    start: int,
    last: int,
    tolerance_m: float,
    state: tuple[NDArray[np.float64], NDArray[np.bool_]] | None = None,
) -> CradleWindow:
    """March fine steps from ``start`` (at most to ``last``) until the window may stop (module docstring).

    Parameters
    ----------
    stepper
        The correction system's step (its ``sign`` says which elements are open in the linear system; its outputs,
        if any, are tracked).
    linear_at
        ``(first, count) -> (count, m + p)``: the linear engagements [m] and outputs at fine steps
        ``first .. first + count - 1`` (fine step ``n`` at ``n dt``).
    trigger
        (n_coarse,) some element may change state near coarse sample ``j`` (fine step ``j ratio``).
    ratio
        Fine steps per coarse sample.
    start, last
        The fine step the window starts from and the last one it may reach.
    tolerance_m
        The free vibration left when the window stops [m].
    state
        The state at ``start`` (:func:`quasi_static_state`); default at rest.
    """
    m, k = stepper.stiffness_N_per_m.size, stepper.stiffness_N_per_m
    assert stepper.modal_stiffness is not None
    r = stepper.engagement_modes.shape[1]
    x, chosen = (np.zeros(3 * r), np.zeros(m, dtype=bool)) if state is None else (state[0].copy(), state[1].copy())
    p = 0 if stepper.output_modes is None else stepper.output_modes.shape[0]
    E, F, G = stepper.engagement_modes, stepper.flexibility, stepper.receptance
    sign = np.ones(m) if stepper.sign is None else stepper.sign
    Yo = np.zeros((0, r)) if stepper.output_modes is None else stepper.output_modes
    Yr = np.zeros((0, m)) if stepper.output_residual is None else stepper.output_residual
    ops = (_c(stepper.predictor), _c(F), _c(E), _c(G), _c(G - E @ F), _c(k), _c(sign), _c(Yo), _c(Yr), _c(stepper.modal_stiffness))
    tallies = (np.full(m, -np.inf), np.full(m, np.inf), np.zeros(p), np.zeros(m, dtype=np.int64))
    solved, step, ended = True, start, False
    while step < last and not ended:
        rows = np.ascontiguousarray(linear_at(step + 1, min(CHUNK_SAMPLES * ratio, last - step)))
        x, chosen, step, ended, ok = march_block(
            ops, float(stepper.dt), rows, x, chosen, np.asarray(trigger, dtype=np.bool_), int(ratio), int(step), float(tolerance_m), tallies
        )
        solved = solved and ok
    return CradleWindow(step, tallies[0], tallies[1], tallies[2], tallies[3], solved)
