"""Settings of the harmonic balance solver (:class:`HBMOptions`) and its grid defaults."""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass, replace
from enum import StrEnum

import numpy as np

from seafast.config.modes import ContactLawKind, Formulation, NonlinearSolver
from seafast.solvers.contact import ContactLaw
from seafast.solvers.periodic import Settings

__all__ = ["HBMOptions", "SAFE_HARMONICS", "SOURCE_OPTIONS", "MINIMUM_TIME_SAMPLES", "samples_for"]

SAFE_HARMONICS = 16
"""The harmonic balance's fixed H where a robust solve matters more than resolving every harmonic: the
adaptive choice falls back on it when its start does not converge (the full fallback chain is affordable
there), above it a fixed H starts from the periodic march first (:mod:`seafast.solvers.hbm.solve`), and
the two-way coupling iterates the deck at it when ``solver.harmonics`` is adaptive (0.4 % of the peak
forces on the base case)."""

MINIMUM_TIME_SAMPLES = 128
"""N never goes below this by default: the peaks are read on the samples (128 samples miss a smooth peak by
<= 0.03 %)."""


def samples_for(harmonics: int) -> int:
    """The default AFT samples N for H harmonics: 2.5 H rounded up to an even number, at least 128 and 2H + 2."""
    H = int(harmonics)
    return int(max(MINIMUM_TIME_SAMPLES, 2 * H + 2, 2 * math.ceil(1.25 * H)))


@dataclass(frozen=True, kw_only=True)
class HBMOptions:
    """Settings of the harmonic balance solver (keyword-only, validated).

    Parameters
    ----------
    harmonics
        H >= 0, number of harmonics above the mean (H = 0: the nonlinear static problem), or None
        (default): chosen adaptively until the saddle-force peaks settle to ``truncation_tolerance``
        (:mod:`seafast.solvers.hbm.harmonics`).
    time_samples
        N >= 2H + 2 AFT samples per period (any integer; powers of 2 not required), or None
        (default): ``max(128, 2.5 H)`` (:func:`~seafast.solvers.hbm.harmonics.samples_for`).
    contact_law
        :class:`~seafast.config.modes.ContactLawKind` (or its value): ``exact`` (default), ``tanh``
        (the source's regularisation) or ``softplus``.
    regularisation_per_m
        kappa [1/m] of ``tanh``/``softplus``, > 0 (default 1000, the source's value).
    formulation
        :class:`~seafast.config.modes.Formulation` (or its value): ``condensed`` (default, fast) or
        ``full`` (all cargo DOFs, as the source).
    solver
        :class:`~seafast.config.modes.NonlinearSolver` (or its value): ``newton`` (default) or ``hybr``
        (Powell hybrid, as the source).
    tolerance
        Relative residual at convergence (> 0, < 1): condensed, max |R| over the largest linear
        saddle compression; full, max |R| over the largest load/saddle force.
    max_iterations
        Nonlinear iterations per solve attempt (>= 1).
    continuation
        Whether a failed direct solve falls back on continuation (in kappa, then in the dynamic
        excitation amplitude).
    truncation_tolerance
        Largest acceptable estimated error of each saddle's peak force from the harmonics left out,
        relative to its force scale (> 0, < 1; default 1e-3): the target of the adaptive H, and the
        level above which a fixed H is reported as too few.
    max_harmonics
        Upper bound of the adaptive H (>= 1).
    """

    harmonics: int | None = None
    time_samples: int | None = None
    contact_law: ContactLawKind = ContactLawKind.EXACT
    regularisation_per_m: float = 1000.0
    formulation: Formulation = Formulation.CONDENSED
    solver: NonlinearSolver = NonlinearSolver.NEWTON
    tolerance: float = 1e-10
    max_iterations: int = 100
    continuation: bool = True
    truncation_tolerance: float = 1e-3
    max_harmonics: int = 512

    def __post_init__(self) -> None:
        def bad(name: str, allowed: str) -> ValueError:
            return ValueError(f"HBMOptions.{name} = {getattr(self, name)!r}; allowed: {allowed}")

        def is_int(v: object) -> bool:
            return isinstance(v, (int, np.integer)) and not isinstance(v, (bool, np.bool_))

        if self.harmonics is not None and (not is_int(self.harmonics) or self.harmonics < 0):
            raise bad("harmonics", "an integer >= 0, or None (adaptive)")
        minimum_samples = 2 * int(self.harmonics) + 2 if self.harmonics is not None else 4
        if self.time_samples is not None and (not is_int(self.time_samples) or self.time_samples < minimum_samples):
            raise bad("time_samples", f"an integer >= 2*harmonics + 2 = {minimum_samples}, or None")

        def mode(name: str, kind: type[StrEnum]) -> None:
            # a mode given by its value becomes the member (the field always holds one)
            value = getattr(self, name)
            if not isinstance(value, str) or value not in set(kind):
                raise bad(name, " | ".join(kind))
            object.__setattr__(self, name, kind(value))

        mode("contact_law", ContactLawKind)
        if (
            isinstance(self.regularisation_per_m, bool)
            or not isinstance(self.regularisation_per_m, (int, float, np.floating, np.integer))
            or not np.isfinite(self.regularisation_per_m)
            or self.regularisation_per_m <= 0
        ):
            raise bad("regularisation_per_m", "a finite number > 0 [1/m]")
        mode("formulation", Formulation)
        mode("solver", NonlinearSolver)
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
        if (
            isinstance(self.truncation_tolerance, bool)
            or not isinstance(self.truncation_tolerance, (int, float, np.floating))
            or not (0.0 < float(self.truncation_tolerance) < 1.0)
        ):
            raise bad("truncation_tolerance", "a number in (0, 1)")
        if not is_int(self.max_harmonics) or self.max_harmonics < 1:
            raise bad("max_harmonics", "an integer >= 1")

    @property
    def adaptive(self) -> bool:
        """Whether H is chosen by the solver."""
        return self.harmonics is None

    def fixed_grid(self) -> tuple[int, int]:
        """(H, N) of options whose harmonics and time samples are both set (e.g. by :meth:`with_harmonics`).

        Raises
        ------
        ValueError
            If either is None (adaptive H, or N left to the solver).
        """
        if self.harmonics is None or self.time_samples is None:
            raise ValueError(
                f"HBMOptions.harmonics = {self.harmonics!r}, time_samples = {self.time_samples!r}; "
                "allowed here: both set (a fixed grid: HBMOptions.with_harmonics(H))"
            )
        return int(self.harmonics), int(self.time_samples)

    def with_harmonics(self, harmonics: int, time_samples: int | None = None) -> HBMOptions:
        """The same settings at a given H (and N: the given one, else this one's if it fits, else the default)."""
        N = time_samples if time_samples is not None else self.time_samples
        if N is None or N < 2 * int(harmonics) + 2:
            N = samples_for(int(harmonics))
        elif self.adaptive and time_samples is None:
            N = max(int(N), samples_for(int(harmonics)))  # with H chosen adaptively, a given N is a minimum
        return replace(self, harmonics=int(harmonics), time_samples=int(N))

    @property
    def law(self) -> ContactLaw:
        """The contact law object."""
        return ContactLaw(self.contact_law, float(self.regularisation_per_m))

    def to_dict(self) -> Settings:
        """Plain dict of the settings (the modes by their values)."""
        return {k: str(v) if isinstance(v, StrEnum) else v for k, v in asdict(self).items()}


SOURCE_OPTIONS = HBMOptions(
    harmonics=5, time_samples=128, contact_law=ContactLawKind.TANH, regularisation_per_m=1000.0, solver=NonlinearSolver.HYBR
)
"""The source's method: tanh law with kappa = 1000 1/m, H = 5, N = 128, Powell's hybrid method."""
