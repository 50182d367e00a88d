"""The operation class applied to the allowable sea states: weather-routing limits, or the route's design sea states checked.

Weather-restricted: at every peak period (and heading) of the operability analysis, the allowable Hs is the
operational limit OP_LIM and the weather-routing limit is OP_WF = alpha OP_LIM
(:mod:`~seafast.analyses.criteria.alpha_factor`), for the linear and the nonlinear allowable Hs alike.

Unrestricted: each route leg's design Hs (:mod:`~seafast.analyses.criteria.route_extremes`) is checked
against the allowable Hs at the analysis's peak periods within the leg's range sqrt(13 Hs) <= Tp <= sqrt(30 Hs)
(and over all its headings): the utilisation is the design Hs over the smallest allowable Hs there. The
nonlinear allowable Hs gives the verdict; a leg whose range holds no analysed peak period, or a nonlinear
search that did not converge in it, is ``not_assessed``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from enum import StrEnum

import numpy as np
from numpy.typing import ArrayLike, NDArray

from seafast.analyses.criteria.alpha_factor import WeatherRestriction, weather_restriction
from seafast.analyses.criteria.route_extremes import RouteDesignSeaState, route_design_sea_states
from seafast.config.modes import OperationClass
from seafast.config.operation import OperationConfig

__all__ = [
    "AllowableTable",
    "WeatherRoutingLimits",
    "RouteVerdict",
    "RouteCheck",
    "OperationPlan",
    "plan_operation",
    "weather_routing_limits",
    "route_checks",
]


@dataclass(frozen=True)
class AllowableTable:
    """The allowable Hs of an operability analysis as flat rows (one per heading and peak period).

    Attributes
    ----------
    heading_deg
        (n,) wave heading [deg] (180 = head seas, 90 = beam seas).
    peak_period_s
        (n,) Tp [s].
    hs_allowable_linear_m, hs_allowable_nonlinear_m
        (n,) allowable Hs [m] (NaN: not found).
    """

    heading_deg: NDArray[np.float64]
    peak_period_s: NDArray[np.float64]
    hs_allowable_linear_m: NDArray[np.float64]
    hs_allowable_nonlinear_m: NDArray[np.float64]

    @classmethod
    def of(cls, heading_deg: ArrayLike, peak_period_s: ArrayLike, hs_linear_m: ArrayLike, hs_nonlinear_m: ArrayLike) -> AllowableTable:
        """From four equally long sequences."""
        arrays = [np.asarray(a, dtype=float).ravel() for a in (heading_deg, peak_period_s, hs_linear_m, hs_nonlinear_m)]
        if len({a.size for a in arrays}) != 1:
            raise ValueError(f"AllowableTable: the columns have {[a.size for a in arrays]} rows; allowed: equal lengths")
        return cls(*arrays)


@dataclass(frozen=True)
class WeatherRoutingLimits:
    """OP_WF = alpha OP_LIM at every row of an allowable table.

    Attributes
    ----------
    restriction
        The weather restriction (periods, forecast level, table).
    table
        The allowable Hs (OP_LIM).
    alpha_linear, alpha_nonlinear
        (n,) alpha at the linear and nonlinear OP_LIM [-] (NaN below 1 m or where OP_LIM was not found).
    hs_forecast_limit_linear_m, hs_forecast_limit_nonlinear_m
        (n,) OP_WF [m].
    """

    restriction: WeatherRestriction
    table: AllowableTable
    alpha_linear: NDArray[np.float64]
    alpha_nonlinear: NDArray[np.float64]
    hs_forecast_limit_linear_m: NDArray[np.float64]
    hs_forecast_limit_nonlinear_m: NDArray[np.float64]


def weather_routing_limits(restriction: WeatherRestriction, table: AllowableTable) -> WeatherRoutingLimits:
    """The forecast limit OP_WF = alpha OP_LIM at every peak period and heading, linear and nonlinear."""
    a_lin = restriction.alpha(table.hs_allowable_linear_m)
    a_nl = restriction.alpha(table.hs_allowable_nonlinear_m)
    return WeatherRoutingLimits(restriction, table, a_lin, a_nl, a_lin * table.hs_allowable_linear_m, a_nl * table.hs_allowable_nonlinear_m)


class RouteVerdict(StrEnum):
    """A route leg's check: its design Hs within the allowable Hs over its peak-period range, or not, or not assessed."""

    PASS = "pass"
    FAIL = "fail"
    NOT_ASSESSED = "not_assessed"


@dataclass(frozen=True)
class RouteCheck:
    """One route leg's design sea state against the allowable Hs.

    Attributes
    ----------
    sea_state
        The leg's design sea state.
    peak_periods_s
        The analysed peak periods within its range [s].
    hs_allowable_linear_m, hs_allowable_nonlinear_m
        The smallest allowable Hs over them (and the headings) [m]; NaN when none (nonlinear: or not converged).
    governing_peak_period_s, governing_heading_deg
        Where the smallest nonlinear allowable Hs is [s, deg]; NaN when none.
    utilisation_linear, utilisation_nonlinear
        Design Hs over the allowable Hs [-].
    verdict
        From the nonlinear utilisation.
    """

    sea_state: RouteDesignSeaState
    peak_periods_s: tuple[float, ...]
    hs_allowable_linear_m: float
    hs_allowable_nonlinear_m: float
    governing_peak_period_s: float
    governing_heading_deg: float
    utilisation_linear: float
    utilisation_nonlinear: float
    verdict: RouteVerdict


def _route_check(state: RouteDesignSeaState, table: AllowableTable) -> RouteCheck:
    tol = 1e-9
    rows = np.flatnonzero((table.peak_period_s >= state.tp_min_s - tol) & (table.peak_period_s <= state.tp_max_s + tol))
    tps = tuple(sorted({float(t) for t in table.peak_period_s[rows]}))
    if rows.size == 0:
        nan = math.nan
        return RouteCheck(state, (), nan, nan, nan, nan, nan, nan, RouteVerdict.NOT_ASSESSED)
    lin, nl = table.hs_allowable_linear_m[rows], table.hs_allowable_nonlinear_m[rows]
    hs_lin = float(np.min(lin)) if not np.isnan(lin).any() else math.nan
    if np.isnan(nl).any():
        u_lin = state.design_hs_m / hs_lin
        return RouteCheck(state, tps, hs_lin, math.nan, math.nan, math.nan, u_lin, math.nan, RouteVerdict.NOT_ASSESSED)
    i = rows[int(np.argmin(nl))]
    hs_nl = float(table.hs_allowable_nonlinear_m[i])
    u_nl = state.design_hs_m / hs_nl
    verdict = RouteVerdict.PASS if u_nl <= 1.0 else RouteVerdict.FAIL
    return RouteCheck(
        state,
        tps,
        hs_lin,
        hs_nl,
        float(table.peak_period_s[i]),
        float(table.heading_deg[i]),
        state.design_hs_m / hs_lin,
        u_nl,
        verdict,
    )


def route_checks(sea_states: tuple[RouteDesignSeaState, ...], table: AllowableTable) -> tuple[RouteCheck, ...]:
    """Each route leg's design Hs against the smallest allowable Hs within its peak-period range."""
    return tuple(_route_check(s, table) for s in sea_states)


@dataclass(frozen=True)
class OperationPlan:
    """What a case's operation class needs before the allowable sea states are known.

    Attributes
    ----------
    operation
        The case's ``criteria.operation``.
    restriction
        Weather-restricted: its periods and alpha table; else None.
    route
        Unrestricted: each leg's design sea state; else empty.
    """

    operation: OperationConfig
    restriction: WeatherRestriction | None
    route: tuple[RouteDesignSeaState, ...]


def plan_operation(operation: OperationConfig) -> OperationPlan:
    """The weather restriction, or the route's design sea states (scatter diagrams read and fitted).

    Raises
    ------
    seafast.config.CaseError, ValueError
        A scatter diagram that cannot be read, or fitted (naming the key, the leg and the file).
    """
    if operation.operation_class is OperationClass.WEATHER_RESTRICTED:
        return OperationPlan(operation, weather_restriction(operation), ())
    return OperationPlan(operation, None, route_design_sea_states(operation))
