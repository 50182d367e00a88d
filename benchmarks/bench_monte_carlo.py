"""Monte Carlo benchmark: one 3-hour nonlinear realisation of the base case, windows against a full march.

Run as ``python benchmarks/bench_monte_carlo.py`` (BEM in the disk cache). All figures in one
process, BLAS on one thread, kernels compiled before timing:

* ``realisation_3h_s``: one 3-hour realisation (synthesis, linear maxima, windowed nonlinear
  march, record statistics) of the base case in Hs = 3 m, Tp = 10 s, where it lifts off a few
  times an hour (target <= 60 s); ``benchmark_realisation()``, as ``bench_seastate.py`` reports;
* ``full_march_3h_s``: the baseline, the same record's nonlinear march over all 3 hours (no
  windows); ``speedup_vs_full_march`` = that / ``realisation_3h_s`` (the whole realisation,
  linear part included); ``us_per_step`` of the full march;
* ``heavy_realisation_3h_s``: Hs = 6 m, Tp = 10 s (lift-off in most waves; a third of the record
  is marched);
* ``step_change_F``, ``step_change_M``: relative change of that record's 3-hour nonlinear maxima
  of saddle force and bending moment when the integrator step is halved (16 -> 32 steps per
  period of the reference mode).

The last line is ``key=value`` pairs.
"""

from __future__ import annotations

import time
from dataclasses import replace

import numpy as np
from scipy.ndimage import spline_filter1d

import seafast
from seafast.analyses.seastate.monte_carlo import BENCHMARK_SEA_STATE, MonteCarloSettings, benchmark_realisation, build_plan
from seafast.analyses.seastate.realisation import evaluate_realisation
from seafast.analyses.seastate.synthesis import realisation_phases, synthesise
from seafast.parallel.threads import one_blas_thread
from seafast.solvers.transient import MarchState, march_window


def _full_march_s(plan, index: int) -> tuple[float, int]:
    """Seconds to march the whole record of realisation ``index`` (no windows), and the steps."""
    grid = plan.grid
    X = synthesise(grid, realisation_phases(plan.seed, index, grid.omega_rad_s.size), plan.transfer)
    coef = np.ascontiguousarray(spline_filter1d(X, order=3, axis=0, mode="grid-wrap"))
    n_fine = grid.samples * plan.ratio
    d0 = plan.compression_static_m + X[0, : plan.saddle_count]
    t0 = time.perf_counter()
    march_window(
        plan.system,
        coef,
        plan.ratio,
        plan.compression_static_m,
        np.ones(grid.samples, dtype=bool),
        0,
        n_fine - 1,
        MarchState.quasi_static(plan.system, d0),
        tolerance_m=plan.tolerance_m,
        moments=plan.moments,
    )
    return time.perf_counter() - t0, n_fine - 1


def main() -> None:
    with one_blas_thread():
        realisation_s = benchmark_realisation()
        case = seafast.load_case(None, BENCHMARK_SEA_STATE)
        plan = build_plan(case)
        t0 = time.perf_counter()
        record, _ = evaluate_realisation(plan, 1)
        total_s = time.perf_counter() - t0
        full_s, steps = _full_march_s(plan, 1)
        window_share = record["window_steps"] / steps
        print(
            f"base case, Hs 3 m, Tp 10 s, 3 h: realisation {realisation_s:.2f} s (again {total_s:.2f} s), "
            f"{record['windows']} windows, {window_share:.2%} of {steps} steps marched, "
            f"{record['nonlinear']['uplift_events']} uplift events"
        )
        print(f"  baseline: marching all {steps} steps {full_s:.2f} s ({1e6 * full_s / steps:.2f} us/step)")

        heavy = seafast.load_case(None, {**BENCHMARK_SEA_STATE, "sea_state.significant_height_m": 6.0})
        heavy_plan = build_plan(heavy)
        evaluate_realisation(heavy_plan, 0)
        t0 = time.perf_counter()
        ref, _ = evaluate_realisation(heavy_plan, 1)
        heavy_s = time.perf_counter() - t0
        fine, _ = evaluate_realisation(build_plan(heavy, replace(MonteCarloSettings(), steps_per_period=32)), 1)
        dF = fine["nonlinear"]["F_N"] / ref["nonlinear"]["F_N"] - 1.0
        dM = fine["nonlinear"]["M_b_Nm"] / ref["nonlinear"]["M_b_Nm"] - 1.0
        print(
            f"Hs 6 m, Tp 10 s, 3 h: realisation {heavy_s:.2f} s, {ref['windows']} windows, "
            f"{ref['window_steps'] / (heavy_plan.grid.samples * heavy_plan.ratio):.1%} of the record marched, "
            f"{ref['nonlinear']['uplift_events']} uplift events"
        )
        print(f"  step halved (32 steps per period): F {dF:+.2e}, M_b {dM:+.2e}")
    print(
        f"realisation_3h_s={realisation_s:.3f} full_march_3h_s={full_s:.3f} speedup_vs_full_march={full_s / realisation_s:.1f} "
        f"us_per_step={1e6 * full_s / steps:.2f} heavy_realisation_3h_s={heavy_s:.3f} step_change_F={dF:.2e} step_change_M={dM:.2e}"
    )


if __name__ == "__main__":
    main()
