"""Operability per heading (docs/operability.md section 4): the loop over headings with an injected
per-heading analysis, the governing heading, a failing heading recorded, the --headings parser, and
`--headings 180` equal to the head-seas command in every number."""

from __future__ import annotations

import csv
import math

import numpy as np
import pytest
import xarray as xr

import seafast
from seafast.analyses.operability.allowable import OperabilityPoint, OperabilityResult, OperabilitySettings
from seafast.analyses.operability.headings import (
    HEADING_FAILED,
    AllowableModel,
    allowable_per_heading,
    case_at_heading,
    check_headings,
)
from seafast.cli import main
from seafast.cli.operability import parse_headings, parse_peak_periods
from seafast.config import CaseError
from seafast.config.schema import SeaStateConfig, max_significant_height_m

HEADINGS = [90.0, 120.0, 150.0, 180.0]
TPS = [6.0, 9.0, 12.0]


def fake_hs(heading_deg: float, tp: float) -> tuple[float, float]:
    """(linear, nonlinear) allowable Hs [m] of the injected analysis: smallest in beam seas near Tp 9 s (linear),
    smallest in head seas at Tp 12 s (nonlinear), so the two models are governed by different headings."""
    beam = abs(math.sin(math.radians(heading_deg)))
    linear = 2.0 - 1.0 * beam + 0.1 * abs(tp - 9.0)
    nonlinear = 1.0 + 0.5 * beam + 0.2 * abs(tp - 12.0)
    return linear, nonlinear


def tag(case, heading):
    """The injected case at a heading: the heading carried in the name (the schema need not know it)."""
    return case.model_copy(update={"name": f"at {heading!r}"})


def heading_of(case) -> float:
    return float(case.name.removeprefix("at "))


def fake_result(case, tps, settings, *, fail_at=(), nan_at=()):
    heading = heading_of(case)
    if heading in fail_at:
        raise np.linalg.LinAlgError(f"singular matrix at {heading:g} deg")
    points = []
    for tp in tps:
        lin, nl = fake_hs(heading, tp)
        bad = (heading, tp) in nan_at
        points.append(
            OperabilityPoint(
                peak_period_s=float(tp),
                hs_allowable_linear_m=lin,
                hs_allowable_nonlinear_m=math.nan if bad else nl,
                hs_uplift_onset_m=2.5,
                governing_linear="saddle_force" if tp < 10 else "bending_stress",
                governing_nonlinear="not_converged" if bad else "saddle_force",
                hs_max_steepness_m=max_significant_height_m(tp),
                hs_force_linear_m=lin,
                hs_stress_linear_m=math.inf,
                hs_force_nonlinear_m=nl,
                hs_stress_nonlinear_m=math.nan,
                converged=not bad,
                evaluations=3,
            )
        )
    return OperabilityResult(case, tuple(points), settings)


@pytest.fixture(scope="module")
def case():
    return seafast.load_case(None)


def test_each_heading_is_analysed_once_in_order_with_its_own_case(case):
    seen = []

    def analyse(c, tps, settings):
        seen.append((heading_of(c), list(tps), settings))
        return fake_result(c, tps, settings)

    settings = OperabilitySettings(hs_tolerance_m=2e-3)
    done = []
    r = allowable_per_heading(case, HEADINGS, TPS, settings, analyse=analyse, at_heading=tag, progress=lambda i, n: done.append((i, n)))
    assert [s[0] for s in seen] == HEADINGS and all(s[1] == TPS and s[2] is settings for s in seen)
    assert done == [(i + 1, 4) for i in range(4)]
    assert r.headings_deg == tuple(HEADINGS) and r.peak_periods_s == tuple(TPS) and r.case is case and r.converged
    for h in r.headings:
        assert [p.peak_period_s for p in h.result.points] == TPS
        assert [p.hs_allowable_nonlinear_m for p in h.result.points] == [fake_hs(h.heading_deg, t)[1] for t in TPS]


def test_the_governing_heading_is_the_smallest_allowable_hs_per_peak_period_and_overall(case):
    r = allowable_per_heading(case, HEADINGS, TPS, analyse=fake_result, at_heading=tag)
    for model, column in ((AllowableModel.LINEAR, 0), (AllowableModel.NONLINEAR, 1)):
        grid = np.array([[fake_hs(h, t)[column] for t in TPS] for h in HEADINGS])  # independent: brute force
        per_tp = r.governing_per_peak_period(model)
        for j, g in enumerate(per_tp):
            assert g.peak_period_s == TPS[j]
            assert g.heading_deg == HEADINGS[int(np.argmin(grid[:, j]))]
            assert g.hs_allowable_m == pytest.approx(grid[:, j].min(), rel=1e-12)
        overall = r.governing_heading(model)
        i, j = np.unravel_index(np.argmin(grid), grid.shape)
        assert (overall.heading_deg, overall.peak_period_s) == (HEADINGS[i], TPS[j])
    # the two models are governed elsewhere: beam seas at Tp 9 s (linear), head seas at Tp 12 s (nonlinear)
    lin, nl = r.governing_heading(AllowableModel.LINEAR), r.governing_heading(AllowableModel.NONLINEAR)
    assert (lin.heading_deg, lin.peak_period_s, lin.hs_allowable_m, lin.governing) == (90.0, 9.0, 1.0, "saddle_force")
    assert (nl.heading_deg, nl.peak_period_s, nl.governing) == (180.0, 12.0, "saddle_force")
    assert nl.hs_allowable_m == pytest.approx(1.0, abs=1e-15)
    assert r.governing_per_peak_period(AllowableModel.LINEAR)[2].governing == "bending_stress"


def test_a_failing_heading_is_recorded_and_the_others_still_run(case, caplog):
    def analyse(c, tps, settings):
        return fake_result(c, tps, settings, fail_at=(150.0,))

    r = allowable_per_heading(case, HEADINGS, TPS, analyse=analyse, at_heading=tag)
    assert [h.failed for h in r.headings] == [False, False, True, False] and not r.converged
    failed = r.headings[2]
    assert failed.error == "LinAlgError: singular matrix at 150 deg" and "150 deg failed" in caplog.text
    for p in failed.result.points:
        assert math.isnan(p.hs_allowable_linear_m) and math.isnan(p.hs_allowable_nonlinear_m) and not p.converged
        assert p.governing_linear == p.governing_nonlinear == HEADING_FAILED
        assert p.hs_max_steepness_m == max_significant_height_m(p.peak_period_s)
    # the other headings are whole, and the failed one takes no part in the governing heading
    assert [p.hs_allowable_nonlinear_m for p in r.headings[3].result.points] == [fake_hs(180.0, t)[1] for t in TPS]
    assert all(g.heading_deg != 150.0 for g in r.governing_per_peak_period())


def test_a_non_converged_point_is_kept_and_left_out_of_the_governing_heading(case):
    def analyse(c, tps, settings):
        return fake_result(c, tps, settings, nan_at=((180.0, 12.0),))

    r = allowable_per_heading(case, HEADINGS, TPS, analyse=analyse, at_heading=tag)
    assert not r.converged and r.headings[3].result.points[2].governing_nonlinear == "not_converged"
    g = r.governing_per_peak_period()[2]  # at Tp 12 s head seas has no answer: 150 deg is the next smallest
    assert (g.heading_deg, g.hs_allowable_m) == (150.0, fake_hs(150.0, 12.0)[1])


def test_an_invalid_case_at_a_heading_is_raised_not_recorded(case):
    def analyse(c, tps, settings):
        raise CaseError(f"wave.heading_deg = {heading_of(c):g}: not supported")

    with pytest.raises(CaseError, match="not supported"):
        allowable_per_heading(case, [180.0], TPS, analyse=analyse, at_heading=tag)


@pytest.mark.parametrize(
    "headings,needle",
    [([], "empty"), ([-1.0], "heading -1 deg"), ([400.0], "0 <= heading <= 360"), ([math.nan], "heading nan"), ([0.0, 360.0], "twice")],
)
def test_bad_headings_are_refused_naming_the_value(case, headings, needle):
    with pytest.raises(ValueError, match=needle):
        allowable_per_heading(case, headings, TPS, analyse=fake_result, at_heading=tag)
    assert check_headings([0, 90, 359.5]) == [0.0, 90.0, 359.5]


def test_the_case_at_a_heading_changes_only_its_heading(case):
    assert case_at_heading(case, 180.0) == case  # head seas: the case itself, to the bit
    key = "sea_state" if "heading_deg" in SeaStateConfig.model_fields else "wave"  # the key the sea-state analysis reads
    for heading, expected in ((150.0, 150.0), (360.0, 0.0), (90.0, 90.0)):
        c = case_at_heading(case, heading)
        assert getattr(c, key).heading_deg == expected
        assert c.model_copy(update={key: getattr(case, key)}) == case


def test_headings_parser():
    assert parse_headings("90:180:15") == [90.0, 105.0, 120.0, 135.0, 150.0, 165.0, 180.0]
    assert parse_headings("150") == [150.0] and parse_headings("0:330:30")[-1] == 330.0
    assert parse_headings("300:360:30") == [300.0, 330.0, 360.0]
    assert parse_peak_periods("10") == [10.0] and parse_peak_periods("5:6:0.5") == [5.0, 5.5, 6.0]  # as --tp


@pytest.mark.parametrize(
    "value,needle",
    [
        ("90:180", "--headings '90:180'"),
        ("180:90:15", "0 <= START <= STOP <= 360"),
        ("90:180:0", "STEP > 0"),
        ("-10", "--headings '-10'"),
        ("361", "--headings '361'"),
        ("a", "--headings 'a'"),
        ("0:360:30", "0 and 360 deg are the same heading"),
        ("0:360:0.5", "at most 361"),
    ],
)
def test_bad_headings_exit_2_with_one_clear_message(tmp_path, capsys, value, needle):
    assert main(["operability", "--tp", "10", "--headings", value, "-o", str(tmp_path / "o"), "-q"]) == 2
    err = capsys.readouterr().err
    assert needle in err and "Traceback" not in err and err.startswith("seafast: error:")
    assert not (tmp_path / "o").exists()


def test_headings_with_a_scatter_diagram_are_refused(tmp_path, capsys):
    f = tmp_path / "s.csv"
    f.write_text("significant_height_m,peak_period_s,occurrence\n1,8,1\n", encoding="utf-8")
    assert main(["operability", "--tp", "8", "--headings", "180", "--scatter", str(f), "-o", str(tmp_path / "o"), "-q"]) == 2
    assert "--scatter" in capsys.readouterr().err


def _csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def test_headings_180_equals_the_head_seas_command_in_every_number(tmp_path):
    args = ["operability", "--tp", "9.5:10:0.5", "--no-plots", "-q"]
    assert main([*args, "-o", str(tmp_path / "plain")]) == 0
    assert main([*args, "--headings", "180", "-o", str(tmp_path / "h180")]) == 0
    plain, h180 = _csv(tmp_path / "plain" / "operability.csv"), _csv(tmp_path / "h180" / "operability.csv")
    assert list(h180[0]) == ["heading_deg", *plain[0]] and len(plain) == len(h180) == 2
    for a, b in zip(plain, h180, strict=True):
        assert b.pop("heading_deg") == "180.0" and a == b  # the same text: every number to the bit
    with xr.open_dataset(tmp_path / "plain" / "operability.nc") as p, xr.open_dataset(tmp_path / "h180" / "operability.nc") as h:
        for name in p.data_vars:
            xr.testing.assert_identical(p[name], h[name].sel(heading_deg=180.0, drop=True))


def test_a_heading_off_head_seas_runs_through_the_command(tmp_path, capsys):
    out = tmp_path / "o"
    code = main(["operability", "--headings", "150:180:30", "--tp", "10", "-o", str(out), "--no-plots", "-q"])
    err = capsys.readouterr().err
    assert code == 0, err
    rows = _csv(out / "operability.csv")
    assert [r["heading_deg"] for r in rows] == ["150.0", "180.0"]
    cap = max_significant_height_m(10.0)
    for r in rows:
        for column in ("hs_allowable_linear_m", "hs_allowable_nonlinear_m"):
            assert 0.0 < float(r[column]) <= cap
        assert r["governing_nonlinear"] in ("saddle_force", "bending_stress", "steepness")
    assert rows[0]["hs_allowable_linear_m"] != rows[1]["hs_allowable_linear_m"]  # the heading changes the answer
    assert main(["operability", "--tp", "10", "-o", str(tmp_path / "head"), "--no-plots", "-q"]) == 0
    head = _csv(tmp_path / "head" / "operability.csv")[0]
    assert {k: v for k, v in rows[1].items() if k != "heading_deg"} == head  # head seas as without --headings
