"""Vessel definition: hull form and particulars (the ship side of the model)."""

from seafast.vessel.hull_form import HullForm

__all__ = ["HullForm"]
