"""seastate.csv's and the terminal table's friction columns (docs/seastate.md#pad-friction-in-the-design-waves): after
the five cradle columns when a row carries them, empty cells elsewhere; absent, and the table as before, without them."""

from __future__ import annotations

import csv
import io
import re

from seafast.analyses.seastate.cradle_extremes import CRADLE_COLUMNS
from seafast.analyses.seastate.cradle_friction_wave import CRADLE_FRICTION_COLUMNS
from seafast.analyses.seastate.spectral import SEASTATE_COLUMNS
from seafast.output.seastate import format_seastate_table, not_computed_row, seastate_csv_text

CRADLE = {"F_pad_N": 5.043e6, "F_stopper_N": 0.0, "lashing_tension_max_N": 74279.5, "lashing_tension_min_N": 74246.6}


def _rows(friction: bool) -> list[dict]:
    spectral = {**not_computed_row("linear", "spectral"), "F_N": 7.0e6, "converged": True, **CRADLE, "transverse_slip_m": 1.14e-3}
    design = {**not_computed_row("nonlinear", "design_wave"), "F_N": 7.0e6, "converged": True, **CRADLE, "transverse_slip_m": 7.1e-4}
    if friction:
        design |= {"pad_friction_utilisation": 1.0, "pad_slip_m": 1.48e-3}
    return [spectral, design]


def test_friction_columns_follow_the_cradle_columns_filled_where_computed():
    rows = list(csv.reader(io.StringIO(seastate_csv_text(_rows(True)))))
    assert rows[0] == list(SEASTATE_COLUMNS + CRADLE_COLUMNS + CRADLE_FRICTION_COLUMNS)
    assert rows[1][-2:] == ["", ""] and rows[2][-2:] == ["1.0", "0.00148"]
    table = format_seastate_table(_rows(True)).splitlines()
    assert "mu use [-]" in table[0] and table[0].rstrip().endswith("pad slip [mm]")
    assert re.search(r"0\.71\s+1\.000\s+1\.48$", table[3]) and re.search(r"1\.14\s+not computed\s+not computed$", table[2])


def test_without_friction_the_csv_and_table_have_no_friction_columns():
    text = seastate_csv_text(_rows(False))
    assert text.splitlines()[0].split(",") == list(SEASTATE_COLUMNS + CRADLE_COLUMNS)
    table = format_seastate_table(_rows(False))
    assert "mu use" not in table and "pad slip" not in table
    assert table.splitlines()[3].split()[-1] == "0.71"
