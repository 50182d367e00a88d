"""Stability of a periodic solution: Floquet multipliers of the condensed contact flow.

A harmonic-balance solution is a periodic orbit; whether the cargo settles on it is decided by
the perturbations about it. With every saddle bilateral the cargo is linear, so a perturbation
lives in the *correction system* of the condensed formulation (``docs/sweeps.md``,
``docs/theory.md`` section 5), here in the modal coordinates of
:func:`seafast.solvers.modal_correction.modal_correction_system` (the modes up to a cutoff, their
full modal damping ``Xi = Phi^T D Phi``, and the static residual flexibility ``R`` of the
truncated modes at the saddles)::

    eta'' + Xi eta' + Omega^2 eta = Phi_s^T c,    c = f(delta) - k_u delta,
    delta = delta_lin(t) - Phi_s eta - R c.

Linearised about the orbit ``delta(t)`` (``W(t) = diag(f'(delta(t)) - k_u)``, so ``dc = W
d delta`` and ``(I + R W) d delta = -Phi_s d eta``)::

    d eta'' + Xi d eta' + K(t) d eta = 0,    K(t) = Omega^2 + Phi_s^T W (I + R W)^-1 Phi_s.

For the exact law ``W`` is ``-k_u`` on the saddles detached at ``t`` and 0 on the others: ``K(t)``
is piecewise constant between the instants where a saddle's compression changes sign, and the
flow is piecewise linear and continuous (the contact force is continuous in ``delta``, so no
saltation matrix is needed at the switches). The monodromy matrix is then exact::

    Phi_T = expm(A_n dt_n) ... expm(A_1 dt_1),    A = [[0, I], [-K, -Xi]],

with the switching instants found as the roots of the orbit's trigonometric polynomials. The
smooth laws (``tanh``, ``softplus``) give a continuous ``K(t)``, taken constant over each of a
fine grid of sub-intervals (its midpoint value; second order in the sub-interval), merged where it
does not change. The orbit is stable when every multiplier (eigenvalue of ``Phi_T``) lies inside
the unit circle; a real multiplier through +1 is a fold of the frequency response, through -1 a
period doubling, a complex pair a Neimark-Sacker bifurcation. Computing the multipliers of the
monodromy matrix needs none of the sorting that Hill's method needs to pick the 2 m meaningful
exponents out of its truncated spectrum (Lazarus and Thomas 2010; Krack and Gross 2019, ch. 4).

Units: time [s], frequency [rad/s], compression [m], stiffness [N/m]; multipliers are
dimensionless. Nothing here prints or reads files.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum

import numpy as np
from numpy.typing import NDArray
from scipy.linalg import expm
from scipy.optimize import brentq

from seafast.fourier import harmonics_to_time, real_to_complex_harmonics
from seafast.model.structure import StructuralModel
from seafast.solvers.contact import ContactLaw
from seafast.solvers.modal_correction import ModalCorrectionSystem, modal_correction_system

__all__ = [
    "STABILITY_TOLERANCE",
    "Stability",
    "FloquetMultipliers",
    "stability_system",
    "floquet_multipliers",
]

STABILITY_TOLERANCE = 1e-6
"""An orbit is called stable when its largest multiplier modulus is at most ``1 + STABILITY_TOLERANCE``
(a neutral mode, e.g. a free rigid-body motion with every saddle detached, has a multiplier of exactly 1).
It knows nothing of the orbit's discretisation: a sweep decides with the tolerance its folds give
(:mod:`seafast.analyses.sweep.stability`), of which this is the floor."""


class Stability(Enum):
    """A periodic orbit's stability verdict, within a tolerance on its largest multiplier modulus ``|mu|``."""

    STABLE = "stable"
    """``|mu| < 1 - tolerance``: every perturbation decays."""
    UNSTABLE = "unstable"
    """``|mu| > 1 + tolerance``: a perturbation grows; the cargo leaves this orbit."""
    MARGINAL = "marginal"
    """``| |mu| - 1 | <= tolerance``: at a fold (or another bifurcation, or a neutral mode) to within what the
    discretisation can tell."""


_CUTOFF_FACTOR = 4.0  # modes kept up to this multiple of the n_s-th natural frequency (and of 2 H omega)
_ROOT_SAMPLES = 64  # samples per harmonic when looking for the sign changes of a saddle's compression
_SMOOTH_SUBINTERVALS = 512  # sub-intervals of a period for the smooth contact laws


@dataclass(frozen=True)
class FloquetMultipliers:
    """The Floquet multipliers of one periodic orbit.

    Attributes
    ----------
    multipliers
        Eigenvalues of the monodromy matrix, (2 m,) complex [-], sorted by decreasing modulus.
    max_modulus
        The largest modulus [-]: the growth of the most unstable perturbation over one period.
    stable
        ``max_modulus <= 1 + STABILITY_TOLERANCE``.
    switching_times_s
        Instants in [0, T) where a saddle's compression changes sign (exact law) [s].
    mode_count
        Modes m of the reduced correction system.
    """

    multipliers: NDArray[np.complex128]
    max_modulus: float
    stable: bool
    switching_times_s: NDArray[np.float64]
    mode_count: int

    @property
    def leading_multiplier(self) -> complex:
        """The multiplier of largest modulus (real and > 1 past a fold, < -1 past a period doubling)."""
        return complex(self.multipliers[0])


def stability_system(model: StructuralModel, omega_max_rad_s: float, harmonics: int) -> ModalCorrectionSystem:
    """The reduced correction system the multipliers are computed with.

    Modes up to ``max(4 omega_ns, 2 H omega_max)`` are kept (``omega_ns`` the ``n_s``-th natural
    frequency on bilateral saddles, the highest of the modes in which the cargo moves on its
    saddles); the others respond quasi-statically through the residual flexibility.
    """
    n_s = max(model.saddle_count, 1)
    omega_ns = float(model.natural_frequencies_rad_s(True, count=n_s)[-1])
    cutoff = max(_CUTOFF_FACTOR * omega_ns, 2.0 * max(int(harmonics), 1) * float(omega_max_rad_s))
    return modal_correction_system(model, cutoff)


def _compression_at(coefficients: NDArray, omega: float, t: float) -> NDArray:
    """delta(t) of real-layout coefficients (2H+1, n_s) at one instant [m]."""
    H = (coefficients.shape[0] - 1) // 2
    k = np.arange(1, H + 1)
    phase = k * omega * t
    return coefficients[0] + np.cos(phase) @ coefficients[1::2] + np.sin(phase) @ coefficients[2::2]


def _switching_times(coefficients: NDArray, omega: float) -> NDArray[np.float64]:
    """Instants in [0, T) where a saddle's compression changes sign [s]."""
    H = (coefficients.shape[0] - 1) // 2
    period = 2.0 * np.pi / omega
    n = max(_ROOT_SAMPLES * max(H, 1), 256)
    delta = harmonics_to_time(real_to_complex_harmonics(coefficients), n)  # (n, n_s)
    t = np.arange(n + 1) * period / n
    closed = np.concatenate([delta, delta[:1]])
    times = []
    for s in range(coefficients.shape[1]):
        d = closed[:, s]
        for i in np.nonzero(np.sign(d[:-1]) * np.sign(d[1:]) < 0)[0]:
            times.append(brentq(lambda x, s=s: float(_compression_at(coefficients, omega, x)[s]), t[i], t[i + 1], xtol=1e-14 * period))
    return np.unique(np.mod(np.asarray(times, dtype=float), period))


def floquet_multipliers(
    model: StructuralModel,
    omega_rad_s: float,
    compression_harmonics_m: NDArray,
    law: ContactLaw,
    *,
    system: ModalCorrectionSystem | None = None,
) -> FloquetMultipliers:
    """Floquet multipliers of the periodic orbit with saddle compressions ``delta(t)``.

    Parameters
    ----------
    model
        The cargo and sea-fastening model (used when ``system`` is not given).
    omega_rad_s
        Fundamental frequency of the orbit [rad/s], > 0.
    compression_harmonics_m
        The orbit's saddle compressions, real harmonic layout (2H+1, n_s) [m] (positive
        compressed), e.g. a condensed HBM solution.
    law
        The contact law the orbit was solved with.
    system
        The reduced correction system (:func:`stability_system`); built from ``model`` when omitted
        (pass it when many orbits of one model are checked).

    Returns
    -------
    FloquetMultipliers
        Sorted multipliers, the largest modulus and the stability verdict.
    """
    omega = float(omega_rad_s)
    if not (np.isfinite(omega) and omega > 0):
        raise ValueError(f"omega_rad_s = {omega_rad_s!r}; allowed: a finite number > 0 [rad/s]")
    U = np.asarray(compression_harmonics_m, dtype=float)
    H = (U.shape[0] - 1) // 2
    if U.ndim != 2 or U.shape[0] != 2 * H + 1:
        raise ValueError(f"compression_harmonics_m: shape {U.shape}; must be (2H+1, n_saddles)")
    sys_ = stability_system(model, omega, H) if system is None else system
    if U.shape[1] != sys_.saddle_count:
        raise ValueError(f"compression_harmonics_m has {U.shape[1]} saddles; the system has {sys_.saddle_count}")
    period = 2.0 * np.pi / omega
    k_u = sys_.unilateral_stiffness_N_per_m
    if law.is_smooth:
        edges = np.linspace(0.0, period, _SMOOTH_SUBINTERVALS + 1)
        switching = np.zeros(0)
    else:
        switching = _switching_times(U, omega)
        edges = np.unique(np.concatenate([[0.0], switching, [period]]))
    mids = 0.5 * (edges[:-1] + edges[1:])
    delta_mid = np.stack([_compression_at(U, omega, t) for t in mids])  # (n_int, n_s)
    W = law.derivative(delta_mid, k_u) - k_u
    W[np.abs(W) <= 1e-12 * k_u] = 0.0  # in contact: exactly no correction stiffness
    m = sys_.mode_count
    Phi, Xi, R = sys_.saddle_mode_shape, sys_.modal_damping, sys_.residual_flexibility_m_per_N
    eye_s = np.eye(sys_.saddle_count)
    base = np.zeros((2 * m, 2 * m))
    base[:m, m:] = np.eye(m)
    base[m:, m:] = -Xi
    monodromy = np.eye(2 * m)
    start = 0
    n_int = mids.size
    while start < n_int:
        stop = start + 1  # merge the sub-intervals over which W does not change
        while stop < n_int and np.array_equal(W[stop], W[start]):
            stop += 1
        w = W[start]
        stiffness = np.diag(sys_.natural_frequency_rad_s**2) + Phi.T @ (w[:, None] * np.linalg.solve(eye_s + R * w[None, :], Phi))
        A = base.copy()
        A[m:, :m] = -stiffness
        monodromy = expm(A * (edges[stop] - edges[start])) @ monodromy
        start = stop
    mu = np.asarray(np.linalg.eigvals(monodromy), dtype=np.complex128)
    mu = mu[np.argsort(-np.abs(mu), kind="stable")]
    top = float(np.abs(mu[0])) if mu.size else 0.0
    return FloquetMultipliers(mu, top, top <= 1.0 + STABILITY_TOLERANCE, switching, m)
