"""Rigid-body heave and pitch of the vessel in head seas (docs/theory.md#36-rigid-body-motions).

Linear potential flow (radiation + diffraction) with capytaine, hydrostatic stiffness from the
hull form, and the 2-DOF equation of motion in heave and pitch, giving response amplitude
operators (RAOs) per metre of wave amplitude. Results are cached on disk; coefficients can also
be imported from a capytaine NetCDF file or from WAMIT ``.1``/``.3`` output.

Conventions (seafast; other modules rely on them)
-------------------------------------------------
* Time dependence ``x(t) = Re(X exp(+i omega t))``.
* Coordinates: ``x`` from the aft perpendicular (AP), forward positive; ``z`` up. The vertical
  position of the centre of gravity is given **above the keel (baseline)**; internally
  (capytaine's frame) heights are relative to the design waterline, ``z_wl = z_keel - T``.
* Regular head-sea wave: ``zeta(x, t) = zeta_a cos(omega t + k (x - x_mid))``,
  ``x_mid = L/2`` (crest at midship at ``t = 0``; the wave travels towards ``-x``, from bow to
  stern; capytaine's ``wave_direction = pi``). The complex wave elevation per unit amplitude is
  ``exp(i k (x - x_mid))``, so the phases of all RAOs refer to the wave crest at midship.
* Heave ``w`` positive up, at ``x = reference_x_m`` (the CoG x). Pitch ``theta = dz/dx``, positive
  **bow up**. The rigid-body vertical displacement at ``x`` is ``w + theta (x - reference_x_m)``.
* DOF order everywhere: (heave, pitch). Generalised force conjugate to ``theta`` is the moment
  ``sum f_z (x - reference_x_m)`` (bow-up positive). Units of the 2x2 matrices: ``[[kg, kg m],
  [kg m, kg m^2]]`` (added mass), same per second (damping), ``[N/m, N]`` (stiffness row 1,
  column by column: N/m, N/rad; N, N m/rad); excitation ``[N/m, N m/m]`` per metre of wave
  amplitude.

Mapping from capytaine (and WAMIT) conventions: both use a rotation about ``+y`` (``eta_5``),
which with ``x`` forward is bow *down*, so ``theta = -eta_5``. Capytaine uses
``exp(-i omega t)``: its complex amplitudes are complex-conjugated. WAMIT already uses
``exp(+i omega t)``.

Long-wave limit (checked in the tests): the ship follows the wave, the vertical displacement at
``x_mid`` tends to ``1`` m/m with zero phase and ``theta/zeta_a`` tends to the wave slope ``i k``
(magnitude ``k`` rad/m, phase +90 deg).

Surge (for the cargo's axial analysis, docs/axial.md): ``x`` displacement of the pitch reference
point (the CoG: ``x = reference_x_m`` at ``reference_z_m`` above the keel), positive forward. When
the hydrodynamic data hold surge (capytaine's ``Surge`` dof, WAMIT mode 1), surge, heave and pitch
are also solved as one coupled 3-DOF system (head seas couple surge and pitch through added mass,
damping and excitation; DOF order (surge, heave, pitch) in the 3-DOF helpers): ``surge_rao_m_per_m``,
``coupled_heave_rao_m_per_m``, ``coupled_pitch_rao_rad_per_m``. The heave-pitch fields stay the
2-DOF solution of the heave-pitch coefficients (the source's model, unchanged bit for bit). Without
surge in the data the surge and coupled fields are ``None`` (never silently zero). A point at height
``z`` above the keel moves forward by ``surge - theta (z - z_ref)``.
"""

from __future__ import annotations

import functools
import hashlib
import json
import logging
import math
import os
import tempfile
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any, Literal, TypeAlias

import numpy as np
import xarray as xr
from numpy.typing import ArrayLike, NDArray

from seafast.vessel.hull_form import HullForm
from seafast.vessel.hull_mesh import hull_mesh_arrays, section_profile

__all__ = [
    "RigidBodyMotions",
    "base_vessel_mass_properties",
    "compute_motions",
    "load_motions",
    "read_wamit_1",
    "read_wamit_3",
    "hydrostatic_stiffness_matrix",
    "mass_matrix",
    "solve_heave_pitch",
    "solve_rigid_body",
    "BEM_DOFS",
    "strip_theory_estimate",
    "wavenumber_rad_per_m",
    "default_cache_dir",
    "MESH_ALGORITHM_VERSION",
]

logger = logging.getLogger(__name__)

#: Bump when the mesher or the post-processing changes, to invalidate cached BEM results.
MESH_ALGORITHM_VERSION = "seafast-hull-mesh-1"

# an RAO at one frequency (a scalar omega) or at several (an array)
ComplexValue: TypeAlias = complex | NDArray[np.complexfloating[Any, Any]]

_T = np.diag([1.0, -1.0])  # capytaine/WAMIT (heave, eta5) -> seafast (heave, theta)
_T3 = np.diag([1.0, 1.0, -1.0])  # capytaine/WAMIT (surge, heave, eta5) -> seafast (surge, heave, theta)
#: Radiating DOFs of the BEM run (surge added for the axial analysis; part of the cache key).
BEM_DOFS: tuple[str, ...] = ("Surge", "Heave", "Pitch")


# ---------------------------------------------------------------------------------- results
@dataclass(frozen=True, eq=False)
class RigidBodyMotions:
    """Heave and pitch RAOs of the vessel in regular head seas (seafast conventions, see module).

    Attributes
    ----------
    omega_rad_s
        Wave frequencies [rad/s], shape (n_w,), strictly increasing.
    heave_rao_m_per_m
        Complex heave amplitude at ``x = reference_x_m`` per metre of wave amplitude [m/m].
    pitch_rao_rad_per_m
        Complex pitch ``theta = dz/dx`` (bow up) per metre of wave amplitude [rad/m].
    added_mass
        Added mass, shape (n_w, 2, 2), (heave, pitch) about ``reference_x_m`` [kg, kg m, kg m^2].
    radiation_damping
        Radiation damping, shape (n_w, 2, 2) [kg/s, kg m/s, kg m^2/s].
    excitation_force
        Complex wave excitation per metre of wave amplitude, shape (n_w, 2) [N/m, N m/m].
    reference_x_m
        ``x`` from the AP about which pitch acts (the CoG x) [m].
    mass_matrix
        Rigid-body mass matrix (2, 2) about ``reference_x_m`` [kg, kg m^2].
    hydrostatic_stiffness
        Hydrostatic stiffness (2, 2) [N/m, N/rad; N, N m/rad].
    wave_phase_reference_x_m
        ``x_mid``: where the wave crest is at ``t = 0`` [m].
    wavenumber_rad_per_m
        Wave number of each frequency [rad/m] (finite depth if applicable).
    source
        Free text describing where the coefficients come from.
    surge_rao_m_per_m
        Complex surge (forward +) of the reference point per metre of wave amplitude [m/m], from
        the coupled surge-heave-pitch solution; ``None`` when the data hold no surge.
    coupled_heave_rao_m_per_m, coupled_pitch_rao_rad_per_m
        Heave [m/m] and pitch [rad/m] of the same coupled solution (``None`` without surge).
    reference_z_m
        Height above the keel of the reference point (pitch axis, surge point) [m]; NaN if unknown.
    """

    omega_rad_s: NDArray[np.float64]
    heave_rao_m_per_m: NDArray[np.complex128]
    pitch_rao_rad_per_m: NDArray[np.complex128]
    added_mass: NDArray[np.float64]
    radiation_damping: NDArray[np.float64]
    excitation_force: NDArray[np.complex128]
    reference_x_m: float
    mass_matrix: NDArray[np.float64] = field(default_factory=lambda: np.full((2, 2), np.nan))
    hydrostatic_stiffness: NDArray[np.float64] = field(default_factory=lambda: np.full((2, 2), np.nan))
    wave_phase_reference_x_m: float = float("nan")
    wavenumber_rad_per_m: NDArray[np.float64] | None = None
    source: str = ""
    surge_rao_m_per_m: NDArray[np.complex128] | None = None
    reference_z_m: float = float("nan")
    coupled_heave_rao_m_per_m: NDArray[np.complex128] | None = None
    coupled_pitch_rao_rad_per_m: NDArray[np.complex128] | None = None

    def __post_init__(self) -> None:
        w = np.asarray(self.omega_rad_s, dtype=float)
        if w.ndim != 1 or w.size < 1 or np.any(np.diff(w) <= 0):
            raise ValueError("RigidBodyMotions: omega_rad_s must be a non-empty, strictly increasing 1-D array")
        n = w.size
        arrays = {
            "heave_rao_m_per_m": (np.complex128, (n,)),
            "pitch_rao_rad_per_m": (np.complex128, (n,)),
            "added_mass": (np.float64, (n, 2, 2)),
            "radiation_damping": (np.float64, (n, 2, 2)),
            "excitation_force": (np.complex128, (n, 2)),
            "mass_matrix": (np.float64, (2, 2)),
            "hydrostatic_stiffness": (np.float64, (2, 2)),
        }
        object.__setattr__(self, "omega_rad_s", w)
        for name, (dtype, shape) in arrays.items():
            a: NDArray[np.generic] = np.asarray(getattr(self, name), dtype=dtype)
            if a.shape != shape:
                raise ValueError(f"RigidBodyMotions: {name} has shape {a.shape}, expected {shape}")
            a.setflags(write=False)
            object.__setattr__(self, name, a)
        if self.wavenumber_rad_per_m is not None:
            k = np.asarray(self.wavenumber_rad_per_m, dtype=float)
            if k.shape != (n,):
                raise ValueError("RigidBodyMotions: wavenumber_rad_per_m must have the shape of omega_rad_s")
            object.__setattr__(self, "wavenumber_rad_per_m", k)
        for name in ("surge_rao_m_per_m", "coupled_heave_rao_m_per_m", "coupled_pitch_rao_rad_per_m"):
            if getattr(self, name) is not None:
                u = np.asarray(getattr(self, name), dtype=np.complex128)
                if u.shape != (n,):
                    raise ValueError(f"RigidBodyMotions: {name} has shape {u.shape}, expected {(n,)}")
                u.setflags(write=False)
                object.__setattr__(self, name, u)
        w.setflags(write=False)

    @property
    def has_surge(self) -> bool:
        """Whether the hydrodynamic data held surge (``surge_rao_m_per_m`` is not ``None``)."""
        return self.surge_rao_m_per_m is not None

    def surge_at(self, omega: ArrayLike) -> ComplexValue:
        """Surge RAO at ``omega`` [rad/s] (forward +, of the reference point) [m/m], interpolated.

        Raises
        ------
        ValueError
            If the data hold no surge (message says so), or ``omega`` is outside the range.
        """
        if self.surge_rao_m_per_m is None:
            raise ValueError(f"RigidBodyMotions: no surge in the hydrodynamic data ({self.source})")
        return self._interp(omega, self.surge_rao_m_per_m)

    def coupled_at(self, omega: ArrayLike) -> tuple[ComplexValue, ComplexValue, ComplexValue]:
        """Surge [m/m], heave [m/m] and pitch [rad/m] of the coupled 3-DOF solution at ``omega``, interpolated.

        Raises
        ------
        ValueError
            If the data hold no surge, or ``omega`` is outside the range.
        """
        if self.coupled_heave_rao_m_per_m is None or self.coupled_pitch_rao_rad_per_m is None:
            raise ValueError(f"RigidBodyMotions: no surge in the hydrodynamic data ({self.source})")
        return (
            self.surge_at(omega),
            self._interp(omega, self.coupled_heave_rao_m_per_m),
            self._interp(omega, self.coupled_pitch_rao_rad_per_m),
        )

    # ---------------------------------------------------------------- interpolation
    def _check_range(self, omega: NDArray[np.float64]) -> None:
        lo, hi = self.omega_rad_s[0], self.omega_rad_s[-1]
        bad = omega[(omega < lo * (1 - 1e-12)) | (omega > hi * (1 + 1e-12)) | ~np.isfinite(omega)]
        if bad.size:
            raise ValueError(f"RigidBodyMotions: omega = {float(bad[0])!r} rad/s is outside the computed range [{lo:.6g}, {hi:.6g}] rad/s")

    def _interp(self, omega: ArrayLike, values: NDArray[np.complex128]) -> ComplexValue:
        w = np.asarray(omega, dtype=float)
        self._check_range(np.atleast_1d(w))
        wc = np.clip(w, self.omega_rad_s[0], self.omega_rad_s[-1])
        out = np.interp(wc, self.omega_rad_s, values.real) + 1j * np.interp(wc, self.omega_rad_s, values.imag)
        return complex(out) if np.ndim(w) == 0 else out

    def rao_at(self, omega: ArrayLike) -> tuple[ComplexValue, ComplexValue]:
        """Heave and pitch RAOs at ``omega`` [rad/s], linearly interpolated (real and imaginary parts).

        Returns
        -------
        (heave [m/m], pitch [rad/m])
            Complex scalars for a scalar ``omega``, arrays otherwise.

        Raises
        ------
        ValueError
            If any ``omega`` lies outside the computed range (message names value and range).
        """
        return self._interp(omega, self.heave_rao_m_per_m), self._interp(omega, self.pitch_rao_rad_per_m)

    def vertical_displacement_rao(self, x_m: ArrayLike, omega: ArrayLike | None = None) -> ComplexValue:
        """Rigid-body vertical displacement ``w + theta (x - reference_x_m)`` per metre of wave [m/m].

        Parameters
        ----------
        x_m
            Positions from the AP [m].
        omega
            Frequency [rad/s] (interpolated); ``None``: all computed frequencies, shape
            ``(n_w,) + shape(x_m)``.
        """
        x = np.asarray(x_m, dtype=float)
        if omega is None:
            h, p = self.heave_rao_m_per_m, self.pitch_rao_rad_per_m
            return h.reshape((-1,) + (1,) * x.ndim) + p.reshape((-1,) + (1,) * x.ndim) * (x - self.reference_x_m)
        h_w, p_w = self.rao_at(omega)
        if np.ndim(omega) == 0:
            return h_w + p_w * (x - self.reference_x_m)
        h_a, p_a = np.asarray(h_w, dtype=np.complex128), np.asarray(p_w, dtype=np.complex128)
        return h_a[(...,) + (None,) * x.ndim] + p_a[(...,) + (None,) * x.ndim] * (x - self.reference_x_m)

    # ---------------------------------------------------------------- export
    def to_dataset(self) -> xr.Dataset:
        """Export as an :class:`xarray.Dataset` writable with ``to_netcdf`` (real/imag split).

        Complex quantities are stored as ``<name>_real`` / ``<name>_imag`` plus ``<name>_abs``
        and ``<name>_phase_deg`` (phase of ``exp(+i omega t)`` amplitudes, relative to the wave
        crest at ``wave_phase_reference_x_m``).
        """
        dof = ["heave", "pitch"]
        coords = {
            "omega": ("omega", self.omega_rad_s, {"units": "rad/s", "long_name": "wave angular frequency"}),
            "dof": ("dof", dof, {"long_name": "degree of freedom (heave up at reference_x_m, pitch bow up)"}),
            "radiating_dof": ("radiating_dof", dof, {"long_name": "radiating (motion) degree of freedom"}),
        }
        ds = xr.Dataset(coords={k: xr.Variable(*v) for k, v in coords.items()})

        def add_complex(name: str, data: NDArray[np.complex128], dims: tuple[str, ...], units: str, long_name: str) -> None:
            for part, fn, u in (
                ("real", np.real, units),
                ("imag", np.imag, units),
                ("abs", np.abs, units),
                ("phase_deg", lambda a: np.degrees(np.angle(a)), "deg"),
            ):
                ds[f"{name}_{part}"] = xr.Variable(dims, fn(data), {"units": u, "long_name": f"{long_name} ({part})"})

        add_complex("heave_rao", self.heave_rao_m_per_m, ("omega",), "m/m", "heave RAO at reference_x_m")
        add_complex("pitch_rao", self.pitch_rao_rad_per_m, ("omega",), "rad/m", "pitch RAO theta=dz/dx, bow up")
        if self.surge_rao_m_per_m is not None:
            add_complex("surge_rao", self.surge_rao_m_per_m, ("omega",), "m/m", "surge RAO (forward +) at the reference point")
        if self.coupled_heave_rao_m_per_m is not None and self.coupled_pitch_rao_rad_per_m is not None:
            add_complex("coupled_heave_rao", self.coupled_heave_rao_m_per_m, ("omega",), "m/m", "heave RAO, coupled with surge")
            add_complex(
                "coupled_pitch_rao", self.coupled_pitch_rao_rad_per_m, ("omega",), "rad/m", "pitch RAO (bow up), coupled with surge"
            )
        add_complex(
            "excitation_force",
            self.excitation_force,
            ("omega", "dof"),
            "N/m (heave), N m/m (pitch)",
            "wave excitation per metre of wave amplitude",
        )
        ds["added_mass"] = xr.Variable(
            ("omega", "dof", "radiating_dof"), self.added_mass, {"units": "kg, kg m, kg m^2", "long_name": "added mass (heave, pitch)"}
        )
        ds["radiation_damping"] = xr.Variable(
            ("omega", "dof", "radiating_dof"), self.radiation_damping, {"units": "kg/s, kg m/s, kg m^2/s", "long_name": "radiation damping"}
        )
        ds["mass_matrix"] = xr.Variable(
            ("dof", "radiating_dof"), self.mass_matrix, {"units": "kg, kg m^2", "long_name": "rigid-body mass matrix"}
        )
        ds["hydrostatic_stiffness"] = xr.Variable(
            ("dof", "radiating_dof"), self.hydrostatic_stiffness, {"units": "N/m, N/rad, N m/rad", "long_name": "hydrostatic stiffness"}
        )
        if self.wavenumber_rad_per_m is not None:
            ds["wavenumber"] = xr.Variable(("omega",), self.wavenumber_rad_per_m, {"units": "rad/m", "long_name": "wave number"})
        ds.attrs.update(
            reference_x_m=float(self.reference_x_m),
            wave_phase_reference_x_m=float(self.wave_phase_reference_x_m),
            time_convention="x(t) = Re(X exp(+i omega t))",
            wave_convention="zeta = zeta_a cos(omega t + k (x - wave_phase_reference_x_m)), head seas towards -x",
            pitch_convention="theta = dz/dx, bow up positive, about x = reference_x_m",
            source=self.source,
            reference_z_m=float(self.reference_z_m),
            has_surge=int(self.has_surge),
        )
        return ds


# ---------------------------------------------------------------------------------- physics helpers
def wavenumber_rad_per_m(omega_rad_s: ArrayLike, water_depth_m: float = math.inf, gravity_m_per_s2: float = 9.81) -> NDArray[np.float64]:
    """Wave number from the linear dispersion relation ``omega^2 = g k tanh(k h)`` [rad/m]."""
    w = np.asarray(omega_rad_s, dtype=float)
    k = w**2 / gravity_m_per_s2
    if math.isinf(water_depth_m):
        return k
    h = float(water_depth_m)
    k = np.where(k > 0, k, 0.0)
    k = np.maximum(k, w / math.sqrt(gravity_m_per_s2 * h))
    for _ in range(100):  # Newton on f(k) = g k tanh(kh) - w^2
        th = np.tanh(k * h)
        f = gravity_m_per_s2 * k * th - w**2
        df = gravity_m_per_s2 * (th + k * h * (1 - th**2))
        dk = np.where(df > 0, f / np.where(df > 0, df, 1.0), 0.0)
        k = k - dk
        if np.all(np.abs(dk) <= 1e-14 * np.maximum(k, 1e-30)):
            break
    return k


def _section_centroid_below_wl(hull: HullForm) -> float:
    """Height of the sectional-area centroid relative to the waterline [m] (negative)."""
    prof = section_profile(hull.section_area_coefficient, hull.draft_m)
    poly = np.vstack([prof, [[0.0, 0.0]]])  # close along the centre line and the waterline
    y, z = poly[:, 0], poly[:, 1]
    cross = y * np.roll(z, -1) - np.roll(y, -1) * z
    area = 0.5 * np.sum(cross)
    return float(np.sum((z + np.roll(z, -1)) * cross) / (6.0 * area))


def _x_grid(hull: HullForm, n: int = 4001) -> NDArray[np.float64]:
    return np.unique(np.concatenate([np.linspace(hull.station_x_m[0], hull.station_x_m[-1], n), hull.station_x_m]))


def hydrostatic_stiffness_matrix(
    hull: HullForm,
    *,
    mass_kg: float,
    centre_of_gravity_m: Sequence[float],
    water_density_kg_per_m3: float = 1025.0,
    gravity_m_per_s2: float = 9.81,
) -> NDArray[np.float64]:
    """Heave-pitch hydrostatic stiffness of the wall-sided hull about the CoG x (seafast DOFs).

    ``C_ww = rho g A_wp``; ``C_wt = C_tw = rho g int b (x - x_G) dx``;
    ``C_tt = rho g int b (x - x_G)^2 dx + rho g V z_B - m g z_G`` with heights relative to the
    waterline (``z_G`` given above the keel in ``centre_of_gravity_m``).

    Returns
    -------
    ndarray (2, 2)
        [[N/m, N/rad], [N, N m/rad]].
    """
    x = _x_grid(hull)
    b = hull.breadth_at(x)
    xg, zg_keel = float(centre_of_gravity_m[0]), float(centre_of_gravity_m[2])
    rg = water_density_kg_per_m3 * gravity_m_per_s2
    c11 = rg * np.trapezoid(b, x)
    c12 = rg * np.trapezoid(b * (x - xg), x)
    c22 = rg * np.trapezoid(b * (x - xg) ** 2, x)
    zb = _section_centroid_below_wl(hull)
    zg = zg_keel - hull.draft_m
    c22 += rg * hull.displaced_volume_m3() * zb - mass_kg * gravity_m_per_s2 * zg
    return np.array([[c11, c12], [c12, c22]])


def mass_matrix(mass_kg: float, pitch_radius_of_gyration_m: float) -> NDArray[np.float64]:
    """Rigid-body mass matrix about the CoG: ``diag(m, m r_yy^2)`` [kg, kg m^2]."""
    return np.diag([float(mass_kg), float(mass_kg) * float(pitch_radius_of_gyration_m) ** 2])


def solve_heave_pitch(
    omega_rad_s: ArrayLike,
    added_mass: ArrayLike,
    radiation_damping: ArrayLike,
    excitation_force: ArrayLike,
    mass_matrix_: ArrayLike,
    hydrostatic_stiffness: ArrayLike,
) -> tuple[NDArray[np.complex128], NDArray[np.complex128]]:
    """Solve ``[-omega^2 (M + A) + i omega B + C] X = F`` per frequency (seafast conventions).

    Returns
    -------
    (heave [m/m], pitch [rad/m]), each complex (n_w,).
    """
    w = np.asarray(omega_rad_s, dtype=float)
    a = np.asarray(added_mass, dtype=float)
    b = np.asarray(radiation_damping, dtype=float)
    f = np.asarray(excitation_force, dtype=complex)
    m = np.asarray(mass_matrix_, dtype=float)
    c = np.asarray(hydrostatic_stiffness, dtype=float)
    z = -(w[:, None, None] ** 2) * (m[None] + a) + 1j * w[:, None, None] * b + c[None]
    x = np.linalg.solve(z, f[..., None])[..., 0]
    return x[:, 0], x[:, 1]


def solve_rigid_body(
    omega_rad_s: ArrayLike,
    added_mass: ArrayLike,
    radiation_damping: ArrayLike,
    excitation_force: ArrayLike,
    mass_matrix_: ArrayLike,
    hydrostatic_stiffness: ArrayLike,
) -> NDArray[np.complex128]:
    """Solve ``[-omega^2 (M + A) + i omega B + C] X = F`` per frequency, any number of DOFs.

    Returns
    -------
    ndarray (n_w, n_dof)
        Complex amplitudes per metre of wave amplitude, in the DOF order of the inputs.
    """
    w = np.asarray(omega_rad_s, dtype=float)
    z = (
        -(w[:, None, None] ** 2) * (np.asarray(mass_matrix_, dtype=float)[None] + np.asarray(added_mass, dtype=float))
        + 1j * w[:, None, None] * np.asarray(radiation_damping, dtype=float)
        + np.asarray(hydrostatic_stiffness, dtype=float)[None]
    )
    return np.linalg.solve(z, np.asarray(excitation_force, dtype=complex)[..., None])[..., 0]


def _shift_reference(dx_ref_minus_new: float) -> NDArray[np.float64]:
    """Matrix ``P`` with ``q_old = P q_new`` when pitch moves from ``x_old`` to ``x_new``.

    ``w_old = w_new + theta (x_old - x_new)``; forces transform with ``P^T``.
    """
    return np.array([[1.0, dx_ref_minus_new], [0.0, 1.0]])


def base_vessel_mass_properties(hull: HullForm, *, water_density_kg_per_m3: float = 1025.0) -> dict:
    """Documented default mass properties of the vessel (keyword arguments of :func:`compute_motions`).

    * ``mass_kg = rho * V`` (free floating at the design draught; 1025 * 32 000 kg for the base hull),
    * ``centre_of_gravity_m = (x_LCB, 0, 8.0)``: x at the longitudinal centre of buoyancy (even
      keel), z = 8 m **above the keel** (internally 8 - T = 1.5 m above the waterline),
    * ``pitch_radius_of_gyration_m = 0.25 L``.
    """
    return {
        "mass_kg": float(water_density_kg_per_m3 * hull.displaced_volume_m3()),
        "centre_of_gravity_m": (float(hull.centre_of_buoyancy_x_m()), 0.0, 8.0),
        "pitch_radius_of_gyration_m": 0.25 * hull.length_m,
    }


# ---------------------------------------------------------------------------------- capytaine
def default_cache_dir() -> Path:
    """``$SEAFAST_CACHE_DIR`` if set, else ``~/.cache/seafast/hydrodynamics``."""
    env = os.environ.get("SEAFAST_CACHE_DIR")
    return Path(env) if env else Path.home() / ".cache" / "seafast" / "hydrodynamics"


def _cache_key(payload: dict) -> str:
    return hashlib.sha256(json.dumps(payload, sort_keys=True).encode()).hexdigest()[:32]


def _run_bem(
    hull: HullForm,
    omega: NDArray[np.float64],
    rotation_center_wl: NDArray[np.float64],
    panel_size_m: float,
    rho: float,
    g: float,
    depth: float,
) -> xr.Dataset:
    """Radiation (:data:`BEM_DOFS`: surge, heave, pitch) and head-sea diffraction; returns capytaine's dataset.

    Frame: origin at midship on the waterline (see :mod:`seafast.vessel.hull_mesh`).
    """
    import capytaine as cpt

    hm = hull_mesh_arrays(hull, panel_size_m)
    mesh, lid = hm.to_capytaine()
    body = cpt.FloatingBody(
        mesh=mesh,
        lid_mesh=lid,
        dofs=cpt.rigid_body_dofs(only=list(BEM_DOFS), rotation_center=rotation_center_wl),
        center_of_mass=rotation_center_wl,
        name="seafast_vessel",
    )
    solver = cpt.BEMSolver()
    problems = []
    for w in omega:
        kw = dict(body=body, omega=float(w), rho=rho, g=g, water_depth=depth)
        problems += [cpt.RadiationProblem(radiating_dof=d, **kw) for d in BEM_DOFS]
        problems.append(cpt.DiffractionProblem(wave_direction=np.pi, **kw))
    from threadpoolctl import threadpool_limits

    # the BEM's dense complex solves do profit from every core (callers may have pinned BLAS)
    with threadpool_limits(limits=os.cpu_count() or 1, user_api="blas"):
        results = solver.solve_all(problems, progress_bar=False)
    ds = cpt.assemble_dataset(results, hydrostatics=False)
    ds.attrs["seafast_origin_x_m"] = float(hm.x_mid_m)
    ds.attrs["seafast_panel_size_m"] = float(panel_size_m)
    ds.attrs["seafast_nb_panels_hull"] = hm.nb_hull_panels_full
    ds.attrs["seafast_nb_panels_lid"] = hm.nb_lid_panels_full
    return ds


def compute_motions(
    hull: HullForm,
    *,
    mass_kg: float,
    centre_of_gravity_m: Sequence[float],
    pitch_radius_of_gyration_m: float,
    omega_rad_s: ArrayLike,
    panel_size_m: float = 3.0,
    water_density_kg_per_m3: float = 1025.0,
    gravity_m_per_s2: float = 9.81,
    water_depth_m: float = math.inf,
    cache_dir: str | os.PathLike | None = None,
    use_cache: bool = True,
) -> RigidBodyMotions:
    """Heave and pitch RAOs of the vessel in head seas from capytaine (BEM), cached on disk.

    Parameters
    ----------
    hull
        Hull form; meshed with :func:`seafast.vessel.hull_mesh.hull_mesh_arrays` (sides, bottom,
        transom, plus an interior waterplane lid removing irregular frequencies; y-symmetry used).
    mass_kg
        Ship mass [kg] (given explicitly; capytaine's uniform-density default is not used).
    centre_of_gravity_m
        ``(x from AP, y, z above keel)`` [m]. Pitch acts about ``x_G``; ``z_G`` enters the
        pitch restoring term ``-m g z_G`` and the rotation centre.
    pitch_radius_of_gyration_m
        Radius of gyration about the transverse axis through the CoG [m].
    omega_rad_s
        Wave frequencies [rad/s] (> 0; sorted internally, duplicates removed).
    panel_size_m
        Target panel size [m]: 3 m for production, ~8 m for quick checks.
    water_density_kg_per_m3, gravity_m_per_s2
        Passed to capytaine explicitly (its default density is 1000).
    water_depth_m
        Water depth [m] (``inf``: deep water).
    cache_dir
        Directory of cached capytaine datasets; default :func:`default_cache_dir`.
    use_cache
        Read and write the cache (default True).

    Returns
    -------
    RigidBodyMotions
        About ``reference_x_m = x_G``; phases relative to the wave crest at ``L/2``.

    Notes
    -----
    The cache key hashes the hull geometry, the BEM pitch axis (LCB x at the CoG height),
    frequencies, panel size, density, gravity, depth, the capytaine version and
    :data:`MESH_ALGORITHM_VERSION`; mass, CoG x and inertia are applied after the BEM, so a
    change of loading reuses the cached hydrodynamic coefficients. The cache file is
    the capytaine dataset written with capytaine's own NetCDF export, so it can be read back with
    :func:`load_motions` as well.
    """
    import capytaine as cpt

    omega = np.unique(np.asarray(omega_rad_s, dtype=float).ravel())
    if omega.size == 0 or not np.all(np.isfinite(omega)) or np.any(omega <= 0):
        raise ValueError(f"compute_motions: omega_rad_s must be finite and > 0, got {omega_rad_s!r}")
    if not mass_kg > 0 or not pitch_radius_of_gyration_m > 0:
        raise ValueError("compute_motions: mass_kg and pitch_radius_of_gyration_m must be > 0")
    cog = tuple(float(c) for c in centre_of_gravity_m)
    if len(cog) != 3:
        raise ValueError("compute_motions: centre_of_gravity_m must be (x, y, z)")
    x_mid = 0.5 * (hull.station_x_m[0] + hull.station_x_m[-1])
    # The BEM pitch axis is fixed at the hull's LCB (at the CoG height): the radiation and
    # diffraction coefficients then depend on the hull alone, so one cached BEM run serves every
    # loading (studies vary the cargo and with it the CoG); they are moved to the CoG x below.
    rotation_center = np.array([hull.centre_of_buoyancy_x_m() - x_mid, 0.0, cog[2] - hull.draft_m])
    depth = float(water_depth_m)

    payload = {
        "stations": [repr(float(v)) for v in hull.station_x_m],
        "breadth": [repr(float(v)) for v in hull.waterline_breadth_m],
        "draft": repr(float(hull.draft_m)),
        "cs": repr(float(hull.section_area_coefficient)),
        "rotation_center": [repr(float(c)) for c in rotation_center],
        "omega": [repr(float(v)) for v in omega],
        "panel": repr(float(panel_size_m)),
        "rho": repr(float(water_density_kg_per_m3)),
        "g": repr(float(gravity_m_per_s2)),
        "depth": repr(depth),
        "capytaine": cpt.__version__,
        "mesh": MESH_ALGORITHM_VERSION,
        "dofs": list(BEM_DOFS),
    }
    key = _cache_key(payload)
    cdir = Path(cache_dir) if cache_dir is not None else default_cache_dir()
    path = cdir / f"motions_{key}.nc"
    ds = None
    if use_cache and path.is_file():
        try:
            ds = _read_capytaine_netcdf(path)
            logger.debug("BEM cache hit: %s", path)
        except Exception:  # noqa: BLE001 - a corrupt or foreign cache file, whatever the error: recompute it
            logger.warning("BEM cache file %s is unreadable; recomputing it", path)
            ds = None
    if ds is None:
        logger.info("computing the vessel's hydrodynamics with capytaine (BEM, tens of seconds); cache: %s", path if use_cache else "off")
        ds = _run_bem(hull, omega, rotation_center, float(panel_size_m), float(water_density_kg_per_m3), float(gravity_m_per_s2), depth)
        if use_cache:
            cdir.mkdir(parents=True, exist_ok=True)
            ds.attrs["seafast_cache_key"] = key
            fd, tmp = tempfile.mkstemp(suffix=".nc", dir=cdir)
            os.close(fd)
            try:
                cpt.export_dataset(tmp, ds)
                os.replace(tmp, path)
            finally:
                if os.path.exists(tmp):
                    os.remove(tmp)
    # the coefficients depend on the hull alone: extracted from the dataset once per process (a
    # cargo study changes the loading, hence mass and CoG, at every point, not the hull)
    held = _CAPYTAINE_COEFFICIENTS.get(key)
    if held is None or held[0] is not ds:  # extracted from this very dataset (a re-read or re-run dataset is new)
        held = (ds, _capytaine_rigid_coefficients(ds, x_mid, gravity_m_per_s2))
        if len(_CAPYTAINE_COEFFICIENTS) >= 8:
            _CAPYTAINE_COEFFICIENTS.pop(next(iter(_CAPYTAINE_COEFFICIENTS)))
        _CAPYTAINE_COEFFICIENTS[key] = held
    omega_c, k_c, a_c, b_c, f_c, x_rot, z_rot_wl = held[1]
    return _motions_from_rigid_coefficients(
        omega_c,
        k_c,
        a_c,
        b_c,
        f_c,
        hull,
        coeff_reference_x_m=x_rot,
        wave_phase_origin_x_m=x_mid,
        coeff_reference_z_wl_m=z_rot_wl,
        mass_kg=mass_kg,
        centre_of_gravity_m=cog,
        pitch_radius_of_gyration_m=pitch_radius_of_gyration_m,
        water_density_kg_per_m3=water_density_kg_per_m3,
        gravity_m_per_s2=gravity_m_per_s2,
        source=f"capytaine {cpt.__version__} BEM, panel size {panel_size_m} m, cache key {key}",
    )


# (dataset, its rigid-body coefficients) of BEM runs, by cache key (the key covers the hull,
# frequencies, panel size, density, gravity, depth and the capytaine version)
_CAPYTAINE_COEFFICIENTS: dict[str, tuple[xr.Dataset, tuple]] = {}


def _read_capytaine_netcdf(path: str | os.PathLike) -> xr.Dataset:
    """Read a capytaine NetCDF export (memoised per file version: studies read it once per process)."""
    p = Path(path)
    stat = p.stat()
    return _read_capytaine_netcdf_cached(str(p.resolve()), stat.st_mtime_ns, stat.st_size)


@functools.lru_cache(maxsize=8)
def _read_capytaine_netcdf_cached(path: str, mtime_ns: int, size: int) -> xr.Dataset:
    from capytaine.io.xarray import merge_complex_values

    with xr.open_dataset(path) as raw:
        ds = merge_complex_values(raw.load())
    return ds


def _has_dof(values: Iterable[object], name: str) -> bool:
    return name.lower() in [str(v).lower() for v in values]


def _dof_index(values: Iterable[object], name: str) -> int:
    found = list(values)
    names = [str(v).lower() for v in found]
    if name.lower() not in names:
        raise ValueError(f"capytaine dataset: dof {name!r} missing (found {found})")
    return names.index(name.lower())


def _motions_from_capytaine(
    ds: xr.Dataset,
    hull: HullForm,
    *,
    mass_kg: float,
    centre_of_gravity_m: Sequence[float],
    pitch_radius_of_gyration_m: float,
    origin_x_m: float | None,
    water_density_kg_per_m3: float,
    gravity_m_per_s2: float,
    source: str,
) -> RigidBodyMotions:
    """Convert a capytaine dataset (heave + pitch radiation, head-sea diffraction) to seafast motions."""
    x_mid = 0.5 * (hull.station_x_m[0] + hull.station_x_m[-1])
    if origin_x_m is None:
        origin_x_m = float(ds.attrs.get("seafast_origin_x_m", x_mid))
    omega, k, a_c, b_c, f_conj, x_rot, z_rot_wl = _capytaine_rigid_coefficients(ds, origin_x_m, gravity_m_per_s2)
    return _motions_from_rigid_coefficients(
        omega,
        k,
        a_c,
        b_c,
        f_conj,
        hull,
        coeff_reference_x_m=x_rot,
        wave_phase_origin_x_m=origin_x_m,
        coeff_reference_z_wl_m=z_rot_wl,
        mass_kg=mass_kg,
        centre_of_gravity_m=centre_of_gravity_m,
        pitch_radius_of_gyration_m=pitch_radius_of_gyration_m,
        water_density_kg_per_m3=water_density_kg_per_m3,
        gravity_m_per_s2=gravity_m_per_s2,
        source=source,
    )


def _capytaine_rigid_coefficients(ds: xr.Dataset, origin_x_m: float, gravity_m_per_s2: float) -> tuple:
    """Added mass, damping and excitation of a capytaine dataset, by frequency.

    Returns ``(omega, k, a, b, conj(f), x_rot, z_rot_wl)``: frequencies [rad/s] ascending,
    wavenumbers [rad/m], added mass and damping (n_w, d, d) and the conjugated head-sea excitation
    (n_w, d) in capytaine's (heave, pitch) DOFs, or (surge, heave, pitch) when the dataset holds
    surge, about ``x_rot`` (ship x of the dataset's rotation centre) and ``z_rot_wl`` [m] above the
    waterline.
    """
    if "omega" not in ds.dims:
        if "omega" in ds.coords:
            ds = ds.swap_dims({next(d for d in ds["omega"].dims): "omega"})
        else:
            raise ValueError("capytaine dataset: no 'omega' coordinate")
    ds = ds.sortby("omega")
    for v in ("added_mass", "radiation_damping", "excitation_force"):
        if v not in ds:
            raise ValueError(f"capytaine dataset: variable {v!r} missing")
    omega = np.asarray(ds["omega"].values, dtype=float)
    # head seas: wave_direction = pi
    exc = ds["excitation_force"]
    if "wave_direction" in exc.dims:
        wd = np.asarray(exc["wave_direction"].values, dtype=float)
        i = int(np.argmin(np.abs(np.angle(np.exp(1j * (wd - np.pi))))))
        if abs(np.angle(np.exp(1j * (wd[i] - np.pi)))) > 1e-6:
            raise ValueError(f"capytaine dataset: no head-sea (wave_direction = pi) case, found {wd}")
        exc = exc.isel(wave_direction=i)
    elif "wave_direction" in exc.coords and abs(float(exc["wave_direction"]) - np.pi) > 1e-6:
        raise ValueError("capytaine dataset: excitation is not for wave_direction = pi")
    for d in [d for d in exc.dims if d not in ("omega", "influenced_dof")]:
        exc = exc.isel({d: 0})
    inf_dofs = ds["influenced_dof"].values
    rad_dofs = ds["radiating_dof"].values
    ih, ip = _dof_index(inf_dofs, "Heave"), _dof_index(inf_dofs, "Pitch")
    jh, jp = _dof_index(rad_dofs, "Heave"), _dof_index(rad_dofs, "Pitch")
    rows, cols = [ih, ip], [jh, jp]
    has_surge = _has_dof(inf_dofs, "Surge") and _has_dof(rad_dofs, "Surge")
    if has_surge:  # (surge, heave, eta5)
        rows, cols = [_dof_index(inf_dofs, "Surge"), *rows], [_dof_index(rad_dofs, "Surge"), *cols]

    def mat(v: str) -> NDArray[np.float64]:
        da = ds[v]
        for d in [d for d in da.dims if d not in ("omega", "influenced_dof", "radiating_dof")]:
            da = da.isel({d: 0})
        values = da.transpose("omega", "influenced_dof", "radiating_dof").values
        return np.real(values[:, rows][:, :, cols])

    a_c, b_c = mat("added_mass"), mat("radiation_damping")
    f_c = exc.transpose("omega", "influenced_dof").values[:, rows]
    if "wavenumber" in ds.coords or "wavenumber" in ds:
        k = np.broadcast_to(np.asarray(ds["wavenumber"].values, dtype=float), omega.shape).copy()
    else:
        depth = float(ds["water_depth"].values) if "water_depth" in ds.coords else math.inf
        k = wavenumber_rad_per_m(omega, depth, gravity_m_per_s2)

    # rotation centre of the dataset (capytaine frame: x relative to origin_x_m)
    z_rot_wl = 0.0
    if "rotation_center" in ds.coords or "rotation_center" in ds:
        rc = np.asarray(ds["rotation_center"].values, dtype=float).reshape(-1)[:3]
        x_rot = origin_x_m + float(rc[0])
        z_rot_wl = float(rc[2])
    else:
        x_rot = origin_x_m
    return omega, k, a_c, b_c, np.conj(f_c), x_rot, z_rot_wl


def _motions_from_rigid_coefficients(
    omega: NDArray[np.float64],
    k: NDArray[np.float64],
    a_eta: NDArray[np.float64],
    b_eta: NDArray[np.float64],
    f_eta_plus: NDArray[np.complex128],
    hull: HullForm,
    *,
    coeff_reference_x_m: float,
    wave_phase_origin_x_m: float,
    mass_kg: float,
    centre_of_gravity_m: Sequence[float],
    pitch_radius_of_gyration_m: float,
    water_density_kg_per_m3: float,
    gravity_m_per_s2: float,
    source: str,
    coeff_reference_z_wl_m: float = 0.0,
) -> RigidBodyMotions:
    """Common back end of the importers.

    Inputs in (heave, eta5) DOFs (eta5 = rotation about +y, bow down) about
    ``coeff_reference_x_m``, excitation in the ``exp(+i omega t)`` convention with the incident
    wave phase referred to ``wave_phase_origin_x_m``. With 3x3 inputs the DOFs are (surge,
    heave, eta5) about the point (``coeff_reference_x_m``, ``coeff_reference_z_wl_m`` above the
    waterline), and surge, heave and pitch are solved together (:func:`_coupled_surge_motions`).
    """
    if np.shape(a_eta)[-1] == 3:
        # heave and pitch by the 2-DOF solve of their block (unchanged), plus the coupled solution
        two = _motions_from_rigid_coefficients(
            omega,
            k,
            np.asarray(a_eta)[:, 1:, 1:],
            np.asarray(b_eta)[:, 1:, 1:],
            np.asarray(f_eta_plus)[:, 1:],
            hull,
            coeff_reference_x_m=coeff_reference_x_m,
            wave_phase_origin_x_m=wave_phase_origin_x_m,
            mass_kg=mass_kg,
            centre_of_gravity_m=centre_of_gravity_m,
            pitch_radius_of_gyration_m=pitch_radius_of_gyration_m,
            water_density_kg_per_m3=water_density_kg_per_m3,
            gravity_m_per_s2=gravity_m_per_s2,
            source=source,
        )
        x3 = _coupled_surge_motions(
            omega,
            k,
            a_eta,
            b_eta,
            f_eta_plus,
            hull,
            coeff_reference_x_m=coeff_reference_x_m,
            coeff_reference_z_wl_m=coeff_reference_z_wl_m,
            wave_phase_origin_x_m=wave_phase_origin_x_m,
            mass_kg=mass_kg,
            centre_of_gravity_m=centre_of_gravity_m,
            pitch_radius_of_gyration_m=pitch_radius_of_gyration_m,
            water_density_kg_per_m3=water_density_kg_per_m3,
            gravity_m_per_s2=gravity_m_per_s2,
        )
        return replace(two, surge_rao_m_per_m=x3[:, 0], coupled_heave_rao_m_per_m=x3[:, 1], coupled_pitch_rao_rad_per_m=x3[:, 2])
    x_mid = 0.5 * (hull.station_x_m[0] + hull.station_x_m[-1])
    x_g = float(centre_of_gravity_m[0])
    # eta5 -> theta (bow up)
    a = _T @ a_eta @ _T
    b = _T @ b_eta @ _T
    f = f_eta_plus @ _T
    # incident wave phase: unit crest at the origin <-> seafast wave exp(i k (x - x_mid))
    f = f * np.exp(1j * k * (wave_phase_origin_x_m - x_mid))[:, None]
    # move the pitch reference from the coefficient reference to the CoG x
    p = _shift_reference(coeff_reference_x_m - x_g)
    a = p.T @ a @ p
    b = p.T @ b @ p
    f = f @ p
    m = mass_matrix(mass_kg, pitch_radius_of_gyration_m)
    c = hydrostatic_stiffness_matrix(
        hull,
        mass_kg=mass_kg,
        centre_of_gravity_m=centre_of_gravity_m,
        water_density_kg_per_m3=water_density_kg_per_m3,
        gravity_m_per_s2=gravity_m_per_s2,
    )
    heave, pitch = solve_heave_pitch(omega, a, b, f, m, c)
    return RigidBodyMotions(
        omega_rad_s=omega,
        heave_rao_m_per_m=heave,
        pitch_rao_rad_per_m=pitch,
        added_mass=a,
        radiation_damping=b,
        excitation_force=f,
        reference_x_m=x_g,
        mass_matrix=m,
        hydrostatic_stiffness=c,
        wave_phase_reference_x_m=x_mid,
        wavenumber_rad_per_m=k,
        source=source,
        reference_z_m=float(centre_of_gravity_m[2]),
    )


def _shift_reference_3(dx_new_minus_old: float, dz_new_minus_old: float) -> NDArray[np.float64]:
    """``P`` with ``q_old = P q_new`` for (surge, heave, theta) when the reference point moves.

    A point's displacement is ``(X - theta (z - z_ref), W + theta (x - x_ref))``, so
    ``X_old = X_new + theta dz`` and ``W_old = W_new - theta dx`` (``d = new - old``);
    forces transform with ``P^T``.
    """
    return np.array([[1.0, 0.0, dz_new_minus_old], [0.0, 1.0, -dx_new_minus_old], [0.0, 0.0, 1.0]])


def _coupled_surge_motions(
    omega: NDArray[np.float64],
    k: NDArray[np.float64],
    a_eta: NDArray[np.float64],
    b_eta: NDArray[np.float64],
    f_eta_plus: NDArray[np.complex128],
    hull: HullForm,
    *,
    coeff_reference_x_m: float,
    coeff_reference_z_wl_m: float,
    wave_phase_origin_x_m: float,
    mass_kg: float,
    centre_of_gravity_m: Sequence[float],
    pitch_radius_of_gyration_m: float,
    water_density_kg_per_m3: float,
    gravity_m_per_s2: float,
) -> NDArray[np.complex128]:
    """Surge, heave and pitch solved together about the CoG (x_G, z_G), from (surge, heave, eta5) data.

    Mass ``diag(m, m, m r^2)`` about the CoG; hydrostatic stiffness: the heave-pitch block of
    :func:`hydrostatic_stiffness_matrix` (no restoring in surge).

    Returns
    -------
    ndarray (n_w, 3)
        (surge [m/m], heave [m/m], pitch [rad/m]) per metre of wave amplitude, seafast conventions.
    """
    x_mid = 0.5 * (hull.station_x_m[0] + hull.station_x_m[-1])
    x_g, z_g_keel = float(centre_of_gravity_m[0]), float(centre_of_gravity_m[2])
    a = _T3 @ np.asarray(a_eta, dtype=float) @ _T3
    b = _T3 @ np.asarray(b_eta, dtype=float) @ _T3
    f = np.asarray(f_eta_plus, dtype=complex) @ _T3
    f = f * np.exp(1j * k * (wave_phase_origin_x_m - x_mid))[:, None]
    p = _shift_reference_3(x_g - coeff_reference_x_m, (z_g_keel - hull.draft_m) - coeff_reference_z_wl_m)
    a = p.T @ a @ p
    b = p.T @ b @ p
    f = f @ p
    m3 = np.zeros((3, 3))
    c3 = np.zeros((3, 3))
    m3[0, 0] = float(mass_kg)
    m3[1:, 1:] = mass_matrix(mass_kg, pitch_radius_of_gyration_m)
    c3[1:, 1:] = hydrostatic_stiffness_matrix(
        hull,
        mass_kg=mass_kg,
        centre_of_gravity_m=centre_of_gravity_m,
        water_density_kg_per_m3=water_density_kg_per_m3,
        gravity_m_per_s2=gravity_m_per_s2,
    )
    return solve_rigid_body(omega, a, b, f, m3, c3)


# ---------------------------------------------------------------------------------- WAMIT
def read_wamit_1(
    path: str | os.PathLike,
    *,
    ulen_m: float,
    water_density_kg_per_m3: float,
    frequency_column: Literal["period", "omega"] = "period",
    modes: tuple[int, ...] = (3, 5),
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """Read heave/pitch (``modes``: also surge, mode 1) added mass and damping from a WAMIT ``.1`` file.

    Lines ``PER I J Abar Bbar``; ``Abar = A / (rho L^k)``, ``Bbar = B / (rho L^k omega)`` with
    ``k = 3`` (translation-translation), 4 (mixed), 5 (rotation-rotation), ``L = ULEN``.
    Lines with ``PER <= 0`` (zero/infinite frequency limits) are skipped.

    Returns
    -------
    omega [rad/s] (n_w,), A (n_w, n, n), B (n_w, n, n) in WAMIT ``modes`` (default (3, 5), n = 2).
    """
    rows: dict[float, dict[tuple[int, int], tuple[float, float]]] = {}
    for line in Path(path).read_text().splitlines():
        parts = line.split()
        if len(parts) < 5:
            continue
        per, i, j, abar, bbar = float(parts[0]), int(parts[1]), int(parts[2]), float(parts[3]), float(parts[4])
        if per <= 0 or i not in modes or j not in modes:
            continue
        w = 2 * math.pi / per if frequency_column == "period" else per
        rows.setdefault(round(w, 12), {})[(i, j)] = (abar, bbar)
    if not rows:
        raise ValueError(f"WAMIT .1 file {path}: no coefficients of modes {modes} found")
    omega = np.array(sorted(rows))
    n_m = len(modes)
    a = np.zeros((omega.size, n_m, n_m))
    b = np.zeros((omega.size, n_m, n_m))
    idx = {m: q for q, m in enumerate(modes)}
    for n, w in enumerate(omega):
        for (i, j), (abar, bbar) in rows[w].items():
            kexp = 3 + (i > 3) + (j > 3)
            scale = water_density_kg_per_m3 * ulen_m**kexp
            a[n, idx[i], idx[j]] = abar * scale
            b[n, idx[i], idx[j]] = bbar * scale * w
        missing = {(i, i) for i in modes} - set(rows[w])
        if missing:
            raise ValueError(f"WAMIT .1 file {path}: diagonal terms {sorted(missing)} missing at omega = {w:.6g} rad/s")
    return omega, a, b


def read_wamit_3(
    path: str | os.PathLike,
    *,
    ulen_m: float,
    water_density_kg_per_m3: float,
    gravity_m_per_s2: float,
    heading_deg: float = 180.0,
    frequency_column: Literal["period", "omega"] = "period",
    modes: tuple[int, ...] = (3, 5),
) -> tuple[NDArray[np.float64], NDArray[np.complex128]]:
    """Read heave/pitch (``modes``: also surge, mode 1) wave excitation from a WAMIT ``.3`` file, one heading.

    Lines ``PER BETA I |X| phase Re Im``; ``Xbar = X / (rho g A L^m)``, ``m = 2`` for forces,
    3 for moments; ``exp(+i omega t)`` convention, phase relative to the incident wave at the
    WAMIT origin. The real and imaginary columns are used.

    Returns
    -------
    omega [rad/s] (n_w,), X (n_w, n) complex per metre of wave amplitude, in ``modes``.
    """
    rows: dict[float, dict[int, complex]] = {}
    headings: set[float] = set()
    for line in Path(path).read_text().splitlines():
        parts = line.split()
        if len(parts) < 7:
            continue
        per, beta, i = float(parts[0]), float(parts[1]), int(parts[2])
        headings.add(beta)
        if per <= 0 or i not in modes or abs((beta - heading_deg + 180.0) % 360.0 - 180.0) > 1e-3:
            continue
        w = 2 * math.pi / per if frequency_column == "period" else per
        m = 2 if i <= 3 else 3
        rows.setdefault(round(w, 12), {})[i] = (float(parts[5]) + 1j * float(parts[6])) * (
            water_density_kg_per_m3 * gravity_m_per_s2 * ulen_m**m
        )
    if not rows:
        raise ValueError(
            f"WAMIT .3 file {path}: no excitation of modes {modes} for heading {heading_deg} deg (headings found: {sorted(headings)})"
        )
    omega = np.array(sorted(rows))
    x = np.zeros((omega.size, len(modes)), dtype=complex)
    for n, w in enumerate(omega):
        if set(rows[w]) != set(modes):
            raise ValueError(f"WAMIT .3 file {path}: modes {sorted(set(modes) - set(rows[w]))} missing at omega = {w:.6g} rad/s")
        x[n] = [rows[w][m] for m in modes]
    return omega, x


def _wamit_has_surge(f1: Path, f3: Path) -> bool:
    """Whether both WAMIT files hold mode 1 (surge): the .1 file its diagonal term, the .3 file its force."""

    def has(path: Path, test: Callable[[list[str]], bool]) -> bool:
        for line in path.read_text().splitlines():
            parts = line.split()
            try:
                if test(parts):
                    return True
            except (ValueError, IndexError):
                continue
        return False

    return has(f1, lambda q: len(q) >= 5 and float(q[0]) > 0 and int(q[1]) == 1 and int(q[2]) == 1) and has(
        f3, lambda q: len(q) >= 7 and float(q[0]) > 0 and int(q[2]) == 1
    )


def load_motions(
    path: str | os.PathLike,
    hull: HullForm,
    *,
    mass_kg: float,
    centre_of_gravity_m: Sequence[float],
    pitch_radius_of_gyration_m: float,
    format: Literal["auto", "capytaine", "wamit"] = "auto",  # noqa: A002 - the public keyword users' scripts pass
    origin_x_m: float | None = None,
    ulen_m: float = 1.0,
    water_density_kg_per_m3: float = 1025.0,
    gravity_m_per_s2: float = 9.81,
    water_depth_m: float = math.inf,
    frequency_column: Literal["period", "omega"] = "period",
) -> RigidBodyMotions:
    """Import hydrodynamic coefficients and solve heave and pitch with given mass properties.

    Parameters
    ----------
    path
        A capytaine NetCDF file (``.nc``, as written by ``capytaine.export_dataset``; complex
        values split and merged back with capytaine's ``merge_complex_values``), or a WAMIT
        output: the ``.1`` file, the ``.3`` file or their common stem (both must exist).
    hull
        Hull form (hydrostatics are computed from it, consistently with :func:`compute_motions`).
    mass_kg, centre_of_gravity_m, pitch_radius_of_gyration_m
        Mass properties, as in :func:`compute_motions` (z above keel).
    format
        ``"auto"``: ``.nc`` -> capytaine, otherwise WAMIT.
    origin_x_m
        seafast ``x`` (from the AP) of the file's coordinate origin, which is also the phase
        reference of its incident wave. Default: the ``seafast_origin_x_m`` attribute of a
        seafast-written capytaine file, otherwise ``L/2`` (midship).
    ulen_m
        WAMIT ``ULEN`` [m] (non-dimensionalising length).
    water_density_kg_per_m3, gravity_m_per_s2
        WAMIT's ``rho`` and ``g`` used to dimensionalise, and used for the hydrostatics.
    water_depth_m
        Water depth for the wave number (WAMIT only; capytaine files carry their wave numbers).
    frequency_column
        WAMIT: whether the first column holds periods [s] (default, WAMIT's usual output) or
        angular frequencies [rad/s].

    Notes
    -----
    WAMIT assumptions: modes 3 (heave) and 5 (pitch, rotation about +y, i.e. bow down with the
    body x-axis pointing forward, parallel to seafast x), coefficients about the WAMIT body
    origin, which lies on the waterline at ``x = origin_x_m``; head seas ``beta = 180 deg``;
    ``exp(+i omega t)`` with phases relative to the incident wave crest at the origin. When both
    files hold mode 1 (surge), surge, heave and pitch are solved together about the CoG (x and
    height); otherwise the heave-pitch coefficients are transferred to the CoG x, couplings
    with surge are ignored and the motions carry no surge (``surge_rao_m_per_m = None``).
    A capytaine file with a ``Surge`` dof is treated the same way.
    """
    p = Path(path)
    fmt = format
    if fmt == "auto":
        fmt = "capytaine" if p.suffix.lower() in (".nc", ".netcdf", ".cdf") else "wamit"
    x_mid = 0.5 * (hull.station_x_m[0] + hull.station_x_m[-1])
    if fmt == "capytaine":
        ds = _read_capytaine_netcdf(p)
        return _motions_from_capytaine(
            ds,
            hull,
            origin_x_m=origin_x_m,
            source=f"capytaine file {p}",
            mass_kg=mass_kg,
            centre_of_gravity_m=centre_of_gravity_m,
            pitch_radius_of_gyration_m=pitch_radius_of_gyration_m,
            water_density_kg_per_m3=water_density_kg_per_m3,
            gravity_m_per_s2=gravity_m_per_s2,
        )
    if fmt != "wamit":
        raise ValueError(f"load_motions: unknown format {format!r}")
    stem = p.with_suffix("") if p.suffix in (".1", ".3") else p
    f1, f3 = Path(f"{stem}.1"), Path(f"{stem}.3")
    for f in (f1, f3):
        if not f.is_file():
            raise FileNotFoundError(f"load_motions: WAMIT file {f} not found")
    modes = (1, 3, 5) if _wamit_has_surge(f1, f3) else (3, 5)
    w1, a, b = read_wamit_1(
        f1, ulen_m=ulen_m, water_density_kg_per_m3=water_density_kg_per_m3, frequency_column=frequency_column, modes=modes
    )
    w3, x = read_wamit_3(
        f3,
        ulen_m=ulen_m,
        water_density_kg_per_m3=water_density_kg_per_m3,
        gravity_m_per_s2=gravity_m_per_s2,
        frequency_column=frequency_column,
        modes=modes,
    )
    if w1.shape != w3.shape or not np.allclose(w1, w3, rtol=1e-6):
        common_w = np.intersect1d(np.round(w1, 9), np.round(w3, 9))
        if common_w.size == 0:
            raise ValueError("load_motions: the .1 and .3 files share no frequency")
        i1 = np.isin(np.round(w1, 9), common_w)
        i3 = np.isin(np.round(w3, 9), common_w)
        w1, a, b, x = w1[i1], a[i1], b[i1], x[i3]
    origin = x_mid if origin_x_m is None else float(origin_x_m)
    k = wavenumber_rad_per_m(w1, water_depth_m, gravity_m_per_s2)
    return _motions_from_rigid_coefficients(
        w1,
        k,
        a,
        b,
        x,
        hull,
        coeff_reference_x_m=origin,
        wave_phase_origin_x_m=origin,
        source=f"WAMIT files {f1}, {f3} (ULEN = {ulen_m} m)",
        mass_kg=mass_kg,
        centre_of_gravity_m=centre_of_gravity_m,
        pitch_radius_of_gyration_m=pitch_radius_of_gyration_m,
        water_density_kg_per_m3=water_density_kg_per_m3,
        gravity_m_per_s2=gravity_m_per_s2,
    )


# ---------------------------------------------------------------------------------- strip theory
def strip_theory_estimate(
    hull: HullForm,
    *,
    mass_kg: float,
    centre_of_gravity_m: Sequence[float],
    pitch_radius_of_gyration_m: float,
    omega_rad_s: ArrayLike,
    water_density_kg_per_m3: float = 1025.0,
    gravity_m_per_s2: float = 9.81,
    n_sections: int = 400,
) -> RigidBodyMotions:
    """Independent zero-speed strip-theory estimate of heave and pitch in deep-water head seas.

    Relative-motion strip theory: each section of waterline breadth ``b(x)`` has hydrostatic
    stiffness ``c = rho g b``, a frequency-independent flat-plate added mass
    ``a = rho pi b^2 / 8`` and a 2-D radiation damping ``d = rho g^2 Abar^2 / omega^3`` with the
    wave-amplitude ratio ``Abar = 2 sin(k b / 2) exp(-k T)``. The section force is
    ``(c - omega^2 a + i omega d) (zeta*(x) - w(x))`` with the Smith-corrected wave
    ``zeta*(x) = exp(-k T_m) exp(i k (x - x_mid))`` (``T_m`` = sectional area / breadth, the
    mean draught of the section), which is exact Froude-Krylov for box sections in head seas.
    Integrated along the ship with the ``(1, x - x_G)`` weights, plus the ``rho g V z_B - m g z_G``
    pitch restoring term, it gives a 2-DOF system like the BEM one. Valid at low frequency
    (long waves); no 3-D end effects, no forward speed.
    """
    omega = np.asarray(omega_rad_s, dtype=float).ravel()
    if omega.size == 0 or np.any(omega <= 0) or np.any(np.diff(omega) <= 0):
        raise ValueError("strip_theory_estimate: omega_rad_s must be > 0 and strictly increasing")
    rho, g = float(water_density_kg_per_m3), float(gravity_m_per_s2)
    x_mid = 0.5 * (hull.station_x_m[0] + hull.station_x_m[-1])
    x_g = float(centre_of_gravity_m[0])
    x = np.unique(np.concatenate([np.linspace(hull.station_x_m[0], hull.station_x_m[-1], n_sections + 1), hull.station_x_m]))
    b = hull.breadth_at(x)
    t_mean = hull.section_area_coefficient * hull.draft_m
    k = wavenumber_rad_per_m(omega, math.inf, g)
    lever = x - x_g
    wts = np.stack([np.ones_like(x), lever])  # (2, n_x)
    a_sec = rho * np.pi * b**2 / 8.0
    c_sec = rho * g * b
    a_mat = np.zeros((omega.size, 2, 2))
    b_mat = np.zeros((omega.size, 2, 2))
    f = np.zeros((omega.size, 2), dtype=complex)
    for n, (w, kk) in enumerate(zip(omega, k, strict=True)):
        abar = 2.0 * np.sin(kk * b / 2.0) * np.exp(-kk * hull.draft_m)
        d_sec = rho * g**2 * abar**2 / w**3
        a_mat[n] = np.trapezoid(a_sec * wts[:, None, :] * wts[None, :, :], x, axis=-1)
        b_mat[n] = np.trapezoid(d_sec * wts[:, None, :] * wts[None, :, :], x, axis=-1)
        zeta_star = np.exp(-kk * t_mean) * np.exp(1j * kk * (x - x_mid))
        f[n] = np.trapezoid((c_sec - w**2 * a_sec + 1j * w * d_sec) * zeta_star * wts, x, axis=-1)
    m = mass_matrix(mass_kg, pitch_radius_of_gyration_m)
    c = hydrostatic_stiffness_matrix(
        hull, mass_kg=mass_kg, centre_of_gravity_m=centre_of_gravity_m, water_density_kg_per_m3=rho, gravity_m_per_s2=g
    )
    heave, pitch = solve_heave_pitch(omega, a_mat, b_mat, f, m, c)
    return RigidBodyMotions(
        omega_rad_s=omega,
        heave_rao_m_per_m=heave,
        pitch_rao_rad_per_m=pitch,
        added_mass=a_mat,
        radiation_damping=b_mat,
        excitation_force=f,
        reference_x_m=x_g,
        mass_matrix=m,
        hydrostatic_stiffness=c,
        wave_phase_reference_x_m=x_mid,
        wavenumber_rad_per_m=k,
        source="strip theory estimate",
    )
