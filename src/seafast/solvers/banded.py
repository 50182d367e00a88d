"""Batched banded solves of the dynamic stiffness ``K - w^2 M + i w D`` at many frequencies.

The cargo's matrices are banded (two DOFs per node, a handful of diagonals). A harmonic balance with H
harmonics needs ``K_d(k w)^-1`` applied to a few right-hand sides for k = 0 .. H: as many small banded
systems. LAPACK's banded LU (``gbsv``) makes several BLAS calls per column, whose call overhead dominates
for a bandwidth of 3 (about 20 ms for 160 harmonics of a 154-DOF cargo, against 2 MFLOP of arithmetic).
This module compiles the same algorithm (LU with partial pivoting inside the band, LAPACK's ``gbtf2``
layout) with numba, one frequency after the other, which costs the arithmetic alone.

Band storage as LAPACK's general band without the fill rows: ``band[bw + i - j, j] = A[i, j]`` for
``|i - j| <= bw``, shape ``(2 bw + 1, n)`` (what :func:`to_band` returns).
"""

from __future__ import annotations

import numpy as np
from numba import njit
from numpy.typing import NDArray

__all__ = ["to_band", "solve_dynamic_band_stack"]


def to_band(A: NDArray, bandwidth: int) -> NDArray:
    """The band of a square matrix with ``bandwidth`` sub- and super-diagonals, shape ``(2 bw + 1, n)``."""
    n = A.shape[0]
    ab = np.zeros((2 * bandwidth + 1, n), dtype=A.dtype)
    for offset in range(-bandwidth, bandwidth + 1):
        d = np.diagonal(A, offset)
        if offset >= 0:
            ab[bandwidth - offset, offset:] = d
        else:
            ab[bandwidth - offset, : n + offset] = d
    return ab


def solve_dynamic_band_stack(
    stiffness_band: NDArray[np.float64],
    mass_band: NDArray[np.float64],
    damping_band: NDArray[np.float64],
    omega_rad_s: NDArray[np.float64],
    rhs: NDArray,
) -> NDArray[np.complex128]:
    """Solve ``(K - w_k^2 M + i w_k D) x_k = rhs_k`` for every k.

    Parameters
    ----------
    stiffness_band, mass_band, damping_band
        Bands of K, M, D (same bandwidth), shape ``(2 bw + 1, n)``.
    omega_rad_s
        Frequencies ``w_k`` [rad/s], shape (n_k,).
    rhs
        Right-hand sides, shape (n_k, n, n_rhs).

    Returns
    -------
    x, shape (n_k, n, n_rhs), complex.

    Raises
    ------
    numpy.linalg.LinAlgError
        If a matrix is singular (an exactly zero pivot).
    """
    K = np.ascontiguousarray(stiffness_band, dtype=float)
    M = np.ascontiguousarray(mass_band, dtype=float)
    D = np.ascontiguousarray(damping_band, dtype=float)
    w = np.ascontiguousarray(omega_rad_s, dtype=float)
    b = np.ascontiguousarray(rhs, dtype=np.complex128)
    if K.shape != M.shape or K.shape != D.shape or K.shape[0] % 2 != 1:
        raise ValueError(f"bands of K, M, D must share one shape (2 bw + 1, n); got {K.shape}, {M.shape}, {D.shape}")
    if b.ndim != 3 or b.shape[0] != w.size or b.shape[1] != K.shape[1]:
        raise ValueError(f"rhs: shape {b.shape}; must be ({w.size}, {K.shape[1]}, n_rhs)")
    x, singular = _solve_stack(K, M, D, w, b)
    if singular >= 0:
        raise np.linalg.LinAlgError(f"the dynamic stiffness at {w[singular]:.6g} rad/s is singular")
    return x


@njit(cache=True)
def _solve_stack(K: NDArray, M: NDArray, D: NDArray, w: NDArray, rhs: NDArray) -> tuple[NDArray, int]:
    n_k, n, n_rhs = rhs.shape
    bw = (K.shape[0] - 1) // 2
    kl = bw
    ku = bw
    kv = kl + ku
    width = 2 * kl + ku + 1
    x = rhs.copy()
    # column-major band: ab[j, kv + i - j] = A[i, j] (walking down a column is contiguous)
    ab = np.zeros((n, width), dtype=np.complex128)
    piv = np.zeros(n, dtype=np.int64)
    for k in range(n_k):
        wk = w[k]
        w2 = wk * wk
        for j in range(n):
            for r in range(kl):
                ab[j, r] = 0.0
            for r in range(2 * bw + 1):
                ab[j, kl + r] = complex(K[r, j] - w2 * M[r, j], wk * D[r, j])
        # LU with partial pivoting (LAPACK gbtf2)
        ju = 0
        for j in range(n):
            km = min(kl, n - 1 - j)
            jp = 0
            best = abs(ab[j, kv])
            for t in range(1, km + 1):
                v = abs(ab[j, kv + t])
                if v > best:
                    best = v
                    jp = t
            piv[j] = j + jp
            if best == 0.0:
                return x, k
            ju = max(ju, min(j + ku + jp, n - 1))
            if jp != 0:
                for c in range(j, ju + 1):
                    r1 = kv + j - c
                    tmp = ab[c, r1]
                    ab[c, r1] = ab[c, r1 + jp]
                    ab[c, r1 + jp] = tmp
            inv_pivot = 1.0 / ab[j, kv]
            for t in range(1, km + 1):
                ab[j, kv + t] *= inv_pivot
            for c in range(j + 1, ju + 1):
                base = kv + j - c
                a_jc = ab[c, base]
                if a_jc != 0.0:
                    for t in range(1, km + 1):
                        ab[c, base + t] -= ab[j, kv + t] * a_jc
        # forward and back substitution for every right-hand side
        for m in range(n_rhs):
            for j in range(n):
                p = piv[j]
                if p != j:
                    tmp = x[k, j, m]
                    x[k, j, m] = x[k, p, m]
                    x[k, p, m] = tmp
                km = min(kl, n - 1 - j)
                bj = x[k, j, m]
                if bj != 0.0:
                    for t in range(1, km + 1):
                        x[k, j + t, m] -= ab[j, kv + t] * bj
            for i in range(n - 1, -1, -1):
                s = x[k, i, m]
                for c in range(i + 1, min(n - 1, i + kv) + 1):
                    s -= ab[c, kv + i - c] * x[k, c, m]
                x[k, i, m] = s / ab[i, kv]
    return x, -1
