"""Excitation: what the vessel does to the cargo (hull-girder deflection, rigid-body motions).

* :mod:`seafast.hull` (the layer below) - still-water and quasi-static wave hull deflection.
* :mod:`~seafast.excitation.hydrodynamics` - heave and pitch RAOs from capytaine (BEM) or imported.
* :mod:`~seafast.excitation.deck_table` - the user's own deck-deflection table.
* :mod:`~seafast.excitation.deck_motion` - assembling the cargo model's harmonic excitation.
* :mod:`~seafast.excitation.vessel` - choosing among those from a case.
"""

from seafast.excitation.deck_motion import RigidBodyAmplitudes, assemble_excitation
from seafast.excitation.deck_table import DeckDeflectionTable, read_deck_deflection_table
from seafast.excitation.harmonic import HarmonicExcitation

__all__ = [
    "HarmonicExcitation",
    "RigidBodyAmplitudes",
    "assemble_excitation",
    "DeckDeflectionTable",
    "read_deck_deflection_table",
]
