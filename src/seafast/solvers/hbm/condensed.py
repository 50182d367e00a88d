"""The condensed formulation: the HBM problem reduced exactly onto the saddle compressions.

Every saddle is kept *bilaterally* in the linear part (well conditioned, never a mechanism);
the nonlinearity is the correction force ``c = f(delta) - k_u delta`` that removes the tension
a bilateral spring would carry. Per harmonic the receptance ``G_k = B^T (K_d^cc(k omega))^-1 B``
(one banded factorisation per harmonic) condenses the problem onto the saddle compressions:
unknowns are their n_s (2H+1) harmonic coefficients (real layout of :mod:`seafast.fourier`) and
``R = delta - delta_lin + G DFT[c(IDFT delta)] = 0``, Jacobian
``I + G DFT diag(f'(delta) - k_u) IDFT``. Units: compressions [m], forces [N], receptances
[m/N]; compression positive when the saddle is compressed.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from seafast.excitation.harmonic import HarmonicExcitation
from seafast.fourier import complex_to_real_harmonics, real_dft_matrices
from seafast.model.structure import StructuralModel
from seafast.solvers.contact import ContactLaw
from seafast.solvers.dynamic_stiffness import quadratic_matrices, saddle_selection, solve_dynamic_stack
from seafast.solvers.exact_contact import solve_exact_contact
from seafast.solvers.hbm.nonlinear import DenseJacobian

__all__ = ["CondensedOperators", "condensed_operators", "CondensedProblem"]


@dataclass(frozen=True)
class CondensedOperators:
    """The linear problem condensed onto the saddle compressions, harmonics 0 .. H.

    Attributes
    ----------
    omega_rad_s, harmonics
        Fundamental frequency [rad/s] and H.
    saddle_stiffness_N_per_m
        k_u, the compression-only stiffness of each saddle [N/m], shape (n_s,).
    receptance
        Real block-diagonal receptance [m/N], shape (n_u, n_u), n_u = (2H+1) n_s, unknown
        ordering ``row * n_s + saddle`` in the real harmonic layout; ``-receptance @ C`` is the
        change in saddle compression caused by upward cargo forces C at the saddles.
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
    receptance: NDArray[np.float64]
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

    def linear_compression_at(self, amplitude_scale: float) -> NDArray[np.float64]:
        """Linear compression with the dynamic harmonics scaled by ``amplitude_scale``."""
        if amplitude_scale == 1.0:
            return self.linear_compression_m
        out = self.linear_compression_m * amplitude_scale
        out[0] = self.linear_compression_m[0]
        return out


def condensed_operators(model: StructuralModel, excitation: HarmonicExcitation, harmonics: int) -> CondensedOperators:
    """Receptances and linear solution per harmonic (saddles bilateral), k = 0 .. H.

    The static load of the model (gravity, pretension) is added at k = 0.
    """
    H = int(harmonics)
    q = quadratic_matrices(model, True)
    n_c, n_s = model.cargo_dof_count, model.saddle_count
    sad_c = model.saddle_cargo_dof
    sad_o = model.saddle_deck_dof
    n_k = excitation.harmonic_count
    ignored = bool(n_k > H + 1 and (np.any(excitation.deck_displacement[H + 1 :]) or np.any(excitation.cargo_load_N[H + 1 :])))
    w = float(excitation.omega_rad_s)
    B = saddle_selection(model)
    xo = np.zeros((H + 1, model.deck_dof_count), dtype=complex)
    f = np.zeros((H + 1, n_c), dtype=complex)
    m = min(n_k, H + 1)
    xo[:m] = excitation.deck_displacement[:m]
    f[:m] = excitation.cargo_load_N[:m]
    f[0] = (f[0] + model.static_load_N).real
    xo[0] = xo[0].real
    wk = w * np.arange(H + 1)
    coupling = (
        q.coupling_stiffness[None] - (wk**2)[:, None, None] * q.coupling_mass[None] + 1j * wk[:, None, None] * q.coupling_damping[None]
    )
    rhs = np.empty((H + 1, n_c, n_s + 1), dtype=complex)
    rhs[:, :, :n_s] = B
    rhs[:, :, n_s] = f - np.einsum("kco,ko->kc", coupling, xo)
    sol = solve_dynamic_stack(q, wk, rhs)  # (H+1, n_c, n_s+1)
    Y = sol[:, :, :n_s]
    X_lin = sol[:, :, n_s]
    X_lin[0] = X_lin[0].real
    delta_lin = xo[:, sad_o] - X_lin[:, sad_c]
    G = Y[:, sad_c, :]  # (H+1, n_s, n_s) complex receptance
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
    return CondensedOperators(
        omega_rad_s=w,
        harmonics=H,
        saddle_stiffness_N_per_m=np.asarray(model.saddle_unilateral_stiffness_N_per_m, dtype=float),
        receptance=Greal,
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
        self.inverse, self.forward = real_dft_matrices(ops.harmonics, time_samples)
        self.k_u = ops.saddle_stiffness_N_per_m
        # receptance columns per saddle, (n_s, n_u, n_h): the Jacobian is then one batched matmul
        self.G_by_saddle = np.ascontiguousarray(ops.receptance.reshape(self.size, self.n_h, self.n_s).transpose(2, 0, 1))
        self.scale = ops.compression_scale_m
        self._eye = np.eye(self.size)

    @property
    def compression_scale_m(self) -> float:
        """The largest linear compression coefficient [m] (>= 1 um)."""
        return self.ops.compression_scale_m

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
        return _static_contact_compressions(d_lin, self.ops.receptance[: self.n_s, : self.n_s], self.k_u)

    def predictor(self, amplitude: float) -> NDArray:
        """Harmonics of :meth:`predictor_compression` (the linear solution when contact is kept)."""
        d_lin = self.inverse @ self.ops.linear_compression_at(amplitude)
        if not np.any(d_lin < 0.0):
            return self.initial_guess(amplitude)
        return (self.forward @ self.predictor_compression(amplitude)).ravel()

    def evaluate(self, u: NDArray, law: ContactLaw, amplitude: float) -> tuple[NDArray, NDArray]:
        U = u.reshape(self.n_h, self.n_s)
        delta = self.inverse @ U
        f, fp = law.force_and_derivative(delta, self.k_u)
        correction = f - self.k_u * delta
        C = self.forward @ correction
        R = u - self.ops.linear_compression_at(amplitude).ravel() + self.ops.receptance @ C.ravel()
        return R, fp

    def jacobian(self, fp: NDArray) -> NDArray:
        w = fp - self.k_u  # (N, n_s)
        PW = self.forward[None, :, :] * w.T[:, None, :]  # (n_s, n_h, N)
        T = PW @ self.inverse  # (n_s, n_h, n_h): d C[i, s] / d U[j, s]
        GT = self.G_by_saddle @ T  # (n_s, n_u, n_h): column (j, s) of G . dC/dU
        return self._eye + GT.transpose(1, 2, 0).reshape(self.size, self.size)

    def factorise(self, fp: NDArray) -> DenseJacobian:
        return DenseJacobian(self.jacobian(fp))
