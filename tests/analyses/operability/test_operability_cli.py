"""`seafast operability` as a user meets it: outputs, columns, the seastate consistency, scatter
diagrams, bad input, the report section."""

from __future__ import annotations

import csv
import math

import numpy as np
import pytest
import xarray as xr

from seafast.analyses.operability.scatter import assess_scatter, read_scatter_diagram
from seafast.cli import main
from seafast.cli.operability import default_peak_periods, parse_peak_periods
from seafast.config import CaseError, load_case
from seafast.output.operability import OPERABILITY_COLUMNS

RAISED = ["--set", "limits.max_saddle_force_N=11.5e6", "--set", "limits.max_bending_stress_Pa=28e6"]


def _rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    out = tmp_path_factory.mktemp("operability")
    scatter = out / "scatter_in.csv"
    scatter.write_text(
        "# Hs x Tp occurrences (counts)\nsignificant_height_m,peak_period_s,occurrence\n"
        "1.0,10,40\n2.5,10,30\n3.5,10,20\n5.0,10,10\n2.0,13,0\n",
        encoding="utf-8",
    )
    code = main(["operability", "--tp", "9:10:1", "-o", str(out), "--scatter", str(scatter), "-q", *RAISED])
    return out, code


def test_operability_csv_has_the_contract_columns_one_row_per_peak_period(run):
    out, code = run
    assert code == 0
    with open(out / "operability.csv") as f:
        assert (
            f.readline().strip()
            == ",".join(OPERABILITY_COLUMNS)
            == ("peak_period_s,hs_allowable_linear_m,hs_allowable_nonlinear_m,hs_uplift_onset_m,governing_linear,governing_nonlinear")
        )
    rows = _rows(out / "operability.csv")
    assert [float(r["peak_period_s"]) for r in rows] == [9.0, 10.0]
    for r in rows:
        assert r["governing_linear"] == r["governing_nonlinear"] == "saddle_force"
        assert float(r["hs_uplift_onset_m"]) < float(r["hs_allowable_linear_m"]) < float(r["hs_allowable_nonlinear_m"])
    with xr.open_dataset(out / "operability.nc") as ds:
        for name, var in list(ds.data_vars.items()) + list(ds.coords.items()):
            assert var.attrs.get("units") and var.attrs.get("long_name"), name
        assert ds.attrs["max_saddle_force_N"] == 11.5e6
    assert (out / "operability.png").stat().st_size > 20_000


def test_seafast_seastate_at_the_reported_allowable_hs_gives_the_limit_within_one_percent(run, tmp_path):
    # consistency, command to command: the nonlinear design-wave row at the
    # nonlinear allowable Hs, the linear spectral row at the linear one
    out, _ = run
    row = _rows(out / "operability.csv")[1]
    for column, method in (("hs_allowable_nonlinear_m", "design_wave"), ("hs_allowable_linear_m", "spectral")):
        d = tmp_path / method
        assert (
            main(
                [
                    "seastate",
                    "-o",
                    str(d),
                    "--no-monte-carlo",
                    "--no-plots",
                    "-q",
                    *RAISED,
                    "--set",
                    f"sea_state.significant_height_m={row[column]}",
                    "--set",
                    f"sea_state.peak_period_s={row['peak_period_s']}",
                ]
            )
            == 0
        )
        got = next(r for r in _rows(d / "seastate.csv") if r["method"] == method)
        assert float(got["F_N"]) == pytest.approx(11.5e6, rel=0.01), method
        assert float(got["sigma_b_Pa"]) < 28e6


def test_the_scatter_diagram_share_within_the_limits(run):
    out, _ = run
    rows = _rows(out / "operability.csv")
    hs_lin, hs_nl = float(rows[1]["hs_allowable_linear_m"]), float(rows[1]["hs_allowable_nonlinear_m"])
    assert 2.5 < hs_lin < 3.5 and hs_nl < 3.5  # the cells straddle the limits as intended
    cells = _rows(out / "scatter.csv")
    assert [c["within_limits_linear"] for c in cells] == ["true", "true" if 2.5 <= hs_lin else "false", "false", "false", "false"]
    assert [c["within_limits_nonlinear"] for c in cells][:3] == ["true", "true", "false"]
    with xr.open_dataset(out / "operability.nc") as ds:
        assert ds.attrs["share_within_limits_nonlinear"] == pytest.approx(0.7)  # (40 + 30) of 100
        assert ds.attrs["share_within_limits_linear"] == pytest.approx(0.7 if hs_lin >= 2.5 else 0.4)


def test_assess_scatter_by_hand(tmp_path):
    f = tmp_path / "s.csv"
    f.write_text("significant_height_m,peak_period_s,occurrence\n1,8,1\n2,8,1\n1,12,2\n3,12,0\n", encoding="utf-8")
    d = read_scatter_diagram(f)
    assert d.occurrence.sum() == pytest.approx(1.0) and list(d.peak_periods_s) == [8.0, 12.0]
    a = assess_scatter(d, [8.0, 12.0], [1.5, 0.5], [2.5, math.nan])
    assert list(a.within_linear) == [True, False, False, False]
    assert list(a.within_nonlinear) == [True, True, False, False]
    assert a.share_within_linear == pytest.approx(0.25) and a.share_within_nonlinear == pytest.approx(0.5)
    assert list(a.not_assessed) == [False, False, True, False]  # a failed search is never counted within


def test_peak_periods_include_stop():
    assert len(parse_peak_periods("5:16:0.5")) == 23
    assert parse_peak_periods("6:6:1") == [6.0]
    assert parse_peak_periods("6:8.9:1") == [6.0, 7.0, 8.0]


def test_without_tp_the_default_range_runs_and_holds_the_response_peak(tmp_path, capsys):
    """``seafast operability`` with no arguments: Tp 5 to 20 s every 0.5 s; the smallest allowable Hs
    (the response peak per metre of Hs, wave length near the ship's) lies inside the range, not at an end."""
    out = tmp_path / "o"
    assert main(["operability", "-o", str(out), "--no-plots"]) == 0
    assert "31 peak periods 5-20 s every 0.5 s (the default" in capsys.readouterr().err
    rows = _rows(out / "operability.csv")
    assert [float(r["peak_period_s"]) for r in rows] == [5.0 + 0.5 * i for i in range(31)]
    hs = [float(r["hs_allowable_linear_m"]) for r in rows]
    i_min = hs.index(min(hs))
    assert 6 <= i_min <= 12  # Tp 8-11 s; 0.37 m at 9.5-10 s on the base case
    assert hs[0] > 3 * hs[i_min] and hs[-1] > 1.5 * hs[i_min]


def test_the_default_range_starts_where_the_spectrum_is_resolved():
    from seafast.analyses.seastate.spectrum import sea_state_spectrum

    for spectrum, gamma, first in (("jonswap", 3.3, 5.0), ("pierson_moskowitz", 1.0, 5.5), ("jonswap", 10.0, 5.0)):
        shape = {"sea_state.spectrum": spectrum, "sea_state.peak_enhancement": gamma, "sea_state.significant_height_m": 1.0}
        tps = default_peak_periods(load_case(overrides=shape))
        assert tps[0] == first and tps[-1] == 20.0 and len(tps) == round((20.0 - first) / 0.5) + 1
        sea_state_spectrum(load_case(overrides={**shape, "sea_state.peak_period_s": first}))  # resolved: no error
    pm = {"sea_state.spectrum": "pierson_moskowitz", "sea_state.significant_height_m": 1.0, "sea_state.peak_period_s": 5.0}
    with pytest.raises(CaseError, match=r"peak_period_s >= 5\.25 s"):  # the bound the start is rounded up from
        sea_state_spectrum(load_case(overrides=pm))


@pytest.mark.parametrize(
    "args,needle",
    [
        (["--tp", "5:16"], "--tp '5:16'"),
        (["--tp", "16:5:1"], "0 < START <= STOP"),
        (["--tp", "a:b:c"], "--tp 'a:b:c'"),
        (["--tp", "5:16:0"], "STEP > 0"),
        (["--tp", "1:3:1"], "peak_period_s"),
        (["--tp", "8:10:1", "--set", "sea_state.spectrum=hindcast.csv", "--set", "sea_state.peak_period_s=null"], "sea_state.spectrum"),
        (["--tp", "8:10:1", "--set", "limits.max_saddle_force_N=-1"], "limits.max_saddle_force_N"),
        (["--tp", "8:10:1", "--scatter", "missing.csv"], "--scatter"),
    ],
)
def test_bad_input_exits_2_with_one_clear_message(tmp_path, capsys, args, needle):
    assert main(["operability", "-o", str(tmp_path / "o"), "-q", *args]) == 2
    err = capsys.readouterr().err
    assert needle in err and "Traceback" not in err and err.startswith("seafast: error:")


def test_the_scatter_input_is_never_overwritten_by_the_output(tmp_path, capsys):
    f = tmp_path / "scatter.csv"
    f.write_text("significant_height_m,peak_period_s,occurrence\n1,8,1\n", encoding="utf-8")
    assert main(["operability", "--tp", "8:9:1", "-o", str(tmp_path), "--scatter", str(f), "-q"]) == 2
    assert "--scatter" in capsys.readouterr().err and f.read_text().endswith("1,8,1\n")


def test_bad_scatter_files_are_refused_naming_the_line(tmp_path, capsys):
    for text, needle in (
        ("hs,tp,occ\n1,8,1\n", "expected columns"),
        ("significant_height_m,peak_period_s,occurrence\n1,8,-1\n", "line 2"),
        ("significant_height_m,peak_period_s,occurrence\n1,8,0\n", "no sea state"),
    ):
        f = tmp_path / "bad.csv"
        f.write_text(text, encoding="utf-8")
        assert main(["operability", "--tp", "8:9:1", "-o", str(tmp_path / "o"), "--scatter", str(f), "-q"]) == 2
        err = capsys.readouterr().err
        assert needle in err and "Traceback" not in err


def test_report_of_an_operability_directory(run, tmp_path):
    out, _ = run
    page_path = tmp_path / "report.html"
    assert main(["report", str(out), "-o", str(page_path), "--no-figures"]) == 0
    page = page_path.read_text()
    for needle in (
        'id="operability"',
        'data-figure="fig-operability"',
        "Saddles lift off below the linear allowable Hs",
        "70.0% (nonlinear)",
    ):
        assert needle in page, needle
    rows = _rows(out / "operability.csv")
    assert f"{float(rows[0]['hs_allowable_nonlinear_m']):.2f}" in page
    assert np.isfinite(float(rows[0]["hs_allowable_nonlinear_m"]))
