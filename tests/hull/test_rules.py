"""Tests of the classification-rule values (seafast.hull.rules): IACS UR S11."""

from __future__ import annotations

import pytest

from seafast.hull.rules import iacs_wave_bending_moments_Nm, iacs_wave_coefficient


def test_iacs_formula():
    assert iacs_wave_coefficient(171.0) == pytest.approx(10.75 - 1.29**1.5)
    hog, sag = iacs_wave_bending_moments_Nm(171.0, 42.0, 0.686)
    cw = 10.75 - 1.29**1.5
    assert hog == pytest.approx(190 * cw * 171**2 * 42 * 0.686, rel=1e-12)
    assert sag == pytest.approx(-110 * cw * 171**2 * 42 * (0.686 + 0.7), rel=1e-12)
    assert hog > 0 > sag
