"""Tests of the hull girder's wave-torsion estimate (seafast.hull.torsion): the box section's roll moment against
quadrature and its long-wave limit, the load's self-equilibrium, and the twist of a free-free girder with and
without warping against closed forms."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import quad

from seafast.hull.torsion import TorsionSection, box_section_roll_moment_per_m, girder_twist, wave_torsion_load
from seafast.vessel.loading import base_hull_form, base_vessel_loading, mass_distribution_kg_per_m

RHO_G = 1025.0 * 9.81


@pytest.mark.parametrize(("wave_length", "heading"), [(60.0, 120.0), (171.0, 90.0), (300.0, 150.0), (1.0e6, 95.0), (40.0, 250.0)])
def test_the_box_section_roll_moment_is_the_pressure_integral(wave_length, heading):
    """Bottom: ``rho g int y exp(-i kappa y) dy``; sides: the pressures at ``y = -/+ B/2`` over the draught, acting
    at mid-draught, about an axis 9 m below the waterline (``M_x = y F_z - (z - z_axis) F_y``); by ``quad``."""
    k, breadth, draft, below = 2.0 * np.pi / wave_length, 42.0, 6.5, 9.0
    kappa = k * np.sin(np.deg2rad(heading))
    b = 0.5 * breadth
    bottom = [
        quad(lambda y, part=part: part(RHO_G * y * np.exp(-1j * kappa * y)), -b, b, epsabs=1e-3, epsrel=1e-12, limit=200)[0]
        for part in (np.real, np.imag)
    ]
    sway = draft * RHO_G * (np.exp(1j * kappa * b) - np.exp(-1j * kappa * b))  # starboard pushes +y, port -y
    expected = complex(*bottom) - (-0.5 * draft + below) * sway
    got = complex(box_section_roll_moment_per_m(k, np.array([breadth]), draft, heading, below, RHO_G)[0])
    assert abs(got - expected) <= 1e-9 * max(abs(expected), RHO_G * kappa * breadth**3 / 12 * 1e-3)


def test_a_long_oblique_wave_heels_a_section_by_its_transverse_slope_times_the_waterplane_inertia():
    """``kappa B^3 / 12`` (the series branch below kappa b = 1e-3 and the closed form above it agree)."""
    breadth, draft = 42.0, 6.5
    for k in (1e-6, 4.7e-5, 4.8e-5, 1e-3):
        bottom_only = box_section_roll_moment_per_m(k, np.array([breadth]), draft, 90.0, 0.5 * draft, RHO_G)[0]
        assert bottom_only.real == 0.0
        assert -bottom_only.imag == pytest.approx(RHO_G * k * breadth**3 / 12 * (1 - (0.5 * k * breadth) ** 2 / 10), rel=1e-9)


def test_the_torsional_load_is_self_equilibrated_and_vanishes_in_head_seas():
    hull = base_hull_form()
    x = np.linspace(0.0, hull.length_m, 1711)
    mass = mass_distribution_kg_per_m(x, base_vessel_loading())
    section = TorsionSection(9.5, 1.0e4, -3.6)
    load = wave_torsion_load(hull, x, mass, 2 * np.pi / 60.0, 115.0, section, 8.0)
    scale = np.max(np.abs(load)) * hull.length_m
    assert abs(np.trapezoid(load, x)) < 1e-12 * scale
    assert np.max(np.abs(load)) > 1e5  # a real load: N m/m per metre of wave
    for heading in (180.0, 0.0):
        assert np.max(np.abs(wave_torsion_load(hull, x, mass, 2 * np.pi / 60.0, heading, section, 8.0))) == 0.0


def test_the_twist_of_a_free_free_girder_matches_the_closed_forms():
    """Load ``m = T0 (pi/L) cos(pi x/L)``, torque ``T0 sin(pi x/L)``. St Venant: ``phi = T0 L (1 - cos(pi x/L)) / (pi G J)``.
    Warping: ``theta = T0 sin(pi x/L) / D + C cosh(mu (x - L/2))``, ``D = G J + E I_w pi^2/L^2``, ``mu^2 = G J/(E I_w)``,
    ``C`` from ``theta'(0) = 0``; the twist is its integral. Second-order differences on 2001 nodes."""
    length, t0 = 171.0, 1.0e8
    x = np.linspace(0.0, length, 2001)
    load = t0 * np.pi / length * np.cos(np.pi * x / length)
    venant = TorsionSection(9.5)
    torque, phi = girder_twist(x, load, venant)
    np.testing.assert_allclose(torque, t0 * np.sin(np.pi * x / length), rtol=0, atol=1e-6 * t0)
    exact = t0 * length * (1 - np.cos(np.pi * x / length)) / (np.pi * venant.torsional_stiffness_Nm2)
    np.testing.assert_allclose(phi, exact, rtol=0, atol=1e-6 * np.max(exact))
    warped = TorsionSection(9.5, 1.0e4)
    gj, eiw = warped.torsional_stiffness_Nm2, warped.warping_stiffness_Nm4
    mu, d = np.sqrt(gj / eiw), gj + eiw * np.pi**2 / length**2
    c = (t0 * np.pi / (length * d)) / (mu * np.sinh(mu * length / 2))
    exact = t0 * length * (1 - np.cos(np.pi * x / length)) / (np.pi * d) + c / mu * (
        np.sinh(mu * (x - length / 2)) + np.sinh(mu * length / 2)
    )
    _, phi = girder_twist(x, load, warped)
    np.testing.assert_allclose(phi, exact, rtol=0, atol=1e-5 * np.max(np.abs(exact)))
    venant_phi = t0 * length * (1 - np.cos(np.pi * x / length)) / (np.pi * gj)
    assert np.max(np.abs(exact - venant_phi)) > 0.02 * np.max(exact)  # the warping restraint matters here


def test_bad_sections_and_grids_are_refused():
    with pytest.raises(ValueError, match=r"torsion_constant_m4 = 0\.0 must be > 0"):
        TorsionSection(0.0)
    with pytest.raises(ValueError, match="uniform grid"):
        girder_twist(np.array([0.0, 1.0, 3.0]), np.zeros(3), TorsionSection(1.0))
