"""Study throughput against the cost of one nonlinear solve, and serial vs local processes vs Dask.

Usage::

    python benchmarks/bench_study.py            # HBM reference, subset timings, the three source studies
    python benchmarks/bench_study.py --quick    # HBM reference and subset timings only
    python benchmarks/bench_study.py --fake     # a fake (instant) evaluator: runner overhead only

The machine-independent figure is ``cost_per_point_vs_hbm``: a study's wall time times the
processes it used, per point, over the median condensed HBM solve of the base case timed in
this process (``seafast.solvers.from_case.solve_nonlinear`` with the base case's own solver settings, so
it follows any change of the defaults). It is printed per study, and for the saddles, lashing
and cargo studies together (sums of wall x workers over sums of points x the HBM median taken
just before each study, so a change of the machine's load between studies cancels). On a
shared machine wall times swing with the other users' load; the same ratio in CPU time (this
process and its workers, over the HBM's CPU median) is printed as ``cpu_cost_per_point_vs_hbm``.
The last line is ``key=value`` pairs.
"""

from __future__ import annotations

import argparse
import math
import os
import resource
import shutil
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from seafast.parallel.executor import ExecutionOptions
from seafast.parallel.threads import one_blas_thread
from seafast.studies.runner import StudyRun, run_study
from seafast.studies.spec import build_grid, load_study_spec, study_spec_from_mapping

SUBSET = {
    "name": "bench-subset",
    "axes": [
        {"key": "seafastening.saddle_count", "values": [2, 3, 4, 5]},
        {"key": "seafastening.saddle_stiffness_N_per_m", "start": 1.1e7, "stop": 1.1e10, "num": 10, "scale": "log"},
    ],
}
SOURCE_STUDIES = ("saddles", "lashing", "cargo")


def fake_evaluator(case):
    """Instant evaluator (runner overhead only)."""
    rows = []
    for load_case in ("static", "dynamic"):
        for model in ("linear", "nonlinear"):
            rows.append(
                dict(
                    load_case=load_case,
                    model=model,
                    u_c_m=0.0,
                    u_s_m=0.0,
                    u_d_m=0.0,
                    F_N=float(case.seafastening.saddle_count),
                    M_b_Nm=1.0,
                    sigma_b_Pa=1.0,
                    converged=True,
                    contact_preserved=True,
                    residual_norm=0.0,
                    iterations=0,
                )
            )
    return rows


def hbm_median_ms(repeats: int = 200) -> tuple[float, float]:
    """Median wall and CPU time [ms] of the base case's dynamic nonlinear solve with its own settings (condensed HBM)."""
    from seafast.config import load_case
    from seafast.excitation.vessel import vessel_excitation
    from seafast.model.from_case import build_model
    from seafast.solvers.from_case import solve_nonlinear

    case = load_case()
    assert case.solver.method == "hbm" and case.solver.formulation == "condensed", "the base case is solved by the condensed HBM"
    model = build_model(case)
    excitation = vessel_excitation(case).cargo_excitation(model, case)
    times, cpu = [], []
    with one_blas_thread():
        solve_nonlinear(model, excitation, case, static=False)  # warm the per-model caches
        for _ in range(repeats):
            t0, c0 = time.perf_counter(), time.process_time()
            solve_nonlinear(model, excitation, case, static=False)
            times.append(time.perf_counter() - t0)
            cpu.append(time.process_time() - c0)
    return 1e3 * float(np.median(times)), 1e3 * float(np.median(cpu))


def _cpu_seconds() -> float:
    """CPU time of this process and its finished child processes [s] (user + system)."""
    children = resource.getrusage(resource.RUSAGE_CHILDREN)
    return time.process_time() + children.ru_utime + children.ru_stime


def _run(grid, execution: ExecutionOptions, evaluator) -> StudyRun:
    out = Path(tempfile.mkdtemp(prefix="seafast-bench-"))
    try:
        run = run_study(grid, out, evaluator=evaluator, execution=execution)
        assert run.computed == grid.size and run.failed == 0, f"{run.failed} failed points"
        return run
    finally:
        shutil.rmtree(out, ignore_errors=True)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--quick", action="store_true", help="skip the full studies")
    parser.add_argument("--fake", action="store_true", help="use an instant fake evaluator")
    parser.add_argument("--studies", default=",".join(SOURCE_STUDIES), help="full studies to time (default: %(default)s)")
    parser.add_argument("--workers", type=int, default=None, help="local processes for the full studies (default: all cores)")
    args = parser.parse_args(argv)
    evaluator = "bench_study:fake_evaluator" if args.fake else None
    if args.fake:
        sys.path.insert(0, str(Path(__file__).resolve().parent))
        os.environ["PYTHONPATH"] = os.pathsep.join([str(Path(__file__).resolve().parent), os.environ.get("PYTHONPATH", "")])
    cores = os.cpu_count() or 1
    hbm_ms, hbm_cpu_ms = hbm_median_ms()
    print(f"base case: condensed HBM median {hbm_ms:.3f} ms wall, {hbm_cpu_ms:.3f} ms CPU (the reference of cost_per_point_vs_hbm)")
    names = [] if args.quick else [n for n in args.studies.split(",") if n]
    figures: dict[str, float] = {}
    core_seconds = weighted_points = cpu_seconds = weighted_cpu = 0.0
    total_points, t_full = 0, 0.0
    for name in names:
        study_grid = build_grid(*load_study_spec(name))
        hbm_before, hbm_cpu_before = hbm_median_ms(100)
        execution = ExecutionOptions(workers=args.workers, progress=sys.stderr.isatty())
        cpu0 = _cpu_seconds()
        run = _run(study_grid, execution, evaluator)
        cpu = _cpu_seconds() - cpu0
        workers = getattr(run, "workers", execution.worker_count())  # (older runners did not record it)
        cost = run.seconds * workers / study_grid.size / (1e-3 * hbm_before)
        figures[name] = cost
        core_seconds += run.seconds * workers
        weighted_points += study_grid.size * 1e-3 * hbm_before
        cpu_seconds += cpu
        weighted_cpu += study_grid.size * 1e-3 * hbm_cpu_before
        total_points += study_grid.size
        t_full += run.seconds
        print(
            f"study {name:8s}: {study_grid.size:4d} points in {run.seconds:6.2f} s on {workers} processes "
            f"({study_grid.size / run.seconds:6.1f} points/s, {1e3 * run.seconds * workers / study_grid.size:6.2f} ms x process "
            f"per point, {1e3 * cpu / study_grid.size:6.2f} ms CPU per point); HBM median {hbm_before:.3f} ms; "
            f"cost_per_point_vs_hbm = {cost:.2f} (CPU: {cpu / study_grid.size / (1e-3 * hbm_cpu_before):.2f})"
        )
    grid = build_grid(study_spec_from_mapping(SUBSET))
    # the subset last: a Dask LocalCluster leaves threads in this process, after which local
    # workers are no longer forked (see seafast.parallel.executor)
    print(
        f"subset: {grid.size} points ({' x '.join(grid.keys)}), {cores} cores, evaluator: {'fake' if args.fake else 'seafast.analyses.run'}"
    )
    t_serial = _run(grid, ExecutionOptions(workers=1, progress=False), evaluator).seconds
    print(f"serial:    {t_serial:6.2f} s  {grid.size / t_serial:7.1f} points/s")
    t_proc = _run(grid, ExecutionOptions(workers=cores, progress=False), evaluator).seconds
    print(f"processes: {t_proc:6.2f} s  {grid.size / t_proc:7.1f} points/s  ({cores} workers, incl. start-up)")
    from distributed import LocalCluster

    with LocalCluster(processes=True, n_workers=cores, threads_per_worker=1, host="127.0.0.1", dashboard_address=None) as cluster:
        t_dask = _run(grid, ExecutionOptions(scheduler=cluster.scheduler_address, progress=False), evaluator).seconds
    print(f"dask:      {t_dask:6.2f} s  {grid.size / t_dask:7.1f} points/s  (LocalCluster {cores} x 1 thread, first use)")
    together = core_seconds / weighted_points if weighted_points else math.nan
    together_cpu = cpu_seconds / weighted_cpu if weighted_cpu else math.nan
    if names:
        print(
            f"studies {', '.join(names)}: {total_points} points in {t_full:.1f} s; cost per point = {together:.2f} x the HBM solve "
            f"(target for saddles,lashing,cargo: <= 8); in CPU time (load-independent): {together_cpu:.2f}"
        )
    source = tuple(names) == SOURCE_STUDIES
    per_study = " ".join(f"cost_{n.replace('-', '_')}={figures[n]:.3g}" for n in names)
    print(
        f"cost_per_point_vs_hbm={together if source else math.nan:.3g} "
        f"cpu_cost_per_point_vs_hbm={together_cpu if source else math.nan:.3g} "
        f"hbm_median_ms={hbm_ms:.3g} {per_study} "
        f"points_per_s_serial={grid.size / t_serial:.3g} points_per_s_processes={grid.size / t_proc:.3g} "
        f"points_per_s_dask={grid.size / t_dask:.3g} full_three_studies_s={t_full if source else math.nan:.3g} "
        f"full_studies_points={total_points} workers={args.workers or cores}".replace("  ", " ")
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
