"""Frequency response of the nonlinear (unilateral-saddle) system by pseudo-arclength continuation.

The condensed HBM system (see :mod:`seafast.solvers.hbm`) ``R(u, omega) = 0`` -- u the harmonic
coefficients of the saddle compressions -- is followed in omega with a predictor-corrector
pseudo-arclength method (Keller 1977): tangent predictor, Newton corrector on ``R = 0`` plus the
arclength condition ``t . (y - y_pred) = 0`` (scaled variables: u over the largest linear
compression fluctuation at the start, omega over the sweep span), step-size control on the
corrector's iteration count and on how far the tangent turns, and the tangent's orientation kept
from step to step so the branch turns at folds. ``dR/domega`` is a central difference of the
residual (the receptances depend on omega through the dynamic stiffness): central for the
tangent, one-sided in the corrector's iterations (the residual there is already known).

Round-off. Moving omega re-solves the dynamic stiffness; with soft saddles on a stiff beam its
condition number reaches 1e8-1e9 and the residual is noisy at up to ~1e-7 of the compression
scale, which no corrector can go below. A corrector that stalls is therefore asked whether its
residual is at the round-off floor *of that point* (the residual's change when omega moves by a
few units of round-off) and accepted if it is within ten times that floor: the branch is followed
through grazing folds and resonances of soft saddles instead of stopping there.

Each point records the compression harmonics (for stability, moments and post-processing) and
the omega component of the unit tangent, whose sign changes at the folds
(:class:`~seafast.solvers.branch.FrequencyResponseBranch`).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np
from numpy.typing import NDArray

from seafast.excitation.harmonic import HarmonicExcitation
from seafast.fourier import harmonics_to_time, real_dft_matrices, real_to_complex_harmonics
from seafast.model.structure import StructuralModel
from seafast.solvers.branch import BranchEnd, FrequencyResponseBranch
from seafast.solvers.contact import ContactLaw
from seafast.solvers.hbm import CondensedOperators, CondensedProblem, HBMOptions, condensed_operators, solve_condensed

__all__ = ["DEFAULT_HARMONICS", "BranchEnd", "FrequencyResponseBranch", "frequency_response"]

DEFAULT_HARMONICS = 10
"""H of a continuation whose options leave ``harmonics`` unset (one branch is followed at a fixed H)."""

_NOISE_FACTOR = 10.0  # a stalled corrector is accepted within this multiple of the point's round-off floor
_NOISE_CAP = 1e-5  # ... and never above this relative residual
_ROUND_OFF_SHIFTS = (1e-13, -1e-13, 3e-13)  # relative omega shifts that sample the round-off of the residual


class _Branch:
    """Residual, Jacobian and metrics of the condensed system as functions of omega."""

    def __init__(self, model: StructuralModel, excitation_at: Callable[[float], HarmonicExcitation], options: HBMOptions):
        self.model = model
        self.excitation_at = excitation_at
        self.options = options
        self.harmonics, self.time_samples = options.fixed_grid()  # one branch, at a fixed H
        self.law: ContactLaw = options.law
        self._ops_cache: dict[float, CondensedOperators] = {}

    def ops(self, omega: float) -> CondensedOperators:
        ops = self._ops_cache.get(omega)
        if ops is None:
            ex = self.excitation_at(float(omega))
            if not np.isclose(ex.omega_rad_s, omega, rtol=1e-12, atol=0.0):
                raise ValueError(f"excitation_at({omega!r}) returned an excitation at omega = {ex.omega_rad_s!r}")
            ops = condensed_operators(self.model, ex, self.harmonics)
            if len(self._ops_cache) > 8:
                self._ops_cache.clear()
            self._ops_cache[omega] = ops
        return ops

    def problem(self, omega: float) -> CondensedProblem:
        return CondensedProblem(self.ops(omega), self.time_samples)

    def residual(self, u: NDArray, omega: float) -> tuple[NDArray, Any, CondensedProblem]:
        p = self.problem(omega)
        R, state = p.evaluate(u, self.law, 1.0)
        return R, state, p

    def d_residual_d_omega(self, u: NDArray, omega: float, R: NDArray | None = None) -> NDArray:
        """dR/domega [m s/rad]: central difference, or one-sided from ``R = R(u, omega)`` when given."""
        h = 1e-6 * max(abs(omega), 1e-3)
        if R is not None:
            return (self.residual(u, omega + h)[0] - R) / h
        return (self.residual(u, omega + h)[0] - self.residual(u, omega - h)[0]) / (2.0 * h)

    def round_off(self, u: NDArray, omega: float, R: NDArray) -> float:
        """Largest change of R [m] when omega moves by a few units of round-off (the residual's noise floor)."""
        return max(float(np.max(np.abs(self.residual(u, omega * (1.0 + e))[0] - R))) for e in _ROUND_OFF_SHIFTS)

    def metrics(self, u: NDArray, omega: float) -> tuple[float, float, float, bool]:
        ops = self.ops(omega)
        n_h, n_s = 2 * ops.harmonics + 1, ops.saddle_count
        inverse, forward = real_dft_matrices(ops.harmonics, self.time_samples)
        U = u.reshape(n_h, n_s)
        delta = inverse @ U
        force = self.law.force(delta, ops.saddle_stiffness_N_per_m)
        corr = forward @ (force - ops.saddle_stiffness_N_per_m * delta)
        C = real_to_complex_harmonics(corr)
        X = ops.linear_cargo_displacement + np.einsum("kcs,ks->kc", ops.cargo_influence, C)
        z = harmonics_to_time(X[:, 0::2], self.time_samples)
        return float(np.max(force)), float(max(-np.min(delta), 0.0)), float(np.max(np.abs(z))), bool(np.all(delta > 0.0))


def frequency_response(
    model: StructuralModel,
    excitation_at: Callable[[float], HarmonicExcitation],
    omega_start_rad_s: float,
    omega_end_rad_s: float,
    options: HBMOptions | None = None,
    *,
    initial_step: float = 0.02,
    min_step: float = 1e-5,
    max_step: float = 1.0,
    max_omega_step: float = 0.01,
    max_points: int = 2000,
    corrector_iterations: int = 12,
    stop_when: Callable[[float, NDArray[np.float64]], bool] | None = None,
) -> FrequencyResponseBranch:
    """Follow the periodic response from ``omega_start`` to ``omega_end`` by pseudo-arclength continuation.

    Parameters
    ----------
    model
        Cargo and sea-fastening.
    excitation_at
        ``omega -> HarmonicExcitation`` at that frequency (deck motion and loads may depend on
        omega, e.g. inertia loads ~ omega^2).
    omega_start_rad_s, omega_end_rad_s
        Sweep limits [rad/s], either order.
    options
        HBM settings with a fixed ``harmonics`` (condensed formulation; ``solver`` applies to the
        first point only).
    initial_step, min_step, max_step
        Arclength steps in scaled variables (omega scaled by the sweep span, compressions by
        their largest linear fluctuation at the start). The step grows when the corrector
        converges in few iterations and the tangent turns by less than 5 degrees, shrinks
        otherwise, and is halved on corrector failure.
    max_omega_step
        Largest step in omega as a share of the span (so that no peak is stepped over).
    max_points
        Safety limit on the number of branch points.
    corrector_iterations
        Newton iterations per corrector before the step is halved.
    stop_when
        Optional ``(omega [rad/s], compression harmonics (2H+1, n_s) [m]) -> bool``, asked after each
        recorded point; True ends the branch there (:attr:`BranchEnd.STOPPED`).

    Returns
    -------
    FrequencyResponseBranch
        The branch; points that could not be continued end it (``end`` and ``message`` say why). Never
        raises for non-convergence.
    """
    options = HBMOptions() if options is None else options
    if not (omega_start_rad_s > 0 and omega_end_rad_s > 0) or omega_start_rad_s == omega_end_rad_s:
        raise ValueError(
            f"omega_start_rad_s = {omega_start_rad_s!r}, omega_end_rad_s = {omega_end_rad_s!r}; allowed: two different positive frequencies"
        )
    if not (0 < min_step <= initial_step <= max_step) or not (0 < max_omega_step <= 1):
        raise ValueError(
            f"steps: need 0 < min_step <= initial_step <= max_step and 0 < max_omega_step <= 1, got "
            f"{min_step}, {initial_step}, {max_step}, {max_omega_step}"
        )
    H = DEFAULT_HARMONICS if options.harmonics is None else int(options.harmonics)  # one branch, at a fixed H
    options = options.with_harmonics(H)
    branch = _Branch(model, excitation_at, options)
    w0, w1 = float(omega_start_rad_s), float(omega_end_rad_s)
    direction = 1.0 if w1 > w0 else -1.0
    first = solve_condensed(branch.ops(w0), options)
    tol = float(options.tolerance)
    # scale the compressions by their linear *fluctuation* at the start, so that a resonance
    # (growing fluctuation) is resolved with small steps
    lin = branch.ops(w0).linear_compression_m
    u_scale = float(max(np.max(np.abs(lin[1:])) if lin.shape[0] > 1 else 0.0, 1e-3 * np.max(np.abs(lin)), 1e-9))
    w_scale = abs(w1 - w0)
    tol_corrector = max(tol, 1e-7)
    r_scale = branch.ops(w0).compression_scale_m
    shape = (2 * H + 1, model.saddle_count)
    pts: list[tuple[float, float, float, float, bool, bool]] = []
    extra: list[tuple[NDArray, float, float]] = []  # harmonics, tangent omega component, residual

    def record(u: NDArray, omega: float, ok: bool, t_omega: float, residual: float) -> None:
        f, g, z, keep = branch.metrics(u, omega)
        pts.append((omega, f, g, z, ok, keep))
        extra.append((u.reshape(shape).copy(), t_omega, residual))

    u = first.saddle_compression.ravel().copy()
    omega = w0
    if not first.converged:
        record(u, omega, False, 0.0, first.residual_norm)
        return _finish(pts, extra, "the first point did not converge", 0, options, BranchEnd.FIRST_POINT_FAILED)

    def tangent(u: NDArray, omega: float, previous: NDArray | None) -> NDArray:
        """Unit tangent in scaled variables."""
        _, state, p = branch.residual(u, omega)
        J = p.jacobian(state) * u_scale  # dR / d(u/u_scale)
        Rw = branch.d_residual_d_omega(u, omega) * w_scale
        n = u.size
        t: NDArray
        if previous is None:
            t_u = np.linalg.solve(J, -Rw)
            t = np.append(t_u, 1.0) * direction
        else:
            A = np.zeros((n + 1, n + 1))
            A[:n, :n], A[:n, n], A[n] = J, Rw, previous
            b = np.zeros(n + 1)
            b[n] = 1.0
            t = np.linalg.solve(A, b)
        return t / np.linalg.norm(t)

    t = tangent(u, omega, None)
    record(u, omega, True, float(t[-1]), first.residual_norm)
    ds = float(initial_step)
    steps = 0
    message = "reached omega_end"
    ending = BranchEnd.REACHED_END

    def augmented(yk: NDArray, y_pred: NDArray, t: NDArray) -> tuple[NDArray, Any]:
        uk, wk = yk[:-1] * u_scale, yk[-1] * w_scale
        R, state, p = branch.residual(uk, wk)
        return np.append(R / r_scale, t @ (yk - y_pred)), (state, p, uk, wk)

    while len(pts) < max_points:
        if direction * (omega - w1) >= -1e-12 * w_scale:
            break
        y = np.append(u / u_scale, omega / w_scale)
        # limit the step in omega to max_omega_step of the span, and do not overshoot the end
        step_w = abs(t[-1]) * w_scale
        ds_try = min(ds, max_omega_step * w_scale / step_w) if step_w > 0 else ds
        if direction * t[-1] > 0:
            ds_end = (w1 / w_scale - y[-1]) / t[-1]
            if 0 < ds_end < ds_try * 1.05:
                ds_try = ds_end
        y_pred = y + ds_try * t
        yk = y_pred.copy()
        ok = False
        its = 0
        residual = np.inf
        try:
            F, (state, p, uk, wk) = augmented(yk, y_pred, t)
            for its in range(1, corrector_iterations + 1):  # noqa: B007 - the count sets the next step length below
                residual = float(np.max(np.abs(F[:-1])))
                if residual <= tol_corrector and abs(F[-1]) <= 1e-8:
                    ok = True
                    break
                J = p.jacobian(state) * (u_scale / r_scale)
                column = branch.d_residual_d_omega(uk, wk, F[:-1] * r_scale) * (w_scale / r_scale)
                n = uk.size
                A = np.zeros((n + 1, n + 1))
                A[:n, :n], A[:n, n], A[n] = J, column, t
                dy = np.linalg.solve(A, -F)
                norm0 = float(np.linalg.norm(F))
                lam = 1.0
                while lam >= 1.0 / 64:  # backtracking keeps the corrector from cycling at kinks
                    y_try = yk + lam * dy
                    if y_try[-1] > 0:
                        F_try, aux = augmented(y_try, y_pred, t)
                        if np.linalg.norm(F_try) < (1.0 - 1e-4 * lam) * norm0:
                            break
                    lam *= 0.5
                else:
                    break
                yk, F, (state, p, uk, wk) = y_try, F_try, aux
            else:
                residual = float(np.max(np.abs(F[:-1])))
            if not ok and residual <= _NOISE_CAP and abs(F[-1]) <= 1e-6:
                # stalled: accept if the residual is at this point's round-off floor
                floor = branch.round_off(uk, wk, F[:-1] * r_scale) / r_scale
                ok = residual <= _NOISE_FACTOR * floor
        except (np.linalg.LinAlgError, FloatingPointError):
            ok = False
        steps += 1
        if not ok:
            ds = 0.5 * ds_try
            if ds < min_step:
                message = f"step size fell below min_step at omega = {omega:.6g} rad/s"
                ending = BranchEnd.STEP_BELOW_MIN
                break
            continue
        u_new, w_new = yk[:-1] * u_scale, yk[-1] * w_scale
        t_new = tangent(u_new, w_new, t)
        cos_angle = float(t_new @ t)
        u, omega, t = u_new, w_new, t_new
        record(u, omega, True, float(t[-1]), residual)
        if stop_when is not None and stop_when(omega, u.reshape(shape)):
            message = f"stopped at omega = {omega:.6g} rad/s by the caller's range check"
            ending = BranchEnd.STOPPED
            break
        if its <= 3 and cos_angle > np.cos(np.radians(5.0)):
            grow = 1.6
        elif its <= 6 and cos_angle > np.cos(np.radians(12.0)):
            grow = 1.0
        else:
            grow = 0.6
        ds = float(np.clip(ds_try * grow, min_step, max_step))
    else:
        message = f"stopped at max_points = {max_points}"
        ending = BranchEnd.MAX_POINTS
    if ending is BranchEnd.REACHED_END and omega != w1:
        # land exactly on omega_end (the corrector moves omega slightly off the predictor)
        end = solve_condensed(branch.ops(w1), options, initial_compression=u)
        if end.converged:
            if direction * (omega - w1) > 0:
                pts.pop()
                extra.pop()
            record(end.saddle_compression.ravel(), w1, True, float(t[-1]), end.residual_norm)
    return _finish(pts, extra, message, steps, options, ending)


def _finish(
    pts: list, extra: list[tuple[NDArray, float, float]], message: str, steps: int, options: HBMOptions, end: BranchEnd
) -> FrequencyResponseBranch:
    a: list[Any] = list(zip(*pts, strict=True)) if pts else [[]] * 6
    return FrequencyResponseBranch(
        omega_rad_s=np.asarray(a[0], dtype=float),
        max_saddle_force_N=np.asarray(a[1], dtype=float),
        max_gap_m=np.asarray(a[2], dtype=float),
        max_cargo_deflection_m=np.asarray(a[3], dtype=float),
        converged=np.asarray(a[4], dtype=bool),
        contact_preserved=np.asarray(a[5], dtype=bool),
        message=message,
        steps=steps,
        options=options.to_dict(),
        end=end,
        compression_harmonics_m=np.stack([e[0] for e in extra]) if extra else np.zeros((0, 1, 1)),
        tangent_omega=np.array([e[1] for e in extra], dtype=float),
        residual_norm=np.array([e[2] for e in extra], dtype=float),
    )
