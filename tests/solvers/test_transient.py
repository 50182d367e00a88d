"""The non-periodic contact integrator (solvers/transient.py) against independent solutions.

* every mode kept: the march is the full model's Newmark average-acceleration integration, so a
  regular wave marched to steady state equals the periodic full-DOF time-domain reference
  (``solve_time_domain(..., formulation="full", hht_alpha=0)``, banded Cholesky on all cargo
  DOFs, no modal machinery) to round-off;
* the default reduction (4 modes + static residual flexibility) stays within 1e-4 of it;
* the same steady state agrees with the exact-law HBM (H = 16) within 1 % in peak force (3 % in
  peak gap, which 16 harmonics truncate);
* convergence in the time step; a free decay gives the model's own damping (complex eigenvalue
  of M s^2 + D s + K); a detached start is the exact static contact state; the direct per-set
  solve (more than 10 saddles) equals the precomputed table.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.linalg import eig

from seafast.solvers import transient
from seafast.solvers.hbm import HBMOptions, solve_hbm
from seafast.solvers.linear import solve_linear
from seafast.solvers.periodic import harmonics_to_time
from seafast.solvers.references import solve_exact_contact, solve_time_domain
from seafast.solvers.transient import (
    MarchState,
    integrate_record,
    modal_correction,
    reference_frequency_rad_s,
    time_step_s,
)
from solver_cases import base_model, wave_excitation

N = 128


@pytest.fixture(scope="module")
def wave():
    model = base_model()
    ex = wave_excitation(model)
    compression = solve_linear(model, ex).saddle_compression_m  # harmonics of delta_lin (still water included)
    return model, ex, compression


def steady_period(model, ex, compression, steps, cutoff=None, periods=8):
    """Last period of the march of the periodic linear compression, sampled at the N-point grid."""
    T = 2 * np.pi / ex.omega_rad_s
    system = modal_correction(model, T / steps, cutoff)
    d_lin = harmonics_to_time(compression, steps)
    record = integrate_record(system, np.vstack([np.tile(d_lin, (periods, 1)), d_lin[:1]]))
    assert record.solved
    last = record.compression_m[-steps - 1 : -1]
    return last[:: steps // N] if steps % N == 0 else last, record


def test_every_mode_kept_equals_the_full_dof_time_domain_reference(wave):
    model, ex, compression = wave
    ref = solve_time_domain(model, ex, N, steps_per_period=2048, hht_alpha=0.0)
    assert ref.converged
    delta, _ = steady_period(model, ex, compression, 2048, cutoff=np.inf)
    force = model.saddle_unilateral_stiffness_N_per_m * np.maximum(delta, 0.0)
    assert np.min(ref.saddle_compression_time_m) < -1e-3  # the middle saddle lifts off: contact is exercised
    assert np.max(np.abs(force - ref.saddle_force_time_N)) < 1e-7 * np.max(ref.saddle_force_time_N)
    assert np.max(np.abs(delta - ref.saddle_compression_time_m)) < 1e-7 * np.max(np.abs(ref.saddle_compression_time_m))


def test_default_reduction_is_within_1e4_of_the_full_model(wave):
    model, ex, compression = wave
    ref = solve_time_domain(model, ex, N, steps_per_period=2048, hht_alpha=0.0)
    delta, _ = steady_period(model, ex, compression, 2048)
    system = modal_correction(model, 0.01)
    assert system.mode_count == 4  # 44, 51, 72, 167 rad/s below 4 x 72 rad/s
    force = model.saddle_unilateral_stiffness_N_per_m * np.maximum(delta, 0.0)
    assert np.max(np.abs(force - ref.saddle_force_time_N)) < 1e-4 * np.max(ref.saddle_force_time_N)
    gap, gap_ref = np.max(-delta), np.max(-ref.saddle_compression_time_m)
    assert abs(gap / gap_ref - 1.0) < 3e-4


def test_steady_state_agrees_with_exact_law_hbm(wave):
    model, ex, compression = wave
    hbm = solve_hbm(model, ex, HBMOptions(harmonics=16, time_samples=N, contact_law="exact"))
    assert hbm.converged
    delta, _ = steady_period(model, ex, compression, 2048)
    force = model.saddle_unilateral_stiffness_N_per_m * np.maximum(delta, 0.0)
    assert abs(force.max() / hbm.max_saddle_force_N - 1.0) < 0.01
    # the gap is a kinked signal: 16 harmonics miss 1.9 % of its peak (the full reference above agrees to 1e-7)
    assert abs(np.max(-delta) / hbm.max_gap_m - 1.0) < 0.03


def test_time_step_convergence(wave):
    """Peak force and gap at 4..32 steps per period of the reference mode against 64 steps."""
    model, ex, compression = wave
    T = 2 * np.pi / ex.omega_rad_s
    w_ref = reference_frequency_rad_s(model)
    assert w_ref == pytest.approx(72.11, rel=1e-3)
    peaks = {}
    for spp in (4, 8, 16, 64):
        steps = int(round(T / (2 * np.pi / w_ref / spp)))
        delta, _ = steady_period(model, ex, compression, steps, periods=6)
        peaks[spp] = (np.max(model.saddle_unilateral_stiffness_N_per_m * np.maximum(delta, 0.0)), np.max(-delta))
    F64, gap64 = peaks[64]
    for spp, tol_f, tol_gap in ((4, 1e-3, 1.5e-2), (8, 3e-4, 5e-3), (16, 3e-4, 2e-3)):
        assert abs(peaks[spp][0] / F64 - 1.0) < tol_f
        assert abs(peaks[spp][1] / gap64 - 1.0) < tol_gap
    # the gap converges at second order: halving the step cuts its error by about 4
    err8, err16 = abs(peaks[8][1] - gap64), abs(peaks[16][1] - gap64)
    assert err16 < 0.5 * err8


def test_free_decay_gives_the_model_damping():
    """Newmark average acceleration adds no damping: a free decay of the first mode decays at -Re(s_1)."""
    model = base_model()
    M, D = model.cargo.mass, model.damping_cc
    K = model.dynamic_stiffness(0.0, True)[0]
    n = M.shape[0]
    # complex eigenvalues of M s^2 + D s + K (first-order form)
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-np.linalg.solve(M, K), -np.linalg.solve(M, D)]])
    s = eig(A, right=False)
    s1 = s[np.argmin(np.abs(np.abs(s) - 44.03))]
    decay, omega_d = -s1.real, abs(s1.imag)
    # the model's damping ratio, realised on the first mode (issue 12: Rayleigh fitted on the modes)
    assert decay / abs(s1) == pytest.approx(model.modal_damping_ratios(1)[0], rel=0.02)
    system = modal_correction(model, 2 * np.pi / omega_d / 128, np.inf)
    state = MarchState.at_rest(system)
    state.eta[0] = 1e-4  # first mode displaced, released from rest
    n_t = int(40 * 2 * np.pi / omega_d / system.time_step_s)
    d_lin = np.full((n_t, 3), 1.0)  # far from lift-off: no contact change
    rec = integrate_record(system, d_lin, initial=state)
    y = 1.0 - rec.compression_m[:, 0]  # q_c at the aft saddle
    peaks = np.flatnonzero((y[1:-1] > y[:-2]) & (y[1:-1] >= y[2:])) + 1
    t, a = rec.time_s[peaks], y[peaks]
    rate = -np.polyfit(t, np.log(a), 1)[0]
    assert rate == pytest.approx(decay, rel=5e-3)
    assert 2 * np.pi / np.mean(np.diff(t)) == pytest.approx(omega_d, rel=1e-3)


def test_detached_start_is_the_exact_static_contact_state():
    model = base_model()
    system = modal_correction(model, 0.01)
    d_lin = np.array([4e-3, -2e-3, 5e-3])  # the middle saddle would be in tension
    state = MarchState.quasi_static(system, d_lin)
    delta0 = d_lin - system.saddle_displacement_m(state.eta, state.force_N)
    ref, correction = solve_exact_contact(d_lin[None], system.static_receptance_m_per_N, system.stiffness_N_per_m)
    assert np.allclose(delta0, ref[0], atol=1e-12)
    assert np.allclose(state.force_N, correction[0], rtol=1e-10)
    # held there, it stays there: a static load gives a static response
    rec = integrate_record(system, np.tile(d_lin, (500, 1)))
    assert np.max(np.abs(rec.compression_m - ref[0])) < 1e-10


def test_direct_set_solves_equal_the_precomputed_table(wave, monkeypatch):
    model, ex, compression = wave
    T = 2 * np.pi / ex.omega_rad_s
    d_lin = harmonics_to_time(compression, 1024)
    d_lin = np.vstack([d_lin, d_lin, d_lin[:1]])
    table = modal_correction(model, T / 1024)
    assert table.set_inverses.shape == (8, 3, 3)
    monkeypatch.setattr(transient, "PRECOMPUTED_SETS_LIMIT", 2)
    direct = modal_correction(model, T / 1024)
    assert direct.set_inverses.shape[0] == 0
    a, b = integrate_record(table, d_lin), integrate_record(direct, d_lin)
    assert a.solved and b.solved
    assert np.max(np.abs(a.compression_m - b.compression_m)) < 1e-12


def test_bad_settings_are_refused():
    model = base_model()
    with pytest.raises(ValueError, match="steps_per_period"):
        time_step_s(model, 1)
    with pytest.raises(ValueError, match="time_step_s"):
        modal_correction(model, 0.0)
    with pytest.raises(ValueError, match="cutoff_rad_s"):
        modal_correction(model, 0.01, -1.0)
    with pytest.raises(ValueError, match="saddles"):
        integrate_record(modal_correction(model, 0.01), np.zeros((10, 2)))
