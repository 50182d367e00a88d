"""A whole record marched from its first sample to its last (:func:`integrate_record`)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray
from scipy.ndimage import spline_filter1d

from seafast.solvers.transient.newmark import MarchState, NewmarkStep
from seafast.solvers.transient.window import march_window

__all__ = ["TransientRecord", "integrate_record"]


@dataclass(frozen=True)
class TransientRecord:
    """One record marched from its first sample to its last.

    Attributes
    ----------
    time_s
        Sample times ``t_n = n dt`` [s] (n_t,).
    compression_m
        Nonlinear saddle compression ``delta = delta_lin - B^T q_c`` (n_t, n_s) [m].
    saddle_force_N
        Compression-only saddle force ``k_u max(delta, 0)`` (n_t, n_s) [N], upward on the cargo.
    solved
        Every step's contact problem was solved exactly.
    """

    time_s: NDArray[np.float64]
    compression_m: NDArray[np.float64]
    saddle_force_N: NDArray[np.float64]
    solved: bool


def integrate_record(system: NewmarkStep, linear_compression_m: NDArray, *, initial: MarchState | None = None) -> TransientRecord:
    """March one record of linear compressions sampled at the integrator's step.

    Parameters
    ----------
    system
        The reduced correction system for the step dt of the samples.
    linear_compression_m
        ``delta_lin`` at ``t_n = n dt`` (n_t, n_s) [m], still water included.
    initial
        State at t_0; default the quasi-static exact-contact state of ``delta_lin(t_0)``
        (q_c = 0 when every saddle is compressed).
    """
    d_lin = np.atleast_2d(np.asarray(linear_compression_m, dtype=float))
    n_t, n_s = d_lin.shape
    if n_s != system.saddle_count:
        raise ValueError(f"linear_compression_m has {n_s} columns; the model has {system.saddle_count} saddles")
    state = initial if initial is not None else MarchState.quasi_static(system, d_lin[0])
    # at integer positions the interpolating spline returns the samples themselves
    coef = np.ascontiguousarray(spline_filter1d(d_lin, order=3, axis=0, mode="grid-wrap"))
    compression = np.empty((n_t, n_s))
    lifted = np.zeros((n_t, n_s), dtype=bool)
    compression[0] = d_lin[0] - system.saddle_displacement_m(state.eta, state.force_N)
    outcome = march_window(
        system,
        coef,
        1,
        np.zeros(n_s),
        np.ones(n_t, dtype=bool),
        0,
        n_t - 1,
        state,
        tolerance_m=0.0,
        capture_every=1,
        capture_compression=compression,
        capture_lifted=lifted,
    )
    return TransientRecord(
        np.asarray(np.arange(n_t) * system.time_step_s, dtype=np.float64),
        compression,
        system.reduced.unilateral_stiffness_N_per_m * np.maximum(compression, 0.0),
        outcome.solved,
    )
