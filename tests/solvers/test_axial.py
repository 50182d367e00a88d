"""Axial stick-slip solvers: the Jenkins AFT kernel, the HBM and the rigid-Coulomb time-domain reference
against closed forms (Den Hartog 1931, the frictionless oscillator, stick statics) and each other."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from seafast.excitation.axial import AxialLoad
from seafast.model.axial import AxialRestraint
from seafast.solvers.axial import (
    AxialHBMOptions,
    LockCheck,
    clamp_prefix,
    critical_friction_coefficient,
    lock_range_m,
    march_jenkins,
    solve_axial_hbm,
    solve_axial_time_domain,
)
from seafast.solvers.axial.problem import AxialProblem, lock_check
from seafast.solvers.axial.time_domain import remaining_distance

M, K, P0 = 1.0e6, 1.0e6, 1.0e6  # mass [kg], spring [N/m] (omega_n = 1 rad/s), force amplitude [N]
KT = 1e12  # rigid contact


def _den_hartog_amplitude(beta: float, friction_N: float) -> float:
    """Den Hartog (1931), motion without stops: x0 = sqrt(q^2 - (F0/k)^2 U^2),
    q = P0 / (k (1 - beta^2)), U = sin(pi/beta) / (beta (1 + cos(pi/beta)))."""
    q = P0 / (K * (1.0 - beta**2))
    g = math.pi / beta
    u = math.sin(g) / (beta * (1.0 + math.cos(g)))
    return math.sqrt(q * q - (friction_N / K) ** 2 * u * u)


def _oscillator(mu: float, **kw) -> AxialRestraint:
    return AxialRestraint(M, np.array([mu]), np.array([KT]), lashing_axial_stiffness_N_per_m=K, **kw)


# ------------------------------------------------------------------------------ Jenkins kernel
def _march_loop(u, cap, k, w0=0.0):
    """Sample-by-sample return mapping, two periods (the definition the prefix scan must reproduce)."""
    w = w0
    for _ in range(2):
        out = []
        for un, cn in zip(u, cap, strict=True):
            w = min(max(w, un - cn / k), un + cn / k)
            out.append(w)
    return np.array(out)


@settings(derandomize=True, max_examples=60, deadline=None)
@given(st.integers(2, 200), st.integers(0, 2**31 - 1))
def test_prefix_scan_equals_the_sample_loop(n, seed):
    rng = np.random.default_rng(seed)
    u = np.cumsum(rng.normal(size=n))
    cap = np.abs(rng.normal(size=n)) * rng.choice([0.0, 1.0, 5.0])
    jen = march_jenkins(u, cap, 2.0)
    np.testing.assert_allclose(jen.slider_m, _march_loop(u, cap, 2.0), atol=1e-12)
    a, b = clamp_prefix(u - cap / 2, u + cap / 2)
    assert np.all(a <= b + 1e-12)
    # the period is closed: marching again from the end state returns the same period
    again = march_jenkins(u, cap, 2.0, w_init_m=float(jen.slider_m[-1]))
    np.testing.assert_allclose(again.slider_m, jen.slider_m, atol=1e-12)
    assert np.all(np.abs(jen.force_N) <= cap + 1e-9)


def test_jacobian_equals_finite_differences():
    r = AxialRestraint(
        M, np.array([0.2, 0.1]), np.array([1e9, 1e9]), lashing_axial_stiffness_N_per_m=K, stopper_gap_m=0.3, stopper_stiffness_N_per_m=5e7
    )
    load = AxialLoad(0.8, np.array([0.0, 1.2 * P0 - 0.4j * P0]))
    cap = r.capacity_N(np.column_stack([np.full(256, 1e6), 1e6 * (1 + 0.5 * np.sin(2 * np.pi * np.arange(256) / 256))]))
    p = AxialProblem(r, load, cap, 7, 256)
    X = np.random.default_rng(3).normal(size=15) * 0.3
    R, state = p.residual(X)
    J = p.jacobian(state)
    h = 1e-8
    fd = np.column_stack([(p.residual(X + h * e)[0] - R) / h for e in np.eye(15)])
    assert np.max(np.abs(fd - J)) < 1e-5 * np.max(np.abs(J))


# ------------------------------------------------------------------------------ closed forms
@pytest.mark.parametrize("beta", [0.6, 1.5])
def test_den_hartog_closed_form(beta):
    """Harmonically forced mass on a spring with Coulomb friction under a constant normal force,
    steady motion without stops (Den Hartog 1931): amplitude within 1 % (HBM) and 1e-4 (time domain)."""
    mu, normal = 0.3, 1.0e6
    x0 = _den_hartog_amplitude(beta, mu * normal)
    load = AxialLoad(beta, np.array([0.0, P0], dtype=complex))
    n = np.full((128, 1), normal)
    hbm = solve_axial_hbm(_oscillator(mu), load, n, AxialHBMOptions(harmonics=25, time_samples=512))
    td = solve_axial_time_domain(_oscillator(mu), load, n, time_samples=1024)
    assert hbm.converged and td.converged
    for res, tol in ((hbm, 0.01), (td, 1e-4)):
        amp = 0.5 * np.ptp(res.displacement_m)
        assert amp == pytest.approx(x0, rel=tol)
        assert res.slip_m == pytest.approx(4 * x0, rel=tol)  # slides all the time: 4 x0 per period
        assert not np.any(res.friction_utilisation < 1.0)
    # friction opposes the sliding velocity (a sign error would flip it)
    moving = np.abs(td.velocity_m_per_s) > 1e-3 * np.max(np.abs(td.velocity_m_per_s))
    assert np.all(np.sign(td.friction_force_N[moving]) == -np.sign(td.velocity_m_per_s[moving]))


def test_frictionless_gives_the_lashing_oscillator():
    """mu = 0: u = F / (k_a - m w^2 + i w c), both solvers (5 % damping lets the time domain settle)."""
    w = 0.6
    c = 2 * 0.05 * math.sqrt(K * M)
    load = AxialLoad(w, np.array([0.0, P0 * (0.3 - 0.8j)]))
    x = load.force_N[1] / (K - M * w**2 + 1j * w * c)
    n = np.full((64, 1), 1e6)
    hbm = solve_axial_hbm(_oscillator(0.0, damping_N_s_per_m=c), load, n, AxialHBMOptions(harmonics=5, time_samples=64))
    td = solve_axial_time_domain(_oscillator(0.0, damping_N_s_per_m=c), load, n, time_samples=64)
    assert td.converged
    assert hbm.harmonics[1] == pytest.approx(x, rel=1e-9)
    exact = np.real(x * np.exp(2j * np.pi * np.arange(64) / 64))
    np.testing.assert_allclose(td.displacement_m, exact, atol=1e-5 * abs(x))
    assert hbm.axial_force_N == pytest.approx(K * np.max(np.abs(exact)), rel=1e-9)  # lashing force, sampled peak


def test_large_coefficient_sticks_with_the_statics_utilisation():
    """Friction that holds: no slip, utilisation = max|F| / (mu N) (the statics), lashings unloaded."""
    w, mu = 0.6, 0.5
    load = AxialLoad(w, np.array([0.0, 0.2 * P0 + 0.1j * P0]))
    t = np.arange(128) / 128
    normal = np.column_stack([1e6 * (1 + 0.3 * np.cos(2 * np.pi * t)), np.full(128, 0.8e6)])
    r = AxialRestraint(M, np.array([mu, mu]), np.array([KT, KT]), lashing_axial_stiffness_N_per_m=K)
    f = np.real(load.force_N[1] * np.exp(2j * np.pi * t))
    statics = float(np.max(np.abs(f) / (mu * normal.sum(axis=1))))
    assert statics < 1.0
    for res in (
        solve_axial_hbm(r, load, normal, AxialHBMOptions(harmonics=15, time_samples=256)),
        solve_axial_time_domain(r, load, normal, time_samples=128),
    ):
        assert res.converged and res.slip_m == 0.0 and not res.sliding.any()
        assert res.friction_utilisation == pytest.approx(statics, rel=1e-4)
        assert res.axial_force_N < 1e-6 * P0
    assert critical_friction_coefficient(f, normal) == pytest.approx(statics * mu, rel=1e-12)


def test_stoppers_against_the_time_domain():
    """Sliding into stiff end stoppers: HBM and the time-domain reference agree within 1 %."""
    w = 0.6
    r = AxialRestraint(
        M, np.array([0.1]), np.array([KT]), lashing_axial_stiffness_N_per_m=K, stopper_gap_m=0.3, stopper_stiffness_N_per_m=5e6
    )
    load = AxialLoad(w, np.array([0.0, P0], dtype=complex))
    n = np.full((128, 1), 1e6)
    hbm = solve_axial_hbm(r, load, n, AxialHBMOptions(harmonics=25, time_samples=512))
    td = solve_axial_time_domain(r, load, n, time_samples=512)
    assert hbm.converged and td.converged
    assert hbm.axial_force_N == pytest.approx(td.axial_force_N, rel=0.01)
    assert np.max(hbm.stopper_force_N) > 0 > np.min(hbm.stopper_force_N)  # both stoppers hit
    assert hbm.slip_m == pytest.approx(td.slip_m, rel=0.01)


def test_tangential_stiffness_does_not_change_the_sliding_solution():
    """The Jenkins spring is the AFT's regularisation: 1e11 .. 1e13 N/m give the same answer."""
    load = AxialLoad(1.5, np.array([0.0, P0], dtype=complex))
    n = np.full((128, 1), 1e6)
    slips = []
    for kt in (1e11, 1e12, 1e13):
        r = AxialRestraint(M, np.array([0.3]), np.array([kt]), lashing_axial_stiffness_N_per_m=K)
        slips.append(solve_axial_hbm(r, load, n, AxialHBMOptions(harmonics=25, time_samples=512)).slip_m)
    assert max(slips) / min(slips) - 1 < 1e-4


def test_failure_is_reported_not_raised():
    r = _oscillator(0.3)
    res = solve_axial_hbm(
        r,
        AxialLoad(1.5, np.array([0.0, P0], dtype=complex)),
        np.full((64, 1), 1e6),
        AxialHBMOptions(harmonics=25, time_samples=512, max_iterations=1),
    )
    assert not res.converged and res.residual_norm > 1e-9 and res.lock_check is LockCheck.NOT_LOCKED


def test_walking_cargo():
    """Friction stronger on the forward push than on the aft one: the cargo walks aft. Held by
    lashings it settles where their force balances the walk (the reference extrapolates the
    geometric walk to its limit: 8 periods); with nothing else holding it, it walks for ever and
    the reference says how far per period."""
    w = 0.6
    t = np.arange(128) / 128
    normal = (1e6 * (1 + 0.5 * np.cos(2 * np.pi * t)))[:, None]  # most friction when the load pushes forward
    load = AxialLoad(w, np.array([0.0, 0.4 * P0], dtype=complex))
    held = AxialRestraint(M, np.array([0.3]), np.array([KT]), lashing_axial_stiffness_N_per_m=2e5)
    td = solve_axial_time_domain(held, load, normal, time_samples=512)
    assert td.converged and td.iterations < 30
    assert np.mean(td.displacement_m) < -0.1  # settled aft
    assert np.mean(td.lashing_force_N) > 0  # the lashings pull it forward
    # where it settled, the period's mean friction balances the mean lashing force (the 0th harmonic)
    # (to the sampling of the switching friction: 1 % of the lashing force)
    assert abs(np.mean(td.friction_force_N + td.lashing_force_N)) < 0.01 * np.mean(td.lashing_force_N)
    free = AxialRestraint(M, np.array([0.3]), np.array([KT]))
    walk = solve_axial_time_domain(free, load, normal, time_samples=512, max_periods=30)
    assert not walk.converged and walk.walk_m_per_period is not None and walk.walk_m_per_period < -0.01
    assert td.walk_m_per_period is None  # held by its lashings it settles: no walk


# ------------------------------------------------------------------------------ near the critical coefficient
def _ringing_case():
    """A base-case-like cargo: soft lashings, the normal force dipping briefly (the vertical solution's
    ringing after re-contact, 27 dips a period while the load pushes forward)."""
    t = np.arange(540) / 540
    ring = np.maximum(0.0, np.cos(2 * np.pi * 27 * t)) * (np.cos(2 * np.pi * t) > 0)
    normal = (12e6 * (1 + 0.08 * np.cos(2 * np.pi * t + 0.5)) * (1 - 0.04 * ring))[:, None]
    load = AxialLoad(0.6, np.array([0.0, 0.655e6 * np.exp(0.3j)]))
    # the load and the friction available per unit coefficient, finely sampled (C is linear between samples)
    tt = np.arange(8640) / 8640
    force = np.real(load.force_N[1] * np.exp(2j * np.pi * tt))
    total = np.interp(tt, np.r_[t, 1.0], np.r_[normal[:, 0], normal[0, 0]])
    return normal, load, force, total


def _shakedown_coefficient(force, total):
    """Below it no position holds the cargo: max(F - mu N) = min(F + mu N) (docs/axial.md)."""
    from scipy.optimize import brentq

    return brentq(lambda mu: np.max(force - mu * total) - np.min(force + mu * total), 1e-6, np.max(np.abs(force) / total))


def test_a_converged_locked_answer_obeys_the_friction_law():
    """Just below the shakedown coefficient the periodic state slips a little in the capacity's dips;
    the truncated series can balance its harmonics on a locked state whose friction demand exceeds the
    capacity there. A converged answer must be a real state: if it is locked, |F - r(u)| <= C at every
    sample (within the Newton tolerance); otherwise the solver says it did not converge."""
    normal, load, force, total = _ringing_case()
    mu_crit = float(np.max(np.abs(force) / total))
    mu_sd = _shakedown_coefficient(force, total)
    assert mu_sd < mu_crit
    for frac in (0.02, 0.05):
        mu = mu_sd - frac * (mu_crit - mu_sd)
        r = AxialRestraint(1.156e6, np.array([mu]), np.array([3e12]), lashing_axial_stiffness_N_per_m=37.5e3)
        hbm = solve_axial_hbm(r, load, normal, AxialHBMOptions(harmonics=100, time_samples=1080))
        demand = np.abs(hbm.load_N + hbm.lashing_force_N + hbm.stopper_force_N)  # what the friction must carry, stuck
        locked = hbm.slip_m <= 4 * np.max(hbm.capacity_N) / r.stick_stiffness_N_per_m
        if hbm.converged and locked:
            assert np.max(demand - hbm.capacity_N) <= 1e-6 * np.max(hbm.capacity_N)
        if not hbm.converged:
            assert hbm.lock_check in (LockCheck.VIOLATED, LockCheck.NOT_LOCKED) and hbm.residual_norm > 0.0


def test_lock_check_against_the_friction_law():
    """The check itself: a locked state whose demand exceeds the capacity at one sample is VIOLATED,
    the same state with the capacity raised there HOLDS, and a sliding state is not a lock."""
    r = AxialRestraint(M, np.array([0.5]), np.array([KT]), lashing_axial_stiffness_N_per_m=K)
    load = AxialLoad(0.6, np.array([0.0, 0.4 * P0], dtype=complex))
    N = 256
    cap = np.full(N, 0.5e6)
    u = np.full(N, -0.05)  # locked 5 cm aft: the lashings pull it forward with 50 kN
    for dip, expected in ((0.3e6, LockCheck.VIOLATED), (0.5e6, LockCheck.HOLDS)):
        c = cap.copy()
        c[N // 2] = dip  # at t = T/2 the load pushes aft with 0.4 MN, the lashings forward: 0.35 MN for the friction
        p = AxialProblem(r, load, c, 10, N)
        jen = march_jenkins(u, c, KT, w_init_m=-0.05)
        check, excess, sample = lock_check(p, jen, u, 1e-9)
        assert check is expected
        if expected is LockCheck.VIOLATED:
            assert sample == N // 2 and excess == pytest.approx(0.35e6 - 0.3e6, rel=1e-6)
    slide = np.sin(2 * np.pi * np.arange(N) / N)
    p = AxialProblem(r, load, cap, 10, N)
    assert lock_check(p, march_jenkins(slide, cap, KT), slide, 1e-9)[0] is LockCheck.NOT_LOCKED


def _walking(mu, k_a):
    t = np.arange(128) / 128
    normal = (1e6 * (1 + 0.5 * np.cos(2 * np.pi * t)))[:, None]  # most friction when the load pushes forward
    load = AxialLoad(0.6, np.array([0.0, 0.4 * P0], dtype=complex))
    return AxialRestraint(M, np.array([mu]), np.array([KT]), lashing_axial_stiffness_N_per_m=k_a), load, normal


@pytest.mark.parametrize("mu", [0.45, 0.6, 0.75])
@pytest.mark.parametrize("k_a", [2e5, 2e4])
def test_walk_into_shakedown_ends_at_the_edge_of_the_lock_range(mu, k_a):
    """Between the shakedown coefficient (0.4 here) and the critical one (0.8) the cargo cannot hold
    where it was set down but can hold off it: it walks, more slowly every period (the slip shrinks
    with the square of the distance left: a 1/n walk, which a geometric stopping rule stops early), to
    the edge of the positions where it holds: the lashings then carry -min(F + mu N) = (0.4 - mu/2) MN
    (the load 0.4 MN cos, the normal force 1 MN (1 + cos/2): the minimum at t = T/2, a sample of both
    solvers' grids). Both solvers land there; the reference says how far it stopped from the limit."""
    r, load, normal = _walking(mu, k_a)
    edge = (0.4 - 0.5 * mu) * 1e6
    td = solve_axial_time_domain(r, load, normal, time_samples=512)
    assert td.converged and td.slip_m == 0.0
    assert td.axial_force_N == pytest.approx(edge, rel=1e-6)
    assert np.all(td.displacement_m == pytest.approx(-edge / k_a, rel=1e-6))  # aft, where it stays
    assert 0.0 <= td.residual_drift_m <= 1e-7 * 0.4e6 / (M * 0.6**2)
    hbm = solve_axial_hbm(r, load, normal, AxialHBMOptions(harmonics=25, time_samples=512))
    assert hbm.converged and hbm.lock_check is LockCheck.HOLDS
    # within the contacts' elastic range 2 C / k_t times the lashings' and the inertia's stiffness (1.1 N at most)
    assert hbm.axial_force_N == pytest.approx(edge, abs=(k_a + M * 0.6**2) * 2 * 1.5e6 / KT)
    assert lock_range_m(r, td.load_N, td.capacity_N)[1] == pytest.approx(-edge / k_a, rel=1e-9)


def test_remaining_distance_bounds_geometric_and_algebraic_walks():
    """The stopping rule's estimate of the distance left is an upper bound (within 10 %) for a geometric
    walk and for the 1/n walk into shakedown, whose last step is far smaller than the distance left."""
    for n in (10, 100, 1000):
        steps = [1.0 / k - 1.0 / (k + 1) for k in range(1, n + 1)]  # distance 1/(n+1) left
        est = remaining_distance(steps)
        assert 1.0 / (n + 1) <= est <= 2.2 / (n + 1)
        assert steps[-1] < 0.01 * est or n == 10
    for rho in (0.5, 0.9, 0.99):
        steps = [rho**k for k in range(1, 30)]
        left = rho**30 / (1 - rho)
        assert left <= remaining_distance(steps) <= 2.2 * left / rho
    assert remaining_distance([1.0, 0.0]) == 0.0 and remaining_distance([1.0]) == math.inf
    assert remaining_distance([1.0, 1.0]) == math.inf


def test_a_walk_stopped_early_reports_its_residual_drift():
    """The reference stopped before its walk settles (too few periods) says it did not converge and how
    far it still is from the periodic state, in metres."""
    r, load, normal = _walking(0.3, 2e5)  # below the shakedown coefficient: the walk converges geometrically
    full = solve_axial_time_domain(r, load, normal, time_samples=512)
    early = solve_axial_time_domain(r, load, normal, time_samples=512, max_periods=4)
    assert full.converged and not early.converged
    off = abs(np.mean(early.displacement_m) - np.mean(full.displacement_m))
    assert early.residual_drift_m > 1e-7 * 0.4e6 / (M * 0.6**2)
    assert off <= 3 * early.residual_drift_m  # the estimate has the size of the distance left
    assert early.walk_m_per_period is None and full.residual_drift_m < early.residual_drift_m


def test_jacobian_of_a_cargo_locked_off_its_set_down_position():
    """Locked at the edge of its lock range, the slider sits at the band edge of the sample that bounds
    it and follows the cargo: the mean stiffness is the lashings' alone (finite differences)."""
    r, load, normal = _walking(0.6, 2e5)
    cap = r.capacity_N(np.repeat(normal, 2, axis=0))
    p = AxialProblem(r, load, cap, 5, 256)
    X = p.locked_guess()
    R, state = p.residual(X)
    jen = state.jenkins
    assert jen.slip_path_m == 0.0 and np.all(jen.last_slip == 128)  # clamped at t = T/2, no sample slips
    J = p.jacobian(state)
    # the mean moves the residual by k_a h only: a larger step there, above the residual's round-off (k_t 1e-16 m);
    # the harmonics below the 2e-10 m by which the neighbouring samples' band edges clear the bounding one
    steps = np.r_[1e-7, np.full(10, 1e-11)]
    fd = np.column_stack([(p.residual(X + h * e)[0] - R) / h for h, e in zip(steps, np.eye(11), strict=True)])
    assert J[0, 0] == pytest.approx(2e5, rel=1e-9) and fd[0, 0] == pytest.approx(2e5, rel=1e-2)
    assert np.max(np.abs(fd - J)) < 1e-4 * np.max(np.abs(J))


@pytest.mark.parametrize(("beta", "ratio"), [(0.6, 0.45), (0.6, 0.5), (0.8, 0.6), (1.5, 0.45), (1.5, 0.5), (1.5, 0.6)])
def test_den_hartog_at_large_friction(beta, ratio):
    """Friction 0.45 to 0.6 of the force amplitude, still sliding all period (no stops, Den Hartog's
    motion without stops): the stuck start has a smaller residual than the frictionless one but is the
    wrong state; the HBM converges from the sliding start (describing function) or the
    contact-stiffness continuation to the closed form within 2 % at H = 100 (1.1 % measured at most: the friction's reversals are
    resolved more slowly than at small friction), the time domain within 1e-4."""
    x0 = _den_hartog_amplitude(beta, ratio * 1e6)
    load = AxialLoad(beta, np.array([0.0, P0], dtype=complex))
    n = np.full((128, 1), 1e6)
    hbm = solve_axial_hbm(_oscillator(ratio), load, n, AxialHBMOptions(harmonics=100, time_samples=800))
    td = solve_axial_time_domain(_oscillator(ratio), load, n, time_samples=512)
    assert hbm.converged and td.converged and hbm.lock_check is LockCheck.NOT_LOCKED
    assert td.sliding.all()  # slides all period (no stops)
    assert 0.5 * np.ptp(hbm.displacement_m) == pytest.approx(x0, rel=0.02)
    assert 0.5 * np.ptp(td.displacement_m) == pytest.approx(x0, rel=1e-4)
    assert hbm.slip_m == pytest.approx(td.slip_m, rel=0.02)
