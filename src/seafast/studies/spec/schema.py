"""The study file's schema: pydantic models of a study, its axes and its design limits.

Frozen, extra keys forbidden; every key an axis or a derived key names is checked to be a
numeric case key (:func:`~seafast.studies.spec.case_keys.case_key_kind`).
"""

from __future__ import annotations

import math
from typing import Annotated, Any, Literal

import numpy as np
from pydantic import BaseModel, ConfigDict, Field, field_validator, model_validator

from seafast.studies.spec.case_keys import case_key_kind
from seafast.studies.spec.errors import StudyError
from seafast.studies.spec.expressions import expression_keys

__all__ = ["AxisSpec", "LimitsSpec", "StudySpec"]


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


_OptionalLimit = Annotated[float, Field(gt=0, allow_inf_nan=False)] | None


class LimitsSpec(_Strict):
    """Design limits (the source's: 7 MN saddle force, 20 MPa bending stress), and optional limits on the cargo on
    its cradles, judged at the points off head seas (null: not checked)."""

    max_saddle_force_N: Annotated[float, Field(gt=0, allow_inf_nan=False)] = Field(7.0e6, description="Largest allowed saddle force F [N]")
    max_bending_stress_Pa: Annotated[float, Field(gt=0, allow_inf_nan=False)] = Field(
        20.0e6, description="Largest allowed cargo bending stress sigma_b [Pa]"
    )
    max_pad_force_N: _OptionalLimit = Field(None, description="Largest allowed cradle pad force F_pad_N [N]; null: not checked")
    max_lashing_tension_N: _OptionalLimit = Field(
        None, description="Largest allowed lashing-wire tension lashing_tension_max_N [N]; null: not checked"
    )
    max_transverse_slip_m: _OptionalLimit = Field(
        None, description="Largest allowed lateral displacement of the cargo at a saddle transverse_slip_m [m]; null: not checked"
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
