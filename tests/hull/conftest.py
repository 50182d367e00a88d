"""Shared fixture of the hull-girder tests: the base vessel's girder, loading and still-water response."""

from __future__ import annotations

import pytest

from seafast.hull.girder import HullGirder
from seafast.hull.still_water import still_water_response
from seafast.vessel.loading import base_hull_form, base_vessel_loading


@pytest.fixture(scope="session")
def base():
    """(girder, loading, still-water response) of the base vessel with its documented default loading."""
    girder = HullGirder(base_hull_form())
    loading = base_vessel_loading()
    return girder, loading, still_water_response(girder, loading)
