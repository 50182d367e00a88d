"""The two-way coupling of one case, row by row: the one entry point of :mod:`seafast.coupling`."""

from __future__ import annotations

from dataclasses import replace

from seafast.config.modes import SolverMethod
from seafast.config.schema import Case
from seafast.coupling.deck_iteration import DeckCoupling, couple_deck, linear_coupling_jacobians
from seafast.coupling.deck_loads import HullCompliance, deck_forces_N, hull_compliance
from seafast.excitation.harmonic import HarmonicExcitation
from seafast.excitation.vessel import VesselExcitation
from seafast.model.structure import StructuralModel
from seafast.solvers.from_case import solve_nonlinear
from seafast.solvers.hbm.options import SAFE_HARMONICS
from seafast.solvers.linear import LinearResponse, solve_linear
from seafast.solvers.periodic import PeriodicResponse

__all__ = ["couple_hull_and_cargo", "case_compliance"]


def case_compliance(case: Case, model: StructuralModel, vessel: VesselExcitation | None) -> HullCompliance:
    """The hull's compliance at the model's sea-fastening points (two-way coupling)."""
    if vessel is None or vessel.girder is None or vessel.loading is None:
        raise ValueError("vessel.coupling = 'two_way' needs the computed hull girder and its loading (no vessel data was given)")
    return hull_compliance(vessel.girder, vessel.loading, model, vessel.cargo_aft_end_x_m, case.cargo.units_abreast)


def couple_hull_and_cargo(
    case: Case,
    model: StructuralModel,
    excitation: HarmonicExcitation,
    vessel: VesselExcitation | None,
    compliance: HullCompliance | None = None,
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
        compliance = case_compliance(case, model, vessel)
    static = excitation.static_part()
    k_linear = excitation.harmonic_count
    # the deck forces exchanged with the hull: harmonics 0 .. H of a fixed H, else 0 .. SAFE_HARMONICS (the
    # adaptive H of each cargo solve can be hundreds; the quasi-static hull girder is no model for loads that fast)
    k_nonlinear = max((case.solver.harmonics if case.solver.harmonics is not None else SAFE_HARMONICS) + 1, k_linear)
    omega = excitation.omega_rad_s
    jac = linear_coupling_jacobians(model, omega, compliance, (1, k_linear, k_nonlinear))

    def linear(exc: HarmonicExcitation) -> LinearResponse:
        return solve_linear(model, exc)

    last: dict[str, PeriodicResponse] = {}
    dynamic_case = case
    adaptive = case.solver.method == SolverMethod.HBM and case.solver.harmonics is None
    if adaptive:
        # the deck is iterated at a fixed H = SAFE_HARMONICS, then the cargo solved on the coupled deck with the
        # adaptive H (below): an H chosen afresh at each iterate makes the coupling map jump (Broyden stalls), and
        # the hundreds of harmonics of a heavy lift-off are both slow to iterate and beyond what the quasi-static
        # hull girder models (docs/coupling.md)
        # (the iterates' truncation is not the reported answer's: their estimate is not warned about)
        held = {"harmonics": SAFE_HARMONICS, "time_samples": None, "truncation_tolerance": 0.5}
        dynamic_case = case.model_copy(update={"solver": case.solver.model_copy(update=held)})

    def warm_dynamic(exc: HarmonicExcitation) -> PeriodicResponse:
        # each coupling iterate starts the HBM from the previous one: the deck moves little
        # between iterates, and the solution followed stays on one branch
        response = solve_nonlinear(model, exc, dynamic_case, static=False, warm_start=last.get("response"))
        if response.converged:
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
