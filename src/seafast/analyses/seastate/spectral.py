"""Linear spectral extremes: response spectra, moments, Rayleigh most probable maxima, uplift rate.

For a linear response r with transfer function H(omega) per metre of wave amplitude in a sea of
one-sided spectrum S(omega) (a stationary Gaussian process):

* response spectrum ``S_r = |H|^2 S`` (a short-crested sea: ``S sum_j w_j |H(omega, theta_j)|^2`` over the
  spreading's quadrature directions, :mod:`seafast.analyses.seastate.directional_transfer`); moments
  ``m_n = int omega^n S_r d omega`` (trapezoid on the sea-state grid); standard deviation ``sigma = sqrt(m0)``; mean zero-crossing period
  ``Tz = 2 pi sqrt(m0 / m2)``;
* most probable maximum over a duration D (narrow-band, Rayleigh-distributed peaks, N = D / Tz
  cycles): ``MPM = sigma sqrt(2 ln(D / Tz))`` (0 when D < Tz or sigma = 0);
* rate of downward crossings of a level below the mean (Rice): a saddle with still-water
  compression mu lifts off at ``nu = (1 / 2 pi) sqrt(m2 / m0) exp(-mu^2 / (2 m0))`` per second.

Totals add the still-water part with the sign that governs each limit: saddle force and
compression ``max over saddles (static + MPM)``; bending moment and stress ``max over x of
(|static(x)| + MPM(x))`` (the dynamic part is symmetric, so the larger excursion is the one
that adds to the static moment's magnitude). The linear model's saddles are bilateral and never
open: its u_d is 0, as in ``seafast run``; whether that can be trusted is what
``uplift_per_hour`` (summed over the saddles) says.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from seafast.analyses.seastate.directional_transfer import SeaStateTransfer, sea_state_roll_damping, sea_state_transfer
from seafast.analyses.seastate.spectrum import WaveSpectrum, sea_state_spectrum
from seafast.analyses.seastate.transfer import StillWater, TransferFunctions, still_water
from seafast.config.schema import Case
from seafast.model.from_case import build_model
from seafast.model.structure import StructuralModel

__all__ = [
    "ResponseStatistics",
    "SpectralExtremes",
    "SpectralAnalysis",
    "SEASTATE_COLUMNS",
    "response_statistics",
    "squared_response_statistics",
    "rayleigh_mpm",
    "downcrossing_rate_per_s",
    "spectral_extremes",
    "spectral_analysis",
]

SEASTATE_COLUMNS = ("model", "method", "F_N", "M_b_Nm", "sigma_b_Pa", "u_s_m", "u_d_m", "uplift_per_hour", "converged")
"""Columns of seastate.csv (the scriptable contract)."""


def rayleigh_mpm(m0: NDArray[np.float64], m2: NDArray[np.float64], duration_s: float) -> NDArray[np.float64]:
    """Most probable maximum ``sqrt(m0) sqrt(2 ln(D / Tz))`` of a Gaussian response over ``duration_s`` [unit of r].

    0 where the response is zero or has fewer than one cycle in the duration.
    """
    m0, m2 = np.asarray(m0, dtype=float), np.asarray(m2, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        tz = 2.0 * np.pi * np.sqrt(m0 / m2)
        cycles = np.where((m0 > 0) & (m2 > 0), duration_s / tz, 0.0)
    return np.sqrt(m0 * 2.0 * np.log(np.maximum(cycles, 1.0)))


def downcrossing_rate_per_s(mean: NDArray[np.float64], m0: NDArray[np.float64], m2: NDArray[np.float64]) -> NDArray[np.float64]:
    """Rice's rate [1/s] of downward crossings of zero by a Gaussian process of ``mean`` and moments m0, m2."""
    mean, m0, m2 = (np.asarray(a, dtype=float) for a in (mean, m0, m2))
    with np.errstate(divide="ignore", invalid="ignore"):
        rate = np.sqrt(m2 / m0) / (2.0 * np.pi) * np.exp(-(mean**2) / (2.0 * m0))
    return np.where(m0 > 0, rate, 0.0)


@dataclass(frozen=True)
class ResponseStatistics:
    """Spectral statistics of one response quantity at several locations (saddles or x).

    Attributes
    ----------
    spectrum
        (n_w, n_loc) response spectrum ``|H|^2 S`` [unit^2 s/rad].
    m0, m2, m4
        (n_loc,) spectral moments [unit^2, unit^2 (rad/s)^2, unit^2 (rad/s)^4].
    sigma
        (n_loc,) standard deviation [unit].
    zero_crossing_period_s
        (n_loc,) ``2 pi sqrt(m0 / m2)`` [s] (inf for a zero response).
    mpm
        (n_loc,) Rayleigh most probable maximum of the dynamic part over the duration [unit].
    """

    spectrum: NDArray[np.float64]
    m0: NDArray[np.float64]
    m2: NDArray[np.float64]
    m4: NDArray[np.float64]
    sigma: NDArray[np.float64]
    zero_crossing_period_s: NDArray[np.float64]
    mpm: NDArray[np.float64]


def response_statistics(transfer: NDArray[np.complex128], spectrum: WaveSpectrum, duration_s: float) -> ResponseStatistics:
    """Statistics of the responses whose transfer functions are the columns of ``transfer`` (n_w, n_loc)."""
    return squared_response_statistics(np.abs(transfer) ** 2, spectrum, duration_s)


def squared_response_statistics(squared: NDArray[np.float64], spectrum: WaveSpectrum, duration_s: float) -> ResponseStatistics:
    """Statistics of the responses whose squared transfer functions ``|H|^2`` (a short-crested sea: ``sum_j w_j |H_j|^2``)
    are the columns of ``squared`` (n_w, n_loc) [unit^2/m^2]."""
    w = spectrum.omega_rad_s
    s_r = squared * spectrum.density_m2_s_per_rad[:, None]
    m0, m2, m4 = (np.atleast_1d(np.trapezoid(w[:, None] ** n * s_r, w, axis=0)) for n in (0, 2, 4))
    with np.errstate(divide="ignore", invalid="ignore"):
        tz = np.where(m2 > 0, 2.0 * np.pi * np.sqrt(m0 / m2), np.inf)
    return ResponseStatistics(s_r, m0, m2, m4, np.sqrt(m0), tz, rayleigh_mpm(m0, m2, duration_s))


@dataclass(frozen=True)
class SpectralExtremes:
    """Linear spectral extremes of one sea state (per location, and the totals of seastate.csv).

    Attributes
    ----------
    duration_s
        Duration the maxima are taken over [s].
    saddle_force, saddle_compression, bending_moment, bending_stress
        :class:`ResponseStatistics` per saddle [N], [m] and per x [N m], [Pa].
    still_water
        The still-water state added to the dynamic part.
    uplift_per_hour_per_saddle
        (n_s,) expected downward zero crossings of each saddle's compression per hour [1/h].
    totals
        ``F_N`` [N], ``M_b_Nm`` [N m], ``sigma_b_Pa`` [Pa], ``u_s_m`` [m], ``u_d_m`` [m] (0,
        bilateral saddles), ``uplift_per_hour`` [1/h] (summed over saddles).
    """

    duration_s: float
    saddle_force: ResponseStatistics
    saddle_compression: ResponseStatistics
    bending_moment: ResponseStatistics
    bending_stress: ResponseStatistics
    still_water: StillWater
    uplift_per_hour_per_saddle: NDArray[np.float64]
    totals: Mapping[str, float]

    def row(self) -> dict[str, Any]:
        """The (linear, spectral) row of seastate.csv."""
        return {"model": "linear", "method": "spectral", **{k: float(v) for k, v in self.totals.items()}, "converged": True}


def spectral_extremes(
    tf: TransferFunctions, spectrum: WaveSpectrum, still: StillWater, duration_s: float, directional: SeaStateTransfer | None = None
) -> SpectralExtremes:
    """Linear spectral extremes over ``duration_s`` (see the module docstring).

    ``directional``: a short-crested sea's transfer functions per direction; the response spectra are then
    ``S sum_j w_j |H_j|^2`` (``tf`` is not used for them). None: ``|H|^2 S`` of ``tf``.
    """
    if not np.array_equal(tf.omega_rad_s, spectrum.omega_rad_s):
        raise ValueError("spectral_extremes: the transfer functions must be on the spectrum's grid")
    if directional is None:
        force = response_statistics(tf.saddle_force_N, spectrum, duration_s)
        comp = response_statistics(tf.saddle_compression_m, spectrum, duration_s)
        moment = response_statistics(tf.bending_moment_Nm, spectrum, duration_s)
        stress = response_statistics(tf.bending_stress_Pa, spectrum, duration_s)
    else:
        force, comp, moment, stress = (
            squared_response_statistics(directional.squared(name), spectrum, duration_s)
            for name in ("saddle_force_N", "saddle_compression_m", "bending_moment_Nm", "bending_stress_Pa")
        )
    uplift = 3600.0 * downcrossing_rate_per_s(still.saddle_compression_m, comp.m0, comp.m2)
    totals = {
        "F_N": float(np.max(still.saddle_force_N + force.mpm)),
        "M_b_Nm": float(np.max(np.abs(still.bending_moment_Nm) + moment.mpm)),
        "sigma_b_Pa": float(np.max(np.abs(still.bending_stress_Pa) + stress.mpm)),
        "u_s_m": float(max(np.max(still.saddle_compression_m + comp.mpm), 0.0)),
        "u_d_m": 0.0,
        "uplift_per_hour": float(np.sum(uplift)),
    }
    return SpectralExtremes(float(duration_s), force, comp, moment, stress, still, uplift, totals)


@dataclass(frozen=True)
class SpectralAnalysis:
    """Everything the linear spectral method computes for one case's sea state.

    ``transfer`` holds the transfer functions at the mean heading; ``directional`` those of every direction (one for a
    long-crested sea) and the roll damping's stochastic linearisation.
    """

    case: Case
    model: StructuralModel
    spectrum: WaveSpectrum
    transfer: TransferFunctions
    extremes: SpectralExtremes
    directional: SeaStateTransfer | None = None


def spectral_analysis(case: Case, model: StructuralModel | None = None) -> SpectralAnalysis:
    """Spectrum, transfer functions and linear spectral extremes of the case's sea state at its heading and spreading.

    Raises
    ------
    seafast.config.CaseError
        Invalid or unresolvable sea state, or a vessel set-up without per-frequency hull response.
    """
    model = build_model(case) if model is None else model
    spectrum = sea_state_spectrum(case)
    sea = sea_state_transfer(case, model, spectrum.omega_rad_s, sea_state_roll_damping(case, spectrum))
    spread = None if sea.quadrature.long_crested else sea
    extremes = spectral_extremes(sea.mean, spectrum, still_water(case, model), case.sea_state.duration_s, spread)
    return SpectralAnalysis(case, model, spectrum, sea.mean, extremes, sea)
