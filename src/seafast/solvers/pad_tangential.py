"""The pads' tangential coordinates on the whole cargo, and the typed result of a solve with pad friction.

Every pad of a :class:`~seafast.solvers.transverse_statics.CradleProblem` (port then starboard per pair, the order
of the engagements) has two tangential coordinates (circumferential, axial; :mod:`seafast.model.pad_friction`)
``delta = A_t q + E_t x_o`` [m], linear in the cargo DOFs ``q`` and the deck DOFs ``x_o`` (z, theta per deck
point), as its compression is. The sliders start relaxed at rest: ``w = delta_rest = A_t q_rest`` with
``q_rest`` the frictionless statics at zero heel and trim (the cargo landed on its pads), so at rest every
friction force is zero and the friction only answers what changes from there.

Units: [m], [N], [N/m].
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from seafast.model.pad_friction import PadFriction, pad_tangential_deck, pad_tangential_gradients
from seafast.solvers.cradle_hbm import CradleResponse
from seafast.solvers.friction_cone import ConePeriod
from seafast.solvers.transverse_statics import CradleProblem, StaticsOutcome, solve_transverse_statics

__all__ = ["PadTangents", "pad_tangents", "FrictionalCradleResponse", "frictional_response"]


@dataclass(frozen=True)
class PadTangents:
    """The pads' tangential kinematics and friction (P pads, 5 n cargo DOFs, n_o deck DOFs).

    Attributes
    ----------
    matrix
        ``A_t`` (P, 2, 5 n) [m/m, m/rad]: (circumferential, axial) per pad.
    deck
        ``E_t`` (P, 2, n_o) [m/m]; zeros for a rigid deck.
    stiffness_N_per_m
        k_t per pad (P,) [N/m].
    normal_stiffness_N_per_m
        k_n per pad (P,) [N/m]; the pads' normal engagements are the problem's first P.
    friction_coefficient
        mu [-].
    rest_m
        ``delta_rest`` (P, 2) [m]: the sliders' initial positions.
    rest_displacement
        ``q_rest`` (5 n,) [m, rad]: the cargo at rest, where the sliders are relaxed.
    """

    matrix: NDArray[np.float64]
    deck: NDArray[np.float64]
    stiffness_N_per_m: NDArray[np.float64]
    normal_stiffness_N_per_m: NDArray[np.float64]
    friction_coefficient: float
    rest_m: NDArray[np.float64]
    rest_displacement: NDArray[np.float64]

    @property
    def pad_count(self) -> int:
        return int(self.matrix.shape[0])

    @property
    def rows(self) -> NDArray[np.float64]:
        """``A_t`` as (2 P, 5 n) rows, pad by pad (circumferential, axial)."""
        return self.matrix.reshape(2 * self.pad_count, -1)


def pad_tangents(
    problem: CradleProblem, friction: PadFriction, deck_x_m: NDArray[np.float64] | None = None, gravity_m_per_s2: float = 9.81
) -> PadTangents:
    """The tangential kinematics of ``problem``'s pads, with the deck points ``deck_x_m`` (None: a rigid deck).

    Raises ValueError when the cargo has no frictionless rest on its restraints (the sliders' reference).
    """
    cargo = problem.cargo
    P = 2 * len(problem.pad_pairs)
    deck_x = np.zeros(0) if deck_x_m is None else np.atleast_1d(np.asarray(deck_x_m, dtype=float))
    A = np.zeros((P, 2, cargo.dof_count))
    E = np.zeros((P, 2, 2 * deck_x.size))
    kt, kn = np.zeros(P), np.zeros(P)
    for i, pair in enumerate(problem.pad_pairs):
        A[2 * i : 2 * i + 2][:, :, cargo.node_dofs(cargo.node_at(pair.x_m, "pad_pairs: x_m"))] = pad_tangential_gradients(pair)
        if deck_x.size:
            E[2 * i : 2 * i + 2, :, 2 * int(np.argmin(np.abs(deck_x - pair.x_m)))] = pad_tangential_deck(pair)
        kt[2 * i : 2 * i + 2] = friction.tangential_stiffness_N_per_m(pair)
        kn[2 * i : 2 * i + 2] = pair.pad_stiffness_N_per_m
    rest = solve_transverse_statics(problem, 0.0, 0.0, gravity_m_per_s2=gravity_m_per_s2)
    if rest.outcome is not StaticsOutcome.CONVERGED:
        raise ValueError(f"problem: no frictionless rest at zero heel to relax the pads' sliders at ({rest.message})")
    return PadTangents(A, E, kt, kn, float(friction.friction_coefficient), A @ rest.displacement, rest.displacement)


@dataclass(frozen=True)
class FrictionalCradleResponse:
    """One period of the 3-D cargo on frictional pads: the frictionless record of the elements plus the friction.

    Attributes
    ----------
    cradle
        The elements' engagements and normal forces, the cargo's displacements, the outcome
        (:class:`~seafast.solvers.cradle_hbm.CradleResponse`).
    friction_coefficient
        mu [-].
    friction_force_N
        (N, P, 2) [N]: each pad's friction force resisting its (circumferential, axial) motion; on the cargo the
        opposite. ``|f| <= mu F_n``, exactly zero where the pad is open.
    slip_m
        (N, P, 2) [m]: each slider's displacement from its position at rest (the accumulated slip).
    """

    cradle: CradleResponse
    friction_coefficient: float
    friction_force_N: NDArray[np.float64]
    slip_m: NDArray[np.float64]

    @property
    def converged(self) -> bool:
        return self.cradle.converged

    @property
    def normal_force_N(self) -> NDArray[np.float64]:
        """(N, P) [N]: each pad's normal force (port, starboard per pair)."""
        return self.cradle.element_force_N[:, : self.cradle.pad_count]

    @property
    def friction_magnitude_N(self) -> NDArray[np.float64]:
        """``|f|`` (N, P) [N]."""
        return np.hypot(self.friction_force_N[..., 0], self.friction_force_N[..., 1])

    @property
    def friction_utilisation(self) -> NDArray[np.float64]:
        """``|f| / (mu F_n)`` (N, P) [-]: 1 in slip, below 1 in stick; 0 where the pad is open (no force, no limit)."""
        limit = self.friction_coefficient * self.normal_force_N
        return np.divide(self.friction_magnitude_N, limit, out=np.zeros_like(limit), where=limit > 0.0)

    @property
    def max_friction_N(self) -> NDArray[np.float64]:
        """Each pad's largest ``|f|`` over the period (P,) [N]."""
        return np.max(self.friction_magnitude_N, axis=0)

    @property
    def max_slip_m(self) -> NDArray[np.float64]:
        """Each pad's largest slider displacement from rest ``|w - w_rest|`` over the period (P,) [m]."""
        return np.max(np.hypot(self.slip_m[..., 0], self.slip_m[..., 1]), axis=0)

    @property
    def slip_range_m(self) -> NDArray[np.float64]:
        """Each pad's slip over the period, the largest distance between two of its slider positions (P, 2) [m] per
        direction (peak to peak): 0 for a pad that sticks all period."""
        return np.ptp(self.slip_m, axis=0)


def frictional_response(cradle: CradleResponse, tangents: PadTangents, period: ConePeriod) -> FrictionalCradleResponse:
    """The :class:`FrictionalCradleResponse` of a solve: its elements, and the pads' marched sliders."""
    return FrictionalCradleResponse(cradle, tangents.friction_coefficient, period.force_N, period.slider_m - tangents.rest_m[None])
