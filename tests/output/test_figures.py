"""The figures say what they show: units that suit the data, plain-number ticks, legends off the
data, every plotted series visible, the computed points drawn as computed.

Checked on the artists (matplotlib) and the figure objects (plotly), never on pixels: tick labels
and axis units, where legends stand against the axes, line styles and drawing order of series
that coincide, colour bars, what a limit line is drawn along.
"""

from __future__ import annotations

import re
from itertools import combinations
from pathlib import Path

import matplotlib
import numpy as np
import pytest
import xarray as xr

matplotlib.use("Agg")
import matplotlib.pyplot as plt

from seafast.analyses.run import run_case
from seafast.config import load_case
from seafast.output import plots
from seafast.output.report.axial_figures import stick_slip_figure
from seafast.output.report.cargo_figures import saddle_time_history_figure
from seafast.output.report.print_figures import plot_contact_timeline
from seafast.output.report.run_figures import run_figures
from seafast.output.report.study_figures import compliance_map_figure, study_surface_figure
from seafast.output.report.vessel_figures import rao_figure
from seafast.output.study_plots import plot_compliance_map, plot_profiles, plot_surfaces
from seafast.output.style import cell_boundary, scaled_unit

PLAIN_NUMBER = re.compile("^[\u2212-]?\\d+(\\.\\d+)?$")  # matplotlib writes U+2212 for minus


@pytest.fixture(scope="module")
def run_ds() -> xr.Dataset:
    """The base case with its BEM motions (RAOs), hull girder and the axial friction analysis (mu = 0.14: it sticks)."""
    case = load_case(overrides={"seafastening.friction_coefficient": 0.14, "model.element_length_m": 2.0})
    return run_case(case).dataset


def synthetic_study() -> xr.Dataset:
    """Saddle count 2..4 x saddle stiffness 1.1e7..1.1e10 N/m (log), limits crossed inside the grid."""
    counts = np.array([2, 3, 4])
    stiffness = np.geomspace(1.1e7, 1.1e10, 6)
    grow = (1.0 + np.arange(3))[:, None] * (1.0 + np.log10(stiffness / 1e7))[None, :]
    full = grow[..., None, None] * np.array([1.0, 1.6])[:, None] * np.array([1.1, 1.0])[None, :]
    dims = ("seafastening.saddle_count", "seafastening.saddle_stiffness_N_per_m", "load_case", "model")
    return xr.Dataset(
        {
            "F_N": (dims, 1.2e6 * full, {"units": "N"}),
            "M_b_Nm": (dims, 1e7 * full, {"units": "N m"}),
            "sigma_b_Pa": (dims, 3e6 * full, {"units": "Pa"}),
            "converged": (dims, np.ones(full.shape, bool)),
            "contact_preserved": (dims, full < 4.0),
            "error": (dims[:2], np.full(grow.shape, "", dtype=object).astype(str)),
        },
        coords={
            dims[0]: (dims[0], counts, {"units": "1", "scale": "linear", "base_value": 3.0}),
            dims[1]: (dims[1], stiffness, {"units": "N/m", "scale": "log", "base_value": 1.1e9}),
            "load_case": ("load_case", ["static", "dynamic"]),
            "model": ("model", ["linear", "nonlinear"]),
        },
        attrs={"study": "synthetic", "max_saddle_force_N": 7e6, "max_bending_stress_Pa": 2e7},
    )


@pytest.fixture
def capture(monkeypatch: pytest.MonkeyPatch):
    """Run a plotting function and return its matplotlib figure (its ``plt.close`` is held back)."""
    kept: list = []
    real_close = plt.close
    monkeypatch.setattr(plt, "close", lambda fig=None: kept.append(fig))

    def draw(fn, *args, **kwargs):
        fn(*args, **kwargs)
        fig = kept[-1]
        fig.canvas.draw()
        return fig

    yield draw
    real_close("all")


# ----------------------------------------------------------------------------- helpers
def _data_axes(fig) -> list:
    return [ax for ax in fig.axes if ax.get_label() != "<colorbar>" and not hasattr(ax, "_colorbar")]


def _legend_overlaps(fig) -> list[str]:
    """Legends whose box overlaps an axes' data area."""
    renderer = fig.canvas.get_renderer()
    legends = [ax.get_legend() for ax in fig.axes if ax.get_legend() is not None] + list(fig.legends)
    found = []
    for legend in legends:
        box = legend.get_window_extent(renderer)
        for ax in _data_axes(fig):
            if box.overlaps(ax.get_window_extent(renderer)):
                found.append(f"legend {[t.get_text() for t in legend.get_texts()][:2]} over axes '{ax.get_title() or ax.get_ylabel()}'")
    return found


def _hidden_lines(ax) -> list[str]:
    """Pairs of lines that coincide (to 1e-3 of their span) over at least 30 % of the points where
    either is away from zero, the upper one solid and nearly as wide as the lower one (so the
    lower one cannot be seen there)."""
    lines = [ln for ln in ax.get_lines() if ln.get_visible() and len(np.atleast_1d(ln.get_xdata())) > 10]
    order = {id(ln): i for i, ln in enumerate(ax.get_lines())}
    found = []
    for a, b in combinations(lines, 2):
        xa, ya = np.asarray(a.get_xdata(), float), np.asarray(a.get_ydata(), float)
        xb, yb = np.asarray(b.get_xdata(), float), np.asarray(b.get_ydata(), float)
        if xa.shape != xb.shape or not np.allclose(xa, xb):
            continue
        span = float(np.ptp(np.concatenate([ya, yb]))) or 1.0
        telling = (np.abs(ya) > 1e-2 * span) | (np.abs(yb) > 1e-2 * span)  # two curves that both vanish do not hide each other
        if telling.sum() < 10 or np.mean(np.abs(ya - yb)[telling] <= 1e-3 * span) < 0.3:
            continue
        top, bottom = (b, a) if (b.get_zorder(), order[id(b)]) > (a.get_zorder(), order[id(a)]) else (a, b)
        if top.get_linestyle() == "-" and top.get_linewidth() >= 0.75 * bottom.get_linewidth() and top.get_alpha() in (None, 1.0):
            found.append(f"'{bottom.get_label()}' under '{top.get_label()}' in '{ax.get_title() or ax.get_ylabel()}'")
    return found


def _tick_texts(axis, view: tuple[float, float]) -> list[str]:
    lo, hi = sorted(view)
    return [t.get_text() for t in axis.get_majorticklabels() if t.get_text() and lo <= t.get_position()[axis.axis_name == "y"] <= hi]


def _unit_in(label: str) -> str:
    return re.search(r"\[([^\]]+)\]", label).group(1)


# ----------------------------------------------------------------------------- units and ticks
def test_scaled_unit_puts_the_largest_value_between_1_and_1000():
    assert scaled_unit([2.2e-7, -1e-7], "m") == (1e6, "µm")
    assert scaled_unit([0.0093], "m") == (1e3, "mm")
    assert scaled_unit([74.0], "m") == (1.0, "m")  # lengths never go to km
    factor, unit = scaled_unit([1.1e7, 1.1e10], "N/m")
    assert unit == "GN/m" and factor == pytest.approx(1e-9)
    assert scaled_unit([4.9e7], "N m")[1] == "MN m" and scaled_unit([2.7e7], "Pa")[1] == "MPa"
    assert scaled_unit([3.0], "1") == (1.0, "1") and scaled_unit([0.6], "rad/s") == (1.0, "rad/s")
    assert scaled_unit([0.0, np.nan], "m") == (1.0, "m")


def test_stick_slip_displacement_reads_plain_numbers_in_the_unit_of_its_label(run_ds, capture, tmp_path):
    fig = capture(plots.plot_stick_slip, run_ds, tmp_path / "stick_slip.png")
    ax_u = fig.axes[0]
    unit = _unit_in(ax_u.get_ylabel())
    u = run_ds["axial_displacement_m"].sel(load_case="dynamic", model="nonlinear").values
    factor = {"m": 1.0, "mm": 1e3, "µm": 1e6}[unit]
    plotted = max(float(np.abs(ln.get_ydata()).max()) for ln in ax_u.get_lines() if len(ln.get_xdata()) > 10)
    assert plotted == pytest.approx(float(np.abs(u).max()) * factor, rel=1e-9)  # the data are in the label's unit
    assert 0.1 <= plotted < 1000.0  # a unit that suits them: the stuck cargo creeps 0.22 µm, not "0.0002 mm"
    texts = _tick_texts(ax_u.yaxis, ax_u.get_ylim())
    assert texts and all(PLAIN_NUMBER.match(t) for t in texts), texts
    assert ax_u.yaxis.get_offset_text().get_text() == ""


def test_interactive_stick_slip_axis_has_no_si_letters_and_data_in_its_unit(run_ds):
    fig = stick_slip_figure(run_ds)
    unit = _unit_in(fig.layout.yaxis.title.text)
    factor = {"m": 1.0, "mm": 1e3, "µm": 1e6}[unit]
    u = np.abs(run_ds["axial_displacement_m"].sel(load_case="dynamic").values).max()
    top = [t for t in fig.data if t.yaxis in (None, "y")]
    plotted = max(float(np.nanmax(np.abs(np.asarray(t.y, float)))) for t in top)
    assert plotted == pytest.approx(float(u) * factor, rel=1e-9) and 0.1 <= plotted < 1000.0
    for axis in (fig.layout.yaxis, fig.layout.yaxis2):
        assert axis.exponentformat not in (None, "B", "SI"), "plotly's default writes 200µ and 1B on ticks"


def test_study_axes_read_in_scaled_units_with_ticks_at_the_saddle_counts(capture, tmp_path):
    ds = synthetic_study()
    for fn, name in ((plot_surfaces, "surface.png"), (plot_compliance_map, "compliance.png")):
        fig = capture(fn, ds, tmp_path / name)
        for ax in _data_axes(fig):
            assert ax.get_xlabel().endswith("[GN/m]"), ax.get_xlabel()
            xt = _tick_texts(ax.xaxis, ax.get_xlim())
            assert xt and all(PLAIN_NUMBER.match(t) for t in xt), xt  # 0.01, 0.1, 1, 10: not 10^7 or 1B
            assert {float(t) for t in xt} <= {0.001, 0.01, 0.1, 1.0, 10.0, 100.0}
            assert [t.get_text() for t in ax.yaxis.get_majorticklabels()] == ["2", "3", "4"]  # not 1.5, 2.5
    profile = ds.isel({"seafastening.saddle_count": 1})
    fig = capture(plot_profiles, profile, tmp_path / "profiles.png")
    assert all(ax.get_xlabel().endswith("[GN/m]") for ax in _data_axes(fig))


def test_interactive_study_axes_in_gn_per_m_and_limits_on_cell_edges():
    ds = synthetic_study()
    fig = study_surface_figure(ds, "nonlinear")
    assert fig.layout.xaxis.title.text.endswith("[GN/m]")
    assert fig.layout.xaxis.exponentformat == "none" and fig.layout.xaxis.dtick == 1  # decades as 0.01 ... 10
    heat = [t for t in fig.data if t.type == "heatmap"]
    assert heat and all(0.001 < min(t.x) and max(t.x) < 100.0 for t in heat)
    assert not [t for t in fig.data if t.type == "contour"], "a contour interpolates between saddle counts"
    limits = [t for t in fig.data if t.name and t.name.startswith("design limit")]
    assert limits
    xe, ye = np.asarray(heat[0].x, float), np.asarray(heat[0].y, float)
    for trace in limits:  # every vertex on a cell edge: the boundary between computed points
        xs = np.array([v for v in trace.x if v is not None], float)
        ys = np.array([v for v in trace.y if v is not None], float)
        assert xs.size and all(np.isclose(xe, x).any() or np.isclose(ye, y).any() for x, y in zip(xs, ys, strict=True))
    cmap = compliance_map_figure(ds)
    assert cmap.layout.xaxis.title.text.endswith("[GN/m]")


def test_study_limit_lines_follow_the_cell_edges_not_a_contour(capture, tmp_path):
    ds = synthetic_study()
    fig = capture(plot_surfaces, ds, tmp_path / "surface.png", "nonlinear")
    for ax in _data_axes(fig):
        assert not ax.collections or all(type(c).__name__ != "QuadContourSet" for c in ax.collections)
    xs, ys = cell_boundary([0, 1, 2], [0, 1], [[True, False]])
    assert (xs, ys) == ([1.0, 1.0, None], [0.0, 1.0, None])  # the one interior edge between the two cells


# ----------------------------------------------------------------------------- legends and visibility
def _run_matplotlib_figures(run_ds, capture, tmp_path) -> dict[str, object]:
    jobs = {
        "deflection": plots.plot_deflection,
        "forces_moments": plots.plot_forces_and_moments,
        "saddle_time_histories": plots.plot_saddle_time_histories,
        "aft": plots.plot_aft_picture,
        "hull_girder": plots.plot_hull_girder,
        "raos": plots.plot_raos,
        "stick_slip": plots.plot_stick_slip,
        "contact_timeline": plot_contact_timeline,
    }
    return {name: capture(fn, run_ds, tmp_path / f"{name}.png") for name, fn in jobs.items()}


def test_legends_stand_outside_the_data_and_every_series_stays_visible(run_ds, capture, tmp_path):
    figures = _run_matplotlib_figures(run_ds, capture, tmp_path)
    figures["study_profiles"] = capture(plot_profiles, synthetic_study().isel({"seafastening.saddle_count": 1}), tmp_path / "p.png")
    overlaps = [f"{name}: {o}" for name, fig in figures.items() for o in _legend_overlaps(fig)]
    assert overlaps == []
    hidden = [f"{name}: {h}" for name, fig in figures.items() for ax in _data_axes(fig) for h in _hidden_lines(ax)]
    assert hidden == []
    # the checks see what they look for: a legend on the data and a solid line on its twin are found
    fig, ax = plt.subplots()
    x = np.linspace(0.0, 1.0, 50)
    ax.plot(x, x, lw=2, label="a")
    ax.plot(x, x, lw=2, label="b")
    ax.legend(loc="center")
    fig.canvas.draw()
    assert _legend_overlaps(fig) and _hidden_lines(ax)


def test_sea_state_and_operability_legends_stand_outside_the_data(capture, tmp_path):
    from seafast.cli import main
    from seafast.output.operability import plot_operability
    from seafast.output.seastate_plots import write_seastate_figures

    assert main(["seastate", "-o", str(tmp_path / "ss"), "--no-monte-carlo", "--no-plots", "-q"]) == 0
    assert main(["operability", "--tp", "8:12:1", "-o", str(tmp_path / "op"), "--no-plots", "-q"]) == 0
    with xr.open_dataset(tmp_path / "ss" / "seastate.nc") as ss, xr.open_dataset(tmp_path / "op" / "operability.nc") as op:
        plot_operability(op.load(), tmp_path / "operability.png")
        write_seastate_figures(ss.load(), tmp_path)  # the spectrum and the transfer functions
    drawn = [plt.figure(n) for n in plt.get_fignums()]  # capture holds back plt.close: all three are open
    assert len(drawn) == 3
    for fig in drawn:
        fig.canvas.draw()
    assert [o for fig in drawn for o in _legend_overlaps(fig)] == []
    assert [h for fig in drawn for ax in _data_axes(fig) for h in _hidden_lines(ax)] == []


def test_saddle_heat_maps_draw_the_computed_saddles_with_colour_bars(run_ds, capture, tmp_path):
    fig = capture(plots.plot_saddle_surfaces, run_ds, tmp_path / "saddle_surfaces.png")
    axes = _data_axes(fig)
    assert all(ax.name == "rectilinear" for ax in axes), "no 3-D surface interpolated between saddles"
    n_saddles, n_samples = run_ds.sizes["saddle"], run_ds.sizes["period_fraction"]
    labels = []
    for ax in axes:
        (mesh,) = [c for c in ax.collections if type(c).__name__ == "QuadMesh"]
        assert mesh.get_array().shape == (n_samples, n_saddles)  # one column per computed saddle
        assert mesh.colorbar is not None
        labels.append(mesh.colorbar.ax.get_ylabel())
        assert [t.get_text().split("\n")[0] for t in ax.get_xticklabels()] == [str(j) for j in range(n_saddles)]
    assert labels == ["saddle force [MN]", "compression [mm] (negative = gap)"]
    force = run_ds["saddle_force_N"].sel(load_case="dynamic", model="nonlinear").transpose("period_fraction", "saddle").values
    drawn = axes[0].collections[0].get_array().reshape(n_samples, n_saddles)
    np.testing.assert_allclose(drawn, force / 1e6, rtol=1e-12)


def test_rao_wave_frequency_is_named_off_the_subplot_titles(run_ds, capture, tmp_path):
    omega = float(run_ds.attrs["wave_frequency_rad_s"])
    fig = capture(plots.plot_raos, run_ds, tmp_path / "raos.png")
    assert f"{omega:.3f} rad/s" in fig.get_suptitle()
    assert all(not ax.texts for ax in fig.axes)
    interactive = rao_figure(run_ds)
    titles = {a.text for a in interactive.layout.annotations}
    assert titles == {f"{n} {kind}" for n in ("surge", "heave", "pitch") for kind in ("phase",)} | {
        "surge amplitude (forward +)",
        "heave amplitude",
        "pitch amplitude (bow up +)",
    }, "only the subplot titles: no label placed on top of them"
    named = [t for t in interactive.data if t.name and f"{omega:.3f} rad/s" in t.name]
    assert named and named[0].showlegend is not False


def test_interactive_legends_stand_beside_the_plot_and_linear_traces_on_top(run_ds):
    for item in run_figures(run_ds):
        legend = item.figure.layout.legend
        # plotly's default place (right of the plot, margin widened for it); never the band of the titles
        assert legend.orientation in (None, "v") and legend.y is None, item.id
    fig = saddle_time_history_figure(run_ds)
    force = [t for t in fig.data if t.xaxis in (None, "x") and t.yaxis in (None, "y")]
    assert [t.name for t in force] == ["nonlinear", "linear"]  # drawn in this order: linear on top
    lin, non = force[1].line, force[0].line
    assert lin.dash == "dash" and lin.width < non.width


def test_a_run_directory_report_draws_every_figure(run_ds, tmp_path):
    """The print figures of a run are written (the functions above, through the report's writer)."""
    from seafast.output.report.print_figures import write_print_figures

    paths = write_print_figures(run_ds, None, tmp_path / "figs", None)
    assert {Path(p).name for p in paths} >= {"stick_slip.png", "raos.png", "deflection.png", "contact_timeline.png"}
