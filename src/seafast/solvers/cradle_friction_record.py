"""The frictional correction of the 3-D cargo marched along a given record of its stuck linear response.

The frictional march of :mod:`seafast.solvers.cradle_friction_march` (the same stepper,
:func:`~seafast.solvers.cradle_friction_march.friction_stepper`, and the same per-step problem: the normal law and
each pad's friction-cone return map, solved by the semi-smooth Newton), compiled over blocks of fine steps in
:mod:`seafast.solvers.friction_kernels`, driven not by a periodic linear solution but by any record ``z_s(t)`` of
the stuck linear system's engagements and pads' tangential motions (every element bilateral, every pad's tangential
spring stuck at its slider's rest), e.g. a random sea's. The nonlinear response is ``z = z_s + [A; A_t] q_c`` with
``q_c`` the response to the corrections ``C = [k max(-s, 0); -k_t (w - delta_rest)]``. Sliders persist after a slip,
so the record is marched whole, from the correction at rest and the sliders at rest (no windows). The record's
maxima are kept, not its samples.

Units: engagements and motions [m]; forces [N]; time [s].
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from seafast.solvers.cradle_march import CradleStepper
from seafast.solvers.friction_kernels import march_friction_block
from seafast.solvers.pad_tangential import PadTangents

__all__ = ["FrictionRecord", "march_friction_record"]

CHUNK_STEPS = 4096
"""Fine steps of the linear record asked for at a time."""


@dataclass(frozen=True)
class FrictionRecord:
    """The maxima of a frictional march along a record (the steps after ``measured_from``).

    Attributes
    ----------
    max_force_N, min_force_N
        (m,) every element's largest and least force ``k max(s, 0)`` [N] (a stopper's ``s`` its overclosure).
    friction_utilisation
        (P,) each pad's largest ``|f| / (mu F_n)`` [-] (1 in slip; open pads carry no limit and are skipped).
    max_slip_m
        (P,) each pad's largest slider displacement from rest ``|w - w_rest|`` [m].
    max_abs_output
        (o,) the largest ``|q|`` of each output DOF of the cargo (the stuck linear part and the correction's) [m, rad].
    negative_fraction
        (m,) the fraction of the steps each element's engagement is below 0 (a pad lifted, a lashing slack) [-].
    slipped_steps, unresolved_steps, steps
        Steps where some pad slipped, steps whose problem missed the tolerance, steps marched (all of the record).
    """

    max_force_N: NDArray[np.float64]
    min_force_N: NDArray[np.float64]
    friction_utilisation: NDArray[np.float64]
    max_slip_m: NDArray[np.float64]
    max_abs_output: NDArray[np.float64]
    negative_fraction: NDArray[np.float64]
    slipped_steps: int
    unresolved_steps: int
    steps: int

    @property
    def solved(self) -> bool:
        """Every step's problem solved to the tolerance."""
        return self.unresolved_steps == 0


def march_friction_record(
    stepper: CradleStepper,
    tangents: PadTangents,
    linear_at: Callable[[int, int], NDArray[np.float64]],
    steps: int,
    tolerance_m: float,
    measured_from: int = 0,
    outputs: NDArray[np.intp] | None = None,
) -> FrictionRecord:
    """March the frictional correction over ``steps`` fine steps of a stuck linear record (module docstring).

    Parameters
    ----------
    stepper
        :func:`~seafast.solvers.cradle_friction_march.friction_stepper` of the cargo and ``tangents`` at the step.
    tangents
        The pads' tangential kinematics, friction and sliders' rest.
    linear_at
        ``(first, count) -> (count, m + 2 P + o)`` the stuck linear engagements and tangential motions, then the
        stuck linear displacements of the ``outputs``, at the fine steps ``first .. first + count - 1`` [m, rad].
    steps
        Fine steps marched (from step 0, the correction and sliders at rest).
    tolerance_m
        A step's problem is solved when ``max |R|`` is below this [m] (the periodic march's ``step_tolerance``
        times the largest linear amplitude).
    measured_from
        The maxima and fractions are those of the steps ending after this step (0: the whole record).
    outputs
        The cargo DOFs whose largest ``|q|`` is kept (None: none).
    """
    if int(steps) < 1 or not 0 <= int(measured_from) < int(steps):
        raise ValueError(f"steps = {steps!r}, measured_from = {measured_from!r}: allowed steps >= 1 and 0 <= measured_from < steps")
    m = stepper.stiffness_N_per_m.size - 2 * tangents.pad_count
    P, r = tangents.pad_count, stepper.flexibility.shape[0]
    chosen = np.zeros(0, dtype=np.intp) if outputs is None else np.asarray(outputs, dtype=np.intp)
    assert stepper.output_modes is not None and stepper.output_residual is not None
    matrices = (stepper.predictor, stepper.engagement_modes, stepper.flexibility, stepper.receptance)
    system = tuple(np.ascontiguousarray(a) for a in (*matrices, stepper.output_modes[chosen], stepper.output_residual[chosen]))
    kt = np.asarray(tangents.stiffness_N_per_m, dtype=float)
    mu_kn = np.asarray(tangents.friction_coefficient * tangents.normal_stiffness_N_per_m, dtype=float) * np.ones(P)
    rest = np.ascontiguousarray(tangents.rest_m, dtype=float).ravel()
    law = (np.ascontiguousarray(stepper.stiffness_N_per_m[:m]), kt * np.ones(P), mu_kn, rest, m, P)
    state = (np.zeros(3 * r), np.zeros(m + 2 * P), rest.reshape(P, 2).copy())
    tallies = [_empty_tally(m, P, chosen.size) for _ in range(2)]  # before measured_from, then after
    position = 0
    while position < steps:
        end = min(position + CHUNK_STEPS, int(steps) if position >= measured_from else int(measured_from))
        block = np.ascontiguousarray(linear_at(position, end - position + 1), dtype=float)
        march_friction_block(block, system, law, float(stepper.dt), float(tolerance_m), state, tallies[position >= measured_from])
        position = end
    counts = tallies[0][4] + tallies[1][4]
    force_max, force_min, utilisation, slip, _, output_max, negative = tallies[1]
    fraction = negative / float(int(steps) - int(measured_from))
    return FrictionRecord(force_max, force_min, utilisation, slip, output_max, fraction, int(counts[0]), int(counts[1]), int(steps))


def _empty_tally(m: int, P: int, o: int) -> tuple[NDArray, ...]:
    """(largest force, least force, utilisation, slip, counts, largest |output|, negative steps) before any step."""
    counts, negative = np.zeros(2, dtype=np.int64), np.zeros(m, dtype=np.int64)
    return (np.full(m, -np.inf), np.full(m, np.inf), np.zeros(P), np.zeros(P), counts, np.zeros(o), negative)
