"""The nonlinear Monte Carlo reference of a sea state: realisations, extreme-value statistics, resumable runs.

``run_monte_carlo(case, directory)`` draws ``sea_state.realisations`` random-phase records of
``sea_state.duration_s`` (:mod:`seafast.analyses.seastate.synthesis`), evaluates each for the linear
(bilateral-saddle) and the nonlinear (compression-only saddles, exact contact) model
(:mod:`seafast.analyses.seastate.realisation`, integrator :mod:`seafast.solvers.transient`), stores each
realisation as it finishes in ``DIR/monte_carlo/`` (``manifest.json``, ``records.jsonl``: the
shared resumable store :class:`seafast.parallel.store.RecordStore`; a killed run resumes without
loss or duplication; more realisations later extend the same store, since realisation i depends
only on ``sea_state.seed`` and i), runs them on the shared executor
(:func:`seafast.parallel.executor.map_batches`: serial, local worker processes or Dask, one
realisation a task), and estimates per quantity the most probable maximum over the duration with
a bootstrap confidence interval (:mod:`seafast.analyses.seastate.extremes`).

The linear Monte Carlo is the exact frequency-domain synthesis of the linear model (the
integrator with bilateral saddles has no correction to march: q_c = 0); it checks the synthesis
against the spectral method (same transfer functions), and the nonlinear model differs from it
only where a saddle lifts off.

Size: over 400 lines as ruff formats it (one keyword argument a line in a call that does not fit on
one line; about 380 lines before): the plan, the resumable run and its statistics share the run's
fingerprint and result record.
"""

from __future__ import annotations

import hashlib
import json
import math
import time
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import xarray as xr
from numpy.typing import NDArray

from seafast.analyses.seastate.cradle_friction_realisation import (
    FrictionalRealisationPlan,
    case_frictional_plan,
    evaluate_frictional_cradle_realisation,
)
from seafast.analyses.seastate.cradle_realisation import CradleRealisationPlan, evaluate_cradle_realisation
from seafast.analyses.seastate.cradle_statistics import CradleStatistics, cradle_statistics, cradle_statistics_variables
from seafast.analyses.seastate.extremes import CONFIDENCE_LEVEL, MPMEstimate, most_probable_maximum
from seafast.analyses.seastate.realisation import (
    QUANTITIES,
    MonteCarloSettings,
    RealisationPlan,
    RealisationTimeSeries,
    evaluate_realisation,
    realisation_plan,
)
from seafast.config.schema import Case
from seafast.parallel.executor import ExecutionOptions, error_text, map_batches, plan_batches
from seafast.parallel.progress import progress as progress_reporter
from seafast.parallel.store import DICT_RECORDS, RecordStore
from seafast.parallel.threads import one_blas_thread

__all__ = [
    "MODELS",
    "STORE_DIRECTORY",
    "MonteCarloStatistics",
    "MonteCarloResult",
    "MonteCarloSettings",
    "RealisationTimeSeries",
    "build_plan",
    "build_cradle_plan",
    "run_monte_carlo",
    "statistics_from_records",
    "benchmark_realisation",
]

MODELS: tuple[str, ...] = ("linear", "nonlinear")
STORE_DIRECTORY = "monte_carlo"
"""Subdirectory of the output directory holding the resumable store."""

_NUMERICS_VERSION = 1  # bump when a change alters stored realisations (the fingerprint then refuses old stores)
_CRADLE_VERSION = 1  # off head seas the records hold the cradle extremes: stores without them are another run
_CRADLE_FRICTION_VERSION = 1  # on frictional pads the nonlinear cradle extremes are the frictional march's

_UNITS = {"F_N": "N", "M_b_Nm": "N m", "sigma_b_Pa": "Pa", "u_s_m": "m", "u_d_m": "m"}
_LONG = {
    "F_N": "maximum saddle normal force over the duration (still water included)",
    "M_b_Nm": "maximum absolute cargo bending moment over the cargo and the duration (still water included)",
    "sigma_b_Pa": "maximum absolute cargo bending stress M_b (D/2)/I over the cargo and the duration (still water included)",
    "u_s_m": "maximum saddle compression over the duration (still water included)",
    "u_d_m": "maximum saddle detachment gap over the duration (0 for the linear model: bilateral saddles)",
}


@dataclass(frozen=True)
class MonteCarloStatistics:
    """Statistics of one model (``linear`` or ``nonlinear``) over the realisations.

    Attributes
    ----------
    model
        ``linear`` (bilateral saddles) or ``nonlinear`` (compression-only saddles).
    maxima
        Per realisation (n_r,), keys ``F_N, M_b_Nm, sigma_b_Pa, u_s_m, u_d_m``: maxima over the
        duration, totals including still water [N, N m, Pa, m, m]; NaN for a failed realisation.
    mpm
        Most probable maximum over the duration per key (see :mod:`seafast.analyses.seastate.extremes`).
    mpm_interval
        (low, high) bootstrap confidence interval of the MPM at ``confidence_level``.
    uplift_per_hour
        Mean number of uplift events (a saddle going from compressed to detached, summed over
        saddles) per hour [1/h]; 0 without lift-off.
    time_lifted_fraction
        Per realisation, the fraction of the duration with at least one saddle detached [-].
    uplift_events
        Per realisation, the number of uplift events.
    converged
        Every realisation was evaluated and every step's contact problem solved exactly.
    mpm_method
        Estimator per key: ``gumbel_mode``, ``empirical_quantile`` or ``constant``.
    confidence_level
        Level of the intervals.
    failed
        Realisations that failed (index -> error text).
    """

    model: str
    maxima: Mapping[str, NDArray[np.float64]]
    mpm: Mapping[str, float]
    mpm_interval: Mapping[str, tuple[float, float]]
    uplift_per_hour: float
    time_lifted_fraction: NDArray[np.float64]
    uplift_events: NDArray[np.int64]
    converged: bool
    mpm_method: Mapping[str, str] = field(default_factory=dict)
    confidence_level: float = CONFIDENCE_LEVEL
    failed: Mapping[int, str] = field(default_factory=dict)

    def row(self) -> dict[str, Any]:
        """The (model, monte_carlo) row of seastate.csv."""
        return {
            "model": self.model,
            "method": "monte_carlo",
            **{q: float(self.mpm[q]) for q in QUANTITIES},
            "uplift_per_hour": float(self.uplift_per_hour),
            "converged": bool(self.converged),
        }


@dataclass(frozen=True)
class MonteCarloResult:
    """Linear and nonlinear Monte Carlo statistics of one sea state.

    Attributes
    ----------
    linear, nonlinear
        Statistics per model.
    example
        One realisation's saddle forces over time (the one with the most nonlinear uplift
        events), downsampled, lift-off marked.
    duration_s, seed
        Record length [s] and phase seed.
    settings
        The numerical settings of the run (time steps, modes, tolerances; plain values).
    std_saddle_force_N
        (n_r, n_s) linear standard deviation of each saddle force over each record [N].
    std_bending_moment_Nm
        (n_r, n_x) linear standard deviation of the moment at each point over each record [N m].
    moment_x_m, saddle_x_m
        Positions of the moment points and the saddles along the cargo [m].
    seconds
        Wall time per realisation [s] (n_r,), NaN where reused from the store.
    reused
        Realisations found in the store (not recomputed by this run).
    cradle
        Off head seas the cargo on its cradles' statistics, linear and nonlinear
        (:mod:`seafast.analyses.seastate.cradle_realisation`); None at head seas.
    """

    linear: MonteCarloStatistics
    nonlinear: MonteCarloStatistics
    example: RealisationTimeSeries | None
    duration_s: float
    seed: int
    settings: Mapping[str, Any]
    std_saddle_force_N: NDArray[np.float64]
    std_bending_moment_Nm: NDArray[np.float64]
    moment_x_m: NDArray[np.float64]
    saddle_x_m: NDArray[np.float64]
    seconds: NDArray[np.float64]
    reused: int = 0
    cradle: tuple[CradleStatistics, CradleStatistics] | None = None

    def to_dataset(self) -> xr.Dataset:
        """Per-realisation maxima and uplift statistics, MPMs and intervals, the example series.

        Variables are prefixed ``mc_``; dimensions ``model`` (linear, nonlinear),
        ``realisation``, ``saddle``, ``x_moment_m`` and ``mc_example_time_s``; ``units`` and
        ``long_name`` on every variable.
        """
        random_amplitudes = bool(self.settings.get("random_amplitudes", True))
        # deterministic amplitudes: the maxima scatter less between records than in a Gaussian sea (docs/monte_carlo.md)
        caveat = "" if random_amplitudes else " (deterministic amplitudes: narrower than for a Gaussian sea)"
        dv: dict[str, Any] = {}
        for q in QUANTITIES:
            dv.update(_quantity_variables(self, q, caveat))
        dv.update(_record_variables(self))
        if self.cradle is not None:
            dv.update(cradle_statistics_variables(self.cradle))
        coords = _coordinates(self)
        if self.example is not None:
            coords.update(_example_coordinate(self.example))
            dv.update(_example_variables(self.example))
        return xr.Dataset(dv, coords=coords, attrs=_attributes(self, random_amplitudes))


def _quantity_variables(result: MonteCarloResult, q: str, caveat: str) -> dict[str, Any]:
    """One quantity's per-realisation maxima, MPMs and interval bounds, both models."""
    stats, u, ln = (result.linear, result.nonlinear), _UNITS[q], _LONG[q]
    level = f"{result.linear.confidence_level:.0%}"
    return {
        f"mc_{q}": (("model", "realisation"), np.stack([s.maxima[q] for s in stats]), {"units": u, "long_name": f"{ln}, per realisation"}),
        f"mc_mpm_{q}": (
            ("model",),
            np.array([s.mpm[q] for s in stats]),
            {"units": u, "long_name": f"most probable maximum: {ln}", "method": ", ".join(s.mpm_method.get(q, "") for s in stats)},
        ),
        f"mc_mpm_low_{q}": (
            ("model",),
            np.array([s.mpm_interval[q][0] for s in stats]),
            {"units": u, "long_name": f"lower bound of the {level} bootstrap interval of the MPM of {q}{caveat}"},
        ),
        f"mc_mpm_high_{q}": (
            ("model",),
            np.array([s.mpm_interval[q][1] for s in stats]),
            {"units": u, "long_name": f"upper bound of the {level} bootstrap interval of the MPM of {q}{caveat}"},
        ),
    }


def _record_variables(result: MonteCarloResult) -> dict[str, Any]:
    """Uplift statistics per record and model, the records' linear standard deviations, wall times."""
    stats = (result.linear, result.nonlinear)
    return {
        "mc_time_lifted_fraction": (
            ("model", "realisation"),
            np.stack([s.time_lifted_fraction for s in stats]),
            {"units": "1", "long_name": "fraction of the duration with at least one saddle detached (linear: compression below zero)"},
        ),
        "mc_uplift_events": (
            ("model", "realisation"),
            np.stack([s.uplift_events for s in stats]),
            {"units": "1", "long_name": "saddle separations (compressed to detached), summed over saddles"},
        ),
        "mc_uplift_per_hour": (
            ("model",),
            np.array([s.uplift_per_hour for s in stats]),
            {"units": "1/h", "long_name": "mean saddle separations per hour, summed over saddles"},
        ),
        "mc_std_saddle_force_N": (
            ("realisation", "saddle"),
            result.std_saddle_force_N,
            {"units": "N", "long_name": "standard deviation of the linear saddle force over the record"},
        ),
        "mc_std_bending_moment_Nm": (
            ("realisation", "x_moment_m"),
            result.std_bending_moment_Nm,
            {"units": "N m", "long_name": "standard deviation of the linear bending moment over the record"},
        ),
        "mc_seconds": (
            ("realisation",),
            result.seconds,
            {"units": "s", "long_name": "wall time of the realisation (NaN: reused from the store)"},
        ),
    }


def _coordinates(result: MonteCarloResult) -> dict[str, Any]:
    n_r = result.linear.time_lifted_fraction.size
    return {
        "model": ("model", list(MODELS), {"long_name": "response model (linear: bilateral saddles)"}),
        "realisation": (
            "realisation",
            np.arange(n_r),
            {"units": "1", "long_name": "realisation index (phases from SeedSequence(seed) child i)"},
        ),
        "saddle": ("saddle", np.arange(result.saddle_x_m.size), {"units": "1", "long_name": "saddle index, aft to fore"}),
        "x_moment_m": ("x_moment_m", result.moment_x_m, {"units": "m", "long_name": "position along the cargo from its aft end"}),
    }


def _example_coordinate(ex: RealisationTimeSeries) -> dict[str, Any]:
    return {"mc_example_time_s": ("mc_example_time_s", ex.time_s, {"units": "s", "long_name": f"time in example realisation {ex.index}"})}


def _example_variables(ex: RealisationTimeSeries) -> dict[str, Any]:
    """The example realisation's wave, saddle forces (both models) and lift-off over its window."""
    return {
        "mc_example_wave_elevation_m": (
            ("mc_example_time_s",),
            ex.wave_elevation_m,
            {"units": "m", "long_name": "wave elevation at midship"},
        ),
        "mc_example_saddle_force_N": (
            ("model", "mc_example_time_s", "saddle"),
            np.stack([ex.linear_saddle_force_N, ex.nonlinear_saddle_force_N]),
            {"units": "N", "long_name": "saddle normal force (compression-only part; linear may be negative)"},
        ),
        "mc_example_saddle_lifted": (
            ("mc_example_time_s", "saddle"),
            ex.saddle_lifted.astype(np.int8),
            {"units": "1", "long_name": "saddle detached (nonlinear) within the sample's interval"},
        ),
    }


def _attributes(result: MonteCarloResult, random_amplitudes: bool) -> dict[str, Any]:
    return {
        "mc_duration_s": result.duration_s,
        "mc_seed": result.seed,
        "mc_realisations": result.linear.time_lifted_fraction.size,
        "mc_confidence_level": result.linear.confidence_level,
        "mc_mpm_estimator": (
            "mode of a maximum-likelihood Gumbel fit to the maxima (1/e quantile where some maxima are 0); percentile bootstrap interval"
        ),
        "mc_random_amplitudes": int(random_amplitudes),
        "mc_example_realisation": -1 if result.example is None else result.example.index,
        "mc_settings_json": json.dumps(dict(result.settings)),
    }


# ---------------------------------------------------------------------------- plan and fingerprint
def build_plan(case: Case, settings: MonteCarloSettings = MonteCarloSettings()) -> RealisationPlan:
    """The case's realisation plan (spectrum, transfer functions, still water, integrator).

    Raises
    ------
    seafast.config.CaseError
        Invalid or unresolvable sea state, or a vessel set-up without per-frequency hull response.
    """
    from seafast.analyses.seastate.directional_transfer import sea_state_quadrature, sea_state_roll_damping, sea_state_transfer
    from seafast.analyses.seastate.spectrum import sea_state_spectrum
    from seafast.analyses.seastate.transfer import still_water
    from seafast.model.from_case import build_model

    model = build_model(case)
    spectrum = sea_state_spectrum(case)
    roll = sea_state_roll_damping(case, spectrum)  # the spectral analysis's B_eq, from the same spectrum
    if case.sea_state.spreading_exponent is None:
        still = still_water(case, model)
        return realisation_plan(case, model, spectrum, lambda w: sea_state_transfer(case, model, w, roll).mean, still, settings)
    weights = sea_state_quadrature(case).weight
    return realisation_plan(
        case, model, spectrum, lambda w: sea_state_transfer(case, model, w, roll).per_direction, still_water(case, model), settings, weights
    )


def build_cradle_plan(case: Case) -> CradleRealisationPlan | None:
    """Off head seas the plan of the cargo on its cradles' realisations (the same sea); None at head seas."""
    from seafast.analyses.seastate.cradle_extremes import is_off_head_seas
    from seafast.analyses.seastate.cradle_realisation import cradle_realisation_plan
    from seafast.analyses.seastate.cradle_transfer import cradle_sea_model, cradle_still_water, cradle_transfer_functions
    from seafast.analyses.seastate.directional_transfer import sea_state_quadrature, sea_state_roll_damping, sea_state_transfer
    from seafast.analyses.seastate.spectrum import sea_state_spectrum
    from seafast.model.from_case import build_model

    if not is_off_head_seas(case):
        return None
    model, spectrum = build_model(case), sea_state_spectrum(case)
    roll, sea = sea_state_roll_damping(case, spectrum), cradle_sea_model(case, model)
    weights = None if case.sea_state.spreading_exponent is None else sea_state_quadrature(case).weight
    per = lambda w: [cradle_transfer_functions(sea, tf) for tf in sea_state_transfer(case, model, w, roll).per_direction]  # noqa: E731
    return cradle_realisation_plan(case, spectrum, per, sea.dynamics, cradle_still_water(sea), direction_weights=weights)


def _fingerprint(case: Case, settings: MonteCarloSettings, plan: RealisationPlan, cradle: bool = False, friction: bool = False) -> str:
    """Identity of a run's realisations.

    The case without the realisation count and name, the settings, and the plan's amplitudes and
    transfer functions to 10 significant digits (so a changed input file behind an unchanged
    path, e.g. a spectrum table, is a different run).
    """
    data = json.loads(case.model_dump_json())
    sea = data.get("sea_state", {})
    sea.pop("realisations", None)
    if sea.get("heading_deg") == 180.0 and sea.get("spreading_exponent") is None:  # head seas, long-crested: as before the keys
        sea.pop("heading_deg", None)
        sea.pop("spreading_exponent", None)
    data.pop("name", None)
    identity = (
        {"case": data, "settings": settings.__dict__, "numerics": _NUMERICS_VERSION}
        | ({"cradle": _CRADLE_VERSION} if cradle else {})
        | ({"cradle_friction": _CRADLE_FRICTION_VERSION} if friction else {})
    )
    blob = json.dumps(identity, sort_keys=True, default=str)
    digest = hashlib.sha256(blob.encode("utf-8"))
    for array in (plan.grid.amplitude_m, plan.transfer.real, plan.transfer.imag, plan.compression_static_m):
        scale = float(np.max(np.abs(array))) or 1.0
        digest.update((np.round(np.asarray(array) / scale, 10) + 0.0).tobytes())  # + 0.0: no negative zeros
    return digest.hexdigest()[:16]


def _realisations(
    plans: tuple[RealisationPlan, CradleRealisationPlan | None, FrictionalRealisationPlan | None], indices: list[int]
) -> list[dict[str, Any]]:
    """The records of a batch of realisations (off head seas with their ``cradle`` part, its nonlinear model the
    frictional march's on frictional pads); one that fails is a record with its error text (the run goes on)."""
    plan, cradle, friction = plans
    records = []
    for index in indices:
        t0 = time.perf_counter()
        try:
            record = evaluate_realisation(plan, index)[0]
            if cradle is not None:
                record["cradle"] = {k: v for k, v in evaluate_cradle_realisation(cradle, index).items() if k != "index"}
                if friction is not None:  # the frictionless windows' nonlinear model replaced
                    frictional = evaluate_frictional_cradle_realisation(cradle, friction, index)
                    frictional["seconds"] += record["cradle"]["seconds"]
                    record["cradle"].update(frictional)
            records.append(record)
        except Exception as exc:  # noqa: BLE001 - any failure of one realisation is recorded
            records.append({"index": int(index), "error": error_text(exc), "seconds": time.perf_counter() - t0})
    return records


# ---------------------------------------------------------------------------- statistics
def _model_statistics(model: str, records: list[dict[str, Any]], duration_s: float, seed: int) -> MonteCarloStatistics:
    ok = [r for r in records if "error" not in r]
    maxima = {q: np.array([r[model][q] if "error" not in r else np.nan for r in records]) for q in QUANTITIES}
    estimates: dict[str, MPMEstimate] = {q: most_probable_maximum(maxima[q], seed=seed + i) for i, q in enumerate(QUANTITIES)}
    lifted = np.array([r[model]["time_lifted_fraction"] if "error" not in r else np.nan for r in records])
    events = np.array([r[model]["uplift_events"] if "error" not in r else -1 for r in records], dtype=np.int64)
    per_hour = float(np.mean(events[events >= 0]) / (duration_s / 3600.0)) if ok else math.nan
    failed = {int(r["index"]): str(r["error"]) for r in records if "error" in r}
    converged = not failed and all(bool(r.get("solved", True)) for r in ok)
    return MonteCarloStatistics(
        model=model,
        maxima=maxima,
        mpm={q: e.value for q, e in estimates.items()},
        mpm_interval={q: e.interval for q, e in estimates.items()},
        uplift_per_hour=per_hour,
        time_lifted_fraction=lifted,
        uplift_events=events,
        converged=converged,
        mpm_method={q: e.method for q, e in estimates.items()},
        failed=failed,
    )


def statistics_from_records(
    records: list[dict[str, Any]], duration_s: float, seed: int
) -> tuple[MonteCarloStatistics, MonteCarloStatistics]:
    """Linear and nonlinear statistics of realisation records (ordered by index)."""
    return _model_statistics("linear", records, duration_s, seed), _model_statistics("nonlinear", records, duration_s, seed)


# ---------------------------------------------------------------------------- the run
def run_monte_carlo(
    case: Case,
    directory: str | Path,
    *,
    workers: int | None = None,
    scheduler: str | None = None,
    progress: bool = True,
    settings: MonteCarloSettings = MonteCarloSettings(),
) -> MonteCarloResult:
    """Run (or resume) the Monte Carlo reference of the case's sea state.

    Parameters
    ----------
    case
        The case; its ``sea_state`` gives Hs, Tp, spectrum, duration, realisations and seed.
    directory
        Output directory; the resumable store goes to ``DIR/monte_carlo/``.
    workers
        Local processes (None: all cores; 1: serial in this process).
    scheduler
        Dask scheduler address; overrides ``workers``.
    progress
        Show progress on stderr (:func:`seafast.parallel.progress.progress`: a bar on a terminal,
        else a plain line every few per cent).
    settings
        Numerical settings (defaults verified by the tests).

    Returns
    -------
    MonteCarloResult
        A realisation that fails is recorded with its error (statistics over the others,
        ``converged = False``); non-convergence is never raised.

    Raises
    ------
    seafast.config.CaseError
        Invalid sea state (from the spectrum or the transfer functions).
    seafast.parallel.errors.ParallelError
        The directory holds another run (:class:`~seafast.parallel.errors.ForeignStoreError`), or
        the scheduler cannot be reached.
    """
    plan, cradle_plan = build_plan(case, settings), build_cradle_plan(case)
    friction_plan = None if cradle_plan is None else case_frictional_plan(case, cradle_plan)
    n_r = int(case.sea_state.realisations)
    fingerprint = _fingerprint(case, settings, plan, cradle_plan is not None, friction_plan is not None)
    described = plan.describe() | ({} if cradle_plan is None else cradle_plan.describe())
    manifest = {"case": case.name, "duration_s": plan.duration_s, "seed": plan.seed, "settings": described}
    seconds = np.full(n_r, np.nan)
    execution = ExecutionOptions(workers=workers, scheduler=scheduler, batch_size=1, progress=progress)
    with RecordStore(Path(directory) / STORE_DIRECTORY, fingerprint, manifest, DICT_RECORDS) as store:
        pending = store.pending(n_r)
        reused = n_r - len(pending)
        bar = progress_reporter(n_r, reused, label=f"Monte Carlo {case.name}", unit="realisations", enabled=progress and bool(pending))
        try:
            batches = plan_batches(pending, execution.worker_count(), execution.batch_size)
            for batch in map_batches(_realisations, (plan, cradle_plan, friction_plan), batches, execution):
                bar.update(store.append(batch))
                for record in batch:
                    if 0 <= int(record["index"]) < n_r:
                        seconds[int(record["index"])] = float(record.get("seconds", np.nan))
        finally:
            bar.close()
        records = [store.completed[i] for i in range(n_r)]
    linear, nonlinear = statistics_from_records(records, plan.duration_s, plan.seed)
    ok = [r for r in records if "error" not in r]
    example = None
    if ok:
        chosen = max(ok, key=lambda r: (r["nonlinear"]["uplift_events"], -r["index"]))
        example = evaluate_realisation(plan, int(chosen["index"]), capture=True)[1]
    nan_s = np.full(plan.saddle_count, np.nan)
    nan_x = np.full(plan.moment_x_m.size, np.nan)
    return MonteCarloResult(
        linear=linear,
        nonlinear=nonlinear,
        example=example,
        duration_s=plan.duration_s,
        seed=plan.seed,
        settings=described,
        std_saddle_force_N=np.array([r.get("std_saddle_force_N", nan_s) for r in records], dtype=float),
        std_bending_moment_Nm=np.array([r.get("std_bending_moment_Nm", nan_x) for r in records], dtype=float),
        moment_x_m=plan.moment_x_m,
        saddle_x_m=plan.saddle_x_m,
        seconds=seconds,
        reused=reused,
        cradle=None
        if cradle_plan is None
        else (cradle_statistics("linear", records, plan.seed), cradle_statistics("nonlinear", records, plan.seed)),
    )


# ---------------------------------------------------------------------------- benchmark
BENCHMARK_SEA_STATE: dict[str, float] = {"sea_state.significant_height_m": 3.0, "sea_state.peak_period_s": 10.0}
"""The benchmark's sea state on the base case (the base case lifts off there: ~2.7 events per hour, linear spectral)."""


def benchmark_realisation(overrides: Mapping[str, Any] | None = None, index: int = 1) -> float:
    """Seconds for one 3-hour nonlinear realisation of the base case on one core.

    The base case in Hs = 3 m, Tp = 10 s (JONSWAP): saddles lift off there. The plan (transfer
    functions, modes) is built first and the kernels compiled on a first realisation; the
    figure is the wall time of realisation ``index`` (synthesis, linear maxima, windows,
    statistics of the record), BLAS on one thread.
    """
    from seafast.config.loader import load_case

    case = load_case(None, {**BENCHMARK_SEA_STATE, "sea_state.duration_s": 10800.0, **dict(overrides or {})})
    with one_blas_thread():
        plan = build_plan(case)
        evaluate_realisation(plan, 0)  # compile / load the kernels
        t0 = time.perf_counter()
        evaluate_realisation(plan, int(index))
        return time.perf_counter() - t0
