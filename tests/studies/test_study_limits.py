"""Design limits: compliance map and ranking on a hand-made dataset; CLI outputs and figures."""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from seafast.cli.study import main as study_main
from seafast.output.study_plots import plot_study
from seafast.studies.limits import DesignLimits, compliance, compliance_rows, format_table, rank_compliant

COUNT, STIFF = "seafastening.saddle_count", "seafastening.saddle_stiffness_N_per_m"


def _dataset() -> xr.Dataset:
    counts, stiff = np.array([2, 3, 4]), np.array([1e8, 1e9])
    F = np.zeros((3, 2, 2, 2))
    S = np.zeros((3, 2, 2, 2))
    # dynamic (load_case 1) nonlinear (model 1) values; limits 7 MN and 20 MPa
    F[..., 1, 1] = [[6.3e6, 7.7e6], [3.5e6, 5.6e6], [2.8e6, 6.9e6]]
    S[..., 1, 1] = [[10e6, 10e6], [14e6, 14e6], [18e6, 15e6]]
    F[..., 1, 0] = F[..., 1, 1] * 0.9  # linear: 10 % lower force
    S[..., 1, 0] = S[..., 1, 1]
    F[..., 0, :] = 1e9  # static rows must be ignored
    converged = np.ones((3, 2, 2, 2), dtype=bool)
    converged[1, 1, :, 1] = False  # (3 saddles, 1e9) did not converge
    error = np.array([["", ""], ["", ""], ["", "RuntimeError: boom"]], dtype=str)
    dims = (COUNT, STIFF, "load_case", "model")
    return xr.Dataset(
        {
            "F_N": (dims, F),
            "sigma_b_Pa": (dims, S),
            "M_b_Nm": (dims, S * 1.0),
            "converged": (dims, converged),
            "contact_preserved": (dims, np.ones_like(converged)),
            "error": ((COUNT, STIFF), error),
        },
        coords={
            COUNT: (COUNT, counts, {"units": "1", "scale": "linear", "base_value": 3}),
            STIFF: (STIFF, stiff, {"units": "N/m", "scale": "log", "base_value": 1.1e9}),
            "load_case": ["static", "dynamic"],
            "model": ["linear", "nonlinear"],
        },
        attrs={"study": "hand-made", "max_saddle_force_N": 7e6, "max_bending_stress_Pa": 20e6},
    )


def test_compliance_uses_the_dynamic_nonlinear_response_and_excludes_failures():
    comp = compliance(_dataset())
    nonlinear = comp["complies"].sel(model="nonlinear").values
    assert nonlinear.tolist() == [[True, False], [True, False], [True, False]]
    linear = comp["complies"].sel(model="linear").values
    assert linear.tolist() == [[True, True], [True, True], [True, False]]  # 0.9 * 7.7 MN < 7 MN; error point never
    assert comp["margin"].sel(model="nonlinear").values[0, 0] == pytest.approx(min(1 - 6.3 / 7, 1 - 10 / 20))


def test_ranking_fewest_saddles_then_largest_margin():
    ranking = rank_compliant(_dataset())
    assert [(r["saddle_count"], r[STIFF]) for r in ranking] == [(2, 1e8), (3, 1e8), (4, 1e8)]
    assert [r["rank"] for r in ranking] == [1, 2, 3]
    assert ranking[0]["margin"] == pytest.approx(1 - 6.3 / 7)
    assert ranking[2]["margin"] == pytest.approx(min(1 - 2.8 / 7, 1 - 18 / 20))
    strict = rank_compliant(_dataset(), DesignLimits(max_saddle_force_N=5e6, max_bending_stress_Pa=20e6))
    assert [(r["saddle_count"], r[STIFF]) for r in strict] == [(3, 1e8), (4, 1e8)]
    relaxed = rank_compliant(_dataset(), DesignLimits(max_saddle_force_N=1e7, max_bending_stress_Pa=20e6))
    assert [(r["saddle_count"], r[STIFF]) for r in relaxed] == [(2, 1e8), (2, 1e9), (3, 1e8), (4, 1e8)]
    assert relaxed[0]["margin"] > relaxed[1]["margin"]


def test_compliance_rows_and_table():
    rows = compliance_rows(_dataset())
    assert len(rows) == 6 and rows[-1]["error"] == "RuntimeError: boom" and rows[3]["converged"] is False
    table = format_table(rows, max_rows=2)
    assert "complies_nonlinear" in table and "... 4 more rows" in table


def test_figures_for_two_one_and_three_axes(tmp_path: Path):
    ds = _dataset()
    two = plot_study(ds, tmp_path / "two")
    assert sorted(p.name for p in two) == ["compliance_map.png", "surface_linear.png", "surface_nonlinear.png"]
    one = plot_study(ds.isel({COUNT: [1]}), tmp_path / "one")
    assert [p.name for p in one] == ["profiles.png"]
    three = ds.expand_dims({"wave.amplitude_m": [2.0, 3.0]}).transpose("wave.amplitude_m", ...)
    three["wave.amplitude_m"].attrs.update(units="m", base_value=3.0)
    assert len(plot_study(three, tmp_path / "three")) == 3
    for p in [*two, *one]:
        assert p.stat().st_size > 10_000 and p.read_bytes()[:4] == b"\x89PNG"


def test_study_command_writes_compliance_ranking_and_figures(small_study_file: Path, tmp_path: Path, monkeypatch, capsys):
    monkeypatch.setenv("SEAFAST_STUDY_EVALUATOR", "study_fakes:fake_evaluate")
    out = tmp_path / "out"
    assert study_main([str(small_study_file), "-o", str(out), "--workers", "1", "--no-progress"]) == 0
    printed = capsys.readouterr().out
    assert "compliant arrangements" in printed and "rank" in printed
    for name in ("study.nc", "study.csv", "compliance.csv", "ranking.csv", "surface_nonlinear.png", "compliance_map.png"):
        assert (out / name).exists(), name
    with open(out / "ranking.csv", newline="") as fh:
        ranking = list(csv.DictReader(fh))
    counts = [int(r["saddle_count"]) for r in ranking]
    assert counts == sorted(counts) and len(ranking) > 0
    with open(out / "compliance.csv", newline="") as fh:
        assert next(csv.reader(fh))[:3] == [COUNT, STIFF, "F_linear_N"]
