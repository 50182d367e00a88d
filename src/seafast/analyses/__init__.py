"""The analyses: each takes a case (and what it needs computed before) and returns typed records.

* :mod:`~seafast.analyses.run` - one case end to end: its four rows (linear and nonlinear, still water
  and wave) solved once, and the case's result (summary, ``results.nc``).
* :mod:`~seafast.analyses.sweep` - the nonlinear frequency response by continuation: the branch, its
  table per point, the stability of each point, the physically meaningful range.
* :mod:`~seafast.analyses.seastate` - irregular seas: spectra, transfer functions, linear spectral
  extremes, design waves, the nonlinear Monte Carlo reference.
* :mod:`~seafast.analyses.operability` - allowable significant wave heights per peak period.
* :mod:`~seafast.analyses.axial` - the axial sliding of the cargo on friction (with
  :mod:`~seafast.analyses.axial_coupling`, the friction's estimated effect on the saddle forces).

An analysis runs the solvers; it never prints, reads or writes files (the command line and
:mod:`seafast.output` do). The labelled datasets of its records are :mod:`seafast.results`'.
"""
