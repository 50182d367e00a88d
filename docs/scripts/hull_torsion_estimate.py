"""The torsion estimate of docs/oblique.md (section 5): the hull girder's wave torsion at the saddles' deck points.

Base vessel (L 171 m, B 42 m, T 6.5 m, depth assumed 12 m), regular oblique waves of amplitude 3 m. For each
wave length and heading: the net torsional load per metre and the twist of the free-free girder
(seafast.hull.torsion), and the relative vertical deck displacement across the cargo's three saddles of the
outermost pile, at y = 16.5 m: ``y (phi(x_mid) - (phi(x_aft) + phi(x_fore)) / 2)`` (a twist linear in x moves
the pile's saddles in a straight line, which does not load it), against the same deck rise from the vertical
bending (seafast.hull.transfer) in the same wave.

Run from the repository root: ``python docs/scripts/hull_torsion_estimate.py``.
"""

import numpy as np

from seafast.hull.girder import HullGirder
from seafast.hull.torsion import TorsionSection, girder_twist, wave_torsion_load
from seafast.hull.transfer import wave_transfer_functions
from seafast.vessel.loading import base_hull_form, base_vessel_loading, mass_distribution_kg_per_m

G = 9.81
AMPLITUDE_M, KG_M, Y_PILE_M = 3.0, 8.0, 16.5
HULL = base_hull_form()
GIRDER = HullGirder(HULL)
LOADING = base_vessel_loading()
X = np.linspace(0.0, HULL.length_m, 1711)
MASS = mass_distribution_kg_per_m(X, LOADING)
SADDLES = 0.5 * HULL.length_m - 37.0 + np.array([14.8, 37.0, 59.2])
SECTIONS = {
    "closed deck (Bredt J = 199 m4)": TorsionSection(199.0, 0.0, 6.0),
    "open deck, warping (J = 9.5 m4, I_w = 1.0e4 m6)": TorsionSection(9.5, 1.0e4, -3.6),
    "open deck, stiffer warping (J = 9.5 m4, I_w = 1.0e5 m6)": TorsionSection(9.5, 1.0e5, -3.6),
    "open deck, St Venant only (J = 9.5 m4)": TorsionSection(9.5, 0.0, -3.6),
}
LENGTHS = (45.0, 50.0, 60.0, 80.0, 100.0, 120.0, 140.0, 171.0, 200.0, 250.0, 300.0)
HEADINGS = range(90, 181, 5)


def rise(f: np.ndarray, x: np.ndarray = X) -> complex:
    """Middle saddle minus the mean of the outer two, of a complex line along the ship."""
    v = np.interp(SADDLES, x, f.real) + 1j * np.interp(SADDLES, x, f.imag)
    return complex(v[1] - 0.5 * (v[0] + v[2]))


def bending_rise_m(wave_length_m: float, heading_deg: float) -> float:
    omega = np.array([np.sqrt(2 * np.pi * G / wave_length_m)])
    tf = wave_transfer_functions(GIRDER, LOADING, omega, heading_deg=heading_deg)
    return AMPLITUDE_M * abs(rise(tf.deflection_m_per_m[0], tf.x_m))


def torsion(wave_length_m: float, heading_deg: float, section: TorsionSection) -> tuple[float, float, float]:
    """(torsional deck rise [m], largest torque [N m], largest twist from midship [rad]) for the wave."""
    load = AMPLITUDE_M * wave_torsion_load(HULL, X, MASS, 2 * np.pi / wave_length_m, heading_deg, section, KG_M)
    torque, phi = girder_twist(X, load, section)
    mid = np.interp(0.5 * HULL.length_m, X, phi.real) + 1j * np.interp(0.5 * HULL.length_m, X, phi.imag)
    return abs(Y_PILE_M * rise(phi)), float(np.max(np.abs(torque))), float(np.max(np.abs(phi - mid)))


def main() -> None:
    worst = max((bending_rise_m(lam, beta), lam, beta) for lam in LENGTHS for beta in HEADINGS)
    print(f"vertical bending: worst deck rise at the saddles {worst[0] * 1e3:.2f} mm (lambda {worst[1]:g} m, {worst[2]} deg)")  # noqa: T201
    for name, section in SECTIONS.items():
        r, lam, beta = max((torsion(lam, beta, section)[0], lam, beta) for lam in LENGTHS for beta in HEADINGS)
        _, torque, twist = torsion(lam, beta, section)
        print(  # noqa: T201
            f"{name}: worst lambda {lam:g} m at {beta} deg: torque {torque:.3g} N m, twist {np.rad2deg(twist):.2g} deg from midship; "
            f"torsional deck rise {r * 1e3:.2f} mm, vertical bending's in the same wave {bending_rise_m(lam, beta) * 1e3:.2f} mm"
        )


if __name__ == "__main__":
    main()
