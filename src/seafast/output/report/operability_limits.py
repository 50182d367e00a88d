"""The limits of an operability report (``seafast report DIR`` of a ``seafast operability`` directory): their text,
what each governing value means, and where the cradles govern; shared by the single-heading and the per-heading
sections."""

from __future__ import annotations

import math

import numpy as np
import xarray as xr

from seafast.output.report.common import Finding

__all__ = ["GOVERNING_TEXT", "limits_html", "cradle_governing_finding"]

GOVERNING_TEXT = {
    "saddle_force": "the saddle force (limits.max_saddle_force_N)",
    "bending_stress": "the cargo's bending stress (limits.max_bending_stress_Pa)",
    "pad_force": "the cradles' pad force (limits.max_pad_force_N)",
    "lashing_tension": "the lashing-wire tension (limits.max_lashing_tension_N)",
    "transverse_slip": "the cargo's lateral displacement at a saddle (limits.max_transverse_slip_m)",
    "steepness": "no limit below the steepest sea state (DNV-RP-C205)",
}
"""What each value of the governing columns means (the limit reached first)."""
_CRADLE_GOVERNING = ("pad_force", "lashing_tension", "transverse_slip")


def limits_html(ds: xr.Dataset) -> str:
    """``Limits: ...`` of an operability.nc: the vertical plane's, and each cradle limit set (judged off head seas)."""
    a = ds.attrs
    f_max, s_max = float(a.get("max_saddle_force_N", math.nan)), float(a.get("max_bending_stress_Pa", math.nan))
    text = f"Limits: saddle force F &le; {f_max / 1e6:g} MN, bending stress &sigma;<sub>b</sub> &le; {s_max / 1e6:g} MPa"
    cradle = [
        f"{label} &le; {float(a[key]) * scale:g} {unit}"
        for key, label, unit, scale in (
            ("max_pad_force_N", "pad force", "MN", 1e-6),
            ("max_lashing_tension_N", "lashing tension", "kN", 1e-3),
            ("max_transverse_slip_m", "transverse slip", "mm", 1e3),
        )
        if key in a
    ]
    if cradle:
        text += "; on the cradles, judged off head seas: " + ", ".join(cradle)
    return text


def cradle_governing_finding(governing: np.ndarray, where: list[str], model: str) -> Finding | None:
    """A NOTE naming the cradle limits that govern (``governing``: the ``model``'s governing values, ``where``: a label
    each), or None."""
    hits = [(str(g), w) for g, w in zip(governing.ravel(), where, strict=True) if str(g) in _CRADLE_GOVERNING]
    if not hits:
        return None
    names = sorted({g for g, _ in hits}, key=_CRADLE_GOVERNING.index)
    return Finding(
        "NOTE",
        f"{model}: the cradles govern ({', '.join(names)}) at {len(hits)} point(s): {', '.join(w for _, w in hits[:12])}"
        + (" ..." if len(hits) > 12 else ""),
        "; ".join(f"{n}: {GOVERNING_TEXT[n]}" for n in names) + ". Off head seas the cargo stands on its cradles (docs/transverse.md).",
    )
