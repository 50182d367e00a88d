"""Vessel side and hull-cargo coupling: hull-girder solves, BEM, and one-way vs two-way runs.

Run ``python benchmarks/bench_vessel.py`` (add ``--no-bem`` to skip the ~15 s BEM run; ``--headings`` also times
the six-DOF run over headings, docs/headings.md). The BEM is timed on the production mesh with an empty temporary
cache, as a first run on a new hull would be (target: under a minute). Prints the figures; the last line is
``key=value`` pairs (docs/interface.md).
"""

from __future__ import annotations

import argparse
import math
import os
import tempfile
import time

import numpy as np

from benchutil import timed
from seafast.parallel.threads import one_blas_thread


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--no-bem", action="store_true", help="skip the BEM run")
    parser.add_argument("--headings", action="store_true", help="also time the six-DOF BEM over headings (against the head-sea run)")
    args = parser.parse_args()

    from seafast.analyses.run import run_case
    from seafast.config import load_case
    from seafast.coupling.deck_loads import hull_compliance
    from seafast.coupling.hull import coupled_hull
    from seafast.excitation.vessel import VesselCache, vessel_excitation
    from seafast.excitation.vessel_inputs import hull_form_of, rigid_body_motions, six_dof_motions_of
    from seafast.hull.still_water import still_water_response
    from seafast.hull.wave import wave_response
    from seafast.model.from_case import build_model

    one_way = load_case()
    two_way = load_case(overrides={"vessel.coupling": "two_way"})
    model = build_model(one_way)
    vessels = VesselCache()  # what a study keeps for its points
    vessel = vessel_excitation(one_way, vessels)  # BEM from the disk cache (computed on first use)
    with one_blas_thread(), vessels.shared():
        _, t_still = timed(lambda: still_water_response(vessel.girder, vessel.loading), 20)
        _, t_wave = timed(lambda: wave_response(vessel.girder, vessel.loading, 171.0, 3.0), 5)
        _, t_comp = timed(lambda: hull_compliance(vessel.girder, vessel.loading, model, vessel.cargo_aft_end_x_m, 4), 10)
        run_case(one_way), run_case(two_way)  # warm
        r1, t_one = timed(lambda: run_case(one_way), 5)
        r2, t_two = timed(lambda: run_case(two_way), 5)
    print(f"still-water hull girder (343 nodes, balance + Timoshenko beam)      median {t_still:8.2f} ms")
    print(f"quasi-static wave response (64 crest positions, vectorised)          median {t_wave:8.2f} ms")
    print(
        f"hull compliance at the saddles for loads on all {model.cargo.node_count} cargo nodes      median {t_comp:8.2f} ms "
        f"({t_comp / t_still:.1f}x one still-water solve)"
    )
    print(f"base case run_case, one-way (4 solves; vessel from the in-memory cache) median {t_one:8.2f} ms")
    print(f"base case run_case, two-way (4 rows coupled)                          median {t_two:8.2f} ms ({t_two / t_one:.1f}x one-way)")
    for status in r2.coupling.values():
        print(f"  {status.message}")
    v2 = r2.vessel
    with one_blas_thread():
        hull, t_hull = timed(
            lambda: coupled_hull(
                v2.girder,
                v2.loading,
                r2.compliance,
                v2.still_water,
                r2.deck_couplings[("static", "nonlinear")],
                v2.wave,
                r2.deck_couplings[("dynamic", "nonlinear")],
            ),
            10,
        )
    mid = int(np.argmin(np.abs(hull.x_m - v2.girder.midship_x_m)))
    print(
        f"coupled hull girder (still water + wave, the lines along the ship)   median {t_hull:8.2f} ms "
        f"({t_hull / t_two:.2f}x a two-way run_case; computed when the dataset is built)"
    )
    print(
        f"  midship still water: moment {v2.still_water.bending_moment_Nm[mid] / 1e6:.1f} -> "
        f"{hull.still_water_bending_moment_Nm[mid] / 1e6:.1f} MN m, deflection {1e3 * v2.still_water.deflection_m[mid]:.1f} -> "
        f"{1e3 * hull.still_water_deflection_m[mid]:.1f} mm (one-way -> two-way)"
    )
    f1 = {(r["load_case"], r["model"]): r["F_N"] for r in r1.summary}
    f2 = {(r["load_case"], r["model"]): r["F_N"] for r in r2.summary}
    for key in f1:
        print(
            f"  peak saddle force {key[0]:7s} {key[1]:9s}: one-way {f1[key] / 1e6:7.3f} MN, two-way {f2[key] / 1e6:7.3f} MN "
            f"({f2[key] / f1[key] - 1.0:+.1%})"
        )

    t_bem = t_headings = math.nan
    if not args.no_bem:
        hull = hull_form_of(one_way)
        previous = os.environ.get("SEAFAST_CACHE_DIR")
        with tempfile.TemporaryDirectory() as cache:  # the BEM takes every core itself
            os.environ["SEAFAST_CACHE_DIR"] = cache  # an empty cache: a first run on a new hull
            try:
                t0 = time.perf_counter()
                m = rigid_body_motions(one_way, hull, vessel.loading)
                t_bem = time.perf_counter() - t0
                if args.headings:
                    beam = load_case(overrides={"wave.heading_deg": 90.0})
                    t0 = time.perf_counter()
                    six_dof_motions_of(beam, hull, vessel.loading)
                    t_headings = time.perf_counter() - t0
            finally:
                if previous is None:
                    os.environ.pop("SEAFAST_CACHE_DIR", None)
                else:
                    os.environ["SEAFAST_CACHE_DIR"] = previous
        heave, pitch = m.rao_at(vessel.omega_rad_s)
        print(
            f"BEM (capytaine, {np.asarray(m.omega_rad_s).size} frequencies, empty cache) {t_bem:6.1f} s "
            f"(target 60 s: {60.0 / t_bem:.1f}x margin); RAOs at {vessel.omega_rad_s:.3f} rad/s: "
            f"heave {abs(heave):.3f} m/m, pitch {np.degrees(abs(pitch)):.3f} deg/m"
        )
    print(
        f"still_water_ms={t_still:.3g} wave_ms={t_wave:.3g} compliance_ms={t_comp:.3g} run_one_way_ms={t_one:.3g} "
        f"run_two_way_ms={t_two:.3g} two_way_vs_one_way={t_two / t_one:.2f} coupled_hull_ms={t_hull:.3g} bem_s={t_bem:.3g} "
        f"bem_headings_s={t_headings:.3g} headings_vs_head_seas={t_headings / t_bem:.2f}"
    )


if __name__ == "__main__":
    main()
