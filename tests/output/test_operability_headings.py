"""The files of `seafast operability --headings` (docs/operability.md section 4): operability.csv with a leading
heading_deg, operability.nc over (heading_deg, peak_period_s), the printed table, the polar chart and the report
section, written from an analysis over headings with an injected per-heading analysis."""

from __future__ import annotations

import csv
import math

import numpy as np
import pytest
import xarray as xr

import seafast
from seafast.analyses.operability.allowable import OperabilityPoint, OperabilityResult
from seafast.analyses.operability.headings import AllowableModel, allowable_per_heading
from seafast.cli import main
from seafast.config.schema import max_significant_height_m
from seafast.output.operability import OPERABILITY_COLUMNS, plot_operability
from seafast.output.operability_headings import (
    format_heading_table,
    governing_heading_text,
    heading_operability_csv_text,
    write_heading_operability_outputs,
)
from seafast.output.report.operability_headings import heading_operability_figure

HEADINGS = [180.0, 90.0, 150.0, 120.0]  # not sorted: the files keep the order given, the chart sorts
TPS = [6.0, 9.0, 12.0]


def hs(heading: float, tp: float) -> tuple[float, float]:
    """(linear, nonlinear) allowable Hs [m]: smallest in beam seas (linear), in head seas at Tp 12 s (nonlinear)."""
    beam = abs(math.sin(math.radians(heading)))
    return 2.0 - beam + 0.1 * abs(tp - 9.0), 1.0 + 0.5 * beam + 0.2 * abs(tp - 12.0)


def analyse(case, tps, settings):
    heading = float(case.name.removeprefix("at "))
    if heading == 150.0:
        raise RuntimeError("no convergence of the hull balance")
    points = tuple(
        OperabilityPoint(tp, *hs(heading, tp), 2.5, "saddle_force", "bending_stress", max_significant_height_m(tp), 1, 2, 3, 4, True, 5)
        for tp in tps
    )
    return OperabilityResult(case, points, settings)


@pytest.fixture(scope="module")
def result():
    case = seafast.load_case(None)
    return allowable_per_heading(case, HEADINGS, TPS, analyse=analyse, at_heading=lambda c, h: c.model_copy(update={"name": f"at {h!r}"}))


@pytest.fixture(scope="module")
def written(result, tmp_path_factory):
    out = tmp_path_factory.mktemp("opheadings")
    return out, write_heading_operability_outputs(result, out)


def test_csv_has_heading_deg_first_then_the_single_heading_columns(written):
    out, _ = written
    with open(out / "operability.csv", newline="") as f:
        rows = list(csv.reader(f))
    assert tuple(rows[0]) == ("heading_deg", *OPERABILITY_COLUMNS)
    assert ",".join(rows[0]) == (
        "heading_deg,peak_period_s,hs_allowable_linear_m,hs_allowable_nonlinear_m,hs_uplift_onset_m,governing_linear,governing_nonlinear"
    )
    body = rows[1:]
    assert [(float(r[0]), float(r[1])) for r in body] == [(h, t) for h in HEADINGS for t in TPS]  # heading-major, order given
    for r in body:
        h, t = float(r[0]), float(r[1])
        if h == 150.0:  # the failed heading: recorded, not lost
            assert r[2:5] == ["", "", ""] and r[5:] == ["failed", "failed"]
        else:
            assert (float(r[2]), float(r[3])) == hs(h, t) and r[5:] == ["saddle_force", "bending_stress"]


def test_netcdf_has_a_heading_dimension_with_units_and_long_names(written, result):
    out, paths = written
    assert set(paths) == {"operability_csv", "case", "operability_nc", "operability_png"}
    with xr.open_dataset(out / "operability.nc") as ds:
        assert ds["hs_allowable_nonlinear_m"].dims == ("heading_deg", "peak_period_s")
        assert ds.sizes == {"heading_deg": 4, "peak_period_s": 3}
        assert list(ds["heading_deg"].values) == HEADINGS and ds["heading_deg"].attrs["units"] == "degree"
        assert "180 = head seas" in ds["heading_deg"].attrs["long_name"]
        for name, var in list(ds.data_vars.items()) + list(ds.coords.items()):
            assert var.attrs.get("units") and var.attrs.get("long_name"), name
        for h in HEADINGS:
            for t in TPS:
                v = float(ds["hs_allowable_linear_m"].sel(heading_deg=h, peak_period_s=t))
                assert math.isnan(v) if h == 150.0 else v == hs(h, t)[0]
        assert list(ds["heading_error"].values) == ["", "", "RuntimeError: no convergence of the hull balance", ""]
        assert list(ds["converged"].sel(heading_deg=150.0).values) == [0, 0, 0]
        # the governing heading: beam seas for the linear model at every Tp, head seas for the nonlinear one
        assert list(ds["governing_heading_linear_deg"].values) == [90.0, 90.0, 90.0]
        assert list(ds["governing_heading_nonlinear_deg"].values) == [180.0, 180.0, 180.0]
        assert list(ds["hs_allowable_nonlinear_all_headings_m"].values) == [hs(180.0, t)[1] for t in TPS]
        assert ds.attrs["governing_heading_nonlinear_deg"] == 180.0 and ds.attrs["governing_peak_period_nonlinear_s"] == 12.0
        assert ds.attrs["governing_heading_linear_deg"] == 90.0 and ds.attrs["governing_peak_period_linear_s"] == 9.0
        assert ds.attrs["governing_limit_nonlinear"] == "bending_stress" and "heading_deg" in ds.attrs["conventions"]
        assert seafast.load_case(None).model_dump_json() == ds.attrs["case_json"]  # the case as given, not one heading's
        assert ds.attrs["title"] == "seafast operability: base-case"


def test_printed_table_names_the_governing_heading(result):
    table = format_heading_table(result)
    lines = table.splitlines()
    assert lines[1].split() == ["Tp", "[s]", "180", "deg", "90", "deg", "150", "deg", "120", "deg", "governing", "[deg]", "limit"]
    assert lines[3].split() == [
        "6",
        f"{hs(180, 6)[1]:.2f}",
        f"{hs(90, 6)[1]:.2f}",
        "failed",
        f"{hs(120, 6)[1]:.2f}",
        "180",
        "bending_stress",
    ]
    text = governing_heading_text(result.governing_heading(AllowableModel.NONLINEAR), AllowableModel.NONLINEAR)
    assert text == "governing heading (nonlinear): 180 deg at Tp 12 s, allowable Hs 1.00 m (bending_stress governs)"
    assert "90 deg at Tp 9 s, allowable Hs 1.00 m (saddle_force governs)" in governing_heading_text(
        result.governing_heading(AllowableModel.LINEAR), AllowableModel.LINEAR
    )


def test_polar_chart_has_head_seas_at_the_top_and_one_curve_per_peak_period(written, monkeypatch, tmp_path):
    import seafast.output.style as style

    out, _ = written
    assert (out / "operability.png").stat().st_size > 20_000
    figures = []
    monkeypatch.setattr(style, "save_png", lambda fig, path, dpi, rect=None: figures.append(fig) or path)
    with xr.open_dataset(out / "operability.nc") as ds:
        plot_operability(ds.load(), tmp_path / "p.png")  # the report's print figure: the polar chart for headings
    ax = figures[0].axes[0]
    assert ax.name == "polar"
    # 0 deg at the bottom (theta offset -pi/2), counter-clockwise: 90 deg on the right, 180 deg at the top
    assert math.remainder(ax.get_theta_offset() + math.pi / 2, 2 * math.pi) == pytest.approx(0.0, abs=1e-12)
    assert ax.get_theta_direction() == 1
    x, y = ax.transData.transform((math.radians(180.0), 1.0)) - ax.transData.transform((0.0, 0.0))
    assert y > 0 and abs(x) < 1e-6 * abs(y)
    x, y = ax.transData.transform((math.radians(90.0), 1.0)) - ax.transData.transform((0.0, 0.0))
    assert x > 0 and abs(y) < 1e-6 * abs(x)
    curves = [line for line in ax.get_lines() if len(line.get_xdata()) == 4]
    assert len(curves) == len(TPS) + 1  # one per Tp and the smallest over Tp
    order = [90.0, 120.0, 150.0, 180.0]
    np.testing.assert_allclose(curves[0].get_xdata(), np.radians(order), rtol=1e-12)
    np.testing.assert_allclose(curves[2].get_ydata(), [np.nan if h == 150.0 else hs(h, 12.0)[1] for h in order], rtol=1e-12)


def test_report_section_names_the_governing_heading(written, tmp_path):
    out, _ = written
    page_path = tmp_path / "report.html"
    assert main(["report", str(out), "-o", str(page_path), "--no-figures"]) == 0
    page = page_path.read_text()
    for needle in (
        'id="operability"',
        'data-figure="fig-operability-headings"',
        "Governing heading (nonlinear): 180 deg at Tp 12 s, allowable Hs 1.00 m (bending_stress governs)",
        "Governing heading (linear): 90 deg at Tp 9 s",
        "The analysis failed at heading 150 deg",
        "180 deg (head seas, waves from ahead) at the top",
        f"{hs(120.0, 6.0)[1]:.2f}",
    ):
        assert needle in page, needle
    with xr.open_dataset(out / "operability.nc") as ds:
        polar = heading_operability_figure(ds).figure.layout.polar.angularaxis
    assert (polar.rotation, polar.direction) == (-90, "counterclockwise")  # 0 deg at the bottom, 90 deg on the right


def test_csv_text_equals_the_file(written, result):
    out, _ = written
    assert (out / "operability.csv").read_text(encoding="utf-8") == heading_operability_csv_text(result)
