"""`seafast seastate` as a user meets it: outputs, columns, units, exit codes on bad input."""

from __future__ import annotations

import csv

import numpy as np
import pytest
import xarray as xr

import seafast
from seafast.analyses.seastate.design_wave import sea_state_design_waves
from seafast.analyses.seastate.spectral import SEASTATE_COLUMNS, spectral_analysis
from seafast.cli import main


@pytest.fixture(scope="module")
def spectral_run(tmp_path_factory):
    out = tmp_path_factory.mktemp("seastate")
    assert main(["seastate", "-o", str(out), "--no-monte-carlo", "-q"]) == 0
    return out


def test_seastate_csv_has_the_contract_columns_and_rows(spectral_run):
    with open(spectral_run / "seastate.csv", newline="") as f:
        header = f.readline().strip()
        f.seek(0)
        rows = list(csv.DictReader(f))
    assert header == ",".join(SEASTATE_COLUMNS) == "model,method,F_N,M_b_Nm,sigma_b_Pa,u_s_m,u_d_m,uplift_per_hour,converged"
    assert [(r["model"], r["method"]) for r in rows] == [
        ("linear", "spectral"),
        ("linear", "monte_carlo"),
        ("nonlinear", "monte_carlo"),
        ("nonlinear", "design_wave"),
    ]
    analysis = spectral_analysis(seafast.load_case(None))
    spectral, design = analysis.extremes.totals, sea_state_design_waves(analysis).totals
    for q in ("F_N", "M_b_Nm", "sigma_b_Pa", "u_s_m", "u_d_m", "uplift_per_hour"):
        assert float(rows[0][q]) == pytest.approx(spectral[q], rel=1e-12), q
        assert float(rows[3][q]) == pytest.approx(design[q], rel=1e-12), q
    assert rows[0]["converged"] == "true" == rows[3]["converged"]
    # not computed: empty cells, never made-up numbers
    for r in rows[1:3]:
        assert all(r[c] == "" for c in SEASTATE_COLUMNS[2:])
    # head seas: the file byte for byte as before the cradle columns (which only a sea off head seas adds)
    quantities = ("F_N", "M_b_Nm", "sigma_b_Pa", "u_s_m", "u_d_m", "uplift_per_hour")
    expected = (
        "model,method,F_N,M_b_Nm,sigma_b_Pa,u_s_m,u_d_m,uplift_per_hour,converged\n"
        "linear,spectral,"
        + ",".join(repr(float(spectral[q])) for q in quantities)
        + ",true\n"
        + "linear,monte_carlo,,,,,,,\nnonlinear,monte_carlo,,,,,,,\n"
        + "nonlinear,design_wave,"
        + ",".join(repr(float(design[q])) for q in quantities)
        + ",true\n"
    )
    assert (spectral_run / "seastate.csv").read_bytes() == expected.encode()


def test_seastate_nc_labels_every_variable_and_the_figures_exist(spectral_run):
    with xr.open_dataset(spectral_run / "seastate.nc") as ds:
        for name, var in list(ds.data_vars.items()) + list(ds.coords.items()):
            assert var.attrs.get("units") and var.attrs.get("long_name"), name
        assert ds["F_N"].sel(model="linear", estimate_method="spectral") > 0
        assert bool(ds["F_N"].sel(model="nonlinear", estimate_method="monte_carlo").isnull())
        assert ds["F_N"].sel(model="nonlinear", estimate_method="design_wave") < ds["F_N"].sel(model="linear", estimate_method="spectral")
        assert bool(ds["F_N"].sel(model="linear", estimate_method="design_wave").isnull())
        # the design waves: 3 per quantity and location (the spectral peak and the ends of its half-peak
        # band), the saddle quantities at each of the 3 saddles, the moment ones at their governing point
        assert ds.sizes["design_wave"] == 3 * (3 * 3 + 2) and set(ds["design_wave_role"].values) == {"peak", "band_low", "band_high"}
        for q in ("F_N", "M_b_Nm", "u_d_m"):  # each quantity from its own waves, read where they are designed
            own = ds[f"design_wave_{q}_read"].where(ds["design_wave_quantity"] == q)
            assert float(own.max()) == pytest.approx(float(ds[q].sel(model="nonlinear", estimate_method="design_wave")), rel=1e-12)
            assert np.all(own.fillna(0.0) <= ds[f"design_wave_{q}"].fillna(0.0) + 1e-12 * abs(float(own.max())))
        assert ds.attrs["significant_height_m"] == 3.0 and ds.attrs["duration_s"] == 10800.0
        for name in ("wave_spectrum_m2_s_per_rad", "saddle_force_transfer_N_per_m_real", "bending_moment_spectrum_Nm2_s_per_rad"):
            assert name in ds
    for png in ("seastate_spectrum.png", "seastate_transfer_functions.png"):
        assert (spectral_run / png).stat().st_size > 10_000
    assert seafast.load_case(spectral_run / "case.yaml").sea_state.peak_period_s == 10.0


@pytest.mark.parametrize(
    "overrides,needle",
    [
        (["sea_state.peak_period_s=3", "sea_state.significant_height_m=0.5"], "sea_state.peak_period_s = 3.0"),
        (["sea_state.peak_period_s=3"], "allowed Hs <= 0.94 m"),
        (["sea_state.significant_height_m=-2"], "sea_state.significant_height_m = -2"),
        (["sea_state.significant_height_m=15"], "allowed Hs <="),
        (["sea_state.spectrum=missing.csv", "sea_state.peak_period_s=null"], "sea_state.spectrum"),
        (["sea_state.spectrum=jonswap", "sea_state.peak_period_s=null"], "sea_state.peak_period_s = null"),
        (["sea_state.duration_s=yes"], "sea_state.duration_s"),
        (["vessel.coupling=two_way"], "vessel.coupling = 'two_way'"),
    ],
)
def test_bad_sea_state_input_exits_2_with_one_clear_message(tmp_path, capsys, overrides, needle):
    args = ["seastate", "-o", str(tmp_path / "o"), "--no-monte-carlo", "-q"]
    for o in overrides:
        args += ["--set", o]
    assert main(args) == 2
    err = capsys.readouterr().err
    assert needle in err and "Traceback" not in err and err.startswith("seafast: error:")


def test_workers_must_be_positive(tmp_path, capsys):
    assert main(["seastate", "-o", str(tmp_path), "--workers", "0", "-q"]) == 2
    assert "--workers 0" in capsys.readouterr().err


def test_report_of_a_seastate_directory_has_the_sea_state_section(spectral_run, tmp_path):
    out = tmp_path / "report.html"
    assert main(["report", str(spectral_run), "-o", str(out), "--no-figures"]) == 0
    page = out.read_text()
    for needle in (
        'id="seastate-summary"',
        'data-figure="fig-seastate-spectrum"',
        'data-figure="fig-seastate-transfer"',
        "uplift events in 3 h",
        "not computed",
    ):
        assert needle in page, needle
    # the table shows the csv's numbers in engineering units
    with open(spectral_run / "seastate.csv", newline="") as f:
        spectral = next(csv.DictReader(f))
    assert f"{float(spectral['F_N']) / 1e6:.3f}" in page


def _fake_statistics(model, converged):
    from types import SimpleNamespace

    import numpy as np

    maxima = {
        q: np.array([1.0, 1.1, 1.2]) * v
        for q, v in (("F_N", 9e6), ("M_b_Nm", 9e7), ("sigma_b_Pa", 2.3e7), ("u_s_m", 9e-3), ("u_d_m", 1e-3))
    }
    mpm = {q: float(np.median(m)) for q, m in maxima.items()}
    return SimpleNamespace(model=model, maxima=maxima, mpm=mpm, uplift_per_hour=1.5, converged=converged)


def test_monte_carlo_rows_and_dataset_are_written_from_the_engine(tmp_path, monkeypatch, capsys):
    # the command's side of the contract, with a stand-in engine: rows from the statistics, its
    # dataset merged into seastate.nc, exit 3 when a nonlinear realisation did not converge
    from types import SimpleNamespace

    import numpy as np

    import seafast.cli.seastate as seastate_cli

    calls = {}

    def engine(case, directory, *, workers=None, scheduler=None, progress=True):
        calls.update(case=case, directory=directory, workers=workers, scheduler=scheduler)

        def var(dims, data, units):
            return xr.Variable(dims, np.asarray(data), {"units": units, "long_name": "stand-in"})

        ds = xr.Dataset(
            {
                "realisation_F_N": var(("realisation",), [9e6, 9.9e6, 1.08e7], "N"),
                "mc_F_N": var(("model", "realisation"), [[9e6, 9.9e6, 1.08e7], [8e6, 9e6, 1e7]], "N"),
                "mc_mpm_F_N": var(("model",), [9.9e6, 9e6], "N"),
                "mc_M_b_Nm": var(("model", "realisation"), [[9e7, 9.9e7, 1.08e8], [8e7, 9e7, 1e8]], "N m"),
                "mc_mpm_M_b_Nm": var(("model",), [9.9e7, 9e7], "N m"),
            },
            coords={
                "realisation": xr.Variable(("realisation",), np.arange(3), {"units": "1", "long_name": "realisation index"}),
                "model": xr.Variable(("model",), ["linear", "nonlinear"], {"units": "1", "long_name": "model"}),
            },
        )
        return SimpleNamespace(
            linear=_fake_statistics("linear", True), nonlinear=_fake_statistics("nonlinear", False), example=None, to_dataset=lambda: ds
        )

    monkeypatch.setattr(seastate_cli, "_monte_carlo_engine", lambda: (engine, ""))
    out = tmp_path / "mc"
    assert main(["seastate", "-o", str(out), "--workers", "1", "--no-plots", "-q"]) == 3
    assert "nonlinear monte_carlo" in capsys.readouterr().err
    assert calls["workers"] == 1 and calls["scheduler"] is None and calls["directory"] == out
    with open(out / "seastate.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert float(rows[1]["F_N"]) == pytest.approx(9.9e6) and rows[1]["converged"] == "true"
    assert float(rows[2]["u_d_m"]) == pytest.approx(1.1e-3) and rows[2]["converged"] == "false"
    assert float(rows[2]["uplift_per_hour"]) == 1.5
    with xr.open_dataset(out / "seastate.nc") as ds:
        assert ds["realisation_F_N"].attrs["units"] == "N"
        assert float(ds["F_N"].sel(model="nonlinear", estimate_method="monte_carlo")) == pytest.approx(9.9e6)
        assert int(ds["converged"].sel(model="nonlinear", estimate_method="monte_carlo")) == 0
    # the report shows the Monte Carlo rows and the distribution of the maxima
    assert main(["report", str(out), "--no-figures"]) == 0
    page = (out / "report.html").read_text()
    assert 'data-figure="fig-seastate-maxima"' in page and "9.900" in page


_SEA_KEYS = [
    "sea_state.significant_height_m",
    "sea_state.peak_period_s",
    "sea_state.spectrum",
    "sea_state.peak_enhancement",
    "sea_state.duration_s",
    "sea_state.realisations",
    "sea_state.seed",
    "sea_state",
    "limits.max_saddle_force_N",
    "limits.max_bending_stress_Pa",
    "limits",
]


def _fuzz_values():
    from hypothesis import strategies as st

    return st.one_of(
        st.floats(allow_nan=True, allow_infinity=True),
        st.floats(0.1, 20.0),
        st.integers(-5, 200),
        st.text(max_size=8),
        st.none(),
        st.booleans(),
        st.sampled_from(["jonswap", "pierson_moskowitz", "x.csv"]),
    )


def test_seastate_never_tracebacks_on_random_sea_state_overrides(tmp_path):
    import io
    from contextlib import redirect_stderr, redirect_stdout

    import yaml
    from hypothesis import given, settings
    from hypothesis import strategies as st

    @settings(max_examples=30, deadline=None, derandomize=True)
    @given(st.lists(st.tuples(st.sampled_from(_SEA_KEYS), _fuzz_values()), min_size=1, max_size=3))
    def check(pairs):
        args = ["seastate", "-o", str(tmp_path / "h"), "--no-monte-carlo", "--no-plots", "-q"]
        for k, v in pairs:
            args += ["--set", f"{k}={yaml.safe_dump(v, default_flow_style=True).strip().removesuffix('...').strip()}"]
        err = io.StringIO()
        with redirect_stderr(err), redirect_stdout(io.StringIO()):
            code = main(args)
        assert code in (0, 2), (code, err.getvalue())
        assert "Traceback" not in err.getvalue()
        if code == 2:
            assert err.getvalue().startswith("seafast: error:")

    check()
