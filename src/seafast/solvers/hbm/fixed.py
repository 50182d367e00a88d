"""One harmonic-balance solve at a fixed H and N, condensed or full, and its truncation estimate.

:func:`solve_at_harmonics` is the solve every route of :func:`~seafast.solvers.hbm.solve_hbm` takes (a fixed
H, and each step of the adaptive choice, :mod:`seafast.solvers.hbm.adaptive`); :func:`solve_condensed` the
condensed system alone, on given operators (also for the continuation); :func:`solve_many_harmonics` a
fixed H above :data:`~seafast.solvers.hbm.options.SAFE_HARMONICS`, started from the periodic march;
:func:`with_truncation` attaches the estimated error of the harmonics left out.
"""

from __future__ import annotations

import logging
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
from seafast.solvers.hbm.harmonics import select_harmonics
from seafast.solvers.hbm.nonlinear import solve_with_fallback
from seafast.solvers.hbm.options import HBMOptions
from seafast.solvers.outcome import HBMPath, HBMStart, SolverOutcome, SolverWarning
from seafast.solvers.periodic import CargoHistory, PeriodicResponse

__all__ = [
    "QUICK_ITERATIONS",
    "CondensedSolution",
    "solve_condensed",
    "solve_at_harmonics",
    "solve_many_harmonics",
    "with_truncation",
    "project_on_harmonics",
    "compression_harmonics",
]

logger = logging.getLogger(__name__)

QUICK_ITERATIONS = 40
"""Newton steps from a start near the solution (the periodic march, or the previous H's solution): no fallbacks."""


@dataclass(frozen=True)
class CondensedSolution:
    """Raw condensed HBM solution (for continuation and post-processing).

    ``saddle_compression`` is the real coefficient array (2H+1, n_s) [m]; ``correction_force``
    the real coefficients (2H+1, n_s) [N] of ``c = f(delta) - k_u delta``; ``path`` how the solve went
    (:class:`~seafast.solvers.outcome.HBMPath`).
    """

    saddle_compression: NDArray[np.float64]
    correction_force: NDArray[np.float64]
    outcome: SolverOutcome
    residual_norm: float
    iterations: int
    function_evaluations: int
    message: str
    path: HBMPath

    @property
    def converged(self) -> bool:
        """Whether the solve met the tolerance (from :attr:`outcome`)."""
        return self.outcome.converged


def solve_condensed(
    ops: CondensedOperators,
    options: HBMOptions,
    initial_compression: NDArray | None = None,
    start: HBMStart = HBMStart.GIVEN,
) -> CondensedSolution:
    """Solve the condensed HBM system for given operators (used by :func:`solve_at_harmonics` and continuation).

    ``initial_compression``: real-layout compression harmonics to start from (``start`` says what they are),
    else the better of the linear solution and the quasi-static predictor.
    """
    if options.time_samples is None or options.harmonics != ops.harmonics:
        options = options.with_harmonics(ops.harmonics)
    problem = CondensedProblem(ops, options.fixed_grid()[1])
    u0 = None if initial_compression is None else np.asarray(initial_compression, dtype=float).ravel()
    a = solve_with_fallback(problem, options.law, options, u0, start)
    U = a.u.reshape(problem.n_h, problem.n_s)
    delta = problem.to_samples(U)
    corr = problem.to_harmonics(options.law.force(delta, problem.k_u) - problem.k_u * delta)
    return CondensedSolution(U, corr, a.outcome, a.residual, a.iterations, a.evaluations, a.note, a.path)


def solve_many_harmonics(
    model: StructuralModel, excitation: HarmonicExcitation, options: HBMOptions, start: NDArray | None
) -> PeriodicResponse:
    """A fixed H above :data:`~seafast.solvers.hbm.options.SAFE_HARMONICS`: a few Newton steps from the given
    start, then from the periodic march (the start from which the semi-smooth Newton converges at many
    harmonics), and only then the full fallback chain, whose continuation costs minutes at hundreds of harmonics."""
    H = int(options.harmonics or 0)
    quick = replace(options, continuation=False, max_iterations=min(int(options.max_iterations), QUICK_ITERATIONS))
    ops = condensed_operators(model, excitation, H)
    if start is not None:
        response = solve_at_harmonics(model, excitation, quick, start, ops)
        if response.converged:
            return response
    selection = select_harmonics(model, excitation, tolerance=options.truncation_tolerance, max_harmonics=max(H, 1))
    if selection.march_periods > 0:
        march = project_on_harmonics(selection.march_compression_m, H)
        response = solve_at_harmonics(model, excitation, quick, march, ops, HBMStart.MARCH)
        if response.converged:
            return replace(response, message=response.message + "; started from the periodic march")
    return solve_at_harmonics(model, excitation, options, start, ops)


def with_truncation(response: PeriodicResponse, error: NDArray, tolerance: float) -> PeriodicResponse:
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


def project_on_harmonics(samples: NDArray, harmonics: int) -> NDArray:
    """Real-layout harmonics 0 .. H of periodic samples (N', n_s) (an exact DFT projection)."""
    X = time_to_harmonics(samples, min(harmonics, samples.shape[0] // 2))
    C = np.zeros((harmonics + 1, samples.shape[1]), dtype=complex)
    C[: X.shape[0]] = X  # harmonics the samples cannot resolve are zero
    return complex_to_real_harmonics(C)


def compression_harmonics(response: PeriodicResponse, harmonics: int) -> NDArray:
    """Real-layout harmonics 0 .. H of a response's saddle compressions [m]."""
    return project_on_harmonics(response.saddle_compression_time_m, harmonics)


def solve_at_harmonics(
    model: StructuralModel,
    excitation: HarmonicExcitation,
    options: HBMOptions,
    start: NDArray | None,
    ops: CondensedOperators | None = None,
    start_kind: HBMStart = HBMStart.GIVEN,
) -> PeriodicResponse:
    """One harmonic-balance solve at the options' H and N.

    ``start``: real-layout compression harmonics (``start_kind`` says what they are), or None (the better of
    the linear solution and the quasi-static predictor); ``ops``: operators to extend to H.
    """
    H, N = options.fixed_grid()
    law = options.law
    ops = condensed_operators(model, excitation, H, reuse=ops)
    if options.formulation is Formulation.CONDENSED:
        sol = solve_condensed(ops, options, start, start_kind)
        C = real_to_complex_harmonics(sol.correction_force)  # (H+1, n_s)
        X = ops.linear_cargo_displacement + np.einsum("kcs,ks->kc", ops.cargo_influence, C)
        U = sol.saddle_compression
        outcome, resid, its, nfev = sol.outcome, sol.residual_norm, sol.iterations, sol.function_evaluations
        note, path = sol.message, sol.path
    else:
        problem = FullProblem(model, excitation, H, N, ops)
        u0 = None if start is None else problem.from_compression(real_dft_matrices(H, N)[0] @ start)
        a = solve_with_fallback(problem, law, options, u0, start_kind)
        Q = problem.cargo_displacement(a.u)
        X = real_to_complex_harmonics(Q)
        U = problem.deck_z - Q[:, model.saddle_cargo_dof]
        outcome, resid, its, nfev, note, path = a.outcome, a.residual, a.iterations, a.evaluations, a.note, a.path
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
        cargo_history=CargoHistory(harmonics_to_time(X, N), X),
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
        path=path,
    )
