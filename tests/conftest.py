"""Test-session settings: one BLAS thread, and Hypothesis profiles so that no test fails by chance.

One BLAS thread: small dense solves are fastest so on 2 cores.

Hypothesis profiles. ``ci`` (the default, and what ``.ci/run`` selects): derandomised -- the
examples are a fixed function of each test, so a run is reproducible and a green commit stays
green -- and no example database (a failure found once is not replayed into later, unrelated
runs). ``explore``: random examples and the local database, to look for new counterexamples
(``HYPOTHESIS_PROFILE=explore python -m pytest tests/solvers/test_references.py``); what it finds
becomes a fix or an ``@example``, never a test that fails now and then. Each test's own
``@settings`` (``max_examples``, ``deadline``, ...) apply on top of the profile.
"""

from __future__ import annotations

import os

import pytest
from hypothesis import settings
from threadpoolctl import threadpool_limits

PROFILE_ENV = "HYPOTHESIS_PROFILE"

settings.register_profile("ci", derandomize=True, database=None, print_blob=True)
settings.register_profile("explore", derandomize=False, print_blob=True)
settings.load_profile(os.environ.get(PROFILE_ENV, "ci"))


@pytest.fixture(autouse=True, scope="session")
def _one_blas_thread():
    with threadpool_limits(limits=1):
        yield
