"""The linear part of the 3-D cargo's dynamics on its cradles, and its condensation onto the engagements.

Equation of motion (docs/transverse.md#7-dynamics), cargo DOFs ``q`` (:mod:`seafast.model.cargo3d`), deck DOFs
``x_o`` prescribed (the vertical plane's: z and theta under each saddle)::

    M q'' + D (q' - S x_o') + K0 q = f(t) - K_co,springs x_o(t) - A^T (k max(s, 0)),
    s = s0 + A q + E x_o(t),

with ``K0`` the beam and the bilateral springs, ``D = alpha M + beta K_beam`` (the vertical plane's Rayleigh
damping on the whole 3-D beam), ``f`` the weight, the given loads and the vessel's loads, ``A`` the engagements'
gradients and ``E`` how the deck's vertical motion moves them: a pad's compression grows by ``cos(alpha) z_deck``
under its pair, a lashing's stretch by ``e_z`` times the deck's rise at its anchor (the deck point nearest
the anchor along the cargo, rigid between: ``z + theta (x_anchor - x_deck)``); a side stopper does not move
(the deck moves only vertically). ``S = -K_lin^-1 K_co`` is the quasi-static influence of the deck DOFs
on the cargo with the pads and lashings bilateral and the stoppers open, as at rest (``K_lin = K0 + A^T k A``,
``K_co = K_co,springs + A^T k E`` over those elements): the damping acts on the motion relative to what the
supports impose, as in the vertical plane, whichever elements are engaged.

Condensed as the vertical plane's harmonic balance (:mod:`seafast.solvers.hbm.condensed`): every element is
kept bilateral in the linear part and the nonlinearity is the correction ``c = k max(s, 0) - k s`` (the
tension a bilateral pad or stopper would carry, the compression of a bilateral lashing), whose generalised
force on the cargo is ``-A^T c``. Per harmonic ``s_k = s_lin,k - G_k C_k`` with the receptance
``G_k = A K_d(k w)^-1 A^T`` [m/N]: the :class:`~seafast.solvers.hbm.condensed.CondensedOperators` of the
engagements, which the vertical plane's condensed solver takes as they are. The dynamic stiffness is solved
in the node-by-node order, where it is banded (half bandwidth 9).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from functools import cached_property

import numpy as np
from numpy.typing import NDArray
from scipy.linalg import eigh

from seafast.excitation.cradle_loads import CradleExcitation
from seafast.fourier import complex_to_real_harmonics
from seafast.model.cargo3d import Cargo3D
from seafast.model.structure import StructuralModel
from seafast.solvers.cradle_blocks import CradleBlocks, NodeBand, band_blocks, node_band, pattern_blocks
from seafast.solvers.dynamic_stiffness import QuadraticMatrices, solve_dynamic_stack
from seafast.solvers.hbm.condensed import CondensedOperators
from seafast.solvers.transverse_statics import CradleProblem, StaticsOutcome, solve_transverse_statics

__all__ = [
    "CradleDynamics",
    "CradleLinearParts",
    "cradle_dynamics_of",
    "cradle_operators",
    "rest_initial_engagement_m",
]


@dataclass(frozen=True)
class CradleDynamics:
    """The 3-D cargo on its cradles, with its damping and the deck it stands on.

    Parameters
    ----------
    problem
        The cargo, its pads, stoppers, lashings, bilateral springs and given loads.
    rayleigh_alpha_per_s, rayleigh_beta_s
        ``D = alpha M + beta K_beam`` [1/s, s] on the 3-D beam (the elements and springs undamped).
    deck_x_m
        Cargo x of each deck point (z, theta DOFs each) [m], shape (n_s,): every pad pair stands on one.
    spring_deck_coupling
        ``K_co`` of the bilateral springs to the deck DOFs [N/m, ...], shape (5 n, 2 n_s), or None (a rigid
        deck under them).
    gravity_m_per_s2
        g [m/s^2].
    """

    problem: CradleProblem
    rayleigh_alpha_per_s: float
    rayleigh_beta_s: float
    deck_x_m: NDArray[np.float64]
    spring_deck_coupling: NDArray[np.float64] | None = None
    gravity_m_per_s2: float = 9.81
    parts_cache: dict[bytes, CradleLinearParts] = field(init=False, repr=False, compare=False, default_factory=dict)

    def __post_init__(self) -> None:
        cargo = self.problem.cargo
        deck_nodes = [cargo.node_at(x, "deck_x_m") for x in np.atleast_1d(self.deck_x_m)]
        for i, pair in enumerate(self.problem.pad_pairs):
            if cargo.node_at(pair.x_m) not in deck_nodes:
                raise ValueError(f"pad_pairs[{i}].x_m = {pair.x_m!r}: allowed a deck point's x (deck_x_m = {list(self.deck_x_m)})")
        shape = (cargo.dof_count, 2 * len(deck_nodes))
        if self.spring_deck_coupling is not None and np.shape(self.spring_deck_coupling) != shape:
            raise ValueError(f"spring_deck_coupling: shape {np.shape(self.spring_deck_coupling)}; allowed {shape}")

    @cached_property
    def order(self) -> NDArray[np.intp]:
        """The node-by-node order of the DOFs: ``q[order]`` is (u, v, w, psi, theta) of node 0, node 1, ..."""
        cargo: Cargo3D = self.problem.cargo
        return np.concatenate([cargo.node_dofs(i) for i in range(cargo.node_count)])

    @cached_property
    def initial_engagement_m(self) -> NDArray[np.float64]:
        return rest_initial_engagement_m(self.problem, self.gravity_m_per_s2)

    @cached_property
    def deck_engagement(self) -> NDArray[np.float64]:
        return _deck_engagement(self)

    @cached_property
    def matrices(self) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
        """(K0, M, D) in the cargo's block order [SI]: the beam and springs, the mass, the Rayleigh damping."""
        cargo = self.problem.cargo
        return self.problem.base_stiffness, cargo.mass, self.rayleigh_alpha_per_s * cargo.mass + self.rayleigh_beta_s * cargo.stiffness

    @cached_property
    def spring_coupling(self) -> NDArray[np.float64]:
        """``K_co`` of the bilateral springs alone (5 n, n_o) [SI]."""
        coupling = self.spring_deck_coupling
        return np.zeros((self.problem.cargo.dof_count, self.deck_engagement.shape[1])) if coupling is None else coupling

    @cached_property
    def node_band(self) -> NodeBand | None:
        """``K0``, M and D at their entries within half bandwidth 9 of the node-by-node order (the beam's elements join
        neighbouring nodes, an engagement acts at one node); None where another entry is not zero
        (:func:`~seafast.solvers.cradle_blocks.node_band`)."""
        problem, cargo = self.problem, self.problem.cargo
        width = 2 * (cargo.dof_count // cargo.node_count) - 1
        rayleigh = (self.rayleigh_alpha_per_s, self.rayleigh_beta_s)
        return node_band(
            self.order, (cargo.stiffness, cargo.mass), problem.spring_diagonal_N_per_m, rayleigh, problem.engagement_matrix, width
        )

    @cached_property
    def static_load(self) -> NDArray[np.float64]:
        """:meth:`static_load_N`, formed once (read-only)."""
        load = self.problem.load(0.0, 0.0, self.gravity_m_per_s2)
        load.setflags(write=False)
        return load

    def static_load_N(self) -> NDArray[np.float64]:
        """The weight at zero heel and trim plus the given loads [N, N m]."""
        return self.static_load.copy()

    @property
    def damping_set(self) -> NDArray[np.bool_]:
        """The elements bilateral in ``S``: every pad and lashing (the stoppers open, as they are at rest)."""
        problem = self.problem
        mask = np.ones(len(problem.engagements), dtype=bool)
        mask[2 * len(problem.pad_pairs) : 2 * len(problem.pad_pairs) + len(problem.stoppers)] = False
        return mask

    @property
    def support_damping_coupling(self) -> NDArray[np.float64]:
        """``D_co = -D S`` (5 n, n_o), ``S = -K_lin^-1 K_co`` with the pads and lashings bilateral (:attr:`damping_set`):
        the damping's coupling to the deck velocities, the same whichever elements are engaged (the vertical plane's law)."""
        return self.linear_parts(self.damping_set).deck_coupling[1]

    def linear_parts(self, included: NDArray[np.bool_] | None = None) -> CradleLinearParts:
        """The linear operators with the elements ``included`` (default all) bilateral, kept per set of elements."""
        mask = np.ones(len(self.problem.engagements), dtype=bool) if included is None else np.asarray(included, dtype=bool)
        key = mask.tobytes()
        if key not in self.parts_cache:
            self.parts_cache[key] = CradleLinearParts(self, mask)
        return self.parts_cache[key]


def cradle_dynamics_of(model: StructuralModel, problem: CradleProblem) -> CradleDynamics:
    """The dynamics of ``problem`` with the vertical-plane model's damping, deck points and lashing springs' deck coupling.

    ``problem.cargo`` must be built on ``model``'s mesh; its bilateral springs on the vertical block are taken as
    ``model``'s lashings (:func:`~seafast.model.cargo3d.vertical_plane_restraint`), so they move with the deck.
    """
    cargo = problem.cargo
    coupling = np.zeros((cargo.dof_count, model.deck_dof_count))
    coupling[: model.cargo_dof_count] = model.spring_parts(False)[1]
    return CradleDynamics(problem, model.rayleigh_alpha_per_s, model.rayleigh_beta_s, model.saddle_x_m, coupling, model.gravity_m_per_s2)


def rest_initial_engagement_m(problem: CradleProblem, gravity_m_per_s2: float = 9.81) -> NDArray[np.float64]:
    """``s0`` of every element [m]; with ``pretension_at_rest`` the lashings' from the cargo at rest on its pads.

    The same reference as :func:`~seafast.solvers.transverse_statics.solve_transverse_statics`: the cargo landed at
    zero heel and trim with each lashing a constant pull of its pretension.
    """
    s0 = problem.initial_engagement_m
    if not (problem.lashings and problem.pretension_at_rest):
        return s0
    lashing = slice(2 * len(problem.pad_pairs) + len(problem.stoppers), None)
    pull = -problem.engagement_matrix[lashing].T @ np.array([item.pretension_N for item in problem.lashings])
    load = pull if problem.load_N is None else np.asarray(problem.load_N, dtype=float) + pull
    rest = solve_transverse_statics(replace(problem, lashings=(), load_N=load), 0.0, 0.0, gravity_m_per_s2=gravity_m_per_s2)
    if rest.outcome is not StaticsOutcome.CONVERGED:
        raise ValueError(f"lashings: the cargo at rest with their pretensions has no equilibrium ({rest.message})")
    s0[lashing] -= problem.engagement_matrix[lashing] @ rest.displacement
    return s0


def _deck_engagement(dynamics: CradleDynamics) -> NDArray[np.float64]:
    """``E`` (m, 2 n_s): the engagements' change per deck DOF (z [m], theta [rad]) [m/m, m/rad]."""
    problem, deck_x = dynamics.problem, np.atleast_1d(dynamics.deck_x_m)
    E = np.zeros((len(problem.engagements), 2 * deck_x.size))
    for i, pair in enumerate(problem.pad_pairs):
        d = int(np.argmin(np.abs(deck_x - pair.x_m)))
        E[2 * i : 2 * i + 2, 2 * d] = np.cos(pair.contact_angle_rad)
    first = 2 * len(problem.pad_pairs) + len(problem.stoppers)
    for j, lashing in enumerate(problem.lashings):
        x_anchor = float(lashing.anchor_point_m[0])
        d = int(np.argmin(np.abs(deck_x - x_anchor)))
        e_z = float(lashing.direction[2])
        E[first + j, 2 * d], E[first + j, 2 * d + 1] = e_z, e_z * (x_anchor - deck_x[d])
    return E


class CradleLinearParts:
    """The linear operators of a :class:`CradleDynamics` with the elements ``included`` bilateral (built on first use).

    The elements left out are taken open in the linear part: the harmonic balance leaves out the side stoppers
    first (open most of the time, they would otherwise be corrected at every sample) and brings in any that closes.
    """

    def __init__(self, dynamics: CradleDynamics, included: NDArray[np.bool_]) -> None:
        self.dynamics = dynamics
        self.included = np.asarray(included, dtype=bool)

    @property
    def engagement_matrix(self) -> NDArray[np.float64]:
        """``A`` of the included elements (m_I, 5 n) [m/m, m/rad]."""
        return self.dynamics.problem.engagement_matrix[self.included]

    @property
    def element_stiffness_N_per_m(self) -> NDArray[np.float64]:
        return self.dynamics.problem.element_stiffness_N_per_m[self.included]

    @cached_property
    def bilateral_stiffness(self) -> NDArray[np.float64]:
        """``K_lin = K0 + A_I^T k_I A_I`` [SI]: the included elements bilateral."""
        A, k = self.engagement_matrix, self.element_stiffness_N_per_m
        return self.dynamics.matrices[0] + A.T @ (k[:, None] * A)

    @cached_property
    def deck_coupling(self) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """(``K_co``, ``D_co``) of this linear part to the deck DOFs (5 n, n_o) [SI]; ``D_co`` the dynamics' own."""
        d = self.dynamics
        A, k = self.engagement_matrix, self.element_stiffness_N_per_m
        K_co = d.spring_coupling + A.T @ (k[:, None] * d.deck_engagement[self.included])
        if np.array_equal(self.included, d.damping_set):
            S = -self.solve_stack(np.zeros(1), K_co[None].astype(complex))[0].real
            DS = np.zeros_like(S)
            for (dofs, _), (_, _, D) in zip(self.blocks, self.block_parts.dense, strict=True):
                DS[dofs] = D @ S[dofs]  # D has no entry between blocks
            return K_co, -DS
        return K_co, d.support_damping_coupling

    @cached_property
    def block_parts(self) -> CradleBlocks:
        """The uncoupled blocks of ``K_lin``, M, D, banded and dense (:mod:`seafast.solvers.cradle_blocks`): from the
        entries near the diagonal in the node-by-node order (the dense matrices never formed), or where the matrices
        have other entries from the scan of the dense ones."""
        d = self.dynamics
        band = d.node_band
        if band is None:
            return pattern_blocks(self.bilateral_stiffness, d.matrices[1], d.matrices[2], d.order)
        stiffness = band.stiffness + band.engagement_stiffness(self.engagement_matrix, self.element_stiffness_N_per_m)
        return band_blocks(band, stiffness, d.order)

    @property
    def blocks(self) -> tuple[tuple[NDArray[np.intp], QuadraticMatrices], ...]:
        """The uncoupled blocks of ``K_lin``, M, D: each one's DOFs (node by node) and its banded matrices.

        Without lashings (the only elements coupling a node's five DOFs) the axial, lateral and vertical motions
        are uncoupled even with the pads bilateral, and each block is banded in its own order (half bandwidth 3 or 1,
        against 9 for the five DOFs together): the solves per harmonic cost a ninth. A pair's two pads couple
        the lateral and vertical motions by ``k cos(alpha) sin(alpha)`` each, with opposite signs: their sum is
        zero but for round-off, which is not a coupling (:func:`~seafast.solvers.cradle_blocks.coupling_pattern`).
        """
        return self.block_parts.banded

    @cached_property
    def block_modes(self) -> tuple[tuple[NDArray[np.float64], NDArray[np.float64]], ...]:
        """Every undamped mode of each block (:attr:`blocks`, deck fixed): its ``w^2`` ascending [rad^2/s^2] and
        mass-normalised eigenvectors (n_b, n_b), solved once for this set of elements (the correction systems of every
        cutoff, and every solve of the same dynamics, take them from here)."""
        return tuple(eigh(K, M, driver="gvd", check_finite=False) for K, M, _ in self.block_parts.dense)

    def solve_stack(self, omegas: NDArray[np.float64], rhs: NDArray[np.complex128]) -> NDArray[np.complex128]:
        """``K_d(w_k)^-1 rhs_k`` with every element bilateral, (n_k, 5 n, r) in the block order [m, rad per N].

        Per block, the right-hand sides that load it; where they load fewer DOFs than they are (a pad pair's two
        pads push on the same two DOFs), the block is solved for a unit load at each loaded DOF and the
        right-hand sides combined from those: ``K^-1 b = sum_i K^-1 e_i b_i``.
        """
        out = np.zeros(rhs.shape, dtype=complex)
        for dofs, q in self.blocks:
            part = rhs[:, dofs]
            columns = np.flatnonzero(np.any(part != 0.0, axis=(0, 1)))  # the right-hand sides that load this block
            rows = np.flatnonzero(np.any(part != 0.0, axis=(0, 2)))  # the DOFs they load
            if columns.size == 0:
                continue
            if rows.size < columns.size:
                units = np.zeros((omegas.size, dofs.size, rows.size), dtype=complex)
                units[:, rows, np.arange(rows.size)] = 1.0
                Z = solve_dynamic_stack(q, omegas, units)
                out[:, dofs[:, None], columns[None, :]] = Z @ part[:, rows[:, None], columns[None, :]]
            elif columns.size == rhs.shape[2]:
                out[:, dofs] = solve_dynamic_stack(q, omegas, np.ascontiguousarray(part))
            else:
                out[:, dofs[:, None], columns[None, :]] = solve_dynamic_stack(q, omegas, np.ascontiguousarray(part[:, :, columns]))
        return out


def cradle_operators(
    dynamics: CradleDynamics,
    excitation: CradleExcitation,
    harmonics: int,
    included: NDArray[np.bool_] | None = None,
    *,
    reuse: CondensedOperators | None = None,
) -> CondensedOperators:
    """The linear problem condensed onto the included engagements, harmonics 0 .. H (those elements bilateral).

    The returned operators' "saddles" are the included engagements (pads, stoppers, lashings, in the problem's
    order): ``saddle_stiffness_N_per_m`` their k, ``linear_compression_m`` their engagements in the linear part,
    ``receptance_harmonics`` ``G_k = A_I K_d^-1 A_I^T``, ``cargo_influence`` ``K_d^-1 (-A_I^T)`` (block order).
    ``included``: default every element; the others are open in the linear part (and carry nothing).
    ``reuse``: the operators of the same dynamics, excitation and ``included`` at fewer harmonics (at least 1):
    theirs are kept and only the receptances of the new harmonics solved (the loads and the deck's motion
    live on k = 0, 1), the same numbers as built afresh.
    """
    H = int(harmonics)
    if reuse is not None and 1 <= reuse.harmonics < H and reuse.omega_rad_s == float(excitation.omega_rad_s):
        return _extended_operators(dynamics.linear_parts(included), reuse, H)
    parts = dynamics.linear_parts(included)
    A, k = parts.engagement_matrix, parts.element_stiffness_N_per_m
    E, s0 = dynamics.deck_engagement[parts.included], dynamics.initial_engagement_m[parts.included]
    m, n = A.shape
    if excitation.cargo_load_N.shape[1] != n or excitation.deck_displacement.shape[1] != E.shape[1]:
        raise ValueError("excitation: its cargo DOFs or deck DOFs do not match the dynamics' cargo and deck points")
    w = float(excitation.omega_rad_s)
    xo = np.zeros((H + 1, E.shape[1]), dtype=complex)
    f = np.zeros((H + 1, n), dtype=complex)
    rows = min(2, H + 1)
    xo[:rows], f[:rows] = excitation.deck_displacement[:rows], excitation.cargo_load_N[:rows]
    xo[0], f[0] = xo[0].real, (f[0] + dynamics.static_load).real
    wk = w * np.arange(H + 1, dtype=np.float64)
    K_co, D_co = parts.deck_coupling
    load = f - xo @ K_co.T - 1j * wk[:, None] * (xo @ D_co.T)
    load[0] -= A.T @ (k * s0)
    Y = parts.solve_stack(wk, np.broadcast_to(-A.T[None], (H + 1, n, m)).astype(complex))
    X_lin = np.zeros((H + 1, n), dtype=complex)
    X_lin[:rows] = parts.solve_stack(wk[:rows], load[:rows, :, None])[:, :, 0]  # the loads live on k = 0, 1
    X_lin[0] = X_lin[0].real
    s_lin = X_lin @ A.T + xo @ E.T
    s_lin[0] += s0
    return CondensedOperators(
        omega_rad_s=w,
        harmonics=H,
        saddle_stiffness_N_per_m=np.asarray(k, dtype=float),
        receptance_harmonics=np.ascontiguousarray(-(A @ Y)),
        linear_compression_m=complex_to_real_harmonics(s_lin),
        linear_cargo_displacement=X_lin,
        cargo_influence=Y,
        ignored_harmonics=False,
    )


def _extended_operators(parts: CradleLinearParts, ops: CondensedOperators, harmonics: int) -> CondensedOperators:
    """``ops`` extended to ``harmonics``: the receptances of the new harmonics solved, the rest kept."""
    A = parts.engagement_matrix
    if A.shape[0] != ops.saddle_count:
        raise ValueError(f"reuse: operators of {ops.saddle_count} elements; the included set has {A.shape[0]}")
    H, h0 = int(harmonics), ops.harmonics
    wk = ops.omega_rad_s * np.arange(h0 + 1, H + 1, dtype=np.float64)
    Y = parts.solve_stack(wk, np.broadcast_to(-A.T[None], (wk.size,) + A.T.shape).astype(complex))
    X_lin = np.zeros((H + 1, A.shape[1]), dtype=complex)
    X_lin[: h0 + 1] = ops.linear_cargo_displacement
    s_lin = np.zeros((2 * H + 1, A.shape[0]))
    s_lin[: 2 * h0 + 1] = ops.linear_compression_m
    return replace(
        ops,
        harmonics=H,
        receptance_harmonics=np.concatenate([ops.receptance_harmonics, -(A @ Y)]),
        linear_compression_m=s_lin,
        linear_cargo_displacement=X_lin,
        cargo_influence=np.concatenate([ops.cargo_influence, Y]),
    )
