"""A peak saddle force that is an elastic impact at a re-contact is flagged, never reported as an answer.

On near-rigid saddles every re-contact after a lift-off is an impact whose force grows with the saddle stiffness
(the base case's geometry: 18.9 MN at 1.1e12 N/m, 44.9 MN at 1e13, 117 MN at 1e14) while the bending moment and
the gap converge. The impact estimate ``v G(k)`` (:mod:`seafast.results.impact`) is checked here against closed
forms and a time integration, the re-contact rate against an analytic signal, and the flag against the run:
raised on a near-rigid case, absent on the base case and on the saddle study's stiff end.
"""

from __future__ import annotations

import csv
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from seafast.analyses.run import run_case
from seafast.cli import EXIT_OUTSIDE_VALIDITY, main
from seafast.config import load_case
from seafast.model.from_case import build_model
from seafast.model.warning import ModelWarning
from seafast.results.dataset import SUMMARY_COLUMNS
from seafast.results.impact import (
    IMPACT_RATIO_LIMIT,
    fixed_harmonics_reason,
    impact_force_per_velocity_N_s_per_m,
    pulse_peak_per_velocity,
    recontact_velocities_m_s,
)


def test_the_pulse_of_a_rigid_body_is_the_closed_form_impact():
    # a mass m on a spring k: F = v sqrt(k m); a rigid bar struck at d from its centre: m_eff = 1 / (1/m + d^2/J)
    m, k = 2.0e5, 3.0e9
    assert pulse_peak_per_velocity(np.zeros((1, 1)), np.array([[m]]), np.array([1.0]), k, np.array([1.0])) == pytest.approx(
        math.sqrt(k * m), rel=2e-3
    )
    J, d = 5.0e7, 20.0
    G = pulse_peak_per_velocity(np.zeros((2, 2)), np.diag([m, J]), np.array([1.0, d]), k, np.array([1.0, 0.0]))
    assert G == pytest.approx(math.sqrt(k / (1.0 / m + d**2 / J)), rel=2e-3)
    assert G < 0.8 * math.sqrt(k * m)  # the rotation gives way: a factor 1 / sqrt(1 + m d^2 / J) = 0.75 would catch none


def test_the_cargo_struck_in_heave_is_rigid_on_soft_saddles_and_local_on_stiff_ones():
    model = build_model(load_case(overrides={"model.element_length_m": 2.0}))
    m = model.cargo.mass_kg
    x = model.cargo.node_x_m
    # the uniform tube: J about its centre m L^2 / 12, the saddle d from it
    d = model.saddle_x_m[2] - 0.5 * (x[0] + x[-1])
    rigid = math.sqrt(1.0e7 / (1.0 / m + d**2 / (m * (x[-1] - x[0]) ** 2 / 12.0)))
    assert impact_force_per_velocity_N_s_per_m(model, 2, 1.0e7) == pytest.approx(rigid, rel=0.01)
    # stiff saddles: far less than the rigid cargo's sqrt(k m_eff), growing as k^(1/3) (the continuous beam), not k^(1/2)
    G12, G14 = (impact_force_per_velocity_N_s_per_m(model, 2, k) for k in (1e12, 1e14))
    assert G14 < 0.2 * math.sqrt(1e14 / (1.0 / m + d**2 / (m * (x[-1] - x[0]) ** 2 / 12.0)))
    assert math.log(G14 / G12) / math.log(100.0) == pytest.approx(1.0 / 3.0, abs=0.05)


def test_the_pulse_of_a_flexible_cargo_matches_a_time_integration():
    model = build_model(load_case(overrides={"model.element_length_m": 8.0}))
    K, M = model.cargo.stiffness.copy(), model.cargo.mass
    i, k = int(model.saddle_cargo_dof[0]), 1e11
    K[i, i] += k
    n = K.shape[0]
    v0 = np.zeros(n)
    v0[0::2] = 1.0
    Minv_K = np.linalg.solve(M, K)
    solution = solve_ivp(
        lambda t, y: np.concatenate([y[n:], -Minv_K @ y[:n]]),
        (0.0, 0.05),
        np.concatenate([np.zeros(n), v0]),
        method="DOP853",
        rtol=1e-10,
        atol=1e-14,
        dense_output=True,
    )
    t = np.linspace(0.0, 0.05, 200_001)
    force = k * solution.sol(t)[i]
    end = np.nonzero(force[1:] < 0.0)[0][0] + 1
    contact = np.zeros(n)
    contact[i] = 1.0
    G = pulse_peak_per_velocity(model.cargo.stiffness, M, contact, k, v0)
    assert G == pytest.approx(float(np.max(force[:end])), rel=1e-3)


def test_the_re_contact_rate_is_read_from_the_gap_side():
    # delta(t) = a sin(w t) - b: re-contact where sin(w t) = b / a, at the rate a w cos(w t) (the analytic one)
    a, b, w = 0.02, 0.01, 2.0 * np.pi / 10.0
    t_c = math.asin(b / a) / w
    for N in (256, 1024):
        t = np.arange(N) * 10.0 / N
        delta = np.stack([a * np.sin(w * t) - b, np.full(N, 0.01)], axis=1)  # the second saddle never lifts off
        rates = recontact_velocities_m_s(delta, 10.0)
        assert rates[1].size == 0 and rates[0].size == 1
        # the parabola through three gap samples: error O(dt^2) of the rate
        assert rates[0][0] == pytest.approx(a * w * math.cos(w * t_c), rel=2.0 * (w * 10.0 / N) ** 2)


@pytest.fixture(scope="module")
def near_rigid():
    return run_case(load_case(overrides={"seafastening.saddle_stiffness_N_per_m": 1e13, "model.element_length_m": 2.0}))


def test_a_near_rigid_saddle_is_flagged_with_its_impact_estimate(near_rigid):
    check = near_rigid.impact
    assert [s.saddle for s in check.flagged] == [2]
    s = check.flagged[0]
    assert not s.bounded  # the pulse computed
    # the peak is the impact's pulse: the estimate is most of it (the pulse rides on the cargo's ringing from the
    # earlier impacts, which it leaves out) and far above the force the saddle carries with its contact kept
    assert 0.6 < s.impact_force_N / s.peak_force_N <= 1.0
    assert s.ratio > 2.0 * IMPACT_RATIO_LIMIT
    row = next(r for r in near_rigid.summary if (r["load_case"], r["model"]) == ("dynamic", "nonlinear"))
    assert ModelWarning.SADDLE_FORCE_ELASTIC_IMPACT in row["warnings"] and row["F_within_validity"] is False
    assert row["within_validity"]  # the bending moment and the displacements remain answers
    others = [r for r in near_rigid.summary if (r["load_case"], r["model"]) != ("dynamic", "nonlinear")]
    assert all(r["F_within_validity"] and ModelWarning.SADDLE_FORCE_ELASTIC_IMPACT not in r["warnings"] for r in others)
    ds = near_rigid.dataset
    assert not bool(ds["F_within_validity"].sel(load_case="dynamic", model="nonlinear"))
    assert "saddle 3" in ds.attrs["saddle_force_impacts"]


def test_the_base_case_and_the_stiff_end_of_the_saddle_study_are_not_flagged():
    # both lift off and re-contact; the impact's pulse stays well under the force the saddle carries anyway (the
    # energy bound sqrt(k m) already says so, so the pulse is not computed: here it is, to show the margin)
    for stiffness, largest in ((1.1e9, 0.2), (1.1e10, 0.4)):
        result = run_case(load_case(overrides={"seafastening.saddle_stiffness_N_per_m": stiffness}))
        check = result.impact
        assert check.saddles and check.flagged == () and all(s.bounded for s in check.saddles)
        assert all(r["F_within_validity"] for r in result.summary)
        pulse = [
            s.approach_velocity_m_s * impact_force_per_velocity_N_s_per_m(result.model, s.saddle, s.stiffness_N_per_m)
            for s in check.saddles
        ]
        ratios = [p / s.contact_kept_force_N for p, s in zip(pulse, check.saddles, strict=True)]
        assert 0.05 < max(ratios) < largest * IMPACT_RATIO_LIMIT
        assert all(p < s.impact_force_N for p, s in zip(pulse, check.saddles, strict=True))  # under the bound


def test_a_fixed_harmonic_count_below_the_re_contacts_ringing_is_named_as_the_reason():
    stiff = load_case(overrides={"seafastening.saddle_stiffness_N_per_m": 1e12, "solver.harmonics": 40})
    model = build_model(stiff)
    reason = fixed_harmonics_reason(stiff, model, 0.6)
    ringing = 1e12 / impact_force_per_velocity_N_s_per_m(model, 0, 1e12)
    assert 2e3 < ringing < 6e3  # a mass-like contact on a few metres of the tube (sqrt(1e12 / 9e4 kg) = 3.3e3 rad/s)
    assert reason is not None and "solver.harmonics = 40" in reason and "24 rad/s" in reason and f"{ringing:.3g} rad/s" in reason
    assert "leave solver.harmonics unset" in reason
    # the default (converged) solver, or harmonics that reach the ringing: no such reason
    assert fixed_harmonics_reason(load_case(overrides={"seafastening.saddle_stiffness_N_per_m": 1e12}), model, 0.6) is None
    assert fixed_harmonics_reason(stiff, model, 0.6 * ringing / 24.0 * 1.01) is None


def test_seafast_run_warns_of_the_elastic_impact_and_keeps_summary_csv(tmp_path, capsys):
    out = tmp_path / "out"
    code = main(
        ["run", "-o", str(out), "--no-plots", "--set", "seafastening.saddle_stiffness_N_per_m=1e13", "--set", "model.element_length_m=2.0"]
    )
    err = capsys.readouterr().err
    assert code == EXIT_OUTSIDE_VALIDITY
    line = next(x for x in err.splitlines() if "elastic impact" in x)
    assert "saddle 3" in line and "MN" in line and "measured saddle stiffness" in line and "bending moment" in line
    with open(out / "summary.csv", newline="") as f:
        assert tuple(next(csv.reader(f))) == SUMMARY_COLUMNS
