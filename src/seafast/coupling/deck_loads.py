"""The loads two-way coupling exchanges on the hull girder, and the hull's compliance under them.

With one-way coupling (the source's assumption) the hull girder carries the cargo as a load
spread over its length (its weight in still water; nothing at wave frequency, since the
quasi-static hull balance has no inertia), and the cargo only follows the deck. With four
monopiles abreast, the cargo's bending stiffness is comparable to the hull's, and its loads reach
the deck at the sea-fastening points only, in proportions the hull's own bending decides.
``two_way`` exchanges, on the hull, the cargo's spread load for the forces it actually exerts at
the sea-fastening points, harmonic by harmonic:

    Z_k = Z_k(one way) + n C (P_k - Q_k),    k = 0 .. K-1

where ``Z_k`` are the deck DOFs under the sea-fastening (deflection z [m] and slope theta [rad]
at each saddle) of harmonic k, ``n`` the number of identical units abreast, ``P_k`` [N] the
downward force one unit exerts on the deck at each sea-fastening point (saddle contact force,
lashing spring force, minus the pretension's reaction, which pulls the deck up;
:func:`deck_forces_N`), ``Q_k`` [N] the same unit's spread load as the one-way model sees it,
lumped on the cargo nodes (its weight at k = 0; at k >= 1 its rigid-body inertia load, so that
the exchange is self-equilibrated and the quasi-static hull, which balances no inertia, is not
asked to; :func:`spread_load_N`), and ``C`` the hull's compliance (:class:`HullCompliance`):
deck deflection and slope per newton of downward load, ``Q`` spread over each cargo node's
tributary length and ``P`` over a patch of the same length centred on its sea-fastening point
(so that its resultant acts at the saddle), the ship re-balanced in sinkage and trim.

The hull girder is quasi-static and linear while no section emerges, so ``C`` is exact and
serves every harmonic. The moments of the rotational lashing springs (a few kN m) are not
applied to the hull. The iteration that makes the deck and the cargo agree is
:mod:`seafast.coupling.deck_iteration`. Theory and checks: ``docs/coupling.md``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from seafast.excitation.harmonic import HarmonicExcitation
from seafast.fourier import harmonics_to_time, time_to_harmonics
from seafast.hull.girder import HullGirder
from seafast.hull.loads import deck_load_influence
from seafast.model.structure import StructuralModel
from seafast.solvers.linear import LinearResponse
from seafast.solvers.periodic import PeriodicResponse
from seafast.vessel.loading import VesselLoading

CargoResponse = LinearResponse | PeriodicResponse
"""The cargo's response to a deck: the linear (bilateral) model's or a nonlinear solver's."""

__all__ = ["CargoResponse", "HullCompliance", "hull_compliance", "spread_load_N", "deck_forces_N"]


@dataclass(frozen=True)
class HullCompliance:
    """The hull girder's compliance at the sea-fastening points, for loads on patches of deck.

    Two kinds of patch: each cargo node's tributary length (where the one-way spread load ``Q``
    acts, so that the patches tile the cargo and a uniform load stays uniform), then one patch
    per sea-fastening point centred on it, of its node's tributary length (where the deck force
    ``P`` acts, so that its resultant sits at the saddle, as a point load's would).

    Attributes
    ----------
    node_x_ship_m
        Ship x of the cargo nodes, from the AP [m], shape (n_nodes,).
    saddle_node
        Cargo node of each sea-fastening point, shape (n_s,).
    patch_start_m, patch_end_m
        Ship x of the patch ends [m], shape (n_nodes + n_s,): the nodes' tributary lengths,
        then the patches centred on the sea-fastening points.
    deflection_m_per_N, slope_rad_per_N
        Deck deflection [m] and slope [rad] at sea-fastening point i per newton of downward load
        spread over patch j (the ship re-balanced), shape (n_s, n_nodes + n_s).
    units_abreast
        Identical cargo units side by side, each on its own saddles at the same x.
    """

    node_x_ship_m: NDArray[np.float64]
    saddle_node: NDArray[np.intp]
    patch_start_m: NDArray[np.float64]
    patch_end_m: NDArray[np.float64]
    deflection_m_per_N: NDArray[np.float64]
    slope_rad_per_N: NDArray[np.float64]
    units_abreast: int

    @property
    def saddle_deflection_m_per_N(self) -> NDArray[np.float64]:
        """Deck deflection at point i per newton of deck force at point j [m/N], (n_s, n_s)."""
        return self.deflection_m_per_N[:, self.node_x_ship_m.size :]

    @property
    def saddle_slope_rad_per_N(self) -> NDArray[np.float64]:
        """Deck slope at point i per newton of deck force at point j [rad/N], (n_s, n_s)."""
        return self.slope_rad_per_N[:, self.node_x_ship_m.size :]

    def patch_loads_N(self, deck_force_N: NDArray, spread_load_N: NDArray) -> NDArray:
        """What two-way coupling adds to the one-way hull loading, per unit, on the patches [N].

        ``-Q_k`` on the nodes' patches and ``P_k`` on the sea-fastening points' patches
        (downward +), shape (K, n_nodes + n_s).

        Parameters
        ----------
        deck_force_N
            ``P_k``: downward force of one unit on the deck at each point [N], (K, n_s).
        spread_load_N
            ``Q_k``: the unit's spread load on its nodes, downward [N], (K, n_nodes).
        """
        Q = np.asarray(spread_load_N)
        P = np.asarray(deck_force_N)
        return np.concatenate([-Q, P], axis=-1).astype(np.result_type(Q, P, float), copy=False)

    def deck_change(self, deck_force_N: NDArray, spread_load_N: NDArray) -> NDArray:
        """Deck DOFs (z, theta interleaved per point) of two-way minus one-way, per harmonic.

        Parameters
        ----------
        deck_force_N
            ``P_k``: downward force of one unit on the deck at each point [N], (K, n_s).
        spread_load_N
            ``Q_k``: the unit's spread load on its nodes, downward [N], (K, n_nodes).
        """
        net = self.patch_loads_N(deck_force_N, spread_load_N)
        out = np.empty((net.shape[0], 2 * self.saddle_node.size), dtype=net.dtype)
        out[:, 0::2] = self.units_abreast * net @ self.deflection_m_per_N.T
        out[:, 1::2] = self.units_abreast * net @ self.slope_rad_per_N.T
        return out


def hull_compliance(
    girder: HullGirder, loading: VesselLoading, model: StructuralModel, cargo_aft_end_x_m: float, units_abreast: int
) -> HullCompliance:
    """:class:`HullCompliance` of ``girder`` under ``loading`` at the model's sea-fastening points.

    One vectorised set of still-water solves: a probe load on each patch.
    """
    xn = float(cargo_aft_end_x_m) + model.cargo.node_x_m
    edges = np.concatenate([[xn[0]], 0.5 * (xn[1:] + xn[:-1]), [xn[-1]]])
    sad = np.asarray(model.saddle_node)
    half = 0.5 * (edges[sad + 1] - edges[sad])
    start = np.concatenate([edges[:-1], xn[sad] - half])
    end = np.concatenate([edges[1:], xn[sad] + half])
    z, s = deck_load_influence(girder, loading, start, end, xn[sad])
    return HullCompliance(xn, sad, start, end, z, s, int(units_abreast))


def spread_load_N(model: StructuralModel, excitation: HarmonicExcitation, harmonic_count: int) -> NDArray[np.complex128]:
    """``Q_k``: one unit's load on the hull as the one-way model spreads it, on the cargo nodes [N].

    Downward positive, shape (K, n_nodes): at k = 0 the weight spread uniformly over the cargo's
    length, as the one-way hull loading carries it (also for a tapered pile), lumped on each
    node's tributary length; at k >= 1 the rigid-body inertia load of the excitation.
    """
    x = model.cargo.node_x_m
    edges = np.concatenate([[x[0]], 0.5 * (x[1:] + x[:-1]), [x[-1]]])
    Q = np.zeros((harmonic_count, model.cargo.node_count), dtype=complex)
    Q[0] = model.cargo.mass_kg * model.gravity_m_per_s2 * np.diff(edges) / (x[-1] - x[0])
    m = min(harmonic_count, excitation.harmonic_count)
    Q[1:m] = -excitation.cargo_load_N[1:m, 0::2]
    return Q


def deck_forces_N(
    model: StructuralModel,
    excitation: HarmonicExcitation,
    response: CargoResponse,
    nonlinear: bool,
    harmonic_count: int = 1,
) -> NDArray:
    """``P_k``: downward force of one cargo unit on the deck at each sea-fastening point [N].

    Parameters
    ----------
    model, excitation
        The model and the excitation the response was solved for.
    response
        A :class:`~seafast.solvers.periodic.PeriodicResponse` (``nonlinear=True``: its saddle
        forces are the compression-only parts; sampled over the period) or a
        :class:`~seafast.solvers.linear.LinearResponse` (``nonlinear=False``: saddles
        bilateral in K; harmonics).
    harmonic_count
        K, harmonics k = 0 .. K-1 returned.

    Returns
    -------
    Complex amplitudes, shape (K, n_s); row 0 (the period mean) is real.
    """
    _, Kco, Koo = model.spring_matrices(include_saddles=not nonlinear)
    sad = model.saddle_deck_dof
    if isinstance(response, PeriodicResponse):  # every method has samples (the references have no harmonics)
        x_c = np.asarray(response.cargo_displacement_time_m, dtype=float)
        n_t = x_c.shape[0]
        x_o = harmonics_to_time(excitation.deck_displacement, n_t)
        p_t = (x_c @ Kco + x_o @ Koo)[:, sad] + np.asarray(response.saddle_force_time_N, dtype=float)
        P = np.zeros((harmonic_count, sad.size), dtype=complex)
        m = min(harmonic_count, n_t // 2 + 1)
        P[:m] = time_to_harmonics(p_t, m - 1)
    else:
        X = np.asarray(response.cargo_displacement)
        Xo = excitation.deck_displacement
        m = min(harmonic_count, X.shape[0], Xo.shape[0])
        P = np.zeros((harmonic_count, sad.size), dtype=complex)
        P[:m] = (X[:m] @ Kco + Xo[:m] @ Koo)[:, sad]
    P[0] -= model.seafastening.saddle_pretension_N
    return P
