"""Two-way hull-cargo coupling: the deck under the sea-fastening iterated until hull and cargo agree.

:func:`couple_deck` solves ``V = n C (P(V) - Q)`` for the change ``V`` of the deck DOFs under the
sea-fastening, two-way minus one-way, harmonic by harmonic (the loads and the hull's compliance
``C``: :mod:`seafast.coupling.deck_loads`): a quasi-Newton (Broyden) iteration in a real packing
of the harmonics, started from the exact Jacobian of the linear model
(:func:`linear_coupling_jacobians`). Convergence is judged on the coupling's own residual,
relative to the deck-motion scale (:data:`COUPLING_RELATIVE_TOLERANCE`), and reported as a
:class:`~seafast.coupling.status.CouplingStatus`. The hull girder along the whole ship under
the coupled cargo is :mod:`seafast.coupling.hull`. Theory and checks: ``docs/coupling.md``.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from seafast.coupling.deck_loads import CargoResponse, HullCompliance, spread_load_N
from seafast.coupling.status import CouplingOutcome, CouplingStatus
from seafast.excitation.harmonic import HarmonicExcitation
from seafast.model.structure import StructuralModel

__all__ = [
    "COUPLING_RELATIVE_TOLERANCE",
    "DeckCoupling",
    "linear_coupling_jacobian",
    "linear_coupling_jacobians",
    "couple_deck",
]


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
    response: CargoResponse
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
        solve: Callable[[HarmonicExcitation], CargoResponse],
        deck_forces: Callable[[HarmonicExcitation, CargoResponse], NDArray],
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
        self.response: CargoResponse | None = None
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
    solve: Callable[[HarmonicExcitation], CargoResponse],
    deck_forces: Callable[[HarmonicExcitation, CargoResponse], NDArray],
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
        :func:`~seafast.coupling.deck_loads.hull_compliance` at the model's sea-fastening points.
    solve
        ``excitation -> response`` of the cargo (the model being coupled).
    deck_forces
        ``(excitation, response) -> P`` (K, n_s), e.g. :func:`~seafast.coupling.deck_loads.deck_forces_N`.
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
    assert residual.response is not None  # the residual was evaluated at least once
    return DeckCoupling(coupled, residual.response, V, np.asarray(residual.deck_force), Q, status)
