"""The pulse of an elastic impact (seafast.solvers.impact_pulse) against closed forms and a time integration.

``G(k)``, the peak force of the cargo striking a saddle's spring per unit approach velocity: a rigid body's
``sqrt(k m_eff)``, the free FE beam rigid on soft springs and local (``k^(1/3)``) on stiff ones, a flexible cargo's
pulse against an ODE integration; each re-contact's approach velocity against an analytic signal.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from seafast.config import load_case
from seafast.model.from_case import build_model
from seafast.solvers.impact_pulse import impact_force_per_velocity_N_s_per_m, pulse_peak_per_velocity, recontact_velocities_m_s


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
