"""The report pages of the cargo on its cradles: a sea state off head seas shows the cradle columns of seastate.csv
(and its cradle limits), operability off head seas names the cradle limits and what governs."""

from __future__ import annotations

import csv

import pytest
import xarray as xr

from seafast.analyses.operability.allowable import CRADLE_OPERABILITY_COLUMNS
from seafast.cli import main
from seafast.output.operability import OPERABILITY_COLUMNS

BEAM = ["--set", "sea_state.heading_deg=90", "--set", "limits.max_pad_force_N=5e6"]


def _rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def _page(directory, tmp_path):
    page = tmp_path / f"{directory.name}.html"
    assert main(["report", str(directory), "-o", str(page), "--no-figures"]) == 0
    return page.read_text()


@pytest.mark.parametrize("heading", [90.0, 180.0])
def test_the_seastate_page_shows_the_cradle_columns_when_the_file_has_them(tmp_path, heading):
    out = tmp_path / f"ss{heading:g}"
    sea = ["--set", "sea_state.significant_height_m=2", "--set", "sea_state.peak_period_s=10"]
    args = ["seastate", "-o", str(out), "--no-monte-carlo", "--no-plots", "-q", *sea, "--set", f"sea_state.heading_deg={heading:g}"]
    assert main([*args, "--set", "limits.max_pad_force_N=5e6"]) == 0
    page = _page(out, tmp_path)
    rows = _rows(out / "seastate.csv")
    if heading == 180.0:  # head seas: no cradle solved, the page as before
        assert "F_pad_N" not in rows[0] and "F_pad [MN]" not in page and "pad force" not in page
        assert ", head seas;" in page
        return
    spectral = next(r for r in rows if r["method"] == "spectral")
    for needle in ("F_pad [MN]", "T_max [kN]", "slip [mm]", "heading 90 deg", f"{float(spectral['F_pad_N']) / 1e6:.3f}"):
        assert needle in page, needle
    # beam seas, Hs 2 m: the pads' 5.10 MN exceeds the 5 MN limit, in both rows judged on
    assert float(spectral["F_pad_N"]) > 5e6
    assert page.count("MPM pad force 5.10 MN exceeds the limit 5 MN") == 2
    assert "not computed" not in page.split("F_pad [MN]")[1].split("spectral")[1].split("</tr>")[0]


def test_the_operability_pages_name_the_cradle_limits_and_what_governs(tmp_path):
    # one heading off head seas (the case's), and the same over headings: the pad force governs in beam seas
    one, over = tmp_path / "one", tmp_path / "over"
    assert main(["operability", "--tp", "10", "-o", str(one), "--no-plots", "-q", *BEAM]) == 0
    assert main(["operability", "--headings", "90", "--tp", "10", "-o", str(over), "--no-plots", "-q", *BEAM]) == 0
    with open(one / "operability.csv") as f:
        assert f.readline().strip() == ",".join(OPERABILITY_COLUMNS + CRADLE_OPERABILITY_COLUMNS)
    row = _rows(one / "operability.csv")[0]
    assert row["governing_linear"] == row["governing_nonlinear"] == "pad_force"
    assert row["hs_pad_force_linear_m"] == row["hs_allowable_linear_m"] and row["hs_lashing_tension_linear_m"] == ""
    assert [r["hs_allowable_nonlinear_m"] for r in _rows(over / "operability.csv")] == [row["hs_allowable_nonlinear_m"]]
    with xr.open_dataset(one / "operability.nc") as ds:
        assert ds.attrs["max_pad_force_N"] == 5e6 and "max_lashing_tension_N" not in ds.attrs
        for name in CRADLE_OPERABILITY_COLUMNS:
            assert ds[name].attrs["units"] == "m" and ds[name].attrs["long_name"], name
    for page in (_page(one, tmp_path), _page(over, tmp_path)):
        assert "on the cradles, judged off head seas: pad force &le; 5 MN" in page
        assert "nonlinear: the cradles govern (pad_force) at 1 point(s)" in page
        assert "pad_force: the cradles" in page and "(limits.max_pad_force_N)" in page
    assert "heading 90 deg" in _page(one, tmp_path)
    assert "(pad_force governs)" in _page(over, tmp_path)
