"""The motion-analysis branch of ``seafast criteria``: the same numbers as ``seafast seastate``, the motions' statistics
against hand-written spectral sums, and the load case at a response's extreme against the regular wave at its crest."""

from __future__ import annotations

import csv
import math

import numpy as np
import pytest

from seafast.analyses.criteria.check import solve_load_case
from seafast.analyses.criteria.load_cases import Motion, apparent_gravity_m_s2
from seafast.analyses.criteria.motion_branch import criteria_analysis, motion_load_cases
from seafast.analyses.criteria.motion_statistics import PITCH, ROLL, SeaStateMotions, sea_state_motions
from seafast.analyses.seastate.spectral import spectral_analysis
from seafast.cli import main
from seafast.config import load_case
from seafast.excitation.vessel import VesselCache
from seafast.model.cradle_case import build_cradle_case
from seafast.output.report import write_report

OBLIQUE = 135.0


@pytest.fixture(scope="module")
def oblique():
    """The base case's sea state at 135 deg: its spectral analysis, motions and the branch at that heading."""
    case = load_case(overrides={"sea_state.heading_deg": OBLIQUE})
    with VesselCache().shared():
        analysis = spectral_analysis(case)
        motions = sea_state_motions(analysis)
        result = criteria_analysis(case, (OBLIQUE,))
    return case, analysis, motions, result


def _cells(path, name):
    with path.open() as handle:
        return [row for row in csv.DictReader(handle) if row.get("load_case", row.get("method")) == name]


def test_the_motion_rows_equal_seafast_seastate_at_the_same_sea_state_and_heading(tmp_path):
    """criteria.csv's spectral and design-wave rows are seastate.csv's numbers (criteria.csv writes 9 significant digits)."""
    sea, crit = tmp_path / "sea", tmp_path / "crit"
    heading = ["--set", f"sea_state.heading_deg={OBLIQUE:g}"]
    assert main(["seastate", "-q", "--no-monte-carlo", "--no-plots", "-o", str(sea), *heading]) == 0
    assert main(["criteria", "-q", "--headings", f"{OBLIQUE:g}", "-o", str(crit)]) == 0
    with (sea / "seastate.csv").open() as handle:
        seastate = {row["method"]: row for row in csv.DictReader(handle)}
    for method in ("spectral", "design_wave"):
        rows = _cells(crit / "criteria.csv", f"motion_h{OBLIQUE:g}_{method}")
        assert [r["check"] for r in rows] == ["saddle_force", "bending_stress"]
        for row in rows:
            assert row["heading_deg"] == f"{OBLIQUE:g}" and row["branch"] == f"motion_{method}"
            for key in ("F_N", "M_b_Nm", "sigma_b_Pa"):
                assert float(row[key]) == pytest.approx(float(seastate[method][key]), rel=5e-9, abs=0.0), (method, key)
    with (crit / "criteria_motions.csv").open() as handle:
        motions = list(csv.DictReader(handle))
    assert [r["heading_deg"] for r in motions] == [f"{OBLIQUE:g}"] and float(motions[0]["roll_deg"]) > 0.0
    # the report's design-criteria section names the motion rows and the governing case over both branches
    section = write_report(crit, figures=False).html.read_text(encoding="utf-8")
    assert f"motion_h{OBLIQUE:g}_roll+" in section and f"motion_h{OBLIQUE:g}_design_wave" in section
    assert "Governing over both branches" in section


def test_the_motion_maxima_are_the_sea_state_analysis_own_to_the_bit(oblique):
    """The branch's spectral row holds the spectral analysis's totals unchanged (the same computation)."""
    _, analysis, _, result = oblique
    spectral = result.headings[0].sea_state[0]
    assert spectral.method == "spectral"
    totals = analysis.extremes.totals
    assert (spectral.F_N, spectral.M_b_Nm, spectral.sigma_b_Pa) == (totals["F_N"], totals["M_b_Nm"], totals["sigma_b_Pa"])


def test_the_motions_are_the_sea_state_analysis_own(oblique):
    """Heave, pitch and roll of the branch are the transfer functions seafast seastate uses, to the bit."""
    _, analysis, motions, _ = oblique
    tf = analysis.transfer
    assert motions.raos.shape == (1, tf.omega_rad_s.size, 6)
    np.testing.assert_array_equal(motions.raos[0, :, 2], tf.heave_m)
    np.testing.assert_array_equal(motions.raos[0, :, PITCH], tf.pitch_rad)
    np.testing.assert_array_equal(motions.raos[0, :, ROLL], tf.roll_rad)


def _mpm(transfer, omega, density, duration):
    """Rayleigh MPM by hand: moments as trapezoid sums, sqrt(m0 2 ln(D / Tz))."""
    s_r = np.abs(transfer) ** 2 * density
    dw = np.diff(omega)
    m0 = float(np.sum(0.5 * (s_r[1:] + s_r[:-1]) * dw))
    m2 = float(np.sum(0.5 * ((omega**2 * s_r)[1:] + (omega**2 * s_r)[:-1]) * dw))
    return math.sqrt(m0 * 2.0 * math.log(duration / (2.0 * math.pi * math.sqrt(m0 / m2))))


def test_the_cargo_accelerations_against_the_rigid_body_by_hand(oblique):
    """The MPMs of the accelerometer's reading at the cargo's CoG and fore end from the six motions written out by hand:
    f = -omega^2 (xi + Omega x r) + g (theta, phi, 0), Omega = (phi, -theta, psi)."""
    case, _, motions, result = oblique
    h = result.headings[0]
    q = motions.raos[0]
    w, s, d, g = motions.omega_rad_s, motions.density_m2_s_per_rad, motions.duration_s, case.model.gravity_m_per_s2
    cradle = build_cradle_case(case)
    beam = cradle.cargo.vertical
    mass = beam.element_mass_per_length_kg_per_m * np.diff(beam.node_x_m)
    cog = float(mass @ beam.element_mid_x_m / mass.sum())
    aft = case.cargo_position_m() - 0.5 * case.cargo.length_m
    for row, x_cargo in ((1, cog), (2, case.cargo.length_m)):
        rx = aft + x_cargo - h.origin.x_m
        ry = case.cargo_transverse_position_m()
        rz = case.vessel.deck_height_m + case.seafastening.saddle_height_m + 0.5 * case.cargo.diameter_m - h.origin.z_above_keel_m
        surge, sway, heave, roll, pitch, yaw = q.T
        fx = -(w**2) * (surge - pitch * rz - yaw * ry) + g * pitch
        fy = -(w**2) * (sway + yaw * rx - roll * rz) + g * roll
        fz = -(w**2) * (heave + roll * ry + pitch * rx)
        for k, f in enumerate((fx, fy, fz)):
            assert h.maxima.cargo_acceleration_m_s2[row, k] == pytest.approx(_mpm(f, w, s, d), rel=1e-12)
    assert math.radians(h.maxima.roll_deg) == pytest.approx(_mpm(q[:, ROLL], w, s, d), rel=1e-12)
    assert h.maxima.heave_acceleration_m_s2 == pytest.approx(_mpm(-(w**2) * q[:, 2], w, s, d), rel=1e-12)


def _one_frequency_motions(rng):
    """A sea whose spectrum is non-zero at one grid frequency only: every response is a regular wave there."""
    w = np.linspace(0.3, 1.5, 13)
    density = np.zeros(w.size)
    density[6] = 2.0
    raos = (rng.normal(size=(1, w.size, 6)) + 1j * rng.normal(size=(1, w.size, 6))) * np.array([0.2, 0.3, 0.5, 0.02, 0.01, 0.005])
    return SeaStateMotions(135.0, w, density, np.ones(1), raos, 60.0, 7.0, 10800.0, 9.81)


def test_the_load_case_at_an_extreme_is_the_regular_wave_at_its_crest():
    """With one frequency the simultaneous values are the regular wave's at the instant the governing response peaks:
    ``Y = u Re(H_Y conj(H_X)) / |H_X|^2``; every motion and acceleration of the case checked against it."""
    motions = _one_frequency_motions(np.random.default_rng(7))
    q, w = motions.raos[0, 6], motions.omega_rad_s[6]
    cog = np.array([5.0, 10.0, 9.0])
    cases = motion_load_cases(motions, cog)
    assert [c.name for c in cases] == [f"motion_h135_{m}{s}" for m in ("roll", "pitch", "heave") for s in "+-"]
    z_cog = -(w**2) * (q[2] + q[ROLL] * cog[1] + q[PITCH] * cog[0])  # vertical acceleration at the CoG
    for case, governing in zip(cases, (q[ROLL], q[ROLL], q[PITCH], q[PITCH], z_cog, z_cog), strict=True):
        mpm = motions.mpm(
            motions.point_acceleration(cog, 2)
            if case.motion is Motion.HEAVE
            else motions.motion(ROLL if case.motion is Motion.ROLL else PITCH)
        )
        u = (1.0 if case.name.endswith("+") else -1.0) * mpm
        crest = u * np.conj(governing) / abs(governing) ** 2  # the wave's complex amplitude times exp(i omega t) at the peak

        def at(h, crest=crest):
            return float(np.real(h * crest))

        assert math.radians(case.roll_deg) == pytest.approx(at(q[ROLL]), rel=1e-12)
        assert math.radians(case.pitch_deg) == pytest.approx(at(q[PITCH]), rel=1e-12)
        np.testing.assert_allclose(case.origin_acceleration_m_s2, [at(-(w**2) * q[k]) for k in range(3)], rtol=1e-12)
        alpha = [at(-(w**2) * q[ROLL]), -at(-(w**2) * q[PITCH]), at(-(w**2) * q[5])]
        np.testing.assert_allclose(case.rotation_acceleration_rad_s2, alpha, rtol=1e-12)
        assert case.period_s == pytest.approx(2.0 * math.pi / w, rel=1e-12)
        assert case.heading_deg == 135.0


def test_at_the_roll_extreme_the_angular_acceleration_is_minus_the_roll_times_omega_z_squared(oblique):
    """E[phi'' | phi = u] = -u m2 / m0 = -u (2 pi / Tz)^2: the default criteria's rule with T = Tz; the roll is its MPM."""
    _, _, _, result = oblique
    h = result.headings[0]
    for item in h.cases:
        lc = item.load_case
        if lc.motion is Motion.ROLL:
            assert abs(lc.roll_deg) == pytest.approx(h.maxima.roll_deg, rel=1e-14)
            expected = -math.radians(lc.roll_deg) * (2.0 * math.pi / lc.period_s) ** 2
            assert lc.rotation_acceleration_rad_s2[0] == pytest.approx(expected, rel=1e-10)
            assert lc.period_s == pytest.approx(h.maxima.roll_period_s, rel=1e-14)


def test_the_motion_cases_are_solved_exactly_on_the_cradles(oblique):
    """Each motion case's apparent gravity at the CoG by the formula, and vertical equilibrium: the pads' pushes less the
    lashings' downward pulls carry -m a_z (1e-8 of the weight)."""
    case, _, _, result = oblique
    cradle = build_cradle_case(case)
    g = case.model.gravity_m_per_s2
    beam = cradle.cargo.vertical
    mass_e = beam.element_mass_per_length_kg_per_m * np.diff(beam.node_x_m)
    mass = float(mass_e.sum())
    h = result.headings[0]
    assert len(h.cases) == 6
    for item in h.cases:
        assert item.outcome == "converged"
        lc = item.load_case
        r = np.array(
            [case.cargo_position_m() - 0.5 * case.cargo.length_m + float(mass_e @ beam.element_mid_x_m / mass) - h.origin.x_m, 0, 0]
        )
        r[1] = case.cargo_transverse_position_m()
        r[2] = case.vessel.deck_height_m + case.seafastening.saddle_height_m + 0.5 * case.cargo.diameter_m - h.origin.z_above_keel_m
        phi, theta = math.radians(lc.roll_deg), math.radians(lc.pitch_deg)
        gravity = g * np.array([-math.sin(theta), -math.cos(theta) * math.sin(phi), -math.cos(theta) * math.cos(phi)])
        expected = gravity - np.cross(lc.rotation_acceleration_rad_s2, r) - np.array(lc.origin_acceleration_m_s2)
        np.testing.assert_allclose(item.apparent_gravity_cog_m_s2, expected, rtol=0, atol=1e-12)
        np.testing.assert_allclose(apparent_gravity_m_s2(lc, r, g), expected, rtol=0, atol=1e-12)
        pulls = sum(t * w.direction[2] for t, w in zip(item.statics.lashing_tension_N, cradle.lashings, strict=True))
        vertical = float(np.sum(item.saddle_vertical_force_N)) + pulls
        assert vertical == pytest.approx(-mass * item.apparent_gravity_cog_m_s2[2], abs=1e-8 * mass * g)
        assert item.friction is not None and item.friction.normal_force_N == pytest.approx(-mass * expected[2], rel=1e-12)
    same = solve_load_case(case, cradle, h.cases[0].load_case, h.origin)
    assert same.saddle_force_N == h.cases[0].saddle_force_N


def test_the_governing_case_is_named_over_both_branches(oblique):
    _, _, _, result = oblique
    rows = result.rows()
    name, u = result.governing
    assert u == max(r[1] for r in rows) and name in {r[0] for r in rows}
    assert len(rows) == 8 + 6 + 2
