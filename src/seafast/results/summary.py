"""Summary quantities of one case straight from its harmonic solutions (what a study records).

A study keeps a few numbers per point and load case/model row: u_c, u_s, u_d, F, M_b, sigma_b,
whether contact is preserved, and the solver's convergence. :func:`summary_rows` computes them
from the row's cargo harmonics and saddle samples without the period time series, moment lines
and labelled Dataset of :func:`seafast.results.dataset.case_arrays`, which cost several times
the nonlinear solve. The definitions are those of :meth:`CaseArrays.maxima` (README, "Outputs"):

* ``u_c_m``: max over the period and the cargo nodes of |z - z_baseline|, z the cargo
  deflection relative to the vessel's rigid-body frame, z_baseline the sea-fastening baseline
  (:func:`seafast.results.dataset.seafastening_baseline`) [m];
* ``u_s_m``: max(max saddle compression, 0) [m]; ``u_d_m``: the largest gap max(-delta, 0),
  nonlinear rows only (0 for the linear model) [m]; ``F_N``: the largest saddle force [N];
* ``M_b_Nm``, ``sigma_b_Pa``: max |M| and max |M (D/2) / I| over the period at each element's
  ends and midpoint, M sagging positive, from the element end moments and the distributed load
  (:func:`seafast.model.beam.element_end_moments`, exact for a uniform load per element) [N m, Pa];
* ``contact_preserved``: every compression sample > 0.

The moments are linear in the displacements and loads, so they are formed per harmonic and
sampled once; the results equal the time-domain route to round-off
(``tests/results/test_summary.py`` and ``tests/analyses/test_run.py``).
"""

from __future__ import annotations

import functools
from collections.abc import Sequence
from dataclasses import dataclass
from itertools import pairwise
from typing import Any

import numpy as np
from numpy.typing import NDArray

from seafast.excitation.harmonic import HarmonicExcitation
from seafast.fourier import harmonics_to_time
from seafast.model.beam import element_end_moments
from seafast.model.structure import StructuralModel
from seafast.results.dataset import largest_slope_rad, row_warnings, seafastening_baseline
from seafast.solvers.outcome import SolverWarning

__all__ = ["RowSolution", "summary_rows", "summary_row", "MOMENT_POINTS_PER_ELEMENT"]

MOMENT_POINTS_PER_ELEMENT = 2
"""Moment samples per element beyond its start (ends and midpoint), as the results' moment lines."""


@dataclass(frozen=True)
class RowSolution:
    """One (load case, model) response in the form the summary needs.

    Attributes
    ----------
    cargo_harmonics : ndarray, complex, shape (n_k, n_c)
        Cargo DOF amplitudes X_k (z [m], theta [rad]) relative to the vessel's rigid-body
        frame, ``x(t) = Re(sum_k X_k exp(i k omega t))``; one row (k = 0) for a static state.
    saddle_compression_m : ndarray, shape (n_t, n_s)
        Saddle compression delta = z_deck - z_cargo over the period (positive compressed) [m];
        one sample for a static state.
    saddle_force_N : ndarray, shape (n_t, n_s)
        Saddle normal force on the cargo (up positive) at the same samples [N].
    excitation : HarmonicExcitation
        The row's excitation (its static part for a static row).
    nonlinear : bool
        Whether the row is the unilateral-saddle model (gaps reported) or the linear one.
    converged : bool
    residual_norm : float
        The nonlinear solver's relative residual (0 for the linear model).
    iterations : int
        Nonlinear iterations (0 for the linear model).
    warnings : tuple of SolverWarning
        The solve's typed warnings.
    """

    cargo_harmonics: NDArray[np.complex128]
    saddle_compression_m: NDArray[np.float64]
    saddle_force_N: NDArray[np.float64]
    excitation: HarmonicExcitation
    nonlinear: bool
    converged: bool = True
    residual_norm: float = 0.0
    iterations: int = 0
    warnings: tuple[SolverWarning, ...] = ()


@functools.lru_cache(maxsize=32)
def _sampling(harmonics: int, time_samples: int) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """cos and sin of k omega t_n, shape (N, n_k): x(t_n) = cos @ Re X - sin @ Im X (as harmonics_to_time)."""
    phase = 2.0 * np.pi * np.outer(np.arange(time_samples), np.arange(harmonics)) / time_samples
    return np.cos(phase), np.sin(phase)


_FFT_HARMONICS = 24  # from this many harmonics on, an inverse FFT samples faster than the cos/sin product


def _sample(X: NDArray, time_samples: int) -> NDArray[np.float64]:
    """``Re(sum_k X_k exp(i k omega t_n))`` at ``t_n = n T / N``, shape (N, ...)."""
    if X.shape[0] >= _FFT_HARMONICS:
        return harmonics_to_time(X, time_samples)  # hundreds of harmonics (the converged default): O(N log N)
    c, s = _sampling(X.shape[0], time_samples)
    flat = X.reshape(X.shape[0], -1)
    return (c @ np.ascontiguousarray(flat.real) - s @ np.ascontiguousarray(flat.imag)).reshape((time_samples,) + X.shape[1:])


def _moment_harmonics(model: StructuralModel, rows: Sequence[RowSolution]) -> list[NDArray[Any]]:
    """Bending-moment amplitudes [N m] at each element's ends and midpoint, (n_k, 3 n_el) per row.

    All rows in one call of :func:`element_end_moments` (the element matrices are formed once).
    """
    beam = model.cargo
    X = np.concatenate([np.asarray(r.cargo_harmonics) for r in rows])
    q = np.zeros((X.shape[0], beam.element_count), dtype=complex)
    start = 0
    for r in rows:
        n_k = np.asarray(r.cargo_harmonics).shape[0]
        m = min(n_k, r.excitation.harmonic_count)
        q[start : start + m] = r.excitation.cargo_line_load_N_per_m[:m]
        q[start] += beam.gravity_line_load_N_per_m
        start += n_k
    m0, m1 = element_end_moments(beam.node_x_m, X, beam.element_bending_stiffness_Nm2, None, q)
    xi = np.linspace(0.0, 1.0, MOMENT_POINTS_PER_ELEMENT + 1)
    lengths = np.diff(beam.node_x_m)
    moment = m0[..., None] * (1.0 - xi) + m1[..., None] * xi - q[..., None] * (lengths[:, None] ** 2) * (xi * (1.0 - xi)) / 2.0
    moment = moment.reshape(X.shape[0], -1)
    bounds = np.cumsum([0] + [np.asarray(r.cargo_harmonics).shape[0] for r in rows])
    return [moment[a:b] for a, b in pairwise(bounds)]


def summary_rows(model: StructuralModel, rows: Sequence[tuple[str, str, RowSolution]], time_samples: int) -> list[dict[str, Any]]:
    """The summary rows of a case's (load case, model) responses.

    Parameters
    ----------
    model : StructuralModel
        The cargo model the responses belong to.
    rows : sequence of (load_case, model_name, RowSolution)
        The responses with their labels (``static``/``dynamic``, ``linear``/``nonlinear``).
    time_samples : int
        Samples per period N at which the maxima over time are taken (a static row needs one).

    Returns
    -------
    list of dict
        Per row: ``load_case, model, u_c_m, u_s_m, u_d_m, F_N, M_b_Nm, sigma_b_Pa, converged,
        contact_preserved, residual_norm, iterations`` (the columns of ``summary.csv`` and
        ``study.csv``, SI units) and ``warnings``, the row's typed warnings
        (:func:`seafast.results.dataset.row_warnings`: the solve's and the model's).
    """
    beam = model.cargo
    modulus = np.repeat(beam.element_second_moment_m4 / (beam.element_outer_diameter_m / 2.0), MOMENT_POINTS_PER_ELEMENT + 1)
    moments = _moment_harmonics(model, [r for _, _, r in rows])
    out = []
    for (load_case, model_name, row), moment_harmonics in zip(rows, moments, strict=True):
        X = np.asarray(row.cargo_harmonics)
        n_k = X.shape[0]
        n_t = 1 if n_k == 1 else int(time_samples)
        exc = row.excitation
        # deck under the saddles, cargo z and moments sampled over the period in one product
        deck = np.zeros((n_k, model.saddle_count), dtype=complex)
        m = min(n_k, exc.harmonic_count)
        deck[:m] = exc.deck_displacement[:m, model.saddle_deck_dof]
        samples = _sample(np.concatenate([deck, X[:, 0::2], moment_harmonics], axis=1), n_t)
        deck_z, z, moment = np.split(samples, [model.saddle_count, model.saddle_count + beam.node_count], axis=1)
        deflection = z - seafastening_baseline(model, exc, deck_z)
        comp = np.asarray(row.saddle_compression_m, dtype=float)
        out.append(
            {
                "load_case": load_case,
                "model": model_name,
                "u_c_m": float(np.max(np.abs(deflection))),
                "u_s_m": float(max(np.max(comp), 0.0)),
                "u_d_m": float(max(np.max(-comp), 0.0)) if row.nonlinear else 0.0,
                "F_N": float(np.max(row.saddle_force_N)),
                "M_b_Nm": float(np.max(np.abs(moment))),
                "sigma_b_Pa": float(np.max(np.abs(moment / modulus))),
                "cargo_slope_rad": float(largest_slope_rad(z, beam.node_x_m)),
                "converged": bool(row.converged),
                "contact_preserved": bool(np.all(comp > 0.0)),
                "residual_norm": float(row.residual_norm),
                "iterations": int(row.iterations),
                "warnings": row_warnings(load_case, row.warnings, model.warnings),
            }
        )
    return out


def summary_row(model: StructuralModel, load_case: str, model_name: str, row: RowSolution, time_samples: int) -> dict[str, Any]:
    """The summary row of one (load case, model) response (see :func:`summary_rows`)."""
    return summary_rows(model, [(load_case, model_name, row)], time_samples)[0]
