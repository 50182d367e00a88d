"""The alpha factor against the standard's tables at their own entries, between them, and bad input refused."""

from __future__ import annotations

import math

import numpy as np
import pytest

from seafast.analyses.criteria.alpha_factor import ALPHA_TABLES, alpha_factor, weather_restriction
from seafast.config.modes import ForecastLevel, OperationClass
from seafast.config.operation import OperationConfig

# DNV-OS-H101 (2011) Sec.4 Tables 4-1 to 4-5, written out again here as the table reads:
# T_POP <= [h] | Hs = 1 | Hs = 2 | Hs = 4 | Hs >= 6
STANDARD = {
    ForecastLevel.BASE: """
        12 0.65 0.76 0.79 0.80
        24 0.63 0.73 0.76 0.78
        36 0.62 0.71 0.73 0.76
        48 0.60 0.68 0.71 0.74
        72 0.55 0.63 0.68 0.72""",
    ForecastLevel.LEVEL_B: """
        12 0.68 0.80 0.83 0.84
        24 0.66 0.77 0.80 0.82
        36 0.65 0.75 0.77 0.80
        48 0.63 0.71 0.75 0.78
        72 0.58 0.66 0.71 0.76""",
    ForecastLevel.LEVEL_A: """
        12 0.72 0.84 0.87 0.88
        24 0.69 0.80 0.84 0.86
        36 0.68 0.78 0.80 0.84
        48 0.66 0.75 0.78 0.81
        72 0.61 0.69 0.75 0.79""",
    ForecastLevel.MONITORING: """
        4 0.90 0.95 1.00 1.00
        12 0.72 0.84 0.87 0.88
        24 0.66 0.77 0.80 0.82""",
    ForecastLevel.MONITORING_LEVEL_A: """
        4 0.90 0.95 1.00 1.00
        12 0.78 0.91 0.95 0.96
        24 0.72 0.84 0.87 0.90""",
}
COLUMNS_M = (1.0, 2.0, 4.0, 6.0)


def _entries():
    for level, text in STANDARD.items():
        rows = [[float(v) for v in line.split()] for line in text.strip().splitlines()]
        for i, (bound, *alphas) in enumerate(rows):
            previous = rows[i - 1][0] if i else 0.0
            for hs, a in zip(COLUMNS_M, alphas, strict=True):
                yield level, previous, bound, hs, a


ENTRIES = list(_entries())


def test_every_entry_of_every_table():
    assert len(ENTRIES) == 4 * (5 + 5 + 5 + 3 + 3)
    for level, previous, bound, hs, expected in ENTRIES:
        # at the row's bound, and just above the previous bound: the same row (rows are steps)
        assert alpha_factor(bound, hs, level) == pytest.approx(expected, abs=1e-15), (level, bound, hs)
        assert alpha_factor(previous + 0.01, hs, level) == pytest.approx(expected, abs=1e-15), (level, previous, hs)
    for level, table in ALPHA_TABLES.items():
        assert table.forecast_level is level and table.name.startswith("DNV-OS-H101 (2011) Sec.4 B700 Table 4-")


@pytest.mark.parametrize(
    ("level", "tpop_h", "hs_m", "expected"),
    [
        (ForecastLevel.BASE, 12.0, 3.5, 0.76 + 0.75 * (0.79 - 0.76)),  # 0.7825
        (ForecastLevel.BASE, 6.0, 2.5, 0.76 + 0.25 * (0.79 - 0.76)),  # 0.7675, row 12
        (ForecastLevel.BASE, 72.0, 1.5, 0.5 * (0.55 + 0.63)),  # 0.59
        (ForecastLevel.BASE, 30.0, 5.0, 0.5 * (0.73 + 0.76)),  # row 36: 0.745
        (ForecastLevel.BASE, 24.0, 9.0, 0.78),  # from 6 m up: the last column
        (ForecastLevel.LEVEL_A, 48.0, 5.0, 0.5 * (0.78 + 0.81)),
        (ForecastLevel.LEVEL_B, 40.0, 3.0, 0.5 * (0.71 + 0.75)),  # row 48
        (ForecastLevel.MONITORING, 3.0, 1.5, 0.925),
        (ForecastLevel.MONITORING_LEVEL_A, 20.0, 5.0, 0.885),
    ],
)
def test_between_the_entries(level, tpop_h, hs_m, expected):
    assert alpha_factor(tpop_h, hs_m, level) == pytest.approx(expected, abs=1e-14)


@pytest.mark.parametrize(
    ("tpop_h", "hs_m", "level", "match"),
    [
        (72.5, 3.0, ForecastLevel.BASE, r"T_POP = 72.5 h .*allowed: 0 < T_POP <= 72 h"),
        (0.0, 3.0, ForecastLevel.BASE, r"T_POP = 0 h"),
        (math.nan, 3.0, ForecastLevel.BASE, r"T_POP = nan h"),
        (30.0, 3.0, ForecastLevel.MONITORING, r"T_POP = 30 h .*Table 4-4.*allowed: 0 < T_POP <= 24 h"),
        (24.0, 0.9, ForecastLevel.BASE, r"OP_LIM = 0.9 m .*allowed: Hs >= 1 m"),
    ],
)
def test_outside_the_table_is_refused(tpop_h, hs_m, level, match):
    with pytest.raises(ValueError, match=match):
        alpha_factor(tpop_h, hs_m, level)


def test_weather_restriction_reduces_the_limit():
    op = OperationConfig(operation_class=OperationClass.WEATHER_RESTRICTED, planned_operation_period_h=20.0, contingency_h=10.0)
    wr = weather_restriction(op)
    assert (wr.planned_operation_period_h, wr.contingency_h, wr.reference_period_h) == (20.0, 10.0, 30.0)
    limits = np.array([0.8, 1.0, 3.0, 7.0, np.nan])
    alpha = wr.alpha(limits)
    expected = np.array([np.nan, 0.63, 0.5 * (0.73 + 0.76), 0.78, np.nan])  # row 24 of Table 4-1
    np.testing.assert_allclose(alpha, expected, atol=1e-15)
    np.testing.assert_allclose(wr.forecast_limit_m(limits), expected * limits, atol=1e-14)
    # contingency not given: T_R = 2 T_POP
    assert (
        weather_restriction(OperationConfig(operation_class="weather_restricted", planned_operation_period_h=30.0)).reference_period_h
        == 60.0
    )


def test_an_unrestricted_operation_has_no_weather_restriction():
    op = OperationConfig(operation_class="unrestricted", route=[{"sector": "a", "season": "b", "extreme_hs_m": 5.0}])
    with pytest.raises(ValueError, match="operation_class = unrestricted: no weather restriction"):
        weather_restriction(op)
