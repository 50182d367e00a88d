"""The axial analysis of the base case end to end: the source's results untouched, HBM against the
time-domain reference, the statics, the frictionless limit, the one-way coupling, outputs and studies."""

from __future__ import annotations

import csv
import re
from dataclasses import replace

import numpy as np
import pytest
import xarray as xr

from seafast.analyses.axial import axial_options, solve_axial_row
from seafast.analyses.run import run_case
from seafast.cli import main
from seafast.config import load_case
from seafast.excitation.axial import axial_load_of
from seafast.model.from_case import axial_restraint
from seafast.results.axial import AXIAL_SUMMARY_COLUMNS
from seafast.results.dataset import SUMMARY_COLUMNS
from seafast.solvers.axial import LockCheck, solve_axial_hbm, solve_axial_time_domain
from seafast.solvers.axial.harmonic_balance import axial_time_samples
from seafast.solvers.from_case import solve_nonlinear

FAST = {"solver.time_samples": 64, "model.element_length_m": 2.0}
_MODELS = ("linear", "nonlinear")


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
    assert with_axial.summary_columns == SUMMARY_COLUMNS + ("slip_m", "friction_utilisation", "axial_force_N", "axial_warnings")
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


def _reference(res, model="nonlinear"):
    """The independent rigid-Coulomb reference on the row's own normal forces."""
    normal = np.maximum(res.arrays.saddle_force_N[1, _MODELS.index(model)], 0.0)
    restraint, load = axial_restraint(res.case), axial_load_of(res.case, res.vessel)
    return solve_axial_time_domain(
        restraint, load, normal, time_samples=axial_time_samples(res.case.solver.axial_harmonics, normal.shape[0])
    )


def _coefficients(res, model="nonlinear", oversample=16):
    """The critical and the shakedown coefficients of a row, from its load and normal forces (the
    friction capacity is linear between the vertical solution's samples, as both solvers take it)."""
    from scipy.optimize import brentq

    load = axial_load_of(res.case, res.vessel)
    total = np.maximum(res.arrays.saddle_force_N[1, _MODELS.index(model)], 0.0).sum(axis=1)
    n = total.size
    t = np.arange(n * oversample) / (n * oversample)
    force = np.real(sum(f * np.exp(2j * np.pi * k * t) for k, f in enumerate(load.force_N)))
    total = np.interp(t, np.arange(n + 1) / n, np.r_[total, total[0]])
    mu_crit = float(np.max(np.abs(force) / total))
    mu_sd = brentq(lambda mu: np.max(force - mu * total) - np.min(force + mu * total), 1e-6, mu_crit)
    return mu_crit, mu_sd, force, total, load


@pytest.fixture(scope="module")
def near(cases):
    """Two coefficients placed by the base case's own critical and shakedown coefficients: below the
    shakedown one by half their difference, and midway between them."""
    mu_crit, mu_sd, *_ = _coefficients(cases[0.3])
    assert mu_crit == pytest.approx(_row(cases[0.3])["critical_friction_coefficient"], rel=1e-3)
    assert 0.9 * mu_crit < mu_sd < mu_crit
    mus = {"below": mu_sd - 0.5 * (mu_crit - mu_sd), "shakedown": 0.5 * (mu_sd + mu_crit)}
    return {k: run_case(load_case(None, {**FAST, "seafastening.friction_coefficient": mu})) for k, mu in mus.items()}


def test_just_below_shakedown_the_answer_is_the_reference(near):
    """Just below the shakedown coefficient no position holds the cargo: it slips a little in the normal
    force's dips every period and settles where the lashings balance the walk. The row (whichever solver
    answered it) is the reference's periodic state, not a locked state the truncated series balances in
    its harmonics while the friction it needs exceeds the friction available (before: 0.5-8 % above the
    reference's lashing force over this band, 3.7 % at its middle). The same for a row at a quarter, half and
    three quarters of the band; there the HBM alone may converge on a sliding state 6.6 % above the reference
    (its 100 harmonics cannot carry slips of 47 um), which the row's check against the reference catches."""
    res = near["below"]
    row, td = _row(res), _reference(res)
    assert row["axial_converged"] and td.converged and td.slip_m > 0.0
    assert row["axial_force_N"] == pytest.approx(td.axial_force_N, rel=0.01)
    message = str(res.axial.messages[1, 1])
    # the reference is named exactly when it answered: the HBM did not converge, or slid off the reference's answer
    assert ("time-domain reference" in message) == ("did not converge" in message or "off the time-domain reference" in message)
    mu_crit, mu_sd, *_ = _coefficients(res)
    normal = np.maximum(res.arrays.saddle_force_N[1, 1], 0.0)
    options = axial_options(res.case, normal.shape[0])
    base, load = axial_restraint(res.case), axial_load_of(res.case, res.vessel)
    for frac in (0.25, 0.5, 0.75):
        restraint = replace(base, friction_coefficient=np.full(base.saddle_count, mu_sd - frac * (mu_crit - mu_sd)))
        hbm = solve_axial_hbm(restraint, load, normal, options)
        ref = solve_axial_time_domain(restraint, load, normal, time_samples=options.time_samples)
        answer = solve_axial_row(restraint, load, normal, False, "hbm", options, normal.shape[0])
        assert answer.converged and answer.axial_force_N == pytest.approx(ref.axial_force_N, rel=0.01)
        if not hbm.converged:
            assert hbm.lock_check in (LockCheck.VIOLATED, LockCheck.NOT_LOCKED)


def test_between_shakedown_and_critical_the_cargo_locks_at_the_edge(near):
    """Between the shakedown and the critical coefficient the cargo cannot hold where it was set down but
    holds off it: it walks (like 1/n, ever more slowly) to the nearer edge of the positions where it holds,
    and the lashings then carry exactly the load the friction cannot, -min(F + mu N) (statics, computed
    here on the solvers' fine grid). The row and the reference both land there; the HBM within the load's
    curvature between its samples (about 3 N), the reference to its tolerance (the old stopping rule
    stopped the walk 1-7 % short)."""
    res = near["shakedown"]
    mu = float(res.case.seafastening.friction_coefficient)
    _, _, force, total, load = _coefficients(res, oversample=16)
    low, high = np.max(force - mu * total), np.min(force + mu * total)
    assert low <= high and not low <= 0.0 <= high  # a lock range, off u = 0
    edge = -high if high < 0.0 else low
    row, td = _row(res), _reference(res)
    assert row["axial_converged"] and td.converged and row["slip_m"] == 0.0 and td.slip_m == 0.0
    assert td.axial_force_N == pytest.approx(abs(edge), rel=1e-6)
    n_aft = axial_time_samples(res.case.solver.axial_harmonics, total.size // 16)
    between = (np.pi / n_aft) ** 2 / 2 * sum(k * k * abs(f) for k, f in enumerate(load.force_N))  # F's curvature between samples
    assert row["axial_force_N"] == pytest.approx(abs(edge), abs=between + 1.0)
    assert abs(edge) > 100 * between  # the lashings carry something


def test_friction_carrying_the_load_is_warned(cases):
    """Stuck (mu = 0.3) the friction carries the whole axial load and the lashings nothing: the dynamic rows
    carry friction_carries_load, with what the lashings alone would do (the frictionless answer, which the
    mu = 0 run computes as its solution); the still-water rows carry no load and no warning; without friction
    there is nothing to warn about."""
    held, free = cases[0.3], cases[0.0]
    for model in ("linear", "nonlinear"):
        assert _row(held, model=model)["axial_warnings"] == "friction_carries_load"
        assert _row(held, "static", model)["axial_warnings"] == ""
        assert _row(free, model=model)["axial_warnings"] == ""
    ds = held.dataset
    assert list(ds["axial_warning"].values) == ["friction_carries_load"]
    assert int(ds["axial_warning_flag"].sel(load_case="dynamic", model="nonlinear", axial_warning="friction_carries_load")) == 1
    alone = float(ds["frictionless_axial_force_N"].sel(load_case="dynamic", model="nonlinear"))
    # two routes to one linear oscillator's peak, each read on its own time grid: a sampled sinusoid's maximum is
    # within (pi / N)^2 / 2 (3e-6 at N = 1300) of the true one, whatever the phase
    assert alone == pytest.approx(_row(free)["axial_force_N"], rel=1e-5)
    moves = float(ds["frictionless_axial_displacement_m"].sel(load_case="dynamic", model="nonlinear"))
    assert moves == pytest.approx(
        np.max(np.abs(free.dataset["axial_displacement_m"].sel(load_case="dynamic", model="nonlinear").values)), rel=1e-5
    )
    lines = held.axial.warning_lines()
    assert len(lines) == 2 and not free.axial.warning_lines()
    assert all(line.startswith("dynamic ") and f"carry {alone / 1e3:.1f} kN" in line and f"move {moves:.3g} m" in line for line in lines)


def test_stoppers_carrying_the_load_are_not_warned():
    """Sliding into close stiff stoppers (mu = 0.02, gap 10 mm): the stoppers carry more than the friction."""
    res = run_case(
        load_case(
            None,
            {
                **FAST,
                "seafastening.friction_coefficient": 0.02,
                "seafastening.stopper.gap_m": 0.01,
                "seafastening.stopper.stiffness_N_per_m": 1e8,
            },
        )
    )
    row = _row(res)
    friction = float(np.max(np.abs(res.dataset["friction_force_N"].sel(load_case="dynamic", model="nonlinear"))))
    assert row["axial_converged"] and row["axial_force_N"] > friction
    assert row["axial_warnings"] == ""


def test_zero_coefficient_is_the_lashings_linear_answer(cases):
    res = cases[0.0]
    restraint, load = axial_restraint(res.case), axial_load_of(res.case, res.vessel)
    x = load.force_N[1] / (restraint.lashing_axial_stiffness_N_per_m - restraint.cargo_mass_kg * load.omega_rad_s**2)
    n = res.arrays.period_fraction.size
    u = np.real(x * np.exp(2j * np.pi * np.arange(n) / n))
    got = res.dataset["axial_displacement_m"].sel(load_case="dynamic", model="nonlinear").values
    np.testing.assert_allclose(got, u, atol=1e-6 * abs(x))
    assert _row(res)["axial_force_N"] == pytest.approx(restraint.lashing_axial_stiffness_N_per_m * np.max(np.abs(u)), rel=1e-6)
    assert "a linear oscillator, solved exactly" in str(res.axial.messages[1, 1])  # no reference integrating the decay


def test_one_way_coupling_friction_moment_is_small(cases):
    """Friction at the contact line (D/2 below the axis) puts a moment on the cargo; re-solving the
    vertical HBM with it changes the peak saddle force by < 2 % (docs/axial.md, one-way coupling)."""
    res = cases[0.3]
    model, exc = res.model, res.excitation
    estimate = float(res.axial.rows["friction_moment_saddle_force_change_N"][1, 1])
    per_saddle = res.dataset["friction_force_per_saddle_N"].sel(load_case="dynamic", model="nonlinear").values  # (N, n_s)
    lever = 0.5 * model.cargo.element_outer_diameter_m[0]
    H = int(res.rows.nonlinear_dynamic.options["harmonics"])  # the harmonics the vertical solve used
    moments = np.fft.rfft(per_saddle * lever, axis=0)[: H + 1] / per_saddle.shape[0]
    moments[1:] *= 2.0
    padded = exc.padded(H + 1)
    load = padded.cargo_load_N.copy()
    load[:, model.saddle_cargo_dof + 1] += moments
    # the same harmonics as the uncoupled solve, so that the two compare sample by sample
    nd = res.rows.nonlinear_dynamic
    same = res.case.model_copy(update={"solver": res.case.solver.model_copy(update={"harmonics": H, "time_samples": nd.time_samples})})
    coupled = solve_nonlinear(model, replace(padded, cargo_load_N=load), same, static=False)
    # the peaks (the moment shifts the ringing after a re-contact by a few samples: compare peaks, not samples)
    change = np.max(np.abs(coupled.saddle_force_time_N.max(axis=0) - nd.saddle_force_time_N.max(axis=0)))
    peak = _row(res)["F_N"]
    assert coupled.converged
    # 1.5 % measured with the ringing resolved (the moment shifts it); the quasi-static estimate says 0.5 %
    assert change < 0.02 * peak and estimate < 0.01 * peak
    assert 0.3 < change / estimate < 3.0  # the estimate has the right size


def test_results_netcdf_and_summary_csv(cases, tmp_path, capsys):
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
    # sliding, the friction (up to 0.02 x 12.9 MN) still carries more than the lashings (60 kN): warned on stderr
    assert rows[3]["axial_warnings"] == "friction_carries_load" and rows[0]["axial_warnings"] == ""
    err = capsys.readouterr().err
    assert "seafast: warning: dynamic nonlinear: friction_carries_load" in err and "alone would" in err
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
    from seafast.parallel.executor import ExecutionOptions
    from seafast.studies.runner import run_study
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
