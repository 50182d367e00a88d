"""The cargo on its cradles in a run off head seas: the four rows of the 3-D model (docs/transverse.md#9-in-seafast-run).

The case's cradles, side stoppers and lashing wires (:func:`seafast.model.cradle_case.build_cradle_case`), with
the vertical model's Rayleigh damping and deck points, loaded by the same vessel excitation as the vertical rows
(its six motions at the case's wave and the deck's deflection, built once by the run), solved in four rows:

* ``dynamic nonlinear``: the harmonic balance of the exact law (:func:`seafast.solvers.cradle_hbm.solve_cradle_hbm`,
  the case's solver settings, its adaptive H (docs/transverse.md#7-dynamics) unless ``solver.harmonics`` fixes it);
* ``static nonlinear``: the quasi-static exact-contact reference in still water
  (:func:`seafast.solvers.references.cradle_quasi_static.solve_cradle_quasi_static`): the exact statics, loads constant;
* ``static linear``, ``dynamic linear``: the same model with the pads and lashing wires bilateral and the side
  stoppers open, solved directly (every harmonic of the excitation, k = 0, 1).

All four on the dynamic row's time grid: where the dynamic nonlinear row repeats only every P wave periods (a
subharmonic of the exact-event shooting, ``period_multiple`` P), over those P periods (the other rows repeated).
With ``seafastening.friction_coefficient`` set, the pads carry Coulomb
friction (:class:`~seafast.model.pad_friction.PadFriction`, tangential stiffness equal to the normal one) in the two
nonlinear rows (docs/transverse.md#9-in-seafast-run):

* ``dynamic nonlinear``: the frictional harmonic balance
  (:func:`seafast.solvers.cradle_friction.solve_cradle_friction_hbm`; H = ``solver.harmonics`` or
  :data:`FRICTION_HARMONICS`, N = ``solver.time_samples`` or 8 H), and where it does not converge the time march
  (:func:`seafast.solvers.cradle_friction_solve.solve_cradle_friction`: its own grid, 4096 samples a wave period);
* ``static nonlinear``: the same solver on the still-water loads (constant, H = 1).

In both the sliders are relaxed in still water (the frictionless response to the still-water loads and deck
deflection, ``rest=``): the friction answers the wave alone, and the still-water row carries none.

The linear rows keep their pads bilateral and free tangentially (no friction). Nothing here prints or writes files.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
from numpy.typing import NDArray

from seafast.config.schema import HEAD_SEAS_DEG, Case
from seafast.excitation.cradle_loads import CradleExcitation, cradle_excitation
from seafast.excitation.harmonic import HarmonicExcitation
from seafast.excitation.vessel import VesselExcitation
from seafast.fourier import harmonics_to_time
from seafast.model.cradle_case import CradleCase, build_cradle_case
from seafast.model.pad_friction import PadFriction
from seafast.model.structure import StructuralModel
from seafast.results.cradle import CradleLayout, CradleRow, CradleRows
from seafast.solvers.cradle_dynamics import CradleDynamics, cradle_operators
from seafast.solvers.cradle_friction import FrictionHBMOptions, solve_cradle_friction_hbm
from seafast.solvers.cradle_friction_solve import solve_cradle_friction
from seafast.solvers.cradle_hbm import CradleResponse, cradle_response, solve_cradle_hbm
from seafast.solvers.from_case import hbm_options
from seafast.solvers.outcome import SolverOutcome
from seafast.solvers.references.cradle_quasi_static import solve_cradle_quasi_static
from seafast.solvers.transverse_statics import CradleProblem

__all__ = [
    "FRICTION_HARMONICS",
    "solves_cradles",
    "cradle_problem",
    "cradle_dynamics_of_case",
    "case_cradle_excitation",
    "pad_friction_of_case",
    "friction_options",
    "cradle_rows",
    "solve_cradle_rows",
]

FRICTION_HARMONICS = 32
"""The frictional dynamic row's harmonics H when ``solver.harmonics`` is unset (its Jacobian is dense: H of tens)."""


def solves_cradles(case: Case) -> bool:
    """Whether a run of ``case`` solves the cargo on its cradles: every heading but head seas."""
    return float(case.wave.heading_deg) != HEAD_SEAS_DEG


def cradle_problem(cradle: CradleCase, extra_load_N: NDArray[np.float64] | None = None) -> CradleProblem:
    """A case's cargo on its cradles as a :class:`~seafast.solvers.transverse_statics.CradleProblem`: its pads,
    stoppers, lashing wires and axial holds, loaded by its weight and given loads plus ``extra_load_N`` (5 n,) [N, N m]."""
    load = cradle.load_N if extra_load_N is None else cradle.load_N + extra_load_N
    return CradleProblem(
        cradle.cargo,
        cradle.pad_pairs,
        cradle.stoppers,
        cradle.lashings,
        spring_diagonal_N_per_m=cradle.spring_diagonal_N_per_m,
        load_N=load,
    )


def cradle_dynamics_of_case(cradle: CradleCase) -> CradleDynamics:
    """The dynamics of a case's cradles: its problem with the vertical model's damping, deck points and gravity.

    The bilateral springs of a cradle case are the axial holds, on a deck that moves only vertically: no deck
    coupling (the lashing wires move with the deck through their engagements).
    """
    model = cradle.model
    return CradleDynamics(
        cradle_problem(cradle), model.rayleigh_alpha_per_s, model.rayleigh_beta_s, model.saddle_x_m, None, model.gravity_m_per_s2
    )


def case_cradle_excitation(cradle: CradleCase, excitation: HarmonicExcitation, vessel: VesselExcitation | None) -> CradleExcitation:
    """The loads on the 3-D cargo from the run's own vertical ``excitation`` and the vessel's six motions.

    A vessel without rigid-body motions (``vessel.motions: none``) moves the cargo by the deck's deflection alone.

    Raises
    ------
    ValueError
        If the motions' reference point has no height (the cargo's lever arms are unknown).
    """
    motions = np.zeros(6, dtype=complex)
    axis = (0.0, 0.0, 0.0)
    g = cradle.model.gravity_m_per_s2
    if vessel is not None and vessel.rigid_body is not None and vessel.cargo_points is not None and vessel.motion_amplitudes is not None:
        rigid, points = vessel.rigid_body, vessel.cargo_points
        if not np.isfinite(rigid.reference_z_m):
            raise ValueError("vessel: the motions' reference point has no height (reference_z_m): allowed motions with one")
        motions = np.asarray(vessel.motion_amplitudes, dtype=complex)
        axis = (vessel.cargo_aft_end_x_m - rigid.reference_x_m, points.y_m, points.z_m - rigid.reference_z_m)
        g = vessel.gravity_m_per_s2
    return cradle_excitation(cradle.cargo, excitation, motions, cradle.model.saddle_x_m, axis, g)


def pad_friction_of_case(case: Case) -> PadFriction | None:
    """The pads' friction from ``seafastening.friction_coefficient`` (None when unset: frictionless pads).

    Raises
    ------
    ValueError
        If the key gives different values per saddle: the pads off head seas take one coefficient.
    """
    mu = case.friction_coefficients()
    if mu is None:
        return None
    if len(set(mu)) > 1:
        raise ValueError(
            f"seafastening.friction_coefficient = {list(mu)}: the cradle pads off head seas take one coefficient for every "
            "saddle; allowed one value (or the same value per saddle)"
        )
    return PadFriction(float(mu[0]))


def friction_options(case: Case) -> FrictionHBMOptions:
    """The frictional dynamic row's settings: H = ``solver.harmonics`` or :data:`FRICTION_HARMONICS` (at most
    (N - 2) / 2 when only ``solver.time_samples`` is set), N = ``solver.time_samples`` or 8 H (the slips' onsets
    fall between samples)."""
    samples = case.solver.time_samples
    H = FRICTION_HARMONICS if case.solver.harmonics is None else int(case.solver.harmonics)
    if case.solver.harmonics is None and samples is not None:
        H = max(1, min(H, (int(samples) - 2) // 2))
    N = 8 * H if samples is None else int(samples)
    return FrictionHBMOptions(harmonics=H, time_samples=N)


def _linear_row(dynamics: CradleDynamics, excitation: CradleExcitation, time_samples: int, multiple: int = 1) -> CradleResponse:
    """The pads and lashing wires bilateral, the stoppers open: ``k s`` of each, exact at k = 0, 1 (module docstring);
    the N samples over ``multiple`` wave periods (the wave period's response repeated)."""
    included = dynamics.damping_set
    ops = cradle_operators(dynamics, excitation, 1, included)
    per_period = time_samples // multiple
    q = np.tile(harmonics_to_time(ops.linear_cargo_displacement, per_period), (multiple, 1))
    deck = np.array(excitation.deck_displacement, dtype=complex)
    deck[0] = deck[0].real
    s = (
        dynamics.initial_engagement_m
        + q @ dynamics.problem.engagement_matrix.T
        + np.tile(harmonics_to_time(deck, per_period), (multiple, 1)) @ dynamics.deck_engagement.T
    )
    force = np.where(included, dynamics.problem.element_stiffness_N_per_m * s, 0.0)
    message = "3-D cradle linear model (pads and lashing wires bilateral, side stoppers open), solved directly"
    outcome = (SolverOutcome.CONVERGED, 0.0, message, 1)
    response = cradle_response(dynamics, s, q, excitation.omega_rad_s, outcome, multiple)
    return replace(response, element_force_N=force)


def _layout(cradle: CradleCase) -> CradleLayout:
    cargo = cradle.cargo
    lateral = np.array([cargo.node_dofs(cargo.node_at(float(x)))[1] for x in cradle.saddle_x_m], dtype=np.intp)
    directions: NDArray[np.float64] = np.array([w.direction for w in cradle.lashings], dtype=float).reshape(-1, 3)
    angle = cradle.pad_pairs[0].contact_angle_deg if cradle.pad_pairs else float("nan")
    return CradleLayout(
        saddle_x_m=np.asarray(cradle.saddle_x_m, dtype=float),
        tube_radius_m=np.asarray(cradle.tube_radius_m, dtype=float),
        contact_angle_deg=float(angle),
        lateral_dof=lateral,
        stopper_x_m=np.array([s.x_m for s in cradle.stoppers], dtype=float),
        stopper_side=tuple(str(s.side.value) for s in cradle.stoppers),
        stopper_gap_m=np.array([s.gap_m for s in cradle.stoppers], dtype=float),
        lashing_saddle=np.asarray(cradle.lashing_saddle, dtype=np.intp),
        lashing_direction=directions,
    )


def cradle_rows(
    case: Case, cradle: CradleCase, dynamics: CradleDynamics, excitation: CradleExcitation, friction: PadFriction | None = None
) -> CradleRows:
    """The four rows of ``dynamics`` under ``excitation`` (module docstring), on the dynamic row's time grid; the
    nonlinear rows on frictional pads when ``friction`` is given."""
    if friction is not None:
        return _frictional_rows(case, cradle, dynamics, excitation, friction)
    options = hbm_options(case)
    dynamic = solve_cradle_hbm(dynamics, excitation, options)
    N, P = dynamic.time_s.size, dynamic.period_multiple
    still = excitation.still_water()
    static = solve_cradle_quasi_static(dynamics, still, N)
    rows = {
        ("static", "linear"): CradleRow(_linear_row(dynamics, still, N, P), linear=True),
        ("dynamic", "linear"): CradleRow(_linear_row(dynamics, excitation, N, P), linear=True),
        ("static", "nonlinear"): CradleRow(replace(static, time_s=dynamic.time_s, period_multiple=P), linear=False),
        ("dynamic", "nonlinear"): CradleRow(dynamic, linear=False),
    }
    return CradleRows(rows, _layout(cradle))


def _frictional_rows(
    case: Case, cradle: CradleCase, dynamics: CradleDynamics, excitation: CradleExcitation, friction: PadFriction
) -> CradleRows:
    """The four rows with the nonlinear ones on frictional pads (module docstring)."""
    options = friction_options(case)
    still = excitation.still_water()
    dynamic = solve_cradle_friction(dynamics, friction, excitation, options, rest=still)
    N, P = dynamic.cradle.time_s.size, dynamic.cradle.period_multiple
    static = solve_cradle_friction_hbm(dynamics, friction, still, replace(options, harmonics=1, time_samples=N), rest=still)
    if P > 1:  # a subharmonic of the time march: the still water over the same P wave periods
        static = replace(static, cradle=replace(static.cradle, time_s=dynamic.cradle.time_s, period_multiple=P))
    rows = {
        ("static", "linear"): CradleRow(_linear_row(dynamics, still, N, P), linear=True),
        ("dynamic", "linear"): CradleRow(_linear_row(dynamics, excitation, N, P), linear=True),
        ("static", "nonlinear"): CradleRow(static.cradle, linear=False, friction=static),
        ("dynamic", "nonlinear"): CradleRow(dynamic.cradle, linear=False, friction=dynamic),
    }
    return CradleRows(rows, _layout(cradle))


def solve_cradle_rows(case: Case, model: StructuralModel, excitation: HarmonicExcitation, vessel: VesselExcitation | None) -> CradleRows:
    """The four rows of the case's cargo on its cradles, loaded by the run's ``excitation`` and ``vessel``; the pads
    frictional when ``seafastening.friction_coefficient`` is set (:func:`pad_friction_of_case`).

    Raises
    ------
    ValueError
        If the case's cradles cannot be built (naming the key), the lashings hold no rest position or the friction
        coefficient differs between saddles.
    """
    friction = pad_friction_of_case(case)
    cradle = build_cradle_case(case, model)
    dynamics = cradle_dynamics_of_case(cradle)
    return cradle_rows(case, cradle, dynamics, case_cradle_excitation(cradle, excitation, vessel), friction)
