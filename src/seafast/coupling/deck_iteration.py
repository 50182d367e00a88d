"""Two-way hull-cargo coupling: the cargo's deck forces load the hull girder.

With one-way coupling (the source's assumption) the hull girder carries the cargo as a load
spread over its length (its weight in still water; nothing at wave frequency, since the
quasi-static hull balance has no inertia), and the cargo only follows the deck. With four
monopiles abreast, the cargo's bending stiffness is comparable to the hull's, and its loads reach
the deck at the sea-fastening points only, in proportions the hull's own bending decides.
``two_way`` exchanges, on the hull, the cargo's spread load for the forces it actually exerts at
the sea-fastening points, harmonic by harmonic, and iterates the deck to consistency:

    Z_k = Z_k(one way) + n C (P_k - Q_k),    k = 0 .. K-1

where ``Z_k`` are the deck DOFs under the sea-fastening (deflection z [m] and slope theta [rad]
at each saddle) of harmonic k, ``n`` the number of identical units abreast, ``P_k`` [N] the
downward force one unit exerts on the deck at each sea-fastening point (saddle contact force,
lashing spring force, minus the pretension's reaction, which pulls the deck up), ``Q_k`` [N]
the same unit's spread load as the one-way model sees it, lumped on the cargo nodes (its weight
at k = 0; at k >= 1 its rigid-body inertia load, so that the exchange is self-equilibrated and
the quasi-static hull, which balances no inertia, is not asked to), and ``C`` the hull's
compliance: deck deflection and slope per newton of downward load, ``Q`` spread over each
cargo node's tributary length and ``P`` over a patch of the same length centred on its
sea-fastening point (so that its resultant acts at the saddle), the ship re-balanced in
sinkage and trim.

The hull girder is quasi-static and linear while no section emerges, so ``C`` is exact and
serves every harmonic. The moments of the rotational lashing springs (a few kN m) are not
applied to the hull. Convergence is judged on the coupling's own residual, relative to the
deck-motion scale (:data:`COUPLING_RELATIVE_TOLERANCE`), and reported as a
:class:`~seafast.coupling.status.CouplingStatus`. The hull girder along the whole
ship under the coupled cargo is :mod:`seafast.coupling.hull`. Theory and checks:
``docs/coupling.md``.

Size: about 550 lines, the compliance, the exchanged loads, the linear Jacobians and the
quasi-Newton iteration that uses them; they change together.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from seafast.coupling.status import CouplingOutcome, CouplingStatus
from seafast.excitation.harmonic import HarmonicExcitation
from seafast.fourier import harmonics_to_time
from seafast.hull.girder import HullGirder
from seafast.hull.loads import deck_load_influence
from seafast.model.structure import StructuralModel
from seafast.vessel.loading import VesselLoading

__all__ = [
    "COUPLING_RELATIVE_TOLERANCE",
    "CouplingOutcome",
    "CouplingStatus",
    "HullCompliance",
    "DeckCoupling",
    "hull_compliance",
    "deck_forces_N",
    "spread_load_N",
    "linear_coupling_jacobian",
    "linear_coupling_jacobians",
    "couple_deck",
]


@dataclass(frozen=True)
class HullCompliance:
    """The hull girder's compliance at the sea-fastening points, for loads on patches of deck.

    Two kinds of patch: each cargo node's tributary length (where the one-way spread load ``Q``
    acts, so that the patches tile the cargo and a uniform load stays uniform), then one patch
    per sea-fastening point centred on it, of its node's tributary length (where the deck force
    ``P`` acts, so that its resultant sits at the saddle, as a point load's would).

    Attributes
    ----------
    node_x_ship_m
        Ship x of the cargo nodes, from the AP [m], shape (n_nodes,).
    saddle_node
        Cargo node of each sea-fastening point, shape (n_s,).
    patch_start_m, patch_end_m
        Ship x of the patch ends [m], shape (n_nodes + n_s,): the nodes' tributary lengths,
        then the patches centred on the sea-fastening points.
    deflection_m_per_N, slope_rad_per_N
        Deck deflection [m] and slope [rad] at sea-fastening point i per newton of downward load
        spread over patch j (the ship re-balanced), shape (n_s, n_nodes + n_s).
    units_abreast
        Identical cargo units side by side, each on its own saddles at the same x.
    """

    node_x_ship_m: NDArray[np.float64]
    saddle_node: NDArray[np.intp]
    patch_start_m: NDArray[np.float64]
    patch_end_m: NDArray[np.float64]
    deflection_m_per_N: NDArray[np.float64]
    slope_rad_per_N: NDArray[np.float64]
    units_abreast: int

    @property
    def saddle_deflection_m_per_N(self) -> NDArray[np.float64]:
        """Deck deflection at point i per newton of deck force at point j [m/N], (n_s, n_s)."""
        return self.deflection_m_per_N[:, self.node_x_ship_m.size :]

    @property
    def saddle_slope_rad_per_N(self) -> NDArray[np.float64]:
        """Deck slope at point i per newton of deck force at point j [rad/N], (n_s, n_s)."""
        return self.slope_rad_per_N[:, self.node_x_ship_m.size :]

    def patch_loads_N(self, deck_force_N: NDArray, spread_load_N: NDArray) -> NDArray:
        """What two-way coupling adds to the one-way hull loading, per unit, on the patches [N].

        ``-Q_k`` on the nodes' patches and ``P_k`` on the sea-fastening points' patches
        (downward +), shape (K, n_nodes + n_s).

        Parameters
        ----------
        deck_force_N
            ``P_k``: downward force of one unit on the deck at each point [N], (K, n_s).
        spread_load_N
            ``Q_k``: the unit's spread load on its nodes, downward [N], (K, n_nodes).
        """
        Q = np.asarray(spread_load_N)
        P = np.asarray(deck_force_N)
        return np.concatenate([-Q, P], axis=-1).astype(np.result_type(Q, P, float), copy=False)

    def deck_change(self, deck_force_N: NDArray, spread_load_N: NDArray) -> NDArray:
        """Deck DOFs (z, theta interleaved per point) of two-way minus one-way, per harmonic.

        Parameters
        ----------
        deck_force_N
            ``P_k``: downward force of one unit on the deck at each point [N], (K, n_s).
        spread_load_N
            ``Q_k``: the unit's spread load on its nodes, downward [N], (K, n_nodes).
        """
        net = self.patch_loads_N(deck_force_N, spread_load_N)
        out = np.empty((net.shape[0], 2 * self.saddle_node.size), dtype=net.dtype)
        out[:, 0::2] = self.units_abreast * net @ self.deflection_m_per_N.T
        out[:, 1::2] = self.units_abreast * net @ self.slope_rad_per_N.T
        return out


def hull_compliance(
    girder: HullGirder, loading: VesselLoading, model: StructuralModel, cargo_aft_end_x_m: float, units_abreast: int
) -> HullCompliance:
    """:class:`HullCompliance` of ``girder`` under ``loading`` at the model's sea-fastening points.

    One vectorised set of still-water solves: a probe load on each patch.
    """
    xn = float(cargo_aft_end_x_m) + model.cargo.node_x_m
    edges = np.concatenate([[xn[0]], 0.5 * (xn[1:] + xn[:-1]), [xn[-1]]])
    sad = np.asarray(model.saddle_node)
    half = 0.5 * (edges[sad + 1] - edges[sad])
    start = np.concatenate([edges[:-1], xn[sad] - half])
    end = np.concatenate([edges[1:], xn[sad] + half])
    z, s = deck_load_influence(girder, loading, start, end, xn[sad])
    return HullCompliance(xn, sad, start, end, z, s, int(units_abreast))


def spread_load_N(model: StructuralModel, excitation: HarmonicExcitation, harmonic_count: int) -> NDArray[np.complex128]:
    """``Q_k``: one unit's load on the hull as the one-way model spreads it, on the cargo nodes [N].

    Downward positive, shape (K, n_nodes): at k = 0 the weight spread uniformly over the cargo's
    length, as the one-way hull loading carries it (also for a tapered pile), lumped on each
    node's tributary length; at k >= 1 the rigid-body inertia load of the excitation.
    """
    x = model.cargo.node_x_m
    edges = np.concatenate([[x[0]], 0.5 * (x[1:] + x[:-1]), [x[-1]]])
    Q = np.zeros((harmonic_count, model.cargo.node_count), dtype=complex)
    Q[0] = model.cargo.mass_kg * model.gravity_m_per_s2 * np.diff(edges) / (x[-1] - x[0])
    m = min(harmonic_count, excitation.harmonic_count)
    Q[1:m] = -excitation.cargo_load_N[1:m, 0::2]
    return Q


def deck_forces_N(
    model: StructuralModel, excitation: HarmonicExcitation, response: Any, nonlinear: bool, harmonic_count: int = 1
) -> NDArray:
    """``P_k``: downward force of one cargo unit on the deck at each sea-fastening point [N].

    Parameters
    ----------
    model, excitation
        The model and the excitation the response was solved for.
    response
        A :class:`~seafast.solvers.periodic.PeriodicResponse` (``nonlinear=True``: its saddle
        forces are the compression-only parts; sampled over the period) or a
        :class:`~seafast.solvers.linear.LinearResponse` (``nonlinear=False``: saddles
        bilateral in K; harmonics).
    harmonic_count
        K, harmonics k = 0 .. K-1 returned.

    Returns
    -------
    Complex amplitudes, shape (K, n_s); row 0 (the period mean) is real.
    """
    _, Kco, Koo = model.spring_matrices(include_saddles=not nonlinear)
    sad = model.saddle_deck_dof
    if nonlinear:  # every method has samples (the references have no harmonics)
        x_c = np.asarray(response.cargo_displacement_time_m, dtype=float)
        n_t = x_c.shape[0]
        x_o = harmonics_to_time(excitation.deck_displacement, n_t)
        p_t = (x_c @ Kco + x_o @ Koo)[:, sad] + np.asarray(response.saddle_force_time_N, dtype=float)
        c = np.fft.rfft(p_t, axis=0) / n_t
        P = np.zeros((harmonic_count, sad.size), dtype=complex)
        m = min(harmonic_count, c.shape[0])
        P[:m] = c[:m]
        P[1:m] *= 2.0
        P[0] = P[0].real
    else:
        X = np.asarray(response.cargo_displacement)
        Xo = excitation.deck_displacement
        m = min(harmonic_count, X.shape[0], Xo.shape[0])
        P = np.zeros((harmonic_count, sad.size), dtype=complex)
        P[:m] = (X[:m] @ Kco + Xo[:m] @ Koo)[:, sad]
    P[0] -= model.seafastening.saddle_pretension_N
    return P


COUPLING_RELATIVE_TOLERANCE = 1e-6
"""Default coupling tolerance, relative to the deck-motion scale (see :func:`couple_deck`).

The coupling residual cannot fall below the round-off of the cargo's deck forces, which is
relative to the displacements (tens of mm) and grows with the cargo's conditioning as the mesh
is refined (about 5e-10 m at ``model.element_length_m = 0.1`` on the base case, 3e-14 m at
1 m). 1e-6 of the base case's 74 mm is 74 nm: a saddle-force error of about 80 N on 5 MN."""


@dataclass(frozen=True)
class DeckCoupling:
    """Outcome of :func:`couple_deck`.

    Attributes
    ----------
    excitation
        The excitation with the coupled deck DOFs (harmonics 0 .. K-1 changed).
    response
        The cargo's response to it (whatever ``solve`` returns).
    deck_change
        Two-way minus one-way deck DOFs, (K, 2 n_s) complex (z [m], theta [rad] interleaved).
    deck_force_N
        ``P_k`` at the coupled state [N], (K, n_s).
    spread_load_N
        ``Q_k``, the unit's spread load the one-way hull carries [N], (K, n_nodes).
    status
        Convergence of the coupling (:class:`CouplingStatus`).
    """

    excitation: HarmonicExcitation
    response: Any
    deck_change: NDArray[np.complex128]
    deck_force_N: NDArray[np.complex128]
    spread_load_N: NDArray[np.complex128]
    status: CouplingStatus

    @property
    def converged(self) -> bool:
        """``status.converged``."""
        return self.status.converged

    @property
    def iterations(self) -> int:
        """``status.iterations``."""
        return self.status.iterations

    @property
    def residual_m(self) -> float:
        """``status.residual_m`` [m]."""
        return self.status.residual_m

    @property
    def message(self) -> str:
        """``status.message``."""
        return self.status.message


def _with_deck_change(excitation: HarmonicExcitation, change: NDArray, note: str) -> HarmonicExcitation:
    K = change.shape[0]
    ex = excitation if excitation.harmonic_count >= K else excitation.padded(K)
    deck = np.array(ex.deck_displacement, dtype=complex)
    deck[:K] += change
    deck[0] = deck[0].real
    source = f"{ex.source}; {note}" if note else ex.source
    return HarmonicExcitation(ex.omega_rad_s, deck, ex.cargo_load_N, ex.cargo_line_load_N_per_m, source)


def _pack(V: NDArray) -> NDArray[np.float64]:
    return np.concatenate([V[0].real, V[1:].real.ravel(), V[1:].imag.ravel()])


def _unpack(v: NDArray, K: int, n: int) -> NDArray[np.complex128]:
    V = np.zeros((K, n), dtype=complex)
    V[0] = v[:n]
    m = (K - 1) * n
    V[1:] = (v[n : n + m] + 1j * v[n + m :]).reshape(K - 1, n)
    return V


def linear_coupling_jacobians(
    model: StructuralModel, omega_rad_s: float, compliance: HullCompliance, harmonic_counts: Iterable[int]
) -> dict[int, NDArray]:
    """Exact Jacobians of the coupling residual for the linear (bilateral) model, real packing.

    Per harmonic the deck forces respond to the deck DOFs through the cargo's dynamic stiffness
    seen from the deck, ``S_k = K_oo - K_oc K_d^cc(k w)^-1 K_co`` (saddle rows), so the residual
    ``V - n C (P(V) - Q)`` has the Jacobian ``I - n C S_k`` per harmonic, split into real and
    imaginary parts in the packing of :func:`couple_deck`. One Jacobian per requested K
    (harmonics 0 .. K-1); each harmonic's block is computed once for all of them.
    """
    counts = sorted({int(k) for k in harmonic_counts})
    n_o = model.deck_dof_count
    sad = model.saddle_deck_dof
    C = np.empty((n_o, model.saddle_count))
    C[0::2] = compliance.saddle_deflection_m_per_N
    C[1::2] = compliance.saddle_slope_rad_per_N
    blocks = []
    for k in range(counts[-1]):
        Kd_cc, Kco, Koc, Koo = model.dynamic_stiffness(k * omega_rad_s, include_saddles=True)
        S = (Koo - Koc @ np.linalg.solve(Kd_cc, Kco))[sad, :]
        blocks.append(compliance.units_abreast * C @ S)
    out = {}
    for K in counts:
        size = n_o * (2 * K - 1)
        J = np.eye(size)
        J[:n_o, :n_o] -= np.real(blocks[0])
        m = (K - 1) * n_o
        for k in range(1, K):
            M = blocks[k]
            re = slice(n_o + (k - 1) * n_o, n_o + k * n_o)
            im = slice(n_o + m + (k - 1) * n_o, n_o + m + k * n_o)
            J[re, re] -= M.real
            J[re, im] += M.imag
            J[im, re] -= M.imag
            J[im, im] -= M.real
        out[K] = J
    return out


def linear_coupling_jacobian(model: StructuralModel, omega_rad_s: float, compliance: HullCompliance, harmonic_count: int) -> NDArray:
    """:func:`linear_coupling_jacobians` for one K (harmonics 0 .. K-1)."""
    return linear_coupling_jacobians(model, omega_rad_s, compliance, [harmonic_count])[int(harmonic_count)]


class _CouplingResidual:
    """``r(v) = v - pack(n C (P(unpack(v)) - Q))`` of the cargo model, keeping its last response and forces.

    ``v`` packs the deck change of harmonics 0 .. K-1 (:func:`_pack`); :meth:`size_m` measures a
    residual in metres (deflection entries as they are, slope entries times the lever arm, half
    the cargo's length).
    """

    def __init__(
        self,
        excitation: HarmonicExcitation,
        compliance: HullCompliance,
        solve: Callable[[HarmonicExcitation], object],
        deck_forces: Callable[[HarmonicExcitation, object], NDArray],
        spread_load: NDArray,
        harmonic_count: int,
        dof_count: int,
        lever_arm_m: float,
    ) -> None:
        self.excitation, self.compliance = excitation, compliance
        self.solve, self.deck_forces, self.spread_load = solve, deck_forces, spread_load
        self.harmonic_count, self.dof_count = harmonic_count, dof_count
        self.size = dof_count * (2 * harmonic_count - 1)
        self.weight = np.where(np.arange(self.size) % 2 == 0, 1.0, lever_arm_m)
        self.response: object = None
        self.deck_force: NDArray | None = None

    def __call__(self, v: NDArray) -> NDArray:
        exc = _with_deck_change(self.excitation, _unpack(v, self.harmonic_count, self.dof_count), "")
        self.response = self.solve(exc)
        self.deck_force = self.deck_forces(exc, self.response)
        return v - _pack(self.compliance.deck_change(self.deck_force, self.spread_load))

    def size_m(self, r: NDArray) -> float:
        """The residual's size [m]: its largest entry, slopes times the lever arm."""
        return float(np.max(np.abs(self.weight * r)))

    def jacobian(self, v: NDArray, r: NDArray) -> NDArray:
        """Forward-difference Jacobian at ``v`` (``r`` = the residual there) of the model itself."""
        step = 1e-7  # finite-difference step [m]: well inside the millimetre scale of the deck change
        J = np.empty((self.size, self.size))
        for j in range(self.size):
            dv = np.zeros(self.size)
            dv[j] = step
            J[:, j] = (self(v + dv) - r) / step
        return J


def _deck_motion_scale_m(model: StructuralModel, excitation: HarmonicExcitation, harmonic_count: int, lever_arm_m: float) -> float:
    """The largest one-way deck harmonic under the sea-fastening [m], slopes times the lever arm (at least 1 um)."""
    one_way = np.asarray(excitation.deck_displacement)[:harmonic_count]
    return max(
        float(np.max(np.abs(one_way[:, model.saddle_deck_dof]), initial=0.0)),
        lever_arm_m * float(np.max(np.abs(one_way[:, model.saddle_deck_dof + 1]), initial=0.0)),
        1e-6,
    )


@dataclass
class _Iterate:
    """The state of the quasi-Newton iteration: the packed deck change, its residual and the Jacobian."""

    v: NDArray
    r: NDArray
    J: NDArray
    residual_m: float
    iterations: int = 0
    stalled: bool = False


def _line_search(residual: _CouplingResidual, it: _Iterate) -> tuple[NDArray, NDArray, NDArray] | None:
    """The Newton step on ``it.J``, halved until the residual's norm falls (at most four times).

    Returns ``(step, v, r)``: the step taken, the new point and its residual; ``None`` when no
    step reduces the residual (or ``it.J`` is singular).
    """
    try:
        dv = -np.linalg.solve(it.J, it.r)
    except np.linalg.LinAlgError:
        return None
    alpha = 1.0
    while alpha >= 1.0 / 16.0:
        v_try = it.v + alpha * dv
        r_try = residual(v_try)
        if float(np.linalg.norm(r_try)) < (1.0 - 1e-4 * alpha) * float(np.linalg.norm(it.r)):
            return alpha * dv, v_try, r_try
        alpha *= 0.5
    return None


def _broyden(residual: _CouplingResidual, it: _Iterate, refreshed: bool, tolerance_m: float, max_iterations: int) -> _Iterate:
    """Iterate ``it`` until its residual is within ``tolerance_m`` [m], the limit, or a stall.

    Broyden's ("good") update after each accepted step; when a step fails to reduce the residual
    the model's own finite-difference Jacobian replaces the drifted matrix, once.
    """
    while it.residual_m > tolerance_m and it.iterations < max_iterations:
        it.iterations += 1
        step = _line_search(residual, it)
        if step is not None:
            s_v, v_try, r_try = step
            it.J += np.outer(r_try - it.r - it.J @ s_v, s_v) / float(s_v @ s_v)  # Broyden's ("good") update
            it.v, it.r = v_try, r_try
            it.residual_m = residual.size_m(it.r)
            refreshed = False
        elif not refreshed:
            # Broyden's matrix has drifted (contact switches): the model's own Jacobian, once
            it.J = residual.jacobian(it.v, it.r)
            refreshed = True
        else:
            it.stalled = True
            break
    return it


def _outcome(residual_m: float, tolerance_m: float, stalled: bool) -> CouplingOutcome:
    """How the iteration ended, from its final residual [m]."""
    if not np.isfinite(residual_m):
        return CouplingOutcome.NOT_FINITE
    if residual_m <= tolerance_m:
        return CouplingOutcome.CONVERGED
    return CouplingOutcome.STALLED if stalled else CouplingOutcome.ITERATION_LIMIT


def couple_deck(
    model: StructuralModel,
    excitation: HarmonicExcitation,
    compliance: HullCompliance,
    solve: Callable[[HarmonicExcitation], object],
    deck_forces: Callable[[HarmonicExcitation, object], NDArray],
    harmonic_count: int,
    *,
    jacobian0: NDArray | None = None,
    relative_tolerance: float = COUPLING_RELATIVE_TOLERANCE,
    max_iterations: int = 40,
    label: str = "",
) -> DeckCoupling:
    """Solve ``V = n C (P(V) - Q)`` for the deck change ``V`` (harmonics 0 .. K-1).

    A quasi-Newton (Broyden) iteration with backtracking, started from ``jacobian0`` (the exact
    Jacobian of the linear model, :func:`linear_coupling_jacobian`: the residual is affine
    there, so the linear model converges in one step); Broyden's updates carry it to the
    unilateral model's piecewise-affine residual, and when a step fails to reduce the residual
    the model's own finite-difference Jacobian replaces the drifted matrix.

    Parameters
    ----------
    model, excitation
        The cargo model and its one-way excitation.
    compliance
        :func:`hull_compliance` at the model's sea-fastening points.
    solve
        ``excitation -> response`` of the cargo (the model being coupled).
    deck_forces
        ``(excitation, response) -> P`` (K, n_s), e.g. :func:`deck_forces_N`.
    harmonic_count
        K: harmonics of the deck coupled (1 = the still-water state only).
    jacobian0
        The starting Jacobian, e.g. :func:`linear_coupling_jacobian` (default: finite
        differences of the model itself).
    relative_tolerance
        Convergence: the residual (the largest deck mismatch in metres, slopes times half the
        cargo length) at most this fraction of the deck-motion scale (the largest one-way deck
        harmonic under the sea-fastening, measured the same way). Relative, because the
        residual's floor, the round-off of the cargo's deck forces, is relative to the
        displacements and grows as the cargo mesh is refined.
    max_iterations
        Iteration limit.

    Returns
    -------
    DeckCoupling
        Never raises for non-convergence: ``status`` says how the iteration ended, with the
        coupling's own residual and tolerance.
    """
    K = int(harmonic_count)
    n_o = model.deck_dof_count
    Q = spread_load_N(model, excitation, K)
    x = model.cargo.node_x_m
    lever_arm_m = 0.5 * float(x[-1] - x[0])
    scale_m = _deck_motion_scale_m(model, excitation, K, lever_arm_m)
    tolerance_m = float(relative_tolerance) * scale_m
    residual = _CouplingResidual(excitation, compliance, solve, deck_forces, Q, K, n_o, lever_arm_m)
    v = np.zeros(residual.size)
    r = residual(v)
    J = residual.jacobian(v, r) if jacobian0 is None else np.array(jacobian0, dtype=float)
    it = _broyden(residual, _Iterate(v, r, J, residual.size_m(r)), jacobian0 is None, tolerance_m, max_iterations)
    residual(it.v)  # the response and forces at the final state
    V = _unpack(it.v, K, n_o)
    status = CouplingStatus(
        outcome=_outcome(it.residual_m, tolerance_m, it.stalled),
        iterations=it.iterations,
        residual_m=it.residual_m,
        tolerance_m=tolerance_m,
        deck_motion_scale_m=scale_m,
        relative_tolerance=float(relative_tolerance),
        lever_arm_m=lever_arm_m,
        harmonic_count=K,
        mean_deck_change_m=tuple(float(d) for d in V[0, 0::2].real),
        label=label,
    )
    coupled = _with_deck_change(excitation, V, "two-way coupled deck")
    return DeckCoupling(coupled, residual.response, V, np.asarray(residual.deck_force), Q, status)
