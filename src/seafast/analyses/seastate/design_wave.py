"""Nonlinear most probable maxima of a sea state by the design-wave method, solved by harmonic balance.

The rule (``docs/operability.md``; the equivalent-design-wave approach of offshore and class
practice: the regular wave at the peak of a response's transfer or response spectrum whose
linear response equals the target linear extreme, e.g. DNV-RP-C103 and DNV-CG-0130's design
waves, Lloyd's Register's characteristic wave), per reported quantity q:

1. the locations designed for: every saddle for the saddle quantities (``F_N``, ``u_s_m``,
   ``u_d_m``; the saddle of the linear extreme first), the moment point of the largest linear
   ``|M_0| + MPM`` for ``M_b_Nm`` and ``sigma_b_Pa`` (a field of 228 points: its governing point only);
2. at each location, the response's spectrum ``S_r = |H_r|^2 S``, its peak frequency, and the band
   around it where ``S_r`` is at least :attr:`DesignWaveSettings.band_fraction` of the peak; the
   design frequencies are the peak and the band's two ends;
3. at each design frequency the regular wave of amplitude ``a = MPM_r / |H_r(omega)|``, whose
   linear dynamic response at that location equals its linear spectral MPM (Rayleigh);
4. the harmonic balance of that wave, still water included (exact contact law, fixed H), gives
   the nonlinear response; each wave is read only for its quantity, at its saddle, or for a
   moment quantity at the moment points where it is at most an MPM wave (:func:`read_locations`;
   elsewhere the same wave is not an MPM event: at another saddle its linear response can exceed
   that saddle's MPM); the estimate of q is the largest of these readings over q's waves, as the
   spectral total is the largest over locations of still water + MPM.

Where no saddle lifts off in a design wave its nonlinear answer equals the linear one, so the
method returns the linear spectral total there (to the solvers' round-off, ~1e-8). Waves that
coincide (same frequency and amplitude: ``F_N``, ``u_s_m`` and ``u_d_m`` at one saddle) are solved
once; waves at one frequency share their operators (:mod:`seafast.analyses.seastate.wave_response`).
``uplift_per_hour`` is Rice's rate of the linear compressions (the nonlinear model equals the
linear one until a saddle separates, so the rate of first separations is the same; bounces after
a re-contact are not counted). The rule itself (steps 1-3 and where a wave is read) is
:mod:`seafast.analyses.seastate.design_wave_rule`, re-exported here.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import NDArray

from seafast.analyses.seastate.design_wave_rule import (
    DesignWave,
    DesignWaveSettings,
    design_directions,
    read_locations,
    select_design_waves,
)
from seafast.analyses.seastate.spectral import SpectralAnalysis
from seafast.analyses.seastate.transfer import TransferFunctions
from seafast.analyses.seastate.wave_response import (
    RESPONSE_QUANTITIES,
    MomentMap,
    WaveOperators,
    WaveSolution,
    moment_map,
    solve_wave,
    solve_wave_adaptive,
    wave_operators,
)
from seafast.excitation.harmonic import HarmonicExcitation

__all__ = [
    "DesignWaveSettings",
    "DesignWave",
    "DesignWaveExtremes",
    "select_design_waves",
    "read_locations",
    "unit_wave_excitation",
    "design_wave_extremes",
    "static_totals",
    "still_water_excitation",
    "sea_state_design_waves",
]


def unit_wave_excitation(static: HarmonicExcitation, transfer: TransferFunctions, index: int) -> HarmonicExcitation:
    """Still water (k = 0) plus the regular wave of unit amplitude at grid frequency ``index`` (k = 1)."""
    return HarmonicExcitation(
        float(transfer.omega_rad_s[index]),
        np.vstack([static.deck_displacement[:1], transfer.deck_displacement[index][None]]),
        np.vstack([static.cargo_load_N[:1], transfer.cargo_load_N[index][None]]),
        np.vstack([static.cargo_line_load_N_per_m[:1], transfer.cargo_line_load_N_per_m[index][None]]),
        f"regular wave of unit amplitude at {transfer.omega_rad_s[index]:.4g} rad/s, heading {transfer.heading_deg:g} deg "
        "(transfer functions)",
    )


@dataclass(frozen=True)
class DesignWaveExtremes:
    """The nonlinear design-wave extremes of one sea state.

    Attributes
    ----------
    waves
        The design waves (:func:`select_design_waves`).
    solutions
        One :class:`~seafast.analyses.seastate.wave_response.WaveSolution` per wave, same order.
    totals
        Per quantity, the largest over its design waves of the nonlinear maximum at the wave's own
        location, still water included (at least the still-water value) [N, N m, Pa, m, m], and
        ``uplift_per_hour`` (Rice, linear; see the module docstring).
    governing
        Per quantity, the index in :attr:`waves` of the wave that gave the total (-1: none did,
        the still water governs).
    converged
        Every harmonic-balance solve converged.
    settings
        The settings used.
    read
        Per wave, the locations it is read at for its quantity (:func:`read_locations`).
    """

    waves: tuple[DesignWave, ...]
    solutions: tuple[WaveSolution, ...]
    totals: Mapping[str, float]
    governing: Mapping[str, int]
    converged: bool
    settings: DesignWaveSettings = field(default_factory=DesignWaveSettings)
    read: tuple[NDArray[np.int64], ...] = ()

    def row(self) -> dict[str, Any]:
        """The (nonlinear, design_wave) row of seastate.csv."""
        return {
            "model": "nonlinear",
            "method": "design_wave",
            **{k: float(v) for k, v in self.totals.items()},
            "converged": bool(self.converged),
        }


def static_totals(analysis: SpectralAnalysis) -> dict[str, float]:
    """The still-water values of the quantities (what a sea without waves gives)."""
    sw = analysis.extremes.still_water
    return {
        "F_N": float(np.max(sw.saddle_force_N)),
        "M_b_Nm": float(np.max(np.abs(sw.bending_moment_Nm))),
        "sigma_b_Pa": float(np.max(np.abs(sw.bending_stress_Pa))),
        "u_s_m": float(max(np.max(sw.saddle_compression_m), 0.0)),
        "u_d_m": float(max(np.max(-sw.saddle_compression_m), 0.0)),
    }


def design_wave_extremes(
    analysis: SpectralAnalysis,
    static: HarmonicExcitation,
    settings: DesignWaveSettings = DesignWaveSettings(),
    *,
    quantities: Sequence[str] = RESPONSE_QUANTITIES,
    operators: dict[tuple[int, int, int], WaveOperators] | None = None,
    moments: MomentMap | None = None,
    warm: dict[int, WaveSolution] | None = None,
) -> DesignWaveExtremes:
    """Nonlinear MPM estimates of the case's sea state by the design-wave method.

    Parameters
    ----------
    analysis
        The linear spectral analysis (transfer functions, spectrum, extremes) of the sea state.
    static
        The still-water excitation of the case (``vessel_excitation(case).cargo_excitation(model, case).static_part()``).
    settings
        Rule and harmonic-balance settings.
    quantities
        The quantities to estimate (default all five); the others keep their still-water value.
    operators
        A cache of wave operators by (grid index, direction, H) (filled here; pass the same dict to reuse
        them for another sea state on the same grid, e.g. another Hs).
    moments
        The model's moment map (computed when omitted).
    warm
        Previous solutions by grid index (filled here): each solve starts from the one at its
        frequency, e.g. the neighbouring Hs of an amplitude search.

    Returns
    -------
    DesignWaveExtremes
        A solve that does not converge flags ``converged`` (never raised).
    """
    unknown = [q for q in quantities if q not in RESPONSE_QUANTITIES]
    if unknown:
        raise ValueError(f"design_wave_extremes: quantities {unknown}; allowed: {', '.join(RESPONSE_QUANTITIES)}")
    waves = select_design_waves(analysis, settings, quantities)
    directions = design_directions(analysis)
    options = settings.hbm_options()
    cache: dict[tuple[int, int, int], WaveOperators] = {} if operators is None else operators
    mm = moment_map(analysis.model) if moments is None else moments
    solved: dict[tuple[int, int, float], WaveSolution] = {}
    solutions = []
    last: WaveSolution | None = None
    for wave in waves:
        key = (wave.frequency_index, wave.direction, round(wave.amplitude_m, 12))
        transfer = directions[wave.direction]
        if key not in solved and settings.harmonics is None:
            unit = unit_wave_excitation(static, transfer, wave.frequency_index)
            solved[key] = solve_wave_adaptive(analysis.model, unit, wave.amplitude_m, mm, options)
        elif key not in solved and settings.harmonics is not None:
            # start from this frequency's previous solution (an amplitude search), else from the last wave solved:
            # the quantities' design waves lie close together (neighbouring frequencies, amplitudes within a few
            # per cent), and a start that fails falls back on the solver's own (solve_wave)
            previous = None if warm is None else warm.get(wave.frequency_index)
            previous = previous if previous is not None else last
            for H in (int(settings.harmonics), *settings.fallback_harmonics):
                opts = settings.hbm_options(H)
                op_key = (wave.frequency_index, wave.direction, H)
                if op_key not in cache:
                    unit = unit_wave_excitation(static, transfer, wave.frequency_index)
                    cache[op_key] = wave_operators(analysis.model, unit, opts, mm)
                start = (
                    previous.compression_harmonics_m if previous is not None and previous.converged and previous.harmonics == H else None
                )
                sol = solve_wave(cache[op_key], wave.amplitude_m, opts, start)
                if sol.converged:
                    break
            solved[key] = sol
            last = sol if sol.converged else last
            if warm is not None:
                warm[wave.frequency_index] = sol
        solutions.append(solved[key])
    totals = static_totals(analysis)
    governing = dict.fromkeys(RESPONSE_QUANTITIES, -1)
    read = tuple(read_locations(analysis, wave) for wave in waves)
    for i, (wave, sol) in enumerate(zip(waves, solutions, strict=True)):
        q = wave.quantity
        value = sol.maximum_at(q, read[i])  # read for its quantity, where it is designed (read_locations)
        if value > totals[q] or (governing[q] < 0 and value == totals[q]):
            totals[q], governing[q] = value, i
    totals["uplift_per_hour"] = float(analysis.extremes.totals["uplift_per_hour"])
    converged = all(s.converged for s in solved.values())
    return DesignWaveExtremes(waves, tuple(solutions), totals, governing, converged, settings, read)


def still_water_excitation(analysis: SpectralAnalysis) -> HarmonicExcitation:
    """The case's still-water excitation (deck at k = 0), what every design wave adds to."""
    from seafast.excitation.vessel import vessel_excitation

    return vessel_excitation(analysis.case).cargo_excitation(analysis.model, analysis.case).static_part()


def sea_state_design_waves(analysis: SpectralAnalysis, settings: DesignWaveSettings = DesignWaveSettings()) -> DesignWaveExtremes:
    """The (nonlinear, design_wave) extremes of a spectral analysis's sea state (all five quantities)."""
    return design_wave_extremes(analysis, still_water_excitation(analysis), settings)
