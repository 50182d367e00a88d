"""What the exact references share: their result, built from sampled compressions with the exact law."""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from seafast.config.modes import SolverMethod
from seafast.excitation.harmonic import HarmonicExcitation
from seafast.fourier import high_harmonic_energy_share
from seafast.model.structure import StructuralModel
from seafast.solvers.outcome import OrbitRecord, SolverOutcome, SolverWarning
from seafast.solvers.periodic import CargoHistory, PeriodicResponse, Settings

__all__ = ["exact_law_response"]


def exact_law_response(
    method: SolverMethod,
    model: StructuralModel,
    excitation: HarmonicExcitation,
    cargo_time: NDArray,
    delta: NDArray,
    outcome: SolverOutcome,
    residual: float,
    iterations: int,
    evaluations: int,
    message: str,
    harmonics_for_indicator: int,
    options: Settings,
    warnings: tuple[SolverWarning, ...] = (),
    orbit: OrbitRecord | None = None,
) -> PeriodicResponse:
    """A reference's :class:`PeriodicResponse` from its samples (exact law, no harmonics).

    ``cargo_time`` (N, n_c) [m, rad] and ``delta`` (N, n_s) [m] on the grid ``t_n = n T / N``;
    the saddle force is ``k_u max(delta, 0)`` [N]; the truncation indicator is taken at
    ``harmonics_for_indicator``; ``orbit`` the time-domain reference's record.
    """
    k_u = np.asarray(model.saddle_unilateral_stiffness_N_per_m, dtype=float)
    force = k_u * np.maximum(delta, 0.0)
    return PeriodicResponse(
        method=method,
        omega_rad_s=float(excitation.omega_rad_s),
        cargo_history=CargoHistory(cargo_time, None),
        saddle_compression_time_m=delta,
        saddle_force_time_N=force,
        outcome=outcome,
        residual_norm=float(residual),
        iterations=int(iterations),
        message=message,
        harmonic_truncation_indicator=high_harmonic_energy_share(force, harmonics_for_indicator),
        function_evaluations=int(evaluations),
        options=options,
        warnings=warnings,
        orbit=orbit,
    )
