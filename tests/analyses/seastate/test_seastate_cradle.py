"""Sea states off head seas: the 3-D cargo on its cradles (pads, stoppers, lashings), linear spectral and design-wave MPMs.

Checks against independent solutions: the linear transfer function at a low frequency against the exact heeled statics'
sensitivity, the harmonic balance's linear part and a small wave, a direct integration of the response spectra, the
design wave's harmonic balance against the quasi-static exact-contact reference, and the columns of seastate.csv.
"""

from __future__ import annotations

import csv
import dataclasses
import math

import numpy as np
import pytest
import scipy.integrate
import scipy.linalg
import xarray as xr

import seafast
from seafast.analyses.cradle_run import cradle_dynamics_of_case
from seafast.analyses.seastate import cradle_design_wave
from seafast.analyses.seastate.cradle_design_wave import cradle_design_waves, cradle_sea_state, scaled_excitation
from seafast.analyses.seastate.cradle_extremes import CRADLE_COLUMNS, is_off_head_seas
from seafast.analyses.seastate.cradle_transfer import (
    cradle_linear_transfer,
    cradle_sea_model,
    cradle_still_water,
    cradle_unit_excitations,
)
from seafast.analyses.seastate.directional_transfer import sea_state_quadrature
from seafast.analyses.seastate.spectral import SEASTATE_COLUMNS, spectral_analysis
from seafast.analyses.seastate.transfer import transfer_functions
from seafast.cli import main
from seafast.excitation.cradle_loads import cradle_excitation
from seafast.excitation.harmonic import HarmonicExcitation
from seafast.fourier import real_to_complex_harmonics
from seafast.model.cradle_case import build_cradle_case
from seafast.model.from_case import build_model
from seafast.solvers.cradle_dynamics import cradle_operators
from seafast.solvers.cradle_hbm import solve_cradle_hbm
from seafast.solvers.cradle_shooting import solve_cradle_shooting
from seafast.solvers.outcome import SolverOutcome
from seafast.solvers.references.cradle_quasi_static import solve_cradle_quasi_static
from seafast.solvers.transverse_statics import StaticsOutcome, solve_transverse_statics

STOPPERS = {"seafastening.side_stopper.gap_m": 0.02, "seafastening.side_stopper.stiffness_N_per_m": 2e9}
SPREAD_BEAM_SEA = {"sea_state.heading_deg": 90.0, "sea_state.spreading_exponent": 4.0, **STOPPERS}


@pytest.fixture(scope="module")
def beam():
    """The base case with side stoppers in a short-crested beam sea (cos-2s, s = 4): its analysis and cradle columns."""
    analysis = spectral_analysis(seafast.load_case(None, SPREAD_BEAM_SEA))
    return analysis, cradle_sea_state(analysis)


def _first_harmonic(samples: np.ndarray) -> np.ndarray:
    """Complex amplitude X of ``Re(X exp(i omega t))`` from N samples over one period (axis 0)."""
    n = samples.shape[0]
    return 2.0 / n * np.tensordot(np.exp(-2j * np.pi * np.arange(n) / n), samples, axes=(0, 0))


def test_pad_transfer_at_a_low_frequency_is_the_heeled_statics_sensitivity():
    """A unit roll at 1e-3 rad/s loads the cargo across by m g phi: the linear pad forces, lashing tensions and lateral
    displacements per radian equal the central difference of the exact statics at +-0.01 deg heel (both pads compressed,
    the stoppers open) to 1e-6 of the largest; a wrong sign or a missing g would be off by 100 %."""
    case = seafast.load_case(None, STOPPERS)
    model = build_model(case)
    cradle = build_cradle_case(case, model)
    dynamics = cradle_dynamics_of_case(cradle)
    n = cradle.cargo.node_count
    zero = HarmonicExcitation(
        1e-3, np.zeros((2, model.deck_dof_count), complex), np.zeros((2, 2 * n), complex), np.zeros((2, n - 1), complex)
    )
    roll = np.array([0, 0, 0, 1.0, 0, 0], dtype=complex)
    excitation = cradle_excitation(cradle.cargo, zero, roll, model.saddle_x_m, (0.0, 0.0, 0.0), case.model.gravity_m_per_s2)
    tf = cradle_linear_transfer(dynamics, [excitation], 90.0)
    h = 0.01
    plus, minus = (solve_transverse_statics(dynamics.problem, s * h, 0.0, gravity_m_per_s2=case.model.gravity_m_per_s2) for s in (1, -1))
    assert plus.outcome is StaticsOutcome.CONVERGED and minus.outcome is StaticsOutcome.CONVERGED
    assert np.all(plus.pad_force_N > 0.0) and np.all(plus.stopper_force_N == 0.0)
    per_rad = math.radians(2 * h)
    pads = (plus.pad_force_N - minus.pad_force_N).ravel() / per_rad
    lashings = (plus.lashing_tension_N - minus.lashing_tension_N) / per_rad
    expected = np.concatenate([pads, np.zeros(len(cradle.stoppers)), lashings])
    got = tf.element_force_N[0]
    assert np.max(np.abs(got.imag)) <= 1e-6 * np.max(np.abs(pads))
    assert np.max(np.abs(got.real - expected)) <= 1e-6 * np.max(np.abs(pads))
    assert pads[1] > 0 > pads[0]  # starboard down: the starboard pad takes more, the port pad less
    v_dofs = [cradle.cargo.node_dofs(cradle.cargo.node_at(x))[1] for x in cradle.saddle_x_m]
    v = (plus.displacement[v_dofs] - minus.displacement[v_dofs]) / per_rad
    assert np.max(np.abs(tf.lateral_displacement_m[0].real - v)) <= 1e-6 * np.max(np.abs(v)) and np.all(v < 0)


def test_transfer_is_the_harmonic_balance_linear_part_and_a_small_wave(beam):
    """The transfer functions equal the first harmonic of `cradle_operators`' linear part (pads and lashings bilateral),
    and a wave of 0.1 m solved by `solve_cradle_hbm` (nothing opens) has a first harmonic of a times them (1e-6)."""
    analysis, state = beam
    sea, tf = state.sea, analysis.directional.per_direction[0]
    index = int(np.argmin(np.abs(tf.omega_rad_s - 0.6)))
    unit = cradle_unit_excitations(sea, tf, [index])[0]
    linear = state.transfer.per_direction[0]
    ops = cradle_operators(sea.dynamics, unit, 1, sea.dynamics.damping_set)
    X = real_to_complex_harmonics(ops.linear_compression_m)[1]
    included = sea.dynamics.damping_set
    assert np.max(np.abs(X - linear.engagement_m[index][included])) <= 1e-9 * np.max(np.abs(X))
    a = 0.1
    response = solve_cradle_hbm(sea.dynamics, scaled_excitation(unit, a))
    assert response.converged and np.all(response.open_fraction[included] == 0.0)
    got = _first_harmonic(response.element_force_N)
    want = a * linear.element_force_N[index]
    assert np.max(np.abs(got[included] - want[included])) <= 1e-6 * np.max(np.abs(want))


def test_spectral_mpms_equal_a_direct_integration_of_the_spread_sea(beam):
    """A short-crested beam sea (s = 4): each pad's m0 and m2 by Simpson's rule over the frequencies of the weighted
    squared transfer functions of every direction (1e-3: the two quadratures' difference on the grid), the Rayleigh MPM
    from them, and the columns as still water +- MPM."""
    analysis, state = beam
    case = analysis.case
    q = sea_state_quadrature(case)
    w, s = analysis.spectrum.omega_rad_s, analysis.spectrum.density_m2_s_per_rad
    e = state.spectral
    pads = slice(0, e.pad_count)
    H = np.stack([t.element_force_N[:, pads] for t in state.transfer.per_direction])  # (n_dir, n_w, pads)
    assert H.shape[0] == q.heading_deg.size > 1
    squared = np.einsum("j,jwm->wm", q.weight, np.abs(H) ** 2)
    m0 = scipy.integrate.simpson(squared * s[:, None], x=w, axis=0)
    m2 = scipy.integrate.simpson(squared * (w**2 * s)[:, None], x=w, axis=0)
    assert np.allclose(e.element_force.m0[pads], m0, rtol=1e-3, atol=0)
    assert np.allclose(e.element_force.m2[pads], m2, rtol=1e-3, atol=0)
    duration = case.sea_state.duration_s
    mpm = np.sqrt(2.0 * m0 * np.log(duration / (2.0 * np.pi * np.sqrt(m0 / m2))))
    assert np.allclose(e.element_force.mpm[pads], mpm, rtol=1e-3, atol=0)
    sw = e.still_water.element_force_N
    lashings = slice(e.pad_count + e.stopper_count, None)
    assert e.totals["F_pad_N"] == pytest.approx(float(np.max(sw[pads] + e.element_force.mpm[pads])), rel=1e-14)
    assert e.totals["lashing_tension_min_N"] == pytest.approx(float(np.min(sw[lashings] - e.element_force.mpm[lashings])), rel=1e-14)
    assert e.totals["F_pad_N"] > float(np.max(sw[pads]))


def test_design_wave_harmonic_balance_equals_the_quasi_static_reference_in_a_long_wave():
    """A 685 m beam-sea wave (0.3 rad/s, far below the cargo's first mode on its 20 deg cradles, 16 rad/s) scaled to 1.1
    times the amplitude at which the linear model's first pad would lift: the high-side pads lift, and the harmonic
    balance's peak and least forces of every element equal the quasi-static exact-contact reference's within
    5 (omega / omega_1)^2 + 2e-3 of the largest force (the inertia it neglects, and the harmonics' smoothing of the
    kinks where pads lift and land)."""
    case = seafast.load_case(None, {"sea_state.heading_deg": 90.0, "seafastening.saddle_contact_angle_deg": 20.0, **STOPPERS})
    model = build_model(case)
    sea = cradle_sea_model(case, model)
    tf = transfer_functions(case, model, [0.3], heading_deg=90.0)
    unit = cradle_unit_excitations(sea, tf)[0]
    linear = cradle_linear_transfer(sea.dynamics, [unit], 90.0)
    still = cradle_still_water(sea).element_force_N
    pads = 2 * len(sea.cradle.pad_pairs)
    a = 1.1 * float(np.min(still[:pads] / np.abs(linear.element_force_N[0, :pads])))
    excitation = scaled_excitation(unit, a)
    hbm = solve_cradle_hbm(sea.dynamics, excitation)
    reference = solve_cradle_quasi_static(sea.dynamics, excitation, time_samples=hbm.time_s.size)
    assert hbm.converged and np.any(hbm.open_fraction[:pads] > 0.05)
    parts = sea.dynamics.linear_parts(sea.dynamics.damping_set)
    K, M = parts.bilateral_stiffness, sea.dynamics.matrices[1]
    omega_1 = math.sqrt(scipy.linalg.eigh(K, M, eigvals_only=True, subset_by_index=[0, 0])[0])
    assert omega_1 > 10.0
    tol = (5.0 * (0.3 / omega_1) ** 2 + 2e-3) * float(np.max(reference.element_force_N))
    assert np.max(np.abs(hbm.max_force_N - reference.max_force_N)) <= tol
    assert np.max(np.abs(hbm.min_force_N - reference.min_force_N)) <= tol


def test_design_waves_give_the_linear_columns_where_nothing_opens(beam):
    """In the 3 m spread beam sea the pad waves that open no pad read their pad's still water + MPM (to the period's
    sampling, 1e-3 of the MPM); the nonlinear columns equal the linear ones within 1e-3; no stopper closes."""
    _, state = beam
    e, d = state.spectral, state.design
    assert d is not None and d.converged and {w.quantity for w in d.waves} >= {"F_pad_N", "F_stopper_N", "transverse_slip_m"}
    per = e.element_totals()
    for wave, reading, response in zip(d.waves, d.readings, d.responses, strict=True):
        if wave.quantity == "F_pad_N" and not np.any(response.open_fraction[: e.pad_count] > 0):
            assert reading == pytest.approx(per["F_pad_N"][wave.location], abs=1e-3 * e.element_force.mpm[wave.location])
    for c in ("F_pad_N", "transverse_slip_m"):
        assert d.totals[c] == pytest.approx(e.totals[c], rel=1e-3), c
    assert d.totals["F_stopper_N"] == 0.0 == e.totals["F_stopper_N"]  # 20 mm gap: the stoppers stay open in 3 m


def _shooting_that_fails(outcome: SolverOutcome):
    """A stand-in for the exact-event shooting: its own answer, reported with ``outcome`` (residual 1)."""

    def shoot(dynamics, excitation):
        response = solve_cradle_shooting(dynamics, excitation)
        return dataclasses.replace(response, outcome=outcome, residual=1.0)

    return shoot


def test_a_design_wave_that_does_not_converge_is_flagged_with_its_residual(beam, monkeypatch):
    """The shooting and every H tried report no convergence (the solvers stood in for by ones that say so, with a
    residual per H): each wave keeps the harmonic balance's response of the least residual, and the estimates are
    flagged not converged with the largest of those residuals (never raised, never taken as converged)."""
    analysis, state = beam
    residual = {64: 3e-4, 96: 1e-4, 128: 2e-4, 48: 5e-4}

    def failing(dynamics, excitation, options):
        response = solve_cradle_hbm(dynamics, excitation, options.with_harmonics(8))
        return dataclasses.replace(
            response, outcome=SolverOutcome.NOT_CONVERGED, residual=residual[options.harmonics], harmonics=options.harmonics
        )

    monkeypatch.setattr(cradle_design_wave, "solve_cradle_shooting", _shooting_that_fails(SolverOutcome.NOT_CONVERGED))
    monkeypatch.setattr(cradle_design_wave, "solve_cradle_hbm", failing)
    d = cradle_design_waves(state.sea, analysis.directional, state.transfer, state.spectral)
    assert not d.converged and d.residual == 1e-4
    assert all(not r.converged and r.harmonics == 96 for r in d.responses)
    assert all("exact-event shooting did not converge" in r.message for r in d.responses)


def test_a_design_wave_is_solved_by_shooting_and_its_harmonic_balance_only_where_that_fails(beam, monkeypatch):
    """Where the shooting converges the harmonic balance is never called; a state the shooting shows not to repeat
    every wave period (``NOT_PERIODIC``) is returned as such, flagged, without a harmonic balance at the wave's period
    (which could converge on an unstable orbit); where the shooting fails otherwise, the ladder's first converged H
    answers, and its peaks agree with the shooting's (the same periodic solution, its converged limit)."""
    analysis, state = beam
    calls: list[int] = []

    def counted(dynamics, excitation, options):
        calls.append(int(options.harmonics))
        return solve_cradle_hbm(dynamics, excitation, options)

    monkeypatch.setattr(cradle_design_wave, "solve_cradle_hbm", counted)
    shot = cradle_design_waves(state.sea, analysis.directional, state.transfer, state.spectral)
    assert shot.converged and not calls
    monkeypatch.setattr(cradle_design_wave, "solve_cradle_shooting", _shooting_that_fails(SolverOutcome.NOT_PERIODIC))
    d = cradle_design_waves(state.sea, analysis.directional, state.transfer, state.spectral)
    assert not d.converged and not calls and all(r.outcome is SolverOutcome.NOT_PERIODIC for r in d.responses)
    monkeypatch.setattr(cradle_design_wave, "solve_cradle_shooting", _shooting_that_fails(SolverOutcome.NOT_CONVERGED))
    ladder = cradle_design_waves(state.sea, analysis.directional, state.transfer, state.spectral)
    assert ladder.converged and calls and set(calls) <= {64, 96, 128, 48}
    for column, value in shot.totals.items():  # each within the ladder's 0.1 % truncation
        assert ladder.totals[column] == pytest.approx(value, rel=1e-3, abs=1e-9)


def test_seastate_csv_off_head_seas_has_the_cradle_columns_after_converged(beam, tmp_path):
    """`seafast seastate` in the spread beam sea: the five columns after `converged`, the spectral and design-wave rows
    filled and equal to the analysis, the Monte Carlo rows empty; seastate.nc carries the cradle variables, labelled."""
    out = tmp_path / "beam"
    sets = [arg for key, value in SPREAD_BEAM_SEA.items() for arg in ("--set", f"{key}={value}")]
    assert main(["seastate", "-o", str(out), "--no-monte-carlo", "--no-plots", "-q", *sets]) == 0
    with open(out / "seastate.csv", newline="") as f:
        header = f.readline().strip()
        f.seek(0)
        rows = list(csv.DictReader(f))
    assert header.split(",") == list(SEASTATE_COLUMNS + CRADLE_COLUMNS)
    _, state = beam
    assert state.design is not None
    for c in CRADLE_COLUMNS:
        assert float(rows[0][c]) == pytest.approx(state.spectral.totals[c], rel=1e-12), c
        assert float(rows[3][c]) == pytest.approx(state.design.totals[c], rel=1e-12), c
        assert rows[1][c] == "" == rows[2][c]
    assert float(rows[0]["F_pad_N"]) > float(rows[0]["lashing_tension_max_N"]) > 0
    with xr.open_dataset(out / "seastate.nc") as ds:
        assert ds.sizes["cradle_element"] == 16 and ds["F_pad_N"].attrs["units"] == "N"
        for name in ("cradle_element_force_mpm_dynamic_N", "cradle_design_wave_reading", "lateral_displacement_mpm_dynamic_m"):
            assert ds[name].attrs.get("units") and ds[name].attrs.get("long_name"), name


def test_head_seas_compute_no_cradle_columns():
    """Head seas (long- or short-crested about 180) keep today's seastate: no cradle columns are computed."""
    assert not is_off_head_seas(seafast.load_case(None))
    assert not is_off_head_seas(seafast.load_case(None, {"sea_state.spreading_exponent": 4.0}))
    assert is_off_head_seas(seafast.load_case(None, {"sea_state.heading_deg": 179.0}))
