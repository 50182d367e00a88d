"""The full formulation (as the source): all cargo DOFs are unknowns.

The linear part is taken without the compression-only saddle springs, the contact force comes
from AFT on the saddle DOFs, with an analytic Jacobian. The linear part is block diagonal per
harmonic and banded, coupled only through the saddle DOFs: the Jacobian is assembled sparse on
a fixed pattern and factorised by a sparse LU (SuperLU) once per Newton iteration. Roughly 15x
slower than the condensed formulation (a dense LU per iteration, as the source, costs
seconds); kept as a check and for fidelity to the source. Units: displacements [m, rad],
loads [N, N m].
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray
from scipy import sparse

from seafast.excitation.harmonic import HarmonicExcitation
from seafast.fourier import complex_to_real_harmonics, real_dft_matrices, real_to_complex_harmonics
from seafast.model.structure import StructuralModel
from seafast.solvers.contact import ContactLaw
from seafast.solvers.hbm.condensed import CondensedOperators, CondensedProblem
from seafast.solvers.hbm.nonlinear import SparseJacobian

__all__ = ["FullProblem"]


class FullProblem:
    """R(q) = L q - F - B DFT[f(delta(IDFT q))], q all cargo-DOF coefficients.

    The unknowns are the corrections ``u = q - q_lin`` to the linear (bilateral-saddle)
    response, so ``R = L u + r_lin - B DFT[f]`` with ``r_lin = L q_lin - F`` evaluated once in
    extended precision. In absolute coordinates the round-off of ``L q`` (stiffness terms up to
    ~1e13 N/m times the rigid-body part of q, ~0.1 m) is ~1e-10 of the load scale -- as large
    as the tolerance -- so the residual could not be driven below it; the corrections are
    small, and the shifted residual is accurate to ~1e-14.

    ``L`` (the linear part without the compression-only saddle springs) is block diagonal per
    harmonic, each block banded; the contact couples the harmonics of the saddle DOFs only. It
    is kept sparse: the Jacobian ``L + E T E^T`` (E the saddle-DOF selection, T the AFT block
    of each saddle) is assembled on a fixed sparsity pattern and factorised by a sparse LU
    (SuperLU) once per Newton iteration.
    """

    def __init__(self, model: StructuralModel, excitation: HarmonicExcitation, H: int, N: int, ops: CondensedOperators):
        self.ops = ops
        self.n_c = model.cargo_dof_count
        self.n_s = model.saddle_count
        self.n_h = 2 * H + 1
        self.size = self.n_h * self.n_c
        self.sad = model.saddle_cargo_dof
        self.inverse, self.forward = real_dft_matrices(H, N)
        self.k_u = np.asarray(model.saddle_unilateral_stiffness_N_per_m, dtype=float)
        ex = excitation.padded(H + 1)
        n_c = self.n_c
        rows: list[NDArray] = []
        cols: list[NDArray] = []
        vals: list[NDArray] = []

        def put(A: NDArray, r0: int, c0: int) -> None:
            i, j = np.nonzero(A)
            rows.append(i + r0)
            cols.append(j + c0)
            vals.append(A[i, j])

        F = np.zeros((H + 1, n_c), dtype=complex)
        for k in range(H + 1):
            Kd_cc, Kd_co, _, _ = model.dynamic_stiffness(k * ex.omega_rad_s, False)
            F[k] = ex.cargo_load_N[k] + (model.static_load_N if k == 0 else 0.0) - Kd_co @ ex.deck_displacement[k]
            if k == 0:
                put(np.real(Kd_cc), 0, 0)
            else:
                a, b = (2 * k - 1) * n_c, 2 * k * n_c
                Kr, Ki = np.real(Kd_cc), np.imag(Kd_cc)
                put(Kr, a, a)
                put(Ki, a, b)
                put(-Ki, b, a)
                put(Kr, b, b)
        self.index = np.arange(self.n_h)[None, :] * n_c + self.sad[:, None]  # (n_s, n_h)
        L_rows, L_cols, L_vals = np.concatenate(rows), np.concatenate(cols), np.concatenate(vals)
        self.L = sparse.csr_matrix((L_vals, (L_rows, L_cols)), shape=(self.size, self.size))
        # fixed pattern of L + E T E^T; T's entries are scattered into it per iteration
        T_rows = np.broadcast_to(self.index[:, :, None], (self.n_s, self.n_h, self.n_h)).ravel()
        T_cols = np.broadcast_to(self.index[:, None, :], (self.n_s, self.n_h, self.n_h)).ravel()
        all_rows = np.concatenate([L_rows, T_rows])
        all_cols = np.concatenate([L_cols, T_cols])
        pattern = sparse.csc_matrix((np.arange(1, all_rows.size + 1, dtype=float), (all_rows, all_cols)), shape=(self.size, self.size))
        pattern.sum_duplicates()
        pattern.sort_indices()
        # position of every (row, col) entry in the CSC data array
        key = pattern.indices.astype(np.int64) + self.size * np.repeat(np.arange(self.size, dtype=np.int64), np.diff(pattern.indptr))
        pos = np.searchsorted(key, all_rows.astype(np.int64) + self.size * all_cols.astype(np.int64))
        self._pattern_indices, self._pattern_indptr = pattern.indices, pattern.indptr
        self._base = np.zeros(pattern.data.size)
        np.add.at(self._base, pos[: L_rows.size], L_vals)
        self._T_pos = pos[L_rows.size :]
        self.F = complex_to_real_harmonics(F)
        self.deck_z = complex_to_real_harmonics(ex.deck_displacement[:, model.saddle_deck_dof])
        self.q_lin = complex_to_real_harmonics(ops.linear_cargo_displacement)
        # residual and saddle compressions of the linear response (extended-precision L q_lin)
        x = np.longdouble
        r_lin = np.zeros(self.size, dtype=x)
        np.add.at(r_lin, L_rows, L_vals.astype(x) * self.q_lin.ravel().astype(x)[L_cols])
        self.r_lin = (r_lin - self.F.ravel().astype(x)).astype(float).reshape(self.n_h, self.n_c)
        self.delta_lin = self.deck_z - self.q_lin[:, self.sad]
        force_lin = self.k_u * np.abs(ops.linear_compression_m)
        self.scale = float(max(np.max(np.abs(self.F)), np.max(force_lin), 1.0))

    @property
    def compression_scale_m(self) -> float:
        """The largest linear saddle compression coefficient [m] (>= 1 um)."""
        return self.ops.compression_scale_m

    def _at(self, A: NDArray, amplitude: float) -> NDArray:
        if amplitude == 1.0:
            return A
        out = A * amplitude
        out[0] = A[0]
        return out

    def initial_guess(self, amplitude: float) -> NDArray:
        """The linear response: zero correction (at any amplitude, the linear part scales)."""
        return np.zeros(self.size)

    def cargo_displacement(self, u: NDArray, amplitude: float = 1.0) -> NDArray:
        """Real harmonics (2H+1, n_c) of the cargo DOFs for the correction ``u``."""
        return self._at(self.q_lin, amplitude) + u.reshape(self.n_h, self.n_c)

    def predictor(self, amplitude: float) -> NDArray:
        """The condensed quasi-static exact-contact predictor mapped to every cargo DOF."""
        d_lin = self.inverse @ self.ops.linear_compression_at(amplitude)
        if not np.any(d_lin < 0.0):
            return self.initial_guess(amplitude)
        return self.from_compression(CondensedProblem(self.ops, self.inverse.shape[0]).predictor_compression(amplitude))

    def from_compression(self, compression_m: NDArray) -> NDArray:
        """The unknowns (cargo-DOF corrections) of the exact-law response with these saddle compressions (N, n_s) [m]."""
        C = real_to_complex_harmonics(self.forward @ (self.k_u * np.maximum(-np.asarray(compression_m), 0.0)))
        return complex_to_real_harmonics(np.einsum("kcs,ks->kc", self.ops.cargo_influence, C)).ravel()

    def evaluate(self, u: NDArray, law: ContactLaw, amplitude: float) -> tuple[NDArray, NDArray]:
        Q = u.reshape(self.n_h, self.n_c)
        delta = self.inverse @ (self._at(self.delta_lin, amplitude) - Q[:, self.sad])
        f, fp = law.force_and_derivative(delta, self.k_u)
        Fc = self.forward @ f  # (n_h, n_s)
        R = (self.L @ u).reshape(self.n_h, self.n_c) + self._at(self.r_lin, amplitude)
        R[:, self.sad] -= Fc
        return R.ravel(), fp

    def sparse_jacobian(self, fp: NDArray) -> sparse.csc_matrix:
        PW = self.forward[None, :, :] * fp.T[:, None, :]
        T = PW @ self.inverse  # (n_s, n_h, n_h)
        data = self._base.copy()
        np.add.at(data, self._T_pos, T.ravel())
        return sparse.csc_matrix((data, self._pattern_indices, self._pattern_indptr), shape=(self.size, self.size))

    def jacobian(self, fp: NDArray) -> NDArray:
        return self.sparse_jacobian(fp).toarray()

    def factorise(self, fp: NDArray) -> SparseJacobian:
        return SparseJacobian(self.sparse_jacobian(fp))
