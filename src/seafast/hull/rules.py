"""Classification-rule values of the hull girder: the IACS UR S11 wave coefficient and wave bending moments."""

from __future__ import annotations

__all__ = ["iacs_wave_coefficient", "iacs_wave_bending_moments_Nm"]


def iacs_wave_coefficient(length_m: float) -> float:
    """IACS UR S11 wave coefficient C_w [-] (rule length L in m, 0 < L <= 500)."""
    L = float(length_m)
    if not (0 < L <= 500):
        raise ValueError(f"iacs_wave_coefficient: length_m = {L!r} outside (0, 500]")
    if L < 90:
        return 0.0792 * L
    if L <= 300:
        return 10.75 - ((300.0 - L) / 100.0) ** 1.5
    if L <= 350:
        return 10.75
    return 10.75 - ((L - 350.0) / 150.0) ** 1.5


def iacs_wave_bending_moments_Nm(length_m: float, breadth_m: float, block_coefficient: float) -> tuple[float, float]:
    """IACS UR S11 rule vertical wave bending moments amidships [N m].

    ``M_wh = +190 C_w L^2 B C_b 1e-3`` kN m (hogging) and
    ``M_ws = -110 C_w L^2 B (C_b + 0.7) 1e-3`` kN m (sagging), C_b not less than 0.6,
    C_w from :func:`iacs_wave_coefficient`. NOTE: returned in the IACS sign convention
    (hogging positive, sagging negative), which is the opposite of seafast's
    (sagging positive); compare magnitudes, or negate for seafast.

    Returns
    -------
    hogging_Nm, sagging_Nm
        (positive, negative) [N m].
    """
    L, B = float(length_m), float(breadth_m)
    cb = max(float(block_coefficient), 0.6)
    cw = iacs_wave_coefficient(L)
    hog_kNm = 190.0 * cw * L * L * B * cb * 1e-3
    sag_kNm = -110.0 * cw * L * L * B * (cb + 0.7) * 1e-3
    return hog_kNm * 1e3, sag_kNm * 1e3
