"""Start-up of the command line: ``seafast --help`` and ``seafast run --help`` against the full stack's import.

Run ``python benchmarks/bench_cli.py``. Each figure is the median over fresh interpreters (a
subprocess per call, wall time; CPU time of the child from ``getrusage``). The baseline, timed
the same way on the same machine, is a fresh interpreter importing the whole numerical stack
the commands use (numpy, scipy, xarray, pydantic, matplotlib, the solvers, the study runner,
the report): the parser must cost a small fraction of it. The last line is ``key=value`` pairs
(docs/interface.md).
"""

from __future__ import annotations

import argparse
import resource
import shutil
import statistics
import subprocess
import sys
import time
from pathlib import Path

FULL_STACK = (
    "import scipy.linalg, threadpoolctl, matplotlib.pyplot, seafast.cli, seafast.analyses.run, seafast.output.files, "
    "seafast.output.report.write, seafast.studies.runner, seafast.analyses.seastate.monte_carlo, seafast.analyses.operability.allowable"
)


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


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5, help="fresh processes per figure (default: %(default)s)")
    args = parser.parse_args()
    seafast = _seafast_command()
    python_s, _ = _time([sys.executable, "-c", "pass"], args.repeats)
    help_s, help_cpu_s = _time([*seafast, "--help"], args.repeats)
    run_help_s, run_help_cpu_s = _time([*seafast, "run", "--help"], args.repeats)
    stack_s, stack_cpu_s = _time([sys.executable, "-c", FULL_STACK], args.repeats)
    print(f"empty interpreter (python -c pass)            median {python_s:6.3f} s wall")
    print(f"seafast --help                                median {help_s:6.3f} s wall, {help_cpu_s:6.3f} s CPU")
    print(f"seafast run --help                            median {run_help_s:6.3f} s wall, {run_help_cpu_s:6.3f} s CPU")
    print(f"import of the full stack (baseline)           median {stack_s:6.3f} s wall, {stack_cpu_s:6.3f} s CPU")
    print(f"--help costs {help_s / stack_s:.3f} of the full stack's import ({help_cpu_s / stack_cpu_s:.3f} in CPU time)")
    print(
        f"cli_help_s={help_s:.3f} cli_help_cpu_s={help_cpu_s:.3f} cli_run_help_s={run_help_s:.3f} python_startup_s={python_s:.3f} "
        f"full_stack_import_s={stack_s:.3f} help_vs_full_stack={help_s / stack_s:.3f}"
    )


if __name__ == "__main__":
    main()
