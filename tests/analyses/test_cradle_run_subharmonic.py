"""`seafast run` off head seas where the cargo's response repeats every two wave periods (docs/transverse.md#9-in-seafast-run):
the rows, the summary, the warning and results.nc over the two periods. The subharmonic solve itself is checked in
tests/solvers/test_cradle_subharmonic.py; here the dynamic row is the base case's beam-sea answer repeated over two
periods and marked a subharmonic, to check the wiring alone."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

import seafast.analyses.cradle_run as cradle_run
from seafast.analyses.cradle_run import case_cradle_excitation, cradle_dynamics_of_case, cradle_rows
from seafast.analyses.run import run_case
from seafast.config.loader import load_case
from seafast.model.cradle_case import build_cradle_case
from seafast.solvers.outcome import SolverOutcome


@pytest.fixture(scope="module")
def beam_sea():
    return run_case(load_case(overrides={"wave.heading_deg": 90.0}))


def _twice(response):
    """The response repeated over two wave periods, marked a converged subharmonic."""
    N = response.time_s.size
    return replace(
        response,
        outcome=SolverOutcome.CONVERGED_SUBHARMONIC,
        time_s=np.arange(2 * N) * (response.time_s[1] - response.time_s[0]),
        engagement_m=np.tile(response.engagement_m, (2, 1)),
        element_force_N=np.tile(response.element_force_N, (2, 1)) * np.linspace(1.0, 1.01, 2 * N)[:, None],
        cargo_displacement_m=np.tile(response.cargo_displacement_m, (2, 1)),
        period_multiple=2,
    )


def test_the_rows_summary_warning_and_dataset_span_the_subharmonics_periods(beam_sea, monkeypatch):
    """The linear rows over two periods are the wave period's twice (to 1e-12), the still-water row's time the
    dynamic row's; the summary's dynamic nonlinear row converged with the outcome ``converged_subharmonic`` and its
    maxima over both periods; one warning line, for that row; results.nc's ``cradle_period_fraction`` spans the
    two periods (its attribute and the dataset's ``cradle_period_multiple`` say so)."""
    cradle = build_cradle_case(beam_sea.case, beam_sea.model)
    dynamics = cradle_dynamics_of_case(cradle)
    excitation = case_cradle_excitation(cradle, beam_sea.excitation, beam_sea.vessel)
    once = beam_sea.cradle
    solve = cradle_run.solve_cradle_hbm
    monkeypatch.setattr(cradle_run, "solve_cradle_hbm", lambda d, e, o: _twice(solve(d, e, o)))
    rows = cradle_rows(beam_sea.case, cradle, dynamics, excitation)
    N = once.rows[("dynamic", "linear")].response.time_s.size
    for key in (("static", "linear"), ("dynamic", "linear")):
        twice, single = rows.rows[key].response, once.rows[key].response
        assert twice.period_multiple == 2 and twice.time_s.size == 2 * N
        scale = np.max(np.abs(single.element_force_N))
        assert np.max(np.abs(twice.element_force_N - np.tile(single.element_force_N, (2, 1)))) <= 1e-12 * scale
    dynamic = rows.rows[("dynamic", "nonlinear")].response
    assert np.array_equal(rows.rows[("static", "nonlinear")].response.time_s, dynamic.time_s)
    result = replace(beam_sea, cradle=rows)
    summary = {(r["load_case"], r["model"]): r for r in result.summary}
    row = summary[("dynamic", "nonlinear")]
    assert row["converged"] and row["cradle_outcome"] == "converged_subharmonic" and row["cradle_period_multiple"] == 2
    assert row["F_pad_N"] == pytest.approx(float(np.max(dynamic.pad_force_N)), rel=1e-12)
    assert row["F_pad_N"] > 1.005 * float(np.max(once.rows[("dynamic", "nonlinear")].response.pad_force_N))
    lines = rows.warning_lines()
    assert len(lines) == 1 and lines[0].startswith("dynamic nonlinear:") and "repeats every 2 wave periods" in lines[0]
    ds = result.dataset
    assert ds.attrs["cradle_period_multiple"] == 2 and ds.sizes["cradle_period_fraction"] == 2 * N
    assert "2 wave periods" in ds["cradle_period_fraction"].attrs["long_name"]
    assert once.warning_lines() == [] and once.to_dataset().attrs["cradle_period_multiple"] == 1
