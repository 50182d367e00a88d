"""The periodic response of the 3-D cargo on pads, stoppers and slack lashings: harmonic balance with AFT.

The linear part, every element bilateral, is condensed onto the engagements harmonic by harmonic
(:func:`~seafast.solvers.cradle_dynamics.cradle_operators`); the vertical plane's condensed harmonic balance
(:func:`~seafast.solvers.hbm.solve_condensed`: AFT of the exact law, semi-smooth Newton solved through the samples
where an element is open, the quasi-static exact-contact predictor as its start, the continuations as its fallback)
solves for the engagements' harmonics. Friction at the pads is left out (docs/transverse.md#7-dynamics).

Where no H converges directly, the correction system marched in time (:mod:`seafast.solvers.cradle_march`) says
whether the steady state repeats every wave period and, if it does, starts the adaptive choice again.

Size: the adaptive choice of H, its march fallback, the ladder and the stoppers' passes share one solved set
(:class:`_SetSolution`) and its account in words; split, they would hand private state across modules.

Units: engagements [m]; forces [N]; displacements [m, rad]; time [s].
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
from numpy.typing import NDArray

from seafast.config.modes import ContactLawKind, Formulation
from seafast.excitation.cradle_loads import CradleExcitation
from seafast.fourier import (
    harmonics_to_time,
    real_harmonics_to_time,
    real_to_complex_harmonics,
    time_to_real_harmonics,
)
from seafast.solvers.cradle_dynamics import CradleDynamics, cradle_operators
from seafast.solvers.cradle_march import MARCH_SAMPLES, CradleMarch, Periodicity, march_cradle
from seafast.solvers.cradle_response import CradleResponse, cradle_response
from seafast.solvers.cradle_shooting import solve_cradle_shooting
from seafast.solvers.hbm import CondensedOperators, HBMOptions, solve_condensed
from seafast.solvers.hbm.fixed import QUICK_ITERATIONS, CondensedSolution
from seafast.solvers.hbm.harmonics import force_scale_N, pad_harmonics
from seafast.solvers.outcome import HBMStart, SolverOutcome

__all__ = [
    "ADAPTIVE_HARMONICS",
    "CradleResponse",
    "MARCH_SAMPLES",
    "DEFAULT_CRADLE_HARMONICS",
    "cradle_response",
    "peak_forces_N",
    "solve_cradle_hbm",
    "truncated_operators",
]

DEFAULT_CRADLE_HARMONICS = 64
"""The first H of the adaptive choice (the options' ``harmonics`` None): where every element stays engaged the
linear solution is exact and the solve ends there."""

ADAPTIVE_HARMONICS = (64, 96, 128, 192, 256, 384, 512)
"""The H the adaptive choice climbs (up to the options' ``max_harmonics``), each started from the one before."""

PASSED_LIMIT = 3
"""The adaptive choice's first H that may fail to converge before it falls back on the ladder (where no H converges
directly, climbing further costs seconds a solve: thousands of samples open)."""

PEAK_SAMPLES = 4096
"""Samples per period on which the adaptive choice reads the peak forces (the harmonic series evaluated there:
the AFT grid's own samples miss a peak between them by up to 1e-3 near H = 128)."""


def truncated_operators(ops: CondensedOperators, harmonics: int) -> CondensedOperators:
    """The same condensed operators at fewer harmonics (their first ``harmonics`` + 1): nothing is solved again."""
    h = int(harmonics)
    return replace(
        ops,
        harmonics=h,
        receptance_harmonics=ops.receptance_harmonics[: h + 1],
        linear_compression_m=ops.linear_compression_m[: 2 * h + 1],
        linear_cargo_displacement=ops.linear_cargo_displacement[: h + 1],
        cargo_influence=ops.cargo_influence[: h + 1],
    )


def _ladder(ops: CondensedOperators, options: HBMOptions) -> tuple[CondensedSolution, str]:
    """Solve at H = 8, 16, ... up to the options' H, each rung started from the one before (padded).

    A start from the previous rung is near the solution (a few Newton steps, no fallbacks); a rung that fails
    from it is solved with the full fallback chain. Returns the last solution and the relative change of the
    elements' peak forces from the rung before (the truncation's indicator) in words.
    """
    H = ops.harmonics
    rungs = [h for h in (8, 16, 32, 64, 128, 256) if h < H] + [H]
    previous: CondensedSolution | None = None
    peaks: list[NDArray[np.float64]] = []
    for h in rungs:
        rung_options = options.with_harmonics(h, options.time_samples if h == H else None)
        rung_ops = truncated_operators(ops, h)
        solution = None
        if previous is not None and previous.converged:
            quick = replace(rung_options, continuation=False, max_iterations=min(int(options.max_iterations), QUICK_ITERATIONS))
            start = pad_harmonics(previous.saddle_compression, h)
            solution = solve_condensed(rung_ops, quick, start, HBMStart.PREVIOUS_HARMONICS)
        if solution is None or not solution.converged:
            solution = solve_condensed(rung_ops, rung_options)
        N = rung_options.fixed_grid()[1]
        peaks.append(
            np.max(
                ops.saddle_stiffness_N_per_m
                * np.maximum(harmonics_to_time(real_to_complex_harmonics(solution.saddle_compression), N), 0.0),
                axis=0,
            )
        )
        previous = solution
    assert previous is not None
    if len(peaks) < 2:
        return previous, "no truncation indicator (a single H)"
    change = np.max(np.abs(peaks[-1] - peaks[-2])) / max(float(np.max(peaks[-1])), 1.0)
    return previous, f"peak forces changed by {change:.2e} of the largest from H = {rungs[-2]}"


def peak_forces_N(ops: CondensedOperators, compression: NDArray[np.float64], time_samples: int = PEAK_SAMPLES) -> NDArray[np.float64]:
    """Each element's largest force ``k max(s, 0)`` over the period [N], (m,), from real-layout engagement
    harmonics (2H+1, m) [m] evaluated on ``time_samples`` samples."""
    s = real_harmonics_to_time(compression, max(int(time_samples), 2 * (compression.shape[0] // 2) + 2))
    return np.asarray(np.max(ops.saddle_stiffness_N_per_m * np.maximum(s, 0.0), axis=0), dtype=float)


@dataclass(frozen=True)
class _SetSolution:
    """One included set solved: the solution, its operators (at its H), its grid, how H was reached, the peak change."""

    solution: CondensedSolution
    ops: CondensedOperators
    time_samples: int
    words: str
    peak_force_change: float
    march: CradleMarch | None = None


def _rung(ops: CondensedOperators, options: HBMOptions, start: NDArray[np.float64] | None, quick_only: bool = False) -> CondensedSolution:
    """One H of the adaptive choice: a few Newton steps from ``start`` (real layout, padded), else (unless
    ``quick_only``) a direct solve."""
    H = ops.harmonics
    if start is not None:
        quick = replace(options, continuation=False, max_iterations=min(int(options.max_iterations), QUICK_ITERATIONS))
        solution = solve_condensed(ops, quick, pad_harmonics(start, H), HBMStart.MARCH if quick_only else HBMStart.PREVIOUS_HARMONICS)
        if solution.converged or quick_only:
            return solution
    return solve_condensed(ops, replace(options, continuation=False))


def _adaptive(
    dynamics: CradleDynamics,
    excitation: CradleExcitation,
    options: HBMOptions,
    included: NDArray[np.bool_],
    start: NDArray[np.float64] | None,
    march: CradleMarch | None = None,
) -> _SetSolution:
    """H chosen by the change of the peak forces: :data:`ADAPTIVE_HARMONICS` climbed, each H started from the last
    converged one, until the peaks move by at most ``options.truncation_tolerance`` of their scale.

    An H whose solve does not converge is passed over (a truncation among the modes the elements ring in leaves the
    semi-smooth Newton wandering; above them it converges in a few steps). None of the first :data:`PASSED_LIMIT`
    converging, or none at all: the correction system marched in time (:func:`_after_march`); where that does not
    settle on a solution, the fixed-H ladder at the first H (its fallback chain).
    """
    rungs = [h for h in ADAPTIVE_HARMONICS if h <= int(options.max_harmonics)] or [int(options.max_harmonics)]
    ops: CondensedOperators | None = None
    best: _SetSolution | None = None
    passed: list[int] = []
    failed: CondensedSolution | None = None
    for h in rungs:
        ops = cradle_operators(dynamics, excitation, h, included, reuse=ops)
        rung_options = options.with_harmonics(h)
        solution = _rung(ops, rung_options, start if best is None else best.solution.saddle_compression, march is not None)
        if not solution.converged:
            passed.append(h)
            failed = solution
            if best is None and len(passed) == PASSED_LIMIT:
                break  # not the truncation: the fallbacks, at the first H
            continue
        N = rung_options.fixed_grid()[1]
        if not np.any(solution.correction_force):
            return _SetSolution(solution, ops, N, "every element engaged all period: the linear solution, exact at any H", 0.0)
        if best is not None:
            peaks, before = peak_forces_N(ops, solution.saddle_compression), peak_forces_N(best.ops, best.solution.saddle_compression)
            change = float(np.max(np.abs(peaks - before) / force_scale_N(peaks)))
            words = f"adaptive H: peak forces changed by {change:.1e} of their scale from H = {best.ops.harmonics}"
            words += f" (H = {', '.join(map(str, passed))} not converged, passed over)" if passed else ""
            if change <= float(options.truncation_tolerance):
                return _SetSolution(solution, ops, N, words, change)
            best = _SetSolution(solution, ops, N, words + f", above the tolerance {options.truncation_tolerance:g} at the cap", change)
        else:
            best = _SetSolution(solution, ops, N, "adaptive H: no second H within max_harmonics to compare with", float("nan"))
    if best is not None:
        return best
    assert ops is not None and failed is not None
    if march is None:
        return _after_march(dynamics, excitation, options, included, (failed, ops, rungs))
    first = truncated_operators(ops, rungs[0])
    solution, words = _ladder(first, options.with_harmonics(rungs[0]))
    words = f"adaptive H: no H up to {passed[-1]} converged directly, the ladder at H = {rungs[0]}: {words}"
    return _SetSolution(solution, first, options.with_harmonics(rungs[0]).fixed_grid()[1], words, float("nan"))


def _after_march(
    dynamics: CradleDynamics,
    excitation: CradleExcitation,
    options: HBMOptions,
    included: NDArray[np.bool_],
    failed: tuple[CondensedSolution, CondensedOperators, list[int]],
) -> _SetSolution:
    """No H converging directly: the correction system marched from the linear solution (:func:`march_cradle`).

    Periodic with the wave: the adaptive choice again, started from the march's last period (its engagements'
    harmonics), then the ladder should that fail. A subharmonic or no periodic state: no harmonic balance at the wave's
    period describes it; the last H's iterate returned with the outcome ``NOT_PERIODIC`` (no ladder).
    """
    solution, ops, rungs = failed
    marched = march_cradle(dynamics, excitation, MARCH_SAMPLES)
    said = f"a march of {marched.periods} wave periods ({MARCH_SAMPLES} steps each): {marched.periodicity.value}"
    if marched.periodicity is Periodicity.PERIODIC:
        start = time_to_real_harmonics(marched.engagement_m[:, included], min(rungs[-1], MARCH_SAMPLES // 2 - 1))
        solved = _adaptive(dynamics, excitation, options, included, start, marched)
        return replace(
            solved,
            words=f"no H up to {rungs[2 if len(rungs) > 2 else -1]} converged directly; {said}, started from it; {solved.words}",
            march=marched,
        )
    if marched.periodicity is Periodicity.SUBHARMONIC:
        said += f", repeating every {marched.period_multiple} wave periods (change {marched.period_change:.1e} over them"
    else:
        said += f" (change {marched.period_change:.1e} over a wave period"
    said += ", of the largest linear engagement): no periodic response at the wave's period for the harmonic balance"
    words = f"adaptive H: no H up to {ops.harmonics} converged directly; {said}"
    not_periodic = replace(solution, outcome=SolverOutcome.NOT_PERIODIC)
    return _SetSolution(not_periodic, ops, options.with_harmonics(ops.harmonics).fixed_grid()[1], words, float("nan"), marched)


def _fixed(
    dynamics: CradleDynamics, excitation: CradleExcitation, options: HBMOptions, included: NDArray[np.bool_], start: NDArray | None
) -> _SetSolution:
    """At the options' H: a direct solve (a few Newton steps from ``start`` first, if given), else the ladder."""
    H, N = options.fixed_grid()
    ops = cradle_operators(dynamics, excitation, H, included)
    solution = None
    if start is not None:
        quick = replace(options, continuation=False, max_iterations=min(int(options.max_iterations), QUICK_ITERATIONS))
        solution = solve_condensed(ops, quick, pad_harmonics(start, H), HBMStart.PREVIOUS_HARMONICS)
    if solution is None or not solution.converged:
        solution = solve_condensed(ops, replace(options, continuation=False))
    truncation = "solved directly at H"
    if not solution.converged:
        solution, truncation = _ladder(ops, options)
    return _SetSolution(solution, ops, N, truncation, float("nan"))


def _deck_time_m(excitation: CradleExcitation, time_samples: int) -> NDArray[np.float64]:
    """The deck DOFs over the period (N, n_o) [m, rad]."""
    xo = np.array(excitation.deck_displacement, dtype=complex)
    xo[0] = xo[0].real
    return harmonics_to_time(xo, time_samples)


def _samples(
    dynamics: CradleDynamics, excitation: CradleExcitation, solved: _SetSolution, included: NDArray[np.bool_]
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """(engagements (N, m), cargo DOFs (N, 5 n)) of a solved set: the elements left out follow from the cargo's
    motion and the deck's (open where <= 0)."""
    ops, N = solved.ops, solved.time_samples
    C = real_to_complex_harmonics(solved.solution.correction_force)  # (H+1, m_I)
    q = harmonics_to_time(ops.linear_cargo_displacement + np.einsum("kcs,ks->kc", ops.cargo_influence, C), N)
    problem = dynamics.problem
    s = dynamics.initial_engagement_m + q @ problem.engagement_matrix.T + _deck_time_m(excitation, N) @ dynamics.deck_engagement.T
    s[:, included] = harmonics_to_time(real_to_complex_harmonics(solved.solution.saddle_compression), N)
    return s, q


def solve_cradle_hbm(
    dynamics: CradleDynamics, excitation: CradleExcitation, options: HBMOptions | None = None, *, shooting: bool = True
) -> CradleResponse:
    """The periodic response: the harmonic balance's converged limit by exact-event shooting, or the harmonic balance.

    With ``options.harmonics`` None, the exact law and the condensed formulation (the default) the answer asked for is
    the harmonic balance converged in H: the periodic solution of the piecewise-linear problem, which exact-event
    shooting finds in closed form (:func:`~seafast.solvers.cradle_shooting.solve_cradle_shooting`, ``shooting`` True).
    Where it does not converge (its message says why) the exact-event flow is marched: a subharmonic is solved on its
    P-period map and returned over those P wave periods (``CONVERGED_SUBHARMONIC``, ``period_multiple`` P), a state
    that is not periodic (or a subharmonic not found) as such (``NOT_PERIODIC``); the verdict on ``march`` (no harmonic
    balance at the wave's period describes either);
    otherwise the adaptive harmonic balance below answers, its message saying so. Where every element
    stays engaged the linear solution is exact and the harmonic balance's first H gives it.

    The side stoppers are left out of the linear part at first (taken open: they usually are); any that closes
    in the solution is brought in and the problem solved again (started from the solution before), until none
    left out closes. With ``options.harmonics`` None (the default) H climbs :data:`ADAPTIVE_HARMONICS` from
    :data:`DEFAULT_CRADLE_HARMONICS`, each H started from the one before, until the elements' peak forces change
    by at most ``options.truncation_tolerance`` of their scale (the linear solution, exact, where every element
    stays engaged). At a given H: a direct solve (from the better of the linear solution and the quasi-static
    exact-contact predictor); if that fails, H is doubled from 8, each rung started from the one before, with
    the fallback chain of the vertical plane (:func:`~seafast.solvers.hbm.solve_condensed`) where a rung's start
    is not enough.

    Parameters
    ----------
    dynamics
        The 3-D cargo on its cradles.
    excitation
        The static and first-harmonic loads and deck motion (:func:`~seafast.excitation.cradle_loads.cradle_excitation`).
    options
        The vertical plane's :class:`~seafast.solvers.hbm.HBMOptions` (condensed formulation, exact law or a smooth
        one, Newton or hybr, tolerance, fallbacks; ``harmonics`` None: adaptive, up to ``max_harmonics``, to
        ``truncation_tolerance``; a given ``time_samples`` is then a minimum).

    shooting
        False: the harmonic balance alone, whatever the options.

    Returns
    -------
    CradleResponse
        On the AFT grid (N samples), or where the shooting answered on its event grid (``harmonics`` N / 2 - 1,
        ``peak_force_change`` NaN); ``outcome`` ``NOT_CONVERGED`` with its residual when no route met the tolerance,
        ``CONVERGED_SUBHARMONIC`` over P wave periods where the state repeats only every P, ``NOT_PERIODIC`` where it
        does not repeat at all. Its message says how the solve went and how
        H was reached; ``peak_force_change`` the adaptive H's last change of the peak forces.
    """
    options = options if options is not None else HBMOptions()
    exact_limit = options.harmonics is None and options.contact_law is ContactLawKind.EXACT
    if shooting and exact_limit and options.formulation is Formulation.CONDENSED:
        shot = solve_cradle_shooting(dynamics, excitation)
        if (shot.converged and shot.harmonics > 1) or shot.outcome is SolverOutcome.NOT_PERIODIC:
            return shot  # the converged limit, or no periodic response at the wave's period for any harmonic balance
        if not shot.converged:
            response = _harmonic_balance(dynamics, excitation, options)
            note = f"; exact-event shooting did not converge ({shot.message}), so the adaptive harmonic balance answered"
            return replace(response, message=response.message + note)
    return _harmonic_balance(dynamics, excitation, options)


def _harmonic_balance(dynamics: CradleDynamics, excitation: CradleExcitation, options: HBMOptions) -> CradleResponse:
    """The harmonic balance of :func:`solve_cradle_hbm` (``options.harmonics`` None: H chosen adaptively)."""
    problem = dynamics.problem
    stopper = np.zeros(len(problem.engagements), dtype=bool)
    stopper[2 * len(problem.pad_pairs) : 2 * len(problem.pad_pairs) + len(problem.stoppers)] = True
    included = ~stopper if np.any(~stopper) else stopper
    start: NDArray[np.float64] | None = None
    march: CradleMarch | None = None
    for _ in range(stopper.size + 1):
        if options.harmonics is None:
            solved = _adaptive(dynamics, excitation, options, included, start, march)
            march = solved.march
        else:
            solved = _fixed(dynamics, excitation, options.with_harmonics(int(options.harmonics), options.time_samples), included, start)
        s, q = _samples(dynamics, excitation, solved, included)
        closing = ~included & np.any(s > 0.0, axis=0)
        if not solved.solution.converged or not np.any(closing):
            break
        included = included | closing
        start = time_to_real_harmonics(s[:, included], solved.ops.harmonics)
        if march is not None:  # the march's state has every element in: the better start
            start = time_to_real_harmonics(march.engagement_m[:, included], min(solved.ops.harmonics, MARCH_SAMPLES // 2 - 1))
    solution, H, N = solved.solution, solved.ops.harmonics, solved.time_samples
    message = (
        f"3-D cradle harmonic balance, H = {H}, N = {N}: {solution.message}; {solved.words}; "
        f"{int(np.count_nonzero(~included))} stopper(s) open all period, left out"
    )
    response = cradle_response(dynamics, s, q, excitation.omega_rad_s, (solution.outcome, solution.residual_norm, message, H))
    return replace(response, peak_force_change=solved.peak_force_change, march=solved.march)
