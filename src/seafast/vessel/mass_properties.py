"""The loaded ship's mass properties in three dimensions: KG, roll, pitch and yaw inertia (docs/headings.md#3-the-loaded-ship).

:mod:`seafast.vessel.loading` spreads the weights along the ship; the roll of a ship in oblique seas also needs where they
sit in height and across the deck. The documented defaults place them:

* **lightship** at ``LIGHTSHIP_VCG_FRACTION`` (0.70) of the moulded depth above the keel, with its own roll radius of
  gyration ``LIGHTSHIP_ROLL_RADIUS_FRACTION`` (0.35) of the breadth, and for yaw spread evenly across the breadth;
* **cargo** (the item called ``cargo``): the units abreast on their lanes (``lanes_y_m``, symmetric), their axes at
  ``cargo_vcg_m`` above the keel (deck + saddle height + half the diameter), each with its own radius of gyration about
  its axis;
* **every other item** (ballast, consumables) on the centreline at ``BALLAST_VCG_FRACTION`` (0.20) of the depth, spread
  evenly across the breadth (double bottom and lower wing tanks).

Pitch keeps the longitudinal distribution alone (``sum m (x - x_G)^2``, as the heave-pitch model does); yaw adds the
transverse spread to it; roll is ``sum m ((y - y_G)^2 + (z - z_G)^2)`` plus each item's own part. Products of inertia
are neglected (the loading is symmetric about the centreline).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from seafast.vessel.loading import VesselLoading, mass_distribution_kg_per_m

__all__ = [
    "LIGHTSHIP_VCG_FRACTION",
    "LIGHTSHIP_ROLL_RADIUS_FRACTION",
    "BALLAST_VCG_FRACTION",
    "LoadedShipProperties",
    "loaded_ship_properties",
]

LIGHTSHIP_VCG_FRACTION = 0.70
"""Lightship KG over the moulded depth [-]: cargo ships' lightship KG lies at about 0.55-0.75 D in preliminary design
(e.g. D. G. M. Watson, *Practical Ship Design*, 1998, ch. 4); heavy-lift cranes and a strengthened open deck put it at
the upper part of the range: 0.70 D = 8.4 m on the 12 m deep base vessel."""

LIGHTSHIP_ROLL_RADIUS_FRACTION = 0.35
"""Roll radius of gyration of the lightship about its own centre over the breadth [-]: the usual 0.30-0.40 B of ships
(e.g. J. M. J. Journée and W. W. Massie, *Offshore Hydromechanics*, 2001, ch. 6); its middle value."""

BALLAST_VCG_FRACTION = 0.20
"""KG of ballast (and every item but the cargo) over the moulded depth [-]: the base vessel's 16 700 t of ballast fill its
double bottom (about B/20 = 2.1 m high, some 12 000 t) and the lower wing tanks; 0.20 D = 2.4 m."""


@dataclass(frozen=True)
class LoadedShipProperties:
    """Mass, centre of gravity and radii of gyration of a loading (about the axes through its CoG).

    Attributes
    ----------
    mass_kg
        Total mass [kg].
    lcg_m, kg_m
        CoG x from the AP [m] and height above the keel [m] (y = 0: symmetric loading).
    roll_radius_m, pitch_radius_m, yaw_radius_m
        Radii of gyration about x, y and z through the CoG [m].
    """

    mass_kg: float
    lcg_m: float
    kg_m: float
    roll_radius_m: float
    pitch_radius_m: float
    yaw_radius_m: float


def loaded_ship_properties(
    loading: VesselLoading,
    *,
    length_m: float,
    breadth_m: float,
    depth_m: float,
    cargo_vcg_m: float,
    lanes_y_m: ArrayLike,
    cargo_radius_of_gyration_m: float,
) -> LoadedShipProperties:
    """The loaded ship's mass properties by the placement rules of the module docstring.

    Parameters
    ----------
    loading
        Lightship and items (the one called ``cargo`` holds all units abreast).
    length_m, breadth_m, depth_m
        Ship length (the x grid of the pitch integral), breadth and moulded depth [m].
    cargo_vcg_m
        Height of the cargo units' axes above the keel [m].
    lanes_y_m
        y of each unit's axis [m] (+ to port); their mean must be 0 (no heel).
    cargo_radius_of_gyration_m
        A unit's own radius of gyration about its axis [m] (``sqrt((R_o^2 + R_i^2) / 2)`` for a tube).

    Raises
    ------
    ValueError
        Lanes off the centreline on average (the ship would heel), or a non-positive total mass.
    """
    lanes = np.atleast_1d(np.asarray(lanes_y_m, dtype=float))
    if abs(float(lanes.mean())) > 1e-9 * max(1.0, breadth_m):
        raise ValueError(f"loaded ship: cargo lanes {lanes.tolist()} m are not symmetric about the centreline (the ship would heel)")
    parts = _parts(loading, breadth_m, depth_m, cargo_vcg_m, lanes, cargo_radius_of_gyration_m)
    mass = sum(m for m, *_ in parts)
    if not mass > 0:
        raise ValueError(f"loaded ship: total mass {mass!r} kg; must be > 0")
    kg = sum(m * z for m, z, *_ in parts) / mass
    i_xx = sum(m * ((z - kg) ** 2 + y2 + own) for m, z, y2, own, _ in parts)
    x = np.linspace(0.0, length_m, 4001)
    m_x = mass_distribution_kg_per_m(x, loading)
    lcg = float(np.trapezoid(m_x * x, x) / np.trapezoid(m_x, x))
    i_long = float(np.trapezoid(m_x * (x - lcg) ** 2, x))
    i_lat = sum(m * y_spread for m, _, _, _, y_spread in parts)
    return LoadedShipProperties(
        mass_kg=float(mass),
        lcg_m=lcg,
        kg_m=float(kg),
        roll_radius_m=math.sqrt(i_xx / mass),
        pitch_radius_m=math.sqrt(i_long / mass),
        yaw_radius_m=math.sqrt((i_long + i_lat) / mass),
    )


def _parts(
    loading: VesselLoading, breadth_m: float, depth_m: float, cargo_vcg_m: float, lanes: np.ndarray, cargo_radius_m: float
) -> list[tuple[float, float, float, float, float]]:
    """Per part: (mass [kg], z [m], mean y^2 about the centreline [m^2], own roll part [m^2], mean y^2 for yaw [m^2])."""
    spread = breadth_m**2 / 12.0  # mean y^2 of a mass spread evenly across the breadth
    parts: list[tuple[float, float, float, float, float]] = []
    if loading.lightship is not None:
        ls = loading.lightship.mass_kg
        parts.append((ls, LIGHTSHIP_VCG_FRACTION * depth_m, 0.0, (LIGHTSHIP_ROLL_RADIUS_FRACTION * breadth_m) ** 2, spread))
    z_b = BALLAST_VCG_FRACTION * depth_m
    for item in loading.items:
        if item.name == "cargo":
            y2 = float(np.mean(lanes**2))
            parts.append((item.mass_kg, cargo_vcg_m, y2, cargo_radius_m**2, y2))
        else:
            # a layer across the breadth, 2 z_b high: its own roll part B^2/12 + (2 z_b)^2/12
            parts.append((item.mass_kg, z_b, 0.0, spread + (2.0 * z_b) ** 2 / 12.0, spread))
    return parts
