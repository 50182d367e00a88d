"""The operation class on allowable sea states: OP_WF = alpha OP_LIM per row, and route legs checked over their Tp range."""

from __future__ import annotations

import math

import numpy as np
import pytest

from seafast.analyses.criteria.alpha_factor import weather_restriction
from seafast.analyses.criteria.operation_class import AllowableTable, RouteVerdict, plan_operation, route_checks, weather_routing_limits
from seafast.analyses.criteria.route_extremes import ExtremeMethod, RouteDesignSeaState
from seafast.config.operation import OperationConfig

# two headings x four peak periods; nonlinear NaN at 150 deg, Tp 12 s (a search that did not converge)
TABLE = AllowableTable.of(
    [180.0] * 4 + [150.0] * 4,
    [6.0, 8.0, 10.0, 12.0] * 2,
    [2.4, 1.6, 0.9, 1.2, 2.6, 1.5, 1.1, 1.3],
    [2.5, 1.7, 0.95, 1.25, 2.7, 1.4, 1.2, math.nan],
)


def _state(hs: float, tp_min: float, tp_max: float) -> RouteDesignSeaState:
    return RouteDesignSeaState("S", "W", hs, tp_min, tp_max, ExtremeMethod.EXTREME_TABLE, math.nan, None, "extreme table")


def test_weather_routing_limit_per_row():
    op = OperationConfig(operation_class="weather_restricted", planned_operation_period_h=48.0, contingency_h=24.0)
    limits = weather_routing_limits(weather_restriction(op), TABLE)
    # Table 4-1, row 48: 0.60 / 0.68 / 0.71 / 0.74 at 1 / 2 / 4 / 6 m, linear in between
    row48 = {2.5: 0.68 + 0.25 * 0.03, 1.7: 0.60 + 0.7 * 0.08, 0.95: math.nan, 1.25: 0.60 + 0.25 * 0.08}
    expected = [row48[h] for h in (2.5, 1.7, 0.95, 1.25)]
    np.testing.assert_allclose(limits.alpha_nonlinear[:4], expected, atol=1e-14)
    np.testing.assert_allclose(limits.hs_forecast_limit_nonlinear_m[:4], np.array(expected) * [2.5, 1.7, 0.95, 1.25], atol=1e-14)
    assert limits.alpha_linear[4] == pytest.approx(0.68 + 0.3 * 0.03, abs=1e-14)  # 2.6 m
    assert math.isnan(limits.hs_forecast_limit_nonlinear_m[7])  # OP_LIM not found: no OP_WF
    assert np.all(
        limits.hs_forecast_limit_linear_m[np.isfinite(limits.alpha_linear)] < TABLE.hs_allowable_linear_m[np.isfinite(limits.alpha_linear)]
    )


def test_route_legs_against_the_allowable_hs_in_their_range():
    checks = route_checks(
        (
            _state(0.9, 7.0, 9.0),  # Tp 8 only: smallest nonlinear 1.4 m at 150 deg
            _state(1.5, 5.0, 11.0),  # Tp 6, 8, 10: smallest 0.95 m at 180 deg, Tp 10 -> fails
            _state(1.0, 11.0, 13.0),  # Tp 12: a NaN at 150 deg -> not assessed
            _state(1.0, 13.5, 15.0),  # no analysed Tp -> not assessed
        ),
        TABLE,
    )
    a, b, c, d = checks
    assert a.peak_periods_s == (8.0,) and a.verdict is RouteVerdict.PASS
    assert (a.hs_allowable_nonlinear_m, a.governing_peak_period_s, a.governing_heading_deg) == (1.4, 8.0, 150.0)
    assert a.utilisation_nonlinear == pytest.approx(0.9 / 1.4, rel=1e-15) and a.hs_allowable_linear_m == 1.5
    assert b.peak_periods_s == (6.0, 8.0, 10.0) and b.verdict is RouteVerdict.FAIL
    assert (b.hs_allowable_nonlinear_m, b.governing_peak_period_s, b.governing_heading_deg) == (0.95, 10.0, 180.0)
    assert b.utilisation_nonlinear == pytest.approx(1.5 / 0.95, rel=1e-15)
    assert b.utilisation_linear == pytest.approx(1.5 / 0.9, rel=1e-15)
    assert c.verdict is RouteVerdict.NOT_ASSESSED and math.isnan(c.utilisation_nonlinear)
    assert c.utilisation_linear == pytest.approx(1.0 / 1.2, rel=1e-15)
    assert d.verdict is RouteVerdict.NOT_ASSESSED and d.peak_periods_s == ()


def test_plan_of_each_class():
    wr = plan_operation(OperationConfig(operation_class="weather_restricted", planned_operation_period_h=10.0))
    assert wr.restriction is not None and wr.route == () and wr.restriction.reference_period_h == 20.0
    un = plan_operation(OperationConfig(operation_class="unrestricted", route=[{"sector": "A", "season": "B", "extreme_hs_m": 3.0}]))
    assert un.restriction is None and un.route[0].design_hs_m == 3.0
    assert (un.route[0].tp_min_s, un.route[0].tp_max_s) == pytest.approx((math.sqrt(39.0), math.sqrt(90.0)), rel=1e-15)
