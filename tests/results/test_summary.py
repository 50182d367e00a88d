"""Summary quantities from harmonics (seafast.results.summary) against closed forms."""

from __future__ import annotations

import numpy as np
import pytest

from seafast.excitation.harmonic import HarmonicExcitation
from seafast.model.seafastening import SeaFastening
from seafast.model.sections import CargoGeometry, TubeSegment, tube_area_m2, tube_second_moment_m4
from seafast.model.structure import build_structural_model
from seafast.results.summary import RowSolution, summary_row
from seafast.solvers.linear import solve_linear
from seafast.solvers.periodic import CargoHistory

L, D, T, RHO, G = 74.0, 8.0, 0.08, 7850.0, 9.81
K_SADDLE = 1e14  # rigid supports for the closed forms


def _model(xs, damping_ratio=0.02):
    geometry = CargoGeometry((TubeSegment(0.0, L, D, D, T),), youngs_modulus_Pa=210e9, density_kg_per_m3=RHO)
    sf = SeaFastening(
        np.asarray(xs, float),
        np.full(len(xs), K_SADDLE),
        np.zeros(len(xs), bool),
        lashing_wire_stiffness_N_per_m=0.0,
        lashing_pretension_N=0.0,
    )
    # 0.37 m elements put nodes at the supports (14.8 m = 40 elements) and midspan (44.4 m = 120)
    return build_structural_model(geometry, sf, target_element_length_m=0.3700001, damping_ratio=damping_ratio)


def _linear_row(model, excitation):
    resp = solve_linear(model, excitation)
    n_t = 1 if excitation.harmonic_count == 1 else 64
    from seafast.fourier import harmonics_to_time

    delta = harmonics_to_time(resp.saddle_compression_m, n_t)
    return RowSolution(resp.cargo_displacement, delta, harmonics_to_time(resp.saddle_force_N, n_t), excitation, nonlinear=False)


def test_static_beam_on_two_supports_with_overhangs():
    a = 0.2 * L
    model = _model([a, L - a])
    exc = HarmonicExcitation(
        0.6, np.zeros((1, 4), complex), np.zeros((1, model.cargo_dof_count), complex), np.zeros((1, model.cargo.element_count), complex)
    )
    row = summary_row(model, "static", "linear", _linear_row(model, exc), 64)
    w = RHO * float(tube_area_m2(D, T)) * G  # weight per metre [N/m]
    span = L - 2 * a
    # hogging over the supports -w a^2/2, sagging midspan w span^2/8 - w a^2/2 (here the larger)
    m_mid = w * span**2 / 8 - w * a**2 / 2
    assert row["M_b_Nm"] == pytest.approx(max(abs(m_mid), w * a**2 / 2), rel=1e-6)
    assert row["sigma_b_Pa"] == pytest.approx(row["M_b_Nm"] * (D / 2) / float(tube_second_moment_m4(D, T)), rel=1e-12)
    assert row["F_N"] == pytest.approx(w * L / 2, rel=1e-9)
    assert row["u_s_m"] == pytest.approx(w * L / 2 / K_SADDLE, rel=1e-6)
    assert row["u_d_m"] == 0.0 and row["contact_preserved"] and row["converged"]
    # cargo deflection from the support line: the larger of the overhang tip (cantilever droop
    # w a^4 / 8 EI less the support rotation's lift a theta) and the midspan sag, plus the
    # supports' own settlement W / 2k (the baseline is the deck, the cargo sits that much lower)
    EI = 210e9 * float(tube_second_moment_m4(D, T))
    theta = (w * span**3 / 24 - w * a**2 / 2 * span / 2) / EI  # support rotation, symmetric beam
    tip = w * a**4 / (8 * EI) - a * theta
    midspan = 5 * w * span**4 / (384 * EI) - (w * a**2 / 2) * span**2 / (8 * EI)
    assert row["u_c_m"] == pytest.approx(max(abs(tip), abs(midspan)) + w * L / 2 / K_SADDLE, rel=1e-7)


def test_rigid_deck_motion_is_not_cargo_deflection():
    # the deck under both saddles heaves and pitches rigidly (a straight line): the cargo on rigid
    # supports follows, so relative to the sea-fastening baseline it only bends under its weight
    # (undamped, and slow enough that the inertia of the motion is 1e-9 of the weight)
    a = 0.2 * L
    model = _model([a, L - a], damping_ratio=0.0)
    xs = model.saddle_x_m
    deck = np.zeros((2, 4), complex)
    heave, pitch = 0.05 * np.exp(0.3j), 0.002 * np.exp(-1.1j)
    deck[1, 0::2] = heave + pitch * (xs - L / 2)
    deck[1, 1::2] = pitch
    zeros_c, zeros_e = np.zeros((2, model.cargo_dof_count), complex), np.zeros((2, model.cargo.element_count), complex)
    moving = summary_row(model, "dynamic", "linear", _linear_row(model, HarmonicExcitation(1e-3, deck, zeros_c, zeros_e)), 64)
    still = summary_row(model, "dynamic", "linear", _linear_row(model, HarmonicExcitation(1e-3, np.zeros_like(deck), zeros_c, zeros_e)), 64)
    assert moving["u_c_m"] == pytest.approx(still["u_c_m"], rel=1e-6)  # 50 mm of heave removed by the frame
    assert moving["M_b_Nm"] == pytest.approx(still["M_b_Nm"], rel=1e-6)


def test_a_factored_history_gives_the_summary_of_its_harmonics_and_of_its_time_series():
    """Stiff saddles (8192 samples a period): the moments from the shooting's few time functions equal those of the
    cargo's harmonics (round-off) and those of the sampled history's moment lines (the results' Dataset route)."""
    from seafast.analyses.run import run_case
    from seafast.config import load_case
    from seafast.results.dataset import summary_rows_from_arrays
    from seafast.results.summary import FACTORED_SAMPLES, summary_rows

    result = run_case(load_case(overrides={"seafastening.saddle_stiffness_N_per_m": 1.1e10}), cradles=False)
    response = result.rows.nonlinear("dynamic")
    history, N = response.cargo_history, result.rows.time_samples
    assert history.factored and N == response.time_samples >= FACTORED_SAMPLES and response.max_gap_m > 0.0
    excitation = result.rows.excitations[("dynamic", "nonlinear")]
    forces = (response.saddle_compression_time_m, response.saddle_force_time_N, excitation, True)
    factored = RowSolution(None, *forces, cargo_factors=history)
    dense = RowSolution(response.cargo_displacement_harmonics, *forces)
    got, expected = summary_rows(result.model, [("dynamic", "nonlinear", factored), ("dynamic", "nonlinear", dense)], N)
    from_arrays = next(
        r
        for r in summary_rows_from_arrays(result.arrays, result.model.cargo.node_x_m)
        if r["load_case"] == "dynamic" and r["model"] == "nonlinear"
    )
    for key in ("u_c_m", "M_b_Nm", "sigma_b_Pa", "cargo_slope_rad", "u_d_m", "F_N"):
        assert got[key] == pytest.approx(expected[key], rel=1e-10), key
        assert got[key] == pytest.approx(from_arrays[key], rel=1e-9), key
    assert got["M_b_Nm"] > 5e7  # a bending moment of the base case's size, not a zero read from an empty channel
    assert result.summary[3]["M_b_Nm"] == got["M_b_Nm"]  # what the run and a study report


def test_a_row_is_given_by_its_harmonics_or_its_factors_not_both():
    history = CargoHistory(np.ones((4, 2)), np.ones((3, 2), complex), np.ones((2, 6)))
    exc = HarmonicExcitation(0.6, np.zeros((1, 4), complex), np.zeros((1, 6), complex), np.zeros((1, 2), complex))
    with pytest.raises(ValueError, match="either cargo_harmonics or factored cargo_factors"):
        RowSolution(np.ones((3, 6), complex), np.ones((4, 1)), np.ones((4, 1)), exc, True, cargo_factors=history)
    with pytest.raises(ValueError, match="either cargo_harmonics or factored cargo_factors"):
        RowSolution(None, np.ones((4, 1)), np.ones((4, 1)), exc, True)
