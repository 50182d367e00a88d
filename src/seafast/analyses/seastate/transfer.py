"""Linear transfer functions of the cargo and its sea-fastening per metre of wave amplitude, at a wave heading.

For each wave frequency omega (deep water, ``k = omega^2 / g``) and the heading beta (180 head seas):

1. the hull girder's quasi-static wave deflection and slope under each saddle, from
   :func:`~seafast.hull.transfer.wave_transfer_functions` at that heading (two real load cases per
   frequency; exact while no section emerges, see its ``emergence_amplitude_m``);
2. head seas: heave and pitch from :func:`~seafast.excitation.rao_extension.extended_rao` (BEM inside its
   grid, the long-wave limits below it, decayed above it); any other heading (or ``six_dof=True``): the six
   motions from :func:`~seafast.excitation.rao_extension.extended_six_dof_rao`, folded into the vertical plane
   of the analysed unit as :func:`~seafast.excitation.vessel_amplitudes.six_dof_amplitudes` does (its deck
   rises by heave + roll y + pitch (x - x_G), y = ``case.cargo_transverse_position_m()``);
3. the cargo excitation from :func:`~seafast.excitation.deck_motion.assemble_excitation` (the
   same assembly as ``seafast run``) and the linear (bilateral-saddle) response from
   :func:`~seafast.solvers.linear.solve_harmonic`, the solver of ``seafast run``.

So at a grid frequency, ``zeta_a`` times a transfer function equals the first harmonic of
``seafast run`` (linear model, dynamic minus static) for the regular wave of that frequency, amplitude
and heading, to round-off, as long as that wave keeps the hull immersed (off head seas: without a
quadratic roll damping, whose linearisation depends on the wave; a sea state gives its stochastic
equivalent as ``roll_damping_Nms_per_rad``).

Convention: ``x(t) = Re(X exp(i omega t))`` per metre of ``zeta(t) = zeta_a cos(omega t)``, the
wave elevation at midship (crest amidships at t = 0).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.linalg import solve_banded

from seafast.config.loader import CaseError
from seafast.config.modes import HullCargoCoupling
from seafast.config.schema import HEAD_SEAS_DEG, Case
from seafast.excitation.deck_motion import RigidBodyAmplitudes, assemble_excitation
from seafast.excitation.hydrodynamics.heading_motions import SixDofMotions
from seafast.excitation.rao_extension import extended_rao, extended_six_dof_rao
from seafast.excitation.vessel import VesselExcitation, shared_vessel_cache, vessel_excitation
from seafast.excitation.vessel_inputs import six_dof_motions_of
from seafast.hull.transfer import wave_transfer_functions
from seafast.model.beam import bending_moment_line
from seafast.model.structure import StructuralModel
from seafast.solvers.linear import solve_harmonic, solve_linear

__all__ = ["TransferFunctions", "StillWater", "transfer_functions", "still_water", "six_dof_motions", "MOMENT_POINTS_PER_ELEMENT"]

MOMENT_POINTS_PER_ELEMENT = 2
_HALF_BANDWIDTH = 3  # Hermite beam elements: node i couples to i + 1 (4 DOFs)
"""Bending-moment samples per cargo element (as results.nc's ``x_moment_m``)."""


@dataclass(frozen=True)
class TransferFunctions:
    """Linear transfer functions per metre of wave amplitude at one wave heading.

    Time dependence ``x(t) = Re(X exp(i omega t))``; wave elevation at midship
    ``zeta(t) = zeta_a cos(omega t)``.

    Attributes
    ----------
    omega_rad_s
        (n_w,) wave frequencies [rad/s], strictly increasing.
    deck_displacement
        (n_w, n_deck_dofs): hull elastic deflection z [m/m] and slope [rad/m] under each
        saddle, in the model's deck-DOF order (as ``HarmonicExcitation.deck_displacement[1]``).
    cargo_load_N
        (n_w, n_cargo_dofs): rigid-body inertia nodal load per metre [N/m, N m/m] (as
        ``HarmonicExcitation.cargo_load_N[1]``).
    cargo_line_load_N_per_m
        (n_w, n_elements): the same load per element length [N/m per m] (moment lines).
    heave_m
        (n_w,) heave at the pitch reference [m/m] (six-DOF: of the CoG, on the centreline).
    pitch_rad
        (n_w,) pitch dz/dx, bow up [rad/m].
    pitch_reference_x_m
        Ship x of the pitch reference [m].
    heading_deg
        The wave heading [deg] (180 head seas).
    roll_rad
        (n_w,) roll, starboard down + [rad/m], of the six-DOF motions (the cargo's deck rises by heave + roll y + pitch
        (x - x_G)); None for the head-sea heave-pitch model.
    roll_damping_Nms_per_rad
        Linear roll damping added to the six-DOF motions' (a sea state's stochastic equivalent of the quadratic roll
        damping) [N m s/rad]; 0 for none.
    cargo_displacement
        (n_w, n_cargo_dofs) linear response relative to the rigid-body frame [m/m, rad/m].
    saddle_compression_m
        (n_w, n_s) saddle compression, positive compressed [m/m].
    saddle_force_N
        (n_w, n_s) compression-only part of the saddle force (as ``LinearResponse.saddle_force_N``) [N/m].
    bending_moment_x_m
        (n_x,) positions along the cargo from its aft end [m] where moments are given (element
        ends appear twice, as ``x_moment_m`` in results.nc).
    bending_moment_Nm
        (n_w, n_x) cargo bending moment, sagging + [N m/m].
    bending_section_modulus_m3
        (n_x,) section modulus I / (D/2) at those points [m^3]: stress = moment / modulus.
    hull_emergence_amplitude_m
        (n_w,) regular-wave amplitude [m] beyond which a hull section emerges and the hull's
        response stops being linear.
    """

    omega_rad_s: NDArray[np.float64]
    deck_displacement: NDArray[np.complex128]
    cargo_load_N: NDArray[np.complex128]
    cargo_line_load_N_per_m: NDArray[np.complex128]
    heave_m: NDArray[np.complex128]
    pitch_rad: NDArray[np.complex128]
    pitch_reference_x_m: float
    cargo_displacement: NDArray[np.complex128]
    saddle_compression_m: NDArray[np.complex128]
    saddle_force_N: NDArray[np.complex128]
    bending_moment_x_m: NDArray[np.float64]
    bending_moment_Nm: NDArray[np.complex128]
    bending_section_modulus_m3: NDArray[np.float64]
    hull_emergence_amplitude_m: NDArray[np.float64]
    heading_deg: float = HEAD_SEAS_DEG
    roll_rad: NDArray[np.complex128] | None = None
    roll_damping_Nms_per_rad: float = 0.0

    @property
    def bending_stress_Pa(self) -> NDArray[np.complex128]:
        """(n_w, n_x) bending stress at the outer fibre, bottom tension + [Pa/m]."""
        return self.bending_moment_Nm / self.bending_section_modulus_m3


@dataclass(frozen=True)
class StillWater:
    """The linear model's still-water (static) state, what the sea-state totals add to.

    Attributes
    ----------
    saddle_compression_m, saddle_force_N
        (n_s,) [m], [N].
    bending_moment_Nm, bending_stress_Pa
        (n_x,) at :attr:`TransferFunctions.bending_moment_x_m` [N m], [Pa].
    """

    saddle_compression_m: NDArray[np.float64]
    saddle_force_N: NDArray[np.float64]
    bending_moment_Nm: NDArray[np.float64]
    bending_stress_Pa: NDArray[np.float64]


def _check_supported(case: Case) -> None:
    v = case.vessel
    if v.deck_deflection_table is not None:
        raise CaseError(
            f"vessel.deck_deflection_table = '{v.deck_deflection_table}': a deck table holds the hull's deflection in one "
            "regular wave; a sea state needs it at every frequency: remove the table (the computed hull girder is used)"
        )
    if v.coupling is HullCargoCoupling.TWO_WAY:
        raise CaseError(
            "vessel.coupling = 'two_way': sea states support 'one_way' only (the coupled deck changes with frequency); "
            "use --set vessel.coupling=one_way"
        )


def _head_seas_case(case: Case) -> Case:
    """The case with its regular wave turned to head seas (the case itself when it is): its vessel serves the heave-pitch model."""
    if case.wave.heading_deg == HEAD_SEAS_DEG:
        return case
    return case.model_copy(update={"wave": case.wave.model_copy(update={"heading_deg": HEAD_SEAS_DEG})})


def six_dof_motions(case: Case) -> SixDofMotions | None:
    """The case's six motions at every heading (the six-DOF BEM, read from the caches), None for ``vessel.motions: none``."""
    vessel = vessel_excitation(_head_seas_case(case))
    assert vessel.girder is not None
    cache = shared_vessel_cache()
    return six_dof_motions_of(case, vessel.girder.hull, vessel.loading, None if cache is None else cache.hydrodynamics)


def _section_modulus_m3(model: StructuralModel) -> NDArray[np.float64]:
    beam = model.cargo
    return np.repeat(beam.element_second_moment_m4 / (beam.element_outer_diameter_m / 2.0), MOMENT_POINTS_PER_ELEMENT + 1)


def _harmonic_solves(
    model: StructuralModel, omega_rad_s: NDArray[np.float64], cargo_load: NDArray[np.complex128], deck: NDArray[np.complex128]
) -> NDArray[np.complex128]:
    """``solve_harmonic`` at every frequency, with the banded structure of the cargo matrices.

    The cargo beam couples only neighbouring nodes and the saddle springs are diagonal, so
    ``K_d^cc = K - omega^2 M + i omega D`` has half-bandwidth 3: a banded LU per frequency costs
    O(n) instead of the dense O(n^3) of :func:`~seafast.solvers.linear.solve_harmonic` (~100 x
    faster on the base mesh). Same equations; the tests compare both.
    """
    Kcc, Kco, _ = model.spring_matrices(True)
    K, M, D = model.cargo.stiffness + Kcc, model.cargo.mass, model.damping_cc
    n, u = K.shape[0], _HALF_BANDWIDTH
    full = K + M + D
    if np.any(np.triu(full, u + 1)) or np.any(np.tril(full, -u - 1)):  # pragma: no cover - a new element type
        return np.stack([solve_harmonic(model, float(om), f, xo) for om, f, xo in zip(omega_rad_s, cargo_load, deck, strict=True)])

    def band(A: NDArray[np.float64]) -> NDArray[np.float64]:
        ab = np.zeros((2 * u + 1, n))
        for d in range(-u, u + 1):
            diag = np.diagonal(A, d)
            if d >= 0:
                ab[u - d, d:] = diag
            else:
                ab[u - d, : n + d] = diag
        return ab

    Kb, Mb, Db = band(K), band(M), band(D)
    # the springs' K_co and the damping's coupling to the deck velocities (StructuralModel.support_damping_coupling)
    rhs = cargo_load - deck @ Kco.T - 1j * np.asarray(omega_rad_s)[:, None] * (deck @ model.support_damping_coupling.T)
    out = np.empty_like(rhs)
    for i, om in enumerate(omega_rad_s):
        out[i] = solve_banded((u, u), Kb - om**2 * Mb + 1j * om * Db, rhs[i], check_finite=False)
    return out


def _checked_heading_deg(heading_deg: float) -> float:
    h = float(heading_deg)
    if not (math.isfinite(h) and 0.0 <= h < 360.0):
        raise ValueError(f"transfer_functions: heading_deg = {heading_deg!r}; allowed: [0, 360) deg (180 head seas, 90 beam seas)")
    return h


def _rigid_body_raos(
    case: Case, vessel: VesselExcitation, w: NDArray[np.float64], heading_deg: float, six_dof: bool, roll_damping: float
) -> tuple[NDArray[np.complex128], NDArray[np.complex128], NDArray[np.complex128] | None, float]:
    """Heave [m/m], pitch [rad/m], roll [rad/m] (None: the heave-pitch model) and the pitch reference x [m] per frequency."""
    g, draught = case.model.gravity_m_per_s2, case.vessel.draft_m
    if not six_dof:
        if vessel.motions is None:
            return np.zeros(w.size, complex), np.zeros(w.size, complex), None, 0.0
        heave, pitch = extended_rao(vessel.motions, w, gravity_m_per_s2=g, draught_m=draught)
        return heave, pitch, None, float(vessel.motions.reference_x_m)
    motions6 = six_dof_motions(case)
    if motions6 is None:
        zero = np.zeros(w.size, complex)
        return zero, zero.copy(), zero.copy(), 0.0
    rao = extended_six_dof_rao(
        motions6, w, heading_deg, gravity_m_per_s2=g, draught_m=draught, additional_roll_damping_Nms_per_rad=roll_damping
    )
    return rao[:, 2], rao[:, 4], rao[:, 3], float(motions6.reference_x_m)


def transfer_functions(
    case: Case,
    model: StructuralModel,
    omega_rad_s: ArrayLike,
    *,
    heading_deg: float,
    six_dof: bool = False,
    roll_damping_Nms_per_rad: float = 0.0,
) -> TransferFunctions:
    """Transfer functions of the case's linear model at ``omega_rad_s`` and ``heading_deg`` (see the module docstring).

    Parameters
    ----------
    case
        The case (vessel, cargo position, gravity; one-way coupling, computed hull girder). Its regular wave is not used.
    model
        Its structural model (:func:`seafast.model.from_case.build_model`).
    omega_rad_s
        Wave frequencies [rad/s], > 0, strictly increasing.
    heading_deg
        Wave heading [deg] in [0, 360): 180 head seas (the heave-pitch model, as ``seafast run``), 90 beam seas.
        Sea states pass ``case.sea_state.heading_deg``, the regular-wave sweep ``case.wave.heading_deg``.
    six_dof
        The six-DOF motions at 180 too (a short-crested sea uses one motion model for all its directions);
        any other heading always uses them.
    roll_damping_Nms_per_rad
        Linear roll damping added to the six-DOF motions' [N m s/rad], >= 0 (a sea state's stochastic equivalent of
        the quadratic roll damping); must be 0 for the heave-pitch model.

    Raises
    ------
    CaseError
        For a deck-deflection table or two-way coupling (no per-frequency hull response).
    """
    w = np.asarray(omega_rad_s, dtype=float)
    if w.ndim != 1 or w.size == 0 or not np.all(np.isfinite(w)) or np.any(w <= 0) or np.any(np.diff(w) <= 0):
        raise ValueError("transfer_functions: omega_rad_s must be a non-empty, strictly increasing 1-D array of frequencies > 0")
    heading = _checked_heading_deg(heading_deg)
    six = bool(six_dof) or heading != HEAD_SEAS_DEG
    if roll_damping_Nms_per_rad != 0.0 and not six:
        raise ValueError("transfer_functions: roll_damping_Nms_per_rad applies to the six-DOF motions only (heading 180: six_dof=True)")
    _check_supported(case)
    vessel = vessel_excitation(_head_seas_case(case))
    aft = vessel.cargo_aft_end_x_m
    assert vessel.girder is not None and vessel.loading is not None  # a computed hull (checked above)
    if heading == HEAD_SEAS_DEG:
        hull = wave_transfer_functions(vessel.girder, vessel.loading, w)
    else:
        hull = wave_transfer_functions(vessel.girder, vessel.loading, w, heading_deg=heading)
    heave, pitch, roll, ref_x = _rigid_body_raos(case, vessel, w, heading, six, float(roll_damping_Nms_per_rad))
    # the cargo model is vertical: its deck under the unit at y rises by heave + roll y + pitch (x - x_G)
    deck_heave = heave if roll is None else heave + roll * case.cargo_transverse_position_m()
    load, line, deck, disp = _cargo_response(model, aft, w, deck_heave, pitch, ref_x, hull.deck_at(aft + model.saddle_x_m))
    compression = deck[:, model.saddle_deck_dof] - disp[:, model.saddle_cargo_dof]
    beam = model.cargo
    x_m, moment = bending_moment_line(beam.node_x_m, disp, beam.element_bending_stiffness_Nm2, None, line, MOMENT_POINTS_PER_ELEMENT)
    assert compression.shape == (w.size, model.saddle_count)
    return TransferFunctions(
        omega_rad_s=w,
        deck_displacement=deck,
        cargo_load_N=load,
        cargo_line_load_N_per_m=line,
        heave_m=np.asarray(heave, complex),
        pitch_rad=np.asarray(pitch, complex),
        pitch_reference_x_m=ref_x,
        cargo_displacement=disp,
        saddle_compression_m=compression,
        saddle_force_N=compression * model.saddle_unilateral_stiffness_N_per_m,
        bending_moment_x_m=x_m,
        bending_moment_Nm=moment,
        bending_section_modulus_m3=_section_modulus_m3(model),
        hull_emergence_amplitude_m=hull.emergence_amplitude_m,
        heading_deg=heading,
        roll_rad=None if roll is None else np.asarray(roll, complex),
        roll_damping_Nms_per_rad=float(roll_damping_Nms_per_rad),
    )


def _cargo_response(
    model: StructuralModel,
    aft: float,
    w: NDArray[np.float64],
    heave: NDArray[np.complex128],
    pitch: NDArray[np.complex128],
    ref_x: float,
    deck_at_saddles: tuple[NDArray[np.complex128], NDArray[np.complex128]],
) -> tuple[NDArray[np.complex128], NDArray[np.complex128], NDArray[np.complex128], NDArray[np.complex128]]:
    """Nodal and line inertia loads, deck displacement and cargo displacement per frequency (heave at ``ref_x``, pitch)."""
    deck_z, deck_slope = deck_at_saddles
    # The assembly is linear in the deck motion and in omega^2 (heave, pitch): assemble unit
    # heave and unit pitch once at omega = 1 and superpose (the same numbers as one assembly
    # per frequency, without n_w dense mass products).
    unit = [assemble_excitation(model, aft, 1.0, None, None, RigidBodyAmplitudes(h, p, ref_x)) for h, p in ((1.0, 0.0), (0.0, 1.0))]
    w2 = (w**2)[:, None]
    load = w2 * (heave[:, None] * unit[0].cargo_load_N[1] + pitch[:, None] * unit[1].cargo_load_N[1])
    line = w2 * (heave[:, None] * unit[0].cargo_line_load_N_per_m[1] + pitch[:, None] * unit[1].cargo_line_load_N_per_m[1])
    deck = np.zeros((w.size, model.deck_dof_count), complex)  # (z, slope) per saddle, the assembly's deck-DOF order
    deck[:, model.saddle_deck_dof], deck[:, model.saddle_deck_dof + 1] = deck_z, deck_slope
    return load, line, deck, _harmonic_solves(model, w, load, deck)


def still_water(case: Case, model: StructuralModel) -> StillWater:
    """The linear model's still-water state (``solve_linear`` on the static part, as ``seafast run``)."""
    _check_supported(case)
    head = _head_seas_case(case)
    static = vessel_excitation(head).cargo_excitation(model, head).static_part()
    response = solve_linear(model, static)
    beam = model.cargo
    disp = response.cargo_displacement[0].real
    line = static.cargo_line_load_N_per_m[0].real + beam.gravity_line_load_N_per_m
    _, moment = bending_moment_line(beam.node_x_m, disp, beam.element_bending_stiffness_Nm2, None, line, MOMENT_POINTS_PER_ELEMENT)
    return StillWater(
        saddle_compression_m=response.saddle_compression_m[0].real,
        saddle_force_N=response.saddle_force_N[0].real,
        bending_moment_Nm=moment,
        bending_stress_Pa=moment / _section_modulus_m3(model),
    )
