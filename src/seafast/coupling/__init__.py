"""Two-way hull-cargo coupling (``vessel.coupling: two_way``): the deck under the saddles and the cargo solved together.

* :mod:`~seafast.coupling.deck_iteration` - the hull's compliance at the sea-fastening points, the deck forces of the
  cargo, and the quasi-Newton iteration of the deck (:func:`~seafast.coupling.deck_iteration.couple_deck`).
* :mod:`~seafast.coupling.hull` - the hull girder under the coupled cargo's forces.
* :mod:`~seafast.coupling.status` - how a row's coupling ended (a typed outcome and its residual).

Theory and checks: ``docs/coupling.md``.
"""
