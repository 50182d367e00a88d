"""One solve of a case's four rows, read alike by its summary and by its dataset.

``CaseResult.summary`` (what ``summary.csv`` and a study record) reads the rows from the solution's
harmonics (``seafast.results.summary``: moments per harmonic, sampled once); the dataset (``results.nc``)
reads them from the period time series and moment lines (``seafast.results.dataset``). Two readings of
the same solution: a wrong sign, factor, harmonic or frame in either would show here far beyond the
tolerances (round-off of the moment sampling). A study point never forms the time series.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from seafast.analyses.run import evaluate_summary, run_case
from seafast.config import load_case
from seafast.model.from_case import build_model
from seafast.model.warning import ModelWarning
from seafast.results.dataset import summary_rows_from_arrays
from seafast.results.validity import cargo_diameter_m, with_validity
from seafast.solvers.outcome import SolverWarning

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"

CASES = {
    "base": {},
    "two soft saddles (large lift-off)": {"seafastening.saddle_count": 2, "seafastening.saddle_stiffness_N_per_m": 1.1e7},
    "seven stiff saddles": {"seafastening.saddle_count": 7, "seafastening.saddle_stiffness_N_per_m": 1.1e10},
    "three saddles where the H=5 system has a second solution": {
        "seafastening.saddle_count": 3,
        "seafastening.saddle_stiffness_N_per_m": 1786154413.1075907,
    },
    "stiff, pretensioned lashing": {"seafastening.lashing.stiffness_N_per_m": 1e7, "seafastening.lashing.pretension_N": 1e8},
    "one saddle, stiff lashing (baseline from the deck slope)": {
        "seafastening.saddle_count": 1,
        "seafastening.lashing.stiffness_N_per_m": 1e6,
    },
    "115 m x 12 m cargo, three abreast": {
        "cargo.length_m": 115.0,
        "cargo.diameter_m": 12.0,
        "cargo.wall_thickness_m": 12.0 / 110,
        "cargo.units_abreast": 3,
    },
    "exact law, H = 16": {"solver.contact_law": "exact", "solver.harmonics": 16},
    "no rigid-body motion, steep wave": {"vessel.motions": "none", "wave.amplitude_m": 5.0},
    "calm water": {"wave.amplitude_m": 0.0},
    "user deck table": {"vessel.deck_deflection_table": str(EXAMPLES / "deck_deflection.csv")},
    "two-way coupling": {"vessel.coupling": "two_way"},
}


@pytest.mark.parametrize("name", list(CASES))
def test_the_summary_and_the_dataset_read_the_rows_alike(name):
    case = load_case(overrides=CASES[name])
    result = run_case(case)
    fast = result.summary
    assert "arrays" not in result.__dict__  # the summary formed no time series
    full = with_validity(
        summary_rows_from_arrays(result.arrays, result.model.cargo.node_x_m, result.model.warnings), cargo_diameter_m(result.model)
    )
    for row in full:  # the coupling's own verdict, as the summary applies it
        status = result.coupling.get((row["load_case"], row["model"]))
        row.update({} if status is None else {"converged": row["converged"] and status.converged})
    rel = 1e-8
    assert [(r["load_case"], r["model"]) for r in fast] == [(r["load_case"], r["model"]) for r in full]
    assert [r for r in fast[0] if r in full[0]] == list(full[0])  # the same columns, in the same order
    for f, r in zip(fast, full, strict=True):
        label = f"{f['load_case']}/{f['model']}"
        for key, scale in (("u_c_m", 1e-3), ("u_s_m", 1e-3), ("u_d_m", 1e-3), ("F_N", 1e6), ("M_b_Nm", 1e7), ("sigma_b_Pa", 1e6)):
            assert f[key] == pytest.approx(r[key], rel=rel, abs=1e-10 * scale), f"{label} {key}"
        assert (f["converged"], f["contact_preserved"], f["iterations"]) == (r["converged"], r["contact_preserved"], r["iterations"]), label
        assert f["residual_norm"] == pytest.approx(r["residual_norm"], rel=1e-3, abs=case.solver.tolerance), label
        assert f["warnings"] == r["warnings"], label  # the same typed warnings, in the same order


def test_the_dataset_holds_the_summary_s_numbers():
    result = run_case(load_case())
    ds = result.dataset
    for row in result.summary:
        sel = ds.sel(load_case=row["load_case"], model=row["model"])
        for key in ("u_c_m", "u_s_m", "u_d_m", "F_N", "M_b_Nm", "sigma_b_Pa"):
            assert float(sel[key]) == row[key], key  # one set of numbers in summary.csv and results.nc


def test_a_study_point_is_the_run_s_summary():
    case = load_case(overrides={"solver.harmonics": 16})
    assert evaluate_summary(case) == run_case(case).summary


def test_the_summary_sees_lift_off_where_the_linear_model_pulls():
    # the base case: the linear model carries tension at the fore saddle, the nonlinear one lifts off
    rows = {(r["load_case"], r["model"]): r for r in evaluate_summary(load_case())}
    dyn_lin, dyn_nl = rows[("dynamic", "linear")], rows[("dynamic", "nonlinear")]
    assert not dyn_lin["contact_preserved"] and not dyn_nl["contact_preserved"]
    assert dyn_lin["u_d_m"] == 0.0 and 5e-3 < dyn_nl["u_d_m"] < 12e-3  # the base case lifts off by up to 8 mm
    assert dyn_nl["F_N"] < dyn_lin["F_N"] and dyn_nl["M_b_Nm"] < dyn_lin["M_b_Nm"]
    assert rows[("static", "nonlinear")]["contact_preserved"] and rows[("static", "linear")]["F_N"] == pytest.approx(6.305e6, rel=2e-3)
    assert np.isclose(rows[("static", "nonlinear")]["F_N"], rows[("static", "linear")]["F_N"], rtol=5e-3)


def test_rows_carry_the_typed_warnings_of_their_solve_and_of_the_model():
    """What a study stores per row. Seven saddles at 1.1e10 N/m with H fixed at 16: the re-contact rings far
    above 16 omega, the truncation estimate is about 3 % (30 times the 0.1 % tolerance), so the dynamic
    nonlinear row, and only it, raises too_few_harmonics. Two saddles at 2.57e9 N/m: the first two modes
    (55 and 65 rad/s) ride on the saddles, the Rayleigh fallback realises 2.36 % and 1.58 % for 2 % (21 %
    off), a warning on the dynamic rows (the damping does nothing in still water)."""
    stiff = load_case(overrides={"seafastening.saddle_count": 7, "seafastening.saddle_stiffness_N_per_m": 1.1e10, "solver.harmonics": 16})
    full = run_case(stiff)
    error = float(full.dataset["truncation_error"].sel(load_case="dynamic", model="nonlinear").max())
    assert 10 * stiff.solver.truncation_tolerance < error < 0.1
    for rows in (evaluate_summary(stiff), full.summary):
        by_row = {(r["load_case"], r["model"]): r["warnings"] for r in rows}
        assert by_row == {
            ("static", "linear"): (),
            ("static", "nonlinear"): (),
            ("dynamic", "linear"): (),
            ("dynamic", "nonlinear"): (SolverWarning.TOO_FEW_HARMONICS,),
        }
    damped = load_case(overrides={"seafastening.saddle_count": 2, "seafastening.saddle_stiffness_N_per_m": 2.569e9})
    fit = build_model(damped).rayleigh_fit
    assert fit is not None and not fit.exact and 0.15 < fit.miss < 0.3
    for rows in (evaluate_summary(damped), run_case(damped).summary):
        by_row = {(r["load_case"], r["model"]): r["warnings"] for r in rows}
        fallback = (ModelWarning.RAYLEIGH_FALLBACK,)
        assert by_row == {
            ("static", "linear"): (),
            ("static", "nonlinear"): (),
            ("dynamic", "linear"): fallback,
            ("dynamic", "nonlinear"): fallback,
        }
