"""Two-way hull-cargo coupling of the still-water state.

With one-way coupling (the source's assumption) the hull girder carries the cargo as a weight
spread over its length, and the cargo only follows the deck. With four monopiles abreast, the
cargo's bending stiffness is comparable to the hull's, and its weight reaches the deck at the
sea-fastening points only, in proportions the hull's own bending decides. ``two_way`` solves the
still-water state of hull and cargo together:

    z_deck = z_one_way + n (Phi p - D)

at the deck DOFs under the sea-fastening (deflection z [m] and slope theta [rad] at each
saddle), where ``n`` is the number of identical units abreast, ``p`` [N] the period-mean force
one unit exerts downward on the deck at each sea-fastening point (saddle contact force, lashing
spring force, minus the pretension's reaction, which pulls the deck up), ``Phi`` the hull's
compliance at those points (deck deflection and slope per newton of downward load, the ship
re-balanced in sinkage and trim) and ``D`` the deck deflection and slope that one unit's
distributed weight causes in the one-way hull model. Exchanging the distributed weight for the
point loads keeps the ship's displacement and ballast unchanged.

Scope (documented in the README): the still-water state only; the wave-induced hull bending
stays one-way (the hull is loaded by the cargo's mean forces, not by its wave-frequency
forces). The loads are applied to the hull as uniform patches of ``patch_length_m`` (a saddle's
footprint, default 1 m) and the moments of the rotational lashing springs (a few kN m) are not
applied to the hull. The hull model is linear while no section emerges, so ``Phi`` and ``D``
are exact differences of hull-girder solutions.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace

import numpy as np
from numpy.typing import NDArray

from seafast.excitation.harmonic import HarmonicExcitation
from seafast.excitation.hull_girder import HullGirder, deck_deflection_at, still_water_response
from seafast.model.structure import StructuralModel
from seafast.vessel.loading import VesselLoading, WeightItem

__all__ = ["HullCompliance", "StillWaterCoupling", "hull_compliance", "deck_forces_N", "couple_still_water"]

CARGO_ITEM = "cargo"
"""Name of the cargo's weight item in the default vessel loading."""


@dataclass(frozen=True)
class HullCompliance:
    """The hull girder's still-water compliance at the sea-fastening points.

    Attributes
    ----------
    saddle_x_ship_m
        Ship x of each sea-fastening point, from the AP [m], shape (n_s,).
    deflection_m_per_N, slope_rad_per_N
        Deck deflection [m] and slope [rad] at point i per newton of downward load at point j
        (the ship re-balanced), shape (n_s, n_s).
    unit_weight_deflection_m, unit_weight_slope_rad
        Deck deflection [m] and slope [rad] at each point caused by one cargo unit's weight
        spread over its length, as the one-way model applies it, shape (n_s,).
    units_abreast
        Identical cargo units side by side, each on its own saddles at the same x.
    patch_length_m
        Length over which each point load is spread on the hull [m].
    """

    saddle_x_ship_m: NDArray[np.float64]
    deflection_m_per_N: NDArray[np.float64]
    slope_rad_per_N: NDArray[np.float64]
    unit_weight_deflection_m: NDArray[np.float64]
    unit_weight_slope_rad: NDArray[np.float64]
    units_abreast: int
    patch_length_m: float

    def deck_change(self, deck_force_N: NDArray[np.float64]) -> NDArray[np.float64]:
        """Change of the deck DOFs (z, theta interleaved per point) from one-way to two-way.

        ``deck_force_N`` is the downward force of one unit on the deck at each point [N].
        """
        p = np.asarray(deck_force_N, dtype=float)
        n = self.units_abreast
        out = np.empty(2 * p.size)
        out[0::2] = n * (self.deflection_m_per_N @ p - self.unit_weight_deflection_m)
        out[1::2] = n * (self.slope_rad_per_N @ p - self.unit_weight_slope_rad)
        return out


def hull_compliance(
    girder: HullGirder,
    loading: VesselLoading,
    saddle_x_ship_m: NDArray[np.float64],
    units_abreast: int,
    *,
    patch_length_m: float = 1.0,
    probe_force_N: float = 1.0e6,
) -> HullCompliance:
    """Compliance of the hull at the sea-fastening points, by differences of hull solutions.

    Parameters
    ----------
    girder, loading
        The hull girder and its still-water loading; ``loading`` must hold the cargo as the
        item named ``"cargo"`` (all units abreast).
    saddle_x_ship_m
        Ship x of the sea-fastening points [m].
    units_abreast
        Number of identical cargo units (``n``).
    patch_length_m
        Footprint over which a point load is spread [m] (> 0).
    probe_force_N
        Size of the probe loads [N]; the hull model is linear while no section emerges, so the
        result does not depend on it.

    Raises
    ------
    ValueError
        If the loading has no cargo item, or a patch would reach beyond the hull.
    """
    xs = np.asarray(saddle_x_ship_m, dtype=float)
    try:
        cargo = loading.item(CARGO_ITEM)
    except KeyError:
        raise ValueError("two-way coupling: the vessel loading has no 'cargo' item (a computed default loading is needed)") from None
    g = girder.gravity_m_per_s2
    base = still_water_response(girder, loading)
    z0, s0 = deck_deflection_at(base, xs)
    half = 0.5 * patch_length_m
    flex_z = np.empty((xs.size, xs.size))
    flex_s = np.empty_like(flex_z)
    for j, x in enumerate(xs):
        probe = WeightItem(f"probe at {x:.2f} m", x - half, x + half, probe_force_N / g)
        z, s = deck_deflection_at(still_water_response(girder, loading.with_items(probe)), xs)
        flex_z[:, j] = (z - z0) / probe_force_N
        flex_s[:, j] = (s - s0) / probe_force_N
    n = int(units_abreast)
    lighter = replace(cargo, mass_kg=cargo.mass_kg * (n - 1) / n)
    items = tuple(lighter if it.name == CARGO_ITEM else it for it in loading.items)
    z1, s1 = deck_deflection_at(still_water_response(girder, replace(loading, items=items)), xs)
    return HullCompliance(xs, flex_z, flex_s, z0 - z1, s0 - s1, n, float(patch_length_m))


def deck_forces_N(model: StructuralModel, excitation: HarmonicExcitation, response, nonlinear: bool) -> NDArray[np.float64]:
    """Period-mean downward force of one cargo unit on the deck at each sea-fastening point [N].

    Parameters
    ----------
    model, excitation
        The model and the excitation the response was solved for (its k = 0 deck DOFs).
    response
        A :class:`~seafast.solvers.periodic.PeriodicResponse` (``nonlinear=True``: its saddle
        forces are the compression-only parts) or a
        :class:`~seafast.solvers.linear.LinearResponse` (``nonlinear=False``: saddles
        bilateral in K).
    """
    Kcc, Kco, Koo = model.spring_matrices(include_saddles=not nonlinear)
    if nonlinear:  # the period mean of the samples: every method has them (the references have no harmonics)
        x_c = np.mean(np.asarray(response.cargo_displacement_time_m, dtype=float), axis=0)
    else:
        x_c = np.real(np.asarray(response.cargo_displacement)[0])
    x_o = np.real(excitation.deck_displacement[0])
    spring = Kco.T @ x_c + Koo @ x_o  # force the springs need at the deck DOFs = their push on the deck
    p = spring[model.saddle_deck_dof] - model.seafastening.saddle_pretension_N
    if nonlinear:
        p = p + np.mean(np.asarray(response.saddle_force_time_N, dtype=float), axis=0)
    return p


@dataclass(frozen=True)
class StillWaterCoupling:
    """Outcome of :func:`couple_still_water`.

    Attributes
    ----------
    excitation
        The excitation with the coupled still-water deck DOFs (k = 0 row changed).
    deck_change
        Two-way minus one-way deck DOFs (z [m], theta [rad] interleaved per point).
    deck_force_N
        Converged period-mean downward force of one unit on the deck per point [N].
    converged, iterations, residual_m, message
        Convergence of the coupling iteration (residual: largest deck-DOF mismatch [m or rad]).
    """

    excitation: HarmonicExcitation
    deck_change: NDArray[np.float64]
    deck_force_N: NDArray[np.float64]
    converged: bool
    iterations: int
    residual_m: float
    message: str


def _with_static_deck_change(excitation: HarmonicExcitation, change: NDArray[np.float64], note: str) -> HarmonicExcitation:
    deck = np.array(excitation.deck_displacement, dtype=complex)
    deck[0] = deck[0] + change
    source = f"{excitation.source}; {note}" if note else excitation.source
    return HarmonicExcitation(excitation.omega_rad_s, deck, excitation.cargo_load_N, excitation.cargo_line_load_N_per_m, source)


def couple_still_water(
    model: StructuralModel,
    excitation: HarmonicExcitation,
    compliance: HullCompliance,
    deck_forces: Callable[[HarmonicExcitation], NDArray[np.float64]],
    *,
    tolerance_m: float = 1e-10,
    max_iterations: int = 20,
) -> StillWaterCoupling:
    """Solve ``v = n (Phi p(v) - D)`` for the still-water deck change ``v`` by Newton's method.

    Parameters
    ----------
    model, excitation
        The cargo model and its one-way excitation.
    compliance
        :func:`hull_compliance` at the model's sea-fastening points.
    deck_forces
        ``static excitation -> p``: solves the cargo's still-water state for the given static
        excitation and returns :func:`deck_forces_N` of it. Affine for the linear model (one
        Newton step is exact); piecewise affine with unilateral saddles.
    tolerance_m, max_iterations
        Convergence: largest deck-DOF mismatch [m, rad], and the iteration limit.

    Returns
    -------
    StillWaterCoupling
        Never raises for non-convergence: ``converged=False`` with the residual.
    """
    static = excitation.static_part()
    n_v = model.deck_dof_count

    def residual(v: NDArray) -> tuple[NDArray, NDArray]:
        p = deck_forces(_with_static_deck_change(static, v, ""))
        return v - compliance.deck_change(p), p

    v = np.zeros(n_v)
    r, p = residual(v)
    step_m = 1e-7  # finite-difference step: well inside the millimetre scale of the deck change
    it = 0
    for it in range(1, max_iterations + 1):
        J = np.empty((n_v, n_v))
        for j in range(n_v):
            dv = np.zeros(n_v)
            dv[j] = step_m
            J[:, j] = (residual(v + dv)[0] - r) / step_m
        try:
            v = v - np.linalg.solve(J, r)
        except np.linalg.LinAlgError:
            break
        r, p = residual(v)
        if float(np.max(np.abs(r))) <= tolerance_m:
            break
    res = float(np.max(np.abs(r)))
    ok = bool(np.isfinite(res) and res <= tolerance_m)
    dz = v[0::2]
    message = (
        f"two-way still-water coupling {'converged' if ok else 'NOT converged'} in {it} Newton step(s), "
        f"residual {res:.1e} m; deck change at the saddles {', '.join(f'{1e3 * d:+.2f}' for d in dz)} mm"
    )
    coupled = _with_static_deck_change(excitation, v, "two-way coupled still water")
    return StillWaterCoupling(coupled, v, p, ok, it, res, message)
