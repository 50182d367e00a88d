"""The one Fourier vocabulary (seafast.fourier): FFT transforms against the dense DFT matrices."""

from __future__ import annotations

import numpy as np
import pytest

from seafast.fourier import (
    channel_samples,
    complex_to_real_harmonics,
    harmonics_above,
    harmonics_to_time,
    harmonics_up_to,
    periodic_impulse_response,
    real_dft_matrices,
    real_harmonics_to_time,
    resample_periodic,
    time_to_harmonics,
    time_to_real_harmonics,
)


@pytest.mark.parametrize(("harmonics", "samples"), [(1, 4), (5, 12), (16, 128), (100, 1080), (7, 15)])
def test_the_fft_transforms_are_the_dense_dft_matrices(harmonics, samples):
    rng = np.random.default_rng(20261201)
    inverse, forward = real_dft_matrices(harmonics, samples)
    U = rng.standard_normal((2 * harmonics + 1, 3))
    x = rng.standard_normal((samples, 3))
    np.testing.assert_allclose(real_harmonics_to_time(U, samples), inverse @ U, atol=1e-12 * np.abs(U).sum())
    np.testing.assert_allclose(time_to_real_harmonics(x, harmonics), forward @ x, atol=1e-13 * np.abs(x).sum())
    # a round trip through the samples returns the coefficients (N >= 2H + 1)
    np.testing.assert_allclose(time_to_real_harmonics(real_harmonics_to_time(U, samples), harmonics), U, atol=1e-12)


def test_time_to_harmonics_inverts_harmonics_to_time_and_knows_the_signs():
    # x(t) = 2 + 3 cos(wt) + 4 sin(2 wt): X_0 = 2, X_1 = 3, X_2 = -4i (x = Re sum X_k e^{ik wt})
    t = np.arange(64) / 64 * 2 * np.pi
    x = 2.0 + 3.0 * np.cos(t) + 4.0 * np.sin(2 * t)
    X = time_to_harmonics(x, 3)
    np.testing.assert_allclose(X, [2.0, 3.0, -4.0j, 0.0], atol=1e-13)
    np.testing.assert_allclose(harmonics_to_time(X, 64), x, atol=1e-13)
    np.testing.assert_allclose(complex_to_real_harmonics(X), [2.0, 3.0, 0.0, 0.0, 4.0, 0.0, 0.0], atol=1e-13)


@pytest.mark.parametrize("shape", [(16,), (64, 3), (256, 5, 7), (8192, 40)])
def test_the_transforms_of_many_channels_are_each_channels_own(shape):
    """Each channel transformed with its samples contiguous: the same numbers, to the last bit, as the FFT along the
    first axis, in the same layout; ``channel_samples`` the same samples with time the last axis."""
    rng = np.random.default_rng(20261204)
    x = rng.standard_normal(shape)
    N, H = shape[0], shape[0] // 2 - 1
    X_axis0 = np.fft.rfft(x, axis=0)[: H + 1] * (2.0 / N)
    X_axis0[0] *= 0.5
    X = time_to_harmonics(x, H)
    assert X.flags.c_contiguous and np.array_equal(X, X_axis0)
    spectrum = np.zeros((N // 2 + 1,) + shape[1:], dtype=complex)
    spectrum[0], spectrum[1 : H + 1] = X[0].real * N, X[1:] * (0.5 * N)
    for harmonics in (3, H):
        below = spectrum.copy()
        below[harmonics + 1 :] = 0.0
        samples = harmonics_to_time(X[: harmonics + 1], N)
        assert samples.flags.c_contiguous and np.array_equal(samples, np.fft.irfft(below, n=N, axis=0))
        assert np.array_equal(channel_samples(X[: harmonics + 1], N), np.moveaxis(samples, 0, -1))
    # at or above Nyquist the dense sums, the same either way
    np.testing.assert_array_equal(channel_samples(X[:5], 8), np.moveaxis(harmonics_to_time(X[:5], 8), 0, -1))


def test_too_few_samples_for_the_harmonics_is_refused_by_name():
    with pytest.raises(ValueError, match=r"harmonics = 5 needs at least 10 samples per period; got 8"):
        time_to_harmonics(np.zeros(8), 5)


def test_a_signal_splits_at_a_harmonic_into_its_low_and_high_parts():
    # x = 1 + 2 cos(wt) - 3 sin(3 wt) + 0.5 cos(7 wt) on 32 samples: up to H = 3 the first three terms, above it the last
    t = np.arange(32) / 32 * 2 * np.pi
    low, high = 1.0 + 2.0 * np.cos(t) - 3.0 * np.sin(3 * t), 0.5 * np.cos(7 * t)
    x = np.column_stack([low + high, 2.0 * (low + high)])
    np.testing.assert_allclose(harmonics_up_to(x, 3), np.column_stack([low, 2.0 * low]), atol=1e-14)
    np.testing.assert_allclose(harmonics_above(x, 3), np.column_stack([high, 2.0 * high]), atol=1e-14)
    np.testing.assert_allclose(harmonics_up_to(x, 16), x, atol=1e-14)  # every harmonic the samples hold
    np.testing.assert_allclose(harmonics_above(x, 6) - harmonics_above(x, 7), np.column_stack([high, 2.0 * high]), atol=1e-14)


@pytest.mark.parametrize("samples", [12, 13])
def test_the_impulse_response_is_the_circulant_kernel_of_idft_diag_dft(samples):
    """A unit sample at t_m responds with the kernel rolled by m: IDFT diag(T_k) DFT applied to e_m, by the
    dense real DFT matrices (T_k complex, the real layout's 2 x 2 blocks [[Re, Im], [-Im, Re]] per harmonic)."""
    rng = np.random.default_rng(7)
    H = 5
    T = rng.standard_normal(H + 1) + 1j * rng.standard_normal(H + 1)
    T[0] = T[0].real
    inverse, forward = real_dft_matrices(H, samples)
    D = np.zeros((2 * H + 1, 2 * H + 1))
    D[0, 0] = T[0].real
    for k in range(1, H + 1):
        a, b = 2 * k - 1, 2 * k
        D[a, a] = D[b, b] = T[k].real
        D[a, b], D[b, a] = T[k].imag, -T[k].imag
    operator = inverse @ D @ forward  # samples -> samples
    kernel = periodic_impulse_response(T, samples)
    for m in (0, 3):
        np.testing.assert_allclose(operator[:, m], np.roll(kernel, m), atol=1e-14)
    with pytest.raises(ValueError, match="harmonics need more than"):
        periodic_impulse_response(T, 10)


@pytest.mark.parametrize(("old", "new"), [(16, 40), (16, 10), (15, 64), (16, 16)])
def test_resampling_is_exact_for_a_band_limited_signal_and_keeps_the_nyquist_cosine(old, new):
    """x = 1 + cos(wt) - 2 sin(3 wt) (+ 0.25 cos(8 wt), the Nyquist cosine of 16 samples) on ``old`` samples,
    resampled to ``new``: the signal itself at the new instants (the Nyquist term where 16 samples carry it)."""

    def signal(n: int, nyquist: bool) -> np.ndarray:
        t = np.arange(n) / n * 2 * np.pi
        return 1.0 + np.cos(t) - 2.0 * np.sin(3 * t) + (0.25 * np.cos(8 * t) if nyquist else 0.0)

    nyquist = old == 16 and new > 16
    np.testing.assert_allclose(resample_periodic(signal(old, nyquist), new), signal(new, nyquist), atol=1e-13)
