"""Irregular head seas: spectra, transfer functions, linear spectral extremes (issue 14).

* :mod:`~seafast.seastate.spectrum` - JONSWAP / Pierson-Moskowitz / tabulated spectra and the grid.
* :mod:`~seafast.seastate.transfer` - transfer functions per metre of wave amplitude.
* :mod:`~seafast.seastate.spectral` - response spectra, moments and Rayleigh most probable maxima.
"""
