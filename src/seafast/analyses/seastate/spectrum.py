"""Wave spectra of a sea state and the frequency grid the sea-state analysis runs on.

Formulas (DNV-RP-C205, section 3.5.5; one-sided, angular frequency omega [rad/s], density
S [m^2 s/rad], ``omega_p = 2 pi / Tp``)::

    S_PM(omega) = 5/16 Hs^2 omega_p^4 omega^-5 exp(-5/4 (omega / omega_p)^-4)
    S_J(omega)  = C(gamma) S_PM(omega) gamma^r,   r = exp(-(omega - omega_p)^2 / (2 sigma^2 omega_p^2))

with sigma = 0.07 for omega <= omega_p and 0.09 above. ``int_0^inf S_PM = Hs^2 / 16`` exactly;
DNV's normalising factor ``A_gamma = 1 - 0.287 ln(gamma)`` is an approximation (about 1 %), so
seafast computes ``C(gamma)`` by quadrature so that ``Hs = 4 sqrt(m0)`` holds to round-off.
Pierson-Moskowitz is JONSWAP with gamma = 1. A spectrum table (CSV ``omega_rad_s,S_m2_s_per_rad``)
is interpolated linearly and is zero outside its rows.

Frequency grid: the transfer functions are honest from 0 (long-wave limits) up to
:data:`OMEGA_MAX_RAD_S`; the grid spans the part of that band that holds the spectrum (from its
1e-5 to its 1 - 1e-4 variance quantile) with half its points uniform in omega (response
features anywhere) and half at equal-variance quantiles (the peak resolved). A sea state with
more than :data:`MAX_VARIANCE_OUTSIDE` of its variance outside ``[OMEGA_MIN_RAD_S,
OMEGA_MAX_RAD_S]`` is refused (:class:`~seafast.config.CaseError`).
"""

from __future__ import annotations

import csv
import functools
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.integrate import quad
from scipy.optimize import brentq

from seafast.config.loader import CaseError
from seafast.config.schema import Case

__all__ = [
    "WaveSpectrum",
    "OMEGA_MIN_RAD_S",
    "OMEGA_MAX_RAD_S",
    "MAX_VARIANCE_OUTSIDE",
    "DEFAULT_GRID_POINTS",
    "pierson_moskowitz_density",
    "jonswap_density",
    "jonswap_normalisation",
    "shortest_peak_period_s",
    "read_spectrum_table",
    "sea_state_spectrum",
    "spectrum_grid",
]

OMEGA_MIN_RAD_S = 0.05
"""Lowest grid frequency [rad/s] (a 25 km, 126 s wave): below it no sea holds energy."""

OMEGA_MAX_RAD_S = 4.0
"""Highest grid frequency [rad/s] (a 3.9 m wave). Above the BEM grid (1.8 rad/s) the motions are
extrapolated to zero and the hull girder hardly bends; 4 rad/s keeps about eight hull-girder
nodes per wave length (0.5 m elements)."""

MAX_VARIANCE_OUTSIDE = 0.01
"""Largest share of a sea state's variance allowed outside the grid band."""

DEFAULT_GRID_POINTS = 256
"""Grid points per sea state (half uniform, half equal-variance)."""

_SIGMA_LOW, _SIGMA_HIGH = 0.07, 0.09


def pierson_moskowitz_density(omega_rad_s: ArrayLike, significant_height_m: float, peak_period_s: float) -> NDArray[np.float64]:
    """Pierson-Moskowitz spectral density S(omega) [m^2 s/rad] (DNV-RP-C205 3.5.5.1), one-sided."""
    w = np.asarray(omega_rad_s, dtype=float)
    wp = 2.0 * math.pi / peak_period_s
    out = np.zeros_like(w)
    pos = w > 0
    u = w[pos] / wp
    out[pos] = 5.0 / 16.0 * significant_height_m**2 / wp * u**-5 * np.exp(-1.25 * u**-4)
    return out


def _peak_factor(u: NDArray[np.float64], gamma: float) -> NDArray[np.float64]:
    sigma = np.where(u <= 1.0, _SIGMA_LOW, _SIGMA_HIGH)
    return gamma ** np.exp(-((u - 1.0) ** 2) / (2.0 * sigma**2))


def _shape(u: float, gamma: float) -> float:
    """JONSWAP density with C = 1 per (Hs^2 / omega_p) at u = omega / omega_p (for quadrature)."""
    return 5.0 / 16.0 * u**-5 * math.exp(-1.25 * u**-4) * float(_peak_factor(np.array(u), gamma))


@functools.lru_cache(maxsize=64)
def jonswap_normalisation(gamma: float) -> float:
    """C(gamma) with ``int_0^inf S_J = Hs^2 / 16`` [-] (1 at gamma = 1; DNV's approximation 1 - 0.287 ln gamma)."""
    if gamma == 1.0:
        return 1.0
    pieces = ((0.2, 0.8), (0.8, 1.0), (1.0, 1.3), (1.3, 3.0), (3.0, np.inf))
    total = sum(quad(_shape, a, b, args=(gamma,), limit=200, epsabs=0, epsrel=1e-12)[0] for a, b in pieces)
    return (1.0 / 16.0) / total


def jonswap_density(
    omega_rad_s: ArrayLike, significant_height_m: float, peak_period_s: float, peak_enhancement: float = 3.3
) -> NDArray[np.float64]:
    """JONSWAP spectral density S(omega) [m^2 s/rad] (DNV-RP-C205 3.5.5.2), normalised to Hs = 4 sqrt(m0)."""
    w = np.asarray(omega_rad_s, dtype=float)
    pm = pierson_moskowitz_density(w, significant_height_m, peak_period_s)
    if peak_enhancement == 1.0:
        return pm
    u = w * peak_period_s / (2.0 * math.pi)
    return jonswap_normalisation(float(peak_enhancement)) * pm * _peak_factor(u, float(peak_enhancement))


@dataclass(frozen=True)
class WaveSpectrum:
    """A one-sided wave spectrum on the sea-state frequency grid.

    Attributes
    ----------
    omega_rad_s
        Grid frequencies [rad/s], shape (n_w,), strictly increasing.
    density_m2_s_per_rad
        Spectral density S(omega) [m^2 s/rad] at the grid, shape (n_w,).
    significant_height_m
        Hs = 4 sqrt(m0) of the spectrum over all frequencies [m] (the case's, or the table's).
    peak_period_s
        Tp = 2 pi / omega at the peak [s].
    variance_outside_grid_m2
        Variance of the spectrum outside the grid's band [m^2] (not integrated by the grid).
    description
        What the spectrum is (for outputs).
    """

    omega_rad_s: NDArray[np.float64]
    density_m2_s_per_rad: NDArray[np.float64]
    significant_height_m: float
    peak_period_s: float
    variance_outside_grid_m2: float
    description: str

    def moment(self, order: int) -> float:
        """Spectral moment ``m_n = int omega^n S d omega`` over the grid (trapezoid) [m^2 (rad/s)^n]."""
        return float(np.trapezoid(self.omega_rad_s**order * self.density_m2_s_per_rad, self.omega_rad_s))


def read_spectrum_table(path: str | Path, key: str = "sea_state.spectrum") -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Read a spectrum table (CSV ``omega_rad_s,S_m2_s_per_rad``); errors name ``key`` and the file.

    Raises
    ------
    CaseError
        Unreadable file, wrong columns, non-numeric, negative or non-increasing values.
    """
    p = Path(path)
    try:
        lines = [ln for ln in p.read_text(encoding="utf-8").splitlines() if ln.strip() and not ln.lstrip().startswith("#")]
    except (OSError, UnicodeDecodeError) as exc:
        raise CaseError(
            f"{key} = '{p}': cannot read it ({getattr(exc, 'strerror', None) or exc}); allowed: jonswap, "
            "pierson_moskowitz or a CSV file with columns omega_rad_s,S_m2_s_per_rad"
        ) from None
    rows = list(csv.reader(lines))
    header = [h.strip() for h in rows[0]] if rows else []
    columns = ("omega_rad_s", "S_m2_s_per_rad")
    if any(c not in header for c in columns):
        raise CaseError(f"{key} = '{p}': expected columns omega_rad_s,S_m2_s_per_rad; header is {header}")
    idx = [header.index(c) for c in columns]
    values = []
    for i, r in enumerate(rows[1:], start=2):
        try:
            w, s = (float(r[j]) for j in idx)
        except (ValueError, IndexError):
            raise CaseError(f"{key} = '{p}', line {i}: values must be numbers") from None
        if not (math.isfinite(w) and math.isfinite(s)) or w < 0 or s < 0:
            raise CaseError(f"{key} = '{p}', line {i}: omega_rad_s = {w}, S_m2_s_per_rad = {s}; both must be finite and >= 0")
        values.append((w, s))
    a = np.array(values, dtype=float).reshape(-1, 2)
    if a.shape[0] < 3 or np.any(np.diff(a[:, 0]) <= 0):
        raise CaseError(f"{key} = '{p}': needs at least 3 rows with omega_rad_s strictly increasing")
    if not np.any(a[:, 1] > 0):
        raise CaseError(f"{key} = '{p}': S_m2_s_per_rad is zero everywhere; the sea state has no waves")
    return a[:, 0], a[:, 1]


def _quantile_points(omega: NDArray[np.float64], cumulative: NDArray[np.float64], levels: NDArray[np.float64]) -> NDArray[np.float64]:
    return np.interp(levels, cumulative, omega)


def spectrum_grid(
    reference_omega_rad_s: NDArray[np.float64], reference_density: NDArray[np.float64], n_points: int = DEFAULT_GRID_POINTS
) -> NDArray[np.float64]:
    """Sea-state grid [rad/s] from a finely sampled spectrum: half uniform, half equal-variance points.

    The band runs from the spectrum's 1e-5 to its 1 - 1e-4 variance quantile, clipped to
    ``[OMEGA_MIN_RAD_S, OMEGA_MAX_RAD_S]``.
    """
    w, s = reference_omega_rad_s, reference_density
    cum = np.concatenate([[0.0], np.cumsum(0.5 * (s[1:] + s[:-1]) * np.diff(w))])
    cum = cum / cum[-1]
    lo = max(float(_quantile_points(w, cum, np.array([1e-5]))[0]), OMEGA_MIN_RAD_S)
    hi = min(float(_quantile_points(w, cum, np.array([1.0 - 1e-4]))[0]), OMEGA_MAX_RAD_S)
    n_uniform = n_points - n_points // 2
    uniform = np.linspace(lo, hi, n_uniform)
    inner = (np.arange(n_points // 2) + 0.5) / (n_points // 2)
    equal = _quantile_points(w, cum, inner)
    grid = np.unique(np.concatenate([uniform, equal[(equal > lo) & (equal < hi)]]))
    # drop near-duplicates (a quantile landing on a uniform point)
    keep = np.concatenate([[True], np.diff(grid) > 1e-9 * hi])
    return grid[keep]


def _refuse(key: str, value: object, share: float, where: str, allowed: str) -> CaseError:
    return CaseError(
        f"{key} = {value!r}: {share:.1%} of the spectrum's variance lies {where}, beyond the frequencies seafast's "
        f"transfer functions resolve ({OMEGA_MIN_RAD_S:g} to {OMEGA_MAX_RAD_S:g} rad/s; at most {MAX_VARIANCE_OUTSIDE:.0%} "
        f"allowed outside); allowed: {allowed}"
    )


def _parametric_share_above(u_cap: float, gamma: float) -> float:
    """Share of a JONSWAP/PM spectrum's variance above omega = u_cap omega_p."""
    pieces = ((u_cap, 1.3), (1.3, np.inf)) if u_cap < 1.3 else ((u_cap, np.inf),)
    return 16.0 * jonswap_normalisation(gamma) * sum(quad(_shape, a, b, args=(gamma,), limit=200)[0] for a, b in pieces)


def _parametric_share_below(u_floor: float, gamma: float) -> float:
    """Share of a JONSWAP/PM spectrum's variance below omega = u_floor omega_p (0 below u = 1e-3)."""
    if u_floor <= 1e-3:
        return 0.0
    return 16.0 * jonswap_normalisation(gamma) * quad(_shape, 1e-3, u_floor, args=(gamma,), limit=200)[0]


def shortest_peak_period_s(gamma: float) -> float:
    """Shortest peak period [s] whose JONSWAP spectrum the transfer functions resolve.

    At it :data:`MAX_VARIANCE_OUTSIDE` of the variance lies above :data:`OMEGA_MAX_RAD_S`
    (4.72 s for ``gamma`` = 3.3, 5.25 s for Pierson-Moskowitz, ``gamma`` = 1); independent of Hs.
    """
    return 2.0 * math.pi / OMEGA_MAX_RAD_S * brentq(lambda u: _parametric_share_above(u, gamma) - MAX_VARIANCE_OUTSIDE, 1.01, 100.0)


def sea_state_spectrum(case: Case, n_points: int = DEFAULT_GRID_POINTS) -> WaveSpectrum:
    """The case's wave spectrum on its sea-state grid (one-sided, Hs = 4 sqrt(m0)).

    Raises
    ------
    CaseError
        Missing Hs/Tp for a parametric spectrum, an unreadable table, or a sea state with more
        than :data:`MAX_VARIANCE_OUTSIDE` of its variance outside the resolved band (the
        message names the key, the value and the allowed range).
    """
    ss = case.sea_state
    if ss.spectrum in ("jonswap", "pierson_moskowitz"):
        if ss.significant_height_m is None or ss.peak_period_s is None:
            key = "significant_height_m" if ss.significant_height_m is None else "peak_period_s"
            raise CaseError(f"sea_state.{key} = null: required for the {ss.spectrum} spectrum; give a value > 0")
        hs, tp = float(ss.significant_height_m), float(ss.peak_period_s)
        gamma = 1.0 if ss.spectrum == "pierson_moskowitz" else float(ss.peak_enhancement)
        wp = 2.0 * math.pi / tp
        above = _parametric_share_above(OMEGA_MAX_RAD_S / wp, gamma)
        if above > MAX_VARIANCE_OUTSIDE:
            tp_min = shortest_peak_period_s(gamma)
            raise _refuse(
                "sea_state.peak_period_s",
                tp,
                above,
                f"above {OMEGA_MAX_RAD_S:g} rad/s (waves shorter than "
                f"{2 * math.pi * case.model.gravity_m_per_s2 / OMEGA_MAX_RAD_S**2:.1f} m)",
                f"peak_period_s >= {tp_min:.2f} s for this spectrum",
            )
        below = _parametric_share_below(OMEGA_MIN_RAD_S / wp, gamma)
        if below > MAX_VARIANCE_OUTSIDE:
            tp_max = (
                2.0 * math.pi / OMEGA_MIN_RAD_S * brentq(lambda u: _parametric_share_below(u, gamma) - MAX_VARIANCE_OUTSIDE, 0.05, 0.99)
            )
            raise _refuse(
                "sea_state.peak_period_s",
                tp,
                below,
                f"below {OMEGA_MIN_RAD_S:g} rad/s",
                f"peak_period_s <= {tp_max:.1f} s for this spectrum",
            )
        ref = wp * np.geomspace(0.3, 60.0, 8001)
        ref_s = jonswap_density(ref, hs, tp, gamma)
        grid = spectrum_grid(ref, ref_s, n_points)
        density = jonswap_density(grid, hs, tp, gamma)
        outside = hs**2 / 16.0 * (above + below)
        name = "Pierson-Moskowitz" if gamma == 1.0 else f"JONSWAP gamma = {gamma:g}"
        description = f"{name} (DNV-RP-C205), Hs = {hs:g} m, Tp = {tp:g} s"
        return WaveSpectrum(grid, density, hs, tp, float(outside), description)
    w_tab, s_tab = read_spectrum_table(ss.spectrum)
    total = float(np.trapezoid(s_tab, w_tab))
    scale = 1.0 if ss.significant_height_m is None else (ss.significant_height_m / (4.0 * math.sqrt(total))) ** 2
    s_tab = s_tab * scale
    total *= scale
    fine = np.unique(np.concatenate([w_tab, np.linspace(w_tab[0], w_tab[-1], 8001)]))
    fine_s = np.interp(fine, w_tab, s_tab)
    cum = np.concatenate([[0.0], np.cumsum(0.5 * (fine_s[1:] + fine_s[:-1]) * np.diff(fine))])
    above = (cum[-1] - float(np.interp(OMEGA_MAX_RAD_S, fine, cum))) / cum[-1] if fine[-1] > OMEGA_MAX_RAD_S else 0.0
    below = float(np.interp(OMEGA_MIN_RAD_S, fine, cum)) / cum[-1] if fine[0] < OMEGA_MIN_RAD_S else 0.0
    for share, where in ((above, f"above {OMEGA_MAX_RAD_S:g} rad/s"), (below, f"below {OMEGA_MIN_RAD_S:g} rad/s")):
        if share > MAX_VARIANCE_OUTSIDE:
            raise _refuse("sea_state.spectrum", ss.spectrum, share, where, "a table whose variance lies within the band")
    grid = spectrum_grid(fine, fine_s, n_points)
    # the table's own rows are kept on the grid (its peaks and corners exactly)
    rows_in = w_tab[(w_tab > grid[0]) & (w_tab < grid[-1])]
    grid = np.unique(np.concatenate([grid, rows_in]))
    density = np.interp(grid, w_tab, s_tab, left=0.0, right=0.0)
    tp = 2.0 * math.pi / float(w_tab[np.argmax(s_tab)])
    hs = 4.0 * math.sqrt(total)
    description = f"table '{Path(ss.spectrum).name}'" + ("" if scale == 1.0 else f" rescaled to Hs = {hs:g} m") + f", Tp = {tp:.3g} s"
    return WaveSpectrum(grid, density, hs, tp, float(total * (above + below)), description)
