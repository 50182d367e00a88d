"""Heave and pitch RAOs at any wave frequency: BEM inside its grid, known limits outside.

Inside the computed grid the RAOs are the BEM's, interpolated linearly (exactly
:meth:`RigidBodyMotions.rao_at`). Outside it:

* **Long waves** (below the lowest computed frequency omega_0): a ship much shorter than the
  wave follows the surface, so with the wave ``zeta = zeta_a cos(omega t + k (x - x_w))``
  (crest at ``x_w`` at t = 0) the long-wave limits at the pitch reference ``x_r`` are::

      heave_lw = exp(i k (x_r - x_w)),    pitch_lw = i k exp(i k (x_r - x_w))   (dz/dx, bow up)

  i.e. heave -> 1 and pitch -> i k at midship. The BEM's ratio to the limit at omega_0,
  ``r_0 = RAO(omega_0) / RAO_lw(omega_0)``, is blended into 1 as ``r(omega) = 1 + (r_0 - 1)
  (omega / omega_0)^2``: the deviation from the limit is of first order in k L (~ omega^2).
  Continuous at omega_0, exact as omega -> 0.
* **Short waves** (above the highest computed frequency omega_1): the wave's pressure decays
  as ``exp(-k T)`` over the draught T and the response is inertia-dominated (~ omega^-2), so
  ``RAO(omega) = RAO(omega_1) (omega_1 / omega)^2 exp(-(k - k_1) T)``. On the default vessel
  |heave| is below 3e-4 m/m and |pitch| below 2e-5 rad/m already at 1.8 rad/s: this only
  keeps the RAOs continuous and small.

Deep-water wave numbers ``k = omega^2 / g`` (as the quasi-static hull-girder wave).

The six motions at any heading (:func:`extended_six_dof_rao`, :class:`SixDofMotions`, docs/headings.md) are
extended the same way. In a long wave of heading beta, ``zeta = Re exp(i omega t - i k ((x - x_w) cos beta + y sin
beta))``, the ship follows the surface and the water's orbit: at the CoG ``(x_G, 0)``, with ``e = exp(-i k (x_G - x_w)
cos beta)``::

    surge -> -i cos(beta) e,  sway -> -i sin(beta) e,  heave -> e,
    roll -> -i k sin(beta) e  (dzeta/dy, the wave slope across the ship),
    pitch -> -i k cos(beta) e (dzeta/dx, along the ship; i k e in head seas, as above),
    yaw -> -k sin(beta) cos(beta) e  (the turn of the orbit's sway along the ship).

Each is blended from the BEM at omega_0 into its limit as above (a limit that vanishes at the heading, e.g. roll in
head seas: ``RAO(omega_0) (omega / omega_0)^2``) and decayed above omega_1 as above.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from seafast.excitation.hydrodynamics.heading_motions import SixDofMotions
from seafast.excitation.hydrodynamics.motions import RigidBodyMotions

__all__ = ["extended_rao", "extended_six_dof_rao", "six_dof_long_wave_limits"]


def extended_rao(
    motions: RigidBodyMotions,
    omega_rad_s: ArrayLike,
    *,
    gravity_m_per_s2: float,
    draught_m: float,
    wave_phase_reference_x_m: float | None = None,
) -> tuple[NDArray[np.complex128], NDArray[np.complex128]]:
    """Heave [m/m] and pitch [rad/m] RAOs at any ``omega_rad_s`` > 0 (see the module docstring).

    Parameters
    ----------
    motions
        A :class:`~seafast.excitation.hydrodynamics.RigidBodyMotions`.
    omega_rad_s
        Wave frequencies [rad/s], > 0; scalar or array.
    gravity_m_per_s2
        g [m/s^2] for the deep-water wave number.
    draught_m
        Ship draught T [m] (short-wave decay).
    wave_phase_reference_x_m
        x [m] of the wave crest at t = 0; default ``motions.wave_phase_reference_x_m``.

    Returns
    -------
    heave, pitch
        Complex, the shape of ``omega_rad_s`` (complex scalars for a scalar).
    """
    w_in = np.asarray(omega_rad_s, dtype=float)
    w = np.atleast_1d(w_in)
    if not np.all(np.isfinite(w)) or np.any(w <= 0):
        raise ValueError(f"extended_rao: omega_rad_s must be finite and > 0 (got {w[~(np.isfinite(w) & (w > 0))][:1].tolist()})")
    grid = motions.omega_rad_s
    w0, w1 = float(grid[0]), float(grid[-1])
    heave = np.zeros(w.shape, dtype=complex)
    pitch = np.zeros(w.shape, dtype=complex)
    inside = (w >= w0) & (w <= w1)
    if np.any(inside):
        h, p = motions.rao_at(w[inside])
        heave[inside], pitch[inside] = h, p
    x_w = motions.wave_phase_reference_x_m if wave_phase_reference_x_m is None else wave_phase_reference_x_m
    low = w < w0
    if np.any(low):
        if not np.isfinite(x_w):
            raise ValueError("extended_rao: the motions carry no wave phase reference; give wave_phase_reference_x_m")
        arm = motions.reference_x_m - x_w

        def limits(om: NDArray[np.float64]) -> tuple[NDArray, NDArray]:
            k = om**2 / gravity_m_per_s2
            h_lw = np.exp(1j * k * arm)
            return h_lw, 1j * k * h_lw

        h0, p0 = motions.heave_rao_m_per_m[0], motions.pitch_rao_rad_per_m[0]
        h0_lw, p0_lw = limits(np.array([w0]))
        blend = (w[low] / w0) ** 2
        h_lw, p_lw = limits(w[low])
        heave[low] = h_lw * (1.0 + (h0 / h0_lw[0] - 1.0) * blend)
        pitch[low] = p_lw * (1.0 + (p0 / p0_lw[0] - 1.0) * blend)
    high = w > w1
    if np.any(high):
        k, k1 = w[high] ** 2 / gravity_m_per_s2, w1**2 / gravity_m_per_s2
        decay = (w1 / w[high]) ** 2 * np.exp(-(k - k1) * draught_m)
        heave[high] = motions.heave_rao_m_per_m[-1] * decay
        pitch[high] = motions.pitch_rao_rad_per_m[-1] * decay
    if w_in.ndim == 0:
        # a scalar omega gives two Python complex numbers (the docstring says so); callers pass arrays
        return complex(heave[0]), complex(pitch[0])  # type: ignore[return-value]
    return heave.reshape(w_in.shape), pitch.reshape(w_in.shape)


def six_dof_long_wave_limits(
    omega_rad_s: ArrayLike, heading_deg: float, *, gravity_m_per_s2: float, reference_x_m: float, wave_phase_reference_x_m: float
) -> NDArray[np.complex128]:
    """The six motions' long-wave limits (n, 6) at the CoG ``reference_x_m`` [m] (see the module docstring).

    Surge, sway, heave [m/m]; roll, pitch (bow up), yaw [rad/m]; ``exp(+i omega t)``, the crest at
    ``wave_phase_reference_x_m`` [m] on the centreline at t = 0.
    """
    w = np.atleast_1d(np.asarray(omega_rad_s, dtype=float))
    beta = np.radians(float(heading_deg))
    c, s = float(np.cos(beta)), float(np.sin(beta))
    k = w**2 / gravity_m_per_s2
    e = np.exp(-1j * k * (reference_x_m - wave_phase_reference_x_m) * c)
    return np.stack([-1j * c * e, -1j * s * e, e, -1j * k * s * e, -1j * k * c * e, -k * s * c * e], axis=-1)


def extended_six_dof_rao(
    motions6: SixDofMotions,
    omega_rad_s: ArrayLike,
    heading_deg: float,
    *,
    gravity_m_per_s2: float,
    draught_m: float,
    additional_roll_damping_Nms_per_rad: float = 0.0,
) -> NDArray[np.complex128]:
    """The six RAOs (n, 6) at any ``omega_rad_s`` > 0 (1-D) and ``heading_deg`` [deg] (see the module docstring).

    Inside the BEM grid :meth:`SixDofMotions.rao_at` (with ``additional_roll_damping_Nms_per_rad`` [N m s/rad] added
    to the roll damping); below it the blend into :func:`six_dof_long_wave_limits`, above it the decay, both from the
    RAOs at the grid's ends (with the same added damping). Units: m/m (surge, sway, heave), rad/m (roll, pitch, yaw).
    """
    w = np.atleast_1d(np.asarray(omega_rad_s, dtype=float))
    if w.ndim != 1 or not np.all(np.isfinite(w)) or np.any(w <= 0):
        raise ValueError("extended_six_dof_rao: omega_rad_s must be a 1-D array of finite frequencies > 0")
    grid = motions6.omega_rad_s
    w0, w1 = float(grid[0]), float(grid[-1])
    out = np.zeros((w.size, 6), dtype=complex)
    inside = (w >= w0) & (w <= w1)
    if np.any(inside):
        out[inside] = motions6.rao_at(w[inside], heading_deg, additional_roll_damping_Nms_per_rad)
    low, high = w < w0, w > w1
    if np.any(low):
        end = motions6.rao_at(np.array([w0]), heading_deg, additional_roll_damping_Nms_per_rad)[0]
        limits = six_dof_long_wave_limits(
            np.append(w[low], w0),
            heading_deg,
            gravity_m_per_s2=gravity_m_per_s2,
            reference_x_m=motions6.reference_x_m,
            wave_phase_reference_x_m=motions6.wave_phase_reference_x_m,
        )
        lw, lw0 = limits[:-1], limits[-1]
        blend = ((w[low] / w0) ** 2)[:, None]
        with np.errstate(divide="ignore", invalid="ignore"):
            relative = lw * (1.0 + (end / lw0 - 1.0) * blend)
        out[low] = np.where(lw0 != 0.0, relative, end * blend)
    if np.any(high):
        end = motions6.rao_at(np.array([w1]), heading_deg, additional_roll_damping_Nms_per_rad)[0]
        k, k1 = w[high] ** 2 / gravity_m_per_s2, w1**2 / gravity_m_per_s2
        out[high] = end * ((w1 / w[high]) ** 2 * np.exp(-(k - k1) * draught_m))[:, None]
    return out
