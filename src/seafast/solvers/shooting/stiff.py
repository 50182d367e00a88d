"""The shooting on stiff saddles: which modal basis, how fine a grid to start, and the cutoff doubled until it settles.

With stiff saddles a lifted state's stiffness on the bilateral modes is a difference of huge numbers
(:attr:`~seafast.solvers.shooting.states.ContactStates.cancellation`). :func:`correction_system` then reduces the
correction system on the lifted cargo's modes instead (:class:`~seafast.solvers.modal_correction.CorrectionBasis`),
the period marches are guarded (no impact between two samples is missed, and each peak is found in continuous
time: :func:`~seafast.solvers.shooting.period.flow_period`), and :func:`settled_cutoff` doubles the cutoff until the
peak forces settle (or keeps every mode): docs/theory.md, section 5.8.

Units: SI (m, rad, N, s). Nothing here prints, reads or writes files.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import replace

import numpy as np

from seafast.excitation.harmonic import HarmonicExcitation
from seafast.model.structure import StructuralModel
from seafast.solvers.hbm.harmonics import force_scale_N
from seafast.solvers.modal_correction import CorrectionBasis, ModalCorrectionSystem, UnsupportedBasisError, modal_correction_system
from seafast.solvers.outcome import SolverOutcome
from seafast.solvers.periodic import PeriodicResponse
from seafast.solvers.shooting.failure import FAILURE_KEY, ShootingFailure, shooting_failure
from seafast.solvers.shooting.options import ShootingOptions
from seafast.solvers.shooting.states import stiffness_cancellation

__all__ = [
    "COMPLETE_BASIS_DOFS",
    "MAX_CUTOFF_DOUBLINGS",
    "MODAL_TOLERANCE",
    "STIFF_CANCELLATION",
    "STIFF_SAMPLES_FACTOR",
    "correction_system",
    "settled_cutoff",
]

STIFF_CANCELLATION = 1e8
"""Above this stiffness cancellation (:attr:`~seafast.solvers.shooting.states.ContactStates.cancellation`; 1e7 on
1.1e10 N/m saddles, 1.6e9 on 1e14 N/m) the correction system is reduced on the lifted cargo's modes (where the lashings
hold it), and the cutoff is doubled until the peaks settle."""

MODAL_TOLERANCE = 1e-3
"""Largest change of a saddle's peak force (over its force scale) the cutoff check accepts."""

STIFF_SAMPLES_FACTOR = 8
"""For stiff saddles' impacts, once the cutoff has settled: up to this multiple of ``max_samples`` (2^19 by default)."""

MAX_CUTOFF_DOUBLINGS = 6
"""Doublings of the cutoff at most (x 64); then every mode of a model of at most :data:`COMPLETE_BASIS_DOFS` DOFs."""

COMPLETE_BASIS_DOFS = 400
"""Cargo DOFs at most for the last resort of the cutoff check: every mode kept (no reduction left), the march guarded."""


def correction_system(model: StructuralModel, cutoff_rad_s: float, opts: ShootingOptions) -> ModalCorrectionSystem:
    """The reduced correction system the shooting marches: the modes up to ``cutoff_rad_s`` of the basis chosen.

    ``opts.basis`` None: the bilateral saddles' modes, unless the state with every saddle lifted cancels more than
    :data:`STIFF_CANCELLATION` of their stiffness (stiff saddles) and the lashings hold the lifted cargo: then the
    lifted cargo's modes, on which contact adds stiffness instead (:class:`CorrectionBasis`).
    """
    n_s = model.saddle_count
    if opts.basis is not None:
        return modal_correction_system(model, cutoff_rad_s, minimum_modes=n_s, basis=opts.basis)
    bilateral = modal_correction_system(model, cutoff_rad_s, minimum_modes=n_s)
    if stiffness_cancellation(bilateral, np.ones(n_s, dtype=bool)) <= STIFF_CANCELLATION:
        return bilateral
    try:
        return modal_correction_system(model, cutoff_rad_s, minimum_modes=n_s, basis=CorrectionBasis.LIFTED)
    except UnsupportedBasisError:
        return bilateral  # no lashing holds the lifted cargo: the bilateral modes, checked at twice the cutoff


Solve = Callable[[StructuralModel, HarmonicExcitation, ShootingOptions], PeriodicResponse]
"""The shooting solve (:func:`~seafast.solvers.shooting.solve_shooting`), passed in: it calls this module."""


def settled_cutoff(
    solve: Solve,
    model: StructuralModel,
    excitation: HarmonicExcitation,
    opts: ShootingOptions,
    coarse: PeriodicResponse,
    cancellation: float,
) -> PeriodicResponse:
    """The solve with the cutoff doubled until no saddle's peak force moves by more than :data:`MODAL_TOLERANCE`.

    ``solve``: the shooting solve; ``coarse``: its converged answer at ``opts.cutoff_factor`` (on stiff saddles;
    ``cancellation``: its states' stiffness cancellation). Each doubling is solved in full; the finest solve is
    returned once its peaks are within :data:`MODAL_TOLERANCE` of the previous one's, or once it keeps every mode of
    the model (no residual flexibility: the reduction is exact; after :data:`MAX_CUTOFF_DOUBLINGS`, a model of at most
    :data:`COMPLETE_BASIS_DOFS` DOFs is solved with every mode); if its grid still misses more than
    ``opts.peak_tolerance`` of a peak force, it is solved once more with up to :data:`STIFF_SAMPLES_FACTOR` times
    ``opts.max_samples`` samples a period. Otherwise -- a doubled solve does not converge, :data:`MAX_CUTOFF_DOUBLINGS`
    are spent, or the finest grid still misses a peak -- the last converged one is
    returned not converged, with why. The changes are recorded
    (``cutoff_check_change``: the last one; ``cutoff_doublings``: how many; the message lists each).
    """
    current, factor = coarse, float(opts.cutoff_factor)
    changes: list[float] = []
    why, reason = "", ShootingFailure.CUTOFF_NOT_SETTLED
    while True:
        if len(changes) >= MAX_CUTOFF_DOUBLINGS and math.isfinite(factor) and model.cargo_dof_count <= COMPLETE_BASIS_DOFS:
            factor = math.inf / 2.0  # doubled below: every mode of the model, the reduction exact
        elif len(changes) >= MAX_CUTOFF_DOUBLINGS:
            why = f"the peak forces still move {changes[-1]:.2g} after {len(changes)} doublings of the cutoff"
            unresolved = current.options.get("peak_missed_by_grid", 0.0)
            if isinstance(unresolved, float) and unresolved > opts.peak_tolerance:
                # the changes measured on a grid that misses part of the impacts: the grid, not the modes, is why
                why += f", on an event grid of {current.time_samples} samples per period missing {unresolved:.2g} of a peak force"
                reason = ShootingFailure.IMPACTS_UNRESOLVED
            break
        factor *= 2.0
        finer = solve(model, excitation, replace(opts, cutoff_factor=factor, cutoff_check=False))
        if not finer.converged:
            why = f"the solve with the cutoff factor {factor:g} is not converged ({finer.message})"
            reason = shooting_failure(finer) or ShootingFailure.NOT_PERIODIC
            break
        changes.append(_peak_change(current, finer))
        current = finer
        if changes[-1] <= MODAL_TOLERANCE or current.options.get("complete_basis"):
            break
    last = changes[-1] if changes else math.inf
    record = dict(current.options, stiffness_cancellation=float(cancellation), cutoff_check_change=last, cutoff_doublings=len(changes))
    steps = ", ".join(f"{c:.2g}" for c in changes)
    note = f"{current.message}; cutoff settled by doubling (peak force changes {steps})"
    if current.options.get("complete_basis") and changes and changes[-1] > MODAL_TOLERANCE:
        note += "; every mode of the model kept: the reduction is exact"
    if why and cancellation > STIFF_CANCELLATION:
        why += f" (bilateral modes, a lifted state cancelling {cancellation:.1e} of their stiffness: no lashing holds the lifted cargo)"
    if why:
        note += f"; not converged in the modal reduction: {why}"
        record[FAILURE_KEY] = reason
        return replace(current, outcome=SolverOutcome.NOT_CONVERGED, message=note, options=record)
    missed = current.options.get("peak_missed_by_grid", 0.0)
    assert isinstance(missed, float)
    if missed > opts.peak_tolerance:
        # impacts shorter than the grid allowed resolves: the settled cutoff once more on finer grids
        current, grid_note = _finer_grids(solve, model, excitation, replace(opts, cutoff_factor=factor, cutoff_check=False), current)
        record = dict(current.options, **{k: v for k, v in record.items() if k not in current.options})
        note = f"{current.message}; cutoff settled by doubling (peak force changes {steps}){grid_note}"
    return replace(current, message=note, options=record)


def _finer_grids(
    solve: Solve, model: StructuralModel, excitation: HarmonicExcitation, opts: ShootingOptions, current: PeriodicResponse
) -> tuple[PeriodicResponse, str]:
    """The solve on up to half, then all of :data:`STIFF_SAMPLES_FACTOR` times ``opts.max_samples`` samples a period.

    Accepted when its grid misses at most ``opts.peak_tolerance`` of a peak (the closed-form estimate between
    samples), or when its sampled peak forces are within ``opts.peak_tolerance`` of the previous grid's (the grid's
    own measured convergence). Else the finest is returned not converged, with why. Returns it and a note.
    """
    previous = None
    for factor in (STIFF_SAMPLES_FACTOR // 2, STIFF_SAMPLES_FACTOR):
        finer = solve(model, excitation, replace(opts, max_samples=factor * opts.max_samples))
        if not finer.converged:
            failed = dict(current.options, **{FAILURE_KEY: shooting_failure(finer) or ShootingFailure.NOT_PERIODIC})
            note = f"; not converged on a finer event grid ({finer.message})"
            return replace(current, outcome=SolverOutcome.NOT_CONVERGED, options=failed), note
        missed = finer.options.get("peak_missed_by_grid", 0.0)
        assert isinstance(missed, float)
        if missed <= opts.peak_tolerance:
            return finer, ""
        if previous is not None and _peak_change(previous, finer) <= opts.peak_tolerance:
            change = _peak_change(previous, finer)
            return finer, f"; sampled peak forces within {change:.2g} of those on half the samples"
        previous = finer
    why = (
        f"; not converged on the event grid: {finer.time_samples} samples per period (the most allowed) miss {missed:.2g} of a peak "
        f"force (impacts shorter than the grid resolves)"
    )
    failed = dict(finer.options, **{FAILURE_KEY: ShootingFailure.IMPACTS_UNRESOLVED})
    return replace(finer, outcome=SolverOutcome.NOT_CONVERGED, options=failed), why


def _peak_change(coarse: PeriodicResponse, finer: PeriodicResponse) -> float:
    """How far each saddle's peak force moves to the finer solve's, over its force scale (the largest over saddles) [-]."""
    peaks_N, other = np.max(coarse.saddle_force_time_N, axis=0), np.max(finer.saddle_force_time_N, axis=0)
    return float(np.max(np.abs(other - peaks_N) / force_scale_N(np.maximum(other, peaks_N)), initial=0.0))
