"""BLAS thread pinning: one thread inside ``one_blas_thread`` and every core inside ``blas_on_every_core`` (the
previous counts back after each), the environment defaults and the worker pinning; and the shared machinery
written once: no other module pins threads, starts worker pools or writes a store."""

from __future__ import annotations

import ast
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from threadpoolctl import threadpool_info, threadpool_limits

from seafast.parallel.threads import THREAD_VARIABLES, blas_on_every_core, one_blas_thread

SRC = Path(__file__).resolve().parents[2] / "src" / "seafast"


def _blas() -> list[int]:
    return sorted({int(i["num_threads"]) for i in threadpool_info() if i["user_api"] == "blas"})


@pytest.mark.skipif((os.cpu_count() or 1) < 2, reason="BLAS runs one thread on one core whatever is asked")
def test_one_thread_inside_every_core_for_the_bem_and_the_counts_return():
    import scipy.linalg  # noqa: F401 - both BLAS libraries loaded

    with threadpool_limits(limits=2, user_api="blas"):
        assert _blas() == [2]
        with one_blas_thread():
            assert _blas() == [1]
            with blas_on_every_core():
                assert _blas() == [os.cpu_count()]
            assert _blas() == [1]
        assert _blas() == [2]


PROBE = """
import json, os
from seafast.parallel.threads import default_to_one_thread, pin_worker_threads
default_to_one_thread()
defaults = {k: os.environ.get(k) for k in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS", "NUMEXPR_NUM_THREADS")}
import numpy, scipy.linalg
from threadpoolctl import threadpool_info
def blas():
    return sorted({i["num_threads"] for i in threadpool_info() if i["user_api"] == "blas"})
loaded = blas()
os.environ["OPENBLAS_NUM_THREADS"] = "2"
pin_worker_threads()
print(json.dumps({"defaults": defaults, "loaded": loaded, "pinned": blas(), "env": os.environ["OPENBLAS_NUM_THREADS"]}))
"""


def test_the_environment_defaults_to_one_thread_and_a_worker_pins_itself():
    env = {k: v for k, v in os.environ.items() if k not in THREAD_VARIABLES}
    env["MKL_NUM_THREADS"] = "3"  # the user's: it wins
    env["OPENBLAS_NUM_THREADS"] = "2"
    out = subprocess.run([sys.executable, "-c", PROBE], capture_output=True, text=True, timeout=120, env=env, check=True)
    got = json.loads(out.stdout.strip().splitlines()[-1])
    assert got["defaults"] == {"OPENBLAS_NUM_THREADS": "2", "OMP_NUM_THREADS": "1", "MKL_NUM_THREADS": "3", "NUMEXPR_NUM_THREADS": "1"}
    if (os.cpu_count() or 1) >= 2:
        assert got["loaded"] == [2]  # the user's two threads reached OpenBLAS ...
    assert got["pinned"] == [1] and got["env"] == "1"  # ... and a worker pins them, and the variables, to one


def _imports() -> dict[str, set[str]]:
    """Top-level third-party and standard modules each source file imports (anywhere in it)."""
    out: dict[str, set[str]] = {}
    for path in SRC.rglob("*.py"):
        names: set[str] = set()
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Import):
                names |= {alias.name for alias in node.names}
            elif isinstance(node, ast.ImportFrom) and node.module and not node.level:
                names.add(node.module)
        out[path.relative_to(SRC).as_posix()] = names
    return out


def test_the_machinery_is_written_once():
    imports = _imports()

    def users(*modules: str) -> list[str]:
        return sorted(f for f, names in imports.items() if any(n == m or n.startswith(m + ".") for n in names for m in modules))

    assert users("threadpoolctl") == ["parallel/threads.py"]  # BLAS pinning
    # worker pools: the executor's, and the helpers a command's output work is shared with
    assert users("concurrent.futures", "multiprocessing", "distributed", "dask") == ["parallel/executor.py", "parallel/sharing.py"]
    fsync = sorted(f for f in imports if "os.fsync(" in (SRC / f).read_text(encoding="utf-8"))
    assert fsync == ["parallel/store.py"]  # the resumable store
