"""Wave torsion of the hull girder at a heading, quasi-static: an estimate, not part of the cargo's excitation.

In an oblique wave the part of the wave odd across the breadth heels each section (see
:mod:`seafast.hull.oblique`). :func:`wave_torsion_load` gives the net torsional load per metre of
wave amplitude about the girder's shear centre, for box sections of the hull's waterline breadth
``B(x)`` and draught ``T`` under the hydrostatic wave pressure ``rho g zeta(x, y)`` (uniform in
depth, no Smith effect, as the vertical model); the ship's rigid-body reaction balances it:

* the bottom pressure's moment ``rho g int y zeta dy`` and the side pressures' sway force
  ``rho g T (zeta(-B/2) - zeta(B/2))`` acting at mid-draught, about the shear centre;
* the total sway force taken by sway inertia distributed like the mass per metre and acting at the
  centre of gravity; the remaining roll moment by roll restoring and inertia distributed like
  ``B(x)^3`` (quasi-static: roll resonance is not amplified).

:func:`girder_twist` integrates it to the torque ``T(x)`` and the twist ``phi(x)`` of a free-free
thin-walled girder with warping, ``G J phi' - E I_w phi''' = T``, ``phi'' = 0`` at both ends (free
warping), by second-order finite differences on a uniform grid.

Axes: x from the AP [m], y to port, z up; the twist ``phi`` [rad] is the rotation about +x (the
port side rises for phi > 0), so a deck point at ``y`` rises by ``y phi``. Wave:
:mod:`seafast.hull.oblique`; harmonics ``Re(W exp(i omega t))``. The estimate and what it means for
the saddles: ``docs/oblique.md`` (left out: horizontal bending and torsion).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray
from scipy.linalg import solve_banded

from seafast.hull.oblique import along_ship_wave_number_per_m, heading_cosines
from seafast.vessel.hull_form import HullForm

__all__ = ["TorsionSection", "box_section_roll_moment_per_m", "wave_torsion_load", "girder_twist"]

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class TorsionSection:
    """Torsional properties of the hull girder (uniform along the ship).

    Parameters
    ----------
    torsion_constant_m4
        St Venant torsion constant J [m^4] (> 0).
    warping_constant_m6
        Warping constant I_w [m^6] (>= 0; 0 = St Venant torsion alone).
    shear_centre_above_keel_m
        Height of the shear centre (the twist axis) above the keel [m]; negative below it (open sections).
    youngs_modulus_Pa, shear_modulus_Pa
        E [Pa] and G [Pa] (``None``: ``E / 2.6``).
    """

    torsion_constant_m4: float
    warping_constant_m6: float = 0.0
    shear_centre_above_keel_m: float = 0.0
    youngs_modulus_Pa: float = 210e9
    shear_modulus_Pa: float | None = None

    def __post_init__(self) -> None:
        if not (self.torsion_constant_m4 > 0) or not (self.warping_constant_m6 >= 0) or not (self.youngs_modulus_Pa > 0):
            raise ValueError(
                f"torsion section: torsion_constant_m4 = {self.torsion_constant_m4!r} must be > 0, warping_constant_m6 = "
                f"{self.warping_constant_m6!r} >= 0 and youngs_modulus_Pa = {self.youngs_modulus_Pa!r} > 0"
            )
        if self.shear_modulus_Pa is None:
            object.__setattr__(self, "shear_modulus_Pa", self.youngs_modulus_Pa / 2.6)

    @property
    def torsional_stiffness_Nm2(self) -> float:
        """G J [N m^2]."""
        return float(self.shear_modulus_Pa or 0.0) * self.torsion_constant_m4

    @property
    def warping_stiffness_Nm4(self) -> float:
        """E I_w [N m^4]."""
        return self.youngs_modulus_Pa * self.warping_constant_m6


def box_section_roll_moment_per_m(
    wave_number_per_m: float,
    breadth_m: FloatArray,
    draft_m: float,
    heading_deg: float,
    axis_below_waterline_m: float,
    rho_g_N_per_m3: float,
) -> NDArray[np.complex128]:
    """Wave roll moment [N m/m per m of wave] on box sections about an axis on the centreline, at the section's wave phase.

    ``rho g [int y exp(-i kappa y) dy - (z_side - z_axis) F_y / (rho g)]`` with ``kappa = k sin(beta)``: the
    bottom's ``-i rho g S``, ``S = int_{-b}^{b} y sin(kappa y) dy = 2 (sin(kappa b) - kappa b cos(kappa b)) / kappa^2``
    (``kappa B^3 / 12`` for a long wave), and the sides' sway force ``F_y = 2 i rho g T sin(kappa b)`` at
    mid-draught; ``b = B / 2``. Multiply by ``exp(i k_x (x - L/2))`` for the section at ``x``.
    """
    _, sin_beta = heading_cosines(heading_deg)
    kappa = wave_number_per_m * sin_beta
    b = 0.5 * np.asarray(breadth_m, dtype=float)
    a = kappa * b
    small = np.abs(a) < 1e-3
    safe = np.where(small, 1.0, a)
    s = np.where(small, 2.0 * kappa * b**3 / 3.0 * (1.0 - a * a / 10.0), 2.0 * b * b * (np.sin(safe) - safe * np.cos(safe)) / safe**2)
    sway = 2j * rho_g_N_per_m3 * draft_m * np.sin(a)
    return np.asarray(-1j * rho_g_N_per_m3 * s - (axis_below_waterline_m - 0.5 * draft_m) * sway, dtype=complex)


def wave_torsion_load(
    hull: HullForm,
    x_m: FloatArray,
    mass_per_m: FloatArray,
    wave_number_per_m: float,
    heading_deg: float,
    section: TorsionSection,
    centre_of_gravity_above_keel_m: float,
    rho_g_N_per_m3: float = 1025.0 * 9.81,
) -> NDArray[np.complex128]:
    """Net torsional load per metre [N m/m per m of wave] about the shear centre, self-equilibrated (see the module docstring).

    Parameters
    ----------
    hull
        Hull form (waterline breadth, draught).
    x_m, mass_per_m
        Uniform nodes from the AP [m] and the ship's mass per metre there [kg/m].
    wave_number_per_m, heading_deg
        The wave: k [1/m] and heading beta [deg] (180 = head seas: no torsion).
    section
        The girder's torsional properties (its shear centre is the axis).
    centre_of_gravity_above_keel_m
        Where sway inertia acts [m].
    rho_g_N_per_m3
        Water density times gravity [N/m^3].
    """
    x = np.asarray(x_m, dtype=float)
    breadth = hull.breadth_at(x)
    draft = hull.draft_m
    axis_below = draft - section.shear_centre_above_keel_m
    along = np.exp(1j * along_ship_wave_number_per_m(wave_number_per_m, heading_deg) * (x - 0.5 * hull.length_m))
    moment = along * box_section_roll_moment_per_m(wave_number_per_m, breadth, draft, heading_deg, axis_below, rho_g_N_per_m3)
    _, sin_beta = heading_cosines(heading_deg)
    sway = along * 2j * rho_g_N_per_m3 * draft * np.sin(0.5 * wave_number_per_m * breadth * sin_beta)
    inertia = -np.asarray(mass_per_m, dtype=float) * np.trapezoid(sway, x) / np.trapezoid(mass_per_m, x)
    moment = moment - (centre_of_gravity_above_keel_m - section.shear_centre_above_keel_m) * inertia
    roll = breadth**3
    return np.asarray(moment - roll * np.trapezoid(moment, x) / np.trapezoid(roll, x), dtype=complex)


def girder_twist(x_m: FloatArray, load_per_m: NDArray, section: TorsionSection) -> tuple[NDArray, NDArray]:
    """Torque ``T(x)`` [N m] and twist ``phi(x)`` [rad] (phi = 0 at the AP) of the free-free girder under a torsional load.

    ``T(x) = int_0^x m dx`` (trapezoidal; zero at the FP for a self-equilibrated load); the rate of twist
    ``theta = phi'`` solves ``G J theta - E I_w theta'' = T`` with ``theta' = 0`` at both ends (second-order
    central differences, ghost nodes), or ``theta = T / (G J)`` without warping; ``phi`` is its trapezoidal
    integral. ``x_m`` must be uniform.
    """
    x = np.asarray(x_m, dtype=float)
    h = float(x[1] - x[0])
    if x.ndim != 1 or x.size < 3 or not np.allclose(np.diff(x), h, rtol=1e-9, atol=0.0):
        raise ValueError("girder_twist: x_m must be a uniform grid of at least 3 nodes")
    m = np.asarray(load_per_m)
    torque = np.concatenate([np.zeros(1, m.dtype), np.cumsum(0.5 * h * (m[1:] + m[:-1]))])
    gj, eiw = section.torsional_stiffness_Nm2, section.warping_stiffness_Nm4
    if eiw == 0.0:
        rate = torque / gj
    else:
        c = eiw / h**2
        band = np.zeros((3, x.size))
        band[0, 1:] = band[2, :-1] = -c
        band[1] = gj + 2.0 * c
        band[0, 1] = band[2, -2] = -2.0 * c  # theta'(0) = theta'(L) = 0
        rate = solve_banded((1, 1), band, torque)
    twist = np.concatenate([np.zeros(1, rate.dtype), np.cumsum(0.5 * h * (rate[1:] + rate[:-1]))])
    return torque, twist
