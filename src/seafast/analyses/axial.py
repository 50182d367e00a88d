"""The axial sliding analysis of one case: the cargo's rigid axial translation on Coulomb friction.

Runs when ``seafastening.friction_coefficient`` is set (docs/axial.md). Each row of the vertical
analysis gives the saddles' contact forces over the period (``PeriodTimeSeries.saddle_force_N``;
the linear model's can be negative, a tension no saddle carries, so every row uses
``max(N_i, 0)``); the axial load comes from the ship's surge and pitch. The static rows are the
still-water statics (no axial load at even keel); the dynamic rows are solved by the axial
harmonic balance, or by the rigid-Coulomb time-domain reference where the HBM does not converge
(long stick phases, docs/axial.md; the row's message says so) or when ``solver.method =
time_domain``. The coupling is one way (the friction does not change the normal forces); its size
is estimated per row (``friction_moment_saddle_force_change_N``). The record:
:class:`~seafast.results.axial.AxialCaseArrays`.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import replace
from typing import Any

import numpy as np

from seafast.analyses.axial_coupling import friction_moment_effect_N, saddle_moment_flexibility
from seafast.config.modes import SolverMethod
from seafast.config.schema import Case
from seafast.excitation.axial import AxialLoad, axial_load_of
from seafast.excitation.vessel import VesselExcitation
from seafast.fourier import harmonics_to_time
from seafast.model.axial import AxialRestraint
from seafast.model.from_case import axial_restraint
from seafast.model.structure import StructuralModel
from seafast.results.axial import ROW_VARIABLES, TIME_VARIABLES, AxialCaseArrays
from seafast.results.dataset import LOAD_CASES, MODELS
from seafast.results.timeseries import PeriodTimeSeries
from seafast.solvers.axial import (
    AxialHBMOptions,
    AxialResponse,
    AxialWarning,
    axial_time_samples,
    critical_friction_coefficient,
    solve_axial_hbm,
    solve_axial_time_domain,
    static_response,
)

__all__ = ["run_axial_analysis", "axial_case_arrays", "axial_options", "frictionless_extremes", "row_warnings", "solve_axial_row"]


AXIAL_CROSS_CHECK = 0.01
"""A sliding axial HBM answer more than this share off the time-domain reference's axial force gives way to it."""


def solve_axial_row(
    restraint: AxialRestraint,
    load: AxialLoad,
    normal: np.ndarray,
    static: bool,
    method: str,
    options: AxialHBMOptions,
    N: int,
    start: np.ndarray | None = None,
) -> AxialResponse:
    """One row's axial response on the sample grid of N: the axial HBM, checked by (or replaced with) the reference.

    The still-water row is static; ``method = "time_domain"`` solves by the rigid-Coulomb reference. Otherwise the
    axial HBM answers when it converges locked, or with no friction and no stopper (a linear oscillator); a sliding
    answer is checked against the reference and gives way to it beyond :data:`AXIAL_CROSS_CHECK`; an HBM that does not
    converge gives way to it too (the message says so).
    """
    if static:
        return static_response(restraint, float(load.force_N[0].real), float(restraint.capacity_N(normal[0])), load.omega_rad_s, N)
    if method == SolverMethod.TIME_DOMAIN:
        return solve_axial_time_domain(restraint, load, normal, time_samples=options.time_samples).on_grid(N)
    hbm = solve_axial_hbm(restraint, load, normal, options, initial_harmonics=start)
    if hbm.converged and hbm.slip_m == 0.0:
        return hbm.on_grid(N)
    if hbm.converged and not restraint.has_stoppers and not np.any(restraint.capacity_N(normal)):
        # no friction and no stopper: a linear oscillator on the lashings, which the harmonic balance solves exactly
        # (the reference would integrate the decay of its light damping, hundreds of periods)
        return replace(hbm, message=f"{hbm.message}; no friction and no stopper: a linear oscillator, solved exactly").on_grid(N)
    # long stick phases defeat the truncated Fourier series (docs/axial.md), and so do the brief slips of a cargo
    # walking near the shakedown coefficient: a sliding answer is checked against the reference, which then answers
    td = solve_axial_time_domain(restraint, load, normal, time_samples=options.time_samples)
    if hbm.converged:
        change = abs(hbm.axial_force_N - td.axial_force_N) / max(abs(td.axial_force_N), 1.0)
        if change <= AXIAL_CROSS_CHECK or not td.converged:
            return hbm.on_grid(N)
        note = f"{hbm.message}; its axial force is {change:.1%} off the time-domain reference, which solved the row: {td.message}"
        return replace(td, message=note).on_grid(N)
    return replace(td, message=f"{hbm.message}; row solved by the time-domain reference: {td.message}").on_grid(N)


def frictionless_extremes(restraint: AxialRestraint, load: AxialLoad, options: AxialHBMOptions) -> tuple[float, float]:
    """What the lashings and stoppers alone do under the dynamic load: their largest force [N] and the largest displacement [m].

    The friction credit's counterpart (docs/axial.md#friction-credit): the same cargo and
    load with friction coefficient 0 (linear with lashings only; the stoppers' free play solved by
    the HBM). ``(0, inf)`` when nothing restrains the cargo axially, ``(nan, nan)`` when that solve
    fails.
    """
    if restraint.lashing_axial_stiffness_N_per_m == 0.0 and not restraint.has_stoppers:
        return 0.0, math.inf
    if not restraint.has_stoppers:  # a linear oscillator: per harmonic
        k = np.arange(load.force_N.size)
        w = load.omega_rad_s
        Z = restraint.lashing_axial_stiffness_N_per_m - restraint.cargo_mass_kg * (k * w) ** 2 + 1j * restraint.damping_N_s_per_m * k * w
        u = harmonics_to_time(load.force_N / Z, options.time_samples)
        return restraint.lashing_axial_stiffness_N_per_m * float(np.max(np.abs(u))), float(np.max(np.abs(u)))
    free = replace(restraint, friction_coefficient=np.zeros(restraint.saddle_count))
    resp = solve_axial_hbm(free, load, np.zeros((options.time_samples, restraint.saddle_count)), options)
    if not resp.converged:
        return math.nan, math.nan
    return resp.axial_force_N, float(np.max(np.abs(resp.displacement_m)))


def row_warnings(resp: AxialResponse) -> tuple[AxialWarning, ...]:
    """The typed warnings of one row's response (docs/axial.md#friction-credit)."""
    friction = float(np.max(np.abs(resp.friction_force_N))) if resp.friction_force_N.size else 0.0
    return (AxialWarning.FRICTION_CARRIES_LOAD,) if friction > 0.0 and friction > resp.axial_force_N else ()


def axial_case_arrays(
    restraint: AxialRestraint,
    load: AxialLoad,
    series: Mapping[tuple[str, str], PeriodTimeSeries],
    model: StructuralModel,
    options: AxialHBMOptions,
    method: str = "hbm",
) -> AxialCaseArrays:
    """Solve the axial problem of every (load_case, model) row and collect the arrays.

    Parameters
    ----------
    restraint, load
        The cargo's axial restraint and load.
    series
        The vertical responses keyed by (load_case, model); their saddle forces are the normal forces.
    model
        The vertical structural model (saddle positions, diameters) for the coupling estimate.
    options
        Axial HBM settings (its ``time_samples`` a multiple of the series' N).
    method
        ``"hbm"`` or ``"time_domain"`` (the rigid-Coulomb reference).
    """
    N = next(iter(series.values())).saddle_force_N.shape[0]
    n_s = restraint.saddle_count
    out = AxialCaseArrays(
        np.arange(N) / N,
        {name: np.zeros((2, 2, N)) for name in TIME_VARIABLES},
        np.zeros((2, 2, N, n_s)),
        np.zeros((2, 2, N, n_s)),
        np.zeros((2, 2, N), dtype=bool),
        {name: np.zeros((2, 2)) for name in ROW_VARIABLES},
        np.zeros((2, 2), dtype=bool),
        np.empty((2, 2), dtype=object),
        np.asarray(restraint.friction_coefficient),
        _attrs(restraint, load, options, method),
    )
    nodes = model.saddle_node
    d_el = model.cargo.element_outer_diameter_m
    lever = 0.5 * 0.5 * (d_el[np.maximum(nodes - 1, 0)] + d_el[np.minimum(nodes, d_el.size - 1)])
    start = None
    flexibility = saddle_moment_flexibility(model)
    alone = frictionless_extremes(restraint, load, options)
    for i, lc in enumerate(LOAD_CASES):
        for j, mdl in enumerate(MODELS):
            normal = np.maximum(np.asarray(series[(lc, mdl)].saddle_force_N, dtype=float), 0.0)
            resp = solve_axial_row(restraint, load, normal, lc == "static", method, options, N, start)
            if resp.harmonics is not None and resp.converged:
                start = resp.harmonics  # the next row (nonlinear after linear) starts from it
            _store(out, i, j, replace(resp, warnings=row_warnings(resp)), normal, restraint)
            out.rows["friction_moment_saddle_force_change_N"][i, j] = friction_moment_effect_N(
                model, out.friction_force_per_saddle_N[i, j], lever, flexibility
            )
            static = lc == "static"
            out.rows["frictionless_axial_force_N"][i, j] = 0.0 if static else alone[0]
            out.rows["frictionless_axial_displacement_m"][i, j] = 0.0 if static else alone[1]
    return replace(out, messages=out.messages.astype(str))


def _store(out: AxialCaseArrays, i: int, j: int, resp: AxialResponse, normal: np.ndarray, restraint: AxialRestraint) -> None:
    """One row's response into the case arrays."""
    for name, attr in (
        ("axial_displacement_m", "displacement_m"),
        ("axial_velocity_m_per_s", "velocity_m_per_s"),
        ("friction_force_N", "friction_force_N"),
        ("friction_capacity_N", "capacity_N"),
        ("lashing_axial_force_N", "lashing_force_N"),
        ("stopper_force_N", "stopper_force_N"),
        ("axial_load_N", "load_N"),
    ):
        out.time[name][i, j] = getattr(resp, attr)
    out.friction_force_per_saddle_N[i, j] = resp.friction_force_N[:, None] * restraint.saddle_shares(normal)
    out.normal_force_N[i, j] = normal
    out.sliding[i, j] = resp.sliding
    rows = out.rows
    rows["slip_m"][i, j] = resp.slip_m
    rows["friction_utilisation"][i, j] = resp.friction_utilisation
    rows["axial_force_N"][i, j] = resp.axial_force_N
    rows["critical_friction_coefficient"][i, j] = critical_friction_coefficient(resp.load_N, normal)
    rows["axial_residual_norm"][i, j] = resp.residual_norm
    rows["axial_residual_drift_m"][i, j] = resp.residual_drift_m
    rows["axial_iterations"][i, j] = resp.iterations
    out.converged[i, j] = resp.converged
    out.messages[i, j] = resp.message
    out.warnings[i, j] = [w in resp.warnings for w in AxialWarning]


def _attrs(restraint: AxialRestraint, load: AxialLoad, options: AxialHBMOptions, method: str) -> dict[str, Any]:
    """The axial settings as ``results.nc`` attributes."""
    return {
        "axial_method": method,
        "axial_harmonics": options.harmonics,
        "axial_time_samples": options.time_samples,
        "axial_cargo_mass_kg": restraint.cargo_mass_kg,
        "axial_lashing_stiffness_N_per_m": restraint.lashing_axial_stiffness_N_per_m,
        "axial_tangential_stiffness_N_per_m": restraint.stick_stiffness_N_per_m,
        "axial_stopper_gap_m": float("nan") if restraint.stopper_gap_m is None else restraint.stopper_gap_m,
        "axial_stopper_stiffness_N_per_m": restraint.stopper_stiffness_N_per_m,
        "axial_load_source": load.source,
        "axial_load_lever_m": load.lever_m,
        "axial_load_amplitude_N": float(abs(load.force_N[1])) if load.force_N.size > 1 else 0.0,
        "axial_load_surge_amplitude_N": abs(load.surge_inertia_N),
        "axial_load_pitch_inertia_amplitude_N": abs(load.pitch_inertia_N),
        "axial_load_gravity_amplitude_N": abs(load.gravity_N),
    }


def axial_options(case: Case, vertical_samples: int) -> AxialHBMOptions:
    """Axial HBM settings of the case: ``solver.axial_harmonics``, samples a multiple of the vertical N."""
    H = case.solver.axial_harmonics
    return AxialHBMOptions(harmonics=H, time_samples=axial_time_samples(H, vertical_samples), tolerance=max(case.solver.tolerance, 1e-12))


def run_axial_analysis(
    case: Case, model: StructuralModel, vessel: VesselExcitation | None, series: Mapping[tuple[str, str], PeriodTimeSeries]
) -> AxialCaseArrays:
    """The axial analysis of ``case`` from its vertical responses (``series``) and vessel motions.

    Raises
    ------
    ValueError
        If the hydrodynamic data hold no surge (message says so) or the friction is not set.
    """
    mass = model.cargo.mass_kg  # the structural model's cargo: one mass for the vertical and the axial analysis
    restraint = axial_restraint(case, mass)
    load = axial_load_of(case, vessel, mass)
    method = SolverMethod.TIME_DOMAIN if case.solver.method == SolverMethod.TIME_DOMAIN else SolverMethod.HBM
    vertical_samples = next(iter(series.values())).saddle_force_N.shape[0]  # the rows' time grid (N follows the vertical H)
    return axial_case_arrays(restraint, load, series, model, axial_options(case, vertical_samples), method)
