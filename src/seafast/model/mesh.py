"""Meshing of the cargo beam: a node at every sea-fastening point and segment boundary."""

from __future__ import annotations

from itertools import pairwise

import numpy as np
from numpy.typing import NDArray

__all__ = ["MAX_CARGO_ELEMENTS", "mesh_cargo"]

MAX_CARGO_ELEMENTS = 2000
"""Largest cargo mesh accepted: the model's matrices are dense (2 DOFs per node), so 2000
elements already mean 4000-DOF eigen-solves; a 150 m pile at 0.1 m elements needs 1500."""


def mesh_cargo(length_m: float, fixed_points_m: NDArray[np.float64], target_element_length_m: float) -> NDArray[np.float64]:
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
    counts = [max(1, int(np.ceil((b - a) / target_element_length_m - 1e-9))) for a, b in pairwise(pts)]
    if sum(counts) > MAX_CARGO_ELEMENTS:
        raise ValueError(
            f"cargo mesh: length_m = {length_m!r} with target_element_length_m = {target_element_length_m!r} needs "
            f"{sum(counts)} elements; at most {MAX_CARGO_ELEMENTS} are allowed (check cargo.length_m, or raise "
            "model.element_length_m)"
        )
    nodes = [pts[:1]]
    for (a, b), n in zip(pairwise(pts), counts, strict=True):
        nodes.append(np.linspace(a, b, n + 1)[1:])
    return np.concatenate(nodes)
