"""The 3-D cargo on its cradles in a sea state: its linear transfer functions and its still-water state.

Off head seas (docs/seastate.md#across-the-ship-cradles-stoppers-and-lashings) ``seafast seastate`` also answers across the ship:
the pads' forces per saddle and side, the side stoppers' forces, the lashings' tensions and the cargo's lateral
displacement at the saddles. The cargo and its restraints are the case's (:func:`~seafast.model.cradle_case.build_cradle_case`),
their dynamics :class:`~seafast.solvers.cradle_dynamics.CradleDynamics` with the vertical plane's Rayleigh damping.

**Excitation per frequency.** The vertical block takes the vertical plane's transfer functions as they are (their
cargo loads and deck motion, :class:`~seafast.analyses.seastate.transfer.TransferFunctions`), the lateral and axial
blocks the six motions of the same heading and roll damping (:func:`~seafast.excitation.rao_extension.extended_six_dof_rao`)
through :func:`~seafast.excitation.cradle_loads.cradle_excitation`: the excitation of a regular wave of unit
amplitude, with the still water as its k = 0 part.

**Linear model.** Linearised about the cargo at rest: the pads and the lashings bilateral, the side stoppers open
(their gap), the set of :attr:`~seafast.solvers.cradle_dynamics.CradleDynamics.damping_set`. Per frequency
``K_d(omega) q = f - K_co x_o - i omega D_co x_o`` (:class:`~seafast.solvers.cradle_dynamics.CradleLinearParts`, its
banded solves per uncoupled block) and every engagement's transfer function ``A q + E x_o`` [m/m]: the first
harmonic of the harmonic balance's linear part (:func:`~seafast.solvers.cradle_dynamics.cradle_operators`) to
round-off. A pad's or lashing's force is ``k`` times its engagement; a stopper's engagement (its overclosure beyond
the gap, ``+-v - c``) is that of the cargo's motion across, the stopper carrying nothing in the linear model.

**Still water.** The exact statics of the still-water loads and deck deflection
(:func:`~seafast.solvers.references.cradle_quasi_static.solve_cradle_quasi_static` of a wave of zero amplitude):
the pads compressed, the lashings at their pretension, the stoppers open at rest.

Convention as the vertical plane: ``x(t) = Re(X exp(i omega t))`` per metre of ``zeta(t) = zeta_a cos(omega t)``
at midship. Units: SI.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from seafast.analyses.cradle_run import cradle_dynamics_of_case
from seafast.analyses.seastate.transfer import TransferFunctions, six_dof_motions
from seafast.config.schema import HEAD_SEAS_DEG, Case
from seafast.excitation.cradle_loads import CradleExcitation, cradle_excitation
from seafast.excitation.harmonic import HarmonicExcitation
from seafast.excitation.hydrodynamics.heading_motions import SixDofMotions
from seafast.excitation.rao_extension import extended_six_dof_rao
from seafast.excitation.vessel import vessel_excitation
from seafast.model.cradle_case import CradleCase, build_cradle_case
from seafast.model.structure import StructuralModel
from seafast.solvers.cradle_dynamics import CradleDynamics
from seafast.solvers.references.cradle_quasi_static import solve_cradle_quasi_static

__all__ = [
    "CradleSeaModel",
    "CradleTransfer",
    "CradleStillWater",
    "cradle_sea_model",
    "cradle_unit_excitations",
    "cradle_linear_transfer",
    "cradle_still_water",
    "cradle_transfer_functions",
]


@dataclass(frozen=True)
class CradleSeaModel:
    """What the cradle quantities of a sea state need beside the transfer functions.

    Attributes
    ----------
    cradle
        The case's cargo on its cradles.
    dynamics
        Its dynamics.
    still_water
        The vertical plane's still-water excitation (k = 0 row): deck deflection and loads.
    motions
        The six-DOF motions at every heading.
    axis_from_reference_m
        (x, y, z) of the cargo axis at its aft end from the motions' reference point [m].
    draught_m, gravity_m_per_s2
        For the six-DOF RAOs beyond the BEM grid [m], g [m/s^2].
    """

    cradle: CradleCase
    dynamics: CradleDynamics
    still_water: HarmonicExcitation
    motions: SixDofMotions | None
    axis_from_reference_m: tuple[float, float, float]
    draught_m: float
    gravity_m_per_s2: float


def cradle_sea_model(case: Case, model: StructuralModel) -> CradleSeaModel:
    """The case's cradles, their dynamics, the still water and the six motions (:class:`CradleSeaModel`).

    Raises
    ------
    ValueError
        If the cradles cannot be built from the case (naming the key).
    """
    head = (
        case
        if case.wave.heading_deg == HEAD_SEAS_DEG
        else case.model_copy(update={"wave": case.wave.model_copy(update={"heading_deg": HEAD_SEAS_DEG})})
    )
    vessel = vessel_excitation(head)
    cradle = build_cradle_case(case, model)
    motions = six_dof_motions(case)
    points = vessel.cargo_points
    if motions is None or points is None:
        axis = (float(model.cargo.node_x_m[0]), 0.0, 0.0)
    else:
        axis = (
            vessel.cargo_aft_end_x_m - float(motions.reference_x_m),
            float(points.y_m),
            float(points.z_m) - float(motions.reference_z_m),
        )
    return CradleSeaModel(
        cradle,
        cradle_dynamics_of_case(cradle),
        vessel.cargo_excitation(model, head).static_part(),
        motions,
        axis,
        float(case.vessel.draft_m),
        float(case.model.gravity_m_per_s2),
    )


def cradle_unit_excitations(
    sea: CradleSeaModel, tf: TransferFunctions, indices: Sequence[int] | None = None
) -> tuple[CradleExcitation, ...]:
    """The excitation of the 3-D cargo by a regular wave of unit amplitude at ``tf``'s frequencies (``indices``: those).

    Still water at k = 0; at k = 1 the vertical block's loads and the deck's motion of ``tf``, the lateral and axial
    blocks' of the six motions at ``tf``'s heading and roll damping (the same RAOs ``tf`` was built from).
    """
    chosen = np.arange(tf.omega_rad_s.size) if indices is None else np.asarray(indices, dtype=np.intp)
    w = tf.omega_rad_s[chosen]
    rao = _six_motions(sea, tf, w)
    static, cargo = sea.still_water, sea.cradle.cargo
    out = []
    for j, (i, om) in enumerate(zip(chosen, w, strict=True)):
        vertical = HarmonicExcitation(
            float(om),
            np.vstack([static.deck_displacement[:1], tf.deck_displacement[i][None]]),
            np.vstack([static.cargo_load_N[:1], tf.cargo_load_N[i][None]]),
            np.vstack([static.cargo_line_load_N_per_m[:1], tf.cargo_line_load_N_per_m[i][None]]),
            f"regular wave of unit amplitude at {om:.4g} rad/s, heading {tf.heading_deg:g} deg (transfer functions)",
        )
        model = sea.cradle.model
        out.append(cradle_excitation(cargo, vertical, rao[j], model.saddle_x_m, sea.axis_from_reference_m, sea.gravity_m_per_s2))
    return tuple(out)


@dataclass(frozen=True)
class CradleTransfer:
    """Linear transfer functions of the cradle quantities per metre of wave amplitude, at one heading.

    Attributes
    ----------
    omega_rad_s
        (n_w,) [rad/s].
    heading_deg
        The wave heading [deg].
    engagement_m
        (n_w, m) every element's engagement (pads port then starboard per saddle, stoppers, lashings) [m/m].
    element_force_N
        (n_w, m) ``k`` times the engagement for the pads and lashings, 0 for the stoppers (open in the linear
        model) [N/m].
    lateral_displacement_m
        (n_w, n_s) the cargo's lateral displacement ``v`` (to port +) relative to the deck at each saddle [m/m].
    pad_count, stopper_count
        Pads (two per saddle) and stoppers, to split the elements.
    """

    omega_rad_s: NDArray[np.float64]
    heading_deg: float
    engagement_m: NDArray[np.complex128]
    element_force_N: NDArray[np.complex128]
    lateral_displacement_m: NDArray[np.complex128]
    pad_count: int
    stopper_count: int


def _lateral_dofs(dynamics: CradleDynamics, saddle_x_m: NDArray[np.float64]) -> NDArray[np.intp]:
    """The lateral DOF ``v`` of the node at each saddle."""
    cargo = dynamics.problem.cargo
    return np.array([cargo.node_dofs(cargo.node_at(float(x)))[1] for x in saddle_x_m], dtype=np.intp)


def _linear_response(
    dynamics: CradleDynamics, w: NDArray[np.float64], f: NDArray[np.complex128], xo: NDArray[np.complex128], heading_deg: float
) -> CradleTransfer:
    """The linear model's response to the loads ``f`` (n_w, 5 n) and deck motion ``xo`` (n_w, n_o) at ``w`` (n_w,)."""
    problem = dynamics.problem
    included = dynamics.damping_set
    parts = dynamics.linear_parts(included)
    K_co, D_co = parts.deck_coupling
    load = f - xo @ K_co.T - 1j * w[:, None] * (xo @ D_co.T)
    q = parts.solve_stack(w, load[:, :, None].astype(complex))[:, :, 0]
    s = q @ problem.engagement_matrix.T + xo @ dynamics.deck_engagement.T
    force = np.where(included, problem.element_stiffness_N_per_m, 0.0) * s
    saddles = np.array([pair.x_m for pair in problem.pad_pairs], dtype=float)
    lateral = q[:, _lateral_dofs(dynamics, saddles)]
    return CradleTransfer(w, float(heading_deg), s, force, lateral, 2 * len(problem.pad_pairs), len(problem.stoppers))


def cradle_linear_transfer(dynamics: CradleDynamics, excitations: Sequence[CradleExcitation], heading_deg: float) -> CradleTransfer:
    """The linear model's response (module docstring) to the k = 1 part of each excitation, one per frequency.

    Parameters
    ----------
    dynamics
        The 3-D cargo on its cradles.
    excitations
        One per frequency (increasing), of a unit wave (:func:`cradle_unit_excitations`).
    heading_deg
        The waves' heading [deg], carried for people.
    """
    w = np.array([e.omega_rad_s for e in excitations], dtype=float)
    f = np.stack([e.cargo_load_N[1] for e in excitations])
    xo = np.stack([e.deck_displacement[1] for e in excitations])
    return _linear_response(dynamics, w, f, xo, heading_deg)


def _motion_loads(sea: CradleSeaModel, tf: TransferFunctions) -> NDArray[np.complex128]:
    """The unit waves' loads on the 3-D cargo (n_w, 5 n): those of :func:`cradle_unit_excitations`, superposed.

    The loads of the lateral and axial blocks are linear in the six motions and affine in omega^2 (the reading
    ``-omega^2 T q + g G q``): each motion's load at omega = 1 and 2 gives both parts, and every frequency is their
    sum (the same numbers as an excitation per frequency, without n_w assemblies). The vertical block is ``tf``'s.
    """
    w = tf.omega_rad_s
    cargo, model, n = sea.cradle.cargo, sea.cradle.model, sea.cradle.cargo.node_count
    rao = _six_motions(sea, tf, w)
    zero = np.zeros((2, model.deck_dof_count), dtype=complex)
    unit = np.zeros((2, 6, cargo.dof_count), dtype=complex)
    for i, om in enumerate((1.0, 2.0)):
        vertical = HarmonicExcitation(om, zero, np.zeros((2, 2 * n), dtype=complex), np.zeros((2, n - 1), dtype=complex))
        for k in range(6):
            e = cradle_excitation(
                cargo, vertical, np.eye(6)[k].astype(complex), model.saddle_x_m, sea.axis_from_reference_m, sea.gravity_m_per_s2
            )
            unit[i, k] = e.cargo_load_N[1]
    slope = (unit[1] - unit[0]) / 3.0  # d load / d omega^2, per motion
    base = unit[0] - slope
    load = np.nan_to_num(rao, nan=0.0) @ base + (w**2)[:, None] * (np.nan_to_num(rao, nan=0.0) @ slope)
    load[:, : 2 * n] = tf.cargo_load_N
    return load


def _six_motions(sea: CradleSeaModel, tf: TransferFunctions, w: NDArray[np.float64]) -> NDArray[np.complex128]:
    """The six RAOs (n_w, 6) at ``w``, ``tf``'s heading and roll damping (zero without motions)."""
    if sea.motions is None:
        return np.zeros((w.size, 6), dtype=complex)
    return extended_six_dof_rao(
        sea.motions,
        w,
        tf.heading_deg,
        gravity_m_per_s2=sea.gravity_m_per_s2,
        draught_m=sea.draught_m,
        additional_roll_damping_Nms_per_rad=tf.roll_damping_Nms_per_rad,
    )


def cradle_transfer_functions(sea: CradleSeaModel, tf: TransferFunctions) -> CradleTransfer:
    """The cradle quantities' transfer functions at ``tf``'s frequencies and heading (module docstring)."""
    return _linear_response(sea.dynamics, tf.omega_rad_s, _motion_loads(sea, tf), tf.deck_displacement, tf.heading_deg)


@dataclass(frozen=True)
class CradleStillWater:
    """The cargo's exact still-water state on its cradles.

    Attributes
    ----------
    engagement_m, element_force_N
        (m,) every element's engagement [m] and force [N] (``k max(s, 0)``).
    lateral_displacement_m
        (n_s,) ``v`` at each saddle [m].
    converged
        The statics were exact (:class:`~seafast.solvers.outcome.SolverOutcome`).
    """

    engagement_m: NDArray[np.float64]
    element_force_N: NDArray[np.float64]
    lateral_displacement_m: NDArray[np.float64]
    converged: bool


def cradle_still_water(sea: CradleSeaModel) -> CradleStillWater:
    """The exact statics of the still-water loads and deck deflection (a wave of zero amplitude)."""
    static = sea.still_water
    n = sea.cradle.cargo.dof_count
    zero_wave = HarmonicExcitation(
        1.0,
        np.vstack([static.deck_displacement[:1], np.zeros_like(static.deck_displacement[:1])]),
        np.vstack([static.cargo_load_N[:1], np.zeros_like(static.cargo_load_N[:1])]),
        np.vstack([static.cargo_line_load_N_per_m[:1], np.zeros_like(static.cargo_line_load_N_per_m[:1])]),
        "still water",
    )
    excitation = cradle_excitation(
        sea.cradle.cargo,
        zero_wave,
        np.zeros(6, dtype=complex),
        sea.cradle.model.saddle_x_m,
        sea.axis_from_reference_m,
        sea.gravity_m_per_s2,
    )
    assert excitation.cargo_load_N.shape[1] == n
    response = solve_cradle_quasi_static(sea.dynamics, excitation, time_samples=2)
    saddles = np.array([pair.x_m for pair in sea.dynamics.problem.pad_pairs], dtype=float)
    v = response.cargo_displacement_m[0, _lateral_dofs(sea.dynamics, saddles)]
    return CradleStillWater(
        response.engagement_m[0].copy(), response.element_force_N[0].copy(), np.asarray(v, dtype=float), response.converged
    )
