"""Solvers of the cargo's axial stick-slip on friction (docs/axial.md).

* :func:`solve_axial_hbm` - harmonic balance with AFT over a Jenkins element (the default).
* :func:`solve_axial_time_domain` - event-driven rigid-Coulomb reference (no tangential stiffness).
* :func:`critical_friction_coefficient` - the stick statics: below which coefficient the cargo slides.
* :func:`lock_range_m` - the positions where the cargo can stay locked (shakedown off ``u = 0``).

Both solvers return an :class:`AxialResponse`; non-convergence is reported in it, never raised.
"""

from seafast.solvers.axial.harmonic_balance import AxialHBMOptions, axial_time_samples, solve_axial_hbm
from seafast.solvers.axial.jenkins import JenkinsPeriod, clamp_prefix, march_jenkins
from seafast.solvers.axial.response import (
    AxialResponse,
    AxialWarning,
    LockCheck,
    critical_friction_coefficient,
    lock_range_m,
    periodic_interpolation,
    static_response,
)
from seafast.solvers.axial.time_domain import solve_axial_time_domain

__all__ = [
    "AxialHBMOptions",
    "AxialResponse",
    "AxialWarning",
    "JenkinsPeriod",
    "LockCheck",
    "axial_time_samples",
    "clamp_prefix",
    "critical_friction_coefficient",
    "lock_range_m",
    "march_jenkins",
    "periodic_interpolation",
    "solve_axial_hbm",
    "solve_axial_time_domain",
    "static_response",
]
