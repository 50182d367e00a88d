"""Writing a run's outputs to a directory: results.nc, summary.csv, case.yaml, figures."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import yaml

from seafast.analyses.run import CaseResult
from seafast.output.tables import write_summary_csv

__all__ = ["write_run_outputs", "write_netcdf"]


def write_netcdf(ds: Any, path: Path) -> Path:
    """Write a Dataset to NetCDF4 (compressed)."""
    encoding = {name: {"zlib": True, "complevel": 4} for name, v in ds.data_vars.items() if v.dtype.kind in "fiu"}
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
