"""Tests of the hull girder and its beam kernels (seafast.hull.girder)."""

from __future__ import annotations

import numpy as np
import pytest

from hull_cases import box_hull
from seafast.hull.girder import HullBeam, HullGirder, end_resultants, shear_moment


def test_end_resultants_equal_the_ends_of_the_running_integrals():
    # the balance's residual (net force and moment) by weighted sums, vs integrating V and M along the hull
    rng = np.random.default_rng(3)
    h = rng.uniform(0.1, 1.0, 340)
    qa, qb = rng.normal(size=(2, 65, 340)) * 1e5
    V, M = shear_moment(h, qa, qb)
    ends = end_resultants(h, qa, qb)
    np.testing.assert_allclose(ends[..., 0], V[..., -1], rtol=0, atol=1e-13 * np.max(np.abs(V)))
    np.testing.assert_allclose(ends[..., 1], M[..., -1], rtol=0, atol=1e-13 * np.max(np.abs(M)))


def test_the_girder_names_a_property_out_of_range_and_defaults_steel_shear_modulus():
    hull = box_hull()
    assert HullGirder(hull).shear_modulus_Pa == 210e9 / 2.6  # nu = 0.3: E / (2 (1 + nu))
    for name in ("second_moment_m4", "shear_area_m2", "youngs_modulus_Pa", "water_density_kg_per_m3"):
        with pytest.raises(ValueError, match=f"hull girder: {name} = -1.0; must be > 0"):
            HullGirder(hull, **{name: -1.0})


@pytest.mark.parametrize("shear_area_m2", [np.inf, 0.3])
def test_the_beam_with_its_end_deflections_held_is_simply_supported(shear_area_m2):
    """A uniform upward load q on the beam with z(AP) = z(FP) = 0: the simply supported beam's
    ``q x (L^3 - 2 L x^2 + x^3) / (24 EI) + q x (L - x) / (2 G A_s)``; Hermite elements with
    consistent loads are nodally exact for it, so only round-off remains."""
    girder = HullGirder(box_hull(), second_moment_m4=10.0, shear_area_m2=shear_area_m2)
    L, q = 100.0, 1.0e5
    x = np.linspace(0.0, L, 101)
    qa = qb = np.full(x.size - 1, q)
    V, _ = shear_moment(np.diff(x), qa, qb)
    z, _ = HullBeam.build(x, girder).solve(qa, qb, V)
    shear = 0.0 if np.isinf(shear_area_m2) else q * x * (L - x) / (2 * girder.shear_stiffness_N)
    exact = q * x * (L**3 - 2 * L * x**2 + x**3) / (24 * girder.bending_stiffness_Nm2) + shear
    np.testing.assert_allclose(z, exact, rtol=0, atol=1e-8 * np.max(exact))
