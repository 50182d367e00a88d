"""The one Newton of every harmonic balance: globalised (semi-smooth) Newton on a :class:`NewtonSystem`.

The vertical harmonic balance (condensed and full formulations, :mod:`seafast.solvers.hbm.nonlinear`) and
the axial one (:mod:`seafast.solvers.axial.problem`) both solve ``R(u) = 0`` for the real harmonic
coefficients ``u`` with a contact law that is piecewise smooth (the exact law, the Jenkins element), so
each Jacobian is an element of the generalised Jacobian (semi-smooth Newton). Each problem supplies its
residual and its factorised Jacobian (:class:`NewtonSystem`); how a step is accepted is the
:class:`Globalisation`:

* the Newton direction ``d = -J^-1 R``, backtracked by halving from ``alpha = 1`` down to ``min_step``;
* a trial is accepted on an Armijo rule on a merit: ``merit(u + alpha d) <= reference - c alpha slope``,
  the merit ``||R||^2 / 2`` (slope ``||R||^2``, the merit's decrease along the Newton direction) or the
  relative ``max |R| / scale`` (slope: itself); the reference the largest of the last ``memory`` accepted
  merits (Grippo-Lampariello-Lucidi: non-monotone for ``memory > 1``, which lets the iteration cross the
  kinks of the exact law instead of stalling in front of them), optionally any trial that meets the
  tolerance;
* where no step length is accepted, optionally a Levenberg-Marquardt step ``(J^T J + mu diag(J^T J)) d =
  -J^T R`` with mu rising tenfold from 1e-6 to 1e6, monotone in the merit (Armijo on ``J^T R``); Newton
  resumes at the next iteration;
* optionally an early exit on stagnation: the merit not reduced tenfold over ``stagnation_window``
  iterations (near a solution semi-smooth Newton terminates in a few steps: this is a zig-zag between
  contact patterns, left to the caller's fallbacks).

Convergence is ``max |R| / scale <= tolerance``. How the iteration ended is a typed :class:`NewtonStop`;
``iterations`` counts the accepted steps. Units: whatever the system's (``R`` and ``scale`` share one).
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import StrEnum
from typing import Generic, Protocol, TypeVar

import numpy as np
from numpy.typing import NDArray

__all__ = [
    "Jacobian",
    "NewtonSystem",
    "Merit",
    "Globalisation",
    "NewtonStop",
    "NewtonResult",
    "DenseJacobian",
    "newton",
]

State = TypeVar("State")


class Jacobian(Protocol):
    """A Jacobian J of the residual, prepared for the steps Newton takes."""

    def solve(self, rhs: NDArray) -> NDArray | None:
        """``J^-1 rhs``, or None when J is singular or the result is not finite."""
        ...

    def gradient(self, R: NDArray) -> NDArray:
        """``J^T R``, the gradient of the merit ``||R||^2 / 2``."""
        ...

    def levenberg_marquardt(self, R: NDArray, mu: float) -> NDArray | None:
        """The step ``d`` of ``(J^T J + mu diag(J^T J)) d = -J^T R``, or None."""
        ...


class NewtonSystem(Protocol[State]):
    """``R(u) = 0``: the residual, its normalisation and its Jacobian at an evaluated state.

    ``State`` is whatever :meth:`residual` computed that the Jacobian needs (e.g. the contact law's
    derivative at the AFT samples).
    """

    @property
    def scale(self) -> float:
        """Residual normalisation: convergence is ``max |R| / scale <= tolerance``."""
        ...

    def residual(self, u: NDArray) -> tuple[NDArray, State]:
        """``R(u)`` and the state for :meth:`factorise`."""
        ...

    def factorise(self, state: State) -> Jacobian:
        """``dR/du`` at the evaluated state, ready for Newton (and Levenberg-Marquardt) steps."""
        ...


class Merit(StrEnum):
    """What the line search decreases."""

    SUM_OF_SQUARES = "sum_of_squares"
    """``||R||^2 / 2``."""
    MAX_ABS = "max_abs"
    """``max |R| / scale``, the convergence measure itself."""


@dataclass(frozen=True, kw_only=True)
class Globalisation:
    """How Newton accepts a step (see the module docstring).

    Attributes
    ----------
    merit
        The merit the Armijo rule decreases.
    memory
        Accepted merits the Armijo reference is the largest of (1: monotone).
    sufficient_decrease
        Armijo's c.
    min_step
        The smallest step length tried (halving from 1).
    accept_converged_trial
        Also accept a trial whose relative residual meets the tolerance.
    levenberg_marquardt
        Take a Levenberg-Marquardt step where no step length is accepted.
    levenberg_marquardt_max_unknowns
        Above this many unknowns no Levenberg-Marquardt step is tried (a dense ``J^T J`` costs seconds per
        trial mu): the iteration stops instead.
    stagnation_window
        Stop when the merit has not fallen tenfold over this many iterations (None: never).
    """

    merit: Merit
    memory: int = 1
    sufficient_decrease: float = 1e-4
    min_step: float = 1.0 / 1024
    accept_converged_trial: bool = False
    levenberg_marquardt: bool = False
    levenberg_marquardt_max_unknowns: int = 800
    stagnation_window: int | None = None

    def __post_init__(self) -> None:
        if self.memory < 1 or not (0.0 < self.min_step <= 1.0) or not (0.0 < self.sufficient_decrease < 1.0):
            raise ValueError(
                f"Globalisation: memory = {self.memory!r}, min_step = {self.min_step!r}, sufficient_decrease = "
                f"{self.sufficient_decrease!r}; allowed: memory >= 1, 0 < min_step <= 1, 0 < sufficient_decrease < 1"
            )


class NewtonStop(StrEnum):
    """How a Newton iteration ended."""

    CONVERGED = "converged"
    """``max |R| / scale <= tolerance``."""
    NON_FINITE = "non_finite"
    """The residual is not finite."""
    STAGNATED = "stagnated"
    """The merit did not fall tenfold over the stagnation window."""
    LINE_SEARCH_FAILED = "line_search_failed"
    """No step length accepted, and no Levenberg-Marquardt step tried (not asked for, or too many unknowns)."""
    LEVENBERG_MARQUARDT_FAILED = "levenberg_marquardt_failed"
    """Neither a step length nor a Levenberg-Marquardt step accepted."""
    MAX_ITERATIONS = "max_iterations"
    """The iteration limit was reached."""


@dataclass(frozen=True)
class NewtonResult(Generic[State]):
    """Where a Newton iteration ended.

    Attributes
    ----------
    u, residual, state
        The last accepted iterate, its residual ``R(u)`` and its state.
    relative_residual
        ``max |R| / scale`` [-].
    stop
        How it ended (:class:`NewtonStop`).
    iterations
        Accepted steps.
    evaluations
        Residual evaluations (the start's included, unless it was given).
    levenberg_marquardt_steps
        Accepted steps that were Levenberg-Marquardt steps.
    """

    u: NDArray
    residual: NDArray
    state: State
    relative_residual: float
    stop: NewtonStop
    iterations: int
    evaluations: int
    levenberg_marquardt_steps: int

    @property
    def converged(self) -> bool:
        return self.stop is NewtonStop.CONVERGED


class DenseJacobian:
    """A dense Jacobian with the solves Newton needs (``least_squares``: a singular J solved in least squares)."""

    def __init__(self, J: NDArray, *, least_squares: bool = False):
        self.J = J
        self.least_squares = least_squares

    def solve(self, rhs: NDArray) -> NDArray | None:
        try:
            x = np.linalg.solve(self.J, rhs)
        except np.linalg.LinAlgError:
            if not self.least_squares:
                return None
            x = np.linalg.lstsq(self.J, rhs, rcond=None)[0]
        return x if np.all(np.isfinite(x)) else None

    def gradient(self, R: NDArray) -> NDArray:
        return self.J.T @ R

    def levenberg_marquardt(self, R: NDArray, mu: float) -> NDArray | None:
        A = self.J.T @ self.J
        A[np.diag_indices_from(A)] += mu * np.maximum(np.diag(A), 1e-300)
        try:
            x = np.linalg.solve(A, -(self.J.T @ R))
        except np.linalg.LinAlgError:
            return None
        return x if np.all(np.isfinite(x)) else None


@dataclass(frozen=True)
class _Trial(Generic[State]):
    """An accepted trial iterate."""

    u: NDArray
    residual: NDArray
    state: State
    merit: float


def newton(
    system: NewtonSystem[State],
    u0: NDArray,
    *,
    tolerance: float,
    max_iterations: int,
    globalisation: Globalisation,
    first: tuple[NDArray, State] | None = None,
) -> NewtonResult[State]:
    """Globalised Newton on ``system`` from ``u0`` (see the module docstring).

    Parameters
    ----------
    system
        The residual and its Jacobian.
    u0
        The start.
    tolerance
        Converged when ``max |R| / scale <= tolerance``.
    max_iterations
        Accepted steps at most.
    globalisation
        How a step is accepted.
    first
        ``system.residual(u0)``, when the caller has it already.
    """
    scale = float(system.scale)
    g = globalisation
    R, state = system.residual(u0) if first is None else first
    current = _Trial(u0.copy(), R, state, _merit(R, scale, g.merit))
    evaluations = 1 if first is None else 0
    history = [current.merit]
    lm_steps = 0

    def result(stop: NewtonStop, iterations: int) -> NewtonResult[State]:
        rel = float(np.max(np.abs(current.residual))) / scale
        return NewtonResult(current.u, current.residual, current.state, rel, stop, iterations, evaluations, lm_steps)

    for it in range(max_iterations + 1):
        rel = float(np.max(np.abs(current.residual))) / scale
        if not np.isfinite(rel):
            return result(NewtonStop.NON_FINITE, it)
        if rel <= tolerance:
            return result(NewtonStop.CONVERGED, it)
        if it == max_iterations:
            break
        window = g.stagnation_window
        if window is not None and len(history) > 2 * window and min(history[-window:]) > 0.1 * min(history[:-window]):
            return result(NewtonStop.STAGNATED, it)
        jac = system.factorise(current.state)
        step = jac.solve(-current.residual)
        trial: _Trial[State] | None = None
        if step is not None:
            trial, n = _line_search(system, current, step, max(history[-g.memory :]), tolerance, g)
            evaluations += n
        if trial is None and not g.levenberg_marquardt:
            return result(NewtonStop.LINE_SEARCH_FAILED, it)
        if trial is None and current.u.size > g.levenberg_marquardt_max_unknowns:
            return result(NewtonStop.LINE_SEARCH_FAILED, it)
        if trial is None:
            trial, n = _levenberg_marquardt(system, current, jac, g)
            evaluations += n
            if trial is None:
                return result(NewtonStop.LEVENBERG_MARQUARDT_FAILED, it)
            lm_steps += 1
        current = trial
        history.append(current.merit)
    return result(NewtonStop.MAX_ITERATIONS, max_iterations)


def _merit(R: NDArray, scale: float, kind: Merit) -> float:
    return 0.5 * float(R @ R) if kind is Merit.SUM_OF_SQUARES else float(np.max(np.abs(R))) / scale


def _line_search(
    system: NewtonSystem[State], current: _Trial[State], step: NDArray, reference: float, tolerance: float, g: Globalisation
) -> tuple[_Trial[State] | None, int]:
    """Backtracking from the full Newton step: the accepted trial (None: none) and the evaluations spent.

    The Armijo slope is the merit's decrease along the Newton direction at a unit step: ``||R||^2`` for
    ``||R||^2 / 2``, the merit itself for ``max |R| / scale``.
    """
    scale = float(system.scale)
    slope = 2.0 * current.merit if g.merit is Merit.SUM_OF_SQUARES else current.merit
    alpha = 1.0
    evaluations = 0
    while alpha >= g.min_step:
        u_try = current.u + alpha * step
        R_try, state_try = system.residual(u_try)
        evaluations += 1
        m_try = _merit(R_try, scale, g.merit)
        accepted = bool(np.isfinite(m_try) and m_try <= reference - g.sufficient_decrease * alpha * slope)
        if accepted or (g.accept_converged_trial and float(np.max(np.abs(R_try))) / scale <= tolerance):
            return _Trial(u_try, R_try, state_try, m_try), evaluations
        alpha *= 0.5
    return None, evaluations


def _levenberg_marquardt(
    system: NewtonSystem[State], current: _Trial[State], jac: Jacobian, g: Globalisation
) -> tuple[_Trial[State] | None, int]:
    """A Levenberg-Marquardt step, monotone in the merit (Armijo on ``J^T R``): the accepted trial (None: none) and the
    evaluations spent."""
    scale = float(system.scale)
    gradient = jac.gradient(current.residual)
    mu = 1e-6
    evaluations = 0
    while mu <= 1e6:
        step = jac.levenberg_marquardt(current.residual, mu)
        if step is not None:
            u_try = current.u + step
            R_try, state_try = system.residual(u_try)
            evaluations += 1
            m_try = _merit(R_try, scale, g.merit)
            if np.isfinite(m_try) and m_try <= current.merit + g.sufficient_decrease * float(gradient @ step):
                return _Trial(u_try, R_try, state_try, m_try), evaluations
        mu *= 10.0
    return None, evaluations
