"""How a nonlinear solve ended, as typed values (the human-readable account is the ``message``).

Every solver that returns a :class:`~seafast.solvers.periodic.PeriodicResponse` sets its
``outcome`` (one :class:`SolverOutcome`) and its ``warnings`` (a tuple of
:class:`SolverWarning`). The CLI, the results (``solver_outcome`` and ``solver_warning`` in
``results.nc``) and the report read these; nothing decides anything from the message text.
The values (``"converged"``, ...) are what ``results.nc`` stores.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum, StrEnum

from seafast.config.modes import TimeDomainStart
from seafast.solvers.newton import NewtonStop

__all__ = ["SolverOutcome", "SolverWarning", "OrbitRecord", "HBMStart", "HBMRoute", "HBMPath"]


class SolverOutcome(Enum):
    """How a solve ended.

    ``CONVERGED``
        The direct solve met its tolerance (harmonic balance), the exact active-set solution
        (quasi-static reference), the periodic steady state (time domain), or the direct linear
        solve.
    ``CONVERGED_BY_CONTINUATION``
        Harmonic balance: the direct solve failed and a continuation (in the contact law's
        sharpness, or in the excitation amplitude) reached the requested problem.
    ``NOT_CONVERGED``
        Harmonic balance: neither the direct solve nor any continuation met the tolerance; the
        best iterate is returned with its residual.
    ``NOT_PERIODIC``
        Time-domain reference: no periodic steady state within ``max_periods`` (a motion that
        wanders, is chaotic, or repeats only after several periods). The 3-D cradle harmonic
        balance: no H converged and the march of its correction system in time settled on no state
        repeating every wave period (its ``march.periodicity`` says which: a subharmonic or none).
    ``CONVERGED_SUBHARMONIC``
        The 3-D cradle's exact-event shooting: no stable orbit repeats every wave period, and the flow settles on
        one repeating every ``period_multiple`` (2 to 6) wave periods, found to the tolerance and stable; the
        response is that orbit over its whole period (``period_multiple`` wave periods), its maxima over it.
    ``CONVERGED_BY_TIME_MARCH``
        The 3-D cradle on frictional pads: the harmonic balance did not converge and the periodic steady state is
        the time march's (:mod:`seafast.solvers.cradle_friction_march`): periodic to its tolerance, and its peaks
        agree with a march at half the step within its step tolerance (the residual is that step error).
    ``OTHER_ORBIT``
        Time-domain reference started on a given periodic solution (e.g. the harmonic balance's):
        it reached a periodic steady state, but not the start's (the start's orbit is unstable,
        or not a solution of the same model). The numbers are the orbit reached; the
        :class:`OrbitRecord` says how far it is from the start's.
    """

    CONVERGED = "converged"
    CONVERGED_BY_CONTINUATION = "converged_by_continuation"
    NOT_CONVERGED = "not_converged"
    NOT_PERIODIC = "not_periodic"
    OTHER_ORBIT = "other_orbit"
    CONVERGED_SUBHARMONIC = "converged_subharmonic"
    CONVERGED_BY_TIME_MARCH = "converged_by_time_march"

    @property
    def converged(self) -> bool:
        """Whether the result meets its solver's tolerance (its numbers can be used).

        ``OTHER_ORBIT`` counts: the periodic state reached is a solution; that it is not the
        start's is reported by the outcome itself (the CLI and the report warn); so does ``CONVERGED_SUBHARMONIC``
        (the response repeats every ``period_multiple`` wave periods: the CLI warns).
        """
        return self in (
            SolverOutcome.CONVERGED,
            SolverOutcome.CONVERGED_BY_CONTINUATION,
            SolverOutcome.OTHER_ORBIT,
            SolverOutcome.CONVERGED_SUBHARMONIC,
            SolverOutcome.CONVERGED_BY_TIME_MARCH,
        )


class SolverWarning(Enum):
    """A converged result that needs a second look.

    ``HARMONICS_ABOVE_H_IGNORED``
        Harmonic balance: the excitation has nonzero harmonics above ``harmonics`` (H); they
        were dropped. Raise ``solver.harmonics``.
    ``QUASI_STATICS_QUESTIONABLE``
        Quasi-static reference: ``H_eff omega / omega_1`` exceeds
        :data:`~seafast.solvers.references.QUASI_STATIC_RATIO_LIMIT` (the cargo's dynamics
        matter); use the harmonic balance or the time-domain reference.
    ``TOO_FEW_HARMONICS``
        Harmonic balance: the estimated error of a saddle's peak force from the harmonics left
        out (``truncation_error``) exceeds ``truncation_tolerance`` (a fixed ``solver.harmonics``
        too small, or the adaptive choice stopped at ``max_harmonics``).
    """

    HARMONICS_ABOVE_H_IGNORED = "harmonics_above_h_ignored"
    QUASI_STATICS_QUESTIONABLE = "quasi_statics_questionable"
    TOO_FEW_HARMONICS = "too_few_harmonics"

    @property
    def description(self) -> str:
        """One line for people (report titles, CLI)."""
        return _DESCRIPTIONS[self]


_DESCRIPTIONS = {
    SolverWarning.HARMONICS_ABOVE_H_IGNORED: "excitation harmonics above H were ignored (raise solver.harmonics)",
    SolverWarning.QUASI_STATICS_QUESTIONABLE: "quasi-static assumption questionable (cargo dynamics matter)",
    SolverWarning.TOO_FEW_HARMONICS: "too few harmonics: the peak forces may move by more than solver.truncation_tolerance "
    "(leave solver.harmonics unset, or raise it / solver.max_harmonics)",
}


@dataclass(frozen=True)
class OrbitRecord:
    """Where a time-domain reference started and what it reached.

    Attributes
    ----------
    start
        The start (:class:`~seafast.config.modes.TimeDomainStart`: ``LINEAR``, ``QUASI_STATIC`` or ``GIVEN``;
        a harmonic balance start is ``GIVEN``, its ``start_method`` ``"hbm"``).
    start_method
        What the start came from: ``"linear"``, ``"quasi_static"``, or the given solution's
        ``method`` (``"hbm"``, ...).
    periodic
        Whether a periodic steady state (period T) was reached within the periods allowed.
    periods
        Periods integrated.
    period_change
        Last period-to-period change of the saddle forces, over the largest force seen [-].
    distance_from_start
        ``GIVEN`` only (else None): RMS over the last period and the saddles of the saddle-force
        difference between the orbit reached and the start's orbit, through the start's harmonics,
        over the RMS of the start's saddle forces [-] (both with the exact law, on the reference's
        time grid; :func:`seafast.solvers.references.orbit.orbit_distance`).
    same_as_start
        ``GIVEN`` and periodic only (else None): ``distance_from_start <= orbit_tolerance``.
    orbit_tolerance
        The distance below which two periodic states are the same orbit [-].
    """

    start: TimeDomainStart
    start_method: str
    periodic: bool
    periods: int
    period_change: float
    distance_from_start: float | None
    same_as_start: bool | None
    orbit_tolerance: float


class HBMStart(StrEnum):
    """Where a harmonic balance's direct solve started.

    ``LINEAR``
        The linear (bilateral-saddle) solution.
    ``PREDICTOR``
        The quasi-static exact-contact predictor (the better of the two is taken when no start is given).
    ``GIVEN``
        A start the caller gave (``initial_compression_m``: e.g. a neighbouring solution).
    ``MARCH``
        The periodic march of the adaptive choice of H (:mod:`seafast.solvers.hbm.harmonics`), or of the 3-D
        cargo's correction system (:mod:`seafast.solvers.cradle_march`), projected on the harmonics solved for.
    ``PREVIOUS_HARMONICS``
        The solution at the previous, smaller H of the adaptive refinement.
    """

    LINEAR = "linear"
    PREDICTOR = "quasi_static_predictor"
    GIVEN = "given"
    MARCH = "periodic_march"
    PREVIOUS_HARMONICS = "previous_harmonics"


class HBMRoute(StrEnum):
    """Which solve of the harmonic balance's fallback chain reached the answer.

    ``DIRECT``: the direct solve; ``DIRECT_FROM_LINEAR``: the second direct solve, from the linear solution;
    ``KAPPA_CONTINUATION``: the continuation in the contact law's sharpness; ``AMPLITUDE_CONTINUATION``: the
    continuation in the dynamic excitation amplitude; ``NONE``: none converged.
    """

    DIRECT = "direct"
    DIRECT_FROM_LINEAR = "direct_from_linear"
    KAPPA_CONTINUATION = "kappa_continuation"
    AMPLITUDE_CONTINUATION = "amplitude_continuation"
    NONE = "none"

    @property
    def by_continuation(self) -> bool:
        """Whether the route is a continuation (the outcome ``CONVERGED_BY_CONTINUATION``)."""
        return self in (HBMRoute.KAPPA_CONTINUATION, HBMRoute.AMPLITUDE_CONTINUATION)


@dataclass(frozen=True)
class HBMPath:
    """How a harmonic balance solve went, as typed values (the ``message`` says it in words).

    Attributes
    ----------
    start
        Where the direct solve started (:class:`HBMStart`).
    route
        Which solve reached the answer (:class:`HBMRoute`; ``NONE`` when none converged).
    stop
        How the Newton solve that ended the route stopped (:class:`~seafast.solvers.newton.NewtonStop`; for
        a failed chain, that of its best iterate); None for Powell's method (``hybr``).
    """

    start: HBMStart
    route: HBMRoute
    stop: NewtonStop | None
