"""Shared fixtures of the study tests: a small study file and its grid."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
if str(HERE) not in sys.path:  # worker processes import the fake evaluators from here
    sys.path.insert(0, str(HERE))

SMALL_STUDY = """\
name: small
axes:
  - key: seafastening.saddle_count
    values: [2, 3, 4, 5]
  - key: seafastening.saddle_stiffness_N_per_m
    start: 1.1e+7
    stop: 1.1e+10
    num: 4
    scale: log
"""


@pytest.fixture
def small_study_file(tmp_path: Path) -> Path:
    """A 4 x 4 saddle study file."""
    path = tmp_path / "small.yaml"
    path.write_text(SMALL_STUDY, encoding="utf-8")
    return path


@pytest.fixture
def small_grid(small_study_file: Path):
    from seafast.studies.spec import build_grid, load_study_spec

    spec, directory = load_study_spec(small_study_file)
    return build_grid(spec, directory)
