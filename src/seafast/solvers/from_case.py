"""A case's solver settings as the solvers' options (configuration -> solvers).

:func:`hbm_options` maps ``solver.*`` to :class:`~seafast.solvers.hbm.HBMOptions`;
:func:`nonlinear_options` chooses the method and its options for a still-water or a dynamic row;
:func:`solve_nonlinear` solves a row with them through :func:`~seafast.solvers.solve_periodic`.
"""

from __future__ import annotations

from dataclasses import replace
from typing import Any

import numpy as np

from seafast.config.modes import ContactLawKind, Formulation, SolverMethod
from seafast.config.schema import Case
from seafast.excitation.harmonic import HarmonicExcitation
from seafast.model.structure import StructuralModel
from seafast.solvers.dispatch import PeriodicOptions, solve_periodic
from seafast.solvers.hbm.options import HBMOptions
from seafast.solvers.periodic import PeriodicResponse
from seafast.solvers.references.options import QuasiStaticOptions, TimeDomainOptions
from seafast.solvers.shooting.options import ShootingOptions

__all__ = ["hbm_options", "shooting_options", "converged_by_shooting", "nonlinear_options", "solve_nonlinear"]


def hbm_options(case: Case, **changes: Any) -> HBMOptions:
    """Harmonic-balance options from the case's solver settings, with ``changes`` (HBMOptions fields) applied."""
    s = case.solver
    options = HBMOptions(
        harmonics=s.harmonics,
        time_samples=s.time_samples,
        contact_law=s.contact_law,
        regularisation_per_m=s.regularisation_per_m,
        formulation=s.formulation,
        solver=s.nonlinear_solver,
        tolerance=s.tolerance,
        truncation_tolerance=s.truncation_tolerance,
        max_harmonics=s.max_harmonics,
    )
    return replace(options, **changes) if changes else options


def shooting_options(case: Case) -> ShootingOptions:
    """Exact-event shooting options of the case: the defaults (the grid follows the cargo's modes and the peaks, not
    ``solver.time_samples``, which is the harmonic balance's N)."""
    return ShootingOptions()


def converged_by_shooting(case: Case) -> bool:
    """Whether the case's harmonic balance asks for its converged limit and shooting computes it.

    ``solver.method: hbm`` with ``solver.harmonics`` unset, the exact contact law and the condensed formulation:
    the harmonic balance with every harmonic is the periodic solution of the piecewise-linear problem, which
    exact-event shooting finds in closed form (the adaptive harmonic balance is the fallback when it cannot).
    """
    s = case.solver
    return bool(
        s.method == SolverMethod.HBM
        and s.harmonics is None
        and s.contact_law == ContactLawKind.EXACT
        and s.formulation == Formulation.CONDENSED
    )


def nonlinear_options(case: Case, static: bool) -> tuple[SolverMethod, PeriodicOptions]:
    """The method and options :func:`solve_nonlinear` solves the case with.

    The still-water state (``static``): the harmonic balance at H = 0, or for the references their
    exact-law quasi-static state. The time-domain reference integrates all cargo DOFs (its full
    formulation) from the case's ``time_domain_start``, the HBM start with the case's HBM settings.
    The converged harmonic balance (:func:`converged_by_shooting`) and ``solver.method: shooting``: exact-event
    shooting.
    """
    s = case.solver
    if static:
        if s.method in (SolverMethod.HBM, SolverMethod.SHOOTING):
            return SolverMethod.HBM, hbm_options(case, harmonics=0, time_samples=2)
        return SolverMethod.QUASI_STATIC, QuasiStaticOptions(time_samples=2)
    if s.method == SolverMethod.QUASI_STATIC:
        return SolverMethod.QUASI_STATIC, QuasiStaticOptions(time_samples=s.reference_time_samples)
    if s.method == SolverMethod.TIME_DOMAIN:
        # both formulations start from one state: the linear periodic solution, or the HBM's orbit (docs/orbits.md)
        options = TimeDomainOptions(time_samples=s.reference_time_samples, start=s.time_domain_start, hbm=hbm_options(case))
        return SolverMethod.TIME_DOMAIN, options
    if s.method == SolverMethod.SHOOTING or converged_by_shooting(case):
        return SolverMethod.SHOOTING, shooting_options(case)
    return SolverMethod.HBM, hbm_options(case)


def solve_nonlinear(
    model: StructuralModel, excitation: HarmonicExcitation, case: Case, static: bool, warm_start: PeriodicResponse | None = None
) -> PeriodicResponse:
    """Nonlinear (unilateral-saddle) response by the case's method (:func:`~seafast.solvers.solve_periodic`).

    ``static=True`` solves the still-water state alone (:func:`nonlinear_options`). ``warm_start``: a
    neighbouring response of the same case to start the condensed HBM from (ignored otherwise).
    """
    method, options = nonlinear_options(case, static)
    start = None
    if warm_start is not None and not static and isinstance(options, HBMOptions) and options.formulation is Formulation.CONDENSED:
        start = np.asarray(warm_start.saddle_compression_time_m)
    exc = excitation.static_part() if static else excitation
    response = solve_periodic(model, exc, method, options=options, initial_compression_m=start)
    if not response.converged and not static and converged_by_shooting(case):
        # the harmonic balance's converged limit by its own adaptive route instead (a contact state without
        # stiffness, a chattering contact, or more saddles than the shooting solver's table)
        fallback = solve_periodic(model, exc, SolverMethod.HBM, options=hbm_options(case))
        note = f"; exact-event shooting did not converge ({response.message}), so the adaptive harmonic balance answered"
        return replace(fallback, message=fallback.message + note)
    return response
