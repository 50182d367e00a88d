"""The exported case schema is standard JSON Schema: a standard validator refuses what seafast refuses.

``seafast schema`` is what editors' YAML plugins and users' own checks read. Its bounds must be JSON
Schema's ``minimum`` / ``exclusiveMinimum`` / ``maximum`` / ``exclusiveMaximum`` (pydantic's own
``ge`` / ``gt`` / ``le`` / ``lt`` are unknown keywords to a validator, which then accepts a negative
length). Checked with the ``jsonschema`` package against the example cases and against bad values of
every bounded kind.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import jsonschema
import pytest
import yaml

from seafast.cli import main
from seafast.config import CaseError, case_json_schema
from seafast.config.loader import case_from_mapping

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
PYDANTIC_BOUNDS = {"gt", "ge", "lt", "le"}


def _validator() -> jsonschema.protocols.Validator:
    schema = case_json_schema()
    cls = jsonschema.validators.validator_for(schema, default=jsonschema.Draft202012Validator)
    cls.check_schema(schema)  # the schema itself is valid JSON Schema
    return cls(schema)


def _keys(node: Any) -> set[str]:
    """Every keyword used anywhere in a schema (the property names themselves excluded)."""
    if isinstance(node, list):
        return set().union(*(_keys(v) for v in node)) if node else set()
    if not isinstance(node, dict):
        return set()
    out: set[str] = set()
    for key, value in node.items():
        if key in ("properties", "$defs"):
            out |= set().union(*(_keys(v) for v in value.values())) if value else set()
        else:
            out.add(key)
            out |= _keys(value)
    return out


def test_the_schema_uses_json_schema_bounds_only():
    keywords = _keys(case_json_schema())
    assert not keywords & PYDANTIC_BOUNDS
    assert {"minimum", "exclusiveMinimum", "maximum", "exclusiveMaximum"} <= keywords


def test_the_command_prints_the_same_schema(capsys):
    assert main(["schema"]) == 0
    assert json.loads(capsys.readouterr().out) == case_json_schema()


@pytest.mark.parametrize("path", sorted(EXAMPLES.glob("*.yaml")), ids=lambda p: p.name)
def test_the_example_cases_are_valid(path: Path):
    mapping = yaml.safe_load(path.read_text(encoding="utf-8")) or {}
    case_from_mapping(mapping, str(path))  # seafast accepts it
    errors = list(_validator().iter_errors(mapping))
    assert not errors, [e.message for e in errors]


BAD = [
    ({"cargo": {"length_m": -5}}, "exclusiveMinimum"),
    ({"cargo": {"length_m": 0}}, "exclusiveMinimum"),
    ({"seafastening": {"saddle_count": 0}}, "minimum"),
    ({"seafastening": {"saddle_count": 51}}, "maximum"),
    ({"cargo": {"poisson_ratio": 0.5}}, "exclusiveMaximum"),
    ({"seafastening": {"lashing": {"pretension_N": -1.0}}}, "minimum"),
    ({"solver": {"harmonics": 0}}, "minimum"),
    ({"solver": {"truncation_tolerance": 1.0}}, "exclusiveMaximum"),
    ({"model": {"damping_ratio": -0.01}}, "minimum"),
    ({"sea_state": {"duration_s": 10.0}}, "minimum"),
    ({"cargo": {"lenght_m": 74.0}}, "additionalProperties"),
]


@pytest.mark.parametrize(("mapping", "keyword"), BAD, ids=[json.dumps(m) for m, _ in BAD])
def test_a_standard_validator_refuses_what_seafast_refuses(mapping: dict, keyword: str):
    with pytest.raises(CaseError):
        case_from_mapping(mapping, "test")
    errors = list(_validator().iter_errors(mapping))
    assert errors, f"the JSON Schema accepts {mapping}"
    # an optional key's bound sits inside its anyOf: look into each error's context too
    found = {e.validator for error in errors for e in (error, *error.context)}
    assert keyword in found, found


def test_a_good_case_with_every_bound_at_its_limit_is_valid():
    mapping = {
        "cargo": {"units_abreast": 1, "poisson_ratio": 0.49},
        "seafastening": {"saddle_count": 50, "lashing": {"pretension_N": 0.0}},
        "solver": {"harmonics": 1024, "time_samples": 16384},
        "model": {"damping_ratio": 0.0},
        "sea_state": {"duration_s": 60.0, "peak_enhancement": 1.0},
    }
    assert not list(_validator().iter_errors(mapping))
