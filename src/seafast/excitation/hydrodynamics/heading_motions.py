"""The record of the six rigid-body motions at every heading: :class:`SixDofMotions` (docs/headings.md#4-motions-at-any-heading).

Conventions: :mod:`seafast.excitation.hydrodynamics.six_dof` (DOFs surge, sway, heave, roll, pitch bow up, yaw about the
centre of gravity; heading ``beta`` the direction the waves travel; ``exp(+i omega t)``; crest amidships at ``t = 0``).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.interpolate import CubicSpline

from seafast.excitation.hydrodynamics.equations import rigid_body_impedance, solve_rigid_body
from seafast.excitation.hydrodynamics.roll_damping import HarmonicRollResponse, QuadraticRollDamping, RollModel, harmonic_linearisation

__all__ = ["SixDofMotions", "SIX_DOF_NAMES", "SIX_DOF_UNITS"]

SIX_DOF_NAMES: tuple[str, ...] = ("surge", "sway", "heave", "roll", "pitch", "yaw")
"""seafast's names of the six DOFs, in order."""

SIX_DOF_UNITS: tuple[str, ...] = ("m/m", "m/m", "m/m", "rad/m", "rad/m", "rad/m")
"""Units of the six RAOs, per metre of wave amplitude."""


@dataclass(frozen=True, eq=False)
class SixDofMotions:
    """Hydrodynamic coefficients about the CoG, the loaded ship's mass and stiffness, and the six RAOs they give.

    Attributes
    ----------
    omega_rad_s, wavenumber_rad_per_m
        Frequencies [rad/s], strictly increasing, and their wave numbers [rad/m], shape (n_w,).
    headings_deg
        Wave headings [deg] ascending over [0, 360), shape (n_b,) (the computed ones and their mirror images).
    added_mass, radiation_damping
        (n_w, 6, 6) about the CoG, seafast's DOFs and signs [kg, kg m, kg m^2 and the same per second].
    excitation_force
        (n_w, n_b, 6) per metre of wave amplitude [N/m, N m/m].
    mass_matrix, hydrostatic_stiffness
        (6, 6) about the CoG [kg, kg m^2] and [N/m, N, N m/rad].
    roll_damping_ratio
        Additional linear roll damping as a fraction of critical ``2 sqrt((I44 + A44) C44)`` [-], A44 at the roll
        natural frequency.
    reference_x_m, reference_z_m
        The CoG: x from the AP [m], KG above the keel [m] (on the centreline).
    wave_phase_reference_x_m
        Where the wave crest is at ``t = 0`` (amidships, on the centreline) [m].
    source
        Free text.
    """

    omega_rad_s: NDArray[np.float64]
    wavenumber_rad_per_m: NDArray[np.float64]
    headings_deg: NDArray[np.float64]
    added_mass: NDArray[np.float64]
    radiation_damping: NDArray[np.float64]
    excitation_force: NDArray[np.complex128]
    mass_matrix: NDArray[np.float64]
    hydrostatic_stiffness: NDArray[np.float64]
    roll_damping_ratio: float
    reference_x_m: float
    reference_z_m: float
    wave_phase_reference_x_m: float
    source: str = ""

    def __post_init__(self) -> None:
        w = np.asarray(self.omega_rad_s, dtype=float)
        if w.ndim != 1 or w.size < 4 or np.any(np.diff(w) <= 0):
            raise ValueError("SixDofMotions: omega_rad_s must be a strictly increasing 1-D array of at least 4 frequencies")
        b = np.asarray(self.headings_deg, dtype=float)
        if b.ndim != 1 or b.size < 3 or np.any(np.diff(b) <= 0) or b[0] < 0 or b[-1] >= 360:
            raise ValueError("SixDofMotions: headings_deg must be strictly increasing within [0, 360), at least 3 of them")
        n, nb = w.size, b.size
        shapes: dict[str, tuple[Any, tuple[int, ...]]] = {
            "omega_rad_s": (np.float64, (n,)),
            "wavenumber_rad_per_m": (np.float64, (n,)),
            "headings_deg": (np.float64, (nb,)),
            "added_mass": (np.float64, (n, 6, 6)),
            "radiation_damping": (np.float64, (n, 6, 6)),
            "excitation_force": (np.complex128, (n, nb, 6)),
            "mass_matrix": (np.float64, (6, 6)),
            "hydrostatic_stiffness": (np.float64, (6, 6)),
        }
        for name, (dtype, shape) in shapes.items():
            a = np.array(getattr(self, name), dtype=dtype)
            if a.shape != shape:
                raise ValueError(f"SixDofMotions: {name} has shape {a.shape}, expected {shape}")
            a.setflags(write=False)
            object.__setattr__(self, name, a)
        if not 0.0 <= self.roll_damping_ratio < 1.0:
            raise ValueError(f"SixDofMotions: roll_damping_ratio = {self.roll_damping_ratio!r}; allowed [0, 1)")

    # ---------------------------------------------------------------- roll
    @functools.cached_property
    def _roll_added_inertia(self) -> CubicSpline:
        return CubicSpline(self.omega_rad_s, self.added_mass[:, 3, 3])

    def _a44(self, omega: float) -> float:
        w = min(max(omega, self.omega_rad_s[0]), self.omega_rad_s[-1])
        return float(self._roll_added_inertia(w))

    @functools.cached_property
    def roll_natural_frequency_rad_s(self) -> float:
        """Undamped roll natural frequency ``sqrt(C44 / (I44 + A44(omega)))`` [rad/s], A44 at that frequency (fixed point).

        A44 is taken at the nearest end of the frequency grid when the frequency falls outside it.
        """
        i44, c44 = float(self.mass_matrix[3, 3]), float(self.hydrostatic_stiffness[3, 3])
        if c44 <= 0:
            raise ValueError(f"SixDofMotions: roll restoring C44 = {c44:.4g} N m/rad <= 0 (GM <= 0): the ship is unstable in roll")
        w = math.sqrt(c44 / (i44 + self._a44(math.sqrt(c44 / i44))))
        for _ in range(100):
            w_new = math.sqrt(c44 / (i44 + self._a44(w)))
            if abs(w_new - w) <= 1e-13 * w_new:
                break
            w = w_new
        return w_new

    @property
    def roll_natural_period_s(self) -> float:
        """``2 pi / roll_natural_frequency_rad_s`` [s]."""
        return 2.0 * math.pi / self.roll_natural_frequency_rad_s

    @functools.cached_property
    def additional_roll_damping_Nms_per_rad(self) -> float:
        """``B44_add = roll_damping_ratio * 2 sqrt((I44 + A44(omega_n)) C44)`` [N m s/rad], constant over frequency."""
        if self.roll_damping_ratio == 0.0:
            return 0.0
        i44, c44 = float(self.mass_matrix[3, 3]), float(self.hydrostatic_stiffness[3, 3])
        return self.roll_damping_ratio * 2.0 * math.sqrt((i44 + self._a44(self.roll_natural_frequency_rad_s)) * c44)

    def _damping(self, b: NDArray[np.float64]) -> NDArray[np.float64]:
        out = np.array(b, dtype=float)
        out[..., 3, 3] += self.additional_roll_damping_Nms_per_rad
        return out

    # ---------------------------------------------------------------- RAOs
    @functools.cached_property
    def raos(self) -> NDArray[np.complex128]:
        """RAOs (n_w, n_b, 6) on the computed frequencies and headings [m/m for translations, rad/m for rotations]."""
        n, nb = self.omega_rad_s.size, self.headings_deg.size
        b = self._damping(self.radiation_damping)
        out = np.empty((n, nb, 6), dtype=complex)
        for j in range(nb):
            out[:, j, :] = solve_rigid_body(
                self.omega_rad_s, self.added_mass, b, self.excitation_force[:, j, :], self.mass_matrix, self.hydrostatic_stiffness
            )
        out.setflags(write=False)
        return out

    @functools.cached_property
    def _splines(self) -> tuple[CubicSpline, CubicSpline, CubicSpline]:
        """Cubic splines over frequency of A, B and of the excitation's real and imaginary parts (over headings too: periodic)."""
        heads = np.append(self.headings_deg, 360.0)
        f = np.concatenate([self.excitation_force, self.excitation_force[:, :1]], axis=1)
        f_parts = np.stack([f.real, f.imag], axis=-1)  # (n_w, n_b + 1, 6, 2)
        by_heading = CubicSpline(heads, f_parts, axis=1, bc_type="periodic")
        return CubicSpline(self.omega_rad_s, self.added_mass), CubicSpline(self.omega_rad_s, self.radiation_damping), by_heading

    def _check_omega(self, w: NDArray[np.float64]) -> None:
        lo, hi = self.omega_rad_s[0], self.omega_rad_s[-1]
        bad = w[(w < lo * (1 - 1e-12)) | (w > hi * (1 + 1e-12)) | ~np.isfinite(w)]
        if bad.size:
            raise ValueError(
                f"SixDofMotions: omega = {float(bad[0])!r} rad/s is outside the computed range [{lo:.6g}, {hi:.6g}] rad/s "
                "(waves from 19 m to 1540 m long on the default grid)"
            )

    def excitation_at(self, omega: ArrayLike, heading_deg: float) -> NDArray[np.complex128]:
        """Excitation (..., 6) at ``omega`` [rad/s] and ``heading_deg`` [deg]: periodic cubic spline over headings, cubic over frequency."""
        w = np.atleast_1d(np.asarray(omega, dtype=float))
        self._check_omega(w)
        by_heading = self._splines[2](float(heading_deg) % 360.0)  # (n_w, 6, 2)
        f = CubicSpline(self.omega_rad_s, by_heading)(np.clip(w, self.omega_rad_s[0], self.omega_rad_s[-1]))
        out = f[..., 0] + 1j * f[..., 1]
        return out[0] if np.ndim(omega) == 0 else out

    def rao_at(self, omega: ArrayLike, heading_deg: float, additional_roll_damping_Nms_per_rad: float = 0.0) -> NDArray[np.complex128]:
        """The six RAOs at ``omega`` [rad/s] (scalar: shape (6,); 1-D: (n, 6)) and ``heading_deg`` [deg].

        A, B and the excitation are interpolated by cubic splines (the excitation periodic over headings) and the 6x6
        equation solved at the frequency itself, so a sharp roll resonance between grid frequencies is resolved.
        ``additional_roll_damping_Nms_per_rad`` (>= 0; e.g. a sea state's stochastic equivalent of the quadratic roll
        damping) is added to the roll damping on top of :attr:`additional_roll_damping_Nms_per_rad`.

        Raises
        ------
        ValueError
            ``omega`` outside the computed range (the message names it and the range).
        """
        w = np.atleast_1d(np.asarray(omega, dtype=float))
        f = np.atleast_2d(self.excitation_at(w, heading_deg))
        spl_a, spl_b, _ = self._splines
        wc = np.clip(w, self.omega_rad_s[0], self.omega_rad_s[-1])
        b = self._damping(spl_b(wc))
        if additional_roll_damping_Nms_per_rad != 0.0:
            if not additional_roll_damping_Nms_per_rad > 0.0:
                raise ValueError(f"additional_roll_damping_Nms_per_rad = {additional_roll_damping_Nms_per_rad!r}; allowed: >= 0")
            b[..., 3, 3] += additional_roll_damping_Nms_per_rad
        x = solve_rigid_body(w, spl_a(wc), b, f, self.mass_matrix, self.hydrostatic_stiffness)
        return x[0] if np.ndim(omega) == 0 else x

    def roll_model(self, omega: ArrayLike, heading_deg: float) -> RollModel:
        """The coupled six-DOF system reduced exactly to roll (:meth:`RollModel.from_coupled`) at ``omega`` [rad/s], 1-D.

        Its impedance does not depend on the heading (only the excitation does); the linear damping is the potential
        damping plus :attr:`additional_roll_damping_Nms_per_rad`.
        """
        w = np.atleast_1d(np.asarray(omega, dtype=float))
        f = np.atleast_2d(self.excitation_at(w, heading_deg))
        spl_a, spl_b, _ = self._splines
        wc = np.clip(w, self.omega_rad_s[0], self.omega_rad_s[-1])
        impedance = rigid_body_impedance(w, spl_a(wc), self._damping(spl_b(wc)), self.mass_matrix, self.hydrostatic_stiffness)
        return RollModel.from_coupled(w, impedance, f)

    def rao_in_regular_wave(
        self, omega_rad_s: float, heading_deg: float, amplitude_m: float, quadratic: QuadraticRollDamping | None
    ) -> tuple[NDArray[np.complex128], HarmonicRollResponse | None]:
        """The six RAOs (6,) in a regular wave of ``amplitude_m`` [m], with a quadratic roll damping linearised.

        The quadratic damping ``B44_2 |phi'| phi'`` is replaced by its harmonic equivalent
        ``B_eq = 8 / (3 pi) omega phi_a B44_2``, found with the roll amplitude it gives on the coupled six-DOF system
        (:func:`~seafast.excitation.hydrodynamics.roll_damping.harmonic_linearisation` on its exact roll reduction),
        and added to the roll damping. None (or a zero coefficient): :meth:`rao_at`, and no linearisation.
        """
        if quadratic is None or quadratic.coefficient_Nms2_per_rad2 == 0.0 or amplitude_m == 0.0:
            return np.asarray(self.rao_at(omega_rad_s, heading_deg), dtype=np.complex128), None
        w = np.array([float(omega_rad_s)])
        f = np.atleast_2d(self.excitation_at(w, heading_deg))
        spl_a, spl_b, _ = self._splines
        wc = np.clip(w, self.omega_rad_s[0], self.omega_rad_s[-1])
        impedance = rigid_body_impedance(w, spl_a(wc), self._damping(spl_b(wc)), self.mass_matrix, self.hydrostatic_stiffness)
        response = harmonic_linearisation(RollModel.from_coupled(w, impedance, f), quadratic, float(amplitude_m))
        impedance[:, 3, 3] += 1j * w * response.equivalent_damping_Nms_per_rad
        x = np.linalg.solve(impedance, f[..., None])[..., 0]
        return np.asarray(x[0], dtype=np.complex128), response

    # ---------------------------------------------------------------- export
    def attributes(self) -> dict[str, float | str]:
        """Roll natural period [s], the additional roll damping [N m s/rad] and its ratio [-], the source: results.nc's attributes."""
        return {
            "roll_natural_period_s": self.roll_natural_period_s,
            "additional_roll_damping_Nms_per_rad": self.additional_roll_damping_Nms_per_rad,
            "roll_damping_ratio": float(self.roll_damping_ratio),
            "six_dof_source": self.source,
        }
