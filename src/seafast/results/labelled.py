"""One labelled NetCDF variable: the data with its ``long_name`` and ``units`` (every results file's convention).

The lowest layer of the outputs (imports only numpy and xarray): ``results.nc``, ``seastate.nc`` and
``operability.nc`` build their variables with it.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import xarray as xr

__all__ = ["labelled_variable"]


def labelled_variable(dims: tuple[str, ...], data: Any, long_name: str, units: str) -> xr.Variable:
    """``xr.Variable(dims, data)`` with the attributes ``long_name`` and ``units`` (a unit string such as ``"N m"``, ``"1"``)."""
    return xr.Variable(dims, np.asarray(data), {"long_name": long_name, "units": units})
