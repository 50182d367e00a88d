"""The nonlinear frequency response of a case by pseudo-arclength continuation.

* :mod:`~seafast.analyses.sweep.frequency` - :func:`frequency_sweep`, the sweep end to end (structural
  or wave; the held excitation, the branch, the table).
* :mod:`~seafast.analyses.sweep.table` - :class:`SweepTable`, the branch's points as columns.
* :mod:`~seafast.analyses.sweep.stability` - each point's Floquet verdict and its tolerance.
* :mod:`~seafast.analyses.sweep.range` - where a point leaves the physically meaningful range.
"""
