"""The command line starts without the numerical stack, and the lazy package exports stay true.

``seafast --help`` (and every ``seafast COMMAND --help``) builds the whole parser; that must not
import numpy, scipy, xarray, matplotlib, capytaine, dask, numba or pydantic (they cost seconds of
CPU). Each test runs a fresh interpreter, because this test session has imported everything
already. No timing is asserted: what is loaded is.
"""

from __future__ import annotations

import ast
import importlib
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

import seafast

HEAVY = ("numpy", "scipy", "xarray", "matplotlib", "capytaine", "dask", "numba", "pydantic", "plotly")
SRC = Path(seafast.__file__).resolve().parent
LAZY_PACKAGES = ("seafast.studies", "seafast.analyses.seastate", "seafast.analyses.operability", "seafast.output.report")


def _python(code: str, env: dict[str, str] | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300, env=env, check=False)


def _loaded_heavy(code: str) -> list[str]:
    probe = f"{code}\nimport json, sys\nprint(json.dumps(sorted({{m.split('.')[0] for m in sys.modules}} & {set(HEAVY)!r})))"
    out = _python(probe)
    assert out.returncode == 0, out.stderr
    return json.loads(out.stdout.strip().splitlines()[-1])


def test_building_the_parser_imports_no_numerical_module():
    assert _loaded_heavy("import seafast.cli\nseafast.cli.build_parser()") == []


@pytest.mark.parametrize("argv", [["--help"], ["run", "--help"], ["study", "--help"], ["report", "--help"], ["--version"]])
def test_help_and_version_import_no_numerical_module(argv):
    code = f"import seafast.cli\ntry:\n    seafast.cli.main({argv!r})\nexcept SystemExit as exc:\n    assert exc.code == 0, exc.code"
    assert _loaded_heavy(code) == []


def test_the_packages_import_without_the_numerical_stack():
    assert _loaded_heavy("import seafast, " + ", ".join(LAZY_PACKAGES)) == []


def test_the_probe_sees_a_heavy_import():
    """Guards the tests above against passing vacuously."""
    assert _loaded_heavy("import seafast.studies.runner") != []
    assert "numpy" in _loaded_heavy("from seafast.studies import run_study")


def test_cli_sets_one_blas_thread_before_numpy_and_main_limits_blas_to_one():
    """Importing seafast.cli sets OPENBLAS_NUM_THREADS etc. (an explicit user value wins); main()
    runs the command with BLAS limited to one thread (threadpoolctl), numpy and scipy loaded."""
    env = {k: v for k, v in os.environ.items() if k not in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")}
    env["MKL_NUM_THREADS"] = "2"  # the user's
    code = """
import json, os, sys
import seafast.cli.command as cli
before = {k: os.environ.get(k) for k in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")}
seen = {}
def probe(args):
    from threadpoolctl import threadpool_info
    seen["blas_threads"] = sorted({i["num_threads"] for i in threadpool_info() if i["user_api"] == "blas"})
    seen["scipy"] = "scipy.linalg" in sys.modules
    return 0
real = cli.build_parser
def build():
    parser = real()
    parser.set_defaults(handler=probe)  # the probe runs as the command
    return parser
cli.build_parser = build
numpy_at_import = "numpy" in sys.modules
code = cli.main([])
print(json.dumps({"env": before, "numpy_at_import": numpy_at_import, "code": code, **seen}))
"""
    out = _python(code, env)
    assert out.returncode == 0, out.stderr
    got = json.loads(out.stdout.strip().splitlines()[-1])
    assert got["env"] == {"OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1", "MKL_NUM_THREADS": "2"}
    assert got["numpy_at_import"] is False
    assert got["code"] == 0 and got["scipy"] is True
    assert got["blas_threads"] == [1]


def _static_exports(package: str) -> dict[str, tuple[str, ...]]:
    """The ``if TYPE_CHECKING:`` imports of a package's ``__init__``: module -> names."""
    path = SRC.parent / Path(*package.split(".")) / "__init__.py"
    tree = ast.parse(path.read_text(encoding="utf-8"))
    block = next(n for n in tree.body if isinstance(n, ast.If) and ast.unparse(n.test) == "TYPE_CHECKING")
    out: dict[str, tuple[str, ...]] = {}
    for node in block.body:
        assert isinstance(node, ast.ImportFrom) and node.module
        out[node.module] = out.get(node.module, ()) + tuple(a.name for a in node.names)
    return out


@pytest.mark.parametrize("package", LAZY_PACKAGES)
def test_lazy_exports_agree_with_the_static_imports_and_resolve(package):
    module = importlib.import_module(package)
    exports = module.EXPORTS
    assert {m: set(n) for m, n in exports.items()} == {m: set(n) for m, n in _static_exports(package).items()}
    names = [n for ns in exports.values() for n in ns]
    assert sorted(module.__all__) == sorted(names)
    for defining, ns in exports.items():
        for name in ns:
            assert getattr(module, name) is getattr(importlib.import_module(defining), name)
            assert name in dir(module)
    with pytest.raises(AttributeError, match="no attribute 'not_an_export'"):
        module.not_an_export  # noqa: B018


@pytest.mark.parametrize("name", ["study_figures", "run_figures"])
def test_an_export_named_like_its_submodule_stays_the_export(name):
    """``seafast.output.report.study_figures`` (and ``run_figures``) is a function in the module of the
    same name; importing that module (as the report's page does) must not replace the package's
    attribute by the module."""
    code = f"""
import seafast.output.report as report
import seafast.output.report.{name}
import seafast.output.report.write
print(callable(report.{name}), type(report.{name}).__name__)
"""
    out = _python(code)
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == ["True", "function"]


def test_the_script_freezes_the_collector_before_shutdown_and_main_with_arguments_does_not():
    """``seafast`` (main with no arguments: the process's command line) leaves its objects to a
    quick shutdown (``gc.freeze``); ``main([...])``, as tests and scripts call it, does not."""
    code = """
import contextlib, gc, io, sys
from seafast.cli import main
with contextlib.redirect_stdout(io.StringIO()):
    assert main(["schema"]) == 0
after_list = gc.get_freeze_count()
sys.argv = ["seafast", "schema"]
with contextlib.redirect_stdout(io.StringIO()):
    assert main() == 0
print(after_list, gc.get_freeze_count() > 0)
"""
    out = _python(code)
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == ["0", "True"]
