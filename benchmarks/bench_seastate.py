"""Sea-state benchmark: linear spectral extremes of one sea state, and one 3-hour nonlinear realisation.

Run as ``python benchmarks/bench_seastate.py`` (the BEM must be in the disk cache: any earlier
``seafast run`` puts it there). Figures, all in one process:

* ``spectral_s``: ``spectral_analysis`` of the base case in Hs = 3 m, Tp = 10 s from a fresh
  vessel (hull girder balanced, BEM read from the disk cache, 256 frequencies), target <= 0.5 s;
* ``spectral_warm_s``: the same once the vessel is in memory (the cost per extra sea state);
* ``tf_speedup_vs_dense``: transfer functions (hull + cargo) against the same hull and one dense
  assembly and dense LU (``solve_harmonic``) per frequency for the cargo, same numbers;
* ``hull_speedup_vs_64_crests``: hull transfer functions from two real load cases per
  frequency against ``wave_response`` at 64 crest positions per frequency;
* ``realisation_3h_s``: one 3-hour nonlinear realisation on one core (the Monte Carlo engine's
  ``benchmark_realisation()``), target <= 60 s; ``nan`` until the engine exists.

The last line is ``key=value`` pairs.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

import seafast
from benchutil import timed
from seafast.analyses.seastate.spectral import spectral_analysis
from seafast.analyses.seastate.transfer import transfer_functions
from seafast.excitation.deck_motion import RigidBodyAmplitudes, assemble_excitation
from seafast.excitation.vessel import vessel_excitation
from seafast.hull.deck import deck_harmonics_at
from seafast.hull.transfer import wave_transfer_functions
from seafast.hull.wave import wave_response
from seafast.model.from_case import build_model
from seafast.solvers.linear import solve_harmonic


def _dense_cargo_loop(case, model, tf):
    """The straightforward cargo part: one assembly and one dense LU (``solve_harmonic``) per frequency."""
    aft = vessel_excitation(case).cargo_aft_end_x_m
    out = []
    for i, w in enumerate(tf.omega_rad_s):
        exc = assemble_excitation(
            model,
            aft,
            float(w),
            None,
            lambda _x, i=i: (tf.deck_displacement[i, 0::2], tf.deck_displacement[i, 1::2]),
            RigidBodyAmplitudes(complex(tf.heave_m[i]), complex(tf.pitch_rad[i]), tf.pitch_reference_x_m),
        )
        out.append(solve_harmonic(model, float(w), exc.cargo_load_N[1], exc.deck_displacement[1]))
    return np.array(out)


def main() -> None:
    base = seafast.load_case(None)
    vessel_excitation(base)  # the BEM into the disk cache (first run only)
    counter = iter(range(10_000))

    def fresh() -> object:
        # a wave amplitude never used before: the in-process vessel memo misses, the disk BEM cache hits
        case = seafast.load_case(None, {"wave.amplitude_m": 3.0 + 1e-9 * next(counter)})
        return spectral_analysis(case)

    analysis, cold_ms = timed(fresh, 5)
    _, warm_ms = timed(lambda: spectral_analysis(base), 5)
    e = analysis.extremes.totals
    print(f"linear spectral extremes, base case, Hs = 3 m, Tp = 10 s, {analysis.spectrum.omega_rad_s.size} frequencies:")
    print(f"  fresh vessel (BEM from disk cache): {cold_ms:.0f} ms   vessel in memory: {warm_ms:.0f} ms")
    print(
        f"  F = {e['F_N'] / 1e6:.2f} MN, M_b = {e['M_b_Nm'] / 1e6:.1f} MN m, sigma_b = {e['sigma_b_Pa'] / 1e6:.1f} MPa, "
        f"u_s = {e['u_s_m'] * 1e3:.2f} mm, uplift {e['uplift_per_hour']:.2f} per hour"
    )

    model = build_model(base)
    omega = analysis.spectrum.omega_rad_s
    v = vessel_excitation(base)
    tf, tf_ms = timed(lambda: transfer_functions(base, model, omega), 5)
    _, hull_all_ms = timed(lambda: wave_transfer_functions(v.girder, v.loading, omega), 5)
    dense, loop_ms = timed(lambda: _dense_cargo_loop(base, model, tf), 2)
    dense_ms = hull_all_ms + loop_ms
    diff = float(np.max(np.abs(dense - tf.cargo_displacement)) / np.max(np.abs(dense)))
    print(
        f"transfer functions at {omega.size} frequencies: {tf_ms:.0f} ms (hull {hull_all_ms:.0f} ms); with one assembly and a "
        f"dense LU per frequency {dense_ms:.0f} ms (max rel. difference {diff:.1e})"
    )

    subset = omega[::8]
    hull_tf, hull_ms = timed(lambda: wave_transfer_functions(v.girder, v.loading, subset), 5)
    x = v.cargo_aft_end_x_m + model.saddle_x_m

    def crests() -> np.ndarray:
        return np.array([deck_harmonics_at(wave_response(v.girder, v.loading, 2 * math.pi * 9.81 / w**2, 1.0), x)[0][1] for w in subset])

    z64, crest_ms = timed(crests, 2)
    hdiff = float(np.max(np.abs(z64 - hull_tf.deck_at(x)[0])) / np.max(np.abs(z64)))
    print(
        f"hull transfer functions at {subset.size} frequencies: two load cases {hull_ms:.1f} ms, 64 crest positions "
        f"{crest_ms:.0f} ms (max rel. difference {hdiff:.1e})"
    )

    realisation = float("nan")
    try:
        from seafast.analyses.seastate.monte_carlo import benchmark_realisation
    except ImportError:
        print("one 3-hour nonlinear realisation: the Monte Carlo engine is not in this version")
    else:
        realisation = float(benchmark_realisation())
        print(f"one 3-hour nonlinear realisation on one core: {realisation:.1f} s")
    print(
        f"spectral_s={cold_ms / 1e3:.3f} spectral_warm_s={warm_ms / 1e3:.3f} tf_speedup_vs_dense={dense_ms / tf_ms:.1f} "
        f"hull_speedup_vs_64_crests={crest_ms / hull_ms * 1.0:.1f} realisation_3h_s={realisation:.2f}"
    )


if __name__ == "__main__":
    main()
