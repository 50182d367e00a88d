"""The number types of the case schema: finite floats with bounds, never a yes/no value.

Kept apart from :mod:`seafast.config.schema` so that the schema's modules share them.
"""

from __future__ import annotations

import math
from typing import Annotated

from pydantic import BeforeValidator, Field

__all__ = ["NotBool", "Positive", "NonNegative", "Finite", "Count"]


def _not_bool(value: object) -> object:
    # pydantic's lax mode reads YAML true/yes/on as 1; a boolean is never a valid number here
    if isinstance(value, bool):
        raise ValueError(f"{value!r} is a yes/no value; a number is required")
    if isinstance(value, float) and not math.isfinite(value):
        raise ValueError("must be a finite number")
    return value


# The yes/no check is the last annotation, so it runs first (a before-validator wraps what precedes it) and
# the bounds stay on the number itself, where pydantic exports them as JSON Schema's minimum /
# exclusiveMinimum / maximum / exclusiveMaximum (before the check they come out as pydantic's own ge/gt/le/lt,
# which a standard validator ignores).
NotBool = BeforeValidator(_not_bool)
Positive = Annotated[float, Field(gt=0, allow_inf_nan=False), NotBool]
NonNegative = Annotated[float, Field(ge=0, allow_inf_nan=False), NotBool]
Finite = Annotated[float, Field(allow_inf_nan=False), NotBool]
Count = Annotated[int, NotBool]
