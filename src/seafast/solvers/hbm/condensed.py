"""The condensed formulation: the HBM problem reduced exactly onto the saddle compressions.

Every saddle is kept *bilaterally* in the linear part (well conditioned, never a mechanism);
the nonlinearity is the correction force ``c = f(delta) - k_u delta`` that removes the tension
a bilateral spring would carry. Per harmonic the receptance ``G_k = B^T (K_d^cc(k omega))^-1 B``
(one banded factorisation per harmonic) condenses the problem onto the saddle compressions:
unknowns are their n_s (2H+1) harmonic coefficients (real layout of :mod:`seafast.fourier`) and
``R = delta - delta_lin + G DFT[c(IDFT delta)] = 0``, Jacobian
``I + G DFT diag(f'(delta) - k_u) IDFT``. Units: compressions [m], forces [N], receptances
[m/N]; compression positive when the saddle is compressed.

Cost at many harmonics. ``G`` is block diagonal per harmonic: it is kept as the complex
``G_k`` (H+1, n_s, n_s) and applied harmonic by harmonic; the dense real receptance
(``n_u^2`` entries, n_u = (2H+1) n_s) is built only when a dense Jacobian is asked for. The
Newton step uses that ``f'(delta) - k_u`` vanishes wherever a saddle is in contact (exactly,
for the exact law; to round-off for the smooth laws away from their kink): with S the samples
where it does not, ``J = I + G F_S W_S P_S`` and the Woodbury identity solves ``J x = r`` through
``|S|`` unknowns (the detached samples) instead of n_u. Its matrix ``I + W_S P_S G F_S`` needs no
arithmetic: ``P G F`` is circulant in time (``G`` commutes with time shifts), so its entries are
the sample-space kernel ``kappa_st(t_n - t_m)`` (one inverse FFT of ``G_k`` per saddle pair),
gathered.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np
from numpy.typing import NDArray

from seafast.excitation.harmonic import HarmonicExcitation
from seafast.fourier import (
    complex_to_real_harmonics,
    periodic_impulse_response,
    real_dft_matrices,
    real_harmonics_to_time,
    real_to_complex_harmonics,
    time_to_real_harmonics,
)
from seafast.model.structure import StructuralModel
from seafast.solvers.contact import ContactLaw
from seafast.solvers.dynamic_stiffness import quadratic_matrices, saddle_selection, solve_dynamic_stack
from seafast.solvers.exact_contact import solve_exact_contact
from seafast.solvers.newton import DenseJacobian

__all__ = ["CondensedOperators", "condensed_operators", "CondensedProblem", "DetachedSampleJacobian"]


@dataclass(frozen=True)
class CondensedOperators:
    """The linear problem condensed onto the saddle compressions, harmonics 0 .. H.

    Attributes
    ----------
    omega_rad_s, harmonics
        Fundamental frequency [rad/s] and H.
    saddle_stiffness_N_per_m
        k_u, the compression-only stiffness of each saddle [N/m], shape (n_s,).
    receptance_harmonics
        ``G_k = B^T K_d^cc(k w)^-1 B`` [m/N], complex, shape (H+1, n_s, n_s): the compression change
        at saddle t is ``-G_k[t, s] C_k[s]`` for upward cargo force harmonics C at saddle s.
    linear_compression_m
        Saddle compression of the linear (bilateral) model, real layout (2H+1, n_s), split
        into its static row and the dynamic rows (for amplitude continuation).
    linear_cargo_displacement
        Linear cargo harmonics (H+1, n_c) complex [m, rad].
    cargo_influence
        ``(K_d^cc(k w))^-1 B``, shape (H+1, n_c, n_s) complex [m/N]: cargo response to unit
        upward saddle forces per harmonic.
    ignored_harmonics
        Whether the excitation had nonzero harmonics above H (they are dropped).
    """

    omega_rad_s: float
    harmonics: int
    saddle_stiffness_N_per_m: NDArray[np.float64]
    receptance_harmonics: NDArray[np.complex128]
    linear_compression_m: NDArray[np.float64]
    linear_cargo_displacement: NDArray[np.complex128]
    cargo_influence: NDArray[np.complex128]
    ignored_harmonics: bool

    @property
    def saddle_count(self) -> int:
        return int(self.saddle_stiffness_N_per_m.size)

    @property
    def compression_scale_m(self) -> float:
        """Residual normalisation: the largest linear compression coefficient (>= 1 um)."""
        return float(max(np.max(np.abs(self.linear_compression_m)), 1e-6))

    @cached_property
    def receptance(self) -> NDArray[np.float64]:
        """Real block-diagonal receptance [m/N], (n_u, n_u), n_u = (2H+1) n_s, ordering
        ``row * n_s + saddle`` in the real harmonic layout (built on first use: O(n_u^2) memory)."""
        G = self.receptance_harmonics
        H, n_s = self.harmonics, self.saddle_count
        n_u = (2 * H + 1) * n_s
        Greal = np.zeros((n_u, n_u))
        Greal[:n_s, :n_s] = G[0].real
        for k in range(1, H + 1):
            a = slice((2 * k - 1) * n_s, 2 * k * n_s)
            b = slice(2 * k * n_s, (2 * k + 1) * n_s)
            Gr, Gi = G[k].real, G[k].imag
            Greal[a, a] = Gr
            Greal[a, b] = Gi
            Greal[b, a] = -Gi
            Greal[b, b] = Gr
        return Greal

    @property
    def static_receptance(self) -> NDArray[np.float64]:
        """``G_0`` [m/N], (n_s, n_s)."""
        return np.ascontiguousarray(self.receptance_harmonics[0].real)

    def apply_receptance(self, forces: NDArray) -> NDArray[np.float64]:
        """``G C`` for upward saddle-force harmonics C in the real layout (2H+1, n_s) [N] -> [m]."""
        Cc = real_to_complex_harmonics(forces)
        return complex_to_real_harmonics(np.einsum("kts,ks->kt", self.receptance_harmonics, Cc))

    def time_kernel(self, time_samples: int) -> NDArray[np.float64]:
        """``kappa[tau, t, s]``: compression change at saddle t, ``tau`` samples after a unit correction force
        sample at saddle s, through harmonics 0 .. H (circulant: ``IDFT G DFT``), (N, n_s, n_s) [m/N]."""
        return periodic_impulse_response(self.receptance_harmonics, int(time_samples))

    def linear_compression_at(self, amplitude_scale: float) -> NDArray[np.float64]:
        """Linear compression with the dynamic harmonics scaled by ``amplitude_scale``."""
        if amplitude_scale == 1.0:
            return self.linear_compression_m
        out = self.linear_compression_m * amplitude_scale
        out[0] = self.linear_compression_m[0]
        return out


def condensed_operators(
    model: StructuralModel, excitation: HarmonicExcitation, harmonics: int, *, reuse: CondensedOperators | None = None
) -> CondensedOperators:
    """Receptances and linear solution per harmonic (saddles bilateral), k = 0 .. H.

    The static load of the model (gravity, pretension) is added at k = 0. ``reuse``: operators of the same
    model and excitation at fewer (or as many) harmonics, whose harmonics are kept and only the new ones
    solved (the adaptive harmonic balance raises H this way).
    """
    H = int(harmonics)
    q = quadratic_matrices(model, True)
    n_c, n_s = model.cargo_dof_count, model.saddle_count
    sad_c = model.saddle_cargo_dof
    sad_o = model.saddle_deck_dof
    n_k = excitation.harmonic_count
    ignored = bool(n_k > H + 1 and (np.any(excitation.deck_displacement[H + 1 :]) or np.any(excitation.cargo_load_N[H + 1 :])))
    w = float(excitation.omega_rad_s)
    if reuse is not None and (reuse.omega_rad_s != w or reuse.saddle_count != n_s or reuse.harmonics > H):
        reuse = None
    if reuse is not None and reuse.harmonics == H:
        return reuse  # nothing to add (the operators are immutable)
    k0 = 0 if reuse is None else reuse.harmonics + 1  # first harmonic to solve
    B = saddle_selection(model)
    xo = np.zeros((H + 1, model.deck_dof_count), dtype=complex)
    f = np.zeros((H + 1, n_c), dtype=complex)
    m = min(n_k, H + 1)
    xo[:m] = excitation.deck_displacement[:m]
    f[:m] = excitation.cargo_load_N[:m]
    f[0] = (f[0] + model.static_load_N).real
    xo[0] = xo[0].real
    wk = w * np.arange(H + 1)
    Y = np.empty((H + 1, n_c, n_s), dtype=complex)
    X_lin = np.zeros((H + 1, n_c), dtype=complex)
    if reuse is not None:
        Y[:k0] = reuse.cargo_influence
        X_lin[:k0] = reuse.linear_cargo_displacement
    if k0 <= H:
        # the deck motion and the loads live on the excitation's few harmonics: the coupling term only there
        km = wk[:m, None, None]
        coupling = q.coupling_stiffness[None] - km**2 * q.coupling_mass[None] + 1j * km * q.coupling_damping[None]
        load = f[:m] - np.einsum("kco,ko->kc", coupling, xo[:m])
        rhs = np.zeros((H + 1 - k0, n_c, n_s + 1), dtype=complex)
        rhs[:, :, :n_s] = B
        if m > k0:
            rhs[: m - k0, :, n_s] = load[k0:]
        sol = solve_dynamic_stack(q, wk[k0:], rhs)  # (H+1-k0, n_c, n_s+1)
        Y[k0:] = sol[:, :, :n_s]
        X_lin[k0:] = sol[:, :, n_s]
    X_lin[0] = X_lin[0].real
    delta_lin = xo[:, sad_o] - X_lin[:, sad_c]
    G = np.ascontiguousarray(Y[:, sad_c, :])  # (H+1, n_s, n_s) complex receptance
    return CondensedOperators(
        omega_rad_s=w,
        harmonics=H,
        saddle_stiffness_N_per_m=np.asarray(model.saddle_unilateral_stiffness_N_per_m, dtype=float),
        receptance_harmonics=G,
        linear_compression_m=complex_to_real_harmonics(delta_lin),
        linear_cargo_displacement=X_lin,
        cargo_influence=Y,
        ignored_harmonics=ignored,
    )


def _static_contact_compressions(delta_lin: NDArray, receptance: NDArray, stiffness: NDArray) -> NDArray:
    """Exact static contact ``delta = delta_lin - G_0 k max(-delta, 0)`` at every sample (n_t, n_s).

    Samples whose linear compressions are all positive keep contact (``delta = delta_lin``);
    the others go through the exact active-set solver of :mod:`seafast.solvers.exact_contact`.
    """
    delta = np.array(delta_lin, dtype=float)
    rows = np.nonzero(np.any(delta < 0.0, axis=1))[0]
    if rows.size:
        delta[rows] = solve_exact_contact(delta[rows], receptance, stiffness)[0]
    return delta


class CondensedProblem:
    """R(u) = u - u_lin + G vec(DFT[c(IDFT u)]), u the saddle-compression coefficients."""

    def __init__(self, ops: CondensedOperators, time_samples: int):
        self.ops = ops
        self.n_s = ops.saddle_count
        self.n_h = 2 * ops.harmonics + 1
        self.size = self.n_h * self.n_s
        self.time_samples = int(time_samples)
        self.inverse, self.forward = real_dft_matrices(ops.harmonics, time_samples)
        self.k_u = ops.saddle_stiffness_N_per_m
        self.scale = ops.compression_scale_m

    @cached_property
    def kernel(self) -> NDArray[np.float64]:
        """The sample-space receptance kernel (N, n_s, n_s) [m/N] (:meth:`CondensedOperators.time_kernel`)."""
        return self.ops.time_kernel(self.time_samples)

    @property
    def compression_scale_m(self) -> float:
        """The largest linear compression coefficient [m] (>= 1 um)."""
        return self.ops.compression_scale_m

    def to_samples(self, U: NDArray) -> NDArray[np.float64]:
        """Samples (N, n_s) of real-layout coefficients (2H+1, n_s): ``inverse @ U`` by an inverse real FFT."""
        return real_harmonics_to_time(U, self.time_samples)

    def to_harmonics(self, samples: NDArray) -> NDArray[np.float64]:
        """Real-layout coefficients (2H+1, n_s) of samples (N, n_s): ``forward @ samples`` by a real FFT."""
        return time_to_real_harmonics(samples, self.ops.harmonics)

    def initial_guess(self, amplitude: float) -> NDArray:
        return self.ops.linear_compression_at(amplitude).ravel().copy()

    def predictor_compression(self, amplitude: float) -> NDArray:
        """Saddle compressions (N, n_s) of the quasi-static exact-contact predictor.

        Each sample of the linear (bilateral) compression is corrected by the exact static
        contact problem with the static receptance ``G_0``: exact when the excitation is
        quasi-static (wave frequencies far below the cargo's first mode), and a start inside
        the semi-smooth Newton's basin of attraction otherwise.
        """
        d_lin = self.inverse @ self.ops.linear_compression_at(amplitude)
        return _static_contact_compressions(d_lin, self.ops.static_receptance, self.k_u)

    def predictor(self, amplitude: float) -> NDArray:
        """Harmonics of :meth:`predictor_compression` (the linear solution when contact is kept)."""
        d_lin = self.inverse @ self.ops.linear_compression_at(amplitude)
        if not np.any(d_lin < 0.0):
            return self.initial_guess(amplitude)
        return (self.forward @ self.predictor_compression(amplitude)).ravel()

    def evaluate(self, u: NDArray, law: ContactLaw, amplitude: float) -> tuple[NDArray, NDArray]:
        U = u.reshape(self.n_h, self.n_s)
        delta = self.to_samples(U)
        f, fp = law.force_and_derivative(delta, self.k_u)
        correction = f - self.k_u * delta
        C = self.to_harmonics(correction)
        R = u - self.ops.linear_compression_at(amplitude).ravel() + self.ops.apply_receptance(C).ravel()
        return R, fp

    def jacobian(self, fp: NDArray) -> NDArray:
        """The dense Jacobian (n_u, n_u) (for Powell's method and Levenberg-Marquardt steps)."""
        w = fp - self.k_u  # (N, n_s)
        PW = self.forward[None, :, :] * w.T[:, None, :]  # (n_s, n_h, N)
        T = PW @ self.inverse  # (n_s, n_h, n_h): d C[i, s] / d U[j, s]
        # G . dC/dU harmonic by harmonic (G is block diagonal per harmonic): column (j, s) of the product is
        # G applied to the force harmonics T[s, :, j] at saddle s, i.e. G_k[:, s] times their complex amplitudes
        Tc = real_to_complex_harmonics(T.transpose(1, 0, 2))  # (H+1, n_s source, n_h column j)
        GT = np.einsum("kts,ksj->ktsj", self.ops.receptance_harmonics, Tc)  # (H+1, n_s target, n_s source, n_h)
        J = complex_to_real_harmonics(GT).transpose(0, 1, 3, 2).reshape(self.size, self.size)
        J[np.diag_indices_from(J)] += 1.0
        return J

    def factorise(self, fp: NDArray) -> DetachedSampleJacobian | DenseJacobian:
        w = fp - self.k_u
        # |w| below round-off of k_u: the sample is in contact (the smooth laws' tails)
        support = np.abs(w) > 1e-13 * np.maximum(self.k_u, 1e-300)
        if np.count_nonzero(support) >= self.size:
            return DenseJacobian(self.jacobian(fp))
        return DetachedSampleJacobian(self, fp, np.where(support, w, 0.0))


class DetachedSampleJacobian:
    """The condensed Jacobian ``I + G F W P`` solved through its detached samples (Woodbury).

    ``W = diag(f' - k_u)`` is nonzero only on the samples S where a saddle is detached (or on the
    kink of a smooth law): ``J^-1 r = r - G F_S (I + W_S P_S G F_S)^-1 W_S P_S r`` with ``P_S`` the
    inverse DFT at S and ``F_S`` the forward DFT from S; ``P_S G F_S`` is the circulant time
    kernel gathered at the sample pairs. Gradients and Levenberg-Marquardt steps use the dense
    Jacobian, built on first need.
    """

    def __init__(self, problem: CondensedProblem, fp: NDArray, w: NDArray):
        self.problem = problem
        self.fp = fp
        n, s = np.nonzero(w)
        self.samples, self.saddles = n, s
        self.weights = w[n, s]
        if n.size:
            lag = (n[:, None] - n[None, :]) % problem.time_samples
            A = problem.kernel[lag, s[:, None], s[None, :]] * self.weights[None, :]
            A[np.diag_indices_from(A)] += 1.0
            self.small = A
        self._dense: DenseJacobian | None = None

    def solve(self, rhs: NDArray) -> NDArray | None:
        p = self.problem
        if self.samples.size == 0:
            return rhs.copy()
        r = rhs.reshape(p.n_h, p.n_s)
        r_at_samples = np.einsum("ih,ih->i", p.inverse[self.samples], r[:, self.saddles].T)
        try:
            z = np.linalg.solve(self.small, r_at_samples)
        except np.linalg.LinAlgError:
            return None
        v = np.zeros((p.time_samples, p.n_s))
        v[self.samples, self.saddles] = self.weights * z
        x = (r - p.ops.apply_receptance(p.to_harmonics(v))).ravel()
        return x if np.all(np.isfinite(x)) else None

    def dense(self) -> DenseJacobian:
        if self._dense is None:
            self._dense = DenseJacobian(self.problem.jacobian(self.fp))
        return self._dense

    def gradient(self, R: NDArray) -> NDArray:
        return self.dense().gradient(R)

    def levenberg_marquardt(self, R: NDArray, mu: float) -> NDArray | None:
        return self.dense().levenberg_marquardt(R, mu)
