"""Outputs of ``seafast sweep``: ``frequency_response.csv`` and ``frequency_response.png``.

The CSV has one row per branch point in continuation order (omega is not monotonic past a fold),
the columns of :data:`seafast.analyses.sweep.table.STRUCTURAL_COLUMNS` or
:data:`~seafast.analyses.sweep.table.WAVE_COLUMNS` (the first six are the columns the file always had).
The figure draws stable parts solid, unstable parts dashed red and marginal ones (within the
stability tolerance of a fold) orange, marks the folds and the points with too few harmonics,
shades what lies beyond the physically meaningful range, and puts the linear model beside the
nonlinear one.
"""

from __future__ import annotations

import csv
from pathlib import Path
from typing import Any

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from numpy.typing import NDArray

from seafast.analyses.sweep.frequency import SweepResult
from seafast.analyses.sweep.range import RangeLimit
from seafast.analyses.sweep.table import BASE_COLUMNS, SweepTable
from seafast.model.structure import StructuralModel
from seafast.solvers.floquet import Stability

__all__ = [
    "COLUMNS",
    "write_csv",
    "structural_figure",
    "write_sweep_outputs",
    "format_sweep_summary",
    "range_warning",
    "truncation_warning",
    "fold_warning",
]

COLUMNS = BASE_COLUMNS
"""The first columns of every ``frequency_response.csv`` (kept for the scripts that read them)."""

DPI = 200


def _cell(value: Any) -> str:
    if isinstance(value, (bool, np.bool_)):
        return "true" if value else "false"
    if isinstance(value, str):
        return value
    return repr(float(value))


def write_csv(table: SweepTable, path: Path) -> Path:
    """Write the table as ``frequency_response.csv`` (booleans true/false, floats in full precision)."""
    names = table.column_names
    columns = [table.column(name) for name in names]
    with path.open("w", newline="") as f:
        w = csv.writer(f)
        w.writerow(names)
        for row in zip(*columns, strict=True):
            w.writerow([_cell(v) for v in row])
    return path


def _runs(keys: NDArray) -> list[tuple[int, int, int]]:
    """Maximal runs ``(start, stop, key)`` of equal keys (stop exclusive)."""
    out, start = [], 0
    for i in range(1, keys.size + 1):
        if i == keys.size or keys[i] != keys[start]:
            out.append((start, i, int(keys[start])))
            start = i
    return out


_STYLES = {  # stability -> format, colour, legend label
    Stability.STABLE: ("-", "k", "nonlinear, stable"),
    Stability.UNSTABLE: ("--", "tab:red", "nonlinear, unstable (Floquet multiplier > 1)"),
    Stability.MARGINAL: ("-", "tab:orange", "nonlinear, marginal (at a fold)"),
}
_ORDER = tuple(_STYLES)


def _branch(ax: plt.Axes, table: SweepTable, values: NDArray) -> None:
    """The nonlinear branch by stability (faded beyond the meaningful range); folds as triangles, too few harmonics as crosses."""
    omega, valid = table.omega_rad_s, table.valid
    stability = np.array([_ORDER.index(v) for v in table.stability], dtype=int)
    labelled: set[int] = set()
    for start, stop, key in _runs(2 * stability + valid.astype(int)):
        style = (key // 2, bool(key % 2))
        ls, colour, label = _STYLES[_ORDER[style[0]]]
        seg = slice(max(start - 1, 0), stop)  # joined to the previous run
        alpha = 1.0 if style[1] else 0.3  # faded beyond the meaningful range (one legend entry, see _legend)
        ax.plot(omega[seg], values[seg], ls=ls, color=colour, lw=1.3, alpha=alpha, label=None if style[0] in labelled else label)
        labelled.add(style[0])
    if not valid.all():
        ax.plot([], [], color="0.6", lw=1.3, alpha=0.4, label="faded: beyond the meaningful range")
    f = table.fold
    if np.any(f):
        ax.plot(omega[f], values[f], "^", color="tab:orange", ms=7, label="fold")
    few = table.too_few_harmonics
    if np.any(few):
        label = f"truncation error > {table.truncation_tolerance:g} (too few harmonics)"
        ax.plot(omega[few], values[few], "x", color="0.4", ms=3, lw=0.6, label=label)


def structural_figure(table: SweepTable, model: StructuralModel, acceleration_limit_rad_s: float | None) -> plt.Figure:
    """The structural sweep's figure: saddle force, gap and bending moment against omega, natural frequencies marked."""
    omega = table.omega_rad_s
    fig, axes = plt.subplots(3, 1, figsize=(8, 9), sharex=True)
    order = np.argsort(omega)
    panels = (
        (axes[0], table.max_saddle_force_N / 1e6, table.linear_max_saddle_force_N / 1e6, "max saddle force [MN]"),
        (axes[1], table.max_gap_m * 1e3, None, "max detachment gap [mm]"),
        (axes[2], table.max_bending_moment_Nm / 1e6, table.linear_max_bending_moment_Nm / 1e6, "max bending moment [MN m]"),
    )
    for ax, values, linear, label in panels:
        if linear is not None:
            ax.plot(omega[order], linear[order], color="tab:blue", ls=":", lw=1.2, label="linear model (bilateral saddles)")
        _branch(ax, table, values)
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    axes[1].axhline(table.limits.max_gap_m * 1e3, color="0.5", ls="--", lw=1, label=f"gap limit {table.limits.max_gap_m * 1e3:g} mm")
    shaded = acceleration_limit_rad_s is not None and acceleration_limit_rad_s < float(omega.max())
    if shaded:
        for ax in axes:
            ax.axvspan(acceleration_limit_rad_s, float(omega.max()), color="0.88", zorder=0)
        axes[2].text(acceleration_limit_rad_s, axes[2].get_ylim()[1], " deck acceleration > g", va="top", fontsize=8, color="0.3")
    natural = np.asarray(model.natural_frequencies_rad_s(True, 3), dtype=float)
    inside = natural[(natural >= omega.min()) & (natural <= omega.max())]
    for w in inside:
        for ax in axes:
            ax.axvline(w, color="tab:blue", ls="-.", lw=0.8, alpha=0.6)
    if inside.size:
        lines = "dash-dot: natural frequencies on bilateral saddles (" + ", ".join(f"{w:.3g}" for w in inside) + " rad/s)"
    else:
        side = "above" if natural[0] > omega.max() else "outside"
        lines = f"natural frequencies on bilateral saddles {side} the sweep (the first {natural[0]:.3g} rad/s)"
    _legend(fig, axes)
    axes[0].set_title(
        "Structural frequency response: the case's deck and rigid-body amplitudes held\n"
        + lines
        + ("; grey: deck accelerating faster than g" if shaded else ""),
        fontsize=10,
    )
    axes[-1].set_xlabel("excitation frequency omega [rad/s]")
    fig.tight_layout(rect=(0.0, 0.07, 1.0, 1.0))
    return fig


def _legend(fig: plt.Figure, axes: Any) -> None:
    """One legend for all panels, below them (inside, it covers the branch)."""
    entries: dict[str, Any] = {}
    for ax in axes:
        for handle, label in zip(*ax.get_legend_handles_labels(), strict=True):
            entries.setdefault(label, handle)
    fig.legend(list(entries.values()), list(entries), loc="lower center", ncol=3, fontsize=7, frameon=False)


def _wave_figure(table: SweepTable, limit_N: float, path: Path) -> Path:
    wave = table.wave
    assert wave is not None
    omega = table.omega_rad_s
    order = np.argsort(omega)
    fig, axes = plt.subplots(3, 1, figsize=(8, 9.5), sharex=True)
    panels = (
        (axes[0], wave.saddle_force_rao_N_per_m / 1e6, wave.linear_saddle_force_rao_N_per_m / 1e6, "saddle force RAO [MN/m]"),
        (axes[1], wave.bending_moment_rao_Nm_per_m / 1e6, wave.linear_bending_moment_rao_Nm_per_m / 1e6, "bending moment RAO [MN m/m]"),
        (axes[2], table.max_saddle_force_N / 1e6, table.linear_max_saddle_force_N / 1e6, "max saddle force [MN]"),
    )
    lost = ~table.contact_preserved
    for ax, values, linear, label in panels:
        ax.plot(omega[order], linear[order], color="tab:blue", ls=":", lw=1.4, label="linear model (bilateral saddles)")
        _branch(ax, table, values)
        if np.any(lost):
            ax.plot(omega[lost], values[lost], ".", color="tab:red", ms=2, alpha=0.5, label="contact lost in the period")
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    axes[2].axhline(limit_N / 1e6, color="tab:green", ls="--", lw=1, label=f"design limit {limit_N / 1e6:g} MN")
    breaking = np.array([RangeLimit.WAVE_BREAKING in why for why in table.beyond_range])
    if np.any(breaking):  # a property of omega alone: shade it
        start = float(omega[breaking].min())
        for ax in axes:
            ax.axvspan(
                start,
                float(omega.max()),
                color="0.9",
                zorder=0,
                label=f"breaking waves (H / lambda > 1/{1 / table.limits.breaking_steepness:.0f})",
            )
    _legend(fig, axes)
    top = axes[0].secondary_xaxis("top", functions=(lambda w: 2 * np.pi / np.maximum(w, 1e-9), lambda T: 2 * np.pi / np.maximum(T, 1e-9)))
    periods = np.array([40, 30, 20, 15, 12, 10, 8, 7, 6, 5, 4, 3.5, 3, 2.5, 2])
    lo, hi = 2 * np.pi / omega.max(), 2 * np.pi / omega.min()
    top.set_xticks(periods[(periods >= lo) & (periods <= hi)])
    top.set_xlabel("wave period T [s]")
    amplitude = float(wave.wave_amplitude_m[0]) if wave.wave_amplitude_m.size else float("nan")
    axes[0].set_title(f"Response to regular head waves of amplitude {amplitude:g} m, per metre of wave amplitude (RAOs)", fontsize=10)
    axes[-1].set_xlabel("wave frequency omega [rad/s]")
    fig.tight_layout(rect=(0.0, 0.07, 1.0, 1.0))
    return _save(fig, path)


def _save(fig: plt.Figure, path: Path) -> Path:
    fig.savefig(path, dpi=DPI)
    plt.close(fig)
    return path


def write_sweep_outputs(result: SweepResult, out_dir: str | Path, *, plots: bool = True) -> list[Path]:
    """Write ``frequency_response.csv`` (and ``frequency_response.png`` with ``plots``) of a
    :class:`~seafast.analyses.sweep.frequency.SweepResult`; return their paths."""
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    paths = [write_csv(result.table, out / "frequency_response.csv")]
    if plots and result.table.omega_rad_s.size:
        png = out / "frequency_response.png"
        if result.table.wave is not None:
            paths.append(_wave_figure(result.table, float(result.case.limits.max_saddle_force_N), png))
        else:
            paths.append(_save(structural_figure(result.table, result.model, result.acceleration_limit_rad_s), png))
    return paths


def format_sweep_summary(result: SweepResult) -> list[str]:
    """Lines for people: how the branch ended, its folds and stability, the deck-acceleration limit, the peak RAO."""
    t, b = result.table, result.branch
    unstable = sum(v is Stability.UNSTABLE for v in t.stability)
    lines = [
        (
            f"{result.kind.value} sweep {result.omega_start_rad_s:g} -> {result.omega_end_rad_s:g} rad/s: {b.message}; "
            f"{t.omega_rad_s.size} points ({unstable} unstable, {int(np.count_nonzero(t.marginal))} marginal), "
            f"H = {b.options.get('harmonics')}, N = {b.options.get('time_samples')}"
        )
    ]
    confirmed = [c for c in t.folds if c.confirmed]
    if confirmed:
        lines.append(
            "folds at "
            + ", ".join(f"{t.omega_rad_s[c.index]:.6g}" for c in confirmed)
            + " rad/s (unstable between a pair); a multiplier there within "
            + ", ".join(f"{c.distance_to_one:.2g}" for c in confirmed)
            + " of +1: the stability tolerance"
        )
    zigzag = [c for c in t.folds if len(c.turns) > 1]
    if zigzag:
        lines.append(
            "the sampled contact makes the branch zigzag over the fold at "
            + ", ".join(f"{t.omega_rad_s[c.index]:.4g} ({len(c.turns)} turns)" for c in zigzag)
            + f" rad/s: more AFT samples (solver.time_samples, now {b.options.get('time_samples')}) resolve it"
        )
    few = t.too_few_harmonics
    if np.any(few):
        i = int(np.argmax(t.truncation_error))
        lines.append(
            f"{int(few.sum())} of {few.size} points leave more than {t.truncation_tolerance:g} of a peak saddle force to the "
            f"harmonics above H (worst {t.truncation_error[i]:.2g} at {t.omega_rad_s[i]:.4g} rad/s): too_few_harmonics=true"
        )
    lim = result.acceleration_limit_rad_s
    if lim is not None and lim < max(result.omega_start_rad_s, result.omega_end_rad_s):
        beyond = "the sweep stopped there" if result.stopped_beyond_range else "points beyond it are flagged valid=false"
        lines.append(
            f"the held deck motion accelerates the deck faster than g = {t.limits.gravity_m_per_s2:g} m/s^2 above "
            f"omega_g = {lim:.4g} rad/s: {beyond} (seafast sweep --wave: the waves of these frequencies)"
        )
    if t.wave is not None and np.any(t.valid):
        i = int(np.argmax(np.where(t.valid, t.wave.saddle_force_rao_N_per_m, -np.inf)))
        lines.append(
            f"largest saddle-force RAO in range: {t.wave.saddle_force_rao_N_per_m[i] / 1e6:.4g} MN/m nonlinear, "
            f"{t.wave.linear_saddle_force_rao_N_per_m[i] / 1e6:.4g} MN/m linear, at {t.omega_rad_s[i]:.4g} rad/s "
            f"(wave length {t.wave.wave_length_m[i]:.4g} m)"
        )
    return lines


def range_warning(result: SweepResult) -> str | None:
    """One sentence when points lie beyond the physically meaningful range (which limits, where), else None."""
    t = result.table
    out = ~t.valid
    if not np.any(out):
        return None
    reasons = sorted({r.value for rs in t.beyond_range for r in rs})
    w = t.omega_rad_s[out]
    return (
        f"{int(out.sum())} of {out.size} branch points, between {w.min():.4g} and {w.max():.4g} rad/s, lie beyond the "
        f"physically meaningful range ({', '.join(reasons)}; gap limit {t.limits.max_gap_m:g} m): flagged valid=false "
        "in frequency_response.csv, faded in the figure"
    )


def truncation_warning(result: SweepResult) -> str | None:
    """One sentence when points' truncation error exceeds the tolerance (how many, the worst, what to do), else None."""
    t = result.table
    few = t.too_few_harmonics
    if not np.any(few):
        return None
    i = int(np.argmax(t.truncation_error))
    w = t.omega_rad_s[few]
    H = result.branch.options.get("harmonics")
    return (
        f"{int(few.sum())} of {few.size} branch points, between {w.min():.4g} and {w.max():.4g} rad/s, have too few harmonics: "
        f"H = {H} leaves an estimated {t.truncation_error[i]:.2g} of a saddle's peak force out at {t.omega_rad_s[i]:.4g} rad/s "
        f"(tolerance solver.truncation_tolerance = {t.truncation_tolerance:g}); flagged too_few_harmonics=true in "
        "frequency_response.csv. The sweep runs at a fixed H: raise it (--set solver.harmonics=..., cost about H^3), "
        "or check single frequencies with seafast run (adaptive H)"
    )


def fold_warning(result: SweepResult) -> str | None:
    """One sentence when folds are not confirmed by the Floquet multipliers (no multiplier near +1), else None."""
    t = result.table
    unconfirmed = [c for c in t.folds if not c.confirmed]
    if not unconfirmed:
        return None
    where = ", ".join(
        f"{t.omega_rad_s[c.index]:.6g} rad/s (nearest multiplier {c.distance_to_one:.2g} from +1, truncation error "
        f"{t.truncation_error[c.index]:.2g})"
        for c in unconfirmed
    )
    return (
        f"the branch folds at {where} without a Floquet multiplier at +1, which a fold has: an artefact of the "
        f"discretisation (H = {result.branch.options.get('harmonics')}), not a jump of the response; raise solver.harmonics"
    )
