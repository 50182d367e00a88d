"""The cargo across the ship built from a case: its cradles, side stoppers and lashings (docs/criteria.md).

The parts of a :class:`seafast.solvers.transverse_statics.CradleProblem` (built on floor 5, from these): the 3-D
cargo (:mod:`seafast.model.cargo3d`) on today's beam of :func:`seafast.model.from_case.build_model`,
and at every saddle:

* a pad pair (:class:`~seafast.model.cradle.PadPair`) at ``seafastening.saddle_contact_angle_deg``, its
  vertical stiffness with both pads in contact the saddle's ``k_sad`` less the lashing wires' vertical
  stiffness there (so that the saddle with its lashings is ``k_sad`` vertically, as in the vertical model);
* with ``seafastening.side_stopper.gap_m`` and ``.stiffness_N_per_m`` set, a side stopper port and
  starboard;
* an axial hold: a bilateral spring of :data:`AXIAL_HOLD_N_PER_M` on the cargo's axial DOF, standing
  for the saddles' friction and end stops (the frictionless pads hold nothing along the axis; the
  friction check is the axial analysis's, docs/axial.md).

At every lashed saddle a fore and an aft wire in the ship's vertical-longitudinal plane at
``seafastening.lashing.angle_deg`` from the deck (today's meaning of the lashing keys, docs/axial.md),
attached at the cargo's axis (the lugs' offset from the axis is left out): each wire has stiffness
``k_l / 2`` and pretension ``T_l / (2 n sin(angle))``, so that the pair pulls the cargo down by today's
``T_l / n`` and holds it axially with today's ``k_l cos^2(angle)``. With ``k_l = 0`` the lashings are
their pretension alone (a constant downward force at each lashed saddle).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from seafast.config.schema import Case
from seafast.model.cargo3d import Cargo3D, build_cargo3d
from seafast.model.cradle import Lashing, PadPair, Side, SideStopper
from seafast.model.from_case import build_model, cargo_geometry
from seafast.model.structure import StructuralModel

__all__ = ["CradleCase", "build_cradle_case", "AXIAL_HOLD_N_PER_M"]

AXIAL_HOLD_N_PER_M = 1e12
"""Axial spring per saddle standing for its friction and end stops [N/m]: rigid (the axial analysis's default
stick stiffness, docs/axial.md)."""


@dataclass(frozen=True)
class CradleCase:
    """A case's cargo on its cradles, stoppers and lashings.

    Attributes
    ----------
    cargo
        The 3-D cargo beam.
    pad_pairs, stoppers, lashings
        The unilateral elements (saddles aft to fore; stoppers port then starboard per saddle; lashing
        wires fore then aft per lashed saddle).
    spring_diagonal_N_per_m
        The axial holds on the cargo's DOFs [N/m] (5 n,).
    load_N
        Loads beside the weight [N]: the pretension of stiffness-free lashings (zero otherwise), (5 n,).
    model
        Today's vertical-plane model the cargo beam comes from.
    saddle_x_m
        Saddle positions along the cargo [m].
    lashed
        Which saddles carry lashings.
    tube_radius_m
        The cargo's outer radius at each saddle [m].
    lashing_saddle
        The saddle of each lashing wire (index into ``saddle_x_m``).
    """

    cargo: Cargo3D
    pad_pairs: tuple[PadPair, ...]
    stoppers: tuple[SideStopper, ...]
    lashings: tuple[Lashing, ...]
    spring_diagonal_N_per_m: NDArray[np.float64]
    load_N: NDArray[np.float64]
    model: StructuralModel
    saddle_x_m: NDArray[np.float64]
    lashed: NDArray[np.bool_]
    tube_radius_m: NDArray[np.float64]
    lashing_saddle: NDArray[np.intp]


def _lashing_wires(case: Case, saddle_x_m: NDArray[np.float64], lashed: NDArray[np.bool_]) -> tuple[list[Lashing], list[int]]:
    """The fore and aft wire of every lashed saddle (module docstring); none when ``k_l = 0``."""
    lashing = case.seafastening.lashing
    if lashing.stiffness_N_per_m <= 0.0 or not lashed.any():
        return [], []
    angle = math.radians(lashing.angle_deg)
    n = int(np.count_nonzero(lashed))
    drop_m = 1.0  # the anchor's depth below the lug [m]: only the wire's direction enters
    run_m = drop_m / math.tan(angle)
    wires: list[Lashing] = []
    saddles: list[int] = []
    for i in np.flatnonzero(lashed):
        x = float(saddle_x_m[i])
        for sign in (1.0, -1.0):
            wires.append(
                Lashing(
                    cargo_point_m=(x, 0.0, 0.0),
                    anchor_point_m=(x + sign * run_m, 0.0, -drop_m),
                    stiffness_N_per_m=0.5 * lashing.stiffness_N_per_m,
                    pretension_N=lashing.pretension_N / (2.0 * n * math.sin(angle)),
                )
            )
            saddles.append(int(i))
    return wires, saddles


def build_cradle_case(case: Case, model: StructuralModel | None = None) -> CradleCase:
    """The case's cargo on its cradles, side stoppers and lashings (module docstring).

    Parameters
    ----------
    case
        A validated case.
    model
        Today's structural model of the case (:func:`~seafast.model.from_case.build_model`), built when None.

    Raises
    ------
    ValueError
        If a saddle's stiffness is not larger than its lashing wires' vertical stiffness (naming the keys).
    """
    model = build_model(case) if model is None else model
    cargo = build_cargo3d(model.cargo)
    sf = case.seafastening
    x = np.asarray(model.saddle_x_m, dtype=float)
    lashed = np.asarray(model.seafastening.lashed, dtype=bool)
    radius = 0.5 * np.asarray(cargo_geometry(case).section_at(x)[0], dtype=float)
    wires, wire_saddle = _lashing_wires(case, x, lashed)
    k_wire_vertical = sf.lashing.stiffness_N_per_m * math.sin(math.radians(sf.lashing.angle_deg)) ** 2 if wires else 0.0
    k_pad = np.asarray(model.saddle_stiffness_N_per_m, dtype=float) - np.where(lashed, k_wire_vertical, 0.0)
    if np.any(k_pad <= 0.0):
        raise ValueError(
            f"seafastening.saddle_stiffness_N_per_m = {model.saddle_stiffness_N_per_m.tolist()}: allowed more than the lashing "
            f"wires' vertical stiffness seafastening.lashing.stiffness_N_per_m sin^2(angle_deg) = {k_wire_vertical:g} N/m"
        )
    pairs = tuple(PadPair(float(xi), sf.saddle_contact_angle_deg, float(r), float(k)) for xi, r, k in zip(x, radius, k_pad, strict=True))
    stoppers: tuple[SideStopper, ...] = ()
    if sf.side_stopper.gap_m is not None and sf.side_stopper.stiffness_N_per_m is not None:
        stoppers = tuple(
            SideStopper(float(xi), side, sf.side_stopper.gap_m, sf.side_stopper.stiffness_N_per_m)
            for xi in x
            for side in (Side.PORT, Side.STARBOARD)
        )
    springs = np.zeros(cargo.dof_count)
    load = np.zeros(cargo.dof_count)
    for xi, is_lashed in zip(x, lashed, strict=True):
        dofs = cargo.node_dofs(cargo.node_at(float(xi), "seafastening.saddle_positions_m"))
        springs[dofs[0]] += AXIAL_HOLD_N_PER_M
        if is_lashed and not wires:
            load[dofs[2]] -= sf.lashing.pretension_N / max(int(np.count_nonzero(lashed)), 1)
    return CradleCase(cargo, pairs, stoppers, tuple(wires), springs, load, model, x, lashed, radius, np.asarray(wire_saddle, dtype=np.intp))
