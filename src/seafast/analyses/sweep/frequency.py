"""Frequency sweeps end to end (``seafast sweep``): the structural sweep and the wave sweep.

Both follow the nonlinear periodic response in frequency by pseudo-arclength continuation
(:func:`seafast.solvers.continuation.frequency_response`, through folds), mark each point stable
or unstable (Floquet multipliers), and say where the branch leaves the physically meaningful range
(:mod:`seafast.analyses.sweep.table`); they differ in what is held while omega moves:

``structural``
    The case's excitation *shape*: deck-motion amplitudes and rigid-body displacement amplitudes
    of the case's wave are held (:meth:`HarmonicExcitation.at_frequency`), so inertia loads grow as
    omega^2. It shows the cargo's resonances, but the held motions are no wave's above the wave
    band: their deck acceleration grows as omega^2 and passes g at ``omega_g``. By default the
    sweep stops there (beyond it the cargo is thrown off its saddles by the vessel alone, and the
    still-water contact model describes nothing real); ``follow_beyond_range`` goes on, marking the
    points.
``wave``
    At each frequency the wave of the case's amplitude at that frequency: the hull's quasi-static
    wave deflection at the case's heading (the linear hull transfer function of
    :func:`seafast.analyses.seastate.transfer.transfer_functions`, on a fine grid with a cubic spline in omega), the
    rigid-body motions at that frequency (head seas: heave and pitch, :func:`seafast.excitation.rao_extension.extended_rao`;
    another heading: the six motions folded into the unit's vertical plane as ``seafast run`` does), assembled as ``seafast run`` assembles
    its wave (:func:`seafast.excitation.deck_motion.assemble_excitation`). Its table adds the
    nonlinear and linear RAOs of saddle force and bending moment per metre of wave amplitude.

Nothing here prints or writes files (see :mod:`seafast.output.sweep`).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from enum import Enum

import numpy as np
from numpy.typing import NDArray
from scipy.interpolate import CubicSpline

from seafast.analyses.seastate.transfer import transfer_functions
from seafast.analyses.sweep.range import RangeLimits, deck_acceleration_m_per_s2
from seafast.analyses.sweep.table import SweepTable, sweep_table
from seafast.config.modes import HullCargoCoupling
from seafast.config.schema import Case
from seafast.excitation.deck_motion import RigidBodyAmplitudes, assemble_excitation
from seafast.excitation.harmonic import HarmonicExcitation
from seafast.excitation.hydrodynamics.roll_damping import QuadraticRollDamping
from seafast.excitation.rao_extension import extended_rao, extended_six_dof_rao
from seafast.excitation.vessel import VesselExcitation, vessel_excitation
from seafast.model.from_case import build_model
from seafast.model.structure import StructuralModel
from seafast.solvers.branch import BranchEnd, FrequencyResponseBranch
from seafast.solvers.continuation import CONTINUATION_HARMONICS, frequency_response
from seafast.solvers.from_case import hbm_options
from seafast.solvers.hbm import condensed_operators, solve_condensed
from seafast.solvers.hbm.options import samples_for

__all__ = ["SWEEP_MIN_TIME_SAMPLES", "SweepKind", "SweepResult", "frequency_sweep", "wave_excitation"]

SWEEP_MIN_TIME_SAMPLES = 512
"""AFT samples N of a sweep when the case leaves ``solver.time_samples`` unset (at least ``samples_for(H)``):
with fewer, the sampled contact set's changes make the branch zigzag in omega at a fold (``docs/sweeps.md``)."""

_GRID_STEP_RAD_S = 0.005  # spacing of the hull transfer-function grid of the wave sweep
_GRID_MARGIN = 0.05  # the grid reaches this share of the span beyond each end (corrector excursions)


class SweepKind(Enum):
    """What a sweep holds while the frequency moves."""

    STRUCTURAL = "structural"
    """The case's deck-motion and rigid-body amplitudes."""
    WAVE = "wave"
    """The wave amplitude: a wave of the case's amplitude at each frequency."""


@dataclass(frozen=True)
class SweepResult:
    """A frequency sweep: the branch, its table and how it ended.

    Attributes
    ----------
    kind
        Structural or wave sweep.
    case, model
        The case and its structural model.
    branch
        The continuation's branch (compression harmonics per point).
    table
        The columns of ``frequency_response.csv``.
    omega_start_rad_s, omega_end_rad_s
        The sweep asked for [rad/s].
    acceleration_limit_rad_s
        Structural sweep: the frequency where the held deck motion accelerates the deck by g
        [rad/s] (inf without motion); None for the wave sweep.
    """

    kind: SweepKind
    case: Case
    model: StructuralModel
    branch: FrequencyResponseBranch
    table: SweepTable
    omega_start_rad_s: float
    omega_end_rad_s: float
    acceleration_limit_rad_s: float | None

    @property
    def stopped_beyond_range(self) -> bool:
        """Whether the sweep stopped where the held motion passed g (before ``omega_end``)."""
        return self.branch.end is BranchEnd.STOPPED

    @property
    def converged(self) -> bool:
        """Whether every branch point converged."""
        return bool(np.all(self.branch.converged))


def _structural_limit_rad_s(model: StructuralModel, excitation: HarmonicExcitation, gravity_m_per_s2: float) -> float:
    """Where the held deck motion's acceleration reaches g [rad/s]: it grows exactly as omega^2."""
    a = deck_acceleration_m_per_s2(model, excitation)
    if a <= 0.0 or excitation.omega_rad_s <= 0.0:
        return math.inf
    return float(excitation.omega_rad_s * math.sqrt(gravity_m_per_s2 / a))


def _wave_raos(case: Case, vessel: VesselExcitation) -> tuple[Callable[[float], tuple[complex, complex]], float]:
    """``omega -> (heave [m/m], pitch [rad/m])`` of the cargo's deck in the case's wave at any frequency, and the pitch reference x [m].

    Head seas: the heave-pitch model (:func:`~seafast.excitation.rao_extension.extended_rao`). Another heading: the six
    motions folded into the analysed unit's vertical plane (heave + roll y, as ``seafast run``), inside the BEM grid with
    the quadratic roll damping linearised harmonically at the case's amplitude (``SixDofMotions.rao_in_regular_wave``),
    outside it the linear RAOs extended (:func:`~seafast.excitation.rao_extension.extended_six_dof_rao`).
    """
    g, draught = case.model.gravity_m_per_s2, case.vessel.draft_m
    motions, motions6 = vessel.motions, vessel.motions6
    if motions is not None:

        def head(omega: float) -> tuple[complex, complex]:
            heave, pitch = extended_rao(motions, float(omega), gravity_m_per_s2=g, draught_m=draught)
            return complex(heave), complex(pitch)

        return head, float(motions.reference_x_m)
    if motions6 is None:
        return (lambda omega: (0j, 0j)), 0.0
    heading, amplitude, y = case.wave.heading_deg, float(case.wave.amplitude_m), case.cargo_transverse_position_m()
    b2 = case.vessel.roll_damping_quadratic_Nms2_per_rad2
    quadratic = QuadraticRollDamping(float(b2)) if b2 else None
    lo, hi = float(motions6.omega_rad_s[0]), float(motions6.omega_rad_s[-1])

    def oblique(omega: float) -> tuple[complex, complex]:
        w = float(omega)
        if lo <= w <= hi:
            q = motions6.rao_in_regular_wave(w, heading, amplitude, quadratic)[0]
        else:
            q = extended_six_dof_rao(motions6, np.array([w]), heading, gravity_m_per_s2=g, draught_m=draught)[0]
        return complex(q[2] + q[3] * y), complex(q[4])

    return oblique, float(motions6.reference_x_m)


def wave_excitation(
    case: Case, model: StructuralModel, omega_min_rad_s: float, omega_max_rad_s: float
) -> tuple[Callable[[float], HarmonicExcitation], Callable[[float], tuple[complex, complex]]]:
    """The excitation of a wave of the case's amplitude at any frequency, and the RAOs there.

    Returns
    -------
    excitation_at, rao_at
        ``omega -> HarmonicExcitation`` (still water at k = 0, the wave at k = 1) and ``omega ->
        (heave [m/m], pitch [rad/m])``.

    Raises
    ------
    seafast.config.CaseError
        For a deck-deflection table or two-way coupling (no hull response at other frequencies).
    """
    span = omega_max_rad_s - omega_min_rad_s
    lo = max(omega_min_rad_s - _GRID_MARGIN * span, 0.5 * omega_min_rad_s)
    hi = omega_max_rad_s + _GRID_MARGIN * span
    grid = np.linspace(lo, hi, max(64, math.ceil((hi - lo) / _GRID_STEP_RAD_S) + 1))
    tf = transfer_functions(case, model, grid, heading_deg=case.wave.heading_deg)  # CaseError: a deck table / two-way coupling
    deck = CubicSpline(grid, tf.deck_displacement, axis=0)
    vessel = vessel_excitation(case)
    static = vessel.cargo_excitation(model, case).static_part()
    amplitude = float(case.wave.amplitude_m)
    rao_at, reference_x = _wave_raos(case, vessel)
    moving = vessel.motions is not None or vessel.motions6 is not None

    def excitation_at(omega: float) -> HarmonicExcitation:
        w = float(omega)
        if not lo <= w <= hi:
            raise ValueError(f"wave sweep: omega = {w!r} rad/s outside the transfer-function grid {lo:.4g}..{hi:.4g} rad/s")
        heave, pitch = rao_at(w)
        rigid = RigidBodyAmplitudes(amplitude * heave, amplitude * pitch, reference_x) if moving else None
        wave = assemble_excitation(model, vessel.cargo_aft_end_x_m, w, None, None, rigid, static.source)
        deck_displacement = np.stack([static.deck_displacement[0], amplitude * deck(w)])
        return HarmonicExcitation(
            w,
            deck_displacement,
            np.stack([static.cargo_load_N[0], wave.cargo_load_N[1]]),
            np.stack([static.cargo_line_load_N_per_m[0], wave.cargo_line_load_N_per_m[1]]),
            f"wave sweep: zeta_a = {amplitude:g} m at {w:.4g} rad/s; {static.source}",
        )

    return excitation_at, rao_at


def frequency_sweep(
    case: Case,
    omega_start_rad_s: float,
    omega_end_rad_s: float,
    *,
    kind: SweepKind = SweepKind.STRUCTURAL,
    max_gap_m: float | None = None,
    follow_beyond_range: bool = False,
    max_points: int = 2000,
) -> SweepResult:
    """Nonlinear frequency response of the case by pseudo-arclength continuation, with its table.

    Parameters
    ----------
    case
        The validated case (one-way coupling).
    omega_start_rad_s, omega_end_rad_s
        Sweep limits [rad/s], > 0.
    kind
        :attr:`SweepKind.STRUCTURAL` (the case's motion amplitudes held) or :attr:`SweepKind.WAVE`.
    max_gap_m
        Largest detachment gap inside the meaningful range [m] (default
        :data:`seafast.results.validity.DEFAULT_MAX_GAP_M`).
    follow_beyond_range
        Structural sweep: go on past ``omega_g`` (where the held deck motion accelerates the deck
        by g) instead of stopping there.
    max_points
        Safety limit on the branch points.

    Raises
    ------
    ValueError
        Two-way coupling; a structural sweep that starts beyond ``omega_g`` (unless
        ``follow_beyond_range``); invalid limits.
    seafast.config.CaseError
        A wave sweep of a case with a deck-deflection table.
    """
    if case.vessel.coupling is HullCargoCoupling.TWO_WAY:
        # the coupled deck depends on the cargo's response at each frequency: continuation
        # would have to re-couple at every point, which it does not
        raise ValueError(
            "vessel.coupling = 'two_way': the frequency sweep supports 'one_way' only (the coupled deck changes "
            "with frequency); run the sweep with --set vessel.coupling=one_way, or single frequencies with seafast run"
        )
    limits = RangeLimits(gravity_m_per_s2=case.model.gravity_m_per_s2, **({} if max_gap_m is None else {"max_gap_m": max_gap_m}))
    model = build_model(case)
    # continuation runs on the condensed system with Newton correctors at a fixed H
    opts = hbm_options(case, formulation="condensed", solver="newton", tolerance=max(case.solver.tolerance, 1e-8))
    H = CONTINUATION_HARMONICS if opts.harmonics is None else int(opts.harmonics)  # continuation runs at a fixed H
    # the case's N if it sets one, else at least SWEEP_MIN_TIME_SAMPLES (the sampled contact resolves the folds)
    opts = opts.with_harmonics(H, case.solver.time_samples or max(SWEEP_MIN_TIME_SAMPLES, samples_for(H)))
    w_lo, w_hi = sorted((float(omega_start_rad_s), float(omega_end_rad_s)))
    stop_when: Callable[[float, NDArray[np.float64]], bool] | None = None
    limit_rad_s: float | None = None
    if kind is SweepKind.WAVE:
        excitation_at, rao_at = wave_excitation(case, model, w_lo, w_hi)
    else:
        excitation = vessel_excitation(case).cargo_excitation(model, case)
        excitation_at, rao_at = excitation.at_frequency, None
        limit_rad_s = _structural_limit_rad_s(model, excitation, limits.gravity_m_per_s2)
        if not follow_beyond_range:
            if float(omega_start_rad_s) > limit_rad_s:
                raise ValueError(
                    f"omega_start = {omega_start_rad_s:g} rad/s lies beyond omega_g = {limit_rad_s:.4g} rad/s, where the case's held "
                    "deck motion accelerates the deck by more than g: nothing physically meaningful to sweep; "
                    "sweep the waves of these frequencies (--wave), or follow anyway (--follow-beyond-range)"
                )
            bound = limit_rad_s

            def beyond_limit(omega: float, _u: NDArray[np.float64]) -> bool:  # the held acceleration grows as omega^2
                return omega > bound

            stop_when = beyond_limit
    branch = frequency_response(model, excitation_at, omega_start_rad_s, omega_end_rad_s, opts, max_points=max_points, stop_when=stop_when)
    still = None
    if kind is SweepKind.WAVE:
        static = excitation_at(float(branch.omega_rad_s[0])).static_part()
        still = solve_condensed(condensed_operators(model, static, 0), opts.with_harmonics(0, 2)).saddle_compression
    table = sweep_table(
        model,
        branch,
        excitation_at,
        opts.law,
        limits,
        wave_amplitude_m=float(case.wave.amplitude_m) if kind is SweepKind.WAVE else None,
        rao_at=rao_at,
        still_water_compression_m=still,
    )
    return SweepResult(kind, case, model, branch, table, float(omega_start_rad_s), float(omega_end_rad_s), limit_rad_s)
