"""Design limits: which study points comply, and a ranking of the compliant arrangements.

A point complies with the limits when, in the ``dynamic`` load case (the total response), the
largest saddle force F <= F_max and the largest bending stress sigma_b <= sigma_max, and the point
was evaluated without error (and, for the nonlinear model, the solver converged). The decision is
made with the nonlinear model; the linear model's verdict is reported alongside.

Compliant arrangements are ranked by fewest saddles first, then by the larger margin, where the
margin is the smaller of the two relative margins ``1 - F / F_max`` and ``1 - sigma_b / sigma_max``.

Optional limits on the cargo on its cradles (:data:`CRADLE_LIMITS`: the largest pad force, lashing-wire
tension and lateral displacement at a saddle) are judged the same way where a point's cradles were solved
(off head seas): each one set adds its condition and its relative margin. Where no cradle was solved (head
seas: the columns NaN and ``cradle_converged`` unknown) they do not apply; where the cradle solve raised
(``cradle_converged`` false, the columns NaN) the point does not comply.
"""

from __future__ import annotations

import csv
import math
import os
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import xarray as xr

__all__ = [
    "DesignLimits",
    "CRADLE_LIMITS",
    "SADDLE_COUNT_KEY",
    "compliance",
    "compliance_rows",
    "rank_compliant",
    "format_table",
    "write_rows_csv",
    "COMPLIANCE_COLUMNS",
    "RANKING_COLUMNS",
]

SADDLE_COUNT_KEY = "seafastening.saddle_count"

CRADLE_LIMITS: tuple[tuple[str, str], ...] = (
    ("max_pad_force_N", "F_pad_N"),
    ("max_lashing_tension_N", "lashing_tension_max_N"),
    ("max_transverse_slip_m", "transverse_slip_m"),
)
"""Each optional cradle limit (:class:`DesignLimits` attribute, ``limits`` key of a study) and the study column it bounds."""


@dataclass(frozen=True)
class DesignLimits:
    """Design limits of the sea-fastening and cargo.

    Attributes
    ----------
    max_saddle_force_N : float
        Largest allowed saddle force F_max [N] (source: 7 MN).
    max_bending_stress_Pa : float
        Largest allowed cargo bending stress sigma_max [Pa] (source: 20 MPa, about 10 % of yield).
    max_pad_force_N, max_lashing_tension_N, max_transverse_slip_m : float or None
        Largest allowed cradle pad force [N], lashing-wire tension [N] and lateral displacement of the cargo at a
        saddle [m], judged off head seas (:data:`CRADLE_LIMITS`); None: not checked.
    """

    max_saddle_force_N: float = 7.0e6
    max_bending_stress_Pa: float = 20.0e6
    max_pad_force_N: float | None = None
    max_lashing_tension_N: float | None = None
    max_transverse_slip_m: float | None = None

    @staticmethod
    def from_attrs(attrs: Mapping[str, Any]) -> DesignLimits:
        """The limits recorded in a study dataset's attributes (defaults where absent, cradle limits None)."""
        cradle = {name: float(attrs[name]) for name, _ in CRADLE_LIMITS if name in attrs}
        return DesignLimits(float(attrs.get("max_saddle_force_N", 7.0e6)), float(attrs.get("max_bending_stress_Pa", 20.0e6)), **cradle)

    @staticmethod
    def from_spec(limits: Any) -> DesignLimits:
        """The limits of a study file's ``limits`` section (:class:`~seafast.studies.spec.LimitsSpec`)."""
        cradle = {name: getattr(limits, name) for name, _ in CRADLE_LIMITS}
        return DesignLimits(limits.max_saddle_force_N, limits.max_bending_stress_Pa, **cradle)

    def cradle_limits(self) -> dict[str, float]:
        """The cradle limits that are set: study column -> its largest allowed value."""
        return {column: float(v) for name, column in CRADLE_LIMITS if (v := getattr(self, name)) is not None}


def _axis_keys(ds: xr.Dataset) -> list[str]:
    return [str(d) for d in ds["F_N"].dims if d not in ("load_case", "model")]


def _total_response(ds: xr.Dataset) -> xr.Dataset:
    if "load_case" not in ds.dims:
        return ds
    labels = [str(v) for v in ds["load_case"].values]
    return ds.sel(load_case="dynamic" if "dynamic" in labels else labels[-1])


def compliance(ds: xr.Dataset, limits: DesignLimits | None = None) -> xr.Dataset:
    """Compliance map of a study.

    Parameters
    ----------
    ds : xarray.Dataset
        Study results (:func:`seafast.studies.runner.assemble_dataset`).
    limits : DesignLimits, optional
        Default: the limits recorded in ``ds.attrs``.

    Returns
    -------
    xarray.Dataset
        Over the study dimensions and ``model``: ``F_N`` [N] and ``sigma_b_Pa`` [Pa] of the total
        (dynamic) response, ``margin_force``, ``margin_stress`` and ``margin`` [-] (relative; the
        smaller of the two, NaN where unknown), ``complies`` (bool), ``converged`` and
        ``contact_preserved`` (bool).
    """
    limits = limits or DesignLimits.from_attrs(ds.attrs)
    total = _total_response(ds)
    force, stress = total["F_N"], total["sigma_b_Pa"]
    margin_force = 1.0 - force / limits.max_saddle_force_N
    margin_stress = 1.0 - stress / limits.max_bending_stress_Pa
    margin = xr.where(margin_force < margin_stress, margin_force, margin_stress)
    margin = margin.where(np.isfinite(margin_force) & np.isfinite(margin_stress))
    evaluated = ds["error"] == "" if "error" in ds else xr.ones_like(force, dtype=bool)
    converged = total["converged"].astype(bool) if "converged" in total else xr.ones_like(force, dtype=bool)
    solved = converged | (total["model"] != "nonlinear")
    within = (force <= limits.max_saddle_force_N) & (stress <= limits.max_bending_stress_Pa)
    cradle_margins = _cradle_margins(total, limits)
    for column, cradle_margin in cradle_margins.items():
        within = within & _cradle_within(total, column, cradle_margin)
        margin = xr.where(cradle_margin < margin, cradle_margin, margin)  # NaN (no cradle solved): not a margin
    complies = within & evaluated & solved
    contact = total["contact_preserved"].astype(bool) if "contact_preserved" in total else xr.zeros_like(force, dtype=bool)
    out = xr.Dataset(
        {
            "F_N": force.assign_attrs(units="N", long_name="maximum saddle force, total (dynamic) response"),
            "sigma_b_Pa": stress.assign_attrs(units="Pa", long_name="maximum bending stress, total (dynamic) response"),
            "margin_force": margin_force.assign_attrs(units="1", long_name="1 - F / F_max"),
            "margin_stress": margin_stress.assign_attrs(units="1", long_name="1 - sigma_b / sigma_max"),
            "margin": margin.assign_attrs(units="1", long_name="smaller relative margin"),
            "complies": complies.assign_attrs(units="1", long_name="F <= F_max and sigma_b <= sigma_max"),
            "converged": converged.assign_attrs(units="1", long_name="solver converged"),
            "contact_preserved": contact.assign_attrs(units="1", long_name="contact preserved at every saddle"),
            **{f"margin_{c}": m.assign_attrs(units="1", long_name=f"1 - {c} / its limit") for c, m in cradle_margins.items()},
        }
    )
    out.attrs.update(
        study=ds.attrs.get("study", ""),
        max_saddle_force_N=limits.max_saddle_force_N,
        max_bending_stress_Pa=limits.max_bending_stress_Pa,
        **{name: getattr(limits, name) for name, _ in CRADLE_LIMITS if getattr(limits, name) is not None},
    )
    if "saddle_count" in ds.attrs:
        out.attrs["saddle_count"] = ds.attrs["saddle_count"]
    return out.drop_vars("load_case", errors="ignore")


def _cradle_margins(total: xr.Dataset, limits: DesignLimits) -> dict[str, xr.DataArray]:
    """``1 - value / limit`` of each cradle limit set whose column the study holds (NaN where no cradle was solved)."""
    return {column: 1.0 - total[column] / limit for column, limit in limits.cradle_limits().items() if column in total}


def _cradle_within(total: xr.Dataset, column: str, cradle_margin: xr.DataArray) -> xr.DataArray:
    """Within the column's limit; where it is NaN, only if no cradle was solved (head seas), not if the solve raised."""
    solved = total["cradle_converged"] if "cradle_converged" in total else xr.full_like(cradle_margin, np.nan)
    return (cradle_margin >= 0.0) | (np.isnan(total[column]) & np.isnan(solved))


COMPLIANCE_COLUMNS: tuple[str, ...] = (
    "F_linear_N",
    "sigma_b_linear_Pa",
    "complies_linear",
    "F_nonlinear_N",
    "sigma_b_nonlinear_Pa",
    "margin_nonlinear",
    "complies_nonlinear",
    "contact_preserved",
    "converged",
    "error",
)
RANKING_COLUMNS: tuple[str, ...] = (
    "rank",
    "saddle_count",
    "F_N",
    "sigma_b_Pa",
    "margin_force",
    "margin_stress",
    "margin",
    "contact_preserved",
)


def _scalar(value: Any) -> Any:
    item = value.item() if hasattr(value, "item") else value
    return item


def compliance_rows(ds: xr.Dataset, limits: DesignLimits | None = None) -> list[dict[str, Any]]:
    """One row per study point: the study's keys, each model's F, sigma_b and verdict.

    Columns: the study's dotted keys, then :data:`COMPLIANCE_COLUMNS` (``contact_preserved`` and
    ``converged`` refer to the nonlinear model).
    """
    comp = compliance(ds, limits)
    keys = _axis_keys(ds)
    shape = tuple(ds.sizes[k] for k in keys)
    models = [str(m) for m in comp["model"].values]
    rows = []
    for multi in np.ndindex(*shape):
        at = dict(zip(keys, multi, strict=True))
        point = comp.isel(at)
        row: dict[str, Any] = {k: _scalar(ds[k].values[i]) for k, i in zip(keys, multi, strict=True)}
        for model in ("linear", "nonlinear"):
            if model not in models:
                continue
            p = point.sel(model=model)
            row[f"F_{model}_N"] = float(p["F_N"])
            row[f"sigma_b_{model}_Pa"] = float(p["sigma_b_Pa"])
            if model == "nonlinear":
                row["margin_nonlinear"] = float(p["margin"])
            row[f"complies_{model}"] = bool(p["complies"])
        nonlinear = point.sel(model="nonlinear" if "nonlinear" in models else models[-1])
        row["contact_preserved"] = bool(nonlinear["contact_preserved"])
        row["converged"] = bool(nonlinear["converged"])
        row["error"] = str(ds["error"].isel(at).item()) if "error" in ds else ""
        rows.append(row)
    return rows


def rank_compliant(ds: xr.Dataset, limits: DesignLimits | None = None, model: str = "nonlinear") -> list[dict[str, Any]]:
    """The compliant arrangements, best first.

    Parameters
    ----------
    ds : xarray.Dataset
        Study results.
    limits : DesignLimits, optional
        Default: the limits recorded in ``ds.attrs``.
    model : str
        Model whose verdict decides (default ``nonlinear``).

    Returns
    -------
    list of dict
        Compliant points sorted by saddle count (fewest first), then margin (largest first), then
        the study keys; keys ``rank``, ``saddle_count``, the study's dotted keys, ``F_N`` [N],
        ``sigma_b_Pa`` [Pa], ``margin_force``, ``margin_stress``, ``margin`` [-],
        ``contact_preserved``.
    """
    comp = compliance(ds, limits).sel(model=model)
    keys = _axis_keys(ds)
    shape = tuple(ds.sizes[k] for k in keys)
    fixed_count = comp.attrs.get("saddle_count")
    candidates = []
    complies = comp["complies"].values
    for multi in np.ndindex(*shape):
        if not complies[multi]:
            continue
        values = {k: _scalar(ds[k].values[i]) for k, i in zip(keys, multi, strict=True)}
        count = values.get(SADDLE_COUNT_KEY, fixed_count)
        row: dict[str, Any] = {"saddle_count": int(count) if count is not None else None, **values}
        for name in ("F_N", "sigma_b_Pa", "margin_force", "margin_stress", "margin"):
            row[name] = float(comp[name].values[multi])
        row["contact_preserved"] = bool(comp["contact_preserved"].values[multi])
        candidates.append(row)
    candidates.sort(
        key=lambda r: (
            r["saddle_count"] if r["saddle_count"] is not None else math.inf,
            -r["margin"] if math.isfinite(r["margin"]) else math.inf,
            tuple(r[k] for k in keys),
        )
    )
    ranked = []
    for rank, row in enumerate(candidates, start=1):
        ordered = {"rank": rank, "saddle_count": row["saddle_count"]}
        ordered.update({k: row[k] for k in keys if k != SADDLE_COUNT_KEY})
        ordered.update({k: row[k] for k in RANKING_COLUMNS[2:]})
        ranked.append(ordered)
    return ranked


def _cell(value: Any) -> str:
    if isinstance(value, bool) or isinstance(value, np.bool_):
        return "yes" if value else "no"
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    if isinstance(value, (float, np.floating)):
        if math.isnan(value):
            return "-"
        return f"{value:.4g}"
    if value is None:
        return "-"
    return str(value)


def format_table(rows: Sequence[Mapping[str, Any]], columns: Sequence[str] | None = None, max_rows: int | None = None) -> str:
    """A fixed-width text table (numbers to 4 significant digits, booleans yes/no).

    Parameters
    ----------
    rows : sequence of mapping
        Table rows.
    columns : sequence of str, optional
        Columns to show (default: the keys of the first row).
    max_rows : int, optional
        Show at most this many rows, then a line saying how many were left out.
    """
    if not rows:
        return "(none)"
    cols = list(columns or rows[0].keys())
    shown = list(rows if max_rows is None else rows[:max_rows])
    cells = [[_cell(r.get(c)) for c in cols] for r in shown]
    widths = [max(len(c), *(len(row[i]) for row in cells)) for i, c in enumerate(cols)]
    numeric = [all(_is_number(r.get(c)) for r in shown) for c in cols]
    lines = ["  ".join(c.rjust(w) if num else c.ljust(w) for c, w, num in zip(cols, widths, numeric, strict=True)).rstrip()]
    lines.append("  ".join("-" * w for w in widths))
    for row in cells:
        lines.append("  ".join(v.rjust(w) if num else v.ljust(w) for v, w, num in zip(row, widths, numeric, strict=True)).rstrip())
    if max_rows is not None and len(rows) > max_rows:
        lines.append(f"... {len(rows) - max_rows} more rows")
    return "\n".join(lines)


def _is_number(value: Any) -> bool:
    return isinstance(value, (int, float, np.integer, np.floating)) and not isinstance(value, (bool, np.bool_))


def write_rows_csv(path: str | Path, rows: Iterable[Mapping[str, Any]], columns: Sequence[str]) -> Path:
    """Write rows to a CSV file atomically; returns its path.

    NaN and None are empty cells, booleans ``true``/``false`` (as ``summary.csv``).
    """
    path = Path(path)
    tmp = path.with_name(path.name + ".tmp")
    with open(tmp, "w", newline="", encoding="utf-8") as fh:
        writer = csv.writer(fh, lineterminator="\n")
        writer.writerow(columns)
        for row in rows:
            out = []
            for c in columns:
                v = row.get(c)
                if v is None or (isinstance(v, float) and math.isnan(v)):
                    out.append("")
                elif isinstance(v, (bool, np.bool_)):
                    out.append("true" if v else "false")
                elif isinstance(v, float):
                    out.append(repr(v))
                else:
                    out.append(v)
            writer.writerow(out)
    os.replace(tmp, path)
    return path
