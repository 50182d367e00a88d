"""Tests of the hull girder in oblique seas (seafast.hull.oblique, and the heading of seafast.hull.wave and
seafast.hull.transfer): head seas unchanged bit for bit, the breadth factor against the box section's
integral, the apparent wave length along the ship, beam and following seas, and the emergence across the
waterline."""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from scipy.integrate import quad

from hull_cases import RHO, G, box_hull
from seafast.fourier import period_fraction, time_to_harmonics
from seafast.hull.balance import hydrostatic_balance
from seafast.hull.girder import HullBeam, HullGirder, shear_moment
from seafast.hull.grid import hull_grid, loading_breakpoints, weight_element_ends
from seafast.hull.oblique import breadth_factor, heading_cosines, max_local_draught_change
from seafast.hull.transfer import wave_transfer_functions
from seafast.hull.wave import wave_response
from seafast.vessel.loading import VesselLoading, WeightItem

L, B, T = 100.0, 20.0, 5.0
SHIP_LENGTH_WAVE = 171.0  # the base vessel's length [m]


@pytest.fixture(scope="module")
def barge():
    """A box barge (L 100 m, B 20 m, T 5 m) with its displacement spread uniformly."""
    return HullGirder(box_hull(L, B, T)), VesselLoading(None, (WeightItem("uniform", 0.0, L, RHO * L * B * T),))


def omega_of(wave_length_m: float) -> np.ndarray:
    return np.array([np.sqrt(2.0 * np.pi * G / wave_length_m)])


def test_heading_cosines_are_exact_at_the_quadrants_and_refuse_a_non_finite_heading():
    assert heading_cosines(180.0) == (-1.0, 0.0) and heading_cosines(90.0) == (0.0, 1.0)
    assert heading_cosines(0.0) == (1.0, 0.0) and heading_cosines(270.0) == (0.0, -1.0) and heading_cosines(-90.0) == (0.0, -1.0)
    c, s = heading_cosines(120.0)
    assert c == pytest.approx(-0.5, abs=1e-15) and s == pytest.approx(np.sqrt(3) / 2, abs=1e-15)
    with pytest.raises(ValueError, match="heading_deg = nan; must be finite"):
        heading_cosines(float("nan"))


def test_head_seas_are_bit_identical_to_the_head_sea_formula(base):
    """The default heading (and 180 given explicitly) rebuilds the head-sea model exactly: the wave
    ``zeta_a cos(2 pi s + k (x - L/2))`` balanced, integrated and solved here without the heading code."""
    girder, loading, _ = base
    r = wave_response(girder, loading, SHIP_LENGTH_WAVE, 3.0)
    assert r.heading_deg == 180.0
    x = hull_grid(girder, loading_breakpoints(girder, loading), 343)
    wa, wb = weight_element_ends(girder, loading, x)
    k = 2.0 * np.pi / SHIP_LENGTH_WAVE
    phase = 2.0 * np.pi * period_fraction(64)[:, None] + k * (x[None, :] - girder.midship_x_m)
    zeta = np.vstack([np.zeros((1, x.size)), 3.0 * np.cos(phase)])
    _, _, _, qa, qb = hydrostatic_balance(girder, x, wa, wb, zeta)
    V, M = shear_moment(np.diff(x), qa, qb)
    z, _ = HullBeam.build(x, girder).solve(qa, qb, V)
    for r180 in (r, wave_response(girder, loading, SHIP_LENGTH_WAVE, 3.0, heading_deg=180.0)):
        assert np.array_equal(r180.bending_moment_Nm, M[1:] - M[0]) and np.array_equal(r180.deflection_m, z[1:] - z[0])
        assert np.array_equal(r180.bending_moment_harmonics_Nm, time_to_harmonics(M[1:] - M[0], 5))
    w = np.array([0.3, 0.6004, 1.2])
    head = wave_transfer_functions(girder, loading, w)
    explicit = wave_transfer_functions(girder, loading, w, heading_deg=180.0)
    for a, b in (
        (head.bending_moment_Nm_per_m, explicit.bending_moment_Nm_per_m),
        (head.emergence_amplitude_m, explicit.emergence_amplitude_m),
    ):
        assert np.array_equal(a, b)


def test_the_breadth_factor_is_the_mean_immersion_of_a_box_section():
    """A box section of breadth B in the wave ``zeta_a cos(theta - kappa y)`` (``kappa = k sin beta``):
    the immersed area's change, integrated across the section, over ``B zeta_a cos(theta)`` (the head-sea
    value); closed form ``sin(kappa B / 2) / (kappa B / 2)``, zero where the transverse wave length is B."""
    k, breadth = 2.0 * np.pi / 60.0, 42.0
    for heading in (180.0, 150.0, 120.0, 95.0, 90.0, 60.0, 300.0):
        kappa = k * np.sin(np.deg2rad(heading))
        area = quad(lambda y, kappa=kappa: np.cos(0.3 - kappa * y), -0.5 * breadth, 0.5 * breadth, epsabs=1e-13)[0]
        assert float(breadth_factor(k, breadth, heading)) == pytest.approx(area / (breadth * np.cos(0.3)), rel=1e-10, abs=1e-12)
    assert float(breadth_factor(2.0 * np.pi / breadth, breadth, 90.0)) == pytest.approx(0.0, abs=1e-15)
    assert float(breadth_factor(k, breadth, 90.0)) == pytest.approx(np.sin(k * breadth / 2) / (k * breadth / 2), rel=1e-14)
    assert float(breadth_factor(k, breadth, 180.0)) == 1.0 and float(breadth_factor(k, breadth, 0.0)) == 1.0


def test_an_oblique_wave_bends_a_box_as_the_head_sea_wave_of_its_apparent_length_times_the_breadth_factor(barge):
    """A wave of length lambda at 120 deg on a constant-breadth box = the head-sea wave of length
    ``lambda / |cos 120|`` (same direction along the ship), scaled by ``F = sinc(k B sin 120 / 2)``:
    time series, harmonics and transfer function (at the true wave's frequency)."""
    girder, loading = barge
    lam, heading = 0.8 * L, 120.0
    apparent = lam / abs(np.cos(np.deg2rad(heading)))
    k = 2.0 * np.pi / lam
    factor = np.sin(0.5 * k * B * np.sin(np.deg2rad(heading))) / (0.5 * k * B * np.sin(np.deg2rad(heading)))
    oblique = wave_response(girder, loading, lam, 1.0, n_points=401, heading_deg=heading)
    head = wave_response(girder, loading, apparent, factor, n_points=401)
    scale = np.max(np.abs(head.bending_moment_Nm))
    np.testing.assert_allclose(oblique.bending_moment_Nm, head.bending_moment_Nm, rtol=0, atol=1e-10 * scale)
    np.testing.assert_allclose(oblique.deflection_m, head.deflection_m, rtol=0, atol=1e-10 * np.max(np.abs(head.deflection_m)))
    assert oblique.frequency_rad_s == pytest.approx(np.sqrt(G * k), rel=1e-15)
    tf = wave_transfer_functions(girder, loading, omega_of(lam), n_points=401, heading_deg=heading)
    np.testing.assert_allclose(tf.bending_moment_Nm_per_m[0], head.bending_moment_harmonics_Nm[1], rtol=0, atol=1e-10 * scale)


def direct_midship_moment(girder: HullGirder, k: float, heading_deg: float) -> complex:
    """Midship wave bending moment per metre of wave [N m/m], complex, by quadrature alone.

    The 3-D wave ``exp(-i k ((x - L/2) cos beta + y sin beta))`` is averaged across the waterline numerically
    (Gauss-Legendre in y), the section's buoyancy ``rho g C_s`` times that integral, the ship's heave and
    pitch solved from the two balance integrals, and ``M(L/2) = int_0^{L/2} (L/2 - x) q dx`` (adaptive quad
    per linear piece of the breadth): no part of seafast.hull but the hull form's breadth.
    """
    c, s = np.cos(np.deg2rad(heading_deg)), np.sin(np.deg2rad(heading_deg))
    eta, weights = np.polynomial.legendre.leggauss(40)
    xm, rgc = girder.midship_x_m, girder.buoyancy_per_draught_N_per_m2
    stations = girder.hull.station_x_m

    def wave_force(x: float) -> complex:
        b = float(girder.hull.breadth_at(x))
        y = 0.5 * b * eta
        return rgc * 0.5 * b * complex(np.sum(weights * np.exp(-1j * k * ((x - xm) * c + y * s))))

    def integral(f) -> complex:
        parts = [
            (quad(lambda x: f(x).real, a, b, epsabs=1e-3, epsrel=1e-12)[0], quad(lambda x: f(x).imag, a, b, epsabs=1e-3, epsrel=1e-12)[0])
            for a, b in itertools.pairwise(stations)
        ]
        return complex(sum(p[0] for p in parts), sum(p[1] for p in parts))

    def box(x: float) -> float:
        return rgc * float(girder.hull.breadth_at(x))

    # ship's heave h and pitch p (draught change h - p (x - xm)) cancel the wave's force and moment
    a = np.array(
        [
            [integral(box).real, -integral(lambda x: box(x) * (x - xm)).real],
            [integral(lambda x: box(x) * (x - xm)).real, -integral(lambda x: box(x) * (x - xm) ** 2).real],
        ]
    )
    rhs = -np.array([integral(wave_force), integral(lambda x: wave_force(x) * (x - xm))])
    h, p = np.linalg.solve(a.astype(complex), rhs)

    def load(x: float) -> complex:
        return wave_force(x) + box(x) * (h - p * (x - xm))

    pieces = [(a0, min(b0, xm)) for a0, b0 in itertools.pairwise(stations) if a0 < xm]
    re = sum(quad(lambda x: ((xm - x) * load(x)).real, a0, b0, epsabs=1e-3, epsrel=1e-12)[0] for a0, b0 in pieces)
    im = sum(quad(lambda x: ((xm - x) * load(x)).imag, a0, b0, epsabs=1e-3, epsrel=1e-12)[0] for a0, b0 in pieces)
    return complex(re, im)


@pytest.mark.parametrize("heading", [120.0, 90.0, 150.0])
def test_the_base_hull_at_a_heading_matches_the_wave_averaged_across_its_waterline_by_quadrature(base, heading):
    """The tapered base hull (transom 29.4 m, bow run to the stem), a ship-length wave: the transfer
    function's midship moment against :func:`direct_midship_moment`. The discretisation (linear load per
    0.5 m element) is the only difference: 1e-4 of the head-sea moment."""
    girder, loading, _ = base
    k = 2.0 * np.pi / SHIP_LENGTH_WAVE
    tf = wave_transfer_functions(girder, loading, omega_of(SHIP_LENGTH_WAVE), heading_deg=heading)
    mid = int(np.argmin(np.abs(tf.x_m - girder.midship_x_m)))
    assert tf.x_m[mid] == pytest.approx(girder.midship_x_m, abs=1e-9)
    head_moment = abs(direct_midship_moment(girder, k, 180.0))
    assert head_moment == pytest.approx(
        abs(wave_transfer_functions(girder, loading, omega_of(SHIP_LENGTH_WAVE)).bending_moment_Nm_per_m[0, mid]), rel=1e-4
    )
    assert abs(tf.bending_moment_Nm_per_m[0, mid] - direct_midship_moment(girder, k, heading)) < 1e-4 * head_moment


def test_beam_seas_bend_a_box_not_at_all_and_the_base_hull_by_its_breadth_variation_only(base, barge):
    """Beam seas: the wave is uniform along the ship, ``F(x) zeta_a cos(omega t)``. A constant-breadth box
    heaves without bending; the base hull bends only because F varies with its breadth (0.90 on the
    42 m mid-body, to 1 at the stem for a 171 m wave): 2.9 % of the head-sea midship moment, 3.0 % of the
    head-sea deck deflection amidships."""
    girder, loading = barge
    head = wave_transfer_functions(girder, loading, omega_of(L), n_points=401)
    beam = wave_transfer_functions(girder, loading, omega_of(L), n_points=401, heading_deg=90.0)
    assert np.max(np.abs(beam.bending_moment_Nm_per_m)) < 1e-12 * np.max(np.abs(head.bending_moment_Nm_per_m))
    assert np.max(np.abs(beam.deflection_m_per_m)) < 1e-12 * np.max(np.abs(head.deflection_m_per_m))
    girder, loading, _ = base
    head = wave_transfer_functions(girder, loading, omega_of(SHIP_LENGTH_WAVE))
    beam = wave_transfer_functions(girder, loading, omega_of(SHIP_LENGTH_WAVE), heading_deg=90.0)
    mid = int(np.argmin(np.abs(head.x_m - girder.midship_x_m)))
    ratio = abs(beam.bending_moment_Nm_per_m[0, mid]) / abs(head.bending_moment_Nm_per_m[0, mid])
    assert 0.02 < ratio < 0.04
    assert 0.02 < abs(beam.deflection_m_per_m[0, mid]) / abs(head.deflection_m_per_m[0, mid]) < 0.04
    # in phase with the wave (no wave component along the ship): the imaginary part is round-off
    assert np.max(np.abs(beam.bending_moment_Nm_per_m.imag)) < 1e-9 * np.max(np.abs(beam.bending_moment_Nm_per_m))


def test_the_wave_moment_falls_monotonically_from_head_to_beam_seas_for_a_ship_length_wave(base, barge):
    """Ship-length wave: the largest moment amplitude along the hull and the midship one fall at every
    5 deg from 180 to 90 on the box (to zero), and from 180 to 100 on the base hull, whose beam-sea
    residual (its breadth variation) is reached near 95 deg."""
    headings = np.arange(180.0, 89.0, -5.0)
    for (girder, loading), wave_length, last in ((barge, L, 90.0), (base[:2], SHIP_LENGTH_WAVE, 100.0)):
        peak, mid = [], []
        for heading in headings[headings >= last]:
            tf = wave_transfer_functions(girder, loading, omega_of(wave_length), heading_deg=heading)
            m = tf.bending_moment_Nm_per_m[0]
            peak.append(np.max(np.abs(m)))
            mid.append(abs(m[np.argmin(np.abs(tf.x_m - girder.midship_x_m))]))
        assert np.all(np.diff(peak) < 0) and np.all(np.diff(mid) < 0)
    assert peak[-1] < 0.03 * peak[0]


def test_following_seas_are_head_seas_reversed_in_time_for_any_hull(base):
    """Quasi-static at zero speed: the wave at heading 180 - beta at time t is the wave at beta at time -t,
    so the response is the time reversal (conjugate harmonics); port and starboard (beta, 360 - beta) give
    the same vertical response. Exact for the asymmetric base hull and loading, emergence or not."""
    girder, loading, _ = base
    w = np.array([0.4, 0.6004, 0.9])
    scale = None
    for beta, reversed_, mirrored in ((180.0, 0.0, 180.0), (120.0, 60.0, 240.0), (150.0, 30.0, 210.0)):
        ref = wave_transfer_functions(girder, loading, w, heading_deg=beta)
        scale = scale or np.max(np.abs(ref.bending_moment_Nm_per_m))
        rev = wave_transfer_functions(girder, loading, w, heading_deg=reversed_)
        mir = wave_transfer_functions(girder, loading, w, heading_deg=mirrored)
        np.testing.assert_allclose(rev.bending_moment_Nm_per_m, np.conj(ref.bending_moment_Nm_per_m), rtol=0, atol=1e-11 * scale)
        np.testing.assert_allclose(mir.bending_moment_Nm_per_m, ref.bending_moment_Nm_per_m, rtol=0, atol=1e-11 * scale)
        np.testing.assert_allclose(rev.emergence_amplitude_m, ref.emergence_amplitude_m, rtol=1e-11)
    # a steep wave (sections emerge: the response is not linear) reverses step by step
    head = wave_response(girder, loading, SHIP_LENGTH_WAVE, 7.0)
    following = wave_response(girder, loading, SHIP_LENGTH_WAVE, 7.0, heading_deg=0.0)
    assert np.max(np.abs(head.bending_moment_harmonics_Nm[2])) > 1e-3 * np.max(np.abs(head.bending_moment_harmonics_Nm[1]))
    back = np.roll(head.bending_moment_Nm[::-1], 1, axis=0)  # step j of following seas = step (n - j) mod n of head seas
    np.testing.assert_allclose(following.bending_moment_Nm, back, rtol=0, atol=1e-9 * np.max(np.abs(head.bending_moment_Nm)))


def test_a_fore_aft_symmetric_box_in_following_seas_mirrors_its_head_sea_moment(barge):
    """Only for a hull and loading symmetric about midship: following seas = head seas on the mirrored
    hull, so ``M_following(x) = M_head(L - x)`` (and so ``M_head(L - x) = conj(M_head(x))``)."""
    girder, loading = barge
    w = omega_of(0.6 * L)
    head = wave_transfer_functions(girder, loading, w, n_points=401).bending_moment_Nm_per_m[0]
    following = wave_transfer_functions(girder, loading, w, n_points=401, heading_deg=0.0).bending_moment_Nm_per_m[0]
    assert np.abs(head.imag).max() > 0.1 * np.abs(head).max()  # a wave with a real phase pattern along the hull
    np.testing.assert_allclose(following, head[::-1], rtol=0, atol=1e-9 * np.abs(head).max())


def test_emergence_at_a_heading_is_the_first_point_of_the_waterline_to_reach_the_keel(base):
    """The emergence amplitude against the local draught sampled at 2001 points across every section's
    waterline: the wave ``exp(i k_x (x - L/2) - i k y sin beta)`` plus the ship's heave and pitch."""
    girder, loading, _ = base
    w = np.array([0.45, 0.6004, 1.1])
    for heading in (150.0, 120.0, 90.0):
        tf = wave_transfer_functions(girder, loading, w, heading_deg=heading)
        k = w**2 / G
        c, s = heading_cosines(heading)
        x = tf.x_m
        u = x - girder.midship_x_m
        breadth = girder.hull.breadth_at(x)
        eta = np.linspace(-0.5, 0.5, 2001)
        for i in range(w.size):
            factor = breadth_factor(k[i], breadth, heading)
            # the ship's heave and pitch from the breadth-mean wave (this hull's balance is linear)
            zeta = np.vstack([np.zeros(x.size), factor * np.cos(-k[i] * c * u), factor * np.sin(-k[i] * c * u)])
            wa, wb = weight_element_ends(girder, loading, x)
            sink, trim, *_ = hydrostatic_balance(girder, x, wa, wb, zeta)
            ship = (sink[1] - sink[0]) + 1j * (sink[2] - sink[0]) - ((trim[1] - trim[0]) + 1j * (trim[2] - trim[0])) * u
            local = np.exp(-1j * k[i] * (u[:, None] * c + breadth[:, None] * eta[None, :] * s)) + ship[:, None]
            draught = girder.hull.draft_m + sink[0] - trim[0] * u
            sampled = np.min(draught / np.max(np.abs(local), axis=1))
            assert tf.emergence_amplitude_m[i] == pytest.approx(sampled, rel=1e-6)
            assert tf.emergence_amplitude_m[i] <= sampled * (1 + 1e-12)


def test_max_local_draught_change_is_the_largest_modulus_over_the_interval():
    rng = np.random.default_rng(7)
    wave = rng.normal(size=50) + 1j * rng.normal(size=50)
    ship = rng.normal(size=50) + 1j * rng.normal(size=50)
    half = rng.uniform(0.0, 4.0, size=50)
    theta = np.linspace(-1.0, 1.0, 20001)[None, :] * half[:, None]
    brute = np.max(np.abs(wave[:, None] * np.exp(-1j * theta) + ship[:, None]), axis=1)
    exact = max_local_draught_change(wave, ship, half)
    assert np.all(exact >= brute * (1 - 1e-14))
    np.testing.assert_allclose(exact, brute, rtol=1e-7)


def test_the_transfer_functions_at_a_heading_are_the_first_harmonic_of_the_wave_response(base):
    girder, loading, _ = base
    tf = wave_transfer_functions(girder, loading, omega_of(120.0), heading_deg=135.0)
    amplitude = 0.5 * float(tf.emergence_amplitude_m[0])
    r = wave_response(girder, loading, 120.0, amplitude, heading_deg=135.0)
    scale = np.max(np.abs(tf.bending_moment_Nm_per_m[0]))
    np.testing.assert_allclose(r.bending_moment_harmonics_Nm[1] / amplitude, tf.bending_moment_Nm_per_m[0], rtol=0, atol=1e-9 * scale)
    np.testing.assert_allclose(
        r.deflection_harmonics_m[1] / amplitude, tf.deflection_m_per_m[0], rtol=0, atol=1e-9 * np.max(np.abs(tf.deflection_m_per_m[0]))
    )
    assert np.max(np.abs(r.bending_moment_harmonics_Nm[2])) < 1e-9 * np.max(np.abs(r.bending_moment_harmonics_Nm[1]))


def test_a_case_at_a_heading_gives_the_hull_girder_that_heading(base):
    """``wave.heading_deg`` reaches the regular-wave hull response (the excitation's one hull call); a heading
    outside [0, 360) is refused naming the key."""
    from seafast.config import CaseError, load_case
    from seafast.excitation.vessel import vessel_excitation

    girder, loading, _ = base
    wave = vessel_excitation(load_case(overrides={"vessel.motions": "none", "wave.heading_deg": 120.0})).wave
    assert wave.heading_deg == 120.0
    direct = wave_response(girder, loading, SHIP_LENGTH_WAVE, 3.0, heading_deg=120.0)
    np.testing.assert_allclose(
        wave.bending_moment_Nm, direct.bending_moment_Nm, rtol=0, atol=1e-9 * np.max(np.abs(direct.bending_moment_Nm))
    )
    for bad in (360.0, -1.0):
        with pytest.raises(CaseError, match="heading_deg"):
            load_case(overrides={"wave.heading_deg": bad})
