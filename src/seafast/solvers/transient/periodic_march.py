"""One period of linear compressions marched over and over until the compressions repeat (:func:`march_periodic`).

The start of the high-harmonic harmonic balance (:mod:`seafast.solvers.hbm.harmonics`) and of the stepped-sine
sweep: from rest, the periodic state the physical system settles on from the linear periodic solution.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray
from scipy.ndimage import spline_filter1d

from seafast.solvers.transient.newmark import MarchState, NewmarkStep
from seafast.solvers.transient.window import march_window

__all__ = ["PeriodicMarch", "march_periodic", "march_period"]


@dataclass(frozen=True)
class PeriodicMarch:
    """The periodic state a march of one repeated period settled on.

    Attributes
    ----------
    compression_m
        The last period's compressions at ``t_n = n T / N`` (N, n_s) [m].
    periods
        Periods marched.
    change
        Last largest change of the compressions between two periods, over the largest linear compression [-].
    """

    compression_m: NDArray[np.float64]
    periods: int
    change: float


def march_periodic(
    system: NewmarkStep,
    linear_compression_m: NDArray[np.float64],
    *,
    max_periods: int = 50,
    tolerance: float = 1e-6,
) -> PeriodicMarch:
    """March one period of linear compressions over and over, from rest, until the compressions repeat.

    From rest with no correction force, the start is the linear periodic solution: the periodic state
    reached is the one the physical system settles on from there.

    Parameters
    ----------
    system
        The reduced correction system for the step ``T / N`` (the samples are the steps).
    linear_compression_m
        ``delta_lin`` over one period at ``t_n = n T / N``, (N, n_s) [m].
    max_periods, tolerance
        Stop when the largest change of ``delta`` between two periods is below ``tolerance`` times the
        largest linear compression, or after ``max_periods``.
    """
    d_lin = np.ascontiguousarray(linear_compression_m, dtype=float)
    n_s = d_lin.shape[1]
    if n_s != system.saddle_count:
        raise ValueError(f"linear_compression_m has {n_s} columns; the model has {system.saddle_count} saddles")
    scale = max(float(np.max(np.abs(d_lin))), 1e-12)
    state = MarchState.at_rest(system)
    previous: NDArray[np.float64] | None = None
    change = np.inf
    periods = 0
    delta = d_lin
    for periods in range(1, int(max_periods) + 1):  # noqa: B007 - the count is returned
        delta = march_period(system, d_lin, state)
        if previous is not None:
            change = float(np.max(np.abs(delta - previous))) / scale
            if change <= tolerance:
                break
        previous = delta
    return PeriodicMarch(delta, periods, change)


def march_period(system: NewmarkStep, linear_compression_m: NDArray[np.float64], state: MarchState) -> NDArray[np.float64]:
    """March one period of periodic linear compressions from ``state`` (updated in place to the period's end).

    Parameters
    ----------
    system
        The reduced correction system for the step ``T / N``.
    linear_compression_m
        ``delta_lin`` over one period at ``t_n = n T / N``, (N, n_s) [m] (step N is step 0 again).
    state
        The state at ``t_0``.

    Returns
    -------
    The compressions at ``t_0 .. t_{N-1}`` of this period (N, n_s) [m], ``t_0`` being the state's own.
    """
    d_lin = np.ascontiguousarray(linear_compression_m, dtype=float)
    N, n_s = d_lin.shape
    coef = np.ascontiguousarray(spline_filter1d(d_lin, order=3, axis=0, mode="grid-wrap"))  # periodic: step N is step 0
    captured = np.empty((N + 1, n_s))
    lifted = np.zeros((N + 1, n_s), dtype=bool)
    captured[0] = d_lin[0] - system.saddle_displacement_m(state.eta, state.force_N)
    march_window(
        system,
        coef,
        1,
        np.zeros(n_s),
        np.ones(N, dtype=bool),
        0,
        N,
        state,
        tolerance_m=0.0,
        capture_every=1,
        capture_compression=captured,
        capture_lifted=lifted,
    )
    return np.roll(captured[1:], 1, axis=0)  # t_1 .. t_N, and t_N is t_0 of the next period
