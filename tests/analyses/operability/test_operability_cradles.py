"""Operability judged on the cradles off head seas (docs/operability.md#operability-on-the-cradles): the cradle
limits' keys, the linear allowable Hs against `seafast seastate` at that Hs, the nonlinear one against the cradle
design waves there, which limit governs where, and head seas exactly as before (main's operability.csv)."""

from __future__ import annotations

import csv
import math
from pathlib import Path

import numpy as np
import pytest

from round_off import assert_same_table
from seafast.analyses.operability.allowable import CRADLE_OPERABILITY_COLUMNS, OperabilitySettings, allowable_sea_states
from seafast.analyses.operability.limits import GOVERNING, cradle_limits, linear_limit_hs
from seafast.cli import main
from seafast.config import CaseError, load_case
from seafast.output.operability import OPERABILITY_COLUMNS, operability_csv_text

DATA = Path(__file__).parent / "data"
PAD_LIMIT_N = 5.0e6
"""Beam seas, base case: the middle saddle's pads carry 4.46 MN in still water and about 0.32 MN per metre of Hs
(Tp 10 s), so 5 MN is reached at Hs 1.7 m, before the saddle force's 7 MN (2.9 m)."""
BEAM = {"sea_state.heading_deg": 90.0, "limits.max_pad_force_N": PAD_LIMIT_N}


def _rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def _set(overrides):
    return [a for k, v in overrides.items() for a in ("--set", f"{k}={v!r}" if isinstance(v, float) else f"{k}={v}")]


@pytest.fixture(scope="module")
def beam():
    case = load_case(None, BEAM)
    return case, allowable_sea_states(case, [10.0]).points[0]


@pytest.fixture(scope="module")
def seastate_at_beam_allowable(beam, tmp_path_factory):
    """`seafast seastate` (no Monte Carlo) at the beam-sea allowable Hs, linear and nonlinear: {method: row}."""
    _, p = beam
    out = {}
    for method, hs in (("spectral", p.hs_allowable_linear_m), ("design_wave", p.hs_allowable_nonlinear_m)):
        d = tmp_path_factory.mktemp(method)
        args = ["seastate", "-o", str(d), "--no-monte-carlo", "--no-plots", "-q", *_set(BEAM)]
        args += ["--set", f"sea_state.significant_height_m={hs!r}", "--set", "sea_state.peak_period_s=10"]
        assert main(args) == 0
        out[method] = next(r for r in _rows(d / "seastate.csv") if r["method"] == method)
    return out


def test_the_cradle_limits_are_optional_case_keys_named_when_bad():
    case = load_case(None)
    assert cradle_limits(case) == {}
    assert "max_pad_force_N" not in case.model_dump(mode="json")["limits"]  # unset: the case's dump as before the keys
    set_ = load_case(None, {"limits.max_pad_force_N": 5e6, "limits.max_transverse_slip_m": 0.01})
    assert cradle_limits(set_) == {"pad_force": 5e6, "transverse_slip": 0.01}
    assert set_.model_dump(mode="json")["limits"]["max_pad_force_N"] == 5e6
    for key, bad in (("max_pad_force_N", -1.0), ("max_lashing_tension_N", 0.0), ("max_transverse_slip_m", "abc")):
        with pytest.raises(CaseError, match=f"limits.{key} = "):
            load_case(None, {f"limits.{key}": bad})
    assert {"pad_force", "lashing_tension", "transverse_slip"} <= set(GOVERNING)


def test_linear_limit_hs_closed_form():
    # max(static + Hs per_hs) = limit: location 1 first at (10 - 4) / 3 = 2
    assert linear_limit_hs(np.array([1.0, 4.0, 2.0]), np.array([2.0, 3.0, 0.0]), 10.0) == pytest.approx(2.0, rel=1e-15)
    assert linear_limit_hs(np.array([1.0, 11.0]), np.array([2.0, 3.0]), 10.0) == 0.0  # still water beyond it
    assert linear_limit_hs(np.array([1.0]), np.array([0.0]), 10.0) == math.inf  # never grows
    assert linear_limit_hs(np.array([]), np.array([]), 10.0) == math.inf  # no location (no lashing wires)


def test_head_seas_operability_csv_is_main_s(tmp_path):
    # head seas (the default) and, over headings, beam seas without a cradle limit: the files main writes, to the
    # solvers' round-off across machines (tests/round_off.py; on the machine that wrote them, byte for byte)
    assert main(["operability", "--tp", "6:14:2", "-o", str(tmp_path / "h"), "--no-plots", "-q"]) == 0
    got = (tmp_path / "h" / "operability.csv").read_text()
    assert_same_table(got, (DATA / "operability_head_seas_tp6-14.csv").read_text())
    assert main(["operability", "--headings", "90:180:90", "--tp", "8:12:2", "-o", str(tmp_path / "b"), "--no-plots", "-q"]) == 0
    got = (tmp_path / "b" / "operability.csv").read_text()
    assert_same_table(got, (DATA / "operability_headings_90_180_tp8-12.csv").read_text())


def test_head_seas_with_a_cradle_limit_set_are_judged_as_before():
    # no cradle is solved in head seas: the same numbers, the cradle columns empty
    tps = [8.0, 10.0]
    plain = allowable_sea_states(load_case(None), tps)
    limited = allowable_sea_states(load_case(None, {"limits.max_pad_force_N": 1.0e6}), tps)  # below the still water
    for a, b in zip(plain.points, limited.points, strict=True):
        assert a.row() == b.row()
        assert all(math.isnan(v) for v in b.cradle_row().values())
    text = operability_csv_text(limited)
    assert text.splitlines()[0] == ",".join(OPERABILITY_COLUMNS + CRADLE_OPERABILITY_COLUMNS)
    assert text.splitlines()[1].endswith(",,,,,,")


def test_in_beam_seas_the_pad_force_governs(beam):
    _, p = beam
    assert p.governing_linear == p.governing_nonlinear == "pad_force"
    assert 1.0 < p.hs_allowable_linear_m == p.hs_pad_force_linear_m < 0.7 * p.hs_force_linear_m  # saddle force 2.9 m
    assert p.hs_allowable_nonlinear_m == p.hs_pad_force_nonlinear_m
    assert math.isnan(p.hs_lashing_tension_linear_m) and math.isnan(p.hs_transverse_slip_linear_m)  # not set: not checked
    assert p.converged


def test_the_linear_allowable_gives_the_pad_limit_in_seafast_seastate(seastate_at_beam_allowable):
    # command to command: the linear spectral row at the linear allowable Hs has the pad limit as its MPM
    row = seastate_at_beam_allowable["spectral"]
    assert float(row["F_pad_N"]) == pytest.approx(PAD_LIMIT_N, rel=1e-6)
    assert float(row["F_N"]) < 7.0e6 * 0.99  # the saddle force within its limit there


def test_the_nonlinear_allowable_gives_the_pad_limit_within_the_bracketing_tolerance(beam, seastate_at_beam_allowable):
    # the design-wave row's pad force at the nonlinear allowable Hs: the limit within what an Hs error of the
    # search's tolerance (1e-3 m) moves it, the pad force's slope being its linear MPM per metre of Hs
    _, p = beam
    row_lin = seastate_at_beam_allowable["spectral"]  # at the linear allowable
    row = seastate_at_beam_allowable["design_wave"]
    slope_N_per_m = 0.4e6  # above the 0.32 MN/m of the linear MPM
    assert abs(float(row["F_pad_N"]) - PAD_LIMIT_N) <= slope_N_per_m * OperabilitySettings().hs_tolerance_m
    assert abs(p.hs_allowable_nonlinear_m - p.hs_allowable_linear_m) < 0.01  # no pad lifts in these waves
    assert float(row_lin["F_pad_N"]) == pytest.approx(PAD_LIMIT_N, rel=1e-6)


def test_off_head_seas_the_vertical_plane_can_govern_with_the_cradles_checked():
    # 150 deg: the saddle force is reached before the pads' 5 MN; the cradles then take no part in the answer
    tps = [10.0]
    plain = allowable_sea_states(load_case(None, {"sea_state.heading_deg": 150.0}), tps).points[0]
    p = allowable_sea_states(load_case(None, {"sea_state.heading_deg": 150.0, "limits.max_pad_force_N": PAD_LIMIT_N}), tps).points[0]
    assert p.governing_linear == p.governing_nonlinear == "saddle_force"
    assert p.hs_allowable_linear_m < p.hs_pad_force_linear_m < 1.2 * p.hs_allowable_linear_m
    assert p.row() == plain.row()
    assert math.isnan(p.hs_pad_force_nonlinear_m)  # within its limit where the saddle force is reached: not searched


def test_lashing_and_slip_limits_linear_allowable_against_seastate(tmp_path):
    # every cradle limit's closed form: at its own linear Hs, seafast seastate's linear row reaches it (the
    # lashing's dynamic part is small: judged relative to it)
    limits = {"limits.max_lashing_tension_N": 74_282.0, "limits.max_transverse_slip_m": 1.0e-3}
    overrides = {"sea_state.heading_deg": 90.0, **limits}
    p = allowable_sea_states(load_case(None, overrides), [10.0]).points[0]
    still_N = 74_274.31  # the largest still-water lashing tension
    for column, hs, limit, scale in (
        ("lashing_tension_max_N", p.hs_lashing_tension_linear_m, 74_282.0, 74_282.0 - still_N),
        ("transverse_slip_m", p.hs_transverse_slip_linear_m, 1.0e-3, 1.0e-3),
    ):
        assert 0.5 < hs < 5.0, column
        d = tmp_path / column
        args = ["seastate", "-o", str(d), "--no-monte-carlo", "--no-plots", "-q", *_set(overrides)]
        args += ["--set", f"sea_state.significant_height_m={hs!r}", "--set", "sea_state.peak_period_s=10"]
        assert main(args) in (0, 3)  # 3: a cradle design wave's balance (another column's) flagged; the linear row stands
        row = next(r for r in _rows(d / "seastate.csv") if r["method"] == "spectral")
        assert abs(float(row[column]) - limit) <= 1e-5 * scale, column
    assert p.governing_linear in ("lashing_tension", "transverse_slip")
    assert p.hs_allowable_linear_m == min(p.hs_lashing_tension_linear_m, p.hs_transverse_slip_linear_m)
