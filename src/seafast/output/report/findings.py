"""Diagnostics of the report: whether the numbers of a run or a study can be trusted.

Each diagnostic is a :class:`~seafast.output.report.common.Finding` (WARNING / NOTE / OK),
shown as a coloured box in the HTML, on stderr by ``seafast report`` and in the PDF summary.
"""

from __future__ import annotations

import math

import numpy as np
import xarray as xr

from seafast.output.report.common import Finding, coord_labels, saddle_label, study_keys, total_response
from seafast.solvers.outcome import SolverOutcome, SolverWarning

__all__ = ["TRUNCATION_LIMIT", "TENSILE_NOTE_FRACTION", "run_findings", "study_findings"]

TRUNCATION_LIMIT = 1e-2
"""Harmonic truncation indicator above which a nonlinear result is flagged (share of the
contact-force signal above harmonic H) [-]."""
TENSILE_NOTE_FRACTION = 1e-2
"""A regularised contact law's tensile force above this share of the largest saddle force is noted [-]."""


# =============================================================================== findings
def _warning_title(value: str) -> str:
    try:
        return SolverWarning(value).description
    except ValueError:  # a results.nc from another version of seafast
        return f"solver warning '{value}'"


def _row_findings(ds: xr.Dataset, lc: str, m: str) -> list[Finding]:
    """The WARNINGs of one (load case, model) row: convergence, validity, orbit, truncation, typed warnings."""
    out: list[Finding] = []
    sel = ds.sel(load_case=lc, model=m)
    coupling_failed = "coupling_converged" in sel and not bool(sel["coupling_converged"])
    if coupling_failed:
        out.append(
            Finding(
                "WARNING",
                f"{lc} {m}: the two-way hull-cargo coupling did NOT converge ({sel['coupling_outcome'].values.item()})",
                f"coupling residual {float(sel['coupling_residual_m']):.2e} m > "
                f"tolerance {float(sel['coupling_tolerance_m']):.2e} m "
                f"after {int(sel['coupling_iterations'])} quasi-Newton step(s): "
                "the deck under the saddles and the hull under the cargo's forces disagree, "
                "so this row's numbers and the coupled hull must not be trusted.",
            )
        )
    elif "converged" in sel and not bool(sel["converged"]):
        res = float(sel["residual_norm"]) if "residual_norm" in sel else math.nan
        out.append(
            Finding(
                "WARNING",
                f"{lc} {m}: the solver did NOT converge",
                f"residual norm {res:.3e}. Its numbers (summary, figures) must not be trusted; "
                "try more harmonics/time samples, the 'newton' solver or another contact law.",
            )
        )
    if "within_validity" in sel and not bool(sel["within_validity"]):
        prefix = f"{lc} {m}: "
        lines = [line.removeprefix(prefix) for line in str(ds.attrs.get("validity_issues", "")).splitlines() if line.startswith(prefix)]
        out.append(
            Finding(
                "WARNING",
                f"{lc} {m}: results beyond the model's small-displacement validity",
                "; ".join(lines) + ". The row is written but is not a valid answer (docs/theory.md, validity): "
                "check the units of the inputs that set it (a saddle stiffness in N/m, say).",
            )
        )
    if "solver_outcome" in sel and str(sel["solver_outcome"].values.item()) == SolverOutcome.OTHER_ORBIT.value:
        distance = float(ds.attrs.get("time_domain_orbit_distance_from_start", math.nan))
        out.append(
            Finding(
                "WARNING",
                f"{lc} {m}: the time-domain reference left the orbit it started on",
                f"started on the {ds.attrs.get('time_domain_start', 'given')} solution, it settled on another periodic "
                f"state (RMS saddle-force distance {distance:.2e} > {ds.attrs.get('time_domain_orbit_tolerance', '?')}): "
                "the starting orbit is unstable or not unique (docs/orbits.md). The numbers shown are the orbit reached.",
            )
        )
    if "harmonic_truncation_indicator" in sel:
        ind = np.asarray(sel["harmonic_truncation_indicator"].values, dtype=float)
        if np.any(ind > TRUNCATION_LIMIT):
            j = int(np.nanargmax(ind))
            out.append(
                Finding(
                    "WARNING",
                    f"{lc} {m}: harmonic truncation indicator {np.nanmax(ind):.2e} > {TRUNCATION_LIMIT:g}",
                    f"at {saddle_label(ds, j)}: a noticeable share of the contact force lies above harmonic "
                    f"H = {ds.attrs.get('harmonics', '?')}; increase solver.harmonics (and solver.time_samples) "
                    "until the maxima stop changing.",
                )
            )
    if "solver_warning_flag" in sel:
        msg = str(sel["solver_message"].values.item()) if "solver_message" in sel else ""
        for name in coord_labels(ds["solver_warning"]):
            if bool(sel["solver_warning_flag"].sel(solver_warning=name)):
                out.append(Finding("WARNING", f"{lc} {m}: {_warning_title(name)}", msg))
    return out


def run_findings(ds: xr.Dataset) -> list[Finding]:
    """Diagnostics of a run that decide whether its numbers can be trusted.

    WARNING when: a solve did not converge (a two-way coupling that did not converge is named
    as such, with the coupling's own residual and tolerance); the harmonic truncation indicator exceeds
    :data:`TRUNCATION_LIMIT`; a solve raised a typed warning (``solver_warning_flag``: e.g. the
    quasi-static assumption, or excitation harmonics above H dropped); a row lies beyond the model's
    small-displacement validity (``within_validity``); contact is lost while the linear
    (bilateral) model is used — its forces then include tension a saddle cannot carry.
    NOTE when the regularised contact law's tensile force exceeds
    :data:`TENSILE_NOTE_FRACTION` of the largest saddle force.
    """
    out: list[Finding] = []
    lcs, models = coord_labels(ds["load_case"]), coord_labels(ds["model"])
    for lc in lcs:
        for m in models:
            out += _row_findings(ds, lc, m)
    if "contact_preserved" in ds and "linear" in models:
        lost = [lc for lc in lcs if not bool(ds["contact_preserved"].sel(load_case=lc, model="linear"))]
        if lost:
            out.append(
                Finding(
                    "WARNING",
                    f"contact lost while the linear model is used ({', '.join(lost)})",
                    "The linear (bilateral-saddle) model needs tension at a saddle over part of the period, which a real "
                    "saddle cannot carry: its forces, moments and stresses are not valid here. Use the nonlinear "
                    "(harmonic-balance) results.",
                )
            )
    if "tensile_force_error_N" in ds and "F_N" in ds:
        for lc in lcs:
            for m in models:
                t = float(ds["tensile_force_error_N"].sel(load_case=lc, model=m))
                f = float(ds["F_N"].sel(load_case=lc, model=m))
                if math.isfinite(t) and f > 0 and t > TENSILE_NOTE_FRACTION * f:
                    out.append(
                        Finding(
                            "NOTE",
                            f"{lc} {m}: the regularised contact law carries up to {t / 1e3:.0f} kN of tension",
                            f"{100 * t / f:.1f} % of the largest saddle force: the price of the smooth (tanh) contact law; "
                            "solver.contact_law=exact or softplus, or a larger solver.regularisation_per_m, removes it.",
                        )
                    )
    out += _axial_findings(ds, lcs, models)
    if not any(f.level == "WARNING" for f in out):
        out.insert(0, Finding("OK", "every solve converged; no diagnostic flags a result", ""))
    return out


def _axial_findings(ds: xr.Dataset, lcs: list[str], models: list[str]) -> list[Finding]:
    """WARNING where the cargo slides or the axial solve failed (docs/axial.md)."""
    if "slip_m" not in ds:
        return []
    out: list[Finding] = []
    for lc in lcs:
        for m in models:
            sel = ds.sel(load_case=lc, model=m)
            if "axial_converged" in sel and not bool(sel["axial_converged"]):
                out.append(
                    Finding(
                        "WARNING",
                        f"{lc} {m}: the axial (friction) solve did NOT converge",
                        str(sel["axial_solver_message"].values.item()) if "axial_solver_message" in sel else "",
                    )
                )
            carries = "axial_warning_flag" in sel and bool(sel["axial_warning_flag"].sel(axial_warning="friction_carries_load"))
            if carries:
                out.append(
                    Finding(
                        "WARNING",
                        f"{lc} {m}: the friction carries more of the axial load than the lashings and stoppers",
                        f"friction up to {float(np.max(np.abs(sel['friction_force_N'].values))) / 1e3:.1f} kN, lashings and stoppers "
                        f"{float(sel['axial_force_N']) / 1e3:.1f} kN; without friction they alone would carry "
                        f"{float(sel['frictionless_axial_force_N']) / 1e3:.1f} kN and let the cargo move "
                        f"{float(sel['frictionless_axial_displacement_m']):.3g} m. Check that the friction may be credited "
                        "(docs/axial.md#friction-credit).",
                    )
                )
            slip = float(sel["slip_m"])
            if slip > 0 and m == "nonlinear":
                out.append(
                    Finding(
                        "WARNING",
                        f"{lc} {m}: the cargo slides on its saddles, {slip * 1e3:.1f} mm per period",
                        f"the friction coefficient is below the critical {float(sel['critical_friction_coefficient']):.4f}; the lashings "
                        f"and stoppers carry up to {float(sel['axial_force_N']) / 1e3:.1f} kN. Add stoppers or friction.",
                    )
                )
    return out


def study_findings(sds: xr.Dataset) -> list[Finding]:
    """Diagnostics of a study: failed points, non-converged nonlinear points, linear validity."""
    out: list[Finding] = []
    keys = study_keys(sds)
    n = int(np.prod([sds.sizes[k] for k in keys])) if keys else 1
    if "error" in sds:
        err = np.asarray(sds["error"].values).astype(str)
        bad = int(np.count_nonzero(err != ""))
        if bad:
            first = next(e for e in err.ravel() if e)
            out.append(
                Finding(
                    "WARNING",
                    f"{bad} of {n} study points failed to evaluate",
                    f"their cells are blank / marked x. First error: {first.splitlines()[0][:300]}",
                )
            )
    total = total_response(sds)
    if "converged" in total and "nonlinear" in coord_labels(total["model"]):
        conv = np.asarray(total["converged"].sel(model="nonlinear").values).astype(bool)
        evaluated = (np.asarray(sds["error"].values).astype(str) == "") if "error" in sds else np.ones_like(conv)
        bad = int(np.count_nonzero(~conv & evaluated))
        if bad:
            out.append(
                Finding(
                    "WARNING",
                    f"the nonlinear solver did not converge at {bad} of {n} points",
                    "those points never count as compliant; inspect them with 'seafast run --set ...'.",
                )
            )
    if "contact_preserved" in total and "linear" in coord_labels(total["model"]):
        lost = int(np.count_nonzero(~np.asarray(total["contact_preserved"].sel(model="linear").values).astype(bool)))
        if lost:
            out.append(
                Finding(
                    "NOTE",
                    f"contact is lost at {lost} of {n} points: the linear model is not valid there",
                    "the linear surfaces are shown for comparison only; decisions use the nonlinear model.",
                )
            )
    if not any(f.level == "WARNING" for f in out):
        out.insert(0, Finding("OK", "every study point evaluated and converged", ""))
    return out
