"""Irregular head seas: spectra, transfer functions, linear spectral extremes, Monte Carlo (issue 14).

* :mod:`~seafast.seastate.spectrum` - JONSWAP / Pierson-Moskowitz / tabulated spectra and the grid.
* :mod:`~seafast.seastate.transfer` - transfer functions per metre of wave amplitude.
* :mod:`~seafast.seastate.spectral` - response spectra, moments, Rayleigh most probable maxima, uplift rate.
* :mod:`~seafast.seastate.outputs`, :mod:`~seafast.seastate.figures` - seastate.csv / .nc / PNGs.
* :mod:`~seafast.seastate.cli` - the ``seafast seastate`` command.
* :mod:`~seafast.seastate.monte_carlo` - the nonlinear Monte Carlo reference.

Theory and verification: ``docs/seastate.md``.
"""

from seafast.seastate.spectral import SEASTATE_COLUMNS, SpectralAnalysis, SpectralExtremes, spectral_analysis
from seafast.seastate.spectrum import WaveSpectrum, sea_state_spectrum
from seafast.seastate.transfer import StillWater, TransferFunctions, still_water, transfer_functions

__all__ = [
    "SEASTATE_COLUMNS",
    "SpectralAnalysis",
    "SpectralExtremes",
    "StillWater",
    "TransferFunctions",
    "WaveSpectrum",
    "sea_state_spectrum",
    "spectral_analysis",
    "still_water",
    "transfer_functions",
]
