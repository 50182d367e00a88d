"""The axial load on the cargo: every sign and factor against a hand calculation."""

from __future__ import annotations

import numpy as np
import pytest

from seafast.config import load_case
from seafast.excitation.axial import axial_load, cargo_axis_height_m
from seafast.excitation.deck_motion import RigidBodyAmplitudes

M, W, G = 1.0e6, 0.6, 9.81


def _rb(surge=0j, pitch=0j, z_ref=8.0):
    return RigidBodyAmplitudes(0.1 + 0j, pitch, 85.0, surge_m=surge, reference_z_m=z_ref)


def test_surge_inertia_hand_calculation():
    # surge 0.5 m forward at t = 0: the deck accelerates aft (-w^2 0.5 m/s^2), the cargo is pushed forward
    f = axial_load(M, W, _rb(surge=0.5 + 0j), axis_height_above_keel_m=8.0, gravity_m_per_s2=G)
    assert f.force_N[1] == pytest.approx(M * W**2 * 0.5)  # +180 kN
    assert f.force_N[0] == 0.0


def test_pitch_gravity_and_inertia_hand_calculation():
    # bow up 0.01 rad at t = 0: gravity along the tilted deck pushes the cargo aft, -m g theta = -98.1 kN;
    # the axis 9 m above the pitch reference moves aft by 9 theta, accelerates forward by w^2 9 theta,
    # so the inertia pushes it aft: -m w^2 h theta = -32.4 kN
    f = axial_load(M, W, _rb(pitch=0.01 + 0j), axis_height_above_keel_m=17.0, gravity_m_per_s2=G)
    assert f.gravity_N == pytest.approx(-M * G * 0.01)
    assert f.pitch_inertia_N == pytest.approx(-M * W**2 * 9.0 * 0.01)
    assert f.force_N[1] == pytest.approx(-98100.0 - 32400.0)
    assert f.lever_m == 9.0
    # a quarter period later (phase -90 deg) the same loads, rotated: linearity in the amplitudes
    g = axial_load(M, W, _rb(pitch=-0.01j), axis_height_above_keel_m=17.0, gravity_m_per_s2=G)
    assert g.force_N[1] == pytest.approx(-1j * f.force_N[1])


def test_no_surge_is_refused_and_no_motion_is_no_load():
    with pytest.raises(ValueError, match="surge"):
        axial_load(M, W, RigidBodyAmplitudes(0.1 + 0j, 0.01 + 0j, 85.0), 17.0)
    none = axial_load(M, W, None, 17.0)
    assert not np.any(none.force_N) and "no rigid-body motion" in none.source


def test_axis_height_from_the_case():
    case = load_case(None)
    assert cargo_axis_height_m(case) == pytest.approx(12.0 + 1.0 + 4.0)
    tall = load_case(None, {"vessel.deck_height_m": 14.0, "seafastening.saddle_height_m": 2.0})
    assert cargo_axis_height_m(tall) == pytest.approx(20.0)


def test_axial_load_uses_the_coupled_pitch():
    """Surge and pitch of one solution: the coupled pitch, not the 2-DOF one the vertical analysis may use."""
    rb = RigidBodyAmplitudes(0.1 + 0j, 0.02 + 0j, 85.0, surge_m=0.0j, reference_z_m=8.0, coupled_pitch_rad=0.01 + 0j)
    f = axial_load(M, W, rb, axis_height_above_keel_m=17.0, gravity_m_per_s2=G)
    assert f.gravity_N == pytest.approx(-M * G * 0.01)
