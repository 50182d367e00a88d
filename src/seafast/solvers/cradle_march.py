"""The 3-D cargo's correction system marched in time over repeated wave periods (:func:`march_cradle`).

The start of the cradle harmonic balance where it does not converge on its own (strong lift-off), and the test of
what the steady state is: periodic with the wave, a subharmonic (repeating after several wave periods) or not
periodic within the periods marched.

With every element bilateral the cargo is linear; its periodic response ``s_lin(t)`` (harmonics 0 and 1) is the
condensed operators' (:func:`~seafast.solvers.cradle_dynamics.cradle_operators` with every element included).
The nonlinear response is ``q = q_lin + q_c`` with ``q_c`` the response of the same linear system to the
correction ``c = k max(-s, 0)`` (the tension a bilateral pad or stopper would carry, the compression of a
bilateral lashing, removed)::

    M q_c'' + D q_c' + K_lin q_c = -A^T c,    s = s_lin(t) + A q_c,

on every cargo DOF (dense: ``K_lin``, ``M``, ``D`` of :class:`~seafast.solvers.cradle_dynamics.CradleDynamics`),
by Newmark's average acceleration (no algorithmic damping) at ``T / N``. Per step the predictor ``q_p`` (no
new correction) gives ``s = s_p - G c`` with ``G = A K_eff^-1 A^T``, solved exactly for the correction by an
active set started from the step before (a linear complementarity problem with the positive definite
``diag(1/k) - G``: one solution). From rest (``q_c = 0``: the linear periodic solution), period after period.

The stepper and its step (:func:`cradle_stepper`, :func:`march_step`) also march any record of linear engagements with
some elements open in the linear system (the side stoppers: their correction is the force they carry once closed),
in windows along a sea state's record (:mod:`seafast.solvers.cradle_window`).

Units: engagements [m]; forces [N]; displacements [m, rad]; time [s].
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import StrEnum

import numpy as np
from numpy.typing import NDArray
from scipy.linalg import cholesky, eigh, solve_triangular
from scipy.optimize import nnls

from seafast.excitation.cradle_loads import CradleExcitation
from seafast.fourier import real_harmonics_to_time
from seafast.solvers.cradle_dynamics import CradleDynamics, cradle_operators

__all__ = [
    "MARCH_SAMPLES",
    "CradleMarch",
    "CradleStepper",
    "Periodicity",
    "contact_correction_N",
    "cradle_stepper",
    "march_cradle",
    "march_step",
    "newmark_advance",
    "pivoting_correction_N",
]

MARCH_SAMPLES = 2048
"""Steps per wave period of the march that starts the cradle's adaptive harmonic balance where no H converges
directly (about 17 per period of the highest ringing harmonic, 120, of the base case's beam-sea wave; 1024 with a lower
modal cutoff showed a spurious subharmonic there, and the verdict still depends on the step: docs/transverse.md)."""

SUBHARMONIC_ORDERS = (2, 3, 4, 5, 6)
"""The multiples of the wave period tried when the march does not repeat every period."""


STEPS_PER_MODE_PERIOD = 2
"""The default cutoff keeps the modes whose period spans at least this many steps (the step's Nyquist frequency:
Newmark's average acceleration is stable at any step; a lower cutoff, 4 steps a period at 1024 steps a wave period,
made the base case's beam-sea march at 1.3 times the wave look like a subharmonic of three periods)."""
STEPS_PER_MODE_PERIOD_INV = 1.0 / STEPS_PER_MODE_PERIOD


class Periodicity(StrEnum):
    """What the steady state marched to is.

    ``PERIODIC``: it repeats every wave period; ``SUBHARMONIC``: every ``period_multiple`` wave periods (2 to 6),
    not every one; ``NOT_PERIODIC``: neither within the periods marched (a slow transient, quasi-periodic or chaotic).
    """

    PERIODIC = "periodic"
    SUBHARMONIC = "subharmonic"
    NOT_PERIODIC = "not_periodic"


@dataclass(frozen=True)
class CradleMarch:
    """The last wave period of a march and how it repeats.

    Attributes
    ----------
    engagement_m
        Every element's engagement over the last wave period at ``t_n = n T / N`` (N, m) [m].
    element_force_N
        ``k max(s, 0)`` over the last wave period (N, m) [N]: exactly 0 where open or slack.
    periodicity, period_multiple
        What the steady state is (:class:`Periodicity`) and after how many wave periods it repeats (1 periodic,
        2 to 6 a subharmonic, 0 not periodic).
    periods
        Wave periods marched.
    period_change
        The largest change of an engagement over one wave period (the last against the one before), over the
        largest linear engagement amplitude [-], and at the lag ``period_multiple`` where subharmonic.
    lag_change
        That change at a lag of 1 to 6 wave periods (6,) [-] (NaN where fewer periods were kept).
    change_history
        The change over one wave period after each period marched (periods - 1,) [-]: decaying, a transient;
        level, a steady state that does not repeat every period.
    """

    engagement_m: NDArray[np.float64]
    element_force_N: NDArray[np.float64]
    periodicity: Periodicity
    period_multiple: int
    periods: int
    period_change: float
    lag_change: NDArray[np.float64]
    change_history: NDArray[np.float64]


@dataclass(frozen=True)
class CradleStepper:
    """Newmark's average acceleration for the correction system in the modes kept, at the step ``dt``.

    Attributes
    ----------
    predictor
        (r, 3 r): ``eta_p = P [eta; eta'; eta'']``.
    flexibility
        (r, m): ``K_eff^-1 Phi^T A^T`` [1/N in modal units].
    engagement_modes
        (m, r): ``A Phi`` [m per modal unit].
    receptance
        (m, m): ``G = A Phi K_eff^-1 Phi^T A^T + A R A^T`` [m/N].
    stiffness_N_per_m
        (m,) every element's k [N/m].
    dt
        The step [s].
    sign
        (m,) +1 for the elements bilateral in the linear system (the correction removes their tension), -1 for
        those open in it (the correction adds their compression); None: every element bilateral.
    modal_stiffness
        (r,) ``omega_r^2`` of the modes kept [rad^2/s^2].
    output_modes, output_residual
        (p, r) the rows of ``Phi`` and (p, m) of ``-R A^T`` at the output DOFs (:func:`cradle_stepper`), or None:
        their correction is ``output_modes @ eta + output_residual @ c`` [m, rad].
    """

    predictor: NDArray[np.float64]
    flexibility: NDArray[np.float64]
    engagement_modes: NDArray[np.float64]
    receptance: NDArray[np.float64]
    stiffness_N_per_m: NDArray[np.float64]
    dt: float
    sign: NDArray[np.float64] | None = None
    modal_stiffness: NDArray[np.float64] | None = None
    output_modes: NDArray[np.float64] | None = None
    output_residual: NDArray[np.float64] | None = None


def cradle_stepper(
    dynamics: CradleDynamics,
    dt: float,
    cutoff_rad_s: float,
    included: NDArray[np.bool_] | None = None,
    output_dofs: NDArray[np.intp] | None = None,
) -> CradleStepper:
    """The modes of ``(K_lin, M)`` up to ``cutoff_rad_s`` (their damping ``Phi^T D Phi`` kept whole), the others
    static (their residual flexibility ``A (K_lin^-1 - Phi Omega^-2 Phi^T) A^T``, exact whatever the cutoff).

    ``included``: the elements bilateral in ``K_lin`` (default every one); the others are open in the linear system
    and the correction closes them. ``output_dofs``: cargo DOFs whose correction the stepper also gives.
    """
    K = dynamics.linear_parts(included).bilateral_stiffness
    _, M, D = dynamics.matrices
    A, k = dynamics.problem.engagement_matrix, dynamics.problem.element_stiffness_N_per_m
    w2, phi = eigh(K, M)
    kept = w2 <= cutoff_rad_s**2
    w2, phi = w2[kept], phi[:, kept]
    B = phi.T @ A.T  # (r, m)
    static = np.linalg.solve(K, A.T)
    residual = A @ static - B.T @ (B / w2[:, None])
    r = w2.size
    eye, Xi, W = np.eye(r), phi.T @ D @ phi, np.diag(w2)
    K_eff = W + (2.0 / dt) * Xi + (4.0 / dt**2) * eye
    solved = np.linalg.solve(K_eff, np.hstack([(4.0 / dt**2) * eye + (2.0 / dt) * Xi, (4.0 / dt) * eye + Xi, eye, B]))
    flexibility = np.asarray(solved[:, 3 * r :], dtype=float)
    receptance = B.T @ flexibility + residual
    sign = None if included is None else np.where(np.asarray(included, dtype=bool), 1.0, -1.0)
    rows = None if output_dofs is None else np.asarray(output_dofs, dtype=np.intp)
    return CradleStepper(
        np.ascontiguousarray(solved[:, : 3 * r]),
        flexibility,
        np.ascontiguousarray(B.T),
        0.5 * (receptance + receptance.T),
        k,
        dt,
        sign,
        w2,
        None if rows is None else np.ascontiguousarray(phi[rows]),
        None if rows is None else -(static[rows] - phi[rows] @ (B / w2[:, None])),
    )


def contact_correction_N(
    receptance: NDArray[np.float64],
    k: NDArray[np.float64],
    s_p: NDArray[np.float64],
    open_set: NDArray[np.bool_],
    sign: NDArray[np.float64] | None = None,
) -> tuple[NDArray[np.float64], NDArray[np.bool_]]:
    """The exact correction ``c = k max(-s, 0)`` of ``s = s_p - G c`` [N], and the open set (s < 0).

    An active set started from ``open_set`` (the step before's); should it cycle (stiff elements make
    ``diag(1/k) - G`` ill-conditioned), the complementarity problem ``w = s_p + (diag(1/k) - G) c >= 0``,
    ``c >= 0``, ``w c = 0`` as the non-negative least squares of its Cholesky factor (Lawson-Hanson, exact).

    ``sign`` (m,): where -1 the element is open in the linear system and its correction is the force it carries,
    ``c = k max(s, 0)``; the corrected set is then where ``sign * s < 0``. With mixed signs the complementarity
    matrix ``diag(1/k) - diag(sign) G`` is not symmetric but positive definite (a P-matrix: one solution); the
    fallback is then Murty's least-index principal pivoting (finite for P-matrices).
    """
    if sign is not None and np.any(sign < 0.0):
        return _signed_correction(receptance, k, s_p, open_set, np.asarray(sign, dtype=float))
    open_ = open_set.copy()
    m = s_p.size
    for _ in range(m + 2):
        c = np.zeros(m)
        if np.any(open_):
            s_O = np.linalg.solve(np.eye(int(open_.sum())) - receptance[np.ix_(open_, open_)] * k[open_][None, :], s_p[open_])
            c[open_] = -k[open_] * s_O
        new = s_p - receptance @ c < 0.0
        if np.array_equal(new, open_) and np.all(c >= 0.0):
            return c, open_
        open_ = new
    lower = cholesky(np.diag(1.0 / k) - receptance, lower=True)
    c = nnls(lower.T, -solve_triangular(lower, s_p, lower=True))[0]
    return c, c > 0.0


def _corrected(receptance: NDArray, kappa: NDArray, s_p: NDArray, chosen: NDArray[np.bool_]) -> NDArray[np.float64]:
    """``c`` with ``c = -kappa s`` on ``chosen`` and 0 elsewhere, ``s = s_p - G c`` (``kappa = sign k``)."""
    c = np.zeros(s_p.size)
    if np.any(chosen):
        s_C = np.linalg.solve(np.eye(int(chosen.sum())) - receptance[np.ix_(chosen, chosen)] * kappa[chosen][None, :], s_p[chosen])
        c[chosen] = -kappa[chosen] * s_C
    return c


def _signed_correction(
    receptance: NDArray, k: NDArray, s_p: NDArray, start: NDArray[np.bool_], sign: NDArray
) -> tuple[NDArray[np.float64], NDArray[np.bool_]]:
    """:func:`contact_correction_N` with elements open in the linear system (``sign`` -1)."""
    kappa = sign * k
    chosen = start.copy()
    m = s_p.size
    for _ in range(m + 2):  # the active set from the step before's
        c = _corrected(receptance, kappa, s_p, chosen)
        new = sign * (s_p - receptance @ c) < 0.0
        if np.array_equal(new, chosen) and np.all(c >= 0.0):
            return c, chosen
        chosen = new
    return pivoting_correction_N(receptance, k, s_p, sign)


def pivoting_correction_N(
    receptance: NDArray[np.float64], k: NDArray[np.float64], s_p: NDArray[np.float64], sign: NDArray[np.float64]
) -> tuple[NDArray[np.float64], NDArray[np.bool_]]:
    """:func:`contact_correction_N` by Murty's least-index principal pivoting from the empty set: flip the first
    element that violates its condition (a corrected one with ``c < 0``, another with ``sign s < 0``) until none does;
    finite for the P-matrix ``diag(1/k) - diag(sign) G``. Returns ``c`` [N] and the corrected set."""
    kappa = sign * k
    m = s_p.size
    chosen = np.zeros(m, dtype=bool)
    c = np.zeros(m)
    for _ in range(2 ** min(m, 30)):
        c = _corrected(receptance, kappa, s_p, chosen)
        wrong = np.flatnonzero(np.where(chosen, c < 0.0, sign * (s_p - receptance @ c) < 0.0))
        if wrong.size == 0:
            break
        chosen[wrong[0]] = not chosen[wrong[0]]
    return np.maximum(c, 0.0), chosen


def march_step(
    stepper: CradleStepper, x: NDArray[np.float64], open_set: NDArray[np.bool_], s_next: NDArray[np.float64]
) -> tuple[NDArray[np.float64], NDArray[np.bool_], NDArray[np.float64], NDArray[np.float64]]:
    """One Newmark step of the correction system to the linear engagements ``s_next`` (m,) [m].

    ``x`` = (eta, eta', eta'') of the modes kept and the corrected set of the step before. Returns the new state
    and corrected set, every element's engagement ``s`` [m] and the correction ``c`` [N] at the end of the step.
    """
    dt = stepper.dt
    A, F, G, k = stepper.engagement_modes, stepper.flexibility, stepper.receptance, stepper.stiffness_N_per_m
    q_p = stepper.predictor @ x
    s_p = s_next + A @ q_p
    if not open_set.any() and not np.any((s_p if stepper.sign is None else stepper.sign * s_p) < 0.0):
        c, open_, q, s = np.zeros(s_p.size), open_set, q_p, s_p  # nothing to correct: the solve's answer, c = 0
    else:
        c, open_ = contact_correction_N(G, k, s_p, open_set, stepper.sign)
        q = q_p - F @ c
        s = s_next + A @ q - (G - A @ F) @ c
    return newmark_advance(x, q, dt), open_, s, c


def newmark_advance(x: NDArray[np.float64], q: NDArray[np.float64], dt: float) -> NDArray[np.float64]:
    """The state (q, q', q'') after a step of Newmark's average acceleration that ends at the displacements ``q``,
    from ``x`` = (q, q', q'') at its start [modal units, per s, per s^2]."""
    n = x.size // 3
    a = (4.0 / dt**2) * (q - x[:n]) - (4.0 / dt) * x[n : 2 * n] - x[2 * n :]
    v = x[n : 2 * n] + 0.5 * dt * (x[2 * n :] + a)
    return np.concatenate([q, v, a])


def _march_period(stepper: CradleStepper, s_lin: NDArray[np.float64], state: list[NDArray]) -> NDArray[np.float64]:
    """One wave period of N steps from ``state`` = [x = (q, v, a), open set] (updated); the engagements at t_1 .. t_N."""
    x, open_ = state
    N = s_lin.shape[0]
    out = np.empty_like(s_lin)
    for i in range(N):
        x, open_, out[i], _ = march_step(stepper, x, open_, s_lin[(i + 1) % N])
    state[0], state[1] = x, open_
    return np.roll(out, 1, axis=0)  # t_N is t_0 of the next period


def march_cradle(
    dynamics: CradleDynamics,
    excitation: CradleExcitation,
    time_samples: int = 2048,
    *,
    max_periods: int = 200,
    tolerance: float = 1e-6,
    cutoff_rad_s: float | None = None,
) -> CradleMarch:
    """March the correction system from the linear periodic solution until the engagements repeat.

    Parameters
    ----------
    dynamics, excitation
        The 3-D cargo on its cradles and its loads (:func:`~seafast.excitation.cradle_loads.cradle_excitation`).
    time_samples
        Steps per wave period N (the samples reported); enough for the modes the elements ring in (>= 16).
    max_periods
        Wave periods marched at most (>= 2 * 6 to test the subharmonics).
    tolerance
        Periodic when an engagement changes over one wave period (or ``period_multiple``) by at most this times
        the largest linear engagement amplitude [-].

    Returns
    -------
    CradleMarch
        The last period and what the steady state is; a subharmonic or non-periodic state is read on the last
        ``2 * 6`` periods marched.
    """
    N, P = int(time_samples), int(max_periods)
    if N < 16:
        raise ValueError(f"time_samples = {time_samples!r}: allowed an integer >= 16")
    if P < 2 * max(SUBHARMONIC_ORDERS):
        raise ValueError(f"max_periods = {max_periods!r}: allowed an integer >= {2 * max(SUBHARMONIC_ORDERS)}")
    m, k = len(dynamics.problem.engagements), dynamics.problem.element_stiffness_N_per_m
    ops = cradle_operators(dynamics, excitation, 1, np.ones(m, dtype=bool))
    s_lin = real_harmonics_to_time(ops.linear_compression_m, N)
    scale = max(float(np.max(np.abs(ops.linear_compression_m[1:]))), 1e-12)
    dt = 2.0 * np.pi / float(excitation.omega_rad_s) / N
    stepper = cradle_stepper(dynamics, dt, STEPS_PER_MODE_PERIOD_INV * 2.0 * np.pi / dt if cutoff_rad_s is None else float(cutoff_rad_s))
    r = stepper.flexibility.shape[0]
    state: list[NDArray] = [np.zeros(3 * r), np.zeros(m, dtype=bool)]
    kept: list[NDArray[np.float64]] = []
    lags = np.full(max(SUBHARMONIC_ORDERS), np.nan)
    history: list[float] = []
    periods = 0
    for periods in range(1, P + 1):
        kept.append(_march_period(stepper, s_lin, state))
        kept = kept[-(max(SUBHARMONIC_ORDERS) + 1) :]
        if len(kept) >= 2:
            lags[0] = float(np.max(np.abs(kept[-1] - kept[-2]))) / scale
            history.append(float(lags[0]))
            if lags[0] <= tolerance:
                return CradleMarch(
                    kept[-1], k * np.maximum(kept[-1], 0.0), Periodicity.PERIODIC, 1, periods, float(lags[0]), lags, np.array(history)
                )
    for lag in range(2, len(kept)):
        lags[lag - 1] = float(np.max(np.abs(kept[-1] - kept[-1 - lag]))) / scale
    for lag in SUBHARMONIC_ORDERS:
        if lags[lag - 1] <= tolerance:
            return CradleMarch(
                kept[-1],
                k * np.maximum(kept[-1], 0.0),
                Periodicity.SUBHARMONIC,
                lag,
                periods,
                float(lags[lag - 1]),
                lags,
                np.array(history),
            )
    return CradleMarch(
        kept[-1], k * np.maximum(kept[-1], 0.0), Periodicity.NOT_PERIODIC, 0, periods, float(lags[0]), lags, np.array(history)
    )
