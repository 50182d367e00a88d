"""Nonlinear solvers of the harmonic balance and the fallback chain, for any :class:`NonlinearProblem`.

Solvers: ``newton`` (semi-smooth Newton with the exact law; globalised by a non-monotone
Armijo line search on ``||R||^2 / 2``, a Levenberg-Marquardt step where the line search fails,
and an early exit on stagnation) and ``hybr`` (MINPACK's Powell hybrid method via
``scipy.optimize.root`` with the analytic Jacobian, as the source). :func:`solve_with_fallback`:
if the direct solve fails, a second direct solve starts from the linear solution, then the
solver continues in the contact-law sharpness kappa (soft to the requested law) and then in the
dynamic excitation amplitude (static state to full amplitude) before giving up; failure is
reported (``converged=False``), never raised.

Size: just over 400 lines as ruff formats it (one keyword argument a line in a call that does not
fit on one line; about 390 lines before); the solvers and the fallback chain that calls them in turn
stay together.
"""

from __future__ import annotations

import logging
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, Protocol

import numpy as np
from numpy.typing import NDArray
from scipy import sparse
from scipy.optimize import root
from scipy.sparse.linalg import SuperLU, splu

from seafast.config.modes import ContactLawKind, NonlinearSolver
from seafast.solvers.contact import ContactLaw
from seafast.solvers.hbm.options import HBMOptions
from seafast.solvers.outcome import SolverOutcome

logger = logging.getLogger(__name__)

__all__ = [
    "FactorisedJacobian",
    "NonlinearProblem",
    "DenseJacobian",
    "SparseJacobian",
    "SolveAttempt",
    "solve_with_fallback",
]


class FactorisedJacobian(Protocol):
    """A Jacobian J of the residual, prepared for the steps the nonlinear solvers take."""

    def solve(self, rhs: NDArray) -> NDArray | None:
        """``J^-1 rhs``, or None when J is singular or the result is not finite."""
        ...

    def gradient(self, R: NDArray) -> NDArray:
        """``J^T R``, the gradient of the merit ``||R||^2 / 2``."""
        ...

    def levenberg_marquardt(self, R: NDArray, mu: float) -> NDArray | None:
        """The step ``d`` of ``(J^T J + mu diag(J^T J)) d = -J^T R``, or None."""
        ...


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

    def factorise(self, state: NDArray) -> FactorisedJacobian:
        """``dR/du`` at the evaluated state, ready for Newton and Levenberg-Marquardt steps."""
        ...


class DenseJacobian:
    """A dense Jacobian with the solves the nonlinear solvers need."""

    def __init__(self, J: NDArray):
        self.J = J

    def solve(self, rhs: NDArray) -> NDArray | None:
        try:
            x = np.linalg.solve(self.J, rhs)
        except np.linalg.LinAlgError:
            return None
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


@dataclass
class SolveAttempt:
    """One nonlinear solve (or the whole fallback chain): the iterate reached and how.

    ``residual`` is relative (max |R| over the problem's ``scale``); ``note`` tells people the
    path taken; ``by_continuation`` whether a continuation (not the direct solve) converged.
    """

    u: NDArray
    converged: bool
    residual: float
    iterations: int
    evaluations: int
    note: str
    by_continuation: bool = False

    @property
    def outcome(self) -> SolverOutcome:
        """The typed outcome of this attempt."""
        if not self.converged:
            return SolverOutcome.NOT_CONVERGED
        return SolverOutcome.CONVERGED_BY_CONTINUATION if self.by_continuation else SolverOutcome.CONVERGED


_ARMIJO = 1e-4
_NONMONOTONE_MEMORY = 4
_MIN_STEP = 1.0 / 1024
_STAGNATION_WINDOW = 12
_LEVENBERG_MARQUARDT_MAX_UNKNOWNS = 800


def _newton(problem: NonlinearProblem, law: ContactLaw, amplitude: float, u0: NDArray, tol: float, max_iter: int) -> SolveAttempt:
    """Globalised (semi-smooth) Newton on the merit ``theta = ||R||^2 / 2``.

    Each iteration takes the Newton direction ``d = -J^-1 R`` (with the exact law J is an
    element of the generalised Jacobian: semi-smooth Newton) and backtracks with a
    non-monotone Armijo rule (Grippo-Lampariello-Lucidi: ``theta`` must fall below the largest
    of the last few accepted values by ``1e-4 alpha ||R||^2``), which lets the iteration cross
    the kinks of the piecewise-linear exact law instead of stalling in front of them. When no
    step length down to 1/1024 is accepted (a kink right ahead, a near-singular J), a
    Levenberg-Marquardt step ``(J^T J + mu diag(J^T J)) d = -J^T R`` with increasing mu is taken
    instead, monotone in ``theta``; Newton resumes at the next iteration. The attempt is
    abandoned (for the caller's fallbacks) when ``theta`` has not fallen tenfold over 12
    iterations: near a solution semi-smooth Newton terminates in a few steps, so this is a
    zig-zag between contact patterns, not slow progress.
    """
    scale = problem.scale
    u = u0.copy()
    R, state = problem.evaluate(u, law, amplitude)
    nfev = 1
    theta = 0.5 * float(R @ R)
    history = [theta]
    lm_steps = 0
    for it in range(max_iter + 1):
        rel = float(np.max(np.abs(R))) / scale
        if not np.isfinite(rel):
            return SolveAttempt(u, False, rel, it, nfev, "non-finite residual")
        if rel <= tol:
            extra = f", {lm_steps} Levenberg-Marquardt step(s)" if lm_steps else ""
            return SolveAttempt(u, True, rel, it, nfev, f"newton converged in {it} iteration(s){extra}")
        if it == max_iter:
            break
        if len(history) > 2 * _STAGNATION_WINDOW and min(history[-_STAGNATION_WINDOW:]) > 0.1 * min(history[:-_STAGNATION_WINDOW]):
            return SolveAttempt(u, False, rel, it, nfev, f"newton stagnated (merit not reduced tenfold in {_STAGNATION_WINDOW} iterations)")
        jac = problem.factorise(state)
        step = jac.solve(-R)
        accepted = False
        if step is not None:
            reference = max(history[-_NONMONOTONE_MEMORY:])
            alpha = 1.0
            while alpha >= _MIN_STEP:
                u_try = u + alpha * step
                R_try, state_try = problem.evaluate(u_try, law, amplitude)
                nfev += 1
                th_try = 0.5 * float(R_try @ R_try)
                if np.isfinite(th_try) and th_try <= reference - _ARMIJO * alpha * 2.0 * theta:
                    accepted = True
                    break
                alpha *= 0.5
        if not accepted and u.size > _LEVENBERG_MARQUARDT_MAX_UNKNOWNS:
            # a dense J^T J of this size costs seconds per trial mu: leave it to the caller's fallbacks
            return SolveAttempt(u, False, rel, it, nfev, f"newton line search failed ({u.size} unknowns: no Levenberg-Marquardt step)")
        if not accepted:
            g = jac.gradient(R)
            mu = 1e-6
            while mu <= 1e6:
                step = jac.levenberg_marquardt(R, mu)
                if step is not None:
                    u_try = u + step
                    R_try, state_try = problem.evaluate(u_try, law, amplitude)
                    nfev += 1
                    th_try = 0.5 * float(R_try @ R_try)
                    if np.isfinite(th_try) and th_try <= theta + _ARMIJO * float(g @ step):
                        accepted = True
                        lm_steps += 1
                        break
                mu *= 10.0
            if not accepted:
                return SolveAttempt(u, False, rel, it, nfev, "newton line search and Levenberg-Marquardt steps failed")
        u, R, state, theta = u_try, R_try, state_try, th_try
        history.append(theta)
    return SolveAttempt(u, False, float(np.max(np.abs(R))) / scale, max_iter, nfev, "newton reached max_iterations")


def _hybr(problem: NonlinearProblem, law: ContactLaw, amplitude: float, u0: NDArray, tol: float, max_iter: int) -> SolveAttempt:
    """MINPACK hybrj (Powell hybrid) with the analytic Jacobian."""
    cache: dict[str, Any] = {}
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
    return SolveAttempt(u, ok, rel, counter["jev"], counter["fev"] + 1, note)


_SOLVER_FUNCTIONS: dict[NonlinearSolver, Callable[..., SolveAttempt]] = {NonlinearSolver.NEWTON: _newton, NonlinearSolver.HYBR: _hybr}


def _start(problem: NonlinearProblem, law: ContactLaw, amplitude: float) -> tuple[NDArray, str]:
    """The better (smaller residual) of the linear solution and the quasi-static contact predictor."""
    u_lin = problem.initial_guess(amplitude)
    u_pre = problem.predictor(amplitude)
    if u_pre is u_lin or np.array_equal(u_pre, u_lin):
        return u_lin, "linear solution"
    r_lin = float(np.linalg.norm(problem.evaluate(u_lin, law, amplitude)[0]))
    r_pre = float(np.linalg.norm(problem.evaluate(u_pre, law, amplitude)[0]))
    if r_pre <= r_lin:
        return u_pre, "quasi-static contact predictor"
    return u_lin, "linear solution"


def solve_with_fallback(problem: NonlinearProblem, law: ContactLaw, options: HBMOptions, u_start: NDArray | None = None) -> SolveAttempt:
    """Direct solve; on failure continuation in kappa, then in the dynamic amplitude.

    The direct solve starts from ``u_start`` if given, else from the better of the linear
    solution and the quasi-static exact-contact predictor. The attempt's ``outcome`` says how
    it ended; ``note`` tells people the path taken (also logged: DEBUG for a direct solve, INFO
    for the fallbacks).
    """
    solve = _SOLVER_FUNCTIONS[options.solver]
    tol, maxit = float(options.tolerance), int(options.max_iterations)
    if u_start is None:
        u0, origin = _start(problem, law, 1.0)
    else:
        u0, origin = u_start, "given initial guess"
    first = solve(problem, law, 1.0, u0, tol, maxit)
    total_it, total_ev = first.iterations, first.evaluations
    if first.converged or not options.continuation:
        logger.log(logging.DEBUG if first.converged else logging.INFO, "direct solve: %s (start: %s)", first.note, origin)
        return SolveAttempt(first.u, first.converged, first.residual, total_it, total_ev, f"direct: {first.note} (start: {origin})")
    notes = [f"direct solve failed ({first.note}, start: {origin}, residual {first.residual:.2e})"]
    logger.info("%s; falling back", notes[0])
    best = first
    if u_start is None and origin != "linear solution":
        # a second direct attempt from the linear solution (another path across the kinks)
        second = solve(problem, law, 1.0, problem.initial_guess(1.0), tol, maxit)
        total_it += second.iterations
        total_ev += second.evaluations
        if second.converged:
            logger.info("direct solve from the linear solution converged: %s", second.note)
            return SolveAttempt(
                second.u,
                True,
                second.residual,
                total_it,
                total_ev,
                f"direct: {second.note} (start: linear solution, after a failed start from the {origin})",
            )
        notes.append(f"direct solve from the linear solution failed ({second.note}, residual {second.residual:.2e})")
        best = second if second.residual < best.residual else best

    # (1) continuation in the sharpness kappa, from a soft law to the requested one
    delta_scale = float(problem.compression_scale_m)
    soft_name = ContactLawKind.SOFTPLUS if law.name is ContactLawKind.EXACT else law.name
    kappa_target = law.regularisation_per_m if law.name is not ContactLawKind.EXACT else 1e4 / delta_scale
    kappa_start = min(1.0 / delta_scale, kappa_target / 10.0)
    if kappa_start < kappa_target:
        u = u0
        kappas = list(np.geomspace(kappa_start, kappa_target, 1 + int(np.ceil(2 * np.log10(kappa_target / kappa_start)))))
        reached = 0
        for kappa in kappas:
            a = solve(problem, ContactLaw(soft_name, float(kappa)), 1.0, u, tol, maxit)
            total_it += a.iterations
            total_ev += a.evaluations
            if not a.converged:
                break
            u, reached = a.u, reached + 1
        if reached:
            # the requested law from the sharpest soft solution reached (the whole path, or the
            # part of it that converged: a sharp soft law can be harder than the exact one)
            final = solve(problem, law, 1.0, u, tol, maxit)
            total_it += final.iterations
            total_ev += final.evaluations
            if final.converged:
                notes.append(f"converged by continuation in kappa over {reached} of {len(kappas)} step(s)")
                logger.info(notes[-1])
                return SolveAttempt(final.u, True, final.residual, total_it, total_ev, "; ".join(notes), by_continuation=True)
            best = final if final.residual < best.residual else best
        notes.append("kappa continuation failed")

    # (2) continuation in the dynamic excitation amplitude, from the static state
    static = solve(problem, law, 0.0, _start(problem, law, 0.0)[0], tol, maxit)
    total_it += static.iterations
    total_ev += static.evaluations
    if static.converged:
        lam, step, u = 0.0, 0.25, static.u
        n_steps = 0
        while lam < 1.0 and step >= 1.0 / 2048:
            lam_try = min(1.0, lam + step)
            guess = u + (problem.initial_guess(lam_try) - problem.initial_guess(lam))
            a = solve(problem, law, lam_try, guess, tol, maxit)
            total_it += a.iterations
            total_ev += a.evaluations
            n_steps += 1
            if a.converged:
                lam, u = lam_try, a.u
                step = min(2.0 * step, 0.5)
            else:
                step *= 0.5
        if lam >= 1.0:
            R, _ = problem.evaluate(u, law, 1.0)
            notes.append(f"converged by continuation in excitation amplitude ({n_steps} step(s))")
            logger.info(notes[-1])
            return SolveAttempt(
                u, True, float(np.max(np.abs(R))) / problem.scale, total_it, total_ev, "; ".join(notes), by_continuation=True
            )
        notes.append(f"amplitude continuation stalled at {lam:.3g} of the excitation")
    else:
        notes.append("the static state did not converge")
    logger.info("not converged (residual %.2e): %s", best.residual, "; ".join(notes[1:]))
    return SolveAttempt(best.u, False, best.residual, total_it, total_ev, "; ".join(notes) + "; NOT CONVERGED")
