"""The stuck linear transfer functions of the 3-D cargo on frictional pads in a sea state.

The linear system of the frictional march (:mod:`seafast.solvers.cradle_friction_march`): every element bilateral
and every pad's tangential spring ``k_t`` stuck at its slider's rest. Per frequency of a regular wave of unit
amplitude (:func:`~seafast.analyses.seastate.cradle_transfer.cradle_unit_excitations`) its first harmonic is
:func:`~seafast.solvers.cradle_friction.stuck_linear_solution`'s (the harmonic balance's linear part per harmonic,
``(I + G K_t)^-1``, at the wave's frequency): every element's engagement, every pad's two tangential motions and the
cargo's lateral displacement at each saddle. A random sea's stuck linear record is their superposition (the
synthesis of :mod:`seafast.analyses.seastate.synthesis`), the record
:func:`~seafast.solvers.cradle_friction_record.march_friction_record` marches the frictional correction along. The
Monte Carlo's frictional realisations (:mod:`seafast.analyses.seastate.cradle_friction_realisation`) synthesise it.

Convention as the vertical plane: ``x(t) = Re(X exp(i omega t))`` per metre of ``zeta(t) = zeta_a cos(omega t)``.
Units: engagements and motions [m/m].
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from seafast.analyses.seastate.cradle_transfer import CradleSeaModel, cradle_unit_excitations
from seafast.analyses.seastate.transfer import TransferFunctions
from seafast.solvers.cradle_friction import stuck_linear_solution
from seafast.solvers.pad_tangential import PadTangents

__all__ = ["StuckTransfer", "stuck_transfer_functions"]


@dataclass(frozen=True)
class StuckTransfer:
    """The stuck linear system's still water and transfer functions, channels (m engagements, 2 P tangential motions
    per pad (circumferential, axial), n_s lateral displacements at the saddles).

    Attributes
    ----------
    omega_rad_s
        (n_w,) [rad/s].
    still_m
        (m + 2 P + n_s,) the still water's (the k = 0 part) [m]; the tangential motions are the sliders' rest where
        ``tangents`` were relaxed in this still water.
    transfer_m
        (n_w, m + 2 P + n_s) per metre of wave amplitude [m/m].
    lateral_dofs
        (n_s,) the cargo's lateral DOF at each saddle (the last n_s channels).
    """

    omega_rad_s: NDArray[np.float64]
    still_m: NDArray[np.float64]
    transfer_m: NDArray[np.complex128]
    lateral_dofs: NDArray[np.intp]


def stuck_transfer_functions(sea: CradleSeaModel, tf: TransferFunctions, tangents: PadTangents) -> StuckTransfer:
    """The stuck linear transfer functions at ``tf``'s frequencies and heading (module docstring).

    Parameters
    ----------
    sea
        The cargo on its cradles in the sea state (:func:`~seafast.analyses.seastate.cradle_transfer.cradle_sea_model`).
    tf
        The vertical plane's transfer functions (their frequencies, heading and roll damping).
    tangents
        The pads' tangential kinematics and friction, the sliders' rest (:func:`~seafast.solvers.cradle_friction.relaxed_at`).
    """
    dynamics = sea.dynamics
    cargo = dynamics.problem.cargo
    lateral = np.array([cargo.node_dofs(cargo.node_at(pair.x_m))[1] for pair in dynamics.problem.pad_pairs], dtype=np.intp)
    still, rows = None, []
    for unit in cradle_unit_excitations(sea, tf):
        z, X = stuck_linear_solution(dynamics, unit, tangents)
        rows.append(np.concatenate([z[1] - 1j * z[2], X[1, lateral]]))
        if still is None:
            still = np.concatenate([z[0], X[0, lateral].real])
    assert still is not None
    return StuckTransfer(np.asarray(tf.omega_rad_s, dtype=float), still, np.array(rows, dtype=complex), lateral)
