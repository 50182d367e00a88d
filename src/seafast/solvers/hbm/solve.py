"""The entry point of the harmonic balance: :func:`solve_hbm` (a fixed H, or H chosen adaptively)."""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from seafast.config.modes import Formulation
from seafast.excitation.harmonic import HarmonicExcitation
from seafast.model.structure import StructuralModel
from seafast.solvers.hbm.adaptive import solve_adaptive
from seafast.solvers.hbm.fixed import compression_harmonics, project_on_harmonics, solve_at_harmonics, solve_many_harmonics, with_truncation
from seafast.solvers.hbm.harmonics import truncation_error
from seafast.solvers.hbm.options import SAFE_HARMONICS, HBMOptions
from seafast.solvers.periodic import PeriodicResponse

__all__ = ["solve_hbm"]


def solve_hbm(
    model: StructuralModel,
    excitation: HarmonicExcitation,
    options: HBMOptions | None = None,
    *,
    initial_compression_m: NDArray | None = None,
) -> PeriodicResponse:
    """Periodic steady state with unilateral saddles by harmonic balance + AFT.

    Parameters
    ----------
    model
        The cargo and sea-fastening model.
    excitation
        Deck motion and vessel loads per harmonic (harmonics above ``options.harmonics`` are
        dropped, with ``SolverWarning.HARMONICS_ABOVE_H_IGNORED`` in ``warnings``). The model's static load (gravity, pretension) is
        added at k = 0. With ``harmonics = 0`` only the static part is solved: the nonlinear
        static solution.
    options
        :class:`HBMOptions` (defaults: exact contact law, H chosen adaptively until the saddle-force
        peaks settle to 0.1 %, condensed, Newton). :data:`~seafast.solvers.hbm.options.SOURCE_OPTIONS`
        is the source's method.
    initial_compression_m
        Optional start: saddle compressions sampled over one period at ``t_n = n T / N'``, (N', n_s)
        [m], any N' (e.g. a neighbouring solution's ``saddle_compression_time_m``; condensed
        formulation only); projected on the harmonics solved for. Default: the adaptive choice's
        periodic march (adaptive H), else the better of the linear solution and the quasi-static
        predictor.

    Returns
    -------
    PeriodicResponse
        ``method = "hbm"``; ``outcome`` ``CONVERGED`` (direct solve),
        ``CONVERGED_BY_CONTINUATION`` or ``NOT_CONVERGED`` (never raised). Its
        ``residual_norm`` is relative (see :class:`HBMOptions` ``tolerance``);
        ``truncation_error`` estimates each saddle's peak-force error from the harmonics left out;
        ``options`` records the H and N used (and, adaptive, how they were chosen, :mod:`~seafast.solvers.hbm.adaptive`);
        ``path`` the typed start and route of the solve (:class:`~seafast.solvers.outcome.HBMPath`).
    """
    options = HBMOptions() if options is None else options
    given = None
    if initial_compression_m is not None:
        given = np.asarray(initial_compression_m, dtype=float)
        if given.ndim != 2 or given.shape[1] != model.saddle_count or given.shape[0] < 2:
            raise ValueError(f"initial_compression_m: shape {given.shape}; must be (samples, n_saddles = {model.saddle_count})")
    if options.harmonics is None:
        return solve_adaptive(model, excitation, options, given)
    H = int(options.harmonics)
    fixed = options.with_harmonics(H)
    start = None if given is None else project_on_harmonics(given, H)
    if H > SAFE_HARMONICS and options.formulation is Formulation.CONDENSED:
        response = solve_many_harmonics(model, excitation, fixed, start)
    else:
        response = solve_at_harmonics(model, excitation, fixed, start)
    if H == 0:
        return response
    error = truncation_error(model, excitation.omega_rad_s, compression_harmonics(response, H), fixed.law)
    return with_truncation(response, error, options.truncation_tolerance)
