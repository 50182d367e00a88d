"""Exact-event shooting on stiff saddles: the lifted basis against the bilateral one, against independent modes, and
against the full-DOF transient analysis; what a stiff solve that cannot converge says.

Tolerances: the two bases reduce the same equations differently, so they agree to the modal reduction's error
(measured 2e-4 of the peak force at the default cutoff on 1.1e10 N/m saddles). On 1.1e11 N/m saddles the full-DOF
time-domain reference at 65536 steps a period is 1.3e-3 from the shooting with every mode on the peak force (1.4 %
at 16384 steps: the impacts last a few tens of its steps), 4e-4 on M_b, 1e-4 on the gap. A wrong sign in the
contact stiffness the lifted basis adds, or a lost forcing term, moves the peaks by tens of percent.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import scipy.linalg
from threadpoolctl import threadpool_limits

from seafast.model.seafastening import SeaFastening
from seafast.model.sections import CargoGeometry, TubeSegment
from seafast.model.structure import build_structural_model
from seafast.solvers.modal_correction import CorrectionBasis, UnsupportedBasisError, lashings_hold, modal_basis
from seafast.solvers.references import TimeDomainOptions, solve_time_domain
from seafast.solvers.shooting import ShootingFailure, ShootingOptions, shooting_failure, solve_shooting
from seafast.solvers.shooting import stiff as shooting_stiff
from seafast.solvers.shooting.stiff import correction_system
from solver_cases import base_model, peak_moment, wave_excitation


@pytest.fixture(autouse=True, scope="module")
def _one_blas_thread():
    with threadpool_limits(1):
        yield


@pytest.fixture(scope="module")
def stiff():
    """The synthetic cargo on a coarse mesh (4 m elements) on 1.1e11 N/m saddles: impacts at re-contact."""
    model = base_model(4.0, 100.0)
    return model, wave_excitation(model)


def _peaks(r):
    return np.max(r.saddle_force_time_N, axis=0)


def test_the_lifted_cargos_soft_lashing_modes_are_found_to_their_own_precision():
    # held by its lashings alone the cargo has two soft rigid-body modes (0.1 rad/s) beside beam modes up to 1e6
    # rad/s: independently, the Rayleigh-Ritz values on the rigid heave and pitch (the beam's flexibility lowers
    # them by (0.1 / 59)^2 ~ 3e-6). A single eigh(K, M) is 2e-4 off on this mesh.
    model = base_model()
    basis = modal_basis(model, math.inf, CorrectionBasis.LIFTED)
    n = model.cargo_dof_count
    x = model.cargo.node_x_m - np.mean(model.saddle_x_m)
    rigid = np.zeros((n, 2))
    rigid[0::2, 0], rigid[0::2, 1], rigid[1::2, 1] = 1.0, x, 1.0
    K = np.asarray(model.dynamic_stiffness(0.0, False)[0])
    M = np.asarray(model.cargo.mass)
    ritz = np.sqrt(scipy.linalg.eigh(rigid.T @ K @ rigid, rigid.T @ M @ rigid, eigvals_only=True))
    assert basis.complete and basis.natural_frequency_rad_s.size == n
    assert basis.natural_frequency_rad_s[:2] == pytest.approx(ritz, rel=1e-5)
    assert basis.natural_frequency_rad_s[2] > 50.0  # the first beam mode
    phi = basis.mode_shape
    assert np.max(np.abs(phi.T @ M @ phi - np.eye(n))) < 1e-8


def test_the_lifted_basis_equals_the_bilateral_one_where_both_hold():
    model = base_model(4.0, 10.0)  # 1.1e10 N/m: the bilateral basis is still the default
    ex = wave_excitation(model)
    bilateral = solve_shooting(model, ex)
    lifted = solve_shooting(model, ex, ShootingOptions(basis=CorrectionBasis.LIFTED, cutoff_check=False))
    assert bilateral.options["basis"] == "bilateral" and lifted.options["basis"] == "lifted"
    assert bilateral.converged and lifted.converged
    assert bilateral.max_gap_m > 5e-3  # lift-off and re-contact: the lifted basis's contact states all visited
    assert np.max(np.abs(_peaks(lifted) / _peaks(bilateral) - 1.0)) < 1e-3
    assert peak_moment(model, lifted) == pytest.approx(peak_moment(model, bilateral), rel=1e-3)
    assert lifted.max_gap_m == pytest.approx(bilateral.max_gap_m, rel=1e-4)


def test_stiff_saddles_take_the_lifted_basis_and_lashless_cargo_keeps_the_bilateral_one(stiff):
    model, _ = stiff
    opts = ShootingOptions()

    def cutoff(m):  # the solve's: 16 times the third mode on bilateral saddles
        return 16.0 * float(m.natural_frequencies_rad_s(True, count=3)[-1])

    assert lashings_hold(model)
    assert correction_system(model, cutoff(model), opts).basis is CorrectionBasis.LIFTED  # 1.1e11 N/m: cancellation 1.4e8
    soft = base_model(4.0, 10.0)
    assert correction_system(soft, cutoff(soft), opts).basis is CorrectionBasis.BILATERAL  # 1.1e10 N/m: 1e7
    geometry = CargoGeometry((TubeSegment(0, 74, 8, 8, 0.08),))
    sf = SeaFastening(np.array([14.8, 37, 59.2]), np.full(3, 1.1e11), np.array([False, False, False]))
    lashless = build_structural_model(geometry, sf, target_element_length_m=4.0)
    assert not lashings_hold(lashless)
    with pytest.raises(UnsupportedBasisError, match="lashings do not hold"):
        modal_basis(lashless, 1e3, CorrectionBasis.LIFTED)
    assert correction_system(lashless, cutoff(lashless), opts).basis is CorrectionBasis.BILATERAL


def test_a_stiff_solve_that_cannot_settle_says_why(stiff, monkeypatch):
    model, ex = stiff
    # the modal reduction: one doubling allowed, a tolerance no doubling meets
    # the modal reduction: one doubling allowed, a tolerance no doubling meets, no last resort of every mode
    monkeypatch.setattr(shooting_stiff, "MAX_CUTOFF_DOUBLINGS", 1)
    monkeypatch.setattr(shooting_stiff, "MODAL_TOLERANCE", 1e-12)
    monkeypatch.setattr(shooting_stiff, "COMPLETE_BASIS_DOFS", 0)
    r = solve_shooting(model, ex, ShootingOptions(basis=CorrectionBasis.LIFTED))
    assert not r.converged and "not converged in the modal reduction: the peak forces still move" in r.message
    assert shooting_failure(r) is ShootingFailure.CUTOFF_NOT_SETTLED and r.options["failure"] == "cutoff_not_settled"
    assert r.options["cutoff_doublings"] == 1 and 1e-12 < float(r.options["cutoff_check_change"]) < 0.05
    # a chattering contact: more events than allowed
    r = solve_shooting(model, ex, ShootingOptions(max_events=3))
    assert not r.converged and shooting_failure(r) is ShootingFailure.TOO_MANY_EVENTS and "more than 3 contact events" in r.message


@pytest.mark.slow
def test_stiff_saddles_equal_the_full_dof_transient_analysis(stiff):
    model, ex = stiff
    # every mode of the lifted cargo: no reduction left, the shooting is the FE model's periodic orbit. Its residual
    # is relative to the linear compression (1e-4 m on these saddles): 1e-8 of it, 1e-12 m, is the all-mode march's
    # round-off floor (3e-9 measured), so the tolerance is 1e-8 here
    r = solve_shooting(model, ex, ShootingOptions(basis=CorrectionBasis.LIFTED, cutoff_factor=1e9, tolerance=1e-8))
    assert r.converged and r.options["complete_basis"] and r.options["events"] >= 4
    assert r.max_gap_m > 0.01  # heavy lift-off and impacts at re-contact
    # the time-domain reference (average acceleration, every step an output sample), from the shooting's orbit:
    # it reports another orbit if the shooting's is not the FE model's
    steps = 65536
    ref = solve_time_domain(model, ex, TimeDomainOptions(time_samples=steps, steps_per_period=steps, hht_alpha=0.0), start=r)
    assert ref.converged
    assert r.max_saddle_force_N == pytest.approx(ref.max_saddle_force_N, rel=3e-3)
    assert peak_moment(model, r) == pytest.approx(peak_moment(model, ref), rel=1e-3)
    assert r.max_gap_m == pytest.approx(ref.max_gap_m, rel=1e-3)
