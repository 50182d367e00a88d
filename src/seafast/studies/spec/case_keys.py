"""Case-key introspection: whether a dotted key names a numeric case value, of which kind, in which unit.

Read from the pydantic models of :class:`seafast.config.Case` (nothing is hard-coded per key).
"""

from __future__ import annotations

import functools
import types
import typing
from typing import Annotated, Any, Literal

from pydantic import BaseModel

from seafast.config.schema import Case
from seafast.studies.spec.errors import StudyError

__all__ = ["case_key_kind", "units_of_key"]


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
