"""One case end to end: configuration -> model -> excitation -> solvers -> results.

This is the only place that knows the order of the stages; each stage is a pure function of
the previous one's output. Nothing here prints or writes files (see :mod:`seafast.output`).

Size: over 400 lines because it is the only module that knows the order of the stages, for a run, a
study point's short path and the two-way coupling; each is a short function of the stages below
(frequency sweeps: :mod:`seafast.analyses.sweep.frequency`).
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np
import xarray as xr

import seafast
from seafast.config.schema import Case
from seafast.coupling.deck_iteration import DeckCoupling, couple_deck, linear_coupling_jacobians
from seafast.coupling.deck_loads import HullCompliance, deck_forces_N, hull_compliance
from seafast.coupling.hull import CoupledHull, coupled_hull
from seafast.coupling.status import CouplingStatus
from seafast.excitation.harmonic import HarmonicExcitation
from seafast.model.from_case import cargo_geometry
from seafast.model.seafastening import SeaFastening
from seafast.model.structure import StructuralModel, build_structural_model
from seafast.results.coupling import coupling_dataset, coupling_summary_fields
from seafast.results.dataset import (
    LOAD_CASES,
    MODELS,
    SUMMARY_COLUMNS,
    CaseArrays,
    build_case_dataset,
    case_arrays,
    summary_rows_from_arrays,
)
from seafast.results.timeseries import PeriodTimeSeries, from_periodic_response, linear_time_series
from seafast.results.validity import ValidityIssue, validity_issues, with_validity, within_validity
from seafast.solvers.linear import solve_linear
from seafast.solvers.periodic import harmonics_to_time

__all__ = [
    "CaseResult",
    "build_model",
    "cargo_geometry",
    "run_case",
    "evaluate_summary",
    "solve_nonlinear",
    "couple_hull_and_cargo",
    "hbm_options",
]


def build_model(case: Case) -> StructuralModel:
    """Cargo + sea-fastening structural model of the case.

    Raises
    ------
    seafast.model.MechanismError
        If the support layout leaves the cargo a mechanism.
    """
    positions = np.array(case.saddle_positions_m())
    lashed = np.zeros(positions.size, dtype=bool)
    lashed[list(case.lashed_saddle_indices())] = True
    sf = SeaFastening(
        saddle_x_m=positions,
        saddle_stiffness_N_per_m=np.array(case.saddle_stiffnesses_N_per_m()),
        lashed=lashed,
        lashing_wire_stiffness_N_per_m=case.seafastening.lashing.stiffness_N_per_m,
        lashing_pretension_N=case.seafastening.lashing.pretension_N,
    )
    return build_structural_model(
        cargo_geometry(case),
        sf,
        target_element_length_m=case.model.element_length_m,
        damping_ratio=case.model.damping_ratio,
        gravity_m_per_s2=case.model.gravity_m_per_s2,
    )


def hbm_options(case: Case, **changes: Any) -> Any:
    """Harmonic-balance options (:class:`~seafast.solvers.hbm.HBMOptions`) from the case's solver settings, with ``changes`` applied."""
    return _hbm_options(case, **changes)


def _hbm_options(case: Case, **changes: Any) -> Any:
    """:func:`hbm_options` (the solves here call this name, which tests may patch)."""
    from seafast.solvers.hbm import HBMOptions

    s = case.solver
    settings: dict[str, Any] = dict(
        harmonics=s.harmonics,
        time_samples=s.time_samples,
        contact_law=s.contact_law,
        regularisation_per_m=s.regularisation_per_m,
        formulation=s.formulation,
        solver=s.nonlinear_solver,
        tolerance=s.tolerance,
        truncation_tolerance=s.truncation_tolerance,
        max_harmonics=s.max_harmonics,
    )
    settings.update(changes)
    return HBMOptions(**settings)


def solve_nonlinear(model: StructuralModel, excitation: HarmonicExcitation, case: Case, static: bool, warm_start: Any = None) -> Any:
    """Nonlinear (unilateral-saddle) response by the case's method; returns a PeriodicResponse.

    ``static=True`` solves the still-water state alone (harmonic balance with H = 0).
    ``warm_start``: a neighbouring PeriodicResponse of the same case to start the condensed HBM
    from (ignored by the other methods).
    """
    from seafast.solvers.hbm import solve_hbm

    s = case.solver
    if static and s.method != "hbm":
        # the references use the exact contact law; so does their still-water state
        from seafast.solvers.references import solve_quasi_static

        return solve_quasi_static(model, excitation.static_part(), time_samples=2)
    if static:
        opts = _hbm_options(case, harmonics=0, time_samples=2)
        return solve_hbm(model, excitation.static_part(), opts)
    if s.method == "quasi_static":
        from seafast.solvers.references import solve_quasi_static

        return solve_quasi_static(model, excitation, time_samples=s.reference_time_samples)
    if s.method == "time_domain":
        from seafast.solvers.outcome import TimeDomainStart
        from seafast.solvers.references import solve_time_domain

        # both formulations start from one state: the linear periodic solution, or the HBM's orbit (docs/orbits.md)
        td_start = solve_hbm(model, excitation, _hbm_options(case)) if s.time_domain_start == "hbm" else TimeDomainStart.LINEAR
        return solve_time_domain(model, excitation, time_samples=s.reference_time_samples, start=td_start)
    opts = _hbm_options(case)
    start = None
    if warm_start is not None and s.formulation == "condensed":
        start = np.asarray(warm_start.saddle_compression_time_m)
    return solve_hbm(model, excitation, opts, initial_compression_m=start)


@dataclass(frozen=True)
class CaseResult:
    """Everything computed for one case.

    Two-way runs also hold, keyed ``(load_case, model)``: ``coupling``, each row's coupling
    outcome, and ``deck_couplings``, each row's coupled deck, deck forces and response; and
    ``compliance``, the hull's at the saddles. ``coupled_hull`` (computed when first asked
    for, e.g. by :attr:`dataset`; studies never do) is the hull girder under the coupled cargo.
    One-way runs leave them empty / ``None``.
    """

    case: Case
    model: StructuralModel
    excitation: HarmonicExcitation
    vessel: Any  # seafast.excitation.vessel.VesselExcitation (hull girder, motions) or None
    arrays: CaseArrays
    responses: dict[str, Any]
    attrs: dict[str, Any]
    coupling: Mapping[tuple[str, str], CouplingStatus] = field(default_factory=dict)
    deck_couplings: Mapping[tuple[str, str], DeckCoupling] = field(default_factory=dict)
    compliance: HullCompliance | None = None
    axial: Any = None  # seafast.results.axial.AxialCaseArrays when the axial analysis ran

    @functools.cached_property
    def coupled_hull(self) -> CoupledHull | None:
        """The hull girder under the nonlinear model's coupled cargo (``None`` one-way)."""
        if not self.deck_couplings or self.compliance is None:
            return None
        v = self.vessel
        return coupled_hull(
            v.girder,
            v.loading,
            self.compliance,
            v.still_water,
            self.deck_couplings[("static", "nonlinear")],
            v.wave,
            self.deck_couplings[("dynamic", "nonlinear")] if v.wave is not None else None,
        )

    @property
    def summary(self) -> list[dict[str, Any]]:
        """Summary rows (summary.csv's columns plus contact_preserved, diagnostics, the row's typed
        ``warnings`` and ``within_validity``; a two-way run adds each row's coupling_converged,
        coupling_residual_m, coupling_tolerance_m and coupling_iterations; the axial columns when the
        axial analysis ran)."""
        rows = with_validity(
            summary_rows_from_arrays(self.arrays, self.model.cargo.node_x_m, self.model.warnings), cargo_diameter_m(self.model)
        )
        for row in rows:
            status = self.coupling.get((row["load_case"], row["model"]))
            if status is not None:
                row.update(coupling_summary_fields(status))
        return rows if self.axial is None else self.axial.extend_summary(rows)

    @functools.cached_property
    def validity(self) -> tuple[ValidityIssue, ...]:
        """Every row's results beyond the model's small-displacement validity (empty: all valid; :mod:`seafast.results.validity`)."""
        return validity_issues(self.summary, cargo_diameter_m(self.model))

    @property
    def summary_columns(self) -> tuple[str, ...]:
        """The columns of ``summary.csv``: the source's, then the axial ones when the axial analysis ran."""
        return SUMMARY_COLUMNS + (self.axial.summary_column_names if self.axial is not None else ())

    @functools.cached_property
    def dataset(self) -> xr.Dataset:
        """All results labelled (what results.nc holds), vessel data merged in."""
        ds = build_case_dataset(self.arrays, self.model, self.attrs)
        ds["within_validity"] = xr.DataArray(
            within_validity(self.validity),
            dims=("load_case", "model"),
            attrs={
                "long_name": "the row's results lie within the model's small-displacement validity (docs/theory.md, validity)",
                "units": "1",
            },
        )
        ds.attrs["validity_issues"] = "\n".join(issue.message for issue in self.validity)
        if self.vessel is not None and hasattr(self.vessel, "to_dataset"):
            vds = self.vessel.to_dataset()
            ds = xr.merge([ds, vds], combine_attrs="override")
            ds.attrs.update(vds.attrs)
        if self.coupling:
            ds = xr.merge([ds, coupling_dataset(self.coupling, self.coupled_hull)], combine_attrs="override")
        return ds if self.axial is None else self.axial.merged_into(ds)


def _excitation(case: Case, model: StructuralModel) -> tuple[HarmonicExcitation, Any]:
    from seafast.excitation.vessel import vessel_excitation

    vessel = vessel_excitation(case)
    return vessel.cargo_excitation(model, case), vessel


def run_case(
    case: Case,
    *,
    excitation: HarmonicExcitation | None = None,
    vessel: Any = None,
    progress: Callable[[str], None] | None = None,
) -> CaseResult:
    """Run one case: linear and nonlinear, static and dynamic.

    Parameters
    ----------
    case
        The validated case.
    excitation, vessel
        Precomputed excitation (and the vessel data it came from), e.g. from a study that
        reuses them across points; computed from the case when omitted.
    progress
        Called with a short message as each stage starts (e.g. to print it).
    """
    say = progress or (lambda message: None)
    model = build_model(case)
    if excitation is None:
        say("vessel excitation (hull girder, motions)")
        excitation, vessel = _excitation(case, model)
    couplings: dict[tuple[str, str], DeckCoupling] = {}
    compliance: HullCompliance | None = None
    if case.vessel.coupling == "two_way":
        say("two-way hull-cargo coupling (still water and wave, linear and nonlinear)")
        compliance = _compliance(case, model, vessel)
        couplings = couple_hull_and_cargo(case, model, excitation, vessel, compliance)
        lin_static = couplings[("static", "linear")].response
        lin_dynamic = couplings[("dynamic", "linear")].response
        nl_static = couplings[("static", "nonlinear")].response
        nl_dynamic = couplings[("dynamic", "nonlinear")].response
    else:
        say("linear and nonlinear solves")
        lin_static = solve_linear(model, excitation.static_part())
        lin_dynamic = solve_linear(model, excitation)
        nl_static = solve_nonlinear(model, excitation, case, static=True)
        nl_dynamic = solve_nonlinear(model, excitation, case, static=False)
    # one time grid for every row: the nonlinear dynamic solution's (its N follows its harmonics)
    N = int(nl_dynamic.time_samples)
    series: dict[tuple[str, str], PeriodTimeSeries] = {
        ("static", "linear"): linear_time_series(lin_static, N),
        ("dynamic", "linear"): linear_time_series(lin_dynamic, N),
        ("static", "nonlinear"): from_periodic_response(nl_static, N),
        ("dynamic", "nonlinear"): from_periodic_response(nl_dynamic, N),
    }
    from seafast.solvers.references.orbit import orbit_attributes

    attrs = {
        "title": f"seafast results: {case.name}",
        "seafast_version": seafast.__version__,
        "excitation_source": excitation.source,
        "wave_frequency_rad_s": excitation.omega_rad_s,
        "solver_method": case.solver.method,
        **orbit_attributes(nl_dynamic.orbit),  # the time-domain reference's start and orbit (docs/orbits.md)
        "solver_formulation": case.solver.formulation,
        "contact_law": case.solver.contact_law,
        "harmonics": int(nl_dynamic.options.get("harmonics", -1)) if case.solver.method == "hbm" else -1,
        "harmonics_selection": str(nl_dynamic.options.get("harmonics_selection", "fixed")) if case.solver.method == "hbm" else "none",
        "time_samples": N,
        "case_json": case.model_dump_json(),
        # the damping as built, so that an outside code can rebuild the model: D = alpha M + beta K_<stiffness>
        "rayleigh_alpha_per_s": model.rayleigh_alpha_per_s,
        "rayleigh_beta_s": model.rayleigh_beta_s,
        "rayleigh_stiffness": "beam",
        "damping_ratio": case.model.damping_ratio,
        "realised_damping_ratio_modes_1_2": list(model.modal_damping_ratios(2)),
        "conventions": "x from the cargo's aft end; z up; displacements relative to the vessel's rigid-body frame; "
        "sagging moment positive; saddle compression positive when compressed",
    }
    statuses = {key: c.status for key, c in couplings.items()}
    if couplings:
        attrs["hull_cargo_coupling"] = "\n".join(s.message for s in statuses.values())
    arrays = case_arrays(model, excitation, series, N, {key: c.excitation for key, c in couplings.items()})
    if couplings:
        # a row whose deck did not converge is not converged, whatever its cargo solver says;
        # why is in the row's CouplingStatus (solver_message stays the cargo solver's own)
        converged = arrays.converged.copy()
        for i, lc in enumerate(LOAD_CASES):
            for j, mdl in enumerate(MODELS):
                converged[i, j] &= statuses[(lc, mdl)].converged
        arrays = replace(arrays, converged=converged)
    responses = {"linear_static": lin_static, "linear_dynamic": lin_dynamic, "nonlinear_static": nl_static, "nonlinear_dynamic": nl_dynamic}
    axial = None
    if case.seafastening.friction_coefficient is not None:  # the axial analysis (docs/axial.md), one way
        from seafast.analyses.axial import run_axial_analysis

        say("axial sliding (friction, lashings, stoppers)")
        axial = run_axial_analysis(case, model, vessel, series)
    return CaseResult(case, model, excitation, vessel, arrays, responses, attrs, statuses, couplings, compliance, axial=axial)


def _compliance(case: Case, model: StructuralModel, vessel: Any) -> HullCompliance:
    """The hull's compliance at the model's sea-fastening points (two-way coupling)."""
    if vessel is None or getattr(vessel, "girder", None) is None or getattr(vessel, "loading", None) is None:
        raise ValueError("vessel.coupling = 'two_way' needs the computed hull girder and its loading (no vessel data was given)")
    return hull_compliance(vessel.girder, vessel.loading, model, vessel.cargo_aft_end_x_m, case.cargo.units_abreast)


def couple_hull_and_cargo(
    case: Case, model: StructuralModel, excitation: HarmonicExcitation, vessel: Any, compliance: HullCompliance | None = None
) -> dict[tuple[str, str], DeckCoupling]:
    """Hull and cargo solved together (``vessel.coupling = 'two_way'``), row by row.

    For each (load case, model) the deck under the sea-fastening is iterated until the hull
    girder, loaded by the cargo's deck forces in place of its spread load, and the cargo agree
    (:func:`seafast.coupling.deck_iteration.couple_deck`): the still-water state (harmonic 0) for
    the static rows, harmonics 0 .. H (the linear model: the excitation's harmonics) for the
    dynamic rows. Returns :class:`~seafast.coupling.deck_iteration.DeckCoupling` per row, keyed
    ``(load_case, model)``; each carries the coupled excitation, the cargo's response and its
    :class:`~seafast.coupling.status.CouplingStatus`. ``compliance``: the hull's
    (computed from ``vessel`` when omitted).
    """
    if compliance is None:
        compliance = _compliance(case, model, vessel)
    static = excitation.static_part()
    k_linear = excitation.harmonic_count
    # the deck forces exchanged with the hull: harmonics 0 .. H of a fixed H, else 0 .. COUPLING_HARMONICS (the
    # adaptive H of each cargo solve can be hundreds; the quasi-static hull girder is no model for loads that fast)
    k_nonlinear = max((case.solver.harmonics if case.solver.harmonics is not None else COUPLING_HARMONICS) + 1, k_linear)
    omega = excitation.omega_rad_s
    jac = linear_coupling_jacobians(model, omega, compliance, (1, k_linear, k_nonlinear))

    def linear(exc: HarmonicExcitation) -> Any:
        return solve_linear(model, exc)

    last: dict[str, Any] = {}
    dynamic_case = case
    adaptive = case.solver.method == "hbm" and case.solver.harmonics is None
    if adaptive:
        # the deck is iterated at a fixed H = COUPLING_HARMONICS, then the cargo solved on the coupled deck with the
        # adaptive H (below): an H chosen afresh at each iterate makes the coupling map jump (Broyden stalls), and
        # the hundreds of harmonics of a heavy lift-off are both slow to iterate and beyond what the quasi-static
        # hull girder models (docs/coupling.md)
        # (the iterates' truncation is not the reported answer's: their estimate is not warned about)
        held = {"harmonics": COUPLING_HARMONICS, "time_samples": None, "truncation_tolerance": 0.5}
        dynamic_case = case.model_copy(update={"solver": case.solver.model_copy(update=held)})

    def warm_dynamic(exc: HarmonicExcitation) -> Any:
        # each coupling iterate starts the HBM from the previous one: the deck moves little
        # between iterates, and the solution followed stays on one branch
        response = solve_nonlinear(model, exc, dynamic_case, static=False, warm_start=last.get("response"))
        if getattr(response, "converged", False):
            last["response"] = response
        return response

    out = {
        ("static", "linear"): couple_deck(
            model,
            static,
            compliance,
            linear,
            lambda e, r: deck_forces_N(model, e, r, False, 1),
            1,
            jacobian0=jac[1],
            label="static, linear",
        ),
        ("static", "nonlinear"): couple_deck(
            model,
            static,
            compliance,
            lambda e: solve_nonlinear(model, e, case, static=True),
            lambda e, r: deck_forces_N(model, e, r, True, 1),
            1,
            jacobian0=jac[1],
            label="static, nonlinear",
        ),
        ("dynamic", "linear"): couple_deck(
            model,
            excitation,
            compliance,
            linear,
            lambda e, r: deck_forces_N(model, e, r, False, k_linear),
            k_linear,
            jacobian0=jac[k_linear],
            label="dynamic, linear",
        ),
        ("dynamic", "nonlinear"): couple_deck(
            model,
            excitation,
            compliance,
            warm_dynamic,
            lambda e, r: deck_forces_N(model, e, r, True, k_nonlinear),
            k_nonlinear,
            jacobian0=jac[k_nonlinear],
            label="dynamic, nonlinear",
        ),
    }
    if adaptive:
        coupled = out[("dynamic", "nonlinear")]
        final = solve_nonlinear(model, coupled.excitation, case, static=False)
        out[("dynamic", "nonlinear")] = replace(coupled, response=final)
    return out


def _summary_by_condensation(case: Case) -> bool:
    """Whether :func:`evaluate_summary` can take its short path for this case."""
    s = case.solver
    return (
        case.vessel.coupling == "one_way"
        and s.method == "hbm"
        and s.formulation == "condensed"
        and case.seafastening.friction_coefficient is None  # the axial analysis needs the time series of run_case
    )


def evaluate_summary(case: Case) -> list[dict[str, Any]]:
    """Summary rows of one case (what a study records per point): ``run_case(case).summary``.

    One-way cases solved by the condensed HBM (the default) take a short path with the same
    numbers (to round-off; ``tests/test_pipeline_summary.py``): one linear condensation
    (:func:`~seafast.solvers.hbm.condensed_operators`, one banded factorisation of harmonics
    0 .. H) serves the linear model (its bilateral solution is the linear response), the
    still-water nonlinear solve (its k = 0 block) and the dynamic nonlinear solve
    (:func:`~seafast.solvers.hbm.solve_condensed`, started from the point's own predictor, as
    :func:`solve_nonlinear`); the maxima come from the harmonics (:mod:`seafast.results.summary`)
    with no time-series objects or Dataset. Every other case runs :func:`run_case`.
    """
    if not _summary_by_condensation(case):
        return run_case(case).summary
    from seafast.results.summary import RowSolution, summary_rows
    from seafast.solvers.hbm import CondensedOperators, condensed_operators, real_to_complex_harmonics, solve_condensed, solve_hbm

    model = build_model(case)
    excitation, _ = _excitation(case, model)
    n_k = excitation.harmonic_count
    # the dynamic nonlinear state first: its (possibly adaptive) H sets the time grid N of every row
    dynamic = solve_hbm(model, excitation, _hbm_options(case))
    N = dynamic.time_samples
    if dynamic.warnings and any(w.value == "harmonics_above_h_ignored" for w in dynamic.warnings):
        return run_case(case).summary  # the linear model would see harmonics the condensation drops
    ops = condensed_operators(model, excitation, max(n_k - 1, 0))  # the linear model lives on the excitation's harmonics
    static_ops = CondensedOperators(
        omega_rad_s=ops.omega_rad_s,
        harmonics=0,
        saddle_stiffness_N_per_m=ops.saddle_stiffness_N_per_m,
        receptance_harmonics=ops.receptance_harmonics[:1],
        linear_compression_m=ops.linear_compression_m[:1],
        linear_cargo_displacement=ops.linear_cargo_displacement[:1],
        cargo_influence=ops.cargo_influence[:1],
        ignored_harmonics=False,
    )
    k_u = ops.saddle_stiffness_N_per_m
    static_excitation = excitation.static_part()
    rows: dict[tuple[str, str], RowSolution] = {}
    # linear (bilateral) model: the condensation's linear solution, harmonics of the excitation
    linear_delta = real_to_complex_harmonics(ops.linear_compression_m)
    for load_case, exc, harmonics in (("static", static_excitation, 1), ("dynamic", excitation, n_k)):
        delta = harmonics_to_time(linear_delta[:harmonics], 1 if harmonics == 1 else N)
        rows[(load_case, "linear")] = RowSolution(ops.linear_cargo_displacement[:harmonics], delta, delta * k_u, exc, nonlinear=False)
    # nonlinear (unilateral) model: still water (H = 0) and the dynamic state above
    static_options = _hbm_options(case, harmonics=0, time_samples=2)
    sol = solve_condensed(static_ops, static_options)
    delta = sol.saddle_compression[:1]  # H = 0: the mean is the state
    C = real_to_complex_harmonics(sol.correction_force)
    X = static_ops.linear_cargo_displacement + np.einsum("kcs,ks->kc", static_ops.cargo_influence, C)
    rows[("static", "nonlinear")] = RowSolution(
        X, delta, static_options.law.force(delta, k_u), static_excitation, True, sol.converged, sol.residual_norm, sol.iterations
    )
    assert dynamic.cargo_displacement_harmonics is not None  # the harmonic balance's solution has harmonics
    rows[("dynamic", "nonlinear")] = RowSolution(
        dynamic.cargo_displacement_harmonics,
        dynamic.saddle_compression_time_m,
        dynamic.saddle_force_time_N,
        excitation,
        True,
        dynamic.converged,
        dynamic.residual_norm,
        dynamic.iterations,
        dynamic.warnings,
    )
    return with_validity(
        summary_rows(model, [(lc, mdl, rows[(lc, mdl)]) for lc in LOAD_CASES for mdl in MODELS], N), cargo_diameter_m(model)
    )


def cargo_diameter_m(model: StructuralModel) -> float:
    """The cargo's largest outer diameter [m] (the scale of the validity check's displacement line)."""
    return float(np.max(model.cargo.element_outer_diameter_m))


#: The fixed H at which the two-way coupling iterates the deck when the case leaves H adaptive (the deck forces
#: exchanged with the hull are harmonics 0 .. COUPLING_HARMONICS; the cargo is then solved on the coupled deck
#: with the adaptive H): the safe H of the harmonic balance (solvers/hbm/solve.py), 0.4 % on the base case.
COUPLING_HARMONICS = 16
"""Harmonics of the deck forces the two-way coupling exchanges when ``solver.harmonics`` is adaptive."""
