"""Contact laws of the compression-only saddle springs (docs/theory.md#6-contact-laws).

A saddle's compression is ``delta = z_deck - z_cargo`` [m], positive when compressed. The
contact law gives the (upward, on the cargo) force ``f(delta)`` [N] of the saddle's
compression-only part with stiffness ``k`` [N/m], and its derivative ``df/ddelta`` [N/m]:

``exact``
    ``f = k max(delta, 0)``; generalised derivative ``k H(delta)`` with ``H(0) = 1/2`` (an
    element of Clarke's generalised Jacobian, used by semi-smooth Newton).
``tanh``
    The source's C1 regularisation ``f = k delta (1 + tanh(kappa delta)) / 2``. It produces a
    slight *tensile* force just after separation (minimum ``-0.139 k / kappa`` at
    ``kappa delta = -0.64``); ``kappa`` = ``regularisation_per_m`` (default 1000 1/m).
``softplus``
    ``f = k ln(1 + exp(kappa delta)) / kappa``, smooth and never negative (it overestimates
    the force by at most ``k ln 2 / kappa`` at ``delta = 0``), evaluated without overflow.

All functions are vectorised: ``delta`` of any shape, ``stiffness`` broadcast against it
(typically shape (n_saddles,) against (N, n_saddles)).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import cast

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.special import expit

from seafast.config.modes import ContactLawKind

__all__ = ["ContactLaw", "contact_law"]


@dataclass(frozen=True)
class ContactLaw:
    """A saddle contact law: force and derivative as functions of the compression.

    Parameters
    ----------
    name
        The law (:class:`~seafast.config.modes.ContactLawKind`, or its value).
    regularisation_per_m
        Sharpness kappa [1/m] of the ``tanh`` and ``softplus`` laws (ignored by ``exact``),
        > 0.
    """

    name: ContactLawKind = ContactLawKind.TANH
    regularisation_per_m: float = 1000.0

    def __post_init__(self) -> None:
        if not isinstance(self.name, str) or self.name not in set(ContactLawKind):
            raise ValueError(f"contact_law = {self.name!r}; accepted values: {', '.join(ContactLawKind)}")
        object.__setattr__(self, "name", ContactLawKind(self.name))  # a value given becomes the member
        kappa = float(self.regularisation_per_m)
        if not np.isfinite(kappa) or kappa <= 0.0:
            raise ValueError(f"regularisation_per_m = {self.regularisation_per_m!r}; must be a finite number > 0 [1/m]")

    @property
    def is_smooth(self) -> bool:
        """False for the exact (kinked) law."""
        return self.name is not ContactLawKind.EXACT

    @property
    def can_pull(self) -> bool:
        """True if the law can produce a tensile (negative) force (only ``tanh``)."""
        return self.name is ContactLawKind.TANH

    def force(self, compression_m: ArrayLike, stiffness_N_per_m: ArrayLike) -> NDArray[np.float64]:
        """Contact force on the cargo [N], positive upward."""
        return self.force_and_derivative(compression_m, stiffness_N_per_m)[0]

    def derivative(self, compression_m: ArrayLike, stiffness_N_per_m: ArrayLike) -> NDArray[np.float64]:
        """``df/ddelta`` [N/m] (generalised derivative for the exact law)."""
        return self.force_and_derivative(compression_m, stiffness_N_per_m)[1]

    def force_and_derivative(
        self, compression_m: ArrayLike, stiffness_N_per_m: ArrayLike
    ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Force [N] and its derivative [N/m] in one pass."""
        d = np.asarray(compression_m, dtype=float)
        k = np.asarray(stiffness_N_per_m, dtype=float)
        kappa = float(self.regularisation_per_m)
        if self.name is ContactLawKind.EXACT:
            return k * np.maximum(d, 0.0), k * np.heaviside(d, 0.5)
        if self.name is ContactLawKind.TANH:
            th = np.tanh(kappa * d)
            half = 0.5 * (1.0 + th)
            return k * d * half, k * (half + 0.5 * kappa * d * (1.0 - th * th))
        # softplus
        x = kappa * d
        return k * np.logaddexp(0.0, x) / kappa, k * expit(x)

    def with_regularisation(self, regularisation_per_m: float) -> ContactLaw:
        """The same law with another kappa [1/m]."""
        return ContactLaw(self.name, regularisation_per_m)


def contact_law(name: ContactLawKind | str, regularisation_per_m: float = 1000.0) -> ContactLaw:
    """The contact law called ``name`` (a :class:`~seafast.config.modes.ContactLawKind` or its value).

    Raises
    ------
    ValueError
        For an unknown name (the message lists the accepted ones) or kappa <= 0.
    """
    return ContactLaw(cast(ContactLawKind, name), float(regularisation_per_m))  # ContactLaw checks the name and converts it
