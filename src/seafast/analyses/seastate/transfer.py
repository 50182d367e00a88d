"""Linear transfer functions of the cargo and its sea-fastening per metre of wave amplitude.

For each wave frequency omega (head seas, deep water, ``k = omega^2 / g``):

1. the hull girder's quasi-static wave deflection and slope under each saddle, from
   :func:`~seafast.hull.transfer.wave_transfer_functions` (two real load cases per
   frequency; exact while no section emerges, see its ``emergence_amplitude_m``);
2. heave and pitch from :func:`~seafast.excitation.rao_extension.extended_rao` (BEM inside its
   grid, the long-wave limits below it, decayed above it);
3. the cargo excitation from :func:`~seafast.excitation.deck_motion.assemble_excitation` (the
   same assembly as ``seafast run``) and the linear (bilateral-saddle) response from
   :func:`~seafast.solvers.linear.solve_harmonic`, the solver of ``seafast run``.

So at a grid frequency, ``zeta_a`` times a transfer function equals the first harmonic of
``seafast run`` (linear model, dynamic minus static) for the regular wave of that frequency and
amplitude, to round-off, as long as that wave keeps the hull immersed.

Convention: ``x(t) = Re(X exp(i omega t))`` per metre of ``zeta(t) = zeta_a cos(omega t)``, the
wave elevation at midship (crest amidships at t = 0).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.linalg import solve_banded

from seafast.config.loader import CaseError
from seafast.config.modes import HullCargoCoupling
from seafast.config.schema import Case
from seafast.excitation.deck_motion import RigidBodyAmplitudes, assemble_excitation
from seafast.excitation.rao_extension import extended_rao
from seafast.excitation.vessel import vessel_excitation
from seafast.hull.transfer import wave_transfer_functions
from seafast.model.beam import bending_moment_line
from seafast.model.structure import StructuralModel
from seafast.solvers.linear import solve_harmonic, solve_linear

__all__ = ["TransferFunctions", "StillWater", "transfer_functions", "still_water", "MOMENT_POINTS_PER_ELEMENT"]

MOMENT_POINTS_PER_ELEMENT = 2
_HALF_BANDWIDTH = 3  # Hermite beam elements: node i couples to i + 1 (4 DOFs)
"""Bending-moment samples per cargo element (as results.nc's ``x_moment_m``)."""


@dataclass(frozen=True)
class TransferFunctions:
    """Linear transfer functions per metre of wave amplitude, head seas.

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
        (n_w,) heave at the pitch reference [m/m].
    pitch_rad
        (n_w,) pitch dz/dx, bow up [rad/m].
    pitch_reference_x_m
        Ship x of the pitch reference [m].
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
    if case.wave.heading_deg != 180.0:
        raise CaseError(
            f"wave.heading_deg = {case.wave.heading_deg:g}: sea states and frequency sweeps support head seas (180) only; the other "
            "headings are for seafast run (docs/headings.md#8-what-is-left-out); use --set wave.heading_deg=180"
        )


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


def transfer_functions(case: Case, model: StructuralModel, omega_rad_s: ArrayLike) -> TransferFunctions:
    """Transfer functions of the case's linear model at ``omega_rad_s`` (see the module docstring).

    Parameters
    ----------
    case
        The case (vessel, cargo position, gravity; one-way coupling, computed hull girder).
    model
        Its structural model (:func:`seafast.model.from_case.build_model`).
    omega_rad_s
        Wave frequencies [rad/s], > 0, strictly increasing.

    Raises
    ------
    CaseError
        For a deck-deflection table or two-way coupling (no per-frequency hull response), or a heading other than head seas.
    """
    w = np.asarray(omega_rad_s, dtype=float)
    if w.ndim != 1 or w.size == 0 or not np.all(np.isfinite(w)) or np.any(w <= 0) or np.any(np.diff(w) <= 0):
        raise ValueError("transfer_functions: omega_rad_s must be a non-empty, strictly increasing 1-D array of frequencies > 0")
    _check_supported(case)
    vessel = vessel_excitation(case)
    aft = vessel.cargo_aft_end_x_m
    assert vessel.girder is not None and vessel.loading is not None  # a computed hull (checked above)
    hull = wave_transfer_functions(vessel.girder, vessel.loading, w)
    deck_z, deck_slope = hull.deck_at(aft + model.saddle_x_m)
    if vessel.motions is not None:
        heave, pitch = extended_rao(vessel.motions, w, gravity_m_per_s2=case.model.gravity_m_per_s2, draught_m=case.vessel.draft_m)
        ref_x = float(vessel.motions.reference_x_m)
    else:
        heave, pitch, ref_x = np.zeros(w.size, complex), np.zeros(w.size, complex), 0.0
    n_w, n_s = w.size, model.saddle_count
    # The assembly is linear in the deck motion and in omega^2 (heave, pitch): assemble unit
    # heave and unit pitch once at omega = 1 and superpose (the same numbers as one assembly
    # per frequency, without n_w dense mass products).
    unit = [assemble_excitation(model, aft, 1.0, None, None, RigidBodyAmplitudes(h, p, ref_x)) for h, p in ((1.0, 0.0), (0.0, 1.0))]
    w2 = (w**2)[:, None]
    load = w2 * (heave[:, None] * unit[0].cargo_load_N[1] + pitch[:, None] * unit[1].cargo_load_N[1])
    line = w2 * (heave[:, None] * unit[0].cargo_line_load_N_per_m[1] + pitch[:, None] * unit[1].cargo_line_load_N_per_m[1])
    deck = np.zeros((n_w, model.deck_dof_count), complex)  # (z, slope) per saddle, the assembly's deck-DOF order
    deck[:, model.saddle_deck_dof], deck[:, model.saddle_deck_dof + 1] = deck_z, deck_slope
    disp = _harmonic_solves(model, w, load, deck)
    compression = deck[:, model.saddle_deck_dof] - disp[:, model.saddle_cargo_dof]
    beam = model.cargo
    x_m, moment = bending_moment_line(beam.node_x_m, disp, beam.element_bending_stiffness_Nm2, None, line, MOMENT_POINTS_PER_ELEMENT)
    assert compression.shape == (n_w, n_s)
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
    )


def still_water(case: Case, model: StructuralModel) -> StillWater:
    """The linear model's still-water state (``solve_linear`` on the static part, as ``seafast run``)."""
    _check_supported(case)
    static = vessel_excitation(case).cargo_excitation(model, case).static_part()
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
