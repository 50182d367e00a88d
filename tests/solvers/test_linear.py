"""Verification of the linear (bilateral saddle) solver in its partitioned form (docs/theory.md#4-linear-model).

    K_d^cc x^c = f^c - K_d^co x^o,      f^o = K_d^oc x^c + K_d^oo x^o

f^o is the force the deck must exert on the springs to impose its motion; the force the cargo
(through the springs) exerts on the deck is -f^o. For a z deck DOF f^o equals the total spring
force pushing the cargo up (saddle part plus lashing k_z part).
"""

from __future__ import annotations

import numpy as np
import pytest

from seafast.excitation.harmonic import HarmonicExcitation
from seafast.model.beam import bending_moment_line
from seafast.model.seafastening import SeaFastening
from seafast.model.sections import CargoGeometry, TubeSegment, tube_area_m2
from seafast.model.structure import StructuralModel, build_structural_model
from seafast.solvers.linear import solve_harmonic, solve_linear

LM, G = 74.0, 9.81
BASE_X = np.array([14.8, 37.0, 59.2])
T_L = 210e3


def _model(element_length_m: float = 1.0, geometry: CargoGeometry | None = None, **sf_kw) -> StructuralModel:
    geometry = geometry or CargoGeometry((TubeSegment(0.0, LM, 8.0, 8.0, 0.08),))
    kw = dict(saddle_x_m=BASE_X, saddle_stiffness_N_per_m=np.full(3, 1.1e9), lashed=np.array([True, False, True]))
    kw.update(sf_kw)
    return build_structural_model(geometry, SeaFastening(**kw), target_element_length_m=element_length_m)


def _excitation(model: StructuralModel, omega: float, deck_rows, load_rows=None) -> HarmonicExcitation:
    deck = np.array(deck_rows, dtype=complex)
    n_k = deck.shape[0]
    load = np.zeros((n_k, model.cargo_dof_count), dtype=complex) if load_rows is None else np.array(load_rows, dtype=complex)
    return HarmonicExcitation(omega, deck, load, np.zeros((n_k, model.cargo.element_count), dtype=complex))


def _raised_middle(model: StructuralModel, dz: float) -> np.ndarray:
    xo = np.zeros(model.deck_dof_count)
    xo[2 * (model.saddle_count // 2)] = dz
    return xo


def _weight(model: StructuralModel) -> float:
    return model.cargo.mass_kg * model.gravity_m_per_s2


def _static_moment(model: StructuralModel, resp) -> np.ndarray:
    _, m = bending_moment_line(
        model.cargo.node_x_m,
        resp.cargo_displacement[0].real,
        model.cargo.element_bending_stiffness_Nm2,
        load_N_per_m=model.cargo.gravity_line_load_N_per_m,
    )
    return m


# --------------------------------------------------------------------------- static
def test_flat_deck_equilibrium_and_deck_forces() -> None:
    model = _model()
    resp = solve_linear(model, _excitation(model, 0.6, [np.zeros(model.deck_dof_count)]))
    W = _weight(model)
    assert W == pytest.approx(7850 * float(tube_area_m2(8.0, 0.08)) * LM * G, rel=1e-12)
    kz = model.seafastening.lashing_vertical_stiffness_N_per_m
    spring = (resp.saddle_force_N[0] + kz * resp.saddle_compression_m[0]).real
    assert spring.sum() == pytest.approx(W + T_L, rel=1e-9)
    # saddle forces alone (without the 6.5 kN/m lashing springs) to the lashing share
    assert resp.saddle_force_N[0].real.sum() == pytest.approx(W + T_L, rel=1e-5)
    assert np.all(resp.saddle_force_N[0].real > 0)
    # forces needed at the deck: z rows = spring force on the cargo; the cargo loads the deck with -f^o
    fo = resp.deck_force_N[0].real
    np.testing.assert_allclose(fo[model.saddle_deck_dof], spring, rtol=1e-9)
    assert fo[model.saddle_deck_dof].sum() == pytest.approx(W + T_L, rel=1e-9)
    # theta rows: rotational lashing moment k_theta (theta_deck - theta_cargo)
    kt = model.seafastening.lashing_rotational_stiffness_Nm_per_rad
    th_c = resp.cargo_displacement[0, model.saddle_cargo_dof + 1].real
    np.testing.assert_allclose(fo[model.saddle_deck_dof + 1], kt * (0.0 - th_c), rtol=1e-9, atol=1e-6)
    # global moment balance of the cargo about x = 0 (counter-clockwise positive): spring forces
    # and spring moments on the cargo (the moment k_theta (theta_o - theta_c) = f^o_theta) balance
    # the weight at mid-length and the pretension at the lashed saddles
    x_s = model.saddle_x_m
    lhs = spring @ x_s + fo[model.saddle_deck_dof + 1].sum()
    rhs = W * LM / 2 + (T_L / 2) * (x_s[0] + x_s[2])
    assert lhs == pytest.approx(rhs, rel=1e-9)
    # the static response is real
    assert np.all(resp.cargo_displacement[0].imag == 0)


def test_partitioned_equations_hold() -> None:
    model = _model(2.0)
    rng = np.random.default_rng(1)
    omega = 3.7
    xo = rng.normal(size=model.deck_dof_count) * 1e-3 + 1j * rng.normal(size=model.deck_dof_count) * 1e-3
    f = rng.normal(size=model.cargo_dof_count) * 1e4
    xc = solve_harmonic(model, omega, f, xo)
    Kcc, Kco, Koc, _ = model.dynamic_stiffness(omega, True)
    np.testing.assert_allclose(Kcc @ xc + Kco @ xo, f, rtol=0, atol=1e-6 * np.abs(f).max())
    # the deck sees the springs only; the cargo also the damping of its motion relative to the supports' quasi-static motion
    springs = model.spring_matrices(True)[1]
    np.testing.assert_array_equal(Koc, springs.T)
    np.testing.assert_allclose(Kco, springs + 1j * omega * model.support_damping_coupling, rtol=1e-14)
    # multiple right-hand sides at once equal the columns solved one by one
    xo2 = np.stack([xo, 2 * xo], axis=1)
    f2 = np.stack([f, -f], axis=1)
    X2 = solve_harmonic(model, omega, f2, xo2)
    np.testing.assert_allclose(X2[:, 0], xc, rtol=1e-10)
    np.testing.assert_allclose(X2[:, 1], solve_harmonic(model, omega, -f, 2 * xo), rtol=1e-10)


def test_static_calibration_raised_middle_saddle() -> None:
    """docs/theory.md calibration: still water, middle deck point 5.75 mm up -> F ~ 6.3 MN, M_b ~ 49.3 MNm."""
    model = _model()
    resp = solve_linear(model, _excitation(model, 0.6, [_raised_middle(model, 5.75e-3)]))
    F = resp.saddle_force_N[0].real
    assert F[1] == pytest.approx(6.3e6, rel=0.03)
    assert F.max() == F[1]
    assert F[0] == pytest.approx(F[2], rel=1e-6)
    m = _static_moment(model, resp)
    assert np.abs(m).max() == pytest.approx(49.3e6, rel=0.03)
    assert m.min() == pytest.approx(-np.abs(m).max())  # hogging over the middle saddle
    # max saddle compression 5.7 mm and max cargo deflection (relative frame) ~ 5.9 mm
    assert resp.saddle_compression_m[0].real.max() == pytest.approx(5.7e-3, rel=0.03)
    # equilibrium still holds with the prescribed deck
    kz = model.seafastening.lashing_vertical_stiffness_N_per_m
    spring = F + kz * resp.saddle_compression_m[0].real
    assert spring.sum() == pytest.approx(_weight(model) + T_L, rel=1e-9)


def test_symmetric_layout_gives_equal_outer_forces() -> None:
    for xo_mid in (0.0, 3e-3):
        model = _model(1.0)
        resp = solve_linear(model, _excitation(model, 0.6, [_raised_middle(model, xo_mid)]))
        F = resp.saddle_force_N[0].real
        assert F[0] == pytest.approx(F[2], rel=1e-8)
    # five saddles, symmetric deck hog: pairs equal
    xs = np.linspace(0.2, 0.8, 5) * LM
    model = _model(1.0, saddle_x_m=xs, saddle_stiffness_N_per_m=np.full(5, 1.1e9), lashed=np.array([1, 0, 0, 0, 1], bool))
    xo = np.zeros(model.deck_dof_count)
    s = (xs - LM / 2) / (0.3 * LM)
    xo[0::2] = 4e-3 * (1 - s**2)
    xo[1::2] = 4e-3 * (-2 * s / (0.3 * LM))
    F = solve_linear(model, _excitation(model, 0.6, [xo])).saddle_force_N[0].real
    assert F[0] == pytest.approx(F[4], rel=1e-8)
    assert F[1] == pytest.approx(F[3], rel=1e-8)


def test_mirror_image_layout_mirrors_forces() -> None:
    xs = np.array([10.0, 30.0, 61.0])
    a = _model(1.0, saddle_x_m=xs)
    b = _model(1.0, saddle_x_m=LM - xs[::-1])
    Fa = solve_linear(a, _excitation(a, 0.6, [np.zeros(6)])).saddle_force_N[0].real
    Fb = solve_linear(b, _excitation(b, 0.6, [np.zeros(6)])).saddle_force_N[0].real
    np.testing.assert_allclose(Fa, Fb[::-1], rtol=1e-7)


# --------------------------------------------------------------------------- dynamic
def test_quasi_static_limit() -> None:
    """omega far below the first natural frequency (~44 rad/s): dynamic = static, same deck shape."""
    model = _model(2.0)
    xo = np.zeros(model.deck_dof_count, dtype=complex)
    x = model.saddle_x_m
    xo[0::2] = 4e-3 * np.sin(np.pi * x / LM) + 2e-3j * (x / LM - 0.5)
    xo[1::2] = 4e-3 * np.pi / LM * np.cos(np.pi * x / LM) + 2e-3j / LM
    omega = 0.05
    dyn = solve_linear(model, _excitation(model, omega, [np.zeros(model.deck_dof_count), xo]))
    # static response to the real and the imaginary deck parts (no gravity): solve with K alone
    zero = np.zeros(model.cargo_dof_count)
    x_static = solve_harmonic(model, 0.0, zero, xo.real) + 1j * solve_harmonic(model, 0.0, zero, xo.imag)
    np.testing.assert_allclose(dyn.cargo_displacement[1], x_static, rtol=0, atol=1e-3 * np.abs(x_static).max())
    F_static = (xo[0::2] - x_static[model.saddle_cargo_dof]) * model.saddle_unilateral_stiffness_N_per_m
    np.testing.assert_allclose(dyn.saddle_force_N[1], F_static, rtol=0, atol=1e-3 * np.abs(F_static).max())
    # the harmonic does not disturb the static row
    stat = solve_linear(model, _excitation(model, omega, [np.zeros(model.deck_dof_count)]))
    np.testing.assert_allclose(dyn.cargo_displacement[0], stat.cargo_displacement[0], rtol=1e-12)


def test_resonance_of_rigid_cargo_on_two_springs_follows_dynamic_stiffness() -> None:
    """A very stiff beam on two soft, symmetric springs: bounce is a 1-DOF oscillator.

    Deck heave Z at both saddles, the textbook base excitation (the damping acts on the motion
    relative to the quasi-static support motion, here the rigid translation Z):
    X = (2k + i omega c) Z / (2k - omega^2 m + i omega c), with c = alpha m (Rayleigh beta K_beam
    does no work on a rigid translation). Damping on the motion relative to the rigid-body frame
    instead would drop the ``i omega c`` of the numerator: 2.5 % at 0.3 wn, 8 % at 2.5 wn.
    """
    k = 1.0e5
    geom = CargoGeometry((TubeSegment(0.0, LM, 8.0, 8.0, 0.08),), youngs_modulus_Pa=2100e9)  # 10x steel: beam modes >> bounce
    xs = np.array([0.2, 0.8]) * LM
    model = build_structural_model(
        geom,
        SeaFastening(xs, np.full(2, k), np.zeros(2, bool), lashing_wire_stiffness_N_per_m=0.0, lashing_pretension_N=0.0),
        target_element_length_m=4.0,
        damping_ratio=0.02,
    )
    m = model.cargo.mass_kg
    wn = np.sqrt(2 * k / m)
    w_fe = model.natural_frequencies_rad_s(True, count=2)
    # beam flexibility lowers the bounce frequency by ~2e-5 (relative)
    assert w_fe[0] == pytest.approx(wn, rel=1e-4)
    assert w_fe[0] < wn
    alpha = model.rayleigh_alpha_per_s
    Z = 0.01
    xo = np.zeros(model.deck_dof_count, dtype=complex)
    xo[0::2] = Z
    # at resonance the ~2e-5 frequency shift of the (not quite rigid) beam, over the
    # half-power bandwidth 2 zeta ~ 0.02, costs ~2e-3 in the complex amplitude
    for omega, rtol in ((0.3 * wn, 1e-4), (wn, 5e-3), (2.5 * wn, 1e-4)):
        resp = solve_linear(model, _excitation(model, omega, [np.zeros(model.deck_dof_count), xo]))
        expected = (2 * k + 1j * omega * alpha * m) * Z / (2 * k - omega**2 * m + 1j * omega * alpha * m)
        z_c = resp.cargo_displacement[1, 0::2]
        np.testing.assert_allclose(z_c, expected, rtol=rtol)
        # saddle force: k (Z - X) each, in the same dynamic balance
        np.testing.assert_allclose(resp.saddle_force_N[1], k * (Z - expected), rtol=rtol)
    # at resonance the transmissibility is |2k + i wn c| / (wn c): large, and 90 degrees out of phase less atan(wn c / 2k)
    resp = solve_linear(model, _excitation(model, wn, [np.zeros(model.deck_dof_count), xo]))
    X = resp.cargo_displacement[1, 0]
    c = alpha * m
    assert abs(X) / Z == pytest.approx(abs(2 * k + 1j * wn * c) / (wn * c), rel=5e-3)
    assert abs(X) / Z > 10
    assert np.angle(X) == pytest.approx(-np.pi / 2 + np.arctan(wn * c / (2 * k)), abs=5e-3)


def test_harmonic_inertia_load_matches_dynamic_stiffness_solution() -> None:
    """Cargo load only (deck fixed): X = K_d^-1 F, and response scales linearly."""
    model = _model(2.0)
    omega = 30.0
    F = np.zeros(model.cargo_dof_count, dtype=complex)
    F[0::2] = 1e3 * (1 + 0.5j)
    resp = solve_linear(model, _excitation(model, omega, [np.zeros(model.deck_dof_count)] * 2, [np.zeros(model.cargo_dof_count), F]))
    Kd = model.dynamic_stiffness(omega, True)[0]
    np.testing.assert_allclose(
        resp.cargo_displacement[1], np.linalg.solve(Kd, F), rtol=0, atol=1e-9 * np.abs(resp.cargo_displacement[1]).max()
    )
    resp2 = solve_linear(model, _excitation(model, omega, [np.zeros(model.deck_dof_count)] * 2, [np.zeros(model.cargo_dof_count), 3 * F]))
    np.testing.assert_allclose(
        resp2.cargo_displacement[1], 3 * resp.cargo_displacement[1], rtol=0, atol=1e-10 * np.abs(resp2.cargo_displacement[1]).max()
    )


# --------------------------------------------------------------------------- mesh convergence
def _max_moment(h: float, geometry: CargoGeometry | None = None) -> float:
    model = _model(h, geometry)
    resp = solve_linear(model, _excitation(model, 0.6, [_raised_middle(model, 5.75e-3)]))
    return float(np.abs(_static_moment(model, resp)).max())


def test_mesh_convergence_uniform_base_case() -> None:
    """Hermite elements are nodally exact for the uniform tube: every mesh gives the same M_b."""
    hs = (4.0, 2.0, 1.0, 0.5, 0.25)
    m = np.array([_max_moment(h) for h in hs])
    np.testing.assert_allclose(m, m[-1], rtol=1e-7)
    assert abs(m[2] - m[-1]) <= 5e-3 * m[-1]


def test_mesh_convergence_tapered_cargo() -> None:
    """Tapered tube (midpoint section properties): M_b converges, differences shrink."""
    geom = CargoGeometry(
        (TubeSegment(0.0, 30.0, 8.0, 8.0, 0.08), TubeSegment(30.0, LM, 8.0, 5.0, 0.06)),
    )
    hs = (4.0, 2.0, 1.0, 0.5, 0.25)
    m = np.array([_max_moment(h, geom) for h in hs])
    d = np.abs(np.diff(m))
    assert np.all(d[1:] < d[:-1])
    assert abs(m[2] - m[-1]) <= 5e-3 * abs(m[-1])
