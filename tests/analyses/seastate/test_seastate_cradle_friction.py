"""Sea states off head seas on frictional pads: the cradle design waves with ``seafastening.friction_coefficient``.

Checks: each design wave's frictional columns against the frictional harmonic balance run directly on that wave (the
sliders relaxed in its still water, as ``seafast run``); mu = 0 through the frictional path gives the frictionless
columns; a small mu moves each force by no more than the friction available; in the base case's beam sea the friction
lowers the largest pad force by a physically bounded amount, as in a regular wave; a frictional wave that does not
converge flags the row with its residual; without the key, with mu = 0 or in head seas the outputs are unchanged.
"""

from __future__ import annotations

import csv

import numpy as np
import pytest
import xarray as xr

import seafast
from frictional_stand_in import not_converging
from seafast.analyses.seastate import cradle_friction_wave
from seafast.analyses.seastate.cradle_design_wave import cradle_design_waves, cradle_sea_state, design_wave_excitation
from seafast.analyses.seastate.cradle_extremes import CRADLE_COLUMNS, element_groups
from seafast.analyses.seastate.cradle_friction_wave import (
    CRADLE_FRICTION_COLUMNS,
    DesignWaveFriction,
    design_wave_friction,
    solve_frictional_design_wave,
)
from seafast.analyses.seastate.spectral import SEASTATE_COLUMNS, spectral_analysis
from seafast.cli import main
from seafast.model.pad_friction import PadFriction
from seafast.solvers.cradle_friction import FrictionHBMOptions, solve_cradle_friction_hbm

BEAM = {"sea_state.heading_deg": 90.0}
MU = 0.2
H = 16
"""The frictional harmonic balance's H in these tests (``solver.harmonics``; N = 8 H): the base case's beam-sea
columns at H = 16 are those at the run's default H = 32 within 3e-5 (measured), at a quarter of the cost."""


@pytest.fixture(scope="module")
def frictionless():
    """The base case in its 3 m beam sea (90 deg, long-crested) on frictionless pads: analysis and cradle columns."""
    analysis = spectral_analysis(seafast.load_case(None, BEAM))
    return analysis, cradle_sea_state(analysis)


@pytest.fixture(scope="module")
def frictional():
    """The same sea with ``seafastening.friction_coefficient`` = 0.2 (H = :data:`H`): analysis and cradle columns."""
    analysis = spectral_analysis(seafast.load_case(None, {**BEAM, "seafastening.friction_coefficient": MU, "solver.harmonics": H}))
    return analysis, cradle_sea_state(analysis)


def _excitation(analysis, state, wave):
    """A design wave's excitation, formed from the sea's transfer functions (its still water at k = 0)."""
    return design_wave_excitation(state.sea, analysis.directional, wave)


def _pad_peak_force_N(response) -> float:
    """The pads' peak normal force over the pads and the period [N]."""
    return float(np.max(response.pad_force_N, initial=0.0))


def test_the_key_is_read_as_the_run_reads_it():
    """Unset or 0: no friction (today's design waves); set: the run's coefficient, H = 32 and N = 8 H; per-saddle values
    that differ are refused naming the key."""
    assert design_wave_friction(seafast.load_case(None, BEAM)) is None
    assert design_wave_friction(seafast.load_case(None, {**BEAM, "seafastening.friction_coefficient": 0.0})) is None
    f = design_wave_friction(seafast.load_case(None, {**BEAM, "seafastening.friction_coefficient": MU}))
    assert f == DesignWaveFriction(PadFriction(MU), FrictionHBMOptions(harmonics=32, time_samples=256))
    with pytest.raises(ValueError, match=r"seafastening\.friction_coefficient"):
        design_wave_friction(seafast.load_case(None, {**BEAM, "seafastening.friction_coefficient": [0.1, 0.2, 0.3]}))


def test_frictional_columns_equal_the_frictional_harmonic_balance_run_directly(frictional):
    """Each wave's reading and its friction are those of ``solve_cradle_friction_hbm`` called on the wave with the
    sliders relaxed in its still water (1e-9), shown on one wave per way of reading; the row's columns are the largest readings
    (least for the lashing minimum), the friction's the largest over every wave; all converged."""
    analysis, state = frictional
    d = state.design
    assert d is not None and d.frictional is not None and d.frictionless is not None and d.converged
    assert len(d.frictional) == len(d.waves) == len(d.responses) == len(d.frictionless)
    problem = state.sea.dynamics.problem
    first = {}
    for i, wave in enumerate(d.waves):  # each way of reading a wave: largest force, least tension, lateral displacement
        if wave.quantity != "lashing_tension_max_N":
            first.setdefault(wave.quantity, i)
    for quantity, i in first.items():
        wave, excitation = d.waves[i], _excitation(analysis, state, d.waves[i])
        direct = solve_cradle_friction_hbm(
            state.sea.dynamics, PadFriction(MU), excitation, FrictionHBMOptions(H, 8 * H), rest=excitation.still_water()
        )
        if quantity == "transverse_slip_m":
            dof = problem.cargo.node_dofs(problem.cargo.node_at(problem.pad_pairs[wave.location].x_m))[1]
            expected = float(np.max(np.abs(direct.cradle.cargo_displacement_m[:, dof])))
        elif quantity == "lashing_tension_min_N":
            expected = float(np.min(direct.cradle.element_force_N[:, wave.location]))
        else:
            expected = float(np.max(direct.cradle.element_force_N[:, wave.location]))
        assert d.readings[i] == pytest.approx(expected, rel=1e-9), quantity
        assert np.max(d.frictional[i].max_slip_m) == pytest.approx(np.max(direct.max_slip_m), rel=1e-9, abs=1e-15)
        assert np.max(d.frictional[i].friction_utilisation) == pytest.approx(np.max(direct.friction_utilisation), rel=1e-9)
    sw = state.spectral.still_water
    pads, stoppers, lashings = element_groups(state.spectral.pad_count, state.spectral.stopper_count, sw.element_force_N.size)
    static = {
        "F_pad_N": np.max(sw.element_force_N[pads]),
        "F_stopper_N": np.max(sw.element_force_N[stoppers], initial=0.0),
        "lashing_tension_max_N": np.max(sw.element_force_N[lashings]),
        "lashing_tension_min_N": np.min(sw.element_force_N[lashings]),
        "transverse_slip_m": np.max(np.abs(sw.lateral_displacement_m)),
    }
    for q in CRADLE_COLUMNS:
        mine = [float(r) for w, r in zip(d.waves, d.readings, strict=True) if w.quantity == q]
        pick = min if q == "lashing_tension_min_N" else max
        assert d.totals[q] == pick([float(static[q]), *mine]), q
    assert d.totals["pad_slip_m"] == max(float(np.max(f.max_slip_m)) for f in d.frictional)
    assert d.totals["pad_friction_utilisation"] == max(float(np.max(f.friction_utilisation)) for f in d.frictional)
    assert list(d.columns()) == list(CRADLE_COLUMNS + CRADLE_FRICTION_COLUMNS)


def test_friction_lowers_the_largest_pad_force_in_the_beam_sea_by_a_bounded_amount(frictionless, frictional):
    """Hs 3 m at 90 deg, mu = 0.2: the design-wave pad force falls (5.42 -> 5.04 MN; a regular wave of the run 5.37 ->
    4.96 MN), by less than the friction available at that pad (mu of its frictionless peak) and not below still water;
    the pads slip (utilisation 1 to round-off, never above) by a slip of millimetres; the waves, their amplitudes and
    frequencies and the frictionless solves are those of the frictionless sea state; the spectral row is unchanged."""
    _, plain = frictionless
    _, fric = frictional
    a, b = plain.design, fric.design
    assert a is not None and b is not None and b.frictionless is not None
    assert a.waves == b.waves
    for r0, r1 in zip(a.responses, b.frictionless, strict=True):
        np.testing.assert_array_equal(r0.element_force_N, r1.element_force_N)
    assert dict(plain.spectral.totals) == dict(fric.spectral.totals)
    drop = a.totals["F_pad_N"] - b.totals["F_pad_N"]
    still = float(np.max(fric.spectral.still_water.element_force_N[: fric.spectral.pad_count]))
    assert 0.0 < drop < MU * a.totals["F_pad_N"]
    assert b.totals["F_pad_N"] > still
    assert 0.03 < drop / a.totals["F_pad_N"] < 0.12  # 6.9 %; the run's regular wave 7.6 %
    assert abs(b.totals["pad_friction_utilisation"] - 1.0) < 1e-9
    assert 1e-4 < b.totals["pad_slip_m"] < 1e-2
    assert b.totals["transverse_slip_m"] < a.totals["transverse_slip_m"]  # friction holds the cargo across


def test_zero_friction_through_the_frictional_path_gives_the_frictionless_columns(frictionless):
    """mu = 0 passed to the frictional path (the run's H = 32, N = 256): zero friction and the frictionless design
    waves' columns to the harmonic balance's truncation (1e-4 of each, the shooting being its converged limit)."""
    analysis, state = frictionless
    zero = DesignWaveFriction(PadFriction(0.0), FrictionHBMOptions(32, 256))
    d = cradle_design_waves(state.sea, analysis.directional, state.transfer, state.spectral, friction=zero)
    assert d.converged and d.totals["pad_friction_utilisation"] == 0.0
    assert state.design is not None
    for q in CRADLE_COLUMNS:
        assert d.totals[q] == pytest.approx(state.design.totals[q], rel=1e-4, abs=1e-12), q


def test_a_small_friction_moves_each_force_by_no_more_than_the_friction_available(frictionless):
    """mu = 1e-3 against mu = 0 on the same grid (one wave per column): every element force moves over the period by
    no more than mu times the pads' peak force (the most friction a pad can carry), and the pads' by a good share of it
    (friction acts at the scale of mu F_n: measured 0.82-0.90 of the bound)."""
    analysis, state = frictionless
    assert state.design is not None
    options = FrictionHBMOptions(H, 8 * H)
    seen = set()
    for wave in state.design.waves:
        if wave.quantity in seen:
            continue
        seen.add(wave.quantity)
        excitation = _excitation(analysis, state, wave)
        r0 = solve_frictional_design_wave(state.sea.dynamics, excitation, DesignWaveFriction(PadFriction(0.0), options))
        r1 = solve_frictional_design_wave(state.sea.dynamics, excitation, DesignWaveFriction(PadFriction(1e-3), options))
        assert r1.converged
        change = np.max(np.abs(r1.cradle.element_force_N - r0.cradle.element_force_N), axis=0)
        bound = 1e-3 * _pad_peak_force_N(r0.cradle)
        assert np.all(change <= bound), wave.quantity
        assert np.max(change[: r0.cradle.pad_count]) > 0.5 * bound, wave.quantity


def test_a_frictional_wave_that_does_not_converge_flags_the_row_and_the_study_carries_on(monkeypatch, tmp_path, capsys):
    """Every frictional solve stood in for by one that says it did not converge (residual 3e-3): seastate.csv keeps the
    row's numbers, flags it converged=false, the command warns with the residual and exits 3; the friction columns
    follow the cradle columns, filled in the design-wave row alone; seastate.nc labels the waves' friction."""
    from seafast.analyses.seastate import cradle_design_wave

    monkeypatch.setattr(cradle_design_wave, "solve_frictional_design_wave", not_converging(3e-3))
    out = tmp_path / "mu"
    sets = ["--set", "sea_state.heading_deg=90", "--set", f"seafastening.friction_coefficient={MU}", "--set", f"solver.harmonics={H}"]
    assert main(["seastate", "-o", str(out), "--no-monte-carlo", "--no-plots", "-q", *sets]) == 3
    assert "did not converge (largest residual 0.003)" in capsys.readouterr().err
    with open(out / "seastate.csv", newline="") as f:
        header = f.readline().strip().split(",")
        f.seek(0)
        rows = list(csv.DictReader(f))
    assert header == list(SEASTATE_COLUMNS + CRADLE_COLUMNS + CRADLE_FRICTION_COLUMNS)
    assert rows[3]["converged"] == "false" and float(rows[3]["F_pad_N"]) > 0.0
    assert float(rows[3]["pad_friction_utilisation"]) == 0.0 and float(rows[3]["pad_slip_m"]) > 0.0
    assert all(r[c] == "" for r in rows[:3] for c in CRADLE_FRICTION_COLUMNS)
    with xr.open_dataset(out / "seastate.nc") as ds:
        assert list(ds["cradle_design_wave_converged"].values) == [0] * ds.sizes["cradle_design_wave"]
        for name in ("cradle_design_wave_pad_friction_utilisation", "cradle_design_wave_pad_slip_m", "pad_slip_m"):
            assert ds[name].attrs.get("units") and ds[name].attrs.get("long_name"), name
        np.testing.assert_array_equal(ds["cradle_design_wave_frictionless_converged"].values, 1)


def test_without_the_key_with_zero_friction_and_in_head_seas_the_outputs_are_unchanged(tmp_path, monkeypatch):
    """seastate.csv byte for byte and seastate.nc's values without the key and with mu = 0 at 90 deg; with mu = 0.2 and
    without in head seas; no frictional solve is made in any of them."""
    calls: list[int] = []
    monkeypatch.setattr(cradle_friction_wave, "solve_cradle_friction", lambda *a, **k: calls.append(1))

    def run(name: str, *sets: str) -> tuple[str, xr.Dataset]:
        args = [arg for s in sets for arg in ("--set", s)]
        assert main(["seastate", "-o", str(tmp_path / name), "--no-monte-carlo", "--no-plots", "-q", *args]) == 0
        with xr.open_dataset(tmp_path / name / "seastate.nc") as ds:
            return (tmp_path / name / "seastate.csv").read_text(), ds.load()

    plain, zero = run("plain", "sea_state.heading_deg=90"), run("zero", "sea_state.heading_deg=90", "seafastening.friction_coefficient=0")
    assert plain[0] == zero[0] and "pad_friction_utilisation" not in plain[0]
    xr.testing.assert_identical(plain[1].drop_attrs(), zero[1].drop_attrs())
    head, head_mu = run("head"), run("head_mu", f"seafastening.friction_coefficient={MU}")
    assert head[0] == head_mu[0] and "F_pad_N" not in head[0]
    assert not calls
