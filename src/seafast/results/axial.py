"""The axial sliding analysis of one case: per (load_case, model) row, arrays, summary columns, Dataset.

Runs when ``seafastening.friction_coefficient`` is set (docs/axial.md). Each row of the vertical
analysis gives the saddles' contact forces over the period (``PeriodTimeSeries.saddle_force_N``;
the linear model's can be negative, a tension no saddle carries, so every row uses
``max(N_i, 0)``); the axial load comes from the ship's surge and pitch. The static rows are the
still-water statics (no axial load at even keel); the dynamic rows are solved by the axial
harmonic balance, or by the rigid-Coulomb time-domain reference where the HBM does not converge
(long stick phases, docs/axial.md; the row's message says so) or when ``solver.method =
time_domain``.
The coupling is one way (the friction does not change the normal forces); its size is estimated
per row (``friction_moment_saddle_force_change_N``).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np
import xarray as xr
from scipy.linalg import solveh_banded

from seafast.config.schema import Case
from seafast.excitation.axial import AxialLoad, axial_load_of
from seafast.model.axial import AxialRestraint
from seafast.model.from_case import axial_restraint
from seafast.model.structure import StructuralModel
from seafast.results.timeseries import PeriodTimeSeries
from seafast.solvers.axial import (
    AxialHBMOptions,
    AxialResponse,
    axial_time_samples,
    critical_friction_coefficient,
    solve_axial_hbm,
    solve_axial_time_domain,
    static_response,
)

__all__ = [
    "AXIAL_SUMMARY_COLUMNS",
    "AxialCaseArrays",
    "run_axial_analysis",
    "axial_case_arrays",
    "friction_moment_effect_N",
    "saddle_moment_flexibility",
]

#: Columns ``summary.csv`` gains (after ``converged``) when the axial analysis runs.
AXIAL_SUMMARY_COLUMNS = ("slip_m", "friction_utilisation", "axial_force_N")

_LOAD_CASES = ("static", "dynamic")
_MODELS = ("linear", "nonlinear")

_TIME_VARS: dict[str, tuple[str, str]] = {
    "axial_displacement_m": ("cargo axial displacement relative to the deck (forward +)", "m"),
    "axial_velocity_m_per_s": ("cargo axial velocity relative to the deck (forward +)", "m/s"),
    "friction_force_N": ("friction force of all saddles on the cargo (forward +)", "N"),
    "friction_capacity_N": ("friction available, sum of mu_i max(N_i, 0) over the saddles", "N"),
    "lashing_axial_force_N": ("axial force of the lashings on the cargo (forward +)", "N"),
    "stopper_force_N": ("axial force of the end stoppers on the cargo (forward +)", "N"),
    "axial_load_N": ("axial inertia and gravity load on the cargo in the ship's frame (forward +)", "N"),
}
_ROW_VARS: dict[str, tuple[str, str]] = {
    "slip_m": ("sliding distance of the cargo per period (0 when stuck)", "m"),
    "friction_utilisation": ("friction force over friction available, maximum over the period (1 = slides)", "1"),
    "axial_force_N": ("largest axial force of the lashings and stoppers on the cargo", "N"),
    "critical_friction_coefficient": ("uniform friction coefficient below which the cargo starts to slide", "1"),
    "friction_moment_saddle_force_change_N": (
        (
            "estimated change of the saddle forces by the friction's moment "
            "(friction at the contact line, D/2 below the axis; quasi-static, bilateral saddles)"
        ),
        "N",
    ),
    "axial_residual_norm": ("axial solver residual (HBM: relative; time domain: last period change)", "1"),
    "axial_iterations": ("axial solver iterations (HBM: Newton; time domain: periods)", "1"),
}


@dataclass(frozen=True)
class AxialCaseArrays:
    """The axial numbers of one case, axes (load_case, model, period_fraction[, saddle])."""

    period_fraction: np.ndarray
    time: dict[str, np.ndarray]  # _TIME_VARS, each (2, 2, N)
    friction_force_per_saddle_N: np.ndarray  # (2, 2, N, n_s)
    normal_force_N: np.ndarray  # (2, 2, N, n_s), max(N, 0)
    sliding: np.ndarray  # (2, 2, N) bool
    rows: dict[str, np.ndarray]  # _ROW_VARS, each (2, 2)
    converged: np.ndarray  # (2, 2) bool
    messages: np.ndarray  # (2, 2) str
    friction_coefficient: np.ndarray  # (n_s,)
    attrs: dict[str, Any] = field(default_factory=dict)

    def summary_columns(self, load_case: str, model: str) -> dict[str, Any]:
        """The axial columns of one summary row (plus ``critical_friction_coefficient`` and ``axial_converged``)."""
        i, j = _LOAD_CASES.index(load_case), _MODELS.index(model)
        out: dict[str, Any] = {name: float(self.rows[name][i, j]) for name in (*AXIAL_SUMMARY_COLUMNS, "critical_friction_coefficient")}
        out["axial_converged"] = bool(self.converged[i, j])
        return out

    @property
    def summary_column_names(self) -> tuple[str, ...]:
        """The columns ``summary.csv`` gains: :data:`AXIAL_SUMMARY_COLUMNS`."""
        return AXIAL_SUMMARY_COLUMNS

    def extend_summary(self, rows: list[dict[str, Any]]) -> list[dict[str, Any]]:
        """The summary rows with the axial columns added; ``converged`` then includes the axial solve."""
        for row in rows:
            row.update(self.summary_columns(row["load_case"], row["model"]))
            row["converged"] = bool(row["converged"] and row["axial_converged"])
        return rows

    def merged_into(self, ds: xr.Dataset) -> xr.Dataset:
        """``ds`` (the case's results) with the axial variables and attributes merged in."""
        axial = self.to_dataset()
        out = xr.merge([ds, axial], combine_attrs="override")
        out.attrs.update(ds.attrs)
        out.attrs.update(axial.attrs)
        return out

    def to_dataset(self) -> xr.Dataset:
        """The axial variables of ``results.nc`` (units and long names on every one)."""
        dims3 = ("load_case", "model", "period_fraction")
        data: dict[str, Any] = {
            name: xr.Variable(dims3, self.time[name], {"long_name": ln, "units": u}) for name, (ln, u) in _TIME_VARS.items()
        }
        data["friction_force_per_saddle_N"] = xr.Variable(
            dims3 + ("saddle",),
            self.friction_force_per_saddle_N,
            {"long_name": "friction force of each saddle on the cargo (forward +; shares mu_i N_i / sum mu_j N_j)", "units": "N"},
        )
        data["friction_normal_force_N"] = xr.Variable(
            dims3 + ("saddle",), self.normal_force_N, {"long_name": "saddle contact force the friction acts with, max(N, 0)", "units": "N"}
        )
        data["sliding"] = xr.Variable(dims3, self.sliding.astype(np.int8), {"long_name": "cargo sliding (1) or stuck (0)", "units": "1"})
        for name, (ln, u) in _ROW_VARS.items():
            data[name] = xr.Variable(("load_case", "model"), self.rows[name], {"long_name": ln, "units": u})
        data["axial_converged"] = xr.Variable(
            ("load_case", "model"), self.converged.astype(np.int8), {"long_name": "axial solver converged", "units": "1"}
        )
        data["axial_solver_message"] = xr.Variable(
            ("load_case", "model"), self.messages.astype(str), {"long_name": "axial solver message", "units": "1"}
        )
        data["friction_coefficient"] = xr.Variable(
            ("saddle",), self.friction_coefficient, {"long_name": "Coulomb friction coefficient of each saddle", "units": "1"}
        )
        return xr.Dataset(data, attrs=self.attrs)


def saddle_moment_flexibility(model: StructuralModel) -> np.ndarray:
    """Saddle compression change per unit moment at each saddle, quasi-static, bilateral saddles [m/(N m)], (n_s, n_s).

    ``G[i, j]``: ``-dz_i`` at saddle i for a unit bow-up moment on the cargo at saddle j, from one
    banded Cholesky solve of ``K dq = M`` (the cargo's first natural frequency, 44 rad/s on the
    base case, is far above the wave's 0.6 rad/s).
    """
    K = model.cargo.stiffness + model.spring_matrices(True)[0]
    n = K.shape[0]
    band = 3  # Hermite beam elements couple the (z, theta) pairs of neighbouring nodes; springs are diagonal
    ab = np.zeros((band + 1, n))
    for d in range(band + 1):
        ab[band - d, d:] = np.diagonal(K, d)
    rhs = np.zeros((n, model.saddle_count))
    rhs[model.saddle_cargo_dof + 1, np.arange(model.saddle_count)] = 1.0
    dq = solveh_banded(ab, rhs)
    return -dq[model.saddle_cargo_dof]


def friction_moment_effect_N(
    model: StructuralModel, friction_per_saddle_N: np.ndarray, lever_m: np.ndarray, flexibility: np.ndarray | None = None
) -> float:
    """Largest change of the saddle forces [N] by the friction's moment, quasi-static, bilateral saddles.

    Friction ``f_i`` (forward +) at the contact line ``lever_i`` (D/2) below the cargo's axis
    puts the moment ``+f_i lever_i`` (bow up) on the cargo at saddle ``i``; the saddle forces
    change by ``k_u G M`` (:func:`saddle_moment_flexibility`).
    """
    moments = np.asarray(friction_per_saddle_N, dtype=float) * np.asarray(lever_m, dtype=float)  # (N, n_s)
    if not np.any(moments):
        return 0.0
    G = saddle_moment_flexibility(model) if flexibility is None else flexibility
    return float(np.max(np.abs(model.saddle_unilateral_stiffness_N_per_m[:, None] * (G @ moments.T))))


def _row(
    restraint: AxialRestraint,
    load: AxialLoad,
    normal: np.ndarray,
    static: bool,
    method: str,
    options: AxialHBMOptions,
    N: int,
    start: np.ndarray | None = None,
) -> AxialResponse:
    if static:
        f0 = float(load.force_N[0].real)
        cap = float(restraint.capacity_N(normal[0]))
        if abs(f0) > cap:
            z = np.zeros(N)
            return AxialResponse(
                "statics",
                load.omega_rad_s,
                z,
                z.copy(),
                -np.sign(f0) * cap * np.ones(N),
                cap * np.ones(N),
                z.copy(),
                z.copy(),
                f0 * np.ones(N),
                np.ones(N, dtype=bool),
                float("inf"),
                False,
                float("nan"),
                0,
                "the still-water axial load exceeds the friction: the cargo slides in still water",
            )
        return static_response(restraint, f0, cap, load.omega_rad_s, N)
    if method == "time_domain":
        return solve_axial_time_domain(restraint, load, normal, time_samples=options.time_samples).on_grid(N)
    hbm = solve_axial_hbm(restraint, load, normal, options, initial_harmonics=start)
    if hbm.converged:
        return hbm.on_grid(N)
    # long stick phases defeat the truncated Fourier series (docs/axial.md): the reference solves the row
    td = solve_axial_time_domain(restraint, load, normal, time_samples=options.time_samples)
    return replace(td, message=f"{hbm.message}; row solved by the time-domain reference: {td.message}").on_grid(N)


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
    time = {name: np.zeros((2, 2, N)) for name in _TIME_VARS}
    per_saddle = np.zeros((2, 2, N, n_s))
    normal_all = np.zeros((2, 2, N, n_s))
    sliding = np.zeros((2, 2, N), dtype=bool)
    rows = {name: np.zeros((2, 2)) for name in _ROW_VARS}
    converged = np.zeros((2, 2), dtype=bool)
    messages = np.empty((2, 2), dtype=object)
    nodes = model.saddle_node
    d_el = model.cargo.element_outer_diameter_m
    lever = 0.5 * 0.5 * (d_el[np.maximum(nodes - 1, 0)] + d_el[np.minimum(nodes, d_el.size - 1)])
    start = None
    flexibility = saddle_moment_flexibility(model)
    for i, lc in enumerate(_LOAD_CASES):
        for j, mdl in enumerate(_MODELS):
            normal = np.maximum(np.asarray(series[(lc, mdl)].saddle_force_N, dtype=float), 0.0)
            resp = _row(restraint, load, normal, lc == "static", method, options, N, start)
            if resp.harmonics is not None and resp.converged:
                start = resp.harmonics  # the next row (nonlinear after linear) starts from it
            for name, attr in (
                ("axial_displacement_m", "displacement_m"),
                ("axial_velocity_m_per_s", "velocity_m_per_s"),
                ("friction_force_N", "friction_force_N"),
                ("friction_capacity_N", "capacity_N"),
                ("lashing_axial_force_N", "lashing_force_N"),
                ("stopper_force_N", "stopper_force_N"),
                ("axial_load_N", "load_N"),
            ):
                time[name][i, j] = getattr(resp, attr)
            per_saddle[i, j] = resp.friction_force_N[:, None] * restraint.saddle_shares(normal)
            normal_all[i, j] = normal
            sliding[i, j] = resp.sliding
            rows["slip_m"][i, j] = resp.slip_m
            rows["friction_utilisation"][i, j] = resp.friction_utilisation
            rows["axial_force_N"][i, j] = resp.axial_force_N
            rows["critical_friction_coefficient"][i, j] = critical_friction_coefficient(resp.load_N, normal)
            rows["friction_moment_saddle_force_change_N"][i, j] = friction_moment_effect_N(model, per_saddle[i, j], lever, flexibility)
            rows["axial_residual_norm"][i, j] = resp.residual_norm
            rows["axial_iterations"][i, j] = resp.iterations
            converged[i, j] = resp.converged
            messages[i, j] = resp.message
    attrs = {
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
    return AxialCaseArrays(
        np.arange(N) / N,
        time,
        per_saddle,
        normal_all,
        sliding,
        rows,
        converged,
        messages.astype(str),
        np.asarray(restraint.friction_coefficient),
        attrs,
    )


def axial_options(case: Case, vertical_samples: int) -> AxialHBMOptions:
    """Axial HBM settings of the case: ``solver.axial_harmonics``, samples a multiple of the vertical N."""
    H = case.solver.axial_harmonics
    return AxialHBMOptions(harmonics=H, time_samples=axial_time_samples(H, vertical_samples), tolerance=max(case.solver.tolerance, 1e-12))


def run_axial_analysis(
    case: Case, model: StructuralModel, vessel: Any, series: Mapping[tuple[str, str], PeriodTimeSeries]
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
    method = "time_domain" if case.solver.method == "time_domain" else "hbm"
    vertical_samples = next(iter(series.values())).saddle_force_N.shape[0]  # the rows' time grid (N follows the vertical H)
    return axial_case_arrays(restraint, load, series, model, axial_options(case, vertical_samples), method)
