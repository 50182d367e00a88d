"""``seafast sweep``: the nonlinear frequency response by continuation, its table, figure and warnings."""

from __future__ import annotations

import argparse
import math
import sys
from typing import Any

from seafast.cli.common import EXIT_NOT_CONVERGED, EXIT_OK, add_case_options, error

__all__ = ["add_sweep_subcommand"]


def add_sweep_subcommand(subparsers: Any) -> argparse.ArgumentParser:
    """``seafast sweep``."""
    sweep = subparsers.add_parser(
        "sweep",
        help="nonlinear frequency response by pseudo-arclength continuation (structural, or --wave: the case's wave amplitude)",
        epilog="examples:\n  seafast sweep --omega-min 0.2 --omega-max 2.0            # wave frequencies: quasi-static?\n"
        "  seafast sweep --set seafastening.saddle_stiffness_N_per_m=1.1e7 --omega-min 0.5 --omega-max 12  # through resonance\n"
        "  seafast sweep --wave --omega-min 0.2 --omega-max 1.8     # nonlinear RAOs of saddle force and bending moment",
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    sweep.add_argument("case", nargs="?", help="case file (YAML); omit for the built-in base case")
    sweep.add_argument("-o", "--output", default="seafast-sweep", help="output directory (default: %(default)s)")
    sweep.add_argument("--omega-min", type=float, default=0.2, help="start frequency [rad/s] (default: %(default)s)")
    sweep.add_argument("--omega-max", type=float, default=2.0, help="end frequency [rad/s] (default: %(default)s)")
    sweep.add_argument(
        "--wave",
        action="store_true",
        help=(
            "wave sweep: at each frequency a wave of the case's amplitude (its hull deflection and RAOs) instead of the case's motions held"
        ),
    )
    sweep.add_argument(
        "--max-gap-m",
        type=float,
        default=None,
        metavar="GAP",
        help="largest detachment gap inside the physically meaningful range [m] (default: 0.1); points beyond are flagged valid=false",
    )
    sweep.add_argument(
        "--follow-beyond-range",
        action="store_true",
        help=(
            "structural sweep: go on past the frequency where the held deck motion accelerates the deck faster than g (default: stop there)"
        ),
    )
    sweep.add_argument("--no-plots", action="store_true", help="skip frequency_response.png")
    add_case_options(sweep)
    sweep.set_defaults(handler=_cmd_sweep)
    return sweep


def _cmd_sweep(args: argparse.Namespace) -> int:
    from seafast.analyses.sweep.frequency import SweepKind, frequency_sweep
    from seafast.config import CaseError, load_case, parse_overrides
    from seafast.output.sweep import fold_warning, format_sweep_summary, range_warning, truncation_warning, write_sweep_outputs

    if not all(map(math.isfinite, (args.omega_min, args.omega_max))) or not (0 < args.omega_min < args.omega_max):
        return error(f"--omega-min = {args.omega_min}, --omega-max = {args.omega_max}: need 0 < omega-min < omega-max (rad/s)")
    if args.max_gap_m is not None and not (math.isfinite(args.max_gap_m) and args.max_gap_m > 0):
        return error(f"--max-gap-m = {args.max_gap_m}: need a finite gap > 0 (m)")
    kind = SweepKind.WAVE if args.wave else SweepKind.STRUCTURAL
    try:
        case = load_case(args.case, parse_overrides(args.overrides))
        if kind is SweepKind.WAVE and not case.wave.amplitude_m > 0:
            return error(f"wave.amplitude_m = {case.wave.amplitude_m}: the wave sweep needs a wave amplitude > 0 (m)")
        result = frequency_sweep(
            case, args.omega_min, args.omega_max, kind=kind, max_gap_m=args.max_gap_m, follow_beyond_range=args.follow_beyond_range
        )
    except (CaseError, ValueError) as exc:
        return error(str(exc))
    paths = write_sweep_outputs(result, args.output, plots=not args.no_plots)
    if not args.global_quiet:
        w1 = float(result.model.natural_frequencies_rad_s(True, 1)[0])
        for line in format_sweep_summary(result):
            print(line)
        print(f"first natural frequency on bilateral saddles {w1:.3g} rad/s; wrote {', '.join(str(p) for p in paths)}")
    for warning in (range_warning(result), truncation_warning(result), fold_warning(result)):
        if warning is not None:
            print(f"seafast: warning: {warning}", file=sys.stderr)
    if not result.converged:
        print("seafast: warning: some branch points did NOT converge (converged=false in frequency_response.csv)", file=sys.stderr)
    return EXIT_OK if result.converged else EXIT_NOT_CONVERGED
