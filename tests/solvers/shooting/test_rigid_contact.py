"""Near-rigid saddles (up to 1.1e14 N/m): the guarded period march finds every impact and its peak whatever the grid,
the default solve converges, and the limit k -> infinity of the undamped contact has no finite peak force.

Independent checks: the guarded march on a coarse grid against the unguarded one on a grid 1024 times finer (which
resolves the impacts: their contact frequency is 1e5 rad/s, the fine grid's step 1e-5 s), and the default solve
against the shooting with every mode of the model (no modal reduction) on that fine grid. Tolerances: the fine
grid samples an impact's peak to (w dt / 2)^2 / 2 ~ 1e-3 (3e-3 measured); the orbit and the events are exact in both.
"""

from __future__ import annotations

import numpy as np
import pytest
from threadpoolctl import threadpool_limits

from seafast.fourier import real_to_complex_harmonics
from seafast.solvers.hbm.condensed import condensed_operators
from seafast.solvers.modal_correction import CorrectionBasis, modal_correction_system
from seafast.solvers.references import TimeDomainOptions, solve_time_domain
from seafast.solvers.shooting import shooting_failure, solve_shooting
from seafast.solvers.shooting.period import PeriodGrid, flow_period
from seafast.solvers.shooting.states import ContactStates
from solver_cases import base_model, peak_moment, wave_excitation


@pytest.fixture(autouse=True, scope="module")
def _one_blas_thread():
    with threadpool_limits(1):
        yield


def _sampled_compressions(states, grid, flow):
    """Each sample's saddle compressions (N, n_s) [m], from its state in its contact state's closed form."""
    d = states.forcing(grid.times[:-1])
    out = np.empty_like(d)
    for n, code in enumerate(flow.state_codes):
        s = states.get(states.lifted_of(int(code)))
        out[n] = s.compression_state @ flow.state_samples[n] + s.compression_forcing @ d[n]
    return out


@pytest.fixture(scope="module")
def rigid():
    """The synthetic cargo on a coarse mesh (4 m elements) on 1.1e14 N/m saddles: impacts of some 3e-5 s."""
    model = base_model(4.0, 1e5)
    return model, wave_excitation(model)


def test_the_guarded_march_finds_every_impact_a_fine_grid_finds(rigid):
    model, ex = rigid
    w3 = float(model.natural_frequencies_rad_s(True, count=3)[-1])
    system = modal_correction_system(model, 32.0 * w3, minimum_modes=3, basis=CorrectionBasis.LIFTED)
    ops = condensed_operators(model, ex, ex.harmonic_count - 1)
    states = ContactStates(system, real_to_complex_harmonics(ops.linear_compression_m), ex.omega_rad_s)
    x0 = np.zeros(states.state_size)
    for _ in range(3):  # onto the orbit's neighbourhood: lift-off and impacts
        x0 = flow_period(states, x0, PeriodGrid(states, 1024), guard=True, monodromy=False).end_state
    coarse = flow_period(states, x0, PeriodGrid(states, 1024), guard=True)
    finer = flow_period(states, x0, PeriodGrid(states, 4096), guard=True)
    fine = flow_period(states, x0, PeriodGrid(states, 2**20))  # a step of 1e-5 s: a third of an impact
    assert coarse.peaks is not None and finer.peaks is not None and fine.peaks is None
    assert coarse.events >= fine.events >= 100  # the fine grid may miss a bounce; the guard does not
    scale = np.max(np.abs(fine.end_state))
    assert np.max(np.abs(coarse.end_state - fine.end_state)) < 1e-9 * scale
    assert np.max(np.abs(coarse.monodromy - fine.monodromy)) < 1e-6 * np.max(np.abs(fine.monodromy))
    # the continuous peaks: the same on either grid, each a maximum of the closed form in its contact state
    peaks = coarse.peaks
    assert peaks.compression_m == pytest.approx(finer.peaks.compression_m, rel=1e-9)
    for i in range(peaks.compression_m.size):
        s = states.get(states.lifted_of(int(peaks.code[i])))
        assert not s.lifted[i]
        tau = np.linspace(-3e-5, 3e-5, 601)
        z = s.inverse_eigenvectors @ (peaks.state[i] - states_particular(states, s, peaks.time_s[i]))
        local = np.real((np.exp(np.outer(tau, s.eigenvalues)) * z) @ s.modal_compression[i])
        local += np.real(
            np.exp(1j * ex.omega_rad_s * np.outer(peaks.time_s[i] + tau, np.arange(s.particular_compression.shape[0])))
            @ s.particular_compression[:, i]
        )
        assert local[300] == pytest.approx(peaks.compression_m[i], rel=1e-9)
        assert np.max(local) <= peaks.compression_m[i] * (1.0 + 1e-9)  # a maximum, not a point beside one
        assert peaks.compression_m[i] > 0.0 and np.min(local) < 0.98 * peaks.compression_m[i]  # a short impact's peak


def states_particular(states, s, t_s):
    """The particular solution's state at ``t_s`` in contact state ``s`` (2m,)."""
    k = np.arange(s.particular.shape[0])
    return np.real(np.exp(1j * states.omega_rad_s * k * t_s) @ s.particular)


def test_the_default_solve_converges_on_near_rigid_saddles(rigid):
    model, ex = rigid
    r = solve_shooting(model, ex)
    assert r.converged and shooting_failure(r) is None
    assert r.options["basis"] == "lifted" and r.options["events"] >= 100 and r.max_gap_m > 0.01
    assert r.time_samples <= 8192  # the impacts are found by the guard, not by the grid
    # the continuous peaks are in the samples: the reported peak force is the largest compression times k
    k = model.saddle_unilateral_stiffness_N_per_m
    assert np.max(r.saddle_force_time_N, axis=0) == pytest.approx(k * np.max(r.saddle_compression_time_m, axis=0), rel=1e-12)
    assert float(r.options["peak_missed_by_grid"]) < 1e-9


def test_toward_rigid_saddles_the_moment_and_gap_settle_and_the_peak_force_grows_without_limit():
    # undamped saddles: a re-contact is an elastic impact of the saddle's share of the cargo's mass, its force some
    # v sqrt(k m) above the quasi-static one -- no finite limit (x 3.16 a decade of k in the limit; 2.8 measured
    # from 1.1e13 to 1.1e14 N/m), while the motion and the bending it drives settle (4e-5 on M_b, 9e-5 on u_d)
    responses = []
    for scale in (1e4, 1e5):
        model = base_model(4.0, scale)
        r = solve_shooting(model, wave_excitation(model))
        assert r.converged
        responses.append((r.max_saddle_force_N, peak_moment(model, r), r.max_gap_m))
    (force_13, moment_13, gap_13), (force_14, moment_14, gap_14) = responses
    assert force_14 / force_13 > 2.0
    assert moment_14 == pytest.approx(moment_13, rel=1e-3)
    assert gap_14 == pytest.approx(gap_13, rel=1e-3)


@pytest.mark.slow
def test_the_default_solve_on_stiff_saddles_equals_the_full_dof_transient_analysis():
    # 1.1e11 N/m: the default (guarded, the cutoff doubled until the peaks settle) against the average-acceleration
    # integration of every DOF at 65536 steps a period (its impacts some 30 steps long): measured 1.2e-3 on the
    # peak forces, 1e-4 on M_b, 8e-5 on u_d (at 1.1e12 N/m and 262144 steps: 9.5e-4, 8e-6, 3e-8)
    model = base_model(4.0, 100.0)
    ex = wave_excitation(model)
    r = solve_shooting(model, ex)
    assert r.converged and r.options["basis"] == "lifted"
    steps = 65536
    ref = solve_time_domain(model, ex, TimeDomainOptions(time_samples=steps, steps_per_period=steps, hht_alpha=0.0), start=r)
    assert ref.converged
    own = np.max(r.saddle_force_time_N, axis=0) / np.max(ref.saddle_force_time_N, axis=0) - 1.0
    assert np.max(np.abs(own)) < 5e-3
    assert peak_moment(model, r) == pytest.approx(peak_moment(model, ref), rel=1e-3)
    assert r.max_gap_m == pytest.approx(ref.max_gap_m, rel=1e-3)
