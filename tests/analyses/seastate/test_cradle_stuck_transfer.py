"""The stuck linear transfer functions of the cargo on frictional pads in a sea state, marched along a regular wave's
record at the Monte Carlo's fine step, against the periodic frictional march after the transient.
docs/transverse.md#8-friction-at-the-pads."""

from __future__ import annotations

import numpy as np
import pytest

from seafast.analyses.cradle_run import pad_friction_of_case
from seafast.analyses.seastate.cradle_design_wave import scaled_excitation
from seafast.analyses.seastate.cradle_stuck_transfer import stuck_transfer_functions
from seafast.analyses.seastate.cradle_transfer import cradle_sea_model, cradle_unit_excitations
from seafast.analyses.seastate.directional_transfer import sea_state_roll_damping, sea_state_transfer
from seafast.analyses.seastate.spectrum import sea_state_spectrum
from seafast.config.loader import load_case
from seafast.model.from_case import build_model
from seafast.solvers.cradle_friction import relaxed_at
from seafast.solvers.cradle_friction_march import FrictionMarchOptions, friction_stepper, march_cradle_friction
from seafast.solvers.cradle_friction_record import march_friction_record
from seafast.solvers.cradle_march import STEPS_PER_MODE_PERIOD_INV, Periodicity
from seafast.solvers.pad_tangential import pad_tangents

PERIOD_S, AMPLITUDE_M = 10.0, 2.8
"""A beam-sea wave on the base case with mu = 0.2 where every pad slips part of the period (none lifts)."""
DT_S = 0.05 / 19
"""The base case's Monte Carlo fine step at Hs 3 m, Tp 10 s, 90 deg (not a divisor of the period)."""


@pytest.fixture(scope="module")
def regular():
    case = load_case(overrides={"sea_state.heading_deg": 90.0, "seafastening.friction_coefficient": 0.2})
    model, spectrum = build_model(case), sea_state_spectrum(case)
    sea = cradle_sea_model(case, model)
    omega = np.array([2.0 * np.pi / PERIOD_S])
    tf = sea_state_transfer(case, model, omega, sea_state_roll_damping(case, spectrum)).per_direction[0]
    unit = cradle_unit_excitations(sea, tf)[0]
    friction = pad_friction_of_case(case)
    assert friction is not None
    dynamics = sea.dynamics
    at_rest = pad_tangents(dynamics.problem, friction, dynamics.deck_x_m, dynamics.gravity_m_per_s2)
    tangents = relaxed_at(at_rest, dynamics, unit.still_water())
    stuck = stuck_transfer_functions(sea, tf, tangents)
    excitation = scaled_excitation(unit, AMPLITUDE_M)
    march, _ = march_cradle_friction(dynamics, friction, excitation, FrictionMarchOptions(), rest=excitation.still_water())
    return dynamics, tangents, stuck, march


def test_a_regular_wave_marched_along_its_record_gives_the_periodic_march_after_the_transient(regular):
    dynamics, tangents, stuck, march = regular
    assert march.periodicity is Periodicity.PERIODIC
    omega = float(stuck.omega_rad_s[0])
    X = AMPLITUDE_M * stuck.transfer_m[0]

    def linear_at(first: int, count: int) -> np.ndarray:
        t = (first + np.arange(count)) * DT_S
        return stuck.still_m + np.real(X[None] * np.exp(1j * omega * t)[:, None])

    stepper = friction_stepper(dynamics, tangents, DT_S, STEPS_PER_MODE_PERIOD_INV * 2.0 * np.pi / DT_S)
    steps = round(30 * PERIOD_S / DT_S)
    last = steps - int(np.ceil(PERIOD_S / DT_S)) - 1
    record = march_friction_record(stepper, tangents, linear_at, steps, 1e-11 * float(np.max(np.abs(X))), last, stuck.lateral_dofs)
    assert record.solved and record.slipped_steps > 0
    P = tangents.pad_count
    force = tangents.normal_stiffness_N_per_m * np.maximum(march.engagement_m[:, :P], 0.0)
    largest = float(np.max(force))
    # within 0.5 % of the largest pad force, slip and lateral displacement (measured 2.0e-4 on the pads' peaks, 2.9e-5
    # on the least, 7.0e-4 on the slips, 1.4e-4 lateral, 4.9e-5 on the utilisations: the record's 2.63 ms steps are not
    # the periodic march's 2048 a period)
    np.testing.assert_allclose(record.max_force_N[:P], force.max(axis=0), atol=5e-3 * largest)
    np.testing.assert_allclose(record.min_force_N[:P], force.min(axis=0), atol=5e-3 * largest)
    slip = np.hypot(*np.moveaxis(march.slider_m - tangents.rest_m, -1, 0)).max(axis=0)
    np.testing.assert_allclose(record.max_slip_m, slip, atol=5e-3 * np.max(slip))
    limit = tangents.friction_coefficient * force
    friction = np.hypot(march.friction_force_N[..., 0], march.friction_force_N[..., 1])
    utilisation = np.divide(friction, limit, out=np.zeros_like(limit), where=limit > 0.0).max(axis=0)
    np.testing.assert_allclose(record.friction_utilisation, utilisation, atol=5e-3)
    lateral = np.max(np.abs(march.cargo_displacement_m[:, stuck.lateral_dofs]), axis=0)
    np.testing.assert_allclose(record.max_abs_output, lateral, atol=5e-3 * np.max(lateral))
    assert np.all(record.negative_fraction[:P] == 0.0) and np.max(slip) > 0.0
