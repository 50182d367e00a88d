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

Size: over 400 lines because the model's matrices, their banded forms, the eigen-solves, the damping's
support coupling and the mechanism test share the model's layout; splitting them would make private
layout helpers public. What a study reuses between its models is kept by a
:class:`~seafast.model.cache.ModelCache` its caller owns.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass, field

import numpy as np
import scipy.linalg
from numpy.typing import NDArray

from seafast.model.beam import assemble_beam
from seafast.model.cache import ModelCache, shared_model_cache
from seafast.model.damping import RayleighFit, fit_rayleigh_to_modes, rayleigh_coefficients
from seafast.model.mesh import mesh_cargo
from seafast.model.seafastening import SeaFastening
from seafast.model.sections import CargoGeometry, tube_area_m2, tube_second_moment_m4
from seafast.model.warning import ModelWarning

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

    @property
    def half_bandwidth(self) -> int:
        """Half-bandwidth of K and M: 3 (two-node elements, DOFs numbered node by node)."""
        return 3


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
    I_m4 = tube_second_moment_m4(D, t)
    A = tube_area_m2(D, t)
    EI = geometry.youngs_modulus_Pa * I_m4
    m = geometry.density_kg_per_m3 * A
    q = -m * gravity_m_per_s2
    K, M, f = assemble_beam(x, EI, m, load_N_per_m=q)
    return CargoBeam(
        node_x_m=x,
        element_outer_diameter_m=D,
        element_wall_thickness_m=t,
        element_second_moment_m4=I_m4,
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
    derived_cache
        What the layers above derive from this model and keep with it (the solvers' banded K, M, D and
        modal basis), keyed by what is derived: computed once per model, never shared with another
        (a copy of the model starts empty), dropped with the model.
    """

    cargo: CargoBeam
    seafastening: SeaFastening
    saddle_node: NDArray[np.intp]
    rayleigh_alpha_per_s: float
    rayleigh_beta_s: float
    gravity_m_per_s2: float = 9.81
    rayleigh_fit: RayleighFit | None = None
    _springs: dict = field(default_factory=dict, repr=False, compare=False)
    derived_cache: dict[str, object] = field(default_factory=dict, init=False, repr=False, compare=False)

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
    def warnings(self) -> tuple[ModelWarning, ...]:
        """The model's typed warnings (its Rayleigh fit's)."""
        return () if self.rayleigh_fit is None else self.rayleigh_fit.warnings

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
            diagonal, Kco, Koo = self.spring_parts(include_saddles)
            self._springs[key] = (np.diag(diagonal), Kco, Koo)
        return self._springs[key]

    def spring_parts(self, include_saddles: bool) -> tuple[NDArray, NDArray, NDArray]:
        """The springs' K_cc as its diagonal (it has nothing else), with K_co and K_oo [SI].

        See :meth:`spring_matrices`; O(n) where the dense K_cc is O(n^2).
        """
        key = ("parts", bool(include_saddles))
        if key not in self._springs:
            nc, no = self.cargo_dof_count, self.deck_dof_count
            kz = self.seafastening.lashing_vertical_stiffness_N_per_m.astype(float)
            if include_saddles:
                kz = kz + self.saddle_unilateral_stiffness_N_per_m
            kt = self.seafastening.lashing_rotational_stiffness_Nm_per_rad.astype(float)
            diagonal = np.zeros(nc)
            Kco = np.zeros((nc, no))
            Koo = np.zeros((no, no))
            for k_vec, c_dofs, o_dofs in (
                (kz, self.saddle_cargo_dof, self.saddle_deck_dof),
                (kt, self.saddle_cargo_dof + 1, self.saddle_deck_dof + 1),
            ):
                diagonal[c_dofs] += k_vec
                Kco[c_dofs, o_dofs] -= k_vec
                Koo[o_dofs, o_dofs] += k_vec
            self._springs[key] = (diagonal, Kco, Koo)
        return self._springs[key]

    @property
    def damping_cc(self) -> NDArray[np.float64]:
        """Rayleigh damping of the cargo beam [N s/m, ...]."""
        return self.rayleigh_alpha_per_s * self.cargo.mass + self.rayleigh_beta_s * self.cargo.stiffness

    @property
    def quasi_static_support_influence(self) -> NDArray[np.float64]:
        """``S = -K_cc^-1 K_co`` (n_c, n_o): the cargo displacement the deck DOFs impose quasi-statically [m/m, ...].

        ``S x_o`` is the static response of the cargo on bilateral saddles (their full stiffness, lashings) to the
        deck DOFs ``x_o`` alone: the motion the supports impose. It is the same for the linear and the nonlinear
        model (the damping law below must not depend on which saddles are in contact).
        """
        key = "support_influence"
        if key not in self._springs:
            b = self.cargo.half_bandwidth
            springs, Kco, _ = self.spring_parts(True)
            band = _upper_band(self.cargo.stiffness, b)
            band[b] += springs
            self._springs[key] = -scipy.linalg.solveh_banded(band, Kco, check_finite=False)
        return self._springs[key]

    @property
    def support_damping_coupling(self) -> NDArray[np.float64]:
        """``D_co = -D S`` (n_c, n_o) [N s/m, ...]: the damping's coupling to the deck velocities.

        The cargo's damping acts on its motion relative to the motion the supports impose quasi-statically,
        ``D (q' - S x_o')`` (:attr:`quasi_static_support_influence`): structural damping dissipates on
        deformation, and a cargo that follows the deck's quasi-static deflection rigidly is not damped by it. On
        the right-hand side that is ``+ D S x_o' = - D_co x_o'``, beside the springs' ``- K_co x_o``; per harmonic
        the cargo-deck coupling is ``K_co + i k omega D_co`` (:meth:`dynamic_stiffness`). The springs themselves
        carry no dashpot, so the forces on the deck stay ``K_oc q + K_oo x_o``.
        """
        key = "support_damping"
        if key not in self._springs:
            b = self.cargo.half_bandwidth
            mass, beam = _full_band(self.cargo.mass, b), _full_band(self.cargo.stiffness, b)
            damping = self.rayleigh_alpha_per_s * mass + self.rayleigh_beta_s * beam
            self._springs[key] = -_band_matmul(damping, b, self.quasi_static_support_influence)
        return self._springs[key]

    def dynamic_stiffness(self, omega_rad_s: float, include_saddles: bool) -> tuple[NDArray, NDArray, NDArray, NDArray]:
        """Dynamic stiffness blocks K_d = K - omega^2 M + i omega D at ``omega_rad_s``.

        Returns (Kd_cc, Kd_co, Kd_oc, Kd_oo); real arrays at omega = 0, complex otherwise. Mass and damping live
        on the cargo DOFs only (deck DOFs are prescribed); the damping's coupling to the deck velocities,
        ``Kd_co = K_co + i omega D_co`` (:attr:`support_damping_coupling`), loads the cargo, not the deck:
        ``Kd_oc = K_co^T``.
        """
        Kcc, Kco, Koo = self.spring_matrices(include_saddles)
        Kd_cc = self.cargo.stiffness + Kcc
        Kd_co = Kco
        if omega_rad_s != 0.0:
            Kd_cc = Kd_cc - omega_rad_s**2 * self.cargo.mass + 1j * omega_rad_s * self.damping_cc
            Kd_co = Kco + 1j * omega_rad_s * self.support_damping_coupling
        return Kd_cc, Kd_co, Kco.T, Koo

    def banded_quadratic(self, include_saddles: bool) -> tuple[int, NDArray, NDArray, NDArray, NDArray]:
        """The parts of :meth:`dynamic_stiffness` ``K_d^cc(w) = K - w^2 M + i w D``, banded, in O(n).

        Returns ``(b, K, M, D, K_co)``: the half-bandwidth b, K (beam plus springs), M and the
        Rayleigh D = alpha M + beta K_beam of the cargo DOFs in full band storage
        ``ab[b + i - j, j] = A[i, j]`` (the layout of :func:`scipy.linalg.solve_banded`), and the
        cargo-deck coupling K_co (frequency-independent: the deck carries no mass or damping).
        The same numbers as :meth:`dynamic_stiffness` without forming n x n arrays.
        """
        b = self.cargo.half_bandwidth
        springs, Kco, _ = self.spring_parts(include_saddles)
        beam_K, mass = _full_band(self.cargo.stiffness, b), _full_band(self.cargo.mass, b)
        K = beam_K.copy()
        K[b] += springs
        return b, K, mass, self.rayleigh_alpha_per_s * mass + self.rayleigh_beta_s * beam_K, Kco

    def lowest_modes(
        self, include_saddles: bool = True, count: int = 6, vectors: bool = False
    ) -> tuple[NDArray[np.float64], NDArray[np.float64] | None]:
        """Lowest undamped natural frequencies [rad/s] with the deck held fixed, and (``vectors``) the
        M-normalised mode shapes (n_c, count).

        Dense generalised eigen-solve up to :data:`DENSE_EIGEN_DOFS` cargo DOFs; beyond, the
        lowest ``count`` by shift-invert Lanczos (ARPACK) about 0, the inverse applied by a
        banded Cholesky of K (half-bandwidth 3): O(n) instead of the dense O(n^3), and more
        accurate for the lowest modes of a fine mesh (the dense solve loses them in the
        stiffness's spread). The Lanczos start vector is fixed, so the result is reproducible.
        """
        springs = self.spring_parts(include_saddles)[0]
        n = self.cargo_dof_count
        count = min(count, n)
        phi: NDArray[np.float64] | None
        if n <= DENSE_EIGEN_DOFS or 2 * count + 4 >= n:
            Kcc = self.cargo.stiffness + np.diag(springs)
            if vectors:
                w2, phi = scipy.linalg.eigh(Kcc, self.cargo.mass, subset_by_index=[0, count - 1], check_finite=False)
            else:
                w2 = scipy.linalg.eigh(Kcc, self.cargo.mass, eigvals_only=True, subset_by_index=[0, count - 1], check_finite=False)
                phi = None
        else:
            from scipy import sparse
            from scipy.sparse.linalg import LinearOperator, eigsh

            def symmetric(band: NDArray[np.float64]) -> sparse.csr_matrix:
                upper = sparse.dia_matrix((band[::-1], np.arange(4)), shape=(n, n))
                return (upper + sparse.triu(upper, 1).T).tocsr()

            K_band = _upper_band(self.cargo.stiffness, 3)
            K_band[3] += springs
            factor = (scipy.linalg.cholesky_banded(K_band, check_finite=False), False)
            inverse = LinearOperator((n, n), matvec=lambda v: scipy.linalg.cho_solve_banded(factor, v, check_finite=False), dtype=float)
            M_sparse = symmetric(_upper_band(self.cargo.mass, 3))
            K_sparse = symmetric(K_band)
            # one call per branch: the eigenvectors' flag is a literal for each (the stubs overload on it)
            if vectors:
                w2, phi = eigsh(
                    K_sparse,
                    k=count,
                    M=M_sparse,
                    sigma=0.0,
                    which="LM",
                    OPinv=inverse,
                    v0=np.ones(n),
                    ncv=2 * count + 4,
                    return_eigenvectors=True,
                )
                order = np.argsort(w2)
                w2, phi = w2[order], phi[:, order]
                phi = phi / np.sqrt(np.einsum("ij,ij->j", phi, M_sparse @ phi))
            else:
                w2 = eigsh(
                    K_sparse,
                    k=count,
                    M=M_sparse,
                    sigma=0.0,
                    which="LM",
                    OPinv=inverse,
                    v0=np.ones(n),
                    ncv=2 * count + 4,
                    return_eigenvectors=False,
                )
                w2, phi = np.sort(w2), None
        return np.sqrt(np.maximum(w2, 0.0)), phi

    def natural_frequencies_rad_s(self, include_saddles: bool = True, count: int = 6) -> NDArray[np.float64]:
        """Lowest undamped natural frequencies [rad/s] with the deck held fixed (:meth:`lowest_modes`)."""
        return self.lowest_modes(include_saddles, count)[0]

    def first_modes_beam_share(self, count: int = 2) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Lowest natural frequencies [rad/s] on bilateral saddles and ``kappa_i = phi^T K_beam phi / phi^T M phi``.

        ``kappa_i / omega_i^2`` is the share of the mode's strain energy in the cargo beam (the rest is in the
        saddle and lashing springs).
        """
        w, phi = self.lowest_modes(True, count, vectors=True)
        assert phi is not None
        kappa = np.einsum("ij,ij->j", phi, self.cargo.stiffness @ phi) / np.einsum("ij,ij->j", phi, self.cargo.mass @ phi)
        return w, kappa

    def modal_damping_ratios(self, count: int = 2) -> NDArray[np.float64]:
        """Realised damping ``phi^T D phi / (2 omega phi^T M phi)`` of the lowest modes on bilateral saddles [-]."""
        w, phi = self.lowest_modes(True, count, vectors=True)
        assert phi is not None
        num = np.einsum("ij,ij->j", phi, self.damping_cc @ phi)
        den = 2.0 * w * np.einsum("ij,ij->j", phi, self.cargo.mass @ phi)
        return np.asarray(num / den, dtype=float)


class MechanismError(ValueError):
    """The support layout leaves the cargo free to move as a rigid body (a mechanism)."""


DENSE_EIGEN_DOFS = 200
"""Largest cargo model (DOFs) whose natural frequencies are computed by a dense eigen-solve
(O(n^3); the banded shift-invert Lanczos costs about the same at 180 DOFs and less beyond)."""


def _cargo_beam(
    geometry: CargoGeometry,
    fixed_points_m: NDArray[np.float64],
    target_element_length_m: float,
    gravity_m_per_s2: float,
    cache: ModelCache | None,
) -> tuple[CargoBeam, tuple]:
    """The meshed and assembled cargo beam (the one ``cache`` keeps for these inputs, if any); returns (beam, key)."""
    key = (geometry, tuple(float(x) for x in fixed_points_m), float(target_element_length_m), float(gravity_m_per_s2))

    def build() -> CargoBeam:
        return build_cargo_beam(geometry, fixed_points_m, target_element_length_m, gravity_m_per_s2)

    return (build() if cache is None else cache.beam(key, build)), key


def _full_band(A: NDArray[np.float64], bandwidth: int) -> NDArray[np.float64]:
    """Full band storage ``ab[b + i - j, j] = A[i, j]`` of a banded matrix (read by diagonals, O(n b))."""
    n = A.shape[0]
    band = np.zeros((2 * bandwidth + 1, n), dtype=A.dtype)
    for offset in range(-bandwidth, bandwidth + 1):
        d = np.diagonal(A, offset)
        if offset >= 0:
            band[bandwidth - offset, offset:] = d
        else:
            band[bandwidth - offset, : n + offset] = d
    return band


def _band_matmul(band: NDArray[np.float64], bandwidth: int, X: NDArray[np.float64]) -> NDArray[np.float64]:
    """``A @ X`` for A in full band storage ``band[b + i - j, j] = A[i, j]`` (O(n b) per column of X)."""
    n = band.shape[1]
    out = np.zeros((n, *X.shape[1:]), dtype=np.result_type(band, X))
    for offset in range(-bandwidth, bandwidth + 1):
        rows = np.arange(max(0, -offset), min(n, n - offset))
        out[rows] += band[bandwidth - offset, rows + offset][:, None] * X[rows + offset]
    return out


def _upper_band(A: NDArray[np.float64], bandwidth: int) -> NDArray[np.float64]:
    """Upper band storage ``ab[b + i - j, j] = A[i, j]`` of a symmetric banded matrix (scipy's layout)."""
    band = np.zeros((bandwidth + 1, A.shape[0]))
    for d in range(bandwidth + 1):
        band[bandwidth - d, d:] = np.diagonal(A, d)
    return band


def _is_positive_definite_banded(A: NDArray[np.float64], diagonal: NDArray[np.float64], bandwidth: int, shift: float) -> bool:
    """Whether ``A + diag(diagonal) - shift I`` is positive definite (banded Cholesky, O(n b^2)); A symmetric, banded."""
    band = _upper_band(A, bandwidth)
    band[bandwidth] += diagonal - shift
    try:
        scipy.linalg.cholesky_banded(band, lower=False, check_finite=False)
    except np.linalg.LinAlgError:
        return False
    return True


def build_structural_model(
    geometry: CargoGeometry,
    seafastening: SeaFastening,
    *,
    target_element_length_m: float = 1.0,
    damping_ratio: float = 0.02,
    gravity_m_per_s2: float = 9.81,
    cache: ModelCache | None = None,
) -> StructuralModel:
    """Mesh the cargo with a node at every saddle and assemble the partitioned linear system.

    Rayleigh damping ``D = alpha M + beta K_beam``: the *realised* modal damping of the first two modes of the
    cargo on bilateral saddles (deck fixed) equals ``damping_ratio`` (the documented default is 2 %); see
    :func:`fit_rayleigh_to_modes` for why beta must be fitted on the modes and for the fallback.

    ``cache``: where the meshed beam and the Rayleigh fit are kept and found again
    (:class:`~seafast.model.cache.ModelCache`); default the one shared by the innermost
    ``with cache.shared()`` block around this call, else none (built afresh). The model is the same either way.

    Raises
    ------
    MechanismError
        If the cargo on bilateral saddles and lashings is not stable (fewer than two distinct
        supports and no rotational restraint).
    """
    cache = cache if cache is not None else shared_model_cache()
    xs = np.asarray(seafastening.saddle_x_m, dtype=float)
    beam, beam_key = _cargo_beam(geometry, xs, target_element_length_m, gravity_m_per_s2, cache)
    nodes = np.array([int(np.argmin(np.abs(beam.node_x_m - x))) for x in xs], dtype=np.intp)
    model = StructuralModel(beam, seafastening, nodes, 0.0, 0.0, gravity_m_per_s2)
    # Stability: the cargo on bilateral saddles must have no zero-energy mode: its lowest
    # stiffness eigenvalue must exceed 1e-12 of the beam's stiffness scale, i.e. K - 1e-12 scale I
    # must be positive definite. A chain of two-node beam elements with springs on the
    # diagonal has half-bandwidth 3, so a banded Cholesky decides it in O(n).
    scale = float(np.max(np.diag(beam.stiffness)))
    if not _is_positive_definite_banded(beam.stiffness, model.spring_parts(True)[0], 3, 1e-12 * scale):
        raise MechanismError(
            "seafastening: the support layout leaves the cargo a mechanism (free to translate or "
            f"rotate): {xs.size} saddle(s) at {np.round(xs, 3).tolist()} m with rotational lashing "
            f"stiffness {model.seafastening.lashing_rotational_stiffness_Nm_per_rad.tolist()} N m/rad; "
            "allowed: at least two distinct saddle positions with positive stiffness, or one saddle "
            "with a rotational lashing"
        )
    sf = seafastening
    springs = (sf.lashing_vertical_stiffness_N_per_m, sf.lashing_rotational_stiffness_Nm_per_rad, sf.unilateral_stiffness_N_per_m)
    rayleigh_key = (beam_key, tuple(nodes.tolist()), *(np.asarray(k, dtype=float).tobytes() for k in springs), float(damping_ratio))
    fit = (
        _rayleigh_fit(model, damping_ratio)
        if cache is None
        else cache.rayleigh_fit(rayleigh_key, lambda: _rayleigh_fit(model, damping_ratio))
    )
    return StructuralModel(beam, seafastening, nodes, fit.alpha_per_s, fit.beta_s, gravity_m_per_s2, rayleigh_fit=fit)


def _rayleigh_fit(model: StructuralModel, damping_ratio: float) -> RayleighFit:
    """The Rayleigh fit on the model's first two modes, logged when it falls back (once per fit made)."""
    fit = fit_rayleigh_to_modes(damping_ratio, *model.first_modes_beam_share())
    if not fit.exact:
        # beyond RAYLEIGH_FALLBACK_TOLERANCE a typed warning of the model (StructuralModel.warnings), else a detail
        log = logger.warning if fit.warnings else logger.info
        log(
            "model.damping_ratio = %g: Rayleigh damping cannot give both of the first two modes (%.3g, %.3g rad/s) this "
            "ratio with non-negative, moderate coefficients; fallback (classic beta, least-squares alpha), realised %.4f and %.4f",
            damping_ratio,
            fit.omega_rad_s[0],
            fit.omega_rad_s[1],
            *fit.realised_damping_ratio,
        )
    return fit
