"""The solver modes, as string enums shared by the case schema and the solvers.

Each is a :class:`enum.StrEnum`: a member equals its value (``SolverMethod.HBM == "hbm"``), so the
case file's YAML strings validate to members and the results store the same text they always did.
The case schema (:mod:`seafast.config.schema`) types its keys with them, the solvers take and compare
them (``options.formulation is Formulation.CONDENSED``); nothing compares a mode as a bare string.
This module imports nothing (the lowest floor: the solvers import it, it imports no solver).
"""

from __future__ import annotations

from enum import StrEnum

__all__ = [
    "SolverMethod",
    "Formulation",
    "ContactLawKind",
    "NonlinearSolver",
    "TimeDomainStart",
    "HullCargoCoupling",
    "MotionCoupling",
    "OperationClass",
    "ForecastLevel",
    "DesignFormat",
    "ContactSurface",
]


class SolverMethod(StrEnum):
    """How the nonlinear (unilateral-saddle) periodic response is solved (``solver.method``).

    ``HBM``: harmonic balance with AFT (:func:`seafast.solvers.hbm.solve_hbm`); with ``solver.harmonics``
    unset its converged limit (every harmonic) is computed in closed form by exact-event shooting where the
    contact law is exact; ``QUASI_STATIC``: the exact-contact quasi-static reference; ``TIME_DOMAIN``: the
    exact-contact time-domain reference (:mod:`seafast.solvers.references`); ``SHOOTING``: exact-event
    shooting on the piecewise-linear contact problem (:func:`seafast.solvers.shooting.solve_shooting`).
    """

    HBM = "hbm"
    QUASI_STATIC = "quasi_static"
    TIME_DOMAIN = "time_domain"
    SHOOTING = "shooting"


class Formulation(StrEnum):
    """Which unknowns a solver carries (``solver.formulation``; the time-domain reference's too).

    ``CONDENSED``: every saddle bilateral in the linear part, the problem condensed onto the saddle
    compressions; ``FULL``: all cargo DOFs, the compression-only saddle parts as the contact force.
    """

    CONDENSED = "condensed"
    FULL = "full"


class ContactLawKind(StrEnum):
    """The saddle contact law (``solver.contact_law``; :class:`seafast.solvers.contact.ContactLaw`).

    ``TANH``: the source's C1 regularisation (pulls slightly after separation); ``SOFTPLUS``: smooth and
    never negative; ``EXACT``: ``k max(delta, 0)``.
    """

    TANH = "tanh"
    SOFTPLUS = "softplus"
    EXACT = "exact"


class NonlinearSolver(StrEnum):
    """The harmonic balance's nonlinear solver (``solver.nonlinear_solver``).

    ``NEWTON``: the globalised semi-smooth Newton (:mod:`seafast.solvers.newton`); ``HYBR``: MINPACK's
    Powell hybrid method (``scipy.optimize.root``), as the source.
    """

    NEWTON = "newton"
    HYBR = "hybr"


class TimeDomainStart(StrEnum):
    """The state a time-domain reference starts from at t = 0 (``solver.time_domain_start``: linear or hbm).

    ``LINEAR``
        The linear periodic solution (every saddle bilateral): displacement and velocity at t = 0.
        The default of both formulations.
    ``HBM``
        The harmonic balance's solution with the case's settings; the reference is then started from it
        as from any ``GIVEN`` solution (:func:`seafast.solvers.solve_periodic` solves it first).
    ``QUASI_STATIC``
        The exact-contact quasi-static state at t = 0, velocity from the quasi-static states at
        -dt and +dt (the full-DOF formulation's former start; not a case key).
    ``GIVEN``
        A given periodic solution (e.g. the harmonic balance's): its displacement and velocity at
        t = 0; the orbit reached is compared with it (what the orbit record of a ``HBM`` start says).
    """

    LINEAR = "linear"
    HBM = "hbm"
    QUASI_STATIC = "quasi_static"
    GIVEN = "given"


class HullCargoCoupling(StrEnum):
    """Whether the cargo's saddle forces load the hull girder (``vessel.coupling``).

    ``ONE_WAY``: the hull moves the cargo, the cargo's weight is spread on the hull (the source's);
    ``TWO_WAY``: the deck under the saddles and the cargo are solved together (:mod:`seafast.coupling`).
    """

    ONE_WAY = "one_way"
    TWO_WAY = "two_way"


class MotionCoupling(StrEnum):
    """Which rigid-body motions the vertical analysis uses (``vessel.motion_coupling``).

    ``HEAVE_PITCH``: the 2-DOF heave-pitch solution (the source's model); ``SURGE_HEAVE_PITCH``: coupled
    with surge, when the hydrodynamic data hold it (docs/axial.md).
    """

    HEAVE_PITCH = "heave_pitch"
    SURGE_HEAVE_PITCH = "surge_heave_pitch"


class OperationClass(StrEnum):
    """How the transport's design sea state is set (``criteria.operation.operation_class``; docs/criteria.md).

    ``WEATHER_RESTRICTED``: a planned operation period within the standard's limit (72 h), started on a
    weather forecast: the operational limit OP_LIM is reduced by the alpha factor to the forecast limit
    OP_WF = alpha OP_LIM; ``UNRESTRICTED``: the design sea state is the route's 10-year monthly extreme,
    per route sector and season.
    """

    WEATHER_RESTRICTED = "weather_restricted"
    UNRESTRICTED = "unrestricted"


class ForecastLevel(StrEnum):
    """The weather forecast and monitoring a weather-restricted operation relies on (``criteria.operation.forecast_level``).

    Each selects one of the standard's alpha-factor tables for waves (DNV-OS-H101, 2011, Sec.4 B700):
    ``BASE`` Table 4-1 (one forecast), ``LEVEL_B`` Table 4-2, ``LEVEL_A`` Table 4-3 (a meteorologist
    at site), ``MONITORING`` Table 4-4 (the forecast calibrated by wave monitoring; planned periods up to
    24 h), ``MONITORING_LEVEL_A`` Table 4-5 (monitoring and a meteorologist at site; up to 24 h).
    """

    BASE = "base"
    LEVEL_B = "level_b"
    LEVEL_A = "level_a"
    MONITORING = "monitoring"
    MONITORING_LEVEL_A = "monitoring_level_a"


class DesignFormat(StrEnum):
    """How ``seafast criteria`` factors its load effects and resistances (``criteria.design.format``).

    ``ALLOWABLE_STRESS``: the unfactored load effects against allowable values (the cargo steel's yield times
    ``criteria.design.allowable_stress_factor``); ``LRFD``: the ULS combinations of permanent and environmental load
    factors against the yield over the material factor (docs/criteria.md).
    """

    ALLOWABLE_STRESS = "allowable_stress"
    LRFD = "lrfd"


class ContactSurface(StrEnum):
    """The materials in contact between the cargo and its saddles (``criteria.friction.contact``).

    ``STEEL_ON_STEEL``: no friction may be counted; ``STEEL_ON_TIMBER`` and ``STEEL_ON_RUBBER``: friction may be
    counted, from ``seafastening.friction_coefficient``, reduced by the vertical acceleration (docs/criteria.md).
    """

    STEEL_ON_STEEL = "steel_on_steel"
    STEEL_ON_TIMBER = "steel_on_timber"
    STEEL_ON_RUBBER = "steel_on_rubber"
