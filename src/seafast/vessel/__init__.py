"""Vessel definition: hull form, panel mesh and weight distribution (the ship side of the model)."""

from seafast.vessel.hull_form import HullForm
from seafast.vessel.loading import VesselLoading, WeightItem, base_vessel_loading

__all__ = ["HullForm", "VesselLoading", "WeightItem", "base_vessel_loading"]
