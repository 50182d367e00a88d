"""A frequency-response branch as continuation leaves it: its points and how it ended.

Units: SI, the unit in every name; compressions positive when the saddle is compressed.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from enum import Enum

import numpy as np
from numpy.typing import NDArray

from seafast.solvers.periodic import Settings

__all__ = ["BranchEnd", "FrequencyResponseBranch"]


class BranchEnd(Enum):
    """Why a frequency-response branch ended."""

    REACHED_END = "reached_end"
    """The branch reached ``omega_end``."""
    FIRST_POINT_FAILED = "first_point_failed"
    """The HBM solve at ``omega_start`` did not converge: no branch to follow."""
    STEP_BELOW_MIN = "step_below_min"
    """The corrector kept failing until the step fell below ``min_step`` (e.g. a sharp grazing fold)."""
    MAX_POINTS = "max_points"
    """``max_points`` points were recorded."""
    STOPPED = "stopped"
    """The caller's ``stop_when`` said stop (e.g. the branch left the physically meaningful range)."""


@dataclass(frozen=True)
class FrequencyResponseBranch:
    """Points of a frequency-response branch, in continuation order.

    Attributes
    ----------
    omega_rad_s
        Excitation frequency of each point [rad/s] (not monotonic past a fold).
    max_saddle_force_N
        Largest saddle contact force over the period and the saddles [N].
    max_gap_m
        Largest detachment ``max(-delta)`` [m] (0 while contact is preserved).
    max_cargo_deflection_m
        Largest |z| over the period and the cargo nodes [m] (static part included).
    converged
        Whether each point met the tolerance (or its round-off floor, see the module docstring).
    contact_preserved
        Whether every saddle stayed in contact over the whole period at each point.
    message
        How the sweep ended, for people.
    steps
        Predictor-corrector steps taken (accepted and rejected).
    options
        The HBM settings (``HBMOptions.to_dict``).
    end
        How the sweep ended (:class:`BranchEnd`).
    compression_harmonics_m
        Saddle compressions of each point, real harmonic layout (n_points, 2H+1, n_s) [m].
    tangent_omega
        Omega component of the unit tangent at each point, in the scaled variables [-]: positive
        where omega grows along the branch (near a fold, of the piece of the piecewise-linear
        sampled contact the point lies on: see :attr:`turning_indices`).
    residual_norm
        Relative residual of each point (max |R| over the compression scale) [-].
    at_fold
        Whether each point was located at a fold: where omega turned over two steps, the extreme of
        omega along the branch between them (:func:`seafast.solvers.continuation.frequency_response`).
    """

    omega_rad_s: NDArray[np.float64]
    max_saddle_force_N: NDArray[np.float64]
    max_gap_m: NDArray[np.float64]
    max_cargo_deflection_m: NDArray[np.float64]
    converged: NDArray[np.bool_]
    contact_preserved: NDArray[np.bool_]
    message: str = ""
    steps: int = 0
    options: Settings = field(default_factory=dict)
    end: BranchEnd = BranchEnd.REACHED_END
    compression_harmonics_m: NDArray[np.float64] = field(default_factory=lambda: np.zeros((0, 1, 1)))
    tangent_omega: NDArray[np.float64] = field(default_factory=lambda: np.zeros(0))
    residual_norm: NDArray[np.float64] = field(default_factory=lambda: np.zeros(0))
    at_fold: NDArray[np.bool_] = field(default_factory=lambda: np.zeros(0, dtype=bool))

    @property
    def time_samples(self) -> int | None:
        """N, the AFT samples of the branch's harmonic balance (from ``options``; None when not recorded)."""
        value = self.options.get("time_samples")
        return int(value) if isinstance(value, int) else None

    @property
    def truncation_tolerance(self) -> float | None:
        """The branch's harmonic balance ``truncation_tolerance`` [-] (from ``options``; None when not recorded)."""
        value = self.options.get("truncation_tolerance")
        return float(value) if isinstance(value, (int, float)) else None

    @property
    def peak_omega_rad_s(self) -> float:
        """Frequency of the largest cargo deflection on the branch [rad/s]."""
        return float(self.omega_rad_s[int(np.argmax(self.max_cargo_deflection_m))])

    @property
    def turning_indices(self) -> NDArray[np.intp]:
        """Indices i of the points where the branch turns: omega_i lies beyond both omega_(i-1) and omega_(i+1).

        Every such turn is a fold of the discrete branch (continuation locates it: ``at_fold``).
        The points' omega decides, not the tangent's omega component: with the exact contact law the
        sampled contact set changes along the branch, the residual is piecewise linear in the
        compressions, and near a fold the tangent of the piece a point lies on can point the other way
        than the branch does over a step.
        """
        dw = np.diff(self.omega_rad_s)
        return np.nonzero(dw[1:] * dw[:-1] < 0)[0] + 1

    @property
    def turning_omegas_rad_s(self) -> NDArray[np.float64]:
        """Frequency of each turn [rad/s]."""
        return np.asarray(self.omega_rad_s[self.turning_indices], dtype=float)
