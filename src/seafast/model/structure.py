"""The cargo-and-sea-fastening linear system, partitioned into cargo DOFs and deck DOFs.

DOF layout
----------
* Cargo DOFs ``c``: (z, theta) at every cargo node, ``2 * n_nodes`` of them, node order along
  the cargo from its aft end. ``z`` is relative to the vessel's rigid-body frame [m].
* Deck DOFs ``o``: (z, theta) of the deck point under every saddle, ``2 * n_saddles`` of them,
  saddle order. They are prescribed (the excitation).

Springs connect a cargo DOF and a deck DOF. Saddles act on z; lashings add a vertical spring
k_z and a rotational spring k_theta at the lashed saddles. In the *linear* model every saddle is
a bilateral spring with its full stiffness; in the *nonlinear* model the compression-only part
(k_sad - k_z) is left out of the linear matrices and enters as the contact force
``f(delta)`` with ``delta = z_deck - z_cargo`` (saddle compression, positive when compressed).

Harmonic convention: a periodic quantity is ``x(t) = Re(sum_k X_k exp(i k omega t))``; k = 0 is
the static (mean) part and is real.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from seafast.model.beam import assemble_beam
from seafast.model.damping import RayleighFit, fit_rayleigh_to_modes, rayleigh_coefficients
from seafast.model.mesh import mesh_cargo
from seafast.model.sections import CargoGeometry, tube_area_m2, tube_second_moment_m4
from seafast.model.seafastening import SeaFastening

logger = logging.getLogger(__name__)

__all__ = [
    "CargoBeam",
    "StructuralModel",
    "RayleighFit",
    "build_cargo_beam",
    "build_structural_model",
    "fit_rayleigh_to_modes",
    "rayleigh_coefficients",
]  # the damping names are re-exported from seafast.model.damping


@dataclass(frozen=True)
class CargoBeam:
    """Finite-element model of the free cargo beam (Euler-Bernoulli, consistent mass).

    Per-element arrays have length ``n_nodes - 1``.
    """

    node_x_m: NDArray[np.float64]
    element_outer_diameter_m: NDArray[np.float64]
    element_wall_thickness_m: NDArray[np.float64]
    element_second_moment_m4: NDArray[np.float64]
    element_bending_stiffness_Nm2: NDArray[np.float64]
    element_mass_per_length_kg_per_m: NDArray[np.float64]
    stiffness: NDArray[np.float64]
    mass: NDArray[np.float64]
    gravity_line_load_N_per_m: NDArray[np.float64]
    gravity_load_N: NDArray[np.float64]

    @property
    def node_count(self) -> int:
        return int(self.node_x_m.size)

    @property
    def element_count(self) -> int:
        return int(self.node_x_m.size - 1)

    @property
    def element_mid_x_m(self) -> NDArray[np.float64]:
        return 0.5 * (self.node_x_m[1:] + self.node_x_m[:-1])

    @property
    def mass_kg(self) -> float:
        return float(np.sum(self.element_mass_per_length_kg_per_m * np.diff(self.node_x_m)))


def build_cargo_beam(
    geometry: CargoGeometry,
    fixed_points_m: NDArray[np.float64],
    target_element_length_m: float,
    gravity_m_per_s2: float = 9.81,
) -> CargoBeam:
    """Mesh and assemble the cargo beam; section properties at element midpoints."""
    x = mesh_cargo(geometry.length_m, np.concatenate([fixed_points_m, geometry.segment_boundaries_m]), target_element_length_m)
    xm = 0.5 * (x[1:] + x[:-1])
    D, t = geometry.section_at(xm)
    I = tube_second_moment_m4(D, t)
    A = tube_area_m2(D, t)
    EI = geometry.youngs_modulus_Pa * I
    m = geometry.density_kg_per_m3 * A
    q = -m * gravity_m_per_s2
    K, M, f = assemble_beam(x, EI, m, load_N_per_m=q)
    return CargoBeam(
        node_x_m=x,
        element_outer_diameter_m=D,
        element_wall_thickness_m=t,
        element_second_moment_m4=I,
        element_bending_stiffness_Nm2=EI,
        element_mass_per_length_kg_per_m=m,
        stiffness=K,
        mass=M,
        gravity_line_load_N_per_m=q,
        gravity_load_N=f,
    )


@dataclass(frozen=True)
class StructuralModel:
    """Linear matrices of cargo + sea-fastening, and the saddle (contact) map.

    Attributes
    ----------
    cargo
        The free cargo beam.
    seafastening
        The sea-fastening definition it was built from.
    saddle_node
        Cargo node index of each saddle.
    saddle_cargo_dof, saddle_deck_dof
        Index of the saddle's z DOF in the cargo DOFs and in the deck DOFs.
    saddle_stiffness_N_per_m
        Full saddle stiffness (used bilaterally in the linear model) [N/m].
    saddle_unilateral_stiffness_N_per_m
        Compression-only part (k_sad - k_z at lashed saddles) [N/m]: the nonlinear springs.
    pretension_load_N
        Nodal load vector of lashing pretension on the cargo DOFs [N, N m].
    rayleigh_alpha_per_s, rayleigh_beta_s
        Damping D = alpha M + beta K_beam on the cargo beam (springs undamped), fitted so that the first two
        modes have the requested damping ratio (:func:`fit_rayleigh_to_modes`).
    rayleigh_fit
        The fit (realised modal damping of the first two modes, whether it is exact), or None for a model
        built with given coefficients.
    """

    cargo: CargoBeam
    seafastening: SeaFastening
    saddle_node: NDArray[np.intp]
    rayleigh_alpha_per_s: float
    rayleigh_beta_s: float
    gravity_m_per_s2: float = 9.81
    rayleigh_fit: RayleighFit | None = None
    _springs: dict = field(default_factory=dict, repr=False, compare=False)

    # ---------------------------------------------------------------- sizes and maps
    @property
    def cargo_dof_count(self) -> int:
        return 2 * self.cargo.node_count

    @property
    def deck_dof_count(self) -> int:
        return 2 * self.saddle_count

    @property
    def saddle_count(self) -> int:
        return int(self.saddle_node.size)

    @property
    def saddle_x_m(self) -> NDArray[np.float64]:
        return self.cargo.node_x_m[self.saddle_node]

    @property
    def saddle_cargo_dof(self) -> NDArray[np.intp]:
        return 2 * self.saddle_node

    @property
    def saddle_deck_dof(self) -> NDArray[np.intp]:
        return 2 * np.arange(self.saddle_count)

    @property
    def saddle_stiffness_N_per_m(self) -> NDArray[np.float64]:
        return np.asarray(self.seafastening.saddle_stiffness_N_per_m, dtype=float)

    @property
    def saddle_unilateral_stiffness_N_per_m(self) -> NDArray[np.float64]:
        return self.seafastening.unilateral_stiffness_N_per_m

    @property
    def static_load_N(self) -> NDArray[np.float64]:
        """Cargo self-weight plus lashing pretension, as cargo nodal loads [N, N m]."""
        return self.cargo.gravity_load_N + self.pretension_load_N

    @property
    def pretension_load_N(self) -> NDArray[np.float64]:
        f = np.zeros(self.cargo_dof_count)
        f[self.saddle_cargo_dof] -= self.seafastening.saddle_pretension_N
        return f

    # ---------------------------------------------------------------- matrices
    def spring_matrices(self, include_saddles: bool) -> tuple[NDArray, NDArray, NDArray]:
        """Spring stiffness blocks (K_cc, K_co, K_oo) [SI] of the sea-fastening.

        ``include_saddles=True``: saddles bilateral with their full stiffness (linear model).
        ``include_saddles=False``: lashings only (k_z, k_theta); the compression-only part of
        each saddle is then the nonlinear contact force.
        """
        key = bool(include_saddles)
        if key not in self._springs:
            nc, no = self.cargo_dof_count, self.deck_dof_count
            kz = self.seafastening.lashing_vertical_stiffness_N_per_m.astype(float)
            if include_saddles:
                kz = kz + self.saddle_unilateral_stiffness_N_per_m
            kt = self.seafastening.lashing_rotational_stiffness_Nm_per_rad.astype(float)
            Kcc = np.zeros((nc, nc))
            Kco = np.zeros((nc, no))
            Koo = np.zeros((no, no))
            for k_vec, c_dofs, o_dofs in (
                (kz, self.saddle_cargo_dof, self.saddle_deck_dof),
                (kt, self.saddle_cargo_dof + 1, self.saddle_deck_dof + 1),
            ):
                Kcc[c_dofs, c_dofs] += k_vec
                Kco[c_dofs, o_dofs] -= k_vec
                Koo[o_dofs, o_dofs] += k_vec
            self._springs[key] = (Kcc, Kco, Koo)
        return self._springs[key]

    @property
    def damping_cc(self) -> NDArray[np.float64]:
        """Rayleigh damping of the cargo beam [N s/m, ...]."""
        return self.rayleigh_alpha_per_s * self.cargo.mass + self.rayleigh_beta_s * self.cargo.stiffness

    def dynamic_stiffness(self, omega_rad_s: float, include_saddles: bool) -> tuple[NDArray, NDArray, NDArray, NDArray]:
        """Dynamic stiffness blocks K_d = K - omega^2 M + i omega D at ``omega_rad_s``.

        Returns (Kd_cc, Kd_co, Kd_oc, Kd_oo); real arrays at omega = 0, complex otherwise.
        Mass and damping live on the cargo DOFs only (deck DOFs are prescribed).
        """
        Kcc, Kco, Koo = self.spring_matrices(include_saddles)
        Kd_cc = self.cargo.stiffness + Kcc
        if omega_rad_s != 0.0:
            Kd_cc = Kd_cc - omega_rad_s**2 * self.cargo.mass + 1j * omega_rad_s * self.damping_cc
        return Kd_cc, Kco, Kco.T, Koo

    def natural_frequencies_rad_s(self, include_saddles: bool = True, count: int = 6) -> NDArray[np.float64]:
        """Lowest undamped natural frequencies [rad/s] with the deck held fixed."""
        from scipy.linalg import eigh

        Kcc = self.cargo.stiffness + self.spring_matrices(include_saddles)[0]
        w2 = eigh(Kcc, self.cargo.mass, eigvals_only=True, subset_by_index=[0, min(count, self.cargo_dof_count) - 1])
        return np.sqrt(np.maximum(w2, 0.0))

    def first_modes_beam_share(self, count: int = 2) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Lowest natural frequencies [rad/s] on bilateral saddles and ``kappa_i = phi^T K_beam phi / phi^T M phi``.

        ``kappa_i / omega_i^2`` is the share of the mode's strain energy in the cargo beam (the rest is in the
        saddle and lashing springs).
        """
        from scipy.linalg import eigh

        Kcc = self.cargo.stiffness + self.spring_matrices(True)[0]
        n = min(count, self.cargo_dof_count)
        w2, phi = eigh(Kcc, self.cargo.mass, subset_by_index=[0, n - 1])
        kappa = np.einsum("ij,ik,kj->j", phi, self.cargo.stiffness, phi) / np.einsum("ij,ik,kj->j", phi, self.cargo.mass, phi)
        return np.sqrt(np.maximum(w2, 0.0)), kappa

    def modal_damping_ratios(self, count: int = 2) -> NDArray[np.float64]:
        """Realised damping ``phi^T D phi / (2 omega phi^T M phi)`` of the lowest modes on bilateral saddles [-]."""
        from scipy.linalg import eigh

        Kcc = self.cargo.stiffness + self.spring_matrices(True)[0]
        n = min(count, self.cargo_dof_count)
        w2, phi = eigh(Kcc, self.cargo.mass, subset_by_index=[0, n - 1])
        w = np.sqrt(np.maximum(w2, 0.0))
        num = np.einsum("ij,ik,kj->j", phi, self.damping_cc, phi)
        den = 2.0 * w * np.einsum("ij,ik,kj->j", phi, self.cargo.mass, phi)
        return np.asarray(num / den, dtype=float)


class MechanismError(ValueError):
    """The support layout leaves the cargo free to move as a rigid body (a mechanism)."""


def build_structural_model(
    geometry: CargoGeometry,
    seafastening: SeaFastening,
    *,
    target_element_length_m: float = 1.0,
    damping_ratio: float = 0.02,
    gravity_m_per_s2: float = 9.81,
) -> StructuralModel:
    """Mesh the cargo with a node at every saddle and assemble the partitioned linear system.

    Rayleigh damping ``D = alpha M + beta K_beam``: the *realised* modal damping of the first two modes of the
    cargo on bilateral saddles (deck fixed) equals ``damping_ratio`` (the documented default is 2 %); see
    :func:`fit_rayleigh_to_modes` for why beta must be fitted on the modes and for the fallback.

    Raises
    ------
    MechanismError
        If the cargo on bilateral saddles and lashings is not stable (fewer than two distinct
        supports and no rotational restraint).
    """
    xs = np.asarray(seafastening.saddle_x_m, dtype=float)
    beam = build_cargo_beam(geometry, xs, target_element_length_m, gravity_m_per_s2)
    nodes = np.array([int(np.argmin(np.abs(beam.node_x_m - x))) for x in xs], dtype=np.intp)
    model = StructuralModel(beam, seafastening, nodes, 0.0, 0.0, gravity_m_per_s2)
    # Stability: the cargo on bilateral saddles must have no zero-energy mode. Judge the
    # lowest eigenvalue of K against the beam's stiffness scale.
    Kcc = beam.stiffness + model.spring_matrices(True)[0]
    eig_min = float(np.linalg.eigvalsh(Kcc)[0])
    scale = float(np.max(np.diag(beam.stiffness)))
    if eig_min <= 1e-12 * scale:
        raise MechanismError(
            "seafastening: the support layout leaves the cargo a mechanism (free to translate or "
            f"rotate): {xs.size} saddle(s) at {np.round(xs, 3).tolist()} m with rotational lashing "
            f"stiffness {model.seafastening.lashing_rotational_stiffness_Nm_per_rad.tolist()} N m/rad; "
            "allowed: at least two distinct saddle positions with positive stiffness, or one saddle "
            "with a rotational lashing"
        )
    fit = fit_rayleigh_to_modes(damping_ratio, *model.first_modes_beam_share())
    if not fit.exact:
        logger.warning(
            "model.damping_ratio = %g: Rayleigh damping cannot give both of the first two modes (%.3g, %.3g rad/s) this "
            "ratio with non-negative, moderate coefficients; fallback (classic beta, least-squares alpha), realised %.4f and %.4f",
            damping_ratio, fit.omega_rad_s[0], fit.omega_rad_s[1], *fit.realised_damping_ratio,
        )
    return StructuralModel(beam, seafastening, nodes, fit.alpha_per_s, fit.beta_s, gravity_m_per_s2, rayleigh_fit=fit)
