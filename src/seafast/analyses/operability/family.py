"""The sea states of an operability run: one case's spectrum shape at many (Tp, Hs), transfer functions shared.

The transfer functions are computed once on a fine uniform master grid covering every peak
period's sea-state grid (:func:`sea_state_family`) and interpolated (cubic splines of the real and
imaginary parts) to each Tp's own grid (:func:`analysis_at`): within 1e-4 of each response's
peak (2e-3 of the inertia load where the RAOs, linear between BEM frequencies, have slope kinks
that a spline rounds off), and a sea state's extremes within 1e-6 of ``seafast seastate``'s
(tested). At a given Tp another Hs only scales the spectrum by Hs^2 and every MPM by Hs
(:func:`rescaled`): no response spectrum is integrated again.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, replace
from typing import Any

import numpy as np
from numpy.typing import NDArray
from scipy.interpolate import CubicSpline

from seafast.analyses.operability.cradle import CradleFamily, cradle_family
from seafast.analyses.seastate.spectral import (
    ResponseStatistics,
    SpectralAnalysis,
    SpectralExtremes,
    downcrossing_rate_per_s,
    spectral_extremes,
)
from seafast.analyses.seastate.spectrum import sea_state_spectrum
from seafast.analyses.seastate.transfer import StillWater, TransferFunctions, still_water, transfer_functions
from seafast.analyses.seastate.wave_response import MomentMap, moment_map
from seafast.config.loader import CaseError
from seafast.config.schema import Case
from seafast.excitation.harmonic import HarmonicExcitation
from seafast.excitation.vessel import vessel_excitation
from seafast.model.from_case import build_model
from seafast.model.structure import StructuralModel

__all__ = ["MASTER_STEP_RAD_S", "SeaStateFamily", "sea_state_family", "analysis_at", "rescaled", "case_at"]

MASTER_STEP_RAD_S = 0.005
"""Spacing of the master grid the transfer functions are computed on [rad/s]."""


@dataclass(frozen=True)
class SeaStateFamily:
    """What every peak period of an operability run shares (computed once per case).

    Attributes
    ----------
    case
        The case (its sea-state shape: spectrum kind, gamma, duration; its limits).
    model, moments, static, still
        Structural model, moment map, still-water excitation and linear still-water state.
    master_omega_rad_s
        The master frequency grid [rad/s].
    spline
        Cubic spline of the stacked real and imaginary parts of every transfer function on the master grid.
    layout
        (name, shape) of each stacked transfer function, in order.
    pitch_reference_x_m, moment_x_m, section_modulus_m3
        Copied from the master transfer functions.
    cradle
        Off head seas with a cradle limit set, the cargo on its cradles
        (:func:`~seafast.analyses.operability.cradle.cradle_family`); else None.
    """

    case: Case
    model: StructuralModel
    moments: MomentMap
    static: HarmonicExcitation
    still: StillWater
    master_omega_rad_s: NDArray[np.float64]
    spline: Any
    layout: tuple[tuple[str, tuple[int, ...]], ...]
    pitch_reference_x_m: float
    moment_x_m: NDArray[np.float64]
    section_modulus_m3: NDArray[np.float64]
    cradle: CradleFamily | None = None


_COMPLEX_FIELDS = (
    "deck_displacement",
    "cargo_load_N",
    "cargo_line_load_N_per_m",
    "heave_m",
    "pitch_rad",
    "cargo_displacement",
    "saddle_compression_m",
    "saddle_force_N",
    "bending_moment_Nm",
)


def case_at(case: Case, peak_period_s: float, significant_height_m: float) -> Case:
    """The case with another sea state (no re-validation: the steepness is the caller's to respect)."""
    ss = case.sea_state.model_copy(update={"peak_period_s": float(peak_period_s), "significant_height_m": float(significant_height_m)})
    return case.model_copy(update={"sea_state": ss})


def _check_parametric(case: Case) -> None:
    if case.sea_state.spectrum not in ("jonswap", "pierson_moskowitz"):
        raise CaseError(
            f"sea_state.spectrum = '{case.sea_state.spectrum}': operability varies the peak period, which a spectrum table "
            "fixes; allowed: jonswap or pierson_moskowitz"
        )


def _check_long_crested(case: Case) -> None:
    if case.sea_state.spreading_exponent is not None:
        raise CaseError(
            f"sea_state.spreading_exponent = {case.sea_state.spreading_exponent:g}: operability takes long-crested seas at "
            "sea_state.heading_deg (the quadratic roll damping left out: linear roll damping, conservative); "
            "use --set sea_state.spreading_exponent=null, or seafast seastate for one short-crested sea state"
        )


def sea_state_family(case: Case, peak_periods_s: Sequence[float], master_step_rad_s: float = MASTER_STEP_RAD_S) -> SeaStateFamily:
    """The shared part of the sea states at ``peak_periods_s`` (transfer functions on the master grid).

    Raises
    ------
    CaseError
        A spectrum table, a peak period whose spectrum the transfer functions do not resolve
        (the message names the peak period and the allowed range), or a vessel set-up without
        per-frequency hull response.
    ValueError
        Off head seas with a cradle limit set, cradles that cannot be built from the case (naming the key).
    """
    _check_parametric(case)
    _check_long_crested(case)
    grids = [sea_state_spectrum(case_at(case, tp, 1.0)).omega_rad_s for tp in peak_periods_s]
    lo, hi = min(float(g[0]) for g in grids), max(float(g[-1]) for g in grids)
    n = max(math.ceil((hi - lo) / master_step_rad_s) + 1, 8)
    master = np.linspace(lo, hi, n)
    model = build_model(case)
    tf = transfer_functions(case, model, master, heading_deg=case.sea_state.heading_deg)
    layout = tuple((name, getattr(tf, name).shape[1:]) for name in _COMPLEX_FIELDS)
    stacked = np.concatenate([getattr(tf, name).reshape(n, -1) for name in _COMPLEX_FIELDS], axis=1)
    values = np.concatenate([stacked.real, stacked.imag, tf.hull_emergence_amplitude_m[:, None]], axis=1)
    static = vessel_excitation(case).cargo_excitation(model, case).static_part()
    return SeaStateFamily(
        case=case,
        model=model,
        moments=moment_map(model),
        static=static,
        still=still_water(case, model),
        master_omega_rad_s=master,
        spline=CubicSpline(master, values, axis=0),
        layout=layout,
        pitch_reference_x_m=tf.pitch_reference_x_m,
        moment_x_m=tf.bending_moment_x_m,
        section_modulus_m3=tf.bending_section_modulus_m3,
        cradle=cradle_family(case, model),
    )


def _interpolated_transfer(family: SeaStateFamily, omega: NDArray[np.float64]) -> TransferFunctions:
    v = family.spline(omega)
    n_complex = (v.shape[1] - 1) // 2
    z = v[:, :n_complex] + 1j * v[:, n_complex : 2 * n_complex]
    parts: dict[str, Any] = {}
    start = 0
    for name, shape in family.layout:
        width = int(np.prod(shape, dtype=int)) if shape else 1
        parts[name] = z[:, start : start + width].reshape((omega.size,) + tuple(shape))
        start += width
    return TransferFunctions(
        omega_rad_s=omega,
        pitch_reference_x_m=family.pitch_reference_x_m,
        bending_moment_x_m=family.moment_x_m,
        bending_section_modulus_m3=family.section_modulus_m3,
        hull_emergence_amplitude_m=v[:, -1],
        heading_deg=family.case.sea_state.heading_deg,
        **parts,
    )


def analysis_at(family: SeaStateFamily, peak_period_s: float, significant_height_m: float) -> SpectralAnalysis:
    """The spectral analysis of the family's sea state at (Tp, Hs), transfer functions interpolated."""
    case = case_at(family.case, peak_period_s, significant_height_m)
    spectrum = sea_state_spectrum(case)
    tf = _interpolated_transfer(family, spectrum.omega_rad_s)
    return SpectralAnalysis(case, family.model, spectrum, tf, spectral_extremes(tf, spectrum, family.still, case.sea_state.duration_s))


def _scaled_statistics(stats: ResponseStatistics, k: float) -> ResponseStatistics:
    """Statistics of the response in the same sea scaled in variance by ``k`` (Tz unchanged)."""
    r = math.sqrt(k)
    return ResponseStatistics(
        stats.spectrum * k, stats.m0 * k, stats.m2 * k, stats.m4 * k, stats.sigma * r, stats.zero_crossing_period_s, stats.mpm * r
    )


def rescaled(analysis: SpectralAnalysis, hs: float) -> SpectralAnalysis:
    """The same sea state at significant height ``hs``: the spectrum scales with Hs^2, every MPM with Hs.

    Equal to :func:`~seafast.analyses.seastate.spectral.spectral_extremes` on the scaled spectrum (tested),
    without integrating the response spectra again.
    """
    sp, e = analysis.spectrum, analysis.extremes
    k = (hs / sp.significant_height_m) ** 2
    spectrum = replace(
        sp,
        density_m2_s_per_rad=sp.density_m2_s_per_rad * k,
        significant_height_m=float(hs),
        variance_outside_grid_m2=sp.variance_outside_grid_m2 * k,
        description=sp.description.replace(f"Hs = {sp.significant_height_m:g} m", f"Hs = {hs:g} m"),
    )
    force, comp, moment, stress = (
        _scaled_statistics(s, k) for s in (e.saddle_force, e.saddle_compression, e.bending_moment, e.bending_stress)
    )
    still = e.still_water
    uplift = 3600.0 * downcrossing_rate_per_s(still.saddle_compression_m, comp.m0, comp.m2)
    totals = {
        "F_N": float(np.max(still.saddle_force_N + force.mpm)),
        "M_b_Nm": float(np.max(np.abs(still.bending_moment_Nm) + moment.mpm)),
        "sigma_b_Pa": float(np.max(np.abs(still.bending_stress_Pa) + stress.mpm)),
        "u_s_m": float(max(np.max(still.saddle_compression_m + comp.mpm), 0.0)),
        "u_d_m": 0.0,
        "uplift_per_hour": float(np.sum(uplift)),
    }
    extremes = SpectralExtremes(e.duration_s, force, comp, moment, stress, still, uplift, totals)
    case = case_at(analysis.case, float(analysis.case.sea_state.peak_period_s or sp.peak_period_s), hs)
    return SpectralAnalysis(case, analysis.model, spectrum, analysis.transfer, extremes)
