"""Sea states at any heading: transfer functions against `seafast run`, long-wave limits, beam and following seas,
short-crested spreading (its limit and its quadrature), the roll damping's stochastic linearisation."""

from __future__ import annotations

import csv
import math
from types import SimpleNamespace

import numpy as np
import pytest
import xarray as xr

import seafast
from seafast.analyses.run import run_case
from seafast.analyses.seastate.design_wave_rule import design_directions, quantity_transfer, select_design_waves
from seafast.analyses.seastate.directional import spreading_density_per_rad
from seafast.analyses.seastate.directional_transfer import sea_state_roll_damping, sea_state_transfer
from seafast.analyses.seastate.monte_carlo import build_plan
from seafast.analyses.seastate.spectral import spectral_analysis
from seafast.analyses.seastate.spectrum import sea_state_spectrum
from seafast.analyses.seastate.synthesis import realisation_phases, synthesise
from seafast.analyses.seastate.transfer import six_dof_motions, transfer_functions
from seafast.cli import main
from seafast.cli.seastate import breaking_design_waves_warning
from seafast.excitation.hydrodynamics.roll_damping import STOCHASTIC_FACTOR
from seafast.excitation.rao_extension import extended_six_dof_rao, six_dof_long_wave_limits
from seafast.excitation.vessel import VesselCache
from seafast.model.from_case import build_model

G = 9.81


@pytest.fixture(scope="module")
def base():
    case = seafast.load_case(None)
    return case, build_model(case), sea_state_spectrum(case), six_dof_motions(case)


def _sea(overrides):
    return seafast.load_case(None, overrides)


@pytest.mark.parametrize(("heading", "omega_target", "amplitude"), [(120.0, 0.64, 1.0), (90.0, 1.0, 2.0), (30.0, 0.5, 1.5)])
def test_oblique_transfer_times_amplitude_equals_seafast_run_at_a_grid_frequency(base, heading, omega_target, amplitude):
    """zeta_a TF at a grid frequency = `seafast run`'s linear first harmonic (dynamic minus static) at that heading."""
    case, model, spectrum, _ = base
    index = int(np.argmin(np.abs(spectrum.omega_rad_s - omega_target)))
    w = float(spectrum.omega_rad_s[index])
    tf = transfer_functions(case, model, spectrum.omega_rad_s, heading_deg=heading)
    regular = _sea({"wave.length_m": 2 * math.pi * G / w**2, "wave.amplitude_m": amplitude, "wave.heading_deg": heading})
    result = run_case(regular)
    ds = result.dataset
    n = ds.sizes["period_fraction"]
    phase = np.exp(2j * np.pi * np.arange(n) / n)[:, None]
    for name, transfer in (
        ("saddle_force_N", tf.saddle_force_N[index]),
        ("saddle_compression_m", tf.saddle_compression_m[index]),
        ("bending_moment_Nm", tf.bending_moment_Nm[index]),
    ):
        lin = ds[name].sel(model="linear")
        run = lin.sel(load_case="dynamic").values - lin.sel(load_case="static").values
        expected = np.real(amplitude * transfer[None, :] * phase)
        assert np.max(np.abs(run - expected)) <= 1e-6 * np.max(np.abs(run)), name
    exc = result.excitation
    for run_value, transfer in ((exc.deck_displacement[1], tf.deck_displacement[index]), (exc.cargo_load_N[1], tf.cargo_load_N[index])):
        assert np.max(np.abs(run_value - amplitude * transfer)) <= 1e-6 * np.max(np.abs(run_value))
    rb = result.vessel.rigid_body
    y = case.cargo_transverse_position_m()
    assert rb.heave_m == pytest.approx(amplitude * (tf.heave_m[index] + tf.roll_rad[index] * y), rel=1e-9)
    assert rb.pitch_rad == pytest.approx(amplitude * tf.pitch_rad[index], rel=1e-9)


@pytest.mark.parametrize("heading", [30.0, 60.0, 90.0, 120.0, 150.0])
def test_six_dof_long_wave_limits_agree_with_the_bem_at_the_grid_low_end(base, heading):
    """Heave -> 1, roll -> the slope across the ship -i k sin(beta), pitch -> the slope along it -i k cos(beta).

    At 0.2 rad/s (a 1540 m wave) the BEM is within 3 % and 5 deg of each (roll is 3 % above it: its resonance at
    0.64 rad/s lifts it); a wrong sign would be 180 deg off. Below the grid the extension tends to the limits.
    """
    _, _, _, m6 = base
    kw = {"gravity_m_per_s2": G, "reference_x_m": m6.reference_x_m, "wave_phase_reference_x_m": m6.wave_phase_reference_x_m}
    w0 = float(m6.omega_rad_s[0])
    bem, limit = m6.rao_at(np.array([w0]), heading)[0], six_dof_long_wave_limits([w0], heading, **kw)[0]
    dofs = [2, 3] + ([4] if heading != 90.0 else [])  # pitch's limit vanishes in beam seas
    for dof in dofs:
        ratio = bem[dof] / limit[dof]
        assert abs(ratio) == pytest.approx(1.0, abs=0.035), dof
        assert abs(np.degrees(np.angle(ratio))) < 5.0, dof
    w = np.array([0.01, 0.05, 0.1, w0, w0 * (1 + 1e-9)])
    ext = extended_six_dof_rao(m6, w, heading, gravity_m_per_s2=G, draught_m=6.5)
    lim = six_dof_long_wave_limits(w, heading, **kw)
    for dof in dofs:  # the deviation from the limit falls as omega^2 (relative to the limit)
        expected = abs(bem[dof] / limit[dof] - 1.0) * (w[0] / w0) ** 2
        assert abs(ext[0, dof] / lim[0, dof] - 1.0) == pytest.approx(expected, rel=1e-6)
        assert ext[3, dof] == pytest.approx(bem[dof], rel=1e-12)  # continuous at the grid's end
        assert ext[4, dof] == pytest.approx(bem[dof], rel=1e-6)
    high = extended_six_dof_rao(m6, np.array([1.8, 2.5, 4.0]), heading, gravity_m_per_s2=G, draught_m=6.5)
    assert np.all(np.abs(high[2]) < np.abs(high[1])) and np.all(np.abs(high[1]) <= np.abs(high[0]) + 1e-15)


def test_beam_seas_bend_the_hull_little_while_roll_dominates_the_deck_motion(base):
    case, model, spectrum, _ = base
    w = spectrum.omega_rad_s
    head = transfer_functions(case, model, w, heading_deg=180.0)
    beam = transfer_functions(case, model, w, heading_deg=90.0)
    # the hull's vertical bending: a beam wave has no length along the ship, only its breadth average (which varies a
    # little along the tapered ends: short waves across the ship bend it a little)
    long_waves = w < 0.8
    assert np.max(np.abs(beam.deck_displacement[long_waves])) < 0.1 * np.max(np.abs(head.deck_displacement[long_waves]))
    S = spectrum.density_m2_s_per_rad[:, None]
    sigma_beam, sigma_head = (np.sqrt(np.trapezoid(np.abs(t.deck_displacement) ** 2 * S, w, axis=0)) for t in (beam, head))
    assert np.max(sigma_beam) < 0.2 * np.max(sigma_head)
    y = case.cargo_transverse_position_m()
    roll_deck = np.abs(beam.roll_rad * y)
    assert w[np.argmax(roll_deck)] == pytest.approx(0.642, abs=0.01)  # the roll resonance
    near = (w > 0.6) & (w < 0.66)
    assert np.all(roll_deck[near] > 1.3 * np.abs(beam.heave_m[near]))  # roll lifts the outer unit more than heave
    half_length = 0.5 * case.cargo.length_m
    assert np.all(roll_deck[near] > 5.0 * np.abs(beam.pitch_rad[near]) * half_length)  # and far more than pitch its ends
    # the unit's deck moves almost as one: the saddle forces are a fraction of the head sea's, whose hull bends
    sigma_force_beam, sigma_force_head = (np.sqrt(np.trapezoid(np.abs(t.saddle_force_N) ** 2 * S, w, axis=0)) for t in (beam, head))
    assert np.max(sigma_force_beam) < 0.2 * np.max(sigma_force_head)


def test_following_and_head_seas_bend_the_hull_alike_and_do_not_roll(base):
    """The quasi-static hull under a wave travelling either way along the ship: the same cosine load, the sine one
    reversed, so the following sea's deck transfer is the head sea's conjugate; roll vanishes in both."""
    case, model, spectrum, _ = base
    w = spectrum.omega_rad_s
    head = transfer_functions(case, model, w, heading_deg=180.0, six_dof=True)
    following = transfer_functions(case, model, w, heading_deg=0.0)
    scale = np.max(np.abs(head.deck_displacement))
    assert np.max(np.abs(following.deck_displacement - np.conj(head.deck_displacement))) < 1e-9 * scale
    for tf in (head, following):
        assert np.max(np.abs(tf.roll_rad)) < 1e-9 * np.max(np.abs(tf.pitch_rad))


def test_head_seas_keep_the_heave_pitch_model_bit_for_bit(base):
    case, model, spectrum, _ = base
    direct = transfer_functions(case, model, spectrum.omega_rad_s, heading_deg=180.0)
    sea = sea_state_transfer(case, model, spectrum.omega_rad_s)
    assert sea.mean.roll_rad is None and len(sea.per_direction) == 1
    for name in ("saddle_force_N", "bending_moment_Nm", "deck_displacement", "heave_m"):
        assert np.array_equal(getattr(sea.mean, name), getattr(direct, name))
    # the six-DOF model at 180 differs slightly (another KG, coupled): why a spread sea uses it for every direction
    six = transfer_functions(case, model, spectrum.omega_rad_s, heading_deg=180.0, six_dof=True)
    assert not np.array_equal(six.saddle_force_N, direct.saddle_force_N)
    assert np.max(np.abs(six.saddle_force_N - direct.saddle_force_N)) < 0.1 * np.max(np.abs(direct.saddle_force_N))


def test_a_narrow_spreading_tends_to_the_long_crested_sea_at_the_mean_heading():
    long = spectral_analysis(_sea({"sea_state.heading_deg": 150.0})).extremes
    errors = []
    for s in (10.0, 100.0, 1000.0):
        spread = spectral_analysis(_sea({"sea_state.heading_deg": 150.0, "sea_state.spreading_exponent": s})).extremes
        errors.append(max(abs(spread.totals[q] / long.totals[q] - 1.0) for q in ("F_N", "M_b_Nm", "sigma_b_Pa")))
    assert errors[0] > errors[1] > errors[2]
    assert errors[2] < 2e-3  # s = 1000: about 2.5 deg of spread


def test_a_spread_sea_s_design_waves_come_from_the_most_responsive_direction():
    """Each design wave of a spread beam sea: from the quadrature direction whose transfer function is largest at its
    frequency, its linear response there equal to the spread MPM, and no steeper than a sea carries (at the mean
    heading, 90 deg, the rule's wave was 53 m, height over length 0.72)."""
    analysis = spectral_analysis(_sea({"sea_state.heading_deg": 90.0, "sea_state.spreading_exponent": 8.0}))
    directions = design_directions(analysis)
    assert len(directions) == analysis.directional.quadrature.heading_deg.size > 1
    waves = select_design_waves(analysis)
    assert len(waves) > 0
    stats = {
        "F_N": analysis.extremes.saddle_force,
        "u_s_m": analysis.extremes.saddle_compression,
        "u_d_m": analysis.extremes.saddle_compression,
    }
    stats |= {"M_b_Nm": analysis.extremes.bending_moment, "sigma_b_Pa": analysis.extremes.bending_stress}
    for wave in waves:
        moduli = [abs(complex(quantity_transfer(tf, wave.quantity, wave.location)[wave.frequency_index])) for tf in directions]
        assert moduli[wave.direction] == max(moduli)
        assert wave.heading_deg == directions[wave.direction].heading_deg
        assert wave.amplitude_m * moduli[wave.direction] == pytest.approx(float(stats[wave.quantity].mpm[wave.location]), rel=1e-12)
        assert 2.0 * wave.amplitude_m * wave.omega_rad_s**2 / (2.0 * math.pi * G) < 1.0 / 7.0
    assert len({w.direction for w in waves}) > 1  # not one heading for all: the rule picks per frequency and location
    assert breaking_design_waves_warning(SimpleNamespace(waves=waves), 90.0, G) is None


def test_the_spread_spectral_m0_equals_a_direct_quadrature_over_directions(base):
    """m0 of the spread sea (15-direction rule) against the integral of D(theta) m0(theta) by a fine trapezoid."""
    _, model, spectrum, _ = base
    sea_case = _sea({"sea_state.heading_deg": 120.0, "sea_state.spreading_exponent": 6.0})
    analysis = spectral_analysis(sea_case, model)
    w, S = spectrum.omega_rad_s, spectrum.density_m2_s_per_rad
    theta = np.linspace(-math.pi, math.pi, 73)[1:-1]  # D(+-pi) = 0
    m0 = []
    with VesselCache().shared():  # one vessel (hull, loading, BEM data) for the 71 directions, as the analysis shares it
        for t in theta:
            heading = (120.0 + math.degrees(t)) % 360.0
            tf = transfer_functions(sea_case, model, w, heading_deg=0.0 if heading >= 360.0 else heading, six_dof=True)
            m0.append(np.trapezoid(np.abs(tf.saddle_force_N) ** 2 * S[:, None], w, axis=0))
    direct = np.trapezoid(spreading_density_per_rad(theta, 6.0)[:, None] * np.array(m0), theta, axis=0)
    # measured 0.17-0.20 %: the 15 directions' quadrature error (31 directions: 5e-5; the 71-point trapezoid: 1e-5)
    assert np.allclose(analysis.extremes.saddle_force.m0, direct, rtol=4e-3)
    # and it is not the long-crested sea's
    long = spectral_analysis(_sea({"sea_state.heading_deg": 120.0}), model).extremes.saddle_force.m0
    assert np.max(np.abs(long / direct - 1.0)) > 0.05


def test_the_roll_damping_is_linearised_on_the_spread_sea_s_own_roll(base):
    """B_eq = sqrt(8 / pi) B44_2 sigma_phidot, sigma_phidot summed over the directions from the six-DOF RAOs themselves."""
    _, model, spectrum, m6 = base
    b2 = 2.0e10
    sea_case = _sea(
        {"sea_state.heading_deg": 100.0, "sea_state.spreading_exponent": 4.0, "vessel.roll_damping_quadratic_Nms2_per_rad2": b2}
    )
    roll = sea_state_roll_damping(sea_case, spectrum)
    assert roll is not None and roll.converged and roll.residual_Nms_per_rad < 1e-6 * roll.equivalent_damping_Nms_per_rad
    sea = sea_state_transfer(sea_case, model, spectrum.omega_rad_s, roll)
    w, S = spectrum.omega_rad_s, spectrum.density_m2_s_per_rad
    inside = (w >= m6.omega_rad_s[0]) & (w <= m6.omega_rad_s[-1])
    b_eq = roll.equivalent_damping_Nms_per_rad
    var_v = sum(
        weight * np.trapezoid(w[inside] ** 2 * np.abs(m6.rao_at(w[inside], float(h), b_eq)[:, 3]) ** 2 * S[inside], w[inside])
        for h, weight in zip(sea.quadrature.heading_deg, sea.quadrature.weight, strict=True)
    )
    assert b_eq == pytest.approx(STOCHASTIC_FACTOR * b2 * math.sqrt(var_v), rel=1e-9)
    # the transfer functions carry it: roll below the linear sea's at resonance
    linear = sea_state_transfer(sea_case, model, spectrum.omega_rad_s)
    near = (w > 0.6) & (w < 0.7)
    assert np.all(np.abs(sea.mean.roll_rad[near]) < 0.8 * np.abs(linear.mean.roll_rad[near]))
    attrs = spectral_analysis(sea_case, model).directional.attributes()
    assert attrs["roll_damping_linearisation"] == "stochastic" and attrs["roll_linearisation_converged"] == 1
    assert attrs["roll_equivalent_damping_Nms_per_rad"] == pytest.approx(b_eq, rel=1e-12)


# ---------------------------------------------------------------------------- the Monte Carlo of a short-crested sea
def test_the_linear_monte_carlo_of_a_spread_sea_reproduces_its_spectral_method():
    """Each component's direction drawn from the quadrature's weights: the records' variance is the spread spectral one.

    Deterministic amplitudes and random phases: a record's variance is ``sum_j a_j^2 |H_{d_j}(omega_j)|^2 / 2``, whose
    mean over the draws is the spectral ``sum_j w_j |H_j|^2`` sum and whose scatter is known from the plan itself.
    """
    overrides = {"sea_state.heading_deg": 120.0, "sea_state.spreading_exponent": 4.0, "sea_state.duration_s": 3600.0}
    case = _sea({**overrides, "sea_state.random_amplitudes": False})
    plan = build_plan(case)
    spec = spectral_analysis(case).extremes.saddle_compression
    n_s, grid = plan.saddle_count, plan.grid
    assert plan.transfer.shape[0] == plan.direction_weights.size == 15
    half_a2 = grid.amplitude_m**2 / 2.0
    h2 = np.abs(plan.transfer[:, :, :n_s]) ** 2  # (n_d, n_f, n_s)
    mean_h2 = np.tensordot(plan.direction_weights, h2, axes=(0, 0))
    spread_sd = np.sqrt(np.sum(half_a2[:, None] ** 2 * (np.tensordot(plan.direction_weights, h2**2, axes=(0, 0)) - mean_h2**2), axis=0))
    expected = np.sum(half_a2[:, None] * mean_h2, axis=0)
    assert np.allclose(expected, spec.m0, rtol=1e-3)  # the synthesis grid's sum against the spectral trapezoid
    n = 12
    variances = []
    counts = np.zeros(plan.direction_weights.size)
    for i in range(n):
        transfer = plan.realisation_transfer(i)
        x = synthesise(grid, realisation_phases(plan.seed, i, grid.omega_rad_s.size), transfer, None)
        variances.append(np.mean(x[:, :n_s] ** 2, axis=0))
        drawn = np.argmin(np.abs(transfer[:, None, :n_s] - np.moveaxis(plan.transfer[:, :, :n_s], 0, 1)).sum(axis=2), axis=1)
        counts += np.bincount(drawn, minlength=counts.size)
    rel = np.mean(variances, axis=0) / expected - 1.0
    assert np.all(np.abs(rel) < 4.0 * spread_sd / expected / math.sqrt(n) + 1e-6)
    assert np.all(spread_sd / expected < 0.1)  # a record's share of the directions scatters little: many components
    share = counts / counts.sum()
    assert np.max(np.abs(share - plan.direction_weights)) < 0.01  # categorical draws with the quadrature's weights
    # the directions come from their own stream: another realisation draws others, the same one the same
    assert not np.array_equal(plan.realisation_transfer(0), plan.realisation_transfer(1))
    assert np.array_equal(plan.realisation_transfer(3), plan.realisation_transfer(3))


def test_a_long_crested_plan_keeps_its_transfer_and_phases():
    case = _sea({"sea_state.heading_deg": 90.0, "sea_state.duration_s": 3600.0})
    plan = build_plan(case)
    assert plan.direction_weights is None and plan.realisation_transfer(5) is plan.transfer
    tf = transfer_functions(case, build_model(case), plan.grid.omega_rad_s[100:103], heading_deg=90.0)
    n_s = plan.saddle_count
    assert np.allclose(plan.transfer[100:103, :n_s], tf.saddle_compression_m, rtol=1e-4, atol=1e-4 * np.abs(tf.saddle_compression_m).max())


def test_seastate_runs_at_any_heading_and_records_the_roll_linearisation(tmp_path):
    out = tmp_path / "beam"
    code = main(
        [
            "seastate",
            "-o",
            str(out),
            "--no-monte-carlo",
            "--no-plots",
            "-q",
            "--set",
            "sea_state.heading_deg=120",
            "--set",
            "sea_state.spreading_exponent=8",
            "--set",
            "vessel.roll_damping_quadratic_Nms2_per_rad2=1e10",
        ]
    )
    assert code == 0
    ds = xr.open_dataset(out / "seastate.nc")
    assert ds.attrs["sea_state_heading_deg"] == 120.0 and ds.attrs["sea_state_spreading_exponent"] == 8.0
    assert ds.attrs["motion_model"] == "six-DOF" and ds.attrs["roll_damping_linearisation"] == "stochastic"
    assert ds.attrs["roll_linearisation_converged"] == 1 and ds.attrs["roll_equivalent_damping_Nms_per_rad"] > 0
    assert ds["roll_transfer_rad_per_m_real"].attrs["units"] == "rad/m" and np.max(np.abs(ds["roll_transfer_rad_per_m_imag"])) > 0
    rows = {(r["model"], r["method"]): r for r in csv.DictReader((out / "seastate.csv").open())}
    for key in (("linear", "spectral"), ("nonlinear", "design_wave")):
        assert float(rows[key]["F_N"]) > 0.0


def test_a_design_wave_past_breaking_is_warned_of():
    """A design wave steeper than a regular wave can be is no estimate: the command says so."""
    g = 9.81
    wave = lambda a, w: SimpleNamespace(amplitude_m=a, omega_rad_s=w)  # noqa: E731
    steep = SimpleNamespace(waves=(wave(2.0, 0.6), wave(53.5, 1.0), wave(30.0, 0.9)))
    text = breaking_design_waves_warning(steep, 90.0, g)
    assert text is not None and "2 design wave(s)" in text and "amplitude 53.5 m at 1 rad/s" in text
    assert f"{2 * 53.5 / (2 * math.pi * g / 1.0):.2f} > 1/7" in text
    # a wave just below the limit is not warned of
    limit = 0.5 / 7.0 * 2 * math.pi * g / 0.6**2
    assert breaking_design_waves_warning(SimpleNamespace(waves=(wave(0.999 * limit, 0.6),)), 180.0, g) is None
