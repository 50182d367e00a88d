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

import functools
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from seafast.config.modes import SolverMethod
from seafast.fourier import period_fraction
from seafast.solvers.outcome import HBMPath, OrbitRecord, SolverOutcome, SolverWarning

__all__ = ["CargoHistory", "PeriodicResponse", "SettingValue", "Settings"]

SettingValue = int | float | str | bool | list[int] | None
"""One value of a solver's record of its settings (plain, JSON-serialisable; the modes by their values)."""

Settings = dict[str, SettingValue]
"""A solver's record of the settings it used (``options`` of its result)."""


@dataclass(frozen=True, eq=False)
class CargoHistory:
    """The cargo's DOFs over one period: sampled, or factored into a few time functions and their DOF shapes.

    Factored (``shapes`` given): ``x(t_n) = time_functions[n] @ shapes`` and ``X_k = harmonic_functions[k] @ shapes``.
    The shooting's response is one: the linear solution's cosines and sines, the modal coordinates and the
    correction forces over the period, times their shapes. A linear output ``L x`` (bending moments, a few DOFs) is
    then ``time_functions @ (shapes @ L^T)``: r products a sample instead of n_c, without the (N, n_c) samples a
    stiff saddle's 8192 samples a period make costly. :attr:`time_m` and :attr:`harmonics` form them on first use
    and keep them (a cache owned by this object).

    Sampled (``shapes`` None): ``time_functions`` are the samples (N, n_c) and ``harmonic_functions`` the harmonics
    (H+1, n_c), or None for a time-sampled reference.

    Attributes
    ----------
    time_functions
        (N, r) factored, (N, n_c) sampled [m, rad when sampled; the shapes carry the units when factored].
    harmonic_functions
        The time functions' complex amplitudes k = 0 .. H (H+1, r), or the cargo's (H+1, n_c); None: no harmonics.
    shapes
        (r, n_c), or None (sampled).
    """

    time_functions: NDArray[np.float64]
    harmonic_functions: NDArray[np.complex128] | None
    shapes: NDArray[np.float64] | None = None

    @property
    def factored(self) -> bool:
        """Whether the history is kept as time functions times shapes."""
        return self.shapes is not None

    @functools.cached_property
    def time_m(self) -> NDArray[np.float64]:
        """The samples (N, n_c) [m, rad]."""
        if self.shapes is None:
            return self.time_functions
        return np.asarray(self.time_functions @ self.shapes, dtype=float)

    @functools.cached_property
    def harmonics(self) -> NDArray[np.complex128] | None:
        """The complex amplitudes X_k, k = 0 .. H (H+1, n_c) [m, rad]; None for a time-sampled reference."""
        if self.shapes is None or self.harmonic_functions is None:
            return self.harmonic_functions
        # one real product on the interleaved real and imaginary parts of the time functions' amplitudes
        parts = np.ascontiguousarray(self.harmonic_functions.T).view(np.float64)
        return np.asarray((self.shapes.T @ parts).view(np.complex128).T)


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
    cargo_history
        Cargo DOFs over the period (z [m], theta [rad]) relative to the vessel's rigid-body frame, static part
        included (:class:`CargoHistory`: sampled, or factored by the shooting); read as
        :attr:`cargo_displacement_time_m` (N, n_c) and :attr:`cargo_displacement_harmonics` (H+1, n_c), with
        ``x(t) = Re(sum_k X_k exp(i k omega t))`` (``None`` for the time-sampled references).
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
    cargo_history: CargoHistory
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

    @property
    def cargo_displacement_time_m(self) -> NDArray[np.float64]:
        """Cargo DOFs over the period (z [m], theta [rad]), (N, n_c) (:attr:`CargoHistory.time_m`)."""
        return self.cargo_history.time_m

    @property
    def cargo_displacement_harmonics(self) -> NDArray[np.complex128] | None:
        """Their complex amplitudes X_k, k = 0 .. H, (H+1, n_c); None for the time-sampled references."""
        return self.cargo_history.harmonics

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
