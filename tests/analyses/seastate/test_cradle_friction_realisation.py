"""A Monte Carlo realisation of the cargo on frictional pads (the frictional correction marched along the whole
stuck record) against the frictionless realisation as mu -> 0, where pads lift. docs/transverse.md#8-friction-at-the-pads."""

from __future__ import annotations

import numpy as np
import pytest

from seafast.analyses.cradle_run import pad_friction_of_case
from seafast.analyses.seastate.cradle_friction_realisation import evaluate_frictional_cradle_realisation, frictional_realisation_plan
from seafast.analyses.seastate.cradle_realisation import evaluate_cradle_realisation
from seafast.analyses.seastate.cradle_stuck_transfer import stuck_transfer_functions
from seafast.analyses.seastate.cradle_transfer import cradle_sea_model, cradle_unit_excitations
from seafast.analyses.seastate.directional_transfer import sea_state_roll_damping, sea_state_transfer
from seafast.analyses.seastate.monte_carlo import build_cradle_plan
from seafast.analyses.seastate.spectrum import sea_state_spectrum
from seafast.config.loader import load_case
from seafast.model.from_case import build_model
from seafast.solvers.cradle_friction import relaxed_at
from seafast.solvers.pad_tangential import pad_tangents

INDEX = 2
"""A realisation of the Hs 7 m beam sea below where pads lift (four windows in the frictionless one)."""


def _plans(mu: float):
    overrides = {
        "sea_state.heading_deg": 90.0,
        "sea_state.significant_height_m": 7.0,
        "sea_state.duration_s": 600.0,
        "seafastening.friction_coefficient": mu,
    }
    case = load_case(overrides=overrides)
    plan = build_cradle_plan(case)
    assert plan is not None
    model, spectrum = build_model(case), sea_state_spectrum(case)
    roll, sea = sea_state_roll_damping(case, spectrum), cradle_sea_model(case, model)
    dynamics, friction = sea.dynamics, pad_friction_of_case(case)
    assert friction is not None
    lo, hi = float(spectrum.omega_rad_s[0]), float(spectrum.omega_rad_s[-1])
    omega = np.linspace(lo, hi, int(np.ceil((hi - lo) / plan.settings.transfer_step_rad_s)) + 1)
    still = cradle_unit_excitations(sea, sea_state_transfer(case, model, omega[:1], roll).per_direction[0])[0].still_water()
    tangents = relaxed_at(pad_tangents(dynamics.problem, friction, dynamics.deck_x_m, dynamics.gravity_m_per_s2), dynamics, still)

    def stuck_at(w):
        return [stuck_transfer_functions(sea, tf, tangents) for tf in sea_state_transfer(case, model, w, roll).per_direction]

    return plan, frictional_realisation_plan(plan, dynamics, tangents, stuck_at, omega)


@pytest.mark.slow
def test_vanishing_friction_gives_the_frictionless_realisation_where_pads_lift():
    plan, friction = _plans(1e-9)
    frictionless = evaluate_cradle_realisation(plan, INDEX)
    frictional = evaluate_frictional_cradle_realisation(plan, friction, INDEX)
    assert frictionless["windows"] > 0 and frictionless["nonlinear"]["pad_lifted_fraction"] > 0.0
    assert frictional["solved"] and frictional["slipped_fraction"] == 1.0  # mu -> 0: every pad slides freely
    ours, theirs = frictional["nonlinear"], frictionless["nonlinear"]
    # the same sea, the same fine step: forces and the lateral displacement within 1e-3 (measured 6.5e-5 pad force,
    # 1.3e-7 lashing, 2.0e-4 lateral: the frictional march keeps the modes its step resolves, the windows theirs, and
    # samples every fine step where the frictionless one reads the coarse samples outside its windows)
    for q in ("F_pad_N", "lashing_tension_max_N", "lashing_tension_min_N", "transverse_slip_m"):
        assert ours[q] == pytest.approx(theirs[q], rel=1e-3), q
    assert ours["F_stopper_N"] == theirs["F_stopper_N"] == 0.0
    # the lifted fraction counts fine steps: within 5 % (measured 2.1 %, a step or so at each lift-off and touch-down)
    assert ours["pad_lifted_fraction"] == pytest.approx(theirs["pad_lifted_fraction"], rel=5e-2)
    assert ours["pad_slip_m"] > 0.0 and ours["lashing_slack_fraction"] == theirs["lashing_slack_fraction"] == 0.0


@pytest.mark.slow
def test_friction_lowers_the_pad_force_and_holds_the_cargo_in_the_same_sea():
    plan, friction = _plans(0.2)
    frictionless = evaluate_cradle_realisation(plan, INDEX)["nonlinear"]
    frictional = evaluate_frictional_cradle_realisation(plan, friction, INDEX)
    ours = frictional["nonlinear"]
    assert frictional["solved"] and 0.0 < frictional["slipped_fraction"] < 1.0
    assert ours["pad_friction_utilisation"] == pytest.approx(1.0, abs=1e-9)  # some pad slips: on its cone
    assert ours["F_pad_N"] < frictionless["F_pad_N"] and ours["transverse_slip_m"] < frictionless["transverse_slip_m"]


MC_BEAM = {
    "model.element_length_m": 4.0,
    "sea_state.peak_period_s": 10.0,
    "sea_state.heading_deg": 90.0,
    "sea_state.significant_height_m": 7.0,
    "sea_state.duration_s": 60.0,
    "sea_state.realisations": 3,
}


@pytest.mark.slow
def test_the_monte_carlo_on_frictional_pads_stores_the_frictional_realisations_and_their_statistics(tmp_path):
    """With the key the records' nonlinear cradle part is the frictional realisation's (a pure function of the plans and
    the index), its statistics gain the friction's most probable maxima, the linear part and statistics stay
    frictionless; with 0 there is no frictional plan."""
    import json

    from seafast.analyses.seastate.cradle_friction_realisation import case_frictional_plan
    from seafast.analyses.seastate.extremes import most_probable_maximum
    from seafast.analyses.seastate.monte_carlo import STORE_DIRECTORY, run_monte_carlo
    from seafast.output.seastate_cradle import monte_carlo_cradle_columns
    from seafast.parallel.store import DICT_RECORDS

    case = load_case(overrides={**MC_BEAM, "seafastening.friction_coefficient": 0.2})
    result = run_monte_carlo(case, tmp_path, workers=1, progress=False)
    lines = (tmp_path / STORE_DIRECTORY / DICT_RECORDS.records).read_text(encoding="utf-8").splitlines()
    records = sorted((json.loads(line)["record"] for line in lines), key=lambda r: r["index"])
    plan = build_cradle_plan(case)
    assert plan is not None
    friction = case_frictional_plan(case, plan)
    assert friction is not None and result.cradle is not None
    for r in records:
        again = evaluate_frictional_cradle_realisation(plan, friction, r["index"])
        assert r["cradle"]["nonlinear"] == pytest.approx(again["nonlinear"], rel=1e-12, abs=1e-15)
        assert r["cradle"]["linear"] == pytest.approx(evaluate_cradle_realisation(plan, r["index"])["linear"], rel=1e-12, abs=1e-15)
        assert r["cradle"]["solved"] and "pad_slip_m" not in r["cradle"]["linear"]
    linear, nonlinear = result.cradle
    assert "pad_slip_m" not in linear.mpm and "pad_friction_utilisation" not in linear.mpm
    slips = [r["cradle"]["nonlinear"]["pad_slip_m"] for r in records]
    np.testing.assert_array_equal(nonlinear.extremes["pad_slip_m"], slips)
    assert nonlinear.mpm["pad_slip_m"] == most_probable_maximum(np.array(slips), seed=case.sea_state.seed + 100 + 6).value
    columns = monte_carlo_cradle_columns(nonlinear)
    assert columns["pad_friction_utilisation"] == pytest.approx(1.0, abs=1e-9) and columns["pad_slip_m"] > 0.0
    assert "pad_slip_m" not in monte_carlo_cradle_columns(linear)
    assert case_frictional_plan(load_case(overrides={**MC_BEAM, "seafastening.friction_coefficient": 0.0}), plan) is None


@pytest.mark.slow
def test_a_short_crested_sea_draws_the_same_directions_for_the_frictional_record():
    """Short-crested (120 deg, s = 8) the frictional plan holds one block of stuck transfer functions per direction and a
    realisation draws its components' directions as the frictionless one does: as mu -> 0 the same forces (1e-3)."""
    from seafast.analyses.seastate.cradle_friction_realisation import case_frictional_plan

    overrides = {**MC_BEAM, "sea_state.heading_deg": 120.0, "sea_state.spreading_exponent": 8.0}
    case = load_case(overrides={**overrides, "seafastening.friction_coefficient": 1e-9})
    plan = build_cradle_plan(case)
    assert plan is not None and plan.direction_weights is not None
    friction = case_frictional_plan(case, plan)
    assert friction is not None and friction.transfer.shape[:2] == plan.transfer.shape[:2]
    for index in (0, 1):
        ours = evaluate_frictional_cradle_realisation(plan, friction, index)["nonlinear"]
        theirs = evaluate_cradle_realisation(plan, index)["nonlinear"]
        for q in ("F_pad_N", "lashing_tension_max_N", "transverse_slip_m"):
            assert ours[q] == pytest.approx(theirs[q], rel=1e-3), (index, q)
