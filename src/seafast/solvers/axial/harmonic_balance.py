"""Harmonic balance with AFT for the cargo's axial stick-slip (docs/axial.md).

Unknowns: the 2H+1 real harmonic coefficients ``X = [a0, a1, b1, ..., aH, bH]`` of the axial
displacement ``u(t)`` (layout of :func:`seafast.solvers.hbm.real_dft_matrices`): the problem is
condensed onto the rigid cargo's single axial DOF. Residual::

    R(X) = Z X + DFT[ f_J(IDFT X) + f_s(IDFT X) ] - F,

``Z`` the linear part per harmonic (``k_a - (k w)^2 m``, and ``c k w`` between cosine and sine),
``f_J`` the friction as a Jenkins element (the contacts' tangential stiffness ``k_t`` in series
with the Coulomb slider of capacity ``C(t) = sum_i mu_i max(N_i(t), 0)``) marched over the N
samples until the period closes (:func:`~seafast.solvers.axial.jenkins.march_jenkins`), ``f_s``
the stoppers. The Jenkins spring is what the AFT needs to march the hysteresis; at the default
stiffness (1e12 N/m per saddle, a rigid contact) the periodic solution does not depend on it
(tests: 1e11 to 1e13 N/m agree to 1e-4) and converges to the rigid-Coulomb time-domain reference.

Analytic Jacobian ``Z + DFT (k_t (I - S) + diag f_s') IDFT`` (``S`` picks each sample's last
slip). Damped Newton with a backtracking line search from the best of the stuck, the
frictionless and a given solution. Limitation (docs/axial.md): a truncated Fourier series cannot
hold the cargo exactly still, so long stick phases between slips (friction coefficients just
below the critical one) make the stick state chatter at the samples and Newton may fail; that is
reported (``converged=False`` and the residual), never raised, and the case pipeline then solves
the row with the time-domain reference.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from seafast.excitation.axial import AxialLoad
from seafast.fourier import (
    complex_to_real_harmonics,
    real_dft_matrices,
    real_harmonics_to_time,
    real_to_complex_harmonics,
    time_to_real_harmonics,
)
from seafast.model.axial import AxialRestraint
from seafast.solvers.axial.jenkins import march_jenkins
from seafast.solvers.axial.response import AxialResponse, periodic_interpolation

__all__ = ["AxialHBMOptions", "solve_axial_hbm", "axial_time_samples"]


@dataclass(frozen=True, kw_only=True)
class AxialHBMOptions:
    """Settings of the axial harmonic balance.

    Parameters
    ----------
    harmonics
        H >= 1.
    time_samples
        AFT samples per period N >= 2H + 2 (the normal forces are interpolated onto them).
    tolerance
        Converged when ``max |R|`` is below ``tolerance`` times the load scale (the larger of
        ``max |F|`` and ``max C``).
    max_iterations
        Newton iterations per attempt.
    """

    harmonics: int = 25
    time_samples: int = 512
    tolerance: float = 1e-9
    max_iterations: int = 40

    def __post_init__(self) -> None:
        if not isinstance(self.harmonics, int) or self.harmonics < 1:
            raise ValueError(f"AxialHBMOptions.harmonics = {self.harmonics!r}; allowed an integer >= 1")
        if not isinstance(self.time_samples, int) or self.time_samples < 2 * self.harmonics + 2:
            raise ValueError(f"AxialHBMOptions.time_samples = {self.time_samples!r}; allowed an integer >= 2 harmonics + 2")
        if not (0.0 < self.tolerance < 1.0):
            raise ValueError(f"AxialHBMOptions.tolerance = {self.tolerance!r}; allowed 0 < tolerance < 1")
        if not isinstance(self.max_iterations, int) or self.max_iterations < 1:
            raise ValueError(f"AxialHBMOptions.max_iterations = {self.max_iterations!r}; allowed an integer >= 1")


def axial_time_samples(harmonics: int, vertical_samples: int, minimum: int = 512) -> int:
    """AFT samples for the axial HBM: a multiple of the vertical solution's N, at least ``max(minimum, 8 H)``.

    The slip transitions fall between samples: 512 samples keep that error below 0.1 % of the
    slip on the base case (256 give 1 %).
    """
    need = max(minimum, 8 * harmonics, 2 * harmonics + 2)
    return int(vertical_samples * math.ceil(need / vertical_samples))


class _Problem:
    """Residual and Jacobian of one axial HBM problem (Jenkins element of stiffness ``kt``)."""

    def __init__(self, restraint: AxialRestraint, load: AxialLoad, capacity: NDArray, H: int, N: int):
        self.r = restraint
        self.H, self.N = H, N
        w = load.omega_rad_s
        f = np.zeros(H + 1, dtype=complex)
        n = min(H + 1, load.force_N.size)
        f[:n] = load.force_N[:n]
        self.F = complex_to_real_harmonics(f)
        self.load_t = real_harmonics_to_time(self.F, N)
        self.capacity = capacity
        k = np.arange(1, H + 1)
        k_restore = restraint.lashing_axial_stiffness_N_per_m
        m = restraint.cargo_mass_kg
        self.inertia_N_per_m = m * w**2
        self.kt = restraint.stick_stiffness_N_per_m
        # nothing but friction restrains the cargo's mean position: pin it (docs/axial.md)
        self.gauge = k_restore == 0.0 and not restraint.has_stoppers
        # the linear part Z is block diagonal: Z[0, 0], then [[d_k, c_k], [-c_k, d_k]] per harmonic, applied
        # and solved block by block; the dense matrix only for the Jacobian
        self.mean_stiffness_N_per_m = k_restore if not self.gauge else 1e-9 * max(self.inertia_N_per_m, 1.0)
        self.harmonic_diagonal_N_per_m = k_restore - m * (k * w) ** 2
        self.harmonic_coupling_N_per_m = restraint.damping_N_s_per_m * k * w
        self.scale = max(float(np.max(np.abs(self.load_t))), float(np.max(capacity)) if capacity.size else 0.0, 1e-300)

    def evaluate(self, X: NDArray, capacity: NDArray) -> tuple[NDArray, Any, NDArray]:
        # the transforms by FFT (O(N log N)); the dense E and D only for the Jacobian
        u = real_harmonics_to_time(X, self.N)
        _, stop = self.r.restoring_force_N(u)
        jen = march_jenkins(u, capacity, self.kt)
        R = self.apply_linear(X) + time_to_real_harmonics(jen.force_N + stop, self.H) - self.F
        return R, jen, u

    def jacobian(self, jen: Any, u: NDArray) -> NDArray:
        E, D = real_dft_matrices(self.H, self.N)
        gathered = np.where((jen.last_slip >= 0)[:, None], E[np.maximum(jen.last_slip, 0)], 0.0)
        dfe = self.kt * (E - gathered) + self.r.stopper_tangent_N_per_m(u)[:, None] * E
        return self.Z + D @ dfe

    @property
    def Z(self) -> NDArray:
        """The linear part as a dense (2H+1, 2H+1) matrix [N/m]."""
        k = np.arange(1, self.H + 1)
        d, c = self.harmonic_diagonal_N_per_m, self.harmonic_coupling_N_per_m
        Z = np.zeros((2 * self.H + 1, 2 * self.H + 1))
        Z[0, 0] = self.mean_stiffness_N_per_m
        Z[2 * k - 1, 2 * k - 1] = d
        Z[2 * k, 2 * k] = d
        Z[2 * k - 1, 2 * k] = c
        Z[2 * k, 2 * k - 1] = -c
        return Z

    def apply_linear(self, X: NDArray) -> NDArray:
        """``Z X`` block by block [N]."""
        d, c = self.harmonic_diagonal_N_per_m, self.harmonic_coupling_N_per_m
        a, b = X[1::2], X[2::2]
        out = np.empty_like(X)
        out[0] = self.mean_stiffness_N_per_m * X[0]
        out[1::2] = d * a + c * b
        out[2::2] = -c * a + d * b
        return out

    def solve_linear(self, added_stiffness_N_per_m: float) -> NDArray:
        """``(Z + k I)^-1 F`` block by block; inf or NaN where a block is singular."""
        d = self.harmonic_diagonal_N_per_m + added_stiffness_N_per_m
        c = self.harmonic_coupling_N_per_m
        fa, fb = self.F[1::2], self.F[2::2]
        X = np.empty_like(self.F)
        with np.errstate(divide="ignore", invalid="ignore"):
            X[0] = self.F[0] / (self.mean_stiffness_N_per_m + added_stiffness_N_per_m)
            det = d * d + c * c
            X[1::2] = (d * fa - c * fb) / det
            X[2::2] = (c * fa + d * fb) / det
        return X

    def stick_guess(self) -> NDArray:
        return self.solve_linear(self.kt)

    def free_guess(self) -> NDArray | None:
        X = self.solve_linear(0.0)
        return X if np.all(np.isfinite(X)) else None


def _newton(
    p: _Problem, X: NDArray, capacity: NDArray, tol: float, max_iter: int, first: tuple[NDArray, Any, NDArray] | None = None
) -> tuple[NDArray, float, int, bool, tuple[NDArray, Any, NDArray]]:
    """Damped Newton; returns the iterate, its relative residual, iterations, success and its evaluation."""
    ev = first if first is not None else p.evaluate(X, capacity)
    R, jen, u = ev
    norm = float(np.max(np.abs(R))) / p.scale
    for it in range(1, max_iter + 1):
        if norm <= tol:
            return X, norm, it - 1, True, ev
        J = p.jacobian(jen, u)
        try:
            dX = np.linalg.solve(J, -R)
        except np.linalg.LinAlgError:
            dX = np.linalg.lstsq(J, -R, rcond=None)[0]
        step = 1.0
        for _ in range(30):
            X_try = X + step * dX
            ev_try = p.evaluate(X_try, capacity)
            n_try = float(np.max(np.abs(ev_try[0]))) / p.scale
            if n_try < (1.0 - 1e-4 * step) * norm or n_try <= tol:
                break
            step *= 0.5
        else:
            return X, norm, it, False, ev
        X, ev, norm = X_try, ev_try, n_try
        R, jen, u = ev
    return X, norm, max_iter, norm <= tol, ev


def solve_axial_hbm(
    restraint: AxialRestraint,
    load: AxialLoad,
    normal_force_N: NDArray[np.float64],
    options: AxialHBMOptions = AxialHBMOptions(),
    initial_harmonics: NDArray[np.complex128] | None = None,
) -> AxialResponse:
    """Periodic axial stick-slip response of the rigid cargo by harmonic balance.

    Parameters
    ----------
    restraint
        Friction coefficients, tangential stiffness, lashings, stoppers, cargo mass.
    load
        Axial load harmonics [N] (forward +).
    normal_force_N
        Saddle contact forces over one period from the vertical solution [N], shape (N_v, n_s)
        (``N_v`` samples at ``t = n T / N_v``; linearly interpolated onto the AFT samples).
    options
        Harmonics, samples, tolerance.
    initial_harmonics
        Complex harmonics of ``u`` of a neighbouring solution to start from (a third start).

    Returns
    -------
    AxialResponse
        On ``options.time_samples`` samples; ``converged=False`` (with the residual) when
        Newton fails, never an exception.
    """
    H, N = options.harmonics, options.time_samples
    normal = periodic_interpolation(np.asarray(normal_force_N, dtype=float).reshape(np.shape(normal_force_N)[0], -1), N)
    capacity = restraint.capacity_N(normal)
    p = _Problem(restraint, load, capacity, H, N)

    def given() -> NDArray | None:
        if initial_harmonics is None:
            return None
        x0 = np.zeros(H + 1, dtype=complex)
        n0 = min(H + 1, len(initial_harmonics))
        x0[:n0] = np.asarray(initial_harmonics)[:n0]
        return complex_to_real_harmonics(x0)

    # the candidates are built lazily: when the friction holds, the stick solution is the answer
    starts = (("stuck", p.stick_guess), ("frictionless", p.free_guess), ("given", given))
    best = None
    for name, make in starts:
        X_start = make()
        if X_start is None:
            continue
        ev = p.evaluate(X_start, capacity)
        r = float(np.max(np.abs(ev[0])))
        if best is None or r < best[0]:
            best = (r, name, X_start, ev)
        if r <= options.tolerance * p.scale:
            break
    assert best is not None
    _, start_name, X0, ev0 = best
    X, norm, iters, ok, (_, jen, u) = _newton(p, X0, capacity, options.tolerance, options.max_iterations, ev0)
    path = f"from the {start_name} solution" if ok else f"did not converge (Newton from the {start_name} solution)"
    lam = jen.force_N
    lashing, stop = restraint.restoring_force_N(u)
    V = np.zeros_like(X)
    k = np.arange(1, H + 1)
    V[1::2] = k * load.omega_rad_s * X[2::2]
    V[2::2] = -k * load.omega_rad_s * X[1::2]
    msg = f"axial HBM (H = {H}, N = {N}): {path}, {iters} Newton iterations, residual {norm:.2e}"
    if p.gauge:
        msg += "; no lashing or stopper restrains the cargo axially: its mean position is pinned"
    return AxialResponse(
        "hbm",
        load.omega_rad_s,
        u,
        real_harmonics_to_time(V, N),
        -lam,
        capacity,
        -lashing,
        -stop,
        p.load_t,
        jen.slipped,
        jen.slip_path_m,
        bool(ok),
        norm,
        int(iters),
        msg,
        real_to_complex_harmonics(X),
        {
            "harmonics": H,
            "time_samples": N,
            "tolerance": options.tolerance,
            "max_iterations": options.max_iterations,
            "tangential_stiffness_N_per_m": p.kt,
        },
    )
