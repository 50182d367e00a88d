"""Two-way hull-cargo coupling of the still-water state, checked against the hull-girder solver."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
from scipy.interpolate import CubicHermiteSpline, CubicSpline

from seafast.analyses.run import run_case
from seafast.config import CaseError, load_case
from seafast.coupling.case import couple_hull_and_cargo
from seafast.coupling.deck_iteration import couple_deck, linear_coupling_jacobian
from seafast.coupling.deck_loads import deck_forces_N, hull_compliance, spread_load_N
from seafast.coupling.status import CouplingOutcome
from seafast.excitation.vessel import vessel_excitation
from seafast.fourier import harmonics_to_time
from seafast.hull.deck import deck_deflection_at
from seafast.hull.still_water import still_water_response
from seafast.model.from_case import build_model
from seafast.solvers.from_case import solve_nonlinear
from seafast.solvers.linear import solve_linear
from seafast.vessel.loading import WeightItem

NO_MOTIONS = {"vessel.motions": "none", "solver.time_samples": 32}


def _static(result, model="nonlinear"):
    return next(r for r in result.summary if r["load_case"] == "static" and r["model"] == model)


@pytest.fixture(scope="module")
def coupled():
    case = load_case(overrides=NO_MOTIONS)
    model = build_model(case)
    vessel = vessel_excitation(case)
    excitation = vessel.cargo_excitation(model, case)
    rows = couple_hull_and_cargo(case, model, excitation, vessel)
    return case, model, vessel, excitation, rows[("static", "nonlinear")]


@pytest.fixture(scope="module")
def coupled_in_waves():
    """The base case with heave and pitch: the wave harmonics carry inertia loads too."""
    case = load_case(overrides={"solver.time_samples": 32})
    model = build_model(case)
    vessel = vessel_excitation(case)
    excitation = vessel.cargo_excitation(model, case)
    return case, model, excitation, couple_hull_and_cargo(case, model, excitation, vessel)


def test_deck_forces_carry_exactly_the_cargo_weight(coupled):
    case, model, _, excitation, result = coupled
    unit_weight_N = model.cargo.mass_kg * case.model.gravity_m_per_s2
    static = excitation.static_part()
    p_lin = deck_forces_N(model, static, solve_linear(model, static), nonlinear=False)
    p_nl = deck_forces_N(model, static, solve_nonlinear(model, static, case, static=True), nonlinear=True)
    for p in (p_lin[0].real, p_nl[0].real, result.deck_force_N[0].real):
        assert p.sum() == pytest.approx(unit_weight_N, rel=1e-9)  # the pretension is internal to cargo + deck
    # one-way: the middle saddle takes the hog (the source's finding)
    assert p_nl[0, 1] > 2.0 * p_nl[0, 0]


def test_coupled_deck_is_the_hull_girder_under_the_cargo_point_loads(coupled):
    """Independent check: re-solve the hull girder with the cargo's spread weight replaced by the
    converged deck forces (n units, 1 m patches), and compare the deck under the saddles."""
    case, model, vessel, excitation, result = coupled
    assert result.converged, result.message
    n = case.cargo.units_abreast
    g = case.model.gravity_m_per_s2
    xs = vessel.cargo_aft_end_x_m + model.saddle_x_m
    forces = result.deck_force_N[0].real
    assert np.all(forces > 0.0)
    # the coupling's saddle patch: the node's tributary length centred on the saddle
    xn = vessel.cargo_aft_end_x_m + model.cargo.node_x_m
    half = [0.5 * (xn[i + 1] - xn[i - 1]) / 2.0 for i in model.saddle_node]
    patches = tuple(WeightItem(f"saddle {i}", x - h, x + h, n * p / g) for i, (x, h, p) in enumerate(zip(xs, half, forces, strict=True)))
    items = tuple(it for it in vessel.loading.items if it.name != "cargo") + patches
    hull = still_water_response(vessel.girder, replace(vessel.loading, items=items))
    z, slope = deck_deflection_at(hull, xs)
    deck = np.real(result.excitation.deck_displacement[0])
    # the deck moved by 7-9 mm from one-way; the two routes (the coupling's compliance, and a
    # fresh hull on another grid) agree to the coupling's own tolerance: the deck under the
    # saddles is converged to it (a sign or factor error would be mm)
    tol = result.status.tolerance_m
    assert result.status.residual_m <= tol < 1e-6
    change = deck - np.real(excitation.deck_displacement[0])
    assert np.max(np.abs(change[model.saddle_deck_dof])) > 5e-3
    np.testing.assert_allclose(deck[model.saddle_deck_dof], z, rtol=0, atol=2.0 * tol)
    assert np.max(np.abs(change[model.saddle_deck_dof + 1])) > 3e-5
    np.testing.assert_allclose(deck[model.saddle_deck_dof + 1], slope, rtol=0, atol=2.0 * tol / result.status.lever_arm_m)


def test_the_exchanged_wave_loads_are_self_equilibrated(coupled_in_waves):
    """At wave frequency the hull sees P_k - Q_k: the cargo's deck forces minus its spread
    inertia load. Their resultant and moment are exactly the inertia of the cargo's motion relative
    to the rigid-body frame (it follows the hull's wave deflection) and the mass-proportional
    Rayleigh damping of its motion relative to the quasi-static support motion ``S x_o``: the beam
    stiffness and its beta K_beam damping have no resultant and no moment (rigid-body motions are in
    their null space). A wrong sign or a missing inertia term would leave 100-200 % of the inertia
    resultant."""
    _, model, excitation, rows = coupled_in_waves
    xn = model.cargo.node_x_m
    xs = model.saddle_x_m
    w = excitation.omega_rad_s
    for key in (("dynamic", "linear"), ("dynamic", "nonlinear")):
        row = rows[key]
        assert row.converged, row.message
        P = row.deck_force_N
        Q = spread_load_N(model, row.excitation, P.shape[0])
        inertia = np.abs(Q[1].sum())
        assert inertia > 1e5  # heave and pitch do load the cargo
        X = row.response.cargo_displacement if key[1] == "linear" else row.response.cargo_displacement_harmonics
        # cargo equilibrium, summed over its z DOFs (resultant) and taken about x = 0 (moment)
        deformation = X[1] - model.quasi_static_support_influence @ row.excitation.deck_displacement[1]
        relative = model.cargo.mass @ (-(w**2) * X[1] + 1j * w * model.rayleigh_alpha_per_s * deformation)
        resultant = relative[0::2].sum()
        moment = relative[0::2] @ xn + relative[1::2].sum()
        assert abs(resultant) > 0.05 * inertia  # the relative motion is not negligible: the check has teeth
        # the nonlinear row's P comes from 32 AFT samples of the contact forces: aliasing of its higher harmonics
        tol = 1e-6 if key[1] == "linear" else 2e-3
        assert abs((P[1].sum() - Q[1].sum()) - resultant) < tol * inertia
        # the lashings' rotational springs put a few kN m on the deck that P leaves out (documented)
        assert abs((P[1] @ xs - Q[1] @ xn) - moment) < max(tol, 1e-3) * np.abs(Q[1] @ xn)
        assert P[0].real.sum() == pytest.approx(Q[0].real.sum(), rel=1e-6)


def test_wave_coupling_reduces_the_wave_induced_deck_motion(coupled_in_waves):
    """The cargo resists the hull's wave bending: the coupled deck's first harmonic differs
    less between the saddles than the one-way one, and the linear model needs one step."""
    _, model, excitation, rows = coupled_in_waves
    z = model.saddle_deck_dof

    def differential(exc):
        w = exc.deck_displacement[1, z]
        return np.abs(w[1] - 0.5 * (w[0] + w[-1]))

    lin = rows[("dynamic", "linear")]
    assert lin.iterations == 1
    assert differential(lin.excitation) < 0.8 * differential(excitation)


def test_two_way_coupling_unloads_the_middle_saddle_of_the_base_case():
    one = run_case(load_case(overrides=NO_MOTIONS))
    two = run_case(load_case(overrides={**NO_MOTIONS, "vessel.coupling": "two_way"}))
    f1, f2 = _static(one)["F_N"], _static(two)["F_N"]
    # the four piles' point reactions push the hull down under the middle saddle, flattening the hog
    assert 0.75 * f1 < f2 < 0.9 * f1
    assert _static(two, "linear")["F_N"] == pytest.approx(f2, rel=5e-3)
    assert len(two.coupling) == 4 and all(status.converged for status in two.coupling.values())
    # results.nc: each model's own deck, and the one-way layout holding the nonlinear one
    ds = two.dataset
    per_model = ds["deck_deflection_per_model_m"]
    np.testing.assert_array_equal(ds["deck_deflection_m"].values, per_model.sel(model="nonlinear").values)
    one_deck = one.dataset["deck_deflection_per_model_m"]
    assert float(np.abs(one_deck.sel(model="linear") - one_deck.sel(model="nonlinear")).max()) == 0.0
    assert float(np.abs(per_model.sel(load_case="static") - one_deck.sel(load_case="static")).max()) > 5e-3


@pytest.mark.parametrize("method", ["quasi_static", "time_domain"])
def test_the_reference_methods_couple_to_the_same_still_water_state(method):
    hbm = run_case(load_case(overrides={**NO_MOTIONS, "vessel.coupling": "two_way", "solver.contact_law": "exact"}))
    ref = run_case(load_case(overrides={**NO_MOTIONS, "vessel.coupling": "two_way", "solver.method": method, "wave.amplitude_m": 0.5}))
    assert _static(ref)["F_N"] == pytest.approx(_static(hbm)["F_N"], rel=1e-6)
    assert all(status.converged for status in ref.coupling.values())


def test_a_stiff_hull_makes_the_coupling_vanish():
    stiff = {**NO_MOTIONS, "vessel.hull_second_moment_m4": 103.8e3, "vessel.hull_shear_area_m2": 800.0}
    one = run_case(load_case(overrides=stiff))
    two = run_case(load_case(overrides={**stiff, "vessel.coupling": "two_way"}))
    assert _static(two)["F_N"] == pytest.approx(_static(one)["F_N"], rel=2e-3)


def test_two_way_coupling_needs_the_computed_hull(tmp_path):
    table = tmp_path / "deck.csv"
    table.write_text("x_m,still_water_m,wave_amplitude_m,wave_phase_rad\n0,0,0,0\n171,0,0,0\n")
    with pytest.raises(CaseError, match=r"vessel\.coupling"):
        load_case(overrides={"vessel.coupling": "two_way", "vessel.deck_deflection_table": str(table)})
    with pytest.raises(CaseError, match="one_way"):
        load_case(overrides={"vessel.coupling": "both"})


def test_wave_coupled_hbm_agrees_with_the_coupled_exact_reference():
    """Two independent cargo solvers, each iterated with the hull to its own coupled state."""
    common = {
        "vessel.coupling": "two_way",
        "solver.contact_law": "exact",
        "solver.time_samples": 64,
        "wave.amplitude_m": 5.0,
    }  # a larger wave, so that the cargo lifts off even when coupled
    hbm = run_case(load_case(overrides={**common, "solver.harmonics": 16}))
    ref = run_case(load_case(overrides={**common, "solver.method": "quasi_static"}))
    dyn = [next(r for r in res.summary if r["load_case"] == "dynamic" and r["model"] == "nonlinear") for res in (hbm, ref)]
    assert all(r["converged"] for r in dyn)
    assert dyn[0]["u_d_m"] > 1e-4  # contact is lost: the unilateral coupling is exercised
    assert dyn[0]["F_N"] == pytest.approx(dyn[1]["F_N"], rel=0.01)
    assert dyn[0]["M_b_Nm"] == pytest.approx(dyn[1]["M_b_Nm"], rel=0.01)


def test_a_coupling_that_does_not_converge_is_flagged_with_its_own_residual(monkeypatch):
    """Every row's coupling stopped before its first step: the rows are flagged, and what says
    so is the coupling's typed outcome with the coupling's residual (the deck mismatch, mm
    here), not the cargo solver's (which converged, ~1e-14)."""
    from seafast.coupling import case as coupling_case

    original = coupling_case.couple_deck
    monkeypatch.setattr(coupling_case, "couple_deck", lambda *a, **k: original(*a, **{**k, "max_iterations": 0}))
    result = run_case(load_case(overrides={**NO_MOTIONS, "vessel.coupling": "two_way"}))
    assert set(result.coupling) == {(lc, m) for lc in ("static", "dynamic") for m in ("linear", "nonlinear")}
    for row in result.summary:
        status = result.coupling[(row["load_case"], row["model"])]
        assert status.outcome is CouplingOutcome.ITERATION_LIMIT and status.iterations == 0
        # before any step the residual is the whole deck change, 7-9 mm on the base case
        assert 5e-3 < status.residual_m == row["coupling_residual_m"]
        assert status.residual_m > row["coupling_tolerance_m"] == status.tolerance_m
        assert row["converged"] is False and row["coupling_converged"] is False
        assert row["residual_norm"] < 1e-8  # the cargo solver itself converged
    # the cargo solver's own message is left as it was (no coupling text glued onto it)
    assert not any("two-way coupling" in m for m in result.arrays.solver_message.ravel())
    ds = result.dataset
    np.testing.assert_array_equal(ds["coupling_converged"].values, 0)
    assert set(ds["coupling_outcome"].values.ravel()) == {"iteration_limit"}
    assert float(ds["coupling_residual_m"].sel(load_case="static", model="nonlinear")) == (
        result.coupling[("static", "nonlinear")].residual_m
    )


def test_a_tapered_pile_weighs_the_same_on_the_hull_and_in_the_cargo_model():
    sections = [
        {"x_start_m": 0.0, "x_end_m": 30.0, "diameter_start_m": 8.0, "diameter_end_m": 8.0, "wall_thickness_m": 0.08},
        {"x_start_m": 30.0, "x_end_m": 74.0, "diameter_start_m": 8.0, "diameter_end_m": 6.5, "wall_thickness_m": 0.06},
    ]
    case = load_case(overrides={**NO_MOTIONS, "cargo.sections": sections, "vessel.coupling": "two_way"})
    model = build_model(case)
    vessel = vessel_excitation(case)
    item = vessel.loading.item("cargo")
    # the beam elements take their section at mid-element (1 m elements): 1e-5 from the exact taper
    assert item.mass_kg == pytest.approx(case.cargo.units_abreast * model.cargo.mass_kg, rel=1e-4)
    rows = couple_hull_and_cargo(case, model, vessel.cargo_excitation(model, case), vessel)
    static = rows[("static", "nonlinear")]
    assert static.converged, static.message
    assert static.deck_force_N[0].real.sum() == pytest.approx(model.cargo.mass_kg * case.model.gravity_m_per_s2, rel=1e-6)


def test_the_analytic_linear_jacobian_equals_finite_differences(coupled_in_waves):
    """``I - n C S_k`` per harmonic against finite differences of the linear model's residual."""
    from seafast.coupling import deck_iteration as coupling

    case, model, excitation, _ = coupled_in_waves
    vessel = vessel_excitation(case)
    compliance = hull_compliance(vessel.girder, vessel.loading, model, vessel.cargo_aft_end_x_m, case.cargo.units_abreast)
    K, n_o = 3, model.deck_dof_count
    analytic = coupling.linear_coupling_jacobian(model, excitation.omega_rad_s, compliance, K)
    Q = spread_load_N(model, excitation, K)

    def residual(v):
        exc = coupling._with_deck_change(excitation, coupling._unpack(v, K, n_o), "")
        P = deck_forces_N(model, exc, solve_linear(model, exc), False, K)
        return v - coupling._pack(compliance.deck_change(P, Q))

    size = n_o * (2 * K - 1)
    r0 = residual(np.zeros(size))
    # the linear model's residual is linear in the deck change: a 1 mm step has no truncation error, and its
    # round-off (the solves' condition number, ~1e6, times eps, over the step) stays far below the tolerance
    step = 1e-3
    fd = np.column_stack([(residual(step * np.eye(size)[j]) - r0) / step for j in range(size)])
    assert np.abs(analytic - np.eye(size)).max() > 0.1  # the coupling is not negligible
    np.testing.assert_allclose(analytic, fd, rtol=0, atol=1e-6 * np.abs(analytic).max())


# ------------------------------------------------------------------ the coupled hull girder
@pytest.fixture(scope="module")
def two_way_run():
    """The base case two-way, with heave and pitch (the wave fields carry inertia loads), and
    its coupled rows."""
    result = run_case(load_case(overrides={"vessel.coupling": "two_way", "solver.time_samples": 32}))
    return result, result.deck_couplings


def _saddle_patches(result):
    """Ship x of the saddles and the half-length of the coupling's saddle patches (the node's
    tributary length, centred on the saddle)."""
    aft = result.vessel.cargo_aft_end_x_m
    xn = aft + result.model.cargo.node_x_m
    xs = aft + result.model.saddle_x_m
    half = np.array([0.25 * (xn[i + 1] - xn[i - 1]) for i in result.model.saddle_node])
    return xs, half


def test_the_coupled_still_water_hull_is_a_fresh_hull_solve_under_the_saddle_loads(two_way_run):
    """Independent route: a fresh still-water hull-girder solve (on its own grid) of the ship
    with the four piles' spread weight replaced by their converged deck forces on the saddle
    patches, against the coupled lines of results.nc along the whole ship."""
    result, rows = two_way_run
    ds = result.dataset
    vessel, case = result.vessel, result.case
    n, g = case.cargo.units_abreast, case.model.gravity_m_per_s2
    row = rows[("static", "nonlinear")]
    P = row.deck_force_N[0].real
    np.testing.assert_allclose(
        ds["deck_deflection_m"].sel(load_case="static").values[0],
        row.excitation.deck_displacement[0, result.model.saddle_deck_dof].real,
        rtol=1e-13,
        atol=0,
    )
    xs, half = _saddle_patches(result)
    patches = tuple(WeightItem(f"saddle {i}", x - h, x + h, n * p / g) for i, (x, h, p) in enumerate(zip(xs, half, P, strict=True)))
    items = tuple(it for it in vessel.loading.items if it.name != "cargo") + patches
    fresh = still_water_response(vessel.girder, replace(vessel.loading, items=items))
    x = ds["hull_x_m"].values
    z_fresh, _ = deck_deflection_at(fresh, x)
    # M is cubic per element with M' = V: its Hermite spline and that spline's slope are exact
    spline = CubicHermiteSpline(fresh.x_m, fresh.bending_moment_Nm, fresh.shear_force_N)
    m_fresh, v_fresh = spline(x), spline(x, 1)
    z1, z2 = ds["hull_still_water_deflection_m"].values, ds["hull_still_water_deflection_coupled_m"].values
    m1, m2 = ds["hull_still_water_bending_moment_Nm"].values, ds["hull_still_water_bending_moment_coupled_Nm"].values
    v2 = ds["hull_still_water_shear_force_coupled_N"].values
    # the coupling changes the hull by ~9 mm and ~140 MN m: a sign or factor error would show
    # at that scale; the two routes agree to round-off of the hull solves (1e-9 m, 1e-3 N m
    # measured) - the bounds leave room for another grid, not for physics
    assert np.abs(z2 - z1).max() > 5e-3 and np.abs(m2 - m1).max() > 1e8
    np.testing.assert_allclose(z2, z_fresh, rtol=0, atol=1e-7)
    np.testing.assert_allclose(m2, m_fresh, rtol=0, atol=1e3)
    np.testing.assert_allclose(v2, v_fresh, rtol=0, atol=1e-6 * np.abs(v2).max())
    # the coupled ship is balanced: moment and shear vanish at both ends
    assert abs(m2[-1]) < 1e-9 * np.abs(m2).max() and abs(v2[-1]) < 1e-9 * np.abs(v2).max()


def test_the_coupled_midship_moment_is_the_statics_of_the_saddle_reactions(two_way_run):
    """An outside check's numbers (an independent coupled hull + four-pile model): midship moment -472.5
    MN m one-way, about -328 MN m coupled; deflection 71.2 -> 61.9 mm. Independent statics: the
    coupling moves the piles' weight from uniform (one-way) to the saddles, self-equilibrated
    (the deck forces sum to the weight and keep its moment), so the buoyancy does not change and
    the moment changes by the statics of point loads,
    M2(x) = M1(x) + n [W/L int_cargo (x - xi)_+ dxi - sum_s P_s (x - x_s)_+].
    Away from the saddles the patch loads seafast applies give exactly that; under a saddle the
    patch of length w rounds the point load's peak off by n P w / 8."""
    result, rows = two_way_run
    ds = result.dataset
    case, model, vessel = result.case, result.model, result.vessel
    n, g = case.cargo.units_abreast, case.model.gravity_m_per_s2
    x = ds["hull_x_m"].values
    m1, m2 = ds["hull_still_water_bending_moment_Nm"].values, ds["hull_still_water_bending_moment_coupled_Nm"].values
    xs, half = _saddle_patches(result)
    P = rows[("static", "nonlinear")].deck_force_N[0].real
    aft, length = vessel.cargo_aft_end_x_m, float(model.cargo.node_x_m[-1] - model.cargo.node_x_m[0])
    W = model.cargo.mass_kg * g
    u = np.clip(x, aft, aft + length)
    statics = m1 + n * (
        W / length * ((u - aft) ** 2 / 2.0 + (u - aft) * (x - u)) - sum(p * np.maximum(x - xp, 0.0) for p, xp in zip(P, xs, strict=True))
    )
    away = np.all(np.abs(x[:, None] - xs[None, :]) > half[None, :] + 1e-9, axis=1)
    change = np.abs(m2 - m1).max()
    assert change > 1e8
    # away from the saddles: statics to 2e-5 of the change (the lashing springs' moments, a few
    # kN m per pile, are not applied to the hull; they move the resultant by millimetres)
    np.testing.assert_allclose(m2[away], statics[away], rtol=0, atol=2e-5 * change)
    mid = int(np.argmin(np.abs(x - vessel.girder.midship_x_m)))
    j = int(np.argmin(np.abs(xs - x[mid])))
    assert abs(xs[j] - x[mid]) < 1e-6  # the middle saddle is amidships
    rounding = n * P[j] * (2.0 * half[j]) / 8.0
    assert rounding > 1e6
    assert m2[mid] == pytest.approx(statics[mid] - rounding, abs=2e-5 * change)
    # the outside model's numbers (point loads): -472.5 -> -328 MN m, 71.2 -> 61.9 mm
    assert m1[mid] == pytest.approx(-472.5e6, rel=1e-3)
    assert statics[mid] == pytest.approx(-328e6, rel=3e-3)
    z1 = ds["hull_still_water_deflection_m"].values[mid]
    z2 = ds["hull_still_water_deflection_coupled_m"].values[mid]
    assert z1 == pytest.approx(71.2e-3, rel=1e-3) and z2 == pytest.approx(61.9e-3, rel=3e-3)


def test_the_coupled_wave_hull_carries_the_deck_the_cargo_stood_on(two_way_run):
    """The coupled hull lines minus the one-way ones (still water + wave, sampled over the
    period) under the saddles reproduce, harmonic by harmonic, the deck change of the dynamic
    nonlinear row, which the coupling obtained through its compliance at the saddles only: the
    lines carry the deck the cargo stood on. The wave part changes too (the piles resist the
    hull's wave bending), and no harmonic appears that the coupled deck does not have."""
    result, rows = two_way_run
    ds = result.dataset
    row = rows[("dynamic", "nonlinear")]
    x = ds["hull_x_m"].values
    xs, _ = _saddle_patches(result)
    change_lines = (
        ds["hull_still_water_deflection_coupled_m"].values
        - ds["hull_still_water_deflection_m"].values
        + ds["hull_wave_deflection_coupled_m"].values
        - ds["hull_wave_deflection_m"].values
    )  # (n_t, n_x)
    at_saddles = CubicSpline(x, change_lines, axis=1)(xs)  # between the 0.5 m hull nodes
    n_t = at_saddles.shape[0]
    deck_change = row.deck_change[:, 0::2]  # z under each saddle, harmonics 0 .. K-1
    K = deck_change.shape[0]
    assert np.abs(deck_change[0]).max() > 5e-3 and np.abs(deck_change[1]).max() > 1e-3
    # they differ by the coupling's residual (<= its tolerance, 0.12 um) and the interpolation
    # between hull nodes (0.3 um measured), against changes of mm; compared at the hull's n_t
    # crest positions (the adaptive H puts more harmonics in the deck than n_t samples resolve)
    assert row.status.tolerance_m < 2e-7
    np.testing.assert_allclose(at_saddles, harmonics_to_time(deck_change, n_t), rtol=0, atol=1e-6)
    if 2 * K <= n_t:  # the lines carry no harmonic the coupled deck does not have
        harmonics = np.fft.rfft(at_saddles, axis=0) / n_t
        assert np.abs(harmonics[K:]).max() < 1e-9


# ------------------------------------------------------------------ tolerance on a fine mesh
@pytest.mark.slow
def test_a_fine_cargo_mesh_converges_every_row_to_the_coarse_mesh_results(two_way_run):
    """model.element_length_m = 0.1 (740 cargo elements): the cargo's deck forces carry ~1e4
    times the round-off of the 1 m mesh (the bending stiffness grows as h^-3), so the coupling
    residual stalls near 1e-9 m, which an absolute 1e-10 m tolerance flagged (exit 3). The
    tolerance is relative to the deck motion (1e-6 of 74 mm): every row converges, iterating
    on to the round-off floor moves the saddle forces by less than the tolerance's worth
    (k_saddle x tolerance, ~80 N), and the results are those of the 1 m mesh to the mesh
    convergence of the cargo (0.5 %)."""
    coarse, _ = two_way_run
    case = load_case(overrides={"vessel.coupling": "two_way", "solver.time_samples": 32, "model.element_length_m": 0.1})
    fine = run_case(case)
    assert fine.model.cargo.node_count > 700
    for status in fine.coupling.values():
        assert status.converged, status.message
        assert status.residual_m <= status.tolerance_m
        # the scale is the deck motion under the saddles (still water: 57-74 mm from the end chord)
        assert 0.05 < status.deck_motion_scale_m < 0.2
        assert status.tolerance_m == pytest.approx(1e-6 * status.deck_motion_scale_m, rel=1e-12)
    assert all(row["converged"] for row in fine.summary)
    by_row = {(r["load_case"], r["model"]): r for r in coarse.summary}
    for row in fine.summary:
        ref = by_row[(row["load_case"], row["model"])]
        assert row["F_N"] == pytest.approx(ref["F_N"], rel=5e-3)
        assert row["M_b_Nm"] == pytest.approx(ref["M_b_Nm"], rel=5e-3)
    # iterate the still-water nonlinear row on to the round-off floor: nothing to gain
    model, vessel = fine.model, fine.vessel
    compliance = hull_compliance(vessel.girder, vessel.loading, model, vessel.cargo_aft_end_x_m, case.cargo.units_abreast)
    static = fine.excitation.static_part()
    jac = linear_coupling_jacobian(model, static.omega_rad_s, compliance, 1)

    def couple(rtol):
        return couple_deck(
            model,
            static,
            compliance,
            lambda e: solve_nonlinear(model, e, case, static=True),
            lambda e, r: deck_forces_N(model, e, r, True, 1),
            1,
            jacobian0=jac,
            relative_tolerance=rtol,
        )

    ours, floor = couple(1e-6), couple(1e-14)
    assert ours.converged and not floor.converged and floor.status.outcome is not CouplingOutcome.NOT_FINITE
    assert floor.residual_m < ours.status.tolerance_m
    k_saddle = float(np.max(model.saddle_stiffness_N_per_m))
    force_change = np.abs(ours.deck_force_N[0].real - floor.deck_force_N[0].real).max()
    assert force_change < k_saddle * ours.status.tolerance_m
