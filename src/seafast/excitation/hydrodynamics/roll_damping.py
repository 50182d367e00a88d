"""Quadratic (viscous) roll damping and its equivalent linearisation (docs/roll_damping.md).

Potential flow gives only a small part of a ship's roll damping; the rest (bilge keels, eddy
making, skin friction) is close to quadratic in the roll velocity. The roll equation per
metre of wave amplitude, time dependence ``Re(X exp(+i omega t))``, roll ``phi`` [rad]:

    (I44 + A44(omega)) phi'' + (B44(omega) + B_lin) phi' + B44_2 |phi'| phi' + C44 phi = F44(omega) zeta

(the damping moment on the hull is ``-B44_2 |phi'| phi'``). This module replaces the quadratic
term by an equivalent linear damping ``B_eq`` with the same energy per cycle (regular waves) or
the same mean-square error (Gaussian sea states) and solves for the ``B_eq`` consistent with the
response it produces:

* harmonic, a regular wave of amplitude ``zeta_a`` at each omega (Fourier coefficient of
  ``|sin| sin``): ``B_eq(omega) = 8 / (3 pi) omega phi_a B44_2``;
* stochastic, a sea state of spectrum ``S(omega)`` (Gaussian roll velocity,
  ``E[|v|^3] / E[v^2] = sqrt(8 / pi) sigma_v``): one ``B_eq = sqrt(8 / pi) sigma_phidot B44_2``,
  ``sigma_phidot^2 = int omega^2 |phi(omega)|^2 S d omega``.

The model is a :class:`RollModel`: per frequency the roll impedance ``Z(omega)`` and excitation
``F(omega)`` with ``phi = F / (Z + i omega B_eq)``. A single-DOF roll equation gives
``Z = C44 - omega^2 (I44 + A44) + i omega (B44 + B_lin)`` (:meth:`RollModel.single_dof`); a coupled
6-DOF system reduces exactly to the same form for added roll damping (Sherman-Morrison:
``Z = 1 / (Z_6^{-1})_44``, ``F = phi_0 Z``; :meth:`RollModel.from_coupled`).

Why the fixed point has one root (and is found by bracketing): ``g(B) = k |phi(B)|`` (or
``c sigma_phidot(B)``) is non-increasing in ``B >= 0`` because ``|Z + i omega B|^2 = Re(Z)^2 +
(Im Z + omega B)^2`` grows with ``B`` when ``Im Z >= 0`` (a passive hull: it absorbs energy).
So ``h(B) = B - g(B)`` is strictly increasing, ``h(0) <= 0``, and ``h(B_up) >= 0`` at
``B_up = min(g(0), sqrt(k |F| zeta_a / omega))`` (since ``|phi| <= |F| zeta_a / (omega B)``); the root in
``[0, B_up]`` is unique and is found by ``scipy.optimize.brentq`` on that bracket (per frequency
in regular waves, once for a sea state).

Decay-test coefficients (Froude's decrement law; ITTC Recommended Procedure 7.5-02-07-04.5,
"Numerical estimation of roll damping"; Himeno 1981, "Prediction of ship roll damping: state of
the art"): the decrement per half cycle ``phi_{n} - phi_{n+1} = a phi_m + b phi_m^2`` of the
successive peak magnitudes ``phi_n`` at the mean ``phi_m = (phi_n + phi_{n+1}) / 2`` [rad] gives,
by the energy balance of a half cycle at the roll frequency ``omega``,
``B_lin = 2 a (I44 + A44) omega / pi`` and ``B44_2 = 3 b (I44 + A44) / 4``; in the normalised form
``phi'' + 2 alpha phi' + beta |phi'| phi' + omega^2 phi = 0``: ``alpha = a omega / pi``,
``beta = 3 b / 4 = B44_2 / (I44 + A44)`` [1/rad].

Integrating (how the roll motions call it): build a :class:`RollModel` at the motion grid, a
:class:`QuadraticRollDamping`, then :func:`harmonic_linearisation` (regular waves: one ``B_eq``
per frequency) or :func:`stochastic_linearisation` (a sea state: one ``B_eq``); add the result's
``equivalent_damping_Nms_per_rad`` to the roll diagonal of the damping (for a single DOF,
``total_damping_Nms_per_rad`` is ``B44 + B_lin + B_eq``); ``roll_rao_rad_per_m`` is the converged
roll RAO.

Size: over 400 lines because the damping's description, its decay-test conversions, the roll
model and the two linearisations with their typed outcomes are one documented model (mostly
docstrings: the integrator wires it from them).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from enum import StrEnum

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import brentq

__all__ = [
    "HARMONIC_FACTOR",
    "STOCHASTIC_FACTOR",
    "Linearisation",
    "QuadraticRollDamping",
    "FroudeDecrement",
    "fit_froude_decrement",
    "RollModel",
    "roll_natural_period_s",
    "HarmonicRollResponse",
    "StochasticRollResponse",
    "harmonic_linearisation",
    "stochastic_linearisation",
]

HARMONIC_FACTOR = 8.0 / (3.0 * math.pi)
"""``B_eq = HARMONIC_FACTOR omega phi_a B44_2`` in a regular wave (energy per cycle) [-]."""

STOCHASTIC_FACTOR = math.sqrt(8.0 / math.pi)
"""``B_eq = STOCHASTIC_FACTOR sigma_phidot B44_2`` in a Gaussian sea state [-]."""


class Linearisation(StrEnum):
    """How the quadratic damping was replaced by a linear one."""

    HARMONIC = "harmonic"
    """Regular waves: equal energy per cycle of a harmonic roll (8 / (3 pi) omega phi_a)."""
    STOCHASTIC = "stochastic"
    """A Gaussian sea state: least mean-square error (sqrt(8 / pi) sigma_phidot)."""


def _check_finite(name: str, value: float, minimum: float, strict: bool = False) -> float:
    allowed = f"a finite number {'>' if strict else '>='} {minimum:g}"
    try:
        v = math.nan if isinstance(value, bool) else float(value)
    except (TypeError, ValueError):
        v = math.nan
    if not math.isfinite(v) or v < minimum or (strict and v == minimum):
        raise ValueError(f"{name} = {value!r} is not allowed: {allowed}")
    return v


@dataclass(frozen=True)
class QuadraticRollDamping:
    """The quadratic roll damping coefficient: damping moment ``-B44_2 |phi'| phi'`` [N m].

    Parameters
    ----------
    coefficient_Nms2_per_rad2
        ``B44_2 >= 0`` [N m s^2/rad^2] (0: no quadratic damping).
    """

    coefficient_Nms2_per_rad2: float

    def __post_init__(self) -> None:
        _check_finite("coefficient_Nms2_per_rad2", self.coefficient_Nms2_per_rad2, 0.0)
        object.__setattr__(self, "coefficient_Nms2_per_rad2", float(self.coefficient_Nms2_per_rad2))

    @classmethod
    def from_nondimensional(cls, beta_per_rad: float, inertia_kg_m2: float) -> QuadraticRollDamping:
        """From ``beta = B44_2 / (I44 + A44)`` [1/rad] of ``phi'' + ... + beta |phi'| phi' + ...`` (ITTC 7.5-02-07-04.5).

        ``inertia_kg_m2`` is the roll inertia with added inertia ``I44 + A44`` [kg m^2].
        """
        beta = _check_finite("beta_per_rad", beta_per_rad, 0.0)
        return cls(beta * _check_finite("inertia_kg_m2", inertia_kg_m2, 0.0, strict=True))

    def nondimensional_per_rad(self, inertia_kg_m2: float) -> float:
        """``beta = B44_2 / (I44 + A44)`` [1/rad]."""
        return self.coefficient_Nms2_per_rad2 / _check_finite("inertia_kg_m2", inertia_kg_m2, 0.0, strict=True)

    def harmonic_equivalent_Nms_per_rad(self, omega_rad_s: ArrayLike, amplitude_rad: ArrayLike) -> NDArray[np.float64]:
        """``8 / (3 pi) omega phi_a B44_2`` [N m s/rad]: the linear damping of equal energy per cycle."""
        return HARMONIC_FACTOR * np.asarray(omega_rad_s, float) * np.abs(np.asarray(amplitude_rad, float)) * self.coefficient_Nms2_per_rad2

    def stochastic_equivalent_Nms_per_rad(self, velocity_std_rad_s: float) -> float:
        """``sqrt(8 / pi) sigma_phidot B44_2`` [N m s/rad]: the least-squares linear damping of a Gaussian roll."""
        return STOCHASTIC_FACTOR * abs(float(velocity_std_rad_s)) * self.coefficient_Nms2_per_rad2


@dataclass(frozen=True)
class FroudeDecrement:
    """Froude's decrement law of a roll decay: ``phi_n - phi_{n+1} = a phi_m + b phi_m^2`` per half cycle.

    ``phi_n`` are the successive peak magnitudes (alternately to port and starboard) and
    ``phi_m = (phi_n + phi_{n+1}) / 2`` [rad]. For angles in degrees, ``b_per_rad = b_per_deg * 180 / pi``.

    Parameters
    ----------
    a
        Linear decrement coefficient [-], >= 0.
    b_per_rad
        Quadratic decrement coefficient [1/rad], >= 0.
    """

    a: float
    b_per_rad: float

    def __post_init__(self) -> None:
        object.__setattr__(self, "a", _check_finite("a", self.a, 0.0))
        object.__setattr__(self, "b_per_rad", _check_finite("b_per_rad", self.b_per_rad, 0.0))

    def linear_damping_Nms_per_rad(self, inertia_kg_m2: float, roll_frequency_rad_s: float) -> float:
        """``B_lin = 2 a (I44 + A44) omega / pi`` [N m s/rad] (``alpha = a omega / pi``)."""
        inertia = _check_finite("inertia_kg_m2", inertia_kg_m2, 0.0, strict=True)
        omega = _check_finite("roll_frequency_rad_s", roll_frequency_rad_s, 0.0, strict=True)
        return 2.0 * self.a * inertia * omega / math.pi

    def quadratic_damping(self, inertia_kg_m2: float) -> QuadraticRollDamping:
        """``B44_2 = 3 b (I44 + A44) / 4`` (``beta = 3 b / 4``)."""
        return QuadraticRollDamping.from_nondimensional(0.75 * self.b_per_rad, inertia_kg_m2)

    @classmethod
    def from_damping(
        cls, linear_Nms_per_rad: float, quadratic: QuadraticRollDamping, inertia_kg_m2: float, roll_frequency_rad_s: float
    ) -> FroudeDecrement:
        """The decrement coefficients a decay test of this damping shows (the inverse of the two conversions)."""
        inertia = _check_finite("inertia_kg_m2", inertia_kg_m2, 0.0, strict=True)
        omega = _check_finite("roll_frequency_rad_s", roll_frequency_rad_s, 0.0, strict=True)
        linear = _check_finite("linear_Nms_per_rad", linear_Nms_per_rad, 0.0)
        return cls(math.pi * linear / (2.0 * inertia * omega), 4.0 * quadratic.coefficient_Nms2_per_rad2 / (3.0 * inertia))


def fit_froude_decrement(peak_magnitudes_rad: ArrayLike) -> FroudeDecrement:
    """Least-squares fit of Froude's decrement law to the successive peak magnitudes of a decay [rad].

    Parameters
    ----------
    peak_magnitudes_rad
        ``|phi|`` at the successive extremes of a free decay, alternately to each side, in time
        order (at least 3; decreasing).

    Returns
    -------
    FroudeDecrement
        ``a, b`` minimising ``sum (Delta phi - a phi_m - b phi_m^2)^2``; a negative fitted value
        (noise on a nearly linear or nearly quadratic decay, or another damping law) is refused
        with its value (``ValueError``).
    """
    peaks = np.abs(np.asarray(peak_magnitudes_rad, dtype=float))
    if peaks.ndim != 1 or peaks.size < 3 or not np.all(np.isfinite(peaks)):
        raise ValueError(f"peak_magnitudes_rad needs at least 3 finite peaks in a 1-D array; got shape {peaks.shape}")
    drop, mean = peaks[:-1] - peaks[1:], 0.5 * (peaks[:-1] + peaks[1:])
    (a, b), *_ = np.linalg.lstsq(np.column_stack([mean, mean**2]), drop, rcond=None)
    if a < 0 or b < 0:
        raise ValueError(
            f"peak_magnitudes_rad: the fitted decrement law has a = {a:.6g}, b_per_rad = {b:.6g}; allowed: both >= 0 (the decay "
            "is not linear-plus-quadratic: fit fewer or more peaks, or fit a single term)"
        )
    return FroudeDecrement(float(a), float(b))


def roll_natural_period_s(inertia_kg_m2: float, stiffness_Nm_per_rad: float) -> float:
    """Undamped roll natural period ``2 pi sqrt((I44 + A44) / C44)`` [s]; damping does not enter it."""
    inertia = _check_finite("inertia_kg_m2", inertia_kg_m2, 0.0, strict=True)
    return 2.0 * math.pi * math.sqrt(inertia / _check_finite("stiffness_Nm_per_rad", stiffness_Nm_per_rad, 0.0, strict=True))


def _per_omega(name: str, value: ArrayLike, n: int, dtype: type = float) -> NDArray:
    a: NDArray = np.broadcast_to(np.asarray(value, dtype=dtype), (n,)).copy() if np.ndim(value) == 0 else np.asarray(value, dtype=dtype)
    if a.shape != (n,):
        raise ValueError(f"{name} has shape {a.shape}; allowed: a scalar or one value per frequency, shape ({n},)")
    if not np.all(np.isfinite(a)):
        raise ValueError(f"{name} has non-finite values; allowed: finite numbers")
    return a


@dataclass(frozen=True)
class RollModel:
    """A linear roll model per frequency: ``phi = F / (Z + i omega B_added)`` per metre of wave amplitude.

    Attributes
    ----------
    omega_rad_s
        (n,) frequencies [rad/s], > 0.
    impedance_Nm_per_rad
        (n,) complex roll impedance ``Z(omega)`` [N m/rad], ``Im Z >= 0`` (a passive hull).
    excitation_Nm_per_m
        (n,) complex roll excitation ``F44(omega)`` per metre of wave amplitude [N m/m].
    """

    omega_rad_s: NDArray[np.float64]
    impedance_Nm_per_rad: NDArray[np.complex128]
    excitation_Nm_per_m: NDArray[np.complex128]

    def __post_init__(self) -> None:
        w = np.atleast_1d(np.asarray(self.omega_rad_s, dtype=float))
        if w.ndim != 1 or w.size == 0 or not np.all(np.isfinite(w) & (w > 0)):
            raise ValueError(f"omega_rad_s must be a 1-D array of finite frequencies > 0; got {self.omega_rad_s!r}")
        z = _per_omega("impedance_Nm_per_rad", self.impedance_Nm_per_rad, w.size, complex)
        if np.any(z.imag < -1e-9 * np.abs(z)):  # round-off of a reduced coupled system allowed
            bad = int(np.argmin(z.imag))
            raise ValueError(
                f"impedance_Nm_per_rad has Im Z = {z.imag[bad]:.6g} < 0 at omega = {w[bad]:.6g} rad/s (negative damping); "
                "allowed: Im Z >= 0"
            )
        object.__setattr__(self, "omega_rad_s", w)
        object.__setattr__(self, "impedance_Nm_per_rad", z)
        object.__setattr__(self, "excitation_Nm_per_m", _per_omega("excitation_Nm_per_m", self.excitation_Nm_per_m, w.size, complex))

    @classmethod
    def single_dof(
        cls,
        omega_rad_s: ArrayLike,
        inertia_kg_m2: ArrayLike,
        damping_Nms_per_rad: ArrayLike,
        stiffness_Nm_per_rad: float,
        excitation_Nm_per_m: ArrayLike,
        additional_linear_damping_Nms_per_rad: ArrayLike = 0.0,
    ) -> RollModel:
        """The 1-DOF roll equation ``Z = C44 - omega^2 (I44 + A44) + i omega (B44 + B_lin)``.

        Parameters
        ----------
        omega_rad_s
            (n,) frequencies [rad/s].
        inertia_kg_m2
            ``I44 + A44(omega)`` [kg m^2], > 0 (scalar or (n,)).
        damping_Nms_per_rad
            Potential-flow ``B44(omega)`` [N m s/rad], >= 0 (scalar or (n,)).
        stiffness_Nm_per_rad
            ``C44 = rho g V GM`` [N m/rad], > 0.
        excitation_Nm_per_m
            ``F44(omega)`` per metre of wave amplitude [N m/m] (scalar or (n,), complex).
        additional_linear_damping_Nms_per_rad
            ``B_lin`` added to the potential damping [N m s/rad], >= 0 (scalar or (n,)).
        """
        w = np.atleast_1d(np.asarray(omega_rad_s, dtype=float))
        inertia = _per_omega("inertia_kg_m2", inertia_kg_m2, w.size)
        damping = _per_omega("damping_Nms_per_rad", damping_Nms_per_rad, w.size) + _per_omega(
            "additional_linear_damping_Nms_per_rad", additional_linear_damping_Nms_per_rad, w.size
        )
        for name, values in (("inertia_kg_m2", inertia), ("damping_Nms_per_rad + additional_linear_damping_Nms_per_rad", damping)):
            if np.any(values < 0) or (name == "inertia_kg_m2" and np.any(values == 0)):
                raise ValueError(f"{name} has the value {values.min():.6g}; allowed: {'> 0' if name == 'inertia_kg_m2' else '>= 0'}")
        stiffness = _check_finite("stiffness_Nm_per_rad", stiffness_Nm_per_rad, 0.0, strict=True)
        impedance = (stiffness - w**2 * inertia + 1j * w * damping).astype(np.complex128)
        return cls(w, impedance, np.asarray(excitation_Nm_per_m).astype(np.complex128))

    @classmethod
    def from_coupled(cls, omega_rad_s: ArrayLike, impedance: ArrayLike, excitation: ArrayLike, roll_index: int = 3) -> RollModel:
        """The exact roll model of a coupled linear system ``Z_6(omega) x = F_6(omega)`` for added roll damping.

        Adding ``i omega B`` to ``Z_6[roll, roll]`` gives ``phi = phi_0 / (1 + i omega B G)``,
        ``G = (Z_6^{-1})[roll, roll]`` (Sherman-Morrison), the 1-DOF model ``Z = 1 / G``, ``F = phi_0 Z``.

        Parameters
        ----------
        omega_rad_s
            (n,) frequencies [rad/s].
        impedance
            (n, m, m) ``-omega^2 (M + A) + i omega B + C`` in SI units of each DOF.
        excitation
            (n, m) excitation per metre of wave amplitude.
        roll_index
            Index of roll among the m DOFs (3 in surge, sway, heave, roll, pitch, yaw).
        """
        z6, f6 = np.asarray(impedance, dtype=complex), np.asarray(excitation, dtype=complex)
        w = np.atleast_1d(np.asarray(omega_rad_s, dtype=float))
        if z6.ndim != 3 or z6.shape[0] != w.size or z6.shape[1] != z6.shape[2] or f6.shape != z6.shape[:2]:
            raise ValueError(f"impedance {z6.shape} and excitation {f6.shape} must be (n, m, m) and (n, m) with n = {w.size}")
        x = np.linalg.solve(z6, f6[..., None])[..., 0]
        unit = np.zeros_like(f6)
        unit[:, roll_index] = 1.0
        receptance = np.linalg.solve(z6, unit[..., None])[:, roll_index, 0]
        z = (1.0 / receptance).astype(np.complex128)
        return cls(w, z, (x[:, roll_index] * z).astype(np.complex128))

    def roll_rao_rad_per_m(self, added_damping_Nms_per_rad: ArrayLike = 0.0) -> NDArray[np.complex128]:
        """``phi / zeta_a = F / (Z + i omega B_added)`` [rad/m] with added linear damping (scalar or (n,))."""
        return self.excitation_Nm_per_m / (self.impedance_Nm_per_rad + 1j * self.omega_rad_s * np.asarray(added_damping_Nms_per_rad))


@dataclass(frozen=True)
class HarmonicRollResponse:
    """The roll in regular waves, one per frequency, with the harmonic equivalent damping.

    Attributes
    ----------
    linearisation
        :attr:`Linearisation.HARMONIC`.
    omega_rad_s
        (n,) frequencies [rad/s].
    wave_amplitude_m
        (n,) regular-wave amplitude at each frequency [m].
    equivalent_damping_Nms_per_rad
        (n,) converged ``B_eq = 8 / (3 pi) omega phi_a B44_2`` [N m s/rad].
    total_damping_Nms_per_rad
        (n,) ``Im Z / omega + B_eq``: the model's linear damping (for a single DOF ``B44 + B_lin``) plus ``B_eq`` [N m s/rad].
    roll_rao_rad_per_m
        (n,) complex roll per metre of wave amplitude at the converged damping [rad/m].
    roll_amplitude_rad
        (n,) ``|roll_rao| zeta_a`` [rad].
    iterations
        (n,) root-finder iterations per frequency (0 where the answer is the linear one).
    converged
        (n,) whether each frequency converged.
    residual_Nms_per_rad
        (n,) ``|B_eq - 8 / (3 pi) omega phi_a(B_eq) B44_2|`` at the returned ``B_eq`` [N m s/rad].
    """

    omega_rad_s: NDArray[np.float64]
    wave_amplitude_m: NDArray[np.float64]
    equivalent_damping_Nms_per_rad: NDArray[np.float64]
    total_damping_Nms_per_rad: NDArray[np.float64]
    roll_rao_rad_per_m: NDArray[np.complex128]
    roll_amplitude_rad: NDArray[np.float64]
    iterations: NDArray[np.int64]
    converged: NDArray[np.bool_]
    residual_Nms_per_rad: NDArray[np.float64]
    linearisation: Linearisation = field(default=Linearisation.HARMONIC)


@dataclass(frozen=True)
class StochasticRollResponse:
    """The roll in a sea state, with the one stochastic equivalent damping.

    Attributes
    ----------
    linearisation
        :attr:`Linearisation.STOCHASTIC`.
    omega_rad_s
        (n,) frequencies [rad/s].
    equivalent_damping_Nms_per_rad
        Converged ``B_eq = sqrt(8 / pi) sigma_phidot B44_2`` [N m s/rad].
    total_damping_Nms_per_rad
        (n,) ``Im Z / omega + B_eq`` [N m s/rad].
    roll_rao_rad_per_m
        (n,) complex roll per metre of wave amplitude at the converged damping [rad/m].
    roll_spectrum_rad2_s
        (n,) ``|roll_rao|^2 S`` [rad^2 s/rad].
    roll_std_rad
        ``sigma_phi = sqrt(m0)`` [rad].
    roll_velocity_std_rad_s
        ``sigma_phidot = sqrt(m2)`` [rad/s].
    iterations
        Root-finder iterations (0 where the answer is the linear one).
    converged
        Whether the root finder converged.
    residual_Nms_per_rad
        ``|B_eq - sqrt(8 / pi) sigma_phidot(B_eq) B44_2|`` [N m s/rad].
    """

    omega_rad_s: NDArray[np.float64]
    equivalent_damping_Nms_per_rad: float
    total_damping_Nms_per_rad: NDArray[np.float64]
    roll_rao_rad_per_m: NDArray[np.complex128]
    roll_spectrum_rad2_s: NDArray[np.float64]
    roll_std_rad: float
    roll_velocity_std_rad_s: float
    iterations: int
    converged: bool
    residual_Nms_per_rad: float
    linearisation: Linearisation = field(default=Linearisation.STOCHASTIC)

    @property
    def zero_crossing_period_s(self) -> float:
        """Mean zero-up-crossing period of the roll ``2 pi sigma_phi / sigma_phidot`` [s] (inf for no roll)."""
        return 2.0 * math.pi * self.roll_std_rad / self.roll_velocity_std_rad_s if self.roll_velocity_std_rad_s > 0 else math.inf

    def roll_mpm_rad(self, duration_s: float) -> float:
        """Rayleigh most probable maximum ``sigma_phi sqrt(2 ln(D / Tz))`` over ``duration_s`` [rad] (0 below one cycle)."""
        cycles = _check_finite("duration_s", duration_s, 0.0, strict=True) / self.zero_crossing_period_s
        return self.roll_std_rad * math.sqrt(2.0 * math.log(max(cycles, 1.0)))


def _upper_bound(g0: NDArray[np.float64], slope: NDArray[np.float64], force: NDArray[np.float64]) -> NDArray[np.float64]:
    """``min(g(0), sqrt(slope force))``: ``h(B) = B - g(B) >= 0`` there (module docstring)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.fmin(np.where(np.isfinite(g0), g0, np.inf), np.sqrt(slope * force))


def _fixed_point(
    h: Callable[..., float], upper: float, tolerance: float, max_iterations: int, args: tuple[int, ...] = ()
) -> tuple[float, int, bool]:
    """Root of ``h(B, *args) = B - g(B)`` in ``[0, upper]`` by ``brentq`` (``h(0) <= 0 <= h(upper)``): ``B``, iterations, converged."""
    root, info = brentq(
        h, 0.0, upper, args=args, xtol=tolerance * upper * 1e-3, rtol=max(tolerance, 4.0 * float(np.finfo(float).eps)),
        maxiter=max_iterations, full_output=True, disp=False,
    )  # fmt: skip
    return float(root), int(info.iterations), bool(info.converged)


def harmonic_linearisation(
    model: RollModel, damping: QuadraticRollDamping, wave_amplitude_m: ArrayLike, *, tolerance: float = 1e-12, max_iterations: int = 100
) -> HarmonicRollResponse:
    """Roll in regular waves with the quadratic damping linearised harmonically, ``B_eq`` per frequency.

    Solves ``B = 8 / (3 pi) omega B44_2 zeta_a |F| / |Z + i omega B|`` at each frequency (a unique
    root in ``[0, B_up]``; module docstring) by ``scipy.optimize.brentq`` on that bracket.
    ``B44_2 = 0`` or ``zeta_a = 0`` gives the linear answer exactly (0 iterations).

    Parameters
    ----------
    model
        The linear roll model per frequency.
    damping
        The quadratic damping ``B44_2``.
    wave_amplitude_m
        Regular-wave amplitude [m], >= 0: a scalar (the same at every frequency) or (n,).
    tolerance
        Relative tolerance on ``B_eq`` (of the bracket ``B_up``) [-].
    max_iterations
        Iteration limit of the root finder per frequency.

    Returns
    -------
    HarmonicRollResponse
        Per frequency: ``B_eq``, the total damping, the converged RAO and amplitude, iterations,
        whether it converged and the residual.
    """
    w = model.omega_rad_s
    zeta = _per_omega("wave_amplitude_m", wave_amplitude_m, w.size)
    if np.any(zeta < 0):
        raise ValueError(f"wave_amplitude_m has the value {zeta.min():.6g}; allowed: >= 0")
    slope = HARMONIC_FACTOR * w * damping.coefficient_Nms2_per_rad2  # B_eq per rad of amplitude
    force = np.abs(model.excitation_Nm_per_m) * zeta / w  # |phi| <= force / B

    def g(b: float, j: int) -> float:
        return float(slope[j] * abs(model.excitation_Nm_per_m[j]) * zeta[j] / abs(model.impedance_Nm_per_rad[j] + 1j * w[j] * b))

    def h(b: float, j: int) -> float:
        return b - g(b, j)

    with np.errstate(divide="ignore", invalid="ignore"):
        g0 = slope * np.abs(model.excitation_Nm_per_m) * zeta / np.abs(model.impedance_Nm_per_rad)
    upper = _upper_bound(g0, slope, force)
    b_eq, iterations, converged = np.zeros(w.size), np.zeros(w.size, dtype=np.int64), np.ones(w.size, dtype=bool)
    for j in np.flatnonzero(upper > 0):
        if not np.isfinite(g0[j]):  # Z = 0, no damping at resonance: g(B) = B_up^2 / B, the root is B_up itself
            b_eq[j] = upper[j]
        else:
            b_eq[j], iterations[j], converged[j] = _fixed_point(h, float(upper[j]), tolerance, max_iterations, (int(j),))
    rao = model.roll_rao_rad_per_m(b_eq)
    residual = np.array([abs(b_eq[j] - g(b_eq[j], j)) if upper[j] > 0 else 0.0 for j in range(w.size)])
    return HarmonicRollResponse(
        omega_rad_s=w,
        wave_amplitude_m=zeta,
        equivalent_damping_Nms_per_rad=b_eq,
        total_damping_Nms_per_rad=model.impedance_Nm_per_rad.imag / w + b_eq,
        roll_rao_rad_per_m=rao,
        roll_amplitude_rad=np.abs(rao) * zeta,
        iterations=iterations,
        converged=converged,
        residual_Nms_per_rad=residual,
    )


def _velocity_std(model: RollModel, density: NDArray[np.float64]) -> Callable[[float], float]:
    """``B -> sigma_phidot(B) = sqrt(int omega^2 |phi(B)|^2 S d omega)`` (trapezoid on the model's grid) [rad/s]."""
    w = model.omega_rad_s

    def sigma(b: float) -> float:
        with np.errstate(divide="ignore", invalid="ignore"):  # Z = 0 at a grid point and B = 0: infinite, h(0) = -inf
            return math.sqrt(max(float(np.trapezoid(w**2 * np.abs(model.roll_rao_rad_per_m(b)) ** 2 * density, w)), 0.0))

    return sigma


def stochastic_linearisation(
    model: RollModel,
    damping: QuadraticRollDamping,
    wave_spectrum_m2_s_per_rad: ArrayLike,
    *,
    tolerance: float = 1e-12,
    max_iterations: int = 100,
) -> StochasticRollResponse:
    """Roll in a sea state with the quadratic damping linearised stochastically: one ``B_eq`` for the sea state.

    Solves ``B = sqrt(8 / pi) B44_2 sigma_phidot(B)`` (a unique root in ``[0, B_up]``, ``B_up =
    min(g(0), sqrt(sqrt(8 / pi) B44_2 sqrt(int |F|^2 S d omega)))``; module docstring) with
    ``scipy.optimize.brentq``. The spectral integrals are trapezoids on the model's frequency
    grid, which must resolve the roll resonance. ``B44_2 = 0`` gives the linear answer exactly.

    Parameters
    ----------
    model
        The linear roll model per frequency (its grid is the spectrum's).
    damping
        The quadratic damping ``B44_2``.
    wave_spectrum_m2_s_per_rad
        (n,) one-sided wave spectrum ``S(omega)`` at the model's frequencies [m^2 s/rad], >= 0
        (the roll sees the wave from the heading the model's excitation is for).
    tolerance
        Relative tolerance on ``B_eq`` [-].
    max_iterations
        Iteration limit of ``brentq``.

    Returns
    -------
    StochasticRollResponse
        ``B_eq``, the total damping, RAO, roll spectrum, ``sigma_phi``, ``sigma_phidot``,
        iterations, whether it converged and the residual; ``roll_mpm_rad(duration)`` the Rayleigh MPM.
    """
    w = model.omega_rad_s
    density = _per_omega("wave_spectrum_m2_s_per_rad", wave_spectrum_m2_s_per_rad, w.size)
    if np.any(density < 0):
        raise ValueError(f"wave_spectrum_m2_s_per_rad has the value {density.min():.6g}; allowed: >= 0")
    sigma = _velocity_std(model, density)
    c = STOCHASTIC_FACTOR * damping.coefficient_Nms2_per_rad2
    force = math.sqrt(float(np.trapezoid(np.abs(model.excitation_Nm_per_m) ** 2 * density, w)))
    upper = float(_upper_bound(np.array([c * sigma(0.0)]), np.array([c]), np.array([force]))[0])
    b_eq, iterations, converged = 0.0, 0, True
    if upper > 0:
        b_eq, iterations, converged = _fixed_point(lambda b: b - c * sigma(b), upper, tolerance, max_iterations)
    rao = model.roll_rao_rad_per_m(b_eq)
    spectrum = np.abs(rao) ** 2 * density
    return StochasticRollResponse(
        omega_rad_s=w,
        equivalent_damping_Nms_per_rad=float(b_eq),
        total_damping_Nms_per_rad=model.impedance_Nm_per_rad.imag / w + b_eq,
        roll_rao_rad_per_m=rao,
        roll_spectrum_rad2_s=spectrum,
        roll_std_rad=math.sqrt(float(np.trapezoid(spectrum, w))),
        roll_velocity_std_rad_s=sigma(float(b_eq)),
        iterations=iterations,
        converged=converged,
        residual_Nms_per_rad=abs(float(b_eq) - c * sigma(float(b_eq))),
    )
