"""The entry points of the harmonic balance: :func:`solve_hbm` and :func:`solve_condensed`."""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass, replace

import numpy as np
from numpy.typing import NDArray

from seafast.config.modes import Formulation, SolverMethod
from seafast.excitation.harmonic import HarmonicExcitation
from seafast.fourier import (
    complex_to_real_harmonics,
    harmonics_to_time,
    high_harmonic_energy_share,
    real_dft_matrices,
    real_to_complex_harmonics,
    time_to_harmonics,
)
from seafast.model.structure import StructuralModel
from seafast.solvers.hbm.condensed import CondensedOperators, CondensedProblem, condensed_operators
from seafast.solvers.hbm.full import FullProblem
from seafast.solvers.hbm.harmonics import force_scale_N, pad_harmonics, select_harmonics, truncation_error
from seafast.solvers.hbm.nonlinear import solve_with_fallback
from seafast.solvers.hbm.options import SAFE_HARMONICS, HBMOptions
from seafast.solvers.outcome import SolverOutcome, SolverWarning
from seafast.solvers.periodic import PeriodicResponse

__all__ = ["CondensedSolution", "solve_condensed", "solve_hbm"]

logger = logging.getLogger(__name__)

_QUICK_ITERATIONS = 40  # Newton steps from a start near the solution (the march, or the previous H)
_SELECTION_SHARE = 0.25  # of the truncation tolerance, for the march's choice of the first H


@dataclass(frozen=True)
class CondensedSolution:
    """Raw condensed HBM solution (for continuation and post-processing).

    ``saddle_compression`` is the real coefficient array (2H+1, n_s) [m]; ``correction_force``
    the real coefficients (2H+1, n_s) [N] of ``c = f(delta) - k_u delta``.
    """

    saddle_compression: NDArray[np.float64]
    correction_force: NDArray[np.float64]
    outcome: SolverOutcome
    residual_norm: float
    iterations: int
    function_evaluations: int
    message: str

    @property
    def converged(self) -> bool:
        """Whether the solve met the tolerance (from :attr:`outcome`)."""
        return self.outcome.converged


def solve_condensed(
    ops: CondensedOperators,
    options: HBMOptions,
    initial_compression: NDArray | None = None,
) -> CondensedSolution:
    """Solve the condensed HBM system for given operators (used by :func:`solve_hbm` and continuation)."""
    if options.time_samples is None or options.harmonics != ops.harmonics:
        options = options.with_harmonics(ops.harmonics)
    problem = CondensedProblem(ops, options.fixed_grid()[1])
    u0 = None if initial_compression is None else np.asarray(initial_compression, dtype=float).ravel()
    a = solve_with_fallback(problem, options.law, options, u0)
    U = a.u.reshape(problem.n_h, problem.n_s)
    delta = problem.to_samples(U)
    corr = problem.to_harmonics(options.law.force(delta, problem.k_u) - problem.k_u * delta)
    return CondensedSolution(U, corr, a.outcome, a.residual, a.iterations, a.evaluations, a.note)


def solve_hbm(
    model: StructuralModel,
    excitation: HarmonicExcitation,
    options: HBMOptions | None = None,
    *,
    initial_compression_m: NDArray | None = None,
) -> PeriodicResponse:
    """Periodic steady state with unilateral saddles by harmonic balance + AFT.

    Parameters
    ----------
    model
        The cargo and sea-fastening model.
    excitation
        Deck motion and vessel loads per harmonic (harmonics above ``options.harmonics`` are
        dropped, with ``SolverWarning.HARMONICS_ABOVE_H_IGNORED`` in ``warnings``). The model's static load (gravity, pretension) is
        added at k = 0. With ``harmonics = 0`` only the static part is solved: the nonlinear
        static solution.
    options
        :class:`HBMOptions` (defaults: exact contact law, H chosen adaptively until the saddle-force
        peaks settle to 0.1 %, condensed, Newton). :data:`~seafast.solvers.hbm.options.SOURCE_OPTIONS`
        is the source's method.
    initial_compression_m
        Optional start: saddle compressions sampled over one period at ``t_n = n T / N'``, (N', n_s)
        [m], any N' (e.g. a neighbouring solution's ``saddle_compression_time_m``; condensed
        formulation only); projected on the harmonics solved for. Default: the adaptive choice's
        periodic march (adaptive H), else the better of the linear solution and the quasi-static
        predictor.

    Returns
    -------
    PeriodicResponse
        ``method = "hbm"``; ``outcome`` ``CONVERGED`` (direct solve),
        ``CONVERGED_BY_CONTINUATION`` or ``NOT_CONVERGED`` (never raised). Its
        ``residual_norm`` is relative (see :class:`HBMOptions` ``tolerance``);
        ``truncation_error`` estimates each saddle's peak-force error from the harmonics left out;
        ``options`` records the H and N used (and, adaptive, how they were chosen).
    """
    options = HBMOptions() if options is None else options
    given = None
    if initial_compression_m is not None:
        given = np.asarray(initial_compression_m, dtype=float)
        if given.ndim != 2 or given.shape[1] != model.saddle_count or given.shape[0] < 2:
            raise ValueError(f"initial_compression_m: shape {given.shape}; must be (samples, n_saddles = {model.saddle_count})")
    if options.harmonics is not None:  # a fixed H (not options.adaptive)
        H = int(options.harmonics)
        fixed = options.with_harmonics(H)
        start = None if given is None else _project(given, H)
        if H > SAFE_HARMONICS and options.formulation is Formulation.CONDENSED:
            response = _solve_fixed_many_harmonics(model, excitation, fixed, start)
        else:
            response = _solve_fixed(model, excitation, fixed, start)
        if H == 0:
            return response
        error = truncation_error(model, excitation.omega_rad_s, _compression_harmonics(response, H), fixed.law)
        return _with_truncation(response, error, options.truncation_tolerance)
    # the march asks for a quarter of the tolerance: its estimate is of the march's own truncation, and a first H
    # with margin usually settles at the next step (base case: 144, 216 instead of 120, 180, 270)
    selection = select_harmonics(
        model, excitation, tolerance=_SELECTION_SHARE * options.truncation_tolerance, max_harmonics=options.max_harmonics
    )
    H = selection.harmonics
    # the steps from the march (or from the previous H) are near the solution: a few Newton steps, no fallbacks
    quick = replace(options, continuation=False, max_iterations=min(int(options.max_iterations), _QUICK_ITERATIONS))
    ops = condensed_operators(model, excitation, H)
    response = _solve_fixed(
        model, excitation, quick.with_harmonics(H), selection.start_compression_m if given is None else _project(given, H), ops
    )
    if not response.converged:
        # the robust route at few harmonics: the full fallback chain from the quasi-static predictor (a given
        # start has just failed), then the refinement below from there
        H = min(H, SAFE_HARMONICS)
        ops = condensed_operators(model, excitation, H)
        response = _solve_fixed(model, excitation, options.with_harmonics(H), None, ops)
    path = [H]
    settle = np.full(model.saddle_count, np.inf)
    # "settled": the peaks moved by less than the tolerance from the previous H. The first H comes from the
    # march; a second, 1.5 times larger, is solved to see the peaks settle (a one-step estimate of the
    # truncation misses how a re-contact's impact peak converges). Contact kept by the march: the linear
    # solution with the excitation's harmonics is exact, nothing to settle.
    while response.converged and H < options.max_harmonics and selection.march_periods > 0:
        if np.max(settle) <= options.truncation_tolerance:
            break
        previous = response
        # 1.5 H from the previous solution, else from the march; a truncation that falls among the cargo's
        # contact-state modes can be ill-posed, so then 2 H and 3 H (from the march) before giving up
        attempts = [(1.5, "previous"), (1.5, "march"), (2.0, "march"), (3.0, "march")]
        for factor, origin in attempts:
            H_next = min(max(math.ceil(factor * H), H + 8), int(options.max_harmonics))
            ops = condensed_operators(model, excitation, H_next, reuse=ops)
            if origin == "previous":
                start = pad_harmonics(_compression_harmonics(previous, H), H_next)
            else:
                start = _project(selection.march_compression_m, H_next)
            response = _solve_fixed(model, excitation, quick.with_harmonics(H_next), start, ops)
            if response.converged or H_next >= options.max_harmonics:
                break
        if not response.converged:
            response = previous  # keep the last converged solution; the estimate below says how far from settled
            break
        scale = force_scale_N(np.max(response.saddle_force_time_N, axis=0))
        settle = np.abs(np.max(response.saddle_force_time_N, axis=0) - np.max(previous.saddle_force_time_N, axis=0)) / scale
        H = H_next
        path.append(H)
    error = truncation_error(model, excitation.omega_rad_s, _compression_harmonics(response, H), options.law)
    if np.all(np.isfinite(settle)):
        error = np.maximum(error, settle)
    logger.debug(
        "adaptive H: path %s (march of %d period(s) at %d samples), peaks settled to %.2g, estimate %.2g (tolerance %.2g)",
        path,
        selection.march_periods,
        selection.march_samples,
        float(np.max(settle)),
        float(np.max(error, initial=0.0)),
        options.truncation_tolerance,
    )
    record = dict(response.options)
    record.update(
        harmonics_selection="adaptive",
        harmonics_path=path,
        truncation_tolerance=float(options.truncation_tolerance),
        max_harmonics=int(options.max_harmonics),
        march_samples=selection.march_samples,
        march_periods=selection.march_periods,
        march_change=selection.march_change,
    )
    note = (
        response.message
        + f"; H = {H} chosen adaptively (path {path}; march of {selection.march_periods} period(s) at {selection.march_samples} samples)"
    )
    return _with_truncation(replace(response, options=record, message=note), error, options.truncation_tolerance)


def _solve_fixed_many_harmonics(
    model: StructuralModel, excitation: HarmonicExcitation, options: HBMOptions, start: NDArray | None
) -> PeriodicResponse:
    """A fixed H above :data:`~seafast.solvers.hbm.options.SAFE_HARMONICS`: a few Newton steps from the given start, then from the periodic
    march (the start from which the semi-smooth Newton converges at many harmonics), and only then the full
    fallback chain, whose continuation costs minutes at hundreds of harmonics."""
    H = int(options.harmonics or 0)
    quick = replace(options, continuation=False, max_iterations=min(int(options.max_iterations), _QUICK_ITERATIONS))
    ops = condensed_operators(model, excitation, H)
    if start is not None:
        response = _solve_fixed(model, excitation, quick, start, ops)
        if response.converged:
            return response
    selection = select_harmonics(model, excitation, tolerance=options.truncation_tolerance, max_harmonics=max(H, 1))
    if selection.march_periods > 0:
        response = _solve_fixed(model, excitation, quick, _project(selection.march_compression_m, H), ops)
        if response.converged:
            return replace(response, message=response.message + "; started from the periodic march")
    return _solve_fixed(model, excitation, options, start, ops)


def _with_truncation(response: PeriodicResponse, error: NDArray, tolerance: float) -> PeriodicResponse:
    """The response with its truncation estimate, and the typed warning when it exceeds the tolerance."""
    warnings = response.warnings
    if response.converged and float(np.max(error, initial=0.0)) > tolerance:
        logger.warning(
            "harmonic balance: H = %s leaves an estimated %.2g of a saddle's peak force out (tolerance %.2g)",
            response.options.get("harmonics"),
            float(np.max(error)),
            tolerance,
        )
        warnings = warnings + (SolverWarning.TOO_FEW_HARMONICS,)
    return replace(response, truncation_error=error, warnings=warnings)


def _project(samples: NDArray, harmonics: int) -> NDArray:
    """Real-layout harmonics 0 .. H of periodic samples (N', n_s) (an exact DFT projection)."""
    X = time_to_harmonics(samples, min(harmonics, samples.shape[0] // 2))
    C = np.zeros((harmonics + 1, samples.shape[1]), dtype=complex)
    C[: X.shape[0]] = X  # harmonics the samples cannot resolve are zero
    return complex_to_real_harmonics(C)


def _compression_harmonics(response: PeriodicResponse, harmonics: int) -> NDArray:
    return _project(response.saddle_compression_time_m, harmonics)


def _solve_fixed(
    model: StructuralModel,
    excitation: HarmonicExcitation,
    options: HBMOptions,
    start: NDArray | None,
    ops: CondensedOperators | None = None,
) -> PeriodicResponse:
    """One harmonic-balance solve at the options' H and N (start: real-layout compression harmonics; ``ops``:
    operators to extend to H)."""
    H, N = options.fixed_grid()
    law = options.law
    ops = condensed_operators(model, excitation, H, reuse=ops)
    if options.formulation is Formulation.CONDENSED:
        sol = solve_condensed(ops, options, start)
        C = real_to_complex_harmonics(sol.correction_force)  # (H+1, n_s)
        X = ops.linear_cargo_displacement + np.einsum("kcs,ks->kc", ops.cargo_influence, C)
        U = sol.saddle_compression
        outcome, resid, its, nfev, note = sol.outcome, sol.residual_norm, sol.iterations, sol.function_evaluations, sol.message
    else:
        problem = FullProblem(model, excitation, H, N, ops)
        u0 = None if start is None else problem.from_compression(real_dft_matrices(H, N)[0] @ start)
        a = solve_with_fallback(problem, law, options, u0)
        Q = problem.cargo_displacement(a.u)
        X = real_to_complex_harmonics(Q)
        U = problem.deck_z - Q[:, model.saddle_cargo_dof]
        outcome, resid, its, nfev, note = a.outcome, a.residual, a.iterations, a.evaluations, a.note
    delta = harmonics_to_time(real_to_complex_harmonics(U), N)  # N >= 2H + 2: an inverse real FFT
    force = law.force(delta, ops.saddle_stiffness_N_per_m)
    warnings: tuple[SolverWarning, ...] = ()
    if ops.ignored_harmonics:
        note += f"; excitation harmonics above H={H} were ignored"
        logger.warning("harmonic balance: the excitation has harmonics above H = %d; they were ignored (raise solver.harmonics)", H)
        warnings = (SolverWarning.HARMONICS_ABOVE_H_IGNORED,)
    return PeriodicResponse(
        method=SolverMethod.HBM,
        omega_rad_s=float(excitation.omega_rad_s),
        cargo_displacement_time_m=harmonics_to_time(X, N),
        cargo_displacement_harmonics=X,
        saddle_compression_time_m=delta,
        saddle_force_time_N=force,
        outcome=outcome,
        residual_norm=float(resid),
        iterations=int(its),
        message=note,
        harmonic_truncation_indicator=high_harmonic_energy_share(force, H),
        function_evaluations=int(nfev),
        options=options.to_dict(),
        warnings=warnings,
    )
