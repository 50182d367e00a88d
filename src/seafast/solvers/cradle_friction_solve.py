"""The cargo on frictional pads, solved: the harmonic balance, else the time march (:func:`solve_cradle_friction`).

1. The frictional harmonic balance (:func:`~seafast.solvers.cradle_friction.solve_cradle_friction_hbm`) with the
   given settings: where it converges (or ``mu`` = 0) its result is returned as it is.
2. Otherwise the time march (:func:`~seafast.solvers.cradle_friction_march.march_cradle_friction`) at N steps a
   period, then (unless it does not repeat) at 2 N with the same modes from the state the first reached (the
   step-halving check). The step
   error is the largest change of a peak between the two (each pad's peak and least normal force and peak friction
   force over the largest pad force, each pad's largest slip over the largest slip, every element's peak force over
   the largest element force) [-].
3. Where both marches repeat every wave period, Newton of the harmonic balance started from the finer march's
   periodic state (its engagements and tangential motions projected on the H harmonics): if it converges and its
   peaks agree with the march's within the step tolerance, that is the answer at H (``CONVERGED``, the route in its
   message).
4. Otherwise the finer march's answer: ``CONVERGED_BY_TIME_MARCH`` (``CONVERGED_SUBHARMONIC`` over its
   ``period_multiple`` wave periods where it repeats only after several) when both marches settle on the same
   periodicity, every step's problem was solved and the step error is within :data:`STEP_TOLERANCE`, its residual
   the step error; ``NOT_PERIODIC`` (the period change as residual) where the march does not repeat;
   ``NOT_CONVERGED`` (the step error, or 1 with unresolved steps, as residual) otherwise. Never raised.

Units: SI.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
from numpy.typing import NDArray

from seafast.excitation.cradle_loads import CradleExcitation
from seafast.model.pad_friction import PadFriction
from seafast.solvers.cradle_dynamics import CradleDynamics
from seafast.solvers.cradle_friction import FrictionHBMOptions, solve_cradle_friction_hbm
from seafast.solvers.cradle_friction_march import FrictionalMarch, FrictionMarchOptions, march_cradle_friction
from seafast.solvers.cradle_march import STEPS_PER_MODE_PERIOD_INV, Periodicity
from seafast.solvers.cradle_response import cradle_response
from seafast.solvers.friction_cone import ConePeriod
from seafast.solvers.outcome import SolverOutcome
from seafast.solvers.pad_tangential import FrictionalCradleResponse, frictional_response

__all__ = ["STEP_TOLERANCE", "solve_cradle_friction", "march_peaks"]

STEP_TOLERANCE = 5e-3
"""The largest step error (the change of a peak from N to 2 N steps a period, module docstring) of a converged march."""


@dataclass(frozen=True)
class _Marched:
    """The two marches and what they say."""

    coarse: FrictionalMarch
    fine: FrictionalMarch
    step_error: float


def march_peaks(response: FrictionalCradleResponse) -> tuple[NDArray[np.float64], ...]:
    """The peaks the step check compares, each over its own scale [-]: every element's peak force, the pads' least
    normal force and peak friction force (over the largest pad force), each pad's largest slip (over the largest)."""
    force = response.cradle.element_force_N
    pad = max(float(np.max(response.normal_force_N)), 1e-300)
    slip = max(float(np.max(response.max_slip_m)), 1e-300)
    return (
        np.max(force, axis=0) / max(float(np.max(force)), 1e-300),
        np.min(response.normal_force_N, axis=0) / pad,
        response.max_friction_N / pad,
        response.max_slip_m / slip,
    )


def _peak_change(a: FrictionalCradleResponse, b: FrictionalCradleResponse) -> float:
    """The largest change of :func:`march_peaks` between two responses, on the second's scales [-]."""
    force = max(float(np.max(b.cradle.element_force_N)), 1e-300)
    pad = max(float(np.max(b.normal_force_N)), 1e-300)
    slip = max(float(np.max(b.max_slip_m)), 1e-300)
    pairs = (
        (np.max(a.cradle.element_force_N, axis=0), np.max(b.cradle.element_force_N, axis=0), force),
        (np.min(a.normal_force_N, axis=0), np.min(b.normal_force_N, axis=0), pad),
        (a.max_friction_N, b.max_friction_N, pad),
        (a.max_slip_m, b.max_slip_m, slip),
    )
    return max(float(np.max(np.abs(x - y))) / s for x, y, s in pairs)


def solve_cradle_friction(
    dynamics: CradleDynamics,
    friction: PadFriction,
    excitation: CradleExcitation,
    options: FrictionHBMOptions | None = None,
    *,
    rest: CradleExcitation | None = None,
    march: FrictionMarchOptions | None = None,
) -> FrictionalCradleResponse:
    """The periodic response on frictional pads: the harmonic balance where it converges, else the time march.

    Parameters
    ----------
    dynamics, friction, excitation, options, rest
        As :func:`~seafast.solvers.cradle_friction.solve_cradle_friction_hbm`.
    march
        The coarser march's settings (N; the finer takes 2 N with the same modes). None: the defaults.

    Returns
    -------
    FrictionalCradleResponse
        The harmonic balance's (its grid, H), or the finer march's (2 N samples a wave period, ``harmonics`` N - 1,
        the harmonics they carry, as the shooting's):
        outcome and residual as the module docstring.
    """
    hbm = solve_cradle_friction_hbm(dynamics, friction, excitation, options, rest=rest)
    if hbm.converged or float(friction.friction_coefficient) == 0.0:
        return hbm
    march = march if march is not None else FrictionMarchOptions()
    marched = _march_twice(dynamics, friction, excitation, march, rest)
    fine = _march_response(dynamics, excitation, marched, hbm)
    if fine.converged and marched.fine.periodicity is Periodicity.PERIODIC:
        s, delta = marched.fine.engagement_m, marched.fine.tangential_m
        samples = np.concatenate([s, delta.reshape(s.shape[0], -1)], axis=1)
        restarted = solve_cradle_friction_hbm(dynamics, friction, excitation, options, rest=rest, start=samples)
        if restarted.converged and _peak_change(restarted, fine) <= STEP_TOLERANCE:
            note = f"; the time march agrees on the peaks within {_peak_change(restarted, fine):.1e}"
            return replace(restarted, cradle=replace(restarted.cradle, message=restarted.cradle.message + note))
    return fine


def _march_twice(
    dynamics: CradleDynamics,
    friction: PadFriction,
    excitation: CradleExcitation,
    march: FrictionMarchOptions,
    rest: CradleExcitation | None,
) -> _Marched:
    """The march at N, then at 2 N with the same modes from the state the first reached."""
    N = int(march.time_samples)
    cutoff = march.cutoff_rad_s
    if cutoff is None:
        cutoff = STEPS_PER_MODE_PERIOD_INV * float(excitation.omega_rad_s) * N
    coarse, state = march_cradle_friction(dynamics, friction, excitation, replace(march, cutoff_rad_s=cutoff), rest=rest)
    if coarse.periodicity is Periodicity.NOT_PERIODIC:  # nothing to check the step on
        return _Marched(coarse, coarse, np.inf)
    fine, _ = march_cradle_friction(
        dynamics, friction, excitation, replace(march, time_samples=2 * N, cutoff_rad_s=cutoff), rest=rest, start=state
    )
    change = _peak_change(_response(dynamics, excitation, coarse), _response(dynamics, excitation, fine))
    return _Marched(coarse, fine, change)


def _response(
    dynamics: CradleDynamics,
    excitation: CradleExcitation,
    march: FrictionalMarch,
    outcome: tuple[SolverOutcome, float, str] = (SolverOutcome.NOT_CONVERGED, np.inf, ""),
) -> FrictionalCradleResponse:
    """A march as a :class:`FrictionalCradleResponse` (over its ``period_multiple`` wave periods)."""
    multiple = max(march.period_multiple, 1)
    carried = march.engagement_m.shape[0] // multiple // 2 - 1  # the harmonics a wave period's samples carry
    q = march.cargo_displacement_m
    cradle = cradle_response(dynamics, march.engagement_m, q, excitation.omega_rad_s, (*outcome, carried), multiple)
    tangents = march.tangents
    period = ConePeriod(
        march.friction_force_N, march.slider_m, march.slipped, tangents.rest_m, march.slider_m[-1], march.periods, march.period_change
    )
    return frictional_response(cradle, tangents, period)


def _march_response(
    dynamics: CradleDynamics, excitation: CradleExcitation, marched: _Marched, hbm: FrictionalCradleResponse
) -> FrictionalCradleResponse:
    """The finer march's response with its outcome (module docstring)."""
    coarse, fine, error = marched.coarse, marched.fine, marched.step_error
    N = 2 * coarse.engagement_m.shape[0] // max(coarse.period_multiple, 1)
    same = coarse.periodicity is fine.periodicity and coarse.period_multiple == fine.period_multiple
    if fine.periodicity is Periodicity.NOT_PERIODIC:
        outcome, residual = SolverOutcome.NOT_PERIODIC, fine.period_change
    elif not same or fine.unresolved_steps or coarse.unresolved_steps or not error <= STEP_TOLERANCE:
        outcome, residual = SolverOutcome.NOT_CONVERGED, (1.0 if fine.unresolved_steps or coarse.unresolved_steps else error)
    elif fine.periodicity is Periodicity.SUBHARMONIC:
        outcome, residual = SolverOutcome.CONVERGED_SUBHARMONIC, error
    else:
        outcome, residual = SolverOutcome.CONVERGED_BY_TIME_MARCH, error
    head = (
        f"3-D cradle with pad friction (mu = {fine.tangents.friction_coefficient:g}) marched in time: the harmonic balance at "
        f"H = {hbm.cradle.harmonics} did not converge (residual {hbm.cradle.residual:.2e}); "
    )
    if fine is coarse:
        message = head + f"{N // 2} steps a wave period: not periodic after {coarse.periods} periods (change {coarse.period_change:.1e})"
    else:
        message = head + (
            f"{N // 2} and {N} steps a wave period: {coarse.periodicity.value} / {fine.periodicity.value} (period multiple "
            f"{fine.period_multiple}) after {coarse.periods} + {fine.periods} periods, period change {fine.period_change:.1e}, "
            f"step error on the peaks {error:.1e} (tolerance {STEP_TOLERANCE:g}), "
            f"{coarse.unresolved_steps + fine.unresolved_steps} step(s) unresolved"
        )
    return _response(dynamics, excitation, fine, (outcome, float(residual), message))
