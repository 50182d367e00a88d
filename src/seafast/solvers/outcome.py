"""How a nonlinear solve ended, as typed values (the human-readable account is the ``message``).

Every solver that returns a :class:`~seafast.solvers.periodic.PeriodicResponse` sets its
``outcome`` (one :class:`SolverOutcome`) and its ``warnings`` (a tuple of
:class:`SolverWarning`). The CLI, the results (``solver_outcome`` and ``solver_warning`` in
``results.nc``) and the report read these; nothing decides anything from the message text.
The values (``"converged"``, ...) are what ``results.nc`` stores.
"""

from __future__ import annotations

from enum import Enum

__all__ = ["SolverOutcome", "SolverWarning"]


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
        Time-domain reference: no periodic steady state within ``max_periods``.
    """

    CONVERGED = "converged"
    CONVERGED_BY_CONTINUATION = "converged_by_continuation"
    NOT_CONVERGED = "not_converged"
    NOT_PERIODIC = "not_periodic"

    @property
    def converged(self) -> bool:
        """Whether the result meets its solver's tolerance (its numbers can be used)."""
        return self in (SolverOutcome.CONVERGED, SolverOutcome.CONVERGED_BY_CONTINUATION)


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
