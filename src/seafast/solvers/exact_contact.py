"""Exact solutions of the piecewise-linear contact problems of the unilateral saddles.

Two active-set solvers with the exact law ``f = k max(delta, 0)`` (no regularisation), used by
the exact references and by the harmonic balance's quasi-static predictor:

:class:`ExactContact` / :func:`solve_exact_contact`
    The contact problem condensed on the saddles, ``delta = delta_lin - G c(delta)``,
    ``c = k max(-delta, 0)`` (the correction that cancels the tension a bilateral saddle would
    carry), at many instants at once. For a set S of detached saddles it is linear,
    ``(I - G diag(k 1_S)) delta = delta_lin``; the iteration tries the set of the current
    signs until they agree, with enumeration of every set as a fallback, so the answer is exact
    to round-off.
:class:`BandedActiveSet`
    The same on all cargo DOFs, ``(A0 + B diag(w_A) B^T) q = r + B (w_A z)`` with a banded
    symmetric A0 (one banded Cholesky per active set), for the time-domain reference's steps.

Units: compressions, gaps and displacements [m]; receptances [m/N]; stiffnesses [N/m]; forces
[N], positive pushing the cargo up. Compression ``delta = z_deck - z_cargo``, positive when
compressed.
"""

from __future__ import annotations

from itertools import product

import numpy as np
from numpy.typing import NDArray
from scipy.linalg.lapack import dpbtrf, dpbtrs

__all__ = ["ExactContact", "solve_exact_contact", "BandedActiveSet"]


class ExactContact:
    """Solve ``delta = delta_lin - G c(delta)``, ``c = k max(-delta, 0)``, exactly.

    For a set S of detached saddles the system is linear: ``(I - G diag(k 1_S)) delta =
    delta_lin``; its inverse is cached per set.
    """

    def __init__(self, receptance: NDArray, stiffness: NDArray):
        self.G = np.asarray(receptance, dtype=float)
        self.k = np.asarray(stiffness, dtype=float)
        self.n = self.k.size
        self._inverse: dict[bytes, NDArray] = {}
        self._bits = (1 << np.arange(self.n, dtype=np.int64)) if self.n < 63 else None

    def operator(self, detached: NDArray[np.bool_]) -> NDArray:
        """``(I - G diag(k 1_S))^-1`` for the detached set S (cached): delta = operator @ delta_lin."""
        key = np.asarray(detached, dtype=bool).tobytes()
        op = self._inverse.get(key)
        if op is None:
            A = np.eye(self.n) - self.G * (self.k * detached)[None, :]
            op = np.linalg.inv(A)
            self._inverse[key] = op
        return op

    @staticmethod
    def _consistent(delta: NDArray, detached: NDArray, tol: float) -> NDArray[np.bool_]:
        return np.all(np.where(detached, delta <= tol, delta >= -tol), axis=-1)

    def solve(self, delta_lin: NDArray, detached0: NDArray | None = None) -> tuple[NDArray, NDArray]:
        """Exact compressions (n_t, n_s) and detached sets for linear compressions (n_t, n_s)."""
        d_lin = np.atleast_2d(np.asarray(delta_lin, dtype=float))
        n_t = d_lin.shape[0]
        tol = 1e-12 * max(float(np.max(np.abs(d_lin))), 1e-9)
        detached = (d_lin < 0.0) if detached0 is None else np.array(np.broadcast_to(detached0, d_lin.shape), dtype=bool)
        delta = np.empty_like(d_lin)
        todo = np.arange(n_t)
        for _ in range(4 * self.n + 8):
            if todo.size == 0:
                break
            # group the instants by detached set: an integer code per set (bit s = saddle s)
            if self._bits is not None:
                codes = detached[todo] @ self._bits
            else:  # more saddles than bits in an int64: group by the rows themselves
                codes = np.unique(detached[todo], axis=0, return_inverse=True)[1].ravel()
            for code in np.unique(codes):
                rows = todo[codes == code]
                delta[rows] = d_lin[rows] @ self.operator(detached[rows[0]]).T
            ok = self._consistent(delta[todo], detached[todo], tol)
            bad = todo[~ok]
            detached[bad] = delta[bad] < 0.0
            todo = bad
        for i in todo:  # cycling (rare): enumerate every set, keep the consistent one
            best: tuple[NDArray, NDArray] | None = None
            best_violation = np.inf
            for bits in product((False, True), repeat=self.n):
                mask = np.array(bits)
                d = self.operator(mask) @ d_lin[i]
                violation = float(np.max(np.where(mask, d, -d), initial=0.0))
                if violation < best_violation:
                    best, best_violation = (d, mask), violation
                if violation <= tol:
                    break
            assert best is not None  # the first set tried has a finite violation
            delta[i], detached[i] = best
        return delta, detached


def solve_exact_contact(
    linear_compression_m: NDArray, receptance_m_per_N: NDArray, stiffness_N_per_m: NDArray
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Exact solution of the condensed static contact problem at many instants.

    Parameters
    ----------
    linear_compression_m
        Saddle compressions with every saddle bilateral, shape (n_t, n_s) [m].
    receptance_m_per_N
        ``G = B^T K^-1 B`` with saddles bilateral, (n_s, n_s) [m/N].
    stiffness_N_per_m
        Compression-only stiffness k_u per saddle (n_s,) [N/m].

    Returns
    -------
    compression_m, correction_N
        ``delta`` (n_t, n_s) and the correction force ``c = k_u max(-delta, 0)`` (upward on the
        cargo), with ``delta = delta_lin - G c``.
    """
    solver = ExactContact(receptance_m_per_N, stiffness_N_per_m)
    delta, _ = solver.solve(linear_compression_m)
    return delta, np.asarray(stiffness_N_per_m) * np.maximum(-delta, 0.0)


class BandedActiveSet:
    """Solve ``(A0 + B diag(w_A) B^T) q = r + B (w_A z)`` with ``delta = z - B^T q``, ``A = {delta > 0}``.

    ``A0`` is symmetric positive (semi-)definite and banded, the saddle springs ``w`` act on the
    DOFs ``dofs``. The piecewise-linear problem is solved exactly by a semi-smooth Newton
    (active-set) iteration from a trial set; it stops when the set repeats. One banded Cholesky
    factorisation (LAPACK dpbtrf) is cached per active set; a singular set (a mechanism) is
    skipped, and a cycling iteration falls back to enumerating every set.
    """

    def __init__(self, A0: NDArray, dofs: NDArray, weights: NDArray, tolerance_m: float):
        n = A0.shape[0]
        rows, cols = np.nonzero(A0)
        self.bw = bw = int(np.max(np.abs(rows - cols))) if rows.size else 0
        ab = np.zeros((bw + 1, n))
        for d in range(bw + 1):
            ab[bw - d, d:] = np.diagonal(A0, d)  # LAPACK upper band storage
        self.ab0 = ab
        self.dofs = np.asarray(dofs)
        self.w = np.asarray(weights, dtype=float)
        self.tol = float(tolerance_m)
        self.max_newton = 2 * self.w.size + 4
        self.factors: dict[bytes, NDArray | None] = {}
        self.solves = 0
        self.enumerations = 0

    def factor(self, active: NDArray[np.bool_]) -> NDArray | None:
        """Banded Cholesky factor of the matrix with the ``active`` springs (cached); None if singular."""
        key = active.tobytes()
        try:
            return self.factors[key]
        except KeyError:
            ab = self.ab0.copy()
            ab[self.bw, self.dofs] += self.w * active
            c, info = dpbtrf(ab, lower=0)
            fac = c if info == 0 else None
            self.factors[key] = fac
            return fac

    def _linear(self, fac: NDArray, rhs: NDArray, wz: NDArray, active: NDArray) -> NDArray:
        b = rhs.copy()
        b[self.dofs] += wz * active
        self.solves += 1
        return dpbtrs(fac, b, lower=0)[0]

    def solve(self, rhs: NDArray, z: NDArray, active: NDArray[np.bool_]) -> tuple[NDArray, NDArray, NDArray[np.bool_]]:
        """Exact ``q``, ``delta``, active set from the trial set ``active``."""
        wz = self.w * z
        for _ in range(self.max_newton):
            fac = self.factor(active)
            if fac is None:
                break
            q = self._linear(fac, rhs, wz, active)
            delta = z - q[self.dofs]
            new = delta > 0.0
            if new.tobytes() == active.tobytes() or np.all(np.where(active, delta >= -self.tol, delta <= self.tol)):
                return q, delta, active
            active = new
        return self._enumerate(rhs, z, wz)

    def _enumerate(self, rhs: NDArray, z: NDArray, wz: NDArray) -> tuple[NDArray, NDArray, NDArray[np.bool_]]:
        self.enumerations += 1
        best, best_violation = None, np.inf
        for bits in product((False, True), repeat=self.w.size):
            active = np.array(bits)
            fac = self.factor(active)
            if fac is None:
                continue
            q = self._linear(fac, rhs, wz, active)
            delta = z - q[self.dofs]
            violation = float(np.max(np.where(active, -delta, delta), initial=0.0))
            if violation < best_violation:
                best, best_violation = (q, delta, active), violation
            if violation <= self.tol:
                break
        if best is None:
            raise np.linalg.LinAlgError("every contact state is a mechanism (no saddle or lashing holds the cargo)")
        return best
