"""How many harmonics: the truncation indicator and the adaptive choice of H (and N).

Why it matters. After each re-contact the cargo rings in its modes (44-50 rad/s on the base case,
16 rad/s while the fore saddle is lifted), harmonics 25-85 of a 0.6 rad/s wave; a lift-off also puts a
kink in the compression, whose harmonics decay only as 1/k^2. Five or sixteen harmonics miss both
(0.5-1.5 % on the peaks), and a truncation that falls among those modes (H omega between the
lifted-state and the bilateral modes) makes the truncated problem ill-posed: the semi-smooth Newton
then wanders.

The truncation indicator (:func:`truncation_error`) sees it: it takes the solution's contact
correction force ``c(t)`` on a fine grid, keeps its harmonics above H, and computes the compression
they would cause through the cargo's receptance (modal, with the static residual of the higher modes);
``k_u`` times that compression, where the saddle is in contact, over the saddle's force scale, is the
estimated error of the saddle-force peaks. Unlike the share of force energy above H, it weighs each
missing harmonic by the cargo's dynamic amplification there.

The adaptive choice (:func:`select_harmonics`) marches the correction system of the periodic problem
(:func:`seafast.solvers.transient.march_periodic`, the project's one transient integrator: exact contact,
modes below the march's Nyquist frequency, the rest static) to its periodic state from the linear solution
(the attractor the physical system reaches from there), reads the harmonic content of the compressions, and
takes the smallest H whose neglected harmonics move every saddle force by less than the tolerance. The march, projected on those harmonics,
is also the Newton start: from the few-harmonic solution the semi-smooth Newton at H ~ 150 does not
converge, from the march it takes 2-4 steps.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from seafast.excitation.harmonic import HarmonicExcitation
from seafast.fourier import (
    complex_to_real_harmonics,
    harmonics_above,
    harmonics_to_time,
    real_dft_matrices,
    real_to_complex_harmonics,
    time_to_harmonics,
)
from seafast.model.structure import StructuralModel
from seafast.solvers.contact import ContactLaw
from seafast.solvers.hbm.condensed import condensed_operators
from seafast.solvers.hbm.options import MINIMUM_TIME_SAMPLES, samples_for
from seafast.solvers.modal_correction import modal_basis, modal_correction_system
from seafast.solvers.transient import march_periodic, newmark_step

__all__ = [
    "HarmonicSelection",
    "force_scale_N",
    "peak_change_bound",
    "select_harmonics",
    "truncation_error",
    "pad_harmonics",
]

_MARCH_MAX_PERIODS = 200
_LIGHTLY_LOADED_SHARE = 0.1  # a saddle's force scale is at least this share of the largest saddle force


def peak_change_bound(force_N: NDArray[np.float64], change_N: NDArray[np.float64]) -> NDArray[np.float64]:
    """How far a perturbation ``change_N(t)`` can move each saddle's peak force ``max_t force_N(t)`` [N], (n_s,).

    Only the samples within ``max |change|`` of the peak can become the peak, so the peak moves by at most
    the largest ``|change|`` over those samples (a bound, far tighter than ``max |change|`` over the period
    when the change lives away from the peak, e.g. ringing after a re-contact at low force).
    """
    peak = np.max(force_N, axis=0)
    reach = np.max(np.abs(change_N), axis=0, initial=0.0)
    candidates = force_N >= (peak - reach)[None, :]
    return np.max(np.abs(change_N) * candidates, axis=0, initial=0.0)


def force_scale_N(peak_force_N: NDArray[np.float64]) -> NDArray[np.float64]:
    """Per saddle, the force the truncation error is measured against [N].

    Its own peak, but at least a tenth of the largest saddle's: a nearly unloaded saddle's peak is not
    chased to 0.1 % of itself (its error stays below 1 % of its own peak when the others' are 0.1 %).
    """
    p = np.asarray(peak_force_N, dtype=float)
    return np.maximum(p, _LIGHTLY_LOADED_SHARE * max(float(np.max(p, initial=0.0)), 1.0))


@dataclass(frozen=True)
class HarmonicSelection:
    """The adaptive choice of H.

    Attributes
    ----------
    harmonics, time_samples
        H and N.
    start_compression_m
        The march's compressions projected on harmonics 0 .. H, real layout (2H+1, n_s) [m]: the Newton start.
    march_compression_m
        The march's compressions over one period, (march_samples, n_s) [m] (a start at any other H).
    march_samples, march_periods, march_change
        Samples per period of the march, periods marched, last relative change between periods.
    estimated_error
        Per saddle, the force error the neglected harmonics of the march would cause, over the force scale [-].
    capped
        Whether H was limited by ``max_harmonics`` (the estimate then exceeds the tolerance).
    """

    harmonics: int
    time_samples: int
    start_compression_m: NDArray[np.float64]
    march_compression_m: NDArray[np.float64]
    march_samples: int
    march_periods: int
    march_change: float
    estimated_error: NDArray[np.float64]
    capped: bool


def _march_samples(model: StructuralModel, omega_rad_s: float, max_harmonics: int) -> int:
    # resolve twice the second bilateral mode with 2 samples per period of it (Nyquist), in powers of 2
    w2 = float(modal_basis(model, 0.0).natural_frequency_rad_s[1])
    need = 2.0 * 2.0 * (2.0 * w2) / max(omega_rad_s, 1e-12)
    n = 2 ** math.ceil(math.log2(max(need, MINIMUM_TIME_SAMPLES)))
    return int(min(max(n, MINIMUM_TIME_SAMPLES), 8 * 2 ** math.ceil(math.log2(max(max_harmonics, 8)))))


def select_harmonics(
    model: StructuralModel,
    excitation: HarmonicExcitation,
    *,
    tolerance: float,
    max_harmonics: int,
) -> HarmonicSelection:
    """Choose H (and N) for the periodic response of ``model`` to ``excitation`` (see the module docstring).

    Parameters
    ----------
    tolerance
        Largest acceptable error of each saddle's peak force, relative to its force scale (:func:`force_scale_N`).
    max_harmonics
        Upper bound of H.
    """
    omega = float(excitation.omega_rad_s)
    period = 2.0 * math.pi / omega
    n_exc = max(excitation.harmonic_count - 1, 1)
    lin = condensed_operators(model, excitation, n_exc)
    N0 = _march_samples(model, omega, max_harmonics)
    inverse, _ = real_dft_matrices(lin.harmonics, N0)
    d_lin = inverse @ lin.linear_compression_m
    k_u = lin.saddle_stiffness_N_per_m
    if np.all(d_lin > 0.0):
        # contact kept all period by the linear solution: it is the answer, with the excitation's harmonics
        march, periods, change = d_lin, 0, 0.0
    else:
        # every mode below the march's Nyquist frequency, the rest static
        system = newmark_step(model, period / N0, math.pi * N0 / period, minimum_modes=0)
        periodic = march_periodic(system, d_lin, max_periods=_MARCH_MAX_PERIODS, tolerance=1e-6)
        march, periods, change = periodic.compression_m, periodic.periods, periodic.change
    scale = force_scale_N(np.max(k_u * np.maximum(march, 0.0), axis=0))
    in_contact = march > 0.0

    force = k_u * np.maximum(march, 0.0)

    def neglected_error(H: int) -> NDArray[np.float64]:
        # the change of each saddle's peak force if the compression lost its harmonics above H
        change = harmonics_above(march, H) * k_u * in_contact
        return peak_change_bound(force, change) / scale

    H = n_exc
    estimated = neglected_error(H)
    while np.max(estimated, initial=0.0) > tolerance and H < N0 // 2 - 1 and H < max_harmonics:
        H = min(max(math.ceil(1.2 * H), H + 2), N0 // 2 - 1, int(max_harmonics))
        estimated = neglected_error(H)
    capped = bool(np.max(estimated, initial=0.0) > tolerance)
    C = np.zeros((H + 1, march.shape[1]), dtype=complex)
    m = min(H, N0 // 2)
    C[: m + 1] = time_to_harmonics(march, m)
    return HarmonicSelection(
        harmonics=int(H),
        time_samples=samples_for(H),
        start_compression_m=complex_to_real_harmonics(C),
        march_compression_m=np.asarray(march, dtype=float),
        march_samples=int(N0),
        march_periods=int(periods),
        march_change=float(change),
        estimated_error=np.asarray(estimated, dtype=float),
        capped=bool(capped),
    )


def truncation_error(
    model: StructuralModel,
    omega_rad_s: float,
    compression_harmonics_m: NDArray[np.float64],
    law: ContactLaw,
) -> NDArray[np.float64]:
    """Estimated error of each saddle's peak force caused by truncating at H, relative to its force scale.

    Parameters
    ----------
    compression_harmonics_m
        The solution's saddle compressions, real layout (2H+1, n_s) [m].
    law
        The contact law of the solution (its correction force ``f(delta) - k_u delta`` is what is resampled).

    Returns
    -------
    (n_s,) [-]: the bound :func:`peak_change_bound` of the peak-force change ``k_u delta_missing(t)`` (where the
    saddle is in contact), over :func:`force_scale_N`, with
    ``delta_missing`` the compression the correction force's harmonics above H cause through the
    cargo's receptance (modes up to 1.2 times the highest harmonic considered, the rest static).
    """
    U = np.asarray(compression_harmonics_m, dtype=float)
    H = (U.shape[0] - 1) // 2
    k_u = np.asarray(model.saddle_unilateral_stiffness_N_per_m, dtype=float)
    N_f = 2 ** math.ceil(math.log2(max(8 * max(H, 1), 256)))
    delta = harmonics_to_time(real_to_complex_harmonics(U), N_f)  # an inverse real FFT
    force, _ = law.force_and_derivative(delta, k_u)
    correction = force - k_u * delta
    C = time_to_harmonics(correction, N_f // 2 - 1)  # complex amplitudes X_k
    k = np.arange(H + 1, N_f // 2)
    if k.size == 0:
        return np.zeros(k_u.size)
    system = modal_correction_system(model, 1.2 * float(k[-1]) * omega_rad_s)
    G = system.receptance(k * omega_rad_s)  # (n_k, n_s, n_s)
    missing = np.zeros((N_f // 2, k_u.size), dtype=complex)
    missing[k] = -np.einsum("kts,ks->kt", G, C[k])  # compression harmonics above H
    delta_missing = harmonics_to_time(missing, N_f)  # Re sum_k X_k e^{ik wt}
    change = k_u * delta_missing * (delta > 0.0)
    return np.asarray(peak_change_bound(force, change) / force_scale_N(np.max(force, axis=0)), dtype=float)


def pad_harmonics(U: NDArray[np.float64], harmonics: int) -> NDArray[np.float64]:
    """Real-layout harmonics (2H'+1, ...) padded with zeros (or truncated) to H harmonics."""
    out = np.zeros((2 * int(harmonics) + 1,) + U.shape[1:])
    m = min(out.shape[0], U.shape[0])
    out[:m] = U[:m]
    return out
