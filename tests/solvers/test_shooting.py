"""Exact-event shooting against independent solutions: the converged transient analysis, the linear solution
where contact is kept, the adaptive harmonic balance, finite differences of its own period map.

Tolerances: the shooting's one approximation is the modal reduction (measured 1e-5 of the peaks on the base case
at the default cutoff); the time-domain reference at 8192 steps a period is within 2e-5 of its own halved step. A
wrong sign or factor anywhere moves the peaks by percent.
"""

from __future__ import annotations

import numpy as np
import pytest
from threadpoolctl import threadpool_limits

from seafast.config.modes import SolverMethod
from seafast.fourier import real_to_complex_harmonics
from seafast.model.seafastening import SeaFastening
from seafast.model.sections import CargoGeometry, TubeSegment
from seafast.model.structure import build_structural_model
from seafast.solvers import solve_periodic
from seafast.solvers.hbm import HBMOptions, solve_hbm
from seafast.solvers.hbm.condensed import condensed_operators
from seafast.solvers.linear import solve_linear
from seafast.solvers.modal_correction import modal_correction_system
from seafast.solvers.references import TimeDomainOptions, solve_time_domain
from seafast.solvers.shooting import ShootingOptions, solve_shooting
from seafast.solvers.shooting.period import PeriodGrid, flow_period
from seafast.solvers.shooting.states import ContactStates, SingularStateError
from solver_cases import base_model, peak_moment, wave_excitation


@pytest.fixture(autouse=True, scope="module")
def _one_blas_thread():
    with threadpool_limits(1):
        yield


@pytest.fixture(scope="module")
def real_case():
    from seafast.config import load_case
    from seafast.excitation.vessel import vessel_excitation
    from seafast.model.from_case import build_model

    case = load_case()
    model = build_model(case)
    return model, vessel_excitation(case).cargo_excitation(model, case)


@pytest.fixture(scope="module")
def synthetic():
    model = base_model()
    return model, wave_excitation(model)


def _reference(model, excitation, samples: int, steps: int = 8192):
    return solve_time_domain(model, excitation, TimeDomainOptions(time_samples=samples, steps_per_period=max(steps, samples)))


@pytest.mark.slow
def test_the_base_case_equals_the_converged_transient_analysis(real_case):
    model, ex = real_case
    r = solve_shooting(model, ex)
    assert r.converged and r.method is SolverMethod.SHOOTING
    assert r.options["events"] >= 2 and r.options["floquet_multiplier_max"] < 1.0
    ref = _reference(model, ex, r.time_samples)
    assert ref.converged
    assert r.max_saddle_force_N == pytest.approx(ref.max_saddle_force_N, rel=1e-4)
    own = np.max(r.saddle_force_time_N, axis=0) / np.max(ref.saddle_force_time_N, axis=0) - 1.0
    assert np.max(np.abs(own)) < 2e-4
    assert r.max_gap_m == pytest.approx(ref.max_gap_m, rel=1e-4)
    assert peak_moment(model, r) == pytest.approx(peak_moment(model, ref), rel=1e-4)
    # the whole history, not only the peaks: the worst sample within 0.3 % of the peak (the reference's step)
    assert np.max(np.abs(r.saddle_force_time_N - ref.saddle_force_time_N)) < 3e-3 * ref.max_saddle_force_N


def test_a_second_harmonic_in_the_excitation_equals_the_transient_analysis(synthetic):
    model, ex = synthetic
    assert ex.harmonic_count == 3
    r = solve_shooting(model, ex)
    assert r.converged and r.max_gap_m > 1e-4  # the middle saddle lifts in the sag
    ref = _reference(model, ex, r.time_samples)
    assert r.max_saddle_force_N == pytest.approx(ref.max_saddle_force_N, rel=2e-4)
    assert r.max_gap_m == pytest.approx(ref.max_gap_m, rel=2e-4)


def test_the_adaptive_harmonic_balance_converges_onto_it(synthetic):
    model, ex = synthetic
    r = solve_shooting(model, ex)
    h = solve_hbm(model, ex, HBMOptions())
    assert h.converged
    own = np.max(r.saddle_force_time_N, axis=0) / np.max(h.saddle_force_time_N, axis=0) - 1.0
    assert np.max(np.abs(own)) < 1e-3  # the adaptive H's own tolerance


def test_contact_kept_returns_the_linear_solution_exactly(synthetic):
    model, ex = synthetic
    small = ex.padded(2)
    small = type(ex)(
        ex.omega_rad_s, small.deck_displacement * [[1.0], [0.05]], small.cargo_load_N * [[1.0], [0.05]], small.cargo_line_load_N_per_m, ""
    )
    r = solve_shooting(model, small)
    assert r.converged and r.contact_preserved and "contact kept" in r.message
    lin = solve_linear(model, small)
    X = lin.cargo_displacement
    # the linear solution, through the response's sampled history and back (an FFT round trip: measured 2e-18 and
    # 1.7e-12 of the largest on two machines' BLAS; a wrong solve would be off by the contact's effect, 1e-3 or more)
    assert np.allclose(r.cargo_displacement_harmonics[: X.shape[0]], X, rtol=0, atol=1e-10 * np.max(np.abs(X)))


@pytest.mark.slow
def test_more_modes_converge_onto_the_complete_basis(real_case):
    # the base case rings after each re-contact: the modes above the cutoff respond, a little, dynamically
    model, ex = real_case
    complete = solve_shooting(model, ex, ShootingOptions(cutoff_factor=1e3)).max_saddle_force_N
    errors = [abs(solve_shooting(model, ex, ShootingOptions(cutoff_factor=f)).max_saddle_force_N / complete - 1.0) for f in (1.0, 8.0)]
    assert errors[1] < 0.5 * errors[0] and errors[1] < 3e-5


def test_the_monodromy_matrix_is_the_period_maps_jacobian(synthetic):
    # no saltation terms: the vector field is continuous where a saddle changes state
    model, ex = synthetic
    system = modal_correction_system(model, 8.0 * float(model.natural_frequencies_rad_s(True, count=3)[-1]), minimum_modes=3)
    ops = condensed_operators(model, ex, ex.harmonic_count - 1)
    states = ContactStates(system, real_to_complex_harmonics(ops.linear_compression_m), ex.omega_rad_s)
    grid = PeriodGrid(states, 1024)
    x0 = flow_period(states, np.zeros(states.state_size), grid).end_state  # a state whose period has events
    base = flow_period(states, x0, grid)
    assert base.events >= 2
    scale = np.maximum(np.abs(x0), 1e-3 * np.max(np.abs(x0)))
    for j in range(0, states.state_size, 3):
        h = 1e-6 * scale[j]
        plus, minus = (flow_period(states, x0 + sign * h * np.eye(states.state_size)[j], grid).end_state for sign in (1.0, -1.0))
        column = (plus - minus) / (2.0 * h)
        assert np.allclose(column, base.monodromy[:, j], rtol=1e-4, atol=1e-6 * np.max(np.abs(base.monodromy)))


def test_the_recorded_contact_states_agree_with_the_compressions(synthetic):
    model, ex = synthetic
    r = solve_shooting(model, ex)
    gap = r.saddle_compression_time_m < 0.0
    force = r.saddle_force_time_N
    assert np.all(force[gap] == 0.0) and np.all(force[~gap] >= 0.0)
    # the compressions are continuous through the events: no sample jumps by more than the smooth motion allows
    step = np.max(np.abs(np.diff(r.saddle_compression_time_m, axis=0)))
    assert step < 0.05 * np.max(np.abs(r.saddle_compression_time_m))


def test_a_state_with_no_support_against_rigid_motion_is_refused():
    geometry = CargoGeometry((TubeSegment(0, 74, 8, 8, 0.08),))
    sf = SeaFastening(np.array([14.8, 37, 59.2]), np.full(3, 1.1e9), np.array([False, False, False]))
    model = build_structural_model(geometry, sf, target_element_length_m=2.0)
    system = modal_correction_system(model, 1e3, minimum_modes=3)
    states = ContactStates(system, np.zeros((2, 3), dtype=complex), 0.6)
    with pytest.raises(SingularStateError, match="no stiffness"):
        states.get(np.ones(3, dtype=bool))


@pytest.mark.parametrize(
    ("field", "value"),
    [
        ("cutoff_factor", 0.5),
        ("samples_per_mode", 2),
        ("time_samples", 8),
        ("tolerance", 0.0),
        ("max_iterations", 0),
        ("reference_modes", 0),
    ],
)
def test_bad_options_name_the_field_the_value_and_what_is_allowed(field, value):
    with pytest.raises(ValueError, match=rf"{field} = {value!r}; allowed"):
        ShootingOptions(**{field: value})


def test_the_dispatcher_solves_by_shooting(synthetic):
    model, ex = synthetic
    r = solve_periodic(model, ex, SolverMethod.SHOOTING)
    assert r.method is SolverMethod.SHOOTING and r.converged
    assert r.max_saddle_force_N == pytest.approx(solve_shooting(model, ex).max_saddle_force_N, rel=1e-12)
