"""Model definition: cargo beam, sections, sea-fastening and the assembled linear system."""

from seafast.model.seafastening import SeaFastening
from seafast.model.sections import CargoGeometry, TubeSegment
from seafast.model.structure import CargoBeam, MechanismError, StructuralModel, build_structural_model

__all__ = [
    "CargoGeometry",
    "TubeSegment",
    "SeaFastening",
    "CargoBeam",
    "StructuralModel",
    "MechanismError",
    "build_structural_model",
]
