"""The sweep table's helpers: exact extremes of a harmonic series, fold detection, the stability tolerance and
verdicts, range limits."""

from __future__ import annotations

import numpy as np
import pytest

from seafast.analyses.sweep.range import RangeLimits, time_extremes
from seafast.analyses.sweep.stability import FoldCluster, classify_stability, fold_clusters, stability_tolerances
from seafast.analyses.sweep.table import significant_folds
from seafast.fourier import harmonics_to_time
from seafast.solvers.branch import FrequencyResponseBranch
from seafast.solvers.floquet import STABILITY_TOLERANCE, Stability


def test_time_extremes_of_one_harmonic_are_exact_and_of_several_sampled_finely():
    X = np.array([[2.0, -1.0], [0.5 - 1.2j, 3.0j]])
    top, top_abs = time_extremes(X)
    np.testing.assert_allclose(top, [2.0 + 1.3, -1.0 + 3.0], rtol=1e-15)
    np.testing.assert_allclose(top_abs, [2.0 + 1.3, 1.0 + 3.0], rtol=1e-15)
    Y = np.array([[0.1], [1.0 + 0.3j], [0.0 - 0.4j], [0.2 + 0.0j]])
    dense = harmonics_to_time(Y, 1 << 16)
    top, top_abs = time_extremes(Y)
    assert top[0] == pytest.approx(dense.max(), rel=2e-6) and top_abs[0] == pytest.approx(np.abs(dense).max(), rel=2e-6)


def _branch(omega: list[float], span: list[float]) -> FrequencyResponseBranch:
    w = np.asarray(omega)
    tangent = np.append(np.diff(w), w[-1] - w[-2])  # towards the next point, as the continuation's tangent
    U = np.zeros((w.size, 3, 1))
    U[:, 0, 0] = 1.0
    U[:, 1, 0] = 0.5 * np.asarray(span)  # cosine amplitude: peak-to-peak = span
    n = w.size
    return FrequencyResponseBranch(
        w,
        np.zeros(n),
        np.zeros(n),
        np.zeros(n),
        np.ones(n, bool),
        np.ones(n, bool),
        compression_harmonics_m=U,
        tangent_omega=tangent,
        residual_norm=np.zeros(n),
    )


def test_folds_keep_real_turns_and_merge_the_zigzags_of_a_sharp_fold():
    # up to 2.0 (fold), back to 1.5 where the branch zigzags by 0.1 % with the same response, then up again
    up = list(np.linspace(1.0, 2.0, 21))
    back = list(np.linspace(1.95, 1.505, 10))
    zigzag = [1.5, 1.5015, 1.4995, 1.501, 1.4990, 1.5005]
    again = list(np.linspace(1.51, 3.0, 20))
    omega = up + back + zigzag + again
    span = (
        list(np.linspace(0.5, 1.0, 21))
        + list(np.linspace(1.05, 1.5, 10))
        + [1.5, 1.501, 1.502, 1.503, 1.504, 1.505]
        + list(np.linspace(1.45, 0.5, 20))
    )
    b = _branch(omega, span)
    assert b.turning_indices.size == 6  # the raw turns: the real two and four of the zigzag
    folds = significant_folds(b)
    figures = f"raw turns at {b.turning_omegas_rad_s}; folds at {b.omega_rad_s[folds]}"
    assert b.omega_rad_s[folds] == pytest.approx([2.0, 1.4990]), figures  # the fold at the extreme omega of its zigzag
    # the zigzag's five turns are the second fold's
    assert [len(c.turns) for c in fold_clusters(b)] == [1, 5] and [c.maximum for c in fold_clusters(b)] == [True, False]
    # a pair of turns as close in omega but with a different response is a real fold pair (grazing), kept
    span2 = list(span)
    for i in range(31, 37):
        span2[i] = 1.5 + 0.1 * (i - 31)
    assert significant_folds(_branch(omega, span2)).size == 6


def test_a_point_is_decided_within_the_deviation_of_its_neighbouring_confirmed_folds():
    folds = (
        FoldCluster(10, (10,), True, 0.004),
        FoldCluster(20, (20,), False, 0.02),
        FoldCluster(35, (35,), True, 0.6),  # no multiplier near +1: not a fold of the orbits, sets no tolerance
    )
    assert [c.confirmed for c in folds] == [True, True, False] and not FoldCluster(1, (1,), True).confirmed  # NaN: unknown
    tolerance = stability_tolerances(folds, 50)
    expected = np.full(50, 0.02)
    expected[:11] = 0.004  # before the first fold and at it: its own deviation; between two folds the larger
    np.testing.assert_array_equal(tolerance, expected)
    assert stability_tolerances((), 3).tolist() == [STABILITY_TOLERANCE] * 3
    verdicts = classify_stability(np.array([0.99, 0.99, 1.015, 1.03, 1.0]), np.array([0.004, 0.02, 0.02, 0.02, 0.0]))
    assert verdicts == (Stability.STABLE, Stability.MARGINAL, Stability.MARGINAL, Stability.UNSTABLE, Stability.MARGINAL)


def test_range_limits_name_the_bad_field():
    with pytest.raises(ValueError, match="max_gap_m"):
        RangeLimits(max_gap_m=-0.1)
    with pytest.raises(ValueError, match="gravity_m_per_s2"):
        RangeLimits(gravity_m_per_s2=float("inf"))
