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
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from seafast.excitation.hydrodynamics.motions import RigidBodyMotions

__all__ = ["extended_rao"]


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
