"""Design format (LRFD or allowable stress) and friction credit of ``seafast criteria`` (docs/criteria.md).

**LRFD** (``criteria.design.format: lrfd``): each load case is solved again under the ULS combinations of
:data:`LRFD_COMBINATIONS`, the permanent part of the load (the cargo's weight upright) times ``gamma_G`` and the
environmental part (the angles' gravity components and the motion's accelerations) times ``gamma_E``; the design
value of a check is the largest over the combinations. The bending stress is checked against the yield stress over
the material factor ``f_y / gamma_M``, the saddle force against ``limits.max_saddle_force_N`` (the saddle's design
resistance as the user gives it).

**Allowable stress** (``allowable_stress``, the default): the unfactored load effects; the bending stress against
``eta f_y`` (``criteria.design.allowable_stress_factor``), the saddle force against ``limits.max_saddle_force_N``.

**Friction credit**: the cargo's weight pressed onto its saddles, reduced by the vertical acceleration, is the
resultant ``N = -m a_z`` of the apparent gravity along the deck's normal (``a_z`` at the centre of gravity, the field
being linear along the cargo: ``m (g cos(phi) cos(theta) + a_z,motion)``); friction may be counted as ``mu N`` (``mu``
the smallest of ``seafastening.friction_coefficient``) unless the contact is steel on steel, no friction coefficient is
given, or ``N <= 0``. The lashings' vertical pull is not counted in ``N``. What friction does not hold of the axial
force is left to the end stops and lashings: ``max(|F_axial| - mu N, 0)``.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from seafast.config.modes import ContactSurface, DesignFormat
from seafast.config.schema import CriteriaDesignConfig

__all__ = [
    "LRFD_COMBINATIONS",
    "LRFD_SOURCE",
    "UNFACTORED",
    "LoadCombination",
    "DesignCheck",
    "FrictionCredit",
    "bending_resistance_Pa",
    "design_checks",
    "factored_value",
    "friction_credit",
]


@dataclass(frozen=True)
class LoadCombination:
    """One ULS load combination: its name and the permanent and environmental load factors [-]."""

    name: str
    gamma_G: float
    gamma_E: float


LRFD_COMBINATIONS = (LoadCombination("uls_a", 1.3, 0.7), LoadCombination("uls_b", 1.0, 1.3))
"""The ULS combinations a) and b) of permanent and environmental loads as DNV-ST-N001 takes them from DNV-OS-C101
(quoted values, not verified in the standard's text: docs/criteria.md)."""

LRFD_SOURCE = "DNV-OS-C101 ULS combinations a) (1.3 G + 0.7 E) and b) (1.0 G + 1.3 E), as quoted (not verified)"

UNFACTORED = LoadCombination("unfactored", 1.0, 1.0)
"""The allowable-stress format's single, unfactored combination."""


@dataclass(frozen=True)
class DesignCheck:
    """One check of a load case in the design format.

    Attributes
    ----------
    check
        ``saddle_force`` or ``bending_stress``.
    design_format
        The format.
    combination
        The governing combination's name (``uls_a``, ``uls_b`` or ``unfactored``).
    value
        The design load effect [N or Pa] (factored under LRFD).
    resistance
        The design resistance [N or Pa].
    utilisation
        ``value / resistance`` [-] (inf when the statics did not converge).
    passed
        Whether the utilisation is at most 1 and the statics converged.
    """

    check: str
    design_format: DesignFormat
    combination: str
    value: float
    resistance: float
    utilisation: float
    passed: bool


@dataclass(frozen=True)
class FrictionCredit:
    """The friction the standard allows to be counted in one load case.

    Attributes
    ----------
    contact
        The materials in contact.
    coefficient
        The friction coefficient used (the smallest given) [-]; None when none is given.
    normal_force_N
        The cargo's weight along the deck's normal reduced by the vertical acceleration, ``-m a_z`` [N].
    counted
        Whether friction may be counted.
    reason
        Why not (empty when counted).
    capacity_N
        ``mu N`` when counted, else 0 [N].
    axial_unresisted_N
        The axial force friction does not hold, ``max(|F_axial| - capacity, 0)`` [N].
    """

    contact: ContactSurface
    coefficient: float | None
    normal_force_N: float
    counted: bool
    reason: str
    capacity_N: float
    axial_unresisted_N: float


def bending_resistance_Pa(settings: CriteriaDesignConfig) -> float:
    """The design bending-stress resistance [Pa]: ``f_y / gamma_M`` (LRFD) or ``eta f_y`` (allowable stress)."""
    if settings.format is DesignFormat.LRFD:
        return settings.yield_stress_Pa / settings.material_factor
    return settings.allowable_stress_factor * settings.yield_stress_Pa


def factored_value(total: float, permanent: float, combination: LoadCombination) -> float:
    """``gamma_G S_G + gamma_E (S - S_G)``: a load effect ``total`` whose permanent part is ``permanent`` factored."""
    return combination.gamma_G * permanent + combination.gamma_E * (total - permanent)


def design_checks(
    settings: CriteriaDesignConfig,
    max_saddle_force_N: float,
    effects: Sequence[tuple[LoadCombination, float, float, bool]],
) -> tuple[DesignCheck, DesignCheck]:
    """The saddle-force and bending-stress checks from each combination's ``(combination, F [N], sigma [Pa], converged)``.

    The governing combination of each check is the one of largest design value (a combination that did not converge
    governs with an infinite utilisation).
    """
    if not effects:
        raise ValueError("design_checks: at least one combination's load effects are needed")
    checks = []
    for index, name, resistance in ((0, "saddle_force", max_saddle_force_N), (1, "bending_stress", bending_resistance_Pa(settings))):
        values = [(e[1], e[2])[index] for e in effects]
        utilisations = [v / resistance if e[3] else np.inf for v, e in zip(values, effects, strict=True)]
        k = int(np.argmax(utilisations))
        u = utilisations[k]
        checks.append(DesignCheck(name, settings.format, effects[k][0].name, float(values[k]), resistance, u, bool(u <= 1.0)))
    return checks[0], checks[1]


def friction_credit(
    contact: ContactSurface, coefficients: Sequence[float] | None, mass_kg: float, apparent_gravity_z_m_s2: float, axial_force_N: float
) -> FrictionCredit:
    """The friction credit of a load case (module docstring).

    Parameters
    ----------
    contact
        The materials in contact at the saddles.
    coefficients
        ``seafastening.friction_coefficient`` per saddle (None: none given).
    mass_kg
        The cargo unit's mass [kg].
    apparent_gravity_z_m_s2
        The apparent gravity along the deck's normal at the centre of gravity [m/s^2] (``-9.81`` at rest).
    axial_force_N
        The axial force the saddles must hold [N].
    """
    normal = -mass_kg * apparent_gravity_z_m_s2
    mu = None if not coefficients else float(min(coefficients))
    reason = ""
    if contact is ContactSurface.STEEL_ON_STEEL:
        reason = "steel on steel: no friction may be counted"
    elif mu is None:
        reason = "no seafastening.friction_coefficient given"
    elif normal <= 0.0:
        reason = "the cargo is lifted off its saddles (no normal force)"
    counted = not reason
    capacity = float(mu * normal) if counted and mu is not None else 0.0
    return FrictionCredit(contact, mu, float(normal), counted, reason, capacity, max(abs(float(axial_force_N)) - capacity, 0.0))
