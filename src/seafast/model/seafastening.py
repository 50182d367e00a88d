"""Sea-fastening definition: saddles (compression-only) and lashings (linear, pretensioned)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

__all__ = ["SeaFastening", "BASE_LASHING"]


@dataclass(frozen=True)
class LashingReference:
    """Base-case lashing values (docs/theory.md#22-sea-fastening): wire stiffness and the springs it gives."""

    wire_stiffness_N_per_m: float = 37.5e3
    vertical_stiffness_N_per_m: float = 6.5e3
    rotational_stiffness_Nm_per_rad: float = 1.46e6


BASE_LASHING = LashingReference()


@dataclass(frozen=True)
class SeaFastening:
    """Saddles and lashings, positions along the cargo from its aft end.

    Parameters
    ----------
    saddle_x_m
        Saddle positions along the cargo [m], strictly increasing.
    saddle_stiffness_N_per_m
        Compression stiffness of each saddle [N/m] (the whole saddle, lashing included).
    lashed
        Which saddles carry lashings (default rule: the two outermost).
    lashing_wire_stiffness_N_per_m
        k_l [N/m]; the vertical and rotational springs per lashed saddle scale with it from the
        base values k_z = 6.5 kN/m and k_theta = 1.46 MN m/rad at k_l = 37.5 kN/m.
    lashing_pretension_N
        Total pretension T_l [N], shared equally by the lashed saddles and applied as a
        downward force on the cargo there (wires taken as near-vertical).
    """

    saddle_x_m: NDArray[np.float64]
    saddle_stiffness_N_per_m: NDArray[np.float64]
    lashed: NDArray[np.bool_]
    lashing_wire_stiffness_N_per_m: float = BASE_LASHING.wire_stiffness_N_per_m
    lashing_pretension_N: float = 210e3

    @property
    def saddle_count(self) -> int:
        return int(np.asarray(self.saddle_x_m).size)

    @property
    def lashing_vertical_stiffness_N_per_m(self) -> NDArray[np.float64]:
        """k_z at each saddle [N/m] (0 where unlashed)."""
        kz = self.lashing_wire_stiffness_N_per_m * (BASE_LASHING.vertical_stiffness_N_per_m / BASE_LASHING.wire_stiffness_N_per_m)
        return np.where(self.lashed, kz, 0.0)

    @property
    def lashing_rotational_stiffness_Nm_per_rad(self) -> NDArray[np.float64]:
        """k_theta at each saddle [N m/rad] (0 where unlashed)."""
        kt = self.lashing_wire_stiffness_N_per_m * (BASE_LASHING.rotational_stiffness_Nm_per_rad / BASE_LASHING.wire_stiffness_N_per_m)
        return np.where(self.lashed, kt, 0.0)

    @property
    def saddle_pretension_N(self) -> NDArray[np.float64]:
        """Downward pretension force at each saddle [N] (0 where unlashed)."""
        n = max(int(np.count_nonzero(self.lashed)), 1)
        return np.where(self.lashed, self.lashing_pretension_N / n, 0.0)

    @property
    def unilateral_stiffness_N_per_m(self) -> NDArray[np.float64]:
        """Compression-only part of each saddle [N/m]: k_sad - k_z at lashed saddles (docs/theory.md#22-sea-fastening).

        Never negative: where k_z exceeds the saddle stiffness the lashing carries it all.
        """
        return np.maximum(self.saddle_stiffness_N_per_m - self.lashing_vertical_stiffness_N_per_m, 0.0)
