"""The vessel side of a case: alternative inputs give the same deck excitation as the hull model."""

from __future__ import annotations

import numpy as np
import pytest

from seafast.analyses.run import run_case
from seafast.config import load_case
from seafast.excitation.vessel import VesselCache, shared_vessel_cache, vessel_excitation
from seafast.excitation.vessel_inputs import hull_form_of
from seafast.model.from_case import build_model

NO_MOTIONS = {"vessel.motions": "none"}


def _deck(case):
    model = build_model(case)
    return vessel_excitation(case).cargo_excitation(model, case).deck_displacement


def _middle_rise_m(deck):
    """Rise of the middle of five deck points over the mean of the outer two [m]."""
    return deck[2].real - 0.5 * (deck[0].real + deck[4].real)


def test_still_water_moment_table_reproduces_the_computed_hull(tmp_path):
    """A loading-computer moment table equal to the hull model's moment gives the same deck."""
    base = load_case(overrides=NO_MOTIONS)
    sw = vessel_excitation(base).still_water
    table = tmp_path / "swbm.csv"
    table.write_text(
        "x_m,bending_moment_Nm\n" + "\n".join(f"{float(x)!r},{float(m)!r}" for x, m in zip(sw.x_m, sw.bending_moment_Nm, strict=True))
    )
    case = load_case(overrides={**NO_MOTIONS, "vessel.still_water_bending_moment_table": str(table)})
    deck_table, deck_model = _deck(case)[0], _deck(base)[0]
    # spline integration of the tabulated moment (shear deflection from dM/dx) vs the Timoshenko
    # FE: the relative rise of the middle deck point is what loads the cargo (5.75 mm)
    assert _middle_rise_m(deck_model) == pytest.approx(5.75e-3, rel=0.01)
    assert _middle_rise_m(deck_table) == pytest.approx(_middle_rise_m(deck_model), rel=1e-4)
    f_table = run_case(case).summary[0]["F_N"]
    f_model = run_case(base).summary[0]["F_N"]
    assert f_table == pytest.approx(f_model, rel=1e-3)
    assert "moment table" in vessel_excitation(case).source


def test_hull_form_table_equals_the_parametric_hull(tmp_path):
    base = load_case(overrides=NO_MOTIONS)
    hull = hull_form_of(base)
    table = tmp_path / "hull.csv"
    table.write_text(
        "x_m,breadth_m\n" + "\n".join(f"{float(x)!r},{float(b)!r}" for x, b in zip(hull.station_x_m, hull.waterline_breadth_m, strict=True))
    )
    case = load_case(overrides={**NO_MOTIONS, "vessel.hull_form_table": str(table)})
    np.testing.assert_allclose(_deck(case), _deck(base), rtol=1e-9, atol=1e-12)


def test_zero_wave_amplitude_leaves_only_the_static_part():
    case = load_case(overrides={**NO_MOTIONS, "wave.amplitude_m": 0.0})
    deck = _deck(case)
    assert np.all(deck[1] == 0)
    rows = run_case(case).summary
    static, dynamic = rows[0], rows[2]
    assert dynamic["F_N"] == pytest.approx(static["F_N"], rel=1e-12)


def test_heavy_cargo_falls_back_to_even_keel_ballast_and_says_so():
    case = load_case(
        overrides={
            **NO_MOTIONS,
            "cargo.length_m": 115,
            "cargo.diameter_m": 12,
            "cargo.wall_thickness_m": 12 / 110,
            "cargo.units_abreast": 3,
        }
    )
    assert "even keel only" in vessel_excitation(case).source


def test_wave_deck_motion_scales_with_amplitude():
    d1 = _deck(load_case(overrides={**NO_MOTIONS, "wave.amplitude_m": 1.0}))[1]
    d3 = _deck(load_case(overrides={**NO_MOTIONS, "wave.amplitude_m": 3.0}))[1]
    np.testing.assert_allclose(d3, 3.0 * d1, rtol=1e-4, atol=1e-9)


def test_deck_excitation_from_the_cached_interpolants_equals_the_hull_response():
    """The vessel builds its deck interpolants once; they give deck_deflection_at / deck_harmonics_at."""
    import pickle

    from seafast.hull.deck import deck_deflection_at, deck_harmonics_at

    case = load_case(overrides=NO_MOTIONS)
    vessel, model = vessel_excitation(case), build_model(case)
    x = vessel.cargo_aft_end_x_m + model.saddle_x_m
    deck = vessel.cargo_excitation(model, case).deck_displacement
    z0, s0 = deck_deflection_at(vessel.still_water, x)
    z, s = deck_harmonics_at(vessel.wave, x)
    np.testing.assert_allclose(deck[0, 0::2].real, z0, rtol=1e-13, atol=0)
    np.testing.assert_allclose(deck[0, 1::2].real, s0, rtol=1e-13, atol=0)
    np.testing.assert_allclose(deck[1, 0::2], z[1], rtol=1e-13, atol=0)
    np.testing.assert_allclose(deck[1, 1::2], s[1], rtol=1e-13, atol=0)
    assert np.abs(deck[1, 0::2]).max() > 1e-3  # a wave that bends the hull by millimetres
    again = pickle.loads(pickle.dumps(vessel))  # the interpolants are not pickled, and rebuilt
    np.testing.assert_array_equal(again.cargo_excitation(model, case).deck_displacement, deck)


def test_still_water_state_taken_from_the_wave_balance_equals_a_still_water_solve():
    """The vessel balances the hull once (the wave response's first row is the still-water state)."""
    from seafast.hull.still_water import still_water_response

    vessel = vessel_excitation(load_case(overrides=NO_MOTIONS))
    fresh = still_water_response(vessel.girder, vessel.loading)
    for name in ("deflection_m", "slope_rad", "bending_moment_Nm", "shear_force_N", "buoyancy_N_per_m"):
        a, b = getattr(vessel.still_water, name), getattr(fresh, name)
        np.testing.assert_allclose(a, b, rtol=0, atol=1e-12 * np.max(np.abs(b)), err_msg=name)
    assert vessel.still_water.sinkage_m == pytest.approx(fresh.sinkage_m, abs=1e-12)
    assert np.max(np.abs(fresh.bending_moment_Nm)) > 1e8  # a hull in real hog, not a trivial zero


def test_a_vessel_cache_keeps_each_vessel_once_and_nothing_is_kept_without_one():
    """Explicit cache: a change of the sea-fastening finds the kept vessel, a change of the cargo computes
    another on the same kept hull form and BEM data; without a cache every call computes afresh, to the
    same bits."""
    cache = VesselCache()
    base = load_case()
    kept = vessel_excitation(base, cache)
    assert vessel_excitation(load_case(overrides={"seafastening.saddle_count": 4}), cache) is kept
    fresh = vessel_excitation(base)
    assert fresh is not kept and fresh is not vessel_excitation(base)
    for name in ("deflection_m", "bending_moment_Nm", "slope_rad", "buoyancy_N_per_m"):
        np.testing.assert_array_equal(getattr(fresh.still_water, name), getattr(kept.still_water, name))
    np.testing.assert_array_equal(fresh.wave.deflection_harmonics_m, kept.wave.deflection_harmonics_m)
    np.testing.assert_array_equal(fresh.motions.pitch_rao_rad_per_m, kept.motions.pitch_rao_rad_per_m)
    assert fresh.rigid_body == kept.rigid_body
    longer = vessel_excitation(load_case(overrides={"cargo.length_m": 90.0}), cache)
    assert longer is not kept and len(cache) == 2
    assert longer.girder.hull is kept.girder.hull  # one hull form for every loading
    assert len(cache.hydrodynamics.datasets) == 1 and len(cache.hydrodynamics.coefficients) == 1
    assert longer.motions.reference_x_m != kept.motions.reference_x_m  # the loading moved the centre of gravity


def test_a_shared_vessel_cache_serves_the_calls_inside_its_block_only():
    case = load_case(overrides=NO_MOTIONS)
    outer, inner = VesselCache(), VesselCache(max_vessels=1)
    assert shared_vessel_cache() is None
    with outer.shared():
        assert shared_vessel_cache() is outer
        kept = vessel_excitation(case)
        assert vessel_excitation(case) is kept and len(outer) == 1
        with inner.shared():
            assert vessel_excitation(case) is not kept and len(inner) == 1
            other = vessel_excitation(load_case(overrides={**NO_MOTIONS, "wave.amplitude_m": 2.0}))
            assert len(inner) == 1 and vessel_excitation(load_case(overrides={**NO_MOTIONS, "wave.amplitude_m": 2.0})) is other
        assert shared_vessel_cache() is outer and vessel_excitation(case) is kept
    assert shared_vessel_cache() is None and vessel_excitation(case) is not kept
    with pytest.raises(ValueError, match="max_vessels = 0"):
        VesselCache(max_vessels=0)
