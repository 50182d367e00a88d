"""The resolved study: the base case and the axis coordinates, and every point's case (:class:`StudyGrid`)."""

from __future__ import annotations

import hashlib
import json
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from seafast.config.loader import case_from_mapping, load_case
from seafast.config.schema import Case
from seafast.studies.spec.case_keys import case_key_kind
from seafast.studies.spec.errors import StudyError
from seafast.studies.spec.expressions import evaluate_expression
from seafast.studies.spec.schema import StudySpec

__all__ = ["StudyGrid", "build_grid"]


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
