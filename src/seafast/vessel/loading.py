"""The ship's longitudinal weight distribution: lightship, cargo and ballast.

Coordinates: x along the ship from the aft perpendicular (AP), forward positive [m]. Weights
are masses [kg] here; :func:`weight_distribution_N_per_m` turns them into a downward line load
[N/m] (reported as a positive magnitude).

Lightship (standard method)
---------------------------
The lightship mass is spread with the Prohaska-type trapezoidal distribution of preliminary
ship design (Prohaska 1947; the same construction as the Biles "three-part" curve; see e.g.
D. L. Hansch, *Methods of determining the longitudinal weight distribution of a ship*, SNAME
Hampton Roads 2008, or any longitudinal-strength text book): the length is split into thirds,
the middle third carries a constant ordinate ``b * w_mean`` and the end thirds are linear from
the end ordinates ``a_aft * w_mean`` (at the AP) and ``a_fore * w_mean`` (at the FP) up to
``b * w_mean``; ``w_mean = m_lightship / L``. For a centred LCG ``a_aft = a_fore = a`` and the
area condition gives ``b = (3 - a) / 2``; ``a = 0.75`` (``b = 1.125``) is the classical value
for full-bodied ships (tankers, bulk carriers, barge-like heavy-lift hulls), ``a`` of about
0.55-0.65 for fine cargo ships. An off-centre lightship LCG is met by making the end ordinates
unequal, ``a_aft = a + delta``, ``a_fore = a - delta``, which keeps ``b`` and moves the centroid
by ``-7 delta L / 54`` (so ``delta = -54 (LCG - L/2) / (7 L)``); both end ordinates must stay
non-negative, i.e. ``|LCG - L/2| <= 7 a L / 54``.

Deadweight items
----------------
Cargo, ballast tanks, fuel, etc. are :class:`WeightItem` objects: a mass spread uniformly over
``[x_start_m, x_end_m]``. Monopiles carried side by side load the same x range, so they are one
item with the summed mass.

Ballast (documented choice)
---------------------------
Ballast is modelled as tank groups (weight items of given extent) whose masses are solved by
:func:`balance_ballast` from linear conditions at even keel on the design waterline:
total mass = displacement, LCG = LCB (the ship floats at even keel at its design draught), and,
with a third tank group, a prescribed still-water bending moment at one position. The latter is
what a loading officer does: the ballast plan is chosen to keep the hull girder in moderate
hogging. The base case (:func:`base_vessel_loading`) uses an aft, a midship (double-bottom
under the cargo) and a fore tank group.

Size: over 400 lines because it is one documented loading model (lightship, weight items,
ballast solve, the base case's loading) whose parts are used together, and about half of it is
the docstrings that give each choice its source.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace
from itertools import pairwise

import numpy as np
from numpy.typing import NDArray

from seafast.vessel.hull_form import HullForm

__all__ = [
    "WeightItem",
    "LightshipDistribution",
    "VesselLoading",
    "BallastTank",
    "monopile_mass_kg",
    "mass_distribution_kg_per_m",
    "weight_distribution_N_per_m",
    "still_water_moment_even_keel_Nm",
    "balance_ballast",
    "base_vessel_loading",
    "BASE_LENGTH_M",
    "BASE_BREADTH_M",
    "BASE_DRAFT_M",
    "BASE_DISPLACED_VOLUME_M3",
    "BASE_WATER_DENSITY_KG_PER_M3",
    "BASE_LIGHTSHIP_FRACTION",
    "BASE_LIGHTSHIP_LCG_FRACTION",
    "BASE_STILL_WATER_MOMENT_NM",
    "base_hull_form",
]

FloatArray = NDArray[np.float64]

# ---------------------------------------------------------------------------- base vessel
BASE_LENGTH_M = 171.0
"""Length between perpendiculars of the base (MC-class heavy-lift) vessel [m]."""
BASE_BREADTH_M = 42.0
"""Moulded breadth of the base vessel [m]."""
BASE_DRAFT_M = 6.5
"""Design draught of the base vessel [m]."""
BASE_DISPLACED_VOLUME_M3 = 32000.0
"""Displaced volume of the base vessel at the design draught [m^3] (C_b = 0.686)."""
BASE_WATER_DENSITY_KG_PER_M3 = 1025.0
"""Sea-water density [kg/m^3]."""
BASE_LIGHTSHIP_FRACTION = 0.35
"""Lightship mass / displacement of the base vessel [-].

Heavy-lift and semi-submersible heavy-transport vessels are built strong and heavy (cranes,
strengthened open deck, large ballast capacity); their lightship is typically 30-40 % of the
design displacement (deadweight/displacement 0.6-0.7). The source does not publish it; 35 %
(11 480 t of 32 800 t) is the middle of that range.
"""
BASE_LIGHTSHIP_LCG_FRACTION = 0.46
"""Lightship LCG of the base vessel as a fraction of L from the AP [-]: engine room aft,
cranes and deckhouse forward of it, roughly balanced slightly aft of midship."""
BASE_PROHASKA_END_ORDINATE = 0.75
"""Mean Prohaska end ordinate (fraction of the mean lightship weight per metre) of the base
vessel: the full-bodied value (the hull is barge-like, C_b = 0.69)."""
BASE_STILL_WATER_MOMENT_NM = -4.725e8
"""Still-water bending moment at the cargo midpoint the base ballast plan is set to [N m]
(hogging negative).

Chosen as the calibration of the source's static result (docs/theory.md#32-hull-form-and-weight-distribution: middle saddle
most loaded, F = 6.3 MN, M_b = 49.3 MNm need the deck under the middle saddle ~5.75 mm above
the mean of the deck under the outer saddles, 22.2 m either side). With the default hull
girder (I = 103.8 m^4, A_s = 0.8 m^2, steel) this moment gives that deck rise; it is a
moderate hogging moment, about 30 % of the IACS UR S11 hogging wave moment of the vessel.
"""
BASE_MONOPILE_LENGTH_M = 74.0
BASE_MONOPILE_DIAMETER_M = 8.0
BASE_MONOPILE_WALL_M = 0.080
BASE_MONOPILE_DENSITY_KG_PER_M3 = 7850.0
BASE_MONOPILES_ABREAST = 4
BASE_BALLAST_TANKS_FRACTION: tuple[tuple[str, float, float], ...] = (
    ("ballast aft", 0.02, 0.22),
    ("ballast midship (double bottom under cargo)", 0.30, 0.70),
    ("ballast fore", 0.74, 0.94),
)
"""Ballast tank groups of the base vessel: name, start and end as fractions of L from the AP."""


# ---------------------------------------------------------------------------- items
@dataclass(frozen=True)
class WeightItem:
    """A mass spread uniformly over ``[x_start_m, x_end_m]``.

    Parameters
    ----------
    name
        Label (e.g. ``"cargo: 4 monopiles"``).
    x_start_m, x_end_m
        Aft and fore end of the item from the AP [m], ``x_end_m > x_start_m``.
    mass_kg
        Mass [kg], >= 0.
    """

    name: str
    x_start_m: float
    x_end_m: float
    mass_kg: float

    def __post_init__(self) -> None:
        if not (np.isfinite(self.x_start_m) and np.isfinite(self.x_end_m) and self.x_end_m > self.x_start_m):
            raise ValueError(f"weight item {self.name!r}: x_end_m = {self.x_end_m!r} must be > x_start_m = {self.x_start_m!r}")
        if not (np.isfinite(self.mass_kg) and self.mass_kg >= 0):
            raise ValueError(f"weight item {self.name!r}: mass_kg = {self.mass_kg!r}; must be finite and >= 0")

    @property
    def length_m(self) -> float:
        """Extent of the item [m]."""
        return float(self.x_end_m - self.x_start_m)

    @property
    def lcg_m(self) -> float:
        """Longitudinal centre of gravity from the AP [m]."""
        return 0.5 * (self.x_start_m + self.x_end_m)

    def mass_per_length_kg_per_m(self, x_m: FloatArray | float) -> FloatArray:
        """Mass per metre [kg/m] at ``x_m`` (uniform on ``[x_start, x_end)``, zero outside)."""
        x = np.asarray(x_m, dtype=float)
        inside = (x >= self.x_start_m) & (x < self.x_end_m)
        return np.where(inside, self.mass_kg / self.length_m, 0.0)


@dataclass(frozen=True)
class LightshipDistribution:
    """Prohaska-type trapezoidal lightship distribution (see the module docstring).

    Parameters
    ----------
    mass_kg
        Lightship mass [kg].
    lcg_m
        Lightship LCG from the AP [m].
    length_m
        Length over which the lightship is spread, AP to FP [m].
    end_ordinate_fraction
        Mean of the two end ordinates ``a`` as a fraction of the mean weight per metre [-]
        (0 < a < 3); the middle-third ordinate is ``b = (3 - a) / 2``.
    """

    mass_kg: float
    lcg_m: float
    length_m: float
    end_ordinate_fraction: float = 0.75

    def __post_init__(self) -> None:
        if not (self.mass_kg >= 0 and np.isfinite(self.mass_kg)):
            raise ValueError(f"lightship: mass_kg = {self.mass_kg!r}; must be finite and >= 0")
        if not (self.length_m > 0):
            raise ValueError(f"lightship: length_m = {self.length_m!r}; must be > 0")
        a = self.end_ordinate_fraction
        if not (0.0 <= a < 3.0):
            raise ValueError(f"lightship: end_ordinate_fraction = {a!r}; must be in [0, 3)")
        limit = 7.0 * a * self.length_m / 54.0
        if abs(self.lcg_m - 0.5 * self.length_m) > limit * (1 + 1e-12):
            raise ValueError(
                f"lightship: lcg_m = {self.lcg_m!r} is more than 7 a L / 54 = {limit:.2f} m from midship; "
                "the trapezoidal distribution would need a negative end ordinate"
            )

    @property
    def end_ordinates(self) -> tuple[float, float]:
        """(a_aft, a_fore): end ordinates at the AP and FP as fractions of the mean [-]."""
        delta = -54.0 * (self.lcg_m - 0.5 * self.length_m) / (7.0 * self.length_m)
        a = self.end_ordinate_fraction
        return a + delta, a - delta

    @property
    def middle_ordinate(self) -> float:
        """Ordinate of the middle third as a fraction of the mean [-]."""
        return (3.0 - self.end_ordinate_fraction) / 2.0

    @property
    def breakpoints_m(self) -> tuple[float, ...]:
        """Positions where the distribution has a kink [m]."""
        L = self.length_m
        return (0.0, L / 3.0, 2.0 * L / 3.0, L)

    def mass_per_length_kg_per_m(self, x_m: FloatArray | float) -> FloatArray:
        """Lightship mass per metre [kg/m] at ``x_m`` (zero outside ``[0, L]``)."""
        L = self.length_m
        w = self.mass_kg / L
        a_aft, a_fore = self.end_ordinates
        b = self.middle_ordinate
        xs = np.array([0.0, L / 3.0, 2.0 * L / 3.0, L])
        ys = w * np.array([a_aft, b, b, a_fore])
        return np.interp(np.asarray(x_m, dtype=float), xs, ys, left=0.0, right=0.0)


@dataclass(frozen=True)
class VesselLoading:
    """A loading condition: lightship plus deadweight items.

    Parameters
    ----------
    lightship
        Lightship distribution, or ``None`` (all mass given as items).
    items
        Deadweight items (cargo, ballast, consumables).
    """

    lightship: LightshipDistribution | None
    items: tuple[WeightItem, ...] = field(default_factory=tuple)

    def __post_init__(self) -> None:
        object.__setattr__(self, "items", tuple(self.items))

    @property
    def total_mass_kg(self) -> float:
        """Total mass (displacement) of the condition [kg]."""
        m = sum(it.mass_kg for it in self.items)
        return float(m + (self.lightship.mass_kg if self.lightship is not None else 0.0))

    @property
    def lcg_m(self) -> float:
        """Longitudinal centre of gravity from the AP [m]."""
        mom = sum(it.mass_kg * it.lcg_m for it in self.items)
        m = sum(it.mass_kg for it in self.items)
        if self.lightship is not None:
            mom += self.lightship.mass_kg * self.lightship.lcg_m
            m += self.lightship.mass_kg
        return float(mom / m)

    @property
    def breakpoints_m(self) -> tuple[float, ...]:
        """Sorted positions where the distribution is discontinuous or kinked [m]."""
        pts: list[float] = []
        if self.lightship is not None:
            pts.extend(self.lightship.breakpoints_m)
        for it in self.items:
            pts.extend((it.x_start_m, it.x_end_m))
        return tuple(sorted({float(p) for p in pts}))

    def with_items(self, *items: WeightItem) -> VesselLoading:
        """A copy with ``items`` appended."""
        return replace(self, items=self.items + tuple(items))

    def item(self, name: str) -> WeightItem:
        """The item called ``name`` (KeyError if absent)."""
        for it in self.items:
            if it.name == name:
                return it
        raise KeyError(name)


@dataclass(frozen=True)
class BallastTank:
    """Extent of a ballast tank group whose mass :func:`balance_ballast` solves for [m from AP]."""

    name: str
    x_start_m: float
    x_end_m: float


# ---------------------------------------------------------------------------- distributions
def monopile_mass_kg(length_m: float, diameter_m: float, wall_thickness_m: float, density_kg_per_m3: float = 7850.0) -> float:
    """Mass [kg] of a uniform thin-walled steel tube (monopile).

    ``m = rho * pi / 4 * (D^2 - (D - 2 t)^2) * L``; 74 m x 8 m x 0.080 m gives 1.156e6 kg.
    """
    D, t = float(diameter_m), float(wall_thickness_m)
    return float(density_kg_per_m3 * np.pi / 4.0 * (D * D - (D - 2.0 * t) ** 2) * length_m)


def mass_distribution_kg_per_m(x_m: FloatArray | float, loading: VesselLoading) -> FloatArray:
    """Mass per metre [kg/m] of ``loading`` at positions ``x_m``.

    At a discontinuity (item end) the value is the one on the forward side (items cover
    ``[x_start, x_end)``).
    """
    x = np.asarray(x_m, dtype=float)
    out = np.zeros_like(x)
    if loading.lightship is not None:
        out = out + loading.lightship.mass_per_length_kg_per_m(x)
    for it in loading.items:
        out = out + it.mass_per_length_kg_per_m(x)
    return out


def weight_distribution_N_per_m(x_m: FloatArray | float, loading: VesselLoading, gravity_m_per_s2: float = 9.81) -> FloatArray:
    """Weight per metre [N/m] of ``loading`` at ``x_m`` (a positive number acting downward)."""
    return gravity_m_per_s2 * mass_distribution_kg_per_m(x_m, loading)


# ---------------------------------------------------------------------------- exact quadrature
_GL_X, _GL_W = np.polynomial.legendre.leggauss(6)


def _integrate(
    fun: Callable[[NDArray[np.float64]], NDArray[np.float64]], a: float, b: float, breakpoints: Sequence[float], max_segment_m: float = 2.0
) -> float:
    """Integral of ``fun`` on [a, b] by Gauss-Legendre on segments split at ``breakpoints``.

    Exact (to round-off) for piecewise polynomials of degree <= 11 between breakpoints.
    """
    if b <= a:
        return 0.0
    pts = np.array(sorted({a, b, *[p for p in breakpoints if a < p < b]}))
    edges = [pts[0]]
    for p0, p1 in pairwise(pts):
        n = max(1, int(np.ceil((p1 - p0) / max_segment_m)))
        edges.extend(np.linspace(p0, p1, n + 1)[1:])
    e = np.asarray(edges)
    mid = 0.5 * (e[:-1] + e[1:])
    half = 0.5 * np.diff(e)
    xq = (mid[:, None] + half[:, None] * _GL_X[None, :]).ravel()
    wq = (half[:, None] * _GL_W[None, :]).ravel()
    return float(np.sum(wq * fun(xq)))


def still_water_moment_even_keel_Nm(
    hull: HullForm,
    loading: VesselLoading,
    x_m: float,
    *,
    water_density_kg_per_m3: float = 1025.0,
    gravity_m_per_s2: float = 9.81,
) -> float:
    """Still-water bending moment [N m] at ``x_m`` with the ship at even keel on its design draught.

    ``M(x) = int_0^x (x - xi) (b(xi) - w(xi)) dxi`` with buoyancy ``b`` and weight ``w`` per
    metre; sagging positive, hogging negative. Exact only when the loading is balanced at even
    keel on the design draught (total mass = design displacement, LCG = LCB).
    """
    bp = tuple(hull.station_x_m) + loading.breakpoints_m
    rg = water_density_kg_per_m3 * gravity_m_per_s2

    def q(x: FloatArray) -> FloatArray:
        return rg * hull.sectional_area_at(x) - weight_distribution_N_per_m(x, loading, gravity_m_per_s2)

    x0 = float(hull.station_x_m[0])
    return _integrate(lambda x: (x_m - x) * q(x), x0, float(x_m), bp)


def _unit_tank_moments(hull: HullForm, tanks: tuple[tuple[float, float], ...], x_m: float, rho: float, g: float) -> NDArray[np.float64]:
    """Still-water moment at ``x_m`` of 1 kg in each tank (weight only; the even-keel buoyancy is fixed) [N m/kg]."""
    kw = dict(water_density_kg_per_m3=rho, gravity_m_per_s2=g)
    buoy_only = still_water_moment_even_keel_Nm(hull, VesselLoading(None, ()), x_m, **kw)
    return np.array(
        [
            still_water_moment_even_keel_Nm(hull, VesselLoading(None, (WeightItem("unit", a, b, 1.0),)), x_m, **kw) - buoy_only
            for a, b in tanks
        ]
    )


def balance_ballast(
    hull: HullForm,
    loading: VesselLoading,
    tanks: Sequence[BallastTank],
    *,
    water_density_kg_per_m3: float = 1025.0,
    gravity_m_per_s2: float = 9.81,
    moment_target: tuple[float, float] | None = None,
) -> VesselLoading:
    """Add ballast tank groups with masses that balance the ship at even keel on its design draught.

    Conditions (linear in the tank masses, so solved directly):

    1. total mass = design displacement ``rho * V(T)`` of ``hull``;
    2. LCG = LCB at the design draught (even keel);
    3. only if ``moment_target = (x_m, M_Nm)``: still-water bending moment at ``x_m`` equals
       ``M_Nm`` (hogging negative).

    ``tanks`` must hold exactly 2 (without target) or 3 (with target) tank groups.

    Returns
    -------
    VesselLoading
        ``loading`` with one :class:`WeightItem` per tank appended.

    Raises
    ------
    ValueError
        If the number of tanks does not match the conditions, the system is singular, or a
        tank mass comes out negative (the tank arrangement cannot balance this loading).
    """
    n_cond = 2 if moment_target is None else 3
    if len(tanks) != n_cond:
        raise ValueError(f"balance_ballast: {n_cond} conditions need {n_cond} tank groups, got {len(tanks)}")
    rho = water_density_kg_per_m3
    volume = hull.displaced_volume_m3(n=20001)
    lcb = hull.centre_of_buoyancy_x_m(n=20001)
    displacement = rho * volume
    A = np.zeros((n_cond, n_cond))
    rhs = np.zeros(n_cond)
    A[0, :] = 1.0
    rhs[0] = displacement - loading.total_mass_kg
    unit_items = [WeightItem(t.name, t.x_start_m, t.x_end_m, 1.0) for t in tanks]
    A[1, :] = [u.lcg_m - lcb for u in unit_items]
    m_fixed = loading.total_mass_kg
    rhs[1] = -(loading.lcg_m - lcb) * m_fixed
    if moment_target is not None:
        x_t, m_t = moment_target
        kw = dict(water_density_kg_per_m3=rho, gravity_m_per_s2=gravity_m_per_s2)
        base = still_water_moment_even_keel_Nm(hull, loading, x_t, **kw)
        A[2, :] = _unit_tank_moments(hull, tuple((u.x_start_m, u.x_end_m) for u in unit_items), float(x_t), rho, gravity_m_per_s2)
        rhs[2] = m_t - base
    try:
        masses = np.linalg.solve(A, rhs)
    except np.linalg.LinAlgError as exc:  # pragma: no cover - degenerate tank layout
        raise ValueError(f"balance_ballast: tank arrangement gives a singular system ({exc})") from exc
    if np.any(masses < 0):
        detail = ", ".join(f"{t.name}: {m:.4g} kg" for t, m in zip(tanks, masses, strict=True))
        raise ValueError(f"balance_ballast: negative ballast needed ({detail}); move or resize the tanks")
    new = tuple(WeightItem(t.name, t.x_start_m, t.x_end_m, float(m)) for t, m in zip(tanks, masses, strict=True))
    return loading.with_items(*new)


# ---------------------------------------------------------------------------- base case
def base_hull_form() -> HullForm:
    """Tapered-box hull of the base vessel (L 171 m, B 42 m, T 6.5 m, 32 000 m^3)."""
    cb = BASE_DISPLACED_VOLUME_M3 / (BASE_LENGTH_M * BASE_BREADTH_M * BASE_DRAFT_M)
    return HullForm.tapered_box(BASE_LENGTH_M, BASE_BREADTH_M, BASE_DRAFT_M, cb)


def base_vessel_loading(
    *,
    hull: HullForm | None = None,
    cargo_position_m: float | None = None,
    cargo_length_m: float = BASE_MONOPILE_LENGTH_M,
    cargo_mass_kg: float | None = None,
    lightship_mass_kg: float | None = None,
    lightship_lcg_m: float | None = None,
    still_water_moment_Nm: float | None = BASE_STILL_WATER_MOMENT_NM,
    water_density_kg_per_m3: float = BASE_WATER_DENSITY_KG_PER_M3,
    gravity_m_per_s2: float = 9.81,
) -> VesselLoading:
    """The documented default loading of the base vessel (MC-class heavy-lift, L 171 m).

    * Lightship: ``BASE_LIGHTSHIP_FRACTION`` (35 %) of the design displacement
      (0.35 x 1025 x 32 000 = 11 480 t), Prohaska trapezoid with mean end ordinate 0.75,
      LCG at 0.46 L from the AP.
    * Cargo: four 74 m x 8 m x 0.080 m steel monopiles abreast (4 x 1.156e6 kg), one uniform
      item from ``cargo_position_m - L_m/2`` to ``+ L_m/2``; default midpoint 0.5 L (midship).
    * Ballast: three tank groups (aft 0.02-0.22 L, midship double bottom 0.30-0.70 L, fore
      0.74-0.94 L) solved by :func:`balance_ballast` for total mass = displacement, LCG = LCB
      (even keel at T = 6.5 m) and the still-water moment ``still_water_moment_Nm`` at the cargo
      midpoint (default ``BASE_STILL_WATER_MOMENT_NM``, the calibration). With
      ``still_water_moment_Nm=None`` the midship tank group is dropped and the aft and fore
      groups alone balance the ship.

    Parameters
    ----------
    hull
        Hull form; default :func:`base_hull_form`.
    cargo_position_m
        x of the cargo midpoint from the AP [m]; default ``0.5 * L``.
    cargo_length_m, cargo_mass_kg
        Cargo extent [m] and total mass of all units abreast [kg] (default: the base case).
    lightship_mass_kg, lightship_lcg_m
        Override the lightship mass [kg] and LCG from the AP [m].
    still_water_moment_Nm
        Target still-water bending moment at the cargo midpoint [N m], hogging negative.
    water_density_kg_per_m3, gravity_m_per_s2
        Sea-water density and gravity.
    """
    hull = base_hull_form() if hull is None else hull
    L = hull.length_m
    displacement = water_density_kg_per_m3 * hull.displaced_volume_m3(n=20001)
    m_ls = BASE_LIGHTSHIP_FRACTION * displacement if lightship_mass_kg is None else float(lightship_mass_kg)
    lcg_ls = BASE_LIGHTSHIP_LCG_FRACTION * L if lightship_lcg_m is None else float(lightship_lcg_m)
    lightship = LightshipDistribution(m_ls, lcg_ls, L, BASE_PROHASKA_END_ORDINATE)
    xc = 0.5 * L if cargo_position_m is None else float(cargo_position_m)
    if cargo_mass_kg is None:
        cargo_mass_kg = BASE_MONOPILES_ABREAST * monopile_mass_kg(
            cargo_length_m, BASE_MONOPILE_DIAMETER_M, BASE_MONOPILE_WALL_M, BASE_MONOPILE_DENSITY_KG_PER_M3
        )
    cargo = WeightItem("cargo", xc - 0.5 * cargo_length_m, xc + 0.5 * cargo_length_m, float(cargo_mass_kg))
    loading = VesselLoading(lightship, (cargo,))
    tanks = [BallastTank(n, f0 * L, f1 * L) for n, f0, f1 in BASE_BALLAST_TANKS_FRACTION]
    if still_water_moment_Nm is None:
        return balance_ballast(
            hull,
            loading,
            [tanks[0], tanks[2]],
            water_density_kg_per_m3=water_density_kg_per_m3,
            gravity_m_per_s2=gravity_m_per_s2,
        )
    return balance_ballast(
        hull,
        loading,
        tanks,
        water_density_kg_per_m3=water_density_kg_per_m3,
        gravity_m_per_s2=gravity_m_per_s2,
        moment_target=(xc, float(still_water_moment_Nm)),
    )
