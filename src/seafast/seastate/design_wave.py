"""Nonlinear most probable maxima of a sea state by the design-wave method, solved by harmonic balance.

The rule (``docs/operability.md``; the equivalent-design-wave approach of offshore and class
practice: the regular wave at the peak of a response's transfer or response spectrum whose
linear response equals the target linear extreme, e.g. DNV-RP-C103 and DNV-CG-0130's design
waves, Lloyd's Register's characteristic wave), per reported quantity q:

1. the governing location of the linear spectral extreme: the saddle with the largest
   still-water + MPM force (``F_N``) or compression (``u_s_m``), the moment point with the largest
   ``|M_0| + MPM`` (``M_b_Nm``, ``sigma_b_Pa``), the saddle with the smallest still-water
   compression minus its MPM, the one nearest to lifting off (``u_d_m``);
2. that response's spectrum ``S_r = |H_r|^2 S``, its peak frequency, and the band around it where
   ``S_r`` is at least :attr:`DesignWaveSettings.band_fraction` of the peak; the design
   frequencies are the peak and the band's two ends;
3. at each design frequency the regular wave of amplitude ``a = MPM_r / |H_r(omega)|``, whose
   linear dynamic response equals the linear spectral MPM (Rayleigh);
4. the harmonic balance of that wave, still water included (exact contact law, fixed H), gives
   the nonlinear maxima; the estimate of q is the largest q over q's own design waves.

Where no saddle lifts off in a design wave its nonlinear answer equals the linear one, so the
method returns the linear spectral MPM there exactly. Waves that coincide (same frequency and
amplitude, e.g. F and u_s at one saddle) are solved once; waves at one frequency share their
operators (:mod:`seafast.seastate.wave_response`). ``uplift_per_hour`` is Rice's rate of the
linear compressions (the nonlinear model equals the linear one until a saddle separates, so the
rate of first separations is the same; bounces after a re-contact are not counted).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import NDArray

from seafast.excitation.harmonic import HarmonicExcitation
from seafast.seastate.spectral import ResponseStatistics, SpectralAnalysis
from seafast.seastate.transfer import TransferFunctions
from seafast.seastate.wave_response import (
    RESPONSE_QUANTITIES,
    MomentMap,
    WaveOperators,
    WaveSolution,
    moment_map,
    solve_wave,
    solve_wave_adaptive,
    wave_operators,
)
from seafast.solvers.hbm import SAFE_HARMONICS, HBMOptions

__all__ = [
    "DesignWaveSettings",
    "DesignWave",
    "DesignWaveExtremes",
    "select_design_waves",
    "unit_wave_excitation",
    "design_wave_extremes",
    "static_totals",
    "still_water_excitation",
    "sea_state_design_waves",
]


@dataclass(frozen=True)
class DesignWaveSettings:
    """Settings of the design-wave rule and its harmonic balance (not case keys; defaults verified).

    Attributes
    ----------
    band_fraction
        Design frequencies span the band where the response spectrum is at least this share of its peak [-].
    band_points
        Design frequencies per quantity: 1 (the peak), 3 (peak and band ends) or more (also evenly inside).
    harmonics
        H of the harmonic balance (fixed: the amplitude searches reuse the operators), or None:
        each wave by the package's adaptive harmonic balance (the converged periodic answer, at
        tens to hundreds of times the cost; docs/operability.md).
    fallback_harmonics
        Fewer harmonics tried in turn when the solve at ``harmonics`` does not converge: with the
        exact contact law a truncated harmonic balance of heavy lift-off can have no solution near
        its start (the residual stalls near 1e-3), while fewer harmonics converge in a few Newton
        steps (docs/operability.md); the H used is recorded per wave.
    time_samples
        N, or None for the default of H.
    tolerance
        Relative residual of the harmonic balance.
    """

    band_fraction: float = 0.5
    band_points: int = 3
    harmonics: int | None = SAFE_HARMONICS  # within 0.3 % of the adaptive H on the measured sea states (docs/operability.md)
    fallback_harmonics: tuple[int, ...] = (12, 8)
    time_samples: int | None = None
    tolerance: float = 1e-10

    def __post_init__(self) -> None:
        if not (0.0 < self.band_fraction <= 1.0):
            raise ValueError(f"DesignWaveSettings.band_fraction = {self.band_fraction!r}; allowed: (0, 1]")
        if int(self.band_points) < 1:
            raise ValueError(f"DesignWaveSettings.band_points = {self.band_points!r}; allowed: an integer >= 1")

    def hbm_options(self, harmonics: int | None = -1) -> HBMOptions:
        """The harmonic-balance options (exact contact law, condensed, Newton) at ``harmonics`` (default: this H)."""
        H = self.harmonics if harmonics == -1 else harmonics
        return HBMOptions(harmonics=None if H is None else int(H), time_samples=self.time_samples, tolerance=float(self.tolerance))


@dataclass(frozen=True)
class DesignWave:
    """One design wave: a regular head wave designed for one quantity.

    Attributes
    ----------
    quantity
        The quantity it is designed for (``F_N``, ``M_b_Nm``, ``sigma_b_Pa``, ``u_s_m``, ``u_d_m``).
    location
        Saddle index (``F_N``, ``u_s_m``, ``u_d_m``) or moment-point index (``M_b_Nm``, ``sigma_b_Pa``).
    frequency_index
        Index of its frequency on the sea-state grid.
    omega_rad_s
        Wave frequency [rad/s].
    amplitude_m
        Wave amplitude [m]: the linear MPM of the response over its transfer function's modulus.
    amplitude_per_hs
        ``amplitude_m`` per metre of significant height [m/m] (the linear MPM is proportional to Hs).
    role
        ``peak``, ``band_low``, ``band_high`` or ``band``.
    """

    quantity: str
    location: int
    frequency_index: int
    omega_rad_s: float
    amplitude_m: float
    amplitude_per_hs: float
    role: str


def _statistics(analysis: SpectralAnalysis, quantities: Sequence[str]) -> dict[str, tuple[ResponseStatistics, NDArray[np.complex128], int]]:
    """Per quantity: the response statistics, its transfer function at the governing location, the location."""
    e, tf = analysis.extremes, analysis.transfer
    sw = e.still_water
    out: dict[str, tuple[ResponseStatistics, NDArray[np.complex128], int]] = {}
    for q in quantities:
        if q == "F_N":
            loc = int(np.argmax(sw.saddle_force_N + e.saddle_force.mpm))
            out[q] = (e.saddle_force, tf.saddle_force_N[:, loc], loc)
        elif q == "u_s_m":
            loc = int(np.argmax(sw.saddle_compression_m + e.saddle_compression.mpm))
            out[q] = (e.saddle_compression, tf.saddle_compression_m[:, loc], loc)
        elif q == "M_b_Nm":
            loc = int(np.argmax(np.abs(sw.bending_moment_Nm) + e.bending_moment.mpm))
            out[q] = (e.bending_moment, tf.bending_moment_Nm[:, loc], loc)
        elif q == "sigma_b_Pa":
            loc = int(np.argmax(np.abs(sw.bending_stress_Pa) + e.bending_stress.mpm))
            out[q] = (e.bending_stress, tf.bending_moment_Nm[:, loc] / tf.bending_section_modulus_m3[loc], loc)
        else:  # u_d_m: the saddle nearest to lifting off
            loc = int(np.argmin(sw.saddle_compression_m - e.saddle_compression.mpm))
            out[q] = (e.saddle_compression, tf.saddle_compression_m[:, loc], loc)
    return out


def _band(spectrum: NDArray[np.float64], fraction: float) -> tuple[int, int, int]:
    """(low, peak, high) grid indices of the contiguous band around the peak where S >= fraction * peak."""
    peak = int(np.argmax(spectrum))
    above = spectrum >= fraction * spectrum[peak]
    low = peak
    while low > 0 and above[low - 1]:
        low -= 1
    high = peak
    while high < spectrum.size - 1 and above[high + 1]:
        high += 1
    return low, peak, high


def select_design_waves(
    analysis: SpectralAnalysis, settings: DesignWaveSettings = DesignWaveSettings(), quantities: Sequence[str] = RESPONSE_QUANTITIES
) -> tuple[DesignWave, ...]:
    """The design waves of the given quantities of a sea state (rule in the module docstring).

    A quantity whose response is zero in the sea (no dynamic part) gets no wave.
    """
    hs = float(analysis.spectrum.significant_height_m)
    w = analysis.spectrum.omega_rad_s
    waves: list[DesignWave] = []
    for quantity, (stats, transfer, loc) in _statistics(analysis, quantities).items():
        mpm = float(stats.mpm[loc])
        s_r = stats.spectrum[:, loc]
        if not (mpm > 0.0 and np.max(s_r) > 0.0):
            continue
        low, peak, high = _band(s_r, settings.band_fraction)
        picks: list[tuple[int, str]] = [(peak, "peak")]
        if settings.band_points >= 3:
            picks += [(low, "band_low"), (high, "band_high")]
        if settings.band_points > 3:
            inner = np.linspace(w[low], w[high], int(settings.band_points) - 1)[1:-1]
            picks += [(int(np.argmin(np.abs(w - x))), "band") for x in inner]
        seen: set[int] = set()
        for index, role in picks:
            if index in seen:
                continue
            seen.add(index)
            amplitude = mpm / float(np.abs(transfer[index]))
            waves.append(DesignWave(quantity, loc, index, float(w[index]), amplitude, amplitude / hs if hs > 0 else float("nan"), role))
    return tuple(waves)


def unit_wave_excitation(static: HarmonicExcitation, transfer: TransferFunctions, index: int) -> HarmonicExcitation:
    """Still water (k = 0) plus the regular wave of unit amplitude at grid frequency ``index`` (k = 1)."""
    return HarmonicExcitation(
        float(transfer.omega_rad_s[index]),
        np.vstack([static.deck_displacement[:1], transfer.deck_displacement[index][None]]),
        np.vstack([static.cargo_load_N[:1], transfer.cargo_load_N[index][None]]),
        np.vstack([static.cargo_line_load_N_per_m[:1], transfer.cargo_line_load_N_per_m[index][None]]),
        f"regular head wave of unit amplitude at {transfer.omega_rad_s[index]:.4g} rad/s (transfer functions)",
    )


@dataclass(frozen=True)
class DesignWaveExtremes:
    """The nonlinear design-wave extremes of one sea state.

    Attributes
    ----------
    waves
        The design waves (:func:`select_design_waves`).
    solutions
        One :class:`~seafast.seastate.wave_response.WaveSolution` per wave, same order.
    totals
        Per quantity, the largest nonlinear maximum over its own design waves, still water
        included [N, N m, Pa, m, m], and ``uplift_per_hour`` (Rice, linear; see the module docstring).
    governing
        Per quantity, the index in :attr:`waves` of the wave that gave the total (-1: no wave).
    converged
        Every harmonic-balance solve converged.
    settings
        The settings used.
    """

    waves: tuple[DesignWave, ...]
    solutions: tuple[WaveSolution, ...]
    totals: Mapping[str, float]
    governing: Mapping[str, int]
    converged: bool
    settings: DesignWaveSettings = field(default_factory=DesignWaveSettings)

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
    operators: dict[tuple[int, int], WaveOperators] | None = None,
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
        A cache of wave operators by (grid index, H) (filled here; pass the same dict to reuse
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
    options = settings.hbm_options()
    cache: dict[tuple[int, int], WaveOperators] = {} if operators is None else operators
    mm = moment_map(analysis.model) if moments is None else moments
    solved: dict[tuple[int, float], WaveSolution] = {}
    solutions = []
    last: WaveSolution | None = None
    for wave in waves:
        key = (wave.frequency_index, round(wave.amplitude_m, 12))
        if key not in solved and settings.harmonics is None:
            unit = unit_wave_excitation(static, analysis.transfer, wave.frequency_index)
            solved[key] = solve_wave_adaptive(analysis.model, unit, wave.amplitude_m, mm, options)
        elif key not in solved and settings.harmonics is not None:
            # start from this frequency's previous solution (an amplitude search), else from the last wave solved:
            # the quantities' design waves lie close together (neighbouring frequencies, amplitudes within a few
            # per cent), and a start that fails falls back on the solver's own (solve_wave)
            previous = None if warm is None else warm.get(wave.frequency_index)
            previous = previous if previous is not None else last
            for H in (int(settings.harmonics), *settings.fallback_harmonics):
                opts = settings.hbm_options(H)
                if (wave.frequency_index, H) not in cache:
                    unit = unit_wave_excitation(static, analysis.transfer, wave.frequency_index)
                    cache[(wave.frequency_index, H)] = wave_operators(analysis.model, unit, opts, mm)
                start = (
                    previous.compression_harmonics_m if previous is not None and previous.converged and previous.harmonics == H else None
                )
                sol = solve_wave(cache[(wave.frequency_index, H)], wave.amplitude_m, opts, start)
                if sol.converged:
                    break
            solved[key] = sol
            last = sol if sol.converged else last
            if warm is not None:
                warm[wave.frequency_index] = sol
        solutions.append(solved[key])
    totals = static_totals(analysis)
    governing = dict.fromkeys(RESPONSE_QUANTITIES, -1)
    for i, (wave, sol) in enumerate(zip(waves, solutions, strict=True)):
        q = wave.quantity
        if governing[q] < 0 or sol.maxima[q] > totals[q]:
            totals[q], governing[q] = sol.maxima[q], i
    totals["uplift_per_hour"] = float(analysis.extremes.totals["uplift_per_hour"])
    converged = all(s.converged for s in solved.values())
    return DesignWaveExtremes(waves, tuple(solutions), totals, governing, converged, settings)


def still_water_excitation(analysis: SpectralAnalysis) -> HarmonicExcitation:
    """The case's still-water excitation (deck at k = 0), what every design wave adds to."""
    from seafast.excitation.vessel import vessel_excitation

    return vessel_excitation(analysis.case).cargo_excitation(analysis.model, analysis.case).static_part()


def sea_state_design_waves(analysis: SpectralAnalysis, settings: DesignWaveSettings = DesignWaveSettings()) -> DesignWaveExtremes:
    """The (nonlinear, design_wave) extremes of a spectral analysis's sea state (all five quantities)."""
    return design_wave_extremes(analysis, still_water_excitation(analysis), settings)
