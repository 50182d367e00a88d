"""Study files: a YAML description of a parametric grid over case keys, validated with pydantic.

A study names a base case (a case file, or the built-in base case), fixed overrides of it
(``set``), one or more axes over numeric case keys (dotted paths such as ``cargo.length_m``),
optional derived keys computed from other keys (``cargo.wall_thickness_m: cargo.diameter_m / 110``)
and the design limits used to judge compliance::

    name: saddles
    axes:
      - key: seafastening.saddle_count
        values: [2, 3, 4, 5, 6, 7]
      - key: seafastening.saddle_stiffness_N_per_m
        start: 1.1e7
        stop: 1.1e10
        num: 20
        scale: log
    limits:
      max_saddle_force_N: 7.0e6
      max_bending_stress_Pa: 20.0e6

All input problems surface as :class:`StudyError` (a :class:`seafast.config.CaseError`) whose
message names the field, the value given and what is allowed.
"""

from __future__ import annotations

import ast
import functools
import hashlib
import json
import math
import operator
import types
import typing
from collections.abc import Mapping
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import Annotated, Any, Literal

import numpy as np
from pydantic import BaseModel, ConfigDict, Field, ValidationError, field_validator, model_validator

from seafast.config.loader import CaseError, case_from_mapping, load_case, parse_yaml
from seafast.config.schema import Case

__all__ = [
    "StudyError",
    "AxisSpec",
    "LimitsSpec",
    "StudySpec",
    "StudyGrid",
    "BUILTIN_STUDIES",
    "builtin_study_names",
    "load_study_spec",
    "study_spec_from_mapping",
    "build_grid",
    "case_key_kind",
    "evaluate_expression",
    "units_of_key",
]


class StudyError(CaseError):
    """Invalid study input; the message names the field, the value and what is allowed."""


BUILTIN_STUDIES: tuple[str, ...] = ("saddles", "lashing", "cargo", "cargo-saddles-8m", "cargo-saddles-12m")


# --------------------------------------------------------------------------- case-key introspection
def _numeric_kinds(annotation: Any) -> set[str]:
    """The numeric scalar kinds ('int', 'float') an annotation admits (bool excluded)."""
    origin = typing.get_origin(annotation)
    if origin is Annotated:
        return _numeric_kinds(typing.get_args(annotation)[0])
    if origin in (typing.Union, types.UnionType):
        kinds: set[str] = set()
        for arg in typing.get_args(annotation):
            kinds |= _numeric_kinds(arg)
        return kinds
    if annotation is float:
        return {"float"}
    if annotation is int:
        return {"int"}
    return set()


def _model_class(annotation: Any) -> type[BaseModel] | None:
    origin = typing.get_origin(annotation)
    if origin is Annotated:
        return _model_class(typing.get_args(annotation)[0])
    if origin in (typing.Union, types.UnionType):
        for arg in typing.get_args(annotation):
            found = _model_class(arg)
            if found is not None:
                return found
        return None
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return annotation
    return None


def _field_names(model: type[BaseModel]) -> list[str]:
    return list(model.model_fields)


@functools.lru_cache(maxsize=512)
def case_key_kind(key: str) -> Literal["int", "float"]:
    """The numeric kind of a dotted case key.

    Parameters
    ----------
    key : str
        Dotted path into :class:`seafast.config.Case`, e.g. ``"cargo.length_m"``.

    Returns
    -------
    {'int', 'float'}
        ``'int'`` when the field only admits integers (e.g. ``seafastening.saddle_count``).

    Raises
    ------
    StudyError
        If the key does not exist or is not a numeric field.
    """
    model: type[BaseModel] = Case
    parts = key.split(".")
    walked: list[str] = []
    for depth, part in enumerate(parts):
        fields = model.model_fields
        if part not in fields:
            where = ".".join(walked) or "(case)"
            raise StudyError(f"'{key}' is not a case key: '{part}' is not in {where}; allowed: {', '.join(_field_names(model))}")
        walked.append(part)
        annotation = fields[part].annotation
        if depth < len(parts) - 1:
            sub = _model_class(annotation)
            if sub is None:
                raise StudyError(f"'{key}' is not a case key: '{'.'.join(walked)}' is a value, not a group of keys")
            model = sub
        else:
            if _model_class(annotation) is not None and not _numeric_kinds(annotation):
                sub = _model_class(annotation)
                assert sub is not None
                raise StudyError(
                    f"'{key}' is a group of keys, not a numeric value; allowed: " + ", ".join(f"{key}.{f}" for f in _field_names(sub))
                )
            kinds = _numeric_kinds(annotation)
            if not kinds:
                raise StudyError(f"'{key}' is not numeric and cannot be a study axis or derived key")
            return "float" if "float" in kinds else "int"
    raise StudyError(f"'{key}': empty key")  # pragma: no cover - parts is never empty


_UNIT_SUFFIXES: tuple[tuple[str, str], ...] = (
    ("_kg_per_m3", "kg/m^3"),
    ("_m_per_s2", "m/s^2"),
    ("_N_per_m", "N/m"),
    ("_rad_s", "rad/s"),
    ("_deg", "deg"),
    ("_per_m", "1/m"),
    ("_Nm", "N m"),
    ("_Pa", "Pa"),
    ("_m4", "m^4"),
    ("_m3", "m^3"),
    ("_m2", "m^2"),
    ("_kg", "kg"),
    ("_m", "m"),
    ("_N", "N"),
    ("_s", "s"),
)


def units_of_key(key: str) -> str:
    """SI unit of a (dotted) key from its name suffix; ``'1'`` when dimensionless.

    Parameters
    ----------
    key : str
        Key such as ``"seafastening.saddle_stiffness_N_per_m"`` or ``"F_N"``.

    Returns
    -------
    str
        The unit, e.g. ``"N/m"``.
    """
    last = key.split(".")[-1]
    for suffix, unit in _UNIT_SUFFIXES:
        if last.endswith(suffix):
            return unit
    return "1"


# --------------------------------------------------------------------------- derived expressions
_BINARY_OPS: dict[type, Any] = {
    ast.Add: operator.add,
    ast.Sub: operator.sub,
    ast.Mult: operator.mul,
    ast.Div: operator.truediv,
    ast.Pow: operator.pow,
}
_UNARY_OPS: dict[type, Any] = {ast.USub: operator.neg, ast.UAdd: operator.pos}
_FUNCTIONS: dict[str, Any] = {
    "min": min,
    "max": max,
    "floor": math.floor,
    "ceil": math.ceil,
    "round": round,
    "abs": abs,
    "sqrt": math.sqrt,
    "log": math.log,
    "exp": math.exp,
}
_ALLOWED_TEXT = f"numbers, dotted case keys, + - * / ** , parentheses and {', '.join(_FUNCTIONS)}"


def _dotted_name(node: ast.AST) -> str | None:
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Attribute):
        head = _dotted_name(node.value)
        return None if head is None else f"{head}.{node.attr}"
    return None


@functools.lru_cache(maxsize=256)  # studies evaluate the same derived expressions at every point
def _parse_expression(text: str) -> ast.Expression:
    try:
        tree = ast.parse(str(text), mode="eval")
    except SyntaxError:
        raise StudyError(f"derived expression {text!r} is not valid; allowed: {_ALLOWED_TEXT}") from None
    for node in ast.walk(tree):
        if isinstance(node, ast.Call):
            if not (isinstance(node.func, ast.Name) and node.func.id in _FUNCTIONS) or node.keywords or not node.args:
                raise StudyError(f"derived expression {text!r} calls '{ast.unparse(node.func)}'; allowed: {_ALLOWED_TEXT}")
            continue
        if isinstance(node, ast.Name) and node.id in _FUNCTIONS:
            continue
        allowed = (
            ast.Expression,
            ast.BinOp,
            ast.UnaryOp,
            ast.Constant,
            ast.Name,
            ast.Attribute,
            ast.Load,
            ast.Call,
            *_BINARY_OPS,
            *_UNARY_OPS,
        )
        if not isinstance(node, allowed) or (isinstance(node, ast.Constant) and not isinstance(node.value, (int, float))):
            raise StudyError(
                f"derived expression {text!r} uses '{ast.unparse(node) if isinstance(node, ast.expr) else type(node).__name__}'; "
                f"allowed: {_ALLOWED_TEXT}"
            )
    return tree


def expression_keys(text: str) -> list[str]:
    """The dotted case keys an expression refers to, in order of appearance."""
    tree = _parse_expression(text)
    keys: list[str] = []

    def visit(node: ast.AST) -> None:
        if isinstance(node, ast.Call):
            for arg in node.args:
                visit(arg)
            return
        name = _dotted_name(node)
        if name is not None:
            if name not in keys:
                keys.append(name)
            return
        for child in ast.iter_child_nodes(node):
            visit(child)

    visit(tree.body)
    return keys


def evaluate_expression(text: str, lookup: typing.Callable[[str], float]) -> float:
    """Evaluate a derived-key expression such as ``"cargo.diameter_m / 110"``.

    Parameters
    ----------
    text : str
        Arithmetic over numbers and dotted case keys (``+ - * / **``, parentheses) and the
        functions ``min, max, floor, ceil, round, abs, sqrt, log, exp``.
    lookup : callable
        Returns the value of a dotted case key (SI units).

    Returns
    -------
    float
        The value, in the units of the derived key.
    """
    tree = _parse_expression(text)

    def ev(node: ast.AST) -> float:
        if isinstance(node, ast.Call):
            assert isinstance(node.func, ast.Name)
            return float(_FUNCTIONS[node.func.id](*(ev(a) for a in node.args)))
        name = _dotted_name(node)
        if name is not None:
            return float(lookup(name))
        if isinstance(node, ast.Constant) and isinstance(node.value, (int, float)):  # the only constants parsing admits
            return float(node.value)
        if isinstance(node, ast.BinOp):
            return _BINARY_OPS[type(node.op)](ev(node.left), ev(node.right))
        if isinstance(node, ast.UnaryOp):
            return _UNARY_OPS[type(node.op)](ev(node.operand))
        raise StudyError(f"derived expression {text!r}: unsupported element")  # pragma: no cover

    return ev(tree.body)


# --------------------------------------------------------------------------- the schema
class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class AxisSpec(_Strict):
    """One study axis: a numeric case key and its values.

    Either ``values`` (an explicit list) or ``start``/``stop``/``num`` with ``scale`` linear or
    log (geometric spacing; both ends included).
    """

    key: str = Field(description="Dotted case key, e.g. cargo.length_m")
    values: tuple[float, ...] | None = Field(None, description="Explicit values (SI units of the key)")
    start: float | None = Field(None, description="First value (SI units of the key)")
    stop: float | None = Field(None, description="Last value (SI units of the key)")
    num: Annotated[int, Field(ge=1, le=100_000)] | None = Field(None, description="Number of values")
    scale: Literal["linear", "log"] = Field("linear", description="Spacing of start..stop, and of the axis in figures")

    @field_validator("key")
    @classmethod
    def _key_exists(cls, v: str) -> str:
        case_key_kind(v)
        return v

    @model_validator(mode="after")
    def _check(self) -> AxisSpec:
        ranged = (self.start, self.stop, self.num)
        if self.values is not None:
            if any(x is not None for x in ranged):
                raise ValueError("give either values, or start/stop/num, not both")
            if len(self.values) == 0:
                raise ValueError("values must list at least one value")
            if any(not math.isfinite(x) for x in self.values):
                raise ValueError(f"values {list(self.values)} must be finite numbers")
            if len(set(self.values)) != len(self.values):
                raise ValueError(f"values {list(self.values)} must be distinct")
            if self.scale == "log" and any(x <= 0 for x in self.values):
                raise ValueError(f"values {list(self.values)} must be positive for scale: log")
        else:
            if any(x is None for x in ranged):
                missing = [n for n, x in zip(("start", "stop", "num"), ranged, strict=True) if x is None]
                raise ValueError(f"missing {', '.join(missing)}; give values, or all of start, stop, num")
            assert self.start is not None and self.stop is not None
            if not (math.isfinite(self.start) and math.isfinite(self.stop)):
                raise ValueError("start and stop must be finite numbers")
            if self.scale == "log" and (self.start <= 0 or self.stop <= 0):
                raise ValueError(f"start = {self.start}, stop = {self.stop}: both must be positive for scale: log")
            if self.num is not None and self.num > 1 and self.start == self.stop:
                raise ValueError(f"start = stop = {self.start} with num = {self.num} would repeat one value")
        return self

    def coordinates(self) -> np.ndarray:
        """The axis values (SI units of the key); integers for integer keys.

        Raises
        ------
        StudyError
            If an integer key is given non-integer values.
        """
        if self.values is not None:
            raw = np.asarray(self.values, dtype=float)
        elif self.scale == "log":
            assert self.start is not None and self.stop is not None and self.num is not None
            raw = np.geomspace(self.start, self.stop, self.num)
        else:
            assert self.start is not None and self.stop is not None and self.num is not None
            raw = np.linspace(self.start, self.stop, self.num)
        if case_key_kind(self.key) == "int":
            rounded = np.round(raw)
            if not np.allclose(raw, rounded, rtol=0, atol=1e-9):
                raise StudyError(f"axes[{self.key}]: values {raw.tolist()} are not whole numbers; allowed: integers for {self.key}")
            if len(set(rounded.tolist())) != len(rounded):
                raise StudyError(f"axes[{self.key}]: start/stop/num give repeated integers {rounded.tolist()}")
            return rounded.astype(np.int64)
        return raw


class LimitsSpec(_Strict):
    """Design limits (the source's: 7 MN saddle force, 20 MPa bending stress)."""

    max_saddle_force_N: Annotated[float, Field(gt=0, allow_inf_nan=False)] = Field(7.0e6, description="Largest allowed saddle force F [N]")
    max_bending_stress_Pa: Annotated[float, Field(gt=0, allow_inf_nan=False)] = Field(
        20.0e6, description="Largest allowed cargo bending stress sigma_b [Pa]"
    )


class StudySpec(_Strict):
    """A parametric study: a grid over case keys around a base case."""

    name: Annotated[str, Field(min_length=1, pattern=r"^[A-Za-z0-9_.-]+$")] = Field(
        description="Study name (letters, digits, _ . -); names the output files' study"
    )
    description: str = ""
    base: str | None = Field(None, description="Case file (relative to the study file); default the built-in base case")
    set: dict[str, Any] = Field(default_factory=dict, description="Dotted-key overrides of the base case")
    axes: tuple[AxisSpec, ...] = Field(description="Study axes; the grid is their outer product")
    derived: dict[str, str] = Field(
        default_factory=dict, description="Dotted key -> expression over other keys, applied per point, in order"
    )
    limits: LimitsSpec = LimitsSpec()
    response: Literal["regular_wave", "sea_state"] | None = Field(
        None,
        description="What each point is judged on: 'regular_wave' (seafast run's dynamic response to wave.*) or 'sea_state' "
        "(the most probable maxima in the sea_state.* sea: linear spectral and nonlinear design waves, docs/operability.md); "
        "default: sea_state when an axis or derived key is a sea_state.* key, else regular_wave",
    )

    @field_validator("axes")
    @classmethod
    def _axes(cls, v: tuple[AxisSpec, ...]) -> tuple[AxisSpec, ...]:
        if len(v) == 0:
            raise ValueError("list at least one axis")
        keys = [a.key for a in v]
        dup = sorted({k for k in keys if keys.count(k) > 1})
        if dup:
            raise ValueError(f"axis key(s) {dup} appear more than once; each key may be one axis only")
        return v

    @field_validator("derived")
    @classmethod
    def _derived(cls, v: dict[str, str]) -> dict[str, str]:
        for key, expr in v.items():
            case_key_kind(key)
            if not isinstance(expr, str):
                raise ValueError(f"derived[{key}] = {expr!r}: give an expression string such as 'cargo.diameter_m / 110'")
            for ref in expression_keys(expr):
                case_key_kind(ref)
        return v

    @model_validator(mode="after")
    def _check(self) -> StudySpec:
        axis_keys = {a.key for a in self.axes}
        both = sorted(axis_keys & set(self.derived))
        if both:
            raise ValueError(f"key(s) {both} are both an axis and derived; a key may be one or the other")
        sea = sorted(k for k in (*axis_keys, *self.derived) if k.startswith("sea_state."))
        if sea and self.response == "regular_wave":
            raise ValueError(
                f"response = 'regular_wave' with sea-state key(s) {sea}: a regular-wave study ignores the sea_state section; "
                "allowed: response: sea_state (or leave response unset)"
            )
        return self

    @property
    def evaluates_sea_state(self) -> bool:
        """Whether points are judged on their sea state's MPMs (``response``, or its default)."""
        if self.response is not None:
            return self.response == "sea_state"
        return any(k.startswith("sea_state.") for k in (*self.axis_keys, *self.derived))

    @property
    def axis_keys(self) -> tuple[str, ...]:
        """The dotted keys of the axes, in order (the study's dimensions)."""
        return tuple(a.key for a in self.axes)


# --------------------------------------------------------------------------- loading
def _format_error(err: ValidationError, source: str) -> str:
    lines = []
    for e in err.errors():
        loc = ".".join(str(p) if not isinstance(p, int) else f"[{p}]" for p in e["loc"]).replace(".[", "[")
        msg = e["msg"].removeprefix("Value error, ")
        value = e.get("input")
        if e["type"] == "extra_forbidden":
            lines.append(
                f"{loc}: unknown key (value {value!r}); allowed: name, description, base, set, axes, derived, limits, response "
                "(axes: key, values, start, stop, num, scale; limits: max_saddle_force_N, max_bending_stress_Pa)"
            )
        elif e["type"] == "missing":
            lines.append(f"{loc}: required key is missing")
        elif isinstance(value, (dict, list)) or not loc:
            lines.append(f"{loc or '(study)'}: {msg}")
        else:
            lines.append(f"{loc} = {value!r}: {msg}")
    return f"invalid study {source}:\n  " + "\n  ".join(lines)


def study_spec_from_mapping(data: Any, source: str = "(mapping)") -> StudySpec:
    """Validate a parsed study mapping.

    Raises
    ------
    StudyError
        With one line per problem naming the field, the value and what is allowed.
    """
    if not isinstance(data, Mapping):
        raise StudyError(f"invalid study {source}: the top level must be a mapping of keys (got {type(data).__name__})")
    try:
        return StudySpec.model_validate(dict(data))
    except StudyError as exc:  # raised directly by a validator (not wrapped by pydantic)
        raise StudyError(f"invalid study {source}: {exc}") from None
    except ValidationError as err:
        raise StudyError(_format_error(err, source)) from None


def builtin_study_names() -> tuple[str, ...]:
    """Names of the built-in studies (``seafast study NAME``)."""
    return BUILTIN_STUDIES


def _builtin_text(name: str) -> str:
    return resources.files("seafast.config").joinpath("studies", f"{name}.yaml").read_text(encoding="utf-8")


def load_study_spec(name_or_path: str | Path) -> tuple[StudySpec, Path | None]:
    """Read a built-in study by name, or a study YAML file.

    Parameters
    ----------
    name_or_path : str or Path
        One of :data:`BUILTIN_STUDIES`, or the path of a study file.

    Returns
    -------
    spec : StudySpec
    directory : Path or None
        The study file's directory (for a relative ``base``), None for built-ins.

    Raises
    ------
    StudyError
        If the name is unknown, the file unreadable, or the content invalid.
    """
    text_name = str(name_or_path)
    if text_name in BUILTIN_STUDIES and not Path(text_name).is_file():
        text, source, directory = _builtin_text(text_name), f"'{text_name}' (built-in)", None
    else:
        path = Path(text_name)
        if not path.is_file():
            raise StudyError(
                f"study '{text_name}': no such file, and not a built-in study; allowed: a YAML file or one of " + ", ".join(BUILTIN_STUDIES)
            )
        try:
            text = path.read_text(encoding="utf-8")
        except (OSError, UnicodeDecodeError) as exc:
            raise StudyError(f"cannot read study file '{path}': {exc}") from None
        source, directory = f"'{path}'", path.resolve().parent
    return study_spec_from_mapping(parse_yaml(text, source, StudyError, "study"), source), directory


# --------------------------------------------------------------------------- the grid
def _get_dotted(data: Mapping[str, Any], key: str) -> Any:
    node: Any = data
    for part in key.split("."):
        if not isinstance(node, Mapping) or part not in node:
            raise StudyError(f"'{key}' has no value in the base case")
        node = node[part]
    return node


@dataclass(frozen=True)
class StudyGrid:
    """A resolved study: the base case mapping and the coordinates of every axis.

    Attributes
    ----------
    spec : StudySpec
        The validated study.
    base : dict
        The base case as a JSON-compatible mapping, ``set`` and command-line overrides applied.
    coordinates : tuple of numpy.ndarray
        Values of each axis, in :attr:`StudySpec.axis_keys` order (SI units of the key).
    """

    spec: StudySpec
    base: dict[str, Any]
    coordinates: tuple[np.ndarray, ...]

    @property
    def keys(self) -> tuple[str, ...]:
        """Axis keys (dimension names)."""
        return self.spec.axis_keys

    @property
    def shape(self) -> tuple[int, ...]:
        """Number of values along each axis."""
        return tuple(len(c) for c in self.coordinates)

    @property
    def size(self) -> int:
        """Number of points."""
        return int(np.prod(self.shape, dtype=np.int64))

    def base_value(self, key: str) -> Any:
        """Value of a dotted key in the base case (before axes and derived keys)."""
        return _get_dotted(self.base, key)

    def point_values(self, index: int) -> dict[str, Any]:
        """Axis values (Python scalars) of the point with flat (C-order) ``index``."""
        multi = np.unravel_index(index, self.shape)
        return {key: coords[i].item() for key, coords, i in zip(self.keys, self.coordinates, multi, strict=True)}

    def point_overrides(self, index: int) -> dict[str, Any]:
        """Dotted overrides (axes then derived keys) that turn the base case into point ``index``."""
        overrides = self.point_values(index)

        def lookup(ref: str) -> Any:
            # the point's own values (axes, earlier derived keys) first, then the base case;
            # expressions refer to numeric leaf keys only, so no merged copy of the case is needed
            return overrides[ref] if ref in overrides else _get_dotted(self.base, ref)

        for key, expr in self.spec.derived.items():
            value = evaluate_expression(expr, lookup)
            if case_key_kind(key) == "int":
                value = round(value)
            overrides[key] = value
        return overrides

    def point_case(self, index: int) -> Case:
        """The validated case of point ``index``.

        Raises
        ------
        CaseError
            If the point's combination of values is not a valid case.
        """
        return case_from_mapping(self.base, f"(study point {index})", self.point_overrides(index))

    def manifest(self) -> dict[str, Any]:
        """What ``study.json`` records about the study (name, fingerprint, shape, axes, spec)."""
        return {
            "name": self.spec.name,
            "fingerprint": self.fingerprint(),
            "shape": list(self.shape),
            "axes": {k: c.tolist() for k, c in zip(self.keys, self.coordinates, strict=True)},
            "spec": self.spec.model_dump(mode="json"),
        }

    def fingerprint(self) -> str:
        """SHA-256 (hex, 16 chars) of everything that determines the points' results."""
        payload: dict[str, Any] = {
            "base": self.base,
            "axes": {k: c.tolist() for k, c in zip(self.keys, self.coordinates, strict=True)},
            "derived": self.spec.derived,
        }
        if self.spec.evaluates_sea_state:  # regular-wave studies keep their fingerprint (stores made before resume)
            payload["response"] = "sea_state"
        text = json.dumps(payload, sort_keys=True, separators=(",", ":"), default=str)
        return hashlib.sha256(text.encode("utf-8")).hexdigest()[:16]


def build_grid(spec: StudySpec, directory: Path | None = None, overrides: Mapping[str, Any] | None = None) -> StudyGrid:
    """Resolve a study into its base case and axis coordinates.

    Parameters
    ----------
    spec : StudySpec
        The validated study.
    directory : Path, optional
        Directory a relative ``spec.base`` is resolved against (the study file's).
    overrides : mapping, optional
        Extra dotted overrides of the base case (``seafast study --set``), applied after ``spec.set``.

    Returns
    -------
    StudyGrid

    Raises
    ------
    StudyError or CaseError
        If the base case (with overrides) is invalid.
    """
    all_overrides = {**spec.set, **dict(overrides or {})}
    base_path: Path | None = None
    if spec.base is not None:
        base_path = Path(spec.base)
        if not base_path.is_absolute() and directory is not None:
            base_path = directory / base_path
    base_case = load_case(base_path, all_overrides)
    base = base_case.model_dump(mode="json")
    coordinates = tuple(axis.coordinates() for axis in spec.axes)
    grid = StudyGrid(spec=spec, base=base, coordinates=coordinates)
    if grid.size > 0:
        grid.point_overrides(0)  # surfaces derived-expression errors before any work
    if spec.evaluates_sea_state and base_case.sea_state.spectrum in ("jonswap", "pierson_moskowitz"):
        for key in ("sea_state.significant_height_m", "sea_state.peak_period_s"):
            if grid.base_value(key) is None and key not in spec.axis_keys and key not in spec.derived:
                raise StudyError(f"{key} = null in the base case: a sea-state study needs it; set it (set: or --set) or make it an axis")
    return grid
