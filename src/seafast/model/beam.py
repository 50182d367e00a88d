"""Two-node plane beam finite elements with DOFs (z, theta) per node.

Sign conventions (used everywhere in seafast):

* ``z`` deflection, positive upward [m]; ``theta = dz/dx`` rotation [rad] (positive when the
  beam rises forward).
* Bending moment ``M = EI * d2z/dx2`` [N m]: positive sagging (beam concave upward, tension
  at the bottom fibre), negative hogging.
* Nodal force vector ordering per node: vertical force [N] (positive upward), moment [N m]
  (positive in the sense of positive ``theta``).

Euler-Bernoulli elements use cubic Hermite shape functions and the consistent mass matrix.
Timoshenko elements use the shear-flexible stiffness with ``Phi = 12 EI / (G A_s L^2)`` and the
consistent translational mass of Friedman & Kosmatka (1993); rotary inertia is neglected
(it is second order for the long, slender bodies seafast models at wave frequencies).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

__all__ = [
    "beam_element_stiffness",
    "beam_element_mass",
    "uniform_load_vector",
    "assemble_beam",
    "node_dof_indices",
    "element_end_moments",
    "bending_moment_line",
]

FloatArray = NDArray[np.float64]


def beam_element_stiffness(
    length_m: float, bending_stiffness_Nm2: float, shear_stiffness_N: float | None = None
) -> FloatArray:
    """4x4 element stiffness [N/m, N, N m] in DOF order (z1, theta1, z2, theta2).

    Parameters
    ----------
    length_m
        Element length L [m].
    bending_stiffness_Nm2
        EI [N m^2].
    shear_stiffness_N
        Effective shear stiffness G A_s [N]; ``None`` (or infinite) gives Euler-Bernoulli.
    """
    L = float(length_m)
    EI = float(bending_stiffness_Nm2)
    phi = 0.0 if shear_stiffness_N is None or np.isinf(shear_stiffness_N) else 12.0 * EI / (shear_stiffness_N * L * L)
    c = EI / ((1.0 + phi) * L**3)
    return c * np.array(
        [
            [12.0, 6.0 * L, -12.0, 6.0 * L],
            [6.0 * L, (4.0 + phi) * L * L, -6.0 * L, (2.0 - phi) * L * L],
            [-12.0, -6.0 * L, 12.0, -6.0 * L],
            [6.0 * L, (2.0 - phi) * L * L, -6.0 * L, (4.0 + phi) * L * L],
        ]
    )


def beam_element_mass(
    length_m: float,
    mass_per_length_kg_per_m: float,
    bending_stiffness_Nm2: float = 1.0,
    shear_stiffness_N: float | None = None,
) -> FloatArray:
    """4x4 consistent (translational) mass matrix [kg, kg m, kg m^2] of a beam element.

    With ``shear_stiffness_N=None`` this is the classical Hermite matrix ``mL/420 [156 ...]``.
    """
    L = float(length_m)
    m = float(mass_per_length_kg_per_m) * L
    phi = 0.0
    if shear_stiffness_N is not None and not np.isinf(shear_stiffness_N):
        phi = 12.0 * bending_stiffness_Nm2 / (shear_stiffness_N * L * L)
    p2 = phi * phi
    a = 13 / 35 + 7 * phi / 10 + p2 / 3
    b = (11 / 210 + 11 * phi / 120 + p2 / 24) * L
    c = 9 / 70 + 3 * phi / 10 + p2 / 6
    d = (13 / 420 + 3 * phi / 40 + p2 / 24) * L
    e = (1 / 105 + phi / 60 + p2 / 120) * L * L
    f = (1 / 140 + phi / 60 + p2 / 120) * L * L
    return m / (1.0 + phi) ** 2 * np.array(
        [
            [a, b, c, -d],
            [b, e, d, -f],
            [c, d, a, -b],
            [-d, -f, -b, e],
        ]
    )


def uniform_load_vector(length_m: float, load_N_per_m: float) -> FloatArray:
    """Consistent nodal loads [N, N m] of a uniform distributed load (positive upward)."""
    L = float(length_m)
    q = float(load_N_per_m)
    return np.array([q * L / 2.0, q * L * L / 12.0, q * L / 2.0, -q * L * L / 12.0])


def node_dof_indices(element: int) -> NDArray[np.intp]:
    """Global DOF indices (z1, theta1, z2, theta2) of element ``element`` in a 1-D chain."""
    return np.arange(2 * element, 2 * element + 4)


def assemble_beam(
    node_x_m: FloatArray,
    bending_stiffness_Nm2: FloatArray,
    mass_per_length_kg_per_m: FloatArray,
    shear_stiffness_N: FloatArray | None = None,
    load_N_per_m: FloatArray | None = None,
) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Assemble stiffness, mass and load of a chain of beam elements.

    Parameters
    ----------
    node_x_m
        Node positions [m], strictly increasing, shape (n_nodes,).
    bending_stiffness_Nm2, mass_per_length_kg_per_m
        Per-element EI [N m^2] and mass per length [kg/m], shape (n_nodes - 1,).
    shear_stiffness_N
        Per-element G A_s [N] for Timoshenko elements; ``None`` for Euler-Bernoulli.
    load_N_per_m
        Per-element uniform distributed load [N/m], positive upward; ``None`` for no load.

    Returns
    -------
    K, M, f
        Dense (2 n_nodes)^2 stiffness [SI] and mass [SI], and load vector [N, N m].
    """
    x = np.asarray(node_x_m, dtype=float)
    n_el = x.size - 1
    n_dof = 2 * x.size
    K = np.zeros((n_dof, n_dof))
    M = np.zeros((n_dof, n_dof))
    f = np.zeros(n_dof)
    lengths = np.diff(x)
    for e in range(n_el):
        idx = node_dof_indices(e)
        gas = None if shear_stiffness_N is None else shear_stiffness_N[e]
        K[np.ix_(idx, idx)] += beam_element_stiffness(lengths[e], bending_stiffness_Nm2[e], gas)
        M[np.ix_(idx, idx)] += beam_element_mass(lengths[e], mass_per_length_kg_per_m[e], bending_stiffness_Nm2[e], gas)
        if load_N_per_m is not None:
            f[idx] += uniform_load_vector(lengths[e], load_N_per_m[e])
    return K, M, f


def element_end_moments(
    node_x_m: FloatArray,
    displacement: NDArray,
    bending_stiffness_Nm2: FloatArray,
    shear_stiffness_N: FloatArray | None = None,
    load_N_per_m: FloatArray | NDArray | None = None,
) -> tuple[NDArray, NDArray]:
    """Bending moments [N m] at the start and end of each element (sagging positive).

    ``displacement`` has the chain DOFs on its last axis (shape (..., 2 n_nodes)); real or
    complex (harmonic amplitudes). ``load_N_per_m`` is the per-element distributed load on the
    same leading axes (shape (n_el,) or (..., n_el)).

    Returns
    -------
    moment_start_Nm, moment_end_Nm
        Each of shape (..., n_el).
    """
    x = np.asarray(node_x_m, dtype=float)
    u = np.asarray(displacement)
    n_el = x.size - 1
    lengths = np.diff(x)
    m0 = np.zeros(u.shape[:-1] + (n_el,), dtype=u.dtype if np.iscomplexobj(u) else float)
    m1 = np.zeros_like(m0)
    q = None if load_N_per_m is None else np.broadcast_to(np.asarray(load_N_per_m), u.shape[:-1] + (n_el,))
    for e in range(n_el):
        gas = None if shear_stiffness_N is None else shear_stiffness_N[e]
        ke = beam_element_stiffness(lengths[e], bending_stiffness_Nm2[e], gas)
        end_forces = u[..., 2 * e : 2 * e + 4] @ ke.T
        if q is not None:
            L = lengths[e]
            # subtract the fixed-end equivalent of the distributed load
            end_forces = end_forces - np.stack(
                [q[..., e] * L / 2, q[..., e] * L * L / 12, q[..., e] * L / 2, -q[..., e] * L * L / 12], axis=-1
            )
        m0[..., e] = -end_forces[..., 1]
        m1[..., e] = end_forces[..., 3]
    return m0, m1


def bending_moment_line(
    node_x_m: FloatArray,
    displacement: NDArray,
    bending_stiffness_Nm2: FloatArray,
    shear_stiffness_N: FloatArray | None = None,
    load_N_per_m: FloatArray | NDArray | None = None,
    points_per_element: int = 4,
) -> tuple[FloatArray, NDArray]:
    """Bending-moment line [N m] sampled inside every element (sagging positive).

    Within an element the moment is the linear interpolation of the end moments plus the
    parabola of the distributed load, ``-q L^2 xi (1 - xi) / 2`` (q positive upward), which is
    exact for uniform load on an element.

    Returns
    -------
    x_m, moment_Nm
        Sample positions [m], shape (n_samples,), and moments, shape (..., n_samples). Nodes
        shared by two elements appear twice (once per element) so jumps at point loads show.
    """
    x = np.asarray(node_x_m, dtype=float)
    m0, m1 = element_end_moments(x, displacement, bending_stiffness_Nm2, shear_stiffness_N, load_N_per_m)
    xi = np.linspace(0.0, 1.0, points_per_element + 1)
    lengths = np.diff(x)
    xs = (x[:-1, None] + lengths[:, None] * xi[None, :]).ravel()
    moment = m0[..., :, None] * (1 - xi) + m1[..., :, None] * xi
    if load_N_per_m is not None:
        q = np.broadcast_to(np.asarray(load_N_per_m), m0.shape)
        moment = moment - q[..., :, None] * (lengths[:, None] ** 2) * (xi * (1 - xi))[None, :] / 2.0
    return xs, moment.reshape(moment.shape[:-2] + (-1,))
