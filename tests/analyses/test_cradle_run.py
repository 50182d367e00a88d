"""`seafast run` off head seas: the cargo on its cradles in the four rows (docs/transverse.md#9-in-seafast-run)."""

from __future__ import annotations

import csv
import io
from dataclasses import replace

import numpy as np
import pytest
import scipy.linalg

from round_off import SOLVER_RTOL
from seafast.analyses.cradle_run import cradle_dynamics_of_case, cradle_rows
from seafast.analyses.run import run_case
from seafast.config.loader import load_case
from seafast.excitation.cradle_loads import cradle_excitation
from seafast.model.cradle_case import build_cradle_case
from seafast.output.tables import format_cradle_table, summary_csv_text
from seafast.results.cradle import CRADLE_SUMMARY_COLUMNS
from seafast.results.dataset import SUMMARY_COLUMNS
from seafast.results.validity import ValidityLimit
from seafast.solvers.transverse_statics import StaticsOutcome, solve_transverse_statics

BEAM = {"wave.heading_deg": 90.0}
# 20 deg pads with side stoppers 2 mm off the tube: in beam seas the stoppers engage and a linear pad would pull
NONLINEAR = {
    **BEAM,
    "seafastening.saddle_contact_angle_deg": 20.0,
    "seafastening.side_stopper.gap_m": 0.002,
    "seafastening.side_stopper.stiffness_N_per_m": 1e9,
}

# today's summary.csv of the base case (head seas), the vertical plane alone
HEAD_SEAS_SUMMARY = """load_case,model,u_c_m,u_s_m,u_d_m,F_N,M_b_Nm,sigma_b_Pa,converged
static,linear,0.005332290963469946,0.0057322720184692505,0.0,6305499.220316175,49006602.97254627,12558705.144729758,true
static,nonlinear,0.005332290963469946,0.0057322720184692505,0.0,6305499.220316175,49006602.97254627,12558705.144729758,true
dynamic,linear,0.0069173104312713896,0.01171860767149964,0.0,12890468.438649602,122914247.0836855,31498689.841351014,true
dynamic,nonlinear,0.00931767288298127,0.010284960620266658,0.007683117557895218,11313456.682293324,105038633.3187472,26917785.454228003,true
"""


@pytest.fixture(scope="module")
def beam_sea():
    return run_case(load_case(overrides=BEAM))


@pytest.fixture(scope="module")
def beam_sea_stoppers():
    return run_case(load_case(overrides=NONLINEAR))


def _rows(text: str) -> list[list[str]]:
    return list(csv.reader(io.StringIO(text)))


def test_head_seas_summary_is_todays():
    """Head seas: no cradle solve, summary.csv's columns and values today's (labels exact, numbers to the solvers'
    round-off across machines, tests/round_off.py)."""
    result = run_case(load_case())
    assert result.cradle is None and result.summary_columns == SUMMARY_COLUMNS
    assert not any(key in row for row in result.summary for key in CRADLE_SUMMARY_COLUMNS)
    got, today = _rows(summary_csv_text(result.summary, result.summary_columns)), _rows(HEAD_SEAS_SUMMARY)
    assert [len(r) for r in got] == [len(r) for r in today] and got[0] == today[0]
    for row, expected in zip(got[1:], today[1:], strict=True):
        assert row[:2] == expected[:2] and row[-1] == expected[-1]
        np.testing.assert_allclose(np.array(row[2:-1], dtype=float), np.array(expected[2:-1], dtype=float), rtol=SOLVER_RTOL, atol=0.0)
    assert "pad_force_N" not in result.dataset


def _independent_maxima(result, lc: str, model: str) -> dict[str, float]:
    """The five columns from the row's element histories, split by the cradle case's own element counts."""
    cradle = build_cradle_case(result.case, result.model)
    response = result.cradle.rows[(lc, model)].response
    n_pad, n_stop = 2 * len(cradle.pad_pairs), len(cradle.stoppers)
    forces = response.element_force_N
    v = [cradle.cargo.node_dofs(cradle.cargo.node_at(float(x)))[1] for x in cradle.saddle_x_m]
    wires = forces[:, n_pad + n_stop :]
    return {
        "F_pad_N": forces[:, :n_pad].max(),
        "F_stopper_N": forces[:, n_pad : n_pad + n_stop].max() if n_stop else 0.0,
        "lashing_tension_max_N": wires.max(),
        "lashing_tension_min_N": wires.min(),
        "transverse_slip_m": np.abs(response.cargo_displacement_m[:, v]).max(),
    }


@pytest.mark.parametrize("fixture", ["beam_sea", "beam_sea_stoppers"])
def test_summary_columns_are_the_cradle_rows_maxima(fixture, request):
    """Off head seas the five columns follow converged in summary.csv and hold each row's maxima."""
    result = request.getfixturevalue(fixture)
    columns = result.summary_columns
    assert columns[: columns.index("converged") + 1] == SUMMARY_COLUMNS
    assert columns[len(SUMMARY_COLUMNS) :] == CRADLE_SUMMARY_COLUMNS
    table = _rows(summary_csv_text(result.summary, columns))
    assert table[0] == list(columns)
    for row, line in zip(result.summary, table[1:], strict=True):
        expected = _independent_maxima(result, row["load_case"], row["model"])
        for name, value in expected.items():
            assert float(line[columns.index(name)]) == pytest.approx(value, rel=1e-12, abs=1e-15)
        assert row["converged"] and row["cradle_converged"]
        ds_row = result.dataset.sel(load_case=row["load_case"], model=row["model"])
        assert all(float(ds_row[name]) == row[name] for name in CRADLE_SUMMARY_COLUMNS)
        assert float(ds_row["lashing_wire_tension_min_N"].min()) == row["lashing_tension_min_N"]
    assert "pad [MN]" in format_cradle_table(result.summary)


def test_base_case_in_beam_seas_keeps_every_pad_and_wire_engaged(beam_sea):
    """45 deg pads, no stoppers, 16 deg of roll: no pad lifts and no wire slackens, so the nonlinear rows are the
    linear ones (two solvers: the harmonic balance and the direct bilateral solve), and in still water the pads
    carry the weight plus the wires' pull."""
    rows = beam_sea.cradle.rows
    dynamic = rows[("dynamic", "nonlinear")].response
    assert np.all(dynamic.open_fraction == 0.0)
    assert np.rad2deg(abs(beam_sea.vessel.motion_amplitudes[3])) > 10.0  # a real roll, not a quiet sea
    for lc in ("static", "dynamic"):
        linear, nonlinear = rows[(lc, "linear")].response, rows[(lc, "nonlinear")].response
        scale = np.max(np.abs(nonlinear.element_force_N))
        np.testing.assert_allclose(linear.element_force_N, nonlinear.element_force_N, atol=1e-8 * scale)
    still = rows[("static", "nonlinear")].response
    cradle = build_cradle_case(beam_sea.case, beam_sea.model)
    w = np.arange(0, 2 * cradle.cargo.node_count, 2)  # the vertical translations: e^T M e is the cargo's mass
    weight = beam_sea.model.gravity_m_per_s2 * cradle.cargo.mass[np.ix_(w, w)].sum()
    wire_down = -np.array([w.direction[2] for w in cradle.lashings]) @ still.lashing_tension_N[0]
    np.testing.assert_allclose(still.pair_force_N[0, :, 1].sum(), weight + wire_down, rtol=1e-9)
    assert abs(still.pair_force_N[0, :, 0].sum()) < 1e-9 * weight
    assert "pad_force_N" in beam_sea.dataset and beam_sea.dataset["pad_force_N"].attrs["units"] == "N"


def test_linear_pad_in_tension_is_flagged_and_nonlinear_rows_engage_the_stoppers(beam_sea_stoppers):
    """20 deg pads: the linear wave row's pad pulls (flagged beyond validity), the nonlinear one stays >= 0 and the
    stoppers carry the lateral load the pads cannot."""
    summary = {(r["load_case"], r["model"]): r for r in beam_sea_stoppers.summary}
    linear, nonlinear = summary[("dynamic", "linear")], summary[("dynamic", "nonlinear")]
    assert linear["pad_force_min_N"] < 0.0 and not linear["within_validity"]
    assert ValidityLimit.PAD_TENSION in linear["warnings"]
    (issue,) = [i for i in beam_sea_stoppers.validity if i.limit is ValidityLimit.PAD_TENSION]
    assert (issue.load_case, issue.model) == ("dynamic", "linear") and issue.value == pytest.approx(-linear["pad_force_min_N"])
    assert "linear cradle model's validity" in issue.message
    assert nonlinear["pad_force_min_N"] >= 0.0 and nonlinear["within_validity"]
    assert nonlinear["F_stopper_N"] > 0.05 * nonlinear["F_pad_N"]
    assert linear["F_stopper_N"] == 0.0 and linear["stopper_overclosure_m"] > 0.0  # the linear row leaves them open
    assert summary[("static", "linear")]["within_validity"]
    ds = beam_sea_stoppers.dataset
    assert float(ds["stopper_open_fraction"].sel(load_case="dynamic", model="nonlinear").min()) < 1.0


def _roll_only(result, omega: float, roll_rad: float):
    """The base case's cradle model under a roll of ``roll_rad`` at ``omega`` about the cargo's axis, deck still."""
    cradle = build_cradle_case(result.case, result.model)
    dynamics = cradle_dynamics_of_case(cradle)
    vertical = replace(
        result.excitation,
        omega_rad_s=omega,
        cargo_load_N=0.0 * result.excitation.cargo_load_N,
        deck_displacement=0.0 * result.excitation.deck_displacement,
    )
    motions = np.array([0, 0, 0, roll_rad, 0, 0], dtype=complex)
    excitation = cradle_excitation(cradle.cargo, vertical, motions, result.model.saddle_x_m, (0.0, 0.0, 0.0))
    return cradle, dynamics, excitation


def _lowest_lateral_frequency(dynamics) -> float:
    """omega_1 [rad/s] of the cargo on its bilateral pads and wires (K_lin, M)."""
    parts = dynamics.linear_parts(dynamics.damping_set)
    return float(np.sqrt(scipy.linalg.eigh(parts.bilateral_stiffness, dynamics.matrices[1], eigvals_only=True)[0]))


def test_long_beam_sea_roll_tends_to_the_statics_of_the_heeled_ship(beam_sea):
    """Roll alone, slow: each element's peak over the period is the exact statics at the roll amplitude.

    The harmonic load is gravity linearised, (0, -g phi, -g), the exact equivalent of a heel atan(phi) under
    g sqrt(1 + phi^2); what is left is the cargo's dynamic amplification on its restraints, 1 / (1 - r^2) - 1 = r^2
    to first order in r = omega / omega_1 (the damping's phase lag costs only r^2 at a peak too): the difference is
    within 2 r^2 of the wave's part of the force, and shrinks as omega^2.
    """
    phi = np.deg2rad(5.0)
    errors = []
    for omega in (0.6, 2.4):
        cradle, dynamics, excitation = _roll_only(beam_sea, omega, phi)
        rows = cradle_rows(beam_sea.case, cradle, dynamics, excitation)
        response = rows.rows[("dynamic", "nonlinear")].response
        statics = [
            solve_transverse_statics(dynamics.problem, np.rad2deg(np.arctan(sign * phi)), gravity_m_per_s2=9.81 * np.hypot(1.0, phi))
            for sign in (1.0, -1.0)
        ]
        assert all(s.outcome is StaticsOutcome.CONVERGED for s in statics) and response.converged
        forces = [np.concatenate([s.pad_force_N.ravel(), s.stopper_force_N, s.lashing_tension_N]) for s in statics]
        still = rows.rows[("static", "nonlinear")].response.element_force_N[0]
        wave_part = np.max(np.abs(forces[0] - still))
        r = omega / _lowest_lateral_frequency(dynamics)
        error = np.max(np.abs(response.max_force_N - np.maximum(*forces)))
        assert error <= 2.0 * r**2 * wave_part + 1e-9 * np.max(forces[0])
        errors.append(error)
    assert errors[1] > 8.0 * errors[0]  # the difference is the dynamics: 16 times larger at four times omega


def test_a_cradle_row_that_did_not_converge_is_flagged_with_its_residual(beam_sea):
    """The row's converged is false, its residual and outcome reach the summary and the terminal table."""
    from seafast.output.tables import format_summary_table
    from seafast.results.cradle import CradleRows
    from seafast.solvers.outcome import SolverOutcome

    rows = dict(beam_sea.cradle.rows)
    key = ("dynamic", "nonlinear")
    failed = replace(rows[key].response, outcome=SolverOutcome.NOT_CONVERGED, residual=0.25)
    rows[key] = replace(rows[key], response=failed)
    result = replace(beam_sea, cradle=CradleRows(rows, beam_sea.cradle.layout))
    summary = {(r["load_case"], r["model"]): r for r in result.summary}
    assert not summary[key]["converged"] and summary[key]["cradle_residual"] == 0.25
    assert summary[key]["cradle_outcome"] == "not_converged"
    assert all(r["converged"] for k, r in summary.items() if k != key)
    assert "NO (cradle residual 2.50e-01)" in format_summary_table(result.summary)
    assert "false" in summary_csv_text(result.summary, result.summary_columns).splitlines()[4]
    ds = result.dataset
    assert not bool(ds["converged"].sel(load_case="dynamic", model="nonlinear"))
    assert str(ds["cradle_solver_outcome"].sel(load_case="dynamic", model="nonlinear").values) == "not_converged"
    assert bool(ds["converged"].sel(load_case="static", model="nonlinear"))


def test_the_cross_sections_are_drawn_off_head_seas_only(beam_sea_stoppers, tmp_path):
    from seafast.output.case_figures import case_figure_names, draw_case_figure

    ds = beam_sea_stoppers.dataset
    assert "cradle_sections" in case_figure_names(ds)
    assert "cradle_sections" not in case_figure_names(ds.drop_vars("pad_force_max_N"))
    path = draw_case_figure(ds, "cradle_sections", tmp_path)
    assert path.stat().st_size > 10_000
