"""The compiled frictional step of :func:`~seafast.solvers.cradle_friction_record.march_friction_record` (numba).

The same arithmetic as the frictional march's step (:mod:`seafast.solvers.cradle_friction_march`): Newmark's average
acceleration in the modes kept, and per step the problem ``R(z) = z - z_p + G C(z)`` (the normal law and each pad's
friction-cone return map from the step before's sliders) solved by the semi-smooth Newton with its backtracking
line search, started from the step before's corrections and else from none; over a block of fine steps, with the
record's maxima. ``tests/solvers/test_cradle_friction_record.py`` checks it against that Python step to round-off.
Units: engagements and motions [m]; forces [N].
"""

from __future__ import annotations

import math

import numba
import numpy as np
from numpy.typing import NDArray

__all__ = ["march_friction_block"]

_NEWTON_ITERATIONS = 40
_HALVINGS = 7


@numba.njit(cache=True)
def _forces(
    z: NDArray, w_prev: NDArray, law: tuple, slope: bool, dC: NDArray, w: NDArray, slipped: NDArray
) -> NDArray:  # pragma: no cover - compiled
    """``C(z)``; the sliders ``w`` and where they slipped (out); with ``slope`` ``dC/dz`` into ``dC``."""
    k, kt, mu_kn, rest, m, P = law
    C = np.empty(m + 2 * P)
    if slope:
        dC[:, :] = 0.0
    for e in range(m):
        C[e] = k[e] * max(-z[e], 0.0)
        if slope and z[e] < 0.0:
            dC[e, e] = -k[e]
    for p in range(P):
        a = m + 2 * p
        wx, wy = w_prev[p, 0], w_prev[p, 1]
        fx, fy = kt[p] * (z[a] - wx), kt[p] * (z[a + 1] - wy)
        norm = math.hypot(fx, fy)
        cap = mu_kn[p] * max(z[p], 0.0)
        slipped[p] = norm > cap
        if slipped[p]:
            ex, ey = fx / norm, fy / norm
            wx, wy = z[a] - cap * ex / kt[p], z[a + 1] - cap * ey / kt[p]
            if slope:
                r = cap / norm
                dC[a, a] = -kt[p] * (1.0 - r * (1.0 - ex * ex))
                dC[a, a + 1] = -kt[p] * r * ex * ey
                dC[a + 1, a] = -kt[p] * r * ey * ex
                dC[a + 1, a + 1] = -kt[p] * (1.0 - r * (1.0 - ey * ey))
                if z[p] > 0.0:
                    dC[a, p] = ex * mu_kn[p]
                    dC[a + 1, p] = ey * mu_kn[p]
        w[p, 0], w[p, 1] = wx, wy
        C[a] = -kt[p] * (wx - rest[2 * p])
        C[a + 1] = -kt[p] * (wy - rest[2 * p + 1])
    return C


@numba.njit(cache=True)
def _solve_step(
    z_p: NDArray, C_prev: NDArray, w_prev: NDArray, G: NDArray, law: tuple, tol: float, w_out: NDArray, slipped_out: NDArray
) -> tuple[NDArray, NDArray, bool]:  # pragma: no cover - compiled
    """``(z, C, solved)`` of one step (sliders and slips into ``w_out``, ``slipped_out``): Newton from ``C_prev``,
    then from no correction; the best iterate where both miss ``tol``."""
    n = z_p.size
    P = w_prev.shape[0]
    dC, no_slope = np.zeros((n, n)), np.zeros((1, 1))
    w, slipped = np.empty((P, 2)), np.zeros(P, dtype=np.bool_)
    w_trial, slipped_trial = np.empty((P, 2)), np.zeros(P, dtype=np.bool_)
    best, best_z, best_C = np.inf, z_p.copy(), C_prev.copy()
    eye = np.eye(n)
    for attempt in range(2):
        z = z_p - G @ (C_prev if attempt == 0 else np.zeros(n))
        for _ in range(_NEWTON_ITERATIONS):
            C = _forces(z, w_prev, law, True, dC, w, slipped)
            R = z - z_p + G @ C
            norm = np.max(np.abs(R))
            if norm < best:
                best, best_z, best_C = norm, z.copy(), C.copy()
                w_out[:, :] = w
                slipped_out[:] = slipped
            if norm <= tol:
                return z, C, True
            step = np.linalg.solve(eye + G @ dC, -R)
            t, moved = 1.0, False
            for _ in range(_HALVINGS):
                trial = z + t * step
                C_trial = _forces(trial, w_prev, law, False, no_slope, w_trial, slipped_trial)
                if np.max(np.abs(trial - z_p + G @ C_trial)) < norm:
                    z, moved = trial, True
                    break
                t *= 0.5
            if not moved:
                z = z + step
    return best_z, best_C, False


@numba.njit(cache=True)
def march_friction_block(
    z_lin: NDArray, system: tuple, law: tuple, dt: float, tol: float, state: tuple, tally: tuple
) -> None:  # pragma: no cover - compiled
    """March the steps to ``z_lin[1:]`` from ``z_lin[0]``'s instant, updating ``state`` and ``tally`` in place.

    ``z_lin`` (n, m + 2 P + o): the stuck linear engagements, tangential motions and o outputs (cargo DOFs).
    ``system`` = (predictor, engagement/motion modes, flexibility, receptance G, the outputs' modes (o, r) and
    residual flexibility (o, m + 2 P)); ``law`` = (k (m,), k_t (P,), mu k_n (P,), sliders' rest (2 P,), m, P);
    ``state`` = (x (3 r,), C (m + 2 P,), w (P, 2)); ``tally`` = (largest and least force ``k max(s, 0)`` (m,),
    largest ``|f| / (mu F_n)`` (P,), largest ``|w - w_rest|`` (P,), counts (2,): steps with a slip, steps
    unresolved; largest ``|output|`` (o,), steps each element's engagement is below 0 (m,)).
    """
    predictor, modes, flexibility, G, output_modes, output_residual = system
    k, kt, mu_kn, rest, m, P = law
    x, C, w = state
    force_max, force_min, utilisation, slip_max, counts, output_max, negative = tally
    r, n_z = x.size // 3, m + 2 * P
    w_new, slipped = np.empty((P, 2)), np.zeros(P, dtype=np.bool_)
    for i in range(z_lin.shape[0] - 1):
        q_p = predictor @ x
        z, C_new, solved = _solve_step(z_lin[i + 1, :n_z] + modes @ q_p, C, w, G, law, tol, w_new, slipped)
        C[:] = C_new
        w[:, :] = w_new
        if np.any(slipped):
            counts[0] += 1
        if not solved:
            counts[1] += 1
        q = q_p - flexibility @ C
        a = (4.0 / dt**2) * (q - x[:r]) - (4.0 / dt) * x[r : 2 * r] - x[2 * r :]
        x[r : 2 * r] = x[r : 2 * r] + 0.5 * dt * (x[2 * r :] + a)
        x[:r] = q
        x[2 * r :] = a
        y = z_lin[i + 1, n_z:] + output_modes @ q + output_residual @ C
        for o in range(y.size):
            output_max[o] = max(output_max[o], abs(y[o]))
        for e in range(m):
            if z[e] < 0.0:
                negative[e] += 1
            f = k[e] * max(z[e], 0.0)
            force_max[e] = max(force_max[e], f)
            force_min[e] = min(force_min[e], f)
        for p in range(P):
            limit = mu_kn[p] * max(z[p], 0.0)
            if limit > 0.0:
                utilisation[p] = max(utilisation[p], kt[p] * math.hypot(z[m + 2 * p] - w[p, 0], z[m + 2 * p + 1] - w[p, 1]) / limit)
            slip_max[p] = max(slip_max[p], math.hypot(w[p, 0] - rest[2 * p], w[p, 1] - rest[2 * p + 1]))
