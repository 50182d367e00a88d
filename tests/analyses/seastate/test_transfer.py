"""Transfer functions: equal to `seafast run` at a grid frequency, hull linearity, long-wave limits."""

from __future__ import annotations

import math

import numpy as np
import pytest

import seafast
from seafast.analyses.run import run_case
from seafast.analyses.seastate.spectrum import sea_state_spectrum
from seafast.analyses.seastate.transfer import still_water, transfer_functions
from seafast.cli import main
from seafast.config import CaseError
from seafast.excitation.rao_extension import extended_rao
from seafast.excitation.vessel import vessel_excitation
from seafast.hull.transfer import wave_transfer_functions
from seafast.hull.wave import wave_response
from seafast.model.from_case import build_model
from seafast.solvers.linear import solve_harmonic

G = 9.81


@pytest.fixture(scope="module")
def base():
    case = seafast.load_case(None)
    model = build_model(case)
    omega = sea_state_spectrum(case).omega_rad_s
    return case, model, omega, transfer_functions(case, model, omega, heading_deg=180.0)


@pytest.mark.parametrize("index,amplitude", [(40, 1.0), (128, 2.0), (200, 0.5)])
def test_transfer_times_amplitude_equals_seafast_run_at_a_grid_frequency(base, index, amplitude):
    _, _, omega, tf = base
    w = float(omega[index])
    regular = seafast.load_case(None, {"wave.length_m": 2 * math.pi * G / w**2, "wave.amplitude_m": amplitude})
    assert regular.wave_frequency_rad_s() == pytest.approx(w, rel=1e-14)
    result = run_case(regular)
    ds = result.dataset
    n = ds.sizes["period_fraction"]
    phase = np.exp(2j * np.pi * np.arange(n) / n)[:, None]

    def dynamic_minus_static(name):
        lin = ds[name].sel(model="linear")
        return lin.sel(load_case="dynamic").values - lin.sel(load_case="static").values

    for name, transfer in (
        ("saddle_force_N", tf.saddle_force_N[index]),
        ("saddle_compression_m", tf.saddle_compression_m[index]),
        ("bending_moment_Nm", tf.bending_moment_Nm[index]),
        ("bending_stress_Pa", tf.bending_stress_Pa[index]),
    ):
        run = dynamic_minus_static(name)
        expected = np.real(amplitude * transfer[None, :] * phase)
        assert np.max(np.abs(run - expected)) <= 1e-6 * np.max(np.abs(run)), name
    assert np.allclose(ds["x_moment_m"].values, tf.bending_moment_x_m, rtol=0, atol=1e-12)
    exc = result.excitation
    for run_value, transfer in ((exc.deck_displacement[1], tf.deck_displacement[index]), (exc.cargo_load_N[1], tf.cargo_load_N[index])):
        assert np.max(np.abs(run_value - amplitude * transfer)) <= 1e-6 * np.max(np.abs(run_value))
    rb = result.vessel.rigid_body
    assert rb.heave_m == pytest.approx(amplitude * tf.heave_m[index], rel=1e-12)
    assert rb.pitch_rad == pytest.approx(amplitude * tf.pitch_rad[index], rel=1e-12)


def test_still_water_equals_the_static_linear_row_of_seafast_run(base):
    case, model, _, _ = base
    ds = run_case(case).dataset.sel(load_case="static", model="linear")
    sw = still_water(case, model)
    assert np.allclose(sw.saddle_force_N, ds["saddle_force_N"].values[0], rtol=1e-9)
    assert np.allclose(sw.bending_moment_Nm, ds["bending_moment_Nm"].values[0], rtol=1e-9, atol=1e-6 * np.abs(sw.bending_moment_Nm).max())


def test_banded_solves_equal_the_dense_linear_solver(base):
    _, model, omega, tf = base
    for i in (0, 77, len(omega) - 1):
        dense = solve_harmonic(model, float(omega[i]), tf.cargo_load_N[i], tf.deck_displacement[i])
        assert np.max(np.abs(dense - tf.cargo_displacement[i])) <= 1e-8 * np.max(np.abs(dense))


def test_hull_wave_response_is_linear_until_a_section_emerges():
    case = seafast.load_case(None)
    v = vessel_excitation(case)
    lam = 171.0
    w = math.sqrt(2 * math.pi * G / lam)
    tf = wave_transfer_functions(v.girder, v.loading, np.array([w]))
    onset = float(tf.emergence_amplitude_m[0])
    assert 2.5 < onset < 3.0  # the base wave (3 m) is just past it: the hull's ends emerge in the troughs
    for a, linear in ((0.5, True), (0.98 * onset, True), (1.2 * onset, False), (2.0 * onset, False)):
        r = wave_response(v.girder, v.loading, lam, a)
        err = np.max(np.abs(r.deflection_harmonics_m[1] / a - tf.deflection_m_per_m[0])) / np.max(np.abs(tf.deflection_m_per_m[0]))
        second = np.max(np.abs(r.deflection_harmonics_m[2])) / (a * np.max(np.abs(tf.deflection_m_per_m[0])))
        if linear:
            assert err < 1e-9 and second < 1e-9, a
        else:
            assert err > 1e-5 and second > 1e-5, a
    # moments too, and a crest amidships hogs (negative moment amidships at t = 0)
    r = wave_response(v.girder, v.loading, lam, 1.0)
    assert np.max(np.abs(r.bending_moment_harmonics_Nm[1] - tf.bending_moment_Nm_per_m[0])) < 1e-9 * np.max(
        np.abs(r.bending_moment_harmonics_Nm[1])
    )
    mid = np.argmin(np.abs(tf.x_m - 85.5))
    assert tf.bending_moment_Nm_per_m[0, mid].real < 0


def test_raos_blend_into_the_long_wave_limits_and_decay_in_short_waves():
    case = seafast.load_case(None)
    m = vessel_excitation(case).motions
    arm = m.reference_x_m - m.wave_phase_reference_x_m
    w0, w1 = float(m.omega_rad_s[0]), float(m.omega_rad_s[-1])
    kw = dict(gravity_m_per_s2=G, draught_m=6.5)
    # continuous at both ends of the BEM grid
    for w_edge, side in ((w0, -1e-9), (w1, 1e-9)):
        h_in, p_in = m.rao_at(w_edge)
        h_out, p_out = extended_rao(m, w_edge * (1 + side), **kw)
        assert abs(h_out - h_in) < 1e-6 and abs(p_out - p_in) < 1e-6 * abs(p_in) + 1e-9
    # long waves: heave -> exp(i k arm) (1 at midship), pitch -> i k exp(i k arm)
    for w in (0.02, 0.05, 0.1):
        k = w**2 / G
        h, p = extended_rao(m, w, **kw)
        h_lw = np.exp(1j * k * arm)
        deviation = (w / w0) ** 2
        assert abs(h / h_lw - 1) <= deviation * abs(m.heave_rao_m_per_m[0] / np.exp(1j * w0**2 / G * arm) - 1) * 1.000001
        p0_ratio = m.pitch_rao_rad_per_m[0] / (1j * w0**2 / G * np.exp(1j * w0**2 / G * arm))
        assert abs(p / (1j * k * h_lw) - 1) <= deviation * abs(p0_ratio - 1) * 1.000001
    h, p = extended_rao(m, 1e-3, **kw)
    assert h == pytest.approx(1.0, abs=1e-5) and p / (1j * 1e-6 / G) == pytest.approx(1.0, abs=1e-5)
    # short waves: smaller than at the grid's end, and decaying
    hs, ps = extended_rao(m, np.array([2.0, 3.0, 4.0]), **kw)
    assert np.all(np.diff(np.abs(hs)) < 0) and np.abs(hs[0]) < np.abs(m.heave_rao_m_per_m[-1])
    assert np.all(np.diff(np.abs(ps)) < 0)


def test_seafast_run_accepts_a_wave_longer_than_the_bem_grid(tmp_path):
    # lambda = 2000 m (0.175 rad/s) was refused; the ship now follows the long wave
    assert main(["run", "-o", str(tmp_path / "long"), "--set", "wave.length_m=2000", "--no-plots", "-q"]) == 0
    case = seafast.load_case(None, {"wave.length_m": 2000.0})
    rb = vessel_excitation(case).rigid_body
    k = 2 * math.pi / 2000.0
    assert abs(rb.heave_m) / 3.0 == pytest.approx(1.0, abs=0.015)
    assert abs(rb.pitch_rad) / (3.0 * k) == pytest.approx(1.0, abs=0.03)
    assert np.angle(rb.pitch_rad / rb.heave_m) == pytest.approx(math.pi / 2, abs=0.05)


def test_transfer_functions_vanish_in_very_long_and_very_short_waves(base):
    case, model, _, tf = base
    ends = transfer_functions(case, model, np.array([0.05, 0.6, 4.0]), heading_deg=180.0)
    peak = np.max(np.abs(tf.saddle_force_N))
    assert np.max(np.abs(ends.saddle_force_N[0])) < 1e-3 * peak  # a 25 km wave neither bends nor accelerates
    assert np.max(np.abs(ends.saddle_force_N[2])) < 2e-2 * peak  # a 4 m wave hardly bends a 171 m hull
    assert np.max(np.abs(ends.saddle_force_N[1])) > 0.3 * peak


def test_vessel_setups_without_a_per_frequency_hull_are_refused(tmp_path):
    table = tmp_path / "deck.csv"
    table.write_text("x_m,still_water_m,wave_amplitude_m,wave_phase_rad\n0,0,0,0\n85,0.01,0.02,0\n171,0,0,0\n")
    for overrides, key in (
        ({"vessel.deck_deflection_table": str(table)}, "vessel.deck_deflection_table"),
        ({"vessel.coupling": "two_way"}, "vessel.coupling"),
    ):
        case = seafast.load_case(None, overrides)
        with pytest.raises(CaseError, match=key):
            transfer_functions(case, build_model(case), np.array([0.5, 0.6]), heading_deg=180.0)
