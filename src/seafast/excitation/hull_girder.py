"""Hull-girder bending of the vessel in still water and on a regular wave (quasi-static).

The ship is a free-free Timoshenko beam loaded by ``q(x) = b(x) - w(x)`` [N/m] (buoyancy minus
weight, positive upward). Sections are wall-sided (see :class:`~seafast.vessel.hull_form.HullForm`),
so the buoyancy per metre is ``rho g C_s B(x) d(x)`` with the local draught

    d(x) = T + sinkage - trim (x - x_mid) + zeta(x)

where ``sinkage`` [m] is positive when the ship sinks deeper, ``trim`` [rad] is the ship's
pitch rotation, positive bow up (trim by the stern), ``x_mid = L/2`` and ``zeta`` the wave
elevation (zero in still water). Sinkage and trim are solved so that the buoyancy equals the
weight and LCB = LCG (the two conditions are linear in sinkage and trim while no section
emerges, so one Newton step is exact; emergence is handled by continuing Newton).

Sign conventions (seafast): x from the AP forward [m]; z up; deflection positive up;
slope = dz/dx; shear force ``V(x) = int_0^x q dx`` (net upward force on the part aft of x) [N];
bending moment ``M(x) = int_0^x V dx`` [N m], sagging positive, hogging negative, so that
``M'' = q`` and ``M = EI psi'``. Timoshenko kinematics: ``dz/dx = psi - V / (G A_s)`` so
``z'' = M / (E I) - q / (G A_s)``; the shear deflection of a free-free hull relative to the
chord through its ends is exactly ``-M(x) / (G A_s)``.

Definiteness (documented choice): a free-free beam under a self-equilibrated load has two
rigid-body modes. seafast fixes them by putting the deflection relative to the chord through
the hull's end points (AP and FP): ``z(AP) = z(FP) = 0``. In the FE model this is done by
constraining the two end deflection DOFs; because the load is self-equilibrated to round-off,
the constraint forces vanish and nothing else changes. Only differences along the deck matter
to the cargo; the rigid-body motion of the ship is handled separately (RAOs).

Discretisation: nodes at a uniform spacing plus every break point of the hull form and the
loading; within each element the load is linear between its end values (so discontinuities
of the weight at item ends are exact); shear force and bending moment are integrated exactly
for that load (so they vanish at both ends to round-off); the deflection comes from
``seafast.model.beam`` Timoshenko elements with consistent nodal loads of the linear element
load.

Size: over 400 lines because the still-water and wave responses, the deck-load influence and
the deflection from a bending-moment table share one discretisation and one balance (grid,
element loads, beam, sinkage and trim); split apart, those kernels would have to become public
for modules that only exist to hold them.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
import scipy.linalg
from numpy.typing import NDArray
from scipy.interpolate import CubicHermiteSpline, CubicSpline

from seafast.model.beam import assemble_beam_stiffness_banded
from seafast.vessel.hull_form import HullForm
from seafast.vessel.loading import VesselLoading, weight_distribution_N_per_m

__all__ = [
    "DEFAULT_SHEAR_AREA_M2",
    "HullGirder",
    "HullGirderResponse",
    "HydrostaticBalanceError",
    "WaveHullResponse",
    "still_water_response",
    "deflection_from_bending_moment",
    "deck_load_influence",
    "HullLoadResponse",
    "patch_load_response",
    "wave_response",
    "WaveTransferFunctions",
    "wave_transfer_functions",
    "iacs_wave_bending_moments_Nm",
    "iacs_wave_coefficient",
    "deck_deflection_at",
    "deck_harmonics_at",
    "deck_rise_m",
]

FloatArray = NDArray[np.float64]
WeightSource = VesselLoading | Callable[[FloatArray], FloatArray]

DEFAULT_SHEAR_AREA_M2 = 0.8
"""Default effective vertical shear area of the hull girder [m^2].

Vertical shear is carried by the longitudinal vertical plating: the two side shells and the
two longitudinal bulkheads of the wing (ballast) tanks of a heavy-lift vessel, i.e. four webs
of about 11 m effective depth and 18 mm mean thickness: 4 x 11 x 0.018 = 0.79 m^2. (For the
same section, I = 103.8 m^4 corresponds to deck and bottom flanges of ~1.3 m^2 each at
+/- 6 m, consistent with a ~12 m deep hull.)"""


# ============================================================================ data classes
@dataclass(frozen=True)
class HullGirder:
    """The hull as a Timoshenko beam with wall-sided buoyancy.

    Parameters
    ----------
    hull
        Hull form (waterline breadths, design draught, section-area coefficient).
    second_moment_m4
        Vertical second moment of area of the hull girder I [m^4] (base 103.8).
    shear_area_m2
        Effective vertical shear area A_s [m^2] (default :data:`DEFAULT_SHEAR_AREA_M2`).
    youngs_modulus_Pa
        Young's modulus E [Pa].
    shear_modulus_Pa
        Shear modulus G [Pa]; ``None`` gives ``E / 2.6`` (steel, nu = 0.3).
    water_density_kg_per_m3, gravity_m_per_s2
        Sea water density and gravity.
    """

    hull: HullForm
    second_moment_m4: float = 103.8
    shear_area_m2: float = DEFAULT_SHEAR_AREA_M2
    youngs_modulus_Pa: float = 210e9
    shear_modulus_Pa: float | None = None
    water_density_kg_per_m3: float = 1025.0
    gravity_m_per_s2: float = 9.81

    def __post_init__(self) -> None:
        if self.shear_modulus_Pa is None:
            object.__setattr__(self, "shear_modulus_Pa", self.youngs_modulus_Pa / 2.6)
        for name in (
            "second_moment_m4",
            "shear_area_m2",
            "youngs_modulus_Pa",
            "shear_modulus_Pa",
            "water_density_kg_per_m3",
            "gravity_m_per_s2",
        ):
            v = getattr(self, name)
            if not (v > 0):  # inf shear area is allowed (Euler-Bernoulli)
                raise ValueError(f"hull girder: {name} = {v!r}; must be > 0")

    @property
    def length_m(self) -> float:
        """Hull length AP-FP [m]."""
        return self.hull.length_m

    @property
    def midship_x_m(self) -> float:
        """x of midship (L/2 from the AP) [m]."""
        return float(self.hull.station_x_m[0]) + 0.5 * self.hull.length_m

    @property
    def bending_stiffness_Nm2(self) -> float:
        """EI [N m^2]."""
        return float(self.youngs_modulus_Pa * self.second_moment_m4)

    @property
    def shear_stiffness_N(self) -> float:
        """G A_s [N] (``inf`` for an Euler-Bernoulli hull)."""
        shear_modulus_Pa = self.shear_modulus_Pa
        assert shear_modulus_Pa is not None  # __post_init__ sets the default E / 2.6
        return float(shear_modulus_Pa * self.shear_area_m2)

    @property
    def buoyancy_per_draught_N_per_m2(self) -> float:
        """rho g C_s [N/m^3]: buoyancy per metre = this x breadth x local draught."""
        return float(self.water_density_kg_per_m3 * self.gravity_m_per_s2 * self.hull.section_area_coefficient)


@dataclass(frozen=True)
class HullGirderResponse:
    """Still-water hull-girder response at the nodes ``x_m``.

    Attributes
    ----------
    x_m
        Node positions from the AP [m], shape (n_x,).
    weight_N_per_m
        Weight per metre [N/m] (positive = downward load); at a discontinuity the mean of the
        two sides.
    buoyancy_N_per_m
        Buoyancy per metre [N/m] (upward).
    shear_force_N
        ``V(x) = int_0^x (b - w)`` [N].
    bending_moment_Nm
        Bending moment [N m], sagging positive, hogging negative; zero at AP and FP.
    deflection_m
        Deflection [m], positive up, relative to the chord through AP and FP (zero at both).
    slope_rad
        dz/dx of the deflection line [rad] (Timoshenko: bending rotation plus shear strain).
    sinkage_m
        Parallel sinkage from the design draught [m], positive deeper.
    trim_rad
        Trim angle [rad], positive bow up.
    """

    x_m: FloatArray
    weight_N_per_m: FloatArray
    buoyancy_N_per_m: FloatArray
    shear_force_N: FloatArray
    bending_moment_Nm: FloatArray
    deflection_m: FloatArray
    slope_rad: FloatArray
    sinkage_m: float
    trim_rad: float


@dataclass(frozen=True)
class WaveHullResponse:
    """Quasi-static hull-girder response on a regular head-sea wave, wave-induced part.

    Wave: ``zeta(x, t) = zeta_a cos(omega t + k (x - L/2))``, crest at midship at t = 0,
    travelling from bow to stern. ``deflection_m`` and ``bending_moment_Nm`` are the
    wave-induced parts (total minus still water, ``still_water`` holds the latter).
    Harmonics: ``w(x, t) = Re(sum_k W_k(x) exp(i k omega t))``, k = 0 the (real) mean.

    Attributes
    ----------
    x_m
        Node positions [m], shape (n_x,).
    period_fraction
        s = t / T at the time steps, shape (n_t,), in [0, 1).
    deflection_m, bending_moment_Nm, slope_rad
        Wave-induced deflection [m] (chord-relative), moment [N m] and slope [rad], shape (n_t, n_x).
    deflection_harmonics_m, bending_moment_harmonics_Nm, slope_harmonics_rad
        Complex harmonics, shape (n_harmonics + 1, n_x).
    sinkage_m, trim_rad
        Wave-induced sinkage [m] and trim [rad] time series, shape (n_t,).
    wave_length_m, wave_amplitude_m, frequency_rad_s
        The wave (frequency from deep-water dispersion).
    still_water
        The still-water response of the same loading.
    """

    x_m: FloatArray
    period_fraction: FloatArray
    deflection_m: FloatArray
    bending_moment_Nm: FloatArray
    deflection_harmonics_m: NDArray[np.complex128]
    bending_moment_harmonics_Nm: NDArray[np.complex128]
    slope_rad: FloatArray = field(default_factory=lambda: np.zeros((0, 0)))
    slope_harmonics_rad: NDArray[np.complex128] = field(default_factory=lambda: np.zeros((0, 0), complex))
    sinkage_m: FloatArray = field(default_factory=lambda: np.zeros(0))
    trim_rad: FloatArray = field(default_factory=lambda: np.zeros(0))
    wave_length_m: float = float("nan")
    wave_amplitude_m: float = float("nan")
    frequency_rad_s: float = float("nan")
    still_water: HullGirderResponse | None = None


# ============================================================================ internals
def _grid(girder: HullGirder, breakpoints: tuple[float, ...], n_points: int) -> FloatArray:
    """Node positions: uniform spacing plus all break points (nearby uniform nodes dropped)."""
    x0 = float(girder.hull.station_x_m[0])
    x1 = float(girder.hull.station_x_m[-1])
    if n_points < 3:
        raise ValueError(f"hull girder: n_points = {n_points}; must be >= 3")
    base = np.linspace(x0, x1, n_points)
    h = (x1 - x0) / (n_points - 1)
    tol = 1e-9 * (x1 - x0)
    bp = np.array(sorted({x0, x1, *girder.hull.station_x_m, *breakpoints}))
    bp = bp[(bp >= x0 - tol) & (bp <= x1 + tol)]
    bp = np.clip(bp, x0, x1)
    keep = np.ones(base.size, bool)
    for p in bp:
        keep &= np.abs(base - p) > 0.3 * h
    x = np.unique(np.concatenate([base[keep], bp]))
    # merge nodes closer than tol (round-off duplicates)
    x = x[np.concatenate([[True], np.diff(x) > tol])]
    return x


def _weight_element_ends(girder: HullGirder, loading: WeightSource, x: FloatArray) -> tuple[FloatArray, FloatArray]:
    """Weight per metre at the start and end of each element (one-sided limits) [N/m]."""
    fun: Callable[[FloatArray], FloatArray]
    if isinstance(loading, VesselLoading):
        vessel_loading = loading

        def from_loading(xx: FloatArray) -> FloatArray:
            return weight_distribution_N_per_m(xx, vessel_loading, girder.gravity_m_per_s2)

        fun = from_loading
    elif callable(loading):
        fun = loading
    else:
        raise TypeError("hull girder: loading must be a VesselLoading or a callable x_m -> weight_N_per_m")
    h = np.diff(x)
    x25 = x[:-1] + 0.25 * h
    x75 = x[:-1] + 0.75 * h
    w25 = np.asarray(fun(x25), dtype=float)
    w75 = np.asarray(fun(x75), dtype=float)
    # exact for a load linear inside each element
    wa = 1.5 * w25 - 0.5 * w75
    wb = 1.5 * w75 - 0.5 * w25
    return wa, wb


def _check_loading_extent(girder: HullGirder, loading: WeightSource) -> tuple[float, ...]:
    if not isinstance(loading, VesselLoading):
        return ()
    x0 = float(girder.hull.station_x_m[0])
    x1 = float(girder.hull.station_x_m[-1])
    tol = 1e-9 * (x1 - x0)
    for it in loading.items:
        if it.x_start_m < x0 - tol or it.x_end_m > x1 + tol:
            raise ValueError(
                f"hull girder: weight item {it.name!r} [{it.x_start_m:.2f}, {it.x_end_m:.2f}] m extends beyond "
                f"the hull [{x0:.2f}, {x1:.2f}] m; overhanging weights are not modelled"
            )
    return loading.breakpoints_m


def _shear_moment(h: FloatArray, qa: NDArray, qb: NDArray) -> tuple[NDArray, NDArray]:
    """Exact V and M at the nodes for a load linear in each element (leading axes broadcast)."""
    dV = 0.5 * h * (qa + qb)
    V = np.concatenate([np.zeros(dV.shape[:-1] + (1,)), np.cumsum(dV, axis=-1)], axis=-1)
    dM = V[..., :-1] * h + h * h * (2.0 * qa + qb) / 6.0
    M = np.concatenate([np.zeros(dM.shape[:-1] + (1,)), np.cumsum(dM, axis=-1)], axis=-1)
    return V, M


def _resultant_weights(h: FloatArray) -> tuple[FloatArray, FloatArray]:
    """Weights (n_el, 2) of the element-start and element-end loads in (V(L), M(L)).

    ``V(L) = sum h (qa + qb) / 2`` and ``M(L) = sum_j dV_j (L - x_{j+1}) + h^2 (2 qa + qb) / 6``:
    the end values of :func:`_shear_moment` without the running integrals.
    """
    beyond = np.concatenate([np.cumsum(h[::-1])[::-1][1:], [0.0]])  # L - x_{j+1}, element j's far end
    half = 0.5 * h
    return np.stack([half, half * beyond + h * h / 3.0], axis=-1), np.stack([half, half * beyond + h * h / 6.0], axis=-1)


def _end_resultants(h: FloatArray, qa: NDArray, qb: NDArray) -> NDArray:
    """(V(L), M(L)) stacked on the last axis, for the element loads (see :func:`_resultant_weights`)."""
    start, end = _resultant_weights(h)
    return qa @ start + qb @ end


_HALF_BANDWIDTH = 3


@dataclass(frozen=True)
class _Beam:
    """Factorised free-free Timoshenko hull beam with the two end deflections constrained."""

    x: FloatArray
    h: FloatArray
    EI: float
    GA: float
    fixed: tuple[int, int]
    factor: tuple

    @classmethod
    def build(cls, x: FloatArray, girder: HullGirder) -> _Beam:
        n_el = x.size - 1
        EI = girder.bending_stiffness_Nm2
        GA = girder.shear_stiffness_N
        gas = None if np.isinf(GA) else np.full(n_el, GA)
        # a chain of 2-node elements is banded (half-bandwidth 3): assembled in band storage and
        # factorised by a banded Cholesky, O(n). The two end deflections are held at zero by
        # decoupling their rows and columns (unit diagonal, zero load): with exact zeros the
        # other DOFs see the same elimination as in the reduced system.
        band = assemble_beam_stiffness_banded(x, np.full(n_el, EI), shear_stiffness_N=gas)
        n_dof = 2 * x.size
        fixed = (0, n_dof - 2)
        for dof in fixed:
            for d in range(1, _HALF_BANDWIDTH + 1):
                if dof + d < n_dof:
                    band[_HALF_BANDWIDTH - d, dof + d] = 0.0  # row dof, columns to its right
                if dof - d >= 0:
                    band[_HALF_BANDWIDTH - d, dof] = 0.0  # column dof, rows above
            band[_HALF_BANDWIDTH, dof] = 1.0
        factor = (scipy.linalg.cholesky_banded(band, check_finite=False), False)
        return cls(x, np.diff(x), EI, GA, fixed, factor)

    def solve(self, qa: NDArray, qb: NDArray, V: NDArray) -> tuple[NDArray, NDArray]:
        """Nodal deflection [m] and slope dz/dx [rad], shape (..., n_x), for element loads."""
        h = self.h
        lead = qa.shape[:-1]
        n = self.x.size
        f = np.zeros(lead + (2 * n,))
        f[..., 0:-2:2] += h * (7.0 * qa + 3.0 * qb) / 20.0
        f[..., 1:-1:2] += h * h * (3.0 * qa + 2.0 * qb) / 60.0
        f[..., 2::2] += h * (3.0 * qa + 7.0 * qb) / 20.0
        f[..., 3::2] += -h * h * (2.0 * qa + 3.0 * qb) / 60.0
        f[..., list(self.fixed)] = 0.0
        u = scipy.linalg.cho_solve_banded(self.factor, f.reshape(-1, 2 * n).T, check_finite=False).T.reshape(lead + (2 * n,))
        z = u[..., 0::2]
        psi = u[..., 1::2]
        slope = psi if np.isinf(self.GA) else psi - V / self.GA
        return z, slope


class HydrostaticBalanceError(ValueError):
    """The hull girder finds no hydrostatic balance on the given wave (the hull leaves the water); the message says why."""


def _balance(
    girder: HullGirder,
    x: FloatArray,
    wa: FloatArray,
    wb: FloatArray,
    zeta: NDArray,
    max_iter: int = 50,
) -> tuple[NDArray, NDArray, NDArray, NDArray, NDArray]:
    """Sinkage and trim that balance the element weights; vectorised over leading axes of ``zeta``.

    Returns sinkage, trim (shape lead), nodal buoyancy (lead + (n_x,)) and element load ends
    qa, qb (lead + (n_el,)).
    """
    h = np.diff(x)
    rgc = girder.buoyancy_per_draught_N_per_m2
    breadth = girder.hull.breadth_at(x)
    xm = girder.midship_x_m
    T = girder.hull.draft_m
    lead = zeta.shape[:-1]
    s = np.zeros(lead)
    tr = np.zeros(lead)
    L = girder.length_m
    # (V(L), M(L)) are linear in the nodal buoyancy b: b @ W minus the weight's resultants; the
    # derivatives in sinkage and trim follow with the weights of db/ds and db/dtrim = -(x - xm) db/ds
    start, end = _resultant_weights(h)
    W = np.zeros((x.size, 2))
    W[:-1] += start
    W[1:] += end
    W_jac = np.concatenate([W, -(x - xm)[:, None] * W], axis=1)  # columns: d/ds (V, M), d/dtrim (V, M)
    weight_resultants = wa @ start + wb @ end
    rb = rgc * breadth
    level = T + zeta
    for _ in range(max_iter):
        d = level + s[..., None] - tr[..., None] * (x - xm)
        wet = d > 0
        R = (rb * np.where(wet, d, 0.0)) @ W - weight_resultants
        J = ((rb * wet) @ W_jac).reshape(lead + (2, 2)).swapaxes(-1, -2)  # (..., 2 equations, 2 unknowns)
        delta = np.linalg.solve(J, -R[..., None])[..., 0]
        s = s + delta[..., 0]
        tr = tr + delta[..., 1]
        if np.all(np.abs(delta[..., 0]) < 1e-13 * T) and np.all(np.abs(delta[..., 1]) * L < 1e-13 * T):
            break
    else:
        worst = float(np.max(np.abs(R) / np.maximum(np.abs(weight_resultants), 1.0)))
        raise HydrostaticBalanceError(
            f"hull girder: no hydrostatic balance (sinkage and trim) found in {max_iter} Newton steps on a wave surface "
            f"of up to {float(np.max(np.abs(zeta))):.3g} m against the draught {T:.3g} m (residual {worst:.2e} of the "
            "weight): the hull leaves the water over much of its length, which the quasi-static wall-sided model "
            "does not describe; check the wave amplitude (metres, half the wave height) and the loading"
        )
    d = T + s[..., None] - tr[..., None] * (x - xm) + zeta
    b = rgc * breadth * np.maximum(d, 0.0)
    qa = b[..., :-1] - wa
    qb = b[..., 1:] - wb
    return s, tr, b, qa, qb


def _nodal_weight(wa: FloatArray, wb: FloatArray) -> FloatArray:
    """Nodal weight values: mean of the one-sided limits at interior nodes."""
    w = np.empty(wa.size + 1)
    w[0] = wa[0]
    w[-1] = wb[-1]
    w[1:-1] = 0.5 * (wb[:-1] + wa[1:])
    return w


# ============================================================================ public API
def still_water_response(girder: HullGirder, loading: WeightSource, n_points: int = 343) -> HullGirderResponse:
    """Still-water equilibrium, shear force, bending moment and deflection of the hull girder.

    Parameters
    ----------
    girder
        The hull girder.
    loading
        A :class:`~seafast.vessel.loading.VesselLoading`, or a callable ``x_m -> weight [N/m]``
        (downward positive). The total weight should be close to the displacement at the design
        draught (it need not be equal: sinkage and trim are solved).
    n_points
        Number of uniformly spaced nodes (break points of the hull form and the loading are
        added); the default gives 0.5 m elements on a 171 m hull.

    Returns
    -------
    HullGirderResponse
        Buoyancy equals weight and LCB = LCG to round-off; V and M vanish at both ends to
        round-off; the deflection is relative to the chord through AP and FP (see the module
        docstring), positive up, so a hogging hull shows a positive deflection amidships.
    """
    bp = _check_loading_extent(girder, loading)
    x = _grid(girder, bp, n_points)
    wa, wb = _weight_element_ends(girder, loading, x)
    s, tr, b, qa, qb = _balance(girder, x, wa, wb, np.zeros(x.size))
    h = np.diff(x)
    V, M = _shear_moment(h, qa, qb)
    beam = _Beam.build(x, girder)
    z, slope = beam.solve(qa, qb, V)
    return HullGirderResponse(
        x_m=x,
        weight_N_per_m=_nodal_weight(wa, wb),
        buoyancy_N_per_m=b,
        shear_force_N=V,
        bending_moment_Nm=M,
        deflection_m=z,
        slope_rad=slope,
        sinkage_m=float(s),
        trim_rad=float(tr),
    )


def _patches(
    girder: HullGirder, loading: WeightSource, load_start_m: FloatArray, load_end_m: FloatArray, n_points: int
) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray, NDArray[np.bool_]]:
    """Patch edges, a grid with every edge as a node, its weight ends and the patch of each element."""
    start = np.asarray(load_start_m, dtype=float).ravel()
    end = np.asarray(load_end_m, dtype=float).ravel()
    if start.size != end.size or np.any(end <= start):
        raise ValueError("hull girder: every load patch needs load_end_m > load_start_m")
    bp = tuple(_check_loading_extent(girder, loading)) + tuple(start) + tuple(end)
    x = _grid(girder, bp, n_points)
    wa, wb = _weight_element_ends(girder, loading, x)
    mid = 0.5 * (x[:-1] + x[1:])
    inside = (mid[None, :] > start[:, None]) & (mid[None, :] < end[:, None])  # (n_loads, n_el)
    return start, end, x, np.vstack([wa, wb]), inside


def _solve_with_extra(girder: HullGirder, x: FloatArray, w_ends: FloatArray, extra: NDArray) -> tuple[NDArray, ...]:
    """The still-water state (row 0) and one per row of ``extra`` [N/m per element], re-balanced.

    Returns sinkage, trim, qa, qb, V, M, z, slope with a leading axis of 1 + len(extra).
    """
    wa, wb = w_ends
    wa_all = np.vstack([wa[None, :], wa[None, :] + extra])
    wb_all = np.vstack([wb[None, :], wb[None, :] + extra])
    zeta = np.zeros((wa_all.shape[0], x.size))
    s, tr, _, qa, qb = _balance(girder, x, wa_all, wb_all, zeta)
    V, M = _shear_moment(np.diff(x), qa, qb)
    z, slope = _Beam.build(x, girder).solve(qa, qb, V)
    return s, tr, qa, qb, V, M, z, slope


def deck_load_influence(
    girder: HullGirder,
    loading: WeightSource,
    load_start_m: FloatArray,
    load_end_m: FloatArray,
    target_x_m: FloatArray,
    n_points: int = 343,
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Deck deflection and slope at ``target_x_m`` per newton of extra downward load on patches.

    Each load j is 1 N spread uniformly over ``[load_start_m[j], load_end_m[j]]``; the ship is
    re-balanced in sinkage and trim for every load, all at once (vectorised still-water solves
    on one grid that has every patch edge as a node). While no section emerges the hull
    model is linear, so the result is exact and independent of the probe size.

    Returns
    -------
    deflection_m_per_N, slope_rad_per_N
        Shape (n_targets, n_loads): response at target i to load j, relative to the still-water
        state of ``loading`` (chord through AP and FP, as :func:`still_water_response`).
    """
    start, end, x, w_ends, inside = _patches(girder, loading, load_start_m, load_end_m, n_points)
    probe_N = 1.0e6  # numerically comfortable against the ship's ~3e8 N weight; exact by linearity
    extra = probe_N / (end - start)[:, None] * inside
    *_, z, slope = _solve_with_extra(girder, x, w_ends, extra)
    spl = CubicHermiteSpline(x, z.T, slope.T, axis=0)
    xt = np.asarray(target_x_m, dtype=float).ravel()
    zt, st = spl(xt), spl(xt, 1)  # (n_targets, 1 + n_loads)
    return (zt[:, 1:] - zt[:, :1]) / probe_N, (st[:, 1:] - st[:, :1]) / probe_N


@dataclass(frozen=True)
class HullLoadResponse:
    """Change of the still-water hull-girder response caused by extra loads (the ship re-balanced).

    Returned by :func:`patch_load_response`; every line has the shape of the load sets' leading
    axes + (n_x,), and is the loaded state minus the still-water state of the same loading, in
    the conventions of :class:`HullGirderResponse` (deflection up +, chord through AP and FP;
    ``V = dM/dx``; sagging moment +).

    Attributes
    ----------
    x_m
        Where the lines are evaluated, from the AP [m], shape (n_x,).
    deflection_m, slope_rad, shear_force_N, bending_moment_Nm
        Changes of deflection [m], slope dz/dx [rad], shear force [N] and bending moment [N m].
    sinkage_m, trim_rad
        Changes of sinkage [m] (deeper +) and trim [rad] (bow up +), shape of the leading axes.
    """

    x_m: FloatArray
    deflection_m: FloatArray
    slope_rad: FloatArray
    shear_force_N: FloatArray
    bending_moment_Nm: FloatArray
    sinkage_m: FloatArray
    trim_rad: FloatArray


def patch_load_response(
    girder: HullGirder,
    loading: WeightSource,
    load_start_m: FloatArray,
    load_end_m: FloatArray,
    load_N: NDArray,
    x_m: FloatArray,
    n_points: int = 343,
) -> HullLoadResponse:
    """The hull girder's response along the ship to extra downward loads on patches.

    Load set ``load_N[..., j]`` [N, downward +] puts ``load_N[..., j]`` spread uniformly over
    ``[load_start_m[j], load_end_m[j]]`` on the still-water ship of ``loading``, which is
    re-balanced in sinkage and trim (the same vectorised solves as :func:`deck_load_influence`;
    negative loads lift). The lines are evaluated at ``x_m`` exactly for the grid's piecewise
    linear load (shear force quadratic and bending moment cubic within each element), the
    deflection and slope by the C1 Hermite interpolant of :func:`deck_deflection_at`.

    Parameters
    ----------
    girder, loading
        As for :func:`still_water_response`.
    load_start_m, load_end_m
        Patch ends from the AP [m], shape (n_loads,), ``load_end_m > load_start_m``.
    load_N
        Total load on each patch [N], shape (..., n_loads): one load set per leading index.
    x_m
        Where to evaluate the lines, from the AP [m], within the hull.

    Returns
    -------
    HullLoadResponse
        The loaded minus the still-water response, per load set.
    """
    start, end, x, w_ends, inside = _patches(girder, loading, load_start_m, load_end_m, n_points)
    loads = np.asarray(load_N, dtype=float)
    if loads.shape[-1:] != start.shape or not np.all(np.isfinite(loads)):
        raise ValueError(f"patch_load_response: load_N must be finite with a last axis of {start.size} (one per patch)")
    lead = loads.shape[:-1]
    extra = (loads.reshape(-1, start.size) / (end - start)) @ inside.astype(float)
    s, tr, qa, qb, V, M, z, slope = _solve_with_extra(girder, x, w_ends, extra)
    xt = np.asarray(x_m, dtype=float).ravel()
    i = np.clip(np.searchsorted(x, xt, side="right") - 1, 0, x.size - 2)
    d = xt - x[i]
    h = x[i + 1] - x[i]
    dq = qb[:, i] - qa[:, i]
    Vt = V[:, i] + qa[:, i] * d + dq * d * d / (2.0 * h)
    Mt = M[:, i] + V[:, i] * d + qa[:, i] * d * d / 2.0 + dq * d**3 / (6.0 * h)
    spl = CubicHermiteSpline(x, z.T, slope.T, axis=0)
    zt, st = spl(xt).T, spl(xt, 1).T

    def change(a: NDArray) -> NDArray:
        return (a[1:] - a[:1]).reshape(lead + a.shape[1:])

    return HullLoadResponse(xt, change(zt), change(st), change(Vt), change(Mt), change(s), change(tr))


def deflection_from_bending_moment(
    girder: HullGirder,
    x_m: FloatArray,
    bending_moment_Nm: FloatArray,
    shear_force_N: FloatArray | None = None,
) -> tuple[FloatArray, FloatArray]:
    """Hull deflection from a given still-water bending-moment distribution (loading computer).

    Integrates the Timoshenko curvature ``z'' = M / (E I) - V' / (G A_s)`` exactly for a cubic
    spline through the table: ``z = int int M / (EI) - int V / (G A_s)``, then removes the
    chord through the first and last table points (normally AP and FP; the same definiteness
    as :func:`still_water_response`).

    Parameters
    ----------
    girder
        Supplies EI and G A_s (the hull form is not used).
    x_m
        Table positions from the AP [m], strictly increasing, at least 4 points.
    bending_moment_Nm
        Still-water bending moment [N m], sagging positive, hogging negative (note: many
        loading computers print hogging positive; flip the sign of such tables).
    shear_force_N
        Optional shear force [N] in the seafast convention ``V = dM/dx``; if omitted it is the
        derivative of the moment spline and the shear deflection is ``-(M - M(x_0)) / G A_s``.

    Returns
    -------
    deflection_m, slope_rad
        At ``x_m``: deflection [m] (positive up, zero at both ends) and dz/dx [rad].

    Raises
    ------
    ValueError
        On a malformed table, or if ``shear_force_N`` has the opposite sign convention
        (anti-correlated with dM/dx).
    """
    x = np.asarray(x_m, dtype=float)
    M = np.asarray(bending_moment_Nm, dtype=float)
    if x.ndim != 1 or x.shape != M.shape or x.size < 4:
        raise ValueError("deflection_from_bending_moment: x_m and bending_moment_Nm must be 1-D of equal length >= 4")
    if np.any(np.diff(x) <= 0) or not (np.all(np.isfinite(x)) and np.all(np.isfinite(M))):
        raise ValueError("deflection_from_bending_moment: x_m must be strictly increasing and all values finite")
    EI = girder.bending_stiffness_Nm2
    GA = girder.shear_stiffness_N
    spl = CubicSpline(x, M)
    S1 = spl.antiderivative(1)
    S2 = spl.antiderivative(2)
    dMdx = spl.derivative(1)(x)
    if shear_force_N is None:
        V = dMdx
        intV = M - M[0]
    else:
        V = np.asarray(shear_force_N, dtype=float)
        if V.shape != x.shape or not np.all(np.isfinite(V)):
            raise ValueError("deflection_from_bending_moment: shear_force_N must match x_m and be finite")
        if np.dot(V, dMdx) < 0:
            raise ValueError(
                "deflection_from_bending_moment: shear_force_N is anti-correlated with dM/dx; seafast uses V = dM/dx "
                "(flip the sign of the shear-force table)"
            )
        vs = CubicSpline(x, V).antiderivative(1)
        intV = vs(x) - vs(x[0])
    shear_term = 0.0 if np.isinf(GA) else 1.0 / GA
    z = (S2(x) - S2(x[0]) - S1(x[0]) * (x - x[0])) / EI - shear_term * intV
    slope = (S1(x) - S1(x[0])) / EI - shear_term * V
    chord_slope = (z[-1] - z[0]) / (x[-1] - x[0])
    z = z - z[0] - chord_slope * (x - x[0])
    slope = slope - chord_slope
    return z, slope


def wave_response(
    girder: HullGirder,
    loading: WeightSource,
    wave_length_m: float,
    wave_amplitude_m: float,
    n_steps: int = 64,
    n_harmonics: int = 5,
    n_points: int = 343,
) -> WaveHullResponse:
    """Quasi-static hull-girder response on a regular head-sea wave over one period.

    Wave elevation (phase convention relied on by other modules)::

        zeta(x, t) = zeta_a cos(omega t + k (x - L/2)),   k = 2 pi / lambda,

    crest at midship at t = 0, waves travelling from bow to stern; ``omega = sqrt(g k)``
    (deep water). At each of ``n_steps`` equal steps of the period fraction ``s = t / T`` in
    [0, 1) the ship is re-balanced (sinkage and trim) on the wave surface with wall-sided
    sections (buoyancy to the local wave surface; the Smith effect and dynamics are ignored),
    and the bending moment and chord-relative deflection follow as in still water. The
    wave-induced part (total minus still water) is returned. While no section emerges
    (local draught > 0 everywhere) the buoyancy is linear in the draught, so the wave-induced
    response is exactly linear in ``zeta_a`` and purely first-harmonic; emergence (very steep
    waves or light draught) makes it nonlinear, which the Newton balance handles.

    A crest amidships (t = 0) gives hogging (negative moment, midship deflected up); a trough
    amidships (s = 0.5) gives sagging.

    Parameters
    ----------
    girder, loading
        As for :func:`still_water_response`.
    wave_length_m, wave_amplitude_m
        Wave length lambda [m] and amplitude zeta_a [m].
    n_steps
        Time steps per period (> 2 n_harmonics).
    n_harmonics
        Highest harmonic returned.
    n_points
        Uniform nodes along the hull (plus break points).

    Returns
    -------
    WaveHullResponse
    """
    if not (wave_length_m > 0) or not np.isfinite(wave_amplitude_m):
        raise ValueError("wave_response: wave_length_m must be > 0 and wave_amplitude_m finite")
    if n_steps <= 2 * n_harmonics:
        raise ValueError(f"wave_response: n_steps = {n_steps} must exceed 2 n_harmonics = {2 * n_harmonics}")
    bp = _check_loading_extent(girder, loading)
    x = _grid(girder, bp, n_points)
    wa, wb = _weight_element_ends(girder, loading, x)
    k = 2.0 * np.pi / wave_length_m
    omega = float(np.sqrt(girder.gravity_m_per_s2 * k))
    sfrac = np.arange(n_steps) / n_steps
    phase = 2.0 * np.pi * sfrac[:, None] + k * (x[None, :] - girder.midship_x_m)
    zeta = np.vstack([np.zeros((1, x.size)), wave_amplitude_m * np.cos(phase)])
    s, tr, b, qa, qb = _balance(girder, x, wa, wb, zeta)
    h = np.diff(x)
    V, M = _shear_moment(h, qa, qb)
    beam = _Beam.build(x, girder)
    z, slope = beam.solve(qa, qb, V)
    still = HullGirderResponse(
        x_m=x,
        weight_N_per_m=_nodal_weight(wa, wb),
        buoyancy_N_per_m=b[0],
        shear_force_N=V[0],
        bending_moment_Nm=M[0],
        deflection_m=z[0],
        slope_rad=slope[0],
        sinkage_m=float(s[0]),
        trim_rad=float(tr[0]),
    )
    zw = z[1:] - z[0]
    Mw = M[1:] - M[0]
    sw = slope[1:] - slope[0]

    def harmonics(a: NDArray) -> NDArray[np.complex128]:
        c = np.fft.rfft(a, axis=0)[: n_harmonics + 1] / n_steps  # real samples: half the transform
        c[1:] *= 2.0
        c[0] = c[0].real
        return c

    return WaveHullResponse(
        x_m=x,
        period_fraction=sfrac,
        deflection_m=zw,
        bending_moment_Nm=Mw,
        deflection_harmonics_m=harmonics(zw),
        bending_moment_harmonics_Nm=harmonics(Mw),
        slope_rad=sw,
        slope_harmonics_rad=harmonics(sw),
        sinkage_m=s[1:] - s[0],
        trim_rad=tr[1:] - tr[0],
        wave_length_m=float(wave_length_m),
        wave_amplitude_m=float(wave_amplitude_m),
        frequency_rad_s=omega,
        still_water=still,
    )


@dataclass(frozen=True)
class WaveTransferFunctions:
    """Quasi-static hull-girder response per metre of wave amplitude, at several frequencies.

    First harmonics in the convention of :class:`WaveHullResponse` (``w(x, t) = Re(W(x)
    exp(i omega t))``, wave ``zeta = zeta_a cos(omega t + k (x - L/2))``, deep water
    ``k = omega^2 / g``), divided by ``zeta_a``.

    Attributes
    ----------
    x_m
        Hull nodes from the AP [m], shape (n_x,) (the grid of :func:`wave_response`).
    omega_rad_s
        Wave frequencies [rad/s], shape (n_w,).
    deflection_m_per_m, slope_rad_per_m, bending_moment_Nm_per_m
        Complex, shape (n_w, n_x): chord-relative deflection [m/m], slope dz/dx [rad/m] and
        bending moment (sagging +) [N m/m].
    emergence_amplitude_m
        Shape (n_w,): the regular-wave amplitude [m] at which the first section emerges (the
        local draught ``T + sinkage - trim (x - L/2) + zeta`` reaches 0). Below it the response
        is exactly linear in the amplitude; above it, not.
    """

    x_m: FloatArray
    omega_rad_s: FloatArray
    deflection_m_per_m: NDArray[np.complex128]
    slope_rad_per_m: NDArray[np.complex128]
    bending_moment_Nm_per_m: NDArray[np.complex128]
    emergence_amplitude_m: FloatArray

    def deck_at(self, x_m: FloatArray) -> tuple[NDArray[np.complex128], NDArray[np.complex128]]:
        """Deflection [m/m] and slope [rad/m] at ``x_m`` (cubic Hermite, as :func:`deck_harmonics_at`), (n_w, n_q)."""
        xq = np.atleast_1d(np.asarray(x_m, dtype=float))
        out = []
        for part in (np.real, np.imag):
            spl = CubicHermiteSpline(self.x_m, part(self.deflection_m_per_m).T, part(self.slope_rad_per_m).T, axis=0)
            out.append((spl(xq).T, spl(xq, 1).T))
        return out[0][0] + 1j * out[1][0], out[0][1] + 1j * out[1][1]


def wave_transfer_functions(
    girder: HullGirder, loading: WeightSource, omega_rad_s: FloatArray, n_points: int = 343
) -> WaveTransferFunctions:
    """Hull-girder transfer functions per metre of wave amplitude, two real load cases per frequency.

    While every section stays immersed the wall-sided buoyancy is linear in the local draught,
    so the wave-induced response is linear in the wave: its first harmonic is the response to
    the wave frozen at t = 0 (``cos k(x - L/2)``) plus i times the response to it a quarter
    period earlier (``sin k(x - L/2)``). Both are solved for a 1 m wave, all frequencies in one
    vectorised balance on the grid of :func:`wave_response`, so ``zeta_a`` times the result
    equals the first harmonic of :func:`wave_response` (64 crest positions) to round-off for
    any wave that keeps the hull immersed (no emergence: ``zeta_a`` below about the draught).

    Parameters
    ----------
    girder, loading
        As for :func:`still_water_response`.
    omega_rad_s
        Wave frequencies [rad/s] (> 0), deep-water wave number ``omega^2 / g``.
    n_points
        Uniform nodes along the hull (plus break points), as :func:`wave_response`.
    """
    w = np.atleast_1d(np.asarray(omega_rad_s, dtype=float))
    if w.ndim != 1 or not np.all(np.isfinite(w)) or np.any(w <= 0):
        raise ValueError("wave_transfer_functions: omega_rad_s must be finite and > 0")
    bp = _check_loading_extent(girder, loading)
    x = _grid(girder, bp, n_points)
    wa, wb = _weight_element_ends(girder, loading, x)
    k = w**2 / girder.gravity_m_per_s2
    phase = k[:, None] * (x[None, :] - girder.midship_x_m)
    zeta = np.vstack([np.zeros((1, x.size)), np.cos(phase), np.sin(phase)])  # 1 m wave
    sink, trim, _, qa, qb = _balance(girder, x, wa, wb, zeta)
    V, M = _shear_moment(np.diff(x), qa, qb)
    z, slope = _Beam.build(x, girder).solve(qa, qb, V)
    n = w.size

    def first_harmonic(a: NDArray) -> NDArray[np.complex128]:
        d = a[1:] - a[0]
        return d[:n] + 1j * d[n:]

    arm = x - girder.midship_x_m
    still_draught = girder.hull.draft_m + sink[0] - trim[0] * arm
    # local draught change per metre of wave (complex): wave minus the ship's sinkage and trim
    immersion = np.exp(1j * phase) + first_harmonic(sink)[:, None] - first_harmonic(trim)[:, None] * arm
    emergence = np.min(still_draught / np.maximum(np.abs(immersion), 1e-300), axis=1)
    return WaveTransferFunctions(x, w, first_harmonic(z), first_harmonic(slope), first_harmonic(M), emergence)


def iacs_wave_coefficient(length_m: float) -> float:
    """IACS UR S11 wave coefficient C_w [-] (rule length L in m, 0 < L <= 500)."""
    L = float(length_m)
    if not (0 < L <= 500):
        raise ValueError(f"iacs_wave_coefficient: length_m = {L!r} outside (0, 500]")
    if L < 90:
        return 0.0792 * L
    if L <= 300:
        return 10.75 - ((300.0 - L) / 100.0) ** 1.5
    if L <= 350:
        return 10.75
    return 10.75 - ((L - 350.0) / 150.0) ** 1.5


def iacs_wave_bending_moments_Nm(length_m: float, breadth_m: float, block_coefficient: float) -> tuple[float, float]:
    """IACS UR S11 rule vertical wave bending moments amidships [N m].

    ``M_wh = +190 C_w L^2 B C_b 1e-3`` kN m (hogging) and
    ``M_ws = -110 C_w L^2 B (C_b + 0.7) 1e-3`` kN m (sagging), C_b not less than 0.6,
    C_w from :func:`iacs_wave_coefficient`. NOTE: returned in the IACS sign convention
    (hogging positive, sagging negative), which is the opposite of seafast's
    (sagging positive); compare magnitudes, or negate for seafast.

    Returns
    -------
    hogging_Nm, sagging_Nm
        (positive, negative) [N m].
    """
    L, B = float(length_m), float(breadth_m)
    cb = max(float(block_coefficient), 0.6)
    cw = iacs_wave_coefficient(L)
    hog_kNm = 190.0 * cw * L * L * B * cb * 1e-3
    sag_kNm = -110.0 * cw * L * L * B * (cb + 0.7) * 1e-3
    return hog_kNm * 1e3, sag_kNm * 1e3


def deck_deflection_at(response: HullGirderResponse | WaveHullResponse, x_m: FloatArray | float) -> tuple[NDArray, NDArray]:
    """Deck deflection [m] and slope dz/dx [rad] at ``x_m`` by cubic Hermite interpolation.

    The interpolant uses the nodal deflections and the nodal slopes of the Timoshenko
    solution, so it is C1 and consistent with the FE result. For a
    :class:`WaveHullResponse` the wave-induced time series is interpolated: the outputs have
    shape (n_t,) + shape(x_m).
    """
    xq = np.asarray(x_m, dtype=float)
    x = response.x_m
    if isinstance(response, WaveHullResponse):
        spl = CubicHermiteSpline(x, response.deflection_m.T, response.slope_rad.T, axis=0)
        z = np.moveaxis(spl(xq), -1, 0) if xq.ndim else spl(xq)
        sl = np.moveaxis(spl(xq, 1), -1, 0) if xq.ndim else spl(xq, 1)
        return np.asarray(z), np.asarray(sl)
    spl = CubicHermiteSpline(x, response.deflection_m, response.slope_rad)
    return np.asarray(spl(xq)), np.asarray(spl(xq, 1))


def deck_harmonics_at(response: WaveHullResponse, x_m: FloatArray | float) -> tuple[NDArray[np.complex128], NDArray[np.complex128]]:
    """Complex harmonics of the wave-induced deck deflection [m] and slope [rad] at ``x_m``.

    Returns arrays of shape (n_harmonics + 1,) + shape(x_m) in the convention
    ``w(t) = Re(sum_k W_k exp(i k omega t))``; ``abs(W_1)`` and ``angle(W_1)`` are the
    ``wave_amplitude_m`` and ``wave_phase_rad`` of a deck deflection table.
    """
    xq = np.asarray(x_m, dtype=float)
    x = response.x_m
    out_z = []
    out_s = []
    for part in (np.real, np.imag):
        spl = CubicHermiteSpline(x, part(response.deflection_harmonics_m).T, part(response.slope_harmonics_rad).T, axis=0)
        zz = spl(xq)
        ss = spl(xq, 1)
        out_z.append(np.moveaxis(zz, -1, 0) if xq.ndim else zz)
        out_s.append(np.moveaxis(ss, -1, 0) if xq.ndim else ss)
    return out_z[0] + 1j * out_z[1], out_s[0] + 1j * out_s[1]


def deck_rise_m(response: HullGirderResponse, centre_x_m: float, half_span_m: float) -> float:
    """Deck rise [m] at ``centre_x_m`` above the mean of the deck at ``centre_x_m +/- half_span_m``.

    The one non-rigid combination of three deck points: positive when the hull hogs between
    them (the middle saddle of a three-saddle cargo is then the most loaded).
    """
    z, _ = deck_deflection_at(response, np.array([centre_x_m - half_span_m, centre_x_m, centre_x_m + half_span_m]))
    return float(z[1] - 0.5 * (z[0] + z[2]))
