"""Short-crested sea states: the cos-2s directional spreading, its quadrature and its random directions.

A short-crested sea spreads each frequency's energy over directions, ``S(omega, theta) = S(omega) D(theta)``,
with the spreading function of Longuet-Higgins, Cartwright and Smith (1963) (also DNV-RP-C205, section 3.5.8,
and ISO 19901-1)::

    D(theta) = G(s) cos^{2s}((theta - theta_m) / 2),   |theta - theta_m| <= pi,
    G(s) = Gamma(s + 1) / (2 sqrt(pi) Gamma(s + 1/2))      (so that the integral of D over a circle is 1),

``theta_m`` the mean direction the waves travel (the case's heading convention: 180 deg = head seas) and ``s`` the
spreading exponent (wind seas about 5-15, swell 25 and more; s -> infinity is long-crested). Its circular moments
are known in closed form, ``E[cos(theta - theta_m)] = s / (s + 1)`` and
``E[cos 2(theta - theta_m)] = s (s - 1) / ((s + 1)(s + 2))``, which the tests use to check the quadrature.

A linear response then has the spectrum ``S_r(omega) = S(omega) sum_j w_j |H(omega, theta_j)|^2`` over the
quadrature's directions ``theta_j`` and weights ``w_j`` (:func:`directional_quadrature`); a random realisation
draws each wave component's direction from ``D`` (:func:`random_directions_deg`).

Units: directions in degrees at the interface (as the case keys), radians inside; weights dimensionless.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.integrate import cumulative_trapezoid
from scipy.special import gammaln

__all__ = [
    "DirectionalQuadrature",
    "directional_quadrature",
    "random_directions_deg",
    "spreading_density_per_rad",
    "spreading_normalisation",
    "weighted_squared_transfer",
]

DEFAULT_DIRECTIONS = 15
"""Directions of the quadrature by default (odd: the mean direction is one of them)."""

_CDF_POINTS = 4097  # fine grid of the cumulative spreading (inverse-CDF sampling and the bins' exact weights)


def spreading_normalisation(spreading_exponent: float) -> float:
    """``G(s) = Gamma(s + 1) / (2 sqrt(pi) Gamma(s + 1/2))`` [1/rad]: the integral of ``G cos^{2s}(theta / 2)`` over a circle is 1."""
    s = _checked_exponent(spreading_exponent)
    return float(math.exp(gammaln(s + 1.0) - gammaln(s + 0.5)) / (2.0 * math.sqrt(math.pi)))


def spreading_density_per_rad(relative_direction_rad: ArrayLike, spreading_exponent: float) -> NDArray[np.float64]:
    """``D(theta)`` [1/rad] at directions relative to the mean direction [rad] (any real values: wrapped to a circle)."""
    s = _checked_exponent(spreading_exponent)
    theta = np.asarray(relative_direction_rad, dtype=float)
    return spreading_normalisation(s) * np.abs(np.cos(0.5 * _wrap_rad(theta))) ** (2.0 * s)


@dataclass(frozen=True)
class DirectionalQuadrature:
    """Directions and weights that integrate the spreading function.

    Attributes
    ----------
    heading_deg
        (n_d,) the directions the wave components travel [deg], in [0, 360) (180 = head seas).
    weight
        (n_d,) the share of the sea's energy each direction carries [-]; the weights sum to 1.
    spreading_exponent
        ``s`` of the cos-2s spreading, or None for a long-crested sea (one direction, weight 1).
    """

    heading_deg: NDArray[np.float64]
    weight: NDArray[np.float64]
    spreading_exponent: float | None

    @property
    def long_crested(self) -> bool:
        """One direction: the sea is long-crested."""
        return self.spreading_exponent is None


def directional_quadrature(
    mean_heading_deg: float, spreading_exponent: float | None, directions: int = DEFAULT_DIRECTIONS
) -> DirectionalQuadrature:
    """The cos-2s spreading as ``directions`` wave directions and their shares of the energy.

    The midpoint rule over the directions that hold all but 1e-6 of the energy (at most a full circle): equal
    spacing, each direction weighted by ``D`` there, the weights scaled to sum to 1. ``D`` and its derivatives
    vanish at the ends of that range, so the rule converges faster than any power of the spacing (the circular
    moments of s >= 4 to 1e-6 with 9 directions; s = 1, whose range is the whole circle, to 1e-4). None:
    long-crested (the mean direction, weight 1).

    Parameters
    ----------
    mean_heading_deg
        The mean direction the waves travel [deg] (180 = head seas, 90 = beam seas).
    spreading_exponent
        ``s`` (> 0), or None.
    directions
        Directions (an odd number puts one on the mean direction).
    """
    mean = float(mean_heading_deg)
    if not math.isfinite(mean):
        raise ValueError(f"mean_heading_deg = {mean_heading_deg!r}; allowed: a finite angle in degrees")
    if spreading_exponent is None:
        return DirectionalQuadrature(np.array([mean % 360.0]), np.array([1.0]), None)
    if isinstance(directions, bool) or not isinstance(directions, int) or directions < 1:
        raise ValueError(f"directions = {directions!r}; allowed: an integer >= 1")
    s = _checked_exponent(spreading_exponent)
    half_width = _energy_half_width_rad(s, 1e-6)
    spacing = 2.0 * half_width / directions
    theta = -half_width + spacing * (np.arange(directions) + 0.5)
    weight = spreading_density_per_rad(theta, s)
    return DirectionalQuadrature((mean + np.degrees(theta)) % 360.0, weight / np.sum(weight), s)


def random_directions_deg(
    mean_heading_deg: float, spreading_exponent: float | None, count: int, rng: np.random.Generator
) -> NDArray[np.float64]:
    """``count`` directions [deg] drawn from the cos-2s spreading (inverse CDF on a fine grid); None: all the mean."""
    mean = float(mean_heading_deg)
    if spreading_exponent is None:
        return np.full(int(count), mean % 360.0)
    s = _checked_exponent(spreading_exponent)
    theta = np.linspace(-math.pi, math.pi, _CDF_POINTS)
    density = spreading_density_per_rad(theta, s)
    cdf = cumulative_trapezoid(density, theta, initial=0)
    cdf /= cdf[-1]
    drawn = np.interp(rng.random(int(count)), cdf, theta)
    return np.asarray((mean + np.degrees(drawn)) % 360.0, dtype=float)


def weighted_squared_transfer(transfer_per_direction: NDArray[np.complex128], quadrature: DirectionalQuadrature) -> NDArray[np.float64]:
    """``sum_j w_j |H(omega, theta_j)|^2``: the squared transfer function of a short-crested sea [unit^2 per m^2].

    ``transfer_per_direction``: (n_d, n_w, ...) the transfer functions at the quadrature's directions, in its order.
    """
    H = np.asarray(transfer_per_direction)
    w = quadrature.weight
    if H.shape[0] != w.size:
        raise ValueError(f"transfer functions for {H.shape[0]} directions; the quadrature has {w.size}")
    return np.asarray(np.tensordot(w, np.abs(H) ** 2, axes=(0, 0)), dtype=float)


def _checked_exponent(spreading_exponent: float) -> float:
    s = spreading_exponent
    if isinstance(s, bool) or not isinstance(s, (int, float)) or not math.isfinite(s) or s <= 0.0:
        raise ValueError(f"spreading_exponent = {s!r}; allowed: a number > 0 (cos-2s spreading), or None (long-crested)")
    return float(s)


def _wrap_rad(theta: NDArray[np.float64]) -> NDArray[np.float64]:
    """Angles wrapped to [-pi, pi]."""
    return np.asarray(np.mod(theta + math.pi, 2.0 * math.pi) - math.pi, dtype=float)


def _energy_half_width_rad(spreading_exponent: float, tail: float) -> float:
    """The half-width about the mean direction outside which the spreading holds less than ``tail`` of the energy."""
    theta = np.linspace(0.0, math.pi, _CDF_POINTS)
    density = spreading_density_per_rad(theta, spreading_exponent)
    inside = cumulative_trapezoid(density, theta, initial=0)
    outside = 2.0 * (inside[-1] - inside)
    index = int(np.argmax(outside <= tail)) if np.any(outside <= tail) else theta.size - 1
    return float(theta[max(index, 1)])
