"""Settings of the exact-contact references: :class:`QuasiStaticOptions` and :class:`TimeDomainOptions`.

Keyword-only and validated on construction, like :class:`~seafast.solvers.hbm.options.HBMOptions`: a bad
value raises ``ValueError`` naming the field, the value and what is allowed.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from seafast.config.modes import Formulation, TimeDomainStart
from seafast.solvers.hbm.options import HBMOptions
from seafast.solvers.references.orbit import ORBIT_TOLERANCE

__all__ = ["QuasiStaticOptions", "TimeDomainOptions", "TIME_DOMAIN_STEPS_PER_SAMPLE"]

TIME_DOMAIN_STEPS_PER_SAMPLE = 16
"""Time steps per output sample of the time-domain reference when ``steps_per_period`` is left unset."""


def _is_int(value: object) -> bool:
    return isinstance(value, (int, np.integer)) and not isinstance(value, (bool, np.bool_))


def _is_number(value: object) -> bool:
    return isinstance(value, (int, float, np.integer, np.floating)) and not isinstance(value, (bool, np.bool_))


@dataclass(frozen=True, kw_only=True)
class QuasiStaticOptions:
    """Settings of the quasi-static exact-contact reference (:func:`~seafast.solvers.references.solve_quasi_static`).

    Parameters
    ----------
    time_samples
        N >= 2 instants of the period, ``t_n = n T / N``.
    harmonics_for_indicator
        H >= 0 of the truncation indicator the response reports (what an HBM with that H would miss).
    """

    time_samples: int = 128
    harmonics_for_indicator: int = 5

    def __post_init__(self) -> None:
        if not _is_int(self.time_samples) or self.time_samples < 2:
            raise ValueError(f"time_samples = {self.time_samples!r}; allowed: an integer >= 2")
        if not _is_int(self.harmonics_for_indicator) or self.harmonics_for_indicator < 0:
            raise ValueError(f"harmonics_for_indicator = {self.harmonics_for_indicator!r}; allowed: an integer >= 0")


@dataclass(frozen=True, kw_only=True)
class TimeDomainOptions:
    """Settings of the time-domain exact-contact reference (:func:`~seafast.solvers.references.solve_time_domain`).

    Parameters
    ----------
    time_samples
        N >= 2 output samples per period (the HBM grid).
    formulation
        :class:`~seafast.config.modes.Formulation`: ``FULL`` (default, HHT-alpha on all cargo DOFs, the
        independent reference) or ``CONDENSED`` (each step's contact condensed onto the saddles).
    start
        :class:`~seafast.config.modes.TimeDomainStart`: ``LINEAR`` (default), ``QUASI_STATIC``, or ``HBM``
        (the harmonic balance's solution with :attr:`hbm`: :func:`seafast.solvers.solve_periodic` solves it
        first; :func:`~seafast.solvers.references.solve_time_domain` takes it as its ``start`` solution).
    hbm
        The harmonic balance's settings of a ``start = HBM``.
    steps_per_period
        Time steps per period, a positive multiple of N; None (default): :data:`TIME_DOMAIN_STEPS_PER_SAMPLE` N.
    max_periods
        Periods integrated at most (>= 2); None (default): twice what the slowest free vibration needs to
        decay by ``tolerance`` (:func:`~seafast.solvers.references.orbit.settling_periods`, at least 40).
    tolerance
        Steady state when the largest change of the saddle forces between two consecutive periods, over the
        largest saddle force, is below this (> 0, < 1).
    hht_alpha
        HHT-alpha parameter in [-1/3, 0]; 0 is the average-acceleration Newmark rule, a small negative value
        damps the spurious high-frequency response of contact switches.
    harmonics_for_indicator
        H >= 0 of the truncation indicator the response reports.
    orbit_tolerance
        With a given start: the distance (:func:`~seafast.solvers.references.orbit.orbit_distance`) above which
        the periodic state reached is another orbit (> 0, < 1; default
        :data:`~seafast.solvers.references.orbit.ORBIT_TOLERANCE`).
    """

    time_samples: int = 128
    formulation: Formulation = Formulation.FULL
    start: TimeDomainStart = TimeDomainStart.LINEAR
    hbm: HBMOptions = field(default_factory=HBMOptions)
    steps_per_period: int | None = None
    max_periods: int | None = None
    tolerance: float = 1e-7
    hht_alpha: float = -0.05
    harmonics_for_indicator: int = 5
    orbit_tolerance: float = ORBIT_TOLERANCE

    def __post_init__(self) -> None:
        if not isinstance(self.formulation, str) or self.formulation not in set(Formulation):
            raise ValueError(f"formulation = {self.formulation!r}; allowed: 'full', 'condensed'")
        object.__setattr__(self, "formulation", Formulation(self.formulation))
        allowed_starts = (TimeDomainStart.LINEAR, TimeDomainStart.QUASI_STATIC, TimeDomainStart.HBM)
        if not isinstance(self.start, str) or self.start not in allowed_starts:
            raise ValueError(
                f"start = {self.start!r}; allowed: 'linear', 'quasi_static', 'hbm' (a given solution: solve_time_domain's start)"
            )
        object.__setattr__(self, "start", TimeDomainStart(self.start))
        if not isinstance(self.hbm, HBMOptions):
            raise ValueError(f"hbm = {self.hbm!r}; allowed: HBMOptions")
        N = self.time_samples
        if not _is_int(N) or N < 2:
            raise ValueError(f"time_samples = {N!r}; allowed: an integer >= 2")
        S = self.steps_per_period
        if S is not None and (not _is_int(S) or S < N or S % N):
            raise ValueError(f"steps_per_period = {S!r}; allowed: a positive multiple of time_samples = {N}")
        if not _is_number(self.hht_alpha) or not (-1.0 / 3.0 <= self.hht_alpha <= 0.0):
            raise ValueError(f"hht_alpha = {self.hht_alpha!r}; allowed: a number in [-1/3, 0]")
        if self.max_periods is not None and (not _is_int(self.max_periods) or self.max_periods < 2):
            raise ValueError(f"max_periods = {self.max_periods!r}; allowed: an integer >= 2, or None")
        if not _is_number(self.tolerance) or not (0.0 < self.tolerance < 1.0) or not math.isfinite(self.tolerance):
            raise ValueError(f"tolerance = {self.tolerance!r}; allowed: a number in (0, 1)")
        if not _is_int(self.harmonics_for_indicator) or self.harmonics_for_indicator < 0:
            raise ValueError(f"harmonics_for_indicator = {self.harmonics_for_indicator!r}; allowed: an integer >= 0")
        if not _is_number(self.orbit_tolerance) or not (0.0 < float(self.orbit_tolerance) < 1.0):
            raise ValueError(f"orbit_tolerance = {self.orbit_tolerance!r}; allowed: a number in (0, 1)")

    @property
    def steps(self) -> int:
        """S, the time steps per period (``steps_per_period``, else :data:`TIME_DOMAIN_STEPS_PER_SAMPLE` N)."""
        return int(self.steps_per_period) if self.steps_per_period is not None else TIME_DOMAIN_STEPS_PER_SAMPLE * int(self.time_samples)
