"""Operability off head seas judged on the cradles too: the cradle limits' linear and nonlinear allowable Hs.

Off head seas, with a cradle limit set (:data:`~seafast.analyses.operability.limits.CRADLE_LIMITS`), the cargo on
its cradles is built once per case (:func:`cradle_family`: the cradles, their dynamics and the exact still water,
those of ``seafast seastate``, :mod:`seafast.analyses.seastate.cradle_transfer`). Per peak period
(:func:`cradle_at_peak_period`) the cradle transfer functions are computed on that Tp's own sea-state grid from the
family's interpolated vertical transfer functions and the six motions at the Tp's frequencies, and their linear
spectral MPMs per metre of Hs (:func:`~seafast.analyses.seastate.cradle_extremes.cradle_spectral_extremes` at
Hs = 1 m); every MPM is proportional to Hs, so:

* **linear allowable** per limit (:func:`cradle_linear_limits`): ``min over locations (limit - static) / m``, ``m``
  the MPM per metre of Hs: the pads' force (still water + MPM, as the saddle force), the lashings' tension (still
  water + MPM, the lashing maximum) and the lateral displacement at the saddles (``|static|`` + MPM);
* **nonlinear**: the column's design-wave estimate at an Hs (:func:`cradle_design_wave_value`): the cradle design
  waves of that column alone (:func:`~seafast.analyses.seastate.cradle_design_wave.select_cradle_design_waves` on
  the linear MPMs at that Hs), each solved as ``seafast seastate`` solves it
  (:func:`~seafast.analyses.seastate.cradle_design_wave.solve_cradle_design_wave`), the largest reading and
  at least the still water's: the column of ``seafast seastate``'s design-wave row. The unit waves' excitations
  do not change with Hs and are formed once per peak period.

**Pad friction.** With ``seafastening.friction_coefficient`` above 0 (:class:`CradleFamily` ``friction``, that of
``seafast seastate``, :func:`~seafast.analyses.seastate.cradle_friction_wave.design_wave_friction`) each design wave,
selected on the linear MPMs as without friction, is solved on frictional pads exactly as ``seafast seastate`` solves
its frictional design-wave row (:func:`~seafast.analyses.seastate.cradle_friction_wave.solve_frictional_design_wave`)
and read there: ``transverse_slip`` keeps seastate's meaning, the lateral displacement of the cargo axis at a saddle
(not the pads' slip, ``pad_slip_m``, which no design wave is designed for). :func:`proxy_friction` gives the same
friction at a smaller H, which the search uses to find the Hs before reading it at the case's H
(:mod:`seafast.analyses.operability.allowable`).

Units: SI (N, m, s).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field, replace

import numpy as np
from numpy.typing import NDArray

from seafast.analyses.operability.limits import CRADLE_LIMITS, cradle_limits, linear_limit_hs
from seafast.analyses.seastate.cradle_design_wave import (
    CradleDesignWave,
    scaled_excitation,
    select_cradle_design_waves,
    solve_cradle_design_wave,
)
from seafast.analyses.seastate.cradle_extremes import (
    CradleSeaTransfer,
    CradleSpectralExtremes,
    cradle_spectral_extremes,
    element_groups,
    is_off_head_seas,
)
from seafast.analyses.seastate.cradle_friction_wave import DesignWaveFriction, design_wave_friction, solve_frictional_design_wave
from seafast.analyses.seastate.cradle_transfer import (
    CradleSeaModel,
    CradleStillWater,
    cradle_sea_model,
    cradle_still_water,
    cradle_transfer_functions,
    cradle_unit_excitations,
)
from seafast.analyses.seastate.directional_transfer import SeaStateTransfer, sea_state_quadrature
from seafast.analyses.seastate.spectral import SpectralAnalysis
from seafast.analyses.seastate.spectrum import WaveSpectrum
from seafast.config.schema import Case
from seafast.excitation.cradle_loads import CradleExcitation
from seafast.model.structure import StructuralModel
from seafast.solvers.cradle_hbm import CradleResponse

__all__ = [
    "PROXY_HARMONICS",
    "CradleFamily",
    "CradlePeakPeriod",
    "cradle_family",
    "cradle_at_peak_period",
    "cradle_extremes_at",
    "cradle_linear_limits",
    "cradle_design_wave_value",
    "cradle_still_value",
    "proxy_friction",
]

_COLUMN = {name: column for name, _, column in CRADLE_LIMITS}

PROXY_HARMONICS = 16
"""H (N = 8 H) of the frictional design waves the allowable-Hs search is led by before its answer is read at the case's
H: on the base case's beam-sea search waves (Tp 8-12 s, Hs 1.7-4 m) their pad force is within 9e-5 of H = 32's at
about a third of the cost (docs/operability.md#operability-on-the-cradles)."""


@dataclass(frozen=True)
class CradleFamily:
    """What every peak period's cradle limits share (built once per case and heading).

    Attributes
    ----------
    sea
        The case's cradles, their dynamics, the vertical plane's still-water excitation and the six motions.
    still
        The cargo's exact still-water state on its cradles.
    limits
        Governing name -> limit [N or m] of each cradle limit set (:func:`~seafast.analyses.operability.limits.cradle_limits`).
    friction
        The pads' friction and the frictional harmonic balance's H and N, ``seafast seastate``'s
        (:func:`~seafast.analyses.seastate.cradle_friction_wave.design_wave_friction`); None: frictionless pads (the key
        unset or 0).
    """

    sea: CradleSeaModel
    still: CradleStillWater
    limits: Mapping[str, float]
    friction: DesignWaveFriction | None = None


def cradle_family(case: Case, model: StructuralModel) -> CradleFamily | None:
    """The cradles of an operability run, or None: head seas (no cradle solved), or no cradle limit set.

    Raises
    ------
    ValueError
        If the cradles cannot be built from the case (naming the key), or the friction coefficient differs between
        saddles.
    """
    limits = cradle_limits(case)
    if not limits or not is_off_head_seas(case):
        return None
    friction = design_wave_friction(case)
    sea = cradle_sea_model(case, model)
    return CradleFamily(sea, cradle_still_water(sea), limits, friction)


def proxy_friction(friction: DesignWaveFriction | None) -> DesignWaveFriction | None:
    """The same friction at H = :data:`PROXY_HARMONICS` (N = 8 H), or None: frictionless, or H not above it."""
    if friction is None or int(friction.options.harmonics) <= PROXY_HARMONICS:
        return None
    return replace(friction, options=replace(friction.options, harmonics=PROXY_HARMONICS, time_samples=8 * PROXY_HARMONICS))


@dataclass(frozen=True)
class CradlePeakPeriod:
    """The cradles at one peak period: transfer functions on its sea-state grid and the MPMs per metre of Hs.

    Attributes
    ----------
    family
        The case's cradles.
    vertical
        The vertical plane's transfer functions of the (long-crested) sea state, one direction.
    transfer
        The cradle transfer functions on the same grid.
    per_metre
        Their linear spectral extremes at Hs = 1 m (the MPMs per metre of Hs; still water exact).
    units
        The excitation of a unit wave per (direction, frequency index) of a design wave, formed once (cache owned here).
    """

    family: CradleFamily
    vertical: SeaStateTransfer
    transfer: CradleSeaTransfer
    per_metre: CradleSpectralExtremes
    units: dict[tuple[int, int], CradleExcitation] = field(default_factory=dict, compare=False)


def cradle_extremes_at(at: CradlePeakPeriod, spectrum: WaveSpectrum) -> CradleSpectralExtremes:
    """The cradles' linear spectral extremes in ``spectrum`` (the peak period's sea state at another Hs, same grid)."""
    sea = at.family.sea
    stiffness = sea.dynamics.problem.element_stiffness_N_per_m
    return cradle_spectral_extremes(at.transfer, spectrum, at.family.still, stiffness, at.per_metre.duration_s)


def cradle_at_peak_period(family: CradleFamily, reference: SpectralAnalysis) -> CradlePeakPeriod:
    """The cradles in the sea state of ``reference`` (a family's analysis at one Tp, Hs = 1 m; module docstring)."""
    tf = reference.transfer
    vertical = SeaStateTransfer(sea_state_quadrature(reference.case), (tf,), tf, None)
    transfer = CradleSeaTransfer(vertical.quadrature, (cradle_transfer_functions(family.sea, tf),))
    stiffness = family.sea.dynamics.problem.element_stiffness_N_per_m
    duration = float(reference.case.sea_state.duration_s)
    per_metre = cradle_spectral_extremes(transfer, reference.spectrum, family.still, stiffness, duration)
    return CradlePeakPeriod(family, vertical, transfer, per_metre)


def _static_and_per_hs(e: CradleSpectralExtremes, name: str) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """The locations' still-water values and MPMs per metre of Hs that a limit bounds."""
    sw = e.still_water
    pads, _, lashings = element_groups(e.pad_count, e.stopper_count, e.element_force.mpm.size)
    if name == "pad_force":
        return sw.element_force_N[pads], e.element_force.mpm[pads]
    if name == "lashing_tension":
        return sw.element_force_N[lashings], e.element_force.mpm[lashings]
    return np.abs(sw.lateral_displacement_m), e.lateral_displacement.mpm


def cradle_linear_limits(at: CradlePeakPeriod) -> dict[str, float]:
    """Per cradle limit set, the Hs [m] at which its linear spectral MPM reaches it (0: still water; inf: never)."""
    return {name: linear_limit_hs(*_static_and_per_hs(at.per_metre, name), limit) for name, limit in at.family.limits.items()}


def cradle_still_value(at: CradlePeakPeriod, name: str) -> float:
    """The limit's column in still water [N or m]: what :func:`cradle_design_wave_value` gives at Hs = 0."""
    return float(np.max(_static_and_per_hs(at.per_metre, name)[0], initial=0.0))


def _solve(at: CradlePeakPeriod, wave: CradleDesignWave, friction: DesignWaveFriction | None) -> CradleResponse:
    """A design wave's periodic response as ``seafast seastate`` solves it: frictionless
    (:func:`~seafast.analyses.seastate.cradle_design_wave.solve_cradle_design_wave`), or on frictional pads
    (:func:`~seafast.analyses.seastate.cradle_friction_wave.solve_frictional_design_wave`, its record of the elements)."""
    key = (wave.direction, wave.frequency_index)
    if key not in at.units:
        at.units[key] = cradle_unit_excitations(at.family.sea, at.vertical.per_direction[wave.direction], [wave.frequency_index])[0]
    excitation = scaled_excitation(at.units[key], wave.amplitude_m)
    if friction is None:
        return solve_cradle_design_wave(at.family.sea.dynamics, excitation)
    return solve_frictional_design_wave(at.family.sea.dynamics, excitation, friction).cradle


def _reading(at: CradlePeakPeriod, name: str, wave: CradleDesignWave, response: CradleResponse) -> float:
    """A wave's nonlinear maximum over the period at its location [N or m]."""
    if name != "transverse_slip":
        return float(np.max(response.element_force_N[:, wave.location]))
    problem = at.family.sea.dynamics.problem
    pair = problem.pad_pairs[wave.location]
    dof = problem.cargo.node_dofs(problem.cargo.node_at(pair.x_m))[1]
    return float(np.max(np.abs(response.cargo_displacement_m[:, dof])))


def cradle_design_wave_value(
    at: CradlePeakPeriod,
    name: str,
    spectrum_at: Callable[[float], WaveSpectrum],
    band_fraction: float = 0.5,
    friction: DesignWaveFriction | None = None,
) -> Callable[[float], tuple[float, bool]]:
    """``value(Hs) -> (the design-wave estimate of the limit's column [N or m], every solve converged)`` (module docstring).

    Parameters
    ----------
    at
        The cradles at the peak period.
    name
        The limit: ``pad_force``, ``lashing_tension`` or ``transverse_slip``.
    spectrum_at
        The peak period's wave spectrum at an Hs [m] (on the grid of ``at``).
    band_fraction
        The design band's share of the response spectrum's peak [-].
    friction
        The pads' friction (the family's, or :func:`proxy_friction`'s): each wave solved on frictional pads; None:
        frictionless pads.
    """
    column = _COLUMN[name]

    def value(hs: float) -> tuple[float, bool]:
        spectral = cradle_extremes_at(at, spectrum_at(hs))
        static, _ = _static_and_per_hs(spectral, name)
        total = float(np.max(static, initial=0.0))
        converged = True
        for wave in select_cradle_design_waves(at.transfer, spectral, band_fraction):
            if wave.quantity != column:
                continue
            response = _solve(at, wave, friction)
            converged &= bool(response.converged)
            total = max(total, _reading(at, name, wave, response))
        return total, converged

    return value
