"""The common result of the axial solvers, and the stick statics (docs/axial.md).

Sign conventions: ``u`` the cargo's axial displacement relative to the deck, forward +; every
force is the force *on the cargo*, forward +; the axial load ``F(t)`` is the inertia and gravity
load in the ship's frame (:mod:`seafast.excitation.axial`).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import NDArray

from seafast.model.axial import AxialRestraint

__all__ = ["AxialResponse", "critical_friction_coefficient", "periodic_interpolation"]


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
    options: dict[str, Any] = field(default_factory=dict)

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
        return AxialResponse(
            self.method,
            self.omega_rad_s,
            slip_m=self.slip_m,
            converged=self.converged,
            residual_norm=self.residual_norm,
            iterations=self.iterations,
            message=self.message,
            harmonics=self.harmonics,
            options=self.options,
            **pick,
        )


def static_response(restraint: AxialRestraint, load_N: float, capacity_N: float, omega_rad_s: float, time_samples: int) -> AxialResponse:
    """A time-invariant state (still water): stuck if ``|F| <= C``; the rigid-Coulomb statics."""
    if abs(load_N) > capacity_N:
        raise ValueError("static_response: a constant load above the friction capacity has no static state")
    z = np.zeros(time_samples)
    full = np.full(time_samples, 1.0)
    return AxialResponse(
        "statics",
        omega_rad_s,
        z,
        z.copy(),
        -load_N * full,
        capacity_N * full,
        z.copy(),
        z.copy(),
        load_N * full,
        np.zeros(time_samples, dtype=bool),
        0.0,
        True,
        0.0,
        0,
        "stuck (statics)",
    )
