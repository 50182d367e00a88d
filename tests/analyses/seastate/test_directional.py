"""The cos-2s spreading: normalisation, circular moments in closed form, the quadrature and the random directions."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad

from seafast.analyses.seastate.directional import (
    directional_quadrature,
    random_directions_deg,
    spreading_density_per_rad,
    spreading_normalisation,
    weighted_squared_transfer,
)


@pytest.mark.parametrize("s", [0.5, 1.0, 2.0, 7.5, 15.0, 75.0])
def test_density_integrates_to_one_over_a_circle(s):
    total, _ = quad(lambda t: float(spreading_density_per_rad(t, s)), -math.pi, math.pi, limit=200)
    assert total == pytest.approx(1.0, abs=1e-10)


def test_normalisation_closed_forms():
    # s = 1: G = 1 / (2 pi) * 2 = 1 / pi (cos^2(t/2) = (1 + cos t) / 2 integrates to pi); s = 2: 2 / (3 pi) * ... = 4 / (3 pi) / 2
    assert spreading_normalisation(1.0) == pytest.approx(1.0 / math.pi, rel=1e-14)
    # cos^4(t/2) = (3 + 4 cos t + cos 2t) / 8 integrates to 3 pi / 4
    assert spreading_normalisation(2.0) == pytest.approx(4.0 / (3.0 * math.pi), rel=1e-14)


@pytest.mark.parametrize("s", [1.0, 4.0, 15.0, 60.0])
@pytest.mark.parametrize("mean", [180.0, 90.0, 10.0])
def test_quadrature_keeps_energy_and_circular_moments(s, mean):
    q = directional_quadrature(mean, s, 15)
    assert q.weight.sum() == pytest.approx(1.0, abs=1e-14)
    assert q.heading_deg.size == 15 and np.all((q.heading_deg >= 0.0) & (q.heading_deg < 360.0))
    relative = np.radians(q.heading_deg - mean)
    first = float(np.sum(q.weight * np.cos(relative)))
    second = float(np.sum(q.weight * np.cos(2.0 * relative)))
    # closed forms of the cos-2s spreading (Longuet-Higgins et al. 1963): 1e-6 of the energy is left out of the
    # range, s = 1 spans the whole circle (its rule converges like the spacing^4 there: 1e-4 at 15 directions)
    tolerance = 2e-4 if s < 2.0 else 1e-5
    assert first == pytest.approx(s / (s + 1.0), abs=tolerance)
    assert second == pytest.approx(s * (s - 1.0) / ((s + 1.0) * (s + 2.0)), abs=tolerance)
    # symmetric about the mean direction: the mean direction is the middle one
    assert float(np.sum(q.weight * np.sin(relative))) == pytest.approx(0.0, abs=1e-12)


def test_quadrature_converges_with_more_directions():
    s = 1.0
    exact = s / (s + 1.0)
    errors = []
    for n in (5, 15, 45):
        q = directional_quadrature(180.0, s, n)
        errors.append(abs(float(np.sum(q.weight * np.cos(np.radians(q.heading_deg - 180.0)))) - exact))
    assert errors[2] < errors[1] < errors[0]
    assert errors[2] < 2e-5


def test_long_crested_is_one_direction():
    q = directional_quadrature(120.0, None)
    assert q.long_crested and q.heading_deg.tolist() == [120.0] and q.weight.tolist() == [1.0]
    transfer = np.array([[1.0 + 2.0j, 3.0]])
    assert weighted_squared_transfer(transfer[None], q) == pytest.approx(np.abs(transfer) ** 2, rel=1e-15)


def test_weighted_squared_transfer_sums_energy():
    q = directional_quadrature(180.0, 2.0, 5)
    transfer = np.ones((5, 3, 2), dtype=complex) * 2.0  # the same |H|^2 = 4 in every direction
    assert weighted_squared_transfer(transfer, q) == pytest.approx(np.full((3, 2), 4.0), rel=1e-14)
    # a response only to the mean direction carries that direction's share of the energy
    only_mean = np.zeros((5, 1))
    only_mean[2] = 1.0
    assert weighted_squared_transfer(only_mean, q)[0] == pytest.approx(q.weight[2], rel=1e-14)
    with pytest.raises(ValueError, match="5"):
        weighted_squared_transfer(np.ones((4, 3)), q)


def test_random_directions_follow_the_spreading():
    rng = np.random.default_rng(0)
    s, count = 6.0, 200_000
    drawn = random_directions_deg(90.0, s, count, rng)
    relative = np.radians(drawn - 90.0)
    first = float(np.mean(np.cos(relative)))
    # the sample mean of cos has a standard deviation below 1 / sqrt(count) = 2.2e-3; 5 sigma
    assert first == pytest.approx(s / (s + 1.0), abs=5.0 / math.sqrt(count))
    assert float(np.mean(np.sin(relative))) == pytest.approx(0.0, abs=5.0 / math.sqrt(count))
    assert np.all((drawn >= 0.0) & (drawn < 360.0))
    assert random_directions_deg(180.0, None, 3, rng).tolist() == [180.0, 180.0, 180.0]


@pytest.mark.parametrize("bad", [0.0, -1.0, math.inf, math.nan, True, "5"])
def test_bad_exponent_names_the_value(bad):
    with pytest.raises(ValueError, match="spreading_exponent"):
        directional_quadrature(180.0, bad)
