"""Frequency-response continuation: quasi-static far below resonance, linear peak, nonlinear pass, folds located."""

from __future__ import annotations

import numpy as np
import pytest
from threadpoolctl import threadpool_limits

from seafast.fourier import harmonics_to_time
from seafast.solvers.contact import ContactLaw
from seafast.solvers.continuation import BranchEnd, frequency_response
from seafast.solvers.floquet import floquet_multipliers, stability_system
from seafast.solvers.hbm import HBMOptions
from seafast.solvers.linear import solve_linear
from seafast.solvers.references import QuasiStaticOptions, solve_quasi_static
from solver_cases import base_model, uniform_heave, wave_excitation


@pytest.fixture(autouse=True, scope="module")
def _one_blas_thread():
    with threadpool_limits(1):
        yield


def deck_only(model, relative_mm):
    """Deck hog/sag only (no inertia load), constant amplitude: excitation at any omega."""
    return lambda w: wave_excitation(
        model, omega_rad_s=w, relative_mm=relative_mm, second_harmonic_mm=0.0, antisymmetric_mm=0.0, heave_m=0.0, pitch_rad=0.0
    )


def test_wave_frequencies_are_quasi_static():
    """Base case, 0.2-2 rad/s: the response is the quasi-static one (first mode ~42 rad/s)."""
    model = base_model(element_length_m=2.0)
    excitation_at = deck_only(model, 12.0)
    opts = HBMOptions(harmonics=10, time_samples=64, contact_law="exact")
    branch = frequency_response(model, excitation_at, 0.2, 2.0, opts)
    assert branch.converged.all() and branch.omega_rad_s[-1] == pytest.approx(2.0, rel=1e-6)
    assert branch.end is BranchEnd.REACHED_END
    assert not branch.contact_preserved.any()  # the middle saddle lifts off throughout
    qs = solve_quasi_static(model, excitation_at(0.2), QuasiStaticOptions(time_samples=64))
    figures = (
        f"omega 0.2..2 rad/s: max force {branch.max_saddle_force_N.min() / 1e6:.4f}..{branch.max_saddle_force_N.max() / 1e6:.4f} MN, "
        f"quasi-static {qs.max_saddle_force_N / 1e6:.4f} MN; {len(branch.omega_rad_s)} points"
    )
    # within the H = 10 truncation error (~0.5 % on the peak force here)
    assert branch.max_saddle_force_N[0] == pytest.approx(qs.max_saddle_force_N, rel=0.01), figures
    assert branch.max_gap_m[0] == pytest.approx(qs.max_gap_m, rel=0.05), figures
    # over the whole wave band the response changes by well under 1 %
    assert np.ptp(branch.max_saddle_force_N) / qs.max_saddle_force_N < 0.01, figures


def linear_peak(model, excitation_at, omegas, N):
    z = [np.abs(harmonics_to_time(solve_linear(model, excitation_at(w)).cargo_displacement[:, 0::2], N)).max() for w in omegas]
    return omegas[int(np.argmax(z))], max(z)


def test_linear_resonance_peak_matches_linear_frf():
    """Soft saddles (1 % of base): contact is kept through resonance, so HBM = linear FRF."""
    model = base_model(element_length_m=2.0, stiffness_scale=0.01)
    excitation_at = deck_only(model, 1.0)
    opts = HBMOptions(harmonics=2, time_samples=16, contact_law="exact")
    branch = frequency_response(model, excitation_at, 1.0, 10.0, opts)
    assert branch.converged.all() and branch.contact_preserved.all()
    w_lin, z_lin = linear_peak(model, excitation_at, np.linspace(1.0, 10.0, 3601), 16)
    figures = (
        f"continuation peak {branch.peak_omega_rad_s:.4f} rad/s vs linear FRF {w_lin:.4f} rad/s "
        f"(first natural frequency {model.natural_frequencies_rad_s(True, 2)[1]:.4f}); {len(branch.omega_rad_s)} points"
    )
    assert branch.peak_omega_rad_s == pytest.approx(w_lin, rel=0.02), figures
    assert branch.max_cargo_deflection_m.max() == pytest.approx(z_lin, rel=0.02), figures


def test_nonlinear_resonance_is_passed_with_lift_off():
    model = base_model(element_length_m=2.0, stiffness_scale=0.01)
    opts = HBMOptions(harmonics=3, time_samples=32, contact_law="tanh")
    # 40 mm of deck hog/sag: with the realised 2 % damping of the bounce mode (it was once about 1 %)
    # the 20 mm this test used no longer lifts the cargo off at resonance
    branch = frequency_response(model, deck_only(model, 40.0), 1.0, 10.0, opts)
    assert branch.converged.all() and branch.omega_rad_s[-1] == pytest.approx(10.0, rel=1e-6)
    assert branch.end is BranchEnd.REACHED_END
    assert not branch.contact_preserved.all() and branch.max_gap_m.max() > 1e-3
    assert 4.5 < branch.peak_omega_rad_s < 5.6


def test_a_fold_is_located_at_the_extreme_of_omega_where_a_multiplier_is_plus_one():
    """The bounce resonance's softening fold pair (uniform 20 mm deck heave, 1 % saddles, H = 16): each turn of
    the branch is a located point beyond both neighbours in omega, and there a Floquet multiplier is +1, as at a
    fold: closer to +1 than a third of its distance at either neighbouring step point (measured 3e-4 and 2e-3 at
    the folds, against 2e-2 and 1e-2 at the nearest steps; the located point is within 1e-3 of the steps around
    it, and the multiplier's distance grows like the square root of the distance from the fold in omega)."""
    model = base_model(element_length_m=2.0, stiffness_scale=0.01)
    opts = HBMOptions(harmonics=16, time_samples=512, contact_law="exact", tolerance=1e-8)
    branch = frequency_response(model, uniform_heave(model, 0.02), 4.8, 6.0, opts)
    assert branch.end is BranchEnd.REACHED_END and branch.converged.all()
    turns = branch.turning_indices
    w = branch.omega_rad_s
    system = stability_system(model, 6.0, 16)
    exact = ContactLaw("exact")

    def from_plus_one(i: int) -> float:
        mu = floquet_multipliers(model, w[i], branch.compression_harmonics_m[i], exact, system=system).multipliers
        return float(np.min(np.abs(mu - 1.0)))

    distance = [from_plus_one(i) for i in turns]
    neighbours = [min(from_plus_one(i - 1), from_plus_one(i + 1)) for i in turns]
    figures = f"turns at {w[turns]} rad/s, located {np.nonzero(branch.at_fold)[0]}, multipliers {distance} from +1 ({neighbours} beside)"
    assert turns.size == 2 and 5.1 < w[turns[0]] < 5.4 and 4.9 < w[turns[1]] < w[turns[0]], figures
    np.testing.assert_array_equal(np.nonzero(branch.at_fold)[0], turns, err_msg=figures)
    assert w[turns[0]] > max(w[turns[0] - 1], w[turns[0] + 1]) and w[turns[1]] < min(w[turns[1] - 1], w[turns[1] + 1]), figures
    assert all(d < neighbour / 3.0 for d, neighbour in zip(distance, neighbours, strict=True)) and max(distance) < 1e-2, figures


def test_invalid_sweep_is_rejected():
    model = base_model(element_length_m=8.0)
    with pytest.raises(ValueError, match="omega"):
        frequency_response(model, deck_only(model, 1.0), 1.0, 1.0)


def test_a_branch_whose_first_point_fails_says_so():
    model = base_model()
    # one Newton step of the smooth law cannot reach 1e-14 (the exact law's piecewise-linear system can)
    options = HBMOptions(harmonics=10, contact_law="tanh", max_iterations=1, continuation=False, tolerance=1e-14)
    branch = frequency_response(model, wave_excitation(model).at_frequency, 0.5, 1.0, options)
    assert branch.end is BranchEnd.FIRST_POINT_FAILED and branch.converged.tolist() == [False]
