"""Where the time-domain reference starts, and which orbit it reaches.

A cargo that lifts off its saddles is a non-smooth oscillator: one excitation can have several
periodic steady states (orbits), and a non-periodic (chaotic) motion beside them. On 1 % saddles
driven near 0.7 of the pitch mode (``docs/verification.md``) a lift-off orbit with 41 mm gaps
coexists with a bouncing motion with metre-high flights and 15-20 MN impacts; which one a time
integration settles on depends on where it starts. Both formulations of
:func:`~seafast.solvers.references.solve_time_domain` therefore start from the *same* state:

* :attr:`~seafast.config.modes.TimeDomainStart.LINEAR` (default): the linear periodic solution
  (every saddle bilateral) at t = 0, its displacement and velocity;
* :attr:`~seafast.config.modes.TimeDomainStart.GIVEN`: a given periodic solution (e.g. the
  harmonic balance's) at t = 0; the orbit reached is then compared with it
  (:func:`orbit_distance`) and a periodic state farther than ``orbit_tolerance`` is reported as
  :attr:`~seafast.solvers.outcome.SolverOutcome.OTHER_ORBIT`;
* :attr:`~seafast.config.modes.TimeDomainStart.QUASI_STATIC`: the exact-contact quasi-static
  state at t = 0 (the full-DOF formulation's former start), kept to reproduce what that start found
  (a bouncing, non-periodic motion on the bistable case of ``docs/orbits.md``).

The acceleration at t = 0 follows from each formulation's own equation of motion. Units: SI (m,
rad, N, s).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from seafast.config.modes import TimeDomainStart
from seafast.excitation.harmonic import HarmonicExcitation
from seafast.fourier import harmonics_up_to, resample_periodic, time_to_harmonics
from seafast.model.structure import StructuralModel
from seafast.solvers.exact_contact import BandedActiveSet
from seafast.solvers.linear import solve_linear
from seafast.solvers.outcome import OrbitRecord, SolverOutcome
from seafast.solvers.periodic import PeriodicResponse

__all__ = [
    "ORBIT_TOLERANCE",
    "StartState",
    "start_state",
    "orbit_distance",
    "orbit_outcome",
    "orbit_attributes",
    "settling_periods",
]

ORBIT_TOLERANCE = 0.05
"""Two periodic states closer than this (:func:`orbit_distance`) are one orbit.

Above what separates one orbit computed two ways (the time step, the contact law and the harmonic
truncation), 3e-5 between the adaptive HBM and the reference on the bistable case of the tests, 0.0038
on the base case, 0.012 for the source's tanh law with H = 5 there; below what separates coexisting
orbits, 0.13 between orbits A and C of the bistable case: about a factor 3 from each."""


@dataclass(frozen=True)
class StartState:
    """The state at t = 0 both formulations start from.

    Attributes
    ----------
    kind, method
        The :class:`~seafast.config.modes.TimeDomainStart` and what it came from (``"linear"``,
        ``"quasi_static"``, or the given solution's ``method``).
    displacement, velocity
        Cargo DOFs and their rates at t = 0 (n_c,) [m, rad], [m/s, rad/s].
    compression_m
        ``GIVEN`` only: the start orbit's saddle compressions over one period on the reference's
        grid ``t_n = n T / N`` (N, n_s) [m]; else None.
    harmonics
        ``GIVEN`` only: the harmonics the start's solution carries (its H; for samples N'/2 - 1): the
        orbits are compared through them.
    """

    kind: TimeDomainStart
    method: str
    displacement: NDArray[np.float64]
    velocity: NDArray[np.float64]
    compression_m: NDArray[np.float64] | None
    harmonics: int | None = None


def _series_at(harmonics: NDArray, omega: float, t: float, derivative: bool = False) -> NDArray[np.float64]:
    """``Re sum_k X_k e^{ik w t}`` (or its time derivative) at one time, X (n_k, ...)."""
    k = np.arange(harmonics.shape[0])
    phase = np.exp(1j * k * omega * t)
    if derivative:
        phase = phase * (1j * k * omega)
    return np.real(np.tensordot(phase, harmonics, axes=(0, 0)))


def _sample_harmonics(samples: NDArray) -> NDArray[np.complex128]:
    """Complex amplitudes X_k (``x = Re sum X_k e^{ik w t}``) of periodic samples (N', ...), k below N'/2: the
    Nyquist term of an even N' dropped (its phase, and rate, is not defined by the samples)."""
    return time_to_harmonics(samples, (samples.shape[0] - 1) // 2)


def start_state(
    model: StructuralModel,
    excitation: HarmonicExcitation,
    start: TimeDomainStart | PeriodicResponse,
    time_samples: int,
    time_step_s: float,
) -> StartState:
    """The state at t = 0 of ``start`` (see the module docstring).

    Raises
    ------
    ValueError
        For ``TimeDomainStart.GIVEN`` without a solution, or a given solution of another frequency or model.
    """
    omega = float(excitation.omega_rad_s)
    if isinstance(start, PeriodicResponse):
        r = start
        if not math.isclose(r.omega_rad_s, omega, rel_tol=1e-9):
            raise ValueError(f"start: a solution at {r.omega_rad_s!r} rad/s; allowed: one at the excitation's {omega!r} rad/s")
        if r.cargo_displacement_time_m.ndim != 2 or r.cargo_displacement_time_m.shape[1] != model.cargo_dof_count:
            raise ValueError(
                f"start: cargo displacements of shape {r.cargo_displacement_time_m.shape}; allowed: (samples, {model.cargo_dof_count})"
            )
        X = r.cargo_displacement_harmonics
        if X is None:
            X = _sample_harmonics(r.cargo_displacement_time_m)
            q0 = np.array(r.cargo_displacement_time_m[0], dtype=float)
        else:
            q0 = _series_at(X, omega, 0.0)
        v0 = _series_at(X, omega, 0.0, derivative=True)
        delta = resample_periodic(r.saddle_compression_time_m, time_samples)
        return StartState(TimeDomainStart.GIVEN, str(r.method), q0, v0, delta, int(X.shape[0] - 1))
    if start is TimeDomainStart.LINEAR:
        X = solve_linear(model, excitation).cargo_displacement
        return StartState(start, "linear", _series_at(X, omega, 0.0), _series_at(X, omega, 0.0, derivative=True), None)
    if start is TimeDomainStart.QUASI_STATIC:
        q = {n: _quasi_static(model, excitation, n * time_step_s) for n in (-1, 0, 1)}
        return StartState(start, "quasi_static", q[0], (q[1] - q[-1]) / (2.0 * time_step_s), None)
    raise ValueError(f"start = {start!r}; allowed: TimeDomainStart.LINEAR, TimeDomainStart.QUASI_STATIC or a PeriodicResponse")


def _quasi_static(model: StructuralModel, excitation: HarmonicExcitation, t: float) -> NDArray[np.float64]:
    """Exact-contact static state at time t: ``K_lin q = P(t) + B k_u max(z(t) - q_s, 0)`` (inertia neglected)."""
    K_lin, K_co, _, _ = model.dynamic_stiffness(0.0, include_saddles=False)
    K_lin, K_co = np.asarray(K_lin, dtype=float), np.asarray(K_co, dtype=float)
    omega = float(excitation.omega_rad_s)
    P = np.asarray(excitation.cargo_load_N, dtype=complex) - np.asarray(excitation.deck_displacement, dtype=complex) @ K_co.T
    P[0] = P[0].real + model.static_load_N
    z = _series_at(np.asarray(excitation.deck_displacement)[:, model.saddle_deck_dof], omega, t)
    k_u = np.asarray(model.saddle_unilateral_stiffness_N_per_m, dtype=float)
    tol_m = 1e-12 * max(float(np.max(np.abs(z))), 1e-3)
    q, _, _ = BandedActiveSet(K_lin, model.saddle_cargo_dof, k_u, tol_m).solve(_series_at(P, omega, t), z, np.ones(k_u.size, dtype=bool))
    return q


def orbit_distance(compression_m: NDArray, start_compression_m: NDArray, stiffness_N_per_m: NDArray, harmonics: int | None = None) -> float:
    """RMS saddle-force difference of two periodic states over the RMS saddle force of the second [-].

    Both (N, n_s) [m] on the same grid; forces with the exact law ``k_u max(delta, 0)``. ``harmonics``:
    compare the forces through their harmonics 0 .. H only (the second state's own content, e.g. an HBM
    start's H), so that what a truncated solution cannot carry (the ringing after a re-contact) does not
    count as a different orbit; None: every harmonic of the grid.
    """
    k = np.asarray(stiffness_N_per_m, dtype=float)
    f = k * np.maximum(compression_m, 0.0)
    f0 = k * np.maximum(start_compression_m, 0.0)
    if harmonics is not None and int(harmonics) + 1 < f.shape[0] // 2 + 1:
        f, f0 = (harmonics_up_to(x, int(harmonics)) for x in (f, f0))
    scale = max(float(np.sqrt(np.mean(f0**2))), 1.0)
    return float(np.sqrt(np.mean((f - f0) ** 2)) / scale)


def orbit_outcome(
    start: StartState,
    stiffness_N_per_m: NDArray,
    compression_m: NDArray,
    periodic: bool,
    periods: int,
    period_change: float,
    orbit_tolerance: float,
) -> tuple[SolverOutcome, OrbitRecord]:
    """The typed outcome of a time-domain run and its :class:`~seafast.solvers.outcome.OrbitRecord`.

    ``NOT_PERIODIC`` when no periodic state was reached; ``OTHER_ORBIT`` when a periodic state was
    reached from a given solution but lies farther than ``orbit_tolerance`` from it; else ``CONVERGED``.
    """
    distance = same = None
    if start.compression_m is not None:
        distance = orbit_distance(compression_m, start.compression_m, stiffness_N_per_m, start.harmonics)
        same = bool(distance <= orbit_tolerance) if periodic else None
    if not periodic:
        outcome = SolverOutcome.NOT_PERIODIC
    elif same is False:
        outcome = SolverOutcome.OTHER_ORBIT
    else:
        outcome = SolverOutcome.CONVERGED
    record = OrbitRecord(
        start.kind, start.method, bool(periodic), int(periods), float(period_change), distance, same, float(orbit_tolerance)
    )
    return outcome, record


def orbit_attributes(orbit: OrbitRecord | None) -> dict[str, object]:
    """An :class:`~seafast.solvers.outcome.OrbitRecord` as plain attributes (``results.nc``); empty for None.

    ``time_domain_start`` (``linear``, ``quasi_static`` or the given solution's method),
    ``time_domain_periods``, ``time_domain_orbit_distance_from_start`` [-] (NaN without a given start) and
    ``time_domain_orbit_tolerance`` [-].
    """
    if orbit is None:
        return {}
    distance = orbit.distance_from_start
    return {
        "time_domain_start": orbit.start_method,
        "time_domain_periods": int(orbit.periods),
        "time_domain_orbit_distance_from_start": math.nan if distance is None else float(distance),
        "time_domain_orbit_tolerance": float(orbit.orbit_tolerance),
    }


def settling_periods(model: StructuralModel, omega_rad_s: float, tolerance: float, *, minimum: int = 40, maximum: int = 2000) -> int:
    """Periods a time-domain run may take to settle: twice those a free vibration needs to decay by ``tolerance``.

    With ``D = alpha M + beta K_beam`` every mode, in every contact state (saddles lifted or not), decays at
    least at ``alpha / 2`` [1/s] (the beam part only adds), so ``ln(1/tolerance) / (alpha/2 T)`` periods bound
    the decay of the slowest one; twice that, within [``minimum``, ``maximum``]. Base case: 40 (the minimum);
    1 % saddles at 3.8 rad/s: 201.
    """
    sigma = 0.5 * float(model.rayleigh_alpha_per_s)
    period = 2.0 * math.pi / float(omega_rad_s)
    if sigma <= 0.0:
        return int(maximum)
    need = 2.0 * math.log(1.0 / min(max(float(tolerance), 1e-300), 0.5)) / (sigma * period)
    return int(min(max(math.ceil(need), minimum), maximum))
