"""Two-way hull-cargo coupling (``vessel.coupling: two_way``): the deck under the saddles and the cargo solved together.

* :mod:`~seafast.coupling.deck_loads` - the loads exchanged on the hull (the cargo's deck forces, its one-way spread
  load) and the hull's compliance under them at the sea-fastening points.
* :mod:`~seafast.coupling.deck_iteration` - the quasi-Newton iteration of the deck until hull and cargo agree
  (:func:`~seafast.coupling.deck_iteration.couple_deck`).
* :mod:`~seafast.coupling.hull` - the hull girder under the coupled cargo's forces.
* :mod:`~seafast.coupling.status` - how a row's coupling ended (a typed outcome and its residual).

Theory and checks: ``docs/coupling.md``.
"""
