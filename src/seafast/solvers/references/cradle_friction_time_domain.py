"""The time-domain reference of the 3-D cargo on frictional pads: the equations of motion with the sliders' rate law.

The frictionless reference's equations (:mod:`seafast.solvers.references.cradle_time_domain`) with each pad's
friction force ``f = k_t (delta - w)`` on the cargo (``-A_t^T f``, :mod:`seafast.solvers.pad_tangential`) and the
sliders ``w`` as states, moving by the rate law of a stiff viscoplastic (Perzyna) slider::

    w' = max(|f| - C, 0) / (k_t tau) * f / |f|,        C = mu k_n max(s_pad, 0),

whose limit for ``tau -> 0`` is the Coulomb slider of the cone (the force exceeds the cone by ``k_t tau |w'|``, a
slip rate's worth). ``tau`` is a small fraction of the period (default 1e-7 T: the excess below 1e-5 of the
limit at the slip rates of the tests). Integrated by scipy's LSODA with the exact Jacobian of the current state,
from the frictionless statics at zero heel with the sliders relaxed there, period after period until the
period-start state repeats. Independent of the harmonic balance's code: no Fourier series, no condensation, no
return map. Dense: small models.

Units: SI; time [s].
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from seafast.excitation.cradle_loads import CradleExcitation
from seafast.model.pad_friction import PadFriction
from seafast.solvers.cradle_dynamics import CradleDynamics
from seafast.solvers.cradle_hbm import cradle_response
from seafast.solvers.friction_cone import ConePeriod
from seafast.solvers.outcome import SolverOutcome
from seafast.solvers.pad_tangential import FrictionalCradleResponse, PadTangents, frictional_response, pad_tangents
from seafast.solvers.references.cradle_time_domain import CradleEquations, CradleTimeDomainOptions, integrate_to_periodic

__all__ = ["FrictionTimeDomainOptions", "solve_cradle_friction_time_domain"]


@dataclass(frozen=True)
class FrictionTimeDomainOptions(CradleTimeDomainOptions):
    """Settings of the frictional time-domain reference: the frictionless reference's
    (:class:`~seafast.solvers.references.cradle_time_domain.CradleTimeDomainOptions`: ``time_samples``,
    ``relative_tolerance``, ``periodicity_tolerance``, ``max_periods``) and the sliders' relaxation.

    Parameters
    ----------
    relaxation_fraction
        tau / T, the sliders' relaxation time over the period (0, 1e-3].
    """

    relaxation_fraction: float = 1e-7

    def __post_init__(self) -> None:
        super().__post_init__()
        if not 0.0 < float(self.relaxation_fraction) <= 1e-3:
            raise ValueError(f"relaxation_fraction = {self.relaxation_fraction!r}: allowed a number in (0, 1e-3]")


class _Equations(CradleEquations):
    """The frictionless reference's system extended to (q, q', w), the sliders' rate law, and its Jacobian."""

    def __init__(self, dynamics: CradleDynamics, excitation: CradleExcitation, tangents: PadTangents, tau_s: float) -> None:
        super().__init__(dynamics, excitation)
        self.P, self.tau = tangents.pad_count, float(tau_s)
        self.At, self.Et = tangents.rows, tangents.deck.reshape(2 * self.P, -1)
        self.kt = np.repeat(tangents.stiffness_N_per_m, 2)
        self.mu_kn = tangents.friction_coefficient * tangents.normal_stiffness_N_per_m
        self.Minv_Att = np.linalg.solve(dynamics.matrices[1], self.At.T)

    def split(self, t: float, y: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
        """(engagements (m,), friction forces (P, 2), limits (P,)) at a state."""
        q, slider = y[: self.n], y[2 * self.n :]
        xo = self.deck(t)
        s = self.s0 + self.A @ q + self.E @ xo
        f = (self.kt * (self.At @ q + self.Et @ xo - slider)).reshape(self.P, 2)
        return s, f, self.mu_kn * np.maximum(s[: self.P], 0.0)

    def rhs(self, t: float, y: NDArray[np.float64]) -> NDArray[np.float64]:
        q, v = y[: self.n], y[self.n : 2 * self.n]
        s, f, C = self.split(t, y)
        a = np.real(self.g[0] + self.g[1] * np.exp(1j * self.w * t)) - self.Minv_K0 @ q - self.Minv_D @ v
        a -= self.Minv_At @ (self.k * np.maximum(s, 0.0)) + self.Minv_Att @ f.ravel()
        norm = np.hypot(f[:, 0], f[:, 1])
        excess = np.maximum(norm - C, 0.0)
        rate = (excess / (self.tau * np.where(norm > 0.0, norm, 1.0)))[:, None] * f / self.kt.reshape(self.P, 2)
        return np.concatenate([v, a, rate.ravel()])

    def jacobian(self, t: float, y: NDArray[np.float64]) -> NDArray[np.float64]:
        n, P = self.n, self.P
        s, f, C = self.split(t, y)
        engaged = s > 0.0
        J = np.zeros((2 * n + 2 * P, 2 * n + 2 * P))
        J[:n, n : 2 * n] = np.eye(n)
        J[n : 2 * n, :n] = (
            -self.Minv_K0
            - self.Minv_At[:, engaged] @ (self.k[engaged, None] * self.A[engaged])
            - self.Minv_Att @ (self.kt[:, None] * self.At)
        )
        J[n : 2 * n, n : 2 * n] = -self.Minv_D
        J[n : 2 * n, 2 * n :] = self.Minv_Att * self.kt
        d_rate_d_f = np.zeros((2 * P, 2 * P))  # d w' / d f
        d_rate_d_C = np.zeros((2 * P, P))
        norm = np.hypot(f[:, 0], f[:, 1])
        for p in np.flatnonzero(norm > C):
            e = f[p] / norm[p]
            block = slice(2 * p, 2 * p + 2)
            d_rate_d_f[block, block] = (np.eye(2) - C[p] / norm[p] * (np.eye(2) - np.outer(e, e))) / (self.tau * self.kt[2 * p])
            d_rate_d_C[block, p] = -e / (self.tau * self.kt[2 * p])
        d_C_d_q = (engaged[:P] * self.mu_kn)[:, None] * self.A[:P]
        J[2 * n :, :n] = d_rate_d_f @ (self.kt[:, None] * self.At) + d_rate_d_C @ d_C_d_q
        J[2 * n :, 2 * n :] = -d_rate_d_f * self.kt
        return J


def solve_cradle_friction_time_domain(
    dynamics: CradleDynamics, friction: PadFriction, excitation: CradleExcitation, options: FrictionTimeDomainOptions | None = None
) -> FrictionalCradleResponse:
    """The periodic steady state on frictional pads by time integration, sampled on the last period at ``t_n = n T / N``.

    Starts at rest on the frictionless statics at zero heel and trim, the sliders relaxed there (as the harmonic
    balance's). ``CONVERGED`` when two successive period starts agree to ``periodicity_tolerance``, else
    ``NOT_PERIODIC`` with the last period and the relative change as its residual.
    """
    options = options if options is not None else FrictionTimeDomainOptions()
    tangents = pad_tangents(dynamics.problem, friction, dynamics.deck_x_m, dynamics.gravity_m_per_s2)
    T = 2.0 * np.pi / float(excitation.omega_rad_s)
    eq = _Equations(dynamics, excitation, tangents, float(options.relaxation_fraction) * T)
    q0 = tangents.rest_displacement
    y = np.concatenate([q0, np.zeros(eq.n), tangents.rest_m.ravel()])
    scale_q = max(float(np.max(np.abs(q0))), 1e-6)
    scale = np.concatenate([np.full(eq.n, scale_q), np.full(eq.n, eq.w * 1e-3), np.full(2 * eq.P, scale_q)])
    N = int(options.time_samples)
    run = integrate_to_periodic(eq.rhs, eq.jacobian, y, scale, T, options)
    change, periods = run.change, run.periods
    states = [eq.split(t, yt) for t, yt in zip(run.time_s, run.states.T, strict=True)]
    s = np.array([state[0] for state in states])
    forces = np.array([state[1] for state in states])
    slider = run.states[2 * eq.n :].T.reshape(N, eq.P, 2)
    outcome = SolverOutcome.CONVERGED if change < options.periodicity_tolerance else SolverOutcome.NOT_PERIODIC
    message = (
        f"3-D cradle time domain with pad friction (LSODA, rtol {options.relative_tolerance:g}, tau/T "
        f"{options.relaxation_fraction:g}): {periods} periods, period-start change {change:.2e}"
    )
    cradle = cradle_response(dynamics, s, run.states[: eq.n].T, eq.w, (outcome, change, message, 0))
    limits = np.array([state[2] for state in states])
    slipping = np.hypot(forces[..., 0], forces[..., 1]) > limits  # the viscoplastic slider moves only above the cone
    record = ConePeriod(forces, slider, slipping, tangents.rest_m, slider[0], periods, change)
    return frictional_response(cradle, tangents, record)
