"""Operability benchmark: the nonlinear design-wave MPM of one sea state, an operability chart, and the speed-up
against the Monte Carlo reference of the same sea state.

Run as ``python benchmarks/bench_operability.py [--skip-monte-carlo]`` (the BEM must be in the disk
cache: any earlier ``seafast run`` puts it there). Figures, all in one process, base case:

* ``design_wave_ms``: :func:`~seafast.analyses.seastate.design_wave.sea_state_design_waves` of Hs = 3 m,
  Tp = 10 s once the transfer functions exist (the spectral analysis done): selecting the 33 design
  waves of the five quantities (three per location: every saddle, the moment's governing point) and
  solving the 12 distinct waves to their converged periodic answer (exact-event shooting, the default);
  median of 7;
* ``design_wave_h16_ms``: the same waves by harmonic balance at H = 16 (``DesignWaveSettings(harmonics=16)``,
  the operators of each wave shape formed once), and ``design_wave_converged_vs_h16``, the ratio (target <= 2);
* ``operability_s``: ``allowable_sea_states`` (converged design waves) over 23 peak periods (5 to 16 s by 0.5 s), limits
  11.5 MN / 28 MPa so that the saddles lift off below the limits at most peak periods (the
  nonlinear search at work), vessel in memory; target <= 5 s; ``operability_base_s``: the base
  case's own limits (7 MN / 20 MPa, reached before any lift-off); ``operability_h16_s``: the first chart with
  design waves at H = 16;
* ``speedup_vs_monte_carlo``: the Monte Carlo reference of the same sea state (20 realisations of
  3 h, one process, plan included) over spectral analysis + design waves from the case.

The last line is ``key=value`` pairs.
"""

from __future__ import annotations

import sys
import tempfile
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

import seafast
from benchutil import timed
from seafast.analyses.operability.allowable import OperabilitySettings, allowable_sea_states
from seafast.analyses.seastate.design_wave import DesignWaveSettings, design_wave_extremes, sea_state_design_waves, still_water_excitation
from seafast.analyses.seastate.spectral import spectral_analysis
from seafast.parallel.threads import one_blas_thread

RAISED = {"limits.max_saddle_force_N": 11.5e6, "limits.max_bending_stress_Pa": 28.0e6}


def timed_cpu(fn, repeats: int) -> tuple[object, float, float]:
    """Call ``fn`` ``repeats`` times; its last result and the median wall and CPU time of this process [ms].

    The CPU time is what the call itself used, whatever the other users of the shared cores do.
    """
    out, wall, cpu = None, [], []
    for _ in range(repeats):
        t0, c0 = time.perf_counter(), time.process_time()
        out = fn()
        wall.append(time.perf_counter() - t0)
        cpu.append(time.process_time() - c0)
    return out, 1e3 * float(np.median(wall)), 1e3 * float(np.median(cpu))


def main() -> None:
    skip_mc = "--skip-monte-carlo" in sys.argv
    with one_blas_thread():
        case = seafast.load_case(None)
        analysis = spectral_analysis(case)
        dw = sea_state_design_waves(analysis)  # warm: vessel, moment map, numba
        distinct = len({(s.amplitude, w.frequency_index) for w, s in zip(dw.waves, dw.solutions, strict=True)})
        _, dw_ms, dw_cpu_ms = timed_cpu(lambda: sea_state_design_waves(analysis), 7)
        h16 = DesignWaveSettings(harmonics=16)
        sea_state_design_waves(analysis, h16)
        _, h16_ms, h16_cpu_ms = timed_cpu(lambda: sea_state_design_waves(analysis, h16), 15)
        t = dw.totals
        print(
            f"design waves, base case Hs = 3 m, Tp = 10 s: {len(dw.waves)} waves ({distinct} distinct), converged "
            f"(the default) {dw_ms:.1f} ms wall, {dw_cpu_ms:.1f} ms CPU; H = 16 {h16_ms:.1f} ms wall, {h16_cpu_ms:.1f} ms CPU: "
            f"{dw_ms / h16_ms:.2f}x (CPU {dw_cpu_ms / h16_cpu_ms:.2f}x)"
        )
        t16 = design_wave_extremes(analysis, still_water_excitation(analysis), h16).totals
        print(
            f"  nonlinear MPM F = {t['F_N'] / 1e6:.3f} MN, M_b = {t['M_b_Nm'] / 1e6:.2f} MN m, u_d = {t['u_d_m'] * 1e3:.2f} mm "
            f"(H = 16: {t16['F_N'] / 1e6:.3f} MN, {t16['M_b_Nm'] / 1e6:.2f} MN m; linear spectral "
            f"{analysis.extremes.totals['F_N'] / 1e6:.3f} MN, {analysis.extremes.totals['M_b_Nm'] / 1e6:.2f} MN m)"
        )

        tps = np.arange(5.0, 16.0 + 1e-9, 0.5)
        raised = seafast.load_case(None, RAISED)
        allowable_sea_states(raised, tps[:2])  # warm
        res, op_ms, op_cpu_ms = timed_cpu(lambda: allowable_sea_states(raised, tps), 1)
        op_s, op_cpu_s = op_ms / 1e3, op_cpu_ms / 1e3
        evaluations = sum(p.evaluations for p in res.points)
        lifted = sum(1 for p in res.points if p.hs_allowable_nonlinear_m != p.hs_allowable_linear_m)
        t0 = time.perf_counter()
        allowable_sea_states(case, tps)
        base_s = time.perf_counter() - t0
        t0 = time.perf_counter()
        allowable_sea_states(raised, tps, OperabilitySettings(design_wave=h16))
        op_h16_s = time.perf_counter() - t0
        print(
            f"operability over {tps.size} peak periods: {op_s:.2f} s wall, {op_cpu_s:.2f} s CPU with limits 11.5 MN / 28 MPa "
            f"({evaluations} design-wave evaluations, nonlinear differs from linear at {lifted} peak periods); "
            f"{base_s:.2f} s with the base limits; {op_h16_s:.2f} s wall with design waves at H = 16"
        )

        mc_s, speedup = float("nan"), float("nan")
        full_s = (
            timed(
                lambda: sea_state_design_waves(spectral_analysis(seafast.load_case(None, {"wave.amplitude_m": 3.0 + 1e-9 * time.time()}))),
                3,
            )[1]
            / 1e3
        )
        if not skip_mc:
            from seafast.analyses.seastate.monte_carlo import run_monte_carlo

            with tempfile.TemporaryDirectory() as d:
                t0 = time.perf_counter()
                mc = run_monte_carlo(case, Path(d), workers=1, progress=False)
                mc_s = time.perf_counter() - t0
            speedup = mc_s / full_s
            print(
                f"Monte Carlo reference (20 x 3 h, one process): {mc_s:.1f} s, F = {mc.nonlinear.mpm['F_N'] / 1e6:.3f} MN; "
                f"spectral analysis + design waves from the case {full_s * 1e3:.0f} ms: {speedup:.0f}x "
                f"({mc_s / (dw_ms / 1e3):.0f}x against the design waves alone)"
            )
    print(
        f"design_wave_ms={dw_ms:.2f} design_wave_cpu_ms={dw_cpu_ms:.2f} design_wave_h16_ms={h16_ms:.2f} "
        f"design_wave_converged_vs_h16={dw_ms / h16_ms:.2f} design_wave_converged_vs_h16_cpu={dw_cpu_ms / h16_cpu_ms:.2f} "
        f"operability_s={op_s:.2f} operability_cpu_s={op_cpu_s:.2f} operability_base_s={base_s:.2f} operability_h16_s={op_h16_s:.2f} "
        f"design_wave_full_s={full_s:.3f} monte_carlo_s={mc_s:.1f} speedup_vs_monte_carlo={speedup:.0f}"
    )


if __name__ == "__main__":
    main()
