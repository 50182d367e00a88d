"""One axial harmonic-balance problem: residual, Jacobian, its start guesses, the lock check.

Unknowns: the 2H+1 real harmonic coefficients ``X = [a0, a1, b1, ..., aH, bH]`` of the axial
displacement ``u(t)`` (layout of :func:`seafast.fourier.real_dft_matrices`). Residual::

    R(X) = Z X + DFT[ f_J(IDFT X) + f_s(IDFT X) ] - F,

``Z`` the linear part per harmonic (``k_a - (k w)^2 m``, and ``c k w`` between cosine and sine),
``f_J`` the friction as a Jenkins element (:func:`~seafast.solvers.axial.jenkins.march_jenkins`),
``f_s`` the stoppers. Analytic Jacobian ``Z + DFT (k_t (I - S) + diag f_s') IDFT``. The problem is a
:class:`~seafast.solvers.newton.NewtonSystem` of the shared Newton (:data:`AXIAL_GLOBALISATION`).

Start guesses (docs/axial.md): stuck (the contacts' spring carries the load), locked at the edge of
the lock range (:func:`~seafast.solvers.axial.response.lock_range_m`), sliding all period (the
describing function of Coulomb friction: its first harmonic is a viscous damper
``4 C / (pi V)``), frictionless. :func:`lock_check` tests a slip-free solution against the
rigid-Coulomb friction law, which the truncated series can satisfy in the harmonics while it
violates it between them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TypedDict

import numpy as np
from numpy.typing import NDArray

from seafast.excitation.axial import AxialLoad
from seafast.fourier import complex_to_real_harmonics, real_dft_matrices, real_harmonics_to_time, time_to_real_harmonics
from seafast.model.axial import AxialRestraint
from seafast.solvers.axial.jenkins import JenkinsPeriod, march_jenkins
from seafast.solvers.axial.response import LockCheck, lock_range_m
from seafast.solvers.newton import DenseJacobian, Globalisation, Merit

__all__ = ["AxialProblem", "AxialIterate", "AXIAL_GLOBALISATION", "IterateArrays", "lock_check", "evaluation_arrays"]

AXIAL_GLOBALISATION = Globalisation(merit=Merit.MAX_ABS, memory=1, min_step=2.0**-29, accept_converged_trial=True)
"""The axial harmonic balance's Newton: monotone backtracking on ``max |R| / scale`` (Armijo c = 1e-4) over up to
30 halvings of the step, a trial that meets the tolerance accepted; a singular Jacobian solved in least squares."""


@dataclass(frozen=True)
class AxialIterate:
    """What one residual evaluation computed besides ``R``: the Jenkins period and the displacement samples [m]."""

    jenkins: JenkinsPeriod
    displacement_m: NDArray[np.float64]


class AxialProblem:
    """Residual and Jacobian of one axial HBM problem (Jenkins element of stiffness ``k_t``).

    Parameters
    ----------
    restraint, load
        The cargo's axial restraint and load.
    capacity
        Friction available at the N samples [N].
    H, N
        Harmonics and AFT samples.
    stick_stiffness_N_per_m
        The Jenkins spring [N/m]; default the restraint's (a softer one regularises the law).
    """

    def __init__(
        self, restraint: AxialRestraint, load: AxialLoad, capacity: NDArray, H: int, N: int, stick_stiffness_N_per_m: float | None = None
    ):
        self.r = restraint
        self.H, self.N = H, N
        w = load.omega_rad_s
        self.omega_rad_s = float(w)
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
        self.kt = restraint.stick_stiffness_N_per_m if stick_stiffness_N_per_m is None else float(stick_stiffness_N_per_m)
        # nothing but friction restrains the cargo's mean position: pin it (docs/axial.md)
        self.gauge = k_restore == 0.0 and not restraint.has_stoppers
        # the linear part Z is block diagonal: Z[0, 0], then [[d_k, c_k], [-c_k, d_k]] per harmonic, applied
        # and solved block by block; the dense matrix only for the Jacobian
        self.mean_stiffness_N_per_m = k_restore if not self.gauge else 1e-9 * max(self.inertia_N_per_m, 1.0)
        self.harmonic_diagonal_N_per_m = k_restore - m * (k * w) ** 2
        self.harmonic_coupling_N_per_m = restraint.damping_N_s_per_m * k * w
        self.scale = max(float(np.max(np.abs(self.load_t))), float(np.max(capacity)) if capacity.size else 0.0, 1e-300)

    def residual(self, X: NDArray) -> tuple[NDArray, AxialIterate]:
        """``R(X)`` [N] and the iterate's Jenkins period and displacement samples."""
        # the transforms by FFT (O(N log N)); the dense E and D only for the Jacobian
        u = real_harmonics_to_time(X, self.N)
        _, stop = self.r.restoring_force_N(u)
        jen = march_jenkins(u, self.capacity, self.kt)
        R = self.apply_linear(X) + time_to_real_harmonics(jen.force_N + stop, self.H) - self.F
        return R, AxialIterate(jen, u)

    def jacobian(self, state: AxialIterate) -> NDArray:
        """The dense Jacobian ``dR/dX`` (2H+1, 2H+1) [N/m] at an evaluated iterate."""
        E, D = real_dft_matrices(self.H, self.N)
        jen = state.jenkins
        gathered = np.where((jen.last_slip >= 0)[:, None], E[np.maximum(jen.last_slip, 0)], 0.0)
        dfe = self.kt * (E - gathered) + self.r.stopper_tangent_N_per_m(state.displacement_m)[:, None] * E
        return self.Z + D @ dfe

    def factorise(self, state: AxialIterate) -> DenseJacobian:
        """The Jacobian for Newton steps (a singular one solved in least squares)."""
        return DenseJacobian(self.jacobian(state), least_squares=True)

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

    def solve_linear(self, added_stiffness_N_per_m: float, added_damping_N_s_per_m: float = 0.0) -> NDArray:
        """``(Z + k I + i k w c_add)^-1 F`` block by block; inf or NaN where a block is singular."""
        d = self.harmonic_diagonal_N_per_m + added_stiffness_N_per_m
        c = self.harmonic_coupling_N_per_m + added_damping_N_s_per_m * np.arange(1, self.H + 1) * self.omega_rad_s
        fa, fb = self.F[1::2], self.F[2::2]
        X = np.empty_like(self.F)
        with np.errstate(divide="ignore", invalid="ignore"):
            X[0] = self.F[0] / (self.mean_stiffness_N_per_m + added_stiffness_N_per_m)
            det = d * d + c * c
            X[1::2] = (d * fa - c * fb) / det
            X[2::2] = (c * fa + d * fb) / det
        return X

    def stick_guess(self) -> NDArray:
        """Stuck: the contacts' spring ``k_t`` carries the load."""
        return self.solve_linear(self.kt)

    def free_guess(self) -> NDArray | None:
        """Frictionless: the lashings' (and stoppers' free-play) linear answer; None at resonance."""
        X = self.solve_linear(0.0)
        return X if np.all(np.isfinite(X)) else None

    def locked_guess(self) -> NDArray | None:
        """Stuck at the edge of the lock range nearest the as-placed ``u = 0`` (None without a range off ``u = 0``).

        Between the shakedown coefficient and the critical one the cargo can stay locked only off
        ``u = 0`` (:func:`~seafast.solvers.axial.response.lock_range_m`); it walks to the range's
        nearer edge, where the Jenkins element (set down relaxed at ``u = 0``) stays.
        """
        lock = lock_range_m(self.r, self.load_t, self.capacity)
        if lock is None or lock[0] <= 0.0 <= lock[1] or not all(map(math.isfinite, lock)):
            return None
        X = self.stick_guess()
        X[0] += lock[1] if lock[1] < 0.0 else lock[0]
        return X

    def sliding_guess(self) -> NDArray | None:
        """Sliding all period: Coulomb friction by its describing function, a damper ``4 C_mean / (pi V)``.

        ``V`` the peak sliding velocity, iterated to a fixed point (relaxed); for one harmonic this
        is the classical equivalent damping, whose amplitude Den Hartog's exact solution refines.
        None when the friction is too strong to slide all period (``4 C / pi >= |F_1|``, no fixed
        point) or the frictionless answer is singular.
        """
        if self.free_guess() is None or not self.capacity.size:
            return None
        c_mean = float(np.mean(self.capacity))
        k = np.arange(1, self.H + 1)
        damping, X = 0.0, self.solve_linear(0.0)
        for _ in range(60):
            V = np.zeros_like(X)
            V[1::2], V[2::2] = k * self.omega_rad_s * X[2::2], -k * self.omega_rad_s * X[1::2]
            peak = float(np.max(np.abs(real_harmonics_to_time(V, self.N))))
            if not peak > 0.0:
                return None
            target = 4.0 * c_mean / (math.pi * peak)
            if abs(target - damping) <= 1e-8 * target:
                break
            damping = target if damping == 0.0 else 0.5 * (damping + target)
            X = self.solve_linear(0.0, damping)
        first = math.hypot(self.F[1], self.F[2]) if self.H >= 1 else 0.0
        return X if 4.0 * c_mean / math.pi < first and np.all(np.isfinite(X)) else None


def lock_check(p: AxialProblem, jen: JenkinsPeriod, u: NDArray, tol: float) -> tuple[LockCheck, float, int]:
    """A slip-free solution against the rigid-Coulomb friction law: ``|F - r(u)| <= C`` at every sample.

    The solution is slip-free when its slider travels no more than twice the contacts' elastic
    range ``2 max C / k_t`` per period (a rigid cargo does not move; what the Jenkins spring
    lets it do is the regularisation). Stuck, the friction must carry ``F - r(u)``; the samples
    are where the harmonic balance holds the law, and the margin is what the discretisation
    leaves there: the Newton tolerance in force, and the change of ``r`` over the displacement's
    wiggle in the contacts' elastic range.

    Returns
    -------
    check, excess_N, sample
        :class:`LockCheck`; the largest ``|F - r(u)| - C`` [N] and the sample where it is (a
        locked solution only; 0 and -1 otherwise).
    """
    band = 2.0 * float(np.max(p.capacity)) / p.kt if p.capacity.size else 0.0
    if jen.slip_path_m > 2.0 * band:
        return LockCheck.NOT_LOCKED, 0.0, -1
    lashing, stop = p.r.restoring_force_N(u)
    excess = np.abs(p.load_t - lashing - stop) - p.capacity
    stiffness = p.r.lashing_axial_stiffness_N_per_m + (p.r.stopper_stiffness_N_per_m if p.r.has_stoppers else 0.0)
    margin = tol * p.scale + stiffness * float(np.ptp(u))
    worst = int(np.argmax(excess))
    return (LockCheck.HOLDS if excess[worst] <= margin else LockCheck.VIOLATED), float(excess[worst]), worst


class IterateArrays(TypedDict):
    """An iterate's displacement [m], velocity [m/s], forces on the cargo [N] (forward +), sliding samples and slip [m]."""

    displacement_m: NDArray[np.float64]
    velocity_m_per_s: NDArray[np.float64]
    friction_force_N: NDArray[np.float64]
    lashing_force_N: NDArray[np.float64]
    stopper_force_N: NDArray[np.float64]
    sliding: NDArray[np.bool_]
    slip_m: float


def evaluation_arrays(p: AxialProblem, X: NDArray, state: AxialIterate) -> IterateArrays:
    """Displacement, velocity and forces of an iterate, as the fields of an AxialResponse."""
    jen, u = state.jenkins, state.displacement_m
    lashing, stop = p.r.restoring_force_N(u)
    V = np.zeros_like(X)
    k = np.arange(1, p.H + 1)
    V[1::2] = k * p.omega_rad_s * X[2::2]
    V[2::2] = -k * p.omega_rad_s * X[1::2]
    return {
        "displacement_m": u,
        "velocity_m_per_s": real_harmonics_to_time(V, p.N),
        "friction_force_N": -jen.force_N,
        "lashing_force_N": -lashing,
        "stopper_force_N": -stop,
        "sliding": jen.slipped,
        "slip_m": jen.slip_path_m,
    }
