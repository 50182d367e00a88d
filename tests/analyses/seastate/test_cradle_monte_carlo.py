"""The Monte Carlo run off head seas: every realisation's record holds the cargo on its cradles' extremes, their most
probable extremes are estimated as the vertical quantities', the store resumes, an older store is refused clearly,
and at head seas nothing changes."""

from __future__ import annotations

import json

import numpy as np
import pytest

import seafast
from seafast.analyses.seastate import monte_carlo
from seafast.analyses.seastate.cradle_realisation import CRADLE_QUANTITIES, evaluate_cradle_realisation
from seafast.analyses.seastate.extremes import most_probable_maximum
from seafast.analyses.seastate.monte_carlo import STORE_DIRECTORY, build_cradle_plan, run_monte_carlo
from seafast.output.seastate_cradle import monte_carlo_cradle_columns
from seafast.parallel.errors import ForeignStoreError
from seafast.parallel.store import DICT_RECORDS

BEAM = {
    "model.element_length_m": 4.0,
    "sea_state.peak_period_s": 10.0,
    "sea_state.heading_deg": 90.0,
    "sea_state.significant_height_m": 9.0,
    "sea_state.duration_s": 60.0,
    "sea_state.realisations": 3,
    "seafastening.side_stopper.gap_m": 2e-3,
    "seafastening.side_stopper.stiffness_N_per_m": 2e9,
    "seafastening.lashing.pretension_N": 0.0,
}


@pytest.fixture(scope="module")
def beam_run(tmp_path_factory):
    case = seafast.load_case(None, BEAM)
    out = tmp_path_factory.mktemp("mc")
    return case, out, run_monte_carlo(case, out, workers=1, progress=False)


def test_off_head_seas_each_record_holds_the_cradle_extremes_of_its_realisation(beam_run):
    """The stored cradle part of realisation i is :func:`evaluate_cradle_realisation` of the plan and i (a pure
    function: the same numbers again), and the statistics' MPMs are the estimator's on those extremes (the lashing
    minimum's the negated MPM of its negative)."""
    case, out, result = beam_run
    lines = (out / STORE_DIRECTORY / DICT_RECORDS.records).read_text(encoding="utf-8").splitlines()
    records = sorted((json.loads(line)["record"] for line in lines), key=lambda r: r["index"])
    assert [r["index"] for r in records] == [0, 1, 2]
    plan = build_cradle_plan(case)
    assert plan is not None and result.cradle is not None
    linear, nonlinear = result.cradle
    for r in records:
        again = evaluate_cradle_realisation(plan, r["index"])
        for model in ("linear", "nonlinear"):
            assert r["cradle"][model] == pytest.approx(again[model], rel=1e-12, abs=1e-15)
    for stats in (linear, nonlinear):
        for q in CRADLE_QUANTITIES:
            np.testing.assert_array_equal(stats.extremes[q], [r["cradle"][stats.model][q] for r in records])
        x = stats.extremes["F_pad_N"]
        assert stats.mpm["F_pad_N"] == most_probable_maximum(x, seed=case.sea_state.seed + 100).value
        least = most_probable_maximum(-stats.extremes["lashing_tension_min_N"], seed=case.sea_state.seed + 103)
        assert stats.mpm["lashing_tension_min_N"] == -least.value
        lo, hi = stats.mpm_interval["F_pad_N"]
        assert lo <= hi
    # the contact at work: stoppers close and limit the slip, slack wires carry nothing
    assert nonlinear.mpm["F_stopper_N"] < linear.mpm["F_stopper_N"] and nonlinear.mpm["transverse_slip_m"] < linear.mpm["transverse_slip_m"]
    assert linear.mpm["lashing_tension_min_N"] < 0.0 <= nonlinear.mpm["lashing_tension_min_N"]
    assert nonlinear.converged and linear.converged
    columns = monte_carlo_cradle_columns(nonlinear)
    assert list(columns) == list(CRADLE_QUANTITIES) and columns["F_pad_N"] == nonlinear.mpm["F_pad_N"]
    assert monte_carlo_cradle_columns(None) == dict.fromkeys(CRADLE_QUANTITIES)


def test_the_dataset_has_the_cradle_variables_with_units(beam_run):
    _, _, result = beam_run
    ds = result.to_dataset()
    for q in CRADLE_QUANTITIES:
        assert ds[f"mc_cradle_{q}"].dims == ("model", "realisation") and ds[f"mc_cradle_{q}"].attrs["units"] in ("N", "m")
        assert ds[f"mc_cradle_mpm_{q}"].attrs["long_name"]
    assert ds["mc_cradle_lashing_slack_fraction"].sel(model="nonlinear").max() > 0.0


def test_the_run_resumes_from_its_store_and_refuses_one_without_cradle_extremes(beam_run, tmp_path, monkeypatch):
    """Run again on the same directory: every realisation reused, the same statistics. A store written without the
    cradle extremes (as before they were computed) is another run: refused, naming the directory."""
    case, out, result = beam_run
    again = run_monte_carlo(case, out, workers=1, progress=False)
    assert again.reused == 3 and again.cradle is not None and result.cradle is not None
    assert again.cradle[1].mpm == result.cradle[1].mpm
    old = tmp_path / "old"
    with monkeypatch.context() as m:
        m.setattr(monte_carlo, "build_cradle_plan", lambda case: None)
        run_monte_carlo(
            case.model_copy(update={"sea_state": case.sea_state.model_copy(update={"realisations": 3})}), old, workers=1, progress=False
        )
    with pytest.raises(ForeignStoreError, match="holds another run"):
        run_monte_carlo(case, old, workers=1, progress=False)


def test_head_seas_records_and_dataset_are_unchanged(tmp_path):
    """At head seas no cradle plan, no cradle part in the records or the dataset."""
    case = seafast.load_case(None, {"model.element_length_m": 4.0, "sea_state.duration_s": 60.0, "sea_state.realisations": 3})
    assert build_cradle_plan(case) is None
    result = run_monte_carlo(case, tmp_path, workers=1, progress=False)
    assert result.cradle is None and not any(k.startswith("mc_cradle") for k in result.to_dataset().data_vars)
    lines = (tmp_path / STORE_DIRECTORY / DICT_RECORDS.records).read_text(encoding="utf-8").splitlines()
    assert lines and all("cradle" not in json.loads(line)["record"] for line in lines)


def test_seastate_command_puts_each_models_cradle_extremes_in_its_monte_carlo_row(beam_run):
    """``seafast seastate`` off head seas, resuming the run above (the same store): seastate.csv's linear and nonlinear
    Monte Carlo rows carry the five cradle columns, each the statistics' most probable extreme of that model."""
    import csv

    from seafast.cli import main

    _case, out, result = beam_run
    args = ["seastate", "-o", str(out), "--workers", "1", "--no-plots", "-q"]
    for key, value in BEAM.items():
        args += ["--set", f"{key}={value}"]
    assert main(args) in (0, 3)  # 3: a design wave flagged not converged (its row), the Monte Carlo rows regardless
    with open(out / "seastate.csv", newline="", encoding="utf-8") as fh:
        rows = {(r["model"], r["method"]): r for r in csv.DictReader(fh)}
    assert result.cradle is not None
    for model, stats in zip(("linear", "nonlinear"), result.cradle, strict=True):
        row = rows[(model, "monte_carlo")]
        for column in CRADLE_QUANTITIES:
            assert float(row[column]) == pytest.approx(stats.mpm[column], rel=1e-9, abs=1e-12)
    assert float(rows[("nonlinear", "monte_carlo")]["F_stopper_N"]) > 0.0  # the stoppers close in this sea
