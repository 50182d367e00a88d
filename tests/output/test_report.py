"""``seafast report``: HTML/PNG/PDF report of run and study directories, checked in a real browser."""

from __future__ import annotations

import os
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from seafast.cli import main
from seafast.output import report

CHROMIUM_CANDIDATES = ("/usr/bin/chromium", "/usr/bin/chromium-browser", "/usr/bin/google-chrome")

RUN_FIGURE_IDS = ("fig-hull-girder", "fig-deck-motion", "fig-saddle-histories", "fig-deflection-moment", "fig-contact-timeline")
STUDY_FIGURE_IDS = ("fig-study-surface-nonlinear", "fig-study-surface-linear", "fig-compliance-map")

SMALL_STUDY = """\
name: report-test
description: 2 x 3 saddle study for the report test
set:
  vessel.motions: none
  solver.time_samples: 32
  model.element_length_m: 2.0
axes:
  - key: seafastening.saddle_count
    values: [2, 3]
  - key: seafastening.saddle_stiffness_N_per_m
    start: 1.1e+8
    stop: 1.1e+10
    num: 3
    scale: log
"""


# ----------------------------------------------------------------------------- fixtures
@pytest.fixture(scope="module")
def run_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A real `seafast run` of the base case without rigid-body motions, small settings."""
    out = tmp_path_factory.mktemp("run")
    code = main(
        [
            "run",
            "-o",
            str(out),
            "-q",
            "--no-plots",
            "--set",
            "vessel.motions=none",
            "--set",
            "solver.time_samples=32",
            "--set",
            "model.element_length_m=2.0",
        ]
    )
    assert code == 0
    assert (out / "results.nc").is_file()
    return out


@pytest.fixture(scope="module")
def study_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A real, small 2 x 3 `seafast study` (serial)."""
    base = tmp_path_factory.mktemp("study")
    spec = base / "small.yaml"
    spec.write_text(SMALL_STUDY, encoding="utf-8")
    out = base / "out"
    code = main(["study", str(spec), "-o", str(out), "--workers", "1", "--no-progress", "--no-figures", "-q"])
    assert code == 0
    assert (out / "study.nc").is_file()
    return out


def synthetic_study(sizes: dict[str, int]) -> xr.Dataset:
    """A hand-made study dataset with the variables of `seafast study` over any number of axes."""
    coords: dict[str, tuple] = {}
    grids = []
    for key, n in sizes.items():
        if key.endswith("saddle_count"):
            values = np.arange(2, 2 + n)
            attrs = {"units": "1", "scale": "linear", "base_value": 3.0}
        else:
            values = np.geomspace(1e7, 1e10, n)
            attrs = {"units": "N/m", "scale": "log", "base_value": 1.1e9}
        coords[key] = (key, values, attrs)
        grids.append(values.astype(float))
    mesh = np.meshgrid(*grids, indexing="ij") if grids else []
    shape = tuple(sizes.values())
    base = np.ones(shape)
    for g in mesh:
        base = base * (1.0 + np.log10(g) / 10.0)
    dims = (*sizes.keys(), "load_case", "model")
    full = base[..., None, None] * np.array([1.0, 1.6])[:, None] * np.array([1.1, 1.0])[None, :]
    data = {
        "F_N": (dims, 5e6 * full, {"units": "N"}),
        "M_b_Nm": (dims, 6e7 * full, {"units": "N m"}),
        "sigma_b_Pa": (dims, 1.5e7 * full, {"units": "Pa"}),
        "u_c_m": (dims, 5e-3 * full, {"units": "m"}),
        "u_s_m": (dims, 5e-3 * full, {"units": "m"}),
        "u_d_m": (dims, 1e-3 * full, {"units": "m"}),
        "converged": (dims, np.ones(full.shape, bool)),
        "contact_preserved": (dims, full < 1.5 * np.median(full)),
        "error": (tuple(sizes), np.full(shape, "", dtype=object).astype(str)),
    }
    coords["load_case"] = ("load_case", ["static", "dynamic"])
    coords["model"] = ("model", ["linear", "nonlinear"])
    return xr.Dataset(data, coords=coords, attrs={"study": "synthetic", "max_saddle_force_N": 7e6, "max_bending_stress_Pa": 2e7})


# ----------------------------------------------------------------------------- HTML content
def _assert_self_contained(text: str) -> None:
    assert not re.search(r"<script[^>]+src=[\"']?https?:", text, re.I), "external script"
    assert not re.search(r"<link[^>]+href=[\"']?https?:", text, re.I), "external stylesheet"
    assert '<script src="http' not in text
    assert text.count("plotly.js v") >= 1  # the inline bundle's banner
    # plotly.js is embedded once: its bundle defines window.Plotly exactly once
    assert len(re.findall(r"<script type=\"text/javascript\">/\*\*\s*\n\* plotly\.js", text)) <= 1


def test_run_report_html(run_dir: Path) -> None:
    out = report.write_report(run_dir)
    assert out.html == run_dir / "report.html"
    text = out.html.read_text(encoding="utf-8")
    _assert_self_contained(text)
    for fid in RUN_FIGURE_IDS:
        assert f'id="{fid}"' in text, fid
    assert "fig-raos" not in out.figure_ids  # vessel.motions = none: no RAOs
    assert f'<meta name="seafast-figure-count" content="{len(out.figure_ids)}">' in text
    # inputs table lists every case key with units; the summary is in engineering units
    for key in ("cargo.length_m", "seafastening.saddle_stiffness_N_per_m", "solver.harmonics", "vessel.motions"):
        assert f"<td>{key}</td>" in text
    assert "<td>N/m</td>" in text and "MN m" in text and "MPa" in text
    # base case: the linear model loses contact in the dynamic case -> a visible WARNING box
    assert 'class="finding WARNING"' in text
    assert "contact lost while the linear model is used" in text
    # print figures: >= 200 dpi PNGs with the run's figures, and the PDF
    names = {p.name for p in out.pngs}
    assert {"deflection.png", "forces_moments.png", "saddle_time_histories.png", "contact_timeline.png", "hull_girder.png"} <= names
    from PIL import Image

    for p in out.pngs:
        with Image.open(p) as im:
            dpi = im.info.get("dpi", (0, 0))[0]
            assert dpi >= 199.0, (p.name, dpi)
    assert out.pdf is not None and out.pdf.stat().st_size > 10_000
    assert out.pdf.read_bytes()[:5] == b"%PDF-"


def test_study_report_html(study_dir: Path) -> None:
    out = report.write_report(study_dir)
    text = out.html.read_text(encoding="utf-8")
    _assert_self_contained(text)
    for fid in STUDY_FIGURE_IDS:
        assert f'id="{fid}"' in text, fid
    assert "Ranking of compliant arrangements" in text
    assert {"surface_nonlinear.png", "compliance_map.png"} <= {p.name for p in out.pngs}


@pytest.mark.parametrize(
    "sizes",
    [
        {"seafastening.saddle_stiffness_N_per_m": 5},
        {"seafastening.saddle_count": 3, "seafastening.saddle_stiffness_N_per_m": 4},
        {"seafastening.saddle_count": 3, "seafastening.saddle_stiffness_N_per_m": 4, "seafastening.lashing.stiffness_N_per_m": 3},
        {"seafastening.saddle_count": 1, "seafastening.saddle_stiffness_N_per_m": 4},
    ],
    ids=["1d", "2d", "3d", "2d-degenerate"],
)
def test_study_figures_any_dimension(sizes: dict[str, int]) -> None:
    ds = synthetic_study(sizes)
    figs = report.study_figures(ds)
    ids = [f.id for f in figs]
    varying = sum(1 for n in sizes.values() if n > 1)
    if varying >= 2:
        assert ids == ["fig-study-surface-nonlinear", "fig-study-surface-linear", "fig-compliance-map"]
    else:
        assert ids == ["fig-study-profiles", "fig-compliance-map"]
    page, _, findings = report.build_report_html(study=ds)
    _assert_self_contained(page)
    assert findings


def test_findings_flag_untrustworthy_results(run_dir: Path) -> None:
    with xr.open_dataset(run_dir / "results.nc") as stored:
        ds = stored.load()
    ok = report.run_findings(ds)
    assert any(f.level == "WARNING" and "linear model" in f.title for f in ok)
    bad = ds.copy(deep=True)
    bad["converged"].loc[dict(load_case="dynamic", model="nonlinear")] = 0
    bad["harmonic_truncation_indicator"].loc[dict(load_case="dynamic", model="nonlinear")] = 0.05
    assert not any("questionable" in f.title for f in ok)
    bad["solver_warning_flag"].loc[dict(load_case="dynamic", model="nonlinear", solver_warning="quasi_statics_questionable")] = 1
    titles = [f.title for f in report.run_findings(bad) if f.level == "WARNING"]
    assert any("did NOT converge" in t for t in titles)
    assert any("truncation indicator" in t for t in titles)
    assert any("quasi-static" in t for t in titles)


def test_report_cli_errors(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["report", str(tmp_path / "nowhere")]) == 2
    err = capsys.readouterr().err
    assert "does not exist" in err and "Traceback" not in err and len(err.strip().splitlines()) == 1
    assert main(["report", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert "neither results.nc" in err and "Traceback" not in err and len(err.strip().splitlines()) == 1
    (tmp_path / "results.nc").write_text("not a netcdf file")
    assert main(["report", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert "cannot read" in err and "Traceback" not in err


def test_report_cli_help(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as exc:
        main(["report", "--help"])
    assert exc.value.code == 0
    assert "examples:" in capsys.readouterr().out


def test_report_cli_output_option(run_dir: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    target = tmp_path / "elsewhere" / "r.html"
    assert main(["report", str(run_dir), "-o", str(target), "--no-figures"]) == 0
    assert target.is_file() and not (target.parent / report.FIGURES_DIRNAME).exists()
    assert "wrote" in capsys.readouterr().out


# ----------------------------------------------------------------------------- in a browser
def _chromium() -> str | None:
    for c in CHROMIUM_CANDIDATES:
        if Path(c).is_file() and os.access(c, os.X_OK):
            return c
    return shutil.which("chromium")


def _browser_args(browser: str, profile: Path) -> list[str]:
    return [
        browser,
        "--headless",
        "--no-sandbox",
        "--disable-gpu",
        "--disable-quic",
        "--no-first-run",
        "--disable-background-networking",
        "--disable-component-update",
        "--disable-sync",
        f"--user-data-dir={profile}",
        "--enable-logging=stderr",
        "--v=0",
        "--virtual-time-budget=10000",
    ]


def _js_errors(stderr: str) -> list[str]:
    return [
        line
        for line in stderr.splitlines()
        if "Uncaught" in line or "ERROR:CONSOLE" in line or (":CONSOLE(" in line and "error" in line.lower())
    ]


@pytest.mark.parametrize("which", ["run", "study"])
def test_report_renders_in_headless_chromium(which: str, run_dir: Path, study_dir: Path, tmp_path: Path) -> None:
    browser = _chromium()
    if browser is None:
        if os.environ.get("SEAFAST_REQUIRE_BROWSER") == "1":
            pytest.fail("headless Chromium is required (SEAFAST_REQUIRE_BROWSER=1) but not installed: apt-get install chromium")
        pytest.skip("Chromium not installed (set SEAFAST_REQUIRE_BROWSER=1 to make this a failure)")
    directory = run_dir if which == "run" else study_dir
    out = report.write_report(directory, tmp_path / "report.html", figures=False)
    url = out.html.resolve().as_uri()
    n_figures = len(out.figure_ids)
    assert n_figures >= 3

    dom = subprocess.run(
        [*_browser_args(browser, tmp_path / "profile-dom"), "--dump-dom", url], capture_output=True, text=True, timeout=180, check=False
    )  # the return code is asserted with the browser's messages
    assert dom.returncode == 0, dom.stderr[-2000:]
    drawn = len(re.findall(r'class="[^"]*\bjs-plotly-plot\b', dom.stdout))
    assert drawn == n_figures, f"{drawn} of {n_figures} plotly figures rendered"
    assert dom.stdout.count('class="main-svg"') >= n_figures
    for fid in out.figure_ids:
        assert re.search(rf'id="{fid}"[^>]*class="[^"]*js-plotly-plot', dom.stdout) or re.search(
            rf'class="[^"]*js-plotly-plot[^"]*"[^>]*id="{fid}"', dom.stdout
        ), f"figure {fid} not drawn"
    assert not _js_errors(dom.stderr), _js_errors(dom.stderr)

    shot = tmp_path / "report.png"
    res = subprocess.run(
        [*_browser_args(browser, tmp_path / "profile-shot"), f"--screenshot={shot}", "--window-size=1400,3000", url],
        capture_output=True,
        text=True,
        timeout=180,
        check=False,  # the return code is asserted with the browser's messages
    )
    assert res.returncode == 0, res.stderr[-2000:]
    assert not _js_errors(res.stderr), _js_errors(res.stderr)
    assert shot.is_file() and shot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    from PIL import Image

    with Image.open(shot) as im:
        assert im.size == (1400, 3000)
        small = np.asarray(im.convert("L").resize((140, 300)), dtype=float)
    assert small.std() > 20.0, "the screenshot is (nearly) blank"
    assert shot.stat().st_size > 50_000
