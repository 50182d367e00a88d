"""The time march on frictional pads against the harmonic balance that fails before it (docs/transverse.md#8-friction-at-the-pads).

Run ``python benchmarks/bench_cradle_friction_march.py``. The base case in beam seas on 20 deg pads, ``mu`` = 0.05,
a pure roll of 26 deg at 0.6 rad/s (every pad lifting a quarter of the period, the cargo sliding 78 mm round its
cradles; ``tests/analyses/test_cradle_run_friction.py``'s case), the sliders relaxed in still water; one process, one
BLAS thread, CPU time: the frictional harmonic balance alone (H = 8, N = 64: it does not converge) and
``solve_cradle_friction`` (the same harmonic balance, then the march at 2048 and 4096 steps a period). The last line
is ``key=value`` pairs: ``march_vs_hbm`` the dispatcher's time over the failed harmonic balance's, its outcome, step
error and the largest pad force [MN] and slip [mm].
"""

from __future__ import annotations

import time
from dataclasses import replace

import numpy as np

from benchutil import timed
from seafast.parallel.threads import one_blas_thread


def main() -> None:
    from seafast.analyses.cradle_run import cradle_dynamics_of_case
    from seafast.analyses.run import run_case
    from seafast.config.loader import load_case
    from seafast.excitation.cradle_loads import cradle_excitation
    from seafast.model.cradle_case import build_cradle_case
    from seafast.model.pad_friction import PadFriction
    from seafast.solvers.cradle_friction import FrictionHBMOptions, solve_cradle_friction_hbm
    from seafast.solvers.cradle_friction_solve import solve_cradle_friction

    overrides = {"wave.heading_deg": 90.0, "solver.harmonics": 8, "solver.time_samples": 64, "seafastening.saddle_contact_angle_deg": 20.0}
    base = run_case(load_case(overrides=overrides))
    cradle = build_cradle_case(base.case, base.model)
    dynamics = cradle_dynamics_of_case(cradle)
    zero = 0.0 * base.excitation.cargo_load_N
    vertical = replace(base.excitation, omega_rad_s=0.6, cargo_load_N=zero, deck_displacement=0.0 * base.excitation.deck_displacement)
    motions = np.array([0, 0, 0, np.deg2rad(26.0), 0, 0], dtype=complex)
    excitation = cradle_excitation(cradle.cargo, vertical, motions, base.model.saddle_x_m, (0.0, 0.0, 0.0))
    friction, options, still = PadFriction(0.05), FrictionHBMOptions(8, 64), excitation.still_water()
    with one_blas_thread():
        hbm, t0 = timed(lambda: solve_cradle_friction_hbm(dynamics, friction, excitation, options, rest=still), 1, time.process_time)
        solved, t1 = timed(lambda: solve_cradle_friction(dynamics, friction, excitation, options, rest=still), 1, time.process_time)
    F, slip = float(np.max(solved.normal_force_N)) * 1e-6, float(np.max(solved.max_slip_m)) * 1e3
    outcome = solved.cradle.outcome.value
    print(f"harmonic balance: {t0:.0f} ms CPU ({hbm.cradle.outcome.value}); with the march: {t1:.0f} ms CPU ({outcome})")
    print(
        f"hbm_ms={t0:.0f} dispatch_ms={t1:.0f} march_vs_hbm={t1 / t0:.2f} outcome={outcome} "
        f"step_error={solved.cradle.residual:.1e} F_pad_MN={F:.3f} slip_mm={slip:.1f}"
    )


if __name__ == "__main__":
    main()
