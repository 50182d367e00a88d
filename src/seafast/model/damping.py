"""Rayleigh damping of the cargo, fitted on its modes as they are.

``D = alpha M + beta K_beam``: beta multiplies the cargo beam's stiffness only (the saddle and lashing springs
carry no dashpot, so a lifted saddle never damps). See ``docs/theory.md`` (damping) for why the coefficients
must be fitted on the modes rather than taken from the textbook two-frequency formula.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from seafast.model.warning import ModelWarning

__all__ = ["RAYLEIGH_BETA_LIMIT", "RAYLEIGH_FALLBACK_TOLERANCE", "RayleighFit", "fit_rayleigh_to_modes", "rayleigh_coefficients"]


def rayleigh_coefficients(damping_ratio: float, omega_1_rad_s: float, omega_2_rad_s: float) -> tuple[float, float]:
    """Classic Rayleigh coefficients (alpha [1/s], beta [s]) for ``D = alpha M + beta K`` with K the *whole* stiffness.

    ``zeta(omega) = alpha / (2 omega) + beta omega / 2`` equals ``damping_ratio`` at both frequencies. seafast's
    beta multiplies the beam stiffness only (see :func:`fit_rayleigh_to_modes`); this is the textbook formula,
    kept for comparison and as the fallback's reference scale.
    """
    a = 2.0 * damping_ratio * omega_1_rad_s * omega_2_rad_s / (omega_1_rad_s + omega_2_rad_s)
    b = 2.0 * damping_ratio / (omega_1_rad_s + omega_2_rad_s)
    return a, b


#: The exact two-mode fit is refused when it needs beta above this multiple of the classic Rayleigh beta
#: (it would overdamp the beam modes, e.g. when both modes are rigid-body-like bounce and pitch).
RAYLEIGH_BETA_LIMIT = 10.0

#: The fallback raises :attr:`ModelWarning.RAYLEIGH_FALLBACK` (and is logged as a warning) when a realised modal
#: ratio misses the requested one by more than this share; within it, it is an engineering detail (logged as info).
RAYLEIGH_FALLBACK_TOLERANCE = 0.1


@dataclass(frozen=True)
class RayleighFit:
    """Rayleigh damping ``D = alpha M + beta K_beam`` fitted on the cargo's first two modes.

    Attributes
    ----------
    alpha_per_s, beta_s
        The coefficients [1/s], [s]; beta multiplies the cargo beam's stiffness only (the saddle and lashing
        springs carry no dashpot, so a lifted saddle never damps).
    omega_rad_s
        The first two natural frequencies of the cargo on bilateral saddles, deck fixed [rad/s].
    realised_damping_ratio
        ``phi^T D phi / (2 omega phi^T M phi)`` of those two modes [-].
    exact
        Whether both modes have exactly the requested ratio (False: the documented fallback was used).
    damping_ratio
        The requested ratio [-] (NaN when not recorded).
    """

    alpha_per_s: float
    beta_s: float
    omega_rad_s: tuple[float, float]
    realised_damping_ratio: tuple[float, float]
    exact: bool
    damping_ratio: float = float("nan")

    @property
    def miss(self) -> float:
        """Largest relative miss ``|zeta_realised / zeta - 1|`` of the two modes [-] (0 when exact or zeta = 0)."""
        if self.exact or not self.damping_ratio > 0.0:
            return 0.0
        return float(np.max(np.abs(np.asarray(self.realised_damping_ratio) / self.damping_ratio - 1.0)))

    @property
    def warnings(self) -> tuple[ModelWarning, ...]:
        """``(RAYLEIGH_FALLBACK,)`` when the fallback misses by more than :data:`RAYLEIGH_FALLBACK_TOLERANCE`, else ()."""
        return (ModelWarning.RAYLEIGH_FALLBACK,) if self.miss > RAYLEIGH_FALLBACK_TOLERANCE else ()


def fit_rayleigh_to_modes(
    damping_ratio: float, omega_rad_s: NDArray[np.float64], beam_stiffness_per_mass_rad2_per_s2: NDArray[np.float64]
) -> RayleighFit:
    """Rayleigh coefficients that give ``damping_ratio`` to the first two modes as they really are.

    With beta multiplying the beam stiffness only, the realised modal damping of a mode with frequency
    ``omega_i`` is ``zeta_i = (alpha + beta kappa_i) / (2 omega_i)``, where ``kappa_i = phi_i^T K_beam phi_i /
    phi_i^T M phi_i`` is the part of ``omega_i^2`` that the beam's strain energy carries (the saddle springs carry
    the rest: 85-95 % in the base case's first two modes, which is why the classic formula, which assumes
    ``kappa_i = omega_i^2``, realised only 1.1 % instead of 2 %). Two equations, two unknowns.

    When the exact solution needs a negative coefficient, or a beta more than :data:`RAYLEIGH_BETA_LIMIT` times
    the classic one (both modes nearly rigid on their supports, so that only an enormous beta could separate
    them), the fallback keeps the classic beta ``2 zeta / (omega_1 + omega_2)`` (it bounds the beam modes as
    textbook Rayleigh damping does) and takes the alpha that brings the two modes closest to the ratio (least
    squares); :attr:`RayleighFit.exact` says which, and the realised ratios are recorded.

    Parameters
    ----------
    damping_ratio
        Target ratio of critical damping [-], >= 0.
    omega_rad_s
        The first two natural frequencies [rad/s], > 0.
    beam_stiffness_per_mass_rad2_per_s2
        ``kappa_i`` of those modes [rad^2/s^2].
    """
    w = np.asarray(omega_rad_s, dtype=float)[:2]
    kappa = np.asarray(beam_stiffness_per_mass_rad2_per_s2, dtype=float)[:2]
    zeta = float(damping_ratio)

    def realised(alpha: float, beta: float) -> tuple[float, float]:
        z = (alpha + beta * kappa) / (2.0 * w)
        return float(z[0]), float(z[1])

    if zeta == 0.0:
        return RayleighFit(0.0, 0.0, (float(w[0]), float(w[1])), (0.0, 0.0), True, zeta)
    _, beta_classic = rayleigh_coefficients(zeta, float(w[0]), float(w[1]))
    det = kappa[1] - kappa[0]
    if abs(det) > 1e-12 * max(float(np.max(np.abs(kappa))), 1e-300):
        beta = 2.0 * zeta * (w[1] - w[0]) / det
        alpha = 2.0 * zeta * w[0] - beta * kappa[0]
        if alpha >= 0.0 and 0.0 <= beta <= RAYLEIGH_BETA_LIMIT * beta_classic:
            return RayleighFit(float(alpha), float(beta), (float(w[0]), float(w[1])), realised(alpha, beta), True, zeta)
    # fallback: the classic beta (it bounds the beam modes as textbook Rayleigh damping does), and the alpha that
    # brings modes 1 and 2 closest to the ratio in the least-squares sense
    beta = beta_classic
    a_i = 2.0 * zeta * w - beta * kappa  # the alpha each mode alone would need
    alpha = max(float(np.sum(a_i / w**2) / np.sum(1.0 / w**2)), 0.0)
    return RayleighFit(alpha, float(beta), (float(w[0]), float(w[1])), realised(alpha, beta), False, zeta)
