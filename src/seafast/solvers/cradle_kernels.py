"""The compiled step loop of :func:`~seafast.solvers.cradle_window.march_cradle_window` (numba).

The same arithmetic as :func:`~seafast.solvers.cradle_march.march_step` and its contact solve
(:func:`~seafast.solvers.cradle_march.contact_correction_N` with ``sign``: the active set from the step before's, then
Murty's least-index principal pivoting), over a block of fine steps, with the window's maxima and stopping rule;
``tests/analyses/seastate/test_cradle_realisation.py`` checks it against that Python step to round-off.
Units: engagements [m]; forces [N].
"""

from __future__ import annotations

import numba
import numpy as np
from numpy.typing import NDArray

__all__ = ["march_block"]


@numba.njit(cache=True)
def _corrected(G: NDArray, kappa: NDArray, s_p: NDArray, chosen: NDArray) -> NDArray:  # pragma: no cover - compiled
    """``c = -kappa s`` on ``chosen``, 0 elsewhere, ``s = s_p - G c``."""
    m = s_p.size
    idx = np.flatnonzero(chosen)
    n = idx.size
    c = np.zeros(m)
    if n:
        mat = np.eye(n)
        rhs = np.empty(n)
        for a in range(n):
            rhs[a] = s_p[idx[a]]
            for b in range(n):
                mat[a, b] -= G[idx[a], idx[b]] * kappa[idx[b]]
        s_c = np.linalg.solve(mat, rhs)
        for a in range(n):
            c[idx[a]] = -kappa[idx[a]] * s_c[a]
    return c


@numba.njit(cache=True)
def _contact(G: NDArray, k: NDArray, sign: NDArray, s_p: NDArray, start: NDArray) -> tuple[NDArray, NDArray]:  # pragma: no cover
    """The exact correction of ``s = s_p - G c`` (``c = k max(-sign s, 0)``) and the corrected set."""
    kappa = sign * k
    m = s_p.size
    chosen = start.copy()
    for _ in range(m + 2):
        c = _corrected(G, kappa, s_p, chosen)
        new = sign * (s_p - G @ c) < 0.0
        if np.all(new == chosen) and np.all(c >= 0.0):
            return c, chosen
        chosen = new
    chosen = np.zeros(m, dtype=np.bool_)
    c = np.zeros(m)
    for _ in range(2 ** min(m, 30)):
        c = _corrected(G, kappa, s_p, chosen)
        s = s_p - G @ c
        first = -1
        for i in range(m):
            if (chosen[i] and c[i] < 0.0) or ((not chosen[i]) and sign[i] * s[i] < 0.0):
                first = i
                break
        if first < 0:
            break
        chosen[first] = not chosen[first]
    return np.maximum(c, 0.0), chosen


@numba.njit(cache=True)
def march_block(  # pragma: no cover - compiled
    ops: tuple[NDArray, NDArray, NDArray, NDArray, NDArray, NDArray, NDArray, NDArray, NDArray, NDArray],
    dt: float,
    rows: NDArray,
    x: NDArray,
    chosen: NDArray,
    trigger: NDArray,
    ratio: int,
    step: int,
    tolerance: float,
    tallies: tuple[NDArray, NDArray, NDArray, NDArray],
) -> tuple[NDArray, NDArray, int, bool, bool]:
    """March the fine steps of ``rows`` (count, m + p) from ``step``; stop early where the window may end.

    ``ops``: predictor, flexibility, ``A Phi``, ``G``, ``G - A Phi F``, k, sign, output modes (p, r), output
    residual (p, m), ``omega_r^2``. ``tallies`` (updated): largest and least forces (m,), largest ``|y|`` (p,),
    corrected steps (m,). Returns the state, corrected set, last step, whether the window ended, whether every
    corrected step met its complementarity conditions to round-off.
    """
    P, F, E, G, GAF, k, sign, Yo, Yr, w2 = ops
    hi, lo, out_max, corrected = tallies
    m, r, p = k.size, w2.size, Yo.shape[0]
    peak = np.zeros(r)
    for j in range(r):
        for i in range(m):
            peak[j] = max(peak[j], abs(E[i, j]))
    solved = True
    for n in range(rows.shape[0]):
        step += 1
        s_next = rows[n, :m]
        q_p = P @ x
        s_p = s_next + E @ q_p
        if (not chosen.any()) and np.all(sign * s_p >= 0.0):
            c = np.zeros(m)
            q = q_p
            s = s_p
        else:
            c, chosen = _contact(G, k, sign, s_p, chosen)
            q = q_p - F @ c
            s = s_next + E @ q - GAF @ c
        a = (4.0 / dt**2) * (q - x[:r]) - (4.0 / dt) * x[r : 2 * r] - x[2 * r :]
        v = x[r : 2 * r] + 0.5 * dt * (x[2 * r :] + a)
        x = np.concatenate((q, v, a))
        scale = 1.0
        for i in range(m):
            f = k[i] * max(s[i], 0.0)
            hi[i] = max(hi[i], f)
            lo[i] = min(lo[i], f)
            corrected[i] += chosen[i]
            scale = max(scale, abs(k[i] * s_next[i]) + 1.0)
        if c.any():
            for i in range(m):
                if abs(c[i] - k[i] * max(-sign[i] * s[i], 0.0)) > 1e-8 * scale:
                    solved = False
        if p:
            y = rows[n, m:] + Yo @ q + Yr @ c
            for i in range(p):
                out_max[i] = max(out_max[i], abs(y[i]))
        if step % ratio == 0 and not trigger[step // ratio] and not chosen.any() and not c.any():
            bound = 0.0
            for j in range(r):
                bound += peak[j] * np.sqrt(x[j] ** 2 + x[r + j] ** 2 / w2[j])
            if bound <= tolerance:
                return x, chosen, step, True, solved
    return x, chosen, step, False, solved
