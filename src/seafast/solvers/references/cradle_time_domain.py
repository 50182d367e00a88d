"""The time-domain reference of the 3-D cargo on its cradles: the equations of motion integrated to the periodic state.

The same equations as the harmonic balance (:mod:`seafast.solvers.cradle_dynamics`), with the exact law and
nothing condensed or truncated::

    M q'' + D q' + K0 q = f(t) - K_co,springs x_o(t) - D_co x_o'(t) - A^T (k max(s0 + A q + E x_o(t), 0)),

on every cargo DOF, integrated by scipy's LSODA (stiff BDF with error control; the Jacobian of the current contact state
given exactly) from the statics at zero heel, period after period, until the state at the
start of a period repeats. Dense in the DOFs: meant for small models (tens of nodes), as an independent check.
Units: SI; time [s].
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray
from scipy.integrate import solve_ivp

from seafast.excitation.cradle_loads import CradleExcitation
from seafast.fourier import period_fraction
from seafast.solvers.cradle_dynamics import CradleDynamics
from seafast.solvers.cradle_hbm import CradleResponse, cradle_response
from seafast.solvers.outcome import SolverOutcome
from seafast.solvers.transverse_statics import StaticsOutcome, solve_transverse_statics

__all__ = ["CradleTimeDomainOptions", "CradleEquations", "PeriodicRun", "integrate_to_periodic", "solve_cradle_time_domain"]


@dataclass(frozen=True)
class CradleTimeDomainOptions:
    """Settings of the 3-D time-domain reference.

    Parameters
    ----------
    time_samples
        N samples of the last period reported (>= 8).
    relative_tolerance
        The integrator's relative error tolerance (its absolute tolerance is this times each DOF's static scale).
    periodicity_tolerance
        The period-start states of two successive periods agree to this, relative to the state's scale.
    max_periods
        Periods integrated at most (>= 2).
    """

    time_samples: int = 256
    relative_tolerance: float = 1e-8
    periodicity_tolerance: float = 1e-6
    max_periods: int = 40

    def __post_init__(self) -> None:
        if int(self.time_samples) < 8:
            raise ValueError(f"time_samples = {self.time_samples!r}: allowed an integer >= 8")
        for name in ("relative_tolerance", "periodicity_tolerance"):
            if not 0.0 < float(getattr(self, name)) < 1.0:
                raise ValueError(f"{name} = {getattr(self, name)!r}: allowed a number in (0, 1)")
        if int(self.max_periods) < 2:
            raise ValueError(f"max_periods = {self.max_periods!r}: allowed an integer >= 2")


class CradleEquations:
    """The right-hand side of the first-order system in (q, q') and its Jacobian (the contact state of the evaluation).

    The frictional reference (:mod:`seafast.solvers.references.cradle_friction_time_domain`) extends it with the
    pads' sliders.
    """

    def __init__(self, dynamics: CradleDynamics, excitation: CradleExcitation) -> None:
        problem = dynamics.problem
        K0, M, D = dynamics.matrices
        self.n = K0.shape[0]
        self.w = float(excitation.omega_rad_s)
        self.A, self.k = problem.engagement_matrix, problem.element_stiffness_N_per_m
        self.E, self.s0 = dynamics.deck_engagement, dynamics.initial_engagement_m
        self.Minv_K0, self.Minv_D = np.linalg.solve(M, K0), np.linalg.solve(M, D)
        self.Minv_At = np.linalg.solve(M, self.A.T)
        xo = np.array(excitation.deck_displacement, dtype=complex)
        xo[0] = xo[0].real
        self.xo = xo
        f = np.array(excitation.cargo_load_N, dtype=complex)
        f[0] = (f[0] + dynamics.static_load_N()).real
        K_co, D_co = dynamics.spring_coupling, dynamics.support_damping_coupling
        # the loads on the cargo, harmonics 0 and 1, with the springs' and the damping's coupling to the deck
        self.g = np.linalg.solve(M, (f - xo @ K_co.T - 1j * self.w * np.array([0.0, 1.0])[:, None] * (xo @ D_co.T)).T).T

    def deck(self, t: float) -> NDArray[np.float64]:
        return np.real(self.xo[0] + self.xo[1] * np.exp(1j * self.w * t))

    def engagement(self, t: float, q: NDArray[np.float64]) -> NDArray[np.float64]:
        return self.s0 + self.A @ q + self.E @ self.deck(t)

    def rhs(self, t: float, y: NDArray[np.float64]) -> NDArray[np.float64]:
        q, v = y[: self.n], y[self.n :]
        force = self.k * np.maximum(self.engagement(t, q), 0.0)
        a = np.real(self.g[0] + self.g[1] * np.exp(1j * self.w * t)) - self.Minv_K0 @ q - self.Minv_D @ v - self.Minv_At @ force
        return np.concatenate([v, a])

    def jacobian(self, t: float, y: NDArray[np.float64]) -> NDArray[np.float64]:
        engaged = self.engagement(t, y[: self.n]) > 0.0
        stiffness = self.Minv_K0 + self.Minv_At[:, engaged] @ (self.k[engaged, None] * self.A[engaged])
        J = np.zeros((2 * self.n, 2 * self.n))
        J[: self.n, self.n :] = np.eye(self.n)
        J[self.n :, : self.n], J[self.n :, self.n :] = -stiffness, -self.Minv_D
        return J


@dataclass(frozen=True)
class PeriodicRun:
    """The last period integrated, sampled at ``t_n = t0 + n T / N``.

    Attributes
    ----------
    time_s, states
        Sample times (N,) [s] and the states there (n_state, N).
    periods
        Periods integrated.
    change
        The largest change of the period-start state over the last period, relative to the state and its scale [-].
    """

    time_s: NDArray[np.float64]
    states: NDArray[np.float64]
    periods: int
    change: float


def integrate_to_periodic(
    rhs: Callable[[float, NDArray[np.float64]], NDArray[np.float64]],
    jacobian: Callable[[float, NDArray[np.float64]], NDArray[np.float64]],
    start: NDArray[np.float64],
    scale: NDArray[np.float64],
    period_s: float,
    options: CradleTimeDomainOptions,
) -> PeriodicRun:
    """Integrate ``y' = rhs(t, y)`` by LSODA period after period from ``start`` until two successive period starts
    agree to ``options.periodicity_tolerance`` (relative to ``|y| + scale``) or ``options.max_periods`` are done.

    Raises RuntimeError when the integrator fails.
    """
    T, N, y = float(period_s), int(options.time_samples), np.asarray(start, dtype=float)
    change = np.inf
    for period in range(int(options.max_periods)):
        t0 = period * T
        run = solve_ivp(
            rhs, (t0, t0 + T), y, method="LSODA", t_eval=t0 + T * np.append(period_fraction(N), 1.0), jac=jacobian,
            rtol=float(options.relative_tolerance), atol=float(options.relative_tolerance) * scale,
        )  # fmt: skip
        if not run.success:
            raise RuntimeError(f"the time integration failed in period {period}: {run.message}")
        change = float(np.max(np.abs(run.y[:, -1] - y) / (np.abs(y) + scale)))
        y = run.y[:, -1]  # the state at the period's end, t0 + T: the next period's start
        if change < options.periodicity_tolerance and period > 0:
            break
    return PeriodicRun(run.t[:-1], run.y[:, :-1], period + 1, change)


def solve_cradle_time_domain(
    dynamics: CradleDynamics, excitation: CradleExcitation, options: CradleTimeDomainOptions | None = None
) -> CradleResponse:
    """The periodic steady state by time integration, sampled on the last period at ``t_n = n T / N``.

    Starts from the exact statics at zero heel and trim (the cargo at rest on its restraints, the deck undeflected)
    at rest. Returns ``CONVERGED`` when two successive period starts agree to ``periodicity_tolerance``, else
    ``NOT_PERIODIC`` with the last period and the relative change as its residual.
    """
    options = options if options is not None else CradleTimeDomainOptions()
    eq = CradleEquations(dynamics, excitation)
    statics = solve_transverse_statics(dynamics.problem, 0.0, 0.0, gravity_m_per_s2=dynamics.gravity_m_per_s2)
    if statics.outcome is not StaticsOutcome.CONVERGED:
        raise ValueError(f"problem: no static equilibrium to start from ({statics.message})")
    T = 2.0 * np.pi / eq.w
    y = np.concatenate([statics.displacement, np.zeros(eq.n)])
    scale = np.concatenate([np.full(eq.n, max(float(np.max(np.abs(statics.displacement))), 1e-6)), np.full(eq.n, eq.w * 1e-3)])
    run = integrate_to_periodic(eq.rhs, eq.jacobian, y, scale, T, options)
    q = run.states[: eq.n].T
    s = np.array([eq.engagement(t, qt) for t, qt in zip(run.time_s, q, strict=True)])
    change = run.change
    outcome = SolverOutcome.CONVERGED if change < options.periodicity_tolerance else SolverOutcome.NOT_PERIODIC
    message = (
        f"3-D cradle time domain (LSODA, rtol {options.relative_tolerance:g}): {run.periods} periods, period-start change {change:.2e}"
    )
    return cradle_response(dynamics, s, q, eq.w, (outcome, change, message, 0))
