"""A sea state's transfer functions at its heading, long- or short-crested, and its roll damping (docs/seastate.md).

* **Long-crested** (``sea_state.spreading_exponent`` unset): one direction, ``sea_state.heading_deg``; head seas keep
  the heave-pitch model (today's numbers, bit for bit), any other heading the six-DOF motions.
* **Short-crested**: the cos-2s spreading's quadrature directions ``theta_j`` and weights ``w_j``
  (:func:`~seafast.analyses.seastate.directional.directional_quadrature`), the transfer functions at each, all from the
  six-DOF motions (180 included: one motion model for the whole sum), and ``S_r = S sum_j w_j |H_j|^2``.
* **Quadratic roll damping** (``vessel.roll_damping_quadratic_Nms2_per_rad2``, six-DOF only): linearised
  stochastically over the sea state (:func:`~seafast.excitation.hydrodynamics.roll_damping.stochastic_linearisation`:
  ``B_eq = sqrt(8 / pi) B44_2 sigma_phidot(B_eq)``). The coupled six-DOF roll reduces exactly to
  ``phi_j = F_j / (Z + i omega B_eq)`` with an impedance ``Z`` that does not depend on the heading, so the spread
  sea's ``sigma_phidot^2 = int omega^2 sum_j w_j |F_j|^2 / |Z + i omega B|^2 S d omega`` is that of one roll model
  with the excitation ``sqrt(sum_j w_j |F_j|^2)``: one call, exact. The integral runs over the sea state's grid
  inside the BEM's frequency range (the roll outside it, far from its resonance, is left out of ``sigma_phidot``).
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass, replace

import numpy as np
from numpy.typing import ArrayLike, NDArray

from seafast.analyses.seastate.directional import DirectionalQuadrature, directional_quadrature, weighted_squared_transfer
from seafast.analyses.seastate.spectrum import WaveSpectrum
from seafast.analyses.seastate.transfer import TransferFunctions, six_dof_motions, transfer_functions
from seafast.config.schema import HEAD_SEAS_DEG, Case
from seafast.excitation.hydrodynamics.roll_damping import QuadraticRollDamping, RollModel, StochasticRollResponse, stochastic_linearisation
from seafast.excitation.vessel import VesselCache, shared_vessel_cache
from seafast.model.structure import StructuralModel

__all__ = ["SeaStateTransfer", "sea_state_quadrature", "uses_six_dof", "sea_state_roll_damping", "sea_state_transfer"]


def sea_state_quadrature(case: Case) -> DirectionalQuadrature:
    """The sea state's directions and weights: its heading alone (long-crested) or the cos-2s quadrature.

    Directions in [0, 360) (a direction a rounding below 0 wraps to 360.0 in floating point: taken as 0).
    """
    ss = case.sea_state
    q = directional_quadrature(ss.heading_deg, ss.spreading_exponent)
    return replace(q, heading_deg=np.where(q.heading_deg >= 360.0, 0.0, q.heading_deg))


def uses_six_dof(case: Case) -> bool:
    """Whether the sea state takes the six-DOF motions: off head seas or short-crested (head seas long-crested: 2-DOF)."""
    ss = case.sea_state
    return ss.heading_deg != HEAD_SEAS_DEG or ss.spreading_exponent is not None


@dataclass(frozen=True)
class SeaStateTransfer:
    """Transfer functions of a sea state's directions.

    Attributes
    ----------
    quadrature
        Directions [deg] and weights [-] (one direction of weight 1 for a long-crested sea).
    per_direction
        One :class:`TransferFunctions` per direction, in the quadrature's order, on the same frequencies.
    mean
        The transfer functions at the mean heading (the long-crested sea's own; for a spread sea the six-DOF ones at
        the mean heading, for design waves).
    roll
        The stochastic linearisation of the quadratic roll damping, or None (no quadratic damping, or the heave-pitch
        model of head seas).
    """

    quadrature: DirectionalQuadrature
    per_direction: tuple[TransferFunctions, ...]
    mean: TransferFunctions
    roll: StochasticRollResponse | None

    @property
    def six_dof(self) -> bool:
        """Whether the six-DOF motions serve (every heading but a long-crested head sea)."""
        return self.mean.roll_rad is not None

    def attributes(self) -> dict[str, float | int | str]:
        """seastate.nc's attributes: heading, spreading, motion model and the roll damping's linearisation."""
        q = self.quadrature
        out: dict[str, float | int | str] = {
            "sea_state_heading_deg": float(self.mean.heading_deg),
            "sea_state_directions": int(q.heading_deg.size),
            "motion_model": "six-DOF" if self.six_dof else "heave-pitch (2-DOF)",
        }
        if q.spreading_exponent is not None:
            out["sea_state_spreading_exponent"] = float(q.spreading_exponent)
        if not self.six_dof:
            return out
        r = self.roll
        out["roll_damping_linearisation"] = "none (no quadratic roll damping)" if r is None else str(r.linearisation)
        if r is not None:
            out["roll_equivalent_damping_Nms_per_rad"] = float(r.equivalent_damping_Nms_per_rad)
            out["roll_linearisation_converged"] = int(r.converged)
            out["roll_linearisation_residual_Nms_per_rad"] = float(r.residual_Nms_per_rad)
            out["roll_linearisation_iterations"] = int(r.iterations)
            out["roll_std_rad"] = float(r.roll_std_rad)
        return out

    def describe(self) -> str:
        """One line for the terminal: heading, spreading, motion model, roll damping."""
        q = self.quadrature
        sea = "long-crested" if q.long_crested else f"short-crested, cos-2s s = {q.spreading_exponent:g}, {q.heading_deg.size} directions"
        text = f"heading {self.mean.heading_deg:g} deg, {sea}; {'six-DOF' if self.six_dof else 'heave-pitch (2-DOF)'} motions"
        r = self.roll
        if r is not None:
            state = "converged" if r.converged else f"NOT converged, residual {r.residual_Nms_per_rad:.3g} N m s/rad"
            text += (
                f"; quadratic roll damping linearised stochastically: B_eq = {r.equivalent_damping_Nms_per_rad:.4g} N m s/rad "
                f"({state}), sigma_roll = {np.degrees(r.roll_std_rad):.3g} deg"
            )
        return text

    def squared(self, name: str) -> NDArray[np.float64]:
        """``sum_j w_j |H_j|^2`` of the field ``name`` of :class:`TransferFunctions` (e.g. ``saddle_force_N``) [unit^2/m^2]."""
        return weighted_squared_transfer(np.stack([getattr(tf, name) for tf in self.per_direction]), self.quadrature)


@contextmanager
def _one_vessel() -> Iterator[None]:
    """The directions share one vessel (hull, loading, BEM data): a shared :class:`VesselCache` unless one is shared."""
    if shared_vessel_cache() is not None:
        yield
        return
    with VesselCache().shared():
        yield


def sea_state_roll_damping(case: Case, spectrum: WaveSpectrum) -> StochasticRollResponse | None:
    """The stochastic linearisation of the quadratic roll damping over the sea state (module docstring), or None.

    None when the case has no quadratic roll damping, no motions, or is a long-crested head sea (no roll).
    """
    b2 = case.vessel.roll_damping_quadratic_Nms2_per_rad2
    if not b2 or not uses_six_dof(case):
        return None
    with _one_vessel():
        motions6 = six_dof_motions(case)
    if motions6 is None:
        return None
    grid = motions6.omega_rad_s
    w = spectrum.omega_rad_s
    inside = (w >= grid[0]) & (w <= grid[-1])
    if np.count_nonzero(inside) < 2:
        raise ValueError(
            f"sea state: fewer than two of its frequencies lie inside the BEM's {grid[0]:g}-{grid[-1]:g} rad/s; "
            "the roll damping cannot be linearised over it"
        )
    quadrature = sea_state_quadrature(case)
    models = [motions6.roll_model(w[inside], float(h)) for h in quadrature.heading_deg]
    force = np.sqrt(np.tensordot(quadrature.weight, np.abs(np.stack([m.excitation_Nm_per_m for m in models])) ** 2, axes=(0, 0)))
    model = RollModel(w[inside], models[0].impedance_Nm_per_rad, force.astype(np.complex128))
    return stochastic_linearisation(model, QuadraticRollDamping(float(b2)), spectrum.density_m2_s_per_rad[inside])


def sea_state_transfer(
    case: Case, model: StructuralModel, omega_rad_s: ArrayLike, roll: StochasticRollResponse | None = None
) -> SeaStateTransfer:
    """The transfer functions of the case's sea state at ``omega_rad_s`` [rad/s] (module docstring).

    ``roll``: the sea state's stochastic roll linearisation (:func:`sea_state_roll_damping`), whose ``B_eq`` is added to
    the six-DOF roll damping; None adds nothing.
    """
    quadrature = sea_state_quadrature(case)
    b_eq = 0.0 if roll is None else float(roll.equivalent_damping_Nms_per_rad)
    if not uses_six_dof(case):
        tf = transfer_functions(case, model, omega_rad_s, heading_deg=HEAD_SEAS_DEG)
        return SeaStateTransfer(quadrature, (tf,), tf, None)
    with _one_vessel():
        per = tuple(
            transfer_functions(case, model, omega_rad_s, heading_deg=float(h), six_dof=True, roll_damping_Nms_per_rad=b_eq)
            for h in quadrature.heading_deg
        )
        if quadrature.long_crested:
            return SeaStateTransfer(quadrature, per, per[0], roll)
        mean = transfer_functions(
            case, model, omega_rad_s, heading_deg=case.sea_state.heading_deg, six_dof=True, roll_damping_Nms_per_rad=b_eq
        )
    return SeaStateTransfer(quadrature, per, mean, roll)
