"""A peak saddle force that is an elastic impact at a re-contact is flagged, never reported as an answer.

On near-rigid saddles every re-contact after a lift-off is an impact whose force grows with the saddle stiffness
(the base case's geometry: 18.9 MN at 1.1e12 N/m, 44.9 MN at 1e13, 117 MN at 1e14) while the bending moment and
the gap converge. The impact estimate ``v G(k)`` (:mod:`seafast.results.impact`) is checked here against closed
forms and a time integration in tests/solvers/test_impact_pulse.py; here the flag against the run:
raised on a near-rigid case, absent on the base case and on the saddle study's stiff end.
"""

from __future__ import annotations

import csv

import pytest

from seafast.analyses.run import run_case
from seafast.cli import EXIT_OUTSIDE_VALIDITY, main
from seafast.config import load_case
from seafast.model.from_case import build_model
from seafast.model.warning import ModelWarning
from seafast.results.dataset import SUMMARY_COLUMNS
from seafast.results.impact import IMPACT_RATIO_LIMIT, fixed_harmonics_reason
from seafast.solvers.impact_pulse import impact_force_per_velocity_N_s_per_m


@pytest.fixture(scope="module")
def near_rigid():
    return run_case(load_case(overrides={"seafastening.saddle_stiffness_N_per_m": 1e13, "model.element_length_m": 2.0}))


def test_a_near_rigid_saddle_is_flagged_with_its_impact_estimate(near_rigid):
    check = near_rigid.impact
    assert [s.saddle for s in check.flagged] == [2]
    s = check.flagged[0]
    assert not s.bounded  # the pulse computed
    # the peak is the impact's pulse: the estimate is most of it (the pulse rides on the cargo's ringing from the
    # earlier impacts, which it leaves out) and far above the force the saddle carries with its contact kept
    assert 0.6 < s.impact_force_N / s.peak_force_N <= 1.0
    assert s.ratio > 2.0 * IMPACT_RATIO_LIMIT
    row = next(r for r in near_rigid.summary if (r["load_case"], r["model"]) == ("dynamic", "nonlinear"))
    assert ModelWarning.SADDLE_FORCE_ELASTIC_IMPACT in row["warnings"] and row["F_within_validity"] is False
    assert row["within_validity"]  # the bending moment and the displacements remain answers
    others = [r for r in near_rigid.summary if (r["load_case"], r["model"]) != ("dynamic", "nonlinear")]
    assert all(r["F_within_validity"] and ModelWarning.SADDLE_FORCE_ELASTIC_IMPACT not in r["warnings"] for r in others)
    ds = near_rigid.dataset
    assert not bool(ds["F_within_validity"].sel(load_case="dynamic", model="nonlinear"))
    assert "saddle 3" in ds.attrs["saddle_force_impacts"]


def test_the_base_case_and_the_stiff_end_of_the_saddle_study_are_not_flagged():
    # both lift off and re-contact; the impact's pulse stays well under the force the saddle carries anyway (the
    # energy bound sqrt(k m) already says so, so the pulse is not computed: here it is, to show the margin)
    for stiffness, largest in ((1.1e9, 0.2), (1.1e10, 0.4)):
        result = run_case(load_case(overrides={"seafastening.saddle_stiffness_N_per_m": stiffness}))
        check = result.impact
        assert check.saddles and check.flagged == () and all(s.bounded for s in check.saddles)
        assert all(r["F_within_validity"] for r in result.summary)
        pulse = [
            s.approach_velocity_m_s * impact_force_per_velocity_N_s_per_m(result.model, s.saddle, s.stiffness_N_per_m)
            for s in check.saddles
        ]
        ratios = [p / s.contact_kept_force_N for p, s in zip(pulse, check.saddles, strict=True)]
        assert 0.05 < max(ratios) < largest * IMPACT_RATIO_LIMIT
        assert all(p < s.impact_force_N for p, s in zip(pulse, check.saddles, strict=True))  # under the bound


def test_a_fixed_harmonic_count_below_the_re_contacts_ringing_is_named_as_the_reason():
    stiff = load_case(overrides={"seafastening.saddle_stiffness_N_per_m": 1e12, "solver.harmonics": 40})
    model = build_model(stiff)
    reason = fixed_harmonics_reason(stiff, model, 0.6)
    ringing = 1e12 / impact_force_per_velocity_N_s_per_m(model, 0, 1e12)
    assert 2e3 < ringing < 6e3  # a mass-like contact on a few metres of the tube (sqrt(1e12 / 9e4 kg) = 3.3e3 rad/s)
    assert reason is not None and "solver.harmonics = 40" in reason and "24 rad/s" in reason and f"{ringing:.3g} rad/s" in reason
    assert "leave solver.harmonics unset" in reason
    # the default (converged) solver, or harmonics that reach the ringing: no such reason
    assert fixed_harmonics_reason(load_case(overrides={"seafastening.saddle_stiffness_N_per_m": 1e12}), model, 0.6) is None
    assert fixed_harmonics_reason(stiff, model, 0.6 * ringing / 24.0 * 1.01) is None


def test_seafast_run_warns_of_the_elastic_impact_and_keeps_summary_csv(tmp_path, capsys):
    out = tmp_path / "out"
    code = main(
        ["run", "-o", str(out), "--no-plots", "--set", "seafastening.saddle_stiffness_N_per_m=1e13", "--set", "model.element_length_m=2.0"]
    )
    err = capsys.readouterr().err
    assert code == EXIT_OUTSIDE_VALIDITY
    line = next(x for x in err.splitlines() if "elastic impact" in x)
    assert "saddle 3" in line and "MN" in line and "measured saddle stiffness" in line and "bending moment" in line
    with open(out / "summary.csv", newline="") as f:
        assert tuple(next(csv.reader(f))) == SUMMARY_COLUMNS
