"""Exact-contact references for the harmonic balance solver.

Both references use the exact contact law ``f = k_u max(delta, 0)`` (no regularisation, no
harmonic truncation) and return a :class:`~seafast.solvers.periodic.PeriodicResponse` on the
same grid ``t_n = n T / N`` as HBM.

``solve_quasi_static``
    At each of the N instants the static problem (cargo inertia and damping neglected; the
    vessel loads in ``excitation.cargo_load_N`` -- e.g. rigid-body inertia -- included) with
    exact contact. Condensed on the saddles: with every saddle bilateral in ``K`` the
    compressions satisfy ``delta = delta_lin - G_0 c`` where ``G_0 = B^T K^-1 B`` and
    ``c = k_u max(-delta, 0)`` cancels the tension a bilateral saddle would carry. This
    piecewise-linear system is solved exactly by an active-set iteration (each iterate solves
    the linear system of a trial set of detached saddles; it stops when the signs agree) with
    enumeration of all sets as a fallback, so the answer is exact to round-off.
``solve_time_domain``
    HHT-alpha integration of the cargo equations with the exact law to the periodic steady
    state, in two formulations of the same equations (``Formulation.FULL``, the independent
    reference, and ``Formulation.CONDENSED``), both started from one stated state and reporting the orbit reached
    (:mod:`~seafast.solvers.references.time_domain`, :mod:`~seafast.solvers.references.orbit`).

``solve_cradle_time_domain`` (:mod:`~seafast.solvers.references.cradle_time_domain`)
    The 3-D cargo on its cradles (pads, stoppers, lashings; docs/transverse.md#7-dynamics) integrated on every DOF
    with the exact law to the periodic state, returning a
    :class:`~seafast.solvers.cradle_hbm.CradleResponse` on the harmonic balance's grid;
    ``solve_cradle_quasi_static`` (:mod:`~seafast.solvers.references.cradle_quasi_static`) its exact static
    response instant by instant.

The references live in :mod:`~seafast.solvers.references.quasi_static` and
:mod:`~seafast.solvers.references.time_domain`, their settings (:class:`QuasiStaticOptions`,
:class:`TimeDomainOptions`) in :mod:`~seafast.solvers.references.options`; the active-set contact
solvers they use in :mod:`seafast.solvers.exact_contact`.
"""

from seafast.solvers.references.options import QuasiStaticOptions, TimeDomainOptions
from seafast.solvers.references.quasi_static import QUASI_STATIC_RATIO_LIMIT, solve_quasi_static
from seafast.solvers.references.time_domain import solve_time_domain

__all__ = [
    "QuasiStaticOptions",
    "TimeDomainOptions",
    "solve_quasi_static",
    "solve_time_domain",
    "QUASI_STATIC_RATIO_LIMIT",
]
