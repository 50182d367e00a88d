"""A window of the transient march: fine steps from a state until the march may stop, with the window's maxima.

:func:`march_window` calls the compiled step loop (:func:`~seafast.solvers.transient.kernels.march_steps`)
and returns a :class:`WindowOutcome`; :class:`MomentOutput` says how the bending moment is evaluated at
every step. The equations and the stopping rule are in :mod:`seafast.solvers.transient`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from seafast.solvers.transient.kernels import march_steps
from seafast.solvers.transient.newmark import MarchState, NewmarkStep

__all__ = ["MomentOutput", "WindowOutcome", "march_window"]


@dataclass(frozen=True)
class MomentOutput:
    """How the march evaluates the cargo's bending moment at every step (optional).

    ``M(x) = moment_static + basis @ [g(t), eta, c]`` with g the linear model's moment
    coordinates (the channels after the n_s compressions in the march's coefficients), so
    ``basis = [U | E Phi | E R]`` with E the moment-recovery map of the cargo DOFs.

    Attributes
    ----------
    moment_static_Nm
        (n_x,) still-water moment [N m].
    basis
        (n_x, n_r + m + n_s) [N m per unit coordinate].
    section_modulus_m3
        (n_x,) [m^3]; stress = |M| / modulus.
    """

    moment_static_Nm: NDArray[np.float64]
    basis: NDArray[np.float64]
    section_modulus_m3: NDArray[np.float64]


@dataclass(frozen=True)
class WindowOutcome:
    """What one call of :func:`march_window` found over steps start+1 .. end.

    Attributes
    ----------
    end
        Last fine step marched.
    max_saddle_force_N, max_compression_m, max_gap_m, max_bending_moment_Nm, max_bending_stress_Pa
        Maxima over the window (0 where nothing exceeded 0; moment and stress 0 without a
        :class:`MomentOutput`).
    lifted_steps
        Steps with at least one saddle detached.
    uplift_events
        Saddle separations (a saddle going from compressed to detached; summed over saddles).
    solved
        Every step's contact problem was solved exactly.
    """

    end: int
    max_saddle_force_N: float
    max_compression_m: float
    max_gap_m: float
    max_bending_moment_Nm: float
    max_bending_stress_Pa: float
    lifted_steps: int
    uplift_events: int
    solved: bool


def march_window(
    system: NewmarkStep,
    coefficients: NDArray[np.float64],
    ratio: int,
    delta_static_m: NDArray[np.float64],
    trigger: NDArray[np.bool_],
    start: int,
    stop: int,
    state: MarchState,
    *,
    tolerance_m: float,
    moments: MomentOutput | None = None,
    capture_every: int = 0,
    capture_compression: NDArray[np.float64] | None = None,
    capture_lifted: NDArray[np.bool_] | None = None,
) -> WindowOutcome:
    """March the correction system from fine step ``start`` until it may stop, or ``stop``.

    Parameters
    ----------
    system
        The Newmark operators of the reduced correction system (:func:`~seafast.solvers.transient.newmark_step`) for
        the fine step.
    coefficients
        Periodic cubic B-spline coefficients (n_tc, n_s [+ n_r]) of the dynamic linear
        compressions [m] (and the linear moment coordinates) on a coarse grid of ``ratio``
        fine steps per sample (``scipy.ndimage.spline_filter1d(..., mode='grid-wrap')``).
    delta_static_m
        (n_s,) still-water linear compression added to the dynamic part [m].
    trigger
        (n_tc,) coarse samples near which the march must go on (linear compression near or
        below zero).
    start, stop
        First (state) and last fine steps.
    state
        The state at ``start``; updated in place to the state at the end.
    tolerance_m
        Free-vibration bound below which a quiet march stops [m].
    moments
        Evaluate bending moment and stress maxima (optional).
    capture_every, capture_compression, capture_lifted
        Record the compression at steps that are multiples of ``capture_every`` into row
        ``p // capture_every`` of ``capture_compression`` (n_b, n_s), and mark the rows whose
        span had a detached saddle in ``capture_lifted``.
    """
    n_s = system.saddle_count
    reduced = system.reduced
    k = reduced.unilateral_stiffness_N_per_m
    if moments is None:
        ms, mb, mod = np.zeros(0), np.zeros((0, 1 + system.mode_count + n_s)), np.ones(0)
    else:
        ms, mb, mod = moments.moment_static_Nm, moments.basis, moments.section_modulus_m3
    cc = np.zeros((0, n_s)) if capture_compression is None else capture_compression
    cl = np.zeros((0, n_s), dtype=bool) if capture_lifted is None else capture_lifted
    tol_sign = 1e-12 * max(float(np.max(np.abs(delta_static_m))), float(np.max(np.abs(coefficients[:, :n_s]))), 1e-9)
    end, maxima, lifted, events, solved = march_steps(
        int(start),
        int(stop),
        float(ratio),
        coefficients,
        np.asarray(delta_static_m, dtype=float),
        trigger,
        system.time_step_s,
        system.predictor,
        system.force_response,
        reduced.saddle_mode_shape,
        system.receptance_m_per_N,
        k,
        system.set_inverses,
        reduced.natural_frequency_rad_s,
        system.mode_deflection_bound,
        float(tolerance_m),
        tol_sign,
        state.eta,
        state.eta_dot,
        state.eta_ddot,
        state.force_N,
        state.detached,
        ms,
        mb,
        mod,
        int(capture_every),
        cc,
        cl,
    )
    F, u_s, u_d, M, sigma = (float(v) for v in maxima)
    return WindowOutcome(int(end), F, u_s, u_d, M, sigma, int(lifted), int(events), bool(solved))
