"""The ``seafast operability`` subcommand: allowable Hs per peak period, linear and nonlinear.

``seafast operability [CASE] [--tp START:STOP:STEP] [--headings START:STOP:STEP] [-o DIR] [--set KEY=VALUE ...] [--scatter FILE]
[--workers N]``

``--workers N`` (above 1): each heading's peak periods on N local processes, each Tp's answer the serial one.

With ``--headings`` (one heading or a range, degrees in [0, 360]; 180 = head seas, 90 = beam seas)
the analysis runs once per heading (:func:`seafast.analyses.operability.headings.allowable_per_heading`),
``operability.csv`` gains a leading ``heading_deg`` column, the chart is polar and the governing
heading is named; without it the outputs are those of the case's own sea state alone.

Without ``--tp`` the peak periods are :data:`DEFAULT_PEAK_PERIODS` (5 to 20 s every 0.5 s; the
start raised to the shortest peak period the case's spectrum allows, see
:func:`default_peak_periods` and ``docs/operability.md`` section 4).

Exit codes as ``seafast run``: 0 success; 2 invalid input (one message naming the option or key,
the value and what is allowed); 3 a nonlinear search did not converge (results written, its
governing_nonlinear is ``not_converged``).
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

from seafast.cli.common import EXIT_NOT_CONVERGED, EXIT_OK, add_set_option, error

if TYPE_CHECKING:
    from seafast.analyses.criteria.operation_class import OperationPlan
    from seafast.analyses.operability.allowable import OperabilityResult
    from seafast.analyses.operability.headings import HeadingOperabilityResult
    from seafast.config import Case
    from seafast.parallel.executor import ExecutionOptions

__all__ = [
    "add_operability_subcommand",
    "parse_peak_periods",
    "parse_headings",
    "default_peak_periods",
    "OPERABILITY_EXAMPLES",
    "MAX_PEAK_PERIODS",
    "MAX_HEADINGS",
    "DEFAULT_PEAK_PERIODS",
]

MAX_PEAK_PERIODS = 1000
MAX_HEADINGS = 361
# START:STOP:STEP [s] without --tp: the wind seas and swell this kind of vessel meets, the
# response peak (Tp 9.5-10 s on the base case) well inside (docs/operability.md section 4)
DEFAULT_PEAK_PERIODS = "5:20:0.5"


def _limits_text(limits: Any) -> str:
    """The limits judged, for the table's title: the vertical plane's two and each cradle limit set."""
    parts = [f"F <= {limits.max_saddle_force_N / 1e6:g} MN", f"sigma_b <= {limits.max_bending_stress_Pa / 1e6:g} MPa"]
    if limits.max_pad_force_N is not None:
        parts.append(f"F_pad <= {limits.max_pad_force_N / 1e6:g} MN off head seas")
    if limits.max_lashing_tension_N is not None:
        parts.append(f"lashing tension <= {limits.max_lashing_tension_N / 1e3:g} kN off head seas")
    if limits.max_transverse_slip_m is not None:
        parts.append(f"slip <= {limits.max_transverse_slip_m * 1e3:g} mm off head seas")
    return ", ".join(parts)


OPERABILITY_EXAMPLES = """examples:
  seafast operability                                        # the base case, Tp 5-20 s every 0.5 s, limits 7 MN / 20 MPa
  seafast operability --tp 5:16:0.5                          # 23 peak periods
  seafast operability case.yaml --tp 6:14:1 -o out/op --set limits.max_saddle_force_N=11.5e6
  seafast operability --tp 4:18:1 --scatter hindcast.csv    # also the share of a scatter diagram within the limits
  seafast operability --headings 90:180:15 --tp 6:14:1       # per heading (180 = head seas, 90 = beam seas): polar chart
  seafast operability --headings 90:180:30 --set limits.max_pad_force_N=5e6   # also the cradles' pads off head seas

Outputs in DIR: operability.csv (peak_period_s,hs_allowable_linear_m,hs_allowable_nonlinear_m,hs_uplift_onset_m,
governing_linear,governing_nonlinear; empty cell = not found), operability.nc, operability.png (Hs against Tp),
case.yaml, and with --scatter scatter.csv. With --headings: operability.csv gains a leading heading_deg column
(one row per heading and Tp), operability.nc a heading_deg dimension, the chart is polar (180 deg = head seas at
the top) and the governing heading (smallest allowable Hs) is printed. With criteria.operation weather-restricted,
operability.csv gains alpha_linear,hs_forecast_limit_linear_m,alpha_nonlinear,hs_forecast_limit_nonlinear_m (the
weather-routing limit OP_WF = alpha x allowable Hs); unrestricted, route.csv checks each route leg's design sea state.
The spectrum shape, gamma and duration are the case's sea_state keys
(its Hs and Tp are not used); the limits are limits.max_saddle_force_N and limits.max_bending_stress_Pa, and off head
seas also limits.max_pad_force_N, max_lashing_tension_N and max_transverse_slip_m where set (the cargo on its
cradles; operability.csv then gains hs_{pad_force,lashing_tension,transverse_slip}_{linear,nonlinear}_m).
'seafast report DIR' adds the operability section.
"""


def _range(text: str, option: str, allowed: str, valid: Callable[[float, float, float], bool], most: int, what: str) -> list[float]:
    """``START:STOP:STEP`` (STOP included) or one value to a list; ValueError naming ``option`` and ``allowed``."""
    parts = str(text).split(":")
    try:
        if len(parts) == 1:
            start = stop = float(parts[0])
            step = 1.0
        else:
            start, stop, step = (float(p) for p in parts)
    except ValueError:
        raise ValueError(f"{option} {text!r}: allowed: {allowed}") from None
    if not all(math.isfinite(v) for v in (start, stop, step)) or not valid(start, stop, step):
        raise ValueError(f"{option} {text!r}: allowed: {allowed}")
    n = math.floor((stop - start) / step + 1e-9) + 1
    if n > most:
        raise ValueError(f"{option} {text!r} gives {n} {what}; allowed: at most {most}")
    return [round(start + i * step, 10) for i in range(n)]


def parse_peak_periods(text: str) -> list[float]:
    """``START:STOP:STEP`` [s] to the peak periods START, START + STEP, ... up to STOP inclusive; or one peak period.

    Raises
    ------
    ValueError
        With a message naming ``--tp``, the value and what is allowed.
    """
    allowed = "START:STOP:STEP in seconds with 0 < START <= STOP and STEP > 0, e.g. 5:16:0.5, or one peak period > 0"
    return _range(text, "--tp", allowed, lambda a, b, s: 0 < a <= b and s > 0, MAX_PEAK_PERIODS, "peak periods")


def parse_headings(text: str) -> list[float]:
    """``START:STOP:STEP`` [deg] to the headings START, START + STEP, ... up to STOP inclusive; or one heading.

    180 = head seas, 90 = beam seas; 0 and 360 are the same heading (not both).

    Raises
    ------
    ValueError
        With a message naming ``--headings``, the value and what is allowed.
    """
    allowed = (
        "START:STOP:STEP in degrees with 0 <= START <= STOP <= 360 and STEP > 0, e.g. 90:180:15, or one heading "
        "in [0, 360] (180 = head seas, 90 = beam seas)"
    )
    headings = _range(text, "--headings", allowed, lambda a, b, s: 0 <= a <= b <= 360 and s > 0, MAX_HEADINGS, "headings")
    if len(headings) > 1 and headings[0] == 0.0 and headings[-1] == 360.0:
        raise ValueError(f"--headings {text!r}: 0 and 360 deg are the same heading; allowed: one of them, e.g. 0:330:30")
    return headings


def default_peak_periods(case: Case) -> list[float]:
    """The peak periods [s] of :data:`DEFAULT_PEAK_PERIODS`, the start raised to the case's spectrum.

    The start is the larger of 5 s and the shortest peak period whose spectrum the transfer
    functions resolve (:func:`seafast.analyses.seastate.spectrum.shortest_peak_period_s`), rounded up to
    the 0.5 s step: 5 s for JONSWAP with gamma = 3.3 (4.72 s), 5.5 s for Pierson-Moskowitz (5.25 s).
    A spectrum table gives the fixed range (operability refuses it with its own message).
    """
    start, stop, step = (float(v) for v in DEFAULT_PEAK_PERIODS.split(":"))
    ss = case.sea_state
    if ss.spectrum in ("jonswap", "pierson_moskowitz"):
        from seafast.analyses.seastate.spectrum import shortest_peak_period_s

        gamma = 1.0 if ss.spectrum == "pierson_moskowitz" else float(ss.peak_enhancement)
        start = max(start, math.ceil(shortest_peak_period_s(gamma) / step - 1e-9) * step)
    return parse_peak_periods(f"{start:g}:{stop:g}:{step:g}")


def _cmd_operability(args: argparse.Namespace) -> int:
    from seafast.analyses.operability.allowable import allowable_sea_states
    from seafast.analyses.operability.family import sea_state_family
    from seafast.analyses.operability.scatter import assess_scatter, read_scatter_diagram
    from seafast.config import CaseError, load_case, parse_overrides
    from seafast.output.operability import format_operability_table, write_operability_outputs

    try:
        tps = parse_peak_periods(args.tp) if args.tp is not None else None
        headings = parse_headings(args.headings) if args.headings is not None else None
    except ValueError as exc:
        return error(str(exc))
    if args.workers < 1:
        return error(f"--workers {args.workers}: allowed: 1 (serial, the default) or more local processes")
    execution = _workers_execution(args.workers)
    if headings is not None and args.scatter:
        return error(
            f"--scatter {args.scatter} with --headings {args.headings}: a scatter diagram is assessed in one heading; allowed: "
            "--scatter without --headings (the case's sea state heading)"
        )
    if args.scatter and Path(args.scatter).resolve() == (Path(args.output) / "scatter.csv").resolve():
        return error(
            f"--scatter {args.scatter}: it is the output scatter.csv of -o {args.output}; allowed: a file outside it, "
            "or another output directory"
        )
    try:
        case = load_case(args.case, parse_overrides(args.overrides))
        scatter = read_scatter_diagram(args.scatter) if args.scatter else None
        plan = _operation_plan(case)
    except (CaseError, ValueError) as exc:
        return error(str(exc))
    say = (lambda *a: None) if args.quiet else (lambda *a: print(*a, file=sys.stderr))
    t0 = time.perf_counter()
    default = tps is None
    if tps is None:
        tps = default_peak_periods(case)
    if headings is not None:
        return _run_headings(args, case, headings, tps, default, t0, plan)
    scatter_tps = [float(t) for t in scatter.peak_periods_s] if scatter is not None else []
    say(
        f"seafast operability: '{case.name}', {len(tps)} peak periods {tps[0]:g}-{tps[-1]:g} s"
        + (f" every {tps[1] - tps[0]:g} s (the default; --tp START:STOP:STEP to choose)" if default else "")
        + (f" and the {len(scatter_tps)} of the scatter diagram" if scatter is not None else "")
    )
    try:
        family = sea_state_family(case, tps + scatter_tps)
    except CaseError as exc:
        message = str(exc)
        if "sea_state.peak_period_s" in message:
            message = f"--tp / --scatter: a peak period is outside what the transfer functions resolve: {message}"
        return error(message)
    except ValueError as exc:
        return error(str(exc))
    say(f"transfer functions on {family.master_omega_rad_s.size} frequencies ({time.perf_counter() - t0:.2f} s)")

    def progress(done: int, total: int) -> None:
        if not args.quiet and sys.stderr.isatty():
            print(f"\r  peak period {done}/{total}", end="" if done < total else "\n", file=sys.stderr)

    result = allowable_sea_states(case, tps, family=family, progress=progress, execution=execution)
    assessment = None
    if scatter is not None:
        at = allowable_sea_states(case, scatter_tps, family=family)
        assessment = assess_scatter(
            scatter,
            [p.peak_period_s for p in at.points],
            [p.hs_allowable_linear_m for p in at.points],
            [p.hs_allowable_nonlinear_m for p in at.points],
        )
    paths = write_operability_outputs(result, args.output, scatter=assessment, plots=not args.no_plots)
    operation_paths, operation_text = _operation_outputs(plan, result, paths["operability_csv"], Path(args.output))
    paths |= operation_paths
    if not args.quiet:
        print(f"{case.name}: allowable Hs per peak period (MPM over {case.sea_state.duration_s / 3600:g} h; {_limits_text(case.limits)})")
        print(format_operability_table(result))
        if operation_text:
            print(operation_text)
        if assessment is not None:
            print(
                f"scatter diagram {assessment.diagram.source}: within the limits {assessment.share_within_linear:.1%} of the "
                f"time (linear), {assessment.share_within_nonlinear:.1%} (nonlinear)"
            )
        print(f"wrote {', '.join(str(p) for p in paths.values())} ({time.perf_counter() - t0:.1f} s)")
    failed = [p.peak_period_s for p in result.points if not p.converged]
    if assessment is not None and bool(assessment.not_assessed.any()):
        failed += sorted(set(assessment.diagram.peak_period_s[assessment.not_assessed].tolist()))
    if failed:
        print(
            f"seafast: warning: the nonlinear search did not converge at Tp = {', '.join(f'{t:g}' for t in failed)} s "
            "(governing_nonlinear = not_converged, empty Hs)",
            file=sys.stderr,
        )
        return EXIT_NOT_CONVERGED
    return EXIT_OK


def _operation_plan(case: Case) -> OperationPlan | None:
    """The case's operation class before the analysis (scatter diagrams of the route read and fitted), or None."""
    from seafast.analyses.criteria.operation_class import plan_operation

    op = case.criteria.operation
    return None if op is None else plan_operation(op)


def _operation_outputs(
    plan: OperationPlan | None, result: OperabilityResult | HeadingOperabilityResult, operability_csv: Path, out_dir: Path
) -> tuple[dict[str, Path], str]:
    """The operation class's columns of operability.csv or its route.csv, and its terminal text."""
    from seafast.analyses.criteria.operation_class import route_checks, weather_routing_limits
    from seafast.output.operation_class import (
        allowable_table_of,
        append_routing_columns,
        format_route_table,
        format_routing_table,
        operation_summary,
        route_csv_text,
    )

    if plan is None:
        return {}, ""
    table = allowable_table_of(result)
    if plan.restriction is not None:
        limits = weather_routing_limits(plan.restriction, table)
        append_routing_columns(operability_csv, limits)
        return {}, operation_summary(plan) + "\n" + format_routing_table(limits)
    checks = route_checks(plan.route, table)
    path = out_dir / "route.csv"
    path.write_text(route_csv_text(plan.route, checks), encoding="utf-8")
    for c in checks:
        if not c.peak_periods_s:
            print(
                f"seafast: warning: route leg '{c.sea_state.sector}, {c.sea_state.season}': no analysed peak period in its range "
                f"{c.sea_state.tp_min_s:.2f}-{c.sea_state.tp_max_s:.2f} s (verdict not_assessed); allowed: a --tp range covering it",
                file=sys.stderr,
            )
    return {"route_csv": path}, operation_summary(plan) + "\n" + format_route_table(checks)


def _workers_execution(workers: int) -> ExecutionOptions | None:
    """``--workers``: the peak periods on local worker processes, one Tp per task (None: 1, serial, the default)."""
    from seafast.parallel.executor import ExecutionOptions

    return ExecutionOptions(workers=workers, progress=False) if workers > 1 else None


def _run_headings(
    args: argparse.Namespace, case: Case, headings: list[float], tps: list[float], default: bool, t0: float, plan: OperationPlan | None
) -> int:
    """``seafast operability --headings``: the analysis per heading, its files and printed table, the exit code."""
    from seafast.analyses.operability.allowable import OperabilitySettings, allowable_sea_states
    from seafast.analyses.operability.headings import AllowableModel, allowable_per_heading
    from seafast.config import CaseError
    from seafast.output.operability_headings import format_heading_table, governing_heading_text, write_heading_operability_outputs

    if not args.quiet:
        print(
            f"seafast operability: '{case.name}', {len(headings)} heading(s) {headings[0]:g}-{headings[-1]:g} deg x {len(tps)} peak "
            f"periods {tps[0]:g}-{tps[-1]:g} s" + (" (the default; --tp START:STOP:STEP to choose)" if default else ""),
            file=sys.stderr,
        )

    def progress(done: int, total: int) -> None:
        if not args.quiet and sys.stderr.isatty():
            print(f"\r  heading {done}/{total}", end="" if done < total else "\n", file=sys.stderr)

    def analyse(case_h: Case, tps_h: Sequence[float], settings: OperabilitySettings) -> OperabilityResult:
        return allowable_sea_states(case_h, tps_h, settings, execution=_workers_execution(args.workers))

    try:
        result = allowable_per_heading(case, headings, tps, analyse=analyse, progress=progress)
    except CaseError as exc:
        message = str(exc)
        if "sea_state.peak_period_s" in message:
            message = f"--tp: a peak period is outside what the transfer functions resolve: {message}"
        return error(f"--headings {args.headings}: {message}")
    paths = write_heading_operability_outputs(result, args.output, plots=not args.no_plots)
    operation_paths, operation_text = _operation_outputs(plan, result, paths["operability_csv"], Path(args.output))
    paths |= operation_paths
    if not args.quiet:
        print(
            f"{case.name}: allowable Hs per heading and peak period (MPM over {case.sea_state.duration_s / 3600:g} h; "
            f"{_limits_text(case.limits)})"
        )
        print(format_heading_table(result))
        if operation_text:
            print(operation_text)
        for model in (AllowableModel.NONLINEAR, AllowableModel.LINEAR):
            print(governing_heading_text(result.governing_heading(model), model))
        print(f"wrote {', '.join(str(p) for p in paths.values())} ({time.perf_counter() - t0:.1f} s)")
    for h in result.headings:
        if h.failed:
            print(f"seafast: warning: heading {h.heading_deg:g} deg failed ({h.error}): its Hs are empty", file=sys.stderr)
        elif not h.result.converged:
            failed = ", ".join(f"{p.peak_period_s:g}" for p in h.result.points if not p.converged)
            print(
                f"seafast: warning: heading {h.heading_deg:g} deg: the nonlinear search did not converge at Tp = {failed} s "
                "(governing_nonlinear = not_converged, empty Hs)",
                file=sys.stderr,
            )
    return EXIT_OK if result.converged else EXIT_NOT_CONVERGED


def add_operability_subcommand(subparsers: Any) -> argparse.ArgumentParser:
    """Register ``seafast operability`` on an argparse subparsers object (handler returns the exit code)."""
    p = subparsers.add_parser(
        "operability",
        help="allowable significant wave height per peak period, linear and nonlinear (design waves)",
        description="For each peak period, the significant wave height at which the most probable maximum saddle force "
        "or bending stress reaches its limit (linear spectral and nonlinear design-wave estimates), and the one at which "
        "a saddle first lifts off; optionally the share of a wave scatter diagram within the limits.",
        epilog=OPERABILITY_EXAMPLES,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("case", nargs="?", help="case file (YAML); omit for the built-in base case")
    p.add_argument(
        "--tp",
        default=None,
        metavar="START:STOP:STEP",
        help=f"peak periods [s], STOP included, e.g. 5:16:0.5 (default: {DEFAULT_PEAK_PERIODS}, the start raised to the shortest "
        "peak period the case's spectrum resolves: 5.5 s for pierson_moskowitz)",
    )
    p.add_argument(
        "--headings",
        default=None,
        metavar="START:STOP:STEP",
        help="wave headings [deg], STOP included, or one heading, in [0, 360]: 180 = head seas, 90 = beam seas from starboard, "
        "e.g. 90:180:15 (default: the case's sea state alone, no heading column)",
    )
    p.add_argument("-o", "--output", default="seafast-operability", help="output directory (default: %(default)s)")
    add_set_option(p, "limits.max_saddle_force_N=11.5e6")
    p.add_argument(
        "--scatter", default=None, metavar="FILE", help="wave scatter diagram, CSV significant_height_m,peak_period_s,occurrence"
    )
    p.add_argument("--no-plots", action="store_true", help="skip the PNG chart")
    p.add_argument("--workers", type=int, default=1, metavar="N", help="local processes over the peak periods (default: 1, serial)")
    p.add_argument("-q", "--quiet", action="store_true", help="print only warnings and errors")
    p.set_defaults(handler=_cmd_operability)
    return p
