"""The periodic response of the 3-D cargo on its cradles by exact-event shooting (:func:`solve_cradle_shooting`).

The correction system of the cradle (docs/transverse.md#7-dynamics): with the elements of the included set I
bilateral the cargo is linear, its periodic response ``s_lin(t)`` the condensed operators' at H = 1
(:func:`~seafast.solvers.cradle_dynamics.cradle_operators`), and the nonlinear response ``q = q_lin + q_c`` with::

    M q_c'' + D q_c' + K_I q_c = -A_I^T c,    s = s_lin(t) + A_I q_c,    c = k max(-s, 0)

(the tension a bilateral pad or stopper would carry, the compression of a bilateral lashing, removed; a stopper's gap
is in its ``s0``). Reduced on the modes of ``(K_I, M)`` up to a cutoff, their damping ``Phi^T D Phi`` kept whole,
and the static residual flexibility of the others, it is the vertical plane's correction system
(:class:`~seafast.solvers.modal_correction.ModalCorrectionSystem`) with the engagements for the saddles: its
``B = -A_I^T``, so ``saddle_mode_shape = -A_I Phi`` and ``residual_flexibility = A_I (K_I^-1 - Phi Omega^-2 Phi^T)
A_I^T``. Piecewise linear in the contact states, it is solved by the vertical plane's exact-event shooting as it is
(:func:`~seafast.solvers.shooting.orbit.shoot_orbit`: closed-form segments, exact events, Newton on the monodromy
matrix), whatever harmonics the ringing after a re-contact needs.

A contact state with a rigid-body motion (a mechanism: the cargo on one pad with its stoppers open slides across,
the lashings holding only its vertical rigid-body motions) is marched exactly, the constant load along it drifting
the cargo at a constant rate (:class:`~seafast.solvers.shooting.states.ContactStates` ``mechanisms``); the other
pads or the stoppers take it back.

The side stoppers are left out of I at first (open, as they usually are); any that closes is brought in and the
orbit found again, as the harmonic balance does (:func:`~seafast.solvers.cradle_hbm.solve_cradle_hbm`); without them
the cargo may have no orbit (lifted off its pads, nothing holds it across), and then every element is brought in.
With a stopper in, the cutoff is doubled until the peaks settle (its impacts converge slowly in the bilateral modes),
a subharmonic's also until its orbit is stable; after the doublings a small cargo is solved with every mode.
Where Newton does not close the period, the exact-event flow is marched and says what the state is
(:func:`flow_verdict`); a subharmonic of P wave periods is then found by the same Newton on the P-period map (the
excitation's period taken as P T: :func:`~seafast.solvers.cradle_shooting_system.subharmonic_harmonics`).
The reduced system itself: :mod:`seafast.solvers.cradle_shooting_system`.

Size: over 400 lines because the included set's solve, its cutoff check (peaks and stability) and the flow's verdict
with the subharmonic it leads to are one algorithm on the same reduced system.

Units: engagements [m]; forces [N]; displacements [m, rad]; time [s]. Nothing here prints, reads or writes files.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np
from numpy.typing import NDArray

from seafast.excitation.cradle_loads import CradleExcitation
from seafast.fourier import real_to_complex_harmonics
from seafast.solvers.cradle_dynamics import CradleDynamics, cradle_operators
from seafast.solvers.cradle_march import SUBHARMONIC_ORDERS, CradleMarch, Periodicity
from seafast.solvers.cradle_response import CradleResponse, cradle_response
from seafast.solvers.cradle_shooting_system import (
    CradleModes,
    all_engagements,
    cradle_correction_system,
    cradle_modes,
    first_harmonic_time,
    kept_modes,
    reassembled,
    reference_frequency_rad_s,
    subharmonic_harmonics,
)
from seafast.solvers.hbm.condensed import CondensedOperators
from seafast.solvers.hbm.harmonics import force_scale_N
from seafast.solvers.outcome import SolverOutcome
from seafast.solvers.shooting.options import ShootingOptions
from seafast.solvers.shooting.orbit import Orbit, sampled_contact, shoot_orbit, state_change
from seafast.solvers.shooting.period import PeriodGrid, TooManyEventsError, flow_period
from seafast.solvers.shooting.states import ContactStates, SingularStateError
from seafast.solvers.shooting.stiff import COMPLETE_BASIS_DOFS, MAX_CUTOFF_DOUBLINGS, MODAL_TOLERANCE

__all__ = ["VERDICT_DOUBLINGS", "VERDICT_PERIODS", "VERDICT_TOLERANCE", "flow_verdict", "solve_cradle_shooting"]


@dataclass(frozen=True)
class _SetOrbit:
    """One included set solved: its engagements of every element (N, m) and cargo DOFs (N, 5 n), how it ended, and
    whether its orbit was shot on every mode of the cargo (``complete``: no modal reduction, nothing finer to try)."""

    engagement_m: NDArray[np.float64]
    cargo_displacement_m: NDArray[np.float64]
    outcome: SolverOutcome
    residual: float
    note: str
    orbit: Orbit | None
    complete: bool = False


def _solve_set(
    dynamics: CradleDynamics,
    excitation: CradleExcitation,
    included: NDArray[np.bool_],
    opts: ShootingOptions,
    multiple: int = 1,
    start: NDArray[np.float64] | None = None,
) -> _SetOrbit:
    """The orbit with the elements ``included`` in the linear part (the others open), of ``multiple`` wave periods
    (its Newton started from ``start``, a correction state, where given: :func:`_orbit_at`).

    With a side stopper included (a stiff element open most of the period: the bilateral modes' reduction of its
    impacts converges slowly) and ``opts.cutoff_check``, the cutoff is doubled until no element's peak force moves by
    more than :data:`~seafast.solvers.shooting.stiff.MODAL_TOLERANCE` of its force scale (or every mode is kept):
    :func:`_settled_cutoff`.
    """
    omega = float(excitation.omega_rad_s)
    ops = cradle_operators(dynamics, excitation, 1, included)
    D = real_to_complex_harmonics(ops.linear_compression_m)
    if multiple == 1 and np.all(D[0].real - np.abs(D[1]) > 0.0):  # the least linear engagement of each element: every one engaged
        N = opts.time_samples or opts.minimum_samples
        q_lin = first_harmonic_time(ops.linear_cargo_displacement, N)
        s = all_engagements(dynamics, excitation, q_lin, included, first_harmonic_time(D, N))
        return _SetOrbit(s, q_lin, SolverOutcome.CONVERGED, 0.0, "every element engaged all period: the linear solution, exact", None)
    modes = cradle_modes(dynamics, included)
    reference = reference_frequency_rad_s(modes, modes.engagement_modes, opts.reference_modes)
    N = opts.time_samples or int(2 ** math.ceil(math.log2(max(opts.samples_per_mode * reference / omega, opts.minimum_samples))))
    N *= multiple
    problem = dynamics.problem
    first_stopper = 2 * len(problem.pad_pairs)
    stiff = bool(np.any(included[first_stopper : first_stopper + len(problem.stoppers)]))
    solved = _orbit_at(dynamics, excitation, included, ops, modes, opts.cutoff_factor * reference, opts, N, multiple, start)
    if not (opts.cutoff_check and stiff and _usable(solved, opts, multiple)):
        return solved
    return _settled_cutoff(dynamics, excitation, included, ops, modes, reference, opts, N, multiple, solved)


def _usable(solved: _SetOrbit, opts: ShootingOptions, multiple: int) -> bool:
    """An orbit the cutoff check goes on from: converged; of ``multiple`` > 1 wave periods, its period closed by Newton
    even if unstable (Newton on the P-period map from the flow's state can land, in too few modes, on the unstable
    wave-period orbit, a fixed point of that map too: the finer cutoffs say which orbit holds)."""
    if multiple > 1:
        return solved.orbit is not None and solved.residual <= opts.tolerance
    return solved.outcome is SolverOutcome.CONVERGED


def _settled_cutoff(
    dynamics: CradleDynamics,
    excitation: CradleExcitation,
    included: NDArray[np.bool_],
    ops: CondensedOperators,
    modes: CradleModes,
    reference: float,
    opts: ShootingOptions,
    samples: int,
    multiple: int,
    solved: _SetOrbit,
) -> _SetOrbit:
    """The orbit ``solved`` (its period closed at ``opts.cutoff_factor`` times ``reference`` [rad/s]) with the cutoff
    doubled until no element's peak force moves by more than :data:`~seafast.solvers.shooting.stiff.MODAL_TOLERANCE`
    of its force scale and the orbit is stable (a subharmonic's stability, like its peaks, a property of the reduction:
    :func:`_usable`). After
    :data:`~seafast.solvers.shooting.stiff.MAX_CUTOFF_DOUBLINGS` with the peaks still moving, a cargo of at most
    :data:`~seafast.solvers.shooting.stiff.COMPLETE_BASIS_DOFS` DOFs is solved with every mode (no reduction: exact).
    Not settled: the last orbit, ``NOT_CONVERGED``, with the changes."""
    k = dynamics.problem.element_stiffness_N_per_m
    factor, changes, doublings = float(opts.cutoff_factor), list[float](), 0
    while math.isfinite(factor):
        if doublings >= MAX_CUTOFF_DOUBLINGS:
            if (changes and changes[-1] <= MODAL_TOLERANCE) or dynamics.problem.cargo.dof_count > COMPLETE_BASIS_DOFS:
                break
            factor = math.inf  # every mode: the reduction exact
        else:
            kept = kept_modes(modes, factor * reference, int(np.count_nonzero(included)))
            if kept == modes.natural_frequency_rad_s.size:
                break  # every mode kept already: nothing finer
            while kept < modes.natural_frequency_rad_s.size and kept_modes(modes, 2.0 * factor * reference, kept) == kept:
                factor *= 2.0  # no mode between: the same reduction
            factor, doublings = 2.0 * factor, doublings + 1
        finer = _orbit_at(dynamics, excitation, included, ops, modes, factor * reference, opts, samples, multiple, _solved_start(solved))
        if not _usable(finer, opts, multiple):
            if solved.outcome is SolverOutcome.CONVERGED:
                break
            continue  # an unstable orbit's Newton may not close at the next cutoff: the one after
        peaks, before = k * np.max(np.maximum(finer.engagement_m, 0.0), axis=0), k * np.max(np.maximum(solved.engagement_m, 0.0), axis=0)
        changes.append(float(np.max(np.abs(peaks - before) / force_scale_N(np.maximum(peaks, before)))))
        solved = finer
        if finer.complete or (changes[-1] <= MODAL_TOLERANCE and finer.outcome is SolverOutcome.CONVERGED):
            break
    if not changes:
        return solved
    settled = (changes[-1] <= MODAL_TOLERANCE or solved.complete) and solved.outcome is SolverOutcome.CONVERGED
    steps = ", ".join(f"{c:.2g}" for c in changes)
    words = f"; cutoff doubled {len(changes)} time(s) for the stoppers' impacts (peak force changes {steps})"
    if solved.complete and changes[-1] > MODAL_TOLERANCE:
        words += "; every mode of the cargo kept: the reduction is exact"
    if not settled:
        words += "; not converged in the modal reduction"
    return replace(solved, note=solved.note + words, outcome=SolverOutcome.CONVERGED if settled else SolverOutcome.NOT_CONVERGED)


def _orbit_at(
    dynamics: CradleDynamics,
    excitation: CradleExcitation,
    included: NDArray[np.bool_],
    ops: CondensedOperators,
    modes: CradleModes,
    cutoff: float,
    opts: ShootingOptions,
    samples: int,
    multiple: int = 1,
    start: NDArray[np.float64] | None = None,
) -> _SetOrbit:
    """The orbit of the correction system reduced at ``cutoff`` [rad/s], from the event grid of ``samples``.

    ``multiple`` (P): the orbit of P wave periods, a fixed point of the P-period map: the excitation's period taken as
    P T (base frequency ``w / P``, the wave's first harmonic at P: :func:`subharmonic_harmonics`), ``samples`` over
    it. ``start``: the correction state Newton starts from (its modes beyond this cutoff's dropped, missing ones 0).
    """
    N, P = samples, int(multiple)
    D = real_to_complex_harmonics(ops.linear_compression_m)
    system = cradle_correction_system(dynamics, ops, included, modes, cutoff)
    states = ContactStates(system, subharmonic_harmonics(D, P) if P > 1 else D, float(excitation.omega_rad_s) / P, mechanisms=True)
    d_grid = first_harmonic_time(D, N, P)
    scale = max(float(np.max(np.abs(d_grid))), 1e-9)
    try:
        x0 = None if start is None else _state_on(start, system.mode_count)
        orbit = shoot_orbit(states, N, scale, opts, system.unilateral_stiffness_N_per_m, x0)
    except (SingularStateError, TooManyEventsError) as error:
        q_lin = first_harmonic_time(ops.linear_cargo_displacement, N, P)
        s = all_engagements(dynamics, excitation, q_lin, included, d_grid, P)  # the linear solution, not converged
        return _SetOrbit(s, q_lin, SolverOutcome.NOT_CONVERGED, math.inf, f"exact-event shooting: {error}", None)
    assert orbit.flow.state_samples is not None
    N = orbit.samples
    contact = (orbit.compression_m, orbit.correction_N)
    s, q = reassembled(dynamics, excitation, included, ops, system, orbit.flow.state_samples, contact, P)
    missed = float(np.max(orbit.missed, initial=0.0))
    kept = "every mode" if system.complete else f"{system.mode_count} modes up to {cutoff:.4g} rad/s"
    note = (
        f"exact-event shooting: {kept}, {N} samples per period{'' if P == 1 else f' of {P} wave periods'}, "
        f"{orbit.flow.events} events per period, {states.visited} contact states, {orbit.periods} period(s) marched, "
        f"{orbit.newton_steps} Newton step(s), residual {orbit.residual:.2g}, largest Floquet multiplier "
        f"{orbit.floquet_multiplier_max:.4f}, sampled peaks within {missed:.1g} of the continuous ones"
    )
    if not orbit.converged:
        note += "; not converged" if orbit.residual > opts.tolerance else "; the orbit found is unstable"
    outcome = SolverOutcome.CONVERGED if orbit.converged else SolverOutcome.NOT_CONVERGED
    return _SetOrbit(s, q, outcome, orbit.residual, note, orbit, system.complete)


def _solved_start(solved: _SetOrbit) -> NDArray[np.float64] | None:
    """The correction state an orbit starts from (None where none was shot)."""
    return None if solved.orbit is None or solved.orbit.flow.state_samples is None else solved.orbit.flow.state_samples[0]


def _state_on(state: NDArray[np.float64], modes: int) -> NDArray[np.float64]:
    """A correction state ``[eta; eta']`` (2 m',) on ``modes`` modes (2 m,): the modes beyond m dropped, missing ones 0."""
    half = state.size // 2
    kept = min(half, int(modes))
    out = np.zeros(2 * int(modes))
    out[:kept], out[modes : modes + kept] = state[:kept], state[half : half + kept]
    return out


def solve_cradle_shooting(
    dynamics: CradleDynamics, excitation: CradleExcitation, options: ShootingOptions | None = None, *, march: bool = True
) -> CradleResponse:
    """The periodic response of the 3-D cargo on its cradles by exact-event shooting (see the module docstring).

    Parameters
    ----------
    dynamics
        The 3-D cargo on its cradles (frictionless pads).
    excitation
        The static and first-harmonic loads and deck motion (:func:`~seafast.excitation.cradle_loads.cradle_excitation`).
    options
        :class:`~seafast.solvers.shooting.ShootingOptions` (None: the defaults). ``cutoff_factor`` times the reference
        frequency (the ``reference_modes``-th lowest mode the elements drive) is the modal cutoff; ``cutoff_check``:
        with a stopper included, the cutoff doubled until the peaks settle; ``basis`` is not taken (the bilateral
        modes always: the cargo without its pads is not held across).

    Returns
    -------
    CradleResponse
        On the event grid (N samples, ``harmonics`` N / 2 - 1: the harmonics the samples carry); ``outcome``
        ``CONVERGED``, or ``NOT_CONVERGED`` with its residual (relative to the largest linear engagement) where Newton
        did not close the period, the orbit is unstable, a contact state has no stiffness or the contact chatters.
        ``peak_force_change`` NaN (no H climbed). Where every element stays engaged all period, the linear solution
        (exact) with ``harmonics`` 1. Not converged and ``march``: the exact-event flow marched (:func:`flow_verdict`)
        says on ``march`` what the steady state is (its ``periodicity``); a subharmonic of P wave periods is then
        solved by Newton on the P-period map (:func:`_subharmonic`) and returned over the P periods: outcome
        ``CONVERGED_SUBHARMONIC``, ``period_multiple`` P (its ``harmonics`` those of ``omega / P``); not periodic, or
        the subharmonic not found: the outcome ``NOT_PERIODIC``.
    """
    opts = ShootingOptions() if options is None else options
    problem = dynamics.problem
    stopper = np.zeros(len(problem.engagements), dtype=bool)
    stopper[2 * len(problem.pad_pairs) : 2 * len(problem.pad_pairs) + len(problem.stoppers)] = True
    included = ~stopper if np.any(~stopper) else stopper
    for _ in range(stopper.size + 1):
        solved = _solve_set(dynamics, excitation, included, opts)
        closing = ~included & np.any(solved.engagement_m > 0.0, axis=0)
        if solved.outcome is not SolverOutcome.CONVERGED and np.any(~included):
            # without the stoppers the cargo may find no orbit (lifted off its pads, nothing holds it across): every
            # element in, once
            closing = ~included
        elif solved.outcome is not SolverOutcome.CONVERGED or not np.any(closing):
            break
        included = included | closing
    N = solved.engagement_m.shape[0]
    message = f"3-D cradle {solved.note}; {int(np.count_nonzero(~included))} stopper(s) open all period, left out"
    outcome = (solved.outcome, solved.residual, message, N // 2 - 1 if solved.orbit is not None else 1)
    response = cradle_response(dynamics, solved.engagement_m, solved.cargo_displacement_m, excitation.omega_rad_s, outcome)
    if solved.outcome is SolverOutcome.CONVERGED or not march or solved.orbit is None:
        return response
    verdict, said, settled, factor = _verdict(dynamics, excitation, included, opts, solved.orbit.samples)
    if verdict.periodicity is Periodicity.SUBHARMONIC:
        at = replace(opts, cutoff_factor=factor)  # the cutoff the verdict settled at: its state starts Newton
        subharmonic = _subharmonic(dynamics, excitation, included, at, verdict.period_multiple, settled)
        if subharmonic is not None:
            return replace(subharmonic, march=verdict, message=subharmonic.message + said)
    if verdict.periodicity is not Periodicity.PERIODIC:
        response = replace(response, outcome=SolverOutcome.NOT_PERIODIC)
    return replace(response, march=verdict, message=response.message + said)


def _subharmonic(
    dynamics: CradleDynamics,
    excitation: CradleExcitation,
    included: NDArray[np.bool_],
    opts: ShootingOptions,
    multiple: int,
    settled: NDArray[np.float64],
) -> CradleResponse | None:
    """The orbit of ``multiple`` wave periods the flow settled on, by the same Newton shooting on the P-period map
    (started from the flow's ``settled`` state), stable (every Floquet multiplier of its monodromy over P T within the
    unit circle); None where it does not converge. An element left out that closes on it is brought in once."""
    solved = _solve_set(dynamics, excitation, included, opts, multiple, settled)
    closing = ~included & np.any(solved.engagement_m > 0.0, axis=0)
    if solved.outcome is SolverOutcome.CONVERGED and np.any(closing):
        included = included | closing
        solved = _solve_set(dynamics, excitation, included, opts, multiple, settled)
    if solved.outcome is not SolverOutcome.CONVERGED or solved.orbit is None:
        return None
    N = solved.engagement_m.shape[0]
    message = (
        f"3-D cradle subharmonic orbit repeating every {multiple} wave periods (the wave-period orbit does not hold), "
        f"{solved.note}; {int(np.count_nonzero(~included))} stopper(s) open all period, left out"
    )
    outcome = (SolverOutcome.CONVERGED_SUBHARMONIC, solved.residual, message, N // 2 - 1)
    return cradle_response(dynamics, solved.engagement_m, solved.cargo_displacement_m, excitation.omega_rad_s, outcome, multiple)


VERDICT_PERIODS = 200
"""Periods of the exact-event flow marched at most for the verdict where Newton does not close the period."""

VERDICT_TOLERANCE = 1e-6
"""The flow repeats after a lag when the state moves by at most this share of the largest linear engagement."""

VERDICT_DOUBLINGS = 3
"""Doublings of the cutoff at most while the verdict changes with it."""


def flow_verdict(
    dynamics: CradleDynamics, excitation: CradleExcitation, included: NDArray[np.bool_], opts: ShootingOptions, samples: int
) -> tuple[CradleMarch, str]:
    """What the steady state of the exact-event flow is, where Newton does not close the period.

    The flow is marched from the linear solution for up to :data:`VERDICT_PERIODS` periods, its state after each
    compared with those 1 to 6 periods before (stopping once one repeats to :data:`VERDICT_TOLERANCE`): periodic,
    a subharmonic (repeating every 2 to 6 periods, not every one) or neither. The cutoff is doubled from
    ``opts.cutoff_factor`` until two cutoffs agree (at most :data:`VERDICT_DOUBLINGS` times: the reduction's own
    convergence). Returns the verdict as a :class:`~seafast.solvers.cradle_march.CradleMarch` (the last period's
    engagements and forces on the event grid) and it in words.
    """
    verdict, said, _, _ = _verdict(dynamics, excitation, included, opts, samples)
    return verdict, said


def _verdict(
    dynamics: CradleDynamics, excitation: CradleExcitation, included: NDArray[np.bool_], opts: ShootingOptions, samples: int
) -> tuple[CradleMarch, str, NDArray[np.float64], float]:
    """:func:`flow_verdict`, the correction state the flow settled on (at the start of its last period) and the cutoff
    factor of the verdict (of the reference frequency)."""
    ops = cradle_operators(dynamics, excitation, 1, included)
    D = real_to_complex_harmonics(ops.linear_compression_m)
    modes = cradle_modes(dynamics, included)
    reference = reference_frequency_rad_s(modes, modes.engagement_modes, opts.reference_modes)
    scale = max(float(np.max(np.abs(first_harmonic_time(D, 64)))), 1e-9)
    factor, verdicts = float(opts.cutoff_factor), []
    while True:
        system = cradle_correction_system(dynamics, ops, included, modes, factor * reference)
        states = ContactStates(system, D, float(excitation.omega_rad_s), mechanisms=True)
        verdicts.append(_marched_flow(dynamics, excitation, included, ops, states, PeriodGrid(states, samples), scale))
        settled = verdicts[-1][1]
        same = len(verdicts) > 1 and (verdicts[-1][0].periodicity, verdicts[-1][0].period_multiple) == (
            verdicts[-2][0].periodicity,
            verdicts[-2][0].period_multiple,
        )
        if same or system.complete or len(verdicts) > VERDICT_DOUBLINGS:
            break
        factor *= 2.0
    last = verdicts[-1][0]
    said = f"; the exact-event flow marched {last.periods} periods ({system.mode_count} modes): {last.periodicity.value}"
    if last.periodicity is Periodicity.SUBHARMONIC:
        said += f", repeating every {last.period_multiple} wave periods (change over one {last.lag_change[0]:.1e}"
        said += " of the largest linear engagement)"
    if not same:
        said += " (the verdict still changed with the cutoff)"
    return last, said, settled, factor


def _marched_flow(
    dynamics: CradleDynamics,
    excitation: CradleExcitation,
    included: NDArray[np.bool_],
    ops: CondensedOperators,
    states: ContactStates,
    grid: PeriodGrid,
    scale_m: float,
) -> tuple[CradleMarch, NDArray[np.float64]]:
    """The flow marched from ``x = 0`` (see :func:`flow_verdict`), what it repeats as, and its last period's start."""
    xs = [np.zeros(states.state_size)]
    history: list[float] = []
    lags = np.full(max(SUBHARMONIC_ORDERS), np.nan)
    for _ in range(VERDICT_PERIODS):
        xs.append(flow_period(states, xs[-1], grid, monodromy=False).end_state)
        xs = xs[-(max(SUBHARMONIC_ORDERS) + 1) :]
        for lag in range(1, len(xs)):
            lags[lag - 1] = state_change(states, xs[-1] - xs[-1 - lag], scale_m)
        history.append(float(lags[0]))
        if np.nanmin(lags) <= VERDICT_TOLERANCE:
            break  # repeats after some lag: settled
    periodicity, multiple = Periodicity.NOT_PERIODIC, 0
    if lags[0] <= VERDICT_TOLERANCE:
        periodicity, multiple = Periodicity.PERIODIC, 1
    else:
        for lag in SUBHARMONIC_ORDERS:
            if lags[lag - 1] <= VERDICT_TOLERANCE:
                periodicity, multiple = Periodicity.SUBHARMONIC, lag
                break
    flow = flow_period(states, xs[-1], grid, record=True, monodromy=False)
    assert flow.state_samples is not None
    s, _ = reassembled(dynamics, excitation, included, ops, states.system, flow.state_samples, sampled_contact(states, grid, flow))
    k = dynamics.problem.element_stiffness_N_per_m
    change = float(lags[multiple - 1]) if multiple else float(lags[0])
    march = CradleMarch(s, k * np.maximum(s, 0.0), periodicity, multiple, len(history), change, lags, np.array(history))
    return march, xs[-1]
