"""Settings of the harmonic balance solver (:class:`HBMOptions`) and the accepted names."""

from __future__ import annotations

from dataclasses import asdict, dataclass
from typing import Any

import numpy as np

from seafast.solvers.contact import CONTACT_LAWS, ContactLaw

__all__ = ["HBMOptions", "FORMULATIONS", "SOLVERS"]

FORMULATIONS: tuple[str, ...] = ("condensed", "full")
SOLVERS: tuple[str, ...] = ("newton", "hybr")


@dataclass(frozen=True, kw_only=True)
class HBMOptions:
    """Settings of the harmonic balance solver (keyword-only, validated).

    Parameters
    ----------
    harmonics
        H >= 0, number of harmonics above the mean (H = 0: the nonlinear static problem).
    time_samples
        N >= 2H + 2 AFT samples per period (any integer; powers of 2 not required).
    contact_law
        ``tanh`` (the source's regularisation), ``softplus`` or ``exact``.
    regularisation_per_m
        kappa [1/m] of ``tanh``/``softplus``, > 0 (default 1000, the source's value).
    formulation
        ``condensed`` (default, fast) or ``full`` (all cargo DOFs, as the source).
    solver
        ``newton`` (default) or ``hybr`` (Powell hybrid, as the source).
    tolerance
        Relative residual at convergence (> 0, < 1): condensed, max |R| over the largest linear
        saddle compression; full, max |R| over the largest load/saddle force.
    max_iterations
        Nonlinear iterations per solve attempt (>= 1).
    continuation
        Whether a failed direct solve falls back on continuation (in kappa, then in the dynamic
        excitation amplitude).
    """

    harmonics: int = 5
    time_samples: int = 128
    contact_law: str = "tanh"
    regularisation_per_m: float = 1000.0
    formulation: str = "condensed"
    solver: str = "newton"
    tolerance: float = 1e-10
    max_iterations: int = 100
    continuation: bool = True

    def __post_init__(self) -> None:
        def bad(name: str, allowed: str) -> ValueError:
            return ValueError(f"HBMOptions.{name} = {getattr(self, name)!r}; allowed: {allowed}")

        def is_int(v: Any) -> bool:
            return isinstance(v, (int, np.integer)) and not isinstance(v, (bool, np.bool_))

        if not is_int(self.harmonics) or self.harmonics < 0:
            raise bad("harmonics", "an integer >= 0")
        if not is_int(self.time_samples) or self.time_samples < 2 * self.harmonics + 2:
            raise bad("time_samples", f"an integer >= 2*harmonics + 2 = {2 * int(self.harmonics) + 2}")
        if self.contact_law not in CONTACT_LAWS:
            raise bad("contact_law", " | ".join(CONTACT_LAWS))
        if (
            isinstance(self.regularisation_per_m, bool)
            or not isinstance(self.regularisation_per_m, (int, float, np.floating, np.integer))
            or not np.isfinite(self.regularisation_per_m)
            or self.regularisation_per_m <= 0
        ):
            raise bad("regularisation_per_m", "a finite number > 0 [1/m]")
        if self.formulation not in FORMULATIONS:
            raise bad("formulation", " | ".join(FORMULATIONS))
        if self.solver not in SOLVERS:
            raise bad("solver", " | ".join(SOLVERS))
        if (
            isinstance(self.tolerance, bool)
            or not isinstance(self.tolerance, (int, float, np.floating))
            or not (0.0 < float(self.tolerance) < 1.0)
        ):
            raise bad("tolerance", "a number in (0, 1)")
        if not is_int(self.max_iterations) or self.max_iterations < 1:
            raise bad("max_iterations", "an integer >= 1")
        if not isinstance(self.continuation, (bool, np.bool_)):
            raise bad("continuation", "True | False")

    @property
    def law(self) -> ContactLaw:
        """The contact law object."""
        return ContactLaw(self.contact_law, float(self.regularisation_per_m))

    def to_dict(self) -> dict[str, Any]:
        """Plain dict of the settings."""
        return asdict(self)
