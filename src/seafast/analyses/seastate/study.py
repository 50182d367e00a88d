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
"""

from __future__ import annotations

from typing import Any

from seafast.analyses.seastate.design_wave import sea_state_design_waves
from seafast.analyses.seastate.spectral import spectral_analysis
from seafast.config.schema import Case
from seafast.results.dataset import row_warnings

__all__ = ["SEA_STATE_LOAD_CASE", "evaluate_sea_state"]

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
    return rows
