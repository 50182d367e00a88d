"""The quasi-static exact-contact reference of the 3-D cargo on its cradles (docs/transverse.md#7-dynamics).

At each of the N instants ``t_n = n T / N`` the static problem of the instant's loads (the weight, the vessel's
inertia and gravity loads, the deck's position; the cargo's own inertia and damping neglected), with the exact
law. Condensed onto the engagements as the vertical plane's quasi-static reference: with every element bilateral
the engagements satisfy ``s = s_lin - G_0 c`` with ``G_0 = A K_lin^-1 A^T`` and ``c = k max(-s, 0)`` the tension a
bilateral pad or stopper (the compression a bilateral lashing) would carry, solved exactly by the active-set
solver of :mod:`seafast.solvers.exact_contact`. Valid where the wave is far below the cargo's modes on its
restraints. Units: SI.
"""

from __future__ import annotations

import numpy as np

from seafast.excitation.cradle_loads import CradleExcitation
from seafast.fourier import harmonics_to_time
from seafast.solvers.cradle_dynamics import CradleDynamics
from seafast.solvers.cradle_hbm import CradleResponse, cradle_response
from seafast.solvers.exact_contact import solve_exact_contact
from seafast.solvers.outcome import SolverOutcome

__all__ = ["solve_cradle_quasi_static"]


def solve_cradle_quasi_static(dynamics: CradleDynamics, excitation: CradleExcitation, time_samples: int = 256) -> CradleResponse:
    """The exact static response at ``time_samples`` instants of the period (inertia and damping of the cargo neglected).

    Returns a :class:`~seafast.solvers.cradle_hbm.CradleResponse` (``CONVERGED``: exact to round-off at every instant;
    its residual the largest sign violation relative to the largest engagement).
    """
    N = int(time_samples)
    if N < 2:
        raise ValueError(f"time_samples = {time_samples!r}: allowed an integer >= 2")
    parts = dynamics.linear_parts()
    problem = dynamics.problem
    A, k, E, s0 = problem.engagement_matrix, problem.element_stiffness_N_per_m, dynamics.deck_engagement, dynamics.initial_engagement_m
    m, n = A.shape
    xo = np.array(excitation.deck_displacement, dtype=complex)
    f = np.array(excitation.cargo_load_N, dtype=complex)
    xo[0], f[0] = xo[0].real, (f[0] + dynamics.static_load_N()).real
    K_co = parts.deck_coupling[0]
    load = f - xo @ K_co.T
    load[0] -= A.T @ (k * s0)
    rhs = np.concatenate([np.broadcast_to(-A.T[None], (2, n, m)), load[:, :, None]], axis=2).astype(complex)
    solved = parts.solve_stack(np.zeros(2), rhs)  # static: both harmonics' loads on K_lin alone
    influence, q_lin = solved[0, :, :m].real, solved[:, :, m]
    s_lin = harmonics_to_time(q_lin @ A.T + xo @ E.T, N) + s0
    s, c = solve_exact_contact(s_lin, A @ -influence, k)
    q = harmonics_to_time(q_lin, N) + c @ influence.T
    violation = float(np.max(np.abs(s - (s_lin - c @ (A @ -influence).T)))) / max(float(np.max(np.abs(s_lin))), 1e-6)
    message = f"3-D cradle quasi-static exact contact at {N} instants"
    return cradle_response(dynamics, s, q, excitation.omega_rad_s, (SolverOutcome.CONVERGED, violation, message, 0))
