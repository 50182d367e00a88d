"""A stand-in for the frictional design-wave solve that says it did not converge (the flagging paths' tests)."""

from __future__ import annotations

import dataclasses
from collections.abc import Callable

from seafast.analyses.seastate.cradle_friction_wave import DesignWaveFriction, solve_frictional_design_wave
from seafast.model.pad_friction import PadFriction
from seafast.solvers.outcome import SolverOutcome


def not_converging(residual: float) -> Callable:
    """A stand-in for :func:`solve_frictional_design_wave`: the mu = 0 answer reported ``NOT_CONVERGED`` with
    ``residual``."""

    def solve(dynamics, excitation, friction):
        zero = DesignWaveFriction(PadFriction(0.0), friction.options)
        response = solve_frictional_design_wave(dynamics, excitation, zero)
        cradle = dataclasses.replace(response.cradle, outcome=SolverOutcome.NOT_CONVERGED, residual=residual)
        return dataclasses.replace(response, cradle=cradle)

    return solve
