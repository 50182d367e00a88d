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
  solves, the Dataset of results.nc, results.nc, summary.csv, the figures one after the other
  (matplotlib's import included, and shown apart); then, in other fresh interpreters, the files
  as the command writes them on an idle two-core machine (results.nc here while one forked
  helper draws figures, whatever the load: ``files_shared_vs_serial`` against the sum of the
  steps), with the CPU time of each process: ``run_idle_two_cores_s``, the CPU time before the
  files plus the longer of the two processes' shares, is the run's wall time on two idle cores
  (on a loaded machine the command forks no helper, and its wall time is the load's).
* The machine's load (1-minute load average) at the start and the end: ``load_start``,
  ``load_end``.

The fresh interpreters read their modules' bytecode, as those of an installed package do (pip
compiles it at install time): where the environment forbids writing it
(``PYTHONDONTWRITEBYTECODE``, as in a development checkout), it is written once, first, under
``PYTHONPYCACHEPREFIX`` (a directory of its own in the temporary directory; the source tree is not
touched), and each interpreter after reads it. Without it every fresh interpreter compiles
seafast's modules again (about 0.3 s of each run's imports). ``--as-is`` keeps the environment as
it is; ``bytecode_cached`` (1 or 0) says which was measured.

The last line is ``key=value`` pairs (docs/interface.md).
"""

from __future__ import annotations

import argparse
import json
import os
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

# the run of seafast.cli.run, step by step, in a fresh interpreter: prints one JSON object of seconds.
# argv[2] "serial": results.nc, then matplotlib's import and the figures one after the other in
# this process (each step's own cost); "shared": the files as the command writes them on an idle
# two-core machine (write_run_outputs with one helper forked whatever the load: results.nc here
# while the helper draws figures, then this process draws too)
BREAKDOWN = """
import json, resource, sys, time
from pathlib import Path
def now():
    return time.perf_counter(), time.process_time()
t = {"start": now()}
import seafast.cli.command
from seafast.analyses.run import run_case
from seafast.config import load_case
from seafast.output.files import no_dask_lookup, write_netcdf, write_run_outputs
from seafast.output.tables import format_summary_table, write_summary_csv
t["imports"] = now()
case = load_case(None, {})
stamps = []
out = Path(sys.argv[1])
out.mkdir(parents=True, exist_ok=True)
with no_dask_lookup():  # as seafast run
    result = run_case(case, progress=lambda message: stamps.append(now()))
    t["solved"] = now()
    rows = result.summary
    format_summary_table(rows)
    t["table"] = now()
    ds = result.dataset
    t["dataset"] = now()
    if sys.argv[2] == "shared":
        paths = write_run_outputs(result, out, helpers=1)  # one helper, as on an idle two-core machine
        t["files"] = now()
        helper = resource.getrusage(resource.RUSAGE_CHILDREN)
        figure_count = len(paths) - 3
    else:
        write_netcdf(ds, out / "results.nc")
        t["netcdf"] = now()
        write_summary_csv(rows, out / "summary.csv", result.summary_columns)
        t["csv"] = now()
        import matplotlib.pyplot
        t["matplotlib"] = now()
        from seafast.output.case_figures import write_case_figures
        figure_count = len(write_case_figures(ds, out))
        t["figures"] = now()
t["vessel"], t["solves"] = stamps[0], stamps[1]  # 'vessel excitation ...' then 'linear and nonlinear solves'
order = ["start", "imports", "vessel", "solves", "solved", "table", "dataset"]
names = ["imports", "model", "vessel", "solve", "table", "dataset"]
if sys.argv[2] == "shared":
    order, names = order + ["files"], names + ["files"]
else:
    order, names = order + ["netcdf", "csv", "matplotlib", "figures"], names + ["netcdf", "csv", "matplotlib_import", "figures"]
steps = {"figure_count": figure_count}
for name, a, b in zip(names, order, order[1:]):
    steps[name] = t[b][0] - t[a][0]
    steps[name + "_cpu"] = t[b][1] - t[a][1]
if sys.argv[2] == "shared":
    steps["files_helper_cpu"] = helper.ru_utime + helper.ru_stime
else:
    steps["figures"] += steps["matplotlib_import"]
    steps["figures_cpu"] += steps["matplotlib_import_cpu"]
print(json.dumps(steps))
"""


def _use_bytecode_cache() -> bool:
    """Let the fresh interpreters write and read bytecode (a cache directory of their own, see the docstring); whether it was off."""
    if not os.environ.get("PYTHONDONTWRITEBYTECODE"):
        return False
    os.environ.pop("PYTHONDONTWRITEBYTECODE", None)
    os.environ.setdefault("PYTHONPYCACHEPREFIX", str(Path(tempfile.gettempdir()) / "seafast-bench-pycache"))
    return True


def _warm_bytecode(seafast: list[str]) -> None:
    """Compile what the measured interpreters import, once, before any is timed (a warm BEM cache, too)."""
    subprocess.run([sys.executable, "-c", FULL_STACK], check=True)
    subprocess.run([*seafast, "--help"], check=True, stdout=subprocess.DEVNULL)
    with tempfile.TemporaryDirectory() as out:
        subprocess.run([*seafast, "-q", "run", "-o", out], check=True)
        subprocess.run([*seafast, "-q", "seastate", "--no-monte-carlo", "-o", out], check=True)
        subprocess.run([sys.executable, "-c", BREAKDOWN, out, "shared"], check=True, capture_output=True)


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


def _breakdown(repeats: int, flavour: str) -> dict[str, float]:
    """Median seconds of each step of a run (:data:`BREAKDOWN`, ``flavour`` "serial" or "shared") over ``repeats`` fresh interpreters."""
    runs = []
    for _ in range(repeats):
        with tempfile.TemporaryDirectory() as out:
            done = subprocess.run([sys.executable, "-c", BREAKDOWN, out, flavour], check=True, capture_output=True, text=True)
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
    b = _breakdown(args.run_repeats, "serial")
    shared = _breakdown(args.run_repeats, "shared")
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
        (f"{b['figure_count']:.0f} figures one after the other, matplotlib's import included", "figures"),
        ("  of which matplotlib's import", "matplotlib_import"),
    ):
        print(f"  {label:70s} {b[key]:6.3f} s")
    files_serial = b["netcdf"] + b["csv"] + b["figures"]
    print(f"  {'results.nc, summary.csv and the figures, one process (the sum above)':70s} {files_serial:6.3f} s")
    print(f"  {'the same, figures shared with one helper (as on an idle 2-core machine)':70s} {shared['files']:6.3f} s")
    steps = ("imports", "model", "vessel", "solve", "table", "dataset")
    before_cpu = sum(shared[f"{k}_cpu"] for k in steps)
    files_cpu = max(shared["files_cpu"], shared["files_helper_cpu"])
    idle_s = before_cpu + files_cpu
    print("CPU time of that shared run (what each process needs of a core; on an idle 2-core machine, its wall time):")
    print(f"  {'imports to the Dataset':70s} {before_cpu:6.3f} s")
    print(f"  {'the files: this process / the helper':70s} {shared['files_cpu']:6.3f} / {shared['files_helper_cpu']:.3f} s")
    print(f"  {'the run on two idle cores (the two above, the longer of the pair)':70s} {idle_s:6.3f} s")
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
        "run_files_shared_s": shared["files"],
        "files_shared_vs_serial": shared["files"] / files_serial,
        "run_cpu_before_files_s": before_cpu,
        "run_files_cpu_s": shared["files_cpu"],
        "run_files_helper_cpu_s": shared["files_helper_cpu"],
        "run_idle_two_cores_s": idle_s,
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5, help="fresh processes per start-up figure (default: %(default)s)")
    parser.add_argument("--run-repeats", type=int, default=3, help="fresh processes per run figure (default: %(default)s)")
    parser.add_argument("--no-run", action="store_true", help="start-up only (no seafast run)")
    parser.add_argument("--as-is", action="store_true", help="the interpreters as the environment sets them (bytecode or not)")
    args = parser.parse_args()
    seafast = _seafast_command()
    cached = (not args.as_is) and _use_bytecode_cache()
    if cached:
        _warm_bytecode(seafast)
    bytecode = cached or not os.environ.get("PYTHONDONTWRITEBYTECODE")
    print(f"the fresh interpreters {'read compiled bytecode' if bytecode else 'compile every module (no bytecode written)'}")
    load_start = os.getloadavg()[0]
    keys = _print_startup(args, seafast)
    if not args.no_run:
        keys.update(_print_run(args, seafast))
    keys.update(load_start=load_start, load_end=os.getloadavg()[0], bytecode_cached=float(bytecode))
    print(f"load average (1 min) {load_start:.1f} at the start, {keys['load_end']:.1f} at the end, on {os.cpu_count()} cores")
    print(" ".join(f"{key}={value:.3f}" for key, value in keys.items()))


if __name__ == "__main__":
    main()
