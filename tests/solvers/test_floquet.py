"""Floquet multipliers of periodic orbits: known answers, and a perturbation marched in time.

* contact kept all period: the orbit is the linear system's, whose multipliers are
  ``exp(lambda T)`` with lambda the eigenvalues of the full (unreduced) quadratic problem;
* a saddle detached all period: the multipliers of the model without that saddle;
* an orbit on the middle branch of a softening fold: a perturbation marched by the Newmark
  integration of the correction system grows by the leading multiplier per period.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.linalg import eig
from threadpoolctl import threadpool_limits

from seafast.fourier import harmonics_to_time, real_to_complex_harmonics
from seafast.solvers.contact import ContactLaw
from seafast.solvers.continuation import frequency_response
from seafast.solvers.floquet import floquet_multipliers, stability_system
from seafast.solvers.hbm import HBMOptions, condensed_operators
from seafast.solvers.transient import MarchState, march_period, newmark_step
from solver_cases import base_model, uniform_heave, wave_excitation

EXACT = ContactLaw("exact")


@pytest.fixture(autouse=True, scope="module")
def _one_blas_thread():
    with threadpool_limits(1):
        yield


@pytest.fixture(scope="module")
def soft_model():
    return base_model(element_length_m=2.0, stiffness_scale=0.01)


def _spectrum(model, K):
    """Eigenvalues of M q'' + D q' + K q = 0 on all cargo DOFs, sorted by decreasing real part."""
    M, D = model.cargo.mass, model.damping_cc
    n = K.shape[0]
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-np.linalg.solve(M, K), -np.linalg.solve(M, D)]])
    lam = eig(A, right=False)
    return lam[np.argsort(-lam.real)]


def test_contact_kept_all_period_gives_the_linear_multipliers(soft_model):
    model, w = soft_model, 3.0
    ex = wave_excitation(model, omega_rad_s=w, relative_mm=1.0, second_harmonic_mm=0.0, antisymmetric_mm=0.0, heave_m=0.0, pitch_rad=0.0)
    U = condensed_operators(model, ex, 3).linear_compression_m
    assert np.all(harmonics_to_time(real_to_complex_harmonics(U), 256) > 0.3)  # every saddle compressed all period
    floquet = floquet_multipliers(model, w, U, EXACT)
    lam = _spectrum(model, model.dynamic_stiffness(0.0, True)[0])
    expected = np.exp(lam[0].real * 2 * np.pi / w)  # the least damped mode
    figures = f"largest |multiplier| {floquet.max_modulus:.10f}, exp(Re(lambda_1) T) = {expected:.10f}"
    assert floquet.max_modulus == pytest.approx(expected, rel=1e-6), figures
    assert floquet.stable and floquet.switching_times_s.size == 0
    # the four leading moduli are the two lowest modes' (complex pairs)
    top = np.sort(np.abs(np.exp(lam * 2 * np.pi / w)))[::-1][:4]
    assert np.abs(floquet.multipliers[:4]) == pytest.approx(top, rel=1e-6)


def test_a_saddle_detached_all_period_gives_the_model_without_it(soft_model):
    model, w = soft_model, 3.0
    U = np.zeros((7, 3))
    U[0] = [-0.01, 0.3, 0.3]  # aft saddle lifted by 1 cm for the whole period, the others compressed
    floquet = floquet_multipliers(model, w, U, EXACT)
    K = model.dynamic_stiffness(0.0, True)[0].copy()
    i = model.saddle_cargo_dof[0]
    K[i, i] -= model.saddle_unilateral_stiffness_N_per_m[0]
    lam = _spectrum(model, K)
    expected = np.exp(lam[0] * 2 * np.pi / w)
    figures = f"leading multiplier {floquet.leading_multiplier:.6f}, without the saddle {expected:.6f}"

    def distance(mu: complex) -> float:  # to the expected multiplier or its conjugate (a pair)
        return min(abs(mu - expected), abs(np.conj(mu) - expected))

    # the modes above the cutoff enter through their static flexibility only: 1e-4
    assert distance(floquet.leading_multiplier) < 1e-4 * abs(expected), figures
    with_saddle = floquet_multipliers(model, w, np.abs(U), EXACT)
    assert distance(with_saddle.leading_multiplier) > 0.1  # the check tells the two models apart


def test_a_perturbation_of_an_unstable_orbit_grows_by_the_leading_multiplier(soft_model):
    """Middle branch of the bounce resonance's softening fold: march the orbit's own state and watch it leave."""
    model = soft_model
    H = 16
    opts = HBMOptions(harmonics=H, contact_law="exact", tolerance=1e-8).with_harmonics(H)
    excitation_at = uniform_heave(model, 0.02)
    branch = frequency_response(model, excitation_at, 4.8, 6.0, opts)
    fold = int(branch.turning_indices[0])
    i = fold + int(np.argmin(np.abs(branch.omega_rad_s[fold:] - 5.1)))  # past the fold, on the way back
    w, U = float(branch.omega_rad_s[i]), branch.compression_harmonics_m[i]
    system = stability_system(model, w, H)
    floquet = floquet_multipliers(model, w, U, EXACT, system=system)
    assert not floquet.stable and floquet.leading_multiplier.imag == 0.0 and floquet.max_modulus > 1.05
    # the orbit's state in the reduced system's coordinates: modal response to its correction forces
    N = 4096
    delta = harmonics_to_time(real_to_complex_harmonics(U), N)
    c = system.unilateral_stiffness_N_per_m * np.maximum(-delta, 0.0)
    C = np.fft.rfft(c, axis=0) / N
    C[1:] *= 2.0
    kw = np.arange(C.shape[0]) * w
    m = system.mode_count
    eta = np.stack(
        [
            np.linalg.solve(
                np.diag(system.natural_frequency_rad_s**2) - k**2 * np.eye(m) + 1j * k * system.modal_damping,
                system.saddle_mode_shape.T @ C[j],
            )
            for j, k in enumerate(kw)
        ]
    )
    state = MarchState(eta.sum(0).real, (1j * kw[:, None] * eta).sum(0).real, (-(kw[:, None] ** 2) * eta).sum(0).real, c[0], c[0] > 0.0)
    linear = harmonics_to_time(real_to_complex_harmonics(condensed_operators(model, excitation_at(w), H).linear_compression_m), N)
    marcher = newmark_step(model, 2 * np.pi / w / N, system.cutoff_rad_s, minimum_modes=0)  # the same modes
    assert marcher.mode_count == m
    deviation = []
    for _ in range(60):
        compression = march_period(marcher, linear, state)
        deviation.append(float(np.max(np.abs(compression - delta))))
    d = np.asarray(deviation)
    grow = np.nonzero((d > 30 * d[0]) & (d < 0.05 * np.ptp(delta)))[0]  # the leading mode dominates, still small
    assert grow.size >= 4
    rate = float(np.exp(np.polyfit(grow, np.log(d[grow]), 1)[0]))
    figures = f"omega {w:.4f} rad/s: leading multiplier {floquet.max_modulus:.4f}, marched growth per period {rate:.4f}"
    assert rate == pytest.approx(floquet.max_modulus, rel=0.02), figures
    assert d[-1] > 0.2 * np.ptp(delta)  # it left the orbit for good


def test_bad_input_is_refused(soft_model):
    with pytest.raises(ValueError, match="omega_rad_s"):
        floquet_multipliers(soft_model, 0.0, np.zeros((3, 3)), EXACT)
    with pytest.raises(ValueError, match="saddles"):
        floquet_multipliers(soft_model, 1.0, np.zeros((3, 2)), EXACT)
