"""The model's data objects built from a validated case (configuration -> model)."""

from __future__ import annotations

from seafast.config.schema import Case
from seafast.model.sections import CargoGeometry, TubeSegment

__all__ = ["cargo_geometry"]


def cargo_geometry(case: Case) -> CargoGeometry:
    """The cargo's tube segments and material from the case (one unit)."""
    c = case.cargo
    if c.sections is None:
        segments = (TubeSegment(0.0, c.length_m, c.diameter_m, c.diameter_m, c.wall_thickness_m),)
    else:
        segments = tuple(
            TubeSegment(s.x_start_m, s.x_end_m, s.diameter_start_m, s.diameter_end_m, s.wall_thickness_m) for s in c.sections
        )
    return CargoGeometry(segments, c.youngs_modulus_Pa, c.density_kg_per_m3, c.poisson_ratio)
