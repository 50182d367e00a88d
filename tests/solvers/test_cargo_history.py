"""A cargo history sampled or factored (seafast.solvers.periodic.CargoHistory): the same samples and harmonics."""

from __future__ import annotations

import numpy as np

from seafast.fourier import harmonics_to_time, time_to_harmonics
from seafast.solvers.periodic import CargoHistory


def test_a_factored_history_is_its_time_functions_times_their_shapes():
    rng = np.random.default_rng(20261204)
    N, r, n_c = 64, 5, 12
    functions = rng.standard_normal((N, r))
    alternating = np.where(np.arange(N) % 2 == 0, 1.0, -1.0)
    functions -= np.outer(alternating, alternating @ functions / N)  # no Nyquist term: N / 2 - 1 harmonics carry them
    shapes = rng.standard_normal((r, n_c))
    history = CargoHistory(functions, time_to_harmonics(functions, N // 2 - 1), shapes)
    samples = functions @ shapes
    assert history.factored
    np.testing.assert_allclose(history.time_m, samples, rtol=0.0, atol=1e-13 * np.abs(samples).max())
    harmonics = history.harmonics
    assert harmonics is not None and harmonics.shape == (N // 2, n_c)
    np.testing.assert_allclose(harmonics, time_to_harmonics(samples, N // 2 - 1), rtol=0.0, atol=1e-13 * np.abs(samples).max())
    np.testing.assert_allclose(harmonics_to_time(harmonics, N), samples, rtol=0.0, atol=1e-12 * np.abs(samples).max())
    assert history.time_m is history.time_m  # formed once, kept by the history


def test_a_sampled_history_is_what_it_was_given():
    samples = np.arange(12.0).reshape(4, 3)
    history = CargoHistory(samples, None)
    assert not history.factored and history.time_m is samples and history.harmonics is None
