"""The compiled kernels of the transient integrator: the step loop and each step's exact contact (numba).

:func:`march_steps` marches the reduced correction system step by step (predictor, the step's contact
problem by :func:`solve_step_contact`, the Newmark update, the window's maxima and captures), the linear
compressions read from periodic cubic B-spline coefficients (:func:`bspline_row`). Called through
:func:`seafast.solvers.transient.march_window`; the equations are in :mod:`seafast.solvers.transient`.
Compiled kernels are exempt from the house's function length (they are one loop each).
"""

from __future__ import annotations

import numba
import numpy as np
from numpy.typing import NDArray

__all__ = ["solve_step_contact", "bspline_row", "march_steps"]


@numba.njit(cache=True)
def solve_step_contact(  # pragma: no cover - compiled
    d_pred: NDArray, G: NDArray, k: NDArray, inverses: NDArray, detached: NDArray, tol: float
) -> tuple[NDArray, bool]:
    """Exact contact of one step; returns (delta, ok), updates ``detached`` in place."""
    n = d_pred.size
    delta = np.empty(n)
    use_table = inverses.shape[0] > 0
    for _ in range(4 * n + 8):
        code = 0
        any_det = False
        for s in range(n):
            if detached[s]:
                code += 1 << s
                any_det = True
        if not any_det:
            delta[:] = d_pred
        elif use_table:
            delta[:] = inverses[code] @ d_pred
        else:
            A = np.eye(n)
            for s in range(n):
                if detached[s]:
                    A[:, s] -= G[:, s] * k[s]
            delta[:] = np.linalg.solve(A, d_pred)
        consistent = True
        for s in range(n):
            if (detached[s] and delta[s] > tol) or ((not detached[s]) and delta[s] < -tol):
                consistent = False
        if consistent:
            return delta, True
        for s in range(n):
            detached[s] = delta[s] < 0.0
    if not use_table:
        return delta, False
    best = np.inf  # cycling: enumerate every set, keep the least violating
    best_code = 0
    for code in range(inverses.shape[0]):
        d = inverses[code] @ d_pred
        violation = 0.0
        for s in range(n):
            v = d[s] if (code >> s) & 1 else -d[s]
            violation = max(violation, v)
        if violation < best:
            best, best_code = violation, code
    delta[:] = inverses[best_code] @ d_pred
    for s in range(n):
        detached[s] = (best_code >> s) & 1 == 1
    return delta, best <= tol


@numba.njit(cache=True)
def bspline_row(coef: NDArray, x: float) -> NDArray:  # pragma: no cover - compiled
    """Cubic B-spline value of every channel at coarse position x (periodic coefficients (n, ch))."""
    n = coef.shape[0]
    i = int(np.floor(x))
    t = x - i
    w0 = (1.0 - t) ** 3 / 6.0
    w1 = (3.0 * t**3 - 6.0 * t**2 + 4.0) / 6.0
    w2 = (-3.0 * t**3 + 3.0 * t**2 + 3.0 * t + 1.0) / 6.0
    w3 = t**3 / 6.0
    return w0 * coef[(i - 1) % n] + w1 * coef[i % n] + w2 * coef[(i + 1) % n] + w3 * coef[(i + 2) % n]


@numba.njit(cache=True)
def march_steps(  # pragma: no cover - compiled
    start: int,
    stop: int,
    ratio: float,
    coef: NDArray,
    delta_static: NDArray,
    trigger: NDArray,
    dt: float,
    predictor: NDArray,
    force_response: NDArray,
    phi_b: NDArray,
    G: NDArray,
    k: NDArray,
    inverses: NDArray,
    omega: NDArray,
    mode_bound: NDArray,
    tol_state: float,
    tol_sign: float,
    eta: NDArray,
    deta: NDArray,
    ddeta: NDArray,
    c: NDArray,
    detached: NDArray,
    moment_static: NDArray,
    moment_basis: NDArray,
    modulus: NDArray,
    capture_every: int,
    capture_compression: NDArray,
    capture_lifted: NDArray,
) -> tuple[int, NDArray, int, int, bool]:
    """March from fine step ``start`` (state given, updated in place) until quiet and untriggered, or ``stop``.

    Fine step p is at coarse position p / ratio of the B-spline coefficients ``coef`` (n_tc,
    n_s + n_r): the first n_s channels are the dynamic linear compressions, the others the
    coefficients of the moment basis's linear part. Returns (end, maxima, lifted_steps, events,
    solved); maxima = [F, u_s, u_d, |M|, |sigma|] over the steps start+1 .. end.
    """
    n_s = delta_static.size
    m = omega.size
    n_x = moment_static.size
    n_h = moment_basis.shape[1]
    n_r = n_h - m - n_s
    state = np.empty(3 * m)
    h = np.empty(n_h)
    maxima = np.zeros(5)
    lifted_steps = 0
    events = 0
    solved = True
    n_tc = trigger.size
    n_b = capture_lifted.shape[0]
    was_detached = detached.copy()
    p = start
    while p < stop:
        p += 1
        x = p / ratio
        row = bspline_row(coef, x)
        d_lin = delta_static + row[:n_s]
        state[:m] = eta
        state[m : 2 * m] = deta
        state[2 * m :] = ddeta
        eta_p = predictor @ state
        delta, ok = solve_step_contact(d_lin - phi_b @ eta_p, G, k, inverses, detached, tol_sign)
        if not ok:
            solved = False
        for s in range(n_s):
            c[s] = k[s] * max(-delta[s], 0.0)
        eta_new = eta_p + force_response @ c
        ddeta_new = 4.0 / dt**2 * (eta_new - eta - dt * deta) - ddeta
        deta[:] = deta + 0.5 * dt * (ddeta + ddeta_new)
        ddeta[:] = ddeta_new
        eta[:] = eta_new
        # outputs at step p
        any_lift = False
        for s in range(n_s):
            d = delta[s]
            if k[s] * max(d, 0.0) > maxima[0]:
                maxima[0] = k[s] * max(d, 0.0)
            if d > maxima[1]:
                maxima[1] = d
            if -d > maxima[2]:
                maxima[2] = -d
            if d < 0.0:
                any_lift = True
                if not was_detached[s]:
                    events += 1
            was_detached[s] = d < 0.0
        if any_lift:
            lifted_steps += 1
        if n_x > 0:
            h[:n_r] = row[n_s:]
            h[n_r : n_r + m] = eta
            h[n_r + m :] = c
            moments = moment_static + moment_basis @ h
            for ix in range(n_x):
                a = abs(moments[ix])
                if a > maxima[3]:
                    maxima[3] = a
                if a / modulus[ix] > maxima[4]:
                    maxima[4] = a / modulus[ix]
        if capture_every > 0:
            b = p // capture_every
            if b < n_b:
                for s in range(n_s):
                    if delta[s] < 0.0:
                        capture_lifted[b, s] = True
                if p % capture_every == 0:
                    capture_compression[b] = delta
        # stop once every saddle is in contact, the caller's trigger is off and q_c is negligible
        if any_lift:
            continue
        i = int(np.floor(x)) % n_tc
        if trigger[i] or trigger[(i + 1) % n_tc]:
            continue
        bound = 0.0
        for r in range(m):
            bound += mode_bound[r] * np.sqrt(eta[r] ** 2 + (deta[r] / omega[r]) ** 2)
        if bound <= tol_state:
            break
    return p, maxima, lifted_steps, events, solved
