"""Studies judged on their sea state (docs/operability.md): sea_state.* axes, the response key,
rows equal to `seafast seastate`, ranking by the nonlinear design-wave MPM."""

from __future__ import annotations

import csv

import pytest

import seafast
from seafast.analyses.seastate.design_wave import sea_state_design_waves
from seafast.analyses.seastate.spectral import spectral_analysis
from seafast.cli import main
from seafast.parallel.executor import ExecutionOptions
from seafast.studies.runner import run_study
from seafast.studies.spec import StudyError, build_grid, study_spec_from_mapping

HS_STUDY = {
    "name": "hs-saddles",
    "axes": [{"key": "sea_state.significant_height_m", "values": [1.0, 4.0]}, {"key": "seafastening.saddle_count", "values": [3, 4]}],
    "limits": {"max_saddle_force_N": 11.8e6, "max_bending_stress_Pa": 28.0e6},
}


def test_a_sea_state_axis_makes_the_study_a_sea_state_study_and_regular_wave_refuses_it():
    spec = study_spec_from_mapping(HS_STUDY)
    assert spec.response is None and spec.evaluates_sea_state
    plain = study_spec_from_mapping({"name": "p", "axes": [{"key": "seafastening.saddle_count", "values": [3]}]})
    assert not plain.evaluates_sea_state
    assert study_spec_from_mapping({**HS_STUDY, "axes": HS_STUDY["axes"][1:], "response": "sea_state"}).evaluates_sea_state
    with pytest.raises(StudyError, match="response = 'regular_wave' with sea-state key"):
        study_spec_from_mapping({**HS_STUDY, "response": "regular_wave"})
    # the response is part of the study's identity: a store of the other kind is not resumed
    one = build_grid(study_spec_from_mapping({**HS_STUDY, "axes": HS_STUDY["axes"][1:]}))
    other = build_grid(study_spec_from_mapping({**HS_STUDY, "axes": HS_STUDY["axes"][1:], "response": "sea_state"}))
    assert one.fingerprint() != other.fingerprint()


def test_a_sea_state_study_needs_hs_and_tp():
    spec = study_spec_from_mapping({**HS_STUDY, "axes": HS_STUDY["axes"][1:], "response": "sea_state"})
    with pytest.raises(StudyError, match=r"sea_state\.peak_period_s = null"):
        build_grid(spec, overrides={"sea_state.peak_period_s": None})


def test_sea_state_study_rows_equal_seafast_seastate_and_rank_by_the_nonlinear_mpm(tmp_path):
    grid = build_grid(study_spec_from_mapping(HS_STUDY))
    run = run_study(grid, tmp_path, execution=ExecutionOptions(workers=1, progress=False))
    ds = run.dataset
    assert list(ds["load_case"].values) == ["sea_state"] and run.failed == 0
    for hs in (1.0, 4.0):
        for n in (3, 4):
            an = spectral_analysis(seafast.load_case(None, {"sea_state.significant_height_m": hs, "seafastening.saddle_count": n}))
            dw = sea_state_design_waves(an)
            point = ds.sel({"sea_state.significant_height_m": hs, "seafastening.saddle_count": n, "load_case": "sea_state"})
            for q in ("F_N", "M_b_Nm", "sigma_b_Pa", "u_s_m", "u_d_m"):
                assert float(point[q].sel(model="linear")) == pytest.approx(an.extremes.totals[q], rel=1e-12, abs=1e-15), q
                assert float(point[q].sel(model="nonlinear")) == pytest.approx(dw.totals[q], rel=1e-12, abs=1e-15), q
            assert bool(point["contact_preserved"].sel(model="nonlinear")) == (not any(s.lifted_off for s in dw.solutions))
            assert not bool(point["warning_flag"].any()) and not an.model.warnings  # the exact Rayleigh fit at 1.1e9 N/m
    # three saddles in Hs 4 m: the linear MPM exceeds 11.8 MN, the nonlinear one (lift-off: 11.66 MN) does not
    p = ds.sel({"sea_state.significant_height_m": 4.0, "seafastening.saddle_count": 3, "load_case": "sea_state"})
    assert float(p["F_N"].sel(model="linear")) > 11.8e6 > float(p["F_N"].sel(model="nonlinear"))
    from seafast.studies.limits import rank_compliant

    ranked = rank_compliant(ds)
    keys = [(r["saddle_count"], r["sea_state.significant_height_m"]) for r in ranked]
    assert (3, 4.0) in keys and (3, 1.0) in keys  # judged on the nonlinear MPM
    assert [r["saddle_count"] for r in ranked] == sorted(r["saddle_count"] for r in ranked)


def test_study_command_response_option(tmp_path, capsys):
    study = tmp_path / "s.yaml"
    study.write_text(
        "name: two\naxes:\n  - {key: seafastening.saddle_count, values: [3, 4]}\n"
        "limits: {max_saddle_force_N: 11.5e+6, max_bending_stress_Pa: 28.0e+6}\n",
        encoding="utf-8",
    )
    out = tmp_path / "o"
    assert (
        main(["study", str(study), "-o", str(out), "--workers", "1", "--no-progress", "--no-figures", "-q", "--response", "sea_state"]) == 0
    )
    with open(out / "study.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert {r["load_case"] for r in rows} == {"sea_state"} and len(rows) == 4
    assert all(r["u_c_m"] == "" for r in rows)  # not computed in a sea state


def test_sea_state_rows_carry_the_models_typed_warnings():
    """Two saddles at 2.57e9 N/m: the Rayleigh fit misses 2 % by 21 % (see tests/analyses/test_run.py); the
    damping shapes the spectral and the design-wave responses alike, so both rows raise rayleigh_fallback."""
    from seafast.analyses.seastate.study import evaluate_sea_state
    from seafast.model.warning import ModelWarning

    overrides = {"sea_state.significant_height_m": 2.0, "seafastening.saddle_count": 2, "seafastening.saddle_stiffness_N_per_m": 2.569e9}
    rows = evaluate_sea_state(seafast.load_case(None, overrides))
    assert [(r["model"], r["warnings"]) for r in rows] == [
        ("linear", (ModelWarning.RAYLEIGH_FALLBACK,)),
        ("nonlinear", (ModelWarning.RAYLEIGH_FALLBACK,)),
    ]
