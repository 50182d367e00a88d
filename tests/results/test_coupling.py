"""Two-way coupling as users' scripts and the report meet it: results.nc, hull_girder.png, the
CLI warning and the report's findings, for a converged and a non-converged coupling."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from seafast.analyses.run import run_case
from seafast.cli import main
from seafast.config import load_case
from seafast.coupling import case as coupling_case
from seafast.output import plots
from seafast.output.report.findings import run_findings
from seafast.output.report.tables import coupling_rows, diagnostics_rows
from seafast.output.report.vessel_figures import hull_girder_figure
from seafast.output.tables import format_summary_table
from seafast.results.coupling import COUPLED_HULL_VARIABLES
from seafast.solvers.references import TimeDomainOptions, solve_time_domain

FAST = {"vessel.motions": "none", "solver.time_samples": 32}


@pytest.fixture(scope="module")
def runs():
    one = run_case(load_case(overrides=FAST))
    two = run_case(load_case(overrides={**FAST, "vessel.coupling": "two_way"}))
    return one, two


@pytest.fixture
def never_converging(monkeypatch):
    """Every coupling stops before its first step (its residual is then the whole deck change)."""
    original = coupling_case.couple_deck
    monkeypatch.setattr(coupling_case, "couple_deck", lambda *a, **k: original(*a, **{**k, "max_iterations": 0}))


def test_results_nc_holds_both_hulls_labelled(runs, tmp_path):
    one, two = runs
    path = tmp_path / "results.nc"
    two.dataset.to_netcdf(path)
    with xr.open_dataset(path) as stored:
        ds = stored.load()
    for coupled, one_way in COUPLED_HULL_VARIABLES.items():
        # the one-way hull keeps its name, grid and values, labelled one-way
        assert ds[one_way].attrs["hull_coupling"] == "one_way" and "one-way" in ds[one_way].attrs["long_name"]
        np.testing.assert_array_equal(ds[one_way].values, one.dataset[one_way].values)
        # the coupled hull beside it, same dimensions and units, labelled two-way
        assert ds[coupled].dims == ds[one_way].dims
        assert ds[coupled].attrs["units"] == ds[one_way].attrs["units"]
        assert ds[coupled].attrs["hull_coupling"] == "two_way" and "two-way" in ds[coupled].attrs["long_name"]
        assert np.abs(ds[coupled].values - ds[one_way].values).max() > 1e-3 * np.abs(ds[one_way].values).max()
    for name in (
        "coupling_converged",
        "coupling_residual_m",
        "coupling_tolerance_m",
        "coupling_deck_motion_scale_m",
        "coupling_iterations",
        "coupling_mean_deck_change_m",
        "coupling_outcome",
        "coupling_message",
    ):
        assert ds[name].dims[:2] == ("load_case", "model") and "long_name" in ds[name].attrs
    np.testing.assert_array_equal(ds["coupling_converged"].values, 1)
    assert np.all(ds["coupling_residual_m"].values <= ds["coupling_tolerance_m"].values)
    # a one-way run: the same hull variables, labelled one-way, and nothing coupled
    ow = one.dataset
    assert ow["hull_still_water_bending_moment_Nm"].attrs["hull_coupling"] == "one_way"
    assert not [v for v in ow.data_vars if "coupled" in v or v.startswith("coupling_")]
    assert all("coupling_residual_m" not in row for row in one.summary)


def test_hull_girder_png_draws_both_hulls_labelled(runs, tmp_path, monkeypatch):
    one, two = runs
    legends = {}
    save = plots._save  # the figure's legends, read as it is written

    def keep(fig, path):
        legends[Path(path).stem] = [t.get_text() for ax in fig.axes if ax.get_legend() for t in ax.get_legend().get_texts()]
        return save(fig, path)

    monkeypatch.setattr(plots, "_save", keep)
    plots.plot_hull_girder(two.dataset, tmp_path / "two.png")
    plots.plot_hull_girder(one.dataset, tmp_path / "one.png")
    two_labels, one_labels = legends["two"], legends["one"]
    for kind in ("still water", "hog", "sag"):
        assert any(kind in t and "one-way" in t for t in two_labels), two_labels
        assert any(kind in t and "two-way coupled" in t for t in two_labels), two_labels
    assert not any("two-way" in t for t in one_labels)
    assert (tmp_path / "two.png").stat().st_size > 1000
    names = [trace.name for trace in hull_girder_figure(two.dataset).data if trace.name]
    assert any("two-way coupled" in n for n in names) and any("one-way" in n for n in names)


def test_a_flagged_row_shows_the_couplings_own_residual(never_converging, tmp_path, capsys):
    out = tmp_path / "run"
    assert main(["run", "-o", str(out), "--set", "vessel.coupling=two_way", "--set", "vessel.motions=none", "--no-plots"]) == 3
    captured = capsys.readouterr()
    warnings = [line for line in captured.err.splitlines() if line.startswith("seafast: warning") and "did NOT converge" in line]
    assert len(warnings) == 4
    with xr.open_dataset(out / "results.nc") as stored:
        ds = stored.load()
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


def test_heavy_lift_off_couples_at_h16_then_solves_the_coupled_deck_with_the_adaptive_h():
    """Three saddles at 5e9 N/m lift off by 23 mm one-way (H = 512): the deck iterated at the adaptive H of each
    iterate stalled (docs/coupling.md). Now the deck converges at H = 16 (the same deck as a run at H = 16) and the
    row's answer is the converged default on that deck (exact-event shooting): converged, its sampled peaks within
    the tolerance of the continuous ones, and within 0.5 % of the independent time-domain reference on the coupled
    deck (1024 steps a period: -0.15 %, -0.10 % at 4096, converging on it), where the H = 16 solution is 2.4 % low."""
    over = {"vessel.coupling": "two_way", "seafastening.saddle_count": 3, "seafastening.saddle_stiffness_N_per_m": 5e9}
    res = run_case(load_case(overrides=over))
    status = res.coupling[("dynamic", "nonlinear")]
    assert status.converged and status.residual_m <= status.tolerance_m
    final = res.rows.nonlinear_dynamic
    assert final.converged and final.options["harmonics_selection"] == "shooting"
    assert float(np.max(final.truncation_error)) <= 1e-3
    at16 = run_case(load_case(overrides={**over, "solver.harmonics": 16}))
    deck = res.deck_couplings[("dynamic", "nonlinear")].excitation
    np.testing.assert_array_equal(deck.deck_displacement, at16.deck_couplings[("dynamic", "nonlinear")].excitation.deck_displacement)
    reference = solve_time_domain(res.model, deck, TimeDomainOptions(time_samples=1024))
    assert reference.converged
    f_adaptive = next(r["F_N"] for r in res.summary if r["load_case"] == "dynamic" and r["model"] == "nonlinear")
    f_16 = next(r["F_N"] for r in at16.summary if r["load_case"] == "dynamic" and r["model"] == "nonlinear")
    assert f_adaptive == pytest.approx(reference.max_saddle_force_N, rel=5e-3)
    assert abs(f_16 / reference.max_saddle_force_N - 1.0) > 0.01
