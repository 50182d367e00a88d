"""The two-dimensional Jenkins element of a pad: a tangential spring in series with a Coulomb slider on a cone.

The axial analysis's Jenkins element (:mod:`seafast.solvers.axial.jenkins`) generalised to a pad's two tangential
directions (circumferential, axial; :mod:`seafast.model.pad_friction`). With ``delta`` the pad's tangential
motion (2-vector) [m], ``w`` the slider's position [m], ``k_t`` the tangential stiffness [N/m] and ``C >= 0`` the
slider's limit [N] (``mu`` times the pad's normal force, 0 when the pad is open), the friction force resisting
``delta`` is ``f = k_t (delta - w)`` (on the cargo ``-f``) with ``|f| <= C``: a friction cone, not two
independent directions. Sample by sample, the return map scales the trial force radially::

    f_trial = k_t (delta_n - w_{n-1}),
    f_n = f_trial                              if |f_trial| <= C_n   (stick: the slider stays)
    f_n = C_n f_trial / |f_trial|               otherwise            (slip: the slider moves along f_n)
    w_n = delta_n - f_n / k_t.

In one direction this is the axial element's clamp. The history of a period is marched from a given slider
position, period after period, until the slider's position at the period's start repeats (a slip erases the
history along the slip, the perpendicular part fades with each slipping sample; without slip the slider never
moves and one period is periodic).

Derivatives (for Newton): ``d f_n = P_n d f_trial + e_n d C_n`` with ``P_n = I`` in stick and
``P_n = (C_n / |f_trial|) (I - e_n e_n^T)`` in slip (``e_n = f_n / |f_n|``, ``e_n = 0`` in stick), and
``d f_trial,n = k_t (d delta_n - d delta_{n-1}) + d f_{n-1}``: :func:`cone_sensitivity` carries them through the
same periods, column by column of a basis (the harmonics' samples), in forward mode.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

__all__ = ["ConePeriod", "cone_return_map", "march_cone", "cone_sensitivity"]


def cone_return_map(trial_N: NDArray[np.float64], capacity_N: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.bool_]]:
    """The force on the cone ``|f| <= C``: the trial (..., 2) [N] scaled radially where it exceeds ``C`` (...) [N].

    Returns the force (..., 2) [N] and where it slipped (...). ``C = 0`` gives exactly zero.
    """
    trial = np.asarray(trial_N, dtype=float)
    capacity = np.maximum(np.asarray(capacity_N, dtype=float), 0.0)
    norm = np.hypot(trial[..., 0], trial[..., 1])
    slipped = norm > capacity
    factor = np.where(slipped, capacity / np.where(slipped, norm, 1.0), 1.0)
    return trial * factor[..., None], slipped


@dataclass(frozen=True)
class ConePeriod:
    """The pads' Jenkins elements over one closed period (N samples, p pads).

    Attributes
    ----------
    force_N
        ``f = k_t (delta - w)`` (N, p, 2) [N]: the friction force resisting the tangential motion.
    slider_m
        ``w`` (N, p, 2) [m].
    slipped
        Where the slider moved at the sample (N, p).
    initial_slider_m
        The sliders' given positions before the first period marched (p, 2) [m].
    start_slider_m
        The slider's position before the returned period's first sample (p, 2) [m].
    periods
        Periods marched from the given start.
    start_change_m
        How far the slider's position at the period's start moved over the last period marched [m] (0: periodic).
    """

    force_N: NDArray[np.float64]
    slider_m: NDArray[np.float64]
    slipped: NDArray[np.bool_]
    initial_slider_m: NDArray[np.float64]
    start_slider_m: NDArray[np.float64]
    periods: int
    start_change_m: float


def _march_once(
    delta: NDArray[np.float64], capacity: NDArray[np.float64], k: NDArray[np.float64], w: NDArray[np.float64]
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.bool_]]:
    """One period of the return map from the sliders ``w`` (p, 2): (forces, sliders (N, p, 2), slipped (N, p)).

    Sample by sample and pad by pad in plain floats: a few pads' 2-vectors are far cheaper so than as arrays.
    """
    N, p = delta.shape[:2]
    d, c, kl = delta.tolist(), capacity.tolist(), k.tolist()
    wl = w.tolist()
    force, slider = np.empty((N, p, 2)), np.empty((N, p, 2))
    slipped = np.zeros((N, p), dtype=bool)
    for n in range(N):
        dn, cn = d[n], c[n]
        for i in range(p):
            ki = kl[i]
            (dx, dy), (wx, wy) = dn[i], wl[i]
            fx, fy = ki * (dx - wx), ki * (dy - wy)
            norm = math.hypot(fx, fy)
            if norm > cn[i]:
                scale = cn[i] / norm
                fx, fy = fx * scale, fy * scale
                slipped[n, i] = True
                wl[i] = [dx - fx / ki, dy - fy / ki]
            force[n, i] = (fx, fy)
            slider[n, i] = wl[i]
    return force, slider, slipped


def march_cone(
    delta_m: NDArray[np.float64],
    capacity_N: NDArray[np.float64],
    stiffness_N_per_m: NDArray[np.float64],
    initial_slider_m: NDArray[np.float64],
    *,
    max_periods: int = 50,
    tolerance_m: float = 1e-13,
) -> ConePeriod:
    """The periodic response of p Jenkins elements on a cone to the tangential motion ``delta_m``.

    Parameters
    ----------
    delta_m
        Tangential motion over one period (N, p, 2) [m], at ``t_n = n T / N``.
    capacity_N
        The sliders' limits ``mu max(F_n, 0)`` (N, p) [N].
    stiffness_N_per_m
        k_t of each element (p,) [N/m], > 0.
    initial_slider_m
        The sliders' positions before the first period (p, 2) [m] (they matter only where the slider never moves).
    max_periods
        Periods marched at most; the last is returned (``start_change_m`` says how far from periodic).
    tolerance_m
        Periodic when the start's slider moved by at most this [m] over a period.
    """
    delta = np.asarray(delta_m, dtype=float)
    capacity = np.maximum(np.asarray(capacity_N, dtype=float), 0.0)
    k = np.asarray(stiffness_N_per_m, dtype=float)
    w0 = np.array(initial_slider_m, dtype=float)
    w = w0
    periods = 0
    while True:
        force, slider, slipped = _march_once(delta, capacity, k, w)
        periods += 1
        change = float(np.max(np.abs(slider[-1] - w), initial=0.0))
        start, w = w, slider[-1]
        if change <= tolerance_m or periods >= int(max_periods):
            return ConePeriod(force, slider, slipped, w0, start, periods, change)


def cone_sensitivity(
    period: ConePeriod,
    delta_m: NDArray[np.float64],
    capacity_N: NDArray[np.float64],
    stiffness_N_per_m: NDArray[np.float64],
    delta_basis: NDArray[np.float64],
    capacity_basis: NDArray[np.float64],
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Forward-mode derivatives of the last period's forces along basis columns of the motion and of the limits.

    The perturbation ``d delta_n = e_b delta_basis[n, j]`` (each direction b, each column j) and
    ``d C_n = capacity_basis[n, p, j]``, carried through the same ``period.periods`` periods as :func:`march_cone`
    from its fixed initial slider (the module's recursion).

    Parameters
    ----------
    period
        :func:`march_cone`'s result for these inputs.
    delta_m, capacity_N, stiffness_N_per_m
        Its inputs (N, p, 2) [m], (N, p) [N], (p,) [N/m].
    delta_basis
        (N, J) [-]: e.g. the real inverse DFT matrix (the samples of each harmonic coefficient).
    capacity_basis
        (N, p, J) [N per unit of the column].

    Returns
    -------
    d_force_d_delta
        (N, p, 2, 2, J) [N/m]: ``d f_n[a] / d (column j of direction b)`` on the last period.
    d_force_d_capacity
        (N, p, 2, J) [-].
    """
    delta = np.asarray(delta_m, dtype=float)
    capacity = np.maximum(np.asarray(capacity_N, dtype=float), 0.0)
    N, p = delta.shape[:2]
    B, Bc = np.asarray(delta_basis, dtype=float), np.asarray(capacity_basis, dtype=float)
    J = B.shape[1]
    k = np.asarray(stiffness_N_per_m, dtype=float)
    kk = k[:, None]
    eye = np.eye(2)
    kI = (k[:, None, None] * eye[None]).reshape(p, 4, 1)  # (p, a b, 1)
    Dd, Dc = np.zeros((p, 4, J)), np.zeros((p, 2, J))  # d f[a] / d delta[b] flattened over (a, b); d f / d C
    out_d, out_c = np.empty((N, p, 4, J)), np.empty((N, p, 2, J))
    w = np.array(period.initial_slider_m, dtype=float)
    previous = np.zeros(J)  # the first period starts from a fixed slider
    for _ in range(period.periods):
        slider = _march_once(delta, capacity, k, w)[1]
        before = np.concatenate([w[None], slider[:-1]])
        w = slider[-1]
        trial = kk[None] * (delta - before)  # (N, p, 2)
        norm = np.hypot(trial[..., 0], trial[..., 1])
        slipped = norm > capacity
        safe = np.where(slipped, norm, 1.0)
        e = np.where(slipped[..., None], trial / safe[..., None], 0.0)
        P = np.where(slipped[..., None, None], (capacity / safe)[..., None, None] * (eye - e[..., :, None] * e[..., None, :]), eye)
        any_slip = slipped.any(axis=1)
        for n in range(N):
            Dd = Dd + kI * (B[n] - previous)
            if any_slip[n]:
                Dd = np.matmul(P[n], Dd.reshape(p, 2, 2 * J)).reshape(p, 4, J)
                Dc = np.matmul(P[n], Dc) + e[n][:, :, None] * Bc[n][:, None, :]
            out_d[n], out_c[n] = Dd, Dc
            previous = B[n]
    return out_d.reshape(N, p, 2, 2, J), out_c
