"""Operability: allowable significant wave heights per peak period, linear and nonlinear.

* :mod:`~seafast.analyses.operability.allowable` - the allowable Hs per Tp (closed forms; bracketing with design waves).
* :mod:`~seafast.analyses.operability.scatter` - a wave scatter diagram's share of sea states within the limits.
* :mod:`~seafast.analyses.operability.headings` - the allowable Hs per heading and the governing heading.

Its files (operability.csv / .nc, the chart): :mod:`seafast.output.operability`.
Theory, rules and verification: ``docs/operability.md``.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from seafast.lazy import lazy_exports

if TYPE_CHECKING:
    from seafast.analyses.operability.allowable import (
        GOVERNING,
        OperabilityPoint,
        OperabilityResult,
        OperabilitySettings,
        allowable_sea_states,
    )
    from seafast.analyses.operability.headings import (
        GoverningHeading,
        HeadingOperability,
        HeadingOperabilityResult,
        allowable_per_heading,
        case_at_heading,
    )

# imported on first use (seafast.lazy), so the command line's parser does not load numpy/xarray
EXPORTS = {
    "seafast.analyses.operability.allowable": (
        "GOVERNING",
        "OperabilityPoint",
        "OperabilityResult",
        "OperabilitySettings",
        "allowable_sea_states",
    ),
    "seafast.analyses.operability.headings": (
        "GoverningHeading",
        "HeadingOperability",
        "HeadingOperabilityResult",
        "allowable_per_heading",
        "case_at_heading",
    ),
}
__all__ = [
    "GOVERNING",
    "OperabilityPoint",
    "OperabilityResult",
    "OperabilitySettings",
    "allowable_sea_states",
    "GoverningHeading",
    "HeadingOperability",
    "HeadingOperabilityResult",
    "allowable_per_heading",
    "case_at_heading",
]
lazy_exports(__name__, EXPORTS)
