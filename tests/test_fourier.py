"""The one Fourier vocabulary (seafast.fourier): FFT transforms against the dense DFT matrices."""

from __future__ import annotations

import numpy as np
import pytest

from seafast.fourier import (
    complex_to_real_harmonics,
    harmonics_to_time,
    real_dft_matrices,
    real_harmonics_to_time,
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


def test_too_few_samples_for_the_harmonics_is_refused_by_name():
    with pytest.raises(ValueError, match=r"harmonics = 5 needs at least 10 samples per period; got 8"):
        time_to_harmonics(np.zeros(8), 5)
