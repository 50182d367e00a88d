"""The command line as a user meets it: outputs, exit codes, and no tracebacks on bad input."""

from __future__ import annotations

import csv
import math

import pytest
import yaml
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from seafast.cli import main

FAST = ["--set", "vessel.motions=none", "--no-plots", "-q"]


def _summary(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def test_run_base_case_writes_interface_outputs(tmp_path):
    out = tmp_path / "run"
    assert main(["run", "-o", str(out), "--set", "vessel.motions=none"]) == 0
    rows = _summary(out / "summary.csv")
    with open(out / "summary.csv") as f:
        header = f.readline().strip()
    assert header == "load_case,model,u_c_m,u_s_m,u_d_m,F_N,M_b_Nm,sigma_b_Pa,converged"
    assert [(r["load_case"], r["model"]) for r in rows] == [
        ("static", "linear"),
        ("static", "nonlinear"),
        ("dynamic", "linear"),
        ("dynamic", "nonlinear"),
    ]
    for r in rows:
        assert r["converged"] == "true"
        if r["model"] == "linear":
            assert float(r["u_d_m"]) == 0.0
    for name in (
        "results.nc",
        "case.yaml",
        "deflection.png",
        "forces_moments.png",
        "saddle_time_histories.png",
        "saddle_surfaces.png",
        "aft_most_loaded_saddle.png",
        "hull_girder.png",
    ):
        assert (out / name).stat().st_size > 1000, name


def test_calibration_static_linear_base_case(tmp_path):
    """docs/theory.md (calibration): static, still-water, linear base case."""
    out = tmp_path / "cal"
    assert main(["run", "-o", str(out), *FAST]) == 0
    row = _summary(out / "summary.csv")[0]
    assert row["load_case"] == "static" and row["model"] == "linear"
    assert float(row["F_N"]) == pytest.approx(6.3e6, rel=0.05)
    assert float(row["u_s_m"]) == pytest.approx(5.7e-3, rel=0.05)
    assert float(row["M_b_Nm"]) == pytest.approx(49.3e6, rel=0.05)
    # u_c depends on the reference frame (docs/limitations.md#5-calibration-against-the-source):
    # the sea-fastening baseline gives 5.33 mm vs the source's 5.9 mm
    assert float(row["u_c_m"]) == pytest.approx(5.33e-3, rel=0.02)
    # sigma_b = M_b (D/2) / I with I = 15.6 m^4
    I_m4 = math.pi / 64 * (8**4 - (8 - 0.16) ** 4)
    assert float(row["sigma_b_Pa"]) == pytest.approx(float(row["M_b_Nm"]) * 4.0 / I_m4, rel=1e-3)


def test_init_writes_a_case_that_runs(tmp_path, capsys):
    case = tmp_path / "my_case.yaml"
    assert main(["init", str(case)]) == 0
    text = case.read_text()
    assert "# " in text and "saddle_stiffness_N_per_m" in text
    assert main(["init", str(case)]) == 2  # refuses to overwrite
    assert "exists" in capsys.readouterr().err
    assert main(["run", str(case), "-o", str(tmp_path / "o"), *FAST]) == 0


def test_schema_is_json(capsys):
    import json

    assert main(["schema"]) == 0
    schema = json.loads(capsys.readouterr().out)
    assert "cargo" in schema["properties"]


@pytest.mark.parametrize(
    "override, expect",
    [
        ("cargo.wall_thickness_m=4.5", "wall_thickness_m"),
        ("cargo.lenght_m=80", "unknown key"),
        ("cargo.length_m=-3", "cargo.length_m"),
        ("cargo.length_m=.nan", "cargo.length_m"),
        ("seafastening.saddle_positions_m=[10, 10]", "coincident"),
        ("seafastening.saddle_positions_m=[10, 90]", "outside the cargo"),
        ("seafastening.saddle_positions_m=[37]", "mechanism"),
        ("solver.contact_law=hertz", "solver.contact_law"),
        ("vessel.deck_deflection_table=/nonexistent.csv", "deck_deflection_table"),
        ("vessel.motions=/nonexistent.nc", "vessel.motions"),
        # a wave past the breaking limit (H / lambda > 1/7), e.g. millimetres typed for metres
        ("wave.amplitude_m=20", "wave: amplitude_m = 20.0 at length_m = 171.0"),
        ("wave.amplitude_m=100", "past the breaking limit 1/7"),
        ("wave.amplitude_m=3000", "allowed amplitude_m <= 12.2 m"),
    ],
)
def test_invalid_input_gives_exit_2_and_one_clear_message(tmp_path, capsys, override, expect):
    code = main(["run", "-o", str(tmp_path / "x"), "--set", override, "--no-plots", "-q"])
    err = capsys.readouterr().err
    assert code == 2
    assert expect in err
    assert "Traceback" not in err


def test_missing_and_malformed_case_files(tmp_path, capsys):
    assert main(["run", str(tmp_path / "nope.yaml"), *FAST]) == 2
    assert "cannot read" in capsys.readouterr().err
    bad = tmp_path / "bad.yaml"
    bad.write_text("cargo: [1, 2\n")
    assert main(["run", str(bad), *FAST]) == 2
    assert "not valid YAML" in capsys.readouterr().err


_keys = st.sampled_from(
    [
        "cargo.length_m",
        "cargo.diameter_m",
        "cargo.wall_thickness_m",
        "cargo.position_m",
        "seafastening.saddle_count",
        "seafastening.saddle_positions_m",
        "seafastening.saddle_stiffness_N_per_m",
        "seafastening.lashing.stiffness_N_per_m",
        "seafastening.lashing.pretension_N",
        "wave.length_m",
        "wave.amplitude_m",
        "solver.harmonics",
        "solver.time_samples",
        "solver.contact_law",
        "model.element_length_m",
        "cargo",
        "solver",
        "nonsense.key",
        "cargo.sections",
    ]
)
_values = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True),
    st.integers(-5, 200),
    st.text(max_size=8),
    st.lists(st.floats(-10, 120), max_size=4),
    st.none(),
    st.booleans(),
)


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(st.lists(st.tuples(_keys, _values), min_size=1, max_size=3))
def test_cli_never_tracebacks_on_random_overrides(tmp_path, capsys, pairs):
    args = ["run", "-o", str(tmp_path / "h"), *FAST]
    for k, v in pairs:
        args += ["--set", f"{k}={yaml.safe_dump(v, default_flow_style=True).strip().removesuffix('...').strip()}"]
    code = main(args)
    err = capsys.readouterr().err
    assert code in (0, 2, 3), (code, err)
    assert "Traceback" not in err
    if code == 2:
        assert err.startswith("seafast: error:")


def test_sweep_writes_the_frequency_response(tmp_path):
    out = tmp_path / "sweep"
    code = main(["sweep", "-o", str(out), "--omega-min", "0.4", "--omega-max", "0.8", "--set", "vessel.motions=none"])
    assert code == 0
    rows = _summary(out / "frequency_response.csv")
    omega = [float(r["omega_rad_s"]) for r in rows]
    assert omega[0] == pytest.approx(0.4) and omega[-1] == pytest.approx(0.8)
    # the 1 % cap on the step in omega, not a step control stalled by a noisy tangent (2000 points then)
    assert len(rows) <= 110
    assert all(r["converged"] == "true" for r in rows)
    # far below the first natural frequency (44 rad/s) the response is quasi-static: flat in omega
    forces = [float(r["max_saddle_force_N"]) for r in rows]
    assert max(forces) / min(forces) == pytest.approx(1.0, abs=0.01)
    assert (out / "frequency_response.png").stat().st_size > 1000


def test_sweep_rejects_a_bad_frequency_range(capsys):
    assert main(["sweep", "--omega-min", "2", "--omega-max", "1"]) == 2
    assert "omega-min" in capsys.readouterr().err


def test_scripting_entry_points():
    import seafast

    result = seafast.run_case(seafast.load_case(overrides={"vessel.motions": "none"}))
    assert result.summary[0]["F_N"] == pytest.approx(6.3e6, rel=0.05)
    with pytest.raises(AttributeError):
        seafast.no_such_thing  # noqa: B018 - the attribute access is what must raise


def test_sweep_says_it_cannot_couple(capsys):
    code = main(["sweep", "--set", "vessel.coupling=two_way", "--set", "vessel.motions=none"])
    assert code == 2
    assert "vessel.coupling" in capsys.readouterr().err


def test_a_nonlinear_solve_that_does_not_converge_exits_3_and_says_how_it_ended(tmp_path, capsys, monkeypatch):
    """The warning is built from the typed outcome and residual, not from the solver's message."""
    import seafast.solvers.from_case as from_case
    from seafast.solvers.shooting import ShootingOptions

    original = from_case.hbm_options
    monkeypatch.setattr(from_case, "hbm_options", lambda case, **k: original(case, **{"max_iterations": 1, "continuation": False, **k}))
    # the default's shooting cannot meet a tolerance below round-off; its fallback, the adaptive HBM, has one Newton step
    monkeypatch.setattr(from_case, "shooting_options", lambda case: ShootingOptions(tolerance=1e-300, max_iterations=1))
    assert main(["run", "-o", str(tmp_path / "run"), *FAST]) == 3
    err = capsys.readouterr().err
    assert "dynamic nonlinear solution did NOT converge (not converged, residual" in err
    with open(tmp_path / "run" / "summary.csv", newline="") as f:
        rows = {(r["load_case"], r["model"]): r["converged"] for r in csv.DictReader(f)}
    assert rows[("dynamic", "nonlinear")] == "false" and rows[("dynamic", "linear")] == "true"


def test_a_coupling_that_does_not_converge_is_named_in_the_warning(tmp_path, capsys, monkeypatch):
    """The warning is built from the coupling's typed outcome, not from a message."""
    import seafast.coupling.case as coupling

    original = coupling.couple_deck
    monkeypatch.setattr(coupling, "couple_deck", lambda *a, **k: original(*a, **{**k, "max_iterations": 0}))
    assert main(["run", "-o", str(tmp_path / "run"), *FAST, "--set", "vessel.coupling=two_way"]) == 3
    err = capsys.readouterr().err
    assert err.count("solution did NOT converge (two-way") == 4 and "residual" in err


@pytest.mark.parametrize(
    "argv, progress, debug, table",
    [
        ([], True, False, True),
        (["-v"], True, True, True),
        (["-q"], False, False, False),
        (["--quiet"], False, False, False),
    ],
)
def test_global_verbosity(tmp_path, capsys, argv, progress, debug, table):
    """Progress by default, debug lines (solver path) with -v, nothing but warnings with -q."""
    assert main([*argv, "run", "-o", str(tmp_path / "run"), *FAST[:-1]]) == 0
    out, err = capsys.readouterr()
    assert ("running 'base-case'" in err) is progress
    assert ("seafast: debug: seafast.solvers.hbm.nonlinear: direct solve" in err) is debug
    assert ("maxima over the cargo" in out) is table
    if not progress:
        assert err == ""


def test_run_quiet_still_works_and_verbose_and_quiet_exclude_each_other(tmp_path, capsys):
    assert main(["run", "-o", str(tmp_path / "run"), *FAST]) == 0
    assert capsys.readouterr() == ("", "")
    with pytest.raises(SystemExit) as info:
        main(["-v", "-q", "run"])
    assert info.value.code == 2
    assert "not allowed with argument" in capsys.readouterr().err


def test_the_library_prints_nothing_unless_logging_is_configured(tmp_path):
    """A solver warning (quasi-statics questionable) reaches a configured logger, never stderr by itself."""
    import subprocess
    import sys

    script = (
        "import logging, sys\n"
        "sys.path.insert(0, 'tests/solvers')\n"
        "from solver_cases import base_model, wave_excitation\n"
        "from seafast.solvers.references import solve_quasi_static\n"
        "model = base_model()\n"
        "ex = wave_excitation(model, relative_mm=16.0, second_harmonic_mm=0.0)\n"
        "r = solve_quasi_static(model, ex)\n"
        "assert r.warnings, r.message\n"
        "if len(sys.argv) > 1:\n"
        "    logging.basicConfig(level=logging.WARNING)\n"
        "    solve_quasi_static(model, ex)\n"
    )
    root = __import__("pathlib").Path(__file__).resolve().parents[2]
    silent = subprocess.run([sys.executable, "-c", script], cwd=root, capture_output=True, text=True, check=True)
    assert silent.stdout == "" and silent.stderr == ""
    logged = subprocess.run([sys.executable, "-c", script, "log"], cwd=root, capture_output=True, text=True, check=True)
    assert "WARNING:seafast.solvers.references.quasi_static:quasi-static reference: quasi-statics questionable" in logged.stderr


@pytest.mark.parametrize("text", ["", "\n\n", "# my case, to be written\n# cargo: {length_m: 90}\n", "---\n"])
def test_an_empty_case_file_is_refused_and_init_suggested(tmp_path, capsys, text):
    """An empty file (or only comments) used to run the base case without a word."""
    empty = tmp_path / "case.yaml"
    empty.write_text(text)
    assert main(["run", str(empty), "-o", str(tmp_path / "out"), *FAST]) == 2
    err = capsys.readouterr().err
    assert err.startswith("seafast: error: case file") and str(empty) in err and "is empty" in err
    assert f"seafast init {empty} --force" in err and len(err.strip().splitlines()) == 1
    assert not (tmp_path / "out").exists()


def test_an_explicitly_empty_mapping_runs_every_default(tmp_path):
    case = tmp_path / "defaults.yaml"
    case.write_text("{}  # every default, on purpose\n")
    assert main(["run", str(case), "-o", str(tmp_path / "out"), *FAST]) == 0
    assert _summary(tmp_path / "out" / "summary.csv")[0]["F_N"] == _summary_of_base(tmp_path)


def _summary_of_base(tmp_path):
    assert main(["run", "-o", str(tmp_path / "base"), *FAST]) == 0
    return _summary(tmp_path / "base" / "summary.csv")[0]["F_N"]


def test_run_prints_its_table_before_it_writes_the_files(tmp_path, capsys, monkeypatch):
    """The summary table is on stdout as soon as the rows are known; results.nc and the figures come after."""
    import seafast.output.files as files

    real, printed_before = files.write_run_outputs, []

    def spy(result, out_dir, **kwargs):
        printed_before.append(capsys.readouterr())
        return real(result, out_dir, **kwargs)

    monkeypatch.setattr(files, "write_run_outputs", spy)
    assert main(["run", "-o", str(tmp_path / "run"), "--set", "vessel.motions=none", "--no-plots"]) == 0
    out = capsys.readouterr().out
    before, progress = printed_before[0]
    assert "maxima over the cargo" in before and "excitation: " in before
    assert "wrote" not in before and out.startswith("wrote ")
    assert progress.rstrip().endswith("writing the results to " + str(tmp_path / "run"))


def test_seastate_prints_its_table_before_it_writes_the_files(tmp_path, capsys, monkeypatch):
    import seafast.output.seastate as seastate_output

    real, printed_before = seastate_output.write_seastate_outputs, []

    def spy(*args, **kwargs):
        printed_before.append(capsys.readouterr().out)
        return real(*args, **kwargs)

    monkeypatch.setattr(seastate_output, "write_seastate_outputs", spy)
    assert main(["seastate", "-o", str(tmp_path / "sea"), "--no-monte-carlo", "--no-plots"]) == 0
    out = capsys.readouterr().out
    assert "most probable maxima" in printed_before[0] and "design_wave" in printed_before[0]
    assert "wrote" not in printed_before[0] and out.startswith("wrote ")


def test_run_with_a_figure_helper_forked_ahead_writes_the_same_figures(tmp_path, monkeypatch):
    """``seafast run`` with its helper forked before the solve (as on an idle core): the figures of a run drawn here alone."""
    import multiprocessing

    from seafast.output import case_figures

    monkeypatch.setattr(case_figures, "helper_count", lambda items: 0)
    assert main(["run", "-o", str(tmp_path / "alone"), "--set", "vessel.motions=none", "-q"]) == 0
    monkeypatch.setattr(case_figures, "helper_count", lambda items: 1)
    assert main(["run", "-o", str(tmp_path / "helped"), "--set", "vessel.motions=none", "-q"]) == 0
    assert multiprocessing.active_children() == []  # the helper ended
    pngs = sorted(p.name for p in (tmp_path / "alone").glob("*.png"))
    assert len(pngs) == 6 and pngs == sorted(p.name for p in (tmp_path / "helped").glob("*.png"))
    for name in pngs:
        assert (tmp_path / "helped" / name).read_bytes() == (tmp_path / "alone" / name).read_bytes(), name
