"""The compiled frictional step along a record against the periodic frictional march's Python step
(docs/transverse.md#8-friction-at-the-pads).

Run ``python benchmarks/bench_friction_record.py``. The base case in beam seas, ``mu`` = 0.2, a regular wave of
2.8 m at 10 s (the pads slipping part of the period, none lifting), the sliders relaxed in still water, 3800 steps a
period (the Monte Carlo's fine step there, 2.6 ms); one process, one BLAS thread, CPU time: ``march_cradle_friction``
(the Python step) until periodic, then ``march_friction_record`` over the same steps of the tiled stuck periodic
solution from the same start (compiled; warmed first). The last line is ``key=value`` pairs: the cost per step of
each [us], ``speedup`` the Python step's over the compiled one's, the steps, and ``peak_change`` the largest change
of a pad's peak force over the last period between the two [-] (round-off: the same steps).
"""

from __future__ import annotations

import time

import numpy as np

from benchutil import timed
from seafast.parallel.threads import one_blas_thread

N = 3800
"""Steps per wave period (10 s / 2.63 ms)."""


def main() -> None:
    from seafast.analyses.cradle_run import pad_friction_of_case
    from seafast.analyses.seastate.cradle_design_wave import scaled_excitation
    from seafast.analyses.seastate.cradle_transfer import cradle_sea_model, cradle_unit_excitations
    from seafast.analyses.seastate.directional_transfer import sea_state_roll_damping, sea_state_transfer
    from seafast.analyses.seastate.spectrum import sea_state_spectrum
    from seafast.config.loader import load_case
    from seafast.fourier import real_harmonics_to_time
    from seafast.model.from_case import build_model
    from seafast.solvers.cradle_friction import stuck_linear_solution
    from seafast.solvers.cradle_friction_march import FrictionMarchOptions, friction_stepper, march_cradle_friction
    from seafast.solvers.cradle_friction_record import march_friction_record
    from seafast.solvers.cradle_march import STEPS_PER_MODE_PERIOD_INV

    case = load_case(overrides={"sea_state.heading_deg": 90.0, "seafastening.friction_coefficient": 0.2})
    model, spectrum = build_model(case), sea_state_spectrum(case)
    sea = cradle_sea_model(case, model)
    omega = np.array([2.0 * np.pi / 10.0])
    transfer = sea_state_transfer(case, model, omega, sea_state_roll_damping(case, spectrum)).per_direction[0]
    excitation = scaled_excitation(cradle_unit_excitations(sea, transfer)[0], 2.8)
    friction, dynamics, options = pad_friction_of_case(case), sea.dynamics, FrictionMarchOptions(time_samples=N)
    assert friction is not None
    with one_blas_thread():
        run = lambda: march_cradle_friction(dynamics, friction, excitation, options, rest=excitation.still_water())[0]  # noqa: E731
        march, t_python = timed(run, 1, time.process_time)
        tangents = march.tangents
        z_lin, _ = stuck_linear_solution(dynamics, excitation, tangents)
        z_s = real_harmonics_to_time(z_lin, N)
        dt = 2.0 * np.pi / float(excitation.omega_rad_s) / N
        stepper = friction_stepper(dynamics, tangents, dt, STEPS_PER_MODE_PERIOD_INV * 2.0 * np.pi / dt)
        steps, tolerance = march.periods * N, options.step_tolerance * float(np.max(np.abs(z_lin[1:])))
        tiled = lambda first, count: z_s[(first + np.arange(count)) % N]  # noqa: E731
        march_friction_record(stepper, tangents, tiled, 16, tolerance)  # compiles (cached on disk after)
        along = lambda: march_friction_record(stepper, tangents, tiled, steps, tolerance, steps - N)  # noqa: E731
        record, t_compiled = timed(along, 1, time.process_time)
    P = tangents.pad_count
    peaks = tangents.normal_stiffness_N_per_m * np.maximum(march.engagement_m[:, :P], 0.0).max(axis=0)
    change = float(np.max(np.abs(record.max_force_N[:P] - peaks)) / np.max(peaks))
    python_us, compiled_us = 1e3 * t_python / steps, 1e3 * t_compiled / steps
    print(f"{steps} steps: Python step {python_us:.1f} us, compiled {compiled_us:.2f} us a step; peaks within {change:.1e}")
    print(
        f"python_us={python_us:.1f} compiled_us={compiled_us:.2f} speedup={python_us / compiled_us:.1f} steps={steps} "
        f"slipped_fraction={record.slipped_steps / steps:.3f} peak_change={change:.1e}"
    )


if __name__ == "__main__":
    main()
