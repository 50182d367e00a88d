"""The model's data objects built from a validated case (configuration -> model)."""

from __future__ import annotations

import numpy as np

from seafast.config.schema import Case
from seafast.model.axial import AxialRestraint, lashing_axial_stiffness_N_per_m
from seafast.model.seafastening import SeaFastening
from seafast.model.sections import CargoGeometry, TubeSegment
from seafast.model.structure import StructuralModel, build_structural_model

__all__ = ["build_model", "cargo_geometry", "axial_restraint", "DEFAULT_TANGENTIAL_STIFFNESS_N_PER_M"]

#: Default stick stiffness of each saddle's friction contact [N/m]: a rigid contact, 1000 times the
#: base saddle's compression stiffness (docs/axial.md: the results do not depend on it).
DEFAULT_TANGENTIAL_STIFFNESS_N_PER_M = 1e12


def cargo_geometry(case: Case) -> CargoGeometry:
    """The cargo's tube segments and material from the case (one unit)."""
    c = case.cargo
    segments: tuple[TubeSegment, ...]
    if c.sections is None:
        segments = (TubeSegment(0.0, c.length_m, c.diameter_m, c.diameter_m, c.wall_thickness_m),)
    else:
        segments = tuple(TubeSegment(s.x_start_m, s.x_end_m, s.diameter_start_m, s.diameter_end_m, s.wall_thickness_m) for s in c.sections)
    return CargoGeometry(segments, c.youngs_modulus_Pa, c.density_kg_per_m3, c.poisson_ratio)


def axial_restraint(case: Case, cargo_mass_kg: float | None = None) -> AxialRestraint:
    """The cargo's axial restraint from the case (friction, Jenkins stiffness, lashings, stoppers).

    ``cargo_mass_kg``: the cargo's mass when known (the structural model's), else from its geometry.

    Raises
    ------
    ValueError
        If ``seafastening.friction_coefficient`` is not set (no axial analysis).
    """
    mu = case.friction_coefficients()
    if mu is None:
        raise ValueError("seafastening.friction_coefficient is not set: there is no axial analysis to build")
    sf = case.seafastening
    lashing = sf.lashing
    if lashing.axial_stiffness_N_per_m is not None:
        k_axial = float(lashing.axial_stiffness_N_per_m)
    else:
        k_axial = lashing_axial_stiffness_N_per_m(lashing.stiffness_N_per_m, lashing.angle_deg, len(case.lashed_saddle_indices()))
    kt = sf.tangential_stiffness_N_per_m if sf.tangential_stiffness_N_per_m is not None else DEFAULT_TANGENTIAL_STIFFNESS_N_PER_M
    return AxialRestraint(
        cargo_mass_kg=cargo_mass_kg if cargo_mass_kg is not None else cargo_geometry(case).mass_kg(),
        friction_coefficient=np.array(mu),
        tangential_stiffness_N_per_m=np.full(len(mu), float(kt)),
        lashing_axial_stiffness_N_per_m=k_axial,
        stopper_gap_m=sf.stopper.gap_m,
        stopper_stiffness_N_per_m=float(sf.stopper.stiffness_N_per_m or 0.0),
    )


def build_model(case: Case) -> StructuralModel:
    """Cargo + sea-fastening structural model of the case (its beam and fit from a shared
    :class:`~seafast.model.cache.ModelCache` when a ``with cache.shared()`` block is around the call).

    Raises
    ------
    seafast.model.structure.MechanismError
        If the support layout leaves the cargo a mechanism.
    """
    positions = np.array(case.saddle_positions_m())
    lashed = np.zeros(positions.size, dtype=bool)
    lashed[list(case.lashed_saddle_indices())] = True
    sf = SeaFastening(
        saddle_x_m=positions,
        saddle_stiffness_N_per_m=np.array(case.saddle_stiffnesses_N_per_m()),
        lashed=lashed,
        lashing_wire_stiffness_N_per_m=case.seafastening.lashing.stiffness_N_per_m,
        lashing_pretension_N=case.seafastening.lashing.pretension_N,
    )
    return build_structural_model(
        cargo_geometry(case),
        sf,
        target_element_length_m=case.model.element_length_m,
        damping_ratio=case.model.damping_ratio,
        gravity_m_per_s2=case.model.gravity_m_per_s2,
    )
