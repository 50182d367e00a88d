"""Harmonic balance of the 3-D cargo on frictional pads: AFT over the normal law and the pads' friction cone.

The unknowns are the real harmonics (0 .. H) of every element's engagement (pads, stoppers, lashings, in the
problem's order) and of every pad's two tangential coordinates (:mod:`seafast.solvers.pad_tangential`), ``z`` [m].
The linear part is the frictionless one, every element bilateral and the pads free tangentially
(:func:`~seafast.solvers.cradle_dynamics.cradle_operators` and ``CradleLinearParts.solve_stack``, used as they
are): per harmonic ``z_k = z_free,k - G_k C_k`` with ``G_k = [A; A_t] K_d(k w)^-1 [A; A_t]^T`` [m/N]. The pads'
tangential springs are then moved into the linear part on the condensed coordinates,
``G' = (I + G K_t)^-1 G`` and ``z_lin = (I + G K_t)^-1 (z_free + G K_t z_rest)``: the linear solution is the pads
stuck at rest, and the nonlinear forces ``C`` are the elements' corrections ``k max(s, 0) - k s`` and the friction's
departure from stick ``f - k_t (delta - delta_rest)``, with ``f`` the cone's force
(:mod:`seafast.solvers.friction_cone`, limit ``mu k_n max(s_pad, 0)``).

AFT: the engagements and tangential motions sampled at N points, the normal law applied sample by sample and the
friction marched over the period from the sliders' rest positions until periodic, the forces back to harmonics.
The residual ``R = z - z_lin + G' C(z)`` is solved by the one Newton (:func:`seafast.solvers.newton.newton`) with
its analytic Jacobian ``I + G' dC/dz``: the normal law's slope on the samples, the friction's derivatives carried
through the marched periods in forward mode (:func:`~seafast.solvers.friction_cone.cone_sensitivity`). Starts: the
pads stuck at rest (the linear solution), then the frictionless solution
(:func:`~seafast.solvers.cradle_hbm.solve_cradle_hbm`), then ``mu`` raised in four steps from the stuck start. Dense
in the unknowns ((2H+1)(m + 2P)): meant for H of tens. With ``mu = 0`` the frictionless solve is returned as it is.

Units: engagements and motions [m]; forces [N].
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace

import numpy as np
from numpy.typing import NDArray

from seafast.excitation.cradle_loads import CradleExcitation
from seafast.fourier import (
    complex_to_real_harmonics,
    harmonics_to_time,
    real_dft_matrices,
    real_to_complex_harmonics,
    time_to_real_harmonics,
)
from seafast.model.pad_friction import PadFriction
from seafast.solvers.cradle_dynamics import CradleDynamics, cradle_operators
from seafast.solvers.cradle_hbm import CradleResponse, cradle_response, solve_cradle_hbm
from seafast.solvers.friction_cone import ConePeriod, cone_sensitivity, march_cone
from seafast.solvers.hbm import HBMOptions
from seafast.solvers.newton import DenseJacobian, Globalisation, Merit, NewtonResult, newton
from seafast.solvers.outcome import SolverOutcome
from seafast.solvers.pad_tangential import FrictionalCradleResponse, PadTangents, frictional_response, pad_tangents

__all__ = ["FrictionHBMOptions", "solve_cradle_friction_hbm", "relaxed_at", "stuck_linear_solution"]

_GLOBALISATION = Globalisation(merit=Merit.SUM_OF_SQUARES, memory=4, accept_converged_trial=True)


@dataclass(frozen=True)
class FrictionHBMOptions:
    """Settings of the frictional harmonic balance.

    Parameters
    ----------
    harmonics
        H >= 1.
    time_samples
        AFT samples N >= 2 H + 2 (the slips' onsets fall between samples: 8 H or more keeps that error small).
    tolerance
        Converged when ``max |R|`` is below this times the largest linear engagement or motion.
    max_iterations
        Newton iterations per solve.
    """

    harmonics: int = 32
    time_samples: int = 256
    tolerance: float = 1e-10
    max_iterations: int = 40

    def __post_init__(self) -> None:
        if int(self.harmonics) < 1:
            raise ValueError(f"harmonics = {self.harmonics!r}: allowed an integer >= 1")
        if int(self.time_samples) < 2 * int(self.harmonics) + 2:
            raise ValueError(f"time_samples = {self.time_samples!r}: allowed an integer >= 2 harmonics + 2")
        if not 0.0 < float(self.tolerance) < 1.0:
            raise ValueError(f"tolerance = {self.tolerance!r}: allowed a number in (0, 1)")
        if int(self.max_iterations) < 1:
            raise ValueError(f"max_iterations = {self.max_iterations!r}: allowed an integer >= 1")


@dataclass(frozen=True)
class _State:
    """What the residual computed that the Jacobian needs."""

    samples: NDArray[np.float64]  # (N, m + 2P)
    period: ConePeriod
    capacity_N: NDArray[np.float64]  # (N, P)


class _System:
    """``R(z) = z - z_lin + G C(z)`` on the real harmonics of the m engagements and the 2P tangential motions."""

    def __init__(
        self, z_lin: NDArray[np.float64], G: NDArray[np.complex128], k: NDArray[np.float64], tangents: PadTangents, mu: float, N: int
    ):
        self.z_lin, self.G, self.k, self.t, self.mu = z_lin, G, k, tangents, float(mu)
        self.H, self.m, self.P = G.shape[0] - 1, k.size, tangents.pad_count
        self.kt = np.repeat(tangents.stiffness_N_per_m, 2)
        self.inverse, self.forward = real_dft_matrices(self.H, N)
        self.scale = max(float(np.max(np.abs(z_lin))), 1e-9)

    def apply_G(self, C: NDArray[np.float64]) -> NDArray[np.float64]:
        """``G C`` on real layouts (2H+1, m_tot, ...)."""
        Cc = real_to_complex_harmonics(C)
        return complex_to_real_harmonics(np.einsum("kab,kb...->ka...", self.G, Cc))

    def forces(self, Z: NDArray[np.float64]) -> tuple[NDArray[np.float64], _State]:
        z = self.inverse @ Z
        s, delta = z[:, : self.m], z[:, self.m :].reshape(-1, self.P, 2)
        capacity = self.mu * self.t.normal_stiffness_N_per_m * np.maximum(s[:, : self.P], 0.0)
        period = march_cone(delta, capacity, self.t.stiffness_N_per_m, self.t.rest_m)
        stick = self.kt * (delta - self.t.rest_m[None]).reshape(z.shape[0], -1)
        c = np.concatenate([self.k * np.maximum(s, 0.0) - self.k * s, period.force_N.reshape(z.shape[0], -1) - stick], axis=1)
        return c, _State(z, period, capacity)

    def full_forces(self, state: _State) -> NDArray[np.float64]:
        """The nonlinear forces of the frictionless linear part: the corrections and the whole friction forces (N, m + 2P)."""
        s = state.samples[:, : self.m]
        return np.concatenate([self.k * np.maximum(s, 0.0) - self.k * s, state.period.force_N.reshape(s.shape[0], -1)], axis=1)

    def residual(self, u: NDArray[np.float64]) -> tuple[NDArray[np.float64], _State]:
        Z = u.reshape(self.z_lin.shape)
        c, state = self.forces(Z)
        return (Z - self.z_lin + self.apply_G(self.forward @ c)).ravel(), state

    def factorise(self, state: _State) -> DenseJacobian:
        m, P, J = self.m, self.P, 2 * self.H + 1
        n_tot = m + 2 * P
        M = np.zeros((J, n_tot, J, n_tot))
        slope = np.where(state.samples[:, :m] > 0.0, 0.0, -self.k)
        for i in range(m):
            M[:, i, :, i] = self.forward @ (slope[:, i, None] * self.inverse)
        delta = state.samples[:, m:].reshape(-1, P, 2)
        engaged = (state.samples[:, :P] > 0.0) * (self.mu * self.t.normal_stiffness_N_per_m)
        d_delta, d_cap = cone_sensitivity(
            state.period, delta, state.capacity_N, self.t.stiffness_N_per_m, self.inverse, engaged[:, :, None] * self.inverse[:, None, :]
        )
        for p in range(P):
            for a in range(2):
                row = m + 2 * p + a
                M[:, row, :, p] = self.forward @ d_cap[:, p, a]
                for b in range(2):
                    M[:, row, :, m + 2 * p + b] = self.forward @ d_delta[:, p, a, b]
                M[:, row, :, row] -= self.kt[2 * p + a] * np.eye(J)
        jac = self.apply_G(M.reshape(J, n_tot, J * n_tot)).reshape(J * n_tot, J * n_tot)
        jac[np.diag_indices_from(jac)] += 1.0
        return DenseJacobian(jac)


def _linear_problem(
    dynamics: CradleDynamics, excitation: CradleExcitation, tangents: PadTangents, H: int
) -> tuple[NDArray[np.float64], NDArray[np.complex128], NDArray[np.complex128], NDArray[np.complex128]]:
    """(z_lin real (2H+1, m + 2P), G (H+1, m_tot, m_tot), the cargo's linear harmonics, its influence (H+1, 5 n, m_tot))."""
    ops = cradle_operators(dynamics, excitation, H)
    wk = excitation.omega_rad_s * np.arange(H + 1, dtype=float)
    At = tangents.rows
    Yt = dynamics.linear_parts().solve_stack(wk, np.broadcast_to(-At.T[None], (H + 1,) + At.T.shape).astype(complex))
    Y = np.concatenate([ops.cargo_influence, Yt], axis=2)
    rows = np.concatenate([dynamics.problem.engagement_matrix, At], axis=0)
    G = -np.einsum("ac,kcb->kab", rows, Y)
    xo = np.zeros((H + 1, tangents.deck.shape[2]), dtype=complex)
    n_x = min(H + 1, excitation.deck_displacement.shape[0])
    xo[:n_x] = excitation.deck_displacement[:n_x]
    xo[0] = xo[0].real
    delta_lin = ops.linear_cargo_displacement @ At.T + xo @ tangents.deck.reshape(2 * tangents.pad_count, -1).T
    z_free = np.concatenate([real_to_complex_harmonics(ops.linear_compression_m), delta_lin], axis=1)
    # the pads' tangential springs into the linear part (stuck at rest): z = z_free - G (C' + K_t (z - z_rest))
    m = ops.saddle_stiffness_N_per_m.size
    Kt = np.zeros(rows.shape[0])
    Kt[m:] = np.repeat(tangents.stiffness_N_per_m, 2)
    z_rest = np.zeros(rows.shape[0])
    z_rest[m:] = tangents.rest_m.ravel()
    lhs = np.eye(rows.shape[0])[None] + G * Kt[None, None, :]
    rhs_z = z_free.copy()
    rhs_z[0] += G[0] @ (Kt * z_rest)
    z_stick = np.linalg.solve(lhs, rhs_z[:, :, None])[:, :, 0]
    G_stick = np.linalg.solve(lhs, G)
    return complex_to_real_harmonics(z_stick), G_stick, ops.linear_cargo_displacement, Y


def solve_cradle_friction_hbm(
    dynamics: CradleDynamics,
    friction: PadFriction,
    excitation: CradleExcitation,
    options: FrictionHBMOptions | None = None,
    *,
    rest: CradleExcitation | None = None,
    start: NDArray[np.float64] | None = None,
) -> FrictionalCradleResponse:
    """The periodic response of the cargo on frictional pads by harmonic balance (module docstring).

    Parameters
    ----------
    dynamics
        The 3-D cargo on its cradles (:class:`~seafast.solvers.cradle_dynamics.CradleDynamics`).
    friction
        The pads' friction coefficient and tangential stiffness (:class:`~seafast.model.pad_friction.PadFriction`).
    excitation
        The static and first-harmonic loads and deck motion.
    options
        H, N, tolerance, iterations.
    rest
        Where the sliders are relaxed: the frictionless response to this excitation's static part (e.g. still water
        with its deck deflection, so that friction answers only the wave); None: the frictionless rest at zero heel
        and trim on an undeflected deck (:func:`~seafast.solvers.pad_tangential.pad_tangents`).
    start
        A periodic state to start Newton from alone (no other start): every element's engagement and every pad's
        tangential motion sampled over one period at ``t_n = n T / N`` (N, m + 2 P) [m], e.g. a time march's,
        projected on the H harmonics; None: the starts of the module docstring.

    Returns
    -------
    FrictionalCradleResponse
        On the AFT grid; ``outcome`` ``NOT_CONVERGED`` with its residual when Newton did not meet the tolerance.
    """
    options = options if options is not None else FrictionHBMOptions()
    H, N = int(options.harmonics), int(options.time_samples)
    tangents = pad_tangents(dynamics.problem, friction, dynamics.deck_x_m, dynamics.gravity_m_per_s2)
    if rest is not None:
        tangents = relaxed_at(tangents, dynamics, rest)
    mu = float(friction.friction_coefficient)
    if mu == 0.0:  # the pads slide freely: zero force, the slider follows the motion
        frictionless = solve_cradle_hbm(dynamics, excitation, HBMOptions(harmonics=H, time_samples=N))
        delta = _tangential_motion(frictionless, excitation, tangents, H).reshape(N, -1, 2)
        free = march_cone(delta, np.zeros((N, tangents.pad_count)), tangents.stiffness_N_per_m, tangents.rest_m)
        return frictional_response(frictionless, tangents, free)
    z_lin, G, X_lin, Y = _linear_problem(dynamics, excitation, tangents, H)
    k = dynamics.problem.element_stiffness_N_per_m
    given = None if start is None else time_to_real_harmonics(np.asarray(start, dtype=float), H).ravel()
    result, route = _newton_route(
        _System(z_lin, G, k, tangents, mu, N), options, lambda: _frictionless_start(dynamics, excitation, tangents, H, N), given
    )
    system = _System(z_lin, G, k, tangents, mu, N)
    state = system.forces(result.u.reshape(z_lin.shape))[1]
    C = real_to_complex_harmonics(system.forward @ system.full_forces(state))
    q = harmonics_to_time(X_lin + np.einsum("kcs,ks->kc", Y, C), N)
    outcome = SolverOutcome.CONVERGED if result.converged else SolverOutcome.NOT_CONVERGED
    message = (
        f"3-D cradle harmonic balance with pad friction (mu = {mu:g}), H = {H}, N = {N}: {result.stop.value} {route}, "
        f"{result.iterations} Newton iterations, residual {result.relative_residual:.2e}; sliders marched over "
        f"{state.period.periods} period(s), their start moving {state.period.start_change_m:.1e} m over the last"
    )
    cradle = cradle_response(
        dynamics, state.samples[:, : k.size], q, excitation.omega_rad_s, (outcome, result.relative_residual, message, H)
    )
    return frictional_response(cradle, tangents, state.period)


def stuck_linear_solution(
    dynamics: CradleDynamics, excitation: CradleExcitation, tangents: PadTangents
) -> tuple[NDArray[np.float64], NDArray[np.complex128]]:
    """The linear periodic response with every element bilateral and the pads stuck at their sliders' rest.

    Returns the real harmonics 0, 1 of every engagement and pad tangential motion (3, m + 2 P) [m] (the linear part
    of the harmonic balance, the module docstring) and the cargo's complex displacement harmonics 0, 1 (2, 5 n)
    [m, rad]: the frictionless linear response plus that of the stuck springs' forces ``k_t (delta - delta_rest)``.
    """
    z_lin, _, X_lin, Y = _linear_problem(dynamics, excitation, tangents, 1)
    m = dynamics.problem.element_stiffness_N_per_m.size
    delta = real_to_complex_harmonics(z_lin)[:, m:]
    delta[0] -= tangents.rest_m.ravel()
    forces = np.repeat(tangents.stiffness_N_per_m, 2)[None] * delta
    return z_lin, X_lin + np.einsum("kcs,ks->kc", Y[:, :, m:], forces)


def _newton_route(
    system: _System,
    options: FrictionHBMOptions,
    frictionless: Callable[[], NDArray[np.float64]],
    given: NDArray[np.float64] | None = None,
) -> tuple[NewtonResult[_State], str]:
    """Newton from the pads stuck at rest (the linear part's own solution); then from the frictionless solution; then
    with mu raised in four steps from the stuck start; or from ``given`` alone (real harmonics, flattened). Returns the
    last result and the route in words."""

    def solve(mu: float, start: NDArray[np.float64]) -> NewtonResult[_State]:
        trial = _System(system.z_lin, system.G, system.k, system.t, mu, system.inverse.shape[0])
        return newton(
            trial, start, tolerance=float(options.tolerance), max_iterations=int(options.max_iterations), globalisation=_GLOBALISATION
        )

    if given is not None:
        return solve(system.mu, given), "from the given periodic state"
    stuck = system.z_lin.ravel()
    result = solve(system.mu, stuck)
    if result.converged:
        return result, "from the pads stuck at rest"
    result = solve(system.mu, frictionless())
    if result.converged:
        return result, "from the frictionless solution"
    route, start = "mu raised in four steps from the pads stuck at rest", stuck
    for factor in (0.25, 0.5, 0.75, 1.0):
        result = solve(factor * system.mu, start)
        if not result.converged:
            return result, route + f" (stopped at mu = {factor * system.mu:g})"
        start = result.u
    return result, route


def relaxed_at(tangents: PadTangents, dynamics: CradleDynamics, rest: CradleExcitation) -> PadTangents:
    """``tangents`` with the sliders relaxed at the frictionless response to ``rest``'s static part (loads and deck).

    The static part alone is solved (one harmonic, exact for a constant load: the engagements do not change in time),
    and the sliders' rest is the pads' tangential position there, ``A_t q + E_t x_o``.
    """
    still = rest.still_water()
    frictionless = solve_cradle_hbm(dynamics, still, HBMOptions(harmonics=1, time_samples=4))
    if not frictionless.converged:
        raise ValueError(
            f"rest: the frictionless still-water state to relax the pads' sliders at did not converge ({frictionless.message})"
        )
    delta = _tangential_motion(frictionless, still, tangents, 0)[0]
    return replace(tangents, rest_m=delta.reshape(tangents.pad_count, 2), rest_displacement=frictionless.cargo_displacement_m[0])


def _tangential_motion(response: CradleResponse, excitation: CradleExcitation, tangents: PadTangents, H: int) -> NDArray[np.float64]:
    """The pads' tangential motion ``A_t q + E_t x_o`` over a response's period (N, 2 P) [m]."""
    N = response.time_s.size
    return (
        response.cargo_displacement_m @ tangents.rows.T + _deck_time(excitation, N, H) @ tangents.deck.reshape(2 * tangents.pad_count, -1).T
    )


def _frictionless_start(
    dynamics: CradleDynamics, excitation: CradleExcitation, tangents: PadTangents, H: int, N: int
) -> NDArray[np.float64]:
    """The frictionless solution's engagements and tangential motions as real harmonics, flattened (a start)."""
    frictionless = solve_cradle_hbm(dynamics, excitation, HBMOptions(harmonics=H, time_samples=N))
    samples = np.concatenate([frictionless.engagement_m, _tangential_motion(frictionless, excitation, tangents, H)], axis=1)
    return time_to_real_harmonics(samples, H).ravel()


def _deck_time(excitation: CradleExcitation, N: int, H: int) -> NDArray[np.float64]:
    xo = np.array(excitation.deck_displacement[: H + 1], dtype=complex)
    xo[0] = xo[0].real
    return harmonics_to_time(xo, N)
