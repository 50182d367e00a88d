"""The adaptive choice of H: the harmonic balance solved at rising H until the saddle-force peaks settle.

The policy of :func:`~seafast.solvers.hbm.solve_hbm` with ``harmonics = None`` (docs/theory.md, section 5):

1. the periodic march chooses the first H and is the Newton start (:func:`~seafast.solvers.hbm.harmonics.select_harmonics`,
   asked for a quarter of the tolerance: its estimate is of the march's own truncation, and a first H with margin
   usually settles at the next step); a few Newton steps from there, no fallbacks;
2. if that fails, the robust route at few harmonics: the full fallback chain at
   :data:`~seafast.solvers.hbm.options.SAFE_HARMONICS` (or the march's H if smaller), from the quasi-static predictor;
3. then H rises 1.5-fold (at least by 8) from the previous solution (or from the march; a truncation that falls among
   the cargo's contact-state modes can be ill-posed, so then 2 H and 3 H from the march) until every saddle's peak
   force moved by less than the tolerance from the previous H (a one-step estimate of the truncation misses how a
   re-contact's impact peak converges), or ``max_harmonics``. Contact kept by the march: the linear solution with the
   excitation's harmonics is exact, nothing to settle.

The reported estimate is the larger of the truncation indicator and the last settling step.
"""

from __future__ import annotations

import logging
import math
from dataclasses import replace

import numpy as np
from numpy.typing import NDArray

from seafast.excitation.harmonic import HarmonicExcitation
from seafast.model.structure import StructuralModel
from seafast.solvers.hbm.condensed import CondensedOperators, condensed_operators
from seafast.solvers.hbm.fixed import QUICK_ITERATIONS, compression_harmonics, project_on_harmonics, solve_at_harmonics, with_truncation
from seafast.solvers.hbm.harmonics import HarmonicSelection, force_scale_N, pad_harmonics, select_harmonics, truncation_error
from seafast.solvers.hbm.options import SAFE_HARMONICS, HBMOptions
from seafast.solvers.outcome import HBMStart
from seafast.solvers.periodic import PeriodicResponse

__all__ = ["SELECTION_SHARE", "REFINEMENT_ATTEMPTS", "solve_adaptive"]

logger = logging.getLogger(__name__)

SELECTION_SHARE = 0.25
"""Share of the truncation tolerance the march's choice of the first H is asked for."""

REFINEMENT_ATTEMPTS: tuple[tuple[float, HBMStart], ...] = (
    (1.5, HBMStart.PREVIOUS_HARMONICS),
    (1.5, HBMStart.MARCH),
    (2.0, HBMStart.MARCH),
    (3.0, HBMStart.MARCH),
)
"""The next H (a factor of the current one) and its start, tried in turn until one converges."""


def solve_adaptive(model: StructuralModel, excitation: HarmonicExcitation, options: HBMOptions, given: NDArray | None) -> PeriodicResponse:
    """The harmonic balance with H chosen adaptively (see the module docstring).

    ``given``: a start, saddle compressions sampled over one period (N', n_s) [m], for the first H instead of
    the march. The response's ``options`` record the H path and the march.
    """
    selection = select_harmonics(
        model, excitation, tolerance=SELECTION_SHARE * options.truncation_tolerance, max_harmonics=options.max_harmonics
    )
    # the steps from the march (or from the previous H) are near the solution: a few Newton steps, no fallbacks
    quick = replace(options, continuation=False, max_iterations=min(int(options.max_iterations), QUICK_ITERATIONS))
    response, H, ops = _first_solve(model, excitation, options, quick, selection, given)
    response, H, harmonics_path, settle = _refine(model, excitation, options, quick, selection, response, H, ops)
    error = truncation_error(model, excitation.omega_rad_s, compression_harmonics(response, H), options.law)
    if np.all(np.isfinite(settle)):
        error = np.maximum(error, settle)
    logger.debug(
        "adaptive H: path %s (march of %d period(s) at %d samples), peaks settled to %.2g, estimate %.2g (tolerance %.2g)",
        harmonics_path,
        selection.march_periods,
        selection.march_samples,
        float(np.max(settle)),
        float(np.max(error, initial=0.0)),
        options.truncation_tolerance,
    )
    return with_truncation(_recorded(response, options, selection, harmonics_path, H), error, options.truncation_tolerance)


def _first_solve(
    model: StructuralModel,
    excitation: HarmonicExcitation,
    options: HBMOptions,
    quick: HBMOptions,
    selection: HarmonicSelection,
    given: NDArray | None,
) -> tuple[PeriodicResponse, int, CondensedOperators]:
    """The solve at the march's H (from the march, or the given start); if it fails, the robust route at few harmonics."""
    H = selection.harmonics
    ops = condensed_operators(model, excitation, H)
    if given is None:
        start, kind = selection.start_compression_m, HBMStart.MARCH
    else:
        start, kind = project_on_harmonics(given, H), HBMStart.GIVEN
    response = solve_at_harmonics(model, excitation, quick.with_harmonics(H), start, ops, kind)
    if not response.converged:
        # the full fallback chain from the quasi-static predictor (a given start has just failed), then the
        # refinement from there
        H = min(H, SAFE_HARMONICS)
        ops = condensed_operators(model, excitation, H)
        response = solve_at_harmonics(model, excitation, options.with_harmonics(H), None, ops)
    return response, H, ops


def _refine(
    model: StructuralModel,
    excitation: HarmonicExcitation,
    options: HBMOptions,
    quick: HBMOptions,
    selection: HarmonicSelection,
    response: PeriodicResponse,
    H: int,
    ops: CondensedOperators,
) -> tuple[PeriodicResponse, int, list[int], NDArray]:
    """Raise H until the peaks settle: (the last converged response, its H, the H path, each saddle's last settling step)."""
    harmonics_path = [H]
    settle = np.full(model.saddle_count, np.inf)
    while response.converged and H < options.max_harmonics and selection.march_periods > 0:
        if np.max(settle) <= options.truncation_tolerance:
            break
        previous = response
        response, H_next, ops = _next_harmonics(model, excitation, options, quick, selection, previous, H, ops)
        if not response.converged:
            response = previous  # keep the last converged solution; the estimate says how far from settled
            break
        scale = force_scale_N(np.max(response.saddle_force_time_N, axis=0))
        settle = np.abs(np.max(response.saddle_force_time_N, axis=0) - np.max(previous.saddle_force_time_N, axis=0)) / scale
        H = H_next
        harmonics_path.append(H)
    return response, H, harmonics_path, settle


def _next_harmonics(
    model: StructuralModel,
    excitation: HarmonicExcitation,
    options: HBMOptions,
    quick: HBMOptions,
    selection: HarmonicSelection,
    previous: PeriodicResponse,
    H: int,
    ops: CondensedOperators,
) -> tuple[PeriodicResponse, int, CondensedOperators]:
    """The solve at the next H: :data:`REFINEMENT_ATTEMPTS` in turn until one converges (or H reaches the bound)."""
    response, H_next = previous, H
    for factor, kind in REFINEMENT_ATTEMPTS:
        H_next = min(max(math.ceil(factor * H), H + 8), int(options.max_harmonics))
        ops = condensed_operators(model, excitation, H_next, reuse=ops)
        if kind is HBMStart.PREVIOUS_HARMONICS:
            start = pad_harmonics(compression_harmonics(previous, H), H_next)
        else:
            start = project_on_harmonics(selection.march_compression_m, H_next)
        response = solve_at_harmonics(model, excitation, quick.with_harmonics(H_next), start, ops, kind)
        if response.converged or H_next >= options.max_harmonics:
            break
    return response, H_next, ops


def _recorded(
    response: PeriodicResponse, options: HBMOptions, selection: HarmonicSelection, harmonics_path: list[int], H: int
) -> PeriodicResponse:
    """The response with the adaptive choice in its ``options`` and its message."""
    record = dict(response.options)
    record.update(
        harmonics_selection="adaptive",
        harmonics_path=harmonics_path,
        truncation_tolerance=float(options.truncation_tolerance),
        max_harmonics=int(options.max_harmonics),
        march_samples=selection.march_samples,
        march_periods=selection.march_periods,
        march_change=selection.march_change,
    )
    march = f"march of {selection.march_periods} period(s) at {selection.march_samples} samples"
    note = response.message + f"; H = {H} chosen adaptively (path {harmonics_path}; {march})"
    return replace(response, options=record, message=note)
