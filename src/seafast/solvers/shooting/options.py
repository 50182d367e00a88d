"""The settings of the exact-event shooting solver (:func:`~seafast.solvers.shooting.solve_shooting`)."""

from __future__ import annotations

from dataclasses import dataclass

from seafast.solvers.modal_correction import CorrectionBasis
from seafast.solvers.periodic import Settings

__all__ = ["ShootingOptions"]


@dataclass(frozen=True, kw_only=True)
class ShootingOptions:
    """Keyword-only, validated on construction (a bad value names the field, the value and what is allowed).

    Attributes
    ----------
    cutoff_factor
        The correction system keeps the cargo's modes on bilateral saddles up to this multiple of the reference
        frequency (the highest of the ``n_s`` lowest modes: the modes the saddles drive); the rest respond
        statically through the residual flexibility.
    samples_per_mode
        Samples of the event grid per period of the reference frequency (rounded up to a power of 2 per period).
    minimum_samples
        At least this many samples per period.
    time_samples
        A fixed number of samples per period instead (None: from ``samples_per_mode``).
    tolerance
        The periodic state is converged when a period moves the saddle compressions (and their rates over a
        modal period) by less than this share of the largest linear compression [-] (or than the march's round-off
        floor, where that is higher: near-rigid saddles' linear compressions are tiny).
    march_periods
        Periods marched from the linear solution before Newton's method takes over.
    max_iterations
        Newton steps at most.
    max_events
        Contact events per period at most (a chattering contact ends the solve, not converged).
    peak_tolerance
        The grid is refined (doubled) until no saddle's sampled peak force is more than this share of the largest
        peak force below its continuous peak (found from the closed form between samples) [-].
    max_samples
        Samples per period at most.
    cutoff_check
        On stiff saddles (the lifted basis, or a lifted state cancelling most of the bilateral modes' stiffness),
        repeat the solve with the cutoff doubled until the peak forces move by at most 0.1 % (or every mode is kept;
        after the last doubling, every mode of a small model), and refine the grid beyond ``max_samples`` (8 times)
        if the peaks need it; what does not settle is reported not converged, with why
        (:func:`~seafast.solvers.shooting.stiff.settled_cutoff`, :class:`~seafast.solvers.shooting.ShootingFailure`).
    basis
        The :class:`~seafast.solvers.modal_correction.CorrectionBasis` of the modal reduction; None (the default):
        the bilateral saddles' modes unless a lifted state would cancel more than
        :data:`~seafast.solvers.shooting.stiff.STIFF_CANCELLATION` of their stiffness (stiff saddles) and the
        lashings hold the lifted cargo, then the lifted cargo's modes.
    """

    cutoff_factor: float = 16.0
    reference_modes: int = 3
    samples_per_mode: int = 8
    minimum_samples: int = 256
    time_samples: int | None = None
    tolerance: float = 1e-9
    march_periods: int = 1
    max_iterations: int = 30
    max_events: int = 100_000
    peak_tolerance: float = 2.5e-4
    max_samples: int = 65536
    cutoff_check: bool = True
    basis: CorrectionBasis | None = None

    def __post_init__(self) -> None:
        def bad(name: str, allowed: str) -> ValueError:
            return ValueError(f"{name} = {getattr(self, name)!r}; allowed: {allowed}")

        def is_int(v: object) -> bool:
            return isinstance(v, int) and not isinstance(v, bool)

        if isinstance(self.cutoff_factor, bool) or not isinstance(self.cutoff_factor, (int, float)) or not self.cutoff_factor >= 1.0:
            raise bad("cutoff_factor", "a number >= 1")
        for name, low in (
            ("samples_per_mode", 4),
            ("reference_modes", 1),
            ("minimum_samples", 16),
            ("march_periods", 0),
            ("max_iterations", 1),
            ("max_events", 1),
        ):
            value = getattr(self, name)
            if not is_int(value) or value < low:
                raise bad(name, f"an integer >= {low}")
        if self.time_samples is not None and (not is_int(self.time_samples) or self.time_samples < 16):
            raise bad("time_samples", "None or an integer >= 16")
        if isinstance(self.tolerance, bool) or not isinstance(self.tolerance, (int, float)) or not 0.0 < float(self.tolerance) < 1.0:
            raise bad("tolerance", "a number in (0, 1)")
        if (
            isinstance(self.peak_tolerance, bool)
            or not isinstance(self.peak_tolerance, (int, float))
            or not 0.0 < self.peak_tolerance < 1.0
        ):
            raise bad("peak_tolerance", "a number in (0, 1)")
        if self.basis is not None and not isinstance(self.basis, CorrectionBasis):
            raise bad("basis", "None or one of " + ", ".join(repr(b.value) for b in CorrectionBasis))

    def to_dict(self) -> Settings:
        """The settings as plain values."""
        return {
            "cutoff_factor": float(self.cutoff_factor),
            "reference_modes": int(self.reference_modes),
            "samples_per_mode": int(self.samples_per_mode),
            "minimum_samples": int(self.minimum_samples),
            "time_samples": self.time_samples,
            "tolerance": float(self.tolerance),
            "march_periods": int(self.march_periods),
            "max_iterations": int(self.max_iterations),
            "max_events": int(self.max_events),
            "peak_tolerance": float(self.peak_tolerance),
            "max_samples": int(self.max_samples),
            "cutoff_check": bool(self.cutoff_check),
            "basis": None if self.basis is None else self.basis.value,
        }
