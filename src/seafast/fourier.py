"""Fourier kernels of one period: harmonics <-> time samples, real and complex harmonic layouts.

The lowest layer of seafast (imports only numpy), shared by the excitation, the solvers and the
results.

Conventions (all of seafast)
----------------------------
* Complex layout: ``x(t) = Re(sum_{k=0..H} X_k exp(i k omega t))``, shape (H+1, ...); row 0 is
  the (real) mean.
* Real layout: row 0 is the mean a_0, rows 2k-1 and 2k the cosine and sine coefficients a_k,
  b_k of harmonic k, so ``x(t) = a_0 + sum_k a_k cos(k omega t) + b_k sin(k omega t)`` and
  ``X_k = a_k - i b_k``; shape (2H+1, ...).
* Time grid: ``t_n = n T / N``, n = 0 .. N-1 (period fraction ``n / N``).
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np
from numpy.typing import NDArray

__all__ = [
    "channel_samples",
    "period_fraction",
    "harmonics_to_time",
    "time_to_harmonics",
    "real_harmonics_to_time",
    "time_to_real_harmonics",
    "real_dft_matrices",
    "complex_to_real_harmonics",
    "real_to_complex_harmonics",
    "high_harmonic_energy_share",
    "harmonics_up_to",
    "harmonics_above",
    "periodic_impulse_response",
    "resample_periodic",
]


def period_fraction(time_samples: int) -> NDArray[np.float64]:
    """The sampling grid ``n / N``, n = 0 .. N-1 (t_n = n T / N) [-]."""
    return np.arange(int(time_samples), dtype=float) / int(time_samples)


def harmonics_to_time(harmonics: NDArray, time_samples: int) -> NDArray[np.float64]:
    """Sample ``x(t) = Re(sum_k X_k exp(i k omega t))`` at ``t_n = n T / N``.

    Parameters
    ----------
    harmonics
        Complex amplitudes, shape (H+1, ...); row 0 is the (real) static part. Any unit: the
        samples carry the unit of the amplitudes.
    time_samples
        N.

    Returns
    -------
    Real samples, shape (N, ...).
    """
    X = np.asarray(harmonics)
    n_k, N = X.shape[0], int(time_samples)
    if 2 * (n_k - 1) < N:
        return np.ascontiguousarray(np.moveaxis(channel_samples(X, N), -1, 0))
    phase = 2.0 * np.pi * np.outer(np.arange(N), np.arange(n_k)) / N
    flat = X.reshape(n_k, -1)
    # real arithmetic: Re(X e^{i p}) = Re X cos p - Im X sin p
    out = np.cos(phase) @ np.ascontiguousarray(flat.real) - np.sin(phase) @ np.ascontiguousarray(flat.imag)
    return out.reshape((N,) + X.shape[1:])


def channel_samples(harmonics: NDArray, time_samples: int) -> NDArray[np.float64]:
    """The samples of :func:`harmonics_to_time` with time as the last axis, shape (..., N): each channel's period
    contiguous, without the transposition back (where only each channel's extremes are wanted).
    """
    X = np.asarray(harmonics)
    n_k, N = X.shape[0], int(time_samples)
    if 2 * (n_k - 1) >= N:
        return np.moveaxis(harmonics_to_time(X, N), 0, -1)
    # no harmonic at or above Nyquist: one inverse real FFT (O(N log N) per channel), each channel's spectrum
    # contiguous (an FFT along the first axis of many channels runs 2-4 times slower)
    channels = X.reshape(n_k, int(np.prod(X.shape[1:], dtype=int)))
    A = np.zeros((channels.shape[1], N // 2 + 1), dtype=complex)
    A[:, 0] = np.real(channels[0]) * N
    A[:, 1:n_k] = channels[1:].T * (0.5 * N)
    return np.fft.irfft(A, n=N, axis=-1).reshape(X.shape[1:] + (N,))


def time_to_harmonics(samples: NDArray, harmonics: int) -> NDArray[np.complex128]:
    """Complex amplitudes ``X_k``, k = 0 .. H, of one period sampled at ``t_n = n T / N`` (the inverse
    of :func:`harmonics_to_time` for H < N / 2), by one real FFT.

    Parameters
    ----------
    samples
        Real samples, shape (N, ...); any unit (the amplitudes carry it).
    harmonics
        H, at most N // 2 (at k = N / 2 only the cosine part is seen).

    Returns
    -------
    Shape (H+1, ...); row 0 the (real) mean.
    """
    x = np.asarray(samples, dtype=float)
    N, H = x.shape[0], int(harmonics)
    if H > N // 2:
        raise ValueError(f"time_to_harmonics: harmonics = {H} needs at least {2 * H} samples per period; got {N}")
    # each channel's samples contiguous (an FFT along the first axis of many channels runs 2-4 times slower)
    channels = x.reshape(N, -1).T
    X = np.ascontiguousarray(np.fft.rfft(channels, axis=-1)[:, : H + 1].T).reshape((H + 1,) + x.shape[1:]) * (2.0 / N)
    X[0] *= 0.5
    return X


def real_harmonics_to_time(coefficients: NDArray, time_samples: int) -> NDArray[np.float64]:
    """Samples (N, ...) of real-layout coefficients (2H+1, ...): ``inverse @ coefficients`` of
    :func:`real_dft_matrices`, by an inverse real FFT when H < N / 2."""
    return harmonics_to_time(real_to_complex_harmonics(coefficients), time_samples)


def time_to_real_harmonics(samples: NDArray, harmonics: int) -> NDArray[np.float64]:
    """Real-layout coefficients (2H+1, ...) of samples (N, ...): ``forward @ samples`` of
    :func:`real_dft_matrices`, by a real FFT."""
    return complex_to_real_harmonics(time_to_harmonics(samples, harmonics))


@lru_cache(maxsize=64)
def real_dft_matrices(harmonics: int, time_samples: int) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Real inverse and forward DFT matrices of the layout ``[a0, a1, b1, ..., aH, bH]``.

    Returns
    -------
    inverse, forward
        ``inverse`` (N, 2H+1) maps coefficients to samples at ``t_n = n T / N``;
        ``forward`` (2H+1, N) maps samples to coefficients (``forward @ inverse = I`` for
        N >= 2H + 1). Read-only, cached per (H, N).
    """
    H, N = int(harmonics), int(time_samples)
    phase = 2.0 * np.pi * np.outer(np.arange(N), np.arange(1, H + 1)) / N  # (N, H)
    inverse = np.empty((N, 2 * H + 1))
    inverse[:, 0] = 1.0
    inverse[:, 1::2] = np.cos(phase)
    inverse[:, 2::2] = np.sin(phase)
    forward = inverse.T * (2.0 / N)
    forward[0] *= 0.5
    inverse.flags.writeable = False
    forward = np.ascontiguousarray(forward)
    forward.flags.writeable = False
    return inverse, forward


def complex_to_real_harmonics(X: NDArray) -> NDArray[np.float64]:
    """Complex amplitudes (H+1, ...) to real coefficients (2H+1, ...): a_k = Re X_k, b_k = -Im X_k."""
    X = np.asarray(X)
    out = np.empty((2 * X.shape[0] - 1,) + X.shape[1:])
    out[0] = X[0].real
    out[1::2] = X[1:].real
    out[2::2] = -X[1:].imag
    return out


def real_to_complex_harmonics(U: NDArray) -> NDArray[np.complex128]:
    """Real coefficients (2H+1, ...) to complex amplitudes (H+1, ...): X_k = a_k - i b_k."""
    U = np.asarray(U, dtype=float)
    out = np.empty(((U.shape[0] + 1) // 2,) + U.shape[1:], dtype=complex)
    out[0] = U[0]
    out[1:] = U[1::2] - 1j * U[2::2]
    return out


def high_harmonic_energy_share(signal: NDArray, harmonics: int) -> NDArray[np.float64]:
    """Share of the fluctuating signal energy carried by harmonics above ``harmonics``.

    ``signal`` has shape (N, n) (one period, N samples, n channels). The energy of harmonic k
    is ``|X_k|^2 / 2`` (k >= 1), computed by DFT of the N samples (harmonics up to N/2); the
    share is ``sum_{k > H} / sum_{k >= 1}`` per channel [-], 0 for a constant channel. It
    measures how much of the signal a truncation at H harmonics misses.
    """
    s = np.asarray(signal, dtype=float)
    N = s.shape[0]
    spectrum = np.fft.rfft(s, axis=0) / N
    energy = np.abs(spectrum) ** 2
    if N % 2 == 0:
        energy[-1] *= 0.5  # the Nyquist bin is not doubled
    energy = energy[1:]
    total = energy.sum(axis=0)
    above = energy[int(harmonics) :].sum(axis=0)
    scale = np.max(np.abs(s), axis=0) ** 2 if s.size else 0.0
    with np.errstate(invalid="ignore", divide="ignore"):
        share = np.where(total > 1e-24 * np.maximum(scale, 1e-300), above / total, 0.0)
    return share


def harmonics_up_to(samples: NDArray, harmonics: int) -> NDArray[np.float64]:
    """Periodic samples (N, ...) keeping only their harmonics 0 .. H (a low-pass on the grid ``t_n = n T / N``).

    Any unit (the result carries it). H >= N / 2 keeps every harmonic the samples hold.
    """
    x = np.asarray(samples, dtype=float)
    X = np.fft.rfft(x, axis=0)
    X[int(harmonics) + 1 :] = 0.0
    return np.fft.irfft(X, n=x.shape[0], axis=0)


def harmonics_above(samples: NDArray, harmonics: int) -> NDArray[np.float64]:
    """What periodic samples (N, ...) hold above harmonic H: the samples less :func:`harmonics_up_to` (a high-pass).

    Any unit (the result carries it).
    """
    x = np.asarray(samples, dtype=float)
    X = np.fft.rfft(x, axis=0)
    X[: int(harmonics) + 1] = 0.0
    return np.fft.irfft(X, n=x.shape[0], axis=0)


def periodic_impulse_response(transfer: NDArray, time_samples: int) -> NDArray[np.float64]:
    """Response over one period to a unit sample at ``t_0`` of an operator that multiplies harmonic k by ``transfer[k]``.

    ``kappa[tau] = (IDFT diag(transfer) DFT e_0)[tau]``, tau = 0 .. N-1: the kernel of the circulant operator
    (a unit sample at ``t_m`` responds with ``kappa[tau - m]``, indices modulo N), through harmonics
    k = 0 .. H of ``transfer`` (shape (H+1, ...), H < N / 2; complex, k = 0 real). Units: the transfer's per
    unit of the sample.
    """
    T = np.asarray(transfer)
    N = int(time_samples)
    if 2 * (T.shape[0] - 1) >= N:
        raise ValueError(f"periodic_impulse_response: {T.shape[0] - 1} harmonics need more than {2 * (T.shape[0] - 1)} samples; got {N}")
    A = np.zeros((N // 2 + 1,) + T.shape[1:], dtype=complex)
    A[: T.shape[0]] = T
    return np.fft.irfft(A, n=N, axis=0)


def resample_periodic(samples: NDArray, time_samples: int) -> NDArray[np.float64]:
    """Periodic samples (N', ...) on the grid ``t_n = n T / N`` (exact for signals band-limited below N' / 2).

    Through the harmonics the N' samples hold; for an even N' the Nyquist term is kept as the cosine the
    samples show (its sine part is not seen). Any unit. N = N' returns a copy.
    """
    x = np.asarray(samples, dtype=float)
    n, N = x.shape[0], int(time_samples)
    if n == N:
        return np.array(x, dtype=float)
    X = time_to_harmonics(x, (n - 1) // 2)
    if n % 2 == 0:  # the Nyquist component, a cosine of amplitude rfft / N' (not doubled)
        nyquist = np.fft.rfft(x, axis=0)[-1:] / n
        X = np.concatenate([X, nyquist.real.astype(complex)])
    return harmonics_to_time(X, N)
