"""Time-domain exact-contact reference: implicit integration to the periodic steady state.

HHT-alpha integration (average-acceleration Newmark for ``hht_alpha = 0``) of the cargo
equations with the exact law, period by period until the change between two periods is
below ``tolerance`` (the periodic steady state). Two formulations of the same equations:

``Formulation.FULL`` (default, the independent reference)
    All cargo DOFs, ``M q'' + D q' + K_lin q = f_static + f_vessel(t) - K_co x_o(t) -
    D_co x_o'(t) + B f_c(delta)`` (``D_co``: the damping acts on the motion relative to the
    quasi-static support motion) with ``K_lin`` the cargo beam and the lashing springs only and the
    saddles as exact unilateral springs ``f_c = k_u max(delta, 0)``, ``delta = z_deck -
    z_cargo``. Each implicit step is solved by a semi-smooth Newton (active-set)
    iteration on the full effective stiffness; one banded Cholesky factorisation is cached
    per active set, so a step costs one banded matrix-vector product and one or two banded
    triangular solves. It uses the model's matrices directly (none of the receptance /
    condensation machinery of the HBM).
``Formulation.CONDENSED``
    The same integration with the saddles bilateral in the linear stiffness and the
    implicit contact problem of each step condensed onto the saddles (the step's
    effective receptance) and solved with the active-set method of
    :class:`~seafast.solvers.exact_contact.ExactContact`.

Both start from the same state (:mod:`~seafast.solvers.references.orbit`): the linear periodic
solution at t = 0 by default, or a given periodic solution (e.g. the HBM's), whose orbit the one
reached is then compared with. A cargo that lifts off can have several periodic states and a
chaotic motion for one excitation; the start decides which one a time integration finds, and the
result says what it found (:class:`~seafast.solvers.outcome.OrbitRecord`, outcome ``CONVERGED``,
``NOT_PERIODIC`` or ``OTHER_ORBIT``).

The settings are :class:`~seafast.solvers.references.options.TimeDomainOptions`.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray
from scipy.sparse import csr_array

from seafast.config.modes import Formulation, SolverMethod, TimeDomainStart
from seafast.excitation.harmonic import HarmonicExcitation
from seafast.fourier import harmonics_to_time
from seafast.model.structure import StructuralModel
from seafast.solvers.dynamic_stiffness import linear_force_harmonics, quadratic_matrices, saddle_selection
from seafast.solvers.exact_contact import BandedActiveSet, ExactContact
from seafast.solvers.outcome import OrbitRecord, SolverOutcome
from seafast.solvers.periodic import PeriodicResponse, Settings
from seafast.solvers.references.common import exact_law_response
from seafast.solvers.references.options import TimeDomainOptions
from seafast.solvers.references.orbit import StartState, orbit_outcome, settling_periods, start_state

__all__ = ["solve_time_domain"]

logger = logging.getLogger(__name__)


@dataclass(frozen=True)
class _Run:
    """What one integration produced: the last period's samples and how the periods went."""

    cargo_m: NDArray[np.float64]
    compression_m: NDArray[np.float64]
    check: _PeriodicityCheck
    periods: int
    steps: int
    description: str
    extra_options: Settings


def solve_time_domain(
    model: StructuralModel,
    excitation: HarmonicExcitation,
    options: TimeDomainOptions | None = None,
    *,
    start: PeriodicResponse | None = None,
) -> PeriodicResponse:
    """Periodic steady state by implicit time integration with the exact contact law.

    Parameters
    ----------
    model, excitation
        The cargo model and its excitation.
    options
        :class:`~seafast.solvers.references.options.TimeDomainOptions` (default: 128 output samples, the
        full-DOF formulation, 16 steps per sample, from the linear periodic solution). ``formulation``
        ``FULL``: HHT-alpha on all cargo DOFs with ``K_lin`` = cargo beam + lashings and the saddles as
        exact unilateral springs, the implicit contact problem of each step solved by an active-set
        (semi-smooth Newton) iteration on the full effective stiffness with banded Cholesky factorisations
        cached per active set; independent of the HBM's receptance machinery. ``CONDENSED``: the same
        equations with the saddles bilateral in ``K`` and each step's contact problem condensed onto the
        saddles. Both integrate the same discrete equations from the same start and agree to the
        period-to-period tolerance.
    start
        A periodic solution of the same model and frequency to start from (e.g. the HBM's: its
        displacement and velocity at t = 0; the orbit reached is compared with it). Without it,
        ``options.start`` (``LINEAR``: the linear periodic solution; ``QUASI_STATIC``: the exact-contact
        quasi-static state; ``HBM`` needs the harmonic balance's solution here).

    Returns
    -------
    PeriodicResponse
        ``method = "time_domain"`` (last period); ``outcome`` ``NOT_PERIODIC`` (``converged``
        False) if the periodic steady state was not reached in ``max_periods``, ``OTHER_ORBIT``
        if it was reached from a given solution but is not that solution's orbit, else
        ``CONVERGED``; ``orbit`` the :class:`~seafast.solvers.outcome.OrbitRecord`;
        ``iterations`` = periods integrated, ``function_evaluations`` = time steps,
        ``residual_norm`` = last period-to-period change; ``message`` and
        ``options["formulation"]``, ``options["start"]`` name the formulation and the start.

    Raises
    ------
    ValueError
        For ``options.start = HBM`` without a ``start`` solution (:func:`seafast.solvers.solve_periodic`
        solves it), or a ``start`` of another frequency or model.
    """
    options = TimeDomainOptions() if options is None else options
    if not isinstance(options, TimeDomainOptions):
        raise TypeError(f"options = {options!r}: allowed a TimeDomainOptions (e.g. TimeDomainOptions(time_samples=128)) or None")
    if start is None and options.start is TimeDomainStart.HBM:
        raise ValueError(
            "start: options.start = 'hbm' needs the harmonic balance's solution; allowed: start=<its PeriodicResponse>, "
            "or solve_periodic(..., method=SolverMethod.TIME_DOMAIN), which solves it first"
        )
    N, S = int(options.time_samples), options.steps
    omega = float(excitation.omega_rad_s)
    periods_allowed = settling_periods(model, omega, float(options.tolerance)) if options.max_periods is None else int(options.max_periods)
    initial = start_state(model, excitation, options.start if start is None else start, N, 2.0 * np.pi / omega / S)
    integrate = _time_domain_full if options.formulation is Formulation.FULL else _time_domain_condensed
    run = integrate(model, excitation, initial, N, S, periods_allowed, float(options.tolerance), float(options.hht_alpha))
    k_u = np.asarray(model.saddle_unilateral_stiffness_N_per_m, dtype=float)
    outcome, orbit = orbit_outcome(
        initial, k_u, run.compression_m, run.check.converged, run.periods, run.check.change, float(options.orbit_tolerance)
    )
    response = exact_law_response(
        SolverMethod.TIME_DOMAIN,
        model,
        excitation,
        run.cargo_m,
        run.compression_m,
        outcome,
        run.check.change,
        run.periods,
        run.steps,
        _message(run, initial, orbit),
        int(options.harmonics_for_indicator),
        _record(options, S, periods_allowed, initial, run),
        orbit=orbit,
    )
    logger.log(logging.DEBUG if outcome is SolverOutcome.CONVERGED else logging.INFO, "time-domain reference: %s", response.message)
    return response


def _record(options: TimeDomainOptions, S: int, periods_allowed: int, initial: StartState, run: _Run) -> Settings:
    """The settings used, as the response's plain ``options`` dict."""
    return {
        "time_samples": int(options.time_samples),
        "steps_per_period": S,
        "max_periods": periods_allowed,
        "tolerance": float(options.tolerance),
        "hht_alpha": float(options.hht_alpha),
        "harmonics_for_indicator": int(options.harmonics_for_indicator),
        "contact_law": "exact",
        "formulation": str(options.formulation),
        "start": str(initial.kind),
        "start_method": initial.method,
        "orbit_tolerance": float(options.orbit_tolerance),
        **run.extra_options,
    }


def _message(run: _Run, initial: StartState, orbit: OrbitRecord) -> str:
    """The account for people: formulation, start, periodicity and (a given start) the orbit reached."""
    given = f" ({initial.method})" if initial.kind is TimeDomainStart.GIVEN else ""
    message = f"{run.description}; from the {_START_WORDS[initial.kind]}{given}; " + run.check.describe(run.periods)
    if orbit.distance_from_start is not None:
        message += (
            f"; distance from the start's orbit {orbit.distance_from_start:.2e} ("
            + ("the same orbit" if orbit.same_as_start else "ANOTHER orbit" if orbit.same_as_start is False else "no orbit reached")
            + f", tolerance {orbit.orbit_tolerance:g})"
        )
    return message


_START_WORDS = {
    TimeDomainStart.LINEAR: "linear periodic solution at t = 0",
    TimeDomainStart.QUASI_STATIC: "exact-contact quasi-static state at t = 0",
    TimeDomainStart.GIVEN: "given periodic solution at t = 0",
}


class _PeriodicityCheck:
    """Change of the saddle-force history from one period to the next, over the largest force seen."""

    def __init__(self, stiffness_N_per_m: NDArray, initial_compression_m: NDArray, tolerance: float):
        self.stiffness = stiffness_N_per_m
        self.tolerance = tolerance
        self.scale = float(max(np.max(stiffness_N_per_m * np.abs(initial_compression_m)), 1.0))
        self.previous: NDArray | None = None
        self.change = np.inf

    def settled(self, compression_m: NDArray) -> bool:
        """Record one period's compressions; True once the change is below the tolerance."""
        force = self.stiffness * np.maximum(compression_m, 0.0)
        self.scale = max(self.scale, float(np.max(np.abs(force))))
        if self.previous is not None:
            self.change = float(np.max(np.abs(force - self.previous))) / self.scale
            if self.change <= self.tolerance:
                return True
        self.previous = force.copy()
        return False

    @property
    def converged(self) -> bool:
        return self.change <= self.tolerance

    def describe(self, periods: int) -> str:
        if self.converged:
            return f"periodic steady state after {periods} periods (change {self.change:.2e})"
        return f"NOT periodic after {periods} periods (change {self.change:.2e} > {self.tolerance:g})"


def _time_domain_full(
    model: StructuralModel,
    excitation: HarmonicExcitation,
    initial: StartState,
    N: int,
    S: int,
    max_periods: int,
    tolerance: float,
    alpha: float,
) -> _Run:
    """Full-DOF HHT-alpha with the exact unilateral saddle springs (see :func:`solve_time_domain`).

    With ``F(q) = K_lin q - B f_c(q)`` the HHT-alpha step reads ``M a_1 + (1+alpha)(D v_1 +
    F(q_1)) - alpha (D v_0 + F(q_0)) = (1+alpha) p_1 - alpha p_0``, with the Newmark relations
    (gamma = 1/2 - alpha, beta = (1 - alpha)^2 / 4) eliminating ``a_1, v_1``: a piecewise-linear
    system for ``q_1`` whose matrix is ``c1 M + (1+alpha) c2 D + (1+alpha) (K_lin + B diag(k_u
    on the active saddles) B^T)``.
    """
    n_c, n_s = model.cargo_dof_count, model.saddle_count
    sad_c, sad_o = model.saddle_cargo_dof, model.saddle_deck_dof
    k_u = np.asarray(model.saddle_unilateral_stiffness_N_per_m, dtype=float)
    M = np.asarray(model.cargo.mass, dtype=float)
    D = np.asarray(model.damping_cc, dtype=float)
    K_lin, K_co, _, _ = model.dynamic_stiffness(0.0, include_saddles=False)  # cargo beam + lashings
    K_lin, K_co = np.asarray(K_lin, dtype=float), np.asarray(K_co, dtype=float)
    omega = float(excitation.omega_rad_s)
    dt = 2.0 * np.pi / omega / S
    gamma = 0.5 - alpha
    beta = 0.25 * (1.0 - alpha) ** 2
    h = 0.5 - beta
    c1, c2 = 1.0 / (beta * dt * dt), gamma / (beta * dt)
    # loads at the step times: f_static + f_vessel(t) - K_co x_o(t) - D_co x_o'(t) (the deck DOFs carry no mass; the
    # cargo is damped on its motion relative to the quasi-static support motion, StructuralModel.support_damping_coupling)
    deck = np.asarray(excitation.deck_displacement, dtype=complex)
    deck_velocity = 1j * omega * np.arange(deck.shape[0])[:, None] * deck
    P = np.asarray(excitation.cargo_load_N, dtype=complex) - deck @ K_co.T - deck_velocity @ model.support_damping_coupling.T
    P[0] = P[0].real + model.static_load_N
    P_t = harmonics_to_time(P, S)  # (S, n_c)
    z_t = harmonics_to_time(np.asarray(excitation.deck_displacement)[:, sad_o], S)  # deck z at the saddles (S, n_s)
    g = (1.0 + alpha) * np.roll(P_t, -1, axis=0) - alpha * P_t  # load of step n -> n+1
    z_next = np.roll(z_t, -1, axis=0)
    tol_m = 1e-12 * max(float(np.max(np.abs(z_t))), 1e-3)
    # the start: q and v given, the acceleration from the equation of motion with the exact contact force
    q0, v0 = initial.displacement, initial.velocity
    delta0 = z_t[0] - q0[sad_c]
    active = delta0 > 0.0
    fc = k_u * delta0 * active
    rhs0 = P_t[0] - D @ v0 - K_lin @ q0
    rhs0[sad_c] += fc
    a0 = np.linalg.solve(M, rhs0)
    # the step: (K0 + (1+alpha) B diag(k_u A) B^T) q_1 = C [q0; v0; a0] + g_n - alpha B f_c,0 + (1+alpha) B k_u A z_1
    step = BandedActiveSet(c1 * M + (1.0 + alpha) * (c2 * D + K_lin), sad_c, (1.0 + alpha) * k_u, tol_m)
    Cq = c1 * M + (1.0 + alpha) * c2 * D + alpha * K_lin
    Cv = c1 * dt * M + (1.0 + alpha) * (c2 * dt - 1.0) * D + alpha * D
    Ca = c1 * dt * dt * h * M + (1.0 + alpha) * (c2 * dt * dt * h - dt * (1.0 - gamma)) * D
    C = csr_array(np.hstack([Cq, Cv, Ca]))
    predict = np.array([[1.0, dt, dt * dt * h], [0.0, 1.0, dt * (1.0 - gamma)]])  # q~ and v~ from [q; v; a]
    gdt = gamma * dt
    state = np.concatenate([q0, v0, a0])
    stride = S // N
    periods = 0
    steps = 0
    check = _PeriodicityCheck(k_u, delta0, tolerance)
    cargo_out = np.empty((N, n_c))
    delta_out = np.empty((N, n_s))
    for periods in range(1, max_periods + 1):  # noqa: B007 - the count is returned
        for n in range(S):
            if n % stride == 0:
                j = n // stride
                cargo_out[j] = state[:n_c]
                delta_out[j] = z_t[n] - state[sad_c]
            rhs = C @ state
            rhs += g[n]
            rhs[sad_c] -= alpha * fc
            q1, delta1, active = step.solve(rhs, z_next[n], active)
            fc = k_u * delta1 * active
            qv = predict @ state.reshape(3, n_c)
            a1 = c1 * (q1 - qv[0])
            state = np.concatenate([q1, qv[1] + gdt * a1, a1])
        steps += S
        if check.settled(delta_out):
            break
    per_step = step.solves / max(steps, 1)
    description = (
        f"full-DOF formulation: HHT-alpha (alpha={alpha:g}) on {n_c} cargo DOFs, exact unilateral saddle springs by active-set "
        f"Newton ({per_step:.3f} banded solves/step, {len(step.factors)} contact states factorised"
        + (f", {step.enumerations} enumerations" if step.enumerations else "")
        + f"), {S} steps/period"
    )
    extra: Settings = {"contact_states_factorised": len(step.factors), "solves_per_step": per_step}
    return _Run(cargo_out.copy(), delta_out.copy(), check, periods, steps, description, extra)


def _time_domain_condensed(
    model: StructuralModel,
    excitation: HarmonicExcitation,
    initial: StartState,
    N: int,
    S: int,
    max_periods: int,
    tolerance: float,
    hht_alpha: float,
) -> _Run:
    """HHT-alpha with the saddles bilateral in K and each step's contact condensed on the saddles."""
    q = quadratic_matrices(model, True)
    K, M, D = q.stiffness, q.mass, q.damping
    B = saddle_selection(model)
    sad_c, sad_o = model.saddle_cargo_dof, model.saddle_deck_dof
    k_u = np.asarray(model.saddle_unilateral_stiffness_N_per_m, dtype=float)
    omega = float(excitation.omega_rad_s)
    T = 2.0 * np.pi / omega
    dt = T / S
    alpha = float(hht_alpha)
    gamma = 0.5 - alpha
    beta = 0.25 * (1.0 - alpha) ** 2
    c1, c2 = 1.0 / (beta * dt * dt), gamma / (beta * dt)
    K_eff = c1 * M + (1.0 + alpha) * c2 * D + (1.0 + alpha) * K
    K_inv = np.linalg.inv(K_eff)
    h = 0.5 - beta
    Cq = alpha * K + c1 * M + (1.0 + alpha) * c2 * D
    Cv = alpha * D + c1 * dt * M + (1.0 + alpha) * D * (c2 * dt - 1.0)
    Ca = c1 * dt * dt * h * M + (1.0 + alpha) * D * (c2 * dt * dt * h - dt * (1.0 - gamma))
    A_state = K_inv @ np.hstack([Cq, Cv, Ca])  # (n_c, 3 n_c)
    Y = K_inv @ B
    contact = ExactContact((1.0 + alpha) * Y[sad_c], k_u)
    # periodic linear forcing and deck motion at the step times
    P = linear_force_harmonics(model, excitation, quasi_static=False)
    P_t = harmonics_to_time(P, S)  # (S, n_c)
    g = ((1.0 + alpha) * np.roll(P_t, -1, axis=0) - alpha * P_t) @ K_inv.T  # forcing of step n -> n+1
    deck_z = harmonics_to_time(excitation.deck_displacement[:, sad_o], S)
    deck_z_next = np.roll(deck_z, -1, axis=0)
    # the start: q and v given, the acceleration from the equation of motion with the exact contact force
    q_n, v_n = initial.displacement, initial.velocity
    delta_n = deck_z[0] - q_n[sad_c]
    c_n = k_u * np.maximum(-delta_n, 0.0)
    a_n = np.linalg.solve(M, P_t[0] + B @ c_n - D @ v_n - K @ q_n)
    state = np.concatenate([q_n, v_n, a_n])
    n_c = model.cargo_dof_count
    stride = S // N
    detached = c_n > 0.0
    periods = 0
    steps = 0
    check = _PeriodicityCheck(k_u, delta_n, tolerance)
    cargo_out = np.empty((N, n_c))
    delta_out = np.empty((N, model.saddle_count))
    for periods in range(1, int(max_periods) + 1):  # noqa: B007 - the count is returned
        for n in range(S):
            if n % stride == 0:
                j = n // stride
                cargo_out[j] = state[:n_c]
                delta_out[j] = deck_z[n] - state[sad_c]
            q_old, v_old, a_old = state[:n_c], state[n_c : 2 * n_c], state[2 * n_c :]
            q_pred = A_state @ state + g[n] - alpha * (Y @ c_n)
            d_pred = deck_z_next[n] - q_pred[sad_c]
            op_delta = contact.operator(detached) @ d_pred
            if not np.all(np.where(detached, op_delta <= 0.0, op_delta >= 0.0)):
                op_delta, det2 = contact.solve(d_pred, detached)
                op_delta, detached = op_delta[0], det2[0]
            c_next = k_u * np.maximum(-op_delta, 0.0)
            q_new = q_pred + (1.0 + alpha) * (Y @ c_next)
            q_tilde = q_old + dt * v_old + dt * dt * h * a_old
            a_new = c1 * (q_new - q_tilde)
            v_new = v_old + dt * ((1.0 - gamma) * a_old + gamma * a_new)
            state = np.concatenate([q_new, v_new, a_new])
            c_n = c_next
            steps += 1
        if check.settled(delta_out):
            break
    description = (
        f"condensed formulation: HHT-alpha (alpha={alpha:g}) on {model.cargo_dof_count} cargo DOFs, saddles bilateral in K "
        f"and each step's contact condensed on the saddles, exact contact, {S} steps/period"
    )
    return _Run(cargo_out.copy(), delta_out.copy(), check, periods, steps, description, {})
