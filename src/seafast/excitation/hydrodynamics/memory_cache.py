"""The hydrodynamic data a sequence of loadings of one hull shares, kept in memory by its owner.

A cargo study changes the loading (mass, centre of gravity, pitch inertia) at every point, not
the hull: the BEM results of :func:`~seafast.excitation.hydrodynamics.bem.compute_motions` (a
capytaine dataset in the disk cache) and the rigid-body coefficients extracted from them are the
same at every point, and reading and extracting them costs several times more than the motions
that follow. A :class:`HydrodynamicsCache` keeps them for whoever passes it
(``memory_cache=``): the file is read once per version (path, modification time and size), the
coefficients extracted once per dataset. Without one, every call reads and extracts afresh.
"""

from __future__ import annotations

import os
import threading
from pathlib import Path

import xarray as xr

from seafast.excitation.hydrodynamics.capytaine_io import RigidCoefficients, capytaine_rigid_coefficients, read_capytaine_netcdf

__all__ = ["HydrodynamicsCache"]


class HydrodynamicsCache:
    """Capytaine datasets read from disk and their rigid-body coefficients, kept for the next loading.

    Parameters
    ----------
    max_entries
        Datasets (and coefficient sets) kept; the oldest goes first [-].

    Attributes
    ----------
    datasets
        Kept datasets by file version ``(resolved path, st_mtime_ns, st_size)``.
    coefficients
        Kept ``(dataset, coefficients)`` by ``(id(dataset), origin_x_m, gravity_m_per_s2)``; the
        dataset is held with them, so the id stays its own.
    """

    def __init__(self, max_entries: int = 8) -> None:
        if max_entries < 1:
            raise ValueError(f"HydrodynamicsCache: max_entries = {max_entries!r}; must be >= 1")
        self.max_entries = int(max_entries)
        self.datasets: dict[tuple[str, int, int], xr.Dataset] = {}
        self.coefficients: dict[tuple[int, float, float], tuple[xr.Dataset, RigidCoefficients]] = {}
        self._lock = threading.Lock()  # the bookkeeping of threads sharing it, not the reading

    def dataset(self, path: str | os.PathLike) -> xr.Dataset:
        """The capytaine dataset in ``path`` (:func:`read_capytaine_netcdf`), read once per file version."""
        p = Path(path)
        stat = p.stat()
        key = (str(p.resolve()), stat.st_mtime_ns, stat.st_size)
        held = self.datasets.get(key)
        if held is None:
            held = read_capytaine_netcdf(p)
            self._keep(self.datasets, key, held)
        return held

    def rigid_coefficients(self, ds: xr.Dataset, origin_x_m: float, gravity_m_per_s2: float) -> RigidCoefficients:
        """:func:`capytaine_rigid_coefficients` of ``ds``, extracted once per dataset object."""
        key = (id(ds), float(origin_x_m), float(gravity_m_per_s2))
        held = self.coefficients.get(key)
        if held is None or held[0] is not ds:
            held = (ds, capytaine_rigid_coefficients(ds, origin_x_m, gravity_m_per_s2))
            self._keep(self.coefficients, key, held)
        return held[1]

    def _keep(self, store: dict, key: object, value: object) -> None:
        """Put ``value`` in ``store``, dropping the oldest entry when it holds ``max_entries``."""
        with self._lock:
            if len(store) >= self.max_entries:
                store.pop(next(iter(store)))
            store[key] = value
