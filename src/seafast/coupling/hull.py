"""The hull girder under the two-way coupled cargo: still water and wave, along the whole ship.

With one-way coupling the hull carries each cargo unit as a weight spread over its length
(:mod:`seafast.vessel.loading`). After a two-way coupling
(:func:`seafast.coupling.deck_iteration.couple_deck`) the cargo's converged deck forces replace it:
on the hull, each unit's spread load ``Q_k`` is exchanged for its deck forces ``P_k`` at the
sea-fastening points, harmonic by harmonic. The hull girder is linear while no section
emerges, so the coupled hull is the one-way hull plus the hull's response to
``n (P_k - Q_k)`` (n units abreast) on the coupling's patches (``Q`` over each cargo node's
tributary length, ``P`` over a patch of that length centred on its saddle), the ship
re-balanced in sinkage and trim (:func:`seafast.hull.loads.patch_load_response`).
Away from the saddle patches the lines are those of point loads at the saddles; within a patch
(about one cargo element, 1 m) the moment is rounded off: under a saddle it is lower than a
point load's peak by ``n P w / 8`` (w the patch length).

Which cargo: the nonlinear (unilateral-saddle) model's, the physical one, as the deck
variables of ``results.nc`` are. Still water: the static row's ``P_0``. Wave-induced part
(total minus still water, as the one-way wave fields): the dynamic row's harmonics
``P_k, k = 0 .. K-1`` (its mean can differ from the still-water state when a saddle lifts off)
minus the still-water change, sampled at the one-way wave balance's period fractions with
``w(t) = Re sum_k W_k exp(i k omega t)``.

Conventions as :mod:`seafast.hull`: x from the AP [m], deflection up +
relative to the chord through AP and FP, ``V = dM/dx``, sagging moment +.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from seafast.coupling.deck_iteration import DeckCoupling
from seafast.coupling.deck_loads import HullCompliance
from seafast.hull.girder import HullGirder
from seafast.hull.loads import patch_load_response
from seafast.hull.still_water import HullGirderResponse
from seafast.hull.wave import WaveHullResponse
from seafast.vessel.loading import VesselLoading

__all__ = ["CoupledHull", "coupled_hull"]


@dataclass(frozen=True)
class CoupledHull:
    """The two-way coupled hull girder along the ship (the one-way hull's grid).

    Attributes
    ----------
    x_m
        Hull nodes from the AP [m], shape (n_x,): those of the one-way still-water response.
    still_water_deflection_m, still_water_bending_moment_Nm, still_water_shear_force_N
        Still-water deflection [m] (up +, chord through AP and FP), bending moment [N m]
        (sagging +) and shear force [N] under the coupled cargo (the static nonlinear row).
    period_fraction
        t / T of the wave samples, shape (n_t,) (those of the one-way wave balance; empty
        without a wave).
    wave_deflection_m, wave_bending_moment_Nm
        Wave-induced deflection [m] and bending moment [N m] (coupled total minus coupled still
        water), shape (n_t, n_x); ``None`` without a wave.
    """

    x_m: NDArray[np.float64]
    still_water_deflection_m: NDArray[np.float64]
    still_water_bending_moment_Nm: NDArray[np.float64]
    still_water_shear_force_N: NDArray[np.float64]
    period_fraction: NDArray[np.float64]
    wave_deflection_m: NDArray[np.float64] | None = None
    wave_bending_moment_Nm: NDArray[np.float64] | None = None


def coupled_hull(
    girder: HullGirder,
    loading: VesselLoading,
    compliance: HullCompliance,
    still_water: HullGirderResponse,
    still_water_row: DeckCoupling,
    wave: WaveHullResponse | None = None,
    wave_row: DeckCoupling | None = None,
) -> CoupledHull:
    """The hull girder under the converged two-way cargo forces.

    Parameters
    ----------
    girder, loading
        The hull girder and the one-way loading it was solved with.
    compliance
        The coupling's :class:`~seafast.coupling.deck_loads.HullCompliance` (cargo nodes on the
        ship, saddle nodes, units abreast).
    still_water
        The one-way still-water response (its nodes are the output grid).
    still_water_row
        The coupled static row (its ``P_0`` and ``Q_0``).
    wave, wave_row
        The one-way wave response and the coupled dynamic row; both or neither.

    Returns
    -------
    CoupledHull
    """
    n = compliance.units_abreast
    sets = [n * np.real(compliance.patch_loads_N(still_water_row.deck_force_N[:1], still_water_row.spread_load_N[:1]))]
    K = 0
    if wave is not None and wave_row is not None:
        net = n * compliance.patch_loads_N(wave_row.deck_force_N, wave_row.spread_load_N)
        K = net.shape[0]
        sets += [net.real, net[1:].imag]  # the hull is linear: real and imaginary parts apart
    response = patch_load_response(girder, loading, compliance.patch_start_m, compliance.patch_end_m, np.concatenate(sets), still_water.x_m)
    static_z, static_m = response.deflection_m[0], response.bending_moment_Nm[0]
    out = CoupledHull(
        x_m=still_water.x_m,
        still_water_deflection_m=still_water.deflection_m + static_z,
        still_water_bending_moment_Nm=still_water.bending_moment_Nm + static_m,
        still_water_shear_force_N=still_water.shear_force_N + response.shear_force_N[0],
        period_fraction=np.zeros(0) if wave is None else wave.period_fraction,
    )
    if K == 0 or wave is None:
        return out
    if not np.array_equal(wave.x_m, still_water.x_m):
        raise ValueError("coupled_hull: the wave and still-water hull responses must share their nodes")

    def harmonics(lines: NDArray) -> NDArray[np.complex128]:
        return lines[1 : 1 + K] + 1j * np.concatenate([np.zeros((1, lines.shape[1])), lines[1 + K :]])

    phase = np.exp(2j * np.pi * np.outer(wave.period_fraction, np.arange(K)))  # (n_t, K)
    dz = np.real(phase @ harmonics(response.deflection_m)) - static_z
    dm = np.real(phase @ harmonics(response.bending_moment_Nm)) - static_m
    return CoupledHull(
        x_m=out.x_m,
        still_water_deflection_m=out.still_water_deflection_m,
        still_water_bending_moment_Nm=out.still_water_bending_moment_Nm,
        still_water_shear_force_N=out.still_water_shear_force_N,
        period_fraction=out.period_fraction,
        wave_deflection_m=wave.deflection_m + dz,
        wave_bending_moment_Nm=wave.bending_moment_Nm + dm,
    )
