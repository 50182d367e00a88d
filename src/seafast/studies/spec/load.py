"""Reading a study: a YAML file or a built-in study, validated into a :class:`StudySpec`.

Validation errors become one :class:`StudyError` with a line per problem naming the field, the
value given and what is allowed.
"""

from __future__ import annotations

from collections.abc import Mapping
from importlib import resources
from pathlib import Path
from typing import Any

from pydantic import ValidationError

from seafast.config.loader import parse_yaml
from seafast.studies.spec.errors import StudyError
from seafast.studies.spec.schema import StudySpec

__all__ = ["BUILTIN_STUDIES", "builtin_study_names", "load_study_spec", "study_spec_from_mapping"]

BUILTIN_STUDIES: tuple[str, ...] = ("saddles", "lashing", "cargo", "cargo-saddles-8m", "cargo-saddles-12m")


def _format_error(err: ValidationError, source: str) -> str:
    lines = []
    for e in err.errors():
        loc = ".".join(str(p) if not isinstance(p, int) else f"[{p}]" for p in e["loc"]).replace(".[", "[")
        msg = e["msg"].removeprefix("Value error, ")
        value = e.get("input")
        if e["type"] == "extra_forbidden":
            lines.append(
                f"{loc}: unknown key (value {value!r}); allowed: name, description, base, set, axes, derived, limits, response "
                "(axes: key, values, start, stop, num, scale; limits: max_saddle_force_N, max_bending_stress_Pa, max_pad_force_N, "
                "max_lashing_tension_N, max_transverse_slip_m)"
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
