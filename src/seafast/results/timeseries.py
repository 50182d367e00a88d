"""Responses over one period on a common time grid, whatever solver produced them."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import NDArray

from seafast.excitation.harmonic import HarmonicExcitation
from seafast.fourier import harmonics_to_time
from seafast.model.beam import bending_moment_line
from seafast.model.structure import StructuralModel
from seafast.solvers.linear import LinearResponse
from seafast.solvers.outcome import SolverOutcome, SolverWarning
from seafast.solvers.periodic import PeriodicResponse

__all__ = ["PeriodTimeSeries", "linear_time_series", "from_periodic_response", "moment_lines"]


@dataclass(frozen=True)
class PeriodTimeSeries:
    """One model's response over one period (or a static state repeated over it).

    Arrays are on the period grid (N samples); z relative to the vessel's rigid-body frame.
    """

    cargo_displacement_m: NDArray[np.float64]  # (N, n_c): z [m] and theta [rad] interleaved
    saddle_compression_m: NDArray[np.float64]  # (N, n_s), positive compressed
    saddle_force_N: NDArray[np.float64]  # (N, n_s), compression part of the saddle, + pushes cargo up
    converged: bool = True
    diagnostics: dict[str, Any] = field(default_factory=dict)
    outcome: SolverOutcome = SolverOutcome.CONVERGED
    warnings: tuple[SolverWarning, ...] = ()


def linear_time_series(response: LinearResponse, time_samples: int) -> PeriodTimeSeries:
    """Time series of a linear (bilateral) response."""
    return PeriodTimeSeries(
        harmonics_to_time(response.cargo_displacement, time_samples),
        harmonics_to_time(response.saddle_compression_m, time_samples),
        harmonics_to_time(response.saddle_force_N, time_samples),
        True,
        {"method": "linear", "residual_norm": 0.0, "iterations": 0, "message": "direct solve"},
    )


def from_periodic_response(response: PeriodicResponse, time_samples: int | None = None) -> PeriodTimeSeries:
    """Adapt a nonlinear solver's ``PeriodicResponse`` (HBM or reference) to the common form.

    A static (time-invariant) response is repeated over ``time_samples``.
    """
    disp = np.asarray(response.cargo_displacement_time_m, dtype=float)
    comp = np.asarray(response.saddle_compression_time_m, dtype=float)
    force = np.asarray(response.saddle_force_time_N, dtype=float)
    if time_samples is not None and disp.shape[0] != time_samples:
        # only a static (time-invariant) response may be spread over a different grid
        if not (np.allclose(disp, disp[:1]) and np.allclose(comp, comp[:1]) and np.allclose(force, force[:1])):
            raise ValueError(f"cannot resample a {disp.shape[0]}-sample periodic response onto {time_samples} samples")
        disp, comp, force = (np.repeat(a[:1], time_samples, axis=0) for a in (disp, comp, force))
    diag = {
        "method": getattr(response, "method", "nonlinear"),
        "residual_norm": float(getattr(response, "residual_norm", np.nan)),
        "iterations": int(getattr(response, "iterations", 0) or 0),
        "message": str(getattr(response, "message", "")),
    }
    for name in ("harmonic_truncation_indicator", "truncation_error", "tensile_force_error_N"):
        if hasattr(response, name) and getattr(response, name) is not None:
            diag[name] = np.asarray(getattr(response, name), dtype=float)
    outcome = getattr(response, "outcome", None)
    if not isinstance(outcome, SolverOutcome):  # a response object from elsewhere: its flag decides
        outcome = SolverOutcome.CONVERGED if response.converged else SolverOutcome.NOT_CONVERGED
    warnings = tuple(getattr(response, "warnings", ()))
    return PeriodTimeSeries(disp, comp, force, bool(response.converged), diag, outcome, warnings)


def moment_lines(
    model: StructuralModel, series: PeriodTimeSeries, excitation: HarmonicExcitation, points_per_element: int = 2
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """Bending moment [N m] and bending stress [Pa] lines over the period.

    Returns ``(x_m, moment_Nm (N, n_x), stress_Pa (N, n_x))``; stress = M (D/2) / I of the local
    section, sagging positive (tension at the bottom fibre).
    """
    n_t = series.cargo_displacement_m.shape[0]
    line = harmonics_to_time(excitation.cargo_line_load_N_per_m, n_t) + model.cargo.gravity_line_load_N_per_m
    beam = model.cargo
    x, moment = bending_moment_line(
        beam.node_x_m, series.cargo_displacement_m, beam.element_bending_stiffness_Nm2, None, line, points_per_element
    )
    modulus = np.repeat(beam.element_second_moment_m4 / (beam.element_outer_diameter_m / 2.0), points_per_element + 1)
    return x, moment, moment / modulus
