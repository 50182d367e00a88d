"""Study files: validation messages, built-in studies, grid construction."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from seafast.cli.study import main as study_main
from seafast.config import CaseError
from seafast.studies.spec import (
    BUILTIN_STUDIES,
    StudyError,
    build_grid,
    case_key_kind,
    evaluate_expression,
    load_study_spec,
    study_spec_from_mapping,
)

AXIS = {"key": "cargo.length_m", "values": [80.0, 90.0]}


def _spec(**changes):
    data = {"name": "t", "axes": [AXIS]}
    data.update(changes)
    return study_spec_from_mapping(data, "(test)")


def test_builtin_studies_load_with_the_source_grids():
    shapes = {}
    for name in BUILTIN_STUDIES:
        spec, directory = load_study_spec(name)
        assert spec.name == name
        shapes[name] = build_grid(spec, directory).shape
    assert shapes == {
        "saddles": (6, 20),
        "lashing": (20, 20),
        "cargo": (20, 20),
        "cargo-saddles-8m": (6, 20),
        "cargo-saddles-12m": (6, 20),
    }


def test_log_axis_is_geometric_and_includes_both_ends():
    grid = build_grid(*load_study_spec("saddles"))
    k = grid.coordinates[1]
    assert k[0] == pytest.approx(0.01 * 1.1e9) and k[-1] == pytest.approx(10.0 * 1.1e9)
    ratios = k[1:] / k[:-1]
    assert np.allclose(ratios, ratios[0])
    assert grid.coordinates[0].dtype.kind == "i" and grid.coordinates[0].tolist() == [2, 3, 4, 5, 6, 7]


def test_linear_axis_and_derived_wall_thickness():
    grid = build_grid(*load_study_spec("cargo"))
    assert np.allclose(np.diff(grid.coordinates[0]), 40.0 / 19)
    for index in (0, 57, grid.size - 1):
        case = grid.point_case(index)
        values = grid.point_values(index)
        assert case.cargo.length_m == values["cargo.length_m"]
        assert case.cargo.diameter_m == values["cargo.diameter_m"]
        assert case.cargo.wall_thickness_m == pytest.approx(case.cargo.diameter_m / 110)
        assert case.cargo.units_abreast == min(4, int(case.vessel.breadth_m // case.cargo.diameter_m))
    assert grid.point_case(grid.size - 1).cargo.units_abreast == 3  # D = 12 m


def test_cargo_saddle_studies_fix_the_heaviest_cargo():
    for name, diameter in (("cargo-saddles-8m", 8.0), ("cargo-saddles-12m", 12.0)):
        grid = build_grid(*load_study_spec(name))
        case = grid.point_case(grid.size - 1)
        assert (case.cargo.length_m, case.cargo.diameter_m) == (115.0, diameter)
        assert case.cargo.wall_thickness_m == pytest.approx(diameter / 110)
        assert case.seafastening.saddle_count == 7
        assert case.seafastening.saddle_stiffness_N_per_m == pytest.approx(1.1e10)


def test_command_line_overrides_apply_to_the_base_and_change_the_fingerprint():
    spec, directory = load_study_spec("saddles")
    plain = build_grid(spec, directory)
    changed = build_grid(spec, directory, {"wave.amplitude_m": 2.0})
    assert changed.point_case(0).wave.amplitude_m == 2.0
    assert plain.fingerprint() != changed.fingerprint()
    assert plain.fingerprint() == build_grid(spec, directory).fingerprint()


def test_case_key_kinds():
    assert case_key_kind("seafastening.saddle_count") == "int"
    assert case_key_kind("seafastening.lashing.pretension_N") == "float"
    assert case_key_kind("cargo.position_m") == "float"


@pytest.mark.parametrize(
    "changes, expected",
    [
        ({"axes": [{"key": "cargo.lenght_m", "values": [1.0]}]}, ["cargo.lenght_m", "allowed", "length_m"]),
        ({"axes": [{"key": "cargo", "values": [1.0]}]}, ["group of keys", "cargo.length_m"]),
        ({"axes": [{"key": "solver.method", "values": [1.0]}]}, ["solver.method", "not numeric"]),
        ({"axes": [{"key": "cargo.length_m", "values": [1.0], "start": 1.0}]}, ["either values", "start/stop/num"]),
        ({"axes": [{"key": "cargo.length_m", "start": 1.0, "stop": 2.0}]}, ["missing num"]),
        ({"axes": [{"key": "cargo.length_m", "start": 0.0, "stop": 2.0, "num": 3, "scale": "log"}]}, ["positive", "log"]),
        ({"axes": [{"key": "cargo.length_m", "start": 1.0, "stop": 2.0, "num": 3, "scale": "ln"}]}, ["scale", "'ln'", "linear", "log"]),
        ({"axes": [AXIS, AXIS]}, ["more than once"]),
        ({"axes": []}, ["at least one axis"]),
        ({"axis": [AXIS]}, ["axis", "unknown key", "allowed"]),
        ({"derived": {"cargo.wall_thickness_m": "cargo.diameter_m / 110 + __import__('os')"}}, ["allowed: numbers", "floor"]),
        ({"derived": {"cargo.wall_thickness_m": "print(cargo.diameter_m)"}}, ["calls 'print'", "allowed"]),
        ({"derived": {"cargo.wall_thickness_m": "cargo.diametre_m / 110"}}, ["cargo.diametre_m", "allowed"]),
        ({"derived": {"cargo.length_m": "cargo.diameter_m * 10"}}, ["both an axis and derived"]),
        ({"limits": {"max_saddle_force_N": -1}}, ["limits.max_saddle_force_N", "-1", "greater than 0"]),
        ({"name": "has space"}, ["name", "has space"]),
    ],
)
def test_invalid_study_messages_name_field_value_and_allowed(changes, expected):
    with pytest.raises(StudyError) as info:
        _spec(**changes)
    message = str(info.value)
    assert isinstance(info.value, CaseError)
    for fragment in expected:
        assert fragment in message, message


def test_integer_axis_rejects_fractions():
    spec = _spec(axes=[{"key": "seafastening.saddle_count", "values": [2, 2.5]}])
    with pytest.raises(StudyError, match="whole numbers"):
        build_grid(spec)


def test_expression_evaluation():
    values = {"cargo.diameter_m": 11.0, "cargo.length_m": 2.0}
    assert evaluate_expression("cargo.diameter_m / 110", values.__getitem__) == pytest.approx(0.1)
    assert evaluate_expression("-(cargo.length_m ** 2) + 1", values.__getitem__) == pytest.approx(-3.0)
    assert evaluate_expression("min(4, floor(42 / cargo.diameter_m))", values.__getitem__) == 3


def test_invalid_point_is_a_case_error_not_a_crash():
    spec = _spec(axes=[{"key": "cargo.wall_thickness_m", "values": [0.05, 5.0]}])
    grid = build_grid(spec)
    grid.point_case(0)
    with pytest.raises(CaseError, match="wall_thickness_m"):
        grid.point_case(1)


def test_cli_exit_code_2_with_one_clear_message(tmp_path: Path, capsys):
    bad = tmp_path / "bad.yaml"
    bad.write_text("name: bad\naxes:\n  - key: cargo.lenght_m\n    values: [1, 2]\n", encoding="utf-8")
    assert study_main([str(bad), "-o", str(tmp_path / "out"), "--no-progress"]) == 2
    err = capsys.readouterr().err
    assert "cargo.lenght_m" in err and "Traceback" not in err
    assert study_main(["no-such-study", "-o", str(tmp_path / "out")]) == 2
    assert "saddles, lashing, cargo" in capsys.readouterr().err
    assert study_main(["saddles", "--set", "cargo.length_m=-3", "-o", str(tmp_path / "out")]) == 2
    assert "cargo.length_m" in capsys.readouterr().err
    assert study_main(["saddles", "--workers", "0", "-o", str(tmp_path / "out")]) == 2
    not_yaml = tmp_path / "broken.yaml"
    not_yaml.write_text("name: [unclosed\n", encoding="utf-8")
    assert study_main([str(not_yaml)]) == 2
    assert "not valid YAML" in capsys.readouterr().err
