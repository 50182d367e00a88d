"""``seafast operability`` and ``seafast criteria`` with an operation class: the routing columns, route.csv, operation.csv."""

from __future__ import annotations

import csv
import math

import pytest

from seafast.analyses.criteria.alpha_factor import alpha_factor
from seafast.cli import main
from seafast.config.modes import ForecastLevel
from seafast.output.operability import OPERABILITY_COLUMNS
from seafast.output.operation_class import OPERATION_COLUMNS, ROUTE_COLUMNS, ROUTING_COLUMNS

RAISED = ["--set", "limits.max_saddle_force_N=11.5e6", "--set", "limits.max_bending_stress_Pa=28e6"]


def _rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def _set_operation(**keys):
    out = []
    for k, v in keys.items():
        out += ["--set", f"criteria.operation.{k}={v}"]
    return out


def test_operability_weather_routing_columns(tmp_path, capsys):
    op = _set_operation(operation_class="weather_restricted", planned_operation_period_h=20, contingency_h=16, forecast_level="level_b")
    assert main(["operability", "--tp", "6:7:1", "-o", str(tmp_path), "--no-plots", *RAISED, *op]) == 0
    with open(tmp_path / "operability.csv", newline="") as f:
        header = next(csv.reader(f))
    assert tuple(header) == (*OPERABILITY_COLUMNS, *ROUTING_COLUMNS)
    rows = _rows(tmp_path / "operability.csv")
    assert [float(r["peak_period_s"]) for r in rows] == [6.0, 7.0]
    defined = 0
    for r in rows:
        for model in ("linear", "nonlinear"):
            op_lim = float(r[f"hs_allowable_{model}_m"])
            if op_lim < 1.0:  # below the tables: no alpha, empty cells
                assert r[f"alpha_{model}"] == "" and r[f"hs_forecast_limit_{model}_m"] == ""
                continue
            alpha = alpha_factor(20.0, op_lim, ForecastLevel.LEVEL_B)  # Table 4-2, row 24
            assert 0.66 <= alpha <= 0.82
            assert float(r[f"alpha_{model}"]) == pytest.approx(alpha, rel=1e-15)
            assert float(r[f"hs_forecast_limit_{model}_m"]) == pytest.approx(alpha * op_lim, rel=1e-15)
            defined += 1
    assert defined >= 2
    out = capsys.readouterr().out
    assert "weather-restricted, T_POP 20 h, T_C 16 h, T_R 36 h" in out and "Table 4-2" in out and "OP_WF" in out


def test_operability_route_checked_over_its_tp_range(tmp_path, capsys):
    # 0.5 m: Tp range sqrt(6.5) - sqrt(15) = 2.55 - 3.87 s (none analysed); 1.0 m: 3.61 - 5.48 s holds Tp 5
    route = "[{sector: A, season: S, extreme_hs_m: 1.0}, {sector: B, season: S, extreme_hs_m: 0.5}]"
    args = ["operability", "--tp", "5", "-o", str(tmp_path), "--no-plots", *RAISED, *_set_operation(operation_class="unrestricted")]
    assert main([*args, "--set", f"criteria.operation.route={route}"]) == 0
    ops = _rows(tmp_path / "operability.csv")
    rows = _rows(tmp_path / "route.csv")
    assert tuple(rows[0]) == ROUTE_COLUMNS and [r["sector"] for r in rows] == ["A", "B"]
    hs_nl = float(ops[0]["hs_allowable_nonlinear_m"])
    assert float(rows[0]["hs_allowable_nonlinear_m"]) == hs_nl and float(rows[0]["governing_peak_period_s"]) == 5.0
    assert float(rows[0]["utilisation_nonlinear"]) == pytest.approx(1.0 / hs_nl, rel=1e-15)
    assert rows[0]["verdict"] == ("pass" if hs_nl >= 1.0 else "fail") and float(rows[0]["governing_heading_deg"]) == 180.0
    assert rows[1]["verdict"] == "not_assessed" and rows[1]["utilisation_nonlinear"] == ""
    captured = capsys.readouterr()
    assert "route leg 'B, S': no analysed peak period in its range 2.55-3.87 s" in captured.err


def test_criteria_states_the_operation_class(tmp_path, capsys):
    op = _set_operation(operation_class="weather_restricted", planned_operation_period_h=36)
    assert main(["criteria", "-o", str(tmp_path), *op]) == 0
    rows = _rows(tmp_path / "operation.csv")
    assert tuple(rows[0]) == OPERATION_COLUMNS
    # Table 4-1, row 36 at 1, 2, 4, 6 m; T_C = T_POP
    assert [float(r["alpha"]) for r in rows] == [0.62, 0.71, 0.73, 0.76]
    assert [float(r["hs_forecast_limit_m"]) for r in rows] == pytest.approx([0.62, 1.42, 2.92, 4.56], rel=1e-15)
    assert {r["reference_period_h"] for r in rows} == {"72.0"}
    assert "weather-restricted, T_POP 36 h" in capsys.readouterr().out
    assert len(_rows(tmp_path / "criteria.csv")) == 16  # the default criteria as before


def test_criteria_route_from_a_scatter_diagram(tmp_path):
    scatter = tmp_path / "leg.csv"
    lines = ["significant_height_m,peak_period_s,occurrence"]
    lines += [f"{0.25 + 0.5 * i},8,{math.exp(-0.5 * i)}" for i in range(14)]
    scatter.write_text("\n".join(lines) + "\n", encoding="utf-8")
    case = tmp_path / "case.yaml"
    case.write_text(
        "criteria:\n  operation:\n    operation_class: unrestricted\n"
        "    route: [{sector: N, season: winter, months: [1, 2], scatter_diagram: leg.csv}]\n",
        encoding="utf-8",
    )
    assert main(["criteria", str(case), "-o", str(tmp_path / "out"), "-q"]) == 0
    (row,) = _rows(tmp_path / "out" / "route.csv")
    assert row["method"] == "weibull_3p" and row["source"] == "leg.csv" and row["verdict"] == ""
    assert float(row["sea_states"]) == pytest.approx(10 * 8 * (31 + 28.25) / 2, rel=1e-15)
    hs = float(row["design_hs_m"])
    assert 7.0 < hs < 12.0  # beyond the diagram's largest class (6.75 m), a 2370-sea-state extreme
    assert float(row["tp_max_s"]) == pytest.approx(math.sqrt(30 * hs), rel=1e-15)


@pytest.mark.parametrize(
    ("keys", "needle"),
    [
        ({"operation_class": "weather_restricted", "planned_operation_period_h": 73}, "planned_operation_period_h = 73 h exceeds"),
        ({"operation_class": "weather_restricted", "planned_operation_period_h": 48, "contingency_h": 60}, "T_R = T_POP + T_C = 108 h"),
        ({"operation_class": "unrestricted"}, "unrestricted needs its route"),
    ],
)
def test_bad_operation_exits_2_naming_the_key(tmp_path, capsys, keys, needle):
    assert main(["criteria", "-o", str(tmp_path / "out"), *_set_operation(**keys)]) == 2
    err = capsys.readouterr().err
    assert "criteria.operation" in err and needle in err
    assert not (tmp_path / "out").exists()
