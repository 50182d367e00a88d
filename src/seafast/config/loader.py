"""Reading case files: YAML -> validated :class:`~seafast.config.schema.Case`, with overrides.

All input problems surface as :class:`CaseError` with one message per problem naming the
dotted key, the value given and what is allowed.
"""

from __future__ import annotations

import copy
from collections.abc import Iterable, Mapping
from importlib import resources
from pathlib import Path
from typing import Any

import yaml
from pydantic import ValidationError

from seafast.config.schema import Case

__all__ = [
    "CaseError",
    "load_case",
    "parse_yaml",
    "case_from_mapping",
    "parse_overrides",
    "apply_overrides",
    "base_case_text",
    "case_json_schema",
]


class CaseError(ValueError):
    """Invalid case input; the message names the field, the value and what is allowed."""


def base_case_text() -> str:
    """The built-in base case as commented YAML text."""
    return resources.files("seafast.config").joinpath("base_case.yaml").read_text(encoding="utf-8")


def _format_validation_error(err: ValidationError, source: str) -> str:
    lines = []
    for e in err.errors():
        loc = ".".join(str(p) if not isinstance(p, int) else f"[{p}]" for p in e["loc"]).replace(".[", "[")
        msg = e["msg"].removeprefix("Value error, ")
        value = e.get("input")
        where = loc or "(case)"
        if e["type"] == "extra_forbidden":
            lines.append(f"{where}: unknown key (value {value!r}); check the spelling against `seafast schema`")
        elif e["type"] in ("missing",):
            lines.append(f"{where}: required key is missing")
        elif isinstance(value, (dict, list)) and loc:
            lines.append(f"{where}: {msg}")
        else:
            lines.append(f"{where} = {value!r}: {msg}" if loc else f"{msg}")
    return f"invalid case {source}:\n  " + "\n  ".join(lines)


def _set_dotted(data: dict[str, Any], key: str, value: Any) -> None:
    parts = key.split(".")
    if not key or any(p == "" for p in parts):
        raise CaseError(f"--set {key}=...: empty key part; use dotted keys such as cargo.length_m")
    node = data
    for p in parts[:-1]:
        nxt = node.get(p)
        if nxt is None:
            nxt = {}
            node[p] = nxt
        if not isinstance(nxt, dict):
            raise CaseError(f"--set {key}: '{p}' is a value, not a group of keys")
        node = nxt
    node[parts[-1]] = value


def parse_overrides(items: Iterable[str]) -> dict[str, Any]:
    """Parse ``KEY=VALUE`` strings; VALUE is read as YAML (numbers, lists, null, strings)."""
    out: dict[str, Any] = {}
    for item in items:
        if "=" not in item:
            raise CaseError(f"--set {item!r}: expected KEY=VALUE, e.g. --set cargo.length_m=90")
        key, _, raw = item.partition("=")
        try:
            out[key.strip()] = yaml.safe_load(raw) if raw.strip() else None
        except yaml.YAMLError as exc:
            raise CaseError(f"--set {key}: value {raw!r} is not valid YAML ({exc.__class__.__name__})") from None
    return out


def apply_overrides(data: Mapping[str, Any], overrides: Mapping[str, Any]) -> dict[str, Any]:
    """A copy of the raw case mapping with dotted-key overrides applied."""
    result = copy.deepcopy(dict(data))
    for key, value in overrides.items():
        _set_dotted(result, key, value)
    return result


def _resolve_route_paths(data: dict[str, Any], base_dir: Path) -> None:
    """criteria.operation.route[*].scatter_diagram relative to the case file's directory."""
    criteria = data.get("criteria")
    operation = criteria.get("operation") if isinstance(criteria, dict) else None
    route = operation.get("route") if isinstance(operation, dict) else None
    for leg in route if isinstance(route, list) else []:
        v = leg.get("scatter_diagram") if isinstance(leg, dict) else None
        if isinstance(v, str) and v and "\0" not in v and not Path(v).is_absolute():
            leg["scatter_diagram"] = str((base_dir / v).resolve())


def _resolve_paths(data: dict[str, Any], base_dir: Path) -> None:
    sea = data.get("sea_state")
    if isinstance(sea, dict):
        v = sea.get("spectrum")
        if isinstance(v, str) and v and v not in ("jonswap", "pierson_moskowitz") and "\0" not in v and not Path(v).is_absolute():
            sea["spectrum"] = str((base_dir / v).resolve())
    _resolve_route_paths(data, base_dir)
    vessel = data.get("vessel")
    if not isinstance(vessel, dict):
        return
    for key in ("deck_deflection_table", "still_water_bending_moment_table", "hull_form_table", "motions"):
        v = vessel.get(key)
        if not isinstance(v, str) or not v or (key == "motions" and v in ("bem", "none")):
            continue
        if "\0" in v:
            raise CaseError(f"vessel.{key} = {v!r}: not a valid path (contains a NUL character)")
        if not Path(v).is_absolute():
            vessel[key] = str((base_dir / v).resolve())


def case_from_mapping(
    data: Any, source: str = "(mapping)", overrides: Mapping[str, Any] | None = None, base_dir: Path | None = None
) -> Case:
    """Validate a raw mapping (parsed YAML) into a :class:`Case`."""
    if data is None:
        data = {}
    if not isinstance(data, Mapping):
        raise CaseError(f"invalid case {source}: the top level must be a mapping of keys (got {type(data).__name__})")
    raw = apply_overrides(data, overrides or {})
    if base_dir is not None:
        _resolve_paths(raw, base_dir)
    try:
        return Case.model_validate(raw)
    except ValidationError as err:
        raise CaseError(_format_validation_error(err, source)) from None


def load_case(path: str | Path | None = None, overrides: Mapping[str, Any] | None = None) -> Case:
    """Load a case file (``None``: the built-in base case) and apply dotted-key overrides.

    Raises
    ------
    CaseError
        If the file cannot be read or parsed, is empty (only blank lines or comments; ``{}``
        runs every default on purpose), or any value is invalid.
    """
    if path is None:
        text, source, base_dir = base_case_text(), "(built-in base case)", Path.cwd()
    else:
        p = Path(path)
        if "\0" in str(path):
            raise CaseError(f"case file {str(path)!r}: not a valid path (contains a NUL character)")
        try:
            text = p.read_text(encoding="utf-8")
        except (OSError, UnicodeDecodeError) as exc:
            raise CaseError(f"cannot read case file '{p}': {exc.strerror if isinstance(exc, OSError) else exc}") from None
        source, base_dir = f"'{p}'", p.resolve().parent
    data = parse_yaml(text, source)
    if data is None and path is not None:
        # an empty file is a truncated copy or the wrong file far more often than a wish for the
        # base case (which needs no file); '{}' says "all defaults" explicitly
        raise CaseError(
            f"case file '{path}' is empty (no keys, only blank lines or comments): nothing says what to run. "
            f"Write a case to edit with 'seafast init {path} --force', run the built-in base case with "
            f"'seafast run' and no file, or put '{{}}' in the file to run every default on purpose"
        )
    return case_from_mapping(data, source, overrides, base_dir)


def parse_yaml(text: str, source: str, error: type[CaseError] = CaseError, kind: str = "case") -> Any:
    """Parse YAML text; a syntax error becomes ``error`` naming the line and column."""
    try:
        return yaml.safe_load(text)
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        where = f" at line {mark.line + 1}, column {mark.column + 1}" if mark is not None else ""
        raise error(f"invalid {kind} {source}: not valid YAML{where}: {getattr(exc, 'problem', exc)}") from None


def case_json_schema() -> dict[str, Any]:
    """JSON Schema of the case format."""
    return Case.model_json_schema()
