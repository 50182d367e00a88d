"""The cargo's axial degree of freedom and its restraints (docs/axial.md).

The cargo is a rigid body in the axial direction: one unknown, its displacement ``u`` along the
deck relative to the ship (forward +). A steel tube is axially far stiffer than anything that
restrains it (EA/L = 5.7e9 N/m for the base monopile, its first axial mode at ~220 rad/s
against waves at 0.2-1.8 rad/s), so its axial strain does not change how the load is shared.

Restraints, as forces on the cargo (forward +):

* Coulomb friction at the saddles, capacity ``C(t) = sum_i mu_i max(N_i(t), 0)`` with ``N_i``
  the saddle's contact (pad) force from the vertical solution. The saddles are linked through
  the rigid cargo, so with rigid contacts the cargo sticks as long as the force it needs stays
  within ``C(t)``. Where the method needs it (harmonic balance) the contacts have a tangential
  stiffness: one Jenkins element (spring ``k_t = sum_i k_t,i`` in series with a slider of
  capacity ``C(t)``) for the cargo as a whole.
* Lashings: a linear axial spring ``k_a`` (fore/aft wire pairs at ``angle`` from the deck:
  ``k_l cos^2(angle)`` per lashed saddle; their axial pretension components cancel).
* End stoppers (optional): unilateral springs ``k_s`` fore and aft with gap ``g``:
  ``-k_s (u - g)`` for ``u > g``, ``-k_s (u + g)`` for ``u < -g``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["AxialRestraint", "lashing_axial_stiffness_N_per_m"]


def lashing_axial_stiffness_N_per_m(wire_stiffness_N_per_m: float, angle_deg: float, lashed_saddles: int) -> float:
    """Total axial stiffness of the lashings [N/m]: ``n k_l cos^2(angle)``.

    Each lashed saddle's wires (stiffness ``k_l``) lean half forward, half aft at ``angle`` from
    the deck in the ship's vertical-longitudinal plane; an axial displacement ``u`` stretches one
    half and slackens the other by ``u cos(angle)`` along the wire, both resisting.
    """
    if not 0.0 < angle_deg <= 90.0:
        raise ValueError(f"lashing angle = {angle_deg} deg; allowed 0 < angle <= 90")
    return float(lashed_saddles) * float(wire_stiffness_N_per_m) * math.cos(math.radians(angle_deg)) ** 2


@dataclass(frozen=True)
class AxialRestraint:
    """Axial restraint of the rigid cargo (one unit).

    Parameters
    ----------
    cargo_mass_kg
        Mass of the cargo [kg].
    friction_coefficient
        Coulomb coefficient of each saddle [-], shape (n_s,), >= 0.
    tangential_stiffness_N_per_m
        Stick stiffness of each saddle's contact [N/m], shape (n_s,), > 0 (summed into the
        cargo-level Jenkins element).
    lashing_axial_stiffness_N_per_m
        Total axial stiffness of the lashings [N/m], >= 0.
    stopper_gap_m
        Gap to the stoppers fore and aft [m], or None (no stoppers).
    stopper_stiffness_N_per_m
        Stiffness of each stopper [N/m] (ignored without stoppers).
    damping_N_s_per_m
        Viscous damping of the axial motion [N s/m] (0 for the cargo; used by verification cases).
    """

    cargo_mass_kg: float
    friction_coefficient: NDArray[np.float64]
    tangential_stiffness_N_per_m: NDArray[np.float64]
    lashing_axial_stiffness_N_per_m: float = 0.0
    stopper_gap_m: float | None = None
    stopper_stiffness_N_per_m: float = 0.0
    damping_N_s_per_m: float = 0.0

    def __post_init__(self) -> None:
        mu = np.atleast_1d(np.asarray(self.friction_coefficient, dtype=float))
        kt = np.broadcast_to(np.asarray(self.tangential_stiffness_N_per_m, dtype=float), mu.shape).copy()
        checks = (
            ("cargo_mass_kg", self.cargo_mass_kg > 0 and math.isfinite(self.cargo_mass_kg), "> 0"),
            ("friction_coefficient", bool(np.all(np.isfinite(mu)) and np.all(mu >= 0)), ">= 0"),
            ("tangential_stiffness_N_per_m", bool(np.all(np.isfinite(kt)) and np.all(kt > 0)), "> 0"),
            (
                "lashing_axial_stiffness_N_per_m",
                math.isfinite(self.lashing_axial_stiffness_N_per_m) and self.lashing_axial_stiffness_N_per_m >= 0,
                ">= 0",
            ),
            ("damping_N_s_per_m", math.isfinite(self.damping_N_s_per_m) and self.damping_N_s_per_m >= 0, ">= 0"),
        )
        for name, ok, allowed in checks:
            if not ok:
                raise ValueError(f"AxialRestraint.{name} = {getattr(self, name)!r}; allowed {allowed}")
        if self.stopper_gap_m is not None and not (self.stopper_gap_m >= 0 and self.stopper_stiffness_N_per_m > 0):
            raise ValueError(
                f"AxialRestraint: stopper gap {self.stopper_gap_m!r} m and stiffness {self.stopper_stiffness_N_per_m!r} N/m; "
                "allowed gap >= 0 and stiffness > 0"
            )
        mu.setflags(write=False)
        kt.setflags(write=False)
        object.__setattr__(self, "friction_coefficient", mu)
        object.__setattr__(self, "tangential_stiffness_N_per_m", kt)

    @property
    def saddle_count(self) -> int:
        return int(self.friction_coefficient.size)

    @property
    def has_stoppers(self) -> bool:
        return self.stopper_gap_m is not None

    @property
    def stick_stiffness_N_per_m(self) -> float:
        """Stiffness of the cargo-level Jenkins spring ``sum_i k_t,i`` [N/m]."""
        return float(np.sum(self.tangential_stiffness_N_per_m))

    def capacity_N(self, normal_force_N: ArrayLike) -> NDArray[np.float64]:
        """Friction available ``sum_i mu_i max(N_i, 0)`` [N] for normal forces of shape (..., n_s)."""
        n = np.asarray(normal_force_N, dtype=float)
        return np.maximum(n, 0.0) @ self.friction_coefficient

    def saddle_shares(self, normal_force_N: ArrayLike) -> NDArray[np.float64]:
        """Each saddle's share of the cargo's friction force, ``mu_i N_i / C`` (equal shares where C = 0)."""
        n = np.maximum(np.asarray(normal_force_N, dtype=float), 0.0) * self.friction_coefficient
        total = n.sum(axis=-1, keepdims=True)
        with np.errstate(invalid="ignore", divide="ignore"):
            return np.where(total > 0, n / np.where(total > 0, total, 1.0), 1.0 / n.shape[-1])

    def restoring_force_N(self, u_m: ArrayLike) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Lashing and stopper forces resisting ``u`` (positive when they push the cargo aft) [N].

        Returns
        -------
        lashing, stopper
            Arrays of the shape of ``u_m``; the force *on the cargo* is their negative.
        """
        u = np.asarray(u_m, dtype=float)
        lashing = self.lashing_axial_stiffness_N_per_m * u
        if self.stopper_gap_m is None:
            return lashing, np.zeros_like(u)
        g, k = float(self.stopper_gap_m), float(self.stopper_stiffness_N_per_m)
        return lashing, k * (np.maximum(u - g, 0.0) + np.minimum(u + g, 0.0))

    def displacement_range_m(self, low_N: float, high_N: float) -> tuple[float, float]:
        """The displacements at which the lashings' and stoppers' force lies in ``[low_N, high_N]`` [m].

        The force ``r(u)`` resisting ``u`` (:meth:`restoring_force_N`: ``k_a u`` plus the
        stoppers') is continuous and non-decreasing, so ``{u : low <= r(u) <= high}`` is an
        interval ``[u_low, u_high]`` (``u_low > u_high`` when it is empty; infinite ends where
        nothing restrains the cargo that way: no lashings, no stoppers).
        """
        return self._inverse_restoring(float(low_N), lower=True), self._inverse_restoring(float(high_N), lower=False)

    def _inverse_restoring(self, force_N: float, lower: bool) -> float:
        """``min {u : r(u) >= f}`` (lower) or ``max {u : r(u) <= f}`` (upper) [m]."""
        ka = float(self.lashing_axial_stiffness_N_per_m)
        gap = math.inf if self.stopper_gap_m is None else float(self.stopper_gap_m)
        if ka == 0.0 and (force_N == 0.0 or gap == math.inf):
            if force_N == 0.0 and gap < math.inf:
                return -gap if lower else gap  # the free play between the stoppers
            # nothing restrains the cargo: r = 0 everywhere
            inside = force_N <= 0.0 if lower else force_N >= 0.0
            return (-math.inf if lower else math.inf) if inside else (math.inf if lower else -math.inf)
        if abs(force_N) <= ka * gap:
            return force_N / ka
        return math.copysign(gap + (abs(force_N) - ka * gap) / (ka + float(self.stopper_stiffness_N_per_m)), force_N)

    def stopper_tangent_N_per_m(self, u_m: ArrayLike) -> NDArray[np.float64]:
        """d(stopper force)/du [N/m]: ``k_s`` where a stopper is engaged, else 0."""
        u = np.asarray(u_m, dtype=float)
        if self.stopper_gap_m is None:
            return np.zeros_like(u)
        return np.where(np.abs(u) > self.stopper_gap_m, float(self.stopper_stiffness_N_per_m), 0.0)
