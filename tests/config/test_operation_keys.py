"""criteria.operation: the operation class's keys, their defaults and the errors that name them."""

from __future__ import annotations

import pytest

from seafast.config import CaseError, load_case
from seafast.config.loader import case_from_mapping
from seafast.config.modes import ForecastLevel, OperationClass


def _op(**keys):
    return {"criteria.operation": keys}


def test_no_operation_class_by_default():
    assert load_case().criteria.operation is None


def test_weather_restricted_keys():
    op = load_case(
        overrides=_op(operation_class="weather_restricted", planned_operation_period_h=30, forecast_level="level_a")
    ).criteria.operation
    assert op is not None
    assert op.operation_class is OperationClass.WEATHER_RESTRICTED and op.forecast_level is ForecastLevel.LEVEL_A
    assert op.reference_period_h() == 60.0  # contingency null: T_R = 2 T_POP
    op = load_case(overrides=_op(operation_class="weather_restricted", planned_operation_period_h=72, contingency_h=24)).criteria.operation
    assert op is not None and op.reference_period_h() == 96.0


@pytest.mark.parametrize(
    ("keys", "match"),
    [
        (
            {"operation_class": "weather_restricted", "planned_operation_period_h": 80},
            r"criteria.operation: planned_operation_period_h = 80 h exceeds the weather-restricted limit of 72 h",
        ),
        (
            {"operation_class": "weather_restricted", "planned_operation_period_h": 60},
            r"T_R = T_POP \+ T_C = 120 h .* exceeds the weather-restricted limit of 96 h",
        ),
        (
            {"operation_class": "weather_restricted", "planned_operation_period_h": 36, "forecast_level": "monitoring"},
            r"forecast_level = monitoring: the monitoring tables stop at 24 h",
        ),
        ({"operation_class": "weather_restricted"}, r"needs planned_operation_period_h"),
        ({"operation_class": "weather_restricted", "planned_operation_period_h": -1}, r"planned_operation_period_h"),
        ({"operation_class": "restricted"}, r"criteria.operation.operation_class = 'restricted'"),
        ({"operation_class": "unrestricted"}, r"unrestricted needs its route"),
        (
            {"operation_class": "unrestricted", "route": [{"sector": "A", "season": "S", "extreme_hs_m": 5, "scatter_diagram": "x.csv"}]},
            r"criteria.operation.route\[0\]: leg 'A, S': .*allowed: exactly one of them",
        ),
        (
            {"operation_class": "unrestricted", "route": [{"sector": "A", "season": "S", "scatter_diagram": "x.csv"}]},
            r"needs its months",
        ),
        (
            {"operation_class": "unrestricted", "route": [{"sector": "A", "season": "S", "months": [13], "scatter_diagram": "x.csv"}]},
            r"criteria.operation.route\[0\].months\[0\]",
        ),
        (
            {"operation_class": "unrestricted", "route": [{"sector": "A", "season": "S", "months": [1, 1], "scatter_diagram": "x.csv"}]},
            r"months = \[1, 1\] repeats a month",
        ),
    ],
)
def test_bad_keys_are_named(keys, match):
    with pytest.raises(CaseError, match=match):
        load_case(overrides=_op(**keys))


def test_a_scatter_diagram_is_relative_to_the_case_file(tmp_path):
    data = {
        "criteria": {
            "operation": {
                "operation_class": "unrestricted",
                "route": [{"sector": "A", "season": "S", "months": [1], "scatter_diagram": "route/winter.csv"}],
            }
        }
    }
    op = case_from_mapping(data, base_dir=tmp_path).criteria.operation
    assert op is not None and op.route[0].scatter_diagram == (tmp_path / "route" / "winter.csv").resolve()
