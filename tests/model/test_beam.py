"""Verification of the beam finite elements against closed-form beam theory.

Conventions under test (beam.py): z up, theta = dz/dx, nodal loads (F_z up, M in +theta sense),
bending moment M = EI z'' sagging positive. Euler-Bernoulli Hermite elements with consistent
loads are nodally exact for uniform beams under point and uniform loads, so the static checks
use tight tolerances (1e-9 relative); the eigenvalue check carries discretisation error.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.linalg import eigh

from seafast.model.beam import (
    assemble_beam,
    beam_element_mass,
    beam_element_stiffness,
    bending_moment_line,
    element_end_moments,
    uniform_load_vector,
)
from seafast.model.sections import tube_area_m2, tube_second_moment_m4

RTOL = 1e-9

L = 10.0
EI = 2.0e8
MPL = 500.0  # kg/m


def _chain(n_el: int, length: float = L, ei: float = EI, q: float | None = None, gas: float | None = None):
    x = np.linspace(0.0, length, n_el + 1)
    eis = np.full(n_el, ei)
    ms = np.full(n_el, MPL)
    qs = None if q is None else np.full(n_el, q)
    gass = None if gas is None else np.full(n_el, gas)
    K, M, f = assemble_beam(x, eis, ms, shear_stiffness_N=gass, load_N_per_m=qs)
    return x, eis, gass, qs, K, M, f


def _solve_fixed(K: np.ndarray, f: np.ndarray, fixed: list[int]) -> np.ndarray:
    n = K.shape[0]
    free = np.setdiff1d(np.arange(n), fixed)
    u = np.zeros(n)
    u[free] = np.linalg.solve(K[np.ix_(free, free)], f[free])
    return u


# --------------------------------------------------------------------------- cantilever
@pytest.mark.parametrize("n_el", [1, 3, 8])
def test_cantilever_tip_load(n_el: int) -> None:
    P = 1.0e4  # magnitude, applied downward
    x, eis, _, _, K, _, f = _chain(n_el)
    f[-2] = -P
    u = _solve_fixed(K, f, [0, 1])
    assert u[-2] == pytest.approx(-P * L**3 / (3 * EI), rel=RTOL)
    assert u[-1] == pytest.approx(-P * L**2 / (2 * EI), rel=RTOL)  # tip slope dz/dx < 0
    xs, m = bending_moment_line(x, u, eis)
    assert xs[0] == 0.0
    assert m[0] == pytest.approx(-P * L, rel=RTOL)  # hogging root moment, negative
    # linear moment line M(x) = -P (L - x) everywhere
    np.testing.assert_allclose(m, -P * (L - xs), rtol=0, atol=RTOL * P * L)


@pytest.mark.parametrize("n_el", [1, 4, 10])
def test_cantilever_uniform_load(n_el: int) -> None:
    q = 2.0e3  # magnitude, downward
    x, eis, _, qs, K, _, f = _chain(n_el, q=-q)
    u = _solve_fixed(K, f, [0, 1])
    assert u[-2] == pytest.approx(-q * L**4 / (8 * EI), rel=RTOL)
    assert u[-1] == pytest.approx(-q * L**3 / (6 * EI), rel=RTOL)
    xs, m = bending_moment_line(x, u, eis, load_N_per_m=qs)
    assert m[0] == pytest.approx(-q * L**2 / 2, rel=RTOL)
    np.testing.assert_allclose(m, -q * (L - xs) ** 2 / 2, rtol=0, atol=RTOL * q * L**2)
    # deflection at interior nodes: z(x) = -q x^2 (6L^2 - 4Lx + x^2) / (24 EI)
    z_exact = -q * x**2 * (6 * L**2 - 4 * L * x + x**2) / (24 * EI)
    np.testing.assert_allclose(u[0::2], z_exact, rtol=0, atol=RTOL * q * L**4 / EI)


# --------------------------------------------------------------------------- simply supported
@pytest.mark.parametrize("n_el", [2, 4, 10])
def test_simply_supported_uniform_load(n_el: int) -> None:
    q = 3.0e3  # downward
    x, eis, _, qs, K, _, f = _chain(n_el, q=-q)
    u = _solve_fixed(K, f, [0, 2 * n_el])
    mid = n_el // 2
    assert u[2 * mid] == pytest.approx(-5 * q * L**4 / (384 * EI), rel=RTOL)
    assert u[1] == pytest.approx(-q * L**3 / (24 * EI), rel=RTOL)
    assert u[-1] == pytest.approx(+q * L**3 / (24 * EI), rel=RTOL)
    xs, m = bending_moment_line(x, u, eis, load_N_per_m=qs)
    np.testing.assert_allclose(m, q * xs * (L - xs) / 2, rtol=0, atol=RTOL * q * L**2)
    assert m.max() == pytest.approx(q * L**2 / 8, rel=RTOL)  # sagging, positive
    # reactions: K u - f at the support z DOFs = q L / 2 upward each
    r = K @ u - f
    assert r[0] == pytest.approx(q * L / 2, rel=RTOL)
    assert r[2 * n_el] == pytest.approx(q * L / 2, rel=RTOL)


def test_simply_supported_midspan_point_load() -> None:
    P = 5.0e4
    n_el = 6
    x, eis, _, _, K, _, f = _chain(n_el)
    f[n_el] = -P  # z DOF of the middle node (node n_el/2 -> DOF n_el)
    u = _solve_fixed(K, f, [0, 2 * n_el])
    assert u[n_el] == pytest.approx(-P * L**3 / (48 * EI), rel=RTOL)
    xs, m = bending_moment_line(x, u, eis)
    assert m.max() == pytest.approx(P * L / 4, rel=RTOL)
    np.testing.assert_allclose(m, P * np.minimum(xs, L - xs) / 2, rtol=0, atol=RTOL * P * L)
    m0, m1 = element_end_moments(x, u, eis)
    # moment continuous across nodes (no applied nodal moments)
    np.testing.assert_allclose(m1[:-1], m0[1:], rtol=0, atol=RTOL * P * L)


def test_moment_line_complex_amplitudes_and_batch() -> None:
    """Moments are linear in the displacement: complex and stacked inputs work elementwise."""
    q = 1.0e3
    x, eis, _, qs, K, _, f = _chain(4, q=-q)
    u = _solve_fixed(K, f, [0, 8])
    stacked = np.stack([u, 2j * u])
    _, m = bending_moment_line(x, stacked, eis, load_N_per_m=np.stack([qs, 2j * qs]))
    _, m_ref = bending_moment_line(x, u, eis, load_N_per_m=qs)
    tol = 1e-12 * q * L**2
    np.testing.assert_allclose(m[0], m_ref, rtol=0, atol=tol)
    np.testing.assert_allclose(m[1], 2j * m_ref, rtol=0, atol=tol)


# --------------------------------------------------------------------------- Timoshenko
def test_timoshenko_deep_cantilever_exact() -> None:
    """Timoshenko element: tip deflection P L^3/(3EI) + P L/(G A_s), exact for any mesh."""
    Ld, ei, gas, P = 4.0, 5.0e9, 2.0e8, 1.0e6  # deep: shear part is large
    exact = -(P * Ld**3 / (3 * ei) + P * Ld / gas)
    assert P * Ld / gas > 0.5 * P * Ld**3 / (3 * ei)  # genuinely shear dominated
    for n_el in (1, 2, 5):
        x, eis, gass, _, K, _, f = _chain(n_el, length=Ld, ei=ei, gas=gas)
        f[-2] = -P
        u = _solve_fixed(K, f, [0, 1])
        assert u[-2] == pytest.approx(exact, rel=RTOL)
        # the cross-section rotation is the bending part only: -P L^2 / (2EI)
        assert u[-1] == pytest.approx(-P * Ld**2 / (2 * ei), rel=RTOL)
        _, m = bending_moment_line(x, u, eis, shear_stiffness_N=gass)
        assert m[0] == pytest.approx(-P * Ld, rel=RTOL)
    # Euler-Bernoulli on the same beam misses the shear part
    x, eis, _, _, K, _, f = _chain(2, length=Ld, ei=ei)
    f[-2] = -P
    u_eb = _solve_fixed(K, f, [0, 1])
    assert u_eb[-2] == pytest.approx(-P * Ld**3 / (3 * ei), rel=RTOL)


def test_timoshenko_tends_to_euler_bernoulli_for_slender_beams() -> None:
    ke_eb = beam_element_stiffness(L, EI)
    assert np.array_equal(ke_eb, beam_element_stiffness(L, EI, None))
    np.testing.assert_allclose(beam_element_stiffness(L, EI, np.inf), ke_eb, rtol=0, atol=0)
    prev = np.inf
    for gas in (1e8, 1e10, 1e12, 1e14):
        diff = np.max(np.abs(beam_element_stiffness(L, EI, gas) - ke_eb)) / np.max(np.abs(ke_eb))
        assert diff < prev
        prev = diff
    assert prev < 1e-6
    np.testing.assert_allclose(beam_element_mass(L, MPL, EI, 1e14), beam_element_mass(L, MPL), rtol=1e-6)


# --------------------------------------------------------------------------- mass
@pytest.mark.parametrize("gas", [None, 5.0e7])
def test_consistent_mass_rigid_body_integrals(gas: float | None) -> None:
    """u^T M u reproduces int m w^2 dx for the rigid-body fields (translation and rotation)."""
    n_el = 5
    x, *_rest, M, _ = _chain(n_el, gas=gas)
    trans = np.zeros(2 * (n_el + 1))
    trans[0::2] = 1.0
    rot = np.zeros_like(trans)
    rot[0::2] = x
    rot[1::2] = 1.0
    assert trans @ M @ trans == pytest.approx(MPL * L, rel=1e-12)
    assert rot @ M @ rot == pytest.approx(MPL * L**3 / 3, rel=1e-12)  # rotary term about x = 0
    assert trans @ M @ rot == pytest.approx(MPL * L**2 / 2, rel=1e-12)  # first moment
    # symmetric and positive definite
    np.testing.assert_allclose(M, M.T, rtol=0, atol=1e-12 * np.abs(M).max())
    assert np.linalg.eigvalsh(M).min() > 0


def test_element_mass_classical_hermite_entries() -> None:
    Le, m = 2.0, 300.0
    ref = (
        m
        * Le
        / 420
        * np.array(
            [
                [156, 22 * Le, 54, -13 * Le],
                [22 * Le, 4 * Le**2, 13 * Le, -3 * Le**2],
                [54, 13 * Le, 156, -22 * Le],
                [-13 * Le, -3 * Le**2, -22 * Le, 4 * Le**2],
            ]
        )
    )
    np.testing.assert_allclose(beam_element_mass(Le, m), ref, rtol=1e-12)


def test_element_stiffness_classical_entries() -> None:
    Le = 2.0
    ref = (
        EI
        / Le**3
        * np.array(
            [
                [12, 6 * Le, -12, 6 * Le],
                [6 * Le, 4 * Le**2, -6 * Le, 2 * Le**2],
                [-12, -6 * Le, 12, -6 * Le],
                [6 * Le, 2 * Le**2, -6 * Le, 4 * Le**2],
            ]
        )
    )
    np.testing.assert_allclose(beam_element_stiffness(Le, EI), ref, rtol=1e-12)


def test_pinned_pinned_frequency_of_base_monopile() -> None:
    Lm, D, t, E, rho = 74.0, 8.0, 0.08, 210e9, 7850.0
    A = float(tube_area_m2(D, t))
    I_m4 = float(tube_second_moment_m4(D, t))
    assert I_m4 == pytest.approx(15.6, rel=0.01)  # docs/theory.md#21-cargo-beam
    n_el = 74
    x = np.linspace(0.0, Lm, n_el + 1)
    K, M, _ = assemble_beam(x, np.full(n_el, E * I_m4), np.full(n_el, rho * A))
    free = np.setdiff1d(np.arange(K.shape[0]), [0, 2 * n_el])
    w2 = eigh(K[np.ix_(free, free)], M[np.ix_(free, free)], eigvals_only=True, subset_by_index=[0, 2])
    w = np.sqrt(w2)
    exact = (np.pi / Lm) ** 2 * np.sqrt(E * I_m4 / (rho * A))
    assert 25.0 < exact < 26.5
    assert w[0] == pytest.approx(exact, rel=5e-3)
    # higher modes follow n^2
    assert w[1] == pytest.approx(4 * exact, rel=5e-3)
    assert w[2] == pytest.approx(9 * exact, rel=5e-3)


def test_uniform_load_vector_integrates_the_load() -> None:
    Le, q = 3.0, -1234.0
    fe = uniform_load_vector(Le, q)
    assert fe[0] + fe[2] == pytest.approx(q * Le, rel=1e-14)
    # moment about the element start: int q x dx = q L^2/2 = F2 L + M1 + M2
    assert fe[2] * Le + fe[1] + fe[3] == pytest.approx(q * Le**2 / 2, rel=1e-14)
    np.testing.assert_allclose(fe, [q * Le / 2, q * Le**2 / 12, q * Le / 2, -q * Le**2 / 12], rtol=1e-14)
    # assembled: total load over a non-uniform chain
    x = np.array([0.0, 1.0, 2.5, 6.0])
    qs = np.array([-10.0, -20.0, 5.0])
    _, _, f = assemble_beam(x, np.ones(3), np.ones(3), load_N_per_m=qs)
    assert f[0::2].sum() == pytest.approx(float(np.sum(qs * np.diff(x))), rel=1e-14)
    assert f[0::2] @ x + f[1::2].sum() == pytest.approx(float(np.sum(qs * np.diff(x) * 0.5 * (x[1:] + x[:-1]))), rel=1e-14)


def test_nonuniform_mesh_cantilever_uniform_load() -> None:
    """Unequal element lengths change nothing: still nodally exact."""
    q = 1.5e3
    x = np.array([0.0, 0.7, 2.0, 4.4, 7.1, 10.0])
    n_el = x.size - 1
    eis = np.full(n_el, EI)
    qs = np.full(n_el, -q)
    K, _, f = assemble_beam(x, eis, np.full(n_el, MPL), load_N_per_m=qs)
    u = _solve_fixed(K, f, [0, 1])
    assert u[-2] == pytest.approx(-q * L**4 / (8 * EI), rel=RTOL)
    xs, m = bending_moment_line(x, u, eis, load_N_per_m=qs)
    np.testing.assert_allclose(m, -q * (L - xs) ** 2 / 2, rtol=0, atol=RTOL * q * L**2)


@pytest.mark.parametrize("timoshenko", [False, True])
def test_banded_stiffness_assembly_equals_the_dense_one(timoshenko):
    from seafast.model.beam import assemble_beam_stiffness_banded

    rng = np.random.default_rng(7)
    x = np.sort(np.concatenate([[0.0, 171.0], rng.uniform(0.0, 171.0, 120)]))
    EI = rng.uniform(1e12, 3e13, x.size - 1)
    GA = rng.uniform(1e10, 5e10, x.size - 1) if timoshenko else None
    K, _, _ = assemble_beam(x, EI, np.zeros(x.size - 1), shear_stiffness_N=GA)
    band = assemble_beam_stiffness_banded(x, EI, GA)
    assert band.shape == (4, K.shape[0])  # half-bandwidth 3: O(n) storage
    for d in range(4):
        np.testing.assert_array_equal(band[3 - d, d:], np.diagonal(K, d))
    assert np.count_nonzero(np.triu(K, 4)) == 0  # nothing outside the band
