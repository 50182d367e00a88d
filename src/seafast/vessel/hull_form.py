"""Parametric and tabulated hull forms.

The hull is described by its waterline breadth along the ship and a constant section-area
coefficient; sections are wall-sided (vertical sides near the waterline), so the immersed
sectional area at local draught ``d`` is ``C_s * b(x) * d``. This is the "tapered box" of
early-design hydrodynamics: simple, exact for hydrostatics of barge-like heavy-lift hulls and
the same geometry feeds both the hull-girder buoyancy and the BEM panel mesh.

Coordinates: x along the ship from the aft perpendicular (AP), forward positive, in metres.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import overload

import numpy as np
from numpy.typing import NDArray

__all__ = ["HullForm"]


@dataclass(frozen=True)
class HullForm:
    """Waterline breadth table of a wall-sided hull.

    Parameters
    ----------
    station_x_m
        Stations along the ship from the AP [m], strictly increasing, first 0, last L.
    waterline_breadth_m
        Waterline breadth at each station [m], non-negative.
    draft_m
        Design (even-keel) draught [m].
    section_area_coefficient
        Immersed sectional area divided by breadth x draught [-] (1 for a box).
    """

    station_x_m: NDArray[np.float64]
    waterline_breadth_m: NDArray[np.float64]
    draft_m: float
    section_area_coefficient: float = 1.0
    # design-draught integrals by quadrature size: the hull is immutable, and the loading and
    # motions ask for them at every loading (each point of a cargo study)
    _integrals: dict[tuple[str, int], float] = field(default_factory=dict, init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        x = np.asarray(self.station_x_m, dtype=float)
        b = np.asarray(self.waterline_breadth_m, dtype=float)
        if x.ndim != 1 or x.shape != b.shape or x.size < 2:
            raise ValueError("hull form: station_x_m and waterline_breadth_m must be 1-D arrays of equal length >= 2")
        if np.any(np.diff(x) <= 0):
            raise ValueError("hull form: station_x_m must be strictly increasing")
        if np.any(b < 0) or not np.all(np.isfinite(b)):
            raise ValueError("hull form: waterline_breadth_m must be finite and >= 0")
        if not (self.draft_m > 0):
            raise ValueError(f"hull form: draft_m = {self.draft_m!r}; must be > 0")
        object.__setattr__(self, "station_x_m", x)
        object.__setattr__(self, "waterline_breadth_m", b)

    # ------------------------------------------------------------------ constructors
    @classmethod
    def tapered_box(
        cls,
        length_m: float,
        breadth_m: float,
        draft_m: float,
        block_coefficient: float,
        *,
        stern_breadth_fraction: float = 0.7,
        aft_run_fraction: float = 0.2,
        bow_breadth_fraction: float = 0.0,
    ) -> HullForm:
        """Box hull with a parallel mid-body and linear tapers in breadth to stern and bow.

        The aft run (length ``aft_run_fraction * L``) tapers from full breadth to
        ``stern_breadth_fraction * B`` at the AP (a broad transom, typical of heavy-lift
        vessels); the fore run tapers to ``bow_breadth_fraction * B`` at the FP. The fore run
        length is solved so that the displaced volume is ``C_b * L * B * T``.

        Raises
        ------
        ValueError
            If no parallel mid-body can reach the requested block coefficient.
        """
        L, B, T, cb = float(length_m), float(breadth_m), float(draft_m), float(block_coefficient)
        aft_run = aft_run_fraction * L
        # breadth deficit (area below the full-breadth rectangle, divided by B), in metres
        deficit = L * (1.0 - cb)
        aft_deficit = aft_run * (1.0 - stern_breadth_fraction) / 2.0
        fore_run = (deficit - aft_deficit) / ((1.0 - bow_breadth_fraction) / 2.0)
        if not (0.0 < fore_run < L - aft_run):
            raise ValueError(
                f"hull form: block_coefficient = {cb:.4f} cannot be reached with "
                f"stern_breadth_fraction = {stern_breadth_fraction} and aft_run_fraction = "
                f"{aft_run_fraction} (fore run would be {fore_run:.1f} m of {L:.1f} m)"
            )
        x = np.array([0.0, aft_run, L - fore_run, L])
        b = B * np.array([stern_breadth_fraction, 1.0, 1.0, bow_breadth_fraction])
        return cls(station_x_m=x, waterline_breadth_m=b, draft_m=T)

    # ------------------------------------------------------------------ geometry
    @property
    def length_m(self) -> float:
        """Length between perpendiculars [m]."""
        return float(self.station_x_m[-1] - self.station_x_m[0])

    @property
    def breadth_m(self) -> float:
        """Maximum waterline breadth [m]."""
        return float(self.waterline_breadth_m.max())

    @overload
    def breadth_at(self, x_m: float) -> float: ...
    @overload
    def breadth_at(self, x_m: NDArray[np.float64]) -> NDArray[np.float64]: ...
    def breadth_at(self, x_m: NDArray[np.float64] | float) -> NDArray[np.float64] | float:
        """Waterline breadth [m] at positions ``x_m`` (piecewise-linear between stations; 0 outside)."""
        return np.interp(x_m, self.station_x_m, self.waterline_breadth_m, left=0.0, right=0.0)

    def sectional_area_at(
        self, x_m: NDArray[np.float64] | float, draft_m: NDArray[np.float64] | float | None = None
    ) -> NDArray[np.float64]:
        """Immersed sectional area [m^2] at ``x_m`` for local draught ``draft_m`` (default: design).

        Negative local draught (section out of water) gives zero area.
        """
        d = self.draft_m if draft_m is None else draft_m
        return self.section_area_coefficient * self.breadth_at(x_m) * np.maximum(d, 0.0)

    def displaced_volume_m3(self, n: int = 2001) -> float:
        """Displaced volume at design even-keel draught [m^3]."""
        key = ("volume", int(n))
        if key not in self._integrals:
            x = np.linspace(self.station_x_m[0], self.station_x_m[-1], n)
            self._integrals[key] = float(np.trapezoid(self.sectional_area_at(x), x))
        return self._integrals[key]

    def block_coefficient(self) -> float:
        """Block coefficient C_b = V / (L B T) [-]."""
        return self.displaced_volume_m3() / (self.length_m * self.breadth_m * self.draft_m)

    def centre_of_buoyancy_x_m(self, n: int = 2001) -> float:
        """Longitudinal centre of buoyancy at design draught, from the AP [m]."""
        key = ("lcb", int(n))
        if key not in self._integrals:
            x = np.linspace(self.station_x_m[0], self.station_x_m[-1], n)
            a = self.sectional_area_at(x)
            self._integrals[key] = float(np.trapezoid(a * x, x) / np.trapezoid(a, x))
        return self._integrals[key]
