"""Shared cases of the hull-girder tests: a prismatic box barge and an exact moment integral."""

from __future__ import annotations

import numpy as np

from seafast.vessel.hull_form import HullForm

RHO, G = 1025.0, 9.81


def box_hull(length: float = 100.0, breadth: float = 20.0, draft: float = 5.0) -> HullForm:
    """A prismatic (wall-sided, constant-breadth) hull [m]."""
    return HullForm(np.array([0.0, length]), np.array([breadth, breadth]), draft)


def exact_moment_integral(x: np.ndarray, f: np.ndarray) -> float:
    """int x f dx, exact for f linear between nodes."""
    h = np.diff(x)
    return float(np.sum(h * (x[:-1] * (2 * f[:-1] + f[1:]) + x[1:] * (f[:-1] + 2 * f[1:])) / 6.0))
