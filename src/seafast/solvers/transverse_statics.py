"""Exact statics of the 3-D cargo on cradle pads, side stoppers and lashings under a steady heel and trim.

The problem (docs/transverse.md): cargo DOFs ``q`` (:mod:`seafast.model.cargo3d`), the beam and
bilateral springs ``K0``, the load ``f`` (weight at the heel and trim, plus given loads), and ``m``
unilateral elements with engagements ``s = s0 + A q`` [m] and stiffnesses ``k``
(:mod:`seafast.model.cradle`), each carrying ``F = k max(s, 0)``. Equilibrium

``K0 q - f + A^T (k max(s, 0)) = 0``

is the stationarity of the convex, piecewise-quadratic energy
``P(q) = q^T K0 q / 2 - f^T q + sum k max(s, 0)^2 / 2``. For an engaged set ``S`` it is linear,
``(K0 + A_S^T diag(k_S) A_S) q = f - A_S^T (k_S s0_S)``. The solve is an active-set (semi-smooth)
Newton iteration on ``P``: from the current set, the linear solution of that set; if its signs agree
with the set (engaged ``s >= -tol``, open ``s <= tol``) it is the exact answer; else a step towards it
with an exact line search on ``P`` (a convex piecewise quadratic along the step, minimised at its
breakpoints), and the set of the new point. The energy falls at every step, so no set repeats
with a larger energy; a set whose cargo is a mechanism is stepped through with a regularised
Newton direction, and an energy without a lower bound along a step (the restraints cannot hold the
weight, e.g. every high-side pad lifted and no stopper) ends as :attr:`StaticsOutcome.MECHANISM`.

Units: displacements and engagements [m, rad]; forces [N]; stiffnesses [N/m].

Size: over 400 lines because the problem, its typed result and the one iteration that fills it (the set's
linear solve, the exact line search, the rigid-body test of a set) share the private ``_System``; split, it
would have to become public.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from enum import StrEnum

import numpy as np
import scipy.linalg
from numpy.typing import NDArray

from seafast.model.cargo3d import Cargo3D
from seafast.model.cradle import Engagement, Lashing, PadPair, Side, SideStopper, lashing_engagement, pad_engagements, stopper_engagement

__all__ = ["StaticsOutcome", "CradleProblem", "TransverseStatics", "solve_transverse_statics"]

CONSISTENCY_TOLERANCE = 1e-9
"""Sign tolerance of the final set: an element force of the wrong sign within this share of the largest load or
element force (or 1 N), the round-off of the linear solve."""

MECHANISM_TOLERANCE = 1e-10
"""A set restrains the cargo when its restraint of the five rigid-body motions has every singular value
above this fraction of the largest stiffness's square root."""


class StaticsOutcome(StrEnum):
    """How the transverse statics ended."""

    CONVERGED = "converged"
    """The exact solution: an engaged set whose linear solution agrees with its signs."""
    MECHANISM = "mechanism"
    """The restraints cannot hold the cargo: its energy falls without bound along a rigid-body motion."""
    NOT_CONVERGED = "not_converged"
    """No consistent set within the iteration limit; the last iterate is returned with its residual."""


@dataclass(frozen=True)
class CradleProblem:
    """The 3-D cargo with its cradles, side stoppers, lashings and bilateral springs.

    Parameters
    ----------
    cargo
        The 3-D cargo beam.
    pad_pairs, stoppers, lashings
        The unilateral elements; each stands at a node of the cargo's mesh.
    spring_diagonal_N_per_m
        Bilateral springs to the (rigid) deck on the cargo's DOFs [N/m, N m/rad], shape (5 n,) or
        None (e.g. today's lashing springs, :func:`seafast.model.cargo3d.vertical_plane_restraint`,
        or an axial restraint on a ``u`` DOF).
    load_N
        Loads beside the weight [N, N m], shape (5 n,) or None (e.g. today's pretension).
    pretension_at_rest
        True (default): each lashing holds its pretension with the cargo at rest on its pads at zero heel
        and trim, the lashings pulling with their pretensions (they are tightened after the cargo is
        landed); its stretch is measured from there. False: at the undisplaced cargo (pads just touching).
    """

    cargo: Cargo3D
    pad_pairs: tuple[PadPair, ...] = ()
    stoppers: tuple[SideStopper, ...] = ()
    lashings: tuple[Lashing, ...] = ()
    spring_diagonal_N_per_m: NDArray[np.float64] | None = None
    load_N: NDArray[np.float64] | None = None
    pretension_at_rest: bool = True
    engagements: tuple[Engagement, ...] = field(init=False, repr=False, compare=False)
    engagement_matrix: NDArray[np.float64] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        items: list[Engagement] = []
        for pair in self.pad_pairs:
            items.extend(pad_engagements(pair))
        items.extend(stopper_engagement(s) for s in self.stoppers)
        items.extend(lashing_engagement(lashing) for lashing in self.lashings)
        A = np.zeros((len(items), self.cargo.dof_count))
        names = ["pad_pairs"] * 2 * len(self.pad_pairs) + ["stoppers"] * len(self.stoppers) + ["lashings"] * len(self.lashings)
        for i, (item, name) in enumerate(zip(items, names, strict=True)):
            A[i, self.cargo.node_dofs(self.cargo.node_at(item.x_m, f"{name}: x_m"))] = item.gradient
        for label, vector in (("spring_diagonal_N_per_m", self.spring_diagonal_N_per_m), ("load_N", self.load_N)):
            if vector is not None and np.shape(vector) != (self.cargo.dof_count,):
                raise ValueError(f"{label}: shape {np.shape(vector)}: allowed ({self.cargo.dof_count},), one value per cargo DOF")
        object.__setattr__(self, "engagements", tuple(items))
        object.__setattr__(self, "engagement_matrix", A)

    @property
    def initial_engagement_m(self) -> NDArray[np.float64]:
        return np.array([e.initial_m for e in self.engagements], dtype=float)

    @property
    def element_stiffness_N_per_m(self) -> NDArray[np.float64]:
        return np.array([e.stiffness_N_per_m for e in self.engagements], dtype=float)

    @property
    def base_stiffness(self) -> NDArray[np.float64]:
        """``K0``: the beam and the bilateral springs [SI]."""
        if self.spring_diagonal_N_per_m is None:
            return self.cargo.stiffness
        return self.cargo.stiffness + np.diag(np.asarray(self.spring_diagonal_N_per_m, dtype=float))

    def load(self, heel_deg: float, trim_deg: float, gravity_m_per_s2: float) -> NDArray[np.float64]:
        """The weight at the heel and trim plus the given loads [N, N m]."""
        f = self.cargo.gravity_load_N(heel_deg, trim_deg, gravity_m_per_s2)
        return f if self.load_N is None else f + np.asarray(self.load_N, dtype=float)


@dataclass(frozen=True)
class TransverseStatics:
    """The exact statics of a :class:`CradleProblem` at one heel and trim.

    Attributes
    ----------
    outcome
        How the solve ended.
    displacement
        Cargo DOFs (5 n,) [m, rad] (:mod:`seafast.model.cargo3d`'s order).
    pad_force_N
        Normal force of each pad, shape (n_pairs, 2): columns port, starboard [N], >= 0.
    stopper_force_N, lashing_tension_N
        Per stopper and lashing [N], >= 0 (exactly 0 when open or slack).
    engagement_m
        Every element's engagement (pads, stoppers, lashings in that order) [m]: compression,
        overclosure, stretch; open where <= 0.
    pair_lateral_force_N, pair_vertical_force_N
        Each pad pair's resultant push on the cargo along y (to port +) and z (up +) [N].
    residual_N
        Largest equilibrium residual ``|K0 q - f + A^T F|`` over the DOFs [N, N m].
    complementarity_m
        Largest sign violation of the final set [m]: an engaged element's ``-s`` or an open one's ``s``
        (zero or round-off when converged).
    iterations
        Linear solves made.
    message
        For people.
    """

    outcome: StaticsOutcome
    displacement: NDArray[np.float64]
    pad_force_N: NDArray[np.float64]
    stopper_force_N: NDArray[np.float64]
    lashing_tension_N: NDArray[np.float64]
    engagement_m: NDArray[np.float64]
    pair_lateral_force_N: NDArray[np.float64]
    pair_vertical_force_N: NDArray[np.float64]
    residual_N: float
    complementarity_m: float
    iterations: int
    message: str

    @property
    def pad_open(self) -> NDArray[np.bool_]:
        """Which pads carry nothing, (n_pairs, 2) (port, starboard)."""
        return self.pad_force_N <= 0.0

    @property
    def stopper_open(self) -> NDArray[np.bool_]:
        return self.stopper_force_N <= 0.0

    @property
    def lashing_slack(self) -> NDArray[np.bool_]:
        return self.lashing_tension_N <= 0.0


@dataclass(frozen=True)
class _System:
    """The numbers of one solve: K0, f, A, s0, k, the rigid-body restraint and the tolerance scale."""

    K0: NDArray[np.float64]
    f: NDArray[np.float64]
    A: NDArray[np.float64]
    s0: NDArray[np.float64]
    k: NDArray[np.float64]
    spring_restraint: NDArray[np.float64]
    engagement_restraint: NDArray[np.float64]
    rigid_modes: NDArray[np.float64]
    scale: float

    def gradient(self, q: NDArray[np.float64]) -> NDArray[np.float64]:
        return self.K0 @ q - self.f + self.A.T @ (self.k * np.maximum(self.s0 + self.A @ q, 0.0))

    def hessian(self, engaged: NDArray[np.bool_]) -> NDArray[np.float64]:
        Ae = self.A[engaged]
        return self.K0 + Ae.T @ (self.k[engaged, None] * Ae)

    def free_motions(self, engaged: NDArray[np.bool_]) -> NDArray[np.float64]:
        """Orthonormal rigid-body motions the set leaves free, (5 n, r): none when ``K0 + A_S^T k A_S`` is positive definite.

        The free beam's null space is its five rigid-body motions; the set restrains one when the springs or
        engaged elements strain it, i.e. the restraint matrix has a singular value above
        :data:`MECHANISM_TOLERANCE` of the stiffness scale along it.
        """
        C = np.vstack([self.spring_restraint, self.engagement_restraint[engaged]])
        _, sv, Vt = np.linalg.svd(C) if C.shape[0] else (None, np.zeros(0), np.eye(5))
        sv = np.concatenate([sv, np.zeros(5 - sv.size)])
        null = Vt[sv <= MECHANISM_TOLERANCE * self.scale]
        return np.linalg.qr(self.rigid_modes @ null.T)[0] if null.size else np.zeros((self.K0.shape[0], 0))

    def solve(self, engaged: NDArray[np.bool_]) -> NDArray[np.float64]:
        rhs = self.f - self.A[engaged].T @ (self.k[engaged] * self.s0[engaged])
        return np.asarray(scipy.linalg.cho_solve(scipy.linalg.cho_factor(self.hessian(engaged)), rhs), dtype=float)


def _system(
    problem: CradleProblem, heel_deg: float, trim_deg: float, gravity_m_per_s2: float, initial_m: NDArray[np.float64] | None = None
) -> _System:
    K0 = problem.base_stiffness
    A, k = problem.engagement_matrix, problem.element_stiffness_N_per_m
    R = problem.cargo.rigid_body_modes()
    springs = np.zeros(K0.shape[0]) if problem.spring_diagonal_N_per_m is None else np.asarray(problem.spring_diagonal_N_per_m)
    spring_restraint = np.sqrt(np.maximum(springs, 0.0))[:, None] * R
    spring_restraint = spring_restraint[np.any(spring_restraint != 0.0, axis=1)]
    scale = float(np.sqrt(max(np.max(np.abs(np.diag(K0))), float(np.max(k, initial=0.0)))))
    return _System(
        K0,
        problem.load(heel_deg, trim_deg, gravity_m_per_s2),
        A,
        problem.initial_engagement_m if initial_m is None else initial_m,
        k,
        spring_restraint,
        np.sqrt(k)[:, None] * (A @ R),
        R,
        scale,
    )


def _line_search(system: _System, q: NDArray[np.float64], d: NDArray[np.float64]) -> float:
    """The exact minimiser ``t >= 0`` of ``P(q + t d)``; ``inf`` when P falls without bound along d.

    ``dP/dt = c0 + c1 t + sum k sigma max(s + t sigma, 0)`` is piecewise linear and non-decreasing:
    its root is found segment by segment between the breakpoints ``-s / sigma``.
    """
    s, sigma = system.s0 + system.A @ q, system.A @ d
    c0, c1 = float(d @ (system.K0 @ q - system.f)), float(d @ (system.K0 @ d))

    def slope(t: float) -> float:
        return c0 + c1 * t + float(np.sum(system.k * sigma * np.maximum(s + t * sigma, 0.0)))

    with np.errstate(divide="ignore", invalid="ignore"):
        breaks = np.where(sigma != 0.0, -s / sigma, -1.0)
    start, value = 0.0, slope(0.0)
    if value >= 0.0:
        return 0.0
    for t in np.sort(breaks[breaks > 0.0]):
        end_value = slope(float(t))
        if end_value >= 0.0:
            return start + (0.0 - value) * (float(t) - start) / (end_value - value)
        start, value = float(t), end_value
    # beyond the last breakpoint dP/dt has the slope of the elements engaged there
    after = c1 + float(np.sum(system.k * sigma**2 * ((s + (start + 1.0) * sigma) > 0.0)))
    if after <= 1e-12 * system.scale**2 * float(d @ d):
        return np.inf
    return start - value / after


def _violation(system: _System, q: NDArray[np.float64], engaged: NDArray[np.bool_]) -> tuple[NDArray[np.float64], float]:
    s = system.s0 + system.A @ q
    return s, float(np.max(np.where(engaged, -s, s), initial=0.0))


def _consistent(system: _System, q: NDArray[np.float64], engaged: NDArray[np.bool_]) -> bool:
    """Whether the set's signs hold at ``q``, as forces: an engaged element's tension or an open element's would-be
    force ``k |s|`` within :data:`CONSISTENCY_TOLERANCE` of the largest load or element force.

    As forces, not as engagements: a soft lashing's engagement (its pretension over its stiffness) can be metres,
    and a tolerance relative to it would pass a pad sign wrong by a millimetre.
    """
    s, _ = _violation(system, q, engaged)
    wrong_N = system.k * np.maximum(np.where(engaged, -s, s), 0.0)
    force_scale_N = max(float(np.max(np.abs(system.f), initial=0.0)), float(np.max(system.k * np.maximum(s, 0.0), initial=0.0)), 1.0)
    return float(np.max(wrong_N, initial=0.0)) <= CONSISTENCY_TOLERANCE * force_scale_N


def _unrestrained_step(
    system: _System, q: NDArray[np.float64], engaged: NDArray[np.bool_], free: NDArray[np.float64]
) -> NDArray[np.float64]:
    """A descent step from a set that leaves rigid-body motions ``free``: along them where the load works on them, else
    the Newton step in the restrained subspace (the free motions projected out)."""
    g = system.gradient(q)
    work = free.T @ g
    if float(np.linalg.norm(work)) > 1e-12 * max(float(np.linalg.norm(g)), 1e-300):
        return -free @ work
    H = system.hessian(engaged)
    P = np.eye(H.shape[0]) - free @ free.T
    d = -np.linalg.solve(P @ H @ P + free @ free.T * system.scale**2, P @ g)
    return d - free @ (free.T @ d)


def _iterate(system: _System, max_iterations: int) -> tuple[StaticsOutcome, NDArray[np.float64], NDArray[np.bool_], int]:
    """The active-set Newton iteration with exact line search (the module's docstring)."""
    n = system.K0.shape[0]
    q = np.zeros(n)
    engaged = system.s0 >= 0.0  # pads touch (s0 = 0), lashings pretensioned, stoppers with no gap
    for iteration in range(1, max_iterations + 1):
        free = system.free_motions(engaged)
        if free.shape[1] == 0:
            trial = system.solve(engaged)
            if _consistent(system, trial, engaged):
                return StaticsOutcome.CONVERGED, trial, engaged, iteration
            d = trial - q
        else:
            d = _unrestrained_step(system, q, engaged, free)
        t = _line_search(system, q, d)
        if not np.isfinite(t):
            return StaticsOutcome.MECHANISM, q, engaged, iteration
        q = q + t * d
        new = (system.s0 + system.A @ q) > 0.0
        if t == 0.0 and np.array_equal(new, engaged):
            break
        engaged = new
    return StaticsOutcome.NOT_CONVERGED, q, engaged, max_iterations


def solve_transverse_statics(
    problem: CradleProblem,
    heel_deg: float = 0.0,
    trim_deg: float = 0.0,
    *,
    gravity_m_per_s2: float = 9.81,
    max_iterations: int | None = None,
) -> TransverseStatics:
    """Exact static equilibrium of the cargo on its unilateral restraints at a steady heel and trim.

    Parameters
    ----------
    problem
        The cargo, its elements and bilateral springs.
    heel_deg
        Steady heel [deg], starboard down + (gravity then has a component to starboard, -y).
    trim_deg
        Steady trim [deg], bow up + (gravity then has a component aft, -x).
    gravity_m_per_s2
        g [m/s^2].
    max_iterations
        Linear solves allowed (default ``4 m + 20`` for m elements).

    Returns
    -------
    TransverseStatics
        The forces, displacements and sets; ``outcome`` says how it ended (``CONVERGED``: exact to
        round-off, signs checked; ``MECHANISM``: the restraints cannot hold the weight;
        ``NOT_CONVERGED``: the last iterate, with its residual).
    """
    limit = 4 * len(problem.engagements) + 20 if max_iterations is None else int(max_iterations)
    if limit < 1:
        raise ValueError(f"max_iterations = {max_iterations!r}: allowed an integer >= 1")
    initial_m = None
    if problem.lashings and problem.pretension_at_rest:
        rest = _rest(problem, gravity_m_per_s2, limit)
        if rest.outcome is not StaticsOutcome.CONVERGED:
            pretension = np.array([item.pretension_N for item in problem.lashings])
            return replace(
                rest,
                lashing_tension_N=pretension,
                engagement_m=np.concatenate([rest.engagement_m, pretension / [item.stiffness_N_per_m for item in problem.lashings]]),
                message=f"the cargo at rest with its lashings' pretensions: {rest.message}",
            )
        lashing = slice(2 * len(problem.pad_pairs) + len(problem.stoppers), None)
        initial_m = problem.initial_engagement_m
        initial_m[lashing] -= problem.engagement_matrix[lashing] @ rest.displacement
    system = _system(problem, heel_deg, trim_deg, gravity_m_per_s2, initial_m)
    outcome, q, engaged, iterations = _iterate(system, limit)
    return _result(problem, system, outcome, q, engaged, iterations, heel_deg, trim_deg)


def _rest(problem: CradleProblem, gravity_m_per_s2: float, limit: int) -> TransverseStatics:
    """The cargo on its pads (and stoppers) at zero heel and trim, each lashing a constant pull of its pretension."""
    lashing = slice(2 * len(problem.pad_pairs) + len(problem.stoppers), None)
    pretension = np.array([item.pretension_N for item in problem.lashings])
    pull = -problem.engagement_matrix[lashing].T @ pretension
    load = pull if problem.load_N is None else np.asarray(problem.load_N, dtype=float) + pull
    resting = replace(problem, lashings=(), load_N=load)
    system = _system(resting, 0.0, 0.0, gravity_m_per_s2)
    outcome, q, engaged, iterations = _iterate(system, limit)
    return _result(resting, system, outcome, q, engaged, iterations, 0.0, 0.0)


def _result(
    problem: CradleProblem,
    system: _System,
    outcome: StaticsOutcome,
    q: NDArray[np.float64],
    engaged: NDArray[np.bool_],
    iterations: int,
    heel_deg: float,
    trim_deg: float,
) -> TransverseStatics:
    s, violation = _violation(system, q, engaged)
    force = system.k * np.maximum(s, 0.0)
    n_pad, n_st = 2 * len(problem.pad_pairs), len(problem.stoppers)
    pads = force[:n_pad].reshape(-1, 2)
    normals = np.array([[pair.pad_normal(side) for side in (Side.PORT, Side.STARBOARD)] for pair in problem.pad_pairs]).reshape(-1, 2, 2)
    push = np.einsum("ps,psj->pj", pads, normals) if pads.size else np.zeros((0, 2))
    residual = float(np.max(np.abs(system.gradient(q)), initial=0.0))
    words = {
        StaticsOutcome.CONVERGED: "exact active-set solution",
        StaticsOutcome.MECHANISM: "the restraints cannot hold the cargo (a rigid-body motion is free; add a stopper or lashing)",
        StaticsOutcome.NOT_CONVERGED: "no consistent contact set within the iteration limit",
    }[outcome]
    open_pads = int(np.count_nonzero(pads <= 0.0))
    message = (
        f"{words} at heel {heel_deg:g} deg, trim {trim_deg:g} deg after {iterations} solve(s): {open_pads} pad(s) open, "
        f"{int(np.count_nonzero(force[n_pad : n_pad + n_st] > 0.0))} stopper(s) in contact, "
        f"{int(np.count_nonzero(force[n_pad + n_st :] <= 0.0))} lashing(s) slack; residual {residual:.3g} N"
    )
    return TransverseStatics(
        outcome=outcome,
        displacement=q,
        pad_force_N=pads,
        stopper_force_N=force[n_pad : n_pad + n_st],
        lashing_tension_N=force[n_pad + n_st :],
        engagement_m=s,
        pair_lateral_force_N=push[:, 0],
        pair_vertical_force_N=push[:, 1],
        residual_N=residual,
        complementarity_m=violation,
        iterations=iterations,
        message=message,
    )
