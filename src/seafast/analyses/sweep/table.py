"""What a frequency sweep reports at each branch point: maxima, RAOs, stability, meaningful range.

A :class:`~seafast.solvers.continuation.FrequencyResponseBranch` holds the saddle compressions of
each point; this module turns them into the columns of ``frequency_response.csv``
(:class:`SweepTable`):

* the nonlinear maxima (saddle force, gap, cargo deflection in two frames, bending moment) and the
  linear (bilateral-saddle) model's at the same frequency;
* stability (:func:`seafast.solvers.floquet.floquet_multipliers`), decided within the tolerance the
  folds give (:mod:`seafast.analyses.sweep.stability`), and the folds;
* the truncation estimate, and whether it exceeds the case's ``truncation_tolerance``;
* the physically meaningful range (:mod:`seafast.analyses.sweep.range`): the deck under the saddles
  accelerating faster than g, a detachment gap beyond a stated size, and, for the wave sweep, a
  wave steeper than the breaking limit;
* for the wave sweep, the nonlinear and linear RAOs of saddle force and bending moment: the
  largest rise above the still-water value per metre of wave amplitude.

Units: SI; the unit is in every name. Nothing here prints or writes files.

Size: the column lists, the table and the one pass over the branch points that fills it belong
together (the verdicts need every point's multipliers first); the fold and stability rules, and the
range checks, are their own modules.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from seafast.analyses.sweep.range import RangeLimit, RangeLimits, deck_acceleration_m_per_s2, time_extremes
from seafast.analyses.sweep.stability import (
    FOLD_RESPONSE_CHANGE,
    FOLD_SEPARATION,
    FoldCluster,
    classify_stability,
    fold_clusters,
    significant_folds,
    stability_tolerances,
    with_multipliers,
)
from seafast.excitation.harmonic import HarmonicExcitation
from seafast.fourier import harmonics_to_time, real_dft_matrices, real_to_complex_harmonics
from seafast.model.beam import bending_moment_line
from seafast.model.structure import StructuralModel
from seafast.results.dataset import seafastening_baseline
from seafast.solvers.branch import FrequencyResponseBranch
from seafast.solvers.contact import ContactLaw
from seafast.solvers.floquet import Stability, floquet_multipliers, stability_system
from seafast.solvers.hbm import CondensedOperators, condensed_operators
from seafast.solvers.hbm.harmonics import truncation_error
from seafast.solvers.modal_correction import ModalCorrectionSystem

__all__ = [
    "FOLD_SEPARATION",
    "FOLD_RESPONSE_CHANGE",
    "WaveColumns",
    "SweepTable",
    "significant_folds",
    "sweep_table",
    "BASE_COLUMNS",
    "ADDED_COLUMNS",
    "STRUCTURAL_COLUMNS",
    "WAVE_COLUMNS",
]

_MOMENT_POINTS_PER_ELEMENT = 2  # as results.nc's x_moment_m

BASE_COLUMNS = ("omega_rad_s", "max_saddle_force_N", "max_gap_m", "max_cargo_deflection_m", "converged", "contact_preserved")
"""The columns ``frequency_response.csv`` always had (users' scripts read them)."""

_STRUCTURAL_CORE = BASE_COLUMNS + (
    "max_bending_moment_Nm",
    "linear_max_saddle_force_N",
    "linear_max_bending_moment_Nm",
    "max_deck_acceleration_m_per_s2",
    "stable",
    "floquet_max_modulus",
    "fold",
    "truncation_error",
    "valid",
    "beyond_range",
)

ADDED_COLUMNS = ("u_c_m", "stability", "stability_tolerance", "too_few_harmonics")
"""The last columns of both files (after the wave sweep's: the earlier columns keep their positions)."""

STRUCTURAL_COLUMNS = _STRUCTURAL_CORE + ADDED_COLUMNS
"""Columns of the structural sweep's ``frequency_response.csv``."""

WAVE_COLUMNS = (
    _STRUCTURAL_CORE
    + (
        "wave_length_m",
        "wave_amplitude_m",
        "wave_steepness",
        "heave_rao_m_per_m",
        "pitch_rao_rad_per_m",
        "saddle_force_rao_N_per_m",
        "linear_saddle_force_rao_N_per_m",
        "bending_moment_rao_Nm_per_m",
        "linear_bending_moment_rao_Nm_per_m",
    )
    + ADDED_COLUMNS
)
"""Columns of the wave sweep's ``frequency_response.csv``."""


@dataclass(frozen=True)
class WaveColumns:
    """The wave sweep's columns, one value per branch point.

    Attributes
    ----------
    wave_length_m
        Deep-water wave length ``2 pi g / omega^2`` [m].
    wave_amplitude_m
        The case's wave amplitude zeta_a [m].
    wave_steepness
        Wave height over length ``2 zeta_a / lambda`` [-].
    heave_rao_m_per_m, pitch_rao_rad_per_m
        |heave| [m/m] and |pitch| [rad/m] per metre of wave amplitude.
    saddle_force_rao_N_per_m, linear_saddle_force_rao_N_per_m
        Largest rise of a saddle force above its still-water value over the period, per metre of
        wave amplitude [N/m], nonlinear / linear model (linear: the first-harmonic amplitude).
    bending_moment_rao_Nm_per_m, linear_bending_moment_rao_Nm_per_m
        Largest |M(x, t) - M_still_water(x)| over the cargo and the period per metre of wave
        amplitude [N m/m], nonlinear / linear model.
    """

    wave_length_m: NDArray[np.float64]
    wave_amplitude_m: NDArray[np.float64]
    wave_steepness: NDArray[np.float64]
    heave_rao_m_per_m: NDArray[np.float64]
    pitch_rao_rad_per_m: NDArray[np.float64]
    saddle_force_rao_N_per_m: NDArray[np.float64]
    linear_saddle_force_rao_N_per_m: NDArray[np.float64]
    bending_moment_rao_Nm_per_m: NDArray[np.float64]
    linear_bending_moment_rao_Nm_per_m: NDArray[np.float64]


@dataclass(frozen=True)
class SweepTable:
    """The columns of ``frequency_response.csv``, one entry per branch point (continuation order).

    Attributes
    ----------
    omega_rad_s, max_saddle_force_N, max_gap_m, converged, contact_preserved
        As :class:`~seafast.solvers.continuation.FrequencyResponseBranch`.
    max_cargo_deflection_m
        Largest |z| over the period and the cargo nodes, z relative to the vessel's rigid-body frame
        (the hull chord): the hull's deflection under the cargo included, static part included [m]
        (``results.nc``'s ``cargo_deflection_vessel_frame_m``).
    u_c_m
        Largest |z - z_baseline| over the period and the cargo nodes, relative to the sea-fastening
        baseline (:func:`seafast.results.dataset.seafastening_baseline`): ``seafast run``'s u_c [m].
    max_bending_moment_Nm
        Largest |bending moment| over the cargo and the period, nonlinear model [N m].
    linear_max_saddle_force_N, linear_max_bending_moment_Nm
        The same maxima of the linear (bilateral-saddle) model at the same frequency [N], [N m].
    max_deck_acceleration_m_per_s2
        Largest vertical acceleration of the deck under a saddle over the period (rigid-body heave and
        pitch plus the hull's deflection) [m/s^2].
    stable
        Whether the point is :attr:`Stability.STABLE` (false for unstable and marginal points).
    floquet_max_modulus
        The largest multiplier modulus [-] (> 1: unstable; crosses 1 at folds).
    stability
        The verdict of each point within its tolerance (:func:`seafast.analyses.sweep.stability.classify_stability`).
    stability_tolerance
        The tolerance on ``|mu| - 1`` of each point [-]: the deviation from 1 of the multiplier at its
        neighbouring folds (:func:`seafast.analyses.sweep.stability.stability_tolerances`).
    fold
        True at the point where the branch turns at a fold (:func:`significant_folds`).
    truncation_error
        Estimated error of the peak saddle force from the harmonics above H, relative to the force
        scale (:func:`seafast.solvers.hbm.harmonics.truncation_error`, largest over the saddles) [-].
    truncation_tolerance
        The case's ``solver.truncation_tolerance`` [-]: above it a point has too few harmonics.
    folds
        The folds, with the discrete turns merged into each (:func:`seafast.analyses.sweep.stability.fold_clusters`).
    beyond_range
        The :class:`RangeLimit` s each point breaks (empty inside the meaningful range).
    limits
        The thresholds used.
    wave
        The wave sweep's columns (None for the structural sweep).
    """

    omega_rad_s: NDArray[np.float64]
    max_saddle_force_N: NDArray[np.float64]
    max_gap_m: NDArray[np.float64]
    max_cargo_deflection_m: NDArray[np.float64]
    converged: NDArray[np.bool_]
    contact_preserved: NDArray[np.bool_]
    max_bending_moment_Nm: NDArray[np.float64]
    linear_max_saddle_force_N: NDArray[np.float64]
    linear_max_bending_moment_Nm: NDArray[np.float64]
    max_deck_acceleration_m_per_s2: NDArray[np.float64]
    stable: NDArray[np.bool_]
    floquet_max_modulus: NDArray[np.float64]
    fold: NDArray[np.bool_]
    truncation_error: NDArray[np.float64]
    beyond_range: tuple[tuple[RangeLimit, ...], ...]
    u_c_m: NDArray[np.float64] = field(default_factory=lambda: np.zeros(0))
    stability: tuple[Stability, ...] = ()
    stability_tolerance: NDArray[np.float64] = field(default_factory=lambda: np.zeros(0))
    truncation_tolerance: float = 1e-3
    folds: tuple[FoldCluster, ...] = ()
    limits: RangeLimits = field(default_factory=RangeLimits)
    wave: WaveColumns | None = None

    @property
    def too_few_harmonics(self) -> NDArray[np.bool_]:
        """Whether each point's truncation error exceeds :attr:`truncation_tolerance` (``seafast run``'s ``too_few_harmonics``)."""
        return np.asarray(self.truncation_error > self.truncation_tolerance, dtype=bool)

    @property
    def marginal(self) -> NDArray[np.bool_]:
        """Whether each point is :attr:`Stability.MARGINAL`."""
        return np.array([v is Stability.MARGINAL for v in self.stability], dtype=bool)

    @property
    def valid(self) -> NDArray[np.bool_]:
        """Whether each point lies inside the physically meaningful range."""
        return np.array([not reasons for reasons in self.beyond_range], dtype=bool)

    @property
    def column_names(self) -> tuple[str, ...]:
        """The CSV columns: :data:`STRUCTURAL_COLUMNS` or :data:`WAVE_COLUMNS`."""
        return WAVE_COLUMNS if self.wave is not None else STRUCTURAL_COLUMNS

    def column(self, name: str) -> NDArray | list[str]:
        """One column by its CSV name (``beyond_range``: the reasons joined by '+', '' when valid)."""
        if name == "beyond_range":
            return ["+".join(r.value for r in reasons) for reasons in self.beyond_range]
        if name == "valid":
            return self.valid
        if name == "stability":
            return [v.value for v in self.stability]
        if name == "too_few_harmonics":
            return self.too_few_harmonics
        if self.wave is not None and name in WaveColumns.__dataclass_fields__:
            return np.asarray(getattr(self.wave, name))
        if name not in STRUCTURAL_COLUMNS:
            raise KeyError(f"no column {name!r}; columns: {', '.join(self.column_names)}")
        return np.asarray(getattr(self, name))

    @property
    def fold_omegas_rad_s(self) -> NDArray[np.float64]:
        """Frequencies of the folds [rad/s], in branch order."""
        return self.omega_rad_s[self.fold]


def _cargo_harmonics(ops: CondensedOperators, U: NDArray, law: ContactLaw, time_samples: int) -> NDArray[np.complex128]:
    """Cargo displacement harmonics (H+1, n_c) of compressions ``U`` (real layout) [m, rad]."""
    inverse, forward = real_dft_matrices(ops.harmonics, time_samples)
    delta = inverse @ U
    k = ops.saddle_stiffness_N_per_m
    correction = forward @ (law.force(delta, k) - k * delta)
    return ops.linear_cargo_displacement + np.einsum("kcs,ks->kc", ops.cargo_influence, real_to_complex_harmonics(correction))


def _moments(model: StructuralModel, displacement: NDArray, excitation: HarmonicExcitation, time_samples: int) -> NDArray:
    """Bending moment (N, n_x) [N m] of cargo harmonics (H+1, n_c), self-weight and vessel line loads included."""
    beam = model.cargo
    disp = harmonics_to_time(displacement, time_samples)
    line = harmonics_to_time(excitation.cargo_line_load_N_per_m, time_samples) + beam.gravity_line_load_N_per_m
    return bending_moment_line(beam.node_x_m, disp, beam.element_bending_stiffness_Nm2, None, line, _MOMENT_POINTS_PER_ELEMENT)[1]


def _moment_harmonics(model: StructuralModel, displacement: NDArray, excitation: HarmonicExcitation) -> NDArray[np.complex128]:
    """Bending-moment harmonics (n_k, n_x) [N m] of cargo harmonics (n_k, n_c) (the moment is linear in both)."""
    beam = model.cargo
    line = np.array(excitation.cargo_line_load_N_per_m, dtype=complex)
    line[0] += beam.gravity_line_load_N_per_m
    n_k = line.shape[0]
    return bending_moment_line(
        beam.node_x_m, displacement[:n_k], beam.element_bending_stiffness_Nm2, None, line, _MOMENT_POINTS_PER_ELEMENT
    )[1]


def _max_deflection_from_baseline(model: StructuralModel, excitation: HarmonicExcitation, displacement: NDArray, samples: int) -> float:
    """``seafast run``'s u_c [m]: max |z - z_baseline| over the period and the cargo nodes, of cargo harmonics (H+1, n_c)."""
    z = harmonics_to_time(displacement[:, 0::2], samples)
    deck = harmonics_to_time(excitation.deck_displacement[:, model.saddle_deck_dof], samples)
    return float(np.max(np.abs(z - seafastening_baseline(model, excitation, deck))))


def _still_water(
    model: StructuralModel, excitation: HarmonicExcitation, law: ContactLaw, compression_m: NDArray
) -> tuple[NDArray, NDArray]:
    """Nonlinear still-water saddle forces (n_s,) [N] and moment line (n_x,) [N m] (``compression_m``: static compressions (1, n_s))."""
    static = excitation.static_part()
    ops = condensed_operators(model, static, 0)
    X = _cargo_harmonics(ops, compression_m, law, 2)
    return law.force(compression_m[0], ops.saddle_stiffness_N_per_m), _moments(model, X, static, 2)[0]


@dataclass(frozen=True)
class _PointSetting:
    """What every branch point's columns are computed with (the loop's invariants)."""

    model: StructuralModel
    law: ContactLaw
    harmonics: int
    time_samples: int
    system: ModalCorrectionSystem
    unilateral_stiffness_N_per_m: NDArray[np.float64]
    inverse_dft: NDArray[np.float64]
    limits: RangeLimits
    wave_amplitude_m: float | None
    still_water: tuple[NDArray, NDArray] | None


_POINT_COLUMNS = ("moment", "u_c", "lin_force", "lin_moment", "accel", "mu", "to_one", "trunc", "f_rao", "lf_rao", "m_rao", "lm_rao")


def _point_columns(
    setting: _PointSetting, excitation: HarmonicExcitation, omega_rad_s: float, U: NDArray, max_gap_m: float
) -> tuple[dict[str, float], tuple[RangeLimit, ...]]:
    """One branch point's entries of the columns (:data:`_POINT_COLUMNS`) and the range limits it breaks."""
    model, law, N, k_u = setting.model, setting.law, setting.time_samples, setting.unilateral_stiffness_N_per_m
    ops = condensed_operators(model, excitation, setting.harmonics)
    n_k = excitation.harmonic_count
    X = _cargo_harmonics(ops, U, law, N)
    moment = _moments(model, X, excitation, N)  # nonlinear: on the HBM's samples, as seafast run
    # the linear model lives on the excitation's harmonics: its extremes exactly
    lin_force = k_u * real_to_complex_harmonics(ops.linear_compression_m)[:n_k]
    lin_moment = _moment_harmonics(model, ops.linear_cargo_displacement, excitation)
    accel = deck_acceleration_m_per_s2(model, excitation)
    floquet = floquet_multipliers(model, omega_rad_s, U, law, system=setting.system)
    row = {
        "moment": float(np.max(np.abs(moment))),
        "u_c": _max_deflection_from_baseline(model, excitation, X, N),
        "lin_force": float(np.max(time_extremes(lin_force)[0])),
        "lin_moment": float(np.max(time_extremes(lin_moment)[1])),
        "accel": accel,
        "mu": floquet.max_modulus,
        "to_one": float(np.min(np.abs(floquet.multipliers - 1.0), initial=np.inf)),
        "trunc": float(np.max(truncation_error(model, omega_rad_s, U, law))),
    }
    why = []
    if accel > setting.limits.gravity_m_per_s2:
        why.append(RangeLimit.DECK_ACCELERATION)
    if max_gap_m > setting.limits.max_gap_m:
        why.append(RangeLimit.GAP)
    if setting.still_water is not None and setting.wave_amplitude_m is not None:
        row.update(_wave_point_columns(setting, setting.still_water, setting.wave_amplitude_m, U, moment, lin_force, lin_moment))
        steepness = 2.0 * setting.wave_amplitude_m * omega_rad_s**2 / (2.0 * np.pi * setting.limits.gravity_m_per_s2)
        if steepness > setting.limits.breaking_steepness:
            why.append(RangeLimit.WAVE_BREAKING)
    return row, tuple(why)


def _wave_point_columns(
    setting: _PointSetting,
    still_water: tuple[NDArray, NDArray],
    wave_amplitude_m: float,
    U: NDArray,
    moment: NDArray,
    lin_force: NDArray,
    lin_moment: NDArray,
) -> dict[str, float]:
    """A wave sweep point's RAOs: the largest rise above the still-water value per metre of wave amplitude.

    ``still_water``: the nonlinear still-water saddle forces [N] and moment line [N m]; ``moment``
    the point's nonlinear moment samples, ``lin_force`` and ``lin_moment`` the linear model's
    harmonics.
    """
    sw_force, sw_moment = still_water
    force = setting.law.force(setting.inverse_dft @ U, setting.unilateral_stiffness_N_per_m)
    dynamic_force, dynamic_moment = lin_force.copy(), lin_moment.copy()
    dynamic_force[0], dynamic_moment[0] = 0.0, 0.0  # the rise above the linear still-water state
    return {
        "f_rao": float(np.max(np.max(force, axis=0) - sw_force)) / wave_amplitude_m,
        "lf_rao": float(np.max(time_extremes(dynamic_force)[0])) / wave_amplitude_m,
        "m_rao": float(np.max(np.abs(moment - sw_moment))) / wave_amplitude_m,
        "lm_rao": float(np.max(time_extremes(dynamic_moment)[1])) / wave_amplitude_m,
    }


def _wave_columns(
    branch: FrequencyResponseBranch,
    limits: RangeLimits,
    wave_amplitude_m: float,
    rao_at: Callable[[float], tuple[complex, complex]],
    cols: dict[str, list[float]],
) -> WaveColumns:
    """The wave sweep's columns of the branch (``cols``: the points' RAO entries)."""
    omegas = branch.omega_rad_s
    length = 2.0 * np.pi * limits.gravity_m_per_s2 / omegas**2
    raos = [rao_at(float(x)) for x in omegas]
    return WaveColumns(
        wave_length_m=length,
        wave_amplitude_m=np.full(omegas.size, float(wave_amplitude_m)),
        wave_steepness=2.0 * wave_amplitude_m / length,
        heave_rao_m_per_m=np.array([abs(r[0]) for r in raos]),
        pitch_rao_rad_per_m=np.array([abs(r[1]) for r in raos]),
        saddle_force_rao_N_per_m=np.array(cols["f_rao"]),
        linear_saddle_force_rao_N_per_m=np.array(cols["lf_rao"]),
        bending_moment_rao_Nm_per_m=np.array(cols["m_rao"]),
        linear_bending_moment_rao_Nm_per_m=np.array(cols["lm_rao"]),
    )


def _table_of(
    branch: FrequencyResponseBranch,
    cols: dict[str, list[float]],
    reasons: tuple[tuple[RangeLimit, ...], ...],
    limits: RangeLimits,
    wave: WaveColumns | None,
) -> SweepTable:
    """The :class:`SweepTable` of the branch and its points' columns: folds and stability decided on all points."""
    n = branch.omega_rad_s.size
    clusters = with_multipliers(fold_clusters(branch), np.array(cols["to_one"], dtype=float))
    fold = np.zeros(n, dtype=bool)
    fold[[c.index for c in clusters]] = True
    mu = np.array(cols["mu"], dtype=float)
    tolerance = stability_tolerances(clusters, n)
    stability = classify_stability(mu, tolerance)
    return SweepTable(
        omega_rad_s=branch.omega_rad_s,
        max_saddle_force_N=branch.max_saddle_force_N,
        max_gap_m=branch.max_gap_m,
        max_cargo_deflection_m=branch.max_cargo_deflection_m,
        converged=branch.converged,
        contact_preserved=branch.contact_preserved,
        max_bending_moment_Nm=np.array(cols["moment"]),
        linear_max_saddle_force_N=np.array(cols["lin_force"]),
        linear_max_bending_moment_Nm=np.array(cols["lin_moment"]),
        max_deck_acceleration_m_per_s2=np.array(cols["accel"]),
        stable=np.array([v is Stability.STABLE for v in stability], dtype=bool),
        floquet_max_modulus=mu,
        fold=fold,
        truncation_error=np.array(cols["trunc"]),
        beyond_range=reasons,
        u_c_m=np.array(cols["u_c"]),
        stability=stability,
        stability_tolerance=tolerance,
        truncation_tolerance=branch.truncation_tolerance or 1e-3,
        folds=clusters,
        limits=limits,
        wave=wave,
    )


def sweep_table(
    model: StructuralModel,
    branch: FrequencyResponseBranch,
    excitation_at: Callable[[float], HarmonicExcitation],
    law: ContactLaw,
    limits: RangeLimits | None = None,
    *,
    wave_amplitude_m: float | None = None,
    rao_at: Callable[[float], tuple[complex, complex]] | None = None,
    still_water_compression_m: NDArray | None = None,
) -> SweepTable:
    """The table of a branch: maxima of both models, stability, folds and the meaningful range.

    Parameters
    ----------
    model
        Cargo and sea-fastening.
    branch
        The continuation's branch (with its compression harmonics).
    excitation_at
        ``omega -> HarmonicExcitation``, as given to the continuation.
    law
        The contact law of the branch.
    limits
        Thresholds of the meaningful range (default :class:`RangeLimits` ()).
    wave_amplitude_m, rao_at, still_water_compression_m
        For a wave sweep: the wave amplitude zeta_a [m], ``omega -> (heave [m/m], pitch [rad/m])``
        and the nonlinear still-water compressions (1, n_s) [m]; all three or none.
    """
    limits = RangeLimits() if limits is None else limits
    wave_sweep = wave_amplitude_m is not None
    if wave_sweep != (rao_at is not None) or wave_sweep != (still_water_compression_m is not None):
        raise ValueError("sweep_table: give wave_amplitude_m, rao_at and still_water_compression_m together (wave sweep) or none")
    n = branch.omega_rad_s.size
    H = branch.compression_harmonics_m.shape[1] // 2
    N = branch.time_samples or 128
    setting = _PointSetting(
        model,
        law,
        H,
        N,
        stability_system(model, float(np.max(branch.omega_rad_s)) if n else 1.0, H),
        np.asarray(model.saddle_unilateral_stiffness_N_per_m, dtype=float),
        real_dft_matrices(H, N)[0],
        limits,
        wave_amplitude_m,
        _still_water(model, excitation_at(float(branch.omega_rad_s[0])), law, np.asarray(still_water_compression_m))
        if wave_sweep
        else None,
    )
    cols: dict[str, list[float]] = {name: [] for name in _POINT_COLUMNS}
    reasons: list[tuple[RangeLimit, ...]] = []
    for i in range(n):
        w = float(branch.omega_rad_s[i])
        row, why = _point_columns(setting, excitation_at(w), w, branch.compression_harmonics_m[i], branch.max_gap_m[i])
        for name, value in row.items():
            cols[name].append(value)
        reasons.append(why)
    wave = None
    if rao_at is not None and wave_amplitude_m is not None:
        wave = _wave_columns(branch, limits, wave_amplitude_m, rao_at, cols)
    return _table_of(branch, cols, tuple(reasons), limits, wave)
