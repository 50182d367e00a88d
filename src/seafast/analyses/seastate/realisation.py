"""One random-phase realisation of a sea state: linear and nonlinear maxima, uplift statistics.

The plan (:func:`realisation_plan`, computed once per Monte Carlo run and shipped to the workers)
holds everything a realisation needs; :func:`evaluate_realisation` is a pure function of the
plan and the realisation index.

Per realisation
---------------
1. Linear model (every saddle bilateral): the dynamic saddle compressions and the cargo's
   bending-moment field (its r leading singular components, :func:`~seafast.analyses.seastate.synthesis.low_rank`)
   synthesised by inverse FFT on the coarse grid ``dt_c`` (:mod:`seafast.analyses.seastate.synthesis`), plus
   the still-water state. Maxima over the coarse samples: ``F = max_s k_u (delta_0 + delta)``,
   ``u_s = max(delta_0 + delta, 0)``, ``M_b = max_x |M_0 + M|``, ``sigma_b = max_x |M_0 + M| / Z``,
   ``u_d = 0`` (bilateral saddles never open, as in ``seafast run``); time lifted and uplift
   events (downward zero crossings of a saddle's compression, summed over saddles) from the same
   samples. A sampled peak falls short of the true one by at most ``1 - cos(omega dt_c / 2)``
   of the component at omega; ``dt_c = 0.15 / omega_s`` by default, with omega_s the frequency
   below which each saddle compression and the moment field have 1 - 1e-5 of their variance:
   <= 0.28 % at omega_s, <= 0.03 % at omega_s / 3 (the spectral peak region).
2. Nonlinear model: ``q = q_lin + q_c`` (:mod:`seafast.solvers.transient`). The correction q_c
   is marched on the fine grid ``dt_f = dt_c / ratio`` only in windows that start at the coarse
   sample before one where some saddle's linear compression is below a margin (the largest dip
   a band-limited record can make between two samples, ``dt_c^2 / 8 sum_j omega_j^2 |X_j|``,
   so no lift-off between samples is missed) and end once contact is back, the linear
   compressions are clear of zero and the correction's free vibration is below
   ``decay_tolerance`` times the largest still-water compression. Inside windows the linear
   parts come from the coarse samples by periodic cubic-spline interpolation; the nonlinear
   maxima are taken at every fine step. Outside windows the nonlinear response equals the
   linear one sample by sample.

Why a coarse and a fine grid: a 3-hour record at the integrator's step is ~10^6 samples per
channel; the linear parts vary at wave frequencies (< 4 rad/s) and are exact on the coarse grid.

Size: over 400 lines because one realisation's synthesis, linear maxima, windowed nonlinear march and
statistics share one plan and one time grid; they are pure functions of it.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any

import numba
import numpy as np
from numpy.typing import NDArray
from scipy.ndimage import spline_filter1d

from seafast.analyses.seastate.spectrum import WaveSpectrum, jonswap_density
from seafast.analyses.seastate.synthesis import (
    SynthesisGrid,
    amplitude_factors,
    interpolate_transfer,
    low_rank,
    realisation_phases,
    record_grids,
    synthesise,
)
from seafast.analyses.seastate.transfer import MOMENT_POINTS_PER_ELEMENT, StillWater, TransferFunctions
from seafast.config.schema import Case
from seafast.model.beam import bending_moment_line
from seafast.model.structure import StructuralModel
from seafast.solvers.transient import (
    DEFAULT_CUTOFF_FACTOR,
    DEFAULT_STEPS_PER_PERIOD,
    MarchState,
    MomentOutput,
    NewmarkStep,
    WindowOutcome,
    march_window,
    newmark_step,
    reference_frequency_rad_s,
    time_step_s,
)

__all__ = [
    "QUANTITIES",
    "MonteCarloSettings",
    "RealisationPlan",
    "realisation_plan",
    "RealisationTimeSeries",
    "evaluate_realisation",
    "spectral_density",
    "drawn_transfer",
    "variance_frequency_rad_s",
]

QUANTITIES: tuple[str, ...] = ("F_N", "M_b_Nm", "sigma_b_Pa", "u_s_m", "u_d_m")
"""Per-realisation maxima (totals including still water), in the order of seastate.csv."""


@dataclass(frozen=True)
class MonteCarloSettings:
    """Numerical settings of the Monte Carlo reference (not case keys; the defaults are verified).

    Attributes
    ----------
    steps_per_period
        Integrator steps per period of the reference frequency (:func:`~seafast.solvers.transient.time_step_s`).
    cutoff_factor
        Modes kept up to this multiple of the reference frequency (``inf``: every mode).
    decay_tolerance
        A window ends when the correction's free vibration is below this fraction of the
        largest still-water saddle compression [-].
    coarse_step_factor
        ``omega_s dt_c`` of the coarse grid, omega_s the frequency below which every response
        (each compression, the moment field) has 1 - 1e-5 of its variance [rad].
    transfer_step_rad_s
        Spacing of the frequencies the transfer functions are computed at before interpolation [rad/s].
    moment_rank_tolerance
        Relative singular-value cut of the bending-moment field [-].
    capture_step_s
        Sampling interval of the example time series [s] (rounded to a multiple of dt_c).
    """

    steps_per_period: int = DEFAULT_STEPS_PER_PERIOD
    cutoff_factor: float = DEFAULT_CUTOFF_FACTOR
    decay_tolerance: float = 1e-4
    coarse_step_factor: float = 0.15
    transfer_step_rad_s: float = 0.01
    moment_rank_tolerance: float = 1e-10
    capture_step_s: float = 0.25


@dataclass(frozen=True)
class RealisationPlan:
    """Everything a realisation needs (picklable; computed once per run).

    Attributes
    ----------
    seed, duration_s
        Phase seed and record length [s].
    random_amplitudes
        Rayleigh-distributed component amplitudes (``sea_state.random_amplitudes``; :mod:`seafast.analyses.seastate.synthesis`).
    grid
        The synthesis grid (frequencies, amplitudes, coarse sampling).
    transfer
        (n_f, n_s + n_r) transfer functions on the grid: the saddle compressions [m/m], then
        the coordinates of the bending-moment field on ``moment_basis`` [N m/m]; a short-crested sea:
        (n_d, n_f, n_s + n_r), one block per direction of the spreading's quadrature.
    direction_weights
        (n_d,) the quadrature's weights [-] of a short-crested sea, None for a long-crested one: each component of a
        realisation travels in a direction drawn from them (:meth:`realisation_transfer`).
    compression_static_m, stiffness_N_per_m
        (n_s,) linear still-water compression [m] and compression-only stiffness k_u [N/m].
    moment_x_m, moment_static_Nm, section_modulus_m3
        (n_x,) moment sample positions [m], still-water moment [N m], section modulus [m^3].
    moment_basis
        (n_x, n_r) orthonormal spatial basis of the dynamic moment field.
    system
        The reduced correction system for the fine step.
    moments
        The march's moment output (basis ``[U | E Phi | E R]``).
    ratio
        Fine steps per coarse sample.
    tolerance_m
        Window-end tolerance on the correction's free vibration [m].
    settings
        The settings the plan was built with.
    """

    seed: int
    duration_s: float
    grid: SynthesisGrid
    transfer: NDArray[np.complex128]
    compression_static_m: NDArray[np.float64]
    stiffness_N_per_m: NDArray[np.float64]
    saddle_x_m: NDArray[np.float64]
    moment_x_m: NDArray[np.float64]
    moment_static_Nm: NDArray[np.float64]
    section_modulus_m3: NDArray[np.float64]
    moment_basis: NDArray[np.float64]
    system: NewmarkStep
    moments: MomentOutput
    ratio: int
    tolerance_m: float
    settings: MonteCarloSettings = field(default_factory=MonteCarloSettings)
    random_amplitudes: bool = True
    direction_weights: NDArray[np.float64] | None = None

    @property
    def saddle_count(self) -> int:
        return int(self.compression_static_m.size)

    def realisation_transfer(self, index: int) -> NDArray[np.complex128]:
        """(n_f, n_s + n_r) transfer functions of realisation ``index``'s components.

        Long-crested: :attr:`transfer`. Short-crested: each component's direction drawn (categorical, the quadrature's
        weights) from its own generator stream, ``SeedSequence(seed, spawn_key=(index, 1))``, apart from the phases' and
        amplitudes' stream (``spawn_key=(index,)``), so these are the long-crested realisation's, unchanged.
        """
        return drawn_transfer(self.transfer, self.direction_weights, self.seed, index)

    @property
    def fine_step_s(self) -> float:
        """Integrator step dt_f [s]."""
        return self.grid.time_step_s / self.ratio

    def describe(self) -> dict[str, Any]:
        """The numerical settings of the run (recorded in outputs)."""
        return {
            "synthesis_components": int(self.grid.omega_rad_s.size),
            "frequency_step_rad_s": self.grid.frequency_step_rad_s,
            "band_rad_s": [float(self.grid.omega_rad_s[0]), float(self.grid.omega_rad_s[-1])],
            "coarse_step_s": self.grid.time_step_s,
            "integrator_step_s": self.fine_step_s,
            "modes_kept": self.system.mode_count,
            "cutoff_rad_s": self.system.reduced.cutoff_rad_s,
            "moment_rank": int(self.moment_basis.shape[1]),
            "window_tolerance_m": self.tolerance_m,
            "steps_per_period": self.settings.steps_per_period,
            "decay_tolerance": self.settings.decay_tolerance,
            "random_amplitudes": self.random_amplitudes,
        }


@numba.njit(cache=True)
def _linear_samples(  # pragma: no cover - compiled
    d_tot: NDArray, k: NDArray, g: NDArray, U: NDArray, moment_static: NDArray, modulus: NDArray
) -> NDArray:
    """Per coarse sample: max_s k d, max_s d, max_x |M|, max_x |M| / Z (M = M_0 + U g)."""
    n_t, n_s = d_tot.shape
    n_x, n_r = U.shape
    out = np.empty((n_t, 4))
    for t in range(n_t):
        f = -np.inf
        d = -np.inf
        for s in range(n_s):
            f = max(f, k[s] * d_tot[t, s])
            d = max(d, d_tot[t, s])
        mm = 0.0
        ss = 0.0
        for x in range(n_x):
            v = moment_static[x]
            for r in range(n_r):
                v += U[x, r] * g[t, r]
            v = abs(v)
            mm = max(mm, v)
            ss = max(ss, v / modulus[x])
        out[t, 0] = f
        out[t, 1] = d
        out[t, 2] = mm
        out[t, 3] = ss
    return out


DIRECTION_STREAM = 1
"""Second spawn-key entry of the generator that draws a short-crested realisation's component directions."""


def drawn_transfer(transfer: NDArray[np.complex128], weights: NDArray[np.float64] | None, seed: int, index: int) -> NDArray[np.complex128]:
    """Realisation ``index``'s (n_f, n_ch) of a plan's ``transfer`` and ``weights``: :meth:`RealisationPlan.realisation_transfer`."""
    if weights is None:
        return transfer
    rng = np.random.default_rng(np.random.SeedSequence(int(seed), spawn_key=(int(index), DIRECTION_STREAM)))
    drawn = rng.choice(weights.size, size=transfer.shape[1], p=weights)
    return np.ascontiguousarray(transfer[drawn, np.arange(transfer.shape[1])])


def variance_frequency_rad_s(omega: NDArray, power: NDArray, share: float) -> float:
    """Highest frequency that matters for sampling [rad/s]: the largest, over the channels of ``power`` (n_f, n_c),
    each channel's power per component, of the frequency below which ``1 - share`` of its variance lies."""
    cum = np.cumsum(power, axis=0)
    top = 0.0
    for j in np.flatnonzero(cum[-1] > 0):
        top = max(top, float(omega[min(int(np.searchsorted(cum[:, j], (1.0 - share) * cum[-1, j])), omega.size - 1)]))
    return top if top > 0 else float(omega[-1])


def _channels(
    held: TransferFunctions | Sequence[TransferFunctions],
    direction_weights: NDArray[np.float64] | None,
    omega_i: NDArray[np.float64],
    density: Callable[[NDArray[np.float64]], NDArray[np.float64]],
    settings: MonteCarloSettings,
) -> tuple[TransferFunctions, NDArray[np.float64], list[NDArray[np.complex128]], float]:
    """The first direction's transfer functions, the moment basis (spanning every direction's moments), each direction's
    channels (saddle compressions, moment coordinates) on ``omega_i``, and the highest frequency they need [rad/s]."""
    tfs = (held,) if isinstance(held, TransferFunctions) else tuple(held)
    spread = direction_weights is not None
    n_weights = 1 if direction_weights is None else int(np.size(direction_weights))
    if spread and len(tfs) != n_weights:
        raise ValueError(f"realisation_plan: {len(tfs)} directions' transfer functions for {n_weights} weights")
    moments_all = tfs[0].bending_moment_Nm if not spread else np.vstack([t.bending_moment_Nm for t in tfs])
    coords_all, basis = low_rank(moments_all, settings.moment_rank_tolerance)
    coords_per = np.split(coords_all, len(tfs)) if spread else [coords_all]
    channels_per = [np.hstack([t.saddle_compression_m, c]) for t, c in zip(tfs, coords_per, strict=True)]
    # coarse step from the highest frequency the responses need (1 - 1e-5 of their variance below it), every direction
    amplitude_i = np.sqrt(np.maximum(density(omega_i), 0.0))
    power = [
        np.column_stack([np.abs(t.saddle_compression_m) ** 2, np.sum(np.abs(c) ** 2, axis=1)]) for t, c in zip(tfs, coords_per, strict=True)
    ]
    omega_s = max(variance_frequency_rad_s(omega_i, p * amplitude_i[:, None] ** 2, 1e-5) for p in power)  # compressions, moment field
    return tfs[0], basis, channels_per, omega_s


def spectral_density(case: Case, spectrum: WaveSpectrum) -> Callable[[NDArray[np.float64]], NDArray[np.float64]]:
    """S(omega) of the case's spectrum anywhere (parametric formulas; tables interpolated as the spectrum does)."""
    ss = case.sea_state
    if ss.spectrum in ("jonswap", "pierson_moskowitz"):
        gamma = 1.0 if ss.spectrum == "pierson_moskowitz" else float(ss.peak_enhancement)
        # set: the spectrum passed here was built from this case, which refuses a parametric sea without them
        assert ss.significant_height_m is not None and ss.peak_period_s is not None
        hs, tp = float(ss.significant_height_m), float(ss.peak_period_s)
        return lambda w: jonswap_density(w, hs, tp, gamma)
    # a table is linear between its rows, which the spectrum's grid keeps: interpolating the grid is exact
    return lambda w: np.interp(w, spectrum.omega_rad_s, spectrum.density_m2_s_per_rad, left=0.0, right=0.0)


def realisation_plan(
    case: Case,
    model: StructuralModel,
    spectrum: WaveSpectrum,
    transfer_at: Callable[[NDArray[np.float64]], TransferFunctions | Sequence[TransferFunctions]],
    still: StillWater,
    settings: MonteCarloSettings = MonteCarloSettings(),
    direction_weights: NDArray[np.float64] | None = None,
) -> RealisationPlan:
    """Build the plan of the case's Monte Carlo run.

    Parameters
    ----------
    case, model
        The case (its ``sea_state``) and its structural model.
    spectrum
        The case's sea-state spectrum (:func:`~seafast.analyses.seastate.spectrum.sea_state_spectrum`): its
        grid's band is the synthesis band.
    transfer_at
        ``omega -> TransferFunctions`` (e.g. ``lambda w: transfer_functions(case, model, w, heading_deg=180.0)``), or a
        short-crested sea's sequence of them, one per direction.
    still
        The linear still-water state (:func:`~seafast.analyses.seastate.transfer.still_water`).
    settings
        Numerical settings.
    direction_weights
        A short-crested sea's quadrature weights (one per direction ``transfer_at`` gives); None: long-crested.
    """
    ss = case.sea_state
    lo, hi = float(spectrum.omega_rad_s[0]), float(spectrum.omega_rad_s[-1])
    density = spectral_density(case, spectrum)
    # transfer functions on a uniform interpolation grid, then cubic splines to the synthesis grid
    n_i = max(int(np.ceil((hi - lo) / settings.transfer_step_rad_s)) + 1, 8)
    omega_i = np.linspace(lo, hi, n_i)
    spread = direction_weights is not None
    tf, basis, channels_per, omega_s = _channels(transfer_at(omega_i), direction_weights, omega_i, density, settings)
    dt_f_max = time_step_s(model, settings.steps_per_period)
    grid, ratio = record_grids((lo, hi), density, ss.duration_s, omega_s, settings.coarse_step_factor, dt_f_max)
    per = [interpolate_transfer(omega_i, ch, grid.omega_rad_s) for ch in channels_per]
    transfer = np.stack(per) if spread else per[0]
    system = newmark_step(model, grid.time_step_s / ratio, settings.cutoff_factor * reference_frequency_rad_s(model))
    beam = model.cargo

    def recover(q: NDArray[np.float64]) -> NDArray[np.float64]:
        """The bending-moment line [N m] of displacement rows (..., n_c)."""
        return bending_moment_line(beam.node_x_m, q, beam.element_bending_stiffness_Nm2, None, None, MOMENT_POINTS_PER_ELEMENT)[1]

    moment_modes = recover(system.reduced.mode_shape.T).T
    moment_residual = recover(system.reduced.residual_displacement_m_per_N.T).T
    modulus = tf.bending_section_modulus_m3
    moments = MomentOutput(
        np.asarray(still.bending_moment_Nm, dtype=float),
        np.ascontiguousarray(np.hstack([basis, moment_modes, moment_residual])),
        np.asarray(modulus, dtype=float),
    )
    d0 = np.asarray(still.saddle_compression_m, dtype=float)
    scale = float(np.max(np.abs(d0))) if np.max(np.abs(d0)) > 0 else 1e-3
    return RealisationPlan(
        seed=int(ss.seed),
        duration_s=float(ss.duration_s),
        grid=grid,
        transfer=np.ascontiguousarray(transfer),
        compression_static_m=d0,
        stiffness_N_per_m=np.asarray(model.saddle_unilateral_stiffness_N_per_m, dtype=float),
        saddle_x_m=np.asarray(model.saddle_x_m, dtype=float),
        moment_x_m=np.asarray(tf.bending_moment_x_m, dtype=float),
        moment_static_Nm=moments.moment_static_Nm,
        section_modulus_m3=moments.section_modulus_m3,
        moment_basis=basis,
        system=system,
        moments=moments,
        ratio=int(ratio),
        tolerance_m=settings.decay_tolerance * scale,
        settings=settings,
        random_amplitudes=bool(ss.random_amplitudes),
        direction_weights=None if direction_weights is None else np.asarray(direction_weights, dtype=float),
    )


@dataclass(frozen=True)
class RealisationTimeSeries:
    """One realisation's saddle forces over time, downsampled, with lift-off marked.

    Attributes
    ----------
    index
        Realisation index.
    time_s
        (n_t,) sample times [s].
    wave_elevation_m
        (n_t,) wave elevation at midship [m].
    linear_saddle_force_N, nonlinear_saddle_force_N
        (n_t, n_s) compression-only saddle force of each model [N] (the linear one can be
        negative: the tension a bilateral saddle carries).
    saddle_lifted
        (n_t, n_s) a saddle was detached (nonlinear model) at some instant of the interval
        ``[t, t + dt)`` after the sample (dt = time_s[1] - time_s[0]).
    saddle_x_m
        (n_s,) saddle positions along the cargo [m].
    """

    index: int
    time_s: NDArray[np.float64]
    wave_elevation_m: NDArray[np.float64]
    linear_saddle_force_N: NDArray[np.float64]
    nonlinear_saddle_force_N: NDArray[np.float64]
    saddle_lifted: NDArray[np.bool_]
    saddle_x_m: NDArray[np.float64]


def _model_record(F: float, M: float, S: float, us: float, ud: float, lifted: float, events: int) -> dict[str, Any]:
    return {
        "F_N": float(F),
        "M_b_Nm": float(M),
        "sigma_b_Pa": float(S),
        "u_s_m": float(max(us, 0.0)),
        "u_d_m": float(max(ud, 0.0)),
        "time_lifted_fraction": float(lifted),
        "uplift_events": int(events),
    }


def _linear_maxima(plan: RealisationPlan, d_tot: NDArray, g: NDArray) -> tuple[dict[str, Any], NDArray, NDArray]:
    """The linear model's record, its per-sample maxima (n_tc, 4) and the moment's standard deviation per point [N m].

    ``d_tot``: the total saddle compressions (n_tc, n_s) [m]; ``g``: the moment field's
    coordinates on ``plan.moment_basis`` (n_tc, n_r) [N m]. Columns of the per-sample maxima:
    saddle force [N], compression [m], absolute moment [N m], stress [Pa].
    """
    U = plan.moment_basis
    k = plan.stiffness_N_per_m
    per_sample = _linear_samples(np.ascontiguousarray(d_tot), k, np.ascontiguousarray(g), U, plan.moment_static_Nm, plan.section_modulus_m3)
    force_t, comp_t, moment_t, stress_t = per_sample.T
    below = d_tot < 0.0
    lifted_t = below.any(axis=1)
    record = _model_record(
        force_t.max(),
        moment_t.max(),
        stress_t.max(),
        comp_t.max(),
        0.0,
        lifted_t.mean(),
        int(np.count_nonzero(~below[:-1] & below[1:])),
    )
    cov = np.cov(g, rowvar=False, bias=True).reshape(g.shape[1], g.shape[1])
    std_moment = np.sqrt(np.maximum(np.einsum("xr,rs,xs->x", U, cov, U), 0.0))
    return record, per_sample, std_moment


@dataclass
class _Windows:
    """What the nonlinear windows of one realisation found, summed (maxima: F, M_b, sigma_b, u_s, u_d)."""

    covered: NDArray[np.bool_]
    capture_every: int
    capture_compression: NDArray[np.float64]
    capture_lifted: NDArray[np.bool_]
    maxima: NDArray[np.float64] = field(default_factory=lambda: np.zeros(5))
    lifted_steps: int = 0
    events: int = 0
    windows: int = 0
    window_steps: int = 0
    solved: bool = True

    def add(self, out: WindowOutcome, start: int, ratio: int) -> None:
        """Count window ``out``, marched from fine step ``start``."""
        self.covered[start // ratio + 1 : out.end // ratio + 1] = True
        self.maxima = np.maximum(
            self.maxima,
            [out.max_saddle_force_N, out.max_bending_moment_Nm, out.max_bending_stress_Pa, out.max_compression_m, out.max_gap_m],
        )
        self.lifted_steps += out.lifted_steps
        self.events += out.uplift_events
        self.solved = self.solved and out.solved
        self.windows += 1
        self.window_steps += out.end - start


def _nonlinear_windows(plan: RealisationPlan, X: NDArray, d_tot: NDArray, factors: NDArray, capture: bool, transfer: NDArray) -> _Windows:
    """March the correction in every window the linear compressions trigger (the module docstring, step 2)."""
    grid, n_s, ratio = plan.grid, plan.saddle_count, plan.ratio
    n_tc = grid.samples
    abs_spec = np.abs(transfer[:, :n_s]) * (grid.amplitude_m * factors)[:, None]  # this record's amplitudes
    margin = grid.time_step_s**2 / 8.0 * (grid.omega_rad_s**2 @ abs_spec)  # largest dip between samples
    trigger = np.any(d_tot < margin, axis=1)
    n_fine = n_tc * ratio
    coef = np.ascontiguousarray(spline_filter1d(X, order=3, axis=0, mode="grid-wrap"))
    every = max(round(plan.settings.capture_step_s / grid.time_step_s), 1) if capture else 0
    n_b = n_tc // every if capture else 0
    tally = _Windows(np.zeros(n_tc, dtype=bool), every, np.zeros((n_b, n_s)), np.zeros((n_b, n_s), dtype=bool))
    starts = np.flatnonzero(trigger)
    position = -1  # last fine step marched
    while True:
        later = starts[starts > position // ratio + 1] if position >= 0 else starts
        if later.size == 0:
            break
        i = int(later[0])
        if i == 0:
            start, state = 0, MarchState.quasi_static(plan.system, d_tot[0])
            tally.covered[0] = True
            if capture:
                tally.capture_compression[0] = d_tot[0] - plan.system.saddle_displacement_m(state.eta, state.force_N)
        else:
            start, state = (i - 1) * ratio, MarchState.at_rest(plan.system)
        out = march_window(
            plan.system,
            coef,
            ratio,
            plan.compression_static_m,
            trigger,
            start,
            n_fine - 1,
            state,
            tolerance_m=plan.tolerance_m,
            moments=plan.moments,
            capture_every=every * ratio,
            capture_compression=tally.capture_compression,
            capture_lifted=tally.capture_lifted,
        )
        tally.add(out, start, ratio)
        position = out.end
        if out.end >= n_fine - 1:
            break
    return tally


def _time_series(
    plan: RealisationPlan, index: int, phases: NDArray, factors: NDArray, d_tot: NDArray, tally: _Windows
) -> RealisationTimeSeries:
    """The downsampled saddle forces of both models and the lift-off marks of a captured realisation."""
    grid, k = plan.grid, plan.stiffness_N_per_m
    rows = np.arange(tally.capture_lifted.shape[0]) * tally.capture_every
    lin_force = k * d_tot[rows]
    nl_comp = np.where(tally.covered[rows][:, None], tally.capture_compression, d_tot[rows])
    wave = synthesise(grid, phases, np.ones(grid.omega_rad_s.size), factors)[rows]
    return RealisationTimeSeries(
        int(index),
        np.asarray(rows * grid.time_step_s, dtype=np.float64),
        wave,
        lin_force,
        k * np.maximum(nl_comp, 0.0),
        tally.capture_lifted,
        plan.saddle_x_m,
    )


def evaluate_realisation(plan: RealisationPlan, index: int, capture: bool = False) -> tuple[dict[str, Any], RealisationTimeSeries | None]:
    """Maxima and uplift statistics of realisation ``index``, linear and nonlinear.

    Returns
    -------
    record, series
        ``record``: ``{"index", "linear": {...}, "nonlinear": {...}, "solved", "windows",
        "window_steps", "std_saddle_force_N", "std_bending_moment_Nm", "seconds"}`` (plain
        JSON types; per model the :data:`QUANTITIES` maxima, ``time_lifted_fraction`` [-] and
        ``uplift_events``; the linear standard deviations per saddle and per moment point
        over the record); ``series`` the downsampled time series when ``capture`` is set.
    """
    t0 = time.perf_counter()
    grid, n_s = plan.grid, plan.saddle_count
    phases = realisation_phases(plan.seed, index, grid.omega_rad_s.size)
    factors = amplitude_factors(plan.seed, index, grid.omega_rad_s.size, plan.random_amplitudes)
    transfer = plan.realisation_transfer(index)
    X = synthesise(grid, phases, transfer, factors)  # (n_tc, n_s + n_r)
    d_tot = plan.compression_static_m + X[:, :n_s]
    linear, per_sample, std_moment = _linear_maxima(plan, d_tot, X[:, n_s:])
    tally = _nonlinear_windows(plan, X, d_tot, factors, capture, transfer)
    nl = tally.maxima
    free = ~tally.covered
    if free.any():  # outside the windows the nonlinear response is the linear one
        force_t, comp_t, moment_t, stress_t = per_sample.T
        nl[:4] = np.maximum(nl[:4], [force_t[free].max(), moment_t[free].max(), stress_t[free].max(), comp_t[free].max()])
    nonlinear = _model_record(nl[0], nl[1], nl[2], nl[3], nl[4], tally.lifted_steps / (grid.samples * plan.ratio), tally.events)
    record = {
        "index": int(index),
        "linear": linear,
        "nonlinear": nonlinear,
        "solved": bool(tally.solved),
        "windows": int(tally.windows),
        "window_steps": int(tally.window_steps),
        "std_saddle_force_N": (plan.stiffness_N_per_m * X[:, :n_s].std(axis=0)).tolist(),
        "std_bending_moment_Nm": std_moment.tolist(),
        "seconds": time.perf_counter() - t0,
    }
    series = _time_series(plan, index, phases, factors, d_tot, tally) if capture else None
    return record, series
