"""Assembly of the cargo excitation: deck deflection under the saddles and rigid-body inertia.

Convention under test (deck_motion.py): displacements relative to the vessel's rigid-body frame;
rigid-body acceleration a_rb(x) = -omega^2 (heave + pitch (x - x_ref)) (complex amplitudes,
x(t) = Re(X e^{i omega t})), acting on the cargo as the inertial load -M a_rb. A positive real
heave amplitude H is the vessel at its highest point at t = 0, accelerating downward, so the
cargo is loaded *upward* by +omega^2 H m.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from seafast.excitation.deck_motion import RigidBodyAmplitudes, assemble_excitation
from seafast.excitation.deck_table import read_deck_deflection_table
from seafast.model.seafastening import SeaFastening
from seafast.model.sections import CargoGeometry, TubeSegment
from seafast.model.structure import StructuralModel, build_structural_model
from seafast.solvers.linear import solve_linear

LM = 74.0
AFT = 48.5  # ship x of the cargo's aft end (cargo midship on a 171 m ship)
OMEGA = 0.6004


@pytest.fixture(scope="module")
def model() -> StructuralModel:
    geom = CargoGeometry((TubeSegment(0.0, 30.0, 8.0, 8.0, 0.08), TubeSegment(30.0, LM, 8.0, 7.0, 0.07)))
    sf = SeaFastening(np.array([14.8, 37.0, 59.2]), np.full(3, 1.1e9), np.array([True, False, True]))
    return build_structural_model(geom, sf, target_element_length_m=2.0)


def _line_integrals(model: StructuralModel, line: np.ndarray, x_ref_ship: float) -> tuple[complex, complex]:
    """Total force and moment about x_ref of a per-element uniform line load (exact for uniform)."""
    x = AFT + model.cargo.node_x_m
    dx = np.diff(x)
    xm = 0.5 * (x[1:] + x[:-1])
    return complex(np.sum(line * dx)), complex(np.sum(line * dx * (xm - x_ref_ship)))


def _nodal_resultants(model: StructuralModel, load: np.ndarray, x_ref_ship: float) -> tuple[complex, complex]:
    x = AFT + model.cargo.node_x_m
    return complex(load[0::2].sum()), complex(load[0::2] @ (x - x_ref_ship) + load[1::2].sum())


def _mass_moments(model: StructuralModel, x_ref_ship: float) -> tuple[float, float, float]:
    """int m dx, int m (x - x_ref) dx, int m (x - x_ref)^2 dx over the FE mass distribution."""
    x = AFT + model.cargo.node_x_m
    m = model.cargo.element_mass_per_length_kg_per_m
    a, b = x[:-1] - x_ref_ship, x[1:] - x_ref_ship
    return float(np.sum(m * (b - a))), float(np.sum(m * (b**2 - a**2) / 2)), float(np.sum(m * (b**3 - a**3) / 3))


def test_pure_heave_gives_total_load_omega2_H_m(model: StructuralModel) -> None:
    H = 1.7
    exc = assemble_excitation(model, AFT, OMEGA, None, None, RigidBodyAmplitudes(H, 0.0, 85.5))
    assert exc.harmonic_count == 2 and exc.omega_rad_s == OMEGA
    mass = model.cargo.mass_kg
    m0, m1, _ = _mass_moments(model, 85.5)
    assert m0 == pytest.approx(mass, rel=1e-12)
    F, Mom = _nodal_resultants(model, exc.cargo_load_N[1], 85.5)
    assert F.real == pytest.approx(+(OMEGA**2) * H * mass, rel=1e-12)  # upward
    assert F.imag == 0.0
    assert Mom.real == pytest.approx(OMEGA**2 * H * m1, rel=1e-10)
    # the line load (for moment lines) carries the same resultants
    Fl, Ml = _line_integrals(model, exc.cargo_line_load_N_per_m[1], 85.5)
    assert Fl.real == pytest.approx(OMEGA**2 * H * mass, rel=1e-12)
    assert Ml.real == pytest.approx(OMEGA**2 * H * m1, rel=1e-10)
    # the static row has no vessel-induced load; no deck motion given
    assert not np.any(exc.cargo_load_N[0]) and not np.any(exc.cargo_line_load_N_per_m[0])
    assert not np.any(exc.deck_displacement)


def test_heave_phase_is_carried(model: StructuralModel) -> None:
    H = 1.2 * np.exp(0.7j)
    exc = assemble_excitation(model, AFT, OMEGA, None, None, RigidBodyAmplitudes(H, 0.0, 85.5))
    F, _ = _nodal_resultants(model, exc.cargo_load_N[1], 85.5)
    assert F == pytest.approx(OMEGA**2 * H * model.cargo.mass_kg, rel=1e-12)


def test_pitch_gives_force_and_moment_about_reference(model: StructuralModel) -> None:
    P, x_ref = 0.02, 80.0  # bow up
    exc = assemble_excitation(model, AFT, OMEGA, None, None, RigidBodyAmplitudes(0.0, P, x_ref))
    _, m1, m2 = _mass_moments(model, x_ref)
    F, Mom = _nodal_resultants(model, exc.cargo_load_N[1], x_ref)
    # -M a: a = -omega^2 P (x - x_ref), so force +omega^2 P int m (x - x_ref)
    assert F.real == pytest.approx(OMEGA**2 * P * m1, rel=1e-10)
    assert Mom.real == pytest.approx(OMEGA**2 * P * m2, rel=1e-10)
    Fl, Ml = _line_integrals(model, exc.cargo_line_load_N_per_m[1], x_ref)
    assert Fl.real == pytest.approx(OMEGA**2 * P * m1, rel=1e-10)
    # the element line load is the midpoint value: its moment misses the int m (x-xm)^2 term only
    assert Ml.real == pytest.approx(OMEGA**2 * P * m2, rel=1e-3)
    # at t = 0 the aft end is at its lowest (z = P (x - x_ref) < 0) and accelerates upward, so its
    # inertia load is downward; the bow end the opposite
    assert exc.cargo_load_N[1, 0].real < 0 and exc.cargo_load_N[1, -2].real > 0


def test_heave_plus_pitch_superpose(model: StructuralModel) -> None:
    rb = RigidBodyAmplitudes(1.5, 0.0175j, 85.5)
    both = assemble_excitation(model, AFT, OMEGA, None, None, rb).cargo_load_N[1]
    h = assemble_excitation(model, AFT, OMEGA, None, None, RigidBodyAmplitudes(1.5, 0.0, 85.5)).cargo_load_N[1]
    p = assemble_excitation(model, AFT, OMEGA, None, None, RigidBodyAmplitudes(0.0, 0.0175j, 85.5)).cargo_load_N[1]
    np.testing.assert_allclose(both, h + p, rtol=1e-12, atol=1e-9)
    # the consistent load equals -M a for the rigid-body acceleration field
    x = AFT + model.cargo.node_x_m
    a = np.zeros(model.cargo_dof_count, dtype=complex)
    a[0::2] = -(OMEGA**2) * (1.5 + 0.0175j * (x - 85.5))
    a[1::2] = -(OMEGA**2) * 0.0175j
    np.testing.assert_allclose(both, -model.cargo.mass @ a, rtol=1e-12, atol=1e-9)


def test_deck_rows_take_deflection_at_ship_positions_of_the_saddles(model: StructuralModel) -> None:
    seen = {}

    def still(xs):
        seen["still"] = np.array(xs)
        return 1e-3 * np.sin(xs / 50), 1e-3 / 50 * np.cos(xs / 50)

    def wave(xs):
        seen["wave"] = np.array(xs)
        return 2e-3j * xs / 100, 2e-3j / 100 * np.ones_like(xs)

    exc = assemble_excitation(model, AFT, OMEGA, still, wave, None, source="unit")
    xs = AFT + np.array([14.8, 37.0, 59.2])
    np.testing.assert_allclose(seen["still"], xs, rtol=1e-12)
    np.testing.assert_allclose(seen["wave"], xs, rtol=1e-12)
    deck = exc.deck_displacement
    assert deck.shape == (2, model.deck_dof_count)
    np.testing.assert_allclose(deck[0, model.saddle_deck_dof], 1e-3 * np.sin(xs / 50), rtol=1e-12)
    np.testing.assert_allclose(deck[0, model.saddle_deck_dof + 1], 1e-3 / 50 * np.cos(xs / 50), rtol=1e-12)
    np.testing.assert_allclose(deck[1, model.saddle_deck_dof], 2e-3j * xs / 100, rtol=1e-12)
    np.testing.assert_allclose(deck[1, model.saddle_deck_dof + 1], 2e-3j / 100, rtol=1e-12)
    assert exc.source == "unit"
    assert not np.any(exc.cargo_load_N)


def test_deck_table_feeds_the_excitation(model: StructuralModel, tmp_path: Path) -> None:
    x = np.linspace(0.0, 171.0, 19)
    z = 1e-3 * (0.5 + 0.02 * x - 3e-4 * x**2 + 2e-6 * x**3)
    lines = ["x_m,still_water_m,wave_amplitude_m,wave_phase_rad"] + [
        f"{a!r},{b!r},0.004,1.0" for a, b in zip(map(float, x), map(float, z), strict=True)
    ]
    p = tmp_path / "deck.csv"
    p.write_text("\n".join(lines) + "\n")
    tab = read_deck_deflection_table(p)
    exc = assemble_excitation(model, AFT, OMEGA, tab.still_water_at, tab.wave_at, None, source=tab.source)
    xs = AFT + model.saddle_x_m
    np.testing.assert_allclose(exc.deck_displacement[0, 0::2].real, 1e-3 * (0.5 + 0.02 * xs - 3e-4 * xs**2 + 2e-6 * xs**3), rtol=1e-10)
    np.testing.assert_allclose(exc.deck_displacement[0, 1::2].real, 1e-3 * (0.02 - 6e-4 * xs + 6e-6 * xs**2), rtol=1e-9)
    np.testing.assert_allclose(exc.deck_displacement[1, 0::2], 0.004 * np.exp(1j), rtol=1e-12)


def test_heave_inertia_is_carried_by_the_saddles(model: StructuralModel) -> None:
    """Quasi-static: far below the cargo's resonance the saddles carry omega^2 H m."""
    H = 2.0
    exc = assemble_excitation(model, AFT, OMEGA, None, None, RigidBodyAmplitudes(H, 0.0, 85.5))
    resp = solve_linear(model, exc)
    kz = model.seafastening.lashing_vertical_stiffness_N_per_m
    spring = resp.saddle_force_N[1] + kz * resp.saddle_compression_m[1]
    # the cargo is pushed up relative to the deck -> saddles unload: force amplitude is -omega^2 H m
    # (a downward-accelerating deck carries the cargo with less force)
    assert spring.sum().real == pytest.approx(-(OMEGA**2) * H * model.cargo.mass_kg, rel=1e-3)
