"""Writing a run's outputs to a directory: results.nc, summary.csv, case.yaml, figures."""

from __future__ import annotations

import sys
from collections.abc import Iterator
from contextlib import contextmanager
from functools import partial
from pathlib import Path
from typing import TYPE_CHECKING, Any

import yaml

from seafast.output.case_figures import CASE_FIGURES, case_figure_names, draw_case_figure
from seafast.parallel.sharing import HelperPool, helper_count

if TYPE_CHECKING:
    from seafast.analyses.run import CaseResult

__all__ = ["write_run_outputs", "write_netcdf", "no_dask_lookup", "NETCDF_COMPRESS_LEVEL"]

NETCDF_COMPRESS_LEVEL = 1
"""zlib level of results.nc's numeric variables [-]: lossless at every level (the same values); on the
base case's file (8.3 MB, mostly float64) level 1 writes in about 0.85 of the CPU time of level 4 for a
file 0.7 % larger."""


@contextmanager
def _unimportable(module: str) -> Iterator[None]:
    """Inside the block ``import module`` fails (Python's documented ``sys.modules[name] = None``); not loaded before."""
    sys.modules[module] = None  # type: ignore[assignment]
    try:
        yield
    finally:
        if sys.modules.get(module, ...) is None:
            del sys.modules[module]


@contextmanager
def _no_dask_client_lookup() -> Iterator[None]:
    """Inside the block, ``import distributed`` fails unless Dask's ``distributed`` is loaded already.

    ``xarray.Dataset.to_netcdf`` asks Dask which scheduler is active, and Dask imports its
    ``distributed`` package (about 0.3 s) to look for a client. No client can exist before
    ``distributed`` was imported, so the answer is the same without it: no client, a local
    scheduler (and an in-memory Dataset is written without Dask anyway).
    """
    if "distributed" in sys.modules:
        yield
        return
    known = getattr(sys.modules.get("dask.base"), "_DISTRIBUTED_AVAILABLE", None)
    try:
        with _unimportable("distributed"):
            yield
    finally:
        dask_base = sys.modules.get("dask.base")
        if known is None and getattr(dask_base, "_DISTRIBUTED_AVAILABLE", None) is False:
            dask_base._DISTRIBUTED_AVAILABLE = None  # type: ignore[union-attr]  # Dask's memo of the hidden package, forgotten


def _forget_dask_lookups() -> None:
    """Forget xarray's memos of a Dask lookup (whether it is installed, whether its arrays exist): the next one looks again."""
    utils = sys.modules.get("xarray.namedarray.utils")
    forget = getattr(getattr(utils, "module_available", None), "cache_clear", None)  # xarray's memo of installed packages
    if forget is not None:
        forget()
    pycompat = sys.modules.get("xarray.namedarray.pycompat")
    memo = getattr(pycompat, "_cached_duck_array_modules", None)  # xarray's memo of the duck-array libraries
    if isinstance(memo, dict) and "dask" in memo and not getattr(memo["dask"], "available", True):
        del memo["dask"]


@contextmanager
def no_dask_lookup() -> Iterator[None]:
    """Inside the block, ``import dask`` fails unless Dask is loaded already (then ``import dask.array`` does, unless loaded).

    xarray asks of the arrays it decodes, wraps and selects whether they are Dask collections,
    and the first time imports ``dask`` (about 0.4 s) to tell, then ``dask.array`` (about 0.3 s)
    for the array type. No Dask collection can exist before Dask was imported, so the answer is
    the same without it: not a Dask collection. xarray is imported on entry, with Dask visible:
    what it records at its import (whether Dask is installed) stays true. On exit Dask is
    importable again and xarray's memos of the failed lookups are forgotten, so Dask collections
    made later are recognised. For a block that makes no Dask collection (``seafast run``: the
    BEM cache read, the Dataset, results.nc, the figures); one that needs Dask fails loudly with
    :class:`ImportError`.
    """
    hidden = next((name for name in ("dask", "dask.array") if name not in sys.modules), None)
    if hidden is None:
        yield
        return
    import xarray  # noqa: F401 - its import-time record of whether Dask is installed, taken while Dask is visible

    _forget_dask_lookups()  # a memo taken before the block would say Dask is there
    try:
        with _unimportable(hidden):
            yield
    finally:
        _forget_dask_lookups()


def write_netcdf(ds: Any, path: Path) -> Path:
    """Write a Dataset to NetCDF4, its numeric variables zlib-compressed (level :data:`NETCDF_COMPRESS_LEVEL`); return ``path``.

    Parameters
    ----------
    ds : xarray.Dataset
        The data (in memory).
    path : Path
        The file to write (replaced if it exists).
    """
    encoding = {name: {"zlib": True, "complevel": NETCDF_COMPRESS_LEVEL} for name, v in ds.data_vars.items() if v.dtype.kind in "fiu"}
    with _no_dask_client_lookup():
        ds.to_netcdf(path, engine="netcdf4", encoding=encoding)
    return path


def write_run_outputs(result: CaseResult, out_dir: str | Path, helpers: int | HelperPool | None = None) -> dict[str, Path]:
    """Write everything ``seafast run`` produces for ``result`` (a :class:`seafast.analyses.run.CaseResult`).

    summary.csv and case.yaml first; then results.nc is written here while forked helper
    processes draw the figures, and this process draws those still left once the file is
    written (:class:`seafast.parallel.sharing.HelperPool`; the costliest figures first).

    Parameters
    ----------
    result : CaseResult
        The run.
    out_dir : str or Path
        The directory (made if missing).
    helpers : int or HelperPool, optional
        Helper processes drawing figures: a pool started ahead
        (:func:`seafast.output.case_figures.figure_helpers`), or how many to fork now; default
        one per further core (:func:`seafast.parallel.sharing.helper_count`); 0 draws everything
        in this process.

    Returns
    -------
    dict of str to Path
        The files by kind: ``summary``, ``case``, ``results`` (when ``outputs.netcdf``), then
        each figure by its name (when ``outputs.plots``), in the report's order.
    """
    from seafast.output.tables import write_summary_csv  # the numerical stack: imported after figure_helpers forked

    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    paths: dict[str, Path] = {}
    paths["summary"] = write_summary_csv(result.summary, out / "summary.csv", getattr(result, "summary_columns", None))
    case_yaml = out / "case.yaml"
    case_yaml.write_text(
        "# the case as run (all defaults filled in)\n" + yaml.safe_dump(result.case.model_dump(mode="json"), sort_keys=False),
        encoding="utf-8",
    )
    paths["case"] = case_yaml
    ds = result.dataset  # built here, before any helper forks: they inherit it
    netcdf = result.case.outputs.netcdf
    if netcdf:
        paths["results"] = out / "results.nc"
    names = case_figure_names(ds) if result.case.outputs.plots else []
    costs = {name: cost for name, _, _, cost in CASE_FIGURES}
    order = sorted(names, key=lambda name: -costs[name])
    work = partial(draw_case_figure, ds, out_dir=out)  # pickles: a pool started ahead receives it
    write = (lambda: write_netcdf(ds, out / "results.nc")) if netcdf else None
    if isinstance(helpers, HelperPool):
        drawn = helpers.share(order, work, first=write)
    else:
        with HelperPool(helper_count(len(order)) if helpers is None else helpers) as pool:
            drawn = pool.share(order, work, first=write)
    by_name = dict(zip(order, drawn, strict=True))
    paths.update((name, by_name[name]) for name in names)
    return paths
