"""Panel mesh of the wetted surface of a :class:`~seafast.vessel.hull_form.HullForm` for BEM.

The mesh is generated from the same breadth table that feeds the hull-girder buoyancy, so the
hydrostatics of the panel mesh equal those of the hull form (the waterline is piecewise linear
between stations and every station is a panel edge).

Geometry of a section
---------------------
For ``section_area_coefficient == 1`` the sections are boxes: vertical sides from the waterline
to the keel and a flat bottom. For ``C_s < 1`` the sides stay vertical near the waterline (the
hull is wall-sided, so the waterplane is unchanged) and a straight chine runs to a narrower flat
bottom, with the sectional area ``C_s * b * T``:

* ``0.75 <= C_s < 1``: vertical sides over the upper half of the draught, flat bottom of breadth
  ``(4 C_s - 3) b``;
* ``0.5 <= C_s < 0.75``: vertical sides down to ``(2 C_s - 1) T`` below the waterline, then a V
  to the keel.

Coordinates of the mesh (capytaine's frame)
-------------------------------------------
``X = x - x_mid`` (origin at midship, ``x_mid = L/2``, forward positive), ``Y`` to port, ``Z`` up
with ``Z = 0`` at the design waterline. Putting the origin at midship makes capytaine's incident
wave phase reference (crest at the origin at ``t = 0``) coincide with seafast's (crest at
``x_mid``). Only the half ``Y >= 0`` is stored; the full mesh is a
:class:`capytaine.ReflectionSymmetricMesh` about the ``xOz`` plane, which capytaine 3 exploits
to halve the size of the linear systems.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from itertools import pairwise
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from seafast.vessel.hull_form import HullForm

__all__ = ["HullMesh", "section_profile", "mesh_hull", "hull_mesh_arrays"]


def section_profile(section_area_coefficient: float, draft_m: float) -> NDArray[np.float64]:
    """Corner points of the half-section profile, from the waterline to the keel centreline.

    Parameters
    ----------
    section_area_coefficient
        ``C_s`` in [0.5, 1] [-].
    draft_m
        Draught ``T`` [m].

    Returns
    -------
    ndarray, shape (n, 2)
        Columns: breadth fraction ``eta = y / (b/2)`` [-] and ``z`` [m] (0 at the waterline,
        ``-T`` at the keel). First point ``(1, 0)``, last point ``(0, -T)``.

    Raises
    ------
    ValueError
        If ``C_s`` is outside [0.5, 1].
    """
    cs, t = float(section_area_coefficient), float(draft_m)
    if not 0.5 <= cs <= 1.0:
        raise ValueError(f"hull mesh: section_area_coefficient = {cs!r} not supported; must be in [0.5, 1]")
    if cs == 1.0:
        return np.array([[1.0, 0.0], [1.0, -t], [0.0, -t]])
    if cs >= 0.75:
        return np.array([[1.0, 0.0], [1.0, -0.5 * t], [4.0 * cs - 3.0, -t], [0.0, -t]])
    return np.array([[1.0, 0.0], [1.0, -(2.0 * cs - 1.0) * t], [0.0, -t]])


def _subdivide(a: float, b: float, h: float) -> NDArray[np.float64]:
    n = max(1, math.ceil(abs(b - a) / h - 1e-9))
    return np.linspace(a, b, n + 1)


@dataclass(frozen=True)
class HullMesh:
    """Port half mesh (``Y >= 0``) of the wetted hull and of its interior lid.

    Attributes
    ----------
    hull_vertices_m, hull_faces
        Vertices ``(n_v, 3)`` [m] and faces ``(n_f, 4)`` (triangles repeat their last vertex) of
        the wetted half hull, normals pointing out of the hull into the water.
    lid_vertices_m, lid_faces
        Same for the interior waterplane lid at ``Z = lid_z_m`` (normals pointing down).
    x_mid_m
        seafast ``x`` of the mesh origin (midship, ``L/2``) [m].
    lid_z_m
        Height of the lid [m] (0: on the waterline).
    """

    hull_vertices_m: NDArray[np.float64]
    hull_faces: NDArray[np.int64]
    lid_vertices_m: NDArray[np.float64]
    lid_faces: NDArray[np.int64]
    x_mid_m: float
    lid_z_m: float

    @property
    def nb_hull_panels_full(self) -> int:
        """Number of hull panels of the full (both sides) mesh."""
        return 2 * int(self.hull_faces.shape[0])

    @property
    def nb_lid_panels_full(self) -> int:
        """Number of lid panels of the full (both sides) mesh."""
        return 2 * int(self.lid_faces.shape[0])

    def to_capytaine(self) -> tuple[Any, Any]:
        """Return ``(hull_mesh, lid_mesh)`` as capytaine ``ReflectionSymmetricMesh`` (plane xOz)."""
        import capytaine as cpt

        hull_half = cpt.Mesh(self.hull_vertices_m, self.hull_faces, name="seafast_half_hull")
        lid_half = cpt.Mesh(self.lid_vertices_m, self.lid_faces, name="seafast_half_lid", auto_check=False)
        hull = cpt.ReflectionSymmetricMesh(half=hull_half, plane="xOz", name="seafast_hull")
        lid = cpt.ReflectionSymmetricMesh(half=lid_half, plane="xOz", name="seafast_lid")
        return hull, lid


class _Builder:
    """Accumulates quads given by vertex coordinates, merging coincident vertices."""

    def __init__(self) -> None:
        self._index: dict[tuple[float, float, float], int] = {}
        self.vertices: list[tuple[float, float, float]] = []
        self.faces: list[list[int]] = []

    def _vid(self, p: NDArray[np.float64]) -> int:
        x, y, z = (round(float(c), 9) + 0.0 for c in p)
        key = (x, y, z)
        i = self._index.get(key)
        if i is None:
            i = len(self.vertices)
            self._index[key] = i
            self.vertices.append(key)
        return i

    def quad(self, p0: ArrayLike, p1: ArrayLike, p2: ArrayLike, p3: ArrayLike) -> None:
        ids: list[int] = []
        for p in (p0, p1, p2, p3):
            i = self._vid(np.asarray(p, dtype=float))
            if i not in ids:
                ids.append(i)
        if len(ids) < 3:
            return
        if len(ids) == 3:
            ids.append(ids[-1])
            self.faces.append(ids)
            return
        v = np.array([self.vertices[i] for i in ids])
        n = np.cross(v[2] - v[0], v[3] - v[1])
        warp = abs(np.dot(n / np.linalg.norm(n), v[1] - v[0]))
        if warp > 1e-6 * max(float(np.linalg.norm(v[2] - v[0])), 1.0):  # twisted quad: two triangles
            self.faces.append([ids[0], ids[1], ids[2], ids[2]])
            self.faces.append([ids[0], ids[2], ids[3], ids[3]])
        else:
            self.faces.append(ids)

    def arrays(self) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
        return np.array(self.vertices, dtype=float), np.array(self.faces, dtype=np.int64)


def _x_breaks(hull: HullForm, h: float) -> NDArray[np.float64]:
    xs = [np.array([hull.station_x_m[0]])]
    for a, b in pairwise(hull.station_x_m):
        xs.append(_subdivide(a, b, h)[1:])
    return np.concatenate(xs)


def _girth(profile: NDArray[np.float64], half_breadth_m: float, h: float) -> NDArray[np.float64]:
    """Points ``(eta, z)`` along the half girth of the section ``profile``, at most ``h`` apart at ``half_breadth_m``."""
    pts = [profile[0]]
    for p, q in pairwise(profile):
        seg_len = math.hypot(half_breadth_m * (q[0] - p[0]), q[1] - p[1])
        n = max(1, math.ceil(seg_len / h - 1e-9))
        for s in np.linspace(0.0, 1.0, n + 1)[1:]:
            pts.append(p + s * (q - p))
    return np.array(pts)  # (n_g, 2)


def _half_breadths(hull: HullForm, x: NDArray[np.float64]) -> NDArray[np.float64]:
    """Waterline half-breadths [m] at the stations ``x``, the end values those of the AP and FP stations."""
    hb = 0.5 * hull.breadth_at(x)
    hb[0] = 0.5 * hull.waterline_breadth_m[0]
    hb[-1] = 0.5 * hull.waterline_breadth_m[-1]
    return hb


def _shell_panels(mesh: _Builder, xb: NDArray[np.float64], hb: NDArray[np.float64], girth: NDArray[np.float64], x_mid: float) -> None:
    """Sides, chine and bottom between the stations ``xb``, ordered so that the normal points outward (+y on the side)."""

    def point(i: int, j: int) -> NDArray[np.float64]:
        return np.array([xb[i] - x_mid, girth[j, 0] * hb[i], girth[j, 1]])

    for i in range(len(xb) - 1):
        for j in range(len(girth) - 1):
            mesh.quad(point(i, j), point(i, j + 1), point(i + 1, j + 1), point(i + 1, j))


def _end_panels(
    mesh: _Builder,
    xb: NDArray[np.float64],
    hb: NDArray[np.float64],
    girth: NDArray[np.float64],
    profile: NDArray[np.float64],
    x_mid: float,
    h: float,
) -> None:
    """The transom (x = x_0, normal -x) and a blunt bow (x = x_end, normal +x), where the breadth there is > 0."""
    t = -float(profile[-1, 1])

    # half-width at depth z of a section of half-breadth half_breadth_m, from the profile (eta as
    # function of z; at -T use bottom eta)
    def width(z: float, half_breadth_m: float) -> float:
        eta = np.interp(-z, -profile[:-1, 1], profile[:-1, 0]) if z > -t else profile[-2, 0]
        return float(eta * half_breadth_m)

    for i_end, sign in ((0, -1.0), (len(xb) - 1, 1.0)):
        if hb[i_end] <= 0:
            continue
        zl = np.unique(np.concatenate([girth[:, 1]]))[::-1]  # 0 .. -T
        ny = max(1, math.ceil(hb[i_end] / h - 1e-9))
        xi = np.linspace(0.0, 1.0, ny + 1)
        x0 = xb[i_end] - x_mid
        for k in range(len(zl) - 1):
            wa, wb = width(zl[k], hb[i_end]), width(zl[k + 1], hb[i_end])
            for m in range(ny):
                a = (x0, xi[m] * wa, zl[k])
                b = (x0, xi[m + 1] * wa, zl[k])
                c = (x0, xi[m + 1] * wb, zl[k + 1])
                d = (x0, xi[m] * wb, zl[k + 1])
                if sign < 0:
                    mesh.quad(a, b, c, d)
                else:
                    mesh.quad(a, d, c, b)


def _lid_panels(
    hull: HullForm, profile: NDArray[np.float64], h_lid: float, lid_z_m: float, x_mid: float
) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
    """Vertices and faces of the interior waterplane lid at ``Z = lid_z_m``, normals pointing down."""
    lid = _Builder()
    xl = _x_breaks(hull, h_lid)
    hl = _half_breadths(hull, xl)
    # at a lid below the waterline the wall-sided hull has the same breadth unless the chine
    # is reached: scale by the profile eta at that depth
    eta_lid = float(np.interp(-lid_z_m, -profile[:-1, 1], profile[:-1, 0]))
    hl = hl * eta_lid
    nyl = max(1, math.ceil(0.5 * hull.breadth_m / h_lid - 1e-9))
    eta = np.linspace(0.0, 1.0, nyl + 1)
    for i in range(len(xl) - 1):
        for m in range(nyl):
            a = (xl[i] - x_mid, eta[m] * hl[i], lid_z_m)
            b = (xl[i + 1] - x_mid, eta[m] * hl[i + 1], lid_z_m)
            c = (xl[i + 1] - x_mid, eta[m + 1] * hl[i + 1], lid_z_m)
            d = (xl[i] - x_mid, eta[m + 1] * hl[i], lid_z_m)
            lid.quad(a, b, c, d)
    lid_v, lid_f = lid.arrays()
    # make lid normals point down (-z)
    normals = _face_normals(lid_v, lid_f)
    flip = normals[:, 2] > 0
    lid_f[flip] = lid_f[flip][:, ::-1]
    return lid_v, lid_f


def hull_mesh_arrays(hull: HullForm, panel_size_m: float = 3.0, *, lid_panel_size_m: float | None = None, lid_z_m: float = 0.0) -> HullMesh:
    """Generate the half mesh (``Y >= 0``) of the wetted hull (sides, bottom, transom) and lid.

    Parameters
    ----------
    hull
        Hull form (stations, waterline breadth, draught, section-area coefficient).
    panel_size_m
        Target panel edge length [m] (3 m production, ~8 m coarse). Every station is a panel
        edge, so panels may be shorter.
    lid_panel_size_m
        Target panel size of the lid [m] (default: ``panel_size_m``).
    lid_z_m
        Height of the lid relative to the waterline [m], <= 0 (default on the waterline, which
        capytaine 3 supports with its default ``gf_singularities="low_freq"``).

    Returns
    -------
    HullMesh
    """
    h = float(panel_size_m)
    if not h > 0:
        raise ValueError(f"hull mesh: panel_size_m = {panel_size_m!r}; must be > 0")
    if lid_z_m > 0 or lid_z_m <= -hull.draft_m:
        raise ValueError(f"hull mesh: lid_z_m = {lid_z_m!r}; must be in (-draft, 0]")
    h_lid = h if lid_panel_size_m is None else float(lid_panel_size_m)
    t = hull.draft_m
    x_mid = 0.5 * (hull.station_x_m[0] + hull.station_x_m[-1])
    prof = section_profile(hull.section_area_coefficient, t)
    girth = _girth(prof, 0.5 * hull.breadth_m, h)
    xb = _x_breaks(hull, h)
    hb = _half_breadths(hull, xb)
    shell = _Builder()
    _shell_panels(shell, xb, hb, girth, x_mid)
    _end_panels(shell, xb, hb, girth, prof, x_mid, h)
    hull_v, hull_f = shell.arrays()
    x_c = hull.centre_of_buoyancy_x_m() - x_mid
    hull_v, hull_f = _orient_outward(hull_v, hull_f, np.array([x_c, 0.0, -0.5 * t]))
    lid_v, lid_f = _lid_panels(hull, prof, h_lid, lid_z_m, x_mid)
    return HullMesh(hull_v, hull_f, lid_v, lid_f, float(x_mid), float(lid_z_m))


def _face_normals(v: NDArray[np.float64], f: NDArray[np.int64]) -> NDArray[np.float64]:
    d1 = v[f[:, 2]] - v[f[:, 0]]
    d2 = v[f[:, 3]] - v[f[:, 1]]
    n = np.cross(d1, d2)
    return n / np.linalg.norm(n, axis=1, keepdims=True)


def _orient_outward(
    v: NDArray[np.float64], f: NDArray[np.int64], interior_point: NDArray[np.float64]
) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
    """Flip faces whose normal points towards ``interior_point`` (valid for convex hulls).

    Wall-sided sections (box or chine) and a convex waterline make the hull convex, so a face
    normal points out of the hull when it points away from any interior point.
    """
    c = v[f].mean(axis=1)
    n = _face_normals(v, f)
    flip = np.einsum("ij,ij->i", n, c - interior_point) < 0
    f = f.copy()
    f[flip] = f[flip][:, ::-1]
    return v, f


def mesh_hull(hull: HullForm, panel_size_m: float = 3.0, *, lid_panel_size_m: float | None = None, lid_z_m: float = 0.0) -> tuple[Any, Any]:
    """Capytaine meshes ``(hull_mesh, lid_mesh)`` of the wetted hull and its interior lid.

    See :func:`hull_mesh_arrays` for the parameters and the frame (origin at midship on the
    waterline, ``X`` forward, ``Z`` up). Both meshes are ``ReflectionSymmetricMesh`` about ``xOz``.
    """
    return hull_mesh_arrays(hull, panel_size_m, lid_panel_size_m=lid_panel_size_m, lid_z_m=lid_z_m).to_capytaine()
