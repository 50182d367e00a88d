"""The correction system reduced to the cargo's lowest modes (solvers/modal_correction.py): its receptance
against the full model's, the pole sum against the per-frequency reduced solve, and the modal basis kept
with the model that owns it (grown when asked for more modes)."""

from __future__ import annotations

import numpy as np

from seafast.solvers.modal_correction import modal_basis, modal_correction_system
from solver_cases import base_model


def _full_receptance(model, w: float) -> np.ndarray:
    """``B^T K_d(w)^-1 B`` of the full model, saddles bilateral [m/N]."""
    Kd = model.dynamic_stiffness(w, include_saddles=True)[0]
    sad = model.saddle_cargo_dof
    B = np.zeros((model.cargo_dof_count, sad.size))
    B[sad, np.arange(sad.size)] = 1.0
    return B.T @ np.linalg.solve(Kd, B)


def test_every_mode_kept_gives_the_full_models_receptance():
    """All 42 modes, through the 84 x 84 state matrix's eigenvectors: the full model's receptance to 1e-7
    (measured 2e-12 at 0.6 rad/s, 3e-9 at the first mode's 44 rad/s and at 300 rad/s: the eigenvectors' round-off)."""
    model = base_model(element_length_m=4.0)
    system = modal_correction_system(model, np.inf)
    assert system.mode_count == model.cargo_dof_count
    for w in (0.0, 0.6, 44.0, 300.0):
        full = _full_receptance(model, w)
        np.testing.assert_allclose(system.receptance(np.array([w]))[0], full, rtol=0, atol=1e-7 * np.max(np.abs(full)))


def test_the_pole_sum_is_the_reduced_solve_and_the_residual_flexibility_makes_statics_exact():
    """Four modes and the static residual of the rest: the pole sum equals Phi_s (Omega^2 - w^2 + i w Xi)^-1
    Phi_s^T + R to round-off (1e-12; measured 4e-15), and at w = 0 the full static flexibility (1e-10: the full
    model's dense solve against the banded one; measured 6e-12)."""
    model = base_model()
    system = modal_correction_system(model, 200.0)
    assert 1 <= system.mode_count < 10
    Omega2, Xi, Ps, R = (
        np.diag(system.natural_frequency_rad_s**2),
        system.modal_damping,
        system.saddle_mode_shape,
        system.residual_flexibility_m_per_N,
    )
    for w in (0.3, 20.0, 60.0):
        direct = Ps @ np.linalg.solve(Omega2 - w**2 * np.eye(system.mode_count) + 1j * w * Xi, Ps.T) + R
        np.testing.assert_allclose(system.receptance(np.array([w]))[0], direct, rtol=0, atol=1e-12 * np.max(np.abs(direct)))
    static = _full_receptance(model, 0.0)
    np.testing.assert_allclose(system.receptance(np.array([0.0]))[0].real, static, rtol=0, atol=1e-10 * np.max(np.abs(static)))


def test_the_modal_basis_is_kept_with_its_model_and_grows_when_asked_for_more():
    model = base_model(element_length_m=0.25)  # 594 DOFs: the lowest modes by shift-invert Lanczos
    low = modal_basis(model, 100.0)
    assert not low.complete and low.natural_frequency_rad_s[-1] > 100.0
    assert modal_basis(model, 50.0) is low and low in model.derived_cache.values()  # a lower cutoff: the kept basis
    high = modal_basis(model, 3.0 * float(low.natural_frequency_rad_s[-1]))
    assert high is not low and high.natural_frequency_rad_s.size > low.natural_frequency_rad_s.size
    assert modal_basis(model, 50.0) is high  # the grown basis replaced the smaller one
    np.testing.assert_allclose(high.natural_frequency_rad_s[: low.natural_frequency_rad_s.size], low.natural_frequency_rad_s, rtol=1e-9)
    assert base_model(element_length_m=0.25).derived_cache == {}  # another model, however equal, has its own
