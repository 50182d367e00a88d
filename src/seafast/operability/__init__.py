"""Operability: allowable significant wave heights per peak period, linear and nonlinear (issue 15).

* :mod:`~seafast.operability.allowable` - the allowable Hs per Tp (closed forms; bracketing with design waves).
* :mod:`~seafast.operability.scatter` - a wave scatter diagram's share of sea states within the limits.
* :mod:`~seafast.operability.outputs` - operability.csv / .nc and the chart.
* :mod:`~seafast.operability.cli` - the ``seafast operability`` command.

Theory, rules and verification: ``docs/operability.md``.
"""

from seafast.operability.allowable import (
    GOVERNING,
    OperabilityPoint,
    OperabilityResult,
    OperabilitySettings,
    allowable_sea_states,
)

__all__ = ["GOVERNING", "OperabilityPoint", "OperabilityResult", "OperabilitySettings", "allowable_sea_states"]
