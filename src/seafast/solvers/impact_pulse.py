"""The pulse of an elastic impact: the cargo striking a saddle's spring, and the speed at which the gap closes.

Numerics of the impact check (:mod:`seafast.results.impact`): :func:`pulse_peak_per_velocity` is the peak force of
a spring struck by a linear structure at rest, per unit approach velocity, by modal superposition;
:func:`impact_force_per_velocity_N_s_per_m` is that for the cargo's free finite-element beam struck in heave at a
saddle (``G(k)``; ``sqrt(k m)`` for a rigid cargo of effective mass ``m``, about ``k^(1/3)`` for a flexible one on
stiff saddles); :func:`recontact_velocities_m_s` reads each re-contact's approach velocity from a sampled period.

Units: SI (m, s, N, kg). Nothing here prints, reads or writes files.
"""

from __future__ import annotations

import math

import numpy as np
import scipy.linalg
from numpy.typing import NDArray

from seafast.model.structure import StructuralModel

__all__ = ["impact_force_per_velocity_N_s_per_m", "pulse_peak_per_velocity", "recontact_velocities_m_s"]


def recontact_velocities_m_s(compression_m: NDArray, period_s: float) -> list[NDArray[np.float64]]:
    """Per saddle, the approach velocity of each re-contact over one period [m/s] (> 0; empty: none).

    A re-contact is a sample in contact (compression > 0) after one in the gap (<= 0), cyclically on the uniform
    grid ``t_n = n T / N`` (a sample the shooting moves onto a peak is in contact, never on the gap side read here).
    The gap closes smoothly (the free flight of the lifted cargo), so the rate is read from
    the gap side alone: the parabola through the last three gap samples (two: the line), its rate where it crosses
    zero in the sample interval (else at the last gap sample). A gap one sample long (a rebound the grid does not
    resolve) has no rate and is left out.

    Parameters
    ----------
    compression_m
        Saddle compressions (N, n_s) [m], positive in contact.
    period_s
        The period T [s].
    """
    delta = np.asarray(compression_m, dtype=float)
    N = delta.shape[0]
    dt = float(period_s) / N
    out: list[NDArray[np.float64]] = []
    for d in delta.T:
        rates = []
        for n in np.nonzero((np.roll(d, 1) <= 0.0) & (d > 0.0))[0]:
            gap = [d[(n - j) % N] for j in (3, 2, 1)]
            known = 3 if all(g <= 0.0 for g in gap) else 2 if gap[1] <= 0.0 else 0
            if known == 0 or N < 4:
                continue
            rate = _closing_rate(np.asarray(gap[3 - known :]), dt)
            if rate > 0.0:
                rates.append(rate)
        out.append(np.asarray(rates, dtype=float))
    return out


def _closing_rate(gap_m: NDArray, dt_s: float) -> float:
    """The rate of the polynomial through the gap samples (the last at t = 0) where it reaches zero in (0, dt]."""
    t = dt_s * np.arange(1 - gap_m.size, 1, dtype=float)
    poly = np.polynomial.Polynomial.fit(t, gap_m, gap_m.size - 1).convert()
    found = np.asarray(poly.roots(), dtype=complex)
    roots = [float(r) for r in found.real[(np.abs(found.imag) <= 1e-12 * dt_s) & (found.real >= 0.0) & (found.real <= dt_s)]]
    return float(poly.deriv()(min(roots) if roots else 0.0))


def pulse_peak_per_velocity(stiffness: NDArray, mass: NDArray, contact: NDArray, spring_N_per_m: float, velocity: NDArray) -> float:
    """The peak force of a spring struck by a linear structure at rest, per unit approach velocity [N s/m].

    ``M x'' + (K + k c c^T) x = 0``, ``x(0) = 0``, ``x'(0) = velocity`` scaled so that the contact closes at unit
    speed (``c^T x'(0) = 1``); the spring's force ``k c^T x(t)`` over its first pulse (until it would pull), by
    modal superposition (exact at each time; the pulse sampled at 64 points per period of the contact on the
    contact point's own mass ``1 / (c^T M^-1 c)``, the fastest it can ring).

    Parameters
    ----------
    stiffness, mass
        ``K`` (may be singular: a free structure) and ``M`` (positive definite), (n, n).
    contact
        ``c`` (n,): the compression of the spring is ``c^T x``.
    spring_N_per_m
        ``k`` [N/m], > 0.
    velocity
        The shape of the initial velocity (n,), ``c^T velocity != 0``.
    """
    c = np.asarray(contact, dtype=float)
    k = float(spring_N_per_m)
    M = np.asarray(mass, dtype=float)
    squared, modes = scipy.linalg.eigh(np.asarray(stiffness, dtype=float) + k * np.outer(c, c), M)
    omega = np.sqrt(np.clip(squared, 0.0, None))
    u0 = np.asarray(velocity, dtype=float) / float(c @ velocity)
    amplitude = k * (modes.T @ c) * (modes.T @ (M @ u0))  # F(t) = sum_j amplitude_j sin(omega_j t) / omega_j
    node_mass = 1.0 / float(c @ scipy.linalg.cho_solve(scipy.linalg.cho_factor(M), c))
    step = 2.0 * np.pi / math.sqrt(k / node_mass) / 64.0
    rigid = omega <= 1e-9 * float(np.max(omega))  # a free structure's rigid modes: sin(w t) / w -> t
    weight, frequency, drift = amplitude[~rigid] / omega[~rigid], omega[~rigid], float(np.sum(amplitude[rigid]))
    peak, done, count = 0.0, 0, 256
    while done < 2**22:  # 65536 of the fastest periods: a pulse on the whole cargo's mass ends long before
        t = (done + np.arange(1, count + 1, dtype=float)) * step
        force = np.sin(np.outer(t, frequency)) @ weight + drift * t
        pulling = np.nonzero(force < 0.0)[0]
        if pulling.size:
            return max(peak, float(np.max(force[: pulling[0]], initial=0.0)))
        peak = max(peak, float(np.max(force)))
        done, count = done + count, min(2 * count, 4096)
    return peak


def impact_force_per_velocity_N_s_per_m(model: StructuralModel, saddle: int, stiffness_N_per_m: float) -> float:
    """``G(k)``: the peak force of the cargo striking a saddle's spring in heave, per unit approach velocity [N s/m].

    The free cargo beam (its stiffness and consistent mass matrices; on the pulse's time scale the other
    saddles and the lashings hold nothing the impact's peak depends on), at rest, moving down at unit speed onto
    the saddle's spring (:func:`pulse_peak_per_velocity`). A rigid cargo gives ``sqrt(k m_eff)``,
    ``m_eff = 1 / (1/m + d^2 / J)`` at a distance ``d`` from its centre of mass; a flexible one on a stiff spring
    less (only the cargo near the saddle takes part). Cached on the model.
    """
    key = f"impact_force_per_velocity {int(saddle)} {float(stiffness_N_per_m):.17g}"
    cached = model.derived_cache.get(key)
    if isinstance(cached, float):
        return cached
    n = model.cargo_dof_count
    contact = np.zeros(n)
    contact[model.saddle_cargo_dof[saddle]] = 1.0
    heave = np.zeros(n)
    heave[0::2] = 1.0  # the vertical DOFs (even); rotations 0
    value = pulse_peak_per_velocity(model.cargo.stiffness, model.cargo.mass, contact, float(stiffness_N_per_m), heave)
    model.derived_cache[key] = value
    return value
