"""The example case files load, and the deck-table example runs end to end."""

from __future__ import annotations

import csv
from pathlib import Path

import pytest

from seafast.cli import main
from seafast.config import load_case

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
CASE_FILES = (
    "base_case.yaml",
    "four_saddles_soft.yaml",
    "lashing_variation.yaml",
    "monopile_115m_12m.yaml",
    "user_deck_table.yaml",
    "two_way_coupling.yaml",
)


@pytest.mark.parametrize("name", CASE_FILES)
def test_example_loads(name: str) -> None:
    case = load_case(EXAMPLES / name)
    assert case.name == Path(name).stem.replace("_", "-")


def test_examples_say_what_they_set() -> None:
    soft = load_case(EXAMPLES / "four_saddles_soft.yaml")
    assert soft.saddle_positions_m() and len(soft.saddle_positions_m()) == 4
    assert soft.saddle_stiffnesses_N_per_m() == (1.1e8,) * 4
    lash = load_case(EXAMPLES / "lashing_variation.yaml")
    assert lash.seafastening.lashing.stiffness_N_per_m == pytest.approx(375e3)
    assert lash.seafastening.lashing.pretension_N == pytest.approx(1e6)
    big = load_case(EXAMPLES / "monopile_115m_12m.yaml")
    assert (big.cargo.length_m, big.cargo.diameter_m) == (115.0, 12.0)
    assert big.cargo.wall_thickness_m == pytest.approx(12.0 / 110.0, rel=1e-4)
    assert load_case(EXAMPLES / "two_way_coupling.yaml").vessel.coupling == "two_way"
    table = load_case(EXAMPLES / "user_deck_table.yaml")
    assert table.vessel.deck_deflection_table is not None and Path(table.vessel.deck_deflection_table).is_file()


def test_deck_table_covers_the_ship() -> None:
    from seafast.excitation.deck_table import DECK_TABLE_COLUMNS, read_deck_deflection_table

    table = read_deck_deflection_table(EXAMPLES / "deck_deflection.csv")
    assert table.x_m[0] == 0.0 and table.x_m[-1] == pytest.approx(171.0)
    lines = (EXAMPLES / "deck_deflection.csv").read_text(encoding="utf-8").splitlines()
    assert lines[0].startswith("#")  # says it is generated
    header = next(csv.reader([next(line for line in lines if not line.startswith("#"))]))
    assert tuple(header) == DECK_TABLE_COLUMNS


def test_deck_table_example_runs(tmp_path: Path) -> None:
    out = tmp_path / "deck"
    code = main(
        [
            "run",
            str(EXAMPLES / "user_deck_table.yaml"),
            "-o",
            str(out),
            "-q",
            "--no-plots",
            "--set",
            "solver.time_samples=32",
            "--set",
            "model.element_length_m=2.0",
        ]
    )
    assert code == 0
    rows = list(csv.DictReader((out / "summary.csv").open(encoding="utf-8")))
    assert len(rows) == 4
    static_linear = next(r for r in rows if r["load_case"] == "static" and r["model"] == "linear")
    # the table is the base case's own hull deflection: the static calibration is reproduced (~6.3 MN)
    assert 5.5e6 < float(static_linear["F_N"]) < 7.0e6
    assert all(r["converged"] == "true" for r in rows)
