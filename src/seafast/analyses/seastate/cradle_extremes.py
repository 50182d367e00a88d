"""The cradle quantities of a sea state off head seas: the columns and their linear spectral most probable maxima.

The five columns seastate.csv adds off head seas (:data:`CRADLE_COLUMNS`), each a most probable maximum (MPM) over
``sea_state.duration_s``, still water included:

``F_pad_N``
    the largest pad force over the saddles and sides;
``F_stopper_N``
    the largest side-stopper force (0 without stoppers);
``lashing_tension_max_N``, ``lashing_tension_min_N``
    the largest and the least lashing-wire tension (0 without lashing wires);
``transverse_slip_m``
    the largest lateral displacement of the cargo relative to the deck at a saddle, ``|v|`` of the cargo axis there
    (the pads are frictionless: nothing holds the cargo across but the pads' slope, the stoppers and the lashings).

**Linear, spectral** (:func:`cradle_spectral_extremes`). The response spectra ``S sum_j w_j |H_j|^2`` of the
transfer functions of :mod:`seafast.analyses.seastate.cradle_transfer` (one direction of weight 1 long-crested, the
directional quadrature of the vertical plane short-crested), their Rayleigh MPMs (narrow band,
:func:`~seafast.analyses.seastate.spectral.rayleigh_mpm`) added to the exact still water: pad force and lashing
maximum ``static + MPM``, lashing minimum ``static - MPM`` (below 0 where the linear model would push on a wire: it
goes slack), slip ``|static| + MPM``, stopper ``k max(s_static + MPM(s), 0)`` with ``s`` the stopper's engagement
from the linear motion across (the stoppers open in the linear model).

The nonlinear design-wave estimates of the same columns: :mod:`seafast.analyses.seastate.cradle_design_wave`.
Units: SI.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, replace

import numpy as np
from numpy.typing import NDArray

from seafast.analyses.seastate.cradle_transfer import (
    CradleSeaModel,
    CradleStillWater,
    CradleTransfer,
    cradle_transfer_functions,
)
from seafast.analyses.seastate.directional import DirectionalQuadrature, weighted_squared_transfer
from seafast.analyses.seastate.directional_transfer import SeaStateTransfer
from seafast.analyses.seastate.spectral import ResponseStatistics, squared_response_statistics
from seafast.analyses.seastate.spectrum import WaveSpectrum
from seafast.config.schema import HEAD_SEAS_DEG, Case

__all__ = [
    "CRADLE_COLUMNS",
    "CradleSeaTransfer",
    "CradleSpectralExtremes",
    "cradle_sea_transfer",
    "cradle_spectral_extremes",
    "cradle_columns",
    "element_groups",
    "is_off_head_seas",
]

CRADLE_COLUMNS = ("F_pad_N", "F_stopper_N", "lashing_tension_max_N", "lashing_tension_min_N", "transverse_slip_m")
"""The columns seastate.csv adds after ``converged`` off head seas."""


@dataclass(frozen=True)
class CradleSeaTransfer:
    """The cradle quantities' transfer functions at each direction of a sea state.

    Attributes
    ----------
    quadrature
        Directions [deg] and weights [-] (the vertical plane's).
    per_direction
        One :class:`~seafast.analyses.seastate.cradle_transfer.CradleTransfer` per direction.
    """

    quadrature: DirectionalQuadrature
    per_direction: tuple[CradleTransfer, ...]

    def squared(self, name: str) -> NDArray[np.float64]:
        """``sum_j w_j |H_j|^2`` of the field ``name`` of :class:`CradleTransfer` (n_w, n_loc) [unit^2/m^2]."""
        return weighted_squared_transfer(np.stack([getattr(t, name) for t in self.per_direction]), self.quadrature)


def cradle_sea_transfer(sea: CradleSeaModel, transfer: SeaStateTransfer) -> CradleSeaTransfer:
    """The cradle transfer functions of every direction of the vertical plane's sea-state transfer functions."""
    return CradleSeaTransfer(transfer.quadrature, tuple(cradle_transfer_functions(sea, tf) for tf in transfer.per_direction))


def element_groups(pads: int, stoppers: int, total: int) -> tuple[slice, slice, slice]:
    """The slices of the pads, stoppers and lashings among ``total`` elements (the problem's order)."""
    return slice(0, pads), slice(pads, pads + stoppers), slice(pads + stoppers, total)


@dataclass(frozen=True)
class CradleSpectralExtremes:
    """Linear spectral extremes of the cradle quantities.

    Attributes
    ----------
    duration_s
        Duration of the maxima [s].
    still_water
        The exact still-water state.
    engagement, element_force, lateral_displacement
        :class:`~seafast.analyses.seastate.spectral.ResponseStatistics` of every element's engagement [m] and force
        [N] (the stoppers' force 0: open in the linear model), and of the lateral displacement at each saddle [m].
    element_stiffness_N_per_m
        (m,) [N/m].
    pad_count, stopper_count
        To split the elements (pads, stoppers, lashings).
    totals
        The five :data:`CRADLE_COLUMNS` [N, N, N, N, m].
    """

    duration_s: float
    still_water: CradleStillWater
    engagement: ResponseStatistics
    element_force: ResponseStatistics
    lateral_displacement: ResponseStatistics
    element_stiffness_N_per_m: NDArray[np.float64]
    pad_count: int
    stopper_count: int
    totals: Mapping[str, float]

    def element_totals(self) -> dict[str, NDArray[np.float64]]:
        """Per element or saddle, the linear MPMs the columns are the extremes of."""
        sw, m = self.still_water, self.element_force.mpm.size
        pads, stoppers, lashings = element_groups(self.pad_count, self.stopper_count, m)
        k = self.element_stiffness_N_per_m
        return {
            "F_pad_N": sw.element_force_N[pads] + self.element_force.mpm[pads],
            "F_stopper_N": k[stoppers] * np.maximum(sw.engagement_m[stoppers] + self.engagement.mpm[stoppers], 0.0),
            "lashing_tension_max_N": sw.element_force_N[lashings] + self.element_force.mpm[lashings],
            "lashing_tension_min_N": sw.element_force_N[lashings] - self.element_force.mpm[lashings],
            "transverse_slip_m": np.abs(sw.lateral_displacement_m) + self.lateral_displacement.mpm,
        }


def cradle_spectral_extremes(
    transfer: CradleSeaTransfer, spectrum: WaveSpectrum, still: CradleStillWater, stiffness_N_per_m: NDArray[np.float64], duration_s: float
) -> CradleSpectralExtremes:
    """The linear spectral MPMs of the cradle quantities (module docstring)."""
    first = transfer.per_direction[0]
    if not np.array_equal(first.omega_rad_s, spectrum.omega_rad_s):
        raise ValueError("cradle_spectral_extremes: the transfer functions must be on the spectrum's grid")
    engagement, force, lateral = (
        squared_response_statistics(transfer.squared(name), spectrum, duration_s)
        for name in ("engagement_m", "element_force_N", "lateral_displacement_m")
    )
    out = CradleSpectralExtremes(
        float(duration_s), still, engagement, force, lateral, np.asarray(stiffness_N_per_m, float), first.pad_count, first.stopper_count, {}
    )
    per = out.element_totals()
    totals = {
        "F_pad_N": float(np.max(per["F_pad_N"], initial=0.0)),
        "F_stopper_N": float(np.max(per["F_stopper_N"], initial=0.0)),
        "lashing_tension_max_N": float(np.max(per["lashing_tension_max_N"], initial=0.0)),
        "lashing_tension_min_N": float(np.min(per["lashing_tension_min_N"])) if per["lashing_tension_min_N"].size else 0.0,
        "transverse_slip_m": float(np.max(per["transverse_slip_m"], initial=0.0)),
    }
    return replace(out, totals=totals)


def cradle_columns(values: Mapping[str, float] | None) -> dict[str, float | None]:
    """The five columns of a row: the values, or empty cells (None) where the method did not compute them."""
    return {c: (None if values is None else float(values[c])) for c in CRADLE_COLUMNS}


def is_off_head_seas(case: Case) -> bool:
    """Whether the sea state's mean heading is not head seas (180 deg): the cradle columns are then computed."""
    return float(case.sea_state.heading_deg) != HEAD_SEAS_DEG
