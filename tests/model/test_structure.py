"""Verification of the cargo + sea-fastening structural model against statics.

Reactions are taken from the linear solver (bilateral saddles, deck held flat) and compared
with closed-form answers: the three-moment equation for a continuous beam with overhangs on
rigid supports, statically determinate beams on springs, and plain force balance.
"""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from seafast.excitation.harmonic import HarmonicExcitation
from seafast.model.cache import ModelCache
from seafast.model.seafastening import BASE_LASHING, SeaFastening
from seafast.model.sections import CargoGeometry, TubeSegment, tube_area_m2
from seafast.model.structure import MechanismError, StructuralModel, build_structural_model
from seafast.model.warning import ModelWarning
from seafast.solvers.linear import solve_linear

LM, D, T, RHO, G = 74.0, 8.0, 0.08, 7850.0, 9.81
BASE_X = np.array([0.2, 0.5, 0.8]) * LM


def _geometry(E: float = 210e9) -> CargoGeometry:
    return CargoGeometry((TubeSegment(0.0, LM, D, D, T),), youngs_modulus_Pa=E, density_kg_per_m3=RHO)


def _weight_N() -> float:
    return float(RHO * tube_area_m2(D, T) * LM * G)


def _flat_deck(model: StructuralModel) -> HarmonicExcitation:
    return HarmonicExcitation(
        0.6,
        np.zeros((1, model.deck_dof_count), dtype=complex),
        np.zeros((1, model.cargo_dof_count), dtype=complex),
        np.zeros((1, model.cargo.element_count), dtype=complex),
    )


def _spring_forces(model: StructuralModel, resp) -> np.ndarray:
    """Total vertical spring force on the cargo at each saddle (saddle + lashing k_z), static part."""
    kz = model.seafastening.lashing_vertical_stiffness_N_per_m
    return (resp.saddle_force_N[0] + kz * resp.saddle_compression_m[0]).real


def three_moment_reactions(xs: np.ndarray, length: float, w: float) -> np.ndarray:
    """Reactions (upward) of a uniform beam on three rigid supports with overhangs, load w down.

    Support moments (sagging positive): the overhangs give M_A = -w a^2/2 and
    M_C = -w (length - c)^2/2; Clapeyron's equation for the two spans then gives M_B:
        M_A L1 + 2 M_B (L1 + L2) + M_C L2 = -w (L1^3 + L2^3) / 4.
    Span shears from M(x) = M_i + V_i x - w x^2/2 with M(L_span) = M_{i+1}.
    """
    a, b, c = xs
    L1, L2 = b - a, c - b
    MA = -w * a**2 / 2
    MC = -w * (length - c) ** 2 / 2
    MB = (-w * (L1**3 + L2**3) / 4 - MA * L1 - MC * L2) / (2 * (L1 + L2))
    V1 = (MB - MA) / L1 + w * L1 / 2  # shear just right of A
    V2 = (MC - MB) / L2 + w * L2 / 2  # shear just right of B
    RA = w * a + V1
    RB = (w * L1 - V1) + V2
    RC = (w * L2 - V2) + w * (length - c)
    return np.array([RA, RB, RC])


def test_three_moment_helper_sanity() -> None:
    # two equal spans, no overhang: 3/8, 10/8 (=5/4), 3/8 of w L_span
    r = three_moment_reactions(np.array([0.0, 5.0, 10.0]), 10.0, 1.0)
    np.testing.assert_allclose(r, [3 * 5 / 8, 10 * 5 / 8, 3 * 5 / 8], rtol=1e-14)


@pytest.mark.parametrize(
    "fractions",
    [(0.2, 0.5, 0.8), (0.1, 0.45, 0.9), (0.25, 0.4, 0.7)],
    ids=["base", "asym-1", "asym-2"],
)
def test_continuous_beam_on_three_rigid_supports(fractions) -> None:
    xs = np.array(fractions) * LM
    sf = SeaFastening(xs, np.full(3, 1e14), np.zeros(3, bool), lashing_wire_stiffness_N_per_m=0.0, lashing_pretension_N=0.0)
    model = build_structural_model(_geometry(), sf, target_element_length_m=1.0)
    np.testing.assert_allclose(model.saddle_x_m, xs, rtol=0, atol=1e-9)
    resp = solve_linear(model, _flat_deck(model))
    w = RHO * float(tube_area_m2(D, T)) * G
    expected = three_moment_reactions(xs, LM, w)
    assert expected.sum() == pytest.approx(w * LM, rel=1e-12)
    # 1e-4 of the largest reaction (the 1e14 N/m saddles are not perfectly rigid; asym-2 has a
    # middle support in tension, where the relative error of that smaller value is larger)
    tol = 1e-4 * np.abs(expected).max()
    np.testing.assert_allclose(resp.saddle_force_N[0].real, expected, rtol=0, atol=tol)
    np.testing.assert_allclose(resp.saddle_force_N[0].imag, 0.0, atol=0)
    # compression is force / stiffness (negative = the support pulls)
    np.testing.assert_allclose(resp.saddle_compression_m[0].real, expected / 1e14, rtol=0, atol=tol / 1e14)


def test_beam_on_two_equal_springs_under_its_weight() -> None:
    """Statically determinate: each spring W/2, compression W/(2k), for any beam stiffness."""
    k = 2.0e8
    xs = np.array([0.2, 0.8]) * LM
    W = _weight_N()
    for E, rtol in ((210e9, 1e-9), (210e12, 1e-6)):  # a 1000x stiffer beam costs conditioning
        sf = SeaFastening(xs, np.full(2, k), np.zeros(2, bool), lashing_wire_stiffness_N_per_m=0.0, lashing_pretension_N=0.0)
        model = build_structural_model(_geometry(E), sf, target_element_length_m=2.0)
        assert model.cargo.mass_kg * G == pytest.approx(W, rel=1e-12)
        resp = solve_linear(model, _flat_deck(model))
        np.testing.assert_allclose(resp.saddle_force_N[0].real, [W / 2, W / 2], rtol=rtol)
        np.testing.assert_allclose(resp.saddle_compression_m[0].real, [W / (2 * k)] * 2, rtol=rtol)
        # the cargo sinks: z at the saddles is -W/(2k) (deck flat at 0)
        np.testing.assert_allclose(resp.cargo_displacement[0, model.saddle_cargo_dof].real, -W / (2 * k), rtol=rtol)


def test_single_saddle_without_rotational_lashing_is_a_mechanism() -> None:
    sf = SeaFastening(np.array([37.0]), np.array([1.1e9]), np.array([False]))
    with pytest.raises(MechanismError) as exc:
        build_structural_model(_geometry(), sf)
    msg = str(exc.value)
    assert "mechanism" in msg
    assert "1 saddle(s)" in msg and "37.0" in msg
    assert isinstance(exc.value, ValueError)


def test_lashed_single_saddle_with_zero_lashing_stiffness_is_a_mechanism() -> None:
    sf = SeaFastening(np.array([30.0]), np.array([1.1e9]), np.array([True]), lashing_wire_stiffness_N_per_m=0.0)
    with pytest.raises(MechanismError, match=r"30\.0"):
        build_structural_model(_geometry(), sf)


def test_single_saddle_with_rotational_lashing_is_stable() -> None:
    sf = SeaFastening(np.array([37.0]), np.array([1.1e9]), np.array([True]))
    model = build_structural_model(_geometry(), sf, target_element_length_m=2.0)
    resp = solve_linear(model, _flat_deck(model))
    W = _weight_N()
    # all weight + pretension through the one support (saddle + lashing spring)
    assert _spring_forces(model, resp).sum() == pytest.approx(W + 210e3, rel=1e-9)


@pytest.mark.parametrize("target", [4.0, 1.0, 0.3])
def test_mesh_has_node_at_every_saddle_and_meets_target_length(target: float) -> None:
    xs = np.array([3.3, 14.8, 37.0, 41.17, 59.2])
    sections = (TubeSegment(0.0, 30.0, 8.0, 8.0, 0.08), TubeSegment(30.0, LM, 8.0, 6.5, 0.06))
    geom = CargoGeometry(sections)
    sf = SeaFastening(xs, np.full(xs.size, 1.1e9), np.array([True, False, False, False, True]))
    model = build_structural_model(geom, sf, target_element_length_m=target)
    x = model.cargo.node_x_m
    assert x[0] == 0.0 and x[-1] == pytest.approx(LM, abs=1e-12)
    assert np.all(np.diff(x) > 0)
    assert np.diff(x).max() <= target + 1e-9
    np.testing.assert_allclose(x[model.saddle_node], xs, rtol=0, atol=1e-9)
    assert np.min(np.abs(x - 30.0)) < 1e-9  # section boundary is a node
    # the element count is minimal per interval: no interval over-refined
    fixed = np.array([0.0, 3.3, 14.8, 30.0, 37.0, 41.17, 59.2, LM])
    n_expected = int(sum(np.ceil((b - a) / target - 1e-9) for a, b in itertools.pairwise(fixed)))
    assert model.cargo.element_count == n_expected
    # the tapered segment gets its midpoint properties
    D_mid, _ = geom.section_at(model.cargo.element_mid_x_m)
    np.testing.assert_allclose(model.cargo.element_outer_diameter_m, D_mid, rtol=1e-12)
    assert model.cargo.mass_kg == pytest.approx(geom.mass_kg(), rel=1e-5)


def test_lashed_saddle_unilateral_stiffness_is_ksad_minus_kz() -> None:
    k_sad = np.array([1.1e9, 5.0e8, 2.0e9])
    sf = SeaFastening(BASE_X, k_sad, np.array([True, False, True]))
    kz = BASE_LASHING.vertical_stiffness_N_per_m
    np.testing.assert_allclose(sf.lashing_vertical_stiffness_N_per_m, [kz, 0.0, kz], rtol=1e-15)
    np.testing.assert_allclose(sf.unilateral_stiffness_N_per_m, [1.1e9 - kz, 5.0e8, 2.0e9 - kz], rtol=1e-15)
    np.testing.assert_allclose(sf.lashing_rotational_stiffness_Nm_per_rad, [1.46e6, 0.0, 1.46e6], rtol=1e-15)
    model = build_structural_model(_geometry(), sf, target_element_length_m=2.0)
    np.testing.assert_allclose(model.saddle_unilateral_stiffness_N_per_m, sf.unilateral_stiffness_N_per_m)
    # linear model: the full saddle stiffness, bilateral, on the saddle z DOFs
    Kcc, Kco, Koo = model.spring_matrices(include_saddles=True)
    cz, oz = model.saddle_cargo_dof, model.saddle_deck_dof
    np.testing.assert_allclose(np.diag(Kcc)[cz], k_sad, rtol=1e-15)
    np.testing.assert_allclose(Kco[cz, oz], -k_sad, rtol=1e-15)
    np.testing.assert_allclose(np.diag(Koo)[oz], k_sad, rtol=1e-15)
    np.testing.assert_allclose(np.diag(Koo)[oz + 1], [1.46e6, 0.0, 1.46e6], rtol=1e-15)
    # nonlinear split: only the lashing springs stay linear
    Kcc_nl, _, Koo_nl = model.spring_matrices(include_saddles=False)
    np.testing.assert_allclose(np.diag(Koo_nl)[oz], [kz, 0.0, kz], rtol=1e-15)
    assert np.diag(Kcc_nl)[cz] == pytest.approx([kz, 0.0, kz], rel=1e-15)


def test_lashing_springs_scale_with_wire_stiffness() -> None:
    sf = SeaFastening(BASE_X, np.full(3, 1.1e9), np.array([True, False, True]), lashing_wire_stiffness_N_per_m=75e3)
    np.testing.assert_allclose(sf.lashing_vertical_stiffness_N_per_m, [13e3, 0, 13e3], rtol=1e-12)
    np.testing.assert_allclose(sf.lashing_rotational_stiffness_Nm_per_rad, [2.92e6, 0, 2.92e6], rtol=1e-12)
    # a lashing stiffer than the saddle: the unilateral part is clipped at zero
    soft = SeaFastening(BASE_X, np.full(3, 1.0e3), np.array([True, False, True]))
    np.testing.assert_allclose(soft.unilateral_stiffness_N_per_m, [0.0, 1.0e3, 0.0])


def test_pretension_adds_to_static_saddle_reactions() -> None:
    W = _weight_N()
    results = {}
    for T_l in (0.0, 210e3, 2.0e6):
        sf = SeaFastening(BASE_X, np.full(3, 1.1e9), np.array([True, False, True]), lashing_pretension_N=T_l)
        model = build_structural_model(_geometry(), sf, target_element_length_m=1.0)
        # pretension shared equally by the lashed saddles, downward on the cargo
        np.testing.assert_allclose(sf.saddle_pretension_N, [T_l / 2, 0.0, T_l / 2])
        assert model.pretension_load_N.sum() == pytest.approx(-T_l, abs=1e-9)
        assert model.static_load_N[0::2].sum() == pytest.approx(-(W + T_l), rel=1e-12)
        resp = solve_linear(model, _flat_deck(model))
        forces = _spring_forces(model, resp)
        assert forces.sum() == pytest.approx(W + T_l, rel=1e-9)
        # saddle (compression) part alone: the lashing k_z part is ~1e-6 of it
        assert resp.saddle_force_N[0].real.sum() == pytest.approx(W + T_l, rel=1e-5)
        results[T_l] = forces
    # linear superposition: the pretension response adds, symmetric layout -> outer saddles equal
    for T_l in (210e3, 2.0e6):
        extra = results[T_l] - results[0.0]
        assert extra.sum() == pytest.approx(T_l, rel=1e-7)
        assert extra[0] == pytest.approx(extra[2], rel=1e-9)
        assert extra[0] > 0


def _state_space_damping(model: StructuralModel, count: int = 2) -> np.ndarray:
    """Damping ratios of the lowest complex modes of M q'' + D q' + K q = 0 (bilateral saddles, deck fixed).

    Independent of any modal formula: the eigenvalues of the first-order system are
    ``-zeta omega +- i omega sqrt(1 - zeta^2)`` whatever the damping matrix, proportional or not.
    """
    from scipy.linalg import eig

    K = model.cargo.stiffness + model.spring_matrices(True)[0]
    M, Dm = model.cargo.mass, model.damping_cc
    n = K.shape[0]
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-np.linalg.solve(M, K), -np.linalg.solve(M, Dm)]])
    lam = eig(A, right=False)
    lam = lam[lam.imag > 0]
    lam = lam[np.argsort(np.abs(lam))][:count]
    return -lam.real / np.abs(lam)


def test_rayleigh_damping_gives_the_modes_the_requested_ratio() -> None:
    """beta multiplies the beam stiffness only, so the classic two-frequency formula realised about
    1.1 % on the base case's first modes (the saddle springs carry most of their strain energy); the fitted
    coefficients give exactly the ratio, measured on the eigenvectors and on the complex modes of the model."""
    sf = SeaFastening(BASE_X, np.full(3, 1.1e9), np.array([True, False, True]))
    for ratio in (0.02, 0.05):
        model = build_structural_model(_geometry(), sf, target_element_length_m=1.0, damping_ratio=ratio)
        assert model.rayleigh_fit is not None and model.rayleigh_fit.exact
        assert model.rayleigh_fit.miss == 0.0 and model.warnings == ()
        np.testing.assert_allclose(model.modal_damping_ratios(2), ratio, rtol=1e-9)
        # the complex modes of the non-proportionally damped model: the modal formula is first-order exact
        np.testing.assert_allclose(_state_space_damping(model), ratio, rtol=0.02)
        # the classic formula would have realised about half of it (as measured on the base case: 1.13 % and 1.10 %)
        from seafast.model.structure import rayleigh_coefficients

        w, kappa = model.first_modes_beam_share()
        a, b = rayleigh_coefficients(ratio, *w)
        classic = (a + b * kappa) / (2 * w)
        assert np.all(classic < 0.6 * ratio)
    # beta exceeds the classic value because the beam carries only part of the strain energy
    assert model.rayleigh_beta_s > 2.0 / (w[0] + w[1]) * 0.05


def test_rayleigh_damping_fallback_when_both_modes_ride_on_the_springs() -> None:
    """Soft saddles: the first two modes are bounce and pitch of the nearly rigid tube on its springs (the beam
    carries almost none of their strain energy), so beta cannot separate them; the fallback is documented,
    flagged and within 10 % on both modes, and the beam modes stay damped (classic beta)."""
    sf = SeaFastening(BASE_X, np.full(3, 1.1e7), np.array([True, False, True]))
    model = build_structural_model(_geometry(), sf, target_element_length_m=1.0, damping_ratio=0.02)
    fit = model.rayleigh_fit
    assert fit is not None and not fit.exact
    realised = model.modal_damping_ratios(4)
    np.testing.assert_allclose(realised[:2], fit.realised_damping_ratio, rtol=1e-5)  # eigenvector round-off of a tiny beam share
    np.testing.assert_allclose(realised[:2], 0.02, rtol=0.10)
    assert np.all(realised[2:] > 0.02)
    assert model.rayleigh_beta_s == pytest.approx(2 * 0.02 / sum(fit.omega_rad_s), rel=1e-12)


def test_zero_damping_ratio_gives_no_damping() -> None:
    sf = SeaFastening(BASE_X, np.full(3, 1.1e9), np.array([True, False, True]))
    model = build_structural_model(_geometry(), sf, target_element_length_m=2.0, damping_ratio=0.0)
    assert model.rayleigh_alpha_per_s == 0.0 and model.rayleigh_beta_s == 0.0


def test_the_damping_acts_on_the_motion_relative_to_the_quasi_static_support_motion() -> None:
    """Structural damping dissipates on deformation: a cargo carried rigidly by a slowly heaving deck is not
    damped. The supports' quasi-static motion S x_o of a rigid deck motion is that rigid motion of the cargo, and
    the spring forces of a cargo on a deck heaving at 0.6 rad/s are its inertia, in phase. Damping on the motion
    relative to the rigid-body frame (alpha M q') would add a drag alpha m omega z0 in quadrature: 2.8 times the
    inertia on this model (alpha = 1.65 1/s)."""
    sf = SeaFastening(BASE_X, np.full(3, 1.1e9), np.array([True, False, True]))
    model = build_structural_model(_geometry(), sf, target_element_length_m=1.0)
    springs_cc, springs_co, _ = model.spring_matrices(True)
    S = model.quasi_static_support_influence
    np.testing.assert_allclose(S, -np.linalg.solve(model.cargo.stiffness + springs_cc, springs_co), rtol=0, atol=1e-9)
    np.testing.assert_allclose(model.support_damping_coupling, -model.damping_cc @ S, rtol=0, atol=1e-9 * np.abs(model.damping_cc).max())
    # a rigid deck motion (heave 0.1 m, pitch 2 mrad about the cargo's aft end) imposes that rigid motion on the cargo
    z0, pitch = 0.1, 2e-3
    xo = np.zeros(model.deck_dof_count)
    xo[model.saddle_deck_dof], xo[model.saddle_deck_dof + 1] = z0 + pitch * model.saddle_x_m, pitch
    rigid = np.zeros(model.cargo_dof_count)
    rigid[0::2], rigid[1::2] = z0 + pitch * model.cargo.node_x_m, pitch
    np.testing.assert_allclose(S @ xo, rigid, rtol=0, atol=1e-9 * z0)
    # deck heave at wave frequency: the spring forces' resultant is the cargo's inertia, without a drag in quadrature
    omega = 0.6
    heave = np.zeros(model.deck_dof_count, dtype=complex)
    heave[model.saddle_deck_dof] = z0
    excitation = HarmonicExcitation(
        omega,
        np.stack([np.zeros(model.deck_dof_count, dtype=complex), heave]),
        np.zeros((2, model.cargo_dof_count), dtype=complex),
        np.zeros((2, model.cargo.element_count), dtype=complex),
    )
    resp = solve_linear(model, excitation)
    kz = model.seafastening.lashing_vertical_stiffness_N_per_m
    resultant = np.sum(resp.saddle_force_N[1] + kz * resp.saddle_compression_m[1])
    inertia = -(omega**2) * model.cargo.mass_kg * z0
    assert resultant.real == pytest.approx(inertia, rel=1e-3)
    # what is left in quadrature is the damping of the dynamic deformation, (omega / omega_1)^2 ~ 2e-4 of the motion
    assert abs(resultant.imag) < 1e-3 * abs(inertia)
    assert model.rayleigh_alpha_per_s * omega * model.cargo.mass_kg * z0 > 2.0 * abs(inertia)  # what the old law added


def test_mechanism_threshold_is_the_lowest_stiffness_eigenvalue() -> None:
    # Two soft saddles: the lowest eigenvalue of K is about the springs' stiffness. The banded
    # Cholesky test must refuse exactly when it falls below 1e-12 of the beam's stiffness scale.
    def layout(k: float) -> SeaFastening:
        return SeaFastening(BASE_X[[0, 2]], np.full(2, k), np.zeros(2, bool), lashing_wire_stiffness_N_per_m=0.0, lashing_pretension_N=0.0)

    probe = build_structural_model(_geometry(), layout(1.0e6), target_element_length_m=2.0)
    K = probe.cargo.stiffness + probe.spring_matrices(True)[0]
    eig_min_per_k = float(np.linalg.eigvalsh(K)[0]) / 1.0e6  # linear in k while k << beam stiffness
    threshold = 1e-12 * float(np.max(np.diag(probe.cargo.stiffness)))
    k_limit = threshold / eig_min_per_k
    build_structural_model(_geometry(), layout(3.0 * k_limit), target_element_length_m=2.0)
    with pytest.raises(MechanismError):
        build_structural_model(_geometry(), layout(k_limit / 3.0), target_element_length_m=2.0)


def test_natural_frequencies_of_a_fine_mesh_by_shift_invert_equal_the_converged_dense_ones() -> None:
    from seafast.model.structure import DENSE_EIGEN_DOFS

    sf = SeaFastening(BASE_X, np.full(3, 1.1e9), np.array([True, False, True]))
    coarse = build_structural_model(_geometry(), sf, target_element_length_m=1.0)  # dense eigen-solve
    fine = build_structural_model(_geometry(), sf, target_element_length_m=0.1)  # sparse shift-invert
    assert coarse.cargo_dof_count <= DENSE_EIGEN_DOFS < fine.cargo_dof_count
    # Hermite elements converge as h^4: the 1 m mesh's lowest modes are within 1e-7 of converged
    np.testing.assert_allclose(fine.natural_frequencies_rad_s(True, 3), coarse.natural_frequencies_rad_s(True, 3), rtol=1e-6)
    # the fit uses the beam's share of the modes' strain energy, which converges with the mesh a little slower
    assert fine.rayleigh_beta_s == pytest.approx(coarse.rayleigh_beta_s, rel=2e-5)


def test_models_along_a_stiffness_axis_share_the_mesh_and_equal_fresh_builds() -> None:
    """A study's :class:`ModelCache` keeps one mesh for models that differ only in their springs, and one
    Rayleigh fit for models that differ only in pretension; every model equals a fresh build (no cache) to the bit."""
    cache = ModelCache()
    soft = SeaFastening(BASE_X, np.full(3, 1.1e8), np.array([True, False, True]))
    stiff = SeaFastening(BASE_X, np.full(3, 1.1e10), np.array([True, False, True]))
    pretensioned = SeaFastening(BASE_X, np.full(3, 1.1e10), np.array([True, False, True]), lashing_pretension_N=5e6)
    a = build_structural_model(_geometry(), soft, target_element_length_m=2.0, cache=cache)
    with cache.shared():  # what a study's evaluator does: the models built inside find the cache
        b = build_structural_model(_geometry(), stiff, target_element_length_m=2.0)
        c = build_structural_model(_geometry(), pretensioned, target_element_length_m=2.0)
    assert a.cargo is b.cargo is c.cargo and len(cache) == 1  # one mesh and beam assembly for the three
    assert a.rayleigh_beta_s != b.rayleigh_beta_s  # the springs move the natural frequencies ...
    assert b.rayleigh_fit is c.rayleigh_fit  # ... pretension does not
    for memoised, sf in ((a, soft), (b, stiff), (c, pretensioned)):
        reference = build_structural_model(_geometry(), sf, target_element_length_m=2.0)
        assert reference.cargo is not memoised.cargo  # no cache outside the block: built afresh
        np.testing.assert_array_equal(memoised.cargo.stiffness, reference.cargo.stiffness)
        assert (memoised.rayleigh_alpha_per_s, memoised.rayleigh_beta_s) == (reference.rayleigh_alpha_per_s, reference.rayleigh_beta_s)
        np.testing.assert_array_equal(memoised.static_load_N, reference.static_load_N)
    small = ModelCache(max_entries=1)
    build_structural_model(_geometry(), soft, target_element_length_m=2.0, cache=small)
    build_structural_model(_geometry(), soft, target_element_length_m=4.0, cache=small)
    assert len(small) == 1  # the oldest goes first


def test_shift_invert_frequencies_equal_the_dense_ones_above_the_threshold_and_repeat_exactly() -> None:
    from scipy.linalg import eigh

    from seafast.model.structure import DENSE_EIGEN_DOFS

    sf = SeaFastening(BASE_X, np.full(3, 1.1e9), np.array([True, False, True]))
    model = build_structural_model(_geometry(), sf, target_element_length_m=0.45)
    assert DENSE_EIGEN_DOFS < model.cargo_dof_count < 2 * DENSE_EIGEN_DOFS
    K = model.cargo.stiffness + model.spring_matrices(True)[0]
    dense = np.sqrt(eigh(K, model.cargo.mass, eigvals_only=True, subset_by_index=[0, 3]))
    lanczos = model.natural_frequencies_rad_s(True, 4)
    np.testing.assert_allclose(lanczos, dense, rtol=1e-6)  # the dense solve's own accuracy here
    np.testing.assert_array_equal(model.natural_frequencies_rad_s(True, 4), lanczos)  # fixed start vector


@pytest.mark.parametrize("include_saddles", [True, False])
def test_banded_quadratic_parts_rebuild_the_dynamic_stiffness(include_saddles) -> None:
    sf = SeaFastening(BASE_X, np.full(3, 1.1e9), np.array([True, False, True]))
    model = build_structural_model(_geometry(), sf, target_element_length_m=2.0)
    b, K, M, D, Kco = model.banded_quadratic(include_saddles)
    n = model.cargo_dof_count

    def dense(band):
        A = np.zeros((n, n), dtype=band.dtype)
        for offset in range(-b, b + 1):
            i = np.arange(max(0, -offset), min(n, n - offset))
            A[i, i + offset] = band[b - offset, i + offset]
        return A

    assert np.count_nonzero(np.triu(model.cargo.stiffness, b + 1)) == 0  # nothing outside the band
    for omega in (0.0, 0.61, 44.0):
        Kd_cc, Kd_co, _, _ = model.dynamic_stiffness(omega, include_saddles)
        rebuilt = dense(K) - omega**2 * dense(M) + 1j * omega * dense(D)
        np.testing.assert_allclose(rebuilt, Kd_cc, rtol=0, atol=1e-15 * np.max(np.abs(Kd_cc)))
        np.testing.assert_array_equal(Kco, Kd_co.real)
        np.testing.assert_array_equal(omega * model.support_damping_coupling, Kd_co.imag)
    np.testing.assert_array_equal(dense(M), model.cargo.mass)  # exactly the model's mass


@pytest.mark.parametrize(("stiffness_N_per_m", "warned"), [(1.1e7, False), (3.0e9, True)])
def test_the_damping_fallback_warns_only_when_it_misses_the_ratio_by_more_than_a_tenth(
    stiffness_N_per_m: float, warned: bool, caplog: pytest.LogCaptureFixture
) -> None:
    """1 % saddles: the fallback realises 2.04 % / 1.96 % (an info line, recorded in results.nc); two
    saddles at 3e9 N/m: 2.39 % / 1.52 %, 24 % off, a warning (a study would otherwise print the first kind
    for every point)."""
    x = BASE_X if not warned else BASE_X[[0, 2]]
    sf = SeaFastening(x, np.full(x.size, stiffness_N_per_m), np.ones(x.size, bool) if warned else np.array([True, False, True]))
    ratio = 0.0201 if warned else 0.0202
    with caplog.at_level("INFO", logger="seafast.model.structure"):
        model = build_structural_model(_geometry(), sf, target_element_length_m=1.0, damping_ratio=ratio)
    fit = model.rayleigh_fit
    assert fit is not None and not fit.exact
    off = float(np.max(np.abs(np.asarray(fit.realised_damping_ratio) / ratio - 1.0)))
    assert (off > 0.1) is warned, fit.realised_damping_ratio
    assert fit.miss == pytest.approx(off, rel=1e-12) and fit.damping_ratio == ratio
    assert model.warnings == ((ModelWarning.RAYLEIGH_FALLBACK,) if warned else ())  # the typed value a study records
    records = [r for r in caplog.records if "cannot give both" in r.getMessage()]
    assert [r.levelname for r in records] == ["WARNING" if warned else "INFO"]
