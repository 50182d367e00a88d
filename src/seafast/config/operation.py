"""The operation class of a transport (``criteria.operation``): weather-restricted with its alpha factor, or unrestricted on its route.

``criteria.operation`` is null by default (no operation class: every output as before). Weather-restricted:
the planned operation period T_POP, the contingency T_C (T_R = T_POP + T_C) and the forecast level pick the
alpha factor (:mod:`seafast.analyses.criteria.alpha_factor`). Unrestricted: the route's legs, each a sector and
season with either a scatter diagram of its months (3-hour sea states; the 10-year monthly extreme is fitted,
:mod:`seafast.analyses.criteria.route_extremes`) or the extreme Hs of the user's own extreme table.

The limits the standard puts on a weather-restricted operation are here, for the schema and the analysis alike.
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

from pydantic import Field, field_validator, model_validator

from seafast.config.fields import NonNegative, NotBool, Positive, StrictSection
from seafast.config.modes import ForecastLevel, OperationClass

__all__ = [
    "OperationConfig",
    "RouteLegConfig",
    "MAX_PLANNED_OPERATION_PERIOD_H",
    "MAX_MONITORED_OPERATION_PERIOD_H",
    "MAX_REFERENCE_PERIOD_H",
    "MONITORED_LEVELS",
]

MAX_PLANNED_OPERATION_PERIOD_H = 72.0
"""Longest planned operation period of a weather-restricted operation [h] (DNV-OS-H101 Sec.4 B501; the alpha tables' last row)."""

MAX_REFERENCE_PERIOD_H = 96.0
"""Longest reference period T_R = T_POP + T_C of a weather-restricted operation [h] (DNV-OS-H101 Sec.4 B501)."""

MAX_MONITORED_OPERATION_PERIOD_H = 24.0
"""Longest planned operation period of the monitoring tables (4-4, 4-5) [h]; longer periods use Tables 4-1 to 4-3."""

MONITORED_LEVELS = (ForecastLevel.MONITORING, ForecastLevel.MONITORING_LEVEL_A)
"""The forecast levels whose tables stop at 24 h."""


class RouteLegConfig(StrictSection):
    """One leg of an unrestricted transport's route: a sector and season and its wave data."""

    sector: str = Field(..., min_length=1, description="Route sector (a label, e.g. 'North Sea')")
    season: str = Field(..., min_length=1, description="Season of the passage through it (a label, e.g. 'winter')")
    months: tuple[Annotated[int, Field(ge=1, le=12), NotBool], ...] = Field(
        (),
        description="Calendar months (1-12) the scatter diagram's sea states belong to; required with scatter_diagram "
        "(they set the number of 3-hour sea states in the return period)",
    )
    scatter_diagram: Path | None = Field(
        None,
        description="CSV significant_height_m,peak_period_s,occurrence of the leg's 3-hour sea states in these months "
        "(the format of seafast operability --scatter); relative to the case file",
    )
    extreme_hs_m: Positive | None = Field(
        None, description="The leg's 10-year monthly extreme Hs from the user's extreme table [m], instead of a scatter diagram"
    )

    @field_validator("months")
    @classmethod
    def _distinct(cls, v: tuple[int, ...]) -> tuple[int, ...]:
        if len(set(v)) != len(v):
            raise ValueError(f"months = {list(v)} repeats a month; allowed: distinct months 1-12")
        return v

    @model_validator(mode="after")
    def _one_source(self) -> RouteLegConfig:
        if (self.scatter_diagram is None) == (self.extreme_hs_m is None):
            raise ValueError(
                f"leg '{self.sector}, {self.season}': scatter_diagram = {self.scatter_diagram}, extreme_hs_m = {self.extreme_hs_m}; "
                "allowed: exactly one of them"
            )
        if self.scatter_diagram is not None and not self.months:
            raise ValueError(f"leg '{self.sector}, {self.season}': a scatter_diagram needs its months (1-12), e.g. months: [12, 1, 2]")
        return self


class OperationConfig(StrictSection):
    """The transport's operation class and what it needs (``criteria.operation``; docs/criteria.md section 12)."""

    operation_class: OperationClass = Field(..., description="'weather_restricted' (alpha factor) or 'unrestricted' (route data)")
    planned_operation_period_h: Positive | None = Field(
        None, description=f"Planned operation period T_POP [h]; weather-restricted: required, at most {MAX_PLANNED_OPERATION_PERIOD_H:g}"
    )
    contingency_h: NonNegative | None = Field(
        None, description="Contingency time T_C [h]; null: T_C = T_POP (T_R = 2 T_POP, the standard's default when not assessed)"
    )
    forecast_level: ForecastLevel = Field(
        ForecastLevel.BASE,
        description="The forecast and monitoring (the alpha table): base, level_b, level_a, monitoring, monitoring_level_a",
    )
    route: tuple[RouteLegConfig, ...] = Field((), description="Unrestricted: the route's legs (sector, season, wave data)")
    return_period_years: Positive = Field(
        10.0, description="Return period of the unrestricted design sea state [years] (10 by the standard)"
    )

    def reference_period_h(self) -> float | None:
        """T_R = T_POP + T_C [h] (T_C = T_POP when not given); None without T_POP."""
        tpop = self.planned_operation_period_h
        if tpop is None:
            return None
        return tpop + (tpop if self.contingency_h is None else self.contingency_h)

    @model_validator(mode="after")
    def _check(self) -> OperationConfig:
        if self.operation_class is OperationClass.UNRESTRICTED:
            if not self.route:
                raise ValueError(
                    "operation_class = unrestricted needs its route: at least one leg (sector, season, scatter_diagram or extreme_hs_m)"
                )
            return self
        if self.route:
            raise ValueError("route is given but operation_class = weather_restricted; allowed: route with unrestricted only")
        tpop = self.planned_operation_period_h
        if tpop is None:
            raise ValueError("operation_class = weather_restricted needs planned_operation_period_h [h]")
        if tpop > MAX_PLANNED_OPERATION_PERIOD_H:
            raise ValueError(
                f"planned_operation_period_h = {tpop:g} h exceeds the weather-restricted limit of {MAX_PLANNED_OPERATION_PERIOD_H:g} h; "
                "allowed: at most 72 h, or operation_class = unrestricted"
            )
        if self.forecast_level in MONITORED_LEVELS and tpop > MAX_MONITORED_OPERATION_PERIOD_H:
            raise ValueError(
                f"planned_operation_period_h = {tpop:g} h with forecast_level = {self.forecast_level.value}: the monitoring tables stop "
                f"at {MAX_MONITORED_OPERATION_PERIOD_H:g} h; allowed: at most 24 h, or forecast_level base, level_b or level_a"
            )
        tr = self.reference_period_h()
        assert tr is not None
        if tr > MAX_REFERENCE_PERIOD_H:
            raise ValueError(
                f"reference period T_R = T_POP + T_C = {tr:g} h (planned_operation_period_h = {tpop:g}, contingency_h = "
                f"{self.contingency_h if self.contingency_h is not None else 'null, i.e. T_POP'}) exceeds the weather-restricted "
                f"limit of {MAX_REFERENCE_PERIOD_H:g} h; allowed: T_R <= 96 h, or operation_class = unrestricted"
            )
        return self
