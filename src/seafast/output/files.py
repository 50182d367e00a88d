"""Writing a run's outputs to a directory: results.nc, summary.csv, case.yaml, figures."""

from __future__ import annotations

import sys
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

import yaml

from seafast.analyses.run import CaseResult
from seafast.output.tables import write_summary_csv

__all__ = ["write_run_outputs", "write_netcdf"]


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
    dask_base = sys.modules.get("dask.base")
    known = getattr(dask_base, "_DISTRIBUTED_AVAILABLE", None)
    sys.modules["distributed"] = None  # type: ignore[assignment]  # Python's documented "cannot be imported"
    try:
        yield
    finally:
        if sys.modules.get("distributed", ...) is None:
            del sys.modules["distributed"]
        dask_base = sys.modules.get("dask.base")
        if known is None and getattr(dask_base, "_DISTRIBUTED_AVAILABLE", None) is False:
            dask_base._DISTRIBUTED_AVAILABLE = None  # type: ignore[union-attr]  # Dask's memo of the hidden package, forgotten


def write_netcdf(ds: Any, path: Path) -> Path:
    """Write a Dataset to NetCDF4, its numeric variables zlib-compressed (level 4); return ``path``.

    Parameters
    ----------
    ds : xarray.Dataset
        The data (in memory).
    path : Path
        The file to write (replaced if it exists).
    """
    encoding = {name: {"zlib": True, "complevel": 4} for name, v in ds.data_vars.items() if v.dtype.kind in "fiu"}
    with _no_dask_client_lookup():
        ds.to_netcdf(path, engine="netcdf4", encoding=encoding)
    return path


def write_run_outputs(result: CaseResult, out_dir: str | Path) -> dict[str, Path]:
    """Write everything ``seafast run`` produces for ``result`` (a :class:`seafast.analyses.run.CaseResult`)."""
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
    if result.case.outputs.netcdf:
        paths["results"] = write_netcdf(result.dataset, out / "results.nc")
    if result.case.outputs.plots:
        from seafast.output.plots import write_case_figures

        for p in write_case_figures(result.dataset, out):
            paths[p.stem] = p
    return paths
