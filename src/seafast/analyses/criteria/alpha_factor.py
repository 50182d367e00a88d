"""The alpha factor of a weather-restricted operation: the forecast limit OP_WF = alpha OP_LIM.

A weather-restricted operation starts on a forecast that must stay at or below OP_WF over its reference
period; the alpha factor (at most 1) allows for the forecast's uncertainty. The standard's tables for waves
(DNV-OS-H101, October 2011, Sec.4 B700, Tables 4-1 to 4-5; carried into DNV-ST-N001's weather-restricted
operations) give alpha by the planned operation period T_POP (rows: T_POP <= 12, 24, 36, 48, 72 h; the
monitoring tables 4, 12, 24 h) and the design wave height, OP_LIM (columns Hs = 1, 2, 4, >= 6 m).

Reading a table (:func:`alpha_factor`): the row is the first whose bound holds (T_POP <= bound: rows are
steps, no interpolation between them is stated); along the row alpha is interpolated linearly in Hs between
the columns, the last column's value from 6 m up. Below 1 m the standard decides case by case: no value.

The values were transcribed from a published verbatim transcription of DNV-OS-H101 (2011) Sec.4 (see
docs/criteria.md section 12); they were not compared with DNV-ST-N001's own tables.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType

import numpy as np
from numpy.typing import ArrayLike, NDArray

from seafast.config.modes import ForecastLevel
from seafast.config.operation import MAX_REFERENCE_PERIOD_H, OperationConfig

__all__ = [
    "DESIGN_HS_COLUMNS_M",
    "ALPHA_TABLES",
    "AlphaTable",
    "WeatherRestriction",
    "alpha_factor",
    "weather_restriction",
]

DESIGN_HS_COLUMNS_M = (1.0, 2.0, 4.0, 6.0)
"""The tables' design wave heights (OP_LIM) [m]: 1, 2, 4 and >= 6 m."""


@dataclass(frozen=True)
class AlphaTable:
    """One alpha-factor table for waves.

    Attributes
    ----------
    name
        The table's number and title in the standard.
    forecast_level
        The forecast and monitoring it applies to.
    rows
        ``(T_POP bound [h], alphas at DESIGN_HS_COLUMNS_M [-])``, bounds ascending: the row applies to
        T_POP <= its bound (and above the previous bound).
    """

    name: str
    forecast_level: ForecastLevel
    rows: tuple[tuple[float, tuple[float, float, float, float]], ...]

    @property
    def max_period_h(self) -> float:
        """The last row's bound: the longest planned operation period the table covers [h]."""
        return self.rows[-1][0]


_SOURCE = "DNV-OS-H101 (2011) Sec.4 B700"

ALPHA_TABLES: Mapping[ForecastLevel, AlphaTable] = MappingProxyType(
    {
        ForecastLevel.BASE: AlphaTable(
            f"{_SOURCE} Table 4-1 (base case)",
            ForecastLevel.BASE,
            (
                (12.0, (0.65, 0.76, 0.79, 0.80)),
                (24.0, (0.63, 0.73, 0.76, 0.78)),
                (36.0, (0.62, 0.71, 0.73, 0.76)),
                (48.0, (0.60, 0.68, 0.71, 0.74)),
                (72.0, (0.55, 0.63, 0.68, 0.72)),
            ),
        ),
        ForecastLevel.LEVEL_B: AlphaTable(
            f"{_SOURCE} Table 4-2 (Level B forecast)",
            ForecastLevel.LEVEL_B,
            (
                (12.0, (0.68, 0.80, 0.83, 0.84)),
                (24.0, (0.66, 0.77, 0.80, 0.82)),
                (36.0, (0.65, 0.75, 0.77, 0.80)),
                (48.0, (0.63, 0.71, 0.75, 0.78)),
                (72.0, (0.58, 0.66, 0.71, 0.76)),
            ),
        ),
        ForecastLevel.LEVEL_A: AlphaTable(
            f"{_SOURCE} Table 4-3 (Level A forecast, meteorologist at site)",
            ForecastLevel.LEVEL_A,
            (
                (12.0, (0.72, 0.84, 0.87, 0.88)),
                (24.0, (0.69, 0.80, 0.84, 0.86)),
                (36.0, (0.68, 0.78, 0.80, 0.84)),
                (48.0, (0.66, 0.75, 0.78, 0.81)),
                (72.0, (0.61, 0.69, 0.75, 0.79)),
            ),
        ),
        ForecastLevel.MONITORING: AlphaTable(
            f"{_SOURCE} Table 4-4 (forecast calibrated by wave monitoring)",
            ForecastLevel.MONITORING,
            (
                (4.0, (0.90, 0.95, 1.00, 1.00)),
                (12.0, (0.72, 0.84, 0.87, 0.88)),
                (24.0, (0.66, 0.77, 0.80, 0.82)),
            ),
        ),
        ForecastLevel.MONITORING_LEVEL_A: AlphaTable(
            f"{_SOURCE} Table 4-5 (wave monitoring and Level A forecast, meteorologist at site)",
            ForecastLevel.MONITORING_LEVEL_A,
            (
                (4.0, (0.90, 0.95, 1.00, 1.00)),
                (12.0, (0.78, 0.91, 0.95, 0.96)),
                (24.0, (0.72, 0.84, 0.87, 0.90)),
            ),
        ),
    }
)
"""The standard's alpha-factor tables for waves, by forecast level (read-only)."""


def alpha_factor(planned_operation_period_h: float, design_hs_m: float, forecast_level: ForecastLevel = ForecastLevel.BASE) -> float:
    """The alpha factor at a planned operation period and design wave height [-].

    Parameters
    ----------
    planned_operation_period_h
        T_POP [h], > 0 and at most the table's last row (72 h; 24 h for the monitoring tables).
    design_hs_m
        The design wave height OP_LIM [m], >= 1 m (below it the standard decides case by case).
    forecast_level
        Which table.

    Raises
    ------
    ValueError
        A period outside the table or a design Hs below 1 m or not finite, naming the value and what is allowed.
    """
    table = ALPHA_TABLES[ForecastLevel(forecast_level)]
    tpop, hs = float(planned_operation_period_h), float(design_hs_m)
    if not (math.isfinite(tpop) and 0.0 < tpop <= table.max_period_h):
        raise ValueError(
            f"planned operation period T_POP = {tpop:g} h is outside {table.name}; allowed: 0 < T_POP <= {table.max_period_h:g} h"
        )
    if not (math.isfinite(hs) and hs >= DESIGN_HS_COLUMNS_M[0]):
        raise ValueError(
            f"design wave height OP_LIM = {hs:g} m is below the alpha tables' first column; allowed: Hs >= "
            f"{DESIGN_HS_COLUMNS_M[0]:g} m (below it the standard decides case by case)"
        )
    alphas = next(a for bound, a in table.rows if tpop <= bound)
    return float(np.interp(hs, DESIGN_HS_COLUMNS_M, alphas))


@dataclass(frozen=True)
class WeatherRestriction:
    """A weather-restricted operation: its periods, forecast level and alpha table.

    Attributes
    ----------
    planned_operation_period_h, contingency_h, reference_period_h
        T_POP, T_C and T_R = T_POP + T_C [h].
    forecast_level
        The forecast and monitoring.
    table
        The alpha table it reads.
    """

    planned_operation_period_h: float
    contingency_h: float
    reference_period_h: float
    forecast_level: ForecastLevel
    table: AlphaTable

    def alpha(self, design_hs_m: ArrayLike) -> NDArray[np.float64]:
        """alpha at each design Hs (OP_LIM) [-]; NaN where OP_LIM is below 1 m or not a number."""
        hs = np.atleast_1d(np.asarray(design_hs_m, dtype=float))
        out = np.full(hs.shape, np.nan)
        ok = np.isfinite(hs) & (hs >= DESIGN_HS_COLUMNS_M[0])
        out[ok] = [alpha_factor(self.planned_operation_period_h, h, self.forecast_level) for h in hs[ok]]
        return out

    def forecast_limit_m(self, operational_limit_hs_m: ArrayLike) -> NDArray[np.float64]:
        """OP_WF = alpha OP_LIM at each OP_LIM [m]; NaN where alpha has no value."""
        hs = np.atleast_1d(np.asarray(operational_limit_hs_m, dtype=float))
        return self.alpha(hs) * hs


def weather_restriction(operation: OperationConfig) -> WeatherRestriction:
    """The weather restriction of a case's ``criteria.operation`` (weather-restricted).

    Raises
    ------
    ValueError
        The operation is not weather-restricted, or its periods are outside the standard's limits.
    """
    tpop, tr = operation.planned_operation_period_h, operation.reference_period_h()
    if tpop is None or tr is None or operation.route:
        raise ValueError(
            f"criteria.operation.operation_class = {operation.operation_class.value}: no weather restriction; "
            "allowed: weather_restricted with planned_operation_period_h"
        )
    table = ALPHA_TABLES[operation.forecast_level]
    if tpop > table.max_period_h or tr > MAX_REFERENCE_PERIOD_H:
        raise ValueError(
            f"T_POP = {tpop:g} h, T_R = {tr:g} h: outside {table.name}; allowed T_POP <= {table.max_period_h:g} h, "
            f"T_R <= {MAX_REFERENCE_PERIOD_H:g} h"
        )
    return WeatherRestriction(tpop, tr - tpop, tr, operation.forecast_level, table)
