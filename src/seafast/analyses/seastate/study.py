"""The study evaluator of sea-state studies: each point judged on its most probable maxima in its sea state.

A study with ``response: sea_state`` (or an axis over a ``sea_state.*`` key) evaluates every
point with :func:`evaluate_sea_state` instead of ``seafast run``'s regular wave: the rows are
``load_case = sea_state`` for the ``linear`` model (the linear spectral MPMs) and the
``nonlinear`` model (the design-wave MPMs, :mod:`seafast.analyses.seastate.design_wave`), so that the
study's compliance and ranking (which judge the nonlinear model's total response) rank the
arrangements by their nonlinear MPM in the design sea state. ``u_c_m`` is not computed (empty);
``contact_preserved`` says that no design wave lifts a saddle off (the linear model then holds);
``uplift_per_hour`` (Rice, linear) is a diagnostic column; ``warnings`` are the model's typed
warnings (:attr:`seafast.model.structure.StructuralModel.warnings`: the damping fit bears on both rows).

**Off head seas** (``sea_state.heading_deg`` not 180) the rows also carry the cargo on its cradles, computed as
``seafast seastate --no-monte-carlo`` computes them
(:func:`~seafast.analyses.seastate.cradle_design_wave.cradle_sea_state`): the five cradle columns
(:data:`~seafast.results.cradle.CRADLE_SUMMARY_COLUMNS`), the linear row's the linear spectral MPMs, the nonlinear
row's the cradle design-wave estimates; with ``seafastening.friction_coefficient`` above 0 the design waves are solved
on frictional pads and both rows gain ``pad_friction_utilisation`` and ``pad_slip_m`` (empty in the linear row, whose
pads are frictionless). Beside them ``cradle_converged``, ``cradle_residual`` (the largest relative residual of the
design waves read; empty in the linear row) and ``cradle_message`` (why a design wave did not converge; empty
otherwise); a design wave that did not converge makes the nonlinear row not ``converged``. Where the cradles cannot
be built or solved (a ``ValueError`` or ``ArithmeticError``) the rows keep the vertical plane, not converged, with the
cradle columns empty and the reason in ``cradle_error``
(:func:`~seafast.results.cradle.failed_cradle_summary`, as a regular-wave study's point): the study goes on.
"""

from __future__ import annotations

from typing import Any

from seafast.analyses.seastate.cradle_design_wave import CradleDesignWaveExtremes, cradle_sea_state
from seafast.analyses.seastate.cradle_extremes import cradle_columns, is_off_head_seas
from seafast.analyses.seastate.cradle_friction_wave import CRADLE_FRICTION_COLUMNS
from seafast.analyses.seastate.design_wave import sea_state_design_waves
from seafast.analyses.seastate.spectral import SpectralAnalysis, spectral_analysis
from seafast.config.schema import Case
from seafast.results.cradle import failed_cradle_summary
from seafast.results.dataset import row_warnings

__all__ = ["SEA_STATE_LOAD_CASE", "evaluate_sea_state", "sea_state_cradle_fields"]

SEA_STATE_LOAD_CASE = "sea_state"
"""The load_case label of a sea-state study's rows."""


def evaluate_sea_state(case: Case) -> list[dict[str, Any]]:
    """The study rows of one case in its sea state (see the module docstring).

    Raises
    ------
    seafast.config.CaseError
        An invalid or unresolvable sea state (the study records it as the point's error).
    """
    analysis = spectral_analysis(case)
    design = sea_state_design_waves(analysis)
    held = not any(s.lifted_off for s in design.solutions)
    warnings = row_warnings(SEA_STATE_LOAD_CASE, (), analysis.model.warnings)
    rows = []
    for model, totals, converged in (("linear", analysis.extremes.totals, True), ("nonlinear", design.totals, design.converged)):
        rows.append(
            {
                "load_case": SEA_STATE_LOAD_CASE,
                "model": model,
                "u_c_m": None,
                "u_s_m": float(totals["u_s_m"]),
                "u_d_m": float(totals["u_d_m"]),
                "F_N": float(totals["F_N"]),
                "M_b_Nm": float(totals["M_b_Nm"]),
                "sigma_b_Pa": float(totals["sigma_b_Pa"]),
                "converged": bool(converged),
                "contact_preserved": bool(held),
                "uplift_per_hour": float(totals["uplift_per_hour"]),
                "warnings": warnings,
            }
        )
    if not is_off_head_seas(case):
        return rows
    return _with_cradles(rows, analysis)


def _with_cradles(rows: list[dict[str, Any]], analysis: SpectralAnalysis) -> list[dict[str, Any]]:
    """The rows with their cradle fields; where the cradle part raises, the vertical plane kept, the reason recorded."""
    try:
        linear, nonlinear = sea_state_cradle_fields(analysis)
    except (ValueError, ArithmeticError) as exc:  # the cradles cannot be built or held: recorded, the study goes on
        return failed_cradle_summary(rows, f"the cargo on its cradles: {exc}")
    out = [{**rows[0], **linear}, {**rows[1], **nonlinear}]
    out[1]["converged"] = bool(rows[1]["converged"]) and bool(nonlinear["cradle_converged"])
    return out


def sea_state_cradle_fields(analysis: SpectralAnalysis) -> tuple[dict[str, Any], dict[str, Any]]:
    """The cradle fields of a sea-state study's linear and nonlinear rows off head seas (module docstring).

    Parameters
    ----------
    analysis
        The sea state's spectral analysis (:func:`~seafast.analyses.seastate.spectral.spectral_analysis`).

    Returns
    -------
    tuple of dict
        The linear row's fields (the linear spectral MPMs [N, N, N, N, m]) and the nonlinear row's (the design-wave
        estimates), each with ``cradle_converged``, ``cradle_residual`` [-] and ``cradle_message``; on frictional pads
        also ``pad_friction_utilisation`` [-] and ``pad_slip_m`` [m] (None in the linear row).

    Raises
    ------
    ValueError
        If the case's cradles cannot be built (naming the key), as
        :func:`~seafast.analyses.seastate.cradle_design_wave.cradle_sea_state`.
    """
    cradle = cradle_sea_state(analysis)
    design = cradle.design
    assert design is not None  # design waves were asked for
    friction = dict.fromkeys(CRADLE_FRICTION_COLUMNS) if design.frictional is not None else {}
    linear = {**cradle_columns(cradle.spectral.totals), **friction, "cradle_converged": True, "cradle_residual": None, "cradle_message": ""}
    nonlinear = {
        **design.columns(),
        "cradle_converged": bool(design.converged),
        "cradle_residual": float(design.residual),
        "cradle_message": _design_message(design),
    }
    return linear, nonlinear


def _design_message(design: CradleDesignWaveExtremes) -> str:
    """Why the cradle design waves' estimate is flagged (empty when every wave read converged)."""
    if design.converged:
        return ""
    which = "frictional harmonic balance (pad friction)" if design.frictional is not None else "harmonic balance"
    failed = sum(1 for r in design.responses if not r.converged)
    return (
        f"{failed} of {len(design.responses)} cradle design waves' {which} did not converge "
        f"(largest residual {design.residual:.3g}); the nonlinear row is flagged converged=false"
    )
