"""The uncoupled blocks of the 3-D cargo's linear part on its cradles (``K_lin``, M, D), banded and dense.

Without lashings (the only elements coupling a node's five DOFs) the axial, lateral and vertical motions are
uncoupled even with the pads bilateral (:class:`~seafast.solvers.cradle_dynamics.CradleLinearParts`): the solves per
harmonic and the modes are found per block. A block is a connected component of the matrices' coupling pattern
(:func:`coupling_pattern`: an entry below ``1e-14 sqrt(|X_ii X_jj|)`` is the round-off of terms that cancel, e.g. a pad
pair's lateral-vertical stiffness, not a coupling), its DOFs taken in the node-by-node order, where it is banded.

The beam's elements join neighbouring nodes and every engagement acts at one node, so in the node-by-node order every
entry lies within ``2 * 5 - 1 = 9`` of the diagonal: :func:`node_band` gathers those entries once per dynamics
(checking that no other is non-zero) and :func:`band_blocks` finds the blocks from them alone, the same blocks, bands
and dense blocks as the scan of the dense matrices (:func:`pattern_blocks`, kept for matrices without that band).

Units: stiffness [N/m, N, N m/rad], mass [kg, kg m, kg m^2], damping [N s/m, ...]. Nothing here prints or writes files.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray
from scipy import sparse
from scipy.sparse.csgraph import connected_components

from seafast.solvers.banded import to_band
from seafast.solvers.dynamic_stiffness import QuadraticMatrices

__all__ = ["CradleBlocks", "NodeBand", "band_blocks", "coupling_pattern", "node_band", "pattern_blocks"]

ROUND_OFF = 1e-14
"""An entry at most this share of ``sqrt(|X_ii X_jj|)`` is no coupling (:func:`coupling_pattern`)."""


@dataclass(frozen=True)
class CradleBlocks:
    """The uncoupled blocks: each one's DOFs (node by node) and banded ``K_lin``, M, D (:attr:`banded`), and the same
    blocks dense (``K_b``, ``M_b``, ``D_b``, each (n_b, n_b), :attr:`dense`) [SI]."""

    banded: tuple[tuple[NDArray[np.intp], QuadraticMatrices], ...]
    dense: tuple[tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]], ...]


@dataclass(frozen=True)
class NodeBand:
    """The entries of ``K0``, M and D within the node-by-node band (every other entry zero).

    Attributes
    ----------
    rows, cols
        Each entry's DOFs (the cargo's block order), (n_e,).
    diagonal
        The entry of each DOF's diagonal, (5 n,).
    stiffness, mass, damping
        ``K0`` (the beam and the bilateral springs), M and ``D = alpha M + beta K_beam`` at the entries (n_e,) [SI].
    """

    rows: NDArray[np.intp]
    cols: NDArray[np.intp]
    diagonal: NDArray[np.intp]
    stiffness: NDArray[np.float64]
    mass: NDArray[np.float64]
    damping: NDArray[np.float64]

    def engagement_stiffness(self, A: NDArray[np.float64], k: NDArray[np.float64]) -> NDArray[np.float64]:
        """``A^T k A`` at the entries (n_e,) [SI]: formed on the DOFs the engagements touch alone."""
        touched = np.flatnonzero(np.any(A != 0.0, axis=0))
        at = np.full(self.diagonal.size, -1)
        at[touched] = np.arange(touched.size)
        A_t = A[:, touched]
        G = A_t.T @ (k[:, None] * A_t)
        r, c = at[self.rows], at[self.cols]
        both = (r >= 0) & (c >= 0)
        out = np.zeros(self.rows.size)
        out[both] = G[r[both], c[both]]
        return out


def node_band(
    order: NDArray[np.intp],
    beam: tuple[NDArray[np.float64], NDArray[np.float64]],
    springs_N_per_m: NDArray[np.float64] | None,
    rayleigh: tuple[float, float],
    engagement_matrix: NDArray[np.float64],
    half_bandwidth: int,
) -> NodeBand | None:
    """The entries of ``K0 = K_beam + diag(springs)``, M and ``D = alpha M + beta K_beam`` within ``half_bandwidth`` of
    the diagonal in the node-by-node ``order`` (``q[order]`` node by node); None where the beam ``(K_beam, M)`` has a
    non-zero entry outside it or an engagement acts on DOFs further apart (:func:`pattern_blocks` then)."""
    K_beam, M = beam
    n = order.size
    offsets = np.arange(-half_bandwidth, half_bandwidth + 1)
    i = np.repeat(np.arange(n), offsets.size)
    j = i + np.tile(offsets, n)
    inside = (j >= 0) & (j < n)
    rows, cols = order[i[inside]], order[j[inside]]
    flat = rows * n + cols
    K_e, M_e = K_beam.ravel()[flat], M.ravel()[flat]
    if np.count_nonzero(K_e) != np.count_nonzero(K_beam) or np.count_nonzero(M_e) != np.count_nonzero(M):
        return None
    where = np.empty(n, dtype=np.intp)
    where[order] = np.arange(n)
    for row in np.asarray(engagement_matrix):
        at = where[np.flatnonzero(row)]
        if at.size and int(np.ptp(at)) > half_bandwidth:
            return None
    diagonal = np.empty(n, dtype=np.intp)
    on = rows == cols
    diagonal[rows[on]] = np.flatnonzero(on)
    K0 = K_e.copy()
    if springs_N_per_m is not None:
        K0[diagonal] = K0[diagonal] + np.asarray(springs_N_per_m, dtype=float)
    alpha, beta = rayleigh
    return NodeBand(rows, cols, diagonal, K0, M_e, alpha * M_e + beta * K_e)


def band_blocks(band: NodeBand, stiffness: NDArray[np.float64], order: NDArray[np.intp]) -> CradleBlocks:
    """The uncoupled blocks of ``K_lin`` (its entries ``stiffness`` on ``band``'s), M and D from the band's entries:
    the same as :func:`pattern_blocks` of the dense matrices."""
    values = (stiffness, band.mass, band.damping)
    coupled = band.rows == band.cols
    for X in values:
        d = np.sqrt(np.abs(X[band.diagonal]))
        coupled |= np.abs(X) > ROUND_OFF * (d[band.rows] * d[band.cols])
    r, c = band.rows[coupled], band.cols[coupled]
    n = order.size
    graph = sparse.csr_matrix((np.ones(r.size, dtype=np.int8), (r, c)), shape=(n, n))
    count, label = connected_components(graph, directed=False)
    rank = np.empty(n, dtype=np.intp)
    members = [order[label[order] == b] for b in range(count)]
    for dofs in members:
        rank[dofs] = np.arange(dofs.size)
    widths = np.zeros(count, dtype=np.intp)
    np.maximum.at(widths, label[r], np.abs(rank[r] - rank[c]))
    same = label[band.rows] == label[band.cols]
    banded, dense = [], []
    for b, dofs in enumerate(members):
        mine = np.flatnonzero(same & (label[band.rows] == b))
        i, j = rank[band.rows[mine]], rank[band.cols[mine]]
        bw = int(widths[b])
        near = np.abs(i - j) <= bw
        blocks, bands = [], []
        for X in values:
            full = np.zeros((dofs.size, dofs.size))
            full[i, j] = X[mine]
            ab = np.zeros((2 * bw + 1, dofs.size))
            ab[bw + i[near] - j[near], j[near]] = X[mine][near]
            blocks.append(full)
            bands.append(ab)
        empty = np.zeros((dofs.size, 0))
        banded.append((dofs, QuadraticMatrices(empty, empty, empty, bw, bands[0], bands[1], bands[2])))
        dense.append((blocks[0], blocks[1], blocks[2]))
    return CradleBlocks(tuple(banded), tuple(dense))


def pattern_blocks(K: NDArray[np.float64], M: NDArray[np.float64], D: NDArray[np.float64], order: NDArray[np.intp]) -> CradleBlocks:
    """The uncoupled blocks of the dense ``K``, ``M``, ``D`` (any pattern): the connected components of their
    :func:`coupling_pattern`, each in the node-by-node ``order``."""
    pattern = coupling_pattern(K) | coupling_pattern(M) | coupling_pattern(D)
    count, label = connected_components(sparse.csr_matrix(pattern.astype(np.int8)), directed=False)
    banded, dense = [], []
    for c in range(count):
        dofs = order[label[order] == c]
        rows, cols = np.nonzero(pattern[np.ix_(dofs, dofs)])
        bw = int(np.max(np.abs(rows - cols), initial=0))
        K_c, M_c, D_c = (np.ascontiguousarray(X[np.ix_(dofs, dofs)]) for X in (K, M, D))
        empty = np.zeros((dofs.size, 0))
        banded.append((dofs, QuadraticMatrices(empty, empty, empty, bw, to_band(K_c, bw), to_band(M_c, bw), to_band(D_c, bw))))
        dense.append((K_c, M_c, D_c))
    return CradleBlocks(tuple(banded), tuple(dense))


def coupling_pattern(X: NDArray[np.float64], round_off: float = ROUND_OFF) -> NDArray[np.bool_]:
    """Where the symmetric matrix ``X`` couples two DOFs: ``|X_ij| > round_off sqrt(|X_ii X_jj|)`` (the diagonal
    always); an entry below it is the round-off of terms that cancel (a pad pair's lateral-vertical stiffness)."""
    d = np.sqrt(np.abs(np.diag(X)))
    pattern = np.abs(X) > round_off * np.outer(d, d)
    pattern[np.diag_indices_from(pattern)] = True
    return pattern
