"""CI cannot fail by chance: its property tests run on the derandomised Hypothesis profile."""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from hypothesis import settings

ROOT = Path(__file__).resolve().parents[1]


def test_ci_selects_the_derandomised_profile():
    assert "export HYPOTHESIS_PROFILE=ci" in (ROOT / ".ci" / "run").read_text(encoding="utf-8")


@pytest.mark.skipif(os.environ.get("HYPOTHESIS_PROFILE", "ci") != "ci", reason="another Hypothesis profile was asked for")
def test_the_default_profile_is_derandomised_without_a_database():
    assert settings.default.derandomize is True
    assert settings.default.database is None
