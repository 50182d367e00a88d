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
from seafast.solvers.shooting import ShootingOptions, shooting_failure, solve_shooting
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
    fine_grid = PeriodGrid(states, 2**20)
    fine = flow_period(states, x0, fine_grid, record=True)
    assert coarse.peaks is not None and finer.peaks is not None and fine.peaks is None
    assert coarse.events >= fine.events >= 100  # the fine grid may miss a bounce; the guard does not
    scale = np.max(np.abs(fine.end_state))
    assert np.max(np.abs(coarse.end_state - fine.end_state)) < 1e-9 * scale
    assert np.max(np.abs(coarse.monodromy - fine.monodromy)) < 1e-6 * np.max(np.abs(fine.monodromy))
    # the continuous peaks: the same on either grid, and what the fine grid samples (from below, to its step)
    assert coarse.peaks.compression_m == pytest.approx(finer.peaks.compression_m, rel=1e-9)
    sampled = np.max(_sampled_compressions(states, fine_grid, fine), axis=0)
    assert np.all(coarse.peaks.compression_m >= sampled * (1.0 - 1e-9))
    assert coarse.peaks.compression_m == pytest.approx(sampled, rel=5e-3)


def test_the_default_solve_converges_on_near_rigid_saddles(rigid):
    model, ex = rigid
    r = solve_shooting(model, ex)
    assert r.converged and shooting_failure(r) is None
    assert r.options["basis"] == "lifted" and r.options["events"] >= 100 and r.max_gap_m > 0.01
    assert r.time_samples <= 8192  # the impacts are found by the guard, not by the grid
    # independently: every mode of the model (no reduction), unguarded on a grid that resolves the impacts
    exact = solve_shooting(
        model, ex, ShootingOptions(basis=CorrectionBasis.LIFTED, cutoff_factor=1e9, time_samples=2**19, cutoff_check=False, tolerance=1e-8)
    )
    assert exact.converged and exact.options["complete_basis"]
    peaks, exact_peaks = np.max(r.saddle_force_time_N, axis=0), np.max(exact.saddle_force_time_N, axis=0)
    assert np.max(np.abs(peaks / exact_peaks - 1.0)) < 5e-3  # the fine grid's sampling of 3e-5 s impacts
    assert np.all(peaks >= exact_peaks * (1.0 - 2e-3))  # the continuous peak: never below the samples'
    assert r.max_gap_m == pytest.approx(exact.max_gap_m, rel=1e-3)
    assert peak_moment(model, r) == pytest.approx(peak_moment(model, exact), rel=5e-3)
