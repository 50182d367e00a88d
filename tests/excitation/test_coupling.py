"""Two-way hull-cargo coupling of the still-water state, checked against the hull-girder solver."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from seafast.config import CaseError, load_case
from seafast.excitation.coupling import deck_forces_N
from seafast.excitation.hull_girder import deck_deflection_at, still_water_response
from seafast.excitation.vessel import vessel_excitation
from seafast.pipeline import build_model, couple_hull_and_cargo, run_case, solve_nonlinear
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
    # the node's tributary length (the mesh puts a node at each saddle; 1 m elements around it)
    xn = vessel.cargo_aft_end_x_m + model.cargo.node_x_m
    half = [0.5 * (xn[i + 1] - xn[i - 1]) / 2.0 for i in model.saddle_node]
    patches = tuple(WeightItem(f"saddle {i}", x - h, x + h, n * p / g) for i, (x, h, p) in enumerate(zip(xs, half, forces)))
    items = tuple(it for it in vessel.loading.items if it.name != "cargo") + patches
    hull = still_water_response(vessel.girder, replace(vessel.loading, items=items))
    z, slope = deck_deflection_at(hull, xs)
    deck = np.real(result.excitation.deck_displacement[0])
    # the deck moved by 7-9 mm from one-way; the two routes agree to 10 um: the fresh solve goes
    # through a 45 MN lighter ship on another hull mesh, and the hull's piecewise-linear buoyancy
    # discretisation differs at the 1e-4 level of that (a sign or factor error would be mm)
    change = deck - np.real(excitation.deck_displacement[0])
    assert np.max(np.abs(change[model.saddle_deck_dof])) > 5e-3
    np.testing.assert_allclose(deck[model.saddle_deck_dof], z, rtol=0, atol=1e-5)
    assert np.max(np.abs(change[model.saddle_deck_dof + 1])) > 3e-5
    np.testing.assert_allclose(deck[model.saddle_deck_dof + 1], slope, rtol=0, atol=3e-6)


def test_the_exchanged_wave_loads_are_self_equilibrated(coupled_in_waves):
    """At wave frequency the hull sees P_k - Q_k: the cargo's deck forces minus its spread
    inertia load. The two nearly share their resultant and moment: the rest is the inertia and
    the mass-proportional Rayleigh damping of the cargo's motion relative to the rigid-body
    frame (it follows the hull's wave deflection), about 2 % of the dynamic deck forces here.
    A wrong sign or a missing inertia term would leave 100-200 % of the inertia resultant."""
    from seafast.excitation.coupling import spread_load_N

    case, model, excitation, rows = coupled_in_waves
    xn = model.cargo.node_x_m
    xs = model.saddle_x_m
    for key in (("dynamic", "linear"), ("dynamic", "nonlinear")):
        row = rows[key]
        assert row.converged, row.message
        P = row.deck_force_N
        Q = spread_load_N(model, row.excitation, P.shape[0])
        inertia = np.abs(Q[1].sum())
        assert inertia > 1e5  # heave and pitch do load the cargo
        assert abs(P[1].sum() - Q[1].sum()) < 0.25 * inertia
        assert abs(P[1].sum() - Q[1].sum()) < 0.03 * np.abs(P[1]).max()
        assert abs(P[1] @ xs - Q[1] @ xn) < 0.25 * np.abs(Q[1] @ xn)
        assert P[0].real.sum() == pytest.approx(Q[0].real.sum(), rel=1e-6)


def test_wave_coupling_reduces_the_wave_induced_deck_motion(coupled_in_waves):
    """The cargo resists the hull's wave bending: the coupled deck's first harmonic differs
    less between the saddles than the one-way one, and the linear model needs one step."""
    case, model, excitation, rows = coupled_in_waves
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
    assert two.attrs["hull_cargo_coupling"].count("converged in") == 4
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
    ref = run_case(load_case(overrides={**NO_MOTIONS, "vessel.coupling": "two_way", "solver.method": method,
                                        "wave.amplitude_m": 0.5}))
    assert _static(ref)["F_N"] == pytest.approx(_static(hbm)["F_N"], rel=1e-6)
    assert "converged in" in ref.attrs["hull_cargo_coupling"]


def test_a_stiff_hull_makes_the_coupling_vanish():
    stiff = {**NO_MOTIONS, "vessel.hull_second_moment_m4": 103.8e3, "vessel.hull_shear_area_m2": 800.0}
    one = run_case(load_case(overrides=stiff))
    two = run_case(load_case(overrides={**stiff, "vessel.coupling": "two_way"}))
    assert _static(two)["F_N"] == pytest.approx(_static(one)["F_N"], rel=2e-3)


def test_two_way_coupling_needs_the_computed_hull(tmp_path):
    table = tmp_path / "deck.csv"
    table.write_text("x_m,still_water_m,wave_amplitude_m,wave_phase_rad\n0,0,0,0\n171,0,0,0\n")
    with pytest.raises(CaseError, match="vessel.coupling"):
        load_case(overrides={"vessel.coupling": "two_way", "vessel.deck_deflection_table": str(table)})
    with pytest.raises(CaseError, match="one_way"):
        load_case(overrides={"vessel.coupling": "both"})


def test_wave_coupled_hbm_agrees_with_the_coupled_exact_reference():
    """Two independent cargo solvers, each iterated with the hull to its own coupled state."""
    common = {"vessel.coupling": "two_way", "solver.contact_law": "exact", "solver.time_samples": 64,
              "wave.amplitude_m": 5.0}  # a larger wave, so that the cargo lifts off even when coupled
    hbm = run_case(load_case(overrides={**common, "solver.harmonics": 16}))
    ref = run_case(load_case(overrides={**common, "solver.method": "quasi_static"}))
    dyn = [next(r for r in res.summary if r["load_case"] == "dynamic" and r["model"] == "nonlinear") for res in (hbm, ref)]
    assert all(r["converged"] for r in dyn)
    assert dyn[0]["u_d_m"] > 1e-4  # contact is lost: the unilateral coupling is exercised
    assert dyn[0]["F_N"] == pytest.approx(dyn[1]["F_N"], rel=0.01)
    assert dyn[0]["M_b_Nm"] == pytest.approx(dyn[1]["M_b_Nm"], rel=0.01)


def test_a_coupling_that_does_not_converge_is_flagged_not_hidden(monkeypatch):
    import seafast.excitation.coupling as coupling

    original = coupling.couple_deck
    monkeypatch.setattr(coupling, "couple_deck", lambda *a, **k: original(*a, **{**k, "max_iterations": 0}))
    result = run_case(load_case(overrides={**NO_MOTIONS, "vessel.coupling": "two_way"}))
    assert not any(row["converged"] for row in result.summary)
    for message in result.arrays.solver_message.ravel():
        assert message.startswith("two-way coupling") and "NOT converged" in message


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
    from seafast.excitation import coupling

    case, model, excitation, _ = coupled_in_waves
    vessel = vessel_excitation(case)
    compliance = coupling.hull_compliance(vessel.girder, vessel.loading, model, vessel.cargo_aft_end_x_m, case.cargo.units_abreast)
    K, n_o = 3, model.deck_dof_count
    analytic = coupling.linear_coupling_jacobian(model, excitation.omega_rad_s, compliance, K)
    Q = coupling.spread_load_N(model, excitation, K)

    def residual(v):
        exc = coupling._with_deck_change(excitation, coupling._unpack(v, K, n_o), "")
        P = deck_forces_N(model, exc, solve_linear(model, exc), False, K)
        return v - coupling._pack(compliance.deck_change(P, Q))

    size = n_o * (2 * K - 1)
    r0 = residual(np.zeros(size))
    fd = np.column_stack([(residual(1e-6 * np.eye(size)[j]) - r0) / 1e-6 for j in range(size)])
    assert np.abs(analytic - np.eye(size)).max() > 0.1  # the coupling is not negligible
    np.testing.assert_allclose(analytic, fd, rtol=0, atol=1e-6 * np.abs(analytic).max())
