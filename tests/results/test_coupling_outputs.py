"""Two-way coupling as users' scripts and the report meet it: results.nc, the CLI warning and
the report's findings, for a converged and a non-converged coupling."""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr

from seafast import pipeline
from seafast.cli import main
from seafast.config import load_case
from seafast.output.report.findings import run_findings
from seafast.output.report.tables import coupling_rows, diagnostics_rows
from seafast.output.tables import format_summary_table
from seafast.pipeline import run_case

FAST = {"vessel.motions": "none", "solver.time_samples": 32}


@pytest.fixture(scope="module")
def runs():
    one = run_case(load_case(overrides=FAST))
    two = run_case(load_case(overrides={**FAST, "vessel.coupling": "two_way"}))
    return one, two


@pytest.fixture
def never_converging(monkeypatch):
    """Every coupling stops before its first step (its residual is then the whole deck change)."""
    original = pipeline.couple_deck
    monkeypatch.setattr(pipeline, "couple_deck", lambda *a, **k: original(*a, **{**k, "max_iterations": 0}))


def test_a_flagged_row_shows_the_couplings_own_residual(never_converging, tmp_path, capsys):
    out = tmp_path / "run"
    assert main(["run", "-o", str(out), "--set", "vessel.coupling=two_way", "--set", "vessel.motions=none", "--no-plots"]) == 3
    captured = capsys.readouterr()
    warnings = [line for line in captured.err.splitlines() if line.startswith("seafast: warning")]
    assert len(warnings) == 4
    with xr.open_dataset(out / "results.nc") as ds:
        ds = ds.load()
    for line in warnings:
        lc, model = line.split()[2:4]
        residual = float(ds["coupling_residual_m"].sel(load_case=lc, model=model))
        tolerance = float(ds["coupling_tolerance_m"].sel(load_case=lc, model=model))
        assert residual > 5e-3  # the deck change of mm, not the cargo solver's ~1e-15
        assert f"coupling residual {residual:.2e} m > tolerance {tolerance:.2e} m" in line, line
        assert "iteration limit" in line
    assert "NO (coupling residual" in captured.out  # the printed summary table
    # the report reads the same values
    findings = [f for f in run_findings(ds) if f.level == "WARNING" and "coupling did NOT converge" in f.title]
    assert len(findings) == 4
    residual = float(ds["coupling_residual_m"].sel(load_case="static", model="nonlinear"))
    assert any(f"coupling residual {residual:.2e} m" in f.text for f in findings)
    header, rows = diagnostics_rows(ds)
    assert "coupling residual [m]" in header
    column = header.index("coupling residual [m]")
    assert {row[column] for row in rows} == {f"{float(v):.2e}" for v in ds["coupling_residual_m"].values.ravel()}
    _, rows = coupling_rows(ds)
    assert [row[2] for row in rows] == ["iteration limit"] * 4


def test_a_converged_coupling_reads_as_converged_everywhere(runs):
    _, two = runs
    ds = two.dataset
    assert not any("coupling" in f.title for f in run_findings(ds))
    _, rows = coupling_rows(ds)
    assert [row[2] for row in rows] == ["converged"] * 4
    table = format_summary_table(two.summary)
    assert "NO" not in table
