"""Most probable maximum over a duration from a sample of per-realisation maxima, with a confidence interval.

Estimator (per quantity, over the n realisations' maxima x_i of one duration):

``gumbel_mode`` (every maximum > 0)
    The mode (location mu) of a Gumbel distribution fitted by maximum likelihood: the scale
    solves ``beta = mean(x) - sum x e^{-x/beta} / sum e^{-x/beta}`` (Newton's method), then
    ``mu = -beta ln(mean e^{-x/beta})`` -- the equations of ``scipy.stats.gumbel_r.fit``, which
    the tests check this against; written here vectorised so the bootstrap's thousands of fits
    take milliseconds instead of seconds. The mode of the distribution of the maximum is the
    most probable maximum; for a Gumbel it is the 1/e quantile.
``empirical_quantile`` (some maxima are 0, e.g. a detachment gap in a sea where some
    realisations never lift off: an atom at 0 that no Gumbel fits)
    The sample's 1/e quantile (linear interpolation).
``constant`` (all maxima equal, e.g. the linear model's gap, 0)
    That value, with an interval of zero width.

Confidence interval: a percentile bootstrap (``scipy.stats.bootstrap``, 2000 resamples, seeded)
of the same estimator at :data:`CONFIDENCE_LEVEL`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray
from scipy import stats

__all__ = ["CONFIDENCE_LEVEL", "BOOTSTRAP_RESAMPLES", "MPMEstimate", "gumbel_fit", "most_probable_maximum"]

CONFIDENCE_LEVEL = 0.95
"""Level of the MPM confidence intervals."""

BOOTSTRAP_RESAMPLES = 2000
"""Bootstrap resamples per interval."""


def gumbel_fit(x: NDArray, axis: int = -1, iterations: int = 60) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Maximum-likelihood Gumbel (right) location and scale along ``axis`` (vectorised).

    Returns
    -------
    loc, scale
        mu and beta; the scale is floored at 1e-12 of the data's magnitude (a sample of equal
        values has beta -> 0).
    """
    a = np.moveaxis(np.asarray(x, dtype=float), axis, -1)
    centre = a.mean(axis=-1, keepdims=True)
    y = a - centre  # the equations are shift-invariant; centring keeps the exponentials tame
    spread = y.std(axis=-1)
    floor = 1e-12 * np.maximum(np.abs(centre[..., 0]), 1e-300)
    beta = np.maximum(spread * math.sqrt(6.0) / math.pi, floor)  # method-of-moments start
    for _ in range(iterations):
        z = -y / beta[..., None]
        w = np.exp(z - z.max(axis=-1, keepdims=True))
        sw = w.sum(axis=-1)
        m1 = (w * y).sum(axis=-1) / sw
        var = (w * y * y).sum(axis=-1) / sw - m1 * m1
        f = beta + m1  # beta - mean(y) + weighted mean(y), mean(y) = 0
        step = f / (1.0 + var / beta**2)
        beta = np.maximum(beta - step, 0.5 * beta)
        if np.all(np.abs(step) <= 1e-13 * beta + floor):
            break
    z = -y / beta[..., None]
    zmax = z.max(axis=-1)
    loc = centre[..., 0] - beta * (zmax + np.log(np.mean(np.exp(z - zmax[..., None]), axis=-1)))
    return loc, beta


def _gumbel_mode(sample: NDArray, axis: int = -1) -> NDArray[np.float64]:
    return gumbel_fit(sample, axis=axis)[0]


def _quantile(sample: NDArray, axis: int = -1) -> NDArray[np.float64]:
    return np.quantile(sample, math.exp(-1.0), axis=axis)


@dataclass(frozen=True)
class MPMEstimate:
    """A most probable maximum and its confidence interval.

    Attributes
    ----------
    value
        The MPM estimate [unit of the quantity].
    interval
        (low, high) at ``confidence_level``.
    method
        ``gumbel_mode``, ``empirical_quantile`` or ``constant``.
    confidence_level
        Level of ``interval``.
    gumbel_scale
        beta of the Gumbel fit (NaN for the other methods).
    """

    value: float
    interval: tuple[float, float]
    method: str
    confidence_level: float
    gumbel_scale: float


def most_probable_maximum(maxima: NDArray, seed: int = 0, confidence_level: float = CONFIDENCE_LEVEL) -> MPMEstimate:
    """MPM over the duration from per-realisation maxima (see the module docstring).

    Parameters
    ----------
    maxima
        (n,) one maximum per realisation (NaN entries, failed realisations, are dropped).
    seed
        Seed of the bootstrap resampling.
    confidence_level
        Level of the interval.
    """
    x = np.asarray(maxima, dtype=float)
    x = x[np.isfinite(x)]
    if x.size == 0:
        return MPMEstimate(math.nan, (math.nan, math.nan), "none", confidence_level, math.nan)
    if np.ptp(x) <= 1e-12 * max(float(np.max(np.abs(x))), 1e-300) or x.size < 3:
        v = float(np.median(x)) if x.size < 3 else float(x[0])
        return MPMEstimate(v, (v, v), "constant", confidence_level, math.nan)
    if np.all(x > 0.0):
        statistic, method = _gumbel_mode, "gumbel_mode"
        value_arr, scale_arr = gumbel_fit(x)
        value, scale = float(value_arr), float(scale_arr)
    else:
        statistic, method = _quantile, "empirical_quantile"
        value, scale = float(_quantile(x)), math.nan
    res = stats.bootstrap(
        (x,),
        statistic,
        vectorized=True,
        n_resamples=BOOTSTRAP_RESAMPLES,
        confidence_level=confidence_level,
        method="percentile",
        rng=np.random.default_rng(seed),
    )
    lo, hi = float(res.confidence_interval.low), float(res.confidence_interval.high)
    return MPMEstimate(value, (lo, hi), method, confidence_level, scale)
