"""Two-way hull-cargo coupling of the still-water state, checked against the hull-girder solver."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from seafast.config import CaseError, load_case
from seafast.excitation.coupling import CARGO_ITEM, deck_forces_N
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
    return case, model, vessel, excitation, couple_hull_and_cargo(case, model, excitation, vessel)


def test_deck_forces_carry_exactly_the_cargo_weight(coupled):
    case, model, _, excitation, result = coupled
    unit_weight_N = model.cargo.mass_kg * case.model.gravity_m_per_s2
    static = excitation.static_part()
    p_lin = deck_forces_N(model, static, solve_linear(model, static), nonlinear=False)
    p_nl = deck_forces_N(model, static, solve_nonlinear(model, static, case, static=True), nonlinear=True)
    for p in (p_lin, p_nl, result.deck_force_N):
        assert p.sum() == pytest.approx(unit_weight_N, rel=1e-9)  # the pretension is internal to cargo + deck
    # one-way: the middle saddle takes the hog (the source's finding)
    assert p_nl[1] > 2.0 * p_nl[0]


def test_coupled_deck_is_the_hull_girder_under_the_cargo_point_loads(coupled):
    """Independent check: re-solve the hull girder with the cargo's spread weight replaced by the
    converged deck forces (n units, 1 m patches), and compare the deck under the saddles."""
    case, model, vessel, excitation, result = coupled
    assert result.converged, result.message
    n = case.cargo.units_abreast
    g = case.model.gravity_m_per_s2
    xs = vessel.cargo_aft_end_x_m + model.saddle_x_m
    assert np.all(result.deck_force_N > 0.0)
    patches = tuple(WeightItem(f"saddle {i}", x - 0.5, x + 0.5, n * p / g) for i, (x, p) in enumerate(zip(xs, result.deck_force_N)))
    items = tuple(it for it in vessel.loading.items if it.name != CARGO_ITEM) + patches
    hull = still_water_response(vessel.girder, replace(vessel.loading, items=items))
    z, slope = deck_deflection_at(hull, xs)
    deck = np.real(result.excitation.deck_displacement[0])
    # the deck moved by millimetres from one-way; the two routes agree to 0.1 um (the hull meshes
    # differ: the patches add break points)
    change = deck - np.real(excitation.deck_displacement[0])
    assert np.max(np.abs(change[model.saddle_deck_dof])) > 5e-3
    np.testing.assert_allclose(deck[model.saddle_deck_dof], z, rtol=0, atol=1e-7)
    np.testing.assert_allclose(deck[model.saddle_deck_dof + 1], slope, rtol=0, atol=1e-9)
    # and the wave harmonics are untouched (the coupling is of the still-water state)
    np.testing.assert_array_equal(result.excitation.deck_displacement[1:], excitation.deck_displacement[1:])


def test_two_way_coupling_unloads_the_middle_saddle_of_the_base_case():
    one = run_case(load_case(overrides=NO_MOTIONS))
    two = run_case(load_case(overrides={**NO_MOTIONS, "vessel.coupling": "two_way"}))
    f1, f2 = _static(one)["F_N"], _static(two)["F_N"]
    # the four piles' point reactions push the hull down under the middle saddle, flattening the hog
    assert 0.75 * f1 < f2 < 0.9 * f1
    assert _static(two, "linear")["F_N"] == pytest.approx(f2, rel=5e-3)
    assert "converged in" in two.attrs["hull_cargo_coupling"]


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
