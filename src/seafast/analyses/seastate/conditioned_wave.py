"""The conditioned wave (most likely extreme response, MLER) of a sea state, solved by harmonic balance.

For a linear response r with transfer function H (per metre of wave amplitude) in a sea of
one-sided spectrum S, the most likely wave given r(0) = a is the conditional mean of the
Gaussian sea (Dietz 2004, *Application of conditional waves as critical wave episodes for
extreme loads on marine structures*, PhD thesis, DTU; Quon, Platt, Yu & Lawson 2016, *Application
of the most likely extreme response method for wave energy converters*, OMAE2016-54751)::

    zeta(t) = (a / m0) sum_j S_j |H_j| cos(omega_j t - theta_j) d_omega,   m0 = sum_j S_j |H_j|^2 d_omega,

(theta_j the phase of H_j; the condition on dr/dt(0) = 0 does not change the mean, r and its
derivative being uncorrelated). Its linear response is ``a R(t) / R(0)``, R the response's
autocovariance: a wave group that builds r up to a at t = 0 and dies away.

Embedded in a long base period T_b (frequencies ``omega_j = j 2 pi / T_b``: the group repeats
every T_b, which leaves it unchanged once R has decayed within T_b / 2), the conditioned wave is a
periodic excitation with harmonics j = 1 .. K of the fundamental 2 pi / T_b, and the nonlinear
response to it is one harmonic balance with H well above K (the contact harmonics). The
estimate of a quantity is the largest value over the base period, still water included.
Transfer functions and the spectrum are interpolated to omega_j from the sea-state grid.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from seafast.analyses.seastate.spectral import SpectralAnalysis
from seafast.analyses.seastate.synthesis import interpolate_transfer
from seafast.analyses.seastate.wave_response import MomentMap, WaveSolution, solve_wave, wave_operators
from seafast.excitation.harmonic import HarmonicExcitation
from seafast.solvers.hbm import HBMOptions

__all__ = ["ConditionedWave", "conditioned_wave", "solve_conditioned_wave", "DEFAULT_BASE_PERIODS"]

DEFAULT_BASE_PERIODS = 16.0
"""Base period T_b in peak periods of the response spectrum."""


@dataclass(frozen=True)
class ConditionedWave:
    """A conditioned wave group as a periodic excitation.

    Attributes
    ----------
    base_period_s
        T_b [s].
    omega_rad_s
        (K,) component frequencies j 2 pi / T_b [rad/s], j = 1 .. K.
    wave_amplitude_m
        (K,) complex amplitudes of the wave elevation at midship [m] (``zeta = Re sum Z_j e^{i omega_j t}``).
    target
        The conditioned linear response value a at t = 0 [unit of r].
    excitation
        Still water at k = 0, the group's deck motion and loads at k = 1 .. K.
    """

    base_period_s: float
    omega_rad_s: NDArray[np.float64]
    wave_amplitude_m: NDArray[np.complex128]
    target: float
    excitation: HarmonicExcitation


def conditioned_wave(
    analysis: SpectralAnalysis,
    static: HarmonicExcitation,
    response_transfer: NDArray[np.complex128],
    target: float,
    base_period_s: float | None = None,
) -> ConditionedWave:
    """The conditioned wave that makes the linear response of ``response_transfer`` reach ``target`` at t = 0.

    Parameters
    ----------
    analysis
        The sea state's spectral analysis (grid, spectrum, transfer functions).
    static
        The still-water excitation.
    response_transfer
        (n_w,) transfer function of the conditioning response on the sea-state grid.
    target
        a: the value the linear dynamic response reaches at t = 0 (e.g. +MPM of a force, -MPM of a compression).
    base_period_s
        T_b; default :data:`DEFAULT_BASE_PERIODS` peak periods of the response spectrum.
    """
    sp, tf = analysis.spectrum, analysis.transfer
    w_grid = sp.omega_rad_s
    s_r = np.abs(response_transfer) ** 2 * sp.density_m2_s_per_rad
    if base_period_s is None:
        base_period_s = DEFAULT_BASE_PERIODS * 2.0 * math.pi / float(w_grid[int(np.argmax(s_r))])
    dw = 2.0 * math.pi / base_period_s
    j = np.arange(max(math.ceil(w_grid[0] / dw), 1), math.floor(w_grid[-1] / dw) + 1)
    w = (j * dw).astype(np.float64)
    S = np.interp(w, w_grid, sp.density_m2_s_per_rad, left=0.0, right=0.0)
    H = interpolate_transfer(w_grid, response_transfer, w)
    m0 = float(np.sum(S * np.abs(H) ** 2) * dw)
    Z = (target / m0) * S * dw * np.conj(H) if m0 > 0 else np.zeros(w.size, complex)
    K = int(j[-1])
    n_deck, n_c, n_el = tf.deck_displacement.shape[1], tf.cargo_load_N.shape[1], tf.cargo_line_load_N_per_m.shape[1]
    deck = np.zeros((K + 1, n_deck), complex)
    load = np.zeros((K + 1, n_c), complex)
    line = np.zeros((K + 1, n_el), complex)
    deck[0], load[0], line[0] = static.deck_displacement[0], static.cargo_load_N[0], static.cargo_line_load_N_per_m[0]
    deck[j] = Z[:, None] * interpolate_transfer(w_grid, tf.deck_displacement, w)
    load[j] = Z[:, None] * interpolate_transfer(w_grid, tf.cargo_load_N, w)
    line[j] = Z[:, None] * interpolate_transfer(w_grid, tf.cargo_line_load_N_per_m, w)
    excitation = HarmonicExcitation(dw, deck, load, line, f"conditioned wave (MLER), base period {base_period_s:.1f} s")
    return ConditionedWave(
        float(base_period_s), np.asarray(w, dtype=np.float64), np.asarray(Z, dtype=np.complex128), float(target), excitation
    )


def solve_conditioned_wave(
    analysis: SpectralAnalysis,
    wave: ConditionedWave,
    harmonics_per_wave: int = 16,
    moments: MomentMap | None = None,
    tolerance: float = 1e-10,
) -> WaveSolution:
    """The nonlinear response to a conditioned wave by harmonic balance over its base period.

    H resolves ``harmonics_per_wave`` harmonics of the response's peak frequency (as the design
    wave's H does for its own frequency) and at least the group's K components.
    """
    K = wave.excitation.harmonic_count - 1
    peak = float(wave.omega_rad_s[int(np.argmax(np.abs(wave.wave_amplitude_m)))])
    H = max(K, math.ceil(harmonics_per_wave * peak / wave.excitation.omega_rad_s))
    options = HBMOptions(harmonics=H, tolerance=tolerance)
    ops = wave_operators(analysis.model, wave.excitation, options, moments)
    return solve_wave(ops, 1.0, options)
