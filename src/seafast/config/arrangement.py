"""The arrangement rule of ``seafastening.saddle_count``: where n saddles go along the cargo."""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

__all__ = ["evenly_spaced_saddles"]


def evenly_spaced_saddles(count: int, cargo_length_m: float) -> NDArray[np.float64]:
    """The arrangement rule: ``count`` saddles evenly from 0.2 L to 0.8 L inclusive [m] (one saddle: at 0.5 L)."""
    if count < 1:
        raise ValueError(f"saddle count = {count}; must be >= 1")
    if count == 1:
        return np.array([0.5 * cargo_length_m])
    return np.linspace(0.2 * cargo_length_m, 0.8 * cargo_length_m, count)
