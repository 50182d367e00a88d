"""The common result of the axial solvers, and the stick statics (docs/axial.md).

Sign conventions: ``u`` the cargo's axial displacement relative to the deck, forward +; every
force is the force *on the cargo*, forward +; the axial load ``F(t)`` is the inertia and gravity
load in the ship's frame (:mod:`seafast.excitation.axial`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from enum import Enum

import numpy as np
from numpy.typing import NDArray

from seafast.model.axial import AxialRestraint
from seafast.solvers.periodic import Settings

__all__ = ["AxialResponse", "AxialWarning", "LockCheck", "critical_friction_coefficient", "lock_range_m", "periodic_interpolation"]


class LockCheck(Enum):
    """A slip-free solution checked against the rigid-Coulomb friction law (docs/axial.md).

    ``NOT_LOCKED``
        The cargo slides (beyond the contacts' elastic range): no lock to check.
    ``HOLDS``
        Locked, and the friction it needs, ``|F(t) - r(u)|``, stays within the friction available
        ``C(t)`` at every sample (to the margin of the discretisation): a real periodic state.
    ``VIOLATED``
        Locked, but the friction needed exceeds the friction available at some samples: the
        truncated Fourier series hid short slips. Not a periodic state of the cargo; never
        reported as converged.
    """

    NOT_LOCKED = "not_locked"
    HOLDS = "holds"
    VIOLATED = "violated"


class AxialWarning(Enum):
    """A converged axial result that needs a second look (docs/axial.md#friction-credit).

    ``FRICTION_CARRIES_LOAD``
        The friction carries more of the axial load than the lashings and stoppers together
        (at its peak): the answer relies on friction credit, which design standards restrict.
    """

    FRICTION_CARRIES_LOAD = "friction_carries_load"

    @property
    def description(self) -> str:
        """One line for people (CLI, report)."""
        return _WARNING_DESCRIPTIONS[self]


_WARNING_DESCRIPTIONS = {
    AxialWarning.FRICTION_CARRIES_LOAD: "the friction carries more of the axial load than the lashings and stoppers (friction credit)",
}


def periodic_interpolation(samples: NDArray[np.float64], time_samples: int) -> NDArray[np.float64]:
    """Samples ``(N, ...)`` of one period, linearly interpolated (periodically) onto ``time_samples`` points."""
    s = np.asarray(samples, dtype=float)
    n = s.shape[0]
    if n == time_samples:
        return s.copy()
    t_old = np.arange(n + 1) / n
    t_new = np.arange(time_samples) / time_samples
    closed = np.concatenate([s, s[:1]], axis=0).reshape(n + 1, -1)
    out = np.stack([np.interp(t_new, t_old, closed[:, j]) for j in range(closed.shape[1])], axis=1)
    return out.reshape((time_samples,) + s.shape[1:])


def critical_friction_coefficient(load_N: NDArray[np.float64], normal_force_N: NDArray[np.float64]) -> float:
    """The uniform friction coefficient below which the cargo starts to slide [-].

    Stuck (``u = 0``: lashings and stoppers unloaded), the friction must carry the whole axial
    load, so the cargo holds while ``|F(t)| <= mu sum_i max(N_i(t), 0)`` at every instant:
    ``mu_crit = max_t |F(t)| / sum_i max(N_i(t), 0)`` (``inf`` if the load is nonzero while
    every saddle is lifted; 0 without load).
    """
    f = np.abs(np.asarray(load_N, dtype=float))
    n = np.maximum(np.asarray(normal_force_N, dtype=float), 0.0).sum(axis=-1)
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = np.where(f > 0, f / n, 0.0)
    return float(np.max(ratio)) if ratio.size else 0.0


def lock_range_m(restraint: AxialRestraint, load_N: NDArray[np.float64], capacity_N: NDArray[np.float64]) -> tuple[float, float] | None:
    """The cargo positions at which it stays locked (never slides) all period, rigid Coulomb [m].

    Locked at ``u`` (constant), the friction must carry ``F(t) - r(u)`` (``r`` the lashings' and
    stoppers' force resisting ``u``), so the cargo holds while ``|F(t) - r(u)| <= C(t)`` at every
    instant: ``max_t (F - C) <= r(u) <= min_t (F + C)``. The samples of ``F`` and ``C`` stand for
    the period (``C`` is linear between its samples, so its extrema are on them). ``None`` when no
    position holds (the cargo slides every period); ``u = 0`` is in the range exactly when the
    friction coefficient is at least :func:`critical_friction_coefficient` (with one coefficient
    for all saddles). Between the two the range lies off ``u = 0`` (shakedown): a cargo set down
    at ``u = 0`` walks to its nearer end, where the lashings take up the difference, and stays.
    """
    f = np.asarray(load_N, dtype=float)
    c = np.asarray(capacity_N, dtype=float)
    low, high = float(np.max(f - c)), float(np.min(f + c))
    if low > high:
        return None
    u_low, u_high = restraint.displacement_range_m(low, high)
    return (u_low, u_high) if u_low <= u_high else None


@dataclass(frozen=True)
class AxialResponse:
    """One period of the steady axial response of the cargo (N samples at ``t_n = n T / N``).

    Attributes
    ----------
    method
        ``"hbm"`` (harmonic balance, Jenkins contact) or ``"time_domain"`` (rigid Coulomb,
        event-driven).
    omega_rad_s
        Fundamental frequency [rad/s].
    displacement_m, velocity_m_per_s
        ``u`` [m] and ``u'`` [m/s] relative to the deck, forward +.
    friction_force_N
        Friction of all saddles on the cargo [N], forward +.
    capacity_N
        Friction available ``sum_i mu_i max(N_i, 0)`` [N].
    lashing_force_N, stopper_force_N
        Axial forces of the lashings and of the stoppers on the cargo [N], forward +.
    load_N
        Axial inertia and gravity load ``F(t)`` [N], forward +.
    sliding
        Samples where the cargo slides (slider moving / rigid-Coulomb slip phase).
    slip_m
        Sliding distance per period [m] (0 when stuck throughout).
    converged, residual_norm, iterations, message
        Solver outcome (never raised).
    harmonics
        Complex amplitudes of ``u`` (HBM), ``None`` for the time-domain reference.
    options
        The settings used.
    lock_check
        HBM: whether a slip-free solution was checked against the friction law
        (:class:`LockCheck`); the time-domain reference obeys it by construction.
    residual_drift_m
        Time domain: the estimated distance [m] of the state it stopped at from the periodic
        state (the remaining walk, extrapolated from the last periods' changes; 0 when a period
        repeats exactly); 0 for the HBM and the statics.
    walk_m_per_period
        Time domain, not converged: the displacement per period [m] of a cargo that walks (its
        velocity repeats from period to period, its position does not; forward +); None otherwise.
    warnings
        Typed warnings (:class:`AxialWarning`), set by the case analysis.
    """

    method: str
    omega_rad_s: float
    displacement_m: NDArray[np.float64]
    velocity_m_per_s: NDArray[np.float64]
    friction_force_N: NDArray[np.float64]
    capacity_N: NDArray[np.float64]
    lashing_force_N: NDArray[np.float64]
    stopper_force_N: NDArray[np.float64]
    load_N: NDArray[np.float64]
    sliding: NDArray[np.bool_]
    slip_m: float
    converged: bool
    residual_norm: float
    iterations: int
    message: str
    harmonics: NDArray[np.complex128] | None = None
    options: Settings = field(default_factory=dict)
    lock_check: LockCheck = LockCheck.NOT_LOCKED
    residual_drift_m: float = 0.0
    walk_m_per_period: float | None = None
    warnings: tuple[AxialWarning, ...] = ()

    @property
    def time_samples(self) -> int:
        return int(self.displacement_m.size)

    @property
    def friction_utilisation(self) -> float:
        """Friction force over friction available, maximum over the period [-]: 1 where it slides."""
        c, f = self.capacity_N, np.abs(self.friction_force_N)
        with np.errstate(divide="ignore", invalid="ignore"):
            ratio = np.where(c > 0, f / np.where(c > 0, c, 1.0), 0.0)
        ratio = np.where(self.sliding, 1.0, np.minimum(ratio, 1.0))
        return float(np.max(ratio)) if ratio.size else 0.0

    @property
    def axial_force_N(self) -> float:
        """Largest axial force of the lashings and stoppers together on the cargo [N] (magnitude)."""
        return float(np.max(np.abs(self.lashing_force_N + self.stopper_force_N))) if self.displacement_m.size else 0.0

    def on_grid(self, time_samples: int) -> AxialResponse:
        """The response at ``time_samples`` points of the period (a divisor of N: every (N / n)-th sample)."""
        n = self.time_samples
        if time_samples == n:
            return self
        if n % time_samples:
            raise ValueError(f"AxialResponse: {time_samples} samples do not divide the solution's {n}")
        step = n // time_samples
        pick = {
            name: getattr(self, name)[::step]
            for name in (
                "displacement_m",
                "velocity_m_per_s",
                "friction_force_N",
                "capacity_N",
                "lashing_force_N",
                "stopper_force_N",
                "load_N",
                "sliding",
            )
        }
        return replace(self, **pick)


def static_response(restraint: AxialRestraint, load_N: float, capacity_N: float, omega_rad_s: float, time_samples: int) -> AxialResponse:
    """A time-invariant state (still water), the rigid-Coulomb statics: stuck if ``|F| <= C``.

    A constant load above the friction has no static state: the cargo slides in still water
    (then ``converged=False``, infinite slip, the friction at its capacity against the load).
    """
    z = np.zeros(time_samples)
    full = np.full(time_samples, 1.0)
    holds = abs(load_N) <= capacity_N
    return AxialResponse(
        "statics",
        omega_rad_s,
        z,
        z.copy(),
        (-load_N if holds else -math.copysign(capacity_N, load_N)) * full,
        capacity_N * full,
        z.copy(),
        z.copy(),
        load_N * full,
        np.full(time_samples, not holds),
        0.0 if holds else math.inf,
        holds,
        0.0 if holds else math.nan,
        0,
        "stuck (statics)" if holds else "the still-water axial load exceeds the friction: the cargo slides in still water",
    )
