"""Design waves against the Monte Carlo reference: the table of docs/operability.md.

Run as ``python benchmarks/design_wave_accuracy.py [--store DIR] [--only NAME ...]``. For each sea
state below (22: base case Hs 1-6 m x Tp 6-16 s, uniform soft saddles, soft outer / middle
saddles, four saddles) it runs (or resumes, from ``DIR/NAME``) the nonlinear Monte Carlo reference
(20 realisations of 3 hours, seed 0, the case's default random amplitudes; 10 s to 10 min each on
one core) and prints, per quantity, the Monte Carlo MPM with its 95 % interval and the ratios to
it of:

* ``dw``: the design-wave estimate as seafast computes it (each wave's converged periodic answer);
* ``dw_h16``: the same design waves by harmonic balance at a fixed H = 16 (the faster screening answer);
* ``mler``: the conditioned wave (MLER) over a long base period (H = 16 per wave period);
* ``linear``: the linear spectral MPM.

The last line is ``key=value`` pairs: the largest |ratio - 1| of F and M_b over the sea states for
each method, and how many sea states are within 10 %.
"""

from __future__ import annotations

import argparse
import json
import logging
import sys
import time
from pathlib import Path

import numpy as np

import seafast
from seafast.analyses.seastate.conditioned_wave import conditioned_wave, solve_conditioned_wave
from seafast.analyses.seastate.design_wave import DesignWaveSettings, design_wave_extremes, still_water_excitation
from seafast.analyses.seastate.monte_carlo import run_monte_carlo
from seafast.analyses.seastate.spectral import spectral_analysis
from seafast.analyses.seastate.wave_response import moment_map

SOFT_OUTER = [1.1e8, 1.1e9, 1.1e8]
SEA_STATES: dict[str, dict[str, object]] = {
    "base_hs1_tp8": {"sea_state.significant_height_m": 1.0, "sea_state.peak_period_s": 8.0},
    "base_hs2_tp6": {"sea_state.significant_height_m": 2.0, "sea_state.peak_period_s": 6.0},
    "base_hs2_tp10": {"sea_state.significant_height_m": 2.0, "sea_state.peak_period_s": 10.0},
    "base_hs2_tp16": {"sea_state.significant_height_m": 2.0, "sea_state.peak_period_s": 16.0},
    "base_hs3_tp6": {"sea_state.significant_height_m": 3.0, "sea_state.peak_period_s": 6.0},
    "base_hs3_tp10": {"sea_state.significant_height_m": 3.0, "sea_state.peak_period_s": 10.0},
    "base_hs3_tp14": {"sea_state.significant_height_m": 3.0, "sea_state.peak_period_s": 14.0},
    "base_hs4_tp8": {"sea_state.significant_height_m": 4.0, "sea_state.peak_period_s": 8.0},
    "base_hs4_tp12": {"sea_state.significant_height_m": 4.0, "sea_state.peak_period_s": 12.0},
    "base_hs5_tp10": {"sea_state.significant_height_m": 5.0, "sea_state.peak_period_s": 10.0},
    "base_hs5.5_tp11": {"sea_state.significant_height_m": 5.5, "sea_state.peak_period_s": 11.0},
    "base_hs6_tp10": {"sea_state.significant_height_m": 6.0, "sea_state.peak_period_s": 10.0},
    "base_hs6_tp16": {"sea_state.significant_height_m": 6.0, "sea_state.peak_period_s": 16.0},
    "soft1e8_hs6_tp10": {
        "seafastening.saddle_stiffness_N_per_m": 1.1e8,
        "sea_state.significant_height_m": 6.0,
        "sea_state.peak_period_s": 10.0,
    },
    "soft1e7_hs6_tp10": {
        "seafastening.saddle_stiffness_N_per_m": 1.1e7,
        "sea_state.significant_height_m": 6.0,
        "sea_state.peak_period_s": 10.0,
    },
    "softouter1e8_hs3_tp10": {
        "seafastening.saddle_stiffness_N_per_m": SOFT_OUTER,
        "sea_state.significant_height_m": 3.0,
        "sea_state.peak_period_s": 10.0,
    },
    "softouter1e8_hs5_tp10": {
        "seafastening.saddle_stiffness_N_per_m": SOFT_OUTER,
        "sea_state.significant_height_m": 5.0,
        "sea_state.peak_period_s": 10.0,
    },
    "softouter1e7_hs3_tp10": {
        "seafastening.saddle_stiffness_N_per_m": [1.1e7, 1.1e9, 1.1e7],
        "sea_state.significant_height_m": 3.0,
        "sea_state.peak_period_s": 10.0,
    },
    "softmid1e8_hs5_tp10": {
        "seafastening.saddle_stiffness_N_per_m": [1.1e9, 1.1e8, 1.1e9],
        "sea_state.significant_height_m": 5.0,
        "sea_state.peak_period_s": 10.0,
    },
    "four_hs2_tp10": {"seafastening.saddle_count": 4, "sea_state.significant_height_m": 2.0, "sea_state.peak_period_s": 10.0},
    "four_hs3_tp10": {"seafastening.saddle_count": 4, "sea_state.significant_height_m": 3.0, "sea_state.peak_period_s": 10.0},
    "four_hs5_tp12": {"seafastening.saddle_count": 4, "sea_state.significant_height_m": 5.0, "sea_state.peak_period_s": 12.0},
}
QUANTITIES = ("F_N", "M_b_Nm", "u_d_m")


def _mler(an, static, mm) -> dict[str, tuple[float, bool]]:
    e, tf, sw = an.extremes, an.transfer, an.extremes.still_water
    s = int(np.argmax(sw.saddle_force_N + e.saddle_force.mpm))
    x = int(np.argmax(np.abs(sw.bending_moment_Nm) + e.bending_moment.mpm))
    d = int(np.argmin(sw.saddle_compression_m - e.saddle_compression.mpm))
    out = {}
    for q, transfer, target in (
        ("F_N", tf.saddle_force_N[:, s], e.saddle_force.mpm[s]),
        ("M_b_Nm", tf.bending_moment_Nm[:, x], np.sign(sw.bending_moment_Nm[x]) * e.bending_moment.mpm[x]),
        ("u_d_m", tf.saddle_compression_m[:, d], -e.saddle_compression.mpm[d]),
    ):
        sol = solve_conditioned_wave(an, conditioned_wave(an, static, transfer, float(target)), moments=mm)
        out[q] = (sol.maxima[q], sol.converged)
    return out


def evaluate(name: str, store: Path) -> dict:
    case = seafast.load_case(None, SEA_STATES[name])
    an = spectral_analysis(case)
    static = still_water_excitation(an)
    mm = moment_map(an.model)
    t0 = time.perf_counter()
    mc = run_monte_carlo(case, store / name, workers=1, progress=False).nonlinear
    mc_s = time.perf_counter() - t0
    t0 = time.perf_counter()
    dw = design_wave_extremes(an, static, DesignWaveSettings(), moments=mm)
    dw_ms = 1e3 * (time.perf_counter() - t0)
    t0 = time.perf_counter()
    dwa = design_wave_extremes(an, static, DesignWaveSettings(harmonics=16), moments=mm)
    dwa_ms = 1e3 * (time.perf_counter() - t0)
    t0 = time.perf_counter()
    ml = _mler(an, static, mm)
    ml_ms = 1e3 * (time.perf_counter() - t0)
    return {
        "name": name,
        "uplift_per_hour": an.extremes.totals["uplift_per_hour"],
        "mc": {q: mc.mpm[q] for q in QUANTITIES},
        "mc_interval": {q: list(mc.mpm_interval[q]) for q in QUANTITIES},
        "mc_uplift_per_hour": mc.uplift_per_hour,
        "dw": {q: dw.totals[q] for q in QUANTITIES},
        "dw_h16": {q: dwa.totals[q] for q in QUANTITIES},
        "mler": {q: ml[q][0] for q in QUANTITIES},
        "linear": {q: an.extremes.totals[q] for q in QUANTITIES},
        "converged": {"dw": dw.converged, "dw_h16": dwa.converged, "mler": all(v[1] for v in ml.values()), "mc": mc.converged},
        "ms": {"dw": dw_ms, "dw_h16": dwa_ms, "mler": ml_ms, "mc_s": mc_s},
    }


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--store", default="design-wave-accuracy", help="directory of the resumable Monte Carlo stores")
    parser.add_argument("--only", nargs="*", default=None, help="sea-state names (default: all)")
    args = parser.parse_args(argv)
    logging.getLogger("seafast").setLevel(logging.ERROR)  # the solvers' notes are not the table
    store = Path(args.store)
    names = args.only or list(SEA_STATES)
    results = [evaluate(n, store) for n in names]
    (store / "design_wave_accuracy.json").write_text(json.dumps(results, indent=1))
    print(
        "| sea state | uplift/h | F MC [MN] (95 %) | dw | dw H = 16 | MLER | linear "
        "| M_b MC [MN m] (95 %) | dw | dw H = 16 | MLER | linear | u_d MC [mm] (95 %) | u_d dw |"
    )
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    worst = dict.fromkeys(("dw", "dw_h16", "mler", "linear"), 0.0)
    within = dict.fromkeys(worst, 0)
    for r in results:
        cells = [r["name"], f"{r['uplift_per_hour']:.1f}"]
        ok = dict.fromkeys(worst, True)
        for q, scale in (("F_N", 1e-6), ("M_b_Nm", 1e-6)):
            lo, hi = r["mc_interval"][q]
            cells.append(f"{r['mc'][q] * scale:.2f} ({lo * scale:.2f}-{hi * scale:.2f})")
            for m in worst:
                ratio = r[m][q] / r["mc"][q]
                worst[m] = max(worst[m], abs(ratio - 1.0))
                ok[m] &= abs(ratio - 1.0) <= 0.10
                cells.append(f"{ratio:.3f}" + ("" if m == "linear" or r["converged"][m] else " (NC)"))
        lo, hi = r["mc_interval"]["u_d_m"]
        cells += [f"{r['mc']['u_d_m'] * 1e3:.2f} ({lo * 1e3:.2f}-{hi * 1e3:.2f})", f"{r['dw']['u_d_m'] * 1e3:.2f}"]
        for m in worst:
            within[m] += int(ok[m])
        print("| " + " | ".join(cells) + " |")
        sys.stdout.flush()
    cost = {m: float(np.median([r["ms"][m] for r in results])) for m in ("dw", "dw_h16", "mler")}
    print(f"median cost: dw {cost['dw']:.0f} ms, dw H = 16 {cost['dw_h16']:.0f} ms, MLER {cost['mler']:.0f} ms")
    print(
        " ".join(f"worst_{m}={worst[m]:.4f}" for m in worst)
        + " "
        + " ".join(f"within10_{m}={within[m]}" for m in within)
        + f" sea_states={len(results)}"
    )


if __name__ == "__main__":
    main()
