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
    "assemble_beam_stiffness_banded",
    "node_dof_indices",
    "element_end_moments",
    "bending_moment_line",
]

FloatArray = NDArray[np.float64]


def beam_element_stiffness(length_m: float, bending_stiffness_Nm2: float, shear_stiffness_N: float | None = None) -> FloatArray:
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
    gas = None if shear_stiffness_N is None else np.array([shear_stiffness_N], dtype=float)
    K, _ = _element_matrices(np.array([length_m], dtype=float), np.array([bending_stiffness_Nm2], dtype=float), np.zeros(1), gas)
    return K[0]


def beam_element_mass(
    length_m: float,
    mass_per_length_kg_per_m: float,
    bending_stiffness_Nm2: float = 1.0,
    shear_stiffness_N: float | None = None,
) -> FloatArray:
    """4x4 consistent (translational) mass matrix [kg, kg m, kg m^2] of a beam element.

    With ``shear_stiffness_N=None`` this is the classical Hermite matrix ``mL/420 [156 ...]``.
    """
    gas = None if shear_stiffness_N is None else np.array([shear_stiffness_N], dtype=float)
    _, M = _element_matrices(
        np.array([length_m], dtype=float),
        np.array([bending_stiffness_Nm2], dtype=float),
        np.array([mass_per_length_kg_per_m], dtype=float),
        gas,
    )
    return M[0]


def uniform_load_vector(length_m: float, load_N_per_m: float) -> FloatArray:
    """Consistent nodal loads [N, N m] of a uniform distributed load (positive upward)."""
    L = float(length_m)
    q = float(load_N_per_m)
    return np.array([q * L / 2.0, q * L * L / 12.0, q * L / 2.0, -q * L * L / 12.0])


def node_dof_indices(element: int) -> NDArray[np.intp]:
    """Global DOF indices (z1, theta1, z2, theta2) of element ``element`` in a 1-D chain."""
    return np.arange(2 * element, 2 * element + 4)


def _element_matrices(
    lengths_m: FloatArray,
    bending_stiffness_Nm2: FloatArray,
    mass_per_length_kg_per_m: FloatArray,
    shear_stiffness_N: FloatArray | None,
) -> tuple[FloatArray, FloatArray]:
    """Stiffness and mass matrices of all elements at once, shape (n_el, 4, 4) each."""
    L = np.asarray(lengths_m, dtype=float)
    EI = np.broadcast_to(np.asarray(bending_stiffness_Nm2, dtype=float), L.shape)
    if shear_stiffness_N is None:
        phi = np.zeros_like(L)
    else:
        gas = np.broadcast_to(np.asarray(shear_stiffness_N, dtype=float), L.shape)
        with np.errstate(divide="ignore"):
            phi = np.where(np.isinf(gas), 0.0, 12.0 * EI / (gas * L * L))
    L2 = L * L
    c = EI / ((1.0 + phi) * L**3)
    K = np.empty(L.shape + (4, 4))
    K[:, 0] = np.stack([12.0 + 0 * L, 6.0 * L, -12.0 + 0 * L, 6.0 * L], axis=-1)
    K[:, 1] = np.stack([6.0 * L, (4.0 + phi) * L2, -6.0 * L, (2.0 - phi) * L2], axis=-1)
    K[:, 2] = -K[:, 0]
    K[:, 3] = np.stack([6.0 * L, (2.0 - phi) * L2, -6.0 * L, (4.0 + phi) * L2], axis=-1)
    K *= c[:, None, None]
    p2 = phi * phi
    a = 13 / 35 + 7 * phi / 10 + p2 / 3
    b = (11 / 210 + 11 * phi / 120 + p2 / 24) * L
    cc = 9 / 70 + 3 * phi / 10 + p2 / 6
    d = (13 / 420 + 3 * phi / 40 + p2 / 24) * L
    e = (1 / 105 + phi / 60 + p2 / 120) * L2
    f = (1 / 140 + phi / 60 + p2 / 120) * L2
    M = np.stack(
        [
            np.stack([a, b, cc, -d], axis=-1),
            np.stack([b, e, d, -f], axis=-1),
            np.stack([cc, d, a, -b], axis=-1),
            np.stack([-d, -f, -b, e], axis=-1),
        ],
        axis=-2,
    )
    M *= (np.asarray(mass_per_length_kg_per_m, dtype=float) * L / (1.0 + phi) ** 2)[:, None, None]
    return K, M


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
    lengths = np.diff(x)
    Ke, Me = _element_matrices(lengths, bending_stiffness_Nm2, mass_per_length_kg_per_m, shear_stiffness_N)
    dofs = 2 * np.arange(n_el)[:, None] + np.arange(4)[None, :]  # (n_el, 4)
    rows = np.broadcast_to(dofs[:, :, None], (n_el, 4, 4))
    cols = np.broadcast_to(dofs[:, None, :], (n_el, 4, 4))
    K = np.zeros((n_dof, n_dof))
    M = np.zeros((n_dof, n_dof))
    np.add.at(K, (rows, cols), Ke)
    np.add.at(M, (rows, cols), Me)
    f = np.zeros(n_dof)
    if load_N_per_m is not None:
        q = np.broadcast_to(np.asarray(load_N_per_m, dtype=float), lengths.shape)
        fe = np.stack([q * lengths / 2, q * lengths**2 / 12, q * lengths / 2, -q * lengths**2 / 12], axis=-1)
        np.add.at(f, dofs, fe)
    return K, M, f


def assemble_beam_stiffness_banded(
    node_x_m: FloatArray,
    bending_stiffness_Nm2: FloatArray,
    shear_stiffness_N: FloatArray | None = None,
) -> FloatArray:
    """Stiffness [SI] of a chain of beam elements in upper banded storage, half-bandwidth 3.

    ``ab[3 + i - j, j] = K[i, j]`` for ``j - 3 <= i <= j`` (the layout of
    :func:`scipy.linalg.cholesky_banded`), the same matrix as :func:`assemble_beam`'s ``K`` in
    O(n) time and memory (each entry receives at most two element contributions, so it is equal
    to the last bit).
    """
    x = np.asarray(node_x_m, dtype=float)
    n_el = x.size - 1
    Ke, _ = _element_matrices(np.diff(x), bending_stiffness_Nm2, np.zeros(n_el), shear_stiffness_N)
    i, j = np.triu_indices(4)  # the element's upper triangle
    dofs = 2 * np.arange(n_el)[:, None]
    ab = np.zeros((4, 2 * x.size))
    rows = np.broadcast_to(3 + i - j, (n_el, i.size)).ravel()
    cols = (dofs + j[None, :]).ravel()
    np.add.at(ab, (rows, cols), Ke[:, i, j].ravel())
    return ab


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
    Ke, _ = _element_matrices(lengths, bending_stiffness_Nm2, np.zeros(n_el), shear_stiffness_N)
    dofs = 2 * np.arange(n_el)[:, None] + np.arange(4)[None, :]
    ue = u[..., dofs]  # (..., n_el, 4)
    # only the two moment rows of the element end forces are needed
    m_start = -np.einsum("ej,...ej->...e", Ke[:, 1, :], ue)
    m_end = np.einsum("ej,...ej->...e", Ke[:, 3, :], ue)
    if load_N_per_m is not None:
        q = np.broadcast_to(np.asarray(load_N_per_m), u.shape[:-1] + (n_el,))
        # remove the fixed-end moments of the distributed load (q L^2 / 12 at each end)
        m_start = m_start + q * lengths**2 / 12.0
        m_end = m_end + q * lengths**2 / 12.0
    return m_start, m_end


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
