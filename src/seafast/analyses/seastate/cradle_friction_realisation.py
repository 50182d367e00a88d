"""One random-phase realisation of a sea state off head seas for the 3-D cargo on frictional pads: nonlinear maxima.

The frictional counterpart of :mod:`seafast.analyses.seastate.cradle_realisation`'s nonlinear model, for the same
realisation (its plan's grid, phases, amplitude factors and, short-crested, directions: the same seed and index give
the same sea). The linear system is the cargo with every element bilateral and the pads stuck at their sliders' rest
(:mod:`seafast.analyses.seastate.cradle_stuck_transfer`); its record (engagements, pads' tangential motions, lateral
displacement at the saddles) is synthesised on the coarse grid from its transfer functions and spline-interpolated
to the fine steps, as the frictionless windows' is; the frictional correction is marched over the whole record
(:func:`~seafast.solvers.cradle_friction_record.march_friction_record`: sliders persist after a slip, so there are
no windows), from the correction at rest and the sliders relaxed in still water, at the frictionless plan's fine
step with the frictional march's modal cutoff. The Monte Carlo (:mod:`seafast.analyses.seastate.monte_carlo`) takes its
nonlinear cradle quantities from here when ``seafastening.friction_coefficient`` is above 0.

Units: SI (forces [N], displacements [m], time [s]).
"""

from __future__ import annotations

import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from seafast.analyses.seastate.cradle_realisation import (
    CradleRealisationPlan,
    fine_interpolant,
    record_extremes,
    record_fractions,
    synthesised_record,
)
from seafast.analyses.seastate.cradle_stuck_transfer import StuckTransfer, stuck_transfer_functions
from seafast.analyses.seastate.synthesis import interpolate_transfer
from seafast.config.schema import Case
from seafast.solvers.cradle_dynamics import CradleDynamics
from seafast.solvers.cradle_friction import relaxed_at
from seafast.solvers.cradle_friction_march import friction_stepper
from seafast.solvers.cradle_friction_record import march_friction_record
from seafast.solvers.cradle_march import STEPS_PER_MODE_PERIOD_INV, CradleStepper
from seafast.solvers.pad_tangential import PadTangents, pad_tangents

__all__ = [
    "FRICTION_QUANTITIES",
    "FrictionalRealisationPlan",
    "case_frictional_plan",
    "evaluate_frictional_cradle_realisation",
    "frictional_realisation_plan",
]

FRICTION_QUANTITIES: tuple[str, ...] = ("pad_friction_utilisation", "pad_slip_m")
"""Per frictional realisation, beside the nonlinear cradle quantities: the largest ``|f| / (mu F_n)`` [-] and slip of a
pad from rest [m]."""

STEP_TOLERANCE = 1e-11
"""A step's problem is solved below this times the realisation's largest stuck linear engagement or motion from the
still water (the periodic march's ``step_tolerance`` on its largest linear amplitude) [-]."""


@dataclass(frozen=True)
class FrictionalRealisationPlan:
    """What a frictional realisation needs beside its :class:`CradleRealisationPlan` (picklable).

    Attributes
    ----------
    still_m
        (m + 2 P + n_s,) the stuck linear still water [m].
    transfer
        (n_f, m + 2 P + n_s) the stuck transfer functions at the grid's components [m/m]; short-crested
        (n_d, n_f, ...), one block per direction.
    tangents, stepper
        The pads' tangential kinematics and friction (sliders' rest in still water); the frictional step at the fine
        step, every cargo DOF an output.
    lateral_dofs
        (n_s,) the lateral DOF at each saddle.
    """

    still_m: NDArray[np.float64]
    transfer: NDArray[np.complex128]
    tangents: PadTangents
    stepper: CradleStepper
    lateral_dofs: NDArray[np.intp]


def frictional_realisation_plan(
    plan: CradleRealisationPlan,
    dynamics: CradleDynamics,
    tangents: PadTangents,
    stuck_at: Callable[[NDArray[np.float64]], Sequence[StuckTransfer]],
    omega_rad_s: NDArray[np.float64],
) -> FrictionalRealisationPlan:
    """The frictional part of ``plan``: the stuck transfer functions ``stuck_at`` (one per direction, as ``plan``'s)
    computed at ``omega_rad_s`` and interpolated to the grid's components, and the frictional step at ``plan``'s
    fine step."""
    held = stuck_at(np.asarray(omega_rad_s, dtype=float))
    per = [interpolate_transfer(omega_rad_s, s.transfer_m, plan.grid.omega_rad_s) for s in held]
    transfer = np.stack(per) if plan.direction_weights is not None else per[0]
    dt = plan.grid.time_step_s / plan.ratio
    stepper = friction_stepper(dynamics, tangents, dt, STEPS_PER_MODE_PERIOD_INV * 2.0 * np.pi / dt)
    return FrictionalRealisationPlan(held[0].still_m, np.ascontiguousarray(transfer), tangents, stepper, held[0].lateral_dofs)


def case_frictional_plan(case: Case, plan: CradleRealisationPlan) -> FrictionalRealisationPlan | None:
    """The frictional part of the case's cradle realisations (``plan``: :func:`~seafast.analyses.seastate.monte_carlo.build_cradle_plan`'s),
    or None when ``seafastening.friction_coefficient`` is unset or 0 (frictionless pads).

    The pads' friction as ``seafast run``'s (:func:`~seafast.analyses.cradle_run.pad_friction_of_case`), the sliders
    relaxed in the still water, the stuck transfer functions at ``plan``'s transfer step over the spectrum's band.
    """
    from seafast.analyses.cradle_run import pad_friction_of_case
    from seafast.analyses.seastate.cradle_transfer import cradle_sea_model, cradle_unit_excitations
    from seafast.analyses.seastate.directional_transfer import sea_state_roll_damping, sea_state_transfer
    from seafast.analyses.seastate.spectrum import sea_state_spectrum
    from seafast.model.from_case import build_model

    friction = pad_friction_of_case(case)
    if friction is None or float(friction.friction_coefficient) == 0.0:
        return None
    model, spectrum = build_model(case), sea_state_spectrum(case)
    roll, sea = sea_state_roll_damping(case, spectrum), cradle_sea_model(case, model)
    lo, hi = float(spectrum.omega_rad_s[0]), float(spectrum.omega_rad_s[-1])
    omega = np.linspace(lo, hi, max(int(np.ceil((hi - lo) / plan.settings.transfer_step_rad_s)) + 1, 8))
    still = cradle_unit_excitations(sea, sea_state_transfer(case, model, omega[:1], roll).per_direction[0])[0].still_water()
    dynamics = sea.dynamics
    tangents = relaxed_at(pad_tangents(dynamics.problem, friction, dynamics.deck_x_m, dynamics.gravity_m_per_s2), dynamics, still)

    def stuck_at(w: NDArray[np.float64]) -> list[StuckTransfer]:
        return [stuck_transfer_functions(sea, tf, tangents) for tf in sea_state_transfer(case, model, w, roll).per_direction]

    return frictional_realisation_plan(plan, dynamics, tangents, stuck_at, omega)


def evaluate_frictional_cradle_realisation(plan: CradleRealisationPlan, friction: FrictionalRealisationPlan, index: int) -> dict[str, Any]:
    """The nonlinear cradle extremes of realisation ``index`` on frictional pads.

    Returns
    -------
    dict
        ``{"nonlinear": {...}, "solved", "unresolved_steps", "slipped_fraction", "seconds"}``: the frictionless nonlinear model's
        quantities (:data:`~seafast.analyses.seastate.cradle_realisation.CRADLE_QUANTITIES`, pad lifted and lashing
        slack fractions) and ``pad_friction_utilisation`` [-], ``pad_slip_m`` [m] (each pad's largest ``|f| /
        (mu F_n)`` and slider displacement from rest, the largest over the pads).
    """
    t0 = time.perf_counter()
    dynamic = synthesised_record(plan, friction.transfer, index)[0]
    n_z = plan.element_count + 2 * friction.tangents.pad_count
    tolerance = STEP_TOLERANCE * max(float(np.max(np.abs(dynamic[:, :n_z]))), 1e-12)
    linear_at = fine_interpolant(plan, friction.still_m + dynamic)
    steps = plan.grid.samples * plan.ratio - 1
    record = march_friction_record(friction.stepper, friction.tangents, linear_at, steps, tolerance, 0, friction.lateral_dofs)
    nonlinear = {
        **record_extremes(plan, record.max_force_N, record.min_force_N, record.max_abs_output),
        **record_fractions(plan, record.negative_fraction),
        "pad_friction_utilisation": float(np.max(record.friction_utilisation, initial=0.0)),
        "pad_slip_m": float(np.max(record.max_slip_m, initial=0.0)),
    }
    return {
        "nonlinear": nonlinear,
        "solved": record.solved,
        "unresolved_steps": record.unresolved_steps,
        "slipped_fraction": record.slipped_steps / float(steps),
        "seconds": time.perf_counter() - t0,
    }
