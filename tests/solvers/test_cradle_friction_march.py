"""The cargo on frictional pads marched in time, and the dispatcher that falls back on it where the harmonic balance
does not converge: against the time domain where pads lift and slip. docs/transverse.md#8-friction-at-the-pads."""

from __future__ import annotations

import numpy as np
import pytest

from seafast.model.pad_friction import PadFriction
from seafast.solvers.cradle_friction import FrictionHBMOptions, solve_cradle_friction_hbm
from seafast.solvers.cradle_friction_march import FrictionMarchOptions, march_cradle_friction
from seafast.solvers.cradle_friction_solve import STEP_TOLERANCE, solve_cradle_friction
from seafast.solvers.cradle_march import Periodicity, march_cradle
from seafast.solvers.outcome import SolverOutcome
from seafast.solvers.references.cradle_friction_time_domain import FrictionTimeDomainOptions, solve_cradle_friction_time_domain
from test_cradle_friction import MOTIONS, tube_dynamics, tube_excitation

LIFT_ROLL = 0.49
"""The roll [rad] at which the forward cradle's high-side pad opens 19 % of the period (0.46: none opens) on mu = 0.1."""


def _motions(roll: float) -> np.ndarray:
    motions = MOTIONS.copy()
    motions[3] = roll
    return motions


def _peaks(force: np.ndarray, friction: np.ndarray, slip: np.ndarray) -> dict[str, np.ndarray]:
    """Per pad: peak and least normal force, peak friction force, largest slip from rest, slip range per direction."""
    return {
        "max": force.max(axis=0),
        "min": force.min(axis=0),
        "friction": np.hypot(friction[..., 0], friction[..., 1]).max(axis=0),
        "slip": np.hypot(slip[..., 0], slip[..., 1]).max(axis=0),
        "range": np.ptp(slip, axis=0),
    }


def _march_peaks(march, stride: int = 1) -> dict[str, np.ndarray]:
    P = march.tangents.pad_count
    k = march.tangents.normal_stiffness_N_per_m
    force = k * np.maximum(march.engagement_m[::stride, :P], 0.0)
    return _peaks(force, march.friction_force_N[::stride], (march.slider_m - march.tangents.rest_m)[::stride])


@pytest.fixture(scope="module")
def lifting():
    dynamics = tube_dynamics()
    excitation = tube_excitation(dynamics.problem.cargo, _motions(LIFT_ROLL))
    return dynamics, excitation


@pytest.mark.slow
def test_the_march_matches_the_time_domain_where_pads_lift_and_slip(lifting):
    dynamics, excitation = lifting
    friction = PadFriction(0.1)
    march, _ = march_cradle_friction(dynamics, friction, excitation, FrictionMarchOptions(time_samples=2048))
    options = FrictionTimeDomainOptions(time_samples=512, relaxation_fraction=1e-6, relative_tolerance=1e-8, max_periods=8)
    reference = solve_cradle_friction_time_domain(dynamics, friction, excitation, options)
    assert march.periodicity is Periodicity.PERIODIC and march.unresolved_steps == 0
    assert reference.cradle.outcome is SolverOutcome.CONVERGED, reference.cradle.message
    P = march.tangents.pad_count
    # the forward cradle's high-side pad lifts 10-30 % of the period, and every pad slips part of it, in both
    for s in (march.engagement_m[:, :P], reference.cradle.engagement_m[:, :P]):
        assert 0.1 < np.mean(s[:, 2] < 0.0) < 0.3 and np.all(np.mean(s[:, [0, 1, 3]] < 0.0, axis=0) == 0.0)
    assert np.all(np.mean(march.slipped, axis=0) > 0.1)
    assert np.all(np.mean(reference.friction_utilisation > 0.999, axis=0) > 0.1)
    ours = _march_peaks(march, stride=4)  # on the reference's samples
    theirs = _peaks(reference.normal_force_N, reference.friction_force_N, reference.slip_m)
    pad = np.max(theirs["max"])
    # forces within 0.5 % of the largest pad force (measured 9e-5 peaks, 1.1e-4 least, 8.5e-5 friction); slips within
    # 1 % of the largest (measured 1.7e-3 largest slip, 1.1e-3 range: the slips' onsets between the steps)
    np.testing.assert_allclose(ours["max"], theirs["max"], atol=5e-3 * pad)
    np.testing.assert_allclose(ours["min"], theirs["min"], atol=5e-3 * pad)
    np.testing.assert_allclose(ours["friction"], theirs["friction"], atol=5e-4 * pad)
    np.testing.assert_allclose(ours["slip"], theirs["slip"], atol=1e-2 * np.max(theirs["slip"]))
    np.testing.assert_allclose(ours["range"], theirs["range"], atol=1e-2 * np.max(theirs["range"]))


def test_the_friction_stays_on_its_cone_and_open_pads_carry_none(lifting):
    dynamics, excitation = lifting
    march, _ = march_cradle_friction(dynamics, PadFriction(0.1), excitation, FrictionMarchOptions(time_samples=512))
    P = march.tangents.pad_count
    normal = march.tangents.normal_stiffness_N_per_m * np.maximum(march.engagement_m[:, :P], 0.0)
    magnitude = np.hypot(march.friction_force_N[..., 0], march.friction_force_N[..., 1])
    assert np.all(magnitude <= 0.1 * normal * (1.0 + 1e-9) + 1e-9 * np.max(normal))
    assert np.all(magnitude[normal == 0.0] <= 1e-9 * np.max(normal)) and np.any(normal == 0.0)
    np.testing.assert_allclose(magnitude[march.slipped], 0.1 * normal[march.slipped], rtol=1e-9)


@pytest.mark.slow
def test_without_friction_the_march_is_the_frictionless_march_where_pads_lift():
    """mu = 0: the sliders follow the pads, the stuck springs' corrections cancel them, and with every mode kept the
    march is the frictionless one's (the same Newmark steps in other coordinates) where pads lift off."""
    dynamics = tube_dynamics()
    excitation = tube_excitation(dynamics.problem.cargo, _motions(0.42))
    march, _ = march_cradle_friction(dynamics, PadFriction(0.0), excitation, FrictionMarchOptions(time_samples=1024, cutoff_rad_s=1e6))
    frictionless = march_cradle(dynamics, excitation, 1024, cutoff_rad_s=1e6)
    assert march.periodicity is frictionless.periodicity is Periodicity.PERIODIC
    force = dynamics.problem.element_stiffness_N_per_m * np.maximum(march.engagement_m, 0.0)
    assert np.mean(force[:, 2] == 0.0) > 0.1  # pads lift off
    np.testing.assert_allclose(force, frictionless.element_force_N, atol=1e-5 * np.max(force))
    assert np.max(np.abs(march.friction_force_N)) == 0.0


@pytest.mark.slow
def test_where_pads_stick_and_slip_without_lifting_the_march_is_the_harmonic_balance():
    dynamics = tube_dynamics()
    excitation = tube_excitation(dynamics.problem.cargo)
    friction = PadFriction(0.1)
    hbm = solve_cradle_friction_hbm(dynamics, friction, excitation, FrictionHBMOptions(harmonics=32, time_samples=256))
    march, _ = march_cradle_friction(dynamics, friction, excitation, FrictionMarchOptions(time_samples=1024))
    assert hbm.converged and march.periodicity is Periodicity.PERIODIC
    ours = _march_peaks(march, stride=4)
    theirs = _peaks(hbm.normal_force_N, hbm.friction_force_N, hbm.slip_m)
    assert np.all(theirs["min"] > 0.0) and np.all(np.mean(march.slipped, axis=0) > 0.1)
    pad = np.max(theirs["max"])
    # measured: peaks 5e-4, least 1.6e-4, friction 5e-5 of the largest pad force; largest slips 0.6 % and ranges 0.5 %
    # of the largest: the harmonic balance's own error (it is 0.5 % from the time domain, the march at N = 2048 2e-4)
    for key in ("max", "min", "friction"):
        np.testing.assert_allclose(ours[key], theirs[key], atol=5e-3 * pad)
    np.testing.assert_allclose(ours["slip"], theirs["slip"], atol=1e-2 * np.max(theirs["slip"]))
    np.testing.assert_allclose(ours["range"], theirs["range"], atol=1e-2 * np.max(theirs["range"]))


def test_the_dispatcher_returns_a_converged_harmonic_balance_as_it_is():
    dynamics = tube_dynamics()
    excitation = tube_excitation(dynamics.problem.cargo)
    options = FrictionHBMOptions(harmonics=16, time_samples=128)
    hbm = solve_cradle_friction_hbm(dynamics, PadFriction(0.1), excitation, options)
    dispatched = solve_cradle_friction(dynamics, PadFriction(0.1), excitation, options)
    assert hbm.converged and dispatched.cradle.outcome is SolverOutcome.CONVERGED
    np.testing.assert_array_equal(dispatched.cradle.element_force_N, hbm.cradle.element_force_N)
    np.testing.assert_array_equal(dispatched.slip_m, hbm.slip_m)
    assert dispatched.cradle.message == hbm.cradle.message


@pytest.mark.slow
def test_where_the_harmonic_balance_fails_the_dispatcher_returns_the_checked_march(lifting):
    """The harmonic balance fails; the march at 512 and 1024 steps repeats and agrees with itself; Newton restarted from
    it gives no answer within the peak check (at H = 32 a truncated one: the next test): the answer is the march's."""
    dynamics, excitation = lifting
    friction, options = PadFriction(0.1), FrictionHBMOptions(harmonics=32, time_samples=256)
    assert not solve_cradle_friction_hbm(dynamics, friction, excitation, options).converged
    response = solve_cradle_friction(dynamics, friction, excitation, options, march=FrictionMarchOptions(time_samples=512))
    assert response.converged and response.cradle.outcome is SolverOutcome.CONVERGED_BY_TIME_MARCH, response.cradle.message
    assert 0.0 < response.cradle.residual <= STEP_TOLERANCE and response.cradle.time_s.size == 1024
    assert "marched in time" in response.cradle.message and "step error" in response.cradle.message
    finer, _ = march_cradle_friction(dynamics, friction, excitation, FrictionMarchOptions(time_samples=2048))
    pad = np.max(_march_peaks(finer)["max"])
    np.testing.assert_allclose(response.cradle.max_force_N[:4], _march_peaks(finer)["max"], atol=5e-3 * pad)
    np.testing.assert_allclose(response.max_slip_m, _march_peaks(finer)["slip"], rtol=1e-2)


@pytest.mark.parametrize(
    ("field", "value"), [("time_samples", 8), ("max_periods", 5), ("tolerance", 0.0), ("step_tolerance", 2.0), ("cutoff_rad_s", -1.0)]
)
def test_bad_march_options_are_refused_naming_the_field(field, value):
    with pytest.raises(ValueError, match=field):
        FrictionMarchOptions(**{field: value})


@pytest.mark.slow
def test_newton_from_the_march_converges_on_a_truncated_answer_the_dispatcher_does_not_keep(lifting):
    """Started from the march's periodic state the harmonic balance converges at H = 32 on the lifting case, with the
    largest slip 3 % above the march's (the kinks of lift-off need more harmonics): beyond the dispatcher's 5e-3, so
    the dispatcher answers with the march (the test above)."""
    dynamics, excitation = lifting
    friction = PadFriction(0.1)
    march, _ = march_cradle_friction(dynamics, friction, excitation, FrictionMarchOptions(time_samples=2048))
    samples = np.concatenate([march.engagement_m, march.tangential_m.reshape(2048, -1)], axis=1)
    restarted = solve_cradle_friction_hbm(dynamics, friction, excitation, FrictionHBMOptions(32, 256), start=samples)
    assert restarted.converged and "from the given periodic state" in restarted.cradle.message
    slip = _march_peaks(march)["slip"]
    assert np.max(np.abs(restarted.max_slip_m - slip)) > 0.02 * np.max(slip) > STEP_TOLERANCE * np.max(slip)
