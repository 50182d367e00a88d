"""The ``seafast seastate`` subcommand: linear spectral extremes and the nonlinear Monte Carlo reference.

``seafast seastate [CASE] -o DIR [--set KEY=VALUE ...] [--workers N | --scheduler ADDRESS]``

Exit codes as ``seafast run``: 0 success; 2 invalid input (one message naming the key, the
value and what is allowed); 3 a nonlinear part did not converge (results written, flagged).
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path
from typing import Any

from seafast.cli.common import EXIT_NOT_CONVERGED, EXIT_OK, add_set_option, error

__all__ = ["add_seastate_subcommand", "SEASTATE_EXAMPLES"]

SEASTATE_EXAMPLES = """examples:
  seafast seastate                                         # the base case in Hs = 3 m, Tp = 10 s (JONSWAP, 3 h)
  seafast seastate case.yaml -o out/hs4 --set sea_state.significant_height_m=4 --set sea_state.peak_period_s=11
  seafast seastate --set sea_state.spectrum=hindcast.csv --set sea_state.peak_period_s=null
  seafast seastate --no-monte-carlo                        # spectral extremes and design waves only (about 4 s, figures included)
  seafast seastate --workers 1                              # Monte Carlo serially; --scheduler tcp://host:8786 for Dask

Outputs in DIR: seastate.csv (model,method,F_N,M_b_Nm,sigma_b_Pa,u_s_m,u_d_m,uplift_per_hour,converged;
rows linear/spectral, linear/monte_carlo, nonlinear/monte_carlo, nonlinear/design_wave; maxima are most
probable maxima over sea_state.duration_s, still water included; empty cells = not computed; off head seas
also F_pad_N,F_stopper_N,lashing_tension_max_N,lashing_tension_min_N,transverse_slip_m after converged, and with
seafastening.friction_coefficient > 0 the design-wave and nonlinear Monte Carlo rows on frictional pads with
pad_friction_utilisation,pad_slip_m),
seastate.nc, case.yaml and PNG figures. 'seafast report DIR' adds the sea-state section.
"""


def _monte_carlo_engine() -> tuple[Any, str]:
    """``(run_monte_carlo, "")`` when the engine loads, else ``(None, why not)``."""
    try:
        from seafast.analyses.seastate import monte_carlo
    except ModuleNotFoundError as exc:
        if exc.name == "seafast.analyses.seastate.monte_carlo":
            return None, "the Monte Carlo engine is not in this version"
        return None, f"the Monte Carlo engine cannot be loaded: {exc} (a missing dependency; reinstall seafast)"
    engine = getattr(monte_carlo, "run_monte_carlo", None)
    return engine, "" if engine is not None else "the Monte Carlo engine has no run_monte_carlo"


def breaking_design_waves_warning(design: Any, heading_deg: float, gravity_m_per_s2: float) -> str | None:
    """The warning when a design wave is steeper than a regular wave can be (2 a / lambda > 1/7), else None.

    Each design wave comes from the direction where the response is largest, so this takes a sea whose response is
    small in every direction at the design frequency against its own MPM; the design_wave row is then no estimate.
    """
    from seafast.config.schema import BREAKING_STEEPNESS

    steep = [(2.0 * w.amplitude_m * w.omega_rad_s**2 / (2.0 * math.pi * gravity_m_per_s2), w) for w in design.waves]
    breaking = [(s, w) for s, w in steep if s > BREAKING_STEEPNESS]
    if not breaking:
        return None
    s, w = max(breaking, key=lambda item: item[0])
    return (
        f"seafast: warning: {len(breaking)} design wave(s) of the sea at {heading_deg:g} deg are steeper than the "
        f"breaking limit (largest: amplitude {w.amplitude_m:.3g} m at {w.omega_rad_s:.3g} rad/s, height / length = "
        f"{s:.2f} > 1/7): no regular wave gives the response's MPM there; "
        "the design_wave row is not a physical estimate (use the spectral and Monte Carlo rows)"
    )


def _cradle_rows(analysis: Any, rows: list[dict[str, Any]], say: Any) -> Any:
    """Off head seas the cargo on its cradles (``CradleSeaState``), its spectral columns put in ``rows[0]``; else None."""
    from seafast.analyses.seastate.cradle_design_wave import cradle_sea_state
    from seafast.analyses.seastate.cradle_extremes import cradle_columns, is_off_head_seas

    if not is_off_head_seas(analysis.case):
        return None
    t0 = time.perf_counter()
    cradle = cradle_sea_state(analysis)
    assert cradle.design is not None
    rows[0].update(cradle_columns(cradle.spectral.totals))
    pads = (
        ""
        if not cradle.design.frictional
        else f", on frictional pads (mu = {cradle.design.frictional[0].friction_coefficient:g}; the linear spectral and linear Monte "
        "Carlo cradle rows stay frictionless)"
    )
    say(
        f"cradles, stoppers and lashings across the ship: linear spectral and {len(cradle.design.waves)} design waves by "
        f"harmonic balance{pads} ({(time.perf_counter() - t0) * 1e3:.0f} ms)"
    )
    return cradle


def _add_cradle_columns(cradle: Any, monte_carlo: Any, rows: list[dict[str, Any]]) -> None:
    """The cradle columns of the Monte Carlo rows (each model's most probable extremes; empty cells where the Monte
    Carlo was not run) and the design-wave row (last), whose ``converged`` then covers the cradle waves too (warned of
    with the largest residual)."""
    from seafast.output.seastate_cradle import monte_carlo_cradle_columns

    if cradle is None or cradle.design is None:
        return
    statistics = (None, None) if monte_carlo is None or monte_carlo.cradle is None else monte_carlo.cradle
    for r, model_statistics in zip(rows[1:-1], statistics, strict=True):
        r.update(monte_carlo_cradle_columns(model_statistics))
    rows[-1].update(cradle.design.columns())
    rows[-1]["converged"] = bool(rows[-1]["converged"]) and cradle.design.converged
    if not cradle.design.converged:
        which = "frictional harmonic balance (pad friction)" if cradle.design.frictional is not None else "harmonic balance"
        print(
            f"seafast: warning: a cradle design wave's {which} did not converge (largest residual "
            f"{cradle.design.residual:.3g}); the design_wave row is flagged converged=false",
            file=sys.stderr,
        )


def _cmd_seastate(args: argparse.Namespace) -> int:
    from seafast.analyses.seastate.design_wave import sea_state_design_waves
    from seafast.analyses.seastate.spectral import spectral_analysis
    from seafast.config import CaseError, load_case, parse_overrides
    from seafast.output.seastate import ROWS, format_seastate_table, monte_carlo_row, not_computed_row, write_seastate_outputs

    if args.workers is not None and args.workers < 1:
        return error(f"--workers {args.workers}: allowed: 1 (serial) or more processes")
    try:
        case = load_case(args.case, parse_overrides(args.overrides))
    except CaseError as exc:
        return error(str(exc))
    say = (lambda *a: None) if args.quiet else (lambda *a: print(*a, file=sys.stderr))
    t0 = time.perf_counter()
    say(f"seafast seastate: '{case.name}'" + (f" from {args.case}" if args.case else " (built-in base case)"))
    try:
        say("spectrum, transfer functions and linear spectral extremes")
        analysis = spectral_analysis(case)
    except (CaseError, ValueError) as exc:
        return error(str(exc))
    say(
        f"{analysis.spectrum.description}: {analysis.spectrum.omega_rad_s.size} frequencies "
        f"{analysis.spectrum.omega_rad_s[0]:.3f}-{analysis.spectrum.omega_rad_s[-1]:.3f} rad/s ({time.perf_counter() - t0:.2f} s)"
    )
    if analysis.directional is not None:
        say(analysis.directional.describe())
    rows = [analysis.extremes.row()]
    try:
        cradle = _cradle_rows(analysis, rows, say)
    except (CaseError, ValueError) as exc:
        return error(str(exc))
    t1 = time.perf_counter()
    design = sea_state_design_waves(analysis)
    how = (
        "converged (exact-event shooting)" if design.settings.harmonics is None else f"by harmonic balance, H = {design.settings.harmonics}"
    )
    say(f"nonlinear design waves: {len(design.waves)} waves, {how} ({(time.perf_counter() - t1) * 1e3:.0f} ms)")
    warning = breaking_design_waves_warning(design, case.sea_state.heading_deg, case.model.gravity_m_per_s2)
    if warning is not None:
        print(warning, file=sys.stderr)
    monte_carlo = None
    engine, why = (None, "--no-monte-carlo") if args.no_monte_carlo else _monte_carlo_engine()
    if engine is None:
        message = f"Monte Carlo rows not computed ({why})"
        if args.no_monte_carlo:
            say(message)
        else:  # the user asked for it: say so even when quiet
            print(f"seafast: warning: {message}", file=sys.stderr)
        rows += [not_computed_row(model, method) for model, method in ROWS[1:3]]
    else:
        ss = case.sea_state
        say(
            f"Monte Carlo reference: {ss.realisations} realisations of {ss.duration_s:g} s, linear and nonlinear "
            f"(resumable in {args.output})"
        )
        try:
            monte_carlo = engine(case, Path(args.output), workers=args.workers, scheduler=args.scheduler, progress=not args.quiet)
        except (CaseError, ValueError) as exc:
            return error(str(exc))
        rows += [monte_carlo_row(monte_carlo.linear), monte_carlo_row(monte_carlo.nonlinear)]
    rows.append(design.row())
    _add_cradle_columns(cradle, monte_carlo, rows)
    if not args.quiet:  # the table as soon as it is known: seastate.nc and the figures take longer
        sp = analysis.spectrum
        d = case.sea_state.duration_s
        span = f"{d / 3600:g} h" if d % 360 == 0 else f"{d:g} s"
        print(format_seastate_table(rows, title=f"{case.name}: {sp.description}, most probable maxima over {span}, still water included"))
        sys.stdout.flush()
    say(f"writing the results to {args.output}")
    paths = write_seastate_outputs(
        analysis, rows, args.output, monte_carlo=monte_carlo, plots=not args.no_plots, design=design, cradle=cradle
    )
    if not args.quiet:
        print(f"wrote {', '.join(str(p) for p in paths.values())} ({time.perf_counter() - t0:.1f} s)")
    bad = [r for r in rows if r["converged"] is False]
    for r in bad:
        what = "a design wave's harmonic balance did not converge" if r["method"] == "design_wave" else "not every realisation converged"
        print(
            f"seafast: warning: {r['model']} {r['method']}: {what}; its numbers are flagged converged=false in seastate.csv",
            file=sys.stderr,
        )
    return EXIT_NOT_CONVERGED if bad else EXIT_OK


def add_seastate_subcommand(subparsers: Any) -> argparse.ArgumentParser:
    """Register ``seafast seastate`` on an argparse subparsers object (handler returns the exit code)."""
    p = subparsers.add_parser(
        "seastate",
        help="extremes in an irregular head sea: linear spectral, nonlinear design waves and Monte Carlo",
        description="Most probable maxima of saddle force, bending moment and stress, saddle compression and "
        "detachment over a sea state (Hs, Tp, spectrum, duration), and the uplift rate: linear spectral analysis, "
        "the nonlinear design-wave estimate (harmonic balance) and the nonlinear Monte Carlo reference; off head seas also "
        "the pad, side-stopper and lashing forces and the cargo's lateral slip at the saddles (spectral and design waves).",
        epilog=SEASTATE_EXAMPLES,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("case", nargs="?", help="case file (YAML); omit for the built-in base case")
    p.add_argument("-o", "--output", default="seafast-seastate", help="output directory (default: %(default)s)")
    add_set_option(p, "sea_state.significant_height_m=4")
    where = p.add_mutually_exclusive_group()
    where.add_argument("--workers", type=int, default=None, metavar="N", help="local worker processes (default: all cores; 1 = serial)")
    where.add_argument("--scheduler", default=None, metavar="ADDRESS", help="Dask distributed scheduler address, e.g. tcp://host:8786")
    p.add_argument("--no-monte-carlo", action="store_true", help="linear spectral extremes only (Monte Carlo rows left empty)")
    p.add_argument("--no-plots", action="store_true", help="skip the PNG figures")
    p.add_argument("-q", "--quiet", action="store_true", help="print only warnings and errors")
    p.set_defaults(handler=_cmd_seastate)
    return p
