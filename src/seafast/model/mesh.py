"""Meshing of the cargo beam: a node at every sea-fastening point and segment boundary."""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

__all__ = ["mesh_cargo"]


def mesh_cargo(
    length_m: float, fixed_points_m: NDArray[np.float64], target_element_length_m: float
) -> NDArray[np.float64]:
    """Node positions [m] along a beam of ``length_m``.

    Every fixed point (sea-fastening points, section changes) and both ends become nodes; each
    interval between them is divided into equal elements no longer than
    ``target_element_length_m``.
    """
    if not target_element_length_m > 0:
        raise ValueError(f"target_element_length_m = {target_element_length_m!r}; must be > 0")
    pts = np.unique(np.concatenate([[0.0, float(length_m)], np.asarray(fixed_points_m, dtype=float)]))
    pts = pts[(pts >= 0.0) & (pts <= length_m)]
    # merge points closer than a micrometre (round-off from arithmetic on positions)
    keep = np.concatenate([[True], np.diff(pts) > 1e-6])
    pts = pts[keep]
    nodes = [pts[:1]]
    for a, b in zip(pts[:-1], pts[1:]):
        n = max(1, int(np.ceil((b - a) / target_element_length_m - 1e-9)))
        nodes.append(np.linspace(a, b, n + 1)[1:])
    return np.concatenate(nodes)
