"""One entry point for the periodic response by any method: :func:`solve_periodic`.

In the manner of ``scipy.optimize.root(fun, x0, method=..., options=...)``: ``method`` (a
:class:`~seafast.config.modes.SolverMethod`) picks the solver, ``options`` carries its validated,
keyword-only settings (one class per method), and every method returns the same
:class:`~seafast.solvers.periodic.PeriodicResponse`. Each method lives in its own module:

=================  ====================================================  =================================
method             solver                                                options
=================  ====================================================  =================================
``HBM``            :func:`seafast.solvers.hbm.solve_hbm`                  :class:`~seafast.solvers.hbm.HBMOptions`
``QUASI_STATIC``   :func:`seafast.solvers.references.solve_quasi_static`  :class:`~seafast.solvers.references.QuasiStaticOptions`
``TIME_DOMAIN``    :func:`seafast.solvers.references.solve_time_domain`   :class:`~seafast.solvers.references.TimeDomainOptions`
``SHOOTING``       :func:`seafast.solvers.shooting.solve_shooting`        :class:`~seafast.solvers.shooting.ShootingOptions`
=================  ====================================================  =================================

A time-domain reference started from the harmonic balance's solution (``TimeDomainOptions(start=HBM)``)
solves that first, with ``TimeDomainOptions.hbm``.
"""

from __future__ import annotations

from numpy.typing import NDArray

from seafast.config.modes import SolverMethod, TimeDomainStart
from seafast.excitation.harmonic import HarmonicExcitation
from seafast.model.structure import StructuralModel
from seafast.solvers.hbm.options import HBMOptions
from seafast.solvers.hbm.solve import solve_hbm
from seafast.solvers.periodic import PeriodicResponse
from seafast.solvers.references.options import QuasiStaticOptions, TimeDomainOptions
from seafast.solvers.references.quasi_static import solve_quasi_static
from seafast.solvers.references.time_domain import solve_time_domain
from seafast.solvers.shooting.options import ShootingOptions
from seafast.solvers.shooting.solve import solve_shooting

__all__ = ["PeriodicOptions", "OPTIONS_CLASSES", "solve_periodic"]

PeriodicOptions = HBMOptions | QuasiStaticOptions | TimeDomainOptions | ShootingOptions
"""The settings of any method of :func:`solve_periodic`."""

OPTIONS_CLASSES: dict[SolverMethod, type[PeriodicOptions]] = {
    SolverMethod.HBM: HBMOptions,
    SolverMethod.QUASI_STATIC: QuasiStaticOptions,
    SolverMethod.TIME_DOMAIN: TimeDomainOptions,
    SolverMethod.SHOOTING: ShootingOptions,
}
"""Each method's options class."""


def solve_periodic(
    model: StructuralModel,
    excitation: HarmonicExcitation,
    method: SolverMethod = SolverMethod.HBM,
    *,
    options: PeriodicOptions | None = None,
    initial_compression_m: NDArray | None = None,
) -> PeriodicResponse:
    """The periodic steady state of the cargo on its unilateral saddles, by ``method``.

    Parameters
    ----------
    model, excitation
        The cargo and sea-fastening model, and its deck motion and vessel loads per harmonic.
    method
        :class:`~seafast.config.modes.SolverMethod` (or its value): ``HBM`` (default), ``QUASI_STATIC``,
        ``TIME_DOMAIN`` or ``SHOOTING``.
    options
        The method's settings (:data:`OPTIONS_CLASSES`); None: that class's defaults.
    initial_compression_m
        ``HBM`` only: a start, saddle compressions over one period (N', n_s) [m]
        (:func:`~seafast.solvers.hbm.solve_hbm`).

    Returns
    -------
    PeriodicResponse
        The method's response (its ``method``, ``outcome`` and ``options`` say how it was solved).

    Raises
    ------
    ValueError
        For an unknown method, options of another method's class, or a start the method does not take.
    """
    if not isinstance(method, str) or method not in set(SolverMethod):
        raise ValueError(f"method = {method!r}; allowed: {', '.join(SolverMethod)}")
    method = SolverMethod(method)
    kind = OPTIONS_CLASSES[method]
    chosen = kind() if options is None else options
    if not isinstance(chosen, kind):
        raise ValueError(f"options: a {type(chosen).__name__} for method = {str(method)!r}; allowed: {kind.__name__} (or None)")
    if initial_compression_m is not None and not isinstance(chosen, HBMOptions):
        raise ValueError(f"initial_compression_m: given for method = {str(method)!r}; allowed: the harmonic balance ('hbm') only")
    if isinstance(chosen, HBMOptions):
        return solve_hbm(model, excitation, chosen, initial_compression_m=initial_compression_m)
    if isinstance(chosen, QuasiStaticOptions):
        return solve_quasi_static(model, excitation, chosen)
    if isinstance(chosen, ShootingOptions):
        return solve_shooting(model, excitation, chosen)
    start = solve_hbm(model, excitation, chosen.hbm) if chosen.start is TimeDomainStart.HBM else None
    return solve_time_domain(model, excitation, chosen, start=start)
