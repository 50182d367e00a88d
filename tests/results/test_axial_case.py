"""The axial analysis of the base case end to end: the source's results untouched, HBM against the
time-domain reference, the statics, the frictionless limit, the one-way coupling, outputs and studies."""

from __future__ import annotations

import csv
import re
from dataclasses import replace

import numpy as np
import pytest
import xarray as xr

from seafast.cli import main
from seafast.config import load_case
from seafast.excitation.axial import axial_load_of
from seafast.model.from_case import axial_restraint
from seafast.pipeline import run_case, solve_nonlinear
from seafast.results.axial import AXIAL_SUMMARY_COLUMNS
from seafast.results.dataset import SUMMARY_COLUMNS
from seafast.solvers.axial import solve_axial_time_domain
from seafast.solvers.axial.harmonic_balance import axial_time_samples

FAST = {"solver.time_samples": 64, "model.element_length_m": 2.0}


@pytest.fixture(scope="module")
def plain():
    return run_case(load_case(None, FAST))


@pytest.fixture(scope="module")
def cases():
    return {mu: run_case(load_case(None, {**FAST, "seafastening.friction_coefficient": mu})) for mu in (0.0, 0.02, 0.05, 0.3)}


def _row(result, load_case="dynamic", model="nonlinear"):
    return next(r for r in result.summary if r["load_case"] == load_case and r["model"] == model)


def test_without_friction_the_source_results_bit_for_bit(plain, cases):
    assert plain.axial is None and plain.summary_columns == SUMMARY_COLUMNS
    assert not any(k in plain.dataset for k in ("slip_m", "friction_force_N"))
    with_axial = cases[0.3]
    assert with_axial.summary_columns == SUMMARY_COLUMNS + ("slip_m", "friction_utilisation", "axial_force_N")
    for a, b in zip(plain.summary, with_axial.summary, strict=True):
        for key in SUMMARY_COLUMNS:
            assert a[key] == b[key], key  # the axial analysis is one way: the vertical numbers are identical
    np.testing.assert_array_equal(plain.dataset["saddle_force_N"].values, with_axial.dataset["saddle_force_N"].values)


def test_base_case_hbm_against_the_time_domain_reference(cases):
    """mu = 0.02 (below mu_crit ~ 0.058): the cargo slides metres per period; HBM = reference within 1 %."""
    res = cases[0.02]
    case = res.case
    restraint, load = axial_restraint(case), axial_load_of(case, res.vessel)
    for j, model in enumerate(("linear", "nonlinear")):
        normal = np.maximum(res.arrays.saddle_force_N[1, j], 0.0)
        td = solve_axial_time_domain(
            restraint, load, normal, time_samples=axial_time_samples(res.case.solver.axial_harmonics, normal.shape[0])
        )
        row = _row(res, model=model)
        assert td.converged and row["axial_converged"]
        assert "axial HBM" in str(res.axial.messages[1, j]) and "time-domain" not in str(res.axial.messages[1, j])
        assert row["slip_m"] > 1.0
        assert row["slip_m"] == pytest.approx(td.slip_m, rel=0.01)
        assert row["axial_force_N"] == pytest.approx(td.axial_force_N, rel=0.01)
        assert row["friction_utilisation"] == 1.0


def test_large_coefficient_sticks_with_the_statics(cases):
    res = cases[0.3]
    for model in ("linear", "nonlinear"):
        row = _row(res, model=model)
        assert row["slip_m"] == 0.0 and row["axial_force_N"] < 1.0
        # stuck, the friction carries the whole axial load: utilisation = mu_crit / mu
        assert row["friction_utilisation"] == pytest.approx(row["critical_friction_coefficient"] / 0.3, rel=1e-3)
        assert 0.03 < row["critical_friction_coefficient"] < 0.1
        static = _row(res, "static", model)
        assert static["slip_m"] == 0.0 and static["friction_utilisation"] == 0.0  # even keel: no still-water axial load
    ds = res.dataset
    f = ds["friction_force_N"].sel(load_case="dynamic", model="nonlinear").values
    load = ds["axial_load_N"].sel(load_case="dynamic", model="nonlinear").values
    np.testing.assert_allclose(f, -load, atol=1e-4 * np.max(np.abs(load)))  # friction holds the load


def test_near_critical_coefficient_is_solved_by_the_reference(cases):
    """mu = 0.05, just below mu_crit: long stick phases; the row is solved (by the reference where the
    HBM fails, and the message says so) and agrees with the reference."""
    res = cases[0.05]
    message = str(res.axial.messages[1, 1])
    row = _row(res)
    assert row["axial_converged"] and row["converged"]
    assert ("did not converge" in message) == ("time-domain reference" in message)
    normal = np.maximum(res.arrays.saddle_force_N[1, 1], 0.0)
    td = solve_axial_time_domain(
        axial_restraint(res.case),
        axial_load_of(res.case, res.vessel),
        normal,
        time_samples=axial_time_samples(res.case.solver.axial_harmonics, normal.shape[0]),
    )
    assert 0.05 < row["slip_m"] < 1.0 and row["friction_utilisation"] == 1.0
    assert row["slip_m"] == pytest.approx(td.slip_m, rel=0.01)
    assert row["critical_friction_coefficient"] > 0.05


def test_zero_coefficient_is_the_lashings_linear_answer(cases):
    res = cases[0.0]
    restraint, load = axial_restraint(res.case), axial_load_of(res.case, res.vessel)
    x = load.force_N[1] / (restraint.lashing_axial_stiffness_N_per_m - restraint.cargo_mass_kg * load.omega_rad_s**2)
    n = res.arrays.period_fraction.size
    u = np.real(x * np.exp(2j * np.pi * np.arange(n) / n))
    got = res.dataset["axial_displacement_m"].sel(load_case="dynamic", model="nonlinear").values
    np.testing.assert_allclose(got, u, atol=1e-6 * abs(x))
    assert _row(res)["axial_force_N"] == pytest.approx(restraint.lashing_axial_stiffness_N_per_m * np.max(np.abs(u)), rel=1e-6)


def test_one_way_coupling_friction_moment_is_small(cases):
    """Friction at the contact line (D/2 below the axis) puts a moment on the cargo; re-solving the
    vertical HBM with it changes the peak saddle force by < 2 % (docs/axial.md, one-way coupling)."""
    res = cases[0.3]
    model, exc = res.model, res.excitation
    estimate = float(res.axial.rows["friction_moment_saddle_force_change_N"][1, 1])
    per_saddle = res.dataset["friction_force_per_saddle_N"].sel(load_case="dynamic", model="nonlinear").values  # (N, n_s)
    lever = 0.5 * model.cargo.element_outer_diameter_m[0]
    H = int(res.responses["nonlinear_dynamic"].options["harmonics"])  # the harmonics the vertical solve used
    moments = np.fft.rfft(per_saddle * lever, axis=0)[: H + 1] / per_saddle.shape[0]
    moments[1:] *= 2.0
    padded = exc.padded(H + 1)
    load = padded.cargo_load_N.copy()
    load[:, model.saddle_cargo_dof + 1] += moments
    # the same harmonics as the uncoupled solve, so that the two compare sample by sample
    nd = res.responses["nonlinear_dynamic"]
    same = res.case.model_copy(update={"solver": res.case.solver.model_copy(update={"harmonics": H, "time_samples": nd.time_samples})})
    coupled = solve_nonlinear(model, replace(padded, cargo_load_N=load), same, static=False)
    # the peaks (the moment shifts the ringing after a re-contact by a few samples: compare peaks, not samples)
    change = np.max(np.abs(coupled.saddle_force_time_N.max(axis=0) - nd.saddle_force_time_N.max(axis=0)))
    peak = _row(res)["F_N"]
    assert coupled.converged
    # 1.5 % measured with the ringing resolved (the moment shifts it); the quasi-static estimate says 0.5 %
    assert change < 0.02 * peak and estimate < 0.01 * peak
    assert 0.3 < change / estimate < 3.0  # the estimate has the right size


def test_results_netcdf_and_summary_csv(cases, tmp_path):
    res = cases[0.02]
    code = main(
        [
            "run",
            "-o",
            str(tmp_path),
            "-q",
            "--no-plots",
            "--set",
            "seafastening.friction_coefficient=0.02",
            "--set",
            "solver.time_samples=64",
            "--set",
            "model.element_length_m=2.0",
        ]
    )
    assert code == 0
    header = (tmp_path / "summary.csv").read_text(encoding="utf-8").splitlines()[0]
    assert header == ",".join(SUMMARY_COLUMNS + AXIAL_SUMMARY_COLUMNS)
    rows = list(csv.DictReader((tmp_path / "summary.csv").open(encoding="utf-8")))
    assert float(rows[3]["slip_m"]) == pytest.approx(_row(res)["slip_m"], rel=1e-12)
    with xr.open_dataset(tmp_path / "results.nc") as ds:
        for name in (
            "axial_displacement_m",
            "friction_force_N",
            "friction_capacity_N",
            "lashing_axial_force_N",
            "stopper_force_N",
            "axial_load_N",
            "friction_force_per_saddle_N",
            "sliding",
            "slip_m",
            "friction_utilisation",
            "critical_friction_coefficient",
            "surge_rao_real",
        ):
            assert ds[name].attrs["units"] and ds[name].attrs["long_name"], name
        assert ds["sliding"].sel(load_case="dynamic", model="nonlinear").values.any()


def test_cli_axial_errors(tmp_path):
    assert main(["run", "-o", str(tmp_path), "-q", "--no-plots", "--set", "seafastening.friction_coefficient=-1"]) == 2
    assert main(["run", "-o", str(tmp_path), "-q", "--no-plots", "--set", "seafastening.friction_coefficient=[0.1, 0.2]"]) == 2


def test_imported_motions_without_surge(tmp_path, capsys, plain):
    """Heave/pitch-only hydrodynamic data: the vertical analysis runs, the axial one refuses (exit 2)."""
    import capytaine as cpt

    from seafast.excitation.hydrodynamics import default_cache_dir
    from seafast.excitation.hydrodynamics.capytaine_io import read_capytaine_netcdf

    key = re.search(r"cache key (\w+)", plain.vessel.motions.source).group(1)
    ds = read_capytaine_netcdf(default_cache_dir() / f"motions_{key}.nc")
    path = tmp_path / "heave_pitch.nc"
    cpt.export_dataset(path, ds.sel(influenced_dof=["Heave", "Pitch"], radiating_dof=["Heave", "Pitch"]))
    common = [
        "-q",
        "--no-plots",
        "--set",
        f"vessel.motions={path}",
        "--set",
        "solver.time_samples=64",
        "--set",
        "model.element_length_m=2.0",
    ]
    assert main(["run", "-o", str(tmp_path / "v"), *common]) == 0
    # the surge problems of the BEM changed nothing of the vertical analysis: same numbers bit for bit
    rows = list(csv.DictReader((tmp_path / "v" / "summary.csv").open(encoding="utf-8")))
    for row, ref in zip(rows, plain.summary, strict=True):
        assert [float(row[k]) for k in SUMMARY_COLUMNS[2:-1]] == [ref[k] for k in SUMMARY_COLUMNS[2:-1]]
    capsys.readouterr()
    assert main(["run", "-o", str(tmp_path / "a"), *common, "--set", "seafastening.friction_coefficient=0.3"]) == 2
    assert "surge" in capsys.readouterr().err


def test_study_over_the_friction_coefficient(tmp_path):
    from seafast.studies.runner import ExecutionOptions, run_study
    from seafast.studies.spec import build_grid, study_spec_from_mapping

    spec = study_spec_from_mapping(
        {
            "name": "friction",
            "set": {**FAST, "seafastening.friction_coefficient": [0.3, 0.3, 0.3]},  # a per-saddle list in the base ...
            "axes": [{"key": "seafastening.friction_coefficient", "values": [0.02, 0.3]}],  # ... replaced by the axis
        }
    )
    run = run_study(build_grid(spec), tmp_path, execution=ExecutionOptions(workers=1, progress=False))
    ds = run.dataset
    slip = ds["slip_m"].sel(load_case="dynamic", model="nonlinear").values
    assert slip[0] > 1.0 and slip[1] == 0.0
    assert ds["slip_m"].attrs["units"] == "m"
    header = (tmp_path / "study.csv").read_text(encoding="utf-8").splitlines()[0].split(",")
    assert {"slip_m", "friction_utilisation", "axial_force_N", "critical_friction_coefficient"} <= set(header)


def test_report_has_the_stick_slip_figure_and_axial_section(tmp_path):
    from seafast.output.report import write_report

    assert (
        main(
            [
                "run",
                "-o",
                str(tmp_path),
                "-q",
                "--set",
                "seafastening.friction_coefficient=0.05",
                "--set",
                "solver.time_samples=64",
                "--set",
                "model.element_length_m=2.0",
            ]
        )
        == 0
    )
    assert (tmp_path / "stick_slip.png").is_file()
    out = write_report(tmp_path)
    assert "fig-stick-slip" in out.figure_ids
    page = out.html.read_text(encoding="utf-8")
    assert "Axial sliding" in page and "critical friction coefficient" in page
    assert any("slides on its saddles" in f.title and f.level == "WARNING" for f in out.findings)
    assert any(p.name == "stick_slip.png" for p in out.pngs)


def test_vertical_motion_coupling_switch(plain):
    """vessel.motion_coupling: the vertical analysis on the 2-DOF heave-pitch (default, the source's) or
    the surge-coupled motions; the switch changes the dynamic saddle force by a fraction of a per cent."""
    coupled = run_case(load_case(None, {**FAST, "vessel.motion_coupling": "surge_heave_pitch"}))
    rb, rb0 = coupled.vessel.rigid_body, plain.vessel.rigid_body
    assert rb.pitch_rad == rb.coupled_pitch_rad and rb0.pitch_rad != rb0.coupled_pitch_rad
    assert abs(abs(rb.pitch_rad) / abs(rb0.pitch_rad) - 1) < 0.05
    for a, b in zip(plain.summary, coupled.summary, strict=True):
        if a["load_case"] == "static":
            assert a["F_N"] == b["F_N"]
        else:
            assert 0 < abs(b["F_N"] / a["F_N"] - 1) < 0.01
