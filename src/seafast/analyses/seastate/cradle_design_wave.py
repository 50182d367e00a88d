"""The cradle columns of a sea state off head seas by design waves, and the whole of them (:func:`cradle_sea_state`).

Per column, the element (or saddle) of the linear
extreme, the peak of its response spectrum and the ends of the band where it is at least
:attr:`~seafast.analyses.seastate.design_wave_rule.DesignWaveSettings.band_fraction` of the peak, and at each such
frequency the regular wave whose linear response there equals that element's linear MPM (from the quadrature
direction whose transfer function is largest, as the vertical plane's rule); each wave is solved with still water by
:func:`solve_cradle_design_wave` (exact-event shooting; pads lift, stoppers close, lashings slacken) and read for its
element over the period. The estimate is the largest reading (least for the lashing minimum), at least the still
water's. Where nothing opens or closes the readings are the linear ones.

**Pad friction.** With ``seafastening.friction_coefficient`` set above 0, each design wave, selected and solved
frictionless as above, is solved again on frictional pads as ``seafast run`` solves its dynamic row and the columns
read that response; the estimates then gain the largest pad friction utilisation and pad slip over every design wave
(:mod:`seafast.analyses.seastate.cradle_friction_wave`). The linear spectral MPMs stay frictionless (the linear model
has bilateral pads, free tangentially).

The columns and their linear spectral MPMs: :mod:`seafast.analyses.seastate.cradle_extremes`. Units: SI.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, replace

import numpy as np
from numpy.typing import NDArray

from seafast.analyses.seastate.cradle_extremes import (
    CRADLE_COLUMNS,
    CradleSeaTransfer,
    CradleSpectralExtremes,
    cradle_sea_transfer,
    cradle_spectral_extremes,
    element_groups,
)
from seafast.analyses.seastate.cradle_friction_wave import (
    CRADLE_FRICTION_COLUMNS,
    DesignWaveFriction,
    design_wave_friction,
    friction_totals,
    solve_frictional_design_wave,
)
from seafast.analyses.seastate.cradle_transfer import CradleSeaModel, cradle_sea_model, cradle_still_water, cradle_unit_excitations
from seafast.analyses.seastate.directional_transfer import SeaStateTransfer
from seafast.analyses.seastate.spectral import ResponseStatistics, SpectralAnalysis
from seafast.excitation.cradle_loads import CradleExcitation
from seafast.solvers.cradle_dynamics import CradleDynamics
from seafast.solvers.cradle_hbm import CradleResponse, solve_cradle_hbm
from seafast.solvers.cradle_shooting import solve_cradle_shooting
from seafast.solvers.hbm import HBMOptions
from seafast.solvers.outcome import SolverOutcome
from seafast.solvers.pad_tangential import FrictionalCradleResponse
from seafast.solvers.transverse_statics import CradleProblem

__all__ = [
    "CRADLE_DESIGN_HARMONICS",
    "CradleDesignWave",
    "CradleDesignWaveExtremes",
    "CradleSeaState",
    "select_cradle_design_waves",
    "cradle_design_wave_readings",
    "solve_cradle_design_wave",
    "scaled_excitation",
    "design_wave_excitation",
    "cradle_design_waves",
    "cradle_sea_state",
]

CRADLE_DESIGN_HARMONICS = (64, 96, 128, 48)
"""The H a cradle design wave's harmonic balance tries in turn where exact-event shooting does not converge (Newton from
its predictors, no continuation): with the exact law a truncation can have no solution near its start where pads lift,
while another H converges in a few steps (at 135 deg on the base case H = 64 fails for 3 of 9 waves in 0.4 s each, H =
96 solves them; the continuations took 26 s to fail)."""


@dataclass(frozen=True)
class CradleDesignWave:
    """One design wave of a cradle column.

    Attributes
    ----------
    quantity
        The column it is designed for (:data:`CRADLE_COLUMNS`).
    location
        The element (pads, stoppers, lashings in the problem's order) or, for ``transverse_slip_m``, the saddle.
    frequency_index, omega_rad_s
        Its frequency on the sea-state grid [rad/s].
    amplitude_m
        Its amplitude [m]: the element's linear MPM over its transfer function's modulus.
    role
        ``peak``, ``band_low`` or ``band_high``.
    direction, heading_deg
        Its direction in the quadrature and heading [deg].
    """

    quantity: str
    location: int
    frequency_index: int
    omega_rad_s: float
    amplitude_m: float
    role: str
    direction: int
    heading_deg: float


@dataclass(frozen=True)
class CradleDesignWaveExtremes:
    """The nonlinear design-wave estimates of the cradle columns.

    Attributes
    ----------
    waves
        The design waves.
    responses
        One :class:`~seafast.solvers.cradle_hbm.CradleResponse` per wave, same order (waves that coincide share one);
        on frictional pads the frictional solves' (the ones read).
    readings
        Per wave, its element's nonlinear maximum (least for ``lashing_tension_min_N``) over the period [N or m].
    totals
        The five :data:`CRADLE_COLUMNS` [N, N, N, N, m]; on frictional pads also
        :data:`~seafast.analyses.seastate.cradle_friction_wave.CRADLE_FRICTION_COLUMNS` [-, m].
    converged
        Every harmonic balance converged (on frictional pads, every frictional one: those are read).
    residual
        The largest relative residual of the solves read [-].
    frictional
        On frictional pads, per wave its frictional solve (``responses`` are their ``cradle``); None frictionless.
    frictionless
        On frictional pads, per wave its frictionless solve (the design wave as without friction); None frictionless.
    """

    waves: tuple[CradleDesignWave, ...]
    responses: tuple[CradleResponse, ...]
    readings: NDArray[np.float64]
    totals: Mapping[str, float]
    converged: bool
    residual: float
    frictional: tuple[FrictionalCradleResponse, ...] | None = None
    frictionless: tuple[CradleResponse, ...] | None = None

    def columns(self) -> dict[str, float]:
        """The design-wave row's cradle columns: the five, then on frictional pads :data:`CRADLE_FRICTION_COLUMNS`."""
        names = CRADLE_COLUMNS + (CRADLE_FRICTION_COLUMNS if self.frictional is not None else ())
        return {c: float(self.totals[c]) for c in names}


def _reader(quantity: str, location: int) -> Callable[[CradleResponse, NDArray[np.intp]], float]:
    """How a wave's response is read for its column at its location (``lateral``: the saddles' v DOFs)."""
    if quantity == "transverse_slip_m":
        return lambda r, lateral: float(np.max(np.abs(r.cargo_displacement_m[:, lateral[location]])))
    if quantity == "lashing_tension_min_N":
        return lambda r, lateral: float(np.min(r.element_force_N[:, location]))
    return lambda r, lateral: float(np.max(r.element_force_N[:, location]))


def cradle_design_wave_readings(
    problem: CradleProblem, waves: Sequence[CradleDesignWave], responses: Sequence[CradleResponse]
) -> NDArray[np.float64]:
    """Per wave, its element's nonlinear maximum (least for ``lashing_tension_min_N``; for ``transverse_slip_m`` the
    largest ``|v|`` of the cargo axis at its saddle) over its response's period [N or m]."""
    lateral = np.array([problem.cargo.node_dofs(problem.cargo.node_at(p.x_m))[1] for p in problem.pad_pairs], dtype=np.intp)
    return np.array([_reader(w.quantity, w.location)(r, lateral) for w, r in zip(waves, responses, strict=True)], dtype=float)


def _targets(spectral: CradleSpectralExtremes) -> list[tuple[str, int, ResponseStatistics, str]]:
    """Per column: (column, location, the statistics designed for, the transfer field) at its linear extreme."""
    per = spectral.element_totals()
    _, stoppers, lashings = element_groups(spectral.pad_count, spectral.stopper_count, spectral.element_force.mpm.size)
    out: list[tuple[str, int, ResponseStatistics, str]] = []
    if per["F_pad_N"].size:
        out.append(("F_pad_N", int(np.argmax(per["F_pad_N"])), spectral.element_force, "element_force_N"))
    if per["F_stopper_N"].size:
        sw = spectral.still_water.engagement_m[stoppers] + spectral.engagement.mpm[stoppers]
        out.append(("F_stopper_N", stoppers.start + int(np.argmax(sw)), spectral.engagement, "engagement_m"))
    if per["lashing_tension_max_N"].size:
        out.append(
            (
                "lashing_tension_max_N",
                lashings.start + int(np.argmax(per["lashing_tension_max_N"])),
                spectral.element_force,
                "element_force_N",
            )
        )
        out.append(
            (
                "lashing_tension_min_N",
                lashings.start + int(np.argmin(per["lashing_tension_min_N"])),
                spectral.element_force,
                "element_force_N",
            )
        )
    out.append(("transverse_slip_m", int(np.argmax(per["transverse_slip_m"])), spectral.lateral_displacement, "lateral_displacement_m"))
    return out


def _band(spectrum: NDArray[np.float64], fraction: float) -> tuple[int, int, int]:
    """(low, peak, high) grid indices of the contiguous band around the peak where S >= fraction * peak."""
    peak = int(np.argmax(spectrum))
    above = spectrum >= fraction * spectrum[peak]
    low, high = peak, peak
    while low > 0 and above[low - 1]:
        low -= 1
    while high < spectrum.size - 1 and above[high + 1]:
        high += 1
    return low, peak, high


def select_cradle_design_waves(
    transfer: CradleSeaTransfer, spectral: CradleSpectralExtremes, band_fraction: float = 0.5
) -> tuple[CradleDesignWave, ...]:
    """The design waves of the cradle columns (module docstring); a response that is zero in the sea gets none."""
    waves: list[CradleDesignWave] = []
    w = transfer.per_direction[0].omega_rad_s
    for quantity, loc, stats, name in _targets(spectral):
        modulus = np.abs(np.stack([getattr(t, name)[:, loc] for t in transfer.per_direction]))  # (n_dir, n_w)
        mpm, s_r = float(stats.mpm[loc]), stats.spectrum[:, loc]
        if not (mpm > 0.0 and np.max(s_r) > 0.0):
            continue
        low, peak, high = _band(s_r, band_fraction)
        seen: set[int] = set()
        for index, role in ((peak, "peak"), (low, "band_low"), (high, "band_high")):
            if index in seen:
                continue
            seen.add(index)
            j = int(np.argmax(modulus[:, index]))
            heading = float(transfer.per_direction[j].heading_deg)
            waves.append(CradleDesignWave(quantity, loc, index, float(w[index]), mpm / float(modulus[j, index]), role, j, heading))
    return tuple(waves)


def solve_cradle_design_wave(
    dynamics: CradleDynamics,
    excitation: CradleExcitation,
    options: HBMOptions | None = None,
    harmonics: tuple[int, ...] = CRADLE_DESIGN_HARMONICS,
) -> CradleResponse:
    """A design wave's periodic response: exact-event shooting, else the harmonic balance at the first H that converges.

    The shooting (:func:`~seafast.solvers.cradle_shooting.solve_cradle_shooting`) is the harmonic balance's converged
    limit; a state it shows not to repeat every wave period is returned as such (``NOT_PERIODIC``). Where it does not
    converge otherwise, the harmonic balance tries each H of ``harmonics`` in turn (``options``' settings, no
    continuation), returning the first that converges, else the least residual's (flagged, never raised).
    """
    shot = solve_cradle_shooting(dynamics, excitation)
    if shot.converged or shot.outcome is SolverOutcome.NOT_PERIODIC:
        return shot
    if not harmonics:
        raise ValueError("harmonics: empty; allowed one H or more")
    base = replace(HBMOptions() if options is None else options, continuation=False)
    best: CradleResponse | None = None
    for H in harmonics:
        response = solve_cradle_hbm(dynamics, excitation, base.with_harmonics(int(H)))
        if response.converged:
            best = response
            break
        best = response if best is None or response.residual < best.residual else best
    assert best is not None
    note = f"; exact-event shooting did not converge ({shot.message}), so the harmonic balance answered"
    return replace(best, message=best.message + note)


def scaled_excitation(unit: CradleExcitation, amplitude_m: float) -> CradleExcitation:
    """A unit wave's excitation (still water at k = 0) for a wave of ``amplitude_m`` [m]."""
    load, deck = np.array(unit.cargo_load_N, dtype=complex), np.array(unit.deck_displacement, dtype=complex)
    load[1] *= amplitude_m
    deck[1] *= amplitude_m
    return CradleExcitation(unit.omega_rad_s, load, deck, unit.deck_x_m, f"{unit.source}, amplitude {amplitude_m:.4g} m")


def design_wave_excitation(sea: CradleSeaModel, transfer: SeaStateTransfer, wave: CradleDesignWave) -> CradleExcitation:
    """A design wave's excitation of the cradles: its direction's unit wave at its frequency (still water at k = 0),
    scaled to its amplitude (:func:`scaled_excitation`)."""
    unit = cradle_unit_excitations(sea, transfer.per_direction[wave.direction], [wave.frequency_index])[0]
    return scaled_excitation(unit, wave.amplitude_m)


def cradle_design_waves(
    sea: CradleSeaModel,
    transfer: SeaStateTransfer,
    cradle_transfer: CradleSeaTransfer,
    spectral: CradleSpectralExtremes,
    *,
    band_fraction: float = 0.5,
    options: HBMOptions | None = None,
    harmonics: tuple[int, ...] = CRADLE_DESIGN_HARMONICS,
    friction: DesignWaveFriction | None = None,
) -> CradleDesignWaveExtremes:
    """The nonlinear design-wave MPMs of the cradle columns (module docstring).

    Parameters
    ----------
    sea
        The case's cradles and their dynamics.
    transfer, cradle_transfer
        The vertical plane's and the cradles' transfer functions of the sea state's directions.
    spectral
        The cradles' linear spectral extremes.
    band_fraction
        The design band's share of the response spectrum's peak [-].
    options
        The harmonic balance's where the shooting does not converge (default: :class:`~seafast.solvers.hbm.HBMOptions`);
        its H and continuation are ``harmonics``' and off.
    harmonics
        The H then tried in turn until one converges (:data:`CRADLE_DESIGN_HARMONICS`).
    friction
        The pads' friction (:func:`design_wave_friction`): each wave then also solved on frictional pads
        (:func:`solve_frictional_design_wave`) and read there; None: frictionless pads.

    Returns
    -------
    CradleDesignWaveExtremes
        A solve that does not converge flags ``converged`` with its residual (never raised).
    """
    waves = select_cradle_design_waves(cradle_transfer, spectral, band_fraction)
    plain: dict[tuple[int, int, float], CradleResponse] = {}
    frictional: dict[tuple[int, int, float], FrictionalCradleResponse] = {}
    keys = []
    for wave in waves:
        key = (wave.frequency_index, wave.direction, round(wave.amplitude_m, 12))
        keys.append(key)
        if key in plain:
            continue
        excitation = design_wave_excitation(sea, transfer, wave)
        plain[key] = solve_cradle_design_wave(sea.dynamics, excitation, options, harmonics)
        if friction is not None:
            frictional[key] = solve_frictional_design_wave(sea.dynamics, excitation, friction)
    read = {k: r.cradle for k, r in frictional.items()} if friction is not None else plain
    responses = tuple(read[k] for k in keys)
    readings = cradle_design_wave_readings(sea.dynamics.problem, waves, responses)
    totals = _static_totals(spectral)
    for wave, value in zip(waves, readings, strict=True):
        q = wave.quantity
        totals[q] = min(totals[q], value) if q == "lashing_tension_min_N" else max(totals[q], value)
    converged = all(r.converged for r in read.values())
    residual = max((float(r.residual) for r in read.values()), default=0.0)
    if friction is None:
        return CradleDesignWaveExtremes(waves, responses, readings, totals, converged, residual)
    totals |= friction_totals(frictional.values())
    per_wave = tuple(frictional[k] for k in keys)
    return CradleDesignWaveExtremes(waves, responses, readings, totals, converged, residual, per_wave, tuple(plain[k] for k in keys))


def _static_totals(spectral: CradleSpectralExtremes) -> dict[str, float]:
    """The columns in still water (what a sea without waves gives)."""
    sw = spectral.still_water
    pads, stoppers, lashings = element_groups(spectral.pad_count, spectral.stopper_count, sw.element_force_N.size)
    lash = sw.element_force_N[lashings]
    return {
        "F_pad_N": float(np.max(sw.element_force_N[pads], initial=0.0)),
        "F_stopper_N": float(np.max(sw.element_force_N[stoppers], initial=0.0)),
        "lashing_tension_max_N": float(np.max(lash, initial=0.0)),
        "lashing_tension_min_N": float(np.min(lash)) if lash.size else 0.0,
        "transverse_slip_m": float(np.max(np.abs(sw.lateral_displacement_m), initial=0.0)),
    }


@dataclass(frozen=True)
class CradleSeaState:
    """Everything the cradle columns of a sea state come from.

    Attributes
    ----------
    sea
        The case's cradles, their dynamics and the six motions.
    transfer
        The cradle transfer functions per direction.
    spectral
        The linear spectral extremes (row linear, spectral).
    design
        The nonlinear design-wave extremes (row nonlinear, design_wave), or None when not computed.
    """

    sea: CradleSeaModel
    transfer: CradleSeaTransfer
    spectral: CradleSpectralExtremes
    design: CradleDesignWaveExtremes | None


def cradle_sea_state(analysis: SpectralAnalysis, *, design_waves: bool = True, options: HBMOptions | None = None) -> CradleSeaState:
    """The cradle columns of a spectral analysis's sea state: linear spectral and (``design_waves``) design-wave MPMs,
    the design waves on frictional pads when ``seafastening.friction_coefficient`` is above 0 (:func:`design_wave_friction`).

    Raises
    ------
    ValueError
        If the case's cradles cannot be built (naming the key), or the friction coefficient differs between saddles.
    """
    directional = analysis.directional
    if directional is None:
        raise ValueError("cradle_sea_state: the analysis has no per-direction transfer functions (spectral_analysis gives them)")
    friction = design_wave_friction(analysis.case)
    sea = cradle_sea_model(analysis.case, analysis.model)
    transfer = cradle_sea_transfer(sea, directional)
    stiffness = sea.dynamics.problem.element_stiffness_N_per_m
    spectral = cradle_spectral_extremes(transfer, analysis.spectrum, cradle_still_water(sea), stiffness, analysis.case.sea_state.duration_s)
    design = cradle_design_waves(sea, directional, transfer, spectral, options=options, friction=friction) if design_waves else None
    return CradleSeaState(sea, transfer, spectral, design)
