"""Quasi-static exact-contact reference: the static contact problem at each instant of the period.

At each of the N instants the static problem (cargo inertia and damping neglected; the vessel
loads in ``excitation.cargo_load_N`` -- e.g. rigid-body inertia -- included) with exact
contact. Condensed on the saddles: with every saddle bilateral in ``K`` the compressions
satisfy ``delta = delta_lin - G_0 c`` where ``G_0 = B^T K^-1 B`` and ``c = k_u max(-delta, 0)``
cancels the tension a bilateral saddle would carry. This piecewise-linear system is solved
exactly by the active-set iteration of :mod:`seafast.solvers.exact_contact`, so the answer is
exact to round-off.
"""

from __future__ import annotations

import logging

import numpy as np
from numpy.typing import NDArray
from scipy.linalg import eigh

from seafast.config.modes import SolverMethod
from seafast.excitation.harmonic import HarmonicExcitation
from seafast.fourier import harmonics_to_time, high_harmonic_energy_share
from seafast.model.structure import StructuralModel
from seafast.solvers.dynamic_stiffness import linear_force_harmonics, quadratic_matrices, saddle_selection, solve_dynamic
from seafast.solvers.exact_contact import solve_exact_contact
from seafast.solvers.outcome import SolverOutcome, SolverWarning
from seafast.solvers.periodic import PeriodicResponse, Settings
from seafast.solvers.references.common import exact_law_response
from seafast.solvers.references.options import QuasiStaticOptions

__all__ = ["QUASI_STATIC_RATIO_LIMIT", "solve_quasi_static"]

logger = logging.getLogger(__name__)

QUASI_STATIC_RATIO_LIMIT = 0.2
"""Quasi-statics is taken as justified when ``H_eff omega / omega_1 <= 0.2``."""


def _effective_harmonic(force: NDArray, omega: float, share: float = 1e-3) -> int:
    """Smallest H whose truncation misses less than ``share`` of the force fluctuation energy."""
    N = force.shape[0]
    for h in range(N // 2 + 1):
        if np.all(high_harmonic_energy_share(force, h) < share):
            return max(h, 1)
    return N // 2


def solve_quasi_static(
    model: StructuralModel, excitation: HarmonicExcitation, options: QuasiStaticOptions | None = None
) -> PeriodicResponse:
    """Exact-contact quasi-static response at ``options.time_samples`` instants of the period.

    Cargo inertia and damping are neglected (each instant is a static problem with the
    stiffness K); the vessel loads of the excitation (e.g. rigid-body inertia -M a_rb) and the
    model's static load are included. Every harmonic of the excitation is used.

    Whether quasi-statics is justified: with ``H_eff`` the smallest harmonic above which the
    contact forces carry < 0.1 % of their fluctuation energy and ``omega_1`` the lowest natural
    frequency of the cargo over the contact states that occur (saddles that detach removed),
    ``warnings`` holds ``SolverWarning.QUASI_STATICS_QUESTIONABLE`` when
    ``H_eff omega / omega_1 > 0.2``; the ``message`` says it in words. A still-water excitation
    (no harmonic above k = 0) is exactly static: ``H_eff = 0``.

    Returns
    -------
    PeriodicResponse
        ``method = "quasi_static"``; ``options`` records ``time_samples``,
        ``effective_harmonic``, ``lowest_natural_frequency_rad_s`` and ``frequency_ratio``.
    """
    options = QuasiStaticOptions() if options is None else options
    if not isinstance(options, QuasiStaticOptions):
        raise TypeError(f"options = {options!r}: allowed a QuasiStaticOptions (e.g. QuasiStaticOptions(time_samples=128)) or None")
    N = int(options.time_samples)
    q = quadratic_matrices(model, True)
    B = saddle_selection(model)
    sad_c, sad_o = model.saddle_cargo_dof, model.saddle_deck_dof
    k_u = np.asarray(model.saddle_unilateral_stiffness_N_per_m, dtype=float)
    P = linear_force_harmonics(model, excitation, quasi_static=True)
    sol = solve_dynamic(q, 0.0, np.column_stack([B, P.real.T, P.imag.T]))
    n_s, n_k = model.saddle_count, excitation.harmonic_count
    Y = sol[:, :n_s]
    X_lin = (sol[:, n_s : n_s + n_k] + 1j * sol[:, n_s + n_k :]).T  # (n_k, n_c)
    x_lin = harmonics_to_time(X_lin, N)
    deck_z = harmonics_to_time(excitation.deck_displacement[:, sad_o], N)
    delta_lin = deck_z - x_lin[:, sad_c]
    delta, correction = solve_exact_contact(delta_lin, Y[sad_c], k_u)
    cargo = x_lin + correction @ Y.T
    # Is quasi-statics justified? Lowest natural frequency over the contact states that occur.
    force = k_u * np.maximum(delta, 0.0)
    # a still-water excitation (no harmonic above k = 0) is exactly static: nothing to justify
    static = not (np.any(excitation.deck_displacement[1:]) or np.any(excitation.cargo_load_N[1:]))
    h_eff = 0 if static else _effective_harmonic(force, excitation.omega_rad_s)
    states = np.unique(delta <= 0.0, axis=0)
    w1 = np.inf
    for detached in states:
        K = q.stiffness.copy()
        K[sad_c, sad_c] -= k_u * detached
        w2 = eigh(K, q.mass, eigvals_only=True, subset_by_index=[0, 0])[0]
        w1 = min(w1, float(np.sqrt(max(w2, 0.0))))
    ratio = h_eff * excitation.omega_rad_s / w1 if w1 > 0 else np.inf
    criterion = f"H_eff*omega/omega_1 = {h_eff}*{excitation.omega_rad_s:.4g}/{w1:.4g} = {ratio:.3g}"
    verdict = (
        f"quasi-statics justified: {criterion} <= {QUASI_STATIC_RATIO_LIMIT}"
        if ratio <= QUASI_STATIC_RATIO_LIMIT
        else f"quasi-statics questionable: {criterion} > {QUASI_STATIC_RATIO_LIMIT} "
        "(cargo dynamics matter; use HBM or the time-domain reference)"
    )
    record: Settings = {
        "time_samples": N,
        "harmonics_for_indicator": int(options.harmonics_for_indicator),
        "effective_harmonic": int(h_eff),
        "lowest_natural_frequency_rad_s": float(w1),
        "frequency_ratio": float(ratio),
        "contact_law": "exact",
    }
    warnings = () if ratio <= QUASI_STATIC_RATIO_LIMIT else (SolverWarning.QUASI_STATICS_QUESTIONABLE,)
    if warnings:
        logger.warning("quasi-static reference: %s", verdict)
    else:
        logger.debug("quasi-static reference: %s", verdict)
    return exact_law_response(
        SolverMethod.QUASI_STATIC,
        model,
        excitation,
        cargo,
        delta,
        SolverOutcome.CONVERGED,
        0.0,
        len(states),
        N,
        f"exact active-set solution at {N} instants; {verdict}",
        int(options.harmonics_for_indicator),
        record,
        warnings,
    )
