"""HBM against the exact-contact references (quasi-static and time domain), and random cases."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, example, given, settings
from hypothesis import strategies as st
from threadpoolctl import threadpool_limits

from seafast.config.arrangement import evenly_spaced_saddles
from seafast.config.modes import Formulation, SolverMethod
from seafast.excitation.harmonic import HarmonicExcitation
from seafast.model.seafastening import SeaFastening
from seafast.model.sections import CargoGeometry, TubeSegment
from seafast.model.structure import build_structural_model
from seafast.solvers.contact import ContactLaw
from seafast.solvers.exact_contact import solve_exact_contact
from seafast.solvers.hbm import HBMOptions, condensed_operators, solve_hbm
from seafast.solvers.hbm.condensed import CondensedProblem
from seafast.solvers.hbm.nonlinear import solve_with_fallback
from seafast.solvers.linear import solve_linear
from seafast.solvers.newton import NewtonStop
from seafast.solvers.outcome import HBMPath, HBMRoute, HBMStart, SolverOutcome, SolverWarning
from seafast.solvers.periodic import PeriodicResponse
from seafast.solvers.references import (
    QUASI_STATIC_RATIO_LIMIT,
    QuasiStaticOptions,
    TimeDomainOptions,
    solve_quasi_static,
    solve_time_domain,
)
from solver_cases import base_model, moments, wave_excitation


@pytest.fixture(autouse=True, scope="module")
def _one_blas_thread():
    with threadpool_limits(1):
        yield


def force_error(r: PeriodicResponse, ref: PeriodicResponse) -> float:
    """max over time and saddles of |F - F_ref|, over max F_ref."""
    return float(np.max(np.abs(r.saddle_force_time_N - ref.saddle_force_time_N)) / np.max(ref.saddle_force_time_N))


def moment_error(model, r: PeriodicResponse, ref: PeriodicResponse) -> float:
    m, m_ref = moments(model, r), moments(model, ref)
    return float(np.max(np.abs(m - m_ref)) / np.max(np.abs(m_ref)))


@pytest.fixture(scope="module")
def base():
    model = base_model()
    ex = wave_excitation(model)
    with threadpool_limits(1):
        qs = solve_quasi_static(model, ex)
        td = solve_time_domain(model, ex)
    return model, ex, qs, td


def test_references_agree_with_each_other(base):
    model, _, qs, td = base
    assert qs.converged and td.converged
    assert qs.outcome is SolverOutcome.CONVERGED and qs.warnings == ()
    assert qs.options["frequency_ratio"] <= QUASI_STATIC_RATIO_LIMIT  # quasi-statics justified
    assert not qs.contact_preserved and qs.max_gap_m > 1e-3
    e_f, e_m = force_error(td, qs), moment_error(model, td, qs)
    assert e_f < 0.01 and e_m < 0.01, f"time domain vs quasi-static: force {e_f:.2%}, moment {e_m:.2%} ({td.message})"
    assert td.saddle_force_time_N.min() >= 0 and qs.saddle_force_time_N.min() >= 0


def test_hbm_exact_law_matches_references(base):
    model, ex, qs, td = base
    r = solve_hbm(model, ex, HBMOptions(harmonics=20, time_samples=128, contact_law="exact"))
    assert r.converged
    rows = {name: (force_error(r, ref), moment_error(model, r, ref)) for name, ref in (("quasi-static", qs), ("time domain", td))}
    for name, (e_f, e_m) in rows.items():
        assert e_f < 0.01 and e_m < 0.01, f"HBM exact H=20 vs {name}: saddle force {e_f:.3%}, bending moment {e_m:.3%}"
    # the peaks (design values) agree much better than the worst sample near a contact switch
    assert r.max_saddle_force_N == pytest.approx(td.max_saddle_force_N, rel=2e-3)
    assert np.abs(moments(model, r)).max() == pytest.approx(np.abs(moments(model, td)).max(), rel=2e-3)


def test_regularised_law_error_against_exact_reference(base):
    """The source's tanh law (kappa = 1000 1/m) vs the exact time-domain reference.

    Measured on this case: about 1.4 % of the largest saddle force (worst sample, with H >= 8);
    it does not shrink with H because it is the law's own error (a tension of up to
    0.139 k / kappa = 153 kN just after lift-off, and a softer force near zero compression).
    The exact law converges to the reference instead. Softplus overestimates the force near
    zero compression (k ln2 / kappa = 0.76 MN at delta = 0).
    """
    model, ex, _, td = base
    lines = []
    errors = {}
    for law in ("tanh", "softplus", "exact"):
        for H in (5, 20):
            r = solve_hbm(model, ex, HBMOptions(harmonics=H, time_samples=128, contact_law=law))
            assert r.converged
            errors[law, H] = (force_error(r, td), moment_error(model, r, td), r.tensile_force_error_N)
            lines.append(
                f"{law:9s} H={H:2d}: force {errors[law, H][0]:.3%}  moment {errors[law, H][1]:.3%}  "
                f"tension {r.tensile_force_error_N / 1e3:.0f} kN"
            )
    figures = "error vs exact time-domain reference (kappa = 1000 1/m):\n" + "\n".join(lines)
    tanh_err = errors["tanh", 20][0]
    assert 0.005 < tanh_err < 0.03, figures  # the documented ~1.4 %
    assert errors["exact", 20][0] < tanh_err, figures
    assert errors["tanh", 20][2] == pytest.approx(0.1392 * 1.1e9 / 1000, rel=0.02), figures


def test_harmonic_convergence_exact_law(base):
    model, ex, qs, td = base
    table = []
    for H in range(1, 21):
        r = solve_hbm(model, ex, HBMOptions(harmonics=H, time_samples=128, contact_law="exact"))
        assert r.converged, (H, r.message)
        table.append((H, force_error(r, qs), force_error(r, td), moment_error(model, r, td), float(r.harmonic_truncation_indicator.max())))
    figures = "\n".join(
        [" H  force vs QS  force vs TD  moment vs TD  energy above H"]
        + [f"{H:2d}  {a:10.3%}  {b:10.3%}  {c:11.3%}  {d:12.2e}" for H, a, b, c, d in table]
    )
    err = np.array([row[2] for row in table])
    assert err[-1] < 0.01, figures
    assert err[-1] < err[4] < err[0], figures
    # error decreasing: every H >= 8 beats every H <= 3
    assert err[7:].max() < err[:3].min(), figures
    indicator = np.array([row[4] for row in table])
    assert indicator[-1] < indicator[0], figures


def test_quasi_static_warns_for_a_seesaw(base):
    """Outer saddles lifting together leave the cargo rocking on the middle saddle (~0.1 rad/s)."""
    model = base[0]
    qs = solve_quasi_static(model, wave_excitation(model, relative_mm=16.0, second_harmonic_mm=0.0))
    assert qs.warnings == (SolverWarning.QUASI_STATICS_QUESTIONABLE,) and qs.options["frequency_ratio"] > QUASI_STATIC_RATIO_LIMIT
    assert qs.converged


def test_a_still_water_reference_is_exactly_static(base):
    """The static load case has no dynamics to justify: no warning, whatever the cargo's frequencies."""
    model, ex = base[0], base[1]
    soft = base_model(stiffness_scale=1e-3)
    for m in (model, soft):
        qs = solve_quasi_static(m, ex.static_part(), QuasiStaticOptions(time_samples=2))
        assert qs.warnings == () and qs.options["effective_harmonic"] == 0 and qs.options["frequency_ratio"] == 0.0
    # the same soft model in the wave: its dynamics matter, and the reference says so
    assert solve_quasi_static(soft, wave_excitation(soft)).warnings == (SolverWarning.QUASI_STATICS_QUESTIONABLE,)


def test_exact_contact_solver_small_problem():
    G = np.array([[5e-10, 1e-10], [1e-10, 5e-10]])
    k = np.array([1e9, 1e9])
    d_lin = np.array([[1e-3, 2e-3], [-1e-3, 2e-3], [-1e-3, -1e-3]])
    d, c = solve_exact_contact(d_lin, G, k)
    assert np.allclose(d + c @ G.T, d_lin, atol=1e-15)
    assert np.all(c >= 0) and np.all((c == 0) | (d < 0)) and np.all((d >= 0) | (c > 0))


def test_time_domain_rejects_bad_steps(base):
    model, ex = base[0], base[1]
    with pytest.raises(ValueError, match="steps_per_period"):
        solve_time_domain(model, ex, TimeDomainOptions(time_samples=128, steps_per_period=1000))


# ---------------------------------------------------------------------- random cases
def random_case(n_saddles: int, stiffness_factors, amplitude: float, phases, static_mm, heave_m: float, element_length_m=4.0):
    length = 74.0
    xs = evenly_spaced_saddles(n_saddles, length)
    lashed = np.zeros(n_saddles, dtype=bool)
    lashed[[0, -1]] = True
    sf = SeaFastening(xs, 1.1e9 * np.asarray(stiffness_factors), lashed)
    model = build_structural_model(CargoGeometry((TubeSegment(0, length, 8, 8, 0.08),)), sf, target_element_length_m=element_length_m)
    n_o, n_c, n_e = model.deck_dof_count, model.cargo_dof_count, model.cargo.element_count
    xo = np.zeros((2, n_o), dtype=complex)
    xo[0, 0::2] = np.asarray(static_mm) * 1e-3
    static = solve_linear(model, HarmonicExcitation(0.6, xo[:1], np.zeros((1, n_c)), np.zeros((1, n_e))))
    scale = float(np.mean(np.abs(static.saddle_compression_m[0])))
    xo[1, 0::2] = amplitude * scale * np.exp(1j * np.asarray(phases))
    load = np.zeros((2, n_c), dtype=complex)
    u = np.zeros(n_c)
    u[0::2] = heave_m
    load[1] = -model.cargo.mass @ (-(0.6**2) * u)
    return model, HarmonicExcitation(0.6, xo, load, np.zeros((2, n_e), dtype=complex), source="random")


case_strategy = st.integers(2, 7).flatmap(
    lambda n: st.tuples(
        st.just(n),
        st.lists(st.floats(np.log10(0.01), np.log10(10.0)), min_size=n, max_size=n).map(lambda v: 10.0 ** np.array(v)),
        st.floats(0.1, 2.5),
        st.lists(st.floats(0, 2 * np.pi), min_size=n, max_size=n),
        st.lists(st.floats(-3.0, 3.0), min_size=n, max_size=n),
        st.floats(-2.0, 2.0),
    )
)


def neglected_inertia(model, qs: PeriodicResponse) -> tuple[np.ndarray, np.ndarray]:
    """What the quasi-static reference neglects, to first order: its own motion's inertia.

    The d'Alembert load ``-M a(t)`` of the quasi-static cargo motion (``a`` by spectral
    differentiation of the N samples), applied statically in each instant's contact state
    (the saddles that the reference finds detached removed from K). Returns the saddle-force
    change (N, n_s) [N] and the cargo-DOF change (N, n_c) [m, rad]. At a frequency ratio r the
    dynamic response amplifies it by at most ``1 / (1 - r^2)``.
    """
    N = qs.time_samples
    spectrum = np.fft.rfft(qs.cargo_displacement_time_m, axis=0)
    k = np.arange(spectrum.shape[0])[:, None]
    acceleration = np.fft.irfft(-((k * qs.omega_rad_s) ** 2) * spectrum, n=N, axis=0)
    load = -acceleration @ np.asarray(model.cargo.mass, dtype=float).T
    K = np.asarray(model.dynamic_stiffness(0.0, True)[0], dtype=float)
    k_u = np.asarray(model.saddle_unilateral_stiffness_N_per_m, dtype=float)
    sad = model.saddle_cargo_dof
    force = np.zeros((N, model.saddle_count))
    displacement = np.zeros_like(load)
    for n in range(N):
        detached = qs.saddle_compression_time_m[n] <= 0.0
        K_n = K.copy()
        K_n[sad, sad] -= k_u * detached
        displacement[n] = np.linalg.solve(K_n, load[n])
        force[n] = np.where(detached, 0.0, -k_u * displacement[n, sad])
    return force, displacement


def above_harmonic(signal: np.ndarray, harmonics: int) -> float:
    """Largest |signal - its first ``harmonics`` harmonics| over the samples: what H harmonics cannot represent."""
    spectrum = np.fft.rfft(signal, axis=0)
    spectrum[harmonics + 1 :] = 0.0
    return float(np.max(np.abs(signal - np.fft.irfft(spectrum, n=signal.shape[0], axis=0))))


HBM_QS_SAFETY = 2.0
"""Margin on the first-order estimate below: over 1574 random cases of this strategy the
largest measured difference was 0.96 of it (peak force), 0.93 (peak deflection) and 0.89
(compression at a contact-state mismatch)."""
HBM_QS_FLOOR = 1e-3
"""Share of each quantity's scale left to what the first-order estimate omits (the Rayleigh
damping forces the reference also neglects, higher-order dynamics, round-off)."""


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(case_strategy)
def test_random_cases_hbm_consistent_with_quasi_static(case):
    """Where quasi-statics is justified (the reference says so: H_eff omega / omega_1 <= 0.2), the
    exact-law HBM (H = 10) agrees with the quasi-static reference within what separates them:

    * the cargo's inertia, which the reference neglects: to first order the static response to
      the d'Alembert load of its own motion (:func:`neglected_inertia`), amplified by
      ``1 / (1 - r^2)`` at the case's frequency ratio r (up to 4 % at r = 0.2 -- more than the
      old fixed 2 %, which is why that test failed now and then);
    * the HBM's truncation: the reference's content above H (:func:`above_harmonic`);
    * where a saddle lifts off, the gap: the detached cargo is free to move within it, and its
      position there is set by dynamics, not statics (deflections and compressions only);

    with the margin :data:`HBM_QS_SAFETY` and the floor :data:`HBM_QS_FLOOR`. Contact states are
    compared, and must agree, wherever the compression is clear of zero by that same tolerance
    (a median 12 % of the compression scale over random cases); near a switch they may differ.
    """
    n, factors, amplitude, phases, static_mm, heave = case
    H = 10
    with threadpool_limits(1):
        model, ex = random_case(n, factors, amplitude, phases, static_mm, heave)
        qs = solve_quasi_static(model, ex, QuasiStaticOptions(time_samples=64))
        for law in ("exact", "softplus"):
            r = solve_hbm(model, ex, HBMOptions(harmonics=H, time_samples=64, contact_law=law))
            if r.converged:
                assert r.saddle_force_time_N.min() >= 0.0
        r = solve_hbm(model, ex, HBMOptions(harmonics=H, time_samples=64, contact_law="exact"))
    ratio = qs.options["frequency_ratio"]
    assume(ratio <= QUASI_STATIC_RATIO_LIMIT)
    # near the quasi-static state a periodic solution exists and the predictor starts next to it
    assert r.converged, r.message
    amplification = 1.0 / (1.0 - ratio**2)
    inertia_force, inertia_displacement = neglected_inertia(model, qs)
    gap = max(qs.max_gap_m, r.max_gap_m)

    def tolerance(first_order: float, reference: np.ndarray, free_play: float) -> float:
        return HBM_QS_SAFETY * (
            amplification * first_order + above_harmonic(reference, H) + free_play + HBM_QS_FLOOR * float(np.max(np.abs(reference)))
        )

    tol_force = tolerance(float(np.max(np.abs(inertia_force))), qs.saddle_force_time_N, 0.0)
    assert abs(r.max_saddle_force_N - qs.max_saddle_force_N) <= tol_force
    z_qs = qs.cargo_displacement_time_m[:, 0::2]
    tol_z = tolerance(float(np.max(np.abs(inertia_displacement[:, 0::2]))), z_qs, gap)
    assert abs(r.max_cargo_deflection_m() - qs.max_cargo_deflection_m()) <= tol_z
    delta_qs = qs.saddle_compression_time_m
    tol_delta = tolerance(float(np.max(np.abs(inertia_displacement[:, model.saddle_cargo_dof]))), delta_qs, gap)
    clear = np.abs(delta_qs) > tol_delta
    assert np.array_equal(r.contact_state[clear], qs.contact_state[clear])


NO_STEADY_STATE_CASE = (3, 10.0 ** np.array([0.25, 0.0, -2.0]), 2.0, [0.1875, 2.0, 0.0], [0.0, 0.0, 0.0], 0.0)
"""Found by Hypothesis: a 1 % saddle and deck motions out of phase rock the cargo far above its
lowest contact state's frequency (H_eff omega / omega_1 = 22.6, gaps of 30 to 55 mm). The
time-domain reference does not become periodic in 200 periods (change 1.5 % per period); the
exact-law HBM reports NOT_CONVERGED at H = 10 and finds different periodic solutions at H = 5
and H = 20 (gaps 54 and 30 mm)."""


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(case_strategy)
@example(NO_STEADY_STATE_CASE)
def test_random_cases_hbm_reports_how_it_ended(case):
    """Anywhere in the strategy, quasi-static or far from it: the HBM returns (never raises) and its
    typed outcome is what its residual says. Convergence itself is required only where a periodic
    state near the quasi-static one exists (the test above); far above the cargo's lowest contact
    frequency the steady state may not be periodic at all (:data:`NO_STEADY_STATE_CASE`)."""
    n, factors, amplitude, phases, static_mm, heave = case
    tolerance = 1e-10
    with threadpool_limits(1):
        model, ex = random_case(n, factors, amplitude, phases, static_mm, heave)
        r = solve_hbm(model, ex, HBMOptions(harmonics=10, time_samples=64, contact_law="exact", tolerance=tolerance))
    assert np.isfinite(r.residual_norm) and np.all(np.isfinite(r.saddle_force_time_N))
    assert r.converged == (r.residual_norm <= tolerance), (r.outcome, r.residual_norm)
    assert r.outcome in (SolverOutcome.CONVERGED, SolverOutcome.CONVERGED_BY_CONTINUATION, SolverOutcome.NOT_CONVERGED)
    assert r.saddle_force_time_N.min() >= 0.0  # the exact law never pulls, converged or not


@settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(case_strategy)
def test_random_cases_condensed_equals_full(case):
    n, factors, amplitude, phases, static_mm, heave = case
    with threadpool_limits(1):
        model, ex = random_case(n, factors, amplitude, phases, static_mm, heave, element_length_m=8.0)
        opts = dict(harmonics=3, time_samples=16, contact_law="tanh")
        rc = solve_hbm(model, ex, HBMOptions(**opts))
        rf = solve_hbm(model, ex, HBMOptions(formulation="full", **opts))
    assume(rc.converged and rf.converged)
    assert np.abs(rf.saddle_force_time_N - rc.saddle_force_time_N).max() <= 1e-6 * max(rc.max_saddle_force_N, 1.0)


# ---------------------------------------------------------------------- full-DOF vs condensed time domain
def displacement_error(r: PeriodicResponse, ref: PeriodicResponse) -> float:
    d = r.cargo_displacement_time_m - ref.cargo_displacement_time_m
    return float(np.max(np.abs(d)) / np.max(np.abs(ref.cargo_displacement_time_m)))


def test_time_domain_default_is_the_full_dof_formulation(base):
    td = base[3]
    assert td.method is SolverMethod.TIME_DOMAIN and td.options["formulation"] == Formulation.FULL
    assert td.options["steps_per_period"] == 16 * 128 and td.options["contact_states_factorised"] >= 1  # the full-DOF integrator's record


def test_time_domain_full_equals_condensed(base):
    """Both formulations integrate the same discrete HHT-alpha equations (the condensed one holds
    the saddles bilateral in K and cancels their tension; the full one has the unilateral springs
    outside K_lin) from the same start (the linear periodic solution): they differ only by
    round-off, bounded by the period-to-period tolerance."""
    model, ex, qs, td = base
    tc = solve_time_domain(model, ex, TimeDomainOptions(formulation="condensed"))
    assert tc.converged and tc.options["formulation"] == Formulation.CONDENSED and "contact_states_factorised" not in tc.options
    e_f, e_x = force_error(td, tc), displacement_error(td, tc)
    assert e_f < 1e-6 and e_x < 1e-6, f"full-DOF vs condensed time domain: force {e_f:.1e}, displacement {e_x:.1e}"
    assert np.array_equal(td.contact_state, tc.contact_state)
    # full-DOF reference vs quasi-static: design value (peak saddle force)
    assert td.max_saddle_force_N == pytest.approx(qs.max_saddle_force_N, rel=0.01)


TWO_ORBIT_CASE = (3, np.array([0.08420277, 1.0, 1.0]), 1.1423779289169924, [0.84375, 4.265625, 0.296875], [0.0, -2.25, -2.75], 1.625)
"""Found by Hypothesis: two saddles lift off (gaps of 6 mm and 1-2 mm) and each re-contact rings
the cargo's 21 rad/s mode. With 16 steps per output sample (512 per period, omega_1 dt = 0.43) the
non-smooth discrete map has more than one periodic orbit: the two formulations, when they started
from different states (as they once did), settled on two periodic states 0.2 % apart in saddle force.
From their common start (the linear periodic solution) they reach the same one, to 3e-11."""


@settings(max_examples=5, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(case_strategy)
@example(TWO_ORBIT_CASE)
def test_random_cases_time_domain_full_equals_condensed(case):
    """Both formulations integrate the same discrete equations from the same start, so
    they reach the same periodic state even at a step where the discrete map has several
    (16 per output sample, see :data:`TWO_ORBIT_CASE`), to the period-to-period tolerance."""
    n, factors, amplitude, phases, static_mm, heave = case
    with threadpool_limits(1):
        model, ex = random_case(n, factors, amplitude, phases, static_mm, heave, element_length_m=8.0)
        rf = solve_time_domain(model, ex, TimeDomainOptions(time_samples=32, formulation="full", steps_per_period=16 * 32))
        rc = solve_time_domain(model, ex, TimeDomainOptions(time_samples=32, formulation="condensed", steps_per_period=16 * 32))
    assume(rf.converged and rc.converged)
    scale = max(rc.max_saddle_force_N, 1.0)
    assert np.abs(rf.saddle_force_time_N - rc.saddle_force_time_N).max() <= 1e-6 * scale
    assert displacement_error(rf, rc) < 1e-6


@pytest.fixture(scope="module")
def real_case():
    from seafast.config import load_case
    from seafast.excitation.vessel import vessel_excitation
    from seafast.model.from_case import build_model

    case = load_case()
    model = build_model(case)
    return model, vessel_excitation(case).cargo_excitation(model, case)


def test_time_domain_full_real_case(real_case):
    """Real base case (fore saddle lifts off): full == condensed, and the peak saddle force of the
    full-DOF reference within 1 % of the quasi-static one."""
    model, ex = real_case
    tf = solve_time_domain(model, ex, TimeDomainOptions(time_samples=128))
    tc = solve_time_domain(model, ex, TimeDomainOptions(time_samples=128, formulation="condensed"))
    qs = solve_quasi_static(model, ex, QuasiStaticOptions(time_samples=128))
    assert tf.converged and tc.converged and qs.converged
    assert tf.options["formulation"] == "full"
    e_f, e_x = force_error(tf, tc), displacement_error(tf, tc)
    e_peak = abs(tf.max_saddle_force_N / qs.max_saddle_force_N - 1.0)
    figures = (
        f"real case: full vs condensed TD force {e_f:.1e}, displacement {e_x:.1e}; full TD vs QS peak force {e_peak:.3%} ({tf.message})"
    )
    assert e_f < 1e-6 and e_x < 1e-6, figures
    assert e_peak < 0.01, figures
    assert not tf.contact_preserved and tf.saddle_force_time_N.min() >= 0.0


@pytest.mark.parametrize("formulation", ["full", "condensed"])
def test_time_domain_non_convergence_is_reported(base, formulation):
    model, ex = base[0], base[1]
    r = solve_time_domain(model, ex, TimeDomainOptions(time_samples=16, formulation=formulation, max_periods=2, tolerance=1e-15))
    assert not r.converged and r.outcome is SolverOutcome.NOT_PERIODIC
    assert not r.orbit.periodic and r.orbit.periods == r.iterations == 2 and r.residual_norm > 1e-15
    assert r.saddle_force_time_N.shape == (16, model.saddle_count)


def test_time_domain_rejects_bad_formulation(base):
    model, ex = base[0], base[1]
    with pytest.raises(ValueError, match=r"formulation.*'full', 'condensed'"):
        solve_time_domain(model, ex, TimeDomainOptions(formulation="dense"))


def test_exact_law_converges_from_the_sharpest_soft_solution_reached():
    """The fallback's continuation in kappa, exercised deterministically: from the mirrored linear solution (every
    compressed saddle lifted as far as it was compressed) Newton on the exact law stagnates, the softplus path of
    rising kappa converges, and the exact law started from its sharpest solution converges: a solution of the
    exact-law balance (residual at tolerance, no saddle pulls), the softplus solution's to 1 %. This near-resonant
    case (a 1 % saddle) has more than one periodic solution at H = 10; the path decides which one is reached."""
    model, ex = random_case(3, np.array([0.01, 1.0, 1.0]), 1.0, [3.0, 0.0, 1.0], [0.0, 0.0, 0.0], 2.0)
    options = HBMOptions(harmonics=10, time_samples=64, contact_law="exact")
    problem = CondensedProblem(condensed_operators(model, ex, 10), 64)
    mirrored = -problem.initial_guess(1.0)
    with threadpool_limits(1):
        direct = solve_with_fallback(problem, options.law, replace(options, continuation=False), u_start=mirrored)
        attempt = solve_with_fallback(problem, options.law, options, u_start=mirrored)
        soft = solve_with_fallback(problem, ContactLaw("softplus", 1e4 / problem.compression_scale_m), options, u_start=mirrored)
    assert not direct.converged and direct.path.route is HBMRoute.NONE  # the direct solve from this start fails
    assert attempt.converged and attempt.by_continuation and attempt.outcome is SolverOutcome.CONVERGED_BY_CONTINUATION
    assert attempt.path == HBMPath(HBMStart.GIVEN, HBMRoute.KAPPA_CONTINUATION, NewtonStop.CONVERGED)
    residual, _ = problem.evaluate(attempt.u, options.law, 1.0)
    assert np.max(np.abs(residual)) <= options.tolerance * problem.scale
    compression = problem.to_samples(attempt.u.reshape(problem.n_h, problem.n_s))
    force = options.law.force(compression, problem.k_u)
    assert force.min() >= 0.0 and np.any(compression < 0.0)  # a saddle lifts off, and none pulls
    soft_force = ContactLaw("softplus", 1e4 / problem.compression_scale_m).force(
        problem.to_samples(soft.u.reshape(problem.n_h, problem.n_s)), problem.k_u
    )
    assert soft.converged and force.max() == pytest.approx(soft_force.max(), rel=0.01)
