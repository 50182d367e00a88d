"""The result record: heave, pitch (and surge) RAOs of the vessel in head seas.

Conventions: :mod:`seafast.excitation.hydrodynamics` (time ``exp(+i omega t)``, pitch bow up,
phases relative to the wave crest at midship).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, TypeAlias

import numpy as np
import xarray as xr
from numpy.typing import ArrayLike, NDArray

__all__ = ["RigidBodyMotions", "ComplexValue"]

# an RAO at one frequency (a scalar omega) or at several (an array)
ComplexValue: TypeAlias = complex | NDArray[np.complexfloating[Any, Any]]


@dataclass(frozen=True, eq=False)
class RigidBodyMotions:
    """Heave and pitch RAOs of the vessel in regular head seas (seafast conventions, see the package).

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
