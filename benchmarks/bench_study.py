"""Study throughput: serial vs local processes vs Dask (LocalCluster), and the source's three studies.

Usage::

    python benchmarks/bench_study.py            # subset timings + the three full studies
    python benchmarks/bench_study.py --quick    # subset timings only
    python benchmarks/bench_study.py --fake     # a fake (instant) evaluator: runner overhead only

Prints the figures; the last line is ``key=value`` pairs: points_per_s_serial,
points_per_s_processes, points_per_s_dask, full_three_studies_s (NaN with --quick), workers.
"""

from __future__ import annotations

import argparse
import math
import os
import shutil
import sys
import tempfile
import time
from pathlib import Path

from seafast.studies.runner import ExecutionOptions, run_study
from seafast.studies.spec import build_grid, load_study_spec, study_spec_from_mapping

SUBSET = {
    "name": "bench-subset",
    "axes": [
        {"key": "seafastening.saddle_count", "values": [2, 3, 4, 5]},
        {"key": "seafastening.saddle_stiffness_N_per_m", "start": 1.1e7, "stop": 1.1e10, "num": 10, "scale": "log"},
    ],
}


def fake_evaluator(case):
    """Instant evaluator (runner overhead only)."""
    rows = []
    for load_case in ("static", "dynamic"):
        for model in ("linear", "nonlinear"):
            rows.append(
                dict(load_case=load_case, model=model, u_c_m=0.0, u_s_m=0.0, u_d_m=0.0, F_N=float(case.seafastening.saddle_count),
                     M_b_Nm=1.0, sigma_b_Pa=1.0, converged=True, contact_preserved=True, residual_norm=0.0, iterations=0)
            )
    return rows


def _timed(grid, execution: ExecutionOptions, evaluator) -> float:
    out = Path(tempfile.mkdtemp(prefix="seafast-bench-"))
    try:
        run = run_study(grid, out, evaluator=evaluator, execution=execution)
        assert run.computed == grid.size and run.failed == 0, f"{run.failed} failed points"
        return run.seconds
    finally:
        shutil.rmtree(out, ignore_errors=True)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--quick", action="store_true", help="skip the three full studies")
    parser.add_argument("--fake", action="store_true", help="use an instant fake evaluator")
    parser.add_argument("--studies", default="saddles,lashing,cargo", help="full studies to time (default: %(default)s)")
    args = parser.parse_args(argv)
    evaluator = "bench_study:fake_evaluator" if args.fake else None
    if args.fake:
        sys.path.insert(0, str(Path(__file__).resolve().parent))
        os.environ["PYTHONPATH"] = os.pathsep.join([str(Path(__file__).resolve().parent), os.environ.get("PYTHONPATH", "")])
    workers = os.cpu_count() or 1
    grid = build_grid(study_spec_from_mapping(SUBSET))
    print(f"subset: {grid.size} points ({' x '.join(grid.keys)}), {workers} cores, evaluator: {'fake' if args.fake else 'seafast.pipeline'}")
    if not args.fake:  # warm the on-disk hydrodynamics cache once, outside the timings
        _timed(build_grid(study_spec_from_mapping({**SUBSET, "axes": [{"key": "cargo.length_m", "values": [74.0]}]})),
               ExecutionOptions(workers=1, progress=False), evaluator)
    t_serial = _timed(grid, ExecutionOptions(workers=1, progress=False), evaluator)
    print(f"serial:    {t_serial:6.2f} s  {grid.size / t_serial:7.1f} points/s")
    t_proc = _timed(grid, ExecutionOptions(workers=workers, progress=False), evaluator)
    print(f"processes: {t_proc:6.2f} s  {grid.size / t_proc:7.1f} points/s  ({workers} workers, incl. start-up)")
    from distributed import LocalCluster

    with LocalCluster(processes=True, n_workers=workers, threads_per_worker=1, host="127.0.0.1", dashboard_address=None) as cluster:
        t_dask = _timed(grid, ExecutionOptions(scheduler=cluster.scheduler_address, progress=False), evaluator)
    print(f"dask:      {t_dask:6.2f} s  {grid.size / t_dask:7.1f} points/s  (LocalCluster {workers} x 1 thread, first use)")
    full, total = math.nan, 0
    if not args.quick:
        t0 = time.perf_counter()
        names = [n for n in args.studies.split(",") if n]
        for name in names:
            study_grid = build_grid(*load_study_spec(name))
            seconds = _timed(study_grid, ExecutionOptions(progress=sys.stderr.isatty()), evaluator)
            total += study_grid.size
            print(f"study {name:8s}: {study_grid.size:4d} points in {seconds:6.1f} s ({study_grid.size / seconds:.1f} points/s)")
        full = time.perf_counter() - t0
        print(f"studies {', '.join(names)}: {total} points in {full:.1f} s (target for saddles,lashing,cargo: <= 30 s)")
    print(
        f"points_per_s_serial={grid.size / t_serial:.3g} points_per_s_processes={grid.size / t_proc:.3g} "
        f"points_per_s_dask={grid.size / t_dask:.3g} full_three_studies_s={full if args.studies == 'saddles,lashing,cargo' else math.nan:.3g} "
        f"full_studies_s={full:.3g} full_studies_points={total if not args.quick else 0} workers={workers}"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
