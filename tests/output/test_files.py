"""Writing a run's files: results.nc as xarray writes it, without loading Dask's distributed package."""

from __future__ import annotations

import json
import subprocess
import sys

import numpy as np
import xarray as xr

from seafast.output.files import NETCDF_COMPRESS_LEVEL, write_netcdf

PROBE = """
import json, sys
import numpy as np, xarray as xr
import dask  # as the numerical stack loads it
from seafast.output.files import write_netcdf
ds = xr.Dataset({"F_N": (("t",), np.arange(4.0), {"units": "N"})}, attrs={"title": "probe"})
write_netcdf(ds, sys.argv[1])
import dask.base
print(json.dumps({
    "distributed": "distributed" in sys.modules,
    "none_left": [name for name, module in sys.modules.items() if module is None and name.startswith("distributed")],
    "dask_memo": getattr(dask.base, "_DISTRIBUTED_AVAILABLE", None),
    "same": xr.open_dataset(sys.argv[1]).identical(ds),
}))
"""


def test_results_nc_is_written_without_importing_distributed_and_reads_back_identical(tmp_path):
    """A fresh interpreter: the write leaves ``distributed`` unloaded and importable, and Dask's memo of it unset."""
    probe = [sys.executable, "-c", PROBE, str(tmp_path / "probe.nc")]
    done = subprocess.run(probe, capture_output=True, text=True, timeout=300, check=False)
    assert done.returncode == 0, done.stderr
    assert json.loads(done.stdout.strip().splitlines()[-1]) == {"distributed": False, "none_left": [], "dask_memo": None, "same": True}


def test_write_netcdf_compresses_the_numbers_and_keeps_the_attributes(tmp_path):
    ds = xr.Dataset(
        {"M_b_Nm": (("t", "x"), np.outer(np.arange(50.0), np.ones(20)), {"units": "N m"}), "ok": (("t",), np.ones(50, bool))},
        attrs={"title": "t"},
    )
    path = write_netcdf(ds, tmp_path / "r.nc")
    with xr.open_dataset(path) as back:
        assert back.identical(ds)
        assert back["M_b_Nm"].encoding["zlib"] and back["M_b_Nm"].encoding["complevel"] == NETCDF_COMPRESS_LEVEL > 0


def test_a_run_writes_the_same_files_whether_helpers_draw_the_figures_or_not(tmp_path):
    """Figures shared with a forked helper while results.nc is written: the same files, byte for byte, in the same order."""
    from seafast.analyses.run import run_case
    from seafast.config import load_case
    from seafast.output.files import write_run_outputs

    result = run_case(load_case(overrides={"vessel.motions": "none"}))
    alone = write_run_outputs(result, tmp_path / "alone", helpers=0)
    shared = write_run_outputs(result, tmp_path / "shared", helpers=1)
    assert (
        list(alone)
        == list(shared)
        == [
            "summary",
            "case",
            "results",
            "deflection",
            "forces_moments",
            "saddle_time_histories",
            "saddle_surfaces",
            "aft_most_loaded_saddle",
            "hull_girder",
        ]
    )
    for key, path in alone.items():
        assert shared[key].name == path.name
        if path.suffix == ".png":
            assert shared[key].read_bytes() == path.read_bytes(), key
    with xr.open_dataset(alone["results"]) as a, xr.open_dataset(shared["results"]) as b:
        assert a.identical(b)


HIDDEN = """
import json, sys
from seafast.output.files import no_dask_lookup, write_netcdf
with no_dask_lookup():
    import numpy as np, xarray as xr
    ds = xr.Dataset({"F_N": (("t", "s"), np.arange(6.0).reshape(3, 2), {"units": "N"})}, coords={"t": [0.0, 0.5, 1.0]})
    write_netcdf(ds, sys.argv[1])
    with xr.open_dataset(sys.argv[1]) as back:
        same = back.identical(ds) and float(back["F_N"].sel(t=0.5, s=1)) == 3.0
    try:
        import dask
        refused = False
    except ImportError:
        refused = True
    loaded_inside = sorted(name for name in sys.modules if name.split(".")[0] in ("dask", "distributed") and sys.modules[name] is not None)
import dask
import dask.array as da
chunked = xr.DataArray(da.ones((4,), chunks=2), dims="t")  # a Dask collection only if xarray sees a Dask array inside
print(json.dumps({
    "same": same,
    "refused": refused,
    "loaded_inside": loaded_inside,
    "recognised_after": dask.is_dask_collection(chunked) and float(chunked.sum()) == 4.0,
    "none_left": [name for name, module in sys.modules.items() if module is None and name.startswith("dask")],
}))
"""


def test_a_block_without_dask_reads_writes_and_selects_then_dask_arrays_are_recognised_again(tmp_path):
    """``no_dask_lookup``: xarray works inside without importing Dask; after the block Dask imports and its arrays are Dask arrays."""
    probe = [sys.executable, "-c", HIDDEN, str(tmp_path / "probe.nc")]
    done = subprocess.run(probe, capture_output=True, text=True, timeout=300, check=False)
    assert done.returncode == 0, done.stderr
    assert json.loads(done.stdout.strip().splitlines()[-1]) == {
        "same": True,
        "refused": True,
        "loaded_inside": [],
        "recognised_after": True,
        "none_left": [],
    }
