"""The cradle design waves of a sea state on frictional pads (``seafastening.friction_coefficient`` above 0).

Each design wave (:mod:`seafast.analyses.seastate.cradle_design_wave`), selected and solved frictionless as without
the key, is solved again as ``seafast run`` solves its dynamic row on frictional pads
(docs/transverse.md#9-in-seafast-run): the frictional harmonic balance, else the time march
(:func:`~seafast.solvers.cradle_friction_solve.solve_cradle_friction`), with the run's friction and settings
(:func:`~seafast.analyses.cradle_run.pad_friction_of_case`, :func:`~seafast.analyses.cradle_run.friction_options`)
and the pads' sliders relaxed in the wave's still water, so that the friction answers the wave alone. The design-wave
columns read that response and gain :data:`CRADLE_FRICTION_COLUMNS`. The linear spectral MPMs stay frictionless (the
linear model: pads bilateral, free tangentially). Units: SI.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

import numpy as np

from seafast.analyses.cradle_run import friction_options, pad_friction_of_case
from seafast.config.schema import Case
from seafast.excitation.cradle_loads import CradleExcitation
from seafast.model.pad_friction import PadFriction
from seafast.solvers.cradle_dynamics import CradleDynamics
from seafast.solvers.cradle_friction import FrictionHBMOptions
from seafast.solvers.cradle_friction_solve import solve_cradle_friction
from seafast.solvers.pad_tangential import FrictionalCradleResponse

__all__ = [
    "CRADLE_FRICTION_COLUMNS",
    "DesignWaveFriction",
    "design_wave_friction",
    "solve_frictional_design_wave",
    "friction_totals",
]

CRADLE_FRICTION_COLUMNS = ("pad_friction_utilisation", "pad_slip_m")
"""The columns the design-wave estimates gain on frictional pads: the largest ``|f| / (mu F_n)`` [-] and the largest
slip of a pad ``|w - w_rest|`` [m] (``seafast run``'s ``transverse_slip_m`` on frictional pads) over the design waves."""


@dataclass(frozen=True)
class DesignWaveFriction:
    """The pads' friction of the design waves and the frictional harmonic balance's settings.

    Attributes
    ----------
    friction
        The pads' friction coefficient (above 0) and tangential stiffness.
    options
        H and N of the frictional harmonic balance (``seafast run``'s dynamic row's).
    """

    friction: PadFriction
    options: FrictionHBMOptions


def design_wave_friction(case: Case) -> DesignWaveFriction | None:
    """The design waves' pad friction from ``seafastening.friction_coefficient`` (``seafast run``'s: one coefficient,
    its H and N), or None when the key is unset or 0 (frictionless pads, today's design waves).

    Raises
    ------
    ValueError
        If the key gives different values per saddle (naming the key).
    """
    friction = pad_friction_of_case(case)
    if friction is None or float(friction.friction_coefficient) == 0.0:
        return None
    return DesignWaveFriction(friction, friction_options(case))


def solve_frictional_design_wave(
    dynamics: CradleDynamics, excitation: CradleExcitation, friction: DesignWaveFriction
) -> FrictionalCradleResponse:
    """A design wave's periodic response on frictional pads, solved as ``seafast run`` solves its dynamic row.

    The frictional harmonic balance (``friction``'s H and N), and where it does not converge the time march
    (:func:`~seafast.solvers.cradle_friction_solve.solve_cradle_friction`), with the pads' sliders relaxed at the
    frictionless response to the wave's still water (its k = 0 loads and deck deflection, ``rest=``): the friction
    answers the wave alone. A solve that does not converge is returned flagged (its outcome and residual), never
    raised.
    """
    return solve_cradle_friction(dynamics, friction.friction, excitation, friction.options, rest=excitation.still_water())


def friction_totals(solves: Iterable[FrictionalCradleResponse]) -> dict[str, float]:
    """:data:`CRADLE_FRICTION_COLUMNS` over the frictional solves (0 without any: the still water carries no friction)."""
    solves = list(solves)
    return {
        "pad_friction_utilisation": max((float(np.max(f.friction_utilisation, initial=0.0)) for f in solves), default=0.0),
        "pad_slip_m": max((float(np.max(f.max_slip_m, initial=0.0)) for f in solves), default=0.0),
    }
