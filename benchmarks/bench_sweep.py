"""Benchmark: what a frequency sweep costs per branch point, against one HBM solve, in one process.

Cases (docs/sweeps.md):

* ``deck``: the example deck table with its wave part scaled by 0.3, no rigid-body motion, 1 % saddles,
  3 -> 8 rad/s: the softening resonance through both folds and back to the linear branch;
* ``wave``: the base case's wave sweep, 0.2 -> 1.8 rad/s (``seafast sweep --wave``).

For each: the continuation's wall time and points, the table's (stability, moments, linear model,
truncation estimate, range checks), both per point and over the median condensed HBM solve of the
same model and excitation at the sweep's H (warm start from the neighbouring point, as
continuation has it; timed in the same process). For ``deck``, also the time-domain stepped-sine
up- and down-sweeps that check its folds, and where they jump.

Run ``python benchmarks/bench_sweep.py``; the last line is ``key=value`` pairs.
"""

from __future__ import annotations

import tempfile
import time
from pathlib import Path

import numpy as np

from benchutil import timed
from seafast.parallel.threads import one_blas_thread

ROOT = Path(__file__).resolve().parents[1]


def deck_case(directory: Path):
    from seafast.config import load_case

    out = []
    for line in (ROOT / "examples" / "deck_deflection.csv").read_text().splitlines():
        if line.startswith(("#", "x_m")):
            out.append(line)
        else:
            x, still, amplitude, phase = line.split(",")
            out.append(f"{x},{still},{0.3 * float(amplitude):.6e},{phase}")
    table = directory / "deck.csv"
    table.write_text("\n".join(out) + "\n")
    return load_case(
        None, {"seafastening.saddle_stiffness_N_per_m": 1.1e7, "vessel.motions": "none", "vessel.deck_deflection_table": str(table)}
    )


def hbm_median_ms(result, omega: float) -> float:
    """Median condensed HBM solve [ms] at ``omega`` on the sweep's model and H, started from the branch's nearest point."""
    from seafast.analyses.sweep.frequency import SweepKind, wave_excitation
    from seafast.fourier import harmonics_to_time, real_to_complex_harmonics
    from seafast.solvers.from_case import hbm_options
    from seafast.solvers.hbm import solve_hbm

    case, model, branch = result.case, result.model, result.branch
    if result.kind is SweepKind.WAVE:
        excitation = wave_excitation(case, model, result.omega_start_rad_s, result.omega_end_rad_s)[0](omega)
    else:
        from seafast.excitation.vessel import vessel_excitation

        excitation = vessel_excitation(case).cargo_excitation(model, case).at_frequency(omega)
    H = int(branch.options["harmonics"])
    i = int(np.argmin(np.abs(branch.omega_rad_s - omega)))
    start = harmonics_to_time(real_to_complex_harmonics(branch.compression_harmonics_m[max(i - 1, 0)]), 128)
    options = hbm_options(case, harmonics=H, time_samples=int(branch.options["time_samples"]), formulation="condensed", solver="newton")
    return timed(lambda: solve_hbm(model, excitation, options, initial_compression_m=start), 15)[1]


def sweep(case, w0: float, w1: float, wave: bool):
    from seafast.analyses.sweep.frequency import SweepKind, frequency_sweep

    t0 = time.perf_counter()
    result = frequency_sweep(case, w0, w1, kind=SweepKind.WAVE if wave else SweepKind.STRUCTURAL)
    total = time.perf_counter() - t0
    return result, total


def main() -> None:
    from seafast.config import load_case
    from seafast.excitation.vessel import vessel_excitation
    from seafast.solvers.stepped_sine import stepped_sine_sweep

    figures: dict[str, float] = {}
    with tempfile.TemporaryDirectory() as tmp, one_blas_thread():
        for name, case, w0, w1, wave in (
            ("deck", deck_case(Path(tmp)), 3.0, 8.0, False),
            ("wave", load_case(None, {}), 0.2, 1.8, True),
        ):
            result, total = sweep(case, w0, w1, wave)
            n = result.branch.omega_rad_s.size
            t0 = time.perf_counter()  # the table alone, again on the same branch
            _ = _table_again(result)
            table_s = time.perf_counter() - t0
            hbm_ms = hbm_median_ms(result, float(np.median(result.branch.omega_rad_s)))
            per_point_ms = 1e3 * total / n
            print(
                f"{name}: {n} points in {total:.2f} s ({per_point_ms:.1f} ms a point; the table {1e3 * table_s / n:.1f} ms of it); "
                f"one warm-started HBM solve {hbm_ms:.2f} ms; a point costs {per_point_ms / hbm_ms:.1f} solves; "
                f"folds at {np.round(result.table.fold_omegas_rad_s, 4).tolist()} rad/s; "
                f"{sum(v.value == 'unstable' for v in result.table.stability)} unstable and "
                f"{int(result.table.marginal.sum())} marginal points"
            )
            figures.update(
                {
                    f"{name}_points": n,
                    f"{name}_s": round(total, 2),
                    f"{name}_table_s": round(table_s, 2),
                    f"{name}_point_vs_hbm": round(per_point_ms / hbm_ms, 1),
                    f"{name}_hbm_ms": round(hbm_ms, 3),
                }
            )
            if name == "deck":
                excitation_at = vessel_excitation(case).cargo_excitation(result.model, case).at_frequency
                t0 = time.perf_counter()
                up = stepped_sine_sweep(result.model, excitation_at, 4.0, 5.5)
                down = stepped_sine_sweep(result.model, excitation_at, 6.0, 4.2)
                td_s = time.perf_counter() - t0
                jumps = [max(s.jumps, key=lambda j: abs(j.range_after_m - j.range_before_m)).omega_rad_s for s in (up, down)]
                folds = result.table.fold_omegas_rad_s
                error = max(abs(jumps[0] / folds[0] - 1.0), abs(jumps[1] / folds[1] - 1.0))
                print(
                    f"deck: time-domain stepped-sine up- and down-sweeps {td_s:.2f} s ({up.periods.sum() + down.periods.sum()} periods); "
                    f"jumps at {jumps[0]:.4f} / {jumps[1]:.4f} rad/s; largest fold difference {100 * error:.3f} %"
                )
                figures.update({"td_sweeps_s": round(td_s, 2), "fold_vs_td_max_rel": float(f"{error:.2e}")})
    print(" ".join(f"{k}={v}" for k, v in figures.items()))


def _table_again(result):
    """The sweep's table (stability, moments, linear model, truncation, range) rebuilt for its branch."""
    from seafast.analyses.sweep.frequency import SweepKind, wave_excitation
    from seafast.analyses.sweep.table import sweep_table
    from seafast.solvers.from_case import hbm_options
    from seafast.solvers.hbm import condensed_operators, solve_condensed

    case, model, branch = result.case, result.model, result.branch
    law = hbm_options(case).law
    if result.kind is SweepKind.WAVE:
        excitation_at, rao_at = wave_excitation(case, model, result.omega_start_rad_s, result.omega_end_rad_s)
        options = hbm_options(case, harmonics=0, time_samples=2)
        still = solve_condensed(
            condensed_operators(model, excitation_at(result.omega_start_rad_s).static_part(), 0), options
        ).saddle_compression
        return sweep_table(
            model,
            branch,
            excitation_at,
            law,
            result.table.limits,
            wave_amplitude_m=float(case.wave.amplitude_m),
            rao_at=rao_at,
            still_water_compression_m=still,
        )
    from seafast.excitation.vessel import vessel_excitation

    return sweep_table(model, branch, vessel_excitation(case).cargo_excitation(model, case).at_frequency, law, result.table.limits)


if __name__ == "__main__":
    main()
