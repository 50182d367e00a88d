"""The entry points of the harmonic balance: :func:`solve_hbm` and :func:`solve_condensed`."""

from __future__ import annotations

import logging
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from seafast.excitation.harmonic import HarmonicExcitation
from seafast.fourier import harmonics_to_time, high_harmonic_energy_share, real_dft_matrices, real_to_complex_harmonics
from seafast.model.structure import StructuralModel
from seafast.solvers.hbm.condensed import CondensedOperators, CondensedProblem, condensed_operators
from seafast.solvers.hbm.full import FullProblem
from seafast.solvers.hbm.nonlinear import solve_with_fallback
from seafast.solvers.hbm.options import HBMOptions
from seafast.solvers.outcome import SolverOutcome, SolverWarning
from seafast.solvers.periodic import PeriodicResponse

__all__ = ["CondensedSolution", "solve_condensed", "solve_hbm"]

logger = logging.getLogger(__name__)


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
    problem = CondensedProblem(ops, options.time_samples)
    u0 = None if initial_compression is None else np.asarray(initial_compression, dtype=float).ravel()
    a = solve_with_fallback(problem, options.law, options, u0)
    U = a.u.reshape(problem.n_h, problem.n_s)
    delta = problem.inverse @ U
    corr = problem.forward @ (options.law.force(delta, problem.k_u) - problem.k_u * delta)
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
        :class:`HBMOptions` (defaults: H = 5, N = 128, tanh law, kappa = 1000 1/m, condensed,
        Newton).
    initial_compression_m
        Optional start: saddle compressions sampled on the options' time grid, (N, n_s) [m]
        (e.g. a neighbouring solution's ``saddle_compression_time_m``; condensed formulation
        only). Default: the better of the linear solution and the quasi-static predictor.

    Returns
    -------
    PeriodicResponse
        ``method = "hbm"``; ``outcome`` ``CONVERGED`` (direct solve),
        ``CONVERGED_BY_CONTINUATION`` or ``NOT_CONVERGED`` (never raised). Its
        ``residual_norm`` is relative (see :class:`HBMOptions` ``tolerance``).
    """
    options = HBMOptions() if options is None else options
    H, N = int(options.harmonics), int(options.time_samples)
    law = options.law
    ops = condensed_operators(model, excitation, H)
    if options.formulation == "condensed":
        start = None
        if initial_compression_m is not None:
            samples = np.asarray(initial_compression_m, dtype=float)
            if samples.shape != (N, model.saddle_count):
                raise ValueError(f"initial_compression_m: shape {samples.shape}; must be (time_samples, n_saddles) = {(N, model.saddle_count)}")
            start = real_dft_matrices(H, N)[1] @ samples
        sol = solve_condensed(ops, options, start)
        C = real_to_complex_harmonics(sol.correction_force)  # (H+1, n_s)
        X = ops.linear_cargo_displacement + np.einsum("kcs,ks->kc", ops.cargo_influence, C)
        U = sol.saddle_compression
        outcome, resid, its, nfev, note = sol.outcome, sol.residual_norm, sol.iterations, sol.function_evaluations, sol.message
    else:
        problem = FullProblem(model, excitation, H, N, ops)
        a = solve_with_fallback(problem, law, options)
        Q = problem.cargo_displacement(a.u)
        X = real_to_complex_harmonics(Q)
        U = problem.deck_z - Q[:, model.saddle_cargo_dof]
        outcome, resid, its, nfev, note = a.outcome, a.residual, a.iterations, a.evaluations, a.note
    inverse, _ = real_dft_matrices(H, N)
    delta = inverse @ U
    force = law.force(delta, ops.saddle_stiffness_N_per_m)
    warnings: tuple[SolverWarning, ...] = ()
    if ops.ignored_harmonics:
        note += f"; excitation harmonics above H={H} were ignored"
        logger.warning("harmonic balance: the excitation has harmonics above H = %d; they were ignored (raise solver.harmonics)", H)
        warnings = (SolverWarning.HARMONICS_ABOVE_H_IGNORED,)
    return PeriodicResponse(
        method="hbm",
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
