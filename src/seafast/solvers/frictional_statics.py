"""Statics of the 3-D cargo on frictional pads under a steady heel and trim, applied in one step from rest.

The frictionless statics (:mod:`seafast.solvers.transverse_statics`) with each pad's Jenkins element on its
tangential motion (:mod:`seafast.solvers.friction_cone`): the sliders start relaxed at the cargo's frictionless
rest at zero heel and trim (:func:`~seafast.solvers.pad_tangential.pad_tangents`) and the heel and trim are
applied in one step (one return map from rest: a proportional loading whose slip does not reverse). Equilibrium::

    K0 q - f + A^T (k max(s, 0)) + A_t^T f_t(q) = 0,   f_t = return map of k_t (A_t q - delta_rest) on |f_t| <= mu k_n max(s_pad, 0),

solved by Newton with its analytic (non-symmetric) Jacobian and a backtracking line search on the residual's norm,
from the pads stuck at rest. Units: SI.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from seafast.model.pad_friction import PadFriction
from seafast.solvers.cradle_dynamics import rest_initial_engagement_m
from seafast.solvers.friction_cone import cone_return_map
from seafast.solvers.pad_tangential import PadTangents, pad_tangents
from seafast.solvers.transverse_statics import CradleProblem, StaticsOutcome

__all__ = ["FrictionalStatics", "solve_frictional_statics"]


@dataclass(frozen=True)
class FrictionalStatics:
    """The statics of a :class:`~seafast.solvers.transverse_statics.CradleProblem` on frictional pads.

    Attributes
    ----------
    outcome
        ``CONVERGED`` (the residual below ``1e-9`` of the largest load or element force, or the beam's round-off) or ``NOT_CONVERGED``
        (e.g. the friction cannot hold a load nothing else restrains: the cargo slides away), with the last iterate.
    displacement
        Cargo DOFs (5 n,) [m, rad].
    engagement_m, element_force_N
        Every element's engagement [m] and force ``k max(s, 0)`` [N] (pads port, starboard per pair, stoppers, lashings).
    friction_force_N
        (P, 2) [N]: each pad's friction force resisting its (circumferential, axial) motion.
    slip_m
        (P, 2) [m]: each slider's displacement from rest; zero where the pad sticks.
    slipped
        (P,): the pads whose friction reached ``mu F_n``.
    residual_N
        The largest equilibrium residual [N, N m].
    iterations
        Newton steps.
    """

    outcome: StaticsOutcome
    displacement: NDArray[np.float64]
    engagement_m: NDArray[np.float64]
    element_force_N: NDArray[np.float64]
    friction_force_N: NDArray[np.float64]
    slip_m: NDArray[np.float64]
    slipped: NDArray[np.bool_]
    residual_N: float
    iterations: int

    @property
    def pad_force_N(self) -> NDArray[np.float64]:
        """(P,) [N]: each pad's normal force."""
        return self.element_force_N[: self.friction_force_N.shape[0]]


class _Equilibrium:
    def __init__(self, problem: CradleProblem, tangents: PadTangents, load: NDArray[np.float64], s0: NDArray[np.float64]):
        self.K0, self.A, self.k, self.t, self.f, self.s0 = (
            problem.base_stiffness,
            problem.engagement_matrix,
            problem.element_stiffness_N_per_m,
            tangents,
            load,
            s0,
        )
        self.kt = tangents.stiffness_N_per_m[:, None]
        self.P = tangents.pad_count

    def state(
        self, q: NDArray[np.float64]
    ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64], NDArray[np.float64], NDArray[np.bool_]]:
        """(engagements, trial tangential forces (P, 2), limits (P,), forces (P, 2), slipped (P,))."""
        s = self.s0 + self.A @ q
        trial = self.kt * (self.t.matrix @ q - self.t.rest_m)
        capacity = self.t.friction_coefficient * self.t.normal_stiffness_N_per_m * np.maximum(s[: self.P], 0.0)
        force, slipped = cone_return_map(trial, capacity)
        return s, trial, capacity, force, slipped

    def residual(self, q: NDArray[np.float64]) -> NDArray[np.float64]:
        s, _, _, force, _ = self.state(q)
        return self.K0 @ q - self.f + self.A.T @ (self.k * np.maximum(s, 0.0)) + self.t.rows.T @ force.ravel()

    def jacobian(self, q: NDArray[np.float64]) -> NDArray[np.float64]:
        s, trial, capacity, _, slipped = self.state(q)
        engaged = s > 0.0
        J = self.K0 + self.A[engaged].T @ (self.k[engaged, None] * self.A[engaged])
        for p in range(self.P):
            At = self.t.matrix[p]
            if not slipped[p]:
                J += self.kt[p, 0] * At.T @ At
                continue
            norm = float(np.hypot(*trial[p]))
            e = trial[p] / norm
            J += At.T @ ((capacity[p] / norm) * (np.eye(2) - np.outer(e, e)) * self.kt[p, 0]) @ At
            if engaged[p]:
                J += self.t.friction_coefficient * self.t.normal_stiffness_N_per_m[p] * np.outer(At.T @ e, self.A[p])
        return J


def solve_frictional_statics(
    problem: CradleProblem,
    friction: PadFriction,
    heel_deg: float,
    trim_deg: float = 0.0,
    *,
    gravity_m_per_s2: float = 9.81,
    max_iterations: int = 60,
) -> FrictionalStatics:
    """The statics at ``heel_deg`` (starboard down +) and ``trim_deg`` (bow up +) on frictional pads (module docstring)."""
    tangents = pad_tangents(problem, friction, None, gravity_m_per_s2)
    load = problem.load(heel_deg, trim_deg, gravity_m_per_s2)
    eq = _Equilibrium(problem, tangents, load, rest_initial_engagement_m(problem, gravity_m_per_s2))
    q = tangents.rest_displacement
    r = eq.residual(q)
    iterations = 0
    while float(np.max(np.abs(r))) > 1e-9 * _scale(eq, q) and iterations < max_iterations:
        q, r = _newton_step(eq, q, r)
        iterations += 1
    s, _, _, force, slipped = eq.state(q)
    residual = float(np.max(np.abs(r)))
    outcome = StaticsOutcome.CONVERGED if residual <= 1e-9 * _scale(eq, q) else StaticsOutcome.NOT_CONVERGED
    slider = tangents.matrix @ q - force / eq.kt
    return FrictionalStatics(
        outcome,
        q,
        s,
        problem.element_stiffness_N_per_m * np.maximum(s, 0.0),
        force,
        slider - tangents.rest_m,
        slipped,
        residual,
        iterations,
    )


def _scale(eq: _Equilibrium, q: NDArray[np.float64]) -> float:
    """The residual's scale [N]: the largest load or element force, or the round-off of the beam's forces ``K0 q`` (a
    1e-12 share of the largest ``sum_j |K0_ij q_j|``: a stiff beam displaced far cancels large terms)."""
    s = eq.s0 + eq.A @ q
    beam = 1e-3 * float(np.max(np.abs(eq.K0) @ np.abs(q)))
    return max(float(np.max(np.abs(eq.f))), float(np.max(eq.k * np.maximum(s, 0.0), initial=0.0)), beam, 1.0)


def _newton_step(eq: _Equilibrium, q: NDArray[np.float64], r: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """One Newton step, halved until the residual's norm falls (Armijo, c = 1e-4); the last trial if none does."""
    step = np.linalg.solve(eq.jacobian(q), -r)
    t, norm = 1.0, float(np.linalg.norm(r))
    while True:
        r_new = eq.residual(q + t * step)
        if float(np.linalg.norm(r_new)) < (1.0 - 1e-4 * t) * norm or t < 1e-6:
            return q + t * step, r_new
        t *= 0.5
