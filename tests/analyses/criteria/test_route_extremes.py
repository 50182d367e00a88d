"""The route's 10-year monthly extreme Hs against a known Weibull distribution: binned exactly, and sampled."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from scipy.stats import weibull_min

from seafast.analyses.criteria.route_extremes import (
    ExtremeMethod,
    design_tp_range_s,
    fit_weibull_hs,
    route_design_sea_states,
    sea_states_in_return_period,
)
from seafast.config import CaseError
from seafast.config.operation import OperationConfig

K, GAMMA_M, BETA_M = 1.4, 0.3, 1.6  # a North-Sea-like Hs marginal
MARKS_M = np.arange(0.25, 12.0, 0.5)  # class marks of 0.5 m classes


def _exact_occurrence(marks: np.ndarray) -> np.ndarray:
    """Each class's probability under the known distribution (classes split half-way between marks)."""
    edges = np.append(0.5 * (marks[1:] + marks[:-1]), marks[-1] + 0.5 * (marks[-1] - marks[-2]))
    cdf = weibull_min.cdf(edges, K, loc=GAMMA_M, scale=BETA_M)
    occ = np.diff(np.concatenate([[0.0], cdf]))
    occ[-1] += 1.0 - cdf[-1]
    return occ


def _write_scatter(path: Path, hs: np.ndarray, occ: np.ndarray) -> Path:
    rows = ["significant_height_m,peak_period_s,occurrence"]
    for h, o in zip(hs, occ, strict=True):  # each Hs class split over two peak periods, as a diagram is
        rows += [f"{float(h)!r},8.0,{float(0.4 * o)!r}", f"{float(h)!r},11.0,{float(0.6 * o)!r}"]
    path.write_text("\n".join(rows) + "\n")
    return path


def test_sea_states_of_ten_years_of_a_month():
    assert sea_states_in_return_period((1,)) == 10 * 31 * 8
    assert sea_states_in_return_period((12, 1, 2), 10.0) == pytest.approx(10 * 8 * (31 + 31 + 28.25) / 3, rel=1e-15)
    assert design_tp_range_s(10.0) == pytest.approx((math.sqrt(130.0), math.sqrt(300.0)), rel=1e-15)


def test_exactly_binned_weibull_is_recovered():
    fit = fit_weibull_hs(MARKS_M, _exact_occurrence(MARKS_M))
    assert (fit.shape, fit.location_m, fit.scale_m) == pytest.approx((K, GAMMA_M, BETA_M), rel=1e-9)
    n = sea_states_in_return_period((1,))
    exact = float(weibull_min.isf(1.0 / n, K, loc=GAMMA_M, scale=BETA_M))
    assert fit.return_value_m(n) == pytest.approx(exact, rel=1e-9)
    assert exact == pytest.approx(7.2497, abs=1e-4)  # (ln 2480)^(1/1.4) x 1.6 + 0.3


def test_a_sample_of_a_known_weibull():
    """A seeded sample of n 3-hour sea states, binned in 0.5 m classes.

    The fit's relative error on the return value has a standard deviation of about 1.5 / sqrt(n) (measured
    over 100 seeds at n = 5000, 20000 and 80000: 1.28, 1.31, 1.51 / sqrt(n)); the tolerance is five of them.
    """
    n = 200_000
    rng = np.random.default_rng(7)
    sample = weibull_min.rvs(K, loc=GAMMA_M, scale=BETA_M, size=n, random_state=rng)
    marks, counts = np.unique(np.floor(sample / 0.5) * 0.5 + 0.25, return_counts=True)
    fit = fit_weibull_hs(marks, counts)
    n_states = sea_states_in_return_period((1,))
    exact = float(weibull_min.isf(1.0 / n_states, K, loc=GAMMA_M, scale=BETA_M))
    tolerance = 5 * 1.5 / math.sqrt(n)
    assert fit.return_value_m(n_states) == pytest.approx(exact, rel=tolerance)
    # a one-year return period would be told apart
    assert abs(fit.return_value_m(n_states / 10) / exact - 1) > 3 * tolerance


def test_route_legs_from_a_file_and_a_table(tmp_path):
    path = _write_scatter(tmp_path / "winter.csv", MARKS_M, _exact_occurrence(MARKS_M))
    op = OperationConfig(
        operation_class="unrestricted",
        route=[
            {"sector": "North Sea", "season": "winter", "months": [1], "scatter_diagram": path},
            {"sector": "Baltic", "season": "summer", "extreme_hs_m": 4.0},
        ],
    )
    fitted, given = route_design_sea_states(op)
    exact = float(weibull_min.isf(1.0 / 2480.0, K, loc=GAMMA_M, scale=BETA_M))
    assert fitted.method is ExtremeMethod.WEIBULL_3P and fitted.sea_states == 2480.0
    assert fitted.design_hs_m == pytest.approx(exact, rel=1e-9)
    assert (fitted.tp_min_s, fitted.tp_max_s) == pytest.approx((math.sqrt(13 * exact), math.sqrt(30 * exact)), rel=1e-12)
    assert fitted.source == "winter.csv"
    assert given.method is ExtremeMethod.EXTREME_TABLE and given.design_hs_m == 4.0 and given.fit is None
    assert (given.tp_min_s, given.tp_max_s) == pytest.approx((math.sqrt(52.0), math.sqrt(120.0)), rel=1e-15)


def test_bad_route_data_is_refused(tmp_path):
    few = _write_scatter(tmp_path / "few.csv", np.array([1.0, 2.0, 3.0]), np.array([0.5, 0.3, 0.2]))
    op = OperationConfig(operation_class="unrestricted", route=[{"sector": "A", "season": "S", "months": [3], "scatter_diagram": few}])
    with pytest.raises(ValueError, match=r"leg 'A, S' \(few.csv\): .*3 Hs classes.*at least 4"):
        route_design_sea_states(op)
    missing = OperationConfig(
        operation_class="unrestricted", route=[{"sector": "A", "season": "S", "months": [3], "scatter_diagram": tmp_path / "none.csv"}]
    )
    with pytest.raises(CaseError, match=r"criteria.operation.route.scatter_diagram '.*none.csv': cannot read it"):
        route_design_sea_states(missing)
