"""Cross-sections of the cargo: thin- and thick-walled circular tubes, uniform or piecewise.

A monopile is a circular steel tube; real ones taper and change wall thickness along their
length. seafast describes the cargo as a chain of segments, each with outer diameter varying
linearly from its start to its end and a constant wall thickness. Section properties are
exact for the annulus (not thin-wall approximations).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

__all__ = ["TubeSegment", "tube_area_m2", "tube_second_moment_m4", "CargoGeometry"]


def tube_area_m2(outer_diameter_m: NDArray | float, wall_thickness_m: NDArray | float) -> NDArray:
    """Steel area of a circular tube, A = pi/4 (D^2 - (D - 2t)^2) [m^2]."""
    D = np.asarray(outer_diameter_m, dtype=float)
    t = np.asarray(wall_thickness_m, dtype=float)
    return np.pi / 4.0 * (D**2 - (D - 2.0 * t) ** 2)


def tube_second_moment_m4(outer_diameter_m: NDArray | float, wall_thickness_m: NDArray | float) -> NDArray:
    """Second moment of area of a circular tube, I = pi/64 (D^4 - (D - 2t)^4) [m^4]."""
    D = np.asarray(outer_diameter_m, dtype=float)
    t = np.asarray(wall_thickness_m, dtype=float)
    return np.pi / 64.0 * (D**4 - (D - 2.0 * t) ** 4)


@dataclass(frozen=True)
class TubeSegment:
    """One segment of a piecewise tube, from ``x_start_m`` to ``x_end_m`` along the cargo [m].

    The outer diameter varies linearly from ``outer_diameter_start_m`` to
    ``outer_diameter_end_m``; the wall thickness is constant.
    """

    x_start_m: float
    x_end_m: float
    outer_diameter_start_m: float
    outer_diameter_end_m: float
    wall_thickness_m: float


@dataclass(frozen=True)
class CargoGeometry:
    """Geometry and material of the cargo beam.

    Parameters
    ----------
    segments
        Contiguous tube segments covering [0, length] (x from the cargo's aft end) [m].
    youngs_modulus_Pa, density_kg_per_m3
        Steel properties.
    """

    segments: tuple[TubeSegment, ...]
    youngs_modulus_Pa: float = 210e9
    density_kg_per_m3: float = 7850.0
    poisson_ratio: float = 0.3

    @property
    def length_m(self) -> float:
        """Cargo length [m]."""
        return float(self.segments[-1].x_end_m - self.segments[0].x_start_m)

    @property
    def segment_boundaries_m(self) -> NDArray[np.float64]:
        """Positions of segment ends along the cargo [m]."""
        return np.array([self.segments[0].x_start_m] + [s.x_end_m for s in self.segments])

    def section_at(self, x_m: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Outer diameter and wall thickness [m] at positions ``x_m`` along the cargo.

        A point on a segment boundary takes the properties of the segment that starts there.
        """
        x = np.atleast_1d(np.asarray(x_m, dtype=float))
        D = np.empty_like(x)
        t = np.empty_like(x)
        starts = np.array([s.x_start_m for s in self.segments])
        idx = np.clip(np.searchsorted(starts, x, side="right") - 1, 0, len(self.segments) - 1)
        for i, seg in enumerate(self.segments):
            sel = idx == i
            frac = (x[sel] - seg.x_start_m) / (seg.x_end_m - seg.x_start_m)
            D[sel] = seg.outer_diameter_start_m + frac * (seg.outer_diameter_end_m - seg.outer_diameter_start_m)
            t[sel] = seg.wall_thickness_m
        return D, t

    def mass_kg(self, n: int = 4001) -> float:
        """Total mass of the cargo [kg] (numerical quadrature of rho A(x))."""
        x = np.linspace(0.0, self.length_m, n)
        D, t = self.section_at(x)
        return float(self.density_kg_per_m3 * np.trapezoid(tube_area_m2(D, t), x))
