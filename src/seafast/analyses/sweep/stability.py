"""Folds of a frequency-response branch and the stability verdict of each point, with its tolerance.

A point's orbit is stable when its largest Floquet multiplier modulus lies inside the unit circle
(:func:`seafast.solvers.floquet.floquet_multipliers`). How far inside must it be before a verdict
is more than round-off? The multipliers are exact for the *computed* orbit; what is not exact is
the orbit (H harmonics, N AFT samples). At a fold the exact answer is known: one real multiplier
is +1. So the multiplier nearest to +1 at each located fold point (``FrequencyResponseBranch.at_fold``,
the extreme of omega along the branch) measures how far the discretisation's stability indicator
is off where it matters: ``min_k |mu_k - 1|`` there. A point between two folds is decided with the
larger of its two folds' deviations (:func:`stability_tolerances`, never below
:data:`seafast.solvers.floquet.STABILITY_TOLERANCE`); within it, its verdict is
:attr:`~seafast.solvers.floquet.Stability.MARGINAL`: the discretisation cannot say on which side of
the fold's stability change the point lies. The deviation shrinks with N: on the example deck
table (docs/sweeps.md) 0.2-0.3 % and 0.7 % at N = 512, 2 % at N = 128, where the sampled contact
also makes the branch zigzag over the lower fold (which turn of the zigzag is the fold, and its
multiplier, then hinge on round-off: hence the sweep's N of at least 512).

A fold whose nearest multiplier lies farther than :data:`FOLD_CONFIRMATION` from +1 is not a
bifurcation of the orbits the branch carries: the discretisation contradicts itself there (the
base case's stiff saddles at H = 10 fold near 2 rad/s with every multiplier below 0.5 and an
estimated truncation error of 17 %; at H = 64 the branch does not fold). Such a fold is reported
unconfirmed (:attr:`FoldCluster.confirmed`) and sets no tolerance.

Units: multipliers and tolerances are dimensionless; omega in rad/s. Nothing here prints or writes files.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
from numpy.typing import NDArray

from seafast.fourier import real_dft_matrices
from seafast.solvers.branch import FrequencyResponseBranch
from seafast.solvers.floquet import STABILITY_TOLERANCE, Stability

__all__ = [
    "FOLD_SEPARATION",
    "FOLD_RESPONSE_CHANGE",
    "FOLD_CONFIRMATION",
    "FoldCluster",
    "fold_clusters",
    "significant_folds",
    "with_multipliers",
    "stability_tolerances",
    "classify_stability",
]

FOLD_SEPARATION = 0.005
"""Two turns of a branch closer than this share of omega ... """

FOLD_RESPONSE_CHANGE = 0.02
"""... and whose peak-to-peak compressions differ by less than this share are one fold (the small
zigzags of the discrete AFT branch at a sharp fold, :func:`fold_clusters`)."""

FOLD_CONFIRMATION = 0.1
"""A fold is confirmed by the Floquet multipliers when one of its fold point's lies within this distance
of +1 [-] (measured: 4e-4 to 0.014 at the folds of the example deck tables at N = 512, 0.023 at N = 128;
0.59 and 0.97 at the spurious folds of a 17 %-truncated branch)."""


@dataclass(frozen=True)
class FoldCluster:
    """One fold of a branch and the discrete turns merged into it.

    Attributes
    ----------
    index
        The fold's point: the extreme omega between the neighbouring folds.
    turns
        Indices of the branch's turns merged into this fold (its own included), ascending.
    maximum
        Whether the fold is a maximum of omega (the branch turned from increasing to decreasing omega).
    distance_to_one
        ``min_k |mu_k - 1|`` of the fold point's multipliers [-] (NaN until the multipliers are known):
        the discretisation's deviation from the +1 a fold has.
    """

    index: int
    turns: tuple[int, ...]
    maximum: bool
    distance_to_one: float = float("nan")

    @property
    def confirmed(self) -> bool:
        """Whether a multiplier of the fold point lies within :data:`FOLD_CONFIRMATION` of +1."""
        return bool(self.distance_to_one <= FOLD_CONFIRMATION)

    @property
    def first(self) -> int:
        """The first point of the fold's zigzag (its index when there is none)."""
        return min((self.index,) + self.turns)

    @property
    def last(self) -> int:
        """The last point of the fold's zigzag."""
        return max((self.index,) + self.turns)


def _spans(branch: FrequencyResponseBranch) -> NDArray[np.float64]:
    """Peak-to-peak saddle compression of each point, largest over the saddles [m]."""
    U = branch.compression_harmonics_m
    inverse = real_dft_matrices(U.shape[1] // 2, 128)[0]
    return np.asarray(np.ptp(np.einsum("th,nhs->nts", inverse, U), axis=1).max(axis=1), dtype=float)


def fold_clusters(
    branch: FrequencyResponseBranch, min_separation: float = FOLD_SEPARATION, min_response_change: float = FOLD_RESPONSE_CHANGE
) -> tuple[FoldCluster, ...]:
    """The folds of a branch (omega extremes), the small zigzags of a sharp fold merged into it.

    The discrete branch turns wherever omega changes direction (:attr:`FrequencyResponseBranch.turning_indices`).
    At a sharp fold the AFT's sampled contact can make it zigzag: two neighbouring turns are merged
    (closest first) when they are closer than ``min_separation`` of omega *and* their peak-to-peak saddle
    compressions differ by less than ``min_response_change`` (a real fold pair, e.g. at grazing, changes
    the response); the merged pair joins the neighbouring turn nearer in omega. Each remaining fold is put
    at the extreme omega between its neighbours.
    """
    turns = [int(i) for i in branch.turning_indices]
    w = branch.omega_rad_s
    if not turns:
        return ()
    upper = {i: bool(w[i] > w[i - 1]) for i in turns}  # a maximum of omega
    span = _spans(branch)
    merged: dict[int, list[int]] = {i: [i] for i in turns}

    def close(a: int, b: int) -> bool:
        near = abs(w[a] - w[b]) < min_separation * w[a]
        return bool(near and abs(span[a] - span[b]) < min_response_change * max(span[a], span[b], 1e-300))

    while len(turns) >= 2:
        pairs = [j for j in range(len(turns) - 1) if close(turns[j], turns[j + 1])]
        if not pairs:
            break
        j = min(pairs, key=lambda j: abs(w[turns[j]] - w[turns[j + 1]]))
        gone = merged.pop(turns[j]) + merged.pop(turns[j + 1])
        neighbours = [turns[k] for k in (j - 1, j + 2) if 0 <= k < len(turns)]
        del turns[j : j + 2]
        if neighbours:
            keep = min(neighbours, key=lambda i: abs(w[i] - w[gone[0]]))
            merged[keep] += gone
    out = []
    bounds = [0] + turns + [w.size - 1]
    for j, i in enumerate(turns):
        lo, hi = bounds[j], bounds[j + 2]
        seg = w[lo : hi + 1]
        index = lo + int(np.argmax(seg) if upper[i] else np.argmin(seg))
        out.append(FoldCluster(index, tuple(sorted(merged[i])), upper[i]))
    return tuple(out)


def significant_folds(
    branch: FrequencyResponseBranch, min_separation: float = FOLD_SEPARATION, min_response_change: float = FOLD_RESPONSE_CHANGE
) -> NDArray[np.intp]:
    """Indices of the branch points at its folds (:func:`fold_clusters`), in branch order."""
    return np.asarray([c.index for c in fold_clusters(branch, min_separation, min_response_change)], dtype=np.intp)


def with_multipliers(clusters: tuple[FoldCluster, ...], distance_to_one: NDArray[np.float64]) -> tuple[FoldCluster, ...]:
    """The folds with their fold point's ``distance_to_one`` (per point ``min_k |mu_k - 1|`` [-])."""
    return tuple(replace(c, distance_to_one=float(distance_to_one[c.index])) for c in clusters)


def stability_tolerances(clusters: tuple[FoldCluster, ...], points: int) -> NDArray[np.float64]:
    """The tolerance on ``|mu| - 1`` of each of the branch's ``points`` [-] (see the module docstring).

    A confirmed fold's deviation is its ``distance_to_one``; each point takes the larger deviation of the
    confirmed folds before and after it, at least :data:`~seafast.solvers.floquet.STABILITY_TOLERANCE`.
    """
    tolerance = np.full(points, STABILITY_TOLERANCE)
    index = np.arange(points)
    folds = [c for c in clusters if c.confirmed]
    for j, c in enumerate(folds):
        before = folds[j - 1].index if j > 0 else -1
        after = folds[j + 1].index if j + 1 < len(folds) else points
        reach = (index > before) & (index < after)
        tolerance[reach] = np.maximum(tolerance[reach], max(STABILITY_TOLERANCE, c.distance_to_one))
    return tolerance


def classify_stability(max_modulus: NDArray[np.float64], tolerance: NDArray[np.float64]) -> tuple[Stability, ...]:
    """Each point's verdict: stable below ``1 - tolerance``, unstable above ``1 + tolerance``, marginal between."""
    out = []
    for mu, tol in zip(np.asarray(max_modulus, dtype=float), np.asarray(tolerance, dtype=float), strict=True):
        out.append(Stability.STABLE if mu < 1.0 - tol else Stability.UNSTABLE if mu > 1.0 + tol else Stability.MARGINAL)
    return tuple(out)
