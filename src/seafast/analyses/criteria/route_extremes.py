"""The design sea states of an unrestricted transport: the 10-year monthly extreme per route sector and season.

For a leg given a scatter diagram of its months' 3-hour sea states (the format of ``seafast operability
--scatter``; each cell's Hs is its class mark), the Hs marginal is fitted with a 3-parameter Weibull
distribution, ``F(h) = 1 - exp(-((h - gamma) / beta)^k)``, by least squares on Weibull paper: the
empirical distribution at the classes' upper edges (half-way to the next class; the last class as wide as
the one below it), ``ln(-ln(1 - F))`` against the model's (scipy.stats.weibull_min, fitted with
scipy.optimize.least_squares). The extreme is the Hs exceeded once in N sea states,
``h_N = F^-1(1 - 1/N)``, with N the 3-hour sea states of the return period's months:
``N = years x 8 x (mean days of the leg's months)`` - a month of that season, the diagram's months taken
alike (the diagram pools them). A leg given the extreme Hs from the user's own extreme table takes it as is.

Each design Hs comes with the standard's range of peak periods, ``sqrt(13 Hs) <= Tp <= sqrt(30 Hs)``
(Hs in m, Tp in s).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from enum import StrEnum

import numpy as np
from numpy.typing import ArrayLike
from scipy.optimize import least_squares
from scipy.stats import weibull_min

from seafast.analyses.operability.scatter import ScatterDiagram, read_scatter_diagram
from seafast.config.operation import OperationConfig, RouteLegConfig

__all__ = [
    "SEA_STATE_DURATION_H",
    "TP_RANGE_COEFFICIENTS_S2_PER_M",
    "ExtremeMethod",
    "WeibullFit",
    "RouteDesignSeaState",
    "fit_weibull_hs",
    "sea_states_in_return_period",
    "design_tp_range_s",
    "route_design_sea_state",
    "route_design_sea_states",
]

SEA_STATE_DURATION_H = 3.0
"""Duration of one sea state of a scatter diagram [h]."""

TP_RANGE_COEFFICIENTS_S2_PER_M = (13.0, 30.0)
"""The peak-period range of a design Hs: 13 Hs <= Tp^2 <= 30 Hs [s^2/m]."""

_DAYS_IN_MONTH = (31.0, 28.25, 31.0, 30.0, 31.0, 30.0, 31.0, 31.0, 30.0, 31.0, 30.0, 31.0)


class ExtremeMethod(StrEnum):
    """Where a leg's design Hs came from."""

    WEIBULL_3P = "weibull_3p"
    EXTREME_TABLE = "extreme_table"


@dataclass(frozen=True)
class WeibullFit:
    """A 3-parameter Weibull distribution of Hs.

    Attributes
    ----------
    shape
        k [-].
    location_m, scale_m
        gamma and beta [m].
    rms_residual
        Root-mean-square residual of the fit on Weibull paper, ``ln(-ln(1 - F))`` [-].
    points
        How many points of the empirical distribution were fitted.
    """

    shape: float
    location_m: float
    scale_m: float
    rms_residual: float
    points: int

    def return_value_m(self, sea_states: float) -> float:
        """The Hs exceeded once in ``sea_states`` sea states, F^-1(1 - 1/N) [m]."""
        return float(weibull_min.isf(1.0 / float(sea_states), self.shape, loc=self.location_m, scale=self.scale_m))


def _class_edges_and_cdf(hs_m: ArrayLike, occurrence: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """The upper edges of the distinct Hs classes [m] and the cumulative occurrence there (normalised)."""
    hs, w = np.asarray(hs_m, dtype=float), np.asarray(occurrence, dtype=float)
    classes = np.unique(hs[w > 0])
    if classes.size < 4:
        raise ValueError(
            f"the scatter diagram has {classes.size} Hs classes with a nonzero occurrence; allowed: at least 4 for a "
            "3-parameter Weibull fit (or give the leg's extreme_hs_m)"
        )
    mass = np.array([w[hs == h].sum() for h in classes])
    cdf = np.cumsum(mass) / mass.sum()
    edges = np.append(0.5 * (classes[1:] + classes[:-1]), classes[-1] + 0.5 * (classes[-1] - classes[-2]))
    return edges, cdf


def fit_weibull_hs(hs_m: ArrayLike, occurrence: ArrayLike) -> WeibullFit:
    """Fit a 3-parameter Weibull distribution to the Hs marginal of binned sea states.

    Parameters
    ----------
    hs_m
        (n,) the cells' Hs [m] (class marks; cells of equal Hs are one class).
    occurrence
        (n,) their occurrences (any unit, >= 0).

    Raises
    ------
    ValueError
        Fewer than 4 classes, or the least-squares fit failed (its message).
    """
    edges, cdf = _class_edges_and_cdf(hs_m, occurrence)
    keep = (cdf > 0) & (cdf < 1.0 - 1e-12)
    x, y = edges[keep], np.log(-np.log1p(-cdf[keep]))
    # each point weighted by the inverse of its standard deviation on Weibull paper, were F the fraction of a
    # sample: sd(F) = sqrt(F (1 - F) / n), times dy/dF = 1 / ((1 - F) (-ln(1 - F))) (n is common to all)
    f = cdf[keep]
    weight = -np.log1p(-f) * np.sqrt((1.0 - f) / f)
    # start: a 2-parameter fit on Weibull paper (location 0), a straight line
    slope, intercept = np.polyfit(np.log(x), y, 1)
    k0 = max(float(slope), 0.3)
    p0 = np.array([k0, 0.0, math.exp(-intercept / k0)])

    def residual(p: np.ndarray) -> np.ndarray:
        return weight * (np.log(-weibull_min.logsf(x, p[0], loc=p[1], scale=p[2])) - y)

    lower, upper = [0.1, -x[0], 1e-6], [20.0, x[0] * (1.0 - 1e-9), np.inf]
    p0[1] = min(max(p0[1], lower[1]), upper[1])
    sol = least_squares(residual, p0, bounds=(lower, upper), x_scale=[1.0, x[0], p0[2]], xtol=1e-14, ftol=1e-14, gtol=1e-14)
    if not sol.success:
        raise ValueError(f"the 3-parameter Weibull fit of the Hs marginal failed: {sol.message}")
    rms = float(np.sqrt(np.mean((sol.fun / weight) ** 2)))
    return WeibullFit(float(sol.x[0]), float(sol.x[1]), float(sol.x[2]), rms, int(x.size))


def sea_states_in_return_period(months: tuple[int, ...], return_period_years: float = 10.0) -> float:
    """N: the 3-hour sea states of one month of the leg's season over the return period [-]."""
    if not months:
        raise ValueError("months: allowed at least one calendar month 1-12")
    days = float(np.mean([_DAYS_IN_MONTH[m - 1] for m in months]))
    return float(return_period_years) * days * 24.0 / SEA_STATE_DURATION_H


def design_tp_range_s(design_hs_m: float) -> tuple[float, float]:
    """The standard's peak periods of a design Hs, sqrt(13 Hs) and sqrt(30 Hs) [s]."""
    lo, hi = TP_RANGE_COEFFICIENTS_S2_PER_M
    return math.sqrt(lo * design_hs_m), math.sqrt(hi * design_hs_m)


@dataclass(frozen=True)
class RouteDesignSeaState:
    """The design sea state of one route leg.

    Attributes
    ----------
    sector, season
        The leg's labels.
    design_hs_m
        The 10-year (``return_period_years``) monthly extreme Hs [m].
    tp_min_s, tp_max_s
        Its peak-period range [s].
    method
        Fitted (``weibull_3p``) or given (``extreme_table``).
    sea_states
        N of the fit [-] (NaN when given).
    fit
        The Weibull fit, or None when given.
    source
        The scatter diagram's file name, or ``extreme table``.
    """

    sector: str
    season: str
    design_hs_m: float
    tp_min_s: float
    tp_max_s: float
    method: ExtremeMethod
    sea_states: float
    fit: WeibullFit | None
    source: str


def route_design_sea_state(
    leg: RouteLegConfig, return_period_years: float = 10.0, diagram: ScatterDiagram | None = None
) -> RouteDesignSeaState:
    """The design sea state of one leg (its scatter diagram read unless given)."""
    if leg.extreme_hs_m is not None:
        lo, hi = design_tp_range_s(leg.extreme_hs_m)
        return RouteDesignSeaState(
            leg.sector, leg.season, leg.extreme_hs_m, lo, hi, ExtremeMethod.EXTREME_TABLE, math.nan, None, "extreme table"
        )
    assert leg.scatter_diagram is not None
    if diagram is None:
        diagram = read_scatter_diagram(leg.scatter_diagram, option="criteria.operation.route.scatter_diagram")
    try:
        fit = fit_weibull_hs(diagram.significant_height_m, diagram.occurrence)
    except ValueError as exc:
        raise ValueError(f"criteria.operation.route leg '{leg.sector}, {leg.season}' ({diagram.source}): {exc}") from None
    n = sea_states_in_return_period(leg.months, return_period_years)
    hs = fit.return_value_m(n)
    lo, hi = design_tp_range_s(hs)
    return RouteDesignSeaState(leg.sector, leg.season, hs, lo, hi, ExtremeMethod.WEIBULL_3P, n, fit, diagram.source)


def route_design_sea_states(operation: OperationConfig) -> tuple[RouteDesignSeaState, ...]:
    """The design sea state of every leg of an unrestricted operation's route.

    Raises
    ------
    seafast.config.CaseError
        A scatter diagram that cannot be read (naming the key and the file).
    ValueError
        A fit that cannot be made (naming the leg).
    """
    return tuple(route_design_sea_state(leg, operation.return_period_years) for leg in operation.route)
