"""A wave scatter diagram and the share of its sea states in which the transport stays within the limits.

The scatter diagram is a CSV file with the columns ``significant_height_m,peak_period_s,occurrence``
(one row per Hs x Tp cell; the occurrence in any unit - counts, per mille, probability - is
normalised by its sum). A cell is within the limits when its Hs is at most the allowable Hs at
its Tp (:mod:`seafast.analyses.operability.allowable`, evaluated at the diagram's own peak periods, so no
interpolation between peak periods); the share is the occurrence-weighted fraction of such cells,
linear and nonlinear. A cell whose nonlinear search failed counts as not within the limits and
is reported.
"""

from __future__ import annotations

import csv
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import ArrayLike, NDArray

from seafast.config.loader import CaseError

__all__ = ["SCATTER_COLUMNS", "ScatterDiagram", "ScatterAssessment", "read_scatter_diagram", "assess_scatter"]

SCATTER_COLUMNS = ("significant_height_m", "peak_period_s", "occurrence")
"""Columns of a scatter-diagram file."""


@dataclass(frozen=True)
class ScatterDiagram:
    """Sea-state occurrences.

    Attributes
    ----------
    significant_height_m, peak_period_s
        (n,) the cells' Hs [m] and Tp [s].
    occurrence
        (n,) occurrence, normalised to sum 1 [-].
    source
        Where it came from (file name).
    """

    significant_height_m: NDArray[np.float64]
    peak_period_s: NDArray[np.float64]
    occurrence: NDArray[np.float64]
    source: str

    @property
    def peak_periods_s(self) -> NDArray[np.float64]:
        """The distinct peak periods of the cells with a nonzero occurrence, ascending [s]."""
        return np.unique(self.peak_period_s[self.occurrence > 0])


def read_scatter_diagram(path: str | Path, option: str = "--scatter") -> ScatterDiagram:
    """Read a scatter diagram (CSV ``significant_height_m,peak_period_s,occurrence``).

    Raises
    ------
    CaseError
        Unreadable file, wrong columns, non-numeric or negative values, no occurrence at all;
        the message names the option, the file, the line and what is allowed.
    """
    p = Path(path)
    try:
        lines = [ln for ln in p.read_text(encoding="utf-8").splitlines() if ln.strip() and not ln.lstrip().startswith("#")]
    except (OSError, UnicodeDecodeError) as exc:
        raise CaseError(
            f"{option} '{p}': cannot read it ({getattr(exc, 'strerror', None) or exc}); allowed: a CSV file with "
            f"columns {','.join(SCATTER_COLUMNS)}"
        ) from None
    rows = list(csv.reader(lines))
    header = [h.strip() for h in rows[0]] if rows else []
    if any(c not in header for c in SCATTER_COLUMNS):
        raise CaseError(f"{option} '{p}': expected columns {','.join(SCATTER_COLUMNS)}; header is {header}")
    idx = [header.index(c) for c in SCATTER_COLUMNS]
    values = []
    for i, r in enumerate(rows[1:], start=2):
        try:
            hs, tp, occ = (float(r[j]) for j in idx)
        except (ValueError, IndexError):
            raise CaseError(f"{option} '{p}', line {i}: values must be numbers") from None
        if not all(math.isfinite(v) for v in (hs, tp, occ)) or hs <= 0 or tp <= 0 or occ < 0:
            raise CaseError(
                f"{option} '{p}', line {i}: significant_height_m = {hs}, peak_period_s = {tp}, occurrence = {occ}; "
                "allowed: Hs > 0, Tp > 0, occurrence >= 0"
            )
        values.append((hs, tp, occ))
    a = np.array(values, dtype=float).reshape(-1, 3)
    total = float(a[:, 2].sum()) if a.size else 0.0
    if not total > 0:
        raise CaseError(f"{option} '{p}': no sea state has a nonzero occurrence")
    return ScatterDiagram(a[:, 0], a[:, 1], a[:, 2] / total, p.name)


@dataclass(frozen=True)
class ScatterAssessment:
    """Which cells of a scatter diagram are within the limits.

    Attributes
    ----------
    diagram
        The diagram.
    within_linear, within_nonlinear
        (n,) per cell.
    not_assessed
        (n,) cells whose nonlinear search failed (counted as not within).
    share_within_linear, share_within_nonlinear
        Occurrence-weighted share of the cells within the limits [-].
    """

    diagram: ScatterDiagram
    within_linear: NDArray[np.bool_]
    within_nonlinear: NDArray[np.bool_]
    not_assessed: NDArray[np.bool_]
    share_within_linear: float
    share_within_nonlinear: float


def assess_scatter(
    diagram: ScatterDiagram, peak_periods_s: ArrayLike, hs_linear_m: ArrayLike, hs_nonlinear_m: ArrayLike
) -> ScatterAssessment:
    """Cells within the limits, from the allowable Hs at the diagram's peak periods.

    Parameters
    ----------
    diagram
        The scatter diagram.
    peak_periods_s, hs_linear_m, hs_nonlinear_m
        Allowable Hs [m] per peak period [s] (every Tp of a cell with nonzero occurrence must be present).
    """
    tp = np.asarray(peak_periods_s, dtype=float)
    hs_lin, hs_nl = np.asarray(hs_linear_m, dtype=float), np.asarray(hs_nonlinear_m, dtype=float)
    lin = np.full(diagram.occurrence.size, -np.inf)
    nl = np.full(diagram.occurrence.size, -np.inf)
    for i, t in enumerate(diagram.peak_period_s):
        j = np.flatnonzero(np.isclose(tp, t, rtol=0, atol=1e-9))
        if j.size:
            lin[i], nl[i] = hs_lin[j[0]], hs_nl[j[0]]
        elif diagram.occurrence[i] > 0:
            raise ValueError(f"assess_scatter: no allowable Hs at Tp = {t} s")
    not_assessed = np.isnan(nl) & (diagram.occurrence > 0)
    hs = diagram.significant_height_m
    within_lin = hs <= lin
    within_nl = np.where(np.isnan(nl), False, hs <= np.nan_to_num(nl, nan=-np.inf))
    w = diagram.occurrence
    return ScatterAssessment(diagram, within_lin, within_nl, not_assessed, float(np.sum(w[within_lin])), float(np.sum(w[within_nl])))
