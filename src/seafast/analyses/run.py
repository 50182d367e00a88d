"""One case end to end: configuration -> model -> excitation -> the four rows -> the case's result.

The four rows of a case are the linear (bilateral-saddle) and nonlinear (unilateral) model, in still
water and in the wave. :func:`solve_rows` is the one place that solves them (one way, or with the
hull coupled, :mod:`seafast.coupling`); :class:`CaseResult` reads them: its :attr:`~CaseResult.summary`
from the harmonics of the solution where every row has them (the harmonic balance's; what a study
records, in a few milliseconds), else from the period time series, which its
:attr:`~CaseResult.dataset` (what ``results.nc`` holds) always reads. The two readings agree to
round-off (``tests/analyses/test_run.py``). Nothing here prints or writes files.

Size: just over 400 lines because :class:`CaseResult` is the one reader of a run's rows (summary, validity,
elastic impacts, dataset), each a few lines calling :mod:`seafast.results`.
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np
import xarray as xr

import seafast
from seafast.analyses.axial import run_axial_analysis
from seafast.analyses.cradle_run import solve_cradle_rows, solves_cradles
from seafast.config.modes import HullCargoCoupling, SolverMethod
from seafast.config.schema import Case
from seafast.coupling.case import case_compliance, couple_hull_and_cargo
from seafast.coupling.deck_iteration import DeckCoupling
from seafast.coupling.deck_loads import HullCompliance
from seafast.coupling.hull import CoupledHull, coupled_hull
from seafast.coupling.status import CouplingStatus
from seafast.excitation.harmonic import HarmonicExcitation
from seafast.excitation.vessel import VesselExcitation, vessel_excitation
from seafast.fourier import harmonics_to_time
from seafast.hull.still_water import HullGirderResponse
from seafast.hull.wave import WaveHullResponse
from seafast.model.from_case import build_model
from seafast.model.structure import StructuralModel
from seafast.results.axial import AxialCaseArrays
from seafast.results.coupling import coupling_dataset, coupling_summary_fields
from seafast.results.cradle import CradleRows, failed_cradle_summary
from seafast.results.dataset import (
    LOAD_CASES,
    MODELS,
    SUMMARY_COLUMNS,
    CaseArrays,
    build_case_dataset,
    case_arrays,
    summary_rows_from_arrays,
)
from seafast.results.impact import ImpactCheck, case_impact, impact_flags, with_impact
from seafast.results.summary import FACTORED_SAMPLES, RowSolution, summary_rows
from seafast.results.timeseries import PeriodTimeSeries, from_periodic_response, linear_time_series
from seafast.results.validity import ValidityIssue, cargo_diameter_m, validity_issues, with_validity, within_validity
from seafast.solvers.from_case import solve_nonlinear
from seafast.solvers.linear import LinearResponse, solve_linear
from seafast.solvers.periodic import PeriodicResponse
from seafast.solvers.references.orbit import orbit_attributes

__all__ = ["CaseRows", "CaseResult", "solve_rows", "run_case", "evaluate_summary"]

Row = tuple[str, str]
"""A row's ``(load_case, model)``: ``static``/``dynamic``, ``linear``/``nonlinear``."""


@dataclass(frozen=True)
class CaseRows:
    """The four responses of one case, each with the excitation it was solved for.

    ``excitations[(load_case, model)]`` is the case's excitation (its static part for a static row),
    or with two-way coupling the row's coupled deck; ``couplings`` holds each row's coupling
    (deck, deck forces, outcome) and ``compliance`` the hull's at the saddles (both empty one way).
    """

    linear_static: LinearResponse
    linear_dynamic: LinearResponse
    nonlinear_static: PeriodicResponse
    nonlinear_dynamic: PeriodicResponse
    excitations: Mapping[Row, HarmonicExcitation]
    couplings: Mapping[Row, DeckCoupling] = field(default_factory=dict)
    compliance: HullCompliance | None = None

    def linear(self, load_case: str) -> LinearResponse:
        return self.linear_static if load_case == "static" else self.linear_dynamic

    def nonlinear(self, load_case: str) -> PeriodicResponse:
        return self.nonlinear_static if load_case == "static" else self.nonlinear_dynamic

    @property
    def time_samples(self) -> int:
        """The one time grid of every row: the nonlinear dynamic solution's (its N follows its harmonics)."""
        return int(self.nonlinear_dynamic.time_samples)

    @property
    def statuses(self) -> dict[Row, CouplingStatus]:
        """Each row's coupling outcome (two-way; empty one way)."""
        return {key: c.status for key, c in self.couplings.items()}


def solve_rows(
    case: Case,
    model: StructuralModel,
    excitation: HarmonicExcitation,
    vessel: VesselExcitation | None,
    say: Callable[[str], None] = lambda message: None,
) -> CaseRows:
    """Solve the four rows of ``case``: one way, or hull and cargo together (``vessel.coupling: two_way``)."""
    static = excitation.static_part()
    if case.vessel.coupling is HullCargoCoupling.TWO_WAY:
        say("two-way hull-cargo coupling (still water and wave, linear and nonlinear)")
        compliance = case_compliance(case, model, vessel)
        couplings = couple_hull_and_cargo(case, model, excitation, vessel, compliance)
        return CaseRows(
            _linear_response(couplings[("static", "linear")]),
            _linear_response(couplings[("dynamic", "linear")]),
            _nonlinear_response(couplings[("static", "nonlinear")]),
            _nonlinear_response(couplings[("dynamic", "nonlinear")]),
            {key: (c.excitation.static_part() if key[0] == "static" else c.excitation) for key, c in couplings.items()},
            couplings,
            compliance,
        )
    say("linear and nonlinear solves")
    return CaseRows(
        solve_linear(model, static),
        solve_linear(model, excitation),
        solve_nonlinear(model, excitation, case, static=True),
        solve_nonlinear(model, excitation, case, static=False),
        {(lc, m): (static if lc == "static" else excitation) for lc in LOAD_CASES for m in MODELS},
    )


def _linear_response(coupling: DeckCoupling) -> LinearResponse:
    """A linear row's response on its coupled deck (the linear solver's, by construction)."""
    assert isinstance(coupling.response, LinearResponse)
    return coupling.response


def _nonlinear_response(coupling: DeckCoupling) -> PeriodicResponse:
    """A nonlinear row's response on its coupled deck (a periodic solver's, by construction)."""
    assert isinstance(coupling.response, PeriodicResponse)
    return coupling.response


def _row_solution(rows: CaseRows, load_case: str, model: str, time_samples: int) -> RowSolution | None:
    """A row in the summary's form, from its harmonics (None: a reference's solution, which has none)."""
    exc = rows.excitations[(load_case, model)]
    if model == "linear":
        lin = rows.linear(load_case)
        n_t = 1 if lin.cargo_displacement.shape[0] == 1 else time_samples
        return RowSolution(
            lin.cargo_displacement,
            harmonics_to_time(lin.saddle_compression_m, n_t),
            harmonics_to_time(lin.saddle_force_N, n_t),
            exc,
            nonlinear=False,
        )
    r = rows.nonlinear(load_case)
    history = r.cargo_history
    factored = history.factored and history.time_functions.shape[0] == time_samples >= FACTORED_SAMPLES
    if not factored and history.harmonic_functions is None:
        return None
    return RowSolution(
        None if factored else r.cargo_displacement_harmonics,
        r.saddle_compression_time_m,
        r.saddle_force_time_N,
        exc,
        True,
        r.converged,
        r.residual_norm,
        r.iterations,
        r.warnings,
        history if factored else None,
    )


@dataclass(frozen=True)
class CaseResult:
    """Everything computed for one case: its model, excitation, vessel, four rows and, with friction, the axial analysis.

    Off head seas ``cradle`` holds the cargo on its cradles (:mod:`seafast.analyses.cradle_run`; None in head seas).
    Two-way runs also hold each row's coupling (``rows.couplings``; ``coupling``: its outcome) and the
    hull's compliance; ``coupled_hull`` (computed when first asked for, e.g. by :attr:`dataset`;
    studies never do) is the hull girder under the coupled cargo.
    """

    case: Case
    model: StructuralModel
    excitation: HarmonicExcitation
    vessel: VesselExcitation | None
    rows: CaseRows
    axial: AxialCaseArrays | None = None
    cradle: CradleRows | None = None

    @property
    def coupling(self) -> dict[Row, CouplingStatus]:
        """Each row's coupling outcome (two-way; empty one way)."""
        return self.rows.statuses

    @property
    def deck_couplings(self) -> Mapping[Row, DeckCoupling]:
        """Each row's coupled deck, deck forces and response (two-way; empty one way)."""
        return self.rows.couplings

    @property
    def compliance(self) -> HullCompliance | None:
        """The hull's compliance at the saddles (two-way; None one way)."""
        return self.rows.compliance

    @functools.cached_property
    def series(self) -> dict[Row, PeriodTimeSeries]:
        """Every row over one period on one time grid (the nonlinear dynamic solution's)."""
        N, r = self.rows.time_samples, self.rows
        return {
            ("static", "linear"): linear_time_series(r.linear_static, N),
            ("dynamic", "linear"): linear_time_series(r.linear_dynamic, N),
            ("static", "nonlinear"): from_periodic_response(r.nonlinear_static, N),
            ("dynamic", "nonlinear"): from_periodic_response(r.nonlinear_dynamic, N),
        }

    @functools.cached_property
    def arrays(self) -> CaseArrays:
        """The rows as arrays over the period; a row whose deck did not converge is not converged."""
        rows = self.rows
        arrays = case_arrays(
            self.model, self.excitation, self.series, rows.time_samples, {k: c.excitation for k, c in rows.couplings.items()}
        )
        if not rows.couplings:
            return arrays
        # why is in the row's CouplingStatus (solver_message stays the cargo solver's own)
        converged = arrays.converged.copy()
        for i, lc in enumerate(LOAD_CASES):
            for j, mdl in enumerate(MODELS):
                converged[i, j] &= rows.statuses[(lc, mdl)].converged
        return replace(arrays, converged=converged)

    @functools.cached_property
    def coupled_hull(self) -> CoupledHull | None:
        """The hull girder under the nonlinear model's coupled cargo (``None`` one-way)."""
        v = self.vessel
        if not self.deck_couplings or self.compliance is None or v is None or v.girder is None or v.loading is None:
            return None
        # a computed hull girder (two-way coupling needs one) has its own still-water and wave responses
        assert isinstance(v.still_water, HullGirderResponse) and (v.wave is None or isinstance(v.wave, WaveHullResponse))
        return coupled_hull(
            v.girder,
            v.loading,
            self.compliance,
            v.still_water,
            self.deck_couplings[("static", "nonlinear")],
            v.wave,
            self.deck_couplings[("dynamic", "nonlinear")] if v.wave is not None else None,
        )

    @functools.cached_property
    def _rows_read(self) -> list[dict[str, Any]]:
        """The summary rows as read from the solution, before the coupling and axial columns."""
        N = self.rows.time_samples
        solved = [(lc, m, _row_solution(self.rows, lc, m, N)) for lc in LOAD_CASES for m in MODELS]
        if all(s is not None for _, _, s in solved):
            rows = summary_rows(self.model, [(lc, m, s) for lc, m, s in solved if s is not None], N)
        else:  # a reference's solution is a time series: read the arrays
            rows = summary_rows_from_arrays(self.arrays, self.model.cargo.node_x_m, self.model.warnings)
        rows = rows if self.cradle is None else self.cradle.extend_summary(rows)
        return with_validity(with_impact(rows, self.impact), cargo_diameter_m(self.model))

    @functools.cached_property
    def impact(self) -> ImpactCheck:
        """Whether the dynamic nonlinear row's saddle forces are elastic impacts (:func:`~seafast.results.impact.case_impact`)."""
        return case_impact(self.model, self.rows.nonlinear_dynamic, self.rows.linear_dynamic.saddle_force_N, self.rows.time_samples)

    @property
    def summary(self) -> list[dict[str, Any]]:
        """Summary rows (summary.csv's columns plus contact_preserved, diagnostics, ``cargo_slope_rad``, the
        row's typed ``warnings`` and ``within_validity``; a two-way run adds each row's coupling_converged,
        coupling_residual_m, coupling_tolerance_m and coupling_iterations, and a row whose deck did not
        converge is not converged; the axial columns when the axial analysis ran)."""
        rows = [dict(row) for row in self._rows_read]
        for row in rows:
            status = self.coupling.get((row["load_case"], row["model"]))
            if status is not None:
                row.update(coupling_summary_fields(status))
                row["converged"] = bool(row["converged"] and status.converged)
        return rows if self.axial is None else self.axial.extend_summary(rows)

    @functools.cached_property
    def validity(self) -> tuple[ValidityIssue, ...]:
        """Every row's results beyond the model's small-displacement validity (empty: all valid; :mod:`seafast.results.validity`)."""
        return validity_issues(self._rows_read, cargo_diameter_m(self.model))

    @property
    def summary_columns(self) -> tuple[str, ...]:
        """The columns of ``summary.csv``: the source's, the cradle ones off head seas, the axial ones when the axial analysis ran."""
        cradle = self.cradle.summary_column_names if self.cradle is not None else ()
        return SUMMARY_COLUMNS + cradle + (self.axial.summary_column_names if self.axial is not None else ())

    @functools.cached_property
    def attrs(self) -> dict[str, Any]:
        """The case's global attributes in ``results.nc``: provenance, solver settings, the damping as built."""
        return _case_attrs(self.case, self.model, self.excitation, self.rows)

    @functools.cached_property
    def dataset(self) -> xr.Dataset:
        """All results labelled (what results.nc holds), vessel data merged in; its summary variables are :attr:`summary`'s."""
        ds = build_case_dataset(self.arrays, self.model, self.attrs)
        summary = self._rows_read
        for name in ("u_c_m", "u_s_m", "u_d_m", "F_N", "M_b_Nm", "sigma_b_Pa"):
            ds[name].values[...] = np.array(
                [[next(r[name] for r in summary if (r["load_case"], r["model"]) == (lc, m)) for m in MODELS] for lc in LOAD_CASES]
            )
        ds["within_validity"] = xr.DataArray(
            within_validity(self.validity),
            dims=("load_case", "model"),
            attrs={
                "long_name": "the row's results lie within the model's small-displacement validity (docs/theory.md, validity)",
                "units": "1",
            },
        )
        ds.attrs["validity_issues"] = "\n".join(issue.message for issue in self.validity)
        ds["F_within_validity"] = impact_flags(summary)
        ds.attrs["saddle_force_impacts"] = "\n".join(self.impact.warning_lines())
        if self.vessel is not None:
            vds = self.vessel.to_dataset()
            ds = xr.merge([ds, vds], compat="no_conflicts", join="outer", combine_attrs="override")
            ds.attrs.update(vds.attrs)
        if self.coupling:
            ds = xr.merge(
                [ds, coupling_dataset(self.coupling, self.coupled_hull)], compat="no_conflicts", join="outer", combine_attrs="override"
            )
        ds = ds if self.cradle is None else self.cradle.merged_into(ds)
        return ds if self.axial is None else self.axial.merged_into(ds)


def _case_attrs(case: Case, model: StructuralModel, excitation: HarmonicExcitation, rows: CaseRows) -> dict[str, Any]:
    """The global attributes of ``results.nc``: what an outside code needs to rebuild and judge the run."""
    nl_dynamic = rows.nonlinear_dynamic
    hbm = case.solver.method == SolverMethod.HBM
    attrs = {
        "title": f"seafast results: {case.name}",
        "seafast_version": seafast.__version__,
        "excitation_source": excitation.source,
        "wave_frequency_rad_s": excitation.omega_rad_s,
        "solver_method": case.solver.method,
        **orbit_attributes(nl_dynamic.orbit),  # the time-domain reference's start and orbit (docs/orbits.md)
        "solver_formulation": case.solver.formulation,
        "contact_law": case.solver.contact_law,
        "harmonics": int(str(nl_dynamic.options.get("harmonics", -1))) if hbm else -1,
        "harmonics_selection": str(nl_dynamic.options.get("harmonics_selection", "fixed")) if hbm else "none",
        "time_samples": rows.time_samples,
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
    if rows.couplings:
        attrs["hull_cargo_coupling"] = "\n".join(s.message for s in rows.statuses.values())
    return attrs


def run_case(
    case: Case,
    *,
    excitation: HarmonicExcitation | None = None,
    vessel: VesselExcitation | None = None,
    progress: Callable[[str], None] | None = None,
    cradles: bool | None = None,
) -> CaseResult:
    """Run one case: linear and nonlinear, static and dynamic (the cradles off head seas, the axial analysis with friction).

    Parameters
    ----------
    case
        The validated case.
    excitation, vessel
        Precomputed excitation (and the vessel data it came from); computed from the case when omitted.
    progress
        Called with a short message as each stage starts (e.g. to print it).
    cradles
        Solve the cargo on its cradles (:mod:`seafast.analyses.cradle_run`; needs ``vessel``); default: off head seas.
    """
    say = progress or (lambda message: None)
    model = build_model(case)
    if excitation is None:
        say("vessel excitation (hull girder, motions)")
        vessel = vessel_excitation(case)
        excitation = vessel.cargo_excitation(model, case)
    result = CaseResult(case, model, excitation, vessel, solve_rows(case, model, excitation, vessel, say))
    if (solves_cradles(case) if cradles is None else cradles) and vessel is not None:
        say("the cargo on its cradles, stoppers and lashings (off head seas)")
        result = replace(result, cradle=solve_cradle_rows(case, model, excitation, vessel))
    if case.seafastening.friction_coefficient is None:
        return result
    say("axial sliding (friction, lashings, stoppers)")  # one way (docs/axial.md)
    return replace(result, axial=run_axial_analysis(case, model, vessel, result.series))


def evaluate_summary(case: Case) -> list[dict[str, Any]]:
    """What a study records per point: ``run_case(case).summary`` (off head seas with the cargo on its cradles; a
    cradle solve that raises keeps the vertical plane, not converged, with the reason: ``failed_cradle_summary``)."""
    result = run_case(case, cradles=False)
    if not solves_cradles(case) or result.vessel is None:
        return result.summary
    try:
        cradle = solve_cradle_rows(case, result.model, result.excitation, result.vessel)
    except (ValueError, ArithmeticError) as exc:  # the cradles cannot be built or held: recorded, the study goes on
        return failed_cradle_summary(result.summary, f"the cargo on its cradles: {exc}")
    return replace(result, cradle=cradle).summary
