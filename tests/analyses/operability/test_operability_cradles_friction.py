"""Operability on the cradles with pad friction (docs/operability.md#operability-on-the-cradles): the cradle limits'
nonlinear allowable Hs on frictional pads read as ``seafast seastate``'s frictional design-wave row reads them, the
search led by the cheaper H = 16 waves answering with a reading at the case's H, a frictional wave that does not
converge flagged, and without the key, with mu = 0 or in head seas ``operability.csv`` byte for byte as before."""

from __future__ import annotations

import csv
import logging
import math
from pathlib import Path

import pytest

import seafast.analyses.operability.allowable as allowable_module
import seafast.analyses.operability.cradle as cradle_module
from frictional_stand_in import not_converging
from round_off import assert_same_table
from seafast.analyses.operability.allowable import OperabilitySettings, allowable_sea_states
from seafast.analyses.operability.cradle import (
    PROXY_HARMONICS,
    cradle_at_peak_period,
    cradle_design_wave_value,
    cradle_still_value,
    proxy_friction,
)
from seafast.analyses.operability.family import analysis_at, rescaled, sea_state_family
from seafast.analyses.seastate.cradle_design_wave import cradle_design_waves
from seafast.analyses.seastate.cradle_friction_wave import DesignWaveFriction, design_wave_friction
from seafast.cli import main
from seafast.config import load_case
from seafast.model.pad_friction import PadFriction
from seafast.solvers.cradle_friction import FrictionHBMOptions

DATA = Path(__file__).parent / "data"
PAD_LIMIT_N = 5.0e6
MU = 0.2
BEAM = {"sea_state.heading_deg": 90.0, "limits.max_pad_force_N": PAD_LIMIT_N}
ROUGH = {**BEAM, "seafastening.friction_coefficient": MU}
SLOPE_N_PER_M = 0.4e6
"""Above the pad force's growth per metre of Hs near the limit at Tp 10 s (0.32 MN/m linear, about 0.25 MN/m on
frictional pads): the reading's distance from the limit that an Hs error of the search's tolerance can make."""
TOLERANCE_M = OperabilitySettings().hs_tolerance_m


@pytest.fixture(scope="module")
def rough():
    """The base case in beam seas, pads limited to 5 MN, mu = 0.2, Tp 10 s: the point, and the cradles at that Tp."""
    case = load_case(None, ROUGH)
    family = sea_state_family(case, [10.0])
    point = allowable_sea_states(case, [10.0], family=family).points[0]
    ref = analysis_at(family, 10.0, 1.0)
    assert family.cradle is not None
    return case, point, ref, cradle_at_peak_period(family.cradle, ref)


@pytest.mark.slow
def test_the_frictional_allowable_reads_seastate_s_frictional_design_wave_row(rough):
    """At the reported Hs each limit's reading (pad force, lashing tension, lateral displacement at a saddle) is the
    column of seastate's frictional design-wave row on the same sea (1e-9), and the pad force reaches its limit there
    within what the search's tolerance in Hs moves it; the friction raises the allowable Hs (the pads carry less)."""
    case, p, ref, at = rough
    assert p.converged and p.governing_nonlinear == "pad_force"
    hs = p.hs_pad_force_nonlinear_m
    assert p.hs_allowable_nonlinear_m == hs
    friction = design_wave_friction(case)
    assert friction is not None and at.family.friction == friction and friction.options.harmonics == 32
    spectrum = rescaled(ref, hs).spectrum
    spectral = cradle_module.cradle_extremes_at(at, spectrum)
    row = cradle_design_waves(at.family.sea, at.vertical, at.transfer, spectral, friction=friction)
    assert row.converged and row.frictional is not None
    for name, column in (("pad_force", "F_pad_N"), ("lashing_tension", "lashing_tension_max_N"), ("transverse_slip", "transverse_slip_m")):
        value, converged = cradle_design_wave_value(at, name, lambda h: rescaled(ref, h).spectrum, 0.5, friction)(hs)
        assert converged
        assert value == pytest.approx(row.totals[column], rel=1e-9, abs=0.0), name
    assert abs(row.totals["F_pad_N"] - PAD_LIMIT_N) <= SLOPE_N_PER_M * TOLERANCE_M
    # frictionless pads: no pad lifts, so the nonlinear allowable is the linear one, 1.69 m; mu = 0.2: 2.82 m
    assert p.hs_pad_force_linear_m == pytest.approx(1.6939, abs=1e-3)
    assert 2.7 < hs < 2.95


@pytest.mark.slow
def test_the_proxy_led_search_lands_where_the_case_s_h_alone_does(rough):
    """The search led by H = 16 answers within the Hs tolerance of Brent's method on the case's H = 32 alone, with a
    reading of the H = 32 waves (never the proxy's) and fewer H = 32 evaluations."""
    case, p, ref, at = rough
    friction = design_wave_friction(case)
    calls: list[int] = []
    value = cradle_design_wave_value(at, "pad_force", lambda h: rescaled(ref, h).spectrum, 0.5, friction)

    def counted(hs: float) -> tuple[float, bool]:
        calls.append(1)
        return value(hs)

    root, ok, _ = allowable_module._nonlinear_limit_hs(
        counted, PAD_LIMIT_N, p.hs_pad_force_linear_m, p.hs_max_steepness_m, OperabilitySettings()
    )
    assert ok and abs(root - p.hs_pad_force_nonlinear_m) <= 2 * TOLERANCE_M
    assert len(calls) >= 5  # the plain search: bracketing and Brent on the H = 32 waves


@pytest.mark.slow
def test_seafast_seastate_at_the_reported_hs_reads_the_pad_limit_in_its_frictional_row(rough, tmp_path):
    """Command to command: `seafast seastate` with the same keys at the reported Hs and Tp has the pad limit in its
    frictional design-wave row, within what the search's tolerance moves it (and the operability family's interpolated
    transfer functions, 1e-6 of the direct ones, move it less); the row converged and frictional."""
    _, p, _, _ = rough
    args = [a for k, v in ROUGH.items() for a in ("--set", f"{k}={v}")]
    args += ["--set", f"sea_state.significant_height_m={p.hs_pad_force_nonlinear_m!r}", "--set", "sea_state.peak_period_s=10"]
    assert main(["seastate", "-o", str(tmp_path), "--no-monte-carlo", "--no-plots", "-q", *args]) == 0
    with open(tmp_path / "seastate.csv", newline="") as f:
        row = next(r for r in csv.DictReader(f) if r["method"] == "design_wave")
    assert row["converged"] == "true" and float(row["pad_friction_utilisation"]) > 0.0
    assert abs(float(row["F_pad_N"]) - PAD_LIMIT_N) <= SLOPE_N_PER_M * TOLERANCE_M + 1e-6 * PAD_LIMIT_N


def test_the_proxy_is_the_same_friction_at_h_16():
    """H = 32 (the default) is led by H = 16, N = 128, same mu; H = 16 or below, or no friction, has no proxy."""
    f32 = DesignWaveFriction(PadFriction(MU), FrictionHBMOptions(harmonics=32, time_samples=256))
    assert proxy_friction(f32) == DesignWaveFriction(PadFriction(MU), FrictionHBMOptions(harmonics=PROXY_HARMONICS, time_samples=128))
    assert proxy_friction(DesignWaveFriction(PadFriction(MU), FrictionHBMOptions(harmonics=16, time_samples=128))) is None
    assert proxy_friction(None) is None


def _led(value, proxy, limit=5.0, start=1.0, cap=10.0):
    return allowable_module._led_limit_hs(value, allowable_module._Proxy(proxy, 3.0), limit, start, cap, OperabilitySettings())


def test_the_led_search_answers_with_the_value_s_root_whatever_the_proxy():
    """On a smooth stand-in (value = 3 + 0.5 Hs + 0.02 Hs^2, limit 5: root 3.6148 m) the answer is within the tolerance
    of value's root with the proxy 1e-4 off (one reading of value), 5 % off (the secant on value corrects it) and
    not converging (value's own search); value reaching the limit only beyond the cap gives inf from one reading at
    the cap; a reading of value that does not converge gives NaN, not converged."""
    exact = (-0.5 + math.sqrt(0.25 + 4 * 0.02 * 2.0)) / (2 * 0.02)
    reads: list[float] = []

    def value(hs: float) -> tuple[float, bool]:
        reads.append(hs)
        return 3.0 + 0.5 * hs + 0.02 * hs**2, True

    for factor, converged in ((1.0 + 1e-4, True), (1.05, True), (1.0, False)):
        reads.clear()
        root, ok, _ = _led(value, lambda hs, f=factor, c=converged: ((3.0 + 0.5 * hs + 0.02 * hs**2) * f, c))
        assert ok and abs(root - exact) <= TOLERANCE_M, factor
        assert root in reads  # the answer is a reading of value
        if converged and factor < 1.01:
            assert len(reads) == 1
    reads.clear()
    root, ok, _ = _led(value, lambda hs: (3.0 + 0.5 * hs + 0.02 * hs**2, True), limit=50.0)
    assert ok and root == math.inf and reads == [10.0]  # one reading, at the cap
    root, ok, _ = _led(lambda hs: (3.0 + 0.5 * hs, False), lambda hs: (3.0 + 0.5 * hs, True))
    assert not ok and math.isnan(root)  # a reading that does not converge: flagged, never an answer


def test_a_frictional_wave_that_does_not_converge_flags_the_point(monkeypatch, caplog):
    """Every frictional solve stood in for by one that says it did not converge: the point is ``not_converged``, its
    nonlinear allowable Hs and the pad limit's NaN (never the stand-in's numbers), warned of; the linear ones stand."""
    monkeypatch.setattr(cradle_module, "solve_frictional_design_wave", not_converging(3e-3))
    with caplog.at_level(logging.WARNING):
        p = allowable_sea_states(load_case(None, ROUGH), [10.0]).points[0]
    assert not p.converged and p.governing_nonlinear == "not_converged"
    assert math.isnan(p.hs_allowable_nonlinear_m) and math.isnan(p.hs_pad_force_nonlinear_m)
    assert p.governing_linear == "pad_force" and p.hs_pad_force_linear_m == pytest.approx(1.6939, abs=1e-3)
    assert "did not converge" in caplog.text


def test_without_the_key_with_zero_friction_and_in_head_seas_operability_csv_is_unchanged(tmp_path, monkeypatch, caplog):
    """operability.csv the files written before friction was applied here (to the solvers' round-off across machines,
    tests/round_off.py; the runs in this process byte for byte each other): beam seas with the pad limit without the
    key and with mu = 0; head seas with mu = 0.2 and the pad limit; no frictional solve made, no warning."""
    calls: list[int] = []
    monkeypatch.setattr(cradle_module, "solve_frictional_design_wave", lambda *a: calls.append(1))

    def run(name: str, tp: str, sets: dict) -> str:
        args = [a for k, v in sets.items() for a in ("--set", f"{k}={v}")]
        assert main(["operability", "--tp", tp, "-o", str(tmp_path / name), "--no-plots", "-q", *args]) == 0
        return (tmp_path / name / "operability.csv").read_text()

    with caplog.at_level(logging.WARNING):
        plain = run("plain", "8:12:2", BEAM)
        assert_same_table(plain, (DATA / "operability_beam_pad_limit_tp8-12.csv").read_text())
        assert run("zero", "8:12:2", {**BEAM, "seafastening.friction_coefficient": 0.0}) == plain
        head = {"seafastening.friction_coefficient": MU, "limits.max_pad_force_N": PAD_LIMIT_N}
        assert_same_table(run("head", "8:12:2", head), (DATA / "operability_head_seas_friction_pad_limit_tp8-12.csv").read_text())
    assert not calls
    assert "friction" not in caplog.text


def test_the_still_value_is_the_column_in_still_water(rough):
    """What the design-wave value gives with no wave: the still water's largest pad force (4.46 MN in the middle
    saddle's pads)."""
    _, _, ref, at = rough
    still = cradle_still_value(at, "pad_force")
    assert still == pytest.approx(4.46e6, rel=5e-3)
    value, ok = cradle_design_wave_value(at, "pad_force", lambda h: rescaled(ref, h).spectrum, 0.5, at.family.friction)(1e-9)
    assert ok and value == pytest.approx(still, rel=1e-6)


def test_worker_processes_over_the_peak_periods_give_the_serial_answer(tmp_path, capsys):
    """``--workers 2`` (one Tp per task on local processes): operability.csv byte for byte the serial one (beam seas,
    pad limit, no key); ``--workers 0`` refused naming it."""
    args = ["operability", "--tp", "8:12:2", "--no-plots", "-q"] + [a for k, v in BEAM.items() for a in ("--set", f"{k}={v}")]
    assert main([*args, "-o", str(tmp_path / "w1")]) == 0
    assert main([*args, "-o", str(tmp_path / "w2"), "--workers", "2"]) == 0
    assert (tmp_path / "w2" / "operability.csv").read_bytes() == (tmp_path / "w1" / "operability.csv").read_bytes()
    assert main([*args, "-o", str(tmp_path / "w0"), "--workers", "0"]) == 2
    assert "--workers 0: allowed: 1" in capsys.readouterr().err
