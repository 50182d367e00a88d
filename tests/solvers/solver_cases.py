"""Shared test cases for the solver tests: the base model and a realistic excitation.

Until the vessel module supplies the real deck motion, the excitation is built here:

* static (k = 0): the deck under the middle saddle raised by 5.75 mm (reproduces the source's
  static result: middle saddle ~6.3 MN, M_b ~49 MNm);
* wave (omega = 0.6 rad/s): a hog/sag deck shape, parabolic about the cargo middle, with a
  first and a second harmonic (sag deeper than hog) and a rigid deck rotation in quadrature,
  theta = dz/dx consistently;
* rigid-body inertia: heave and pitch of the vessel, ``cargo_load_N[1] = -M a_rb`` with
  ``a_rb = -omega^2 (heave + pitch (x - x_ref))`` on z and ``-omega^2 pitch`` on theta.
"""

from __future__ import annotations

import numpy as np

from seafast.excitation.harmonic import HarmonicExcitation
from seafast.model.beam import bending_moment_line
from seafast.model.seafastening import SeaFastening
from seafast.model.sections import CargoGeometry, TubeSegment
from seafast.model.structure import StructuralModel, build_structural_model


def base_model(element_length_m: float = 1.0, stiffness_scale: float = 1.0) -> StructuralModel:
    geometry = CargoGeometry((TubeSegment(0, 74, 8, 8, 0.08),))
    sf = SeaFastening(np.array([14.8, 37, 59.2]), np.full(3, 1.1e9 * stiffness_scale), np.array([True, False, True]))
    return build_structural_model(geometry, sf, target_element_length_m=element_length_m)


def deck_shape(model: StructuralModel, relative_m: float, antisymmetric_m: float, static_mid_m: float = 0.0):
    """Deck z and theta amplitudes under the saddles (complex), and a static part."""
    x = model.saddle_x_m
    xc = 0.5 * (model.cargo.node_x_m[0] + model.cargo.node_x_m[-1])
    half = 0.5 * (x[-1] - x[0]) if x.size > 1 else 1.0
    s = (x - xc) / half
    z = relative_m * (1.0 - s**2) + 1j * antisymmetric_m * s
    th = relative_m * (-2.0 * s / half) + 1j * antisymmetric_m / half
    dyn = np.zeros(model.deck_dof_count, dtype=complex)
    dyn[0::2] = z
    dyn[1::2] = th
    st = np.zeros(model.deck_dof_count, dtype=complex)
    if static_mid_m:
        st[2 * int(np.argmin(np.abs(x - xc)))] = static_mid_m
    return st, dyn


def wave_excitation(
    model: StructuralModel,
    omega_rad_s: float = 0.6,
    relative_mm: float = 12.0,
    second_harmonic_mm: float = -3.0,
    antisymmetric_mm: float = 2.0,
    heave_m: float = 1.5,
    pitch_rad: float = 0.0175,
    static_mid_mm: float = 5.75,
) -> HarmonicExcitation:
    """Static deck offset + wave hog/sag (k = 1, 2) + rigid-body inertia (k = 1).

    The relative deck motion at the middle saddle is ``relative_mm cos(wt) +
    second_harmonic_mm cos(2wt)`` (positive = hog, middle up): with the defaults the sag
    (-15 mm) is deeper than the hog (+9 mm), as in real ships, so the middle saddle lifts off
    in the sag (the cargo then rests on the two outer saddles) while the outer saddles stay
    loaded in the hog. ``antisymmetric_mm`` adds a rigid deck rotation in quadrature.
    """
    n_c, n_o, n_e = model.cargo_dof_count, model.deck_dof_count, model.cargo.element_count
    st, dyn1 = deck_shape(model, relative_mm * 1e-3, antisymmetric_mm * 1e-3, static_mid_mm * 1e-3)
    _, dyn2 = deck_shape(model, second_harmonic_mm * 1e-3, 0.0)
    xo = np.zeros((3, n_o), dtype=complex)
    xo[0], xo[1], xo[2] = st, dyn1, dyn2
    # rigid-body motion of the vessel (pitch in quadrature with heave), inertia load -M a_rb
    x = model.cargo.node_x_m
    x_ref = 0.5 * (x[0] + x[-1])
    u_rb = np.zeros(n_c, dtype=complex)
    u_rb[0::2] = heave_m + 1j * pitch_rad * (x - x_ref)
    u_rb[1::2] = 1j * pitch_rad
    a_rb = -(omega_rad_s**2) * u_rb
    load = np.zeros((3, n_c), dtype=complex)
    line = np.zeros((3, n_e), dtype=complex)
    load[1] = -model.cargo.mass @ a_rb
    xm = model.cargo.element_mid_x_m
    a_mid = -(omega_rad_s**2) * (heave_m + 1j * pitch_rad * (xm - x_ref))
    line[1] = -model.cargo.element_mass_per_length_kg_per_m * a_mid
    return HarmonicExcitation(omega_rad_s, xo, load, line, source="test: parabolic hog/sag (k=1,2) + heave/pitch inertia")


def uniform_heave(model: StructuralModel, amplitude_m: float):
    """``omega -> excitation``: the deck under every saddle moving up and down together (excites the cargo's bounce mode)."""

    def at(omega: float) -> HarmonicExcitation:
        deck = np.zeros((2, model.deck_dof_count), complex)
        deck[1, 0::2] = amplitude_m
        return HarmonicExcitation(
            omega,
            deck,
            np.zeros((2, model.cargo_dof_count), complex),
            np.zeros((2, model.cargo.element_count), complex),
            "uniform deck heave",
        )

    return at


def static_excitation(model: StructuralModel) -> HarmonicExcitation:
    return wave_excitation(model).static_part()


def moments(model: StructuralModel, response) -> np.ndarray:
    """Bending-moment lines [N m] over the period of a periodic response (self-weight included)."""
    _, m = bending_moment_line(
        model.cargo.node_x_m,
        response.cargo_displacement_time_m,
        model.cargo.element_bending_stiffness_Nm2,
        load_N_per_m=model.cargo.gravity_line_load_N_per_m,
    )
    return m


def peak_moment(model: StructuralModel, response) -> float:
    """Largest |bending moment| over the cargo and the period [N m]."""
    return float(np.max(np.abs(moments(model, response))))
