"""The cargo in three dimensions: vertical and lateral bending, and the axial bar.

DOF ordering
------------
Three blocks, each node by node from the cargo's aft end (``n`` nodes, ``5 n`` DOFs):

* ``[0, 2n)``: the vertical plane, ``(w_i, theta_i)``: today's cargo DOFs ``(z, theta = dz/dx)``
  in today's order, so this block's stiffness and mass are today's :class:`CargoBeam` matrices;
* ``[2n, 4n)``: the lateral plane, ``(v_i, psi_i)`` with ``v`` to port and ``psi = dv/dx``: the same
  Hermite element (a tube: ``I_y = I_z``), the same matrices;
* ``[4n, 5n)``: the axial translations ``u_i`` (forward +): two-node bars, ``EA / L [[1, -1], [-1, 1]]``,
  consistent mass ``m L / 6 [[2, 1], [1, 2]]``.

The blocks are uncoupled in the beam (a straight tube, small displacements); the cradles and
lashings couple them (:mod:`seafast.model.cradle`). Torsion is not a DOF.

Gravity in the ship frame
-------------------------
A steady heel ``phi`` (starboard down +, the roll of docs/headings.md) and trim ``theta`` (bow up
+, the project's pitch) put gravity along ``g (-sin theta, -cos theta sin phi, -cos theta cos phi)``
in the ship frame (x forward, y to port, z up): to starboard when heeled to starboard, aft when
trimmed by the bow up. Its linearisation is docs/headings.md's ``(-g theta, -g phi, -g)``; at
``phi = theta = 0`` it is ``(0, 0, -g)`` and the vertical load is today's to the bit.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from seafast.model.beam import assemble_beam
from seafast.model.sections import tube_area_m2
from seafast.model.structure import CargoBeam, StructuralModel

__all__ = ["Cargo3D", "build_cargo3d", "gravity_direction", "vertical_plane_restraint"]

DOFS_PER_NODE = 5
"""u, v, w, psi, theta (three blocks, see the module's docstring)."""


def gravity_direction(heel_deg: float, trim_deg: float) -> NDArray[np.float64]:
    """Unit vector of gravity in the ship frame (x forward, y to port, z up) at a steady heel and trim [-].

    ``heel_deg``: starboard down +; ``trim_deg``: bow up +. ``(-sin theta, -cos theta sin phi, -cos theta cos phi)``.
    """
    phi, theta = np.deg2rad(float(heel_deg)), np.deg2rad(float(trim_deg))
    return np.array([-np.sin(theta), -np.cos(theta) * np.sin(phi), -np.cos(theta) * np.cos(phi)])


@dataclass(frozen=True)
class Cargo3D:
    """The free cargo beam in three dimensions (Euler-Bernoulli, consistent mass).

    Attributes
    ----------
    vertical
        Today's vertical-plane beam (its mesh, sections and matrices, reused as they are).
    element_axial_stiffness_N
        EA per element [N].
    stiffness, mass
        Dense ``(5 n, 5 n)`` stiffness [N/m, N, N m] and mass [kg, kg m, kg m^2] in the block order
        of the module's docstring.
    """

    vertical: CargoBeam
    element_axial_stiffness_N: NDArray[np.float64]
    stiffness: NDArray[np.float64]
    mass: NDArray[np.float64]

    @property
    def node_x_m(self) -> NDArray[np.float64]:
        return self.vertical.node_x_m

    @property
    def node_count(self) -> int:
        return self.vertical.node_count

    @property
    def dof_count(self) -> int:
        return DOFS_PER_NODE * self.node_count

    def node_dofs(self, node: int) -> NDArray[np.intp]:
        """Global indices of node ``node``'s (u, v, w, psi, theta) [the local order of an engagement]."""
        n = self.node_count
        return np.array([4 * n + node, 2 * n + 2 * node, 2 * node, 2 * n + 2 * node + 1, 2 * node + 1], dtype=np.intp)

    def node_at(self, x_m: float, field: str = "x_m") -> int:
        """The node at ``x_m`` along the cargo [m]; a position off the mesh is refused, naming ``field``."""
        node = int(np.argmin(np.abs(self.node_x_m - float(x_m))))
        if abs(self.node_x_m[node] - float(x_m)) > 1e-6 * max(1.0, float(self.node_x_m[-1] - self.node_x_m[0])):
            raise ValueError(
                f"{field} = {x_m!r}: allowed a node of the cargo mesh (nearest {self.node_x_m[node]:.6g} m); "
                "mesh the cargo with a node there (build_cargo_beam's fixed_points_m)"
            )
        return node

    def gravity_load_N(self, heel_deg: float = 0.0, trim_deg: float = 0.0, gravity_m_per_s2: float = 9.81) -> NDArray[np.float64]:
        """Consistent nodal loads of the cargo's weight at a steady heel and trim [N, N m] (module docstring)."""
        x, m = self.node_x_m, self.vertical.element_mass_per_length_kg_per_m
        g = gravity_m_per_s2 * gravity_direction(heel_deg, trim_deg)
        n, EI = self.node_count, self.vertical.element_bending_stiffness_Nm2
        f = np.zeros(self.dof_count)
        f[: 2 * n] = assemble_beam(x, EI, m, load_N_per_m=m * g[2])[2]
        f[2 * n : 4 * n] = assemble_beam(x, EI, m, load_N_per_m=m * g[1])[2]
        half = 0.5 * m * g[0] * np.diff(x)
        np.add.at(f, 4 * n + np.arange(n - 1), half)
        np.add.at(f, 4 * n + np.arange(1, n), half)
        return f

    def rigid_body_modes(self) -> NDArray[np.float64]:
        """The five rigid-body motions (5 n, 5), unit columns: axial, lateral and vertical translation,
        rotation about z (``psi = 1``) and about y (``theta = 1``) about the cargo's middle; the free beam's null space."""
        n, x = self.node_count, self.node_x_m
        xc = x - 0.5 * (x[0] + x[-1])
        R = np.zeros((self.dof_count, 5))
        R[4 * n :, 0] = 1.0
        R[2 * n : 4 * n : 2, 1] = 1.0
        R[0 : 2 * n : 2, 2] = 1.0
        R[2 * n : 4 * n : 2, 3], R[2 * n + 1 : 4 * n : 2, 3] = xc, 1.0
        R[0 : 2 * n : 2, 4], R[1 : 2 * n : 2, 4] = xc, 1.0
        return R / np.linalg.norm(R, axis=0)


def build_cargo3d(beam: CargoBeam) -> Cargo3D:
    """The three-dimensional cargo on the mesh and sections of today's beam ``beam``.

    The vertical block is ``beam``'s own stiffness and mass; the lateral block the same matrices
    (``I_y = I_z`` for a tube); the axial bars take ``EA = E A`` with ``E = EI / I`` of each element.
    """
    n = beam.node_count
    area = tube_area_m2(beam.element_outer_diameter_m, beam.element_wall_thickness_m)
    EA = beam.element_bending_stiffness_Nm2 / beam.element_second_moment_m4 * area
    L = np.diff(beam.node_x_m)
    m = beam.element_mass_per_length_kg_per_m
    K = np.zeros((5 * n, 5 * n))
    M = np.zeros((5 * n, 5 * n))
    for start in (0, 2 * n):
        K[start : start + 2 * n, start : start + 2 * n] = beam.stiffness
        M[start : start + 2 * n, start : start + 2 * n] = beam.mass
    i = 4 * n + np.arange(n - 1)
    for (a, b), k_sign, m_share in (((0, 0), 1.0, 2.0), ((0, 1), -1.0, 1.0), ((1, 0), -1.0, 1.0), ((1, 1), 1.0, 2.0)):
        np.add.at(K, (i + a, i + b), k_sign * EA / L)
        np.add.at(M, (i + a, i + b), m_share * m * L / 6.0)
    return Cargo3D(beam, EA, K, M)


def vertical_plane_restraint(model: StructuralModel, cargo: Cargo3D) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Today's lashing springs and pretension on the 3-D DOFs: (spring diagonal [N/m, N m/rad], load [N, N m]).

    The vertical-plane model's lashings (a bilateral vertical spring ``k_z`` and rotational spring
    ``k_theta`` at each lashed saddle, the pretension a downward force there) placed on the vertical
    block, so that the 3-D cargo with a pad pair of stiffness ``k_sad - k_z`` per saddle is today's
    model at zero heel and trim.
    """
    if cargo.node_count != model.cargo.node_count or not np.array_equal(cargo.node_x_m, model.cargo.node_x_m):
        raise ValueError("cargo: allowed the 3-D cargo built on the model's own mesh (build_cargo3d(model.cargo))")
    diagonal = np.zeros(cargo.dof_count)
    load = np.zeros(cargo.dof_count)
    diagonal[: model.cargo_dof_count] = model.spring_parts(False)[0]
    load[: model.cargo_dof_count] = model.pretension_load_N
    return diagonal, load
