"""The arrangement rule of ``seafastening.saddle_count``: n saddles evenly from 0.2 L to 0.8 L."""

from __future__ import annotations

import numpy as np
import pytest

from seafast.config.arrangement import evenly_spaced_saddles


def test_arrangement_rule() -> None:
    np.testing.assert_allclose(evenly_spaced_saddles(3, 74.0), [14.8, 37.0, 59.2], rtol=1e-14)
    np.testing.assert_allclose(evenly_spaced_saddles(1, 74.0), [37.0])
    xs = evenly_spaced_saddles(7, 100.0)
    assert xs[0] == pytest.approx(20.0) and xs[-1] == pytest.approx(80.0)
    np.testing.assert_allclose(np.diff(xs), 10.0, rtol=1e-12)
    with pytest.raises(ValueError, match="saddle count = 0"):
        evenly_spaced_saddles(0, 74.0)
