"""Axial sliding analysis: what it adds to the base case, and the HBM against the time-domain reference.

Run ``python benchmarks/bench_axial.py``. Times, in one process and one BLAS thread, the base
case's ``run_case`` (the source's model) and, interleaved with it, the axial analysis that
``run_case`` adds when ``seafastening.friction_coefficient`` is set (0.3, plywood: the cargo
sticks; 0.02: it slides metres per period; 0.05, just below the critical coefficient: long stick
phases, solved by the time-domain reference), and the axial solvers alone on the base case's
nonlinear contact forces. Prints the figures; the last line is ``key=value`` pairs: ``axial_ms``
is what the axial analysis adds to the base case (mu = 0.3), ``axial_hbm_ms`` its two HBM solves
(the target: the axial HBM adds at most 1 ms).
"""

from __future__ import annotations

import numpy as np

from benchutil import timed
from seafast.parallel.threads import one_blas_thread


def _series(result):
    return result.series  # every row on the run's own time grid (N follows the adaptive H)


def main() -> None:
    from seafast.analyses.axial import axial_options, run_axial_analysis
    from seafast.analyses.run import run_case
    from seafast.config import load_case
    from seafast.excitation.axial import axial_load_of
    from seafast.model.from_case import axial_restraint
    from seafast.solvers.axial import solve_axial_hbm, solve_axial_time_domain

    base = load_case()
    cases = {mu: load_case(overrides={"seafastening.friction_coefficient": mu}) for mu in (0.3, 0.02, 0.05)}
    with one_blas_thread():
        run_case(base)
        results = {mu: run_case(c) for mu, c in cases.items()}  # warm: vessel and BEM from the caches
        series = {mu: _series(r) for mu, r in results.items()}
        # interleaved, so that the machine's load hits the base case and the axial analysis alike
        t_base, t_stick, t_slide, t_hbm = [], [], [], []
        r3, r2 = results[0.3], results[0.02]
        rest, load = axial_restraint(r3.case), axial_load_of(r3.case, r3.vessel)
        opts = axial_options(r3.case, int(r3.attrs["time_samples"]))
        normals = [np.maximum(r3.arrays.saddle_force_N[1, j], 0.0) for j in (0, 1)]
        for _ in range(31):
            t_base.append(timed(lambda: run_case(base), 1)[1])
            t_stick.append(timed(lambda: run_axial_analysis(r3.case, r3.model, r3.vessel, series[0.3]), 1)[1])
            t_slide.append(timed(lambda: run_axial_analysis(r2.case, r2.model, r2.vessel, series[0.02]), 1)[1])
            t_hbm.append(timed(lambda: [solve_axial_hbm(rest, load, n, opts) for n in normals], 1)[1])
        t_near = timed(lambda: run_axial_analysis(results[0.05].case, results[0.05].model, results[0.05].vessel, series[0.05]), 3)[1]
        # the axial solvers alone on the sliding case, against the reference
        res = results[0.02]
        restraint, load = axial_restraint(res.case), axial_load_of(res.case, res.vessel)
        normal = np.maximum(res.arrays.saddle_force_N[1, 1], 0.0)
        opts = axial_options(res.case, int(res.attrs["time_samples"]))
        hbm, t_h02 = timed(lambda: solve_axial_hbm(restraint, load, normal, opts), 21)
        td, t_td02 = timed(lambda: solve_axial_time_domain(restraint, load, normal, time_samples=opts.time_samples), 3)
    med = np.median
    print(f"base case run_case, no axial analysis (the source's model)            median {med(t_base):8.2f} ms")
    for mu, label, t in ((0.3, "sticks", med(t_stick)), (0.02, "slides", med(t_slide)), (0.05, "near mu_crit, long stick phases", t_near)):
        r = next(x for x in results[mu].summary if x["load_case"] == "dynamic" and x["model"] == "nonlinear")
        print(
            f"  axial analysis, friction_coefficient = {mu:<4} ({label:31s}) median {t:8.2f} ms ({t / med(t_base):.2f}x the base run): "
            f"slip {r['slip_m'] * 1e3:8.1f} mm, utilisation {r['friction_utilisation']:.3f}, "
            f"lashing force {r['axial_force_N'] / 1e3:6.1f} kN, mu_crit {r['critical_friction_coefficient']:.4f}"
        )
    print(f"  of which the two dynamic rows' axial HBM, mu = 0.3                  median {med(t_hbm):8.2f} ms")
    print(
        f"  axial solvers alone, mu = 0.02: HBM {t_h02:7.2f} ms ({hbm.iterations} Newton iterations), time-domain reference "
        f"{t_td02:8.1f} ms ({td.iterations} periods): slip HBM {hbm.slip_m:.5f} m, reference {td.slip_m:.5f} m "
        f"({hbm.slip_m / td.slip_m - 1:+.2%})"
    )
    print(
        f"axial_ms={med(t_stick):.2f} axial_hbm_ms={med(t_hbm):.2f} run_base_ms={med(t_base):.2f} "
        f"axial_vs_base={med(t_stick) / med(t_base):.3f} axial_slide_ms={med(t_slide):.2f} axial_near_critical_ms={t_near:.0f} "
        f"hbm_slide_ms={t_h02:.2f} td_slide_ms={t_td02:.1f} speedup_hbm_vs_td={t_td02 / t_h02:.0f} "
        f"slip_rel_diff={abs(hbm.slip_m / td.slip_m - 1):.2e}"
    )


if __name__ == "__main__":
    main()
