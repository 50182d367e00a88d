"""`seafast run` off head seas with `seafastening.friction_coefficient`: the cradle rows on frictional pads."""

from __future__ import annotations

import csv
import io
from dataclasses import replace

import numpy as np
import pytest

from seafast.analyses.cradle_run import case_cradle_excitation, cradle_dynamics_of_case, cradle_rows, pad_friction_of_case
from seafast.analyses.run import run_case
from seafast.config.loader import load_case
from seafast.excitation.cradle_loads import cradle_excitation
from seafast.model.cradle_case import build_cradle_case
from seafast.model.pad_friction import PadFriction
from seafast.output.tables import format_cradle_table, summary_csv_text
from seafast.results.cradle import CRADLE_SUMMARY_COLUMNS, FRICTION_SUMMARY_COLUMNS
from seafast.results.dataset import SUMMARY_COLUMNS
from seafast.solvers.cradle_friction import FrictionHBMOptions, relaxed_at, solve_cradle_friction_hbm
from seafast.solvers.pad_tangential import pad_tangents

# the base case in beam seas at H = 16 (cheap): 45 deg pads, no stoppers, two lashed saddles; no pad lifts
BEAM = {"wave.heading_deg": 90.0, "solver.harmonics": 16, "solver.time_samples": 128}
MU = 0.2
FORCE_COLUMNS = ("F_pad_N", "F_stopper_N", "lashing_tension_max_N", "lashing_tension_min_N")


@pytest.fixture(scope="module")
def frictionless():
    return run_case(load_case(overrides=BEAM))


@pytest.fixture(scope="module")
def frictional():
    return run_case(load_case(overrides={**BEAM, "seafastening.friction_coefficient": MU}))


def _summary(result) -> dict[tuple[str, str], dict]:
    return {(r["load_case"], r["model"]): r for r in result.summary}


def _library_solve(result, mu: float):
    """The dynamic row re-solved by the library directly: the case's cradles, the run's excitation, H = 16, N = 128,
    the sliders relaxed in still water."""
    cradle = build_cradle_case(result.case, result.model)
    dynamics = cradle_dynamics_of_case(cradle)
    excitation = case_cradle_excitation(cradle, result.excitation, result.vessel)
    solved = solve_cradle_friction_hbm(dynamics, PadFriction(mu), excitation, FrictionHBMOptions(16, 128), rest=excitation)
    return cradle, dynamics, excitation, solved


def test_beam_sea_columns_are_the_frictional_response_maxima(frictional):
    """The pads stick and slip; the summary's columns are the FrictionalCradleResponse's maxima, in order."""
    columns = frictional.summary_columns
    n = len(SUMMARY_COLUMNS) + len(CRADLE_SUMMARY_COLUMNS)
    assert columns[:n] == SUMMARY_COLUMNS + CRADLE_SUMMARY_COLUMNS and columns[n : n + 1] == FRICTION_SUMMARY_COLUMNS
    _, _, _, solved = _library_solve(frictional, MU)
    assert solved.converged
    use = solved.friction_utilisation
    closed = solved.normal_force_N > 0.0
    assert np.max(use) == pytest.approx(1.0, abs=1e-9)  # some pad slips ...
    assert np.min(use[closed]) < 0.9  # ... and some sticks part of the period
    slip = np.hypot(solved.slip_m[..., 0], solved.slip_m[..., 1])
    row = _summary(frictional)[("dynamic", "nonlinear")]
    assert row["converged"] and row["cradle_converged"]
    assert row["transverse_slip_m"] == pytest.approx(slip.max(), rel=1e-9)
    assert row["pad_friction_utilisation"] == pytest.approx(use.max(), rel=1e-9)
    assert row["F_pad_N"] == pytest.approx(solved.normal_force_N.max(), rel=1e-9)
    assert row["transverse_slip_m"] > 1e-4  # a real slip, 0.1 mm or more
    table = list(csv.reader(io.StringIO(summary_csv_text(frictional.summary, columns))))
    assert float(table[4][columns.index("pad_friction_utilisation")]) == row["pad_friction_utilisation"]
    assert "pad friction util." in format_cradle_table(frictional.summary)


def test_the_sliders_are_relaxed_in_still_water(frictional):
    """The sliders are relaxed at the frictionless still-water state (loads and the hull's still-water deck
    deflection): the still-water row carries no friction and no slip, and its pad forces are the frictionless ones."""
    row = frictional.cradle.rows[("static", "nonlinear")]
    f = row.friction
    assert f is not None and row.converged
    capacity = MU * float(np.max(f.normal_force_N))
    assert np.max(np.abs(f.friction_force_N)) <= 1e-9 * capacity
    assert np.max(np.abs(f.slip_m)) <= 1e-12
    fields = frictional.cradle.fields("static", "nonlinear")
    assert fields["transverse_slip_m"] <= 1e-12 and fields["pad_friction_utilisation"] <= 1e-9


def test_linear_rows_and_the_dataset(frictional, frictionless):
    """The linear rows are frictionless as before (NaN utilisation); results.nc carries labelled per-pad histories."""
    with_mu, without = _summary(frictional), _summary(frictionless)
    for lc in ("static", "dynamic"):
        row = with_mu[(lc, "linear")]
        assert np.isnan(row["pad_friction_utilisation"])
        for name in CRADLE_SUMMARY_COLUMNS:
            assert row[name] == without[(lc, "linear")][name]
    ds = frictional.dataset
    force = ds["pad_friction_force_N"].sel(load_case="dynamic", model="nonlinear")
    assert force.dims == ("cradle_period_fraction", "saddle", "pad_side", "pad_direction")
    assert ds["pad_friction_force_N"].attrs["units"] == "N" and ds["pad_slip_m"].attrs["units"] == "m"
    assert ds["pad_friction_utilisation_history"].attrs["long_name"]
    _, _, _, solved = _library_solve(frictional, MU)
    np.testing.assert_allclose(force.values.reshape(solved.friction_force_N.shape), solved.friction_force_N, rtol=1e-9, atol=1e-3)
    assert (
        float(ds["pad_friction_utilisation"].sel(load_case="dynamic", model="nonlinear"))
        == with_mu[("dynamic", "nonlinear")]["pad_friction_utilisation"]
    )
    assert np.all(np.isnan(ds["pad_slip_m"].sel(model="linear").values))
    assert "pad_friction_force_N" not in frictionless.dataset and "pad_direction" not in frictionless.dataset.coords
    assert frictionless.summary_columns[len(SUMMARY_COLUMNS) :] == CRADLE_SUMMARY_COLUMNS
    assert not any("pad_friction_utilisation" in r for r in frictionless.summary)


@pytest.mark.parametrize("mu", [0.0, 1e-3])
def test_vanishing_friction_gives_the_frictionless_run(mu, frictionless):
    """mu = 0: the frictionless forces, no utilisation, and the slip the pads' tangential motion from rest; a small mu
    moves each force by no more than the friction available, mu times the pads' forces."""
    result = run_case(load_case(overrides={**BEAM, "seafastening.friction_coefficient": mu}))
    with_mu, without = _summary(result), _summary(frictionless)
    cradle = build_cradle_case(frictionless.case, frictionless.model)
    dynamics = cradle_dynamics_of_case(cradle)
    excitation = case_cradle_excitation(cradle, frictionless.excitation, frictionless.vessel)
    tangents = pad_tangents(dynamics.problem, PadFriction(0.0), dynamics.deck_x_m, dynamics.gravity_m_per_s2)
    tangents = relaxed_at(tangents, dynamics, excitation)
    for lc in ("static", "dynamic"):
        row, reference = with_mu[(lc, "nonlinear")], without[(lc, "nonlinear")]
        assert row["converged"]
        pads = frictionless.cradle.rows[(lc, "nonlinear")].response.pad_force_N
        allowance = mu * float(np.sum(np.max(pads.reshape(pads.shape[0], -1), axis=0))) + 1e-6 * reference["F_pad_N"]
        for name in FORCE_COLUMNS:
            assert abs(row[name] - reference[name]) <= allowance
        if mu == 0.0:
            assert row["pad_friction_utilisation"] == 0.0
            # the slider follows the pad: its motion from the still-water rest, A_t q + E_t x_o - delta_rest, from the
            # frictionless row
            response = frictionless.cradle.rows[(lc, "nonlinear")].response
            deck = _deck(excitation if lc == "dynamic" else _still(excitation), response.time_s.size)
            position = response.cargo_displacement_m @ tangents.rows.T + deck @ tangents.deck.reshape(tangents.rows.shape[0], -1).T
            motion = position - tangents.rest_m.reshape(-1)
            slip = np.hypot(motion[:, 0::2], motion[:, 1::2]).max()
            assert row["transverse_slip_m"] == pytest.approx(slip, rel=1e-6, abs=1e-12)
        elif lc == "dynamic":
            assert row["pad_friction_utilisation"] == pytest.approx(1.0, abs=1e-9)
            assert max(abs(row[name] - reference[name]) for name in FORCE_COLUMNS) > 0.0
        else:  # still water: the sliders relaxed there, no friction
            assert row["pad_friction_utilisation"] <= 1e-9


def _still(excitation):
    keep = np.array([[1.0], [0.0]])
    return replace(excitation, deck_displacement=excitation.deck_displacement * keep)


def _deck(excitation, N: int) -> np.ndarray:
    from seafast.fourier import harmonics_to_time

    xo = np.array(excitation.deck_displacement, dtype=complex)
    xo[0] = xo[0].real
    return harmonics_to_time(xo, N)


@pytest.mark.slow
def test_where_pads_lift_and_slip_the_row_is_the_time_march(frictionless):
    """26 deg of roll on 20 deg pads with mu = 0.05: every pad lifts a quarter of the period (port and starboard in
    turn) and the cargo slides 78 mm round its cradles; the frictional harmonic balance does not converge and the row
    is the time march's (docs/transverse.md#8-friction-at-the-pads): converged, its step error the residual, every
    row on its grid."""
    case = load_case(overrides={**BEAM, "solver.harmonics": 8, "solver.time_samples": 64, "seafastening.saddle_contact_angle_deg": 20.0})
    base = run_case(case)
    cradle = build_cradle_case(base.case, base.model)
    dynamics = cradle_dynamics_of_case(cradle)
    vertical = replace(
        base.excitation,
        omega_rad_s=0.6,
        cargo_load_N=0.0 * base.excitation.cargo_load_N,
        deck_displacement=0.0 * base.excitation.deck_displacement,
    )
    motions = np.array([0, 0, 0, np.deg2rad(26.0), 0, 0], dtype=complex)
    excitation = cradle_excitation(cradle.cargo, vertical, motions, base.model.saddle_x_m, (0.0, 0.0, 0.0))
    rows = cradle_rows(base.case, cradle, dynamics, excitation, PadFriction(0.05))
    key = ("dynamic", "nonlinear")
    fields = rows.fields(*key)
    assert fields["cradle_converged"] and fields["cradle_outcome"] == "converged_by_time_march"
    assert 0.0 < fields["cradle_residual"] <= 5e-3 and "marched in time" in fields["cradle_message"]
    dynamic = rows.rows[key]
    pads = dynamic.response.engagement_m[:, : dynamic.response.pad_count]
    assert np.all((np.mean(pads < 0.0, axis=0) > 0.2) & (np.mean(pads < 0.0, axis=0) < 0.35))
    assert fields["pad_friction_utilisation"] == pytest.approx(1.0, abs=1e-9) and fields["transverse_slip_m"] > 0.05
    assert all(row.response.time_s.size == 4096 for row in rows.rows.values())
    result = replace(base, cradle=rows)
    assert all(r["converged"] for r in _summary(result).values())


def test_friction_differing_between_saddles_is_refused_naming_the_key():
    case = load_case(overrides={"wave.heading_deg": 90.0, "seafastening.friction_coefficient": [0.1, 0.2, 0.1]})
    with pytest.raises(ValueError, match=r"seafastening.friction_coefficient = \[0.1, 0.2, 0.1\].*allowed one value"):
        pad_friction_of_case(case)
    assert pad_friction_of_case(load_case(overrides={"seafastening.friction_coefficient": [0.3, 0.3, 0.3]})) == PadFriction(0.3)
    assert pad_friction_of_case(load_case()) is None
