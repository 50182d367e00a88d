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

Folds. Where omega turns over two steps (the middle point's omega beyond both neighbours') the
fold between them is located: the branch is cut by planes normal to the chord of the two steps
and omega on them is driven to its extreme by successive parabolic interpolation (a few corrector
solves), and that point is recorded in branch order (``at_fold``), so a fold is a computed point,
not a step stepped over. The points' omega decides, not the tangent's omega component: with the
exact contact law the AFT's sampled contact set changes along the branch, the residual is
piecewise linear in u, and near a fold the tangent of the piece a point lies on can point the
other way than the branch goes over a step (with N = 128 the branch itself zigzags over a sharp
fold: the sweep uses N >= 512, :data:`seafast.analyses.sweep.frequency.SWEEP_MIN_TIME_SAMPLES`).

Each point records the compression harmonics (for stability, moments and post-processing) and
the omega component of its unit tangent (:class:`~seafast.solvers.branch.FrequencyResponseBranch`).

Size: the predictor-corrector, the fold location and the round-off acceptance are one algorithm on
one scaled state (scales, tangent, corrector planes); apart, each would reach into the others.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from seafast.excitation.harmonic import HarmonicExcitation
from seafast.fourier import harmonics_to_time, real_dft_matrices, real_to_complex_harmonics
from seafast.model.structure import StructuralModel
from seafast.solvers.branch import BranchEnd, FrequencyResponseBranch
from seafast.solvers.contact import ContactLaw
from seafast.solvers.hbm import CondensedOperators, CondensedProblem, HBMOptions, condensed_operators, solve_condensed

__all__ = ["CONTINUATION_HARMONICS", "BranchEnd", "FrequencyResponseBranch", "frequency_response"]

CONTINUATION_HARMONICS = 10
"""H of a continuation (a frequency sweep) whose options leave ``harmonics`` unset: one branch is followed at a
fixed H, and every step of it solves the condensed system, so fewer than a single solve's
:data:`~seafast.solvers.hbm.options.SAFE_HARMONICS` (a deliberately different setting: speed along the branch)."""

_NOISE_FACTOR = 10.0  # a stalled corrector is accepted within this multiple of the point's round-off floor
_NOISE_CAP = 1e-5  # ... and never above this relative residual
_ROUND_OFF_SHIFTS = (1e-13, -1e-13, 3e-13)  # relative omega shifts that sample the round-off of the residual
_FOLD_BRACKET = 1e-3  # a fold is located when its bracket is below this share of the two steps around it
_FOLD_ITERATIONS = 16  # corrector solves spent on locating one fold at most


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

    def residual(self, u: NDArray, omega: float) -> tuple[NDArray, NDArray, CondensedProblem]:
        p = self.problem(omega)
        R, state = p.evaluate(u, self.law, 1.0)
        return R, state, p

    def d_residual_d_omega(self, u: NDArray, omega: float, R: NDArray | None = None) -> NDArray:
        """dR/domega [m s/rad]: central difference, or one-sided from ``R = R(u, omega)`` when given.

        The step 1e-4 omega keeps the residual's round-off (up to ~1e-7 of the compression scale) from dominating
        the difference; a step of 1e-6 omega made the tangent jitter and the step control stall on some BLAS builds.
        """
        h = 1e-4 * max(abs(omega), 1e-3)
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


@dataclass(frozen=True)
class _Point:
    """A corrected branch point in scaled variables: ``y = (u / u_scale, omega / w_scale)``."""

    y: NDArray
    iterations: int
    residual: float


@dataclass(frozen=True)
class _Tracer:
    """Predictor-corrector machinery of one branch in scaled variables (see the module docstring)."""

    branch: _Branch
    u_scale: float  # [m]
    w_scale: float  # [rad/s]
    r_scale: float  # [m]
    tolerance: float  # relative residual of the corrector
    iterations: int  # Newton iterations per corrector

    def unscale(self, y: NDArray) -> tuple[NDArray, float]:
        """(compression harmonics [m], omega [rad/s]) of a scaled point."""
        return y[:-1] * self.u_scale, float(y[-1] * self.w_scale)

    def tangent(self, u: NDArray, omega: float, previous: NDArray | None, direction: float = 1.0) -> NDArray:
        """Unit tangent in scaled variables, oriented as ``previous`` (or, without it, omega along ``direction``)."""
        _, state, p = self.branch.residual(u, omega)
        J = p.jacobian(state) * self.u_scale  # dR / d(u/u_scale)
        Rw = self.branch.d_residual_d_omega(u, omega) * self.w_scale
        n = u.size
        t: NDArray
        if previous is None:
            t = np.append(np.linalg.solve(J, -Rw), 1.0) * direction
        else:
            A = np.zeros((n + 1, n + 1))
            A[:n, :n], A[:n, n], A[n] = J, Rw, previous
            b = np.zeros(n + 1)
            b[n] = 1.0
            t = np.linalg.solve(A, b)
        return t / np.linalg.norm(t)

    def _augmented(self, yk: NDArray, y_pred: NDArray, t: NDArray) -> tuple[NDArray, tuple[NDArray, CondensedProblem, NDArray, float]]:
        uk, wk = self.unscale(yk)
        R, state, p = self.branch.residual(uk, wk)
        return np.append(R / self.r_scale, t @ (yk - y_pred)), (state, p, uk, wk)

    def correct(self, y_pred: NDArray, normal: NDArray) -> _Point | None:
        """The branch point on the plane ``normal . (y - y_pred) = 0`` by Newton from ``y_pred``, or None."""
        yk = y_pred.copy()
        try:
            F, (state, p, uk, wk) = self._augmented(yk, y_pred, normal)
            its = 0
            for its in range(1, self.iterations + 1):
                residual = float(np.max(np.abs(F[:-1])))
                if residual <= self.tolerance and abs(F[-1]) <= 1e-8:
                    return _Point(yk, its, residual)
                J = p.jacobian(state) * (self.u_scale / self.r_scale)
                column = self.branch.d_residual_d_omega(uk, wk, F[:-1] * self.r_scale) * (self.w_scale / self.r_scale)
                n = uk.size
                A = np.zeros((n + 1, n + 1))
                A[:n, :n], A[:n, n], A[n] = J, column, normal
                dy = np.linalg.solve(A, -F)
                norm0 = float(np.linalg.norm(F))
                lam = 1.0
                while lam >= 1.0 / 64:  # backtracking keeps the corrector from cycling at kinks
                    y_try = yk + lam * dy
                    if y_try[-1] > 0:
                        F_try, aux = self._augmented(y_try, y_pred, normal)
                        if np.linalg.norm(F_try) < (1.0 - 1e-4 * lam) * norm0:
                            break
                    lam *= 0.5
                else:
                    break
                yk, F, (state, p, uk, wk) = y_try, F_try, aux
            residual = float(np.max(np.abs(F[:-1])))
            if residual <= _NOISE_CAP and abs(F[-1]) <= 1e-6:
                # stalled: accept if the residual is at this point's round-off floor
                floor = self.branch.round_off(uk, wk, F[:-1] * self.r_scale) / self.r_scale
                if residual <= _NOISE_FACTOR * floor:
                    return _Point(yk, its, residual)
        except (np.linalg.LinAlgError, FloatingPointError):
            pass
        return None

    def locate_fold(self, before: _Point, at: _Point, after: _Point) -> _Point | None:
        """The extreme of omega along the branch near ``at``, whose omega lies beyond both its neighbours'.

        The branch is cut by the planes normal to the chord from ``before`` to ``after``; omega of
        the point on the plane at distance sigma is maximised (a fold at a maximum of omega) or
        minimised by successive parabolic interpolation through the best point and its two
        neighbours in sigma, safeguarded by bisection, until they lie within :data:`_FOLD_BRACKET`
        of the chord. Returns the extreme point if it is a new one (None if ``at`` stays the extreme
        or a corrector fails).
        """
        chord = after.y - before.y
        length = float(np.linalg.norm(chord))
        normal = chord / length
        sign = 1.0 if at.y[-1] > before.y[-1] else -1.0  # +1: a maximum of omega
        samples = sorted(((float(normal @ (q.y - before.y)), q) for q in (before, at, after)), key=lambda item: item[0])
        for _ in range(_FOLD_ITERATIONS):
            k = max(range(len(samples)), key=lambda j: sign * samples[j][1].y[-1])
            if k in (0, len(samples) - 1):
                break
            (s0, q0), (s1, q1), (s2, q2) = samples[k - 1 : k + 2]
            if s2 - s0 <= _FOLD_BRACKET * length:
                break
            w0, w1, w2 = q0.y[-1], q1.y[-1], q2.y[-1]
            curvature = (s1 - s0) * (w1 - w2) - (s1 - s2) * (w1 - w0)
            vertex = s1 - 0.5 * ((s1 - s0) ** 2 * (w1 - w2) - (s1 - s2) ** 2 * (w1 - w0)) / curvature if curvature != 0 else s1
            margin = 0.05 * (s2 - s0)
            if not (s0 + margin < vertex < s2 - margin) or abs(vertex - s1) < margin:
                vertex = 0.5 * (s1 + s2) if s2 - s1 > s1 - s0 else 0.5 * (s0 + s1)
            lo, hi = ((s0, q0), (s1, q1)) if vertex < s1 else ((s1, q1), (s2, q2))
            share = (vertex - lo[0]) / (hi[0] - lo[0])
            point = self.correct(lo[1].y + share * (hi[1].y - lo[1].y), normal)
            if point is None:
                break
            samples.insert(k if vertex < s1 else k + 1, (vertex, point))
        best = max(samples, key=lambda item: sign * item[1].y[-1])[1]
        return None if best is at else best


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
        The branch, with a located point at each fold (``at_fold``); points that could not be
        continued end it (``end`` and ``message`` say why). Never raises for non-convergence.
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
    H = CONTINUATION_HARMONICS if options.harmonics is None else int(options.harmonics)  # one branch, at a fixed H
    options = options.with_harmonics(H)
    branch = _Branch(model, excitation_at, options)
    w0, w1 = float(omega_start_rad_s), float(omega_end_rad_s)
    first = solve_condensed(branch.ops(w0), options)
    # scale the compressions by their linear *fluctuation* at the start, so that a resonance
    # (growing fluctuation) is resolved with small steps
    lin = branch.ops(w0).linear_compression_m
    u_scale = float(max(np.max(np.abs(lin[1:])) if lin.shape[0] > 1 else 0.0, 1e-3 * np.max(np.abs(lin)), 1e-9))
    r_scale = branch.ops(w0).compression_scale_m
    tracer = _Tracer(branch, u_scale, abs(w1 - w0), r_scale, max(float(options.tolerance), 1e-7), corrector_iterations)
    points = _Points(branch, (2 * H + 1, model.saddle_count))
    u = first.saddle_compression.ravel().copy()
    if not first.converged:
        points.record(u, w0, False, 0.0, first.residual_norm)
        return points.finish("the first point did not converge", 0, options, BranchEnd.FIRST_POINT_FAILED)
    t = tracer.tangent(u, w0, None, 1.0 if w1 > w0 else -1.0)
    points.record(u, w0, True, float(t[-1]), first.residual_norm)
    steps, message, ending = _trace(tracer, points, u, w0, w1, t, stop_when, max_points, (initial_step, min_step, max_step, max_omega_step))
    omega = float(points.omega[-1])
    if ending is BranchEnd.REACHED_END and omega != w1:
        # land exactly on omega_end (the corrector moves omega slightly off the predictor)
        end = solve_condensed(branch.ops(w1), options, initial_compression=points.harmonics[-1])
        if end.converged:
            if (w1 - w0) * (omega - w1) > 0:
                points.pop()
            points.record(end.saddle_compression.ravel(), w1, True, points.tangent_omega[-1], end.residual_norm)
    return points.finish(message, steps, options, ending)


def _trace(
    tracer: _Tracer,
    points: _Points,
    u: NDArray,
    omega: float,
    w1: float,
    t: NDArray,
    stop_when: Callable[[float, NDArray[np.float64]], bool] | None,
    max_points: int,
    steps_setting: tuple[float, float, float, float],
) -> tuple[int, str, BranchEnd]:
    """The predictor-corrector loop from the first point: (steps taken, message, how it ended)."""
    ds, min_step, max_step, max_omega_step = steps_setting
    w_scale = tracer.w_scale
    direction = 1.0 if w1 > omega else -1.0
    steps = 0
    recent = [_Point(np.append(u / tracer.u_scale, omega / w_scale), 0, 0.0)]  # the last accepted steps' points
    while len(points.omega) < max_points:
        if direction * (omega - w1) >= -1e-12 * w_scale:
            return steps, "reached omega_end", BranchEnd.REACHED_END
        y = np.append(u / tracer.u_scale, omega / w_scale)
        # limit the step in omega to max_omega_step of the span, and do not overshoot the end
        step_w = abs(t[-1]) * w_scale
        ds_try = min(ds, max_omega_step * w_scale / step_w) if step_w > 0 else ds
        if direction * t[-1] > 0:
            ds_end = (w1 / w_scale - y[-1]) / t[-1]
            if 0 < ds_end < ds_try * 1.05:
                ds_try = ds_end
        point = tracer.correct(y + ds_try * t, t)
        steps += 1
        if point is None:
            ds = 0.5 * ds_try
            if ds < min_step:
                return steps, f"step size fell below min_step at omega = {omega:.6g} rad/s", BranchEnd.STEP_BELOW_MIN
            continue
        u_new, w_new = tracer.unscale(point.y)
        t_new = tracer.tangent(u_new, w_new, t)
        if len(recent) == 2 and (point.y[-1] - recent[1].y[-1]) * (recent[1].y[-1] - recent[0].y[-1]) < 0:
            # omega turned at the previous point: locate the fold, record it in branch order
            fold = tracer.locate_fold(recent[0], recent[1], point)
            if fold is None:
                points.at_fold[-1] = True
            else:
                u_f, w_f = tracer.unscale(fold.y)
                ahead = float((fold.y - recent[1].y) @ (point.y - recent[0].y)) > 0
                points.record(u_f, w_f, True, float(tracer.tangent(u_f, w_f, t)[-1]), fold.residual, at_fold=True, before_last=not ahead)
        recent = [recent[-1], point]
        cos_angle = float(t_new @ t)
        u, omega, t = u_new, w_new, t_new
        points.record(u, omega, True, float(t[-1]), point.residual)
        if stop_when is not None and stop_when(omega, points.harmonics[-1].reshape(points.shape)):
            return steps, f"stopped at omega = {omega:.6g} rad/s by the caller's range check", BranchEnd.STOPPED
        if point.iterations <= 3 and cos_angle > np.cos(np.radians(5.0)):
            grow = 1.6
        elif point.iterations <= 6 and cos_angle > np.cos(np.radians(12.0)):
            grow = 1.0
        else:
            grow = 0.6
        ds = float(np.clip(ds_try * grow, min_step, max_step))
    return steps, f"stopped at max_points = {max_points}", BranchEnd.MAX_POINTS


class _Points:
    """The recorded branch points and their metrics, in continuation order."""

    def __init__(self, branch: _Branch, shape: tuple[int, int]):
        self.branch = branch
        self.shape = shape
        self.omega: list[float] = []
        self.metrics: list[tuple[float, float, float, bool]] = []
        self.converged: list[bool] = []
        self.harmonics: list[NDArray] = []
        self.tangent_omega: list[float] = []
        self.residual: list[float] = []
        self.at_fold: list[bool] = []

    def record(
        self, u: NDArray, omega: float, ok: bool, t_omega: float, residual: float, *, at_fold: bool = False, before_last: bool = False
    ) -> None:
        """Append a point (or insert it before the last one)."""
        i = len(self.omega) - 1 if before_last else len(self.omega)
        self.omega.insert(i, float(omega))
        self.metrics.insert(i, self.branch.metrics(u, omega))
        self.converged.insert(i, ok)
        self.harmonics.insert(i, np.asarray(u, dtype=float).ravel().copy())
        self.tangent_omega.insert(i, float(t_omega))
        self.residual.insert(i, float(residual))
        self.at_fold.insert(i, at_fold)

    def pop(self) -> None:
        for values in (self.omega, self.metrics, self.converged, self.harmonics, self.tangent_omega, self.residual, self.at_fold):
            values.pop()

    def finish(self, message: str, steps: int, options: HBMOptions, end: BranchEnd) -> FrequencyResponseBranch:
        m = np.array(self.metrics, dtype=float).reshape(-1, 4)
        return FrequencyResponseBranch(
            omega_rad_s=np.asarray(self.omega, dtype=float),
            max_saddle_force_N=m[:, 0],
            max_gap_m=m[:, 1],
            max_cargo_deflection_m=m[:, 2],
            converged=np.asarray(self.converged, dtype=bool),
            contact_preserved=m[:, 3].astype(bool),
            message=message,
            steps=steps,
            options=options.to_dict(),
            end=end,
            compression_harmonics_m=np.stack([h.reshape(self.shape) for h in self.harmonics]) if self.harmonics else np.zeros((0, 1, 1)),
            tangent_omega=np.asarray(self.tangent_omega, dtype=float),
            residual_norm=np.asarray(self.residual, dtype=float),
            at_fold=np.asarray(self.at_fold, dtype=bool),
        )
