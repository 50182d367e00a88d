"""The Jenkins element over one period: the AFT time step of the axial harmonic balance.

A Jenkins element is a spring ``k`` in series with a Coulomb slider of capacity ``C(t) >= 0``.
With ``u`` the cargo's axial displacement and ``w`` the slider's position, the element's force
is ``f = k (u - w)`` and the slider moves only when ``|f|`` would exceed ``C``::

    w_n = clip(w_{n-1}, u_n - C_n / k, u_n + C_n / k)            (return mapping, sample by sample)

The history enters only through that clamp, and a composition of clamps is again a clamp
(``clip(clip(x, a1, b1), a2, b2) = clip(x, clip(a1, a2, b2), clip(b1, a2, b2))``), so the whole
march is a prefix scan (log2 N vectorised steps) instead of a Python loop over the samples. The
period closes after one pass: with ``(A, B)`` the clamp of the whole period, the state at the
period's start is ``w_0 = clip(w_init, A, B)`` and marching another period from it returns it
(clamps are idempotent). ``w_init = 0``: the cargo was set down with the contacts relaxed at
``u = 0``; it matters only when the slider never moves (pure stick).

Jacobian (for Newton): ``w_n`` equals ``u_s -+ C_s / k`` at the last sample ``s(n)`` where it
slipped (within the period, or the last slip of the previous period), so
``df_n/du_m = k (delta_nm - delta_m,s(n))``. Without any slip, the slider either keeps its
initial position (``df_n/du_m = k delta_nm``) or, when that position was clamped into the
period's band (a cargo locked off its as-placed position, at the edge of its lock range), sits
at the band's edge ``w = u_s -+ C_s / k`` of the sample ``s`` that bounds it, and follows it.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

__all__ = ["JenkinsPeriod", "march_jenkins", "clamp_prefix"]


def clamp_prefix(lo: NDArray[np.float64], hi: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Bounds ``(A_n, B_n)`` of the composition of the clamps ``[lo_0, hi_0] .. [lo_n, hi_n]`` (inclusive scan).

    ``clip(x, A_n, B_n)`` is ``x`` clamped successively to every interval up to ``n``.
    Requires ``lo <= hi``.
    """
    a = np.array(lo, dtype=float)
    b = np.array(hi, dtype=float)
    d = 1
    n = a.size
    while d < n:
        # earlier segment (ending at i - d) first, then the later one (ending at i)
        lo_d, hi_d = a[d:], b[d:]
        a_new = np.minimum(np.maximum(a[:-d], lo_d), hi_d)
        b_new = np.minimum(np.maximum(b[:-d], lo_d), hi_d)
        a[d:], b[d:] = a_new, b_new
        d *= 2
    return a, b


@dataclass(frozen=True)
class JenkinsPeriod:
    """The element over one closed period (arrays of the N samples).

    Attributes
    ----------
    force_N
        ``f = k (u - w)`` [N]: the force resisting ``u`` (on the cargo: ``-f``).
    slider_m
        ``w`` [m].
    slipped
        Where the slider moved at the sample (gross slip).
    last_slip
        ``s(n)``: index of the last slip sample at or before ``n`` (wrapping to the previous
        period); without slip the sample whose band edge holds the clamped start, or -1 where
        the slider keeps its initial position.
    slip_path_m
        Distance the slider travels over the period ``sum |w_n - w_(n-1)|`` [m] (0 when stuck).
    """

    force_N: NDArray[np.float64]
    slider_m: NDArray[np.float64]
    slipped: NDArray[np.bool_]
    last_slip: NDArray[np.intp]
    slip_path_m: float


def march_jenkins(
    u_m: NDArray[np.float64], capacity_N: NDArray[np.float64], stiffness_N_per_m: float, w_init_m: float = 0.0
) -> JenkinsPeriod:
    """The periodic response of the Jenkins element to the displacement samples ``u_m``.

    Parameters
    ----------
    u_m
        Displacement over one period, N samples [m].
    capacity_N
        Slider capacity at the samples [N], >= 0.
    stiffness_N_per_m
        Spring stiffness k [N/m], > 0.
    w_init_m
        Slider position before the first period [m] (matters only if it never slips).
    """
    u = np.asarray(u_m, dtype=float)
    half = np.asarray(capacity_N, dtype=float) / float(stiffness_N_per_m)
    lo, hi = u - half, u + half
    a, b = clamp_prefix(lo, hi)
    w0 = min(max(float(w_init_m), a[-1]), b[-1])  # state after one period: a fixed point of the period's clamp
    w = np.minimum(np.maximum(w0, a), b)
    prev = np.empty_like(w)
    prev[0] = w0
    prev[1:] = w[:-1]
    slipped = (prev < lo) | (prev > hi)
    idx = np.where(slipped, np.arange(u.size), -1)
    last = np.maximum.accumulate(idx)
    if slipped.any():
        last = np.where(last < 0, idx.max(), last)
    elif w0 != float(w_init_m):
        # no sample slips, but the start was clamped into the period's band [A, B] = [max lo, min hi]:
        # the slider sits at the edge of the band it touches, w = hi_s (or lo_s), and follows u_s
        last = np.full(u.size, int(np.argmin(hi)) if w0 < float(w_init_m) else int(np.argmax(lo)))
    return JenkinsPeriod(float(stiffness_N_per_m) * (u - w), w, slipped, last, float(np.sum(np.abs(w - prev))))
