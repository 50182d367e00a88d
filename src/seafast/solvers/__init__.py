"""Solvers: linear (bilateral saddles), harmonic balance with AFT (unilateral saddles), references.

* :func:`solve_periodic` - the periodic response by any method (:class:`~seafast.config.modes.SolverMethod`),
  its settings one options class per method (:mod:`seafast.solvers.dispatch`).
* :func:`solve_linear` - partitioned static + frequency-domain solve.
* :func:`solve_hbm` with :class:`HBMOptions` - periodic steady state with contact (condensed or full).
* :func:`solve_quasi_static`, :func:`solve_time_domain` - exact-contact references.
* :func:`frequency_response` - pseudo-arclength continuation in frequency.

Non-convergence is reported in the result (``outcome``, ``converged``, ``residual_norm``; ``message`` for
people), never raised; typed warnings are in ``warnings``.
"""

from seafast.solvers.contact import ContactLaw, contact_law
from seafast.solvers.continuation import BranchEnd, FrequencyResponseBranch, frequency_response
from seafast.solvers.dispatch import PeriodicOptions, solve_periodic
from seafast.solvers.hbm import HBMOptions, solve_hbm
from seafast.solvers.linear import LinearResponse, solve_linear
from seafast.solvers.outcome import SolverOutcome, SolverWarning
from seafast.solvers.periodic import PeriodicResponse
from seafast.solvers.references import QuasiStaticOptions, TimeDomainOptions, solve_quasi_static, solve_time_domain

__all__ = [
    "solve_periodic",
    "PeriodicOptions",
    "ContactLaw",
    "contact_law",
    "HBMOptions",
    "solve_hbm",
    "LinearResponse",
    "solve_linear",
    "PeriodicResponse",
    "SolverOutcome",
    "SolverWarning",
    "QuasiStaticOptions",
    "TimeDomainOptions",
    "solve_quasi_static",
    "solve_time_domain",
    "BranchEnd",
    "FrequencyResponseBranch",
    "frequency_response",
]
