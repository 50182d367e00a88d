"""Maxima over one period of a periodic response given by its harmonics, read between the samples.

Used by :mod:`seafast.analyses.seastate.wave_response` for the design and conditioned waves. A peak is
located on the N time samples of the period, then read between the neighbouring samples (a
sampled peak falls short by up to ``1 - cos(pi / N)``, 3e-4 at N = 128): 33 evaluations of the
Fourier series over the two sample intervals around it and a parabola through the best three
(the peak to ~1e-12). Harmonics are in the real layout ``[a0, a1, b1, ..., aH, bH]`` of
:func:`seafast.fourier.real_dft_matrices`. Units SI: compression [m] positive when compressed,
contact force [N] upward on the cargo, bending moment [N m] sagging positive, stress [Pa].
"""

from __future__ import annotations

import functools

import numpy as np
from numpy.typing import NDArray

from seafast.solvers.contact import ContactLaw

__all__ = ["refined_peak", "period_maxima", "location_maximum", "location_maxima", "SADDLE_QUANTITIES", "MOMENT_QUANTITIES"]

SADDLE_QUANTITIES: tuple[str, ...] = ("F_N", "u_s_m", "u_d_m")
"""Quantities located at a saddle (location = saddle index)."""
MOMENT_QUANTITIES: tuple[str, ...] = ("M_b_Nm", "sigma_b_Pa")
"""Quantities located at a moment sample point (location = index along ``x_moment_m``)."""

_REFINE_POINTS = 33


@functools.lru_cache(maxsize=512)
def _refine_basis(sample: int, time_samples: int, harmonics: int) -> NDArray[np.float64]:
    """Rows [1, cos k theta, sin k theta] at 33 times over the two sample intervals around ``sample``."""
    theta = 2.0 * np.pi * (sample + np.linspace(-1.0, 1.0, _REFINE_POINTS)) / time_samples
    k = np.arange(1, harmonics + 1)
    basis = np.empty((_REFINE_POINTS, 2 * harmonics + 1))
    basis[:, 0] = 1.0
    basis[:, 1::2] = np.cos(np.outer(theta, k))
    basis[:, 2::2] = np.sin(np.outer(theta, k))
    basis.setflags(write=False)
    return basis


def refined_peak(coefficients: NDArray[np.float64], sample: int, time_samples: int, sign: float) -> float:
    """Largest ``sign * x(t)`` of one real-layout series (2H+1,) over the two sample intervals around ``sample``."""
    y = sign * (_refine_basis(int(sample), int(time_samples), (coefficients.size - 1) // 2) @ coefficients)
    i = int(np.argmax(y))
    if 0 < i < y.size - 1:  # the parabola through the best point and its neighbours (its error ~ step^4)
        curvature = y[i - 1] - 2.0 * y[i] + y[i + 1]
        if curvature < 0.0:
            return float(y[i] - (y[i + 1] - y[i - 1]) ** 2 / (8.0 * curvature))
    return float(y[i])


def period_maxima(
    compression: NDArray[np.float64],
    moment: NDArray[np.float64],
    inverse: NDArray[np.float64],
    stiffness: NDArray[np.float64],
    law: ContactLaw,
    modulus: NDArray[np.float64],
    nonlinear: bool,
) -> dict[str, float]:
    """Maxima over the period and over every location, still water included.

    Parameters
    ----------
    compression
        Real-layout saddle-compression harmonics (2H+1, n_s) [m].
    moment
        Real-layout bending-moment harmonics (2H+1, n_x) [N m].
    inverse
        (N, 2H+1) inverse real DFT matrix.
    stiffness
        (n_s,) compression-only saddle stiffness [N/m].
    law
        The contact law (force of the nonlinear model).
    modulus
        (n_x,) section modulus [m^3].
    nonlinear
        The contact law's force (True) or the bilateral saddles' ``k delta`` (False; ``u_d_m`` = 0).

    Returns
    -------
    dict
        ``F_N`` [N] the largest contact force, ``u_s_m`` [m] the largest compression (>= 0),
        ``u_d_m`` [m] the largest gap (>= 0), ``M_b_Nm`` [N m] and ``sigma_b_Pa`` [Pa] the largest
        absolute moment and stress.
    """
    N = inverse.shape[0]
    delta = inverse @ compression
    force = law.force(delta, stiffness) if nonlinear else delta * stiffness
    m_time = inverse @ moment
    n, s = np.unravel_index(int(np.argmax(force)), force.shape)
    top = refined_peak(compression[:, s], int(n), N, 1.0)
    F = float(law.force(np.array([top]), stiffness[s : s + 1])[0]) if nonlinear else top * float(stiffness[s])
    n, s = np.unravel_index(int(np.argmax(delta)), delta.shape)
    u_s = max(refined_peak(compression[:, s], int(n), N, 1.0), 0.0)
    u_d = 0.0
    if nonlinear and np.min(delta) < 0.0:
        n, s = np.unravel_index(int(np.argmin(delta)), delta.shape)
        u_d = max(refined_peak(compression[:, s], int(n), N, -1.0), 0.0)
    n, x = np.unravel_index(int(np.argmax(np.abs(m_time))), m_time.shape)
    M_b = refined_peak(moment[:, x], int(n), N, float(np.sign(m_time[n, x]) or 1.0))
    stress = np.abs(m_time / modulus)
    n, x = np.unravel_index(int(np.argmax(stress)), stress.shape)
    sigma_b = refined_peak(moment[:, x], int(n), N, float(np.sign(m_time[n, x]) or 1.0)) / float(modulus[x])
    return {"F_N": float(F), "M_b_Nm": float(M_b), "sigma_b_Pa": float(sigma_b), "u_s_m": float(u_s), "u_d_m": float(u_d)}


def location_maximum(
    quantity: str,
    location: int | NDArray[np.int64],
    compression: NDArray[np.float64],
    moment: NDArray[np.float64],
    inverse: NDArray[np.float64],
    stiffness: NDArray[np.float64],
    law: ContactLaw,
    modulus: NDArray[np.float64],
    nonlinear: bool = True,
) -> float:
    """The maximum over the period of one quantity at one location, or over several (arguments as :func:`period_maxima`).

    ``location`` is a saddle index (or indices) for :data:`SADDLE_QUANTITIES`, a moment-point index
    (or indices) for :data:`MOMENT_QUANTITIES`. ``F_N`` [N] the contact force, ``u_s_m`` [m] the
    compression (>= 0), ``u_d_m`` [m] the gap (>= 0), ``M_b_Nm`` [N m] the absolute moment,
    ``sigma_b_Pa`` [Pa] the absolute stress; ``u_d_m`` is 0 for the linear model
    (``nonlinear=False``: bilateral saddles). Over several locations the peak is located on the
    samples and read between them at the location it is found at, as in :func:`period_maxima`.
    """
    N = inverse.shape[0]
    idx = np.atleast_1d(np.asarray(location, dtype=np.int64))
    if quantity in SADDLE_QUANTITIES:
        delta = inverse @ compression[:, idx]
        if quantity == "u_d_m":
            n, j = np.unravel_index(int(np.argmin(delta)), delta.shape)
            if not nonlinear or delta[n, j] >= 0.0:
                return 0.0
            return max(refined_peak(compression[:, idx[j]], int(n), N, -1.0), 0.0)
        n, j = np.unravel_index(int(np.argmax(delta * stiffness[idx] if quantity == "F_N" else delta)), delta.shape)
        i = int(idx[j])
        top = refined_peak(compression[:, i], int(n), N, 1.0)
        if quantity == "u_s_m":
            return max(top, 0.0)
        return float(law.force(np.array([top]), stiffness[i : i + 1])[0]) if nonlinear else top * float(stiffness[i])
    if quantity not in MOMENT_QUANTITIES:
        raise ValueError(f"location_maximum: quantity {quantity!r}; allowed: {', '.join(SADDLE_QUANTITIES + MOMENT_QUANTITIES)}")
    m_time = inverse @ moment[:, idx]
    stress = quantity == "sigma_b_Pa"
    n, j = np.unravel_index(int(np.argmax(np.abs(m_time) / modulus[idx] if stress else np.abs(m_time))), m_time.shape)
    i = int(idx[j])
    peak = refined_peak(moment[:, i], int(n), N, float(np.sign(m_time[n, j]) or 1.0))
    return peak / float(modulus[i]) if stress else peak


def location_maxima(
    compression: NDArray[np.float64],
    moment: NDArray[np.float64],
    inverse: NDArray[np.float64],
    stiffness: NDArray[np.float64],
    law: ContactLaw,
    modulus: NDArray[np.float64],
    nonlinear: bool,
) -> dict[str, NDArray[np.float64]]:
    """:func:`location_maximum` of every quantity at every location: (n_s,) per saddle quantity, (n_x,) per moment one."""
    count: dict[str, int] = dict.fromkeys(SADDLE_QUANTITIES, int(compression.shape[1])) | dict.fromkeys(
        MOMENT_QUANTITIES, int(moment.shape[1])
    )
    return {
        q: np.array([location_maximum(q, i, compression, moment, inverse, stiffness, law, modulus, nonlinear) for i in range(n)])
        for q, n in count.items()
    }
