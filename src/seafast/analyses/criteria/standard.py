"""The standard's default motion criteria for sea transport, by vessel or barge size (docs/criteria.md).

GL Noble Denton 0030/ND, *Guidelines for marine transportations*, section 7.9, Table 7-2 (default motion
criteria), for a transport whose motions are not computed: single-amplitude roll and pitch over a full-cycle
period, with a heave acceleration, for a barge of the size's class. Two rows are carried, those seafast could
verify in quotations of the table: large barges (length > 76 m and breadth > 23 m: roll 20 deg, pitch
12.5 deg, 10 s, 0.2 g; the table's case 2) and small barges (roll 25 deg, pitch 15 deg, 10 s, 0.2 g). The
table's further rows (e.g. for ships) were not verified and are not carried.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from enum import StrEnum

__all__ = [
    "SizeClass",
    "MotionCriteria",
    "SMALL_BARGE",
    "LARGE_BARGE",
    "LARGE_BARGE_MIN_LENGTH_M",
    "LARGE_BARGE_MIN_BREADTH_M",
    "select_motion_criteria",
]

LARGE_BARGE_MIN_LENGTH_M = 76.0
"""A large barge is longer than this [m] (0030/ND Table 7-2)."""

LARGE_BARGE_MIN_BREADTH_M = 23.0
"""... and broader than this [m]."""


class SizeClass(StrEnum):
    """The table's size class of the vessel or barge."""

    SMALL_BARGE = "small_barge"
    LARGE_BARGE = "large_barge"


@dataclass(frozen=True)
class MotionCriteria:
    """One row of the default motion criteria.

    Attributes
    ----------
    size_class
        The row.
    source
        The clause and table the values come from.
    roll_deg, pitch_deg
        Single-amplitude roll and pitch [deg].
    roll_period_s, pitch_period_s
        Their full-cycle periods [s].
    heave_acceleration_g
        Single-amplitude heave acceleration as a fraction of g [-].
    """

    size_class: SizeClass
    source: str
    roll_deg: float
    roll_period_s: float
    pitch_deg: float
    pitch_period_s: float
    heave_acceleration_g: float

    def roll_angular_acceleration_rad_s2(self) -> float:
        """Amplitude of the roll's angular acceleration, ``phi (2 pi / T)^2`` [rad/s^2]."""
        return math.radians(self.roll_deg) * (2.0 * math.pi / self.roll_period_s) ** 2

    def pitch_angular_acceleration_rad_s2(self) -> float:
        """Amplitude of the pitch's angular acceleration, ``theta (2 pi / T)^2`` [rad/s^2]."""
        return math.radians(self.pitch_deg) * (2.0 * math.pi / self.pitch_period_s) ** 2


_TABLE = "GL Noble Denton 0030/ND, section 7.9, Table 7-2 (default motion criteria)"

SMALL_BARGE = MotionCriteria(SizeClass.SMALL_BARGE, f"{_TABLE}, small barges", 25.0, 10.0, 15.0, 10.0, 0.2)
LARGE_BARGE = MotionCriteria(SizeClass.LARGE_BARGE, f"{_TABLE}, case 2, large barges (L > 76 m, B > 23 m)", 20.0, 10.0, 12.5, 10.0, 0.2)


def select_motion_criteria(length_m: float, breadth_m: float) -> MotionCriteria:
    """The row for a vessel of length ``length_m`` and breadth ``breadth_m`` [m].

    Large barges are longer than 76 m *and* broader than 23 m; any other size takes the small barges'
    (larger) motions.
    """
    if not (math.isfinite(length_m) and length_m > 0 and math.isfinite(breadth_m) and breadth_m > 0):
        raise ValueError(f"vessel length {length_m!r} m, breadth {breadth_m!r} m: allowed finite values > 0")
    if length_m > LARGE_BARGE_MIN_LENGTH_M and breadth_m > LARGE_BARGE_MIN_BREADTH_M:
        return LARGE_BARGE
    return SMALL_BARGE
