"""The command line: start-up (``seafast --help``) and a whole ``seafast run`` of the base case, and where its time goes.

Run ``python benchmarks/bench_cli.py``. Each figure is the median over fresh interpreters (a
subprocess per call, wall time; CPU time of the child from ``getrusage``).

* Start-up: ``seafast --help`` and ``seafast run --help`` against a fresh interpreter importing
  the whole numerical stack the commands use (numpy, scipy, xarray, pydantic, matplotlib, the
  solvers, the study runner, the report): the parser must cost a small fraction of it.
* ``seafast run -o DIR`` of the base case with a warm BEM cache (one run first fills it; the
  cache is ``SEAFAST_CACHE_DIR`` as the command reads it), figures included: its wall time, and
  when its summary table reached stdout. ``seafast seastate --no-monte-carlo`` the same way.
* The run's breakdown, in a fresh interpreter through the library calls the command makes:
  imports, the model and its vessel (hull girder, BEM cache read), the linear and nonlinear
  solves, the Dataset of results.nc, results.nc, summary.csv, the figures (matplotlib's import
  included, and shown apart).

The last line is ``key=value`` pairs (docs/interface.md).
"""

from __future__ import annotations

import argparse
import json
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

FULL_STACK = (
    "import scipy.linalg, threadpoolctl, matplotlib.pyplot, seafast.cli, seafast.analyses.run, seafast.output.files, "
    "seafast.output.report.write, seafast.studies.runner, seafast.analyses.seastate.monte_carlo, seafast.analyses.operability.allowable"
)

# the run of seafast.cli.run, step by step, in a fresh interpreter: prints one JSON object of seconds
BREAKDOWN = """
import json, sys, time
from pathlib import Path
t = {"start": time.perf_counter()}
import seafast.cli.command
from seafast.analyses.run import run_case
from seafast.config import load_case
from seafast.output.files import write_netcdf
from seafast.output.tables import format_summary_table, write_summary_csv
t["imports"] = time.perf_counter()
case = load_case(None, {})
stamps = []
result = run_case(case, progress=lambda message: stamps.append(time.perf_counter()))
t["solved"] = time.perf_counter()
rows = result.summary
format_summary_table(rows)
t["table"] = time.perf_counter()
out = Path(sys.argv[1])
out.mkdir(parents=True, exist_ok=True)
ds = result.dataset
t["dataset"] = time.perf_counter()
write_netcdf(ds, out / "results.nc")
t["netcdf"] = time.perf_counter()
write_summary_csv(rows, out / "summary.csv", result.summary_columns)
t["csv"] = time.perf_counter()
import matplotlib.pyplot
t["matplotlib"] = time.perf_counter()
from seafast.output.plots import write_case_figures
figures = write_case_figures(ds, out)
t["figures"] = time.perf_counter()
vessel, solves = stamps[0], stamps[1]  # 'vessel excitation ...' then 'linear and nonlinear solves'
print(json.dumps({
    "imports": t["imports"] - t["start"], "model": vessel - t["imports"], "vessel": solves - vessel,
    "solve": t["solved"] - solves, "table": t["table"] - t["solved"], "dataset": t["dataset"] - t["table"],
    "netcdf": t["netcdf"] - t["dataset"], "csv": t["csv"] - t["netcdf"], "matplotlib_import": t["matplotlib"] - t["csv"],
    "figures": t["figures"] - t["csv"], "figure_count": len(figures),
}))
"""


def _seafast_command() -> list[str]:
    """The installed ``seafast`` script next to this interpreter, else the same entry point via ``-c``."""
    script = shutil.which("seafast", path=str(Path(sys.executable).parent))
    if script:
        return [script]
    return [sys.executable, "-c", "import sys; from seafast.cli import main; sys.exit(main())"]


def _child_cpu_s() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def _time(command: list[str], repeats: int) -> tuple[float, float]:
    """Median wall and CPU time [s] of ``command`` in a fresh process."""
    walls, cpus = [], []
    for _ in range(repeats):
        cpu0, t0 = _child_cpu_s(), time.perf_counter()
        subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
        walls.append(time.perf_counter() - t0)
        cpus.append(_child_cpu_s() - cpu0)
    return statistics.median(walls), statistics.median(cpus)


def _time_command(command: list[str], marker: str) -> tuple[float, float, float]:
    """Wall time [s] of ``command`` (a fresh process), when a stdout line containing ``marker`` came, and its CPU time [s]."""
    cpu0, t0 = _child_cpu_s(), time.perf_counter()
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    assert process.stdout is not None
    seen = float("nan")
    for line in process.stdout:
        if marker in line and seen != seen:
            seen = time.perf_counter() - t0
    if process.wait() != 0:
        raise SystemExit(f"{' '.join(command)} exited with {process.returncode}")
    return time.perf_counter() - t0, seen, _child_cpu_s() - cpu0


def _time_runs(command: list[str], marker: str, repeats: int) -> tuple[float, float, float]:
    """Median wall, time to the ``marker`` line and CPU time [s] of ``command -o TMPDIR`` over ``repeats`` fresh processes."""
    results = []
    for _ in range(repeats):
        with tempfile.TemporaryDirectory() as out:
            results.append(_time_command([*command, "-o", out], marker))
    wall, table, cpu = (statistics.median(r[i] for r in results) for i in range(3))
    return wall, table, cpu


def _breakdown(repeats: int) -> dict[str, float]:
    """Median seconds of each step of a run (:data:`BREAKDOWN`) over ``repeats`` fresh interpreters."""
    runs = []
    for _ in range(repeats):
        with tempfile.TemporaryDirectory() as out:
            done = subprocess.run([sys.executable, "-c", BREAKDOWN, out], check=True, capture_output=True, text=True)
        runs.append(json.loads(done.stdout.strip().splitlines()[-1]))
    return {key: statistics.median(r[key] for r in runs) for key in runs[0]}


def _print_startup(args: argparse.Namespace, seafast: list[str]) -> dict[str, float]:
    python_s, _ = _time([sys.executable, "-c", "pass"], args.repeats)
    help_s, help_cpu_s = _time([*seafast, "--help"], args.repeats)
    run_help_s, run_help_cpu_s = _time([*seafast, "run", "--help"], args.repeats)
    stack_s, stack_cpu_s = _time([sys.executable, "-c", FULL_STACK], args.repeats)
    print(f"empty interpreter (python -c pass)            median {python_s:6.3f} s wall")
    print(f"seafast --help                                median {help_s:6.3f} s wall, {help_cpu_s:6.3f} s CPU")
    print(f"seafast run --help                            median {run_help_s:6.3f} s wall, {run_help_cpu_s:6.3f} s CPU")
    print(f"import of the full stack (baseline)           median {stack_s:6.3f} s wall, {stack_cpu_s:6.3f} s CPU")
    print(f"--help costs {help_s / stack_s:.3f} of the full stack's import ({help_cpu_s / stack_cpu_s:.3f} in CPU time)")
    return {
        "cli_help_s": help_s,
        "cli_help_cpu_s": help_cpu_s,
        "cli_run_help_s": run_help_s,
        "python_startup_s": python_s,
        "full_stack_import_s": stack_s,
        "help_vs_full_stack": help_s / stack_s,
    }


def _print_run(args: argparse.Namespace, seafast: list[str]) -> dict[str, float]:
    with tempfile.TemporaryDirectory() as out:  # fills the BEM cache if it is cold
        subprocess.run([*seafast, "-q", "run", "-o", out], check=True)
    run_s, table_s, run_cpu_s = _time_runs([*seafast, "run"], "maxima over the cargo", args.run_repeats)
    sea_s, sea_table_s, _ = _time_runs([*seafast, "seastate", "--no-monte-carlo"], "most probable maxima", args.run_repeats)
    b = _breakdown(args.run_repeats)
    print(f"seafast run -o DIR (base case, warm cache)    median {run_s:6.2f} s wall, {run_cpu_s:6.2f} s CPU; table after {table_s:.2f} s")
    print(f"seafast seastate --no-monte-carlo -o DIR      median {sea_s:6.2f} s wall; table after {sea_table_s:.2f} s")
    print("the run's steps (fresh interpreter, library calls of seafast run, median):")
    for label, key in (
        ("imports (cli, numerical stack, output)", "imports"),
        ("model", "model"),
        ("vessel (hull girder, BEM cache read)", "vessel"),
        ("linear and nonlinear solves", "solve"),
        ("summary table", "table"),
        ("Dataset of results.nc", "dataset"),
        ("results.nc", "netcdf"),
        ("summary.csv", "csv"),
        (f"{b['figure_count']:.0f} figures, matplotlib's import included", "figures"),
        ("  of which matplotlib's import", "matplotlib_import"),
    ):
        print(f"  {label:48s} {b[key]:6.3f} s")
    return {
        "cli_run_s": run_s,
        "cli_run_cpu_s": run_cpu_s,
        "cli_run_table_s": table_s,
        "cli_seastate_s": sea_s,
        "cli_seastate_table_s": sea_table_s,
        "run_imports_s": b["imports"],
        "run_model_vessel_s": b["model"] + b["vessel"],
        "run_solve_s": b["solve"],
        "run_files_s": b["dataset"] + b["netcdf"] + b["csv"],
        "run_figures_s": b["figures"],
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5, help="fresh processes per start-up figure (default: %(default)s)")
    parser.add_argument("--run-repeats", type=int, default=3, help="fresh processes per run figure (default: %(default)s)")
    parser.add_argument("--no-run", action="store_true", help="start-up only (no seafast run)")
    args = parser.parse_args()
    seafast = _seafast_command()
    keys = _print_startup(args, seafast)
    if not args.no_run:
        keys.update(_print_run(args, seafast))
    print(" ".join(f"{key}={value:.3f}" for key, value in keys.items()))


if __name__ == "__main__":
    main()
