"""The one-way coupling's size: how much the friction's moment would change the saddle forces (docs/axial.md#one-way-coupling).

The friction acts at the saddles' contact line, about D/2 below the cargo's axis, so it puts a
bow-up moment ``f_i D/2`` on the cargo at each saddle, which the vertical model does not carry.
The estimate is the quasi-static response of the cargo on bilateral saddles to those moments.
"""

from __future__ import annotations

import numpy as np
from scipy.linalg import solveh_banded

from seafast.model.structure import StructuralModel

__all__ = ["friction_moment_effect_N", "saddle_moment_flexibility"]


def saddle_moment_flexibility(model: StructuralModel) -> np.ndarray:
    """Saddle compression change per unit moment at each saddle, quasi-static, bilateral saddles [m/(N m)], (n_s, n_s).

    ``G[i, j]``: ``-dz_i`` at saddle i for a unit bow-up moment on the cargo at saddle j, from one
    banded Cholesky solve of ``K dq = M`` (the cargo's first natural frequency, 44 rad/s on the
    base case, is far above the wave's 0.6 rad/s).
    """
    K = model.cargo.stiffness + model.spring_matrices(True)[0]
    n = K.shape[0]
    band = 3  # Hermite beam elements couple the (z, theta) pairs of neighbouring nodes; springs are diagonal
    ab = np.zeros((band + 1, n))
    for d in range(band + 1):
        ab[band - d, d:] = np.diagonal(K, d)
    rhs = np.zeros((n, model.saddle_count))
    rhs[model.saddle_cargo_dof + 1, np.arange(model.saddle_count)] = 1.0
    dq = solveh_banded(ab, rhs)
    return -dq[model.saddle_cargo_dof]


def friction_moment_effect_N(
    model: StructuralModel, friction_per_saddle_N: np.ndarray, lever_m: np.ndarray, flexibility: np.ndarray | None = None
) -> float:
    """Largest change of the saddle forces [N] by the friction's moment, quasi-static, bilateral saddles.

    Friction ``f_i`` (forward +) at the contact line ``lever_i`` (D/2) below the cargo's axis
    puts the moment ``+f_i lever_i`` (bow up) on the cargo at saddle ``i``; the saddle forces
    change by ``k_u G M`` (:func:`saddle_moment_flexibility`).
    """
    moments = np.asarray(friction_per_saddle_N, dtype=float) * np.asarray(lever_m, dtype=float)  # (N, n_s)
    if not np.any(moments):
        return 0.0
    G = saddle_moment_flexibility(model) if flexibility is None else flexibility
    return float(np.max(np.abs(model.saddle_unilateral_stiffness_N_per_m[:, None] * (G @ moments.T))))
