"""The ``seafast criteria`` subcommand: the standard's default motion criteria checked on the cargo in its cradles, and
beside them the motion analysis of the case's sea state per heading.

``seafast criteria [CASE] [-o DIR] [--set KEY=VALUE ...] [--motion] [--headings START:STOP:STEP]``

Exit codes as ``seafast run``: 0 success (whatever the verdict: it is in criteria.csv and the table);
2 invalid input (one message naming the key, the value and what is allowed); 3 a load case's statics did not
converge (results written, its outcome ``not_converged``).
"""

from __future__ import annotations

import argparse
import sys
import time
from typing import Any

from seafast.cli.common import EXIT_NOT_CONVERGED, EXIT_OK, add_set_option, error

__all__ = ["add_criteria_subcommand", "CRITERIA_EXAMPLES"]

CRITERIA_EXAMPLES = """examples:
  seafast criteria                                           # the base case against the default motion criteria
  seafast criteria case.yaml -o out/criteria --set seafastening.saddle_contact_angle_deg=35
  seafast criteria --set seafastening.side_stopper.gap_m=0.02 --set seafastening.side_stopper.stiffness_N_per_m=1e8
  seafast criteria --headings 0:315:45                       # and the motion analysis of sea_state.* at eight headings
  seafast criteria --motion --set criteria.design.format=lrfd  # the sea state's own heading; LRFD combinations
  seafast criteria --set criteria.friction.contact=steel_on_timber --set seafastening.friction_coefficient=0.2

Outputs in DIR: criteria.csv (one row per load case and check: load_case,heading_deg,roll_deg,pitch_deg,
heave_acceleration_m_s2,period_s,a_x_m_s2,a_y_m_s2,a_z_m_s2,F_N,F_pad_N,F_stopper_N,lashing_tension_max_N,M_b_Nm,
sigma_b_Pa,utilisation,verdict,check,limit,outcome,F_axial_N,source, then branch,design_format,design_combination,
design_value,design_resistance,design_utilisation,design_verdict,friction_normal_N,friction_capacity_N,friction_credit,
F_axial_unresisted_N), with the motion analysis criteria_motions.csv (the MPMs per heading), and case.yaml; with
criteria.operation, operation.csv (weather-restricted: alpha and the forecast limit OP_WF at the alpha table's design
wave heights) or route.csv (unrestricted: each route leg's 10-year monthly extreme Hs and its Tp range). The limits
are limits.max_saddle_force_N and limits.max_bending_stress_Pa, the design format criteria.design.*;
docs/criteria.md has the standard's values and clause.
"""


def _cmd_criteria(args: argparse.Namespace) -> int:
    from seafast.analyses.criteria.motion_branch import criteria_analysis
    from seafast.analyses.criteria.operation_class import plan_operation
    from seafast.cli.operability import parse_headings
    from seafast.config import CaseError, load_case, parse_overrides
    from seafast.output.criteria import format_criteria_table, write_criteria_outputs
    from seafast.output.operation_class import write_operation_class
    from seafast.solvers.transverse_statics import StaticsOutcome

    t0 = time.perf_counter()
    try:
        headings = None if args.headings is None else tuple(sorted({h % 360.0 for h in parse_headings(args.headings)}))
        case = load_case(args.case, parse_overrides(args.overrides))
        plan = None if case.criteria.operation is None else plan_operation(case.criteria.operation)
        if headings is None and args.motion:
            given = case.criteria.motion_analysis.headings_deg
            headings = (float(case.sea_state.heading_deg),) if given is None else tuple(float(h) for h in given)
        result = criteria_analysis(case, headings)
    except (CaseError, ValueError) as exc:
        return error(str(exc))
    paths = write_criteria_outputs(result, case, args.output)
    operation_text = ""
    if plan is not None:
        path, operation_text = write_operation_class(plan, args.output)
        paths["operation"] = path
    if not args.quiet:
        print(f"{case.name}: F <= {case.limits.max_saddle_force_N / 1e6:g} MN, sigma_b <= {case.limits.max_bending_stress_Pa / 1e6:g} MPa")
        print(format_criteria_table(result))
        if operation_text:
            print(operation_text)
        print(f"wrote {', '.join(str(p) for p in paths.values())} ({time.perf_counter() - t0:.1f} s)")
    solved = [*result.default.cases, *(c for h in result.headings for c in h.cases)]
    failed = [c for c in solved if c.outcome == StaticsOutcome.NOT_CONVERGED.value]
    waves = [s.name for h in result.headings for s in h.sea_state if not s.converged]
    for name in waves:
        print(f"seafast: warning: {name}: a design wave's harmonic balance did not converge (flagged not_converged)", file=sys.stderr)
    if failed:
        cases = ", ".join(f"{c.load_case.name} (residual {c.statics.residual_N:.3g} N)" for c in failed)
        print(f"seafast: warning: the statics did not converge in {cases}: outcome not_converged", file=sys.stderr)
        return EXIT_NOT_CONVERGED
    return EXIT_NOT_CONVERGED if waves else EXIT_OK


def add_criteria_subcommand(subparsers: Any) -> argparse.ArgumentParser:
    """Register ``seafast criteria`` on an argparse subparsers object (handler returns the exit code)."""
    p = subparsers.add_parser(
        "criteria",
        help="the standard's default motion criteria as quasi-static load cases, solved exactly on the cradles",
        description="Roll and pitch of the standard's default motion criteria (by the vessel's size), each sign with "
        "heave up and down, applied to the cargo on its saddle pads, side stoppers and lashings and solved exactly "
        "(unilateral contact); saddle forces and bending stress checked against the case's limits.",
        epilog=CRITERIA_EXAMPLES,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("case", nargs="?", help="case file (YAML); omit for the built-in base case")
    p.add_argument("-o", "--output", default="seafast-criteria", help="output directory (default: %(default)s)")
    add_set_option(p, "seafastening.saddle_contact_angle_deg=35")
    p.add_argument(
        "--motion",
        action="store_true",
        help="add the motion analysis of sea_state.* at criteria.motion_analysis.headings_deg (default: sea_state.heading_deg)",
    )
    p.add_argument(
        "--headings",
        metavar="START:STOP:STEP",
        help="add the motion analysis of sea_state.* at these headings [deg] (180 head seas, 90 beam seas), e.g. 0:315:45 or 135",
    )
    p.add_argument("-q", "--quiet", action="store_true", help="print only warnings and errors")
    p.set_defaults(handler=_cmd_criteria)
    return p
