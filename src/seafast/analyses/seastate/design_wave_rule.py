"""The design-wave rule: which regular waves a sea state's design waves are, and where each is read.

Per reported quantity (``docs/operability.md`` section 1): the locations designed for (every
saddle for the saddle quantities, the linear extreme's first; the moment field's governing
point), at each location the peak of its response spectrum and the ends of the band where the
spectrum is at least :attr:`DesignWaveSettings.band_fraction` of the peak, and at each such
frequency the regular wave whose linear response there equals the location's linear spectral
MPM (:func:`select_design_waves`); a wave is read for its quantity only where it is at most an
MPM wave (:func:`read_locations`). In a short-crested sea (the MPM from the spread response spectrum) the wave
comes from the quadrature direction whose transfer function there is largest: the smallest wave that gives the
MPM (at the mean heading of a spread beam sea, where the response is small, the rule's wave would be several times
steeper than any sea carries). The harmonic balance of the waves and the estimates are in
:mod:`seafast.analyses.seastate.design_wave`. Units SI.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from seafast.analyses.seastate.spectral import ResponseStatistics, SpectralAnalysis
from seafast.analyses.seastate.transfer import TransferFunctions
from seafast.analyses.seastate.wave_maxima import SADDLE_QUANTITIES
from seafast.analyses.seastate.wave_response import RESPONSE_QUANTITIES
from seafast.solvers.hbm import HBMOptions

__all__ = ["DesignWaveSettings", "DesignWave", "select_design_waves", "read_locations", "quantity_transfer", "design_directions"]


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
        None (the default): each wave's converged periodic answer, every harmonic, by exact-event
        shooting (the package's default solve), kept on 128 harmonics; or a fixed H of the harmonic
        balance (the amplitude searches reuse its operators; H = 16 is about half the cost and
        2-3 % low in heavy lift-off: docs/operability.md).
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
    # converged: the heavy lift-off cases within 1.1 % of the Monte Carlo MPM, against 2-3 % low at H = 16
    # (docs/operability.md, section 3)
    harmonics: int | None = None
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
    """One design wave: a regular wave designed for one quantity.

    Attributes
    ----------
    quantity
        The quantity it is designed for (``F_N``, ``M_b_Nm``, ``sigma_b_Pa``, ``u_s_m``, ``u_d_m``).
    location
        The location it is designed for, where it is read: saddle index (``F_N``, ``u_s_m``,
        ``u_d_m``) or moment-point index (``M_b_Nm``, ``sigma_b_Pa``).
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
    direction
        Index of its direction in the sea state's quadrature (0 for a long-crested sea).
    heading_deg
        Its heading [deg] (180 = head seas).
    """

    quantity: str
    location: int
    frequency_index: int
    omega_rad_s: float
    amplitude_m: float
    amplitude_per_hs: float
    role: str
    direction: int = 0
    heading_deg: float = 180.0


def quantity_transfer(tf: TransferFunctions, quantity: str, location: int) -> NDArray[np.complex128]:
    """A quantity's transfer function at one location (saddle or moment point), (n_w,) per metre of wave."""
    if quantity == "F_N":
        return tf.saddle_force_N[:, location]
    if quantity in SADDLE_QUANTITIES:
        return tf.saddle_compression_m[:, location]
    if quantity == "M_b_Nm":
        return tf.bending_moment_Nm[:, location]
    return tf.bending_stress_Pa[:, location]


def _governing_saddle(analysis: SpectralAnalysis, quantity: str) -> int:
    """The saddle of the linear spectral extreme of a saddle quantity (``u_d_m``: the one nearest to lifting off)."""
    e = analysis.extremes
    sw = e.still_water
    if quantity == "F_N":
        return int(np.argmax(sw.saddle_force_N + e.saddle_force.mpm))
    if quantity == "u_s_m":
        return int(np.argmax(sw.saddle_compression_m + e.saddle_compression.mpm))
    return int(np.argmin(sw.saddle_compression_m - e.saddle_compression.mpm))


def _targets(analysis: SpectralAnalysis, quantities: Sequence[str]) -> list[tuple[str, ResponseStatistics, int]]:
    """Per quantity and location designed for: (quantity, response statistics, location).

    Saddle quantities at every saddle, the linear governing saddle first (it starts the chain of
    warm starts); moment quantities at the moment point of the linear spectral extreme.
    """
    e = analysis.extremes
    sw = e.still_water
    out: list[tuple[str, ResponseStatistics, int]] = []
    for q in quantities:
        if q in SADDLE_QUANTITIES:
            first = _governing_saddle(analysis, q)
            stats = e.saddle_force if q == "F_N" else e.saddle_compression
            out += [(q, stats, loc) for loc in (first, *(s for s in range(analysis.model.saddle_count) if s != first))]
        elif q == "M_b_Nm":
            out.append((q, e.bending_moment, int(np.argmax(np.abs(sw.bending_moment_Nm) + e.bending_moment.mpm))))
        else:  # sigma_b_Pa
            out.append((q, e.bending_stress, int(np.argmax(np.abs(sw.bending_stress_Pa) + e.bending_stress.mpm))))
    return out


def design_directions(analysis: SpectralAnalysis) -> tuple[TransferFunctions, ...]:
    """The transfer functions a design wave may come from: the quadrature's directions of a spread sea, else the mean."""
    sea = analysis.directional
    if sea is None or sea.quadrature.long_crested:
        return (analysis.transfer,)
    return sea.per_direction


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
    directions = design_directions(analysis)
    waves: list[DesignWave] = []
    for quantity, stats, loc in _targets(analysis, quantities):
        modulus = np.abs(np.stack([quantity_transfer(tf, quantity, loc) for tf in directions]))  # (n_dir, n_w)
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
            j = int(np.argmax(modulus[:, index]))  # the direction that needs the smallest wave
            amplitude = mpm / float(modulus[j, index])
            per_hs = amplitude / hs if hs > 0 else float("nan")
            waves.append(DesignWave(quantity, loc, index, float(w[index]), amplitude, per_hs, role, j, float(directions[j].heading_deg)))
    return tuple(waves)


def read_locations(analysis: SpectralAnalysis, wave: DesignWave) -> NDArray[np.int64]:
    """Where a design wave is read for its quantity: saddle indices or moment-point indices.

    A saddle quantity's wave: its own saddle (every saddle has its own waves). A moment quantity's
    wave (designed for the governing point only): every moment point where it is at most an MPM
    wave, ``a |H_x(omega)| <= MPM_x`` (1e-9 relative slack; the governing point itself is at 1).
    Where the wave is more severe than a location's MPM its response there is not that location's
    MPM event and is not read; where it is less severe, its nonlinear maximum there estimates from
    below what that point's own waves would give, and catches a moment peak that lift-off moves
    away from the governing point. In the linear model every reading is at most the location's
    still water + MPM, so the method returns the linear spectral total where nothing lifts off.
    """
    if wave.quantity in SADDLE_QUANTITIES:
        return np.array([wave.location], dtype=np.int64)
    e, tf = analysis.extremes, analysis.transfer
    stats = e.bending_moment if wave.quantity == "M_b_Nm" else e.bending_stress
    field_tf = tf.bending_moment_Nm if wave.quantity == "M_b_Nm" else tf.bending_stress_Pa
    response = wave.amplitude_m * np.abs(field_tf[wave.frequency_index])
    covered = (stats.mpm > 0.0) & (response <= stats.mpm * (1.0 + 1e-9))
    covered[wave.location] = True
    return np.asarray(np.flatnonzero(covered), dtype=np.int64)
