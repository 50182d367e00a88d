"""Nonlinear solvers of the harmonic balance and the fallback chain, for any :class:`NonlinearProblem`.

Solvers: ``newton`` (the shared globalised semi-smooth Newton of :mod:`seafast.solvers.newton`: a
non-monotone Armijo line search on ``||R||^2 / 2``, a Levenberg-Marquardt step where the line search
fails, and an early exit on stagnation) and ``hybr`` (MINPACK's Powell hybrid method via
``scipy.optimize.root`` with the analytic Jacobian, as the source). :func:`solve_with_fallback`:
if the direct solve fails, a second direct solve starts from the linear solution, then the
solver continues in the contact-law sharpness kappa (soft to the requested law) and then in the
dynamic excitation amplitude (static state to full amplitude) before giving up; failure is
reported (``converged=False``), never raised. Which start and which route reached the answer are
typed (:class:`~seafast.solvers.outcome.HBMPath`).
"""

from __future__ import annotations

import logging
from collections.abc import Callable
from dataclasses import dataclass
from typing import Protocol

import numpy as np
from numpy.typing import NDArray
from scipy import sparse
from scipy.optimize import root
from scipy.sparse.linalg import SuperLU, splu

from seafast.config.modes import ContactLawKind, NonlinearSolver
from seafast.solvers.contact import ContactLaw
from seafast.solvers.hbm.options import HBMOptions
from seafast.solvers.newton import Globalisation, Jacobian, Merit, NewtonResult, NewtonStop, newton
from seafast.solvers.outcome import HBMPath, HBMRoute, HBMStart, SolverOutcome

logger = logging.getLogger(__name__)

__all__ = ["NonlinearProblem", "SparseJacobian", "SolveAttempt", "solve_with_fallback"]


class NonlinearProblem(Protocol):
    """A harmonic-balance system ``R(u) = 0`` (condensed or full formulation).

    ``u`` is the real vector of unknown harmonic coefficients; ``amplitude`` in [0, 1] scales
    the dynamic excitation (1 = the problem as posed, 0 = its static part), for continuation.
    ``state`` is whatever :meth:`evaluate` computed that the Jacobian needs (the contact law's
    derivative at the AFT samples, (N, n_s) [N/m]).
    """

    scale: float
    """Residual normalisation: convergence is ``max |R| / scale <= tolerance``."""

    @property
    def compression_scale_m(self) -> float:
        """Typical saddle compression [m] (the largest linear one): sets the kappa path of the fallback."""
        ...

    def initial_guess(self, amplitude: float) -> NDArray:
        """The linear (bilateral-saddle) solution at ``amplitude``."""
        ...

    def predictor(self, amplitude: float) -> NDArray:
        """The quasi-static exact-contact predictor at ``amplitude`` (the linear solution when contact is kept)."""
        ...

    def evaluate(self, u: NDArray, law: ContactLaw, amplitude: float) -> tuple[NDArray, NDArray]:
        """Residual ``R(u)`` and the state for :meth:`jacobian` / :meth:`factorise`."""
        ...

    def jacobian(self, state: NDArray) -> NDArray:
        """Dense ``dR/du`` at the evaluated state."""
        ...

    def factorise(self, state: NDArray) -> Jacobian:
        """``dR/du`` at the evaluated state, ready for Newton and Levenberg-Marquardt steps."""
        ...


class SparseJacobian:
    """A sparse Jacobian factorised once (SuperLU) for Newton steps; LM steps on demand."""

    def __init__(self, J: sparse.csc_matrix | sparse.csr_matrix) -> None:
        self.J = J.tocsc()
        self.lu: SuperLU | None
        try:
            self.lu = splu(self.J)
        except RuntimeError:  # exactly singular
            self.lu = None

    def solve(self, rhs: NDArray) -> NDArray | None:
        if self.lu is None:
            return None
        x = self.lu.solve(rhs)
        return x if np.all(np.isfinite(x)) else None

    def gradient(self, R: NDArray) -> NDArray:
        return self.J.T @ R

    def levenberg_marquardt(self, R: NDArray, mu: float) -> NDArray | None:
        A = (self.J.T @ self.J).tocsc()
        d = A.diagonal()
        A = A + sparse.diags(mu * np.maximum(d, 1e-300), format="csc")
        try:
            x = splu(A).solve(-(self.J.T @ R))
        except RuntimeError:
            return None
        return x if np.all(np.isfinite(x)) else None


@dataclass(frozen=True)
class _Solve:
    """One nonlinear solve from one start: the iterate reached, its relative residual and how it ended."""

    u: NDArray
    converged: bool
    residual: float
    iterations: int
    evaluations: int
    note: str
    stop: NewtonStop | None  # None: Powell's method


@dataclass(frozen=True)
class SolveAttempt:
    """The fallback chain's result: the iterate reached and how.

    ``residual`` is relative (max |R| over the problem's ``scale``); ``path`` the typed start, route and last
    Newton stop (:class:`~seafast.solvers.outcome.HBMPath`); ``note`` tells people the path taken.
    """

    u: NDArray
    converged: bool
    residual: float
    iterations: int
    evaluations: int
    note: str
    path: HBMPath

    @property
    def by_continuation(self) -> bool:
        """Whether a continuation (not a direct solve) converged."""
        return self.path.route.by_continuation

    @property
    def outcome(self) -> SolverOutcome:
        """The typed outcome of this attempt."""
        if not self.converged:
            return SolverOutcome.NOT_CONVERGED
        return SolverOutcome.CONVERGED_BY_CONTINUATION if self.by_continuation else SolverOutcome.CONVERGED


_GLOBALISATION = Globalisation(
    merit=Merit.SUM_OF_SQUARES,
    memory=4,
    min_step=1.0 / 1024,
    levenberg_marquardt=True,
    levenberg_marquardt_max_unknowns=800,
    stagnation_window=12,
)
"""The harmonic balance's Newton: non-monotone Armijo (memory 4) on ``||R||^2 / 2`` down to steps of 1/1024, then a
Levenberg-Marquardt step (up to 800 unknowns: a dense ``J^T J`` beyond costs seconds per trial mu); abandoned when the
merit has not fallen tenfold over 12 iterations (a zig-zag between contact patterns, for the fallbacks)."""


@dataclass(frozen=True)
class _AtLaw:
    """A :class:`NonlinearProblem` at one contact law and excitation amplitude, as a Newton system."""

    problem: NonlinearProblem
    law: ContactLaw
    amplitude: float

    @property
    def scale(self) -> float:
        return float(self.problem.scale)

    def residual(self, u: NDArray) -> tuple[NDArray, NDArray]:
        return self.problem.evaluate(u, self.law, self.amplitude)

    def factorise(self, state: NDArray) -> Jacobian:
        return self.problem.factorise(state)


def _note(result: NewtonResult[NDArray]) -> str:
    """The Newton solve's account for people."""
    if result.stop is NewtonStop.CONVERGED:
        extra = f", {result.levenberg_marquardt_steps} Levenberg-Marquardt step(s)" if result.levenberg_marquardt_steps else ""
        return f"newton converged in {result.iterations} iteration(s){extra}"
    return {
        NewtonStop.NON_FINITE: "non-finite residual",
        NewtonStop.STAGNATED: f"newton stagnated (merit not reduced tenfold in {_GLOBALISATION.stagnation_window} iterations)",
        NewtonStop.LINE_SEARCH_FAILED: f"newton line search failed ({result.u.size} unknowns: no Levenberg-Marquardt step)",
        NewtonStop.LEVENBERG_MARQUARDT_FAILED: "newton line search and Levenberg-Marquardt steps failed",
        NewtonStop.MAX_ITERATIONS: "newton reached max_iterations",
    }[result.stop]


def _newton(problem: NonlinearProblem, law: ContactLaw, amplitude: float, u0: NDArray, tol: float, max_iter: int) -> _Solve:
    """The shared Newton (:func:`seafast.solvers.newton.newton`) with the harmonic balance's globalisation."""
    result = newton(_AtLaw(problem, law, amplitude), u0, tolerance=tol, max_iterations=max_iter, globalisation=_GLOBALISATION)
    return _Solve(result.u, result.converged, result.relative_residual, result.iterations, result.evaluations, _note(result), result.stop)


def _hybr(problem: NonlinearProblem, law: ContactLaw, amplitude: float, u0: NDArray, tol: float, max_iter: int) -> _Solve:
    """MINPACK hybrj (Powell hybrid) with the analytic Jacobian."""
    cache: dict[str, NDArray] = {}
    counter = {"fev": 0, "jev": 0}

    def fun(u: NDArray) -> NDArray:
        R, state = problem.evaluate(u, law, amplitude)
        counter["fev"] += 1
        cache["u"], cache["state"] = u.copy(), state
        return R

    def jac(u: NDArray) -> NDArray:
        counter["jev"] += 1
        if "u" in cache and np.array_equal(cache["u"], u):
            return problem.jacobian(cache["state"])
        return problem.jacobian(problem.evaluate(u, law, amplitude)[1])

    # scipy-stubs 1.17 misspell hybr's maxfev (maxffev), fixed in 1.18.1.1 (scipy/scipy-stubs#2374); drop the ignore then
    options = {"xtol": max(tol, 1e-14), "maxfev": 50 * max_iter}
    sol = root(fun, u0, jac=jac, method="hybr", options=options)  # type: ignore[call-overload]
    u = np.asarray(sol.x, dtype=float)
    R, _ = problem.evaluate(u, law, amplitude)
    rel = float(np.max(np.abs(R))) / problem.scale
    ok = bool(np.isfinite(rel) and rel <= max(tol, 1e-13) * 10.0)
    note = f"hybr: {sol.message.strip()}"
    if ok and not sol.success:
        # MINPACK stops on its own progress test; the residual is what decides convergence here
        note += f" (residual {rel:.1e} within tolerance: accepted)"
    return _Solve(u, ok, rel, counter["jev"], counter["fev"] + 1, note, None)


_SOLVER_FUNCTIONS: dict[NonlinearSolver, Callable[[NonlinearProblem, ContactLaw, float, NDArray, float, int], _Solve]] = {
    NonlinearSolver.NEWTON: _newton,
    NonlinearSolver.HYBR: _hybr,
}

_START_WORDS = {
    HBMStart.LINEAR: "linear solution",
    HBMStart.PREDICTOR: "quasi-static contact predictor",
    HBMStart.GIVEN: "given initial guess",
    HBMStart.MARCH: "given initial guess",
    HBMStart.PREVIOUS_HARMONICS: "given initial guess",
}
"""What the notes call each start (every given start, the march's included, is a "given initial guess")."""


def _start(problem: NonlinearProblem, law: ContactLaw, amplitude: float) -> tuple[NDArray, HBMStart]:
    """The better (smaller residual) of the linear solution and the quasi-static contact predictor."""
    u_lin = problem.initial_guess(amplitude)
    u_pre = problem.predictor(amplitude)
    if u_pre is u_lin or np.array_equal(u_pre, u_lin):
        return u_lin, HBMStart.LINEAR
    r_lin = float(np.linalg.norm(problem.evaluate(u_lin, law, amplitude)[0]))
    r_pre = float(np.linalg.norm(problem.evaluate(u_pre, law, amplitude)[0]))
    if r_pre <= r_lin:
        return u_pre, HBMStart.PREDICTOR
    return u_lin, HBMStart.LINEAR


@dataclass
class _Chain:
    """The fallback chain's running account: the solves' cost, the best failed iterate, the notes."""

    problem: NonlinearProblem
    solve: Callable[[NonlinearProblem, ContactLaw, float, NDArray, float, int], _Solve]
    tolerance: float
    max_iterations: int
    start: HBMStart
    best: _Solve
    notes: list[str]
    iterations: int = 0
    evaluations: int = 0

    def run(self, law: ContactLaw, amplitude: float, u0: NDArray) -> _Solve:
        a = self.solve(self.problem, law, amplitude, u0, self.tolerance, self.max_iterations)
        self.iterations += a.iterations
        self.evaluations += a.evaluations
        return a

    def keep_best(self, a: _Solve) -> None:
        if a.residual < self.best.residual:
            self.best = a

    def converged(self, a: _Solve, route: HBMRoute, note: str) -> SolveAttempt:
        return SolveAttempt(a.u, True, a.residual, self.iterations, self.evaluations, note, HBMPath(self.start, route, a.stop))


def solve_with_fallback(
    problem: NonlinearProblem, law: ContactLaw, options: HBMOptions, u_start: NDArray | None = None, start: HBMStart = HBMStart.GIVEN
) -> SolveAttempt:
    """Direct solve; on failure continuation in kappa, then in the dynamic amplitude.

    The direct solve starts from ``u_start`` if given (``start`` says what it is: a given start, the periodic
    march, the previous H's solution), else from the better of the linear solution and the quasi-static
    exact-contact predictor. The attempt's ``outcome`` and ``path`` say how it ended; ``note`` tells people
    the path taken (also logged: DEBUG for a direct solve, INFO for the fallbacks).
    """
    solve = _SOLVER_FUNCTIONS[options.solver]
    if u_start is None:
        u0, start = _start(problem, law, 1.0)
    else:
        u0 = u_start
    origin = _START_WORDS[start]
    first = solve(problem, law, 1.0, u0, float(options.tolerance), int(options.max_iterations))
    chain = _Chain(
        problem, solve, float(options.tolerance), int(options.max_iterations), start, first, [], first.iterations, first.evaluations
    )
    if first.converged or not options.continuation:
        logger.log(logging.DEBUG if first.converged else logging.INFO, "direct solve: %s (start: %s)", first.note, origin)
        route = HBMRoute.DIRECT if first.converged else HBMRoute.NONE
        path = HBMPath(start, route, first.stop)
        return SolveAttempt(
            first.u, first.converged, first.residual, chain.iterations, chain.evaluations, f"direct: {first.note} (start: {origin})", path
        )
    chain.notes.append(f"direct solve failed ({first.note}, start: {origin}, residual {first.residual:.2e})")
    logger.info("%s; falling back", chain.notes[0])
    if u_start is None and start is not HBMStart.LINEAR:
        # a second direct attempt from the linear solution (another path across the kinks)
        second = chain.run(law, 1.0, problem.initial_guess(1.0))
        if second.converged:
            logger.info("direct solve from the linear solution converged: %s", second.note)
            note = f"direct: {second.note} (start: linear solution, after a failed start from the {origin})"
            return chain.converged(second, HBMRoute.DIRECT_FROM_LINEAR, note)
        chain.notes.append(f"direct solve from the linear solution failed ({second.note}, residual {second.residual:.2e})")
        chain.keep_best(second)
    found = _kappa_continuation(chain, law, u0)
    if found is None:
        found = _amplitude_continuation(chain, law)
    if found is not None:
        return found
    logger.info("not converged (residual %.2e): %s", chain.best.residual, "; ".join(chain.notes[1:]))
    best = chain.best
    path = HBMPath(start, HBMRoute.NONE, best.stop)
    return SolveAttempt(best.u, False, best.residual, chain.iterations, chain.evaluations, "; ".join(chain.notes) + "; NOT CONVERGED", path)


def _kappa_continuation(chain: _Chain, law: ContactLaw, u0: NDArray) -> SolveAttempt | None:
    """Continuation in the sharpness kappa, from a soft law to the requested one (None: it did not converge)."""
    delta_scale = float(chain.problem.compression_scale_m)
    soft_name = ContactLawKind.SOFTPLUS if law.name is ContactLawKind.EXACT else law.name
    kappa_target = law.regularisation_per_m if law.name is not ContactLawKind.EXACT else 1e4 / delta_scale
    kappa_start = min(1.0 / delta_scale, kappa_target / 10.0)
    if not kappa_start < kappa_target:
        return None
    u = u0
    kappas = list(np.geomspace(kappa_start, kappa_target, 1 + int(np.ceil(2 * np.log10(kappa_target / kappa_start)))))
    reached = 0
    for kappa in kappas:
        a = chain.run(ContactLaw(soft_name, float(kappa)), 1.0, u)
        if not a.converged:
            break
        u, reached = a.u, reached + 1
    if reached:
        # the requested law from the sharpest soft solution reached (the whole path, or the
        # part of it that converged: a sharp soft law can be harder than the exact one)
        final = chain.run(law, 1.0, u)
        if final.converged:
            chain.notes.append(f"converged by continuation in kappa over {reached} of {len(kappas)} step(s)")
            logger.info(chain.notes[-1])
            return chain.converged(final, HBMRoute.KAPPA_CONTINUATION, "; ".join(chain.notes))
        chain.keep_best(final)
    chain.notes.append("kappa continuation failed")
    return None


def _amplitude_continuation(chain: _Chain, law: ContactLaw) -> SolveAttempt | None:
    """Continuation in the dynamic excitation amplitude, from the static state (None: it did not converge)."""
    problem = chain.problem
    static = chain.run(law, 0.0, _start(problem, law, 0.0)[0])
    if not static.converged:
        chain.notes.append("the static state did not converge")
        return None
    lam, step, u = 0.0, 0.25, static.u
    n_steps = 0
    last = static
    while lam < 1.0 and step >= 1.0 / 2048:
        lam_try = min(1.0, lam + step)
        guess = u + (problem.initial_guess(lam_try) - problem.initial_guess(lam))
        a = chain.run(law, lam_try, guess)
        n_steps += 1
        if a.converged:
            lam, u, last = lam_try, a.u, a
            step = min(2.0 * step, 0.5)
        else:
            step *= 0.5
    if lam < 1.0:
        chain.notes.append(f"amplitude continuation stalled at {lam:.3g} of the excitation")
        return None
    R, _ = problem.evaluate(u, law, 1.0)
    chain.notes.append(f"converged by continuation in excitation amplitude ({n_steps} step(s))")
    logger.info(chain.notes[-1])
    reached = _Solve(u, True, float(np.max(np.abs(R))) / problem.scale, 0, 0, last.note, last.stop)
    return chain.converged(reached, HBMRoute.AMPLITUDE_CONTINUATION, "; ".join(chain.notes))
