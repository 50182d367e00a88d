"""The banded dynamic stiffness of the cargo DOFs (solvers/dynamic_stiffness.py): the same numbers as the
model's dense K_d(w), the stacked per-harmonic solve, and the matrices kept with the model that owns them."""

from __future__ import annotations

import dataclasses

import numpy as np

from seafast.solvers.dynamic_stiffness import from_band, quadratic_matrices, solve_dynamic, solve_dynamic_stack
from solver_cases import base_model


def test_the_banded_quadratic_matrices_are_the_models_dynamic_stiffness():
    model = base_model(element_length_m=4.0)
    q = quadratic_matrices(model, True)
    for w in (0.0, 0.6, 45.0):
        Kd_cc, Kd_co, _, _ = model.dynamic_stiffness(w, include_saddles=True)
        banded = from_band(q.banded_stiffness - w**2 * q.banded_mass + 1j * w * q.banded_damping, q.bandwidth)
        np.testing.assert_allclose(banded, Kd_cc, rtol=0, atol=1e-12 * np.max(np.abs(Kd_cc)))
        np.testing.assert_allclose(q.coupling_stiffness + 1j * w * q.coupling_damping, Kd_co, rtol=0, atol=1e-12 * np.max(np.abs(Kd_co)))


def test_the_stacked_solve_is_one_dense_solve_per_harmonic():
    """To 1e-8 of the largest displacement: K_d's condition number (a free beam on its saddle springs, ~1e7 at
    w = 0) times round-off separates the compiled banded LU from LAPACK's dense one (measured 7e-11)."""
    model = base_model()  # 150 DOFs, half-bandwidth 3: the compiled banded path
    q = quadratic_matrices(model, True)
    omegas = 0.6 * np.arange(4)
    rhs = np.random.default_rng(5).standard_normal((4, model.cargo_dof_count, 2)).astype(complex)
    stacked = solve_dynamic_stack(q, omegas, rhs)
    for k, w in enumerate(omegas):
        dense = np.linalg.solve(model.dynamic_stiffness(float(w), True)[0], rhs[k])
        scale = np.max(np.abs(dense))
        np.testing.assert_allclose(stacked[k], dense, rtol=0, atol=1e-8 * scale)
        np.testing.assert_allclose(solve_dynamic(q, float(w), rhs[k]), dense, rtol=0, atol=1e-8 * scale)


def test_the_matrices_are_kept_with_the_model_that_owns_them():
    """Computed once and held in the model's derived_cache (no module-level cache): the same object for the
    same model; a copy with other damping starts empty and gets its own D."""
    model = base_model(element_length_m=4.0)
    q = quadratic_matrices(model, True)
    assert quadratic_matrices(model, True) is q and q in model.derived_cache.values()
    assert quadratic_matrices(model, False) is not q
    stiffer_damping = dataclasses.replace(model, rayleigh_beta_s=2.0 * model.rayleigh_beta_s)
    assert stiffer_damping.derived_cache == {}
    q2 = quadratic_matrices(stiffer_damping, True)
    assert q2 is not q and np.max(np.abs(q2.banded_damping - q.banded_damping)) > 0.1 * np.max(np.abs(q.banded_damping))
