"""The frictional correction marched along a record (the compiled step) against the periodic frictional march's
Python step, where pads lift and slip. docs/transverse.md#8-friction-at-the-pads."""

from __future__ import annotations

import numpy as np
import pytest

from seafast.fourier import harmonics_to_time, real_harmonics_to_time
from seafast.model.pad_friction import PadFriction
from seafast.solvers.cradle_friction import stuck_linear_solution
from seafast.solvers.cradle_friction_march import FrictionMarchOptions, friction_stepper, march_cradle_friction
from seafast.solvers.cradle_friction_record import march_friction_record
from seafast.solvers.cradle_march import STEPS_PER_MODE_PERIOD_INV, Periodicity
from test_cradle_friction import tube_dynamics, tube_excitation
from test_cradle_friction_march import LIFT_ROLL, _motions

N = 512
"""Steps per wave period of both marches."""


@pytest.fixture(scope="module")
def periodic_and_record():
    """The periodic march and the record march over the same periods of the tiled stuck linear solution, from rest."""
    dynamics = tube_dynamics()
    excitation = tube_excitation(dynamics.problem.cargo, _motions(LIFT_ROLL))
    options = FrictionMarchOptions(time_samples=N)
    march, _ = march_cradle_friction(dynamics, PadFriction(0.1), excitation, options)
    tangents = march.tangents
    z_lin, X_stuck = stuck_linear_solution(dynamics, excitation, tangents)
    z_s = np.hstack([real_harmonics_to_time(z_lin, N), harmonics_to_time(X_stuck, N)])  # then every cargo DOF
    dt = 2.0 * np.pi / float(excitation.omega_rad_s) / N
    stepper = friction_stepper(dynamics, tangents, dt, STEPS_PER_MODE_PERIOD_INV * 2.0 * np.pi / dt)
    scale = float(np.max(np.abs(z_lin[1:])))
    steps = march.periods * N
    tiled = lambda first, count: z_s[(first + np.arange(count)) % N]  # noqa: E731
    outputs = np.arange(X_stuck.shape[1])
    record = march_friction_record(stepper, tangents, tiled, steps, options.step_tolerance * scale, steps - N, outputs)
    return march, record


def test_the_compiled_record_march_repeats_the_periodic_march_step_for_step(periodic_and_record):
    march, record = periodic_and_record
    assert march.periodicity is Periodicity.PERIODIC and march.unresolved_steps == 0 and record.solved
    tangents = march.tangents
    P, k = tangents.pad_count, tangents.normal_stiffness_N_per_m
    s = march.engagement_m
    # the same steps from the same start: the last period's maxima to round-off
    force = k * np.maximum(s[:, :P], 0.0)
    np.testing.assert_allclose(record.max_force_N[:P], force.max(axis=0), rtol=1e-9, atol=1e-9 * force.max())
    np.testing.assert_allclose(record.min_force_N[:P], force.min(axis=0), rtol=1e-9, atol=1e-9 * force.max())
    limit = tangents.friction_coefficient * force
    friction = np.hypot(march.friction_force_N[..., 0], march.friction_force_N[..., 1])
    utilisation = np.divide(friction, limit, out=np.zeros_like(limit), where=limit > 0.0).max(axis=0)
    np.testing.assert_allclose(record.friction_utilisation, utilisation, rtol=1e-9)
    slip = np.hypot(*np.moveaxis(march.slider_m - tangents.rest_m, -1, 0)).max(axis=0)
    np.testing.assert_allclose(record.max_slip_m, slip, rtol=1e-8, atol=1e-12)
    cargo = np.max(np.abs(march.cargo_displacement_m), axis=0)
    np.testing.assert_allclose(record.max_abs_output, cargo, rtol=1e-9, atol=1e-9 * np.max(cargo))
    np.testing.assert_array_equal(record.negative_fraction, np.mean(s < 0.0, axis=0))
    # the case is the one meant: a pad lifts, every pad slips and the friction reaches its cone
    assert 0.1 < np.max(record.negative_fraction[:P]) < 0.3 and np.all(record.max_slip_m > 0.0)
    assert record.slipped_steps > 0 and np.isclose(np.max(record.friction_utilisation), 1.0, atol=1e-9)


def test_the_record_march_names_bad_step_counts(periodic_and_record):
    march, _ = periodic_and_record
    with pytest.raises(ValueError, match="measured_from"):
        march_friction_record(None, march.tangents, lambda first, count: np.zeros((count, 1)), 10, 1e-9, 10)  # type: ignore[arg-type]
