"""Benchmark: condensed HBM vs full HBM vs the exact references, base case, one BLAS thread.

The time-domain reference is timed in both formulations; the full-DOF one (independent of the
HBM's condensation) is the reference of ``speedup_vs_time_domain``.

Run ``python benchmarks/bench_hbm.py``. The last line is ``key=value`` pairs (docs/interface.md).
Swap the case by editing :func:`base_case_model_and_excitation` only.
"""

from __future__ import annotations

import time

import numpy as np
from benchutil import timed
from threadpoolctl import threadpool_limits

from seafast.excitation.harmonic import HarmonicExcitation
from seafast.model.structure import StructuralModel


def base_case_model_and_excitation() -> tuple[StructuralModel, HarmonicExcitation]:
    """The built-in base case: its model and its real vessel excitation.

    Still-water and quasi-static wave hull deflection (lambda = 171 m, zeta_a = 3 m) plus the
    heave/pitch inertia from the capytaine RAOs (computed once, then read from the disk cache).
    """
    from seafast.config import load_case
    from seafast.excitation.vessel import vessel_excitation
    from seafast.pipeline import build_model

    case = load_case()
    model = build_model(case)
    return model, vessel_excitation(case).cargo_excitation(model, case)


def rel_diff(a, b) -> float:
    """Worst sample: max over time and saddles of |F_a - F_b|, over max |F_b|."""
    return float(np.max(np.abs(a.saddle_force_time_N - b.saddle_force_time_N)) / np.max(np.abs(b.saddle_force_time_N)))


def peak_diff(a, b) -> float:
    """Relative difference of the design value, the peak saddle force."""
    return float(abs(a.max_saddle_force_N / b.max_saddle_force_N - 1.0))


def peak_moment_Nm(model, excitation, response) -> float:
    """Largest |bending moment| over the cargo and the period [N m] of a periodic response."""
    from seafast.results.timeseries import from_periodic_response, moment_lines

    _, moment, _ = moment_lines(model, from_periodic_response(response), excitation)
    return float(np.max(np.abs(moment)))


def main() -> None:
    from seafast.solvers.hbm import HBMOptions, condensed_operators, solve_hbm
    from seafast.solvers.references import solve_quasi_static, solve_time_domain

    t_start = time.perf_counter()
    model, ex = base_case_model_and_excitation()
    # H = 16 with the exact law: the lowest H meeting the 1 % agreement with the references here
    cond = HBMOptions(harmonics=16, time_samples=128, contact_law="exact")
    full = HBMOptions(harmonics=16, time_samples=128, contact_law="exact", formulation="full")
    source = HBMOptions(harmonics=5, time_samples=128, contact_law="tanh")
    source_hybr = HBMOptions(harmonics=5, time_samples=128, contact_law="tanh", solver="hybr")
    cond_hybr = HBMOptions(harmonics=16, time_samples=128, contact_law="exact", solver="hybr")
    # the source's full-DOF HBM: Powell's hybrid method on all cargo DOFs x (2H+1), dense Jacobian
    full_source = HBMOptions(harmonics=5, time_samples=128, contact_law="tanh", formulation="full", solver="hybr")
    with threadpool_limits(1):
        solve_hbm(model, ex, cond)  # warm caches
        r_c, t_c = timed(lambda: solve_hbm(model, ex, cond), 100)
        r_s, t_s = timed(lambda: solve_hbm(model, ex, source), 100)
        r_sh, t_sh = timed(lambda: solve_hbm(model, ex, source_hybr), 30)
        r_ch, t_ch = timed(lambda: solve_hbm(model, ex, cond_hybr), 30)
        r_f, t_f = timed(lambda: solve_hbm(model, ex, full), 10)
        r_q, t_q = timed(lambda: solve_quasi_static(model, ex, 128), 10)
        # the independent reference: full-DOF HHT-alpha; and the saddle-condensed variant of the same equations
        r_t, t_t = timed(lambda: solve_time_domain(model, ex, 128, formulation="full"), 5)
        r_tc, t_tc = timed(lambda: solve_time_domain(model, ex, 128, formulation="condensed"), 5)
        r_fs, t_fs = timed(lambda: solve_hbm(model, ex, full_source), 1)
        # the floor of any condensed solve: the exact linear condensation (one banded LU of all harmonics)
        _, t_ops = timed(lambda: condensed_operators(model, ex, cond.harmonics), 100)
        # is the reference converged in its time step? the same integration with 4x the steps
        r_t4, t_t4 = timed(lambda: solve_time_domain(model, ex, 128, formulation="full", steps_per_period=8192), 1)
    print(f"case: {ex.source}; {model.cargo_dof_count} cargo DOFs, {model.saddle_count} saddles, omega {ex.omega_rad_s:.4g} rad/s")
    rows = (
        ("condensed HBM (H=16, N=128, exact)  newton", t_c, r_c),
        ("condensed HBM (H=5, N=128, tanh)    newton", t_s, r_s),
        ("condensed HBM (H=5, N=128, tanh)    hybr  ", t_sh, r_sh),
        ("condensed HBM (H=16, N=128, exact)  hybr  ", t_ch, r_ch),
        ("full HBM      (H=16, N=128, exact)  newton", t_f, r_f),
        ("full HBM      (H=5, N=128, tanh)    hybr  ", t_fs, r_fs),
    )
    for name, t, r in rows:
        ok = "converged" if r.converged else "NOT CONVERGED"
        print(f"{name} median {t:9.2f} ms  {ok}, {r.iterations} it: {r.message.splitlines()[0] if r.message else ''}")
    print(f"quasi-static reference (N=128)              median {t_q:9.2f} ms")
    print(f"time-domain reference, full-DOF (2048 steps/T)  median {t_t:9.2f} ms  {r_t.message}")
    print(f"time-domain reference, condensed (2048 steps/T) median {t_tc:9.2f} ms  {r_tc.message}")
    print(f"time-domain reference, full-DOF (8192 steps/T)  once     {t_t4:9.2f} ms  peak saddle force {r_t4.max_saddle_force_N / 1e6:.4f} MN "
          f"(2048 steps/T: {r_t.max_saddle_force_N / 1e6:.4f} MN, {peak_diff(r_t, r_t4):.1e} apart: the reference is converged in its time step)")
    print(f"exact condensation alone (H={cond.harmonics}, receptances + linear solution) median {t_ops:9.3f} ms: "
          f"the ceiling of any condensed HBM's speed-up over the time-domain reference is {t_t / t_ops:.0f}x on this mesh")
    print(f"speed-up of condensed vs full {t_f / t_c:.0f}x, vs time domain (full-DOF) {t_t / t_c:.0f}x, "
          f"vs time domain (condensed) {t_tc / t_c:.0f}x, vs quasi-static {t_q / t_c:.1f}x")
    pairs = {
        "condensed vs full": rel_diff(r_c, r_f),
        "condensed vs time domain": rel_diff(r_c, r_t),
        "condensed vs quasi-static": rel_diff(r_c, r_q),
        "time domain vs quasi-static": rel_diff(r_t, r_q),
        "full vs time domain": rel_diff(r_f, r_t),
        "hybr vs newton (H=16 exact)": rel_diff(r_ch, r_c),
        "tanh H=5 (source) vs time domain": rel_diff(r_s, r_t),
        "time domain full-DOF vs condensed": rel_diff(r_t, r_tc),
    }
    for name, v in pairs.items():
        print(f"max saddle-force difference {name:34s} {v:.2e} (worst sample, of the max force)")
    for name, (a, b) in {
        "condensed vs full": (r_c, r_f),
        "condensed vs time domain": (r_c, r_t),
        "condensed vs quasi-static": (r_c, r_q),
        "time domain vs quasi-static": (r_t, r_q),
        "tanh H=5 (source) vs time domain": (r_s, r_t),
    }.items():
        print(f"peak saddle-force difference {name:33s} {peak_diff(a, b):.2e}")
    print(
        f"max saddle force: condensed {r_c.max_saddle_force_N / 1e6:.4f} MN, full {r_f.max_saddle_force_N / 1e6:.4f} MN, "
        f"TD {r_t.max_saddle_force_N / 1e6:.4f} MN, QS {r_q.max_saddle_force_N / 1e6:.4f} MN, tanh H=5 {r_s.max_saddle_force_N / 1e6:.4f} MN; "
        f"max gap {r_c.max_gap_m * 1e3:.3f} mm"
    )
    print("note: the time-domain history rings after each re-contact (cargo mode ~16 rad/s, beyond H=16 and absent from the quasi-static "
          "reference), which dominates the worst-sample differences involving it")
    peaks = {name: (r.max_saddle_force_N, peak_moment_Nm(model, ex, r)) for name, r in
             (("condensed", r_c), ("full", r_f), ("time domain", r_t), ("quasi-static", r_q))}
    for name, (f, m) in peaks.items():
        print(f"peak values {name:13s} F = {f / 1e6:.4f} MN, M_b = {m / 1e6:.3f} MN m")
    peak_rel = max(
        abs(a[i] / b[i] - 1.0) for a in peaks.values() for b in peaks.values() for i in (0, 1)
    )
    speedup_full_source = t_fs / t_sh
    print(f"source-style full HBM (hybr, dense Jacobian, H=5 tanh) vs condensed with the same method and settings: {speedup_full_source:.0f}x")
    print(f"largest mutual difference of the reported peaks (F, M_b) over condensed/full/time domain/quasi-static: {peak_rel:.1e}")
    print(f"benchmark wall time {time.perf_counter() - t_start:.1f} s")
    max_rel = max(pairs[k] for k in ("condensed vs full", "condensed vs time domain", "condensed vs quasi-static", "time domain vs quasi-static"))
    print(
        f"median_ms={t_c:.3g} speedup_vs_full={speedup_full_source:.0f} speedup_vs_full_sparse_newton={t_f / t_c:.0f} "
        f"speedup_vs_time_domain={t_t / t_c:.0f} speedup_vs_time_domain_condensed={t_tc / t_c:.0f} speedup_ceiling_vs_time_domain={t_t / t_ops:.0f} max_rel_diff={peak_rel:.1e} max_rel_diff_worst_sample={max_rel:.1e}"
    )


if __name__ == "__main__":
    main()
