"""Case files: the base case, --set overrides, and a CaseError (naming field and value) for
every kind of invalid input; plus a property test that junk never escapes as another exception."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from pydantic import BaseModel

from seafast.config.loader import (
    CaseError,
    apply_overrides,
    base_case_text,
    case_from_mapping,
    case_json_schema,
    load_case,
    parse_overrides,
)
from seafast.config.schema import Case


# --------------------------------------------------------------------------- base case
def test_base_case_values() -> None:
    case = load_case()
    assert case.name == "base-case"
    assert case.cargo.length_m == 74.0 and case.cargo.diameter_m == 8.0 and case.cargo.wall_thickness_m == 0.08
    assert case.cargo.youngs_modulus_Pa == 210e9 and case.cargo.density_kg_per_m3 == 7850.0
    assert case.cargo.units_abreast == 4 and case.cargo.sections is None
    assert case.saddle_positions_m() == pytest.approx((14.8, 37.0, 59.2), rel=1e-14)
    assert case.saddle_stiffnesses_N_per_m() == (1.1e9, 1.1e9, 1.1e9)
    assert case.lashed_saddle_indices() == (0, 2)
    assert case.seafastening.lashing.stiffness_N_per_m == 37.5e3
    assert case.seafastening.lashing.pretension_N == 210e3
    assert case.wave_frequency_rad_s() == pytest.approx(0.6004, abs=5e-5)
    assert case.wave_frequency_rad_s() == pytest.approx(math.sqrt(2 * math.pi * 9.81 / 171.0), rel=1e-14)
    assert case.wave.amplitude_m == 3.0 and case.wave.length_m == 171.0
    assert case.vessel.length_m == 171.0 and case.vessel.hull_second_moment_m4 == 103.8
    assert case.cargo_position_m() == 85.5
    # exact contact and adaptive harmonics by default; the source's method is the 'source' preset
    assert case.solver.harmonics is None and case.solver.time_samples is None and case.solver.contact_law == "exact"
    source = load_case(overrides={"solver.preset": "source"}).solver
    assert (source.contact_law, source.regularisation_per_m, source.harmonics, source.time_samples, source.nonlinear_solver) == (
        "tanh",
        1000.0,
        5,
        128,
        "hybr",
    )
    # a preset fills only what the case leaves unset
    assert load_case(overrides={"solver.preset": "source", "solver.harmonics": 9}).solver.harmonics == 9
    assert case.solver.regularisation_per_m == 1000.0
    assert case.model.element_length_m == 1.0 and case.model.damping_ratio == 0.02
    # the built-in text equals the schema defaults (apart from the name, and the base case's
    # design sea state: the schema leaves Hs and Tp unset, a sea state is chosen consciously)
    assert case.model_dump(exclude={"name"}) == Case().model_dump(exclude={"name"}) | {"sea_state": case.sea_state.model_dump()}
    assert Case().sea_state.significant_height_m is None and Case().sea_state.peak_period_s is None
    assert case.sea_state.model_dump() == Case().sea_state.model_dump() | {"significant_height_m": 3.0, "peak_period_s": 10.0}
    assert "cargo:" in base_case_text()
    assert "properties" in case_json_schema()


def test_base_case_file_on_disk_equals_builtin(tmp_path: Path) -> None:
    p = tmp_path / "case.yaml"
    p.write_text(base_case_text(), encoding="utf-8")
    assert load_case(p) == load_case()


def test_arrangement_rule_and_derived_values() -> None:
    c = case_from_mapping({"seafastening": {"saddle_count": 5}, "cargo": {"length_m": 100.0}})
    assert c.saddle_positions_m() == pytest.approx((20.0, 35.0, 50.0, 65.0, 80.0))
    assert c.lashed_saddle_indices() == (0, 4)
    one = case_from_mapping({"seafastening": {"saddle_count": 1}})
    assert one.saddle_positions_m() == (37.0,) and one.lashed_saddle_indices() == (0,)
    c = case_from_mapping(
        {
            "seafastening": {
                "saddle_positions_m": [10, 30, 50, 70],
                "saddle_stiffness_N_per_m": [1e9, 2e9, 3e9, 4e9],
                "lashed_saddles": [3, 1, 1],
            }
        }
    )
    assert c.saddle_positions_m() == (10.0, 30.0, 50.0, 70.0)
    assert c.saddle_stiffnesses_N_per_m() == (1e9, 2e9, 3e9, 4e9)
    assert c.lashed_saddle_indices() == (1, 3)
    c = case_from_mapping({"seafastening": {"saddle_stiffness_N_per_m": [5e8]}})
    assert c.saddle_stiffnesses_N_per_m() == (5e8, 5e8, 5e8)
    assert case_from_mapping({"wave": {"frequency_rad_s": 0.5}}).wave_frequency_rad_s() == 0.5
    assert case_from_mapping(None) == Case()


# --------------------------------------------------------------------------- overrides
def test_parse_overrides_yaml_typed_values() -> None:
    o = parse_overrides(
        [
            "cargo.length_m=90",
            "wave.amplitude_m=2.5",
            "seafastening.saddle_positions_m=[10, 40.5, 70]",
            "cargo.position_m=null",
            "name=my case",
            "outputs.plots=false",
            "model.damping_ratio= 0.05 ",
            "vessel.motions=",
            "solver.tolerance=1e-8",
        ]
    )
    assert o["cargo.length_m"] == 90 and isinstance(o["cargo.length_m"], int)
    assert o["wave.amplitude_m"] == 2.5
    assert o["seafastening.saddle_positions_m"] == [10, 40.5, 70]
    assert o["cargo.position_m"] is None
    assert o["name"] == "my case"
    assert o["outputs.plots"] is False
    assert o["model.damping_ratio"] == 0.05
    assert o["vessel.motions"] is None
    # YAML 1.1 reads "1e-8" (no dot) as a string; the schema must still accept it as a number
    assert o["solver.tolerance"] == "1e-8"
    assert load_case(overrides={"solver.tolerance": o["solver.tolerance"]}).solver.tolerance == pytest.approx(1e-8, rel=1e-15)
    assert (
        load_case(overrides=parse_overrides(["seafastening.saddle_stiffness_N_per_m=1.1e9"])).saddle_stiffnesses_N_per_m() == (1.1e9,) * 3
    )


def test_overrides_apply_nested_dotted_keys() -> None:
    o = parse_overrides(
        ["cargo.length_m=90", "seafastening.lashing.pretension_N=1.0e+5", "seafastening.saddle_count=4", "solver.contact_law=softplus"]
    )
    case = load_case(overrides=o)
    assert case.cargo.length_m == 90.0
    assert case.seafastening.lashing.pretension_N == 1e5
    assert case.seafastening.lashing.stiffness_N_per_m == 37.5e3  # sibling untouched
    assert case.saddle_positions_m() == pytest.approx((18.0, 36.0, 54.0, 72.0))
    assert case.solver.contact_law == "softplus"
    assert case.cargo.diameter_m == 8.0
    # creating groups that the file does not list
    case = case_from_mapping({}, overrides={"model.element_length_m": 0.5})
    assert case.model.element_length_m == 0.5
    # the input mapping is not modified
    data: dict[str, Any] = {"cargo": {"length_m": 80.0}}
    out = apply_overrides(data, {"cargo.length_m": 60.0})
    assert data == {"cargo": {"length_m": 80.0}} and out["cargo"]["length_m"] == 60.0


def test_override_of_a_file_case(tmp_path: Path) -> None:
    p = tmp_path / "c.yaml"
    p.write_text("cargo:\n  length_m: 100\nwave:\n  amplitude_m: 1\n", encoding="utf-8")
    case = load_case(p, overrides=parse_overrides(["wave.amplitude_m=4"]))
    assert case.cargo.length_m == 100.0 and case.wave.amplitude_m == 4.0


@pytest.mark.parametrize(
    "items, must_contain",
    [
        (["cargo.length_m"], ["cargo.length_m", "KEY=VALUE"]),
        (["cargo.length_m=[1, 2"], ["cargo.length_m", "not valid YAML"]),
    ],
)
def test_parse_overrides_errors(items: list[str], must_contain: list[str]) -> None:
    with pytest.raises(CaseError) as exc:
        parse_overrides(items)
    for s in must_contain:
        assert s in str(exc.value)


@pytest.mark.parametrize(
    "overrides, must_contain",
    [
        ({"cargo..length_m": 1}, ["cargo..length_m", "empty key part"]),
        ({"": 1}, ["empty key part"]),
        ({"cargo.length_m.x": 1}, ["cargo.length_m.x", "'length_m' is a value"]),
        ({"cargo.lenght_m": 1}, ["cargo.lenght_m", "unknown key"]),
        ({"cargo.length_m": -5}, ["cargo.length_m = -5", "greater than 0"]),
    ],
)
def test_bad_overrides(overrides: dict[str, Any], must_contain: list[str]) -> None:
    with pytest.raises(CaseError) as exc:
        load_case(overrides=overrides)
    for s in must_contain:
        assert s in str(exc.value), str(exc.value)


# --------------------------------------------------------------------------- invalid inputs
SECTION_A = {"x_start_m": 0.0, "x_end_m": 30.0, "diameter_start_m": 8.0, "diameter_end_m": 8.0, "wall_thickness_m": 0.08}


def _sec(**kw: Any) -> dict[str, Any]:
    return {**SECTION_A, **kw}


INVALID = [
    ("unknown-top", {"cargoo": {}}, ["cargoo", "unknown key"]),
    ("unknown-nested", {"cargo": {"lenght_m": 74}}, ["cargo.lenght_m", "unknown key"]),
    ("unknown-deep", {"seafastening": {"lashing": {"pretention_N": 1}}}, ["seafastening.lashing.pretention_N", "unknown key"]),
    ("zero", {"cargo": {"length_m": 0}}, ["cargo.length_m = 0", "greater than 0"]),
    ("negative", {"cargo": {"diameter_m": -8.0}}, ["cargo.diameter_m = -8.0", "greater than 0"]),
    ("nan", {"wave": {"amplitude_m": float("nan")}}, ["wave.amplitude_m = nan", "finite"]),
    ("inf", {"cargo": {"youngs_modulus_Pa": float("inf")}}, ["cargo.youngs_modulus_Pa = inf", "finite"]),
    ("neg-inf", {"seafastening": {"lashing": {"pretension_N": float("-inf")}}}, ["seafastening.lashing.pretension_N = -inf"]),
    (
        "neg-pretension",
        {"seafastening": {"lashing": {"pretension_N": -1.0}}},
        ["seafastening.lashing.pretension_N = -1.0", "greater than or equal to 0"],
    ),
    ("zero-stiffness", {"seafastening": {"saddle_stiffness_N_per_m": 0}}, ["seafastening.saddle_stiffness_N_per_m", "0"]),
    ("nan-position", {"seafastening": {"saddle_positions_m": [10.0, float("nan")]}}, ["seafastening.saddle_positions_m[1] = nan"]),
    ("string-number", {"cargo": {"length_m": "long"}}, ["cargo.length_m = 'long'", "valid number"]),
    ("string-int", {"solver": {"harmonics": "five"}}, ["solver.harmonics = 'five'", "valid integer"]),
    ("fractional-int", {"seafastening": {"saddle_count": 2.5}}, ["seafastening.saddle_count = 2.5", "integer"]),
    ("zero-saddles", {"seafastening": {"saddle_count": 0}}, ["seafastening.saddle_count = 0"]),
    (
        "saddle-at-end",
        {"seafastening": {"saddle_positions_m": [0.0, 37.0, 59.2]}},
        ["seafastening.saddle_positions_m[0] = 0.0", "outside the cargo", "74.0"],
    ),
    (
        "saddle-beyond",
        {"seafastening": {"saddle_positions_m": [14.8, 37.0, 80.0]}},
        ["seafastening.saddle_positions_m[2] = 80.0", "outside the cargo"],
    ),
    (
        "saddle-beyond-new-length",
        {"cargo": {"length_m": 50.0}, "seafastening": {"saddle_positions_m": [14.8, 37.0, 59.2]}},
        ["saddle_positions_m[2] = 59.2", "50.0"],
    ),
    (
        "coincident",
        {"seafastening": {"saddle_positions_m": [14.8, 14.8, 59.2]}},
        ["seafastening.saddle_positions_m", "[14.8, 14.8, 59.2]", "strictly increasing"],
    ),
    (
        "unsorted",
        {"seafastening": {"saddle_positions_m": [37.0, 14.8, 59.2]}},
        ["seafastening.saddle_positions_m", "[37.0, 14.8, 59.2]", "strictly increasing"],
    ),
    ("empty-positions", {"seafastening": {"saddle_positions_m": []}}, ["seafastening.saddle_positions_m", "at least one"]),
    ("wall-half-D", {"cargo": {"wall_thickness_m": 4.0}}, ["wall_thickness_m = 4.0", "diameter_m / 2 = 4.0"]),
    ("wall-over-half-D", {"cargo": {"diameter_m": 1.0, "wall_thickness_m": 0.6}}, ["wall_thickness_m = 0.6", "0.5"]),
    (
        "section-wall",
        {"cargo": {"sections": [_sec(x_end_m=74.0, diameter_end_m=0.1)]}},
        ["cargo.sections[0]", "wall_thickness_m = 0.08", "0.05"],
    ),
    (
        "section-gap",
        {"cargo": {"sections": [SECTION_A, _sec(x_start_m=31.0, x_end_m=74.0)]}},
        ["sections[1].x_start_m = 31.0", "30.0", "contiguous"],
    ),
    (
        "section-overlap",
        {"cargo": {"sections": [SECTION_A, _sec(x_start_m=29.0, x_end_m=74.0)]}},
        ["sections[1].x_start_m = 29.0", "contiguous"],
    ),
    ("section-not-from-0", {"cargo": {"sections": [_sec(x_start_m=1.0, x_end_m=74.0)]}}, ["sections[0].x_start_m = 1.0", "contiguous"]),
    ("section-short", {"cargo": {"sections": [SECTION_A]}}, ["30.0", "length_m = 74.0"]),
    (
        "section-reversed",
        {"cargo": {"sections": [_sec(x_start_m=30.0, x_end_m=10.0)]}},
        ["cargo.sections[0]", "x_end_m = 10.0", "x_start_m = 30.0"],
    ),
    ("sections-empty", {"cargo": {"sections": []}}, ["sections", "at least one"]),
    (
        "stiffness-count",
        {"seafastening": {"saddle_stiffness_N_per_m": [1e9, 1e9]}},
        ["seafastening.saddle_stiffness_N_per_m", "2 values for 3 saddles"],
    ),
    ("stiffness-count-4", {"seafastening": {"saddle_count": 4, "saddle_stiffness_N_per_m": [1e9, 1e9, 1e9]}}, ["3 values for 4 saddles"]),
    (
        "stiffness-negative-item",
        {"seafastening": {"saddle_stiffness_N_per_m": [1e9, -1e9, 1e9]}},
        ["seafastening.saddle_stiffness_N_per_m"],
    ),
    ("lashed-out-of-range", {"seafastening": {"lashed_saddles": [0, 3]}}, ["seafastening.lashed_saddles = [0, 3]", "[3]", "0..2"]),
    ("lashed-negative", {"seafastening": {"lashed_saddles": [-1]}}, ["seafastening.lashed_saddles[0] = -1"]),
    ("time-samples", {"solver": {"harmonics": 5, "time_samples": 11}}, ["time_samples = 11", "2 * harmonics + 2 = 12"]),
    ("time-samples-H", {"solver": {"harmonics": 70, "time_samples": 128}}, ["time_samples = 128", "2 * harmonics + 2 = 142"]),
    ("bad-literal", {"solver": {"contact_law": "hertz"}}, ["solver.contact_law = 'hertz'", "tanh"]),
    ("damping-1", {"model": {"damping_ratio": 1.0}}, ["model.damping_ratio = 1.0", "less than 1"]),
    ("poisson", {"cargo": {"poisson_ratio": 0.5}}, ["cargo.poisson_ratio = 0.5"]),
    ("cargo-off-ship", {"cargo": {"position_m": 20.0}}, ["cargo.position_m = 20.0", "37.0 .. 134.0"]),
    ("group-not-mapping", {"cargo": [1, 2]}, ["cargo", "valid dictionary"]),
    ("group-scalar", {"wave": 3}, ["wave = 3", "valid dictionary"]),
]


@pytest.mark.parametrize("data, must_contain", [(d, m) for _, d, m in INVALID], ids=[i for i, _, _ in INVALID])
def test_invalid_mapping_raises_case_error_naming_field_and_value(data: dict[str, Any], must_contain: list[str]) -> None:
    with pytest.raises(CaseError) as exc:
        case_from_mapping(data, source="'test.yaml'")
    msg = str(exc.value)
    assert msg.startswith("invalid case 'test.yaml'")
    for s in must_contain:
        assert s in msg, f"{s!r} not in:\n{msg}"


def test_all_problems_are_reported_together() -> None:
    with pytest.raises(CaseError) as exc:
        case_from_mapping({"cargo": {"length_m": -1, "diameter_m": "x"}, "wave": {"amplitude_m": float("nan")}})
    msg = str(exc.value)
    assert "cargo.length_m = -1" in msg and "cargo.diameter_m = 'x'" in msg and "wave.amplitude_m = nan" in msg


@pytest.mark.parametrize("key, value", [("cargo.length_m", True), ("cargo.units_abreast", True), ("wave.amplitude_m", False)])
def test_boolean_for_a_number_is_rejected(key: str, value: bool) -> None:
    with pytest.raises(CaseError, match=key.replace(".", r"\.")):
        load_case(overrides={key: value})


def test_numeric_strings_are_accepted_as_numbers() -> None:
    # deliberate leniency: YAML 1.1 leaves "1e9" / quoted numbers as strings
    assert case_from_mapping({"cargo": {"length_m": "74"}}).cargo.length_m == 74.0


# --------------------------------------------------------------------------- files
def test_malformed_yaml_names_file_and_line(tmp_path: Path) -> None:
    p = tmp_path / "broken.yaml"
    p.write_text("cargo:\n  length_m: 74\n  diameter_m: [8, 9\nwave:\n  amplitude_m: 3\n", encoding="utf-8")
    with pytest.raises(CaseError) as exc:
        load_case(p)
    msg = str(exc.value)
    assert "broken.yaml" in msg and "not valid YAML" in msg and "line" in msg


def test_bad_indentation_yaml(tmp_path: Path) -> None:
    p = tmp_path / "indent.yaml"
    p.write_text("cargo:\n  length_m: 74\n diameter_m: 8\n", encoding="utf-8")
    with pytest.raises(CaseError, match=r"indent\.yaml.*not valid YAML at line 3"):
        load_case(p)


@pytest.mark.parametrize("text, typename", [("- 1\n- 2\n", "list"), ("42\n", "int"), ("just text\n", "str")])
def test_top_level_not_a_mapping(tmp_path: Path, text: str, typename: str) -> None:
    p = tmp_path / "top.yaml"
    p.write_text(text, encoding="utf-8")
    with pytest.raises(CaseError) as exc:
        load_case(p)
    msg = str(exc.value)
    assert "top.yaml" in msg and "top level must be a mapping" in msg and typename in msg


@pytest.mark.parametrize("text", ["", "# nothing\n", "\n  \n", "---\n# only a document marker\n"])
def test_an_empty_file_is_refused(tmp_path: Path, text: str) -> None:
    """An empty file does not silently run the base case: it says what to do."""
    p = tmp_path / "empty.yaml"
    p.write_text(text, encoding="utf-8")
    with pytest.raises(CaseError) as exc:
        load_case(p, {"wave.amplitude_m": 2.0})
    msg = str(exc.value)
    assert str(p) in msg and "is empty" in msg and "seafast init" in msg


def test_an_explicit_empty_mapping_is_the_default_case(tmp_path: Path) -> None:
    p = tmp_path / "defaults.yaml"
    p.write_text("{}\n", encoding="utf-8")
    assert load_case(p) == Case()


def test_missing_file(tmp_path: Path) -> None:
    p = tmp_path / "no_such_case.yaml"
    with pytest.raises(CaseError) as exc:
        load_case(p)
    assert "no_such_case.yaml" in str(exc.value) and "cannot read" in str(exc.value)


def test_directory_and_non_utf8_file(tmp_path: Path) -> None:
    with pytest.raises(CaseError, match="cannot read"):
        load_case(tmp_path)
    p = tmp_path / "latin1.yaml"
    p.write_bytes("name: caf\xe9\n".encode("latin-1"))
    with pytest.raises(CaseError, match=r"latin1\.yaml"):
        load_case(p)


def test_relative_table_paths_resolve_against_the_case_file(tmp_path: Path) -> None:
    sub = tmp_path / "cases"
    sub.mkdir()
    p = sub / "c.yaml"
    p.write_text("vessel:\n  deck_deflection_table: tables/deck.csv\n  motions: rao.nc\n", encoding="utf-8")
    case = load_case(p)
    assert case.vessel.deck_deflection_table == (sub / "tables" / "deck.csv").resolve()
    assert Path(case.vessel.motions) == (sub / "rao.nc").resolve()
    assert load_case(p, overrides={"vessel.motions": "none"}).vessel.motions == "none"


@pytest.mark.parametrize("where", ["table", "motions", "case-path"])
def test_nul_byte_in_paths_gives_case_error(tmp_path: Path, where: str) -> None:
    p = tmp_path / "c.yaml"
    if where == "table":
        p.write_text('vessel:\n  deck_deflection_table: "deck\\0.csv"\n', encoding="utf-8")
    elif where == "motions":
        p.write_text('vessel:\n  motions: "rao\\0.nc"\n', encoding="utf-8")
    else:
        p = tmp_path / "c\0.yaml"
    try:
        load_case(p)
    except CaseError:
        return
    except Exception as exc:  # noqa: BLE001 - any other error escaping is the failure this test looks for
        pytest.fail(f"{type(exc).__name__} escaped instead of CaseError: {exc}")
    pytest.fail("no error raised")


# --------------------------------------------------------------------------- property test
def _schema_keys(model: type[BaseModel]) -> dict[str, Any]:
    """Nested dict of the schema: group -> field names (leaves map to None)."""
    out: dict[str, Any] = {}
    for name, f in model.model_fields.items():
        ann = f.annotation
        if isinstance(ann, type) and issubclass(ann, BaseModel):
            out[name] = _schema_keys(ann)
        else:
            out[name] = None
    return out


SCHEMA = _schema_keys(Case)
SECTION_KEYS = list(_schema_keys(Case.model_fields["cargo"].annotation.model_fields["sections"].annotation.__args__[0].__args__[0]))  # type: ignore[union-attr]

TEXT = st.text(max_size=12)
json_scalars = (
    st.none()
    | st.booleans()
    | st.integers(min_value=-(10**20), max_value=10**20)
    | st.floats(allow_nan=True, allow_infinity=True)
    | TEXT
    | st.sampled_from(["bem", "none", "tanh", "hbm", "exact", "1e9", "74", "", "nan", "-inf"])
)
json_values = st.recursive(
    json_scalars,
    lambda children: (
        st.lists(children, max_size=5)
        | st.dictionaries(st.text(st.characters(exclude_characters="\x00"), max_size=8), children, max_size=5)
    ),
    max_leaves=15,
)
plausible_numbers = (
    st.floats(min_value=-10.0, max_value=200.0)
    | st.integers(min_value=-3, max_value=200)
    | st.sampled_from([0, 1e-9, 1e9, 1.1e9, 74.0, 37.0])
)
leaf_values = (
    plausible_numbers
    | json_values
    | st.lists(plausible_numbers, max_size=6)
    | st.lists(st.dictionaries(st.sampled_from(SECTION_KEYS), plausible_numbers, max_size=5), max_size=3)
)


def _schema_mapping(tree: dict[str, Any]) -> st.SearchStrategy[dict[str, Any]]:
    items = {}
    for key, sub in tree.items():
        items[key] = leaf_values if sub is None else (_schema_mapping(sub) | json_values)
    junk_keys = st.text(st.characters(exclude_characters="\x00"), min_size=1, max_size=6)
    return st.fixed_dictionaries({}, optional=items).flatmap(
        lambda d: st.dictionaries(junk_keys, json_values, max_size=1).map(lambda extra: {**d, **extra}) | st.just(d)
    )


case_like = _schema_mapping(SCHEMA) | json_values | st.dictionaries(st.sampled_from(list(SCHEMA)), json_values, max_size=4)


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=case_like)
def test_random_mappings_give_case_or_case_error(data: Any) -> None:
    try:
        case = case_from_mapping(data)
    except CaseError as exc:
        error = str(exc)
    else:
        error = None
    if error is not None:
        assert error.startswith("invalid case")
        return
    assert isinstance(case, Case)
    # a valid case has consistent derived values
    pos = case.saddle_positions_m()
    assert all(0 < x < case.cargo.length_m for x in pos)
    assert len(case.saddle_stiffnesses_N_per_m()) == len(pos)
    assert all(0 <= i < len(pos) for i in case.lashed_saddle_indices())
    if case.solver.time_samples is not None and case.solver.harmonics is not None:
        assert case.solver.time_samples >= 2 * case.solver.harmonics + 2


override_keys = st.sampled_from(
    [f"{g}.{k}" for g, sub in SCHEMA.items() if sub for k in sub]
    + list(SCHEMA)
    + ["cargo.length_m.x", "a..b", "seafastening.lashing.stiffness_N_per_m"]
)


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    data=case_like,
    overrides=st.dictionaries(override_keys, leaf_values, max_size=3),
    base=st.booleans(),
)
def test_random_overrides_give_case_or_case_error(data: Any, overrides: dict[str, Any], base: bool, tmp_path_factory) -> None:
    base_dir = tmp_path_factory.getbasetemp() if base else None
    try:
        case = case_from_mapping(data, overrides=overrides, base_dir=base_dir)
    except CaseError:
        return
    assert isinstance(case, Case)
