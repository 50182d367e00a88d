"""The common result of the nonlinear solvers: one period of the steady-state response.

Harmonic balance (``solve_hbm``) and the exact references (``solve_quasi_static``,
``solve_time_domain``) all return a :class:`PeriodicResponse` sampled on the same time grid
``t_n = n T / N`` (period fraction ``n / N``, n = 0 .. N-1), so they can be compared sample by
sample.

Sign conventions (docs/conventions.md#3-signs)
---------------------------
* Cargo DOFs (z [m], theta [rad]) per cargo node, z positive upward and relative to the
  vessel's rigid-body frame, in the structural model's cargo-DOF order.
* Saddle compression ``delta = z_deck - z_cargo`` [m], positive when compressed; a negative
  value is a gap (detachment).
* Saddle force [N]: the contact force of the compression-only part of the saddle
  (k_sad - k_z at lashed saddles) on the cargo, positive pushing the cargo up.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from seafast.config.modes import SolverMethod
from seafast.fourier import period_fraction
from seafast.solvers.outcome import HBMPath, OrbitRecord, SolverOutcome, SolverWarning

__all__ = ["PeriodicResponse", "SettingValue", "Settings"]

SettingValue = int | float | str | bool | list[int] | None
"""One value of a solver's record of its settings (plain, JSON-serialisable; the modes by their values)."""

Settings = dict[str, SettingValue]
"""A solver's record of the settings it used (``options`` of its result)."""


@dataclass(frozen=True)
class PeriodicResponse:
    """One period of the steady-state response of cargo and saddles.

    Attributes
    ----------
    method
        The solver (:class:`~seafast.config.modes.SolverMethod`: ``"hbm"``, ``"quasi_static"`` or
        ``"time_domain"``).
    omega_rad_s
        Fundamental frequency [rad/s] (period T = 2 pi / omega).
    cargo_displacement_time_m
        Cargo DOFs over the period (z [m], theta [rad]), shape (N, n_c), relative to the
        vessel's rigid-body frame; static part included.
    cargo_displacement_harmonics
        Complex amplitudes X_k of the cargo DOFs, k = 0 .. H, shape (H+1, n_c), with
        ``x(t) = Re(sum_k X_k exp(i k omega t))``; ``None`` for the time-sampled references.
    saddle_compression_time_m
        ``delta = z_deck - z_cargo`` at each saddle [m], shape (N, n_s); negative = gap.
    saddle_force_time_N
        Contact force of the compression-only saddle part on the cargo [N], shape (N, n_s),
        from the contact law used (exact law for the references).
    outcome
        How the solve ended (:class:`~seafast.solvers.outcome.SolverOutcome`). A response that
        did not converge is returned (never an exception) so callers can report it;
        :attr:`converged` is derived from it.
    residual_norm
        Final residual (relative, dimensionless; see the solver for its normalisation).
    iterations, function_evaluations
        Nonlinear iterations (Newton steps, continuation steps included) and residual
        evaluations (time steps for the time-domain reference).
    message
        Human-readable account of the solution path (for people; decide nothing from it).
    warnings
        Typed warnings (:class:`~seafast.solvers.outcome.SolverWarning`), empty when none.
    harmonic_truncation_indicator
        Per saddle, the share of the fluctuating contact-force energy above harmonic H
        (see :func:`seafast.fourier.high_harmonic_energy_share`); for the references H is the ``harmonics``
        recorded in ``options`` (what an HBM with that H would miss).
    options
        The settings used (plain dict, safe to serialise).
    truncation_error
        Per saddle, the estimated error of the peak force from the harmonics left out, relative to
        the saddle's force scale [-] (:func:`seafast.solvers.hbm.harmonics.truncation_error`); None
        for the references (they have no harmonic truncation).
    orbit
        Time-domain reference only (else None): where it started and what it reached
        (:class:`~seafast.solvers.outcome.OrbitRecord`).
    path
        Harmonic balance only (else None): where its direct solve started and which solve of the fallback
        chain reached the answer (:class:`~seafast.solvers.outcome.HBMPath`).
    """

    method: SolverMethod
    omega_rad_s: float
    cargo_displacement_time_m: NDArray[np.float64]
    cargo_displacement_harmonics: NDArray[np.complex128] | None
    saddle_compression_time_m: NDArray[np.float64]
    saddle_force_time_N: NDArray[np.float64]
    outcome: SolverOutcome
    residual_norm: float
    iterations: int
    message: str
    harmonic_truncation_indicator: NDArray[np.float64]
    function_evaluations: int
    options: Settings = field(default_factory=dict)
    truncation_error: NDArray[np.float64] | None = None
    warnings: tuple[SolverWarning, ...] = ()
    orbit: OrbitRecord | None = None
    path: HBMPath | None = None

    @property
    def converged(self) -> bool:
        """Whether the solver met its tolerance (from :attr:`outcome`)."""
        return self.outcome.converged

    # ------------------------------------------------- derived from the samples
    @property
    def time_samples(self) -> int:
        """N."""
        return int(self.saddle_compression_time_m.shape[0])

    @property
    def period_fraction(self) -> NDArray[np.float64]:
        """``n / N``, shape (N,)."""
        return period_fraction(self.time_samples)

    @property
    def contact_state(self) -> NDArray[np.bool_]:
        """``delta > 0`` (in contact), shape (N, n_s)."""
        return self.saddle_compression_time_m > 0.0

    @property
    def tensile_force_error_N(self) -> float:
        """Largest tensile (negative) force the contact law produced over the period [N], >= 0.

        Nonzero only for the ``tanh`` regularisation.
        """
        force = self.saddle_force_time_N
        return float(max(0.0, -np.min(force))) if force.size else 0.0

    @property
    def max_saddle_force_N(self) -> float:
        """Largest saddle force over the period and the saddles [N]."""
        return float(np.max(self.saddle_force_time_N))

    @property
    def max_saddle_compression_m(self) -> float:
        """Largest saddle compression u_s [m] (0 if never compressed)."""
        return float(max(np.max(self.saddle_compression_time_m), 0.0))

    @property
    def max_gap_m(self) -> float:
        """Largest detachment u_d = max(-delta) [m] (0 if contact is preserved)."""
        return float(max(-np.min(self.saddle_compression_time_m), 0.0))

    @property
    def contact_preserved(self) -> bool:
        """True when every saddle stays in contact over the whole period."""
        return bool(np.all(self.contact_state))

    def max_cargo_deflection_m(self, z_dofs: NDArray[np.intp] | None = None) -> float:
        """Largest |z| over the period and the cargo [m]; z DOFs are the even cargo DOFs."""
        z = self.cargo_displacement_time_m[:, 0::2] if z_dofs is None else self.cargo_displacement_time_m[:, z_dofs]
        return float(np.max(np.abs(z)))
