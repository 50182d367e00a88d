"""The arrangement rules: ``seafastening.saddle_count`` saddles along the cargo, ``cargo.units_abreast`` units across the deck."""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

__all__ = ["evenly_spaced_saddles", "abreast_lanes_m", "transverse_position_error"]


def evenly_spaced_saddles(count: int, cargo_length_m: float) -> NDArray[np.float64]:
    """The arrangement rule: ``count`` saddles evenly from 0.2 L to 0.8 L inclusive [m] (one saddle: at 0.5 L)."""
    if count < 1:
        raise ValueError(f"saddle count = {count}; must be >= 1")
    if count == 1:
        return np.array([0.5 * cargo_length_m])
    return np.linspace(0.2 * cargo_length_m, 0.8 * cargo_length_m, count)


def abreast_lanes_m(count: int, breadth_m: float) -> NDArray[np.float64]:
    """The units-abreast rule: the axes of ``count`` units on equal lanes of ``breadth_m / count`` across the deck [m].

    ``y_i = (i - (count - 1) / 2) breadth_m / count``, ``i = 0 .. count - 1``, from the centreline, + to port
    (starboard first): symmetric about the centreline, so the units put no heel on the ship. Four units on a
    42 m deck: -15.75, -5.25, 5.25 and 15.75 m.
    """
    if count < 1:
        raise ValueError(f"units abreast = {count}; must be >= 1")
    lane = float(breadth_m) / count
    return (np.arange(count, dtype=np.float64) - 0.5 * (count - 1)) * lane


def transverse_position_error(y_m: float | None, diameter_m: float, breadth_m: float) -> str:
    """The message refusing ``cargo.transverse_position_m`` when it puts a unit of ``diameter_m`` beyond the ship's side, else ``""``."""
    limit = 0.5 * breadth_m - 0.5 * diameter_m
    if y_m is None or abs(y_m) <= limit:
        return ""
    return (
        f"cargo.transverse_position_m = {y_m} puts the cargo (diameter {diameter_m:g} m) beyond the ship's side; "
        f"allowed {-limit:g} .. {limit:g} (+ to port, from the centreline)"
    )
