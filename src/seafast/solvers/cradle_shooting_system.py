"""The cradle's correction system for the exact-event shooting (:mod:`seafast.solvers.cradle_shooting`).

The modes of the cargo with the included elements bilateral (:func:`cradle_modes`, per uncoupled block), the
correction system reduced on them with the static residual flexibility of the others
(:func:`cradle_correction_system`, the vertical plane's :class:`~seafast.solvers.modal_correction.ModalCorrectionSystem`
with the engagements for the saddles: ``B = -A_I^T``), the first-harmonic sampling of the linear part, and the cargo's
displacements and every element's engagement reassembled from a flow's samples (:func:`reassembled`).

Units: engagements [m]; forces [N]; displacements [m, rad]; time [s]. Nothing here prints, reads or writes files.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from seafast.excitation.cradle_loads import CradleExcitation
from seafast.solvers.cradle_dynamics import CradleDynamics
from seafast.solvers.hbm.condensed import CondensedOperators
from seafast.solvers.modal_correction import ModalCorrectionSystem

__all__ = [
    "CradleModes",
    "all_engagements",
    "cradle_correction_system",
    "cradle_modes",
    "deck_time_m",
    "engagements_of",
    "first_harmonic_basis",
    "first_harmonic_rows",
    "first_harmonic_time",
    "kept_modes",
    "reassembled",
    "reference_frequency_rad_s",
    "subharmonic_harmonics",
]


@dataclass(frozen=True)
class CradleModes:
    """Every undamped mode of the cargo with the elements ``included`` bilateral (deck fixed), mass-normalised, kept per
    uncoupled block (a mode lives in one block) and assembled on the cargo's DOFs only for the modes asked for.

    Attributes
    ----------
    natural_frequency_rad_s
        (n,) ascending [rad/s].
    block, column
        (n,) each mode's block and its column in that block's eigenvectors.
    blocks
        Each block's DOFs (cargo block order) and eigenvectors (n_b, n_b) [m or rad per unit modal coordinate].
    damping
        Each block's ``D`` (n_b, n_b) [N s/m, ...] (``D`` has no entry between blocks): the modal damping of the modes
        kept is ``Phi^T D Phi`` (:meth:`modal_damping`, formed for those alone).
    engagement_modes
        ``A Phi`` (m, n): how each mode moves each element's engagement [m per unit modal coordinate].
    """

    natural_frequency_rad_s: NDArray[np.float64]
    block: NDArray[np.intp]
    column: NDArray[np.intp]
    blocks: tuple[tuple[NDArray[np.intp], NDArray[np.float64]], ...]
    damping: tuple[NDArray[np.float64], ...]
    engagement_modes: NDArray[np.float64]

    def mode_shape(self, count: int) -> NDArray[np.float64]:
        """The lowest ``count`` modes on every cargo DOF (5 n, count)."""
        phi = np.zeros((sum(dofs.size for dofs, _ in self.blocks), int(count)))
        for b, (dofs, vectors) in enumerate(self.blocks):
            mine = np.flatnonzero(self.block[:count] == b)
            phi[dofs[:, None], mine[None, :]] = vectors[:, self.column[mine]]
        return phi

    def modal_damping(self, count: int) -> NDArray[np.float64]:
        """``Phi^T D Phi`` of the lowest ``count`` modes (count, count) [N s/m per unit modal coordinate], block by block."""
        out = np.zeros((int(count), int(count)))
        for b, (_, vectors) in enumerate(self.blocks):
            mine = np.flatnonzero(self.block[:count] == b)
            phi = vectors[:, self.column[mine]]
            out[np.ix_(mine, mine)] = phi.T @ (self.damping[b] @ phi)
        return out


def cradle_modes(dynamics: CradleDynamics, included: NDArray[np.bool_]) -> CradleModes:
    """The modes of ``(K_I, M)``, solved per uncoupled block (:attr:`CradleLinearParts.blocks`) and merged.

    Without lashings the axial, lateral and vertical motions are uncoupled: three dense eigensolves of a third of the
    DOFs each, a ninth of the work of one. The eigensolves are kept with the dynamics' linear parts of ``included``
    (:attr:`~seafast.solvers.cradle_dynamics.CradleLinearParts.block_modes`): solved once per set of elements.
    """
    parts = dynamics.linear_parts(included)
    A = parts.engagement_matrix
    frequencies, blocks, labels, columns, moved = [], [], [], [], []
    for b, ((dofs, _), (w2, phi)) in enumerate(zip(parts.blocks, parts.block_modes, strict=True)):
        frequencies.append(np.sqrt(np.maximum(w2, 0.0)))
        blocks.append((dofs, phi))
        labels.append(np.full(w2.size, b))
        columns.append(np.arange(w2.size))
        moved.append(A[:, dofs] @ phi)
    w = np.concatenate(frequencies)
    order = np.argsort(w, kind="stable")
    damping = tuple(D for _, _, D in parts.block_parts.dense)
    return CradleModes(
        w[order], np.concatenate(labels)[order], np.concatenate(columns)[order], tuple(blocks), damping, np.hstack(moved)[:, order]
    )


def kept_modes(modes: CradleModes, cutoff_rad_s: float, minimum: int) -> int:
    """How many modes a reduction at ``cutoff_rad_s`` keeps: those at or below it, at least ``minimum``."""
    w = modes.natural_frequency_rad_s
    return max(int(np.searchsorted(w, float(cutoff_rad_s), side="right")), min(int(minimum), w.size))


def cradle_correction_system(
    dynamics: CradleDynamics, ops: CondensedOperators, included: NDArray[np.bool_], modes: CradleModes, cutoff_rad_s: float
) -> ModalCorrectionSystem:
    """The cradle's correction system on the modes up to ``cutoff_rad_s`` (at least one per element), the rest static.

    ``ops``: the condensed operators of ``included`` (their ``cargo_influence`` at k = 0 is ``K_I^-1 (-A_I^T)``, the
    static response to unit corrections). The rows of ``saddle_mode_shape`` are the engagements (see the module
    docstring); ``saddle_dof`` is empty (an engagement is no single DOF).
    """
    A = dynamics.problem.engagement_matrix[included]
    w = modes.natural_frequency_rad_s
    m = kept_modes(modes, cutoff_rad_s, A.shape[0])
    complete = m == w.size
    phi, w = modes.mode_shape(m), w[:m]
    engagement_modes = -(A @ phi)  # Phi_s = B^T Phi with B = -A^T
    static = np.asarray(ops.cargo_influence[0].real, dtype=float)  # K_I^-1 B
    residual = np.zeros_like(static) if complete else static - phi @ (engagement_modes.T / w[:, None] ** 2)
    residual_s = -(A @ residual)  # B^T (K^-1 - Phi Omega^-2 Phi^T) B
    flexibility = -(A @ static)
    return ModalCorrectionSystem(
        natural_frequency_rad_s=np.ascontiguousarray(w),
        modal_damping=modes.modal_damping(m),
        mode_shape=np.ascontiguousarray(phi),
        saddle_mode_shape=np.ascontiguousarray(engagement_modes),
        residual_displacement_m_per_N=np.ascontiguousarray(residual),
        residual_flexibility_m_per_N=np.ascontiguousarray(0.5 * (residual_s + residual_s.T)),
        static_flexibility_m_per_N=0.5 * (flexibility + flexibility.T),
        unilateral_stiffness_N_per_m=np.asarray(ops.saddle_stiffness_N_per_m, dtype=float).copy(),
        saddle_dof=np.zeros(0, dtype=np.intp),
        cutoff_rad_s=float(cutoff_rad_s),
        complete=bool(complete),
    )


def reference_frequency_rad_s(modes: CradleModes, engagement_modes: NDArray[np.float64], count: int) -> float:
    """The highest of the ``count`` lowest modes the elements drive (a mode no engagement moves, e.g. the axial
    one on a cargo without lashings, is not one) [rad/s]."""
    driven = modes.natural_frequency_rad_s[np.any(np.abs(engagement_modes) > 1e-9 * np.max(np.abs(engagement_modes)), axis=0)]
    return float(driven[min(max(int(count), 1), driven.size) - 1])


def first_harmonic_time(harmonics: NDArray[np.complex128], samples: int, multiple: int = 1) -> NDArray[np.float64]:
    """``Re(X_0) + Re(X_1 e^{i w t_n})`` at ``t_n = n P T / N`` (N, n) from the harmonics k = 0, 1 (2, n), over
    ``multiple`` (P) wave periods: what :func:`~seafast.fourier.harmonics_to_time` gives for two harmonics, as one
    real product (no transform of N points per column)."""
    return first_harmonic_basis(int(samples), multiple) @ first_harmonic_rows(harmonics)


def first_harmonic_basis(samples: int, multiple: int = 1) -> NDArray[np.float64]:
    """``[1, cos(w t_n), -sin(w t_n)]`` (N, 3) at ``t_n = n P T / N`` (P = ``multiple`` wave periods)."""
    angle = 2.0 * np.pi * int(multiple) * np.arange(samples) / samples
    return np.column_stack([np.ones(samples), np.cos(angle), -np.sin(angle)])


def first_harmonic_rows(harmonics: NDArray[np.complex128]) -> NDArray[np.float64]:
    """``[Re X_0; Re X_1; Im X_1]`` (3, n), the coefficients of :func:`first_harmonic_basis`."""
    X = np.asarray(harmonics, dtype=complex)
    return np.vstack([X[0].real, X[1].real, X[1].imag])


def deck_time_m(excitation: CradleExcitation, samples: int, multiple: int = 1) -> NDArray[np.float64]:
    """The deck DOFs over ``multiple`` wave periods (N, n_o) [m, rad]."""
    return first_harmonic_time(np.asarray(excitation.deck_displacement, dtype=complex), samples, multiple)


def all_engagements(
    dynamics: CradleDynamics,
    excitation: CradleExcitation,
    q: NDArray[np.float64],
    included: NDArray[np.bool_],
    s_included: NDArray,
    multiple: int = 1,
) -> NDArray[np.float64]:
    """Every element's engagement (N, m): the included ones as solved, the others from the cargo's and the deck's motion
    (the samples over ``multiple`` wave periods)."""
    return engagements_of(dynamics, excitation, q @ dynamics.problem.engagement_matrix.T, included, s_included, multiple)


def engagements_of(
    dynamics: CradleDynamics,
    excitation: CradleExcitation,
    cargo_engagement_m: NDArray[np.float64],
    included: NDArray[np.bool_],
    s_included: NDArray,
    multiple: int = 1,
) -> NDArray[np.float64]:
    """Every element's engagement ``s0 + A q + E x_o`` (N, m) from the cargo's part ``A q`` (N, m) [m]: the included
    ones replaced by ``s_included`` as solved (the samples over ``multiple`` wave periods)."""
    s = dynamics.initial_engagement_m + cargo_engagement_m
    s += deck_time_m(excitation, cargo_engagement_m.shape[0], multiple) @ dynamics.deck_engagement.T
    s[:, included] = s_included
    return s


def reassembled(
    dynamics: CradleDynamics,
    excitation: CradleExcitation,
    included: NDArray[np.bool_],
    ops: CondensedOperators,
    system: ModalCorrectionSystem,
    state_samples: NDArray[np.float64],
    contact: tuple[NDArray[np.float64], NDArray[np.float64]],
    multiple: int = 1,
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Every element's engagement (N, m) and the cargo DOFs (N, 5 n) from a flow's states at the samples (N, 2 m_modes)
    and the included elements' compressions and corrections ``contact`` (each (N, m_I)): ``q = q_lin + Phi eta + R_q c``,
    as one product of the samples' columns and their shapes, and the engagements ``s0 + A q + E x_o`` (those left out)
    from the columns and the shapes' engagements ``A shapes``. The samples span ``multiple`` wave periods."""
    N = state_samples.shape[0]
    columns = np.hstack([first_harmonic_basis(N, multiple), state_samples[:, : system.mode_count], contact[1]])
    shapes = np.vstack([first_harmonic_rows(ops.linear_cargo_displacement), system.mode_shape.T, system.residual_displacement_m_per_N.T])
    cargo_engagement = columns @ (shapes @ dynamics.problem.engagement_matrix.T)
    return engagements_of(dynamics, excitation, cargo_engagement, included, contact[0], multiple), columns @ shapes


def subharmonic_harmonics(harmonics: NDArray[np.complex128], multiple: int) -> NDArray[np.complex128]:
    """The harmonics k = 0, 1 of the wave (2, n) as those of a period ``multiple`` (P) times the wave's
    (P + 1, n): the wave's first harmonic placed at P, the others zero. At the base frequency ``w / P`` they are the
    same function of time: ``Re sum_j X'_j e^{i j (w / P) t} = Re(X_0) + Re(X_1 e^{i w t})``."""
    X = np.asarray(harmonics, dtype=complex)
    P = int(multiple)
    out = np.zeros((P + 1, X.shape[1]), dtype=complex)
    out[0], out[P] = X[0], X[1]
    return out
