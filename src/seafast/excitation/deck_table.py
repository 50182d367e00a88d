"""User-supplied deck deflection table (CSV): hull deflection from the user's own analysis.

Format (docs/interface.md#31-deck-deflection-table): columns ``x_m`` (along the ship from the aft perpendicular),
``still_water_m``, ``wave_amplitude_m``, ``wave_phase_rad``; deflection positive upward [m].
The wave-induced deflection is ``wave_amplitude_m * cos(omega t + wave_phase_rad)``, i.e. the
complex harmonic amplitude ``wave_amplitude_m * exp(i wave_phase_rad)``. Deck slopes come from a
cubic-spline interpolant (not-a-knot) of the tabulated values.
"""

from __future__ import annotations

import csv
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import NDArray
from scipy.interpolate import CubicSpline

__all__ = ["DeckDeflectionTable", "read_deck_deflection_table", "DECK_TABLE_COLUMNS"]

DECK_TABLE_COLUMNS = ("x_m", "still_water_m", "wave_amplitude_m", "wave_phase_rad")


@dataclass(frozen=True)
class DeckDeflectionTable:
    """Tabulated deck deflection along the ship.

    Attributes
    ----------
    x_m
        Stations from the aft perpendicular [m], strictly increasing.
    still_water_m
        Still-water deflection [m], positive upward.
    wave_complex_m
        Complex amplitude of the wave-induced deflection [m] (exp(+i omega t) convention).
    source
        File the table was read from.
    """

    x_m: NDArray[np.float64]
    still_water_m: NDArray[np.float64]
    wave_complex_m: NDArray[np.complex128]
    source: str = ""

    def __post_init__(self) -> None:
        if self.x_m.size < 2:
            raise ValueError(f"deck deflection table {self.source}: needs at least 2 rows, got {self.x_m.size}")
        if np.any(np.diff(self.x_m) <= 0):
            raise ValueError(f"deck deflection table {self.source}: x_m must be strictly increasing")

    def _spline(self, values: NDArray) -> CubicSpline | None:
        if self.x_m.size < 4:
            return None
        return CubicSpline(self.x_m, values, bc_type="not-a-knot")

    def still_water_at(self, x_m: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Still-water deflection [m] and slope [rad] at ship positions ``x_m``."""
        return self._eval(self.still_water_m, x_m)

    def wave_at(self, x_m: NDArray[np.float64]) -> tuple[NDArray[np.complex128], NDArray[np.complex128]]:
        """Complex wave-deflection amplitude [m] and slope amplitude [rad] at ``x_m``."""
        zr, sr = self._eval(self.wave_complex_m.real, x_m)
        zi, si = self._eval(self.wave_complex_m.imag, x_m)
        return zr + 1j * zi, sr + 1j * si

    def _eval(self, values: NDArray[np.float64], x_m: NDArray[np.float64]) -> tuple[NDArray, NDArray]:
        x = np.asarray(x_m, dtype=float)
        lo, hi = self.x_m[0], self.x_m[-1]
        if np.any(x < lo - 1e-9) or np.any(x > hi + 1e-9):
            raise ValueError(
                f"deck deflection table {self.source}: covers x = {lo} .. {hi} m, but deflection is needed at "
                f"x = {float(x.min()):.3f} .. {float(x.max()):.3f} m (the sea-fastening points); extend the table"
            )
        spline = self._spline(values)
        if spline is None:  # 2-3 rows: piecewise linear
            z = np.interp(x, self.x_m, values)
            slope = np.interp(x, 0.5 * (self.x_m[1:] + self.x_m[:-1]), np.diff(values) / np.diff(self.x_m))
            return z, slope
        return spline(x), spline(x, 1)


def read_deck_deflection_table(path: str | Path) -> DeckDeflectionTable:
    """Read and validate a deck deflection CSV.

    Raises
    ------
    ValueError
        Naming the file, row and column of any problem (missing/unknown columns, non-numeric
        or non-finite values, x not increasing).
    """
    p = Path(path)
    try:
        text = p.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise ValueError(f"vessel.deck_deflection_table = '{p}': cannot read it ({getattr(exc, 'strerror', exc)})") from None
    # keep each row's line number in the file so messages point at the right line
    numbered = [(n, line) for n, line in enumerate(text.splitlines(), start=1) if line.strip() and not line.lstrip().startswith("#")]
    rows = [(n, next(csv.reader([line]))) for n, line in numbered]
    if not rows:
        raise ValueError(f"vessel.deck_deflection_table = '{p}': the file is empty; expected columns {', '.join(DECK_TABLE_COLUMNS)}")
    header = [h.strip() for h in rows[0][1]]
    missing = [c for c in DECK_TABLE_COLUMNS if c not in header]
    if missing:
        raise ValueError(
            f"vessel.deck_deflection_table = '{p}': missing column(s) {missing}; header is {header}, "
            f"expected {', '.join(DECK_TABLE_COLUMNS)}"
        )
    col = {c: header.index(c) for c in DECK_TABLE_COLUMNS}
    data: dict[str, list[float]] = {c: [] for c in DECK_TABLE_COLUMNS}
    line_of_row: list[int] = []
    for i, row in rows[1:]:
        for c in DECK_TABLE_COLUMNS:
            try:
                v = float(row[col[c]])
            except (IndexError, ValueError):
                cell = row[col[c]] if col[c] < len(row) else "<missing>"
                raise ValueError(f"vessel.deck_deflection_table = '{p}', line {i}, column {c}: {cell!r} is not a number") from None
            if not math.isfinite(v):
                raise ValueError(f"vessel.deck_deflection_table = '{p}', line {i}, column {c}: {v} is not finite")
            data[c].append(v)
        line_of_row.append(i)
    x = np.array(data["x_m"])
    if x.size < 2:
        raise ValueError(f"vessel.deck_deflection_table = '{p}': needs at least 2 data rows, got {x.size}")
    if np.any(np.diff(x) <= 0):
        bad = line_of_row[int(np.argmax(np.diff(x) <= 0)) + 1]
        raise ValueError(f"vessel.deck_deflection_table = '{p}', line {bad}: x_m must be strictly increasing")
    amp = np.array(data["wave_amplitude_m"])
    phase = np.array(data["wave_phase_rad"])
    return DeckDeflectionTable(x, np.array(data["still_water_m"]), amp * np.exp(1j * phase), source=str(p))
