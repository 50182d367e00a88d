"""Order-of-magnitude estimate of the hull girder's wave torsion at the saddles' deck points (docs/theory.md, section 3.5).

Not part of seafast: a hand calculation written out, for the base vessel (L 171 m, B 42 m, T 6.5 m, depth
assumed 12 m) in regular oblique waves of amplitude 3 m. For each wave length and heading:

1. the wave's roll moment per metre about the shear centre of box sections of the hull's waterline breadth
   B(x) and draught T, from the hydrostatic wave pressure ``rho g zeta(x, y)`` (uniform in depth, no Smith
   effect, as the vertical model): bottom pressure times y, side pressures times their height above the
   shear centre;
2. the ship's rigid-body reaction: the wave's total sway force carried by sway inertia distributed like the
   mass per metre and acting at the centre of gravity (8 m above the keel), and the remaining total roll
   moment by roll restoring and inertia distributed like B(x)^3 (quasi-static: no roll resonance);
3. the torque T(x) (the integral of the net moment, zero at both ends) and the twist phi(x) of a free-free
   thin-walled girder with warping, ``G J phi' - E I_w phi''' = T``, ``phi'' = 0`` at the ends (free warping);
4. the relative vertical deck displacement across the cargo's three saddles of the outermost pile, at
   y = 16.5 m from the centreline: ``y (phi(x_mid) - (phi(x_aft) + phi(x_fore)) / 2)`` (a twist linear in x
   moves the pile's saddles in a straight line, which does not load it), against the same deck rise from the
   vertical bending (seafast.hull.transfer) in the same wave.

Run from the repository root: ``python docs/scripts/hull_torsion_estimate.py``.
"""

import numpy as np
from scipy.linalg import solve_banded

from seafast.hull.girder import HullGirder
from seafast.hull.transfer import wave_transfer_functions
from seafast.vessel.loading import base_hull_form, base_vessel_loading, weight_distribution_N_per_m

RHO, G, E = 1025.0, 9.81, 210e9
SHEAR_MODULUS = E / 2.6
AMPLITUDE, DEPTH, KG, Y_PILE = 3.0, 12.0, 8.0, 16.5
hull = base_hull_form()
girder = HullGirder(hull)
loading = base_vessel_loading()
L, T = hull.length_m, hull.draft_m
XM = 0.5 * L
X = np.linspace(0.0, L, 1711)
BREADTH = hull.breadth_at(X)
MASS = weight_distribution_N_per_m(X, loading, G) / G
SADDLES = XM - 37.0 + np.array([14.8, 37.0, 59.2])
ETA, WEIGHTS = np.polynomial.legendre.leggauss(40)

# (G J [N m^2], E I_w [N m^4], shear centre height above the keel [m])
SECTIONS = {
    "closed deck (Bredt J = 199 m4)": (SHEAR_MODULUS * 199.0, 0.0, 6.0),
    "open deck, warping (J = 9.5 m4, I_w = 1.0e4 m6)": (SHEAR_MODULUS * 9.5, E * 1.0e4, -3.6),
    "open deck, stiffer warping (J = 9.5 m4, I_w = 1.0e5 m6)": (SHEAR_MODULUS * 9.5, E * 1.0e5, -3.6),
    "open deck, St Venant only (J = 9.5 m4)": (SHEAR_MODULUS * 9.5, 0.0, -3.6),
}


def net_moment(k: float, beta_deg: float, shear_centre_m: float) -> np.ndarray:
    """Net torsional load per metre [N m/m], complex, about the shear centre, for a wave of amplitude AMPLITUDE."""
    c, s = np.cos(np.deg2rad(beta_deg)), np.sin(np.deg2rad(beta_deg))
    b = 0.5 * BREADTH[:, None]
    along = np.exp(-1j * k * (X - XM) * c)
    p_bottom = RHO * G * AMPLITUDE * along[:, None] * np.exp(-1j * k * b * ETA * s)
    m_bottom = b[:, 0] * np.sum(WEIGHTS * b * ETA * p_bottom, axis=1)  # upward force p dy at y: moment y dF_z
    sway = RHO * G * AMPLITUDE * T * along * (np.exp(1j * k * b[:, 0] * s) - np.exp(-1j * k * b[:, 0] * s))
    zs = shear_centre_m - T  # from the waterline
    moment = m_bottom - (-0.5 * T - zs) * sway  # M_x = y F_z - (z - z_s) F_y, sides at mid-draught
    inertia = -MASS * np.trapezoid(sway, X) / np.trapezoid(MASS, X)  # sway inertia, at the centre of gravity
    moment = moment - (KG - T - zs) * inertia
    roll = BREADTH**3
    return moment - roll * np.trapezoid(moment, X) / np.trapezoid(roll, X)


def twist(moment: np.ndarray, gj: float, eiw: float) -> tuple[np.ndarray, np.ndarray]:
    """Torque T(x) [N m] and twist phi(x) [rad] (up to a constant) of the free-free girder."""
    h = X[1] - X[0]
    torque = np.concatenate([[0.0], np.cumsum(0.5 * h * (moment[1:] + moment[:-1]))])
    if eiw == 0.0:
        rate = torque / gj
    else:  # G J theta - E I_w theta'' = T, theta' = 0 at both ends (ghost nodes)
        n = X.size
        band = np.zeros((3, n))
        band[0, 1:] = band[2, :-1] = -eiw / h**2
        band[1] = gj + 2.0 * eiw / h**2
        band[0, 1] = band[2, -2] = -2.0 * eiw / h**2
        rate = solve_banded((1, 1), band, torque.astype(complex))
    return torque, np.concatenate([[0.0], np.cumsum(0.5 * h * (rate[1:] + rate[:-1]))])


def rise(f: np.ndarray, x: np.ndarray = X) -> complex:
    v = np.interp(SADDLES, x, f.real) + 1j * np.interp(SADDLES, x, f.imag)
    return complex(v[1] - 0.5 * (v[0] + v[2]))


def bending_rise(wave_length: float, beta_deg: float) -> float:
    tf = wave_transfer_functions(girder, loading, np.array([np.sqrt(2 * np.pi * G / wave_length)]), heading_deg=beta_deg)
    return AMPLITUDE * abs(rise(tf.deflection_m_per_m[0], tf.x_m))


lengths = (45.0, 50.0, 60.0, 80.0, 100.0, 120.0, 140.0, 171.0, 200.0, 250.0, 300.0)
headings = range(90, 181, 5)
worst_bending = max((bending_rise(lam, beta), lam, beta) for lam in lengths for beta in headings)
print(f"vertical bending: worst deck rise at the saddles {worst_bending[0] * 1e3:.2f} mm (lambda {worst_bending[1]:g} m, {worst_bending[2]} deg)")
for name, (gj, eiw, zs) in SECTIONS.items():
    worst = max(
        (abs(Y_PILE * rise(twist(net_moment(2 * np.pi / lam, beta, zs), gj, eiw)[1])), lam, beta) for lam in lengths for beta in headings
    )
    r, lam, beta = worst
    torque, phi = twist(net_moment(2 * np.pi / lam, beta, zs), gj, eiw)
    same = bending_rise(lam, beta)
    print(
        f"{name}: worst lambda {lam:g} m at {beta} deg: torque {np.max(np.abs(torque)):.3g} N m, twist {np.rad2deg(np.max(np.abs(phi - np.interp(XM, X, phi.real) - 1j * np.interp(XM, X, phi.imag)))):.2g} deg from midship; "
        f"torsional deck rise {r * 1e3:.2f} mm, vertical bending's in the same wave {same * 1e3:.2f} mm"
    )
