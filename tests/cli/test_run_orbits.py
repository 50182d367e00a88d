"""The time-domain reference's start and orbit as the command line, results.nc and the report show them.

On the bistable case of ``tests/solvers/test_time_domain_orbits.py`` (1 % saddles, deck deflection of a 9 m
wave at 3.8 rad/s, 4 m mesh, 32 reference samples per period): ``solver.method=time_domain`` starts from the
linear periodic solution, or with ``solver.time_domain_start=hbm`` from the harmonic balance's orbit; a run
whose reference leaves its starting orbit (an HBM that landed on the unstable orbit C) is reported as
``other_orbit`` by the typed outcome in results.nc, a warning on stderr and a WARNING in the report; one
that never repeats (at 3.85 rad/s) as ``not_periodic``, exit code 3.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import xarray as xr

import seafast.solvers.dispatch as dispatch
from seafast.cli import main
from seafast.output.report.findings import run_findings
from seafast.solvers.hbm import HBMOptions

CASE = [
    "--set",
    "seafastening.saddle_stiffness_N_per_m=1.1e7",
    "--set",
    "vessel.motions=none",
    "--set",
    "wave.amplitude_m=9.0",
    "--set",
    "wave.frequency_rad_s=3.8",
    "--set",
    "model.element_length_m=4.0",
    "--set",
    "solver.method=time_domain",
    "--set",
    "solver.time_samples=32",
    "--no-plots",
    "-q",
]


def _dynamic_nonlinear(ds: xr.Dataset) -> xr.Dataset:
    return ds.sel(load_case="dynamic", model="nonlinear")


@pytest.mark.parametrize("start", ["linear", "hbm"])
def test_time_domain_run_reaches_the_hbm_orbit_from_either_start(tmp_path, start, capsys):
    out = tmp_path / start
    assert main(["run", "-o", str(out), *CASE, "--set", f"solver.time_domain_start={start}"]) == 0
    assert "ANOTHER periodic state" not in capsys.readouterr().err
    with xr.open_dataset(out / "results.nc") as ds:
        row = _dynamic_nonlinear(ds)
        assert str(row["solver_outcome"].values) == "converged" and bool(row["converged"])
        assert float(row["F_N"]) == pytest.approx(8.141e6, rel=2e-3)  # orbit A
        assert ds.attrs["time_domain_start"] == start
        distance = ds.attrs["time_domain_orbit_distance_from_start"]
        assert math.isnan(distance) if start == "linear" else distance < 1e-3
        assert not any("left the orbit" in f.title for f in run_findings(ds))


def test_a_reference_that_leaves_the_hbm_orbit_is_reported(tmp_path, monkeypatch, capsys):
    """The HBM is made to return orbit C (its solution from a start shifted by half a period): the reference
    started there settles on orbit A, and the run says so as a typed outcome, on stderr and in the report."""
    solve = dispatch.solve_hbm

    def other_orbit(model, excitation, options=None, **kwargs):
        from seafast.fourier import harmonics_to_time
        from seafast.solvers.linear import solve_linear

        lin = harmonics_to_time(solve_linear(model, excitation).saddle_compression_m, 256)
        # H = 10: orbit C is unstable and a march from it reaches orbit A only from this H's truncation
        # error (from H >= 12 it is thrown into the bouncing motion; tests/solvers/test_time_domain_orbits.py)
        options = HBMOptions(continuation=False, harmonics=10)
        return solve(model, excitation, options, initial_compression_m=np.roll(lin, 128, axis=0))

    monkeypatch.setattr(dispatch, "solve_hbm", other_orbit)  # the HBM start solve_periodic solves first
    out = tmp_path / "other"
    assert main(["run", "-o", str(out), *CASE, "--set", "solver.time_domain_start=hbm"]) == 0  # a periodic state: numbers usable
    err = capsys.readouterr().err
    assert "started on the hbm solution's orbit and settled on ANOTHER periodic state" in err
    with xr.open_dataset(out / "results.nc") as ds:
        row = _dynamic_nonlinear(ds)
        assert str(row["solver_outcome"].values) == "other_orbit" and bool(row["converged"])
        assert float(row["F_N"]) == pytest.approx(8.141e6, rel=2e-3)  # what it reached: orbit A, not C's 9.70 MN
        assert ds.attrs["time_domain_orbit_distance_from_start"] > 0.1
        findings = [f for f in run_findings(ds) if f.level == "WARNING" and "left the orbit it started on" in f.title]
        assert len(findings) == 1 and "dynamic nonlinear" in findings[0].title


def test_a_reference_that_never_repeats_exits_3_and_says_not_periodic(tmp_path, capsys):
    """At 3.85 rad/s the linear start itself leads to the bouncing motion: no periodic state in the 201
    periods the damping allows, flagged not converged (exit 3) with the typed outcome, no traceback."""
    out = tmp_path / "np"
    argv = ["run", "-o", str(out), *CASE, "--set", "wave.frequency_rad_s=3.85"]
    assert main(argv) == 3
    err = capsys.readouterr().err
    assert "dynamic nonlinear solution did NOT converge (not periodic, residual" in err and "Traceback" not in err
    with xr.open_dataset(out / "results.nc") as ds:
        row = _dynamic_nonlinear(ds)
        assert str(row["solver_outcome"].values) == "not_periodic" and not bool(row["converged"])
        assert ds.attrs["time_domain_start"] == "linear" and ds.attrs["time_domain_periods"] == pytest.approx(201, abs=2)
        assert float(row["F_N"]) > 1.5 * 8.141e6  # the bouncing motion's impacts
        assert any(f.level == "WARNING" and "did NOT converge" in f.title for f in run_findings(ds))
