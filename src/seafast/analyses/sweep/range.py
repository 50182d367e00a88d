"""The physically meaningful range of a frequency sweep's points, and the deck's acceleration.

A sweep point lies outside the meaningful range (:class:`RangeLimit`) when

* the deck under a saddle accelerates vertically by more than g: the cargo's apparent weight
  reverses, it leaves its saddles whatever the sea-fastening, and the still-water contact model
  (saddles preloaded by the cargo's weight) no longer describes it -- the structural sweep holds the
  case's motion amplitudes, whose acceleration grows as omega^2 and passes g;
* a saddle's detachment gap exceeds a stated size (default :data:`~seafast.results.validity.DEFAULT_MAX_GAP_M`): the
  model's linear lashings, fixed saddle positions and undamped re-contact describe small lift-offs,
  not a cargo bouncing out of its cradles;
* (wave sweep) the wave is steeper than the breaking limit: no such regular wave exists.

Units: SI; nothing here prints or writes files.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum

import numpy as np
from numpy.typing import NDArray
from scipy.linalg import cho_factor, cho_solve

from seafast.config.schema import BREAKING_STEEPNESS
from seafast.excitation.harmonic import HarmonicExcitation
from seafast.fourier import harmonics_to_time
from seafast.model.structure import StructuralModel
from seafast.results.validity import DEFAULT_MAX_GAP_M

__all__ = ["RangeLimit", "RangeLimits", "time_extremes", "deck_acceleration_m_per_s2"]


class RangeLimit(Enum):
    """Why a branch point lies outside the physically meaningful range."""

    DECK_ACCELERATION = "deck_acceleration_above_g"
    """The deck under a saddle accelerates vertically by more than g."""
    GAP = "gap_above_limit"
    """A saddle's detachment gap exceeds :attr:`RangeLimits.max_gap_m`."""
    WAVE_BREAKING = "wave_steeper_than_breaking"
    """The wave's height over its length exceeds :data:`BREAKING_STEEPNESS` (wave sweep)."""


@dataclass(frozen=True)
class RangeLimits:
    """The thresholds of the physically meaningful range.

    Attributes
    ----------
    gravity_m_per_s2
        g [m/s^2]: the largest deck acceleration in range.
    max_gap_m
        Largest detachment gap in range [m] (default :data:`~seafast.results.validity.DEFAULT_MAX_GAP_M`).
    breaking_steepness
        Largest wave height over wave length [-] (default :data:`BREAKING_STEEPNESS`).
    """

    gravity_m_per_s2: float = 9.81
    max_gap_m: float = DEFAULT_MAX_GAP_M
    breaking_steepness: float = BREAKING_STEEPNESS

    def __post_init__(self) -> None:
        for name in ("gravity_m_per_s2", "max_gap_m", "breaking_steepness"):
            value = getattr(self, name)
            if isinstance(value, bool) or not isinstance(value, (int, float)) or not np.isfinite(value) or value <= 0:
                raise ValueError(f"{name} = {value!r}; allowed: a finite number > 0")


def time_extremes(harmonics: NDArray) -> tuple[NDArray, NDArray]:
    """``(max_t x, max_t |x|)`` per channel of ``x(t) = Re sum_k X_k exp(i k omega t)``, harmonics (K+1, ...).

    Exact (``X_0 + |X_1|``) when only the mean and the first harmonic are present, as in a regular
    wave's linear response; otherwise on 2048 K samples, which miss a peak by at most
    ``(pi / 2048)^2 / 2``, about 1.2e-6 of the amplitude.
    """
    X = np.asarray(harmonics)
    if X.shape[0] <= 2 or not np.any(X[2:]):
        a0 = X[0].real
        a1 = np.abs(X[1]) if X.shape[0] > 1 else np.zeros_like(a0)
        return a0 + a1, np.abs(a0) + a1
    x = harmonics_to_time(X, 2048 * (X.shape[0] - 1))
    return x.max(axis=0), np.abs(x).max(axis=0)


def deck_acceleration_m_per_s2(model: StructuralModel, excitation: HarmonicExcitation) -> float:
    """Largest vertical acceleration of the deck under a saddle over the period [m/s^2].

    The rigid-body part comes back from the inertia load ``f = -M a_rb`` (``M a_rb = -f``, exact: a
    rigid-body field is interpolated exactly by the beam's shape functions), the hull deflection's
    from its harmonics, ``-(k omega)^2 Z_k``.
    """
    n_k = excitation.harmonic_count
    if n_k < 2:
        return 0.0
    k = np.arange(n_k)[:, None]
    total = -((k * excitation.omega_rad_s) ** 2) * excitation.deck_displacement[:, model.saddle_deck_dof]
    if np.any(excitation.cargo_load_N[1:]):
        a = cho_solve(cho_factor(model.cargo.mass), -excitation.cargo_load_N[1:].T).T  # (n_k-1, n_c)
        total[1:] += a[:, model.saddle_cargo_dof]
    total[0] = 0.0
    return float(np.max(time_extremes(total)[1]))
