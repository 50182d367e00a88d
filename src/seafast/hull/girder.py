"""The hull girder: its section properties and the factorised free-free Timoshenko beam.

:class:`HullGirder` holds what the hull-girder analyses need to know about the ship (hull form,
I, A_s, E, G, water density, gravity); :class:`HullBeam` is its beam on a node grid, factorised
once and solved for many element loads; :func:`shear_moment` integrates an element load to the
shear force and bending moment, and :func:`end_resultants` gives their values at the FP alone
(the residual of the hydrostatic balance). Conventions: :mod:`seafast.hull`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.linalg
from numpy.typing import NDArray

from seafast.model.beam import assemble_beam_stiffness_banded
from seafast.vessel.hull_form import HullForm

__all__ = [
    "DEFAULT_SHEAR_AREA_M2",
    "HullGirder",
    "HullBeam",
    "shear_moment",
    "resultant_weights",
    "end_resultants",
]

FloatArray = NDArray[np.float64]

DEFAULT_SHEAR_AREA_M2 = 0.8
"""Default effective vertical shear area of the hull girder [m^2].

Vertical shear is carried by the longitudinal vertical plating: the two side shells and the
two longitudinal bulkheads of the wing (ballast) tanks of a heavy-lift vessel, i.e. four webs
of about 11 m effective depth and 18 mm mean thickness: 4 x 11 x 0.018 = 0.79 m^2. (For the
same section, I = 103.8 m^4 corresponds to deck and bottom flanges of ~1.3 m^2 each at
+/- 6 m, consistent with a ~12 m deep hull.)"""


@dataclass(frozen=True)
class HullGirder:
    """The hull as a Timoshenko beam with wall-sided buoyancy.

    Parameters
    ----------
    hull
        Hull form (waterline breadths, design draught, section-area coefficient).
    second_moment_m4
        Vertical second moment of area of the hull girder I [m^4] (base 103.8).
    shear_area_m2
        Effective vertical shear area A_s [m^2] (default :data:`DEFAULT_SHEAR_AREA_M2`).
    youngs_modulus_Pa
        Young's modulus E [Pa].
    shear_modulus_Pa
        Shear modulus G [Pa]; ``None`` gives ``E / 2.6`` (steel, nu = 0.3).
    water_density_kg_per_m3, gravity_m_per_s2
        Sea water density and gravity.
    """

    hull: HullForm
    second_moment_m4: float = 103.8
    shear_area_m2: float = DEFAULT_SHEAR_AREA_M2
    youngs_modulus_Pa: float = 210e9
    shear_modulus_Pa: float | None = None
    water_density_kg_per_m3: float = 1025.0
    gravity_m_per_s2: float = 9.81

    def __post_init__(self) -> None:
        if self.shear_modulus_Pa is None:
            object.__setattr__(self, "shear_modulus_Pa", self.youngs_modulus_Pa / 2.6)
        for name in (
            "second_moment_m4",
            "shear_area_m2",
            "youngs_modulus_Pa",
            "shear_modulus_Pa",
            "water_density_kg_per_m3",
            "gravity_m_per_s2",
        ):
            v = getattr(self, name)
            if not (v > 0):  # inf shear area is allowed (Euler-Bernoulli)
                raise ValueError(f"hull girder: {name} = {v!r}; must be > 0")

    @property
    def length_m(self) -> float:
        """Hull length AP-FP [m]."""
        return self.hull.length_m

    @property
    def midship_x_m(self) -> float:
        """x of midship (L/2 from the AP) [m]."""
        return float(self.hull.station_x_m[0]) + 0.5 * self.hull.length_m

    @property
    def bending_stiffness_Nm2(self) -> float:
        """EI [N m^2]."""
        return float(self.youngs_modulus_Pa * self.second_moment_m4)

    @property
    def shear_stiffness_N(self) -> float:
        """G A_s [N] (``inf`` for an Euler-Bernoulli hull)."""
        shear_modulus_Pa = self.shear_modulus_Pa
        assert shear_modulus_Pa is not None  # __post_init__ sets the default E / 2.6
        return float(shear_modulus_Pa * self.shear_area_m2)

    @property
    def buoyancy_per_draught_N_per_m2(self) -> float:
        """rho g C_s [N/m^3]: buoyancy per metre = this x breadth x local draught."""
        return float(self.water_density_kg_per_m3 * self.gravity_m_per_s2 * self.hull.section_area_coefficient)


def shear_moment(h: FloatArray, qa: NDArray, qb: NDArray) -> tuple[NDArray, NDArray]:
    """Exact V and M at the nodes for a load linear in each element (leading axes broadcast)."""
    dV = 0.5 * h * (qa + qb)
    V = np.concatenate([np.zeros(dV.shape[:-1] + (1,)), np.cumsum(dV, axis=-1)], axis=-1)
    dM = V[..., :-1] * h + h * h * (2.0 * qa + qb) / 6.0
    M = np.concatenate([np.zeros(dM.shape[:-1] + (1,)), np.cumsum(dM, axis=-1)], axis=-1)
    return V, M


def resultant_weights(h: FloatArray) -> tuple[FloatArray, FloatArray]:
    """Weights (n_el, 2) of the element-start and element-end loads in (V(L), M(L)).

    ``V(L) = sum h (qa + qb) / 2`` and ``M(L) = sum_j dV_j (L - x_{j+1}) + h^2 (2 qa + qb) / 6``:
    the end values of :func:`shear_moment` without the running integrals.
    """
    beyond = np.concatenate([np.cumsum(h[::-1])[::-1][1:], [0.0]])  # L - x_{j+1}, element j's far end
    half = 0.5 * h
    return np.stack([half, half * beyond + h * h / 3.0], axis=-1), np.stack([half, half * beyond + h * h / 6.0], axis=-1)


def end_resultants(h: FloatArray, qa: NDArray, qb: NDArray) -> NDArray:
    """(V(L), M(L)) stacked on the last axis, for the element loads (see :func:`resultant_weights`)."""
    start, end = resultant_weights(h)
    return qa @ start + qb @ end


_HALF_BANDWIDTH = 3


@dataclass(frozen=True)
class HullBeam:
    """Factorised free-free Timoshenko hull beam with the two end deflections constrained.

    Attributes
    ----------
    x, h
        Node positions from the AP [m], shape (n_x,), and element lengths [m], shape (n_x - 1,).
    EI, GA
        Bending stiffness [N m^2] and shear stiffness [N] (``inf``: Euler-Bernoulli).
    fixed
        The two constrained DOFs (the deflections at AP and FP).
    factor
        The banded Cholesky factor of the constrained stiffness (``scipy.linalg.cho_solve_banded``).
    """

    x: FloatArray
    h: FloatArray
    EI: float
    GA: float
    fixed: tuple[int, int]
    factor: tuple

    @classmethod
    def build(cls, x: FloatArray, girder: HullGirder) -> HullBeam:
        """Assemble and factorise the beam of ``girder`` on the nodes ``x`` [m]."""
        n_el = x.size - 1
        EI = girder.bending_stiffness_Nm2
        GA = girder.shear_stiffness_N
        gas = None if np.isinf(GA) else np.full(n_el, GA)
        # a chain of 2-node elements is banded (half-bandwidth 3): assembled in band storage and
        # factorised by a banded Cholesky, O(n). The two end deflections are held at zero by
        # decoupling their rows and columns (unit diagonal, zero load): with exact zeros the
        # other DOFs see the same elimination as in the reduced system.
        band = assemble_beam_stiffness_banded(x, np.full(n_el, EI), shear_stiffness_N=gas)
        n_dof = 2 * x.size
        fixed = (0, n_dof - 2)
        for dof in fixed:
            for d in range(1, _HALF_BANDWIDTH + 1):
                if dof + d < n_dof:
                    band[_HALF_BANDWIDTH - d, dof + d] = 0.0  # row dof, columns to its right
                if dof - d >= 0:
                    band[_HALF_BANDWIDTH - d, dof] = 0.0  # column dof, rows above
            band[_HALF_BANDWIDTH, dof] = 1.0
        factor = (scipy.linalg.cholesky_banded(band, check_finite=False), False)
        return cls(x, np.diff(x), EI, GA, fixed, factor)

    def solve(self, qa: NDArray, qb: NDArray, V: NDArray) -> tuple[NDArray, NDArray]:
        """Nodal deflection [m] and slope dz/dx [rad], shape (..., n_x), for element loads."""
        h = self.h
        lead = qa.shape[:-1]
        n = self.x.size
        f = np.zeros(lead + (2 * n,))
        f[..., 0:-2:2] += h * (7.0 * qa + 3.0 * qb) / 20.0
        f[..., 1:-1:2] += h * h * (3.0 * qa + 2.0 * qb) / 60.0
        f[..., 2::2] += h * (3.0 * qa + 7.0 * qb) / 20.0
        f[..., 3::2] += -h * h * (2.0 * qa + 3.0 * qb) / 60.0
        f[..., list(self.fixed)] = 0.0
        u = scipy.linalg.cho_solve_banded(self.factor, f.reshape(-1, 2 * n).T, check_finite=False).T.reshape(lead + (2 * n,))
        z = u[..., 0::2]
        psi = u[..., 1::2]
        slope = psi if np.isinf(self.GA) else psi - V / self.GA
        return z, slope
