"""Cargo mesher: nodes at the fixed points, and a clear refusal of meshes too large to solve."""

from __future__ import annotations

import numpy as np
import pytest

from seafast.model.mesh import MAX_CARGO_ELEMENTS, mesh_cargo


def test_fixed_points_are_nodes_and_elements_respect_the_target():
    x = mesh_cargo(74.0, np.array([14.8, 37.0, 59.2]), 1.0)
    assert x[0] == 0.0 and x[-1] == 74.0
    assert all(np.min(np.abs(x - p)) < 1e-12 for p in (14.8, 37.0, 59.2))
    assert np.diff(x).max() <= 1.0 + 1e-12


def test_an_absurd_mesh_is_refused_with_the_fields_named():
    with pytest.raises(ValueError, match=r"cargo\.length_m") as info:
        mesh_cargo(8.8e11, np.array([1.0]), 1.0)
    assert f"at most {MAX_CARGO_ELEMENTS}" in str(info.value)
    with pytest.raises(ValueError, match=r"model\.element_length_m"):
        mesh_cargo(74.0, np.array([37.0]), 1e-6)
