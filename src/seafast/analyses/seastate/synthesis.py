"""Random-phase realisations of a sea state and the FFT synthesis of linear responses.

A realisation of the (head) sea at midship is

    zeta(t) = sum_j a_j cos(omega_j t + phi_j),   a_j = sqrt(2 S(omega_j) d_omega),

on the uniform grid ``omega_j = j d_omega`` with ``d_omega = 2 pi / T`` (T the duration): the
record is periodic with period T, so it does not repeat within the duration, and every linear
response ``x(t) = Re sum_j a_j H_x(omega_j) exp(i (omega_j t + phi_j))`` (transfer function
H_x per metre of wave amplitude, convention of :mod:`seafast.analyses.seastate.transfer`) is one inverse
real FFT. The phases phi_j are uniform on [0, 2 pi), drawn by ``numpy.random.default_rng`` from
``SeedSequence(seed, spawn_key=(index,))`` (the ``index``-th child of ``SeedSequence(seed)``), so
realisation ``index`` is reproducible on its own, in any order, on any worker.

Amplitudes (:func:`amplitude_factors`): with random amplitudes (the default) each component's
amplitude is ``a_j r_j`` with ``r_j^2`` standard exponential (r_j Rayleigh, mean square 1),
drawn from the same generator after the phases: ``a_j r_j e^{i phi_j}`` is then a complex
Gaussian coefficient and the record a sample of the stationary Gaussian sea the spectral method
assumes (Tucker, Challenor & Carter, Applied Ocean Research 6, 1984: deterministic amplitudes
misrepresent the variability between records). With deterministic amplitudes (``r_j = 1``) each
record's variance equals the spectral variance ``sum_j a_j^2 / 2`` to round-off and its maxima
vary less from record to record. The phases are the same either way.

Transfer functions are computed on a coarser uniform grid (``transfer_step_rad_s``) and
interpolated to the synthesis grid by cubic splines on their real and imaginary parts; the
bending-moment field is carried by its leading singular components (:func:`low_rank`).
Units SI; the spectral density is one-sided [m^2 s/rad].
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray
from scipy.fft import irfft, next_fast_len
from scipy.interpolate import CubicSpline

__all__ = [
    "SynthesisGrid",
    "synthesis_grid",
    "record_grids",
    "realisation_phases",
    "amplitude_factors",
    "synthesise",
    "interpolate_transfer",
    "low_rank",
    "peak_sampling_error",
]


@dataclass(frozen=True)
class SynthesisGrid:
    """Frequencies, amplitudes and time sampling of the random-phase records.

    Attributes
    ----------
    duration_s
        Record length T [s] (the record's period).
    first_index
        j of the first component; ``omega_rad_s = (first_index + arange(n_f)) * 2 pi / T``.
    omega_rad_s
        Component frequencies (n_f,) [rad/s].
    amplitude_m
        Component amplitudes ``sqrt(2 S d_omega)`` (n_f,) [m].
    samples
        Samples per record (the inverse FFT's length).
    """

    duration_s: float
    first_index: int
    omega_rad_s: NDArray[np.float64]
    amplitude_m: NDArray[np.float64]
    samples: int

    @property
    def frequency_step_rad_s(self) -> float:
        """d_omega = 2 pi / T [rad/s]."""
        return 2.0 * math.pi / self.duration_s

    @property
    def time_step_s(self) -> float:
        """Sampling interval T / samples [s]."""
        return self.duration_s / self.samples

    @property
    def variance_m2(self) -> float:
        """Variance of every record, ``sum a_j^2 / 2`` [m^2]."""
        return float(np.sum(self.amplitude_m**2) / 2.0)


def synthesis_grid(
    band_rad_s: tuple[float, float],
    density_m2_s_per_rad: Callable[[NDArray[np.float64]], NDArray[np.float64]],
    duration_s: float,
    max_time_step_s: float,
) -> SynthesisGrid:
    """The synthesis grid over ``band_rad_s`` for a record of ``duration_s``.

    Parameters
    ----------
    band_rad_s
        (lowest, highest) frequency holding the spectrum [rad/s].
    density_m2_s_per_rad
        Callable ``S(omega)`` [m^2 s/rad] (one-sided), evaluated on the grid.
    duration_s
        T [s], > 0.
    max_time_step_s
        Largest allowed sampling interval [s]; the sample count is the next even FFT-friendly
        size at or above ``T / max_time_step_s``.
    """
    T = float(duration_s)
    d_omega = 2.0 * math.pi / T
    j0 = max(math.ceil(band_rad_s[0] / d_omega), 1)
    j1 = math.floor(band_rad_s[1] / d_omega)
    if j1 < j0:
        raise ValueError(f"duration_s = {duration_s!r} is too short to resolve the band {band_rad_s} rad/s")
    omega = np.asarray(np.arange(j0, j1 + 1) * d_omega, dtype=np.float64)
    S = np.asarray(density_m2_s_per_rad(omega), dtype=np.float64)
    amplitude = np.asarray(np.sqrt(2.0 * np.maximum(S, 0.0) * d_omega), dtype=np.float64)
    n = max(math.ceil(T / float(max_time_step_s)), 2 * (j1 + 1) + 2)
    n = next_fast_len(n, real=True)
    while n % 2:
        n = next_fast_len(n + 1, real=True)
    return SynthesisGrid(T, j0, omega, amplitude, n)


def record_grids(
    band_rad_s: tuple[float, float],
    density_m2_s_per_rad: Callable[[NDArray[np.float64]], NDArray[np.float64]],
    duration_s: float,
    sampling_frequency_rad_s: float,
    coarse_step_factor: float,
    max_fine_step_s: float,
) -> tuple[SynthesisGrid, int]:
    """A Monte Carlo record's coarse synthesis grid and its fine (integrator) steps per coarse sample.

    The coarse step is at most ``coarse_step_factor / sampling_frequency_rad_s`` [s] (:func:`synthesis_grid`), the fine
    step at most ``max_fine_step_s`` [s]: ``ratio`` is the least whole number of fine steps per coarse step.
    """
    max_coarse_step_s = coarse_step_factor / sampling_frequency_rad_s
    ratio = max(int(np.ceil(max_coarse_step_s / max_fine_step_s - 1e-9)), 1)
    return synthesis_grid(band_rad_s, density_m2_s_per_rad, duration_s, max_coarse_step_s), ratio


def realisation_phases(seed: int, index: int, count: int) -> NDArray[np.float64]:
    """Phases [rad] of realisation ``index``: uniform on [0, 2 pi), from the ``index``-th child of ``SeedSequence(seed)``."""
    rng = np.random.default_rng(np.random.SeedSequence(int(seed), spawn_key=(int(index),)))
    return rng.uniform(0.0, 2.0 * math.pi, int(count))


def amplitude_factors(seed: int, index: int, count: int, random_amplitudes: bool) -> NDArray[np.float64]:
    """Amplitude factors r_j [-] of realisation ``index`` (see the module docstring): Rayleigh with mean square 1, or ones.

    Drawn from the same generator as :func:`realisation_phases`, after its ``count`` phases.
    """
    if not random_amplitudes:
        return np.ones(int(count))
    rng = np.random.default_rng(np.random.SeedSequence(int(seed), spawn_key=(int(index),)))
    rng.uniform(0.0, 2.0 * math.pi, int(count))  # the phases come first
    return np.sqrt(rng.standard_exponential(int(count)))


def synthesise(grid: SynthesisGrid, phases_rad: NDArray, transfer: NDArray, factors: NDArray | None = None) -> NDArray[np.float64]:
    """Records of the responses with transfer functions ``transfer`` (n_f, n_ch) per metre of wave.

    ``factors``: the amplitude factors r_j of :func:`amplitude_factors` (default 1: deterministic amplitudes).

    Returns
    -------
    (samples, n_ch) real records at ``t_n = n T / samples``:
    ``x(t_n) = Re sum_j r_j a_j H(omega_j) exp(i (omega_j t_n + phi_j))``.
    """
    H = np.asarray(transfer)
    squeeze = H.ndim == 1
    H = H.reshape(H.shape[0], -1)
    spectrum = np.zeros((grid.samples // 2 + 1, H.shape[1]), dtype=complex)
    # irfft(norm="forward") of X gives X_0 + 2 Re sum_k X_k e^{2 pi i k n / N}: X_j = A_j H_j / 2
    r = 1.0 if factors is None else np.asarray(factors, dtype=float)
    A = grid.amplitude_m * r * np.exp(1j * np.asarray(phases_rad))
    spectrum[grid.first_index : grid.first_index + grid.omega_rad_s.size] = 0.5 * A[:, None] * H
    x = irfft(spectrum, n=grid.samples, axis=0, norm="forward")
    return x[:, 0] if squeeze else x


def interpolate_transfer(omega_from: NDArray, values: NDArray, omega_to: NDArray) -> NDArray[np.complex128]:
    """Complex transfer functions (n_from, ...) at ``omega_to``: cubic splines of the real and imaginary parts."""
    v = np.asarray(values)
    re = CubicSpline(omega_from, v.real, axis=0)(omega_to)
    im = CubicSpline(omega_from, v.imag, axis=0)(omega_to)
    return re + 1j * im


def low_rank(transfer: NDArray, relative_tolerance: float = 1e-10) -> tuple[NDArray[np.complex128], NDArray[np.float64]]:
    """Real spatial basis of a complex field transfer function (n_w, n_x).

    ``transfer ~= coordinates @ basis.T`` with ``basis`` (n_x, r) orthonormal (the leading right
    singular vectors of ``[Re; Im]``) and ``coordinates = transfer @ basis`` (n_w, r); r keeps
    every singular value above ``relative_tolerance`` times the largest, so the field is
    reproduced to about that relative accuracy.
    """
    H = np.asarray(transfer)
    _, s, vt = np.linalg.svd(np.vstack([H.real, H.imag]), full_matrices=False)
    r = max(int(np.count_nonzero(s > relative_tolerance * s[0])), 1) if s.size and s[0] > 0 else 1
    basis = np.ascontiguousarray(vt[:r].T)
    return H @ basis, basis


def peak_sampling_error(omega_rad_s: float, time_step_s: float) -> float:
    """Largest relative shortfall of a sampled peak of a sinusoid of frequency omega: ``1 - cos(omega dt / 2)``."""
    return float(1.0 - math.cos(0.5 * omega_rad_s * time_step_s))
