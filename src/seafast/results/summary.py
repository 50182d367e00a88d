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
from seafast.fourier import channel_samples
from seafast.model.beam import element_end_moments
from seafast.model.structure import StructuralModel
from seafast.results.dataset import largest_slope_rad, row_warnings, seafastening_baseline
from seafast.solvers.outcome import SolverWarning
from seafast.solvers.periodic import CargoHistory

__all__ = ["FACTORED_SAMPLES", "RowSolution", "summary_rows", "summary_row", "MOMENT_POINTS_PER_ELEMENT"]

MOMENT_POINTS_PER_ELEMENT = 2
"""Moment samples per element beyond its start (ends and midpoint), as the results' moment lines."""


@dataclass(frozen=True)
class RowSolution:
    """One (load case, model) response in the form the summary needs.

    Attributes
    ----------
    cargo_harmonics : ndarray, complex, shape (n_k, n_c), or None
        Cargo DOF amplitudes X_k (z [m], theta [rad]) relative to the vessel's rigid-body
        frame, ``x(t) = Re(sum_k X_k exp(i k omega t))``; one row (k = 0) for a static state.
        None where ``cargo_factors`` is given.
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
    cargo_factors : CargoHistory or None
        The same history kept factored (:class:`~seafast.solvers.periodic.CargoHistory`, the shooting's), sampled
        on the summary's N: the moments then come from its few time functions; None: ``cargo_harmonics``.
    """

    cargo_harmonics: NDArray[np.complex128] | None
    saddle_compression_m: NDArray[np.float64]
    saddle_force_N: NDArray[np.float64]
    excitation: HarmonicExcitation
    nonlinear: bool
    converged: bool = True
    residual_norm: float = 0.0
    iterations: int = 0
    warnings: tuple[SolverWarning, ...] = ()
    cargo_factors: CargoHistory | None = None

    def __post_init__(self) -> None:
        if (self.cargo_harmonics is None) == (self.cargo_factors is None or not self.cargo_factors.factored):
            raise ValueError("RowSolution: give either cargo_harmonics or factored cargo_factors")


@functools.lru_cache(maxsize=32)
def _sampling(harmonics: int, time_samples: int) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """cos and sin of k omega t_n, shape (N, n_k): x(t_n) = cos @ Re X - sin @ Im X (as harmonics_to_time)."""
    phase = 2.0 * np.pi * np.outer(np.arange(time_samples), np.arange(harmonics)) / time_samples
    return np.cos(phase), np.sin(phase)


FACTORED_SAMPLES = 4096
"""From this many samples a period on, a row's factored cargo history (:class:`~seafast.solvers.periodic.CargoHistory`)
gives its moments through its few time functions (on a stiff saddle's 8192 samples, 3-4 times faster than the
harmonics' route); below, the harmonics' route costs about the same, and its sums in the same order as always keep the
summary of an unchanged case the same to the last bit (the two routes differ by round-off, 1e-11)."""

_FFT_HARMONICS = 24  # from this many harmonics on, an inverse FFT samples faster than the cos/sin product


def _sample(X: NDArray, time_samples: int) -> NDArray[np.float64]:
    """``Re(sum_k X_k exp(i k omega t_n))`` at ``t_n = n T / N``, time the last axis: shape (..., N)."""
    if X.shape[0] >= _FFT_HARMONICS:
        return channel_samples(X, time_samples)  # hundreds of harmonics (the converged default): O(N log N)
    c, s = _sampling(X.shape[0], time_samples)
    flat = X.reshape(X.shape[0], -1)
    samples = c @ np.ascontiguousarray(flat.real) - s @ np.ascontiguousarray(flat.imag)
    return np.moveaxis(samples.reshape((time_samples,) + X.shape[1:]), 0, -1)


def _line_load_harmonics(model: StructuralModel, row: RowSolution, n_k: int) -> NDArray[np.complex128]:
    """The row's distributed load on the cargo [N/m] per harmonic k < ``n_k`` and element, gravity at k = 0, (n_k, n_el)."""
    beam = model.cargo
    q = np.zeros((n_k, beam.element_count), dtype=complex)
    m = min(n_k, row.excitation.harmonic_count)
    q[:m] = row.excitation.cargo_line_load_N_per_m[:m]
    q[0] += beam.gravity_line_load_N_per_m
    return q


def _moment_points(model: StructuralModel, m0: NDArray, m1: NDArray, q: NDArray | None) -> NDArray:
    """The moments at each element's ends and midpoint (..., 3 n_el) from its end moments (..., n_el) and load q."""
    xi = np.linspace(0.0, 1.0, MOMENT_POINTS_PER_ELEMENT + 1)
    moment = m0[..., None] * (1.0 - xi) + m1[..., None] * xi
    if q is not None:
        lengths = np.diff(model.cargo.node_x_m)
        moment = moment - q[..., None] * (lengths[:, None] ** 2) * (xi * (1.0 - xi)) / 2.0
    return moment.reshape(m0.shape[:-1] + (-1,))


def _moment_harmonics(model: StructuralModel, rows: Sequence[RowSolution]) -> list[NDArray[Any]]:
    """Bending-moment amplitudes [N m] at each element's ends and midpoint, (n_k, 3 n_el) per row.

    All rows in one call of :func:`element_end_moments` (the element matrices are formed once).
    """
    if not rows:
        return []
    beam = model.cargo
    harmonics = [np.asarray(r.cargo_harmonics) for r in rows]
    X = np.concatenate(harmonics)
    q = np.concatenate([_line_load_harmonics(model, r, h.shape[0]) for r, h in zip(rows, harmonics, strict=True)])
    m0, m1 = element_end_moments(beam.node_x_m, X, beam.element_bending_stiffness_Nm2, None, q)
    moment = _moment_points(model, m0, m1, q)
    bounds = np.cumsum([0] + [h.shape[0] for h in harmonics])
    return [moment[a:b] for a, b in pairwise(bounds)]


def _sampled_row(model: StructuralModel, row: RowSolution, moment_harmonics: NDArray, n_t: int) -> tuple[NDArray, NDArray, NDArray]:
    """The deck under the saddles, cargo z and moments of a row given by its harmonics, each (N, channels) [m, N m]."""
    X = np.asarray(row.cargo_harmonics)
    n_k = X.shape[0]
    deck = np.zeros((n_k, model.saddle_count), dtype=complex)
    m = min(n_k, row.excitation.harmonic_count)
    deck[:m] = row.excitation.deck_displacement[:m, model.saddle_deck_dof]
    # one sampling of every channel, time the last axis (each channel's period contiguous), then (N, channels) views
    samples = _sample(np.concatenate([deck, X[:, 0::2], moment_harmonics], axis=1), n_t)
    deck_z, z, moment = np.split(samples, [model.saddle_count, model.saddle_count + model.cargo.node_count], axis=0)
    return deck_z.T, z.T, moment.T


def _factored_row(model: StructuralModel, row: RowSolution, n_t: int) -> tuple[NDArray, NDArray, NDArray]:
    """The same of a row whose cargo history is factored (:class:`~seafast.solvers.periodic.CargoHistory`).

    The moments are linear in the displacements: the end moments of each shape (r of them), sampled by the history's
    time functions, plus the load's part from the excitation's few harmonics. Equal to the harmonics' route to
    round-off at r products a sample instead of n_c.
    """
    history = row.cargo_factors
    assert history is not None and history.shapes is not None
    beam, exc = model.cargo, row.excitation
    functions, shapes = history.time_functions, history.shapes
    if functions.shape[0] != n_t:
        raise ValueError(f"a factored history of {functions.shape[0]} samples read at {n_t} samples a period")
    m0, m1 = element_end_moments(beam.node_x_m, shapes, beam.element_bending_stiffness_Nm2)
    n_k = exc.harmonic_count
    q = _line_load_harmonics(model, row, n_k)
    q0, q1 = element_end_moments(beam.node_x_m, np.zeros((n_k, 2 * beam.node_count)), beam.element_bending_stiffness_Nm2, None, q)
    moment = functions @ _moment_points(model, m0, m1, None) + _sample(_moment_points(model, q0, q1, q), n_t).T
    deck = _sample(exc.deck_displacement[:, model.saddle_deck_dof], n_t).T
    return deck, functions @ shapes[:, 0::2], moment


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
    dense = [r for _, _, r in rows if r.cargo_factors is None]
    moments = iter(_moment_harmonics(model, dense))
    out = []
    for load_case, model_name, row in rows:
        exc = row.excitation
        if row.cargo_factors is None:
            n_t = 1 if np.asarray(row.cargo_harmonics).shape[0] == 1 else int(time_samples)
            deck_z, z, moment = _sampled_row(model, row, next(moments), n_t)
        else:
            deck_z, z, moment = _factored_row(model, row, int(time_samples))
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
