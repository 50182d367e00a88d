"""The ``seafast criteria`` subcommand: the standard's default motion criteria checked on the cargo in its cradles.

``seafast criteria [CASE] [-o DIR] [--set KEY=VALUE ...]``

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

Outputs in DIR: criteria.csv (one row per load case and check: load_case,heading_deg,roll_deg,pitch_deg,
heave_acceleration_m_s2,period_s,a_x_m_s2,a_y_m_s2,a_z_m_s2,F_N,F_pad_N,F_stopper_N,lashing_tension_max_N,M_b_Nm,
sigma_b_Pa,utilisation,verdict,check,limit,outcome,F_axial_N,source) and case.yaml; with criteria.operation, operation.csv
(weather-restricted: alpha and the forecast limit OP_WF at the alpha table's design wave heights) or route.csv
(unrestricted: each route leg's 10-year monthly extreme Hs and its Tp range). The limits are
limits.max_saddle_force_N and limits.max_bending_stress_Pa; docs/criteria.md has the standard's values and clause.
"""


def _cmd_criteria(args: argparse.Namespace) -> int:
    from seafast.analyses.criteria.check import criteria_check
    from seafast.analyses.criteria.operation_class import plan_operation
    from seafast.config import CaseError, load_case, parse_overrides
    from seafast.output.criteria import format_criteria_table, write_criteria_outputs
    from seafast.output.operation_class import write_operation_class
    from seafast.solvers.transverse_statics import StaticsOutcome

    t0 = time.perf_counter()
    try:
        case = load_case(args.case, parse_overrides(args.overrides))
        plan = None if case.criteria.operation is None else plan_operation(case.criteria.operation)
        result = criteria_check(case)
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
    failed = [c for c in result.cases if c.outcome == StaticsOutcome.NOT_CONVERGED.value]
    if failed:
        cases = ", ".join(f"{c.load_case.name} (residual {c.statics.residual_N:.3g} N)" for c in failed)
        print(f"seafast: warning: the statics did not converge in {cases}: outcome not_converged", file=sys.stderr)
        return EXIT_NOT_CONVERGED
    return EXIT_OK


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
    p.add_argument("-q", "--quiet", action="store_true", help="print only warnings and errors")
    p.set_defaults(handler=_cmd_criteria)
    return p
