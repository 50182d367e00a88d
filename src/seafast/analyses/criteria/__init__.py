"""Design criteria: the standard's default motion criteria as quasi-static load cases on the cargo in its cradles.

* :mod:`~seafast.analyses.criteria.standard` - the default motion criteria table and its selection by vessel size.
* :mod:`~seafast.analyses.criteria.load_cases` - the load cases (roll or pitch with heave, each sign) and the
  apparent gravity at any cargo point.
* :mod:`~seafast.analyses.criteria.check` - each case solved exactly on the cradles, stoppers and lashings, and
  checked against the case's limits.
* :mod:`~seafast.analyses.criteria.alpha_factor` - the alpha factor of a weather-restricted operation (the standard's tables).
* :mod:`~seafast.analyses.criteria.route_extremes` - an unrestricted operation's 10-year monthly extreme Hs per route leg.
* :mod:`~seafast.analyses.criteria.operation_class` - the operation class on the allowable sea states: weather-routing
  limits, or the route's design sea states checked.
* :mod:`~seafast.analyses.criteria.design` - the design format (LRFD combinations or allowable stress) and the
  friction credit.
* :mod:`~seafast.analyses.criteria.motion_statistics` - the ship's motions in the case's sea state at a heading: their
  covariances, most probable maxima and expected simultaneous values.
* :mod:`~seafast.analyses.criteria.motion_branch` - the motion-analysis branch per heading beside the default
  criteria, and the governing case over both.

Its files (criteria.csv): :mod:`seafast.output.criteria`. Theory, sources and verification: ``docs/criteria.md``.
"""
