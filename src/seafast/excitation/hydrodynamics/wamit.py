"""WAMIT output readers: added mass and damping (``.1``), wave excitation (``.3``).

WAMIT's conventions: ``exp(+i omega t)``, modes 1 (surge), 3 (heave), 5 (pitch about ``+y``,
bow down), non-dimensionalised by ``rho``, ``g`` and ``ULEN``; the readers return dimensional
values in WAMIT's modes (the sign of pitch is changed later, in
:mod:`~seafast.excitation.hydrodynamics.coefficients`).
"""

from __future__ import annotations

import math
import os
from collections.abc import Callable
from pathlib import Path
from typing import Literal

import numpy as np
from numpy.typing import NDArray

__all__ = ["read_wamit_1", "read_wamit_3", "read_wamit_3_headings", "wamit_has_surge"]


def read_wamit_1(
    path: str | os.PathLike,
    *,
    ulen_m: float,
    water_density_kg_per_m3: float,
    frequency_column: Literal["period", "omega"] = "period",
    modes: tuple[int, ...] = (3, 5),
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """Read heave/pitch (``modes``: also surge, mode 1) added mass and damping from a WAMIT ``.1`` file.

    Lines ``PER I J Abar Bbar``; ``Abar = A / (rho L^k)``, ``Bbar = B / (rho L^k omega)`` with
    ``k = 3`` (translation-translation), 4 (mixed), 5 (rotation-rotation), ``L = ULEN``.
    Lines with ``PER <= 0`` (zero/infinite frequency limits) are skipped.

    Returns
    -------
    omega [rad/s] (n_w,), A (n_w, n, n), B (n_w, n, n) in WAMIT ``modes`` (default (3, 5), n = 2).
    """
    rows: dict[float, dict[tuple[int, int], tuple[float, float]]] = {}
    for line in Path(path).read_text().splitlines():
        parts = line.split()
        if len(parts) < 5:
            continue
        per, i, j, abar, bbar = float(parts[0]), int(parts[1]), int(parts[2]), float(parts[3]), float(parts[4])
        if per <= 0 or i not in modes or j not in modes:
            continue
        w = 2 * math.pi / per if frequency_column == "period" else per
        rows.setdefault(round(w, 12), {})[(i, j)] = (abar, bbar)
    if not rows:
        raise ValueError(f"WAMIT .1 file {path}: no coefficients of modes {modes} found")
    omega = np.array(sorted(rows))
    n_m = len(modes)
    a = np.zeros((omega.size, n_m, n_m))
    b = np.zeros((omega.size, n_m, n_m))
    idx = {m: q for q, m in enumerate(modes)}
    for n, w in enumerate(omega):
        for (i, j), (abar, bbar) in rows[w].items():
            kexp = 3 + (i > 3) + (j > 3)
            scale = water_density_kg_per_m3 * ulen_m**kexp
            a[n, idx[i], idx[j]] = abar * scale
            b[n, idx[i], idx[j]] = bbar * scale * w
        missing = {(i, i) for i in modes} - set(rows[w])
        if missing:
            raise ValueError(f"WAMIT .1 file {path}: diagonal terms {sorted(missing)} missing at omega = {w:.6g} rad/s")
    return omega, a, b


def read_wamit_3(
    path: str | os.PathLike,
    *,
    ulen_m: float,
    water_density_kg_per_m3: float,
    gravity_m_per_s2: float,
    heading_deg: float = 180.0,
    frequency_column: Literal["period", "omega"] = "period",
    modes: tuple[int, ...] = (3, 5),
) -> tuple[NDArray[np.float64], NDArray[np.complex128]]:
    """Read heave/pitch (``modes``: also surge, mode 1) wave excitation from a WAMIT ``.3`` file, one heading.

    Lines ``PER BETA I |X| phase Re Im``; ``Xbar = X / (rho g A L^m)``, ``m = 2`` for forces,
    3 for moments; ``exp(+i omega t)`` convention, phase relative to the incident wave at the
    WAMIT origin. The real and imaginary columns are used.

    Returns
    -------
    omega [rad/s] (n_w,), X (n_w, n) complex per metre of wave amplitude, in ``modes``.
    """
    rows: dict[float, dict[int, complex]] = {}
    headings: set[float] = set()
    for line in Path(path).read_text().splitlines():
        parts = line.split()
        if len(parts) < 7:
            continue
        per, beta, i = float(parts[0]), float(parts[1]), int(parts[2])
        headings.add(beta)
        if per <= 0 or i not in modes or abs((beta - heading_deg + 180.0) % 360.0 - 180.0) > 1e-3:
            continue
        w = 2 * math.pi / per if frequency_column == "period" else per
        m = 2 if i <= 3 else 3
        rows.setdefault(round(w, 12), {})[i] = (float(parts[5]) + 1j * float(parts[6])) * (
            water_density_kg_per_m3 * gravity_m_per_s2 * ulen_m**m
        )
    if not rows:
        raise ValueError(
            f"WAMIT .3 file {path}: no excitation of modes {modes} for heading {heading_deg} deg (headings found: {sorted(headings)})"
        )
    omega = np.array(sorted(rows))
    x = np.zeros((omega.size, len(modes)), dtype=complex)
    for n, w in enumerate(omega):
        if set(rows[w]) != set(modes):
            raise ValueError(f"WAMIT .3 file {path}: modes {sorted(set(modes) - set(rows[w]))} missing at omega = {w:.6g} rad/s")
        x[n] = [rows[w][m] for m in modes]
    return omega, x


def read_wamit_3_headings(
    path: str | os.PathLike,
    *,
    ulen_m: float,
    water_density_kg_per_m3: float,
    gravity_m_per_s2: float,
    frequency_column: Literal["period", "omega"] = "period",
    modes: tuple[int, ...] = (1, 2, 3, 4, 5, 6),
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.complex128]]:
    """Read the wave excitation of ``modes`` at every heading of a WAMIT ``.3`` file.

    WAMIT's ``BETA`` [deg] is the direction the waves travel, from ``+x`` towards ``+y``: seafast's heading. Scaling and
    conventions as :func:`read_wamit_3`.

    Returns
    -------
    omega [rad/s] (n_w,), headings [deg] (n_b,) ascending, X (n_w, n_b, n) complex per metre of wave amplitude.

    Raises
    ------
    ValueError
        No excitation of ``modes``, or a (frequency, heading) pair missing one of them.
    """
    headings: set[float] = set()
    for line in Path(path).read_text().splitlines():
        parts = line.split()
        if len(parts) >= 7 and float(parts[0]) > 0 and int(parts[2]) in modes:
            headings.add(round(float(parts[1]) % 360.0, 6))
    if not headings:
        raise ValueError(f"WAMIT .3 file {path}: no excitation of modes {modes} found")
    betas = sorted(headings)
    per_heading = [
        read_wamit_3(
            path,
            ulen_m=ulen_m,
            water_density_kg_per_m3=water_density_kg_per_m3,
            gravity_m_per_s2=gravity_m_per_s2,
            heading_deg=b,
            frequency_column=frequency_column,
            modes=modes,
        )
        for b in betas
    ]
    omega = per_heading[0][0]
    for b, (w, _) in zip(betas, per_heading, strict=True):
        if w.shape != omega.shape or not np.allclose(w, omega, rtol=1e-9):
            raise ValueError(f"WAMIT .3 file {path}: heading {b} deg has other frequencies than heading {betas[0]} deg")
    return omega, np.array(betas), np.stack([x for _, x in per_heading], axis=1)


def wamit_has_surge(f1: Path, f3: Path) -> bool:
    """Whether both WAMIT files hold mode 1 (surge): the .1 file its diagonal term, the .3 file its force."""

    def has(path: Path, test: Callable[[list[str]], bool]) -> bool:
        for line in path.read_text().splitlines():
            parts = line.split()
            try:
                if test(parts):
                    return True
            except (ValueError, IndexError):
                continue
        return False

    return has(f1, lambda q: len(q) >= 5 and float(q[0]) > 0 and int(q[1]) == 1 and int(q[2]) == 1) and has(
        f3, lambda q: len(q) >= 7 and float(q[0]) > 0 and int(q[2]) == 1
    )
