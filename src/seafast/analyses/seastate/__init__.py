"""Irregular head seas: spectra, transfer functions, linear spectral extremes, Monte Carlo.

* :mod:`~seafast.analyses.seastate.spectrum` - JONSWAP / Pierson-Moskowitz / tabulated spectra and the grid.
* :mod:`~seafast.analyses.seastate.transfer` - transfer functions per metre of wave amplitude.
* :mod:`~seafast.analyses.seastate.spectral` - response spectra, moments, Rayleigh most probable maxima, uplift rate.
* :mod:`~seafast.analyses.seastate.monte_carlo` - the nonlinear Monte Carlo reference.

Its files (seastate.csv / .nc, the figures): :mod:`seafast.output.seastate`, :mod:`seafast.output.seastate_plots`.
Theory and verification: ``docs/seastate.md``.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from seafast.lazy import lazy_exports

if TYPE_CHECKING:
    from seafast.analyses.seastate.spectral import SEASTATE_COLUMNS, SpectralAnalysis, SpectralExtremes, spectral_analysis
    from seafast.analyses.seastate.spectrum import WaveSpectrum, sea_state_spectrum
    from seafast.analyses.seastate.transfer import StillWater, TransferFunctions, still_water, transfer_functions

# imported on first use (seafast.lazy), so the command line's parser does not load numpy/xarray
EXPORTS = {
    "seafast.analyses.seastate.spectral": ("SEASTATE_COLUMNS", "SpectralAnalysis", "SpectralExtremes", "spectral_analysis"),
    "seafast.analyses.seastate.spectrum": ("WaveSpectrum", "sea_state_spectrum"),
    "seafast.analyses.seastate.transfer": ("StillWater", "TransferFunctions", "still_water", "transfer_functions"),
}
__all__ = [
    "SEASTATE_COLUMNS",
    "SpectralAnalysis",
    "SpectralExtremes",
    "spectral_analysis",
    "WaveSpectrum",
    "sea_state_spectrum",
    "StillWater",
    "TransferFunctions",
    "still_water",
    "transfer_functions",
]
lazy_exports(__name__, EXPORTS)
