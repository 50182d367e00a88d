"""Hydrostatic balance of the hull girder: the sinkage and trim at which buoyancy carries the weight.

The local draught is ``d(x) = T + sinkage - trim (x - x_mid) + zeta(x)``; sinkage [m] (deeper +)
and trim [rad] (bow up +) are solved by Newton so that the net force and moment on the hull
vanish, vectorised over any number of wave surfaces ``zeta``. While no section emerges the two
conditions are linear, so one step is exact; emergence is handled by continuing Newton, and a
hull that leaves the water raises :class:`HydrostaticBalanceError`. Conventions:
:mod:`seafast.hull`.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from seafast.hull.girder import HullGirder, resultant_weights

__all__ = ["HydrostaticBalanceError", "hydrostatic_balance"]

FloatArray = NDArray[np.float64]


class HydrostaticBalanceError(ValueError):
    """The hull girder finds no hydrostatic balance on the given wave (the hull leaves the water); the message says why."""


def hydrostatic_balance(
    girder: HullGirder,
    x: FloatArray,
    wa: FloatArray,
    wb: FloatArray,
    zeta: NDArray,
    max_iter: int = 50,
) -> tuple[NDArray, NDArray, NDArray, NDArray, NDArray]:
    """Sinkage and trim that balance the element weights; vectorised over leading axes of ``zeta``.

    Returns sinkage, trim (shape lead), nodal buoyancy (lead + (n_x,)) and element load ends
    qa, qb (lead + (n_el,)).
    """
    h = np.diff(x)
    rgc = girder.buoyancy_per_draught_N_per_m2
    breadth = girder.hull.breadth_at(x)
    xm = girder.midship_x_m
    T = girder.hull.draft_m
    lead = zeta.shape[:-1]
    s = np.zeros(lead)
    tr = np.zeros(lead)
    L = girder.length_m
    # (V(L), M(L)) are linear in the nodal buoyancy b: b @ W minus the weight's resultants; the
    # derivatives in sinkage and trim follow with the weights of db/ds and db/dtrim = -(x - xm) db/ds
    start, end = resultant_weights(h)
    W = np.zeros((x.size, 2))
    W[:-1] += start
    W[1:] += end
    W_jac = np.concatenate([W, -(x - xm)[:, None] * W], axis=1)  # columns: d/ds (V, M), d/dtrim (V, M)
    weight_resultants = wa @ start + wb @ end
    rb = rgc * breadth
    level = T + zeta
    for _ in range(max_iter):
        d = level + s[..., None] - tr[..., None] * (x - xm)
        wet = d > 0
        R = (rb * np.where(wet, d, 0.0)) @ W - weight_resultants
        J = ((rb * wet) @ W_jac).reshape(lead + (2, 2)).swapaxes(-1, -2)  # (..., 2 equations, 2 unknowns)
        delta = np.linalg.solve(J, -R[..., None])[..., 0]
        s = s + delta[..., 0]
        tr = tr + delta[..., 1]
        if np.all(np.abs(delta[..., 0]) < 1e-13 * T) and np.all(np.abs(delta[..., 1]) * L < 1e-13 * T):
            break
    else:
        worst = float(np.max(np.abs(R) / np.maximum(np.abs(weight_resultants), 1.0)))
        raise HydrostaticBalanceError(
            f"hull girder: no hydrostatic balance (sinkage and trim) found in {max_iter} Newton steps on a wave surface "
            f"of up to {float(np.max(np.abs(zeta))):.3g} m against the draught {T:.3g} m (residual {worst:.2e} of the "
            "weight): the hull leaves the water over much of its length, which the quasi-static wall-sided model "
            "does not describe; check the wave amplitude (metres, half the wave height) and the loading"
        )
    d = T + s[..., None] - tr[..., None] * (x - xm) + zeta
    b = rgc * breadth * np.maximum(d, 0.0)
    qa = b[..., :-1] - wa
    qb = b[..., 1:] - wb
    return s, tr, b, qa, qb
