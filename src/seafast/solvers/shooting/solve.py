"""The periodic response by shooting on the piecewise-linear correction system: exact events, closed-form segments.

The saddles' contact problem is piecewise linear (:mod:`seafast.solvers.shooting.states`). A periodic solution is
a state ``x0`` the period's flow maps onto itself, ``P(x0) = x0``; ``P`` is marched exactly
(:func:`~seafast.solvers.shooting.period.flow_period`) and its Jacobian, the monodromy matrix ``Phi``, comes with
it, so Newton's method ``x0 <- x0 - (Phi - I)^-1 (P(x0) - x0)`` converges in a few periods, whatever harmonics the
ringing after a re-contact would need. The start is the attractor the physical system heads for from the linear
periodic solution (``x0 = 0``, no correction): a few periods are marched before Newton takes over, and the orbit
found is checked for stability by its Floquet multipliers (the eigenvalues of ``Phi``). The only approximation is
the modal reduction of the correction system (modes up to ``cutoff_factor`` times the reference frequency, the
rest static through the residual flexibility): docs/theory.md, section 6, measures it. On stiff saddles it is
reduced on the lifted cargo's modes and the cutoff is doubled until the peaks settle
(:mod:`seafast.solvers.shooting.stiff`).

Units: SI (m, rad, N, s). Nothing here prints, reads or writes files.
"""

from __future__ import annotations

import logging
import math

import numpy as np
from numpy.typing import NDArray

from seafast.config.modes import SolverMethod
from seafast.excitation.harmonic import HarmonicExcitation
from seafast.fourier import harmonics_to_time, high_harmonic_energy_share, real_to_complex_harmonics, time_to_harmonics
from seafast.model.structure import StructuralModel
from seafast.solvers.hbm.condensed import CondensedOperators, condensed_operators
from seafast.solvers.modal_correction import CorrectionBasis, modal_basis
from seafast.solvers.outcome import SolverOutcome
from seafast.solvers.periodic import CargoHistory, PeriodicResponse
from seafast.solvers.shooting.failure import FAILURE_KEY, ShootingFailure
from seafast.solvers.shooting.options import ShootingOptions
from seafast.solvers.shooting.orbit import shoot_orbit
from seafast.solvers.shooting.period import PeriodFlow, TooManyEventsError
from seafast.solvers.shooting.states import ContactStates, SingularStateError
from seafast.solvers.shooting.stiff import STIFF_CANCELLATION, correction_system, settled_cutoff

__all__ = ["event_samples", "solve_shooting"]

logger = logging.getLogger(__name__)


def _reference_frequency_rad_s(model: StructuralModel, modes: int) -> float:
    """The highest of the cargo's ``modes`` lowest natural frequencies on bilateral saddles [rad/s] (cached modal basis)."""
    basis = modal_basis(model, 0.0)
    count = max(min(int(modes), model.saddle_count), 1)
    if basis.natural_frequency_rad_s.size >= count:
        return float(basis.natural_frequency_rad_s[count - 1])
    return float(model.natural_frequencies_rad_s(True, count=count)[-1])


def event_samples(model: StructuralModel, omega_rad_s: float, options: ShootingOptions) -> int:
    """Samples per period of the event grid: ``samples_per_mode`` per period of the reference frequency, a power of 2."""
    if options.time_samples is not None:
        return int(options.time_samples)
    need = options.samples_per_mode * _reference_frequency_rad_s(model, options.reference_modes) / float(omega_rad_s)
    return int(2 ** math.ceil(math.log2(max(need, options.minimum_samples))))


def solve_shooting(model: StructuralModel, excitation: HarmonicExcitation, options: ShootingOptions | None = None) -> PeriodicResponse:
    """The periodic steady state of the cargo on its unilateral saddles by exact-event shooting.

    Parameters
    ----------
    model, excitation
        The cargo model and its periodic excitation (at least one dynamic harmonic).
    options
        :class:`~seafast.solvers.shooting.ShootingOptions` (None: the defaults).

    Returns
    -------
    PeriodicResponse
        ``method = SolverMethod.SHOOTING``; samples on ``t_n = n T / N`` (N the event grid), cargo harmonics
        from them; ``options`` record the modes kept, the grid, the periods marched, the Newton steps, the
        events per period, the contact states visited and the largest Floquet multiplier.
    """
    opts = ShootingOptions() if options is None else options
    omega = float(excitation.omega_rad_s)
    ops = condensed_operators(model, excitation, max(excitation.harmonic_count - 1, 1))
    D = real_to_complex_harmonics(ops.linear_compression_m)
    N = event_samples(model, omega, opts)
    d_grid = harmonics_to_time(D, N)
    record: dict[str, int | float | str | bool | list[int] | None] = {"time_samples": N, "samples_per_mode": opts.samples_per_mode}
    if np.all(d_grid > 0.0):
        # the linear solution is the answer: it lives on the excitation's harmonics, a coarse grid carries it exactly
        note = "contact kept by the linear solution: exact"
        N_linear = min(N, opts.minimum_samples)
        record.update(time_samples=N_linear)
        return _response(model, ops, opts, None, None, N_linear, SolverOutcome.CONVERGED, 0.0, 0, 0, note, record)
    cutoff = opts.cutoff_factor * _reference_frequency_rad_s(model, opts.reference_modes)
    system = correction_system(model, cutoff, opts)
    # the states' eigendecompositions depend on the model and the modes kept, not on the excitation: the model keeps them
    key = f"shooting_states {system.basis.value} {system.mode_count} {cutoff:.17g}"
    dynamics = model.derived_cache.get(key)
    if not isinstance(dynamics, dict):
        dynamics = model.derived_cache[key] = {}
    states = ContactStates(system, D, omega, dynamics)
    record.update(modes=system.mode_count, cutoff_rad_s=cutoff, basis=system.basis.value, complete_basis=system.complete)
    scale = max(float(np.max(np.abs(d_grid))), 1e-6)
    try:
        orbit = shoot_orbit(states, N, scale, opts, ops.saddle_stiffness_N_per_m)
    except (SingularStateError, TooManyEventsError) as error:
        note = f"shooting: {error}"
        record[FAILURE_KEY] = ShootingFailure.SINGULAR_STATE if isinstance(error, SingularStateError) else ShootingFailure.TOO_MANY_EVENTS
        return _response(model, ops, opts, None, None, N, SolverOutcome.NOT_CONVERGED, math.inf, 0, 0, note, record)
    flow, residual, periods, steps, N, missed = orbit.flow, orbit.residual, orbit.periods, orbit.newton_steps, orbit.samples, orbit.missed
    samples = (orbit.compression_m, orbit.correction_N)
    largest, converged = orbit.floquet_multiplier_max, orbit.converged
    target, times = orbit.residual_target, orbit.times
    record.update(
        time_samples=N,
        periods=periods,
        newton_steps=steps,
        events=flow.events,
        contact_states=states.visited,
        floquet_multiplier_max=largest,
        peak_missed_by_grid=float(np.max(missed, initial=0.0)),
        residual_target=float(target),
    )
    if flow.peaks is not None:
        record.update(guard_sub_steps=flow.peaks.sub_steps)
    note = (
        f"exact-event shooting: {system.mode_count} modes up to {cutoff:.4g} rad/s, {N} samples per period, "
        f"{flow.events} events per period, {periods} period(s) marched, {steps} Newton step(s), residual {residual:.2g}, "
        f"largest Floquet multiplier {largest:.4f}, sampled peaks within {float(np.max(missed, initial=0.0)):.1g} of the continuous ones"
    )
    if not converged:
        note += "; not converged" if residual > target else "; the orbit found is unstable"
        record[FAILURE_KEY] = ShootingFailure.NOT_PERIODIC if residual > target else ShootingFailure.UNSTABLE_ORBIT
    outcome = SolverOutcome.CONVERGED if converged else SolverOutcome.NOT_CONVERGED
    response = _response(model, ops, opts, states, flow, N, outcome, residual, steps, periods, note, record, missed, samples, times)
    stiff = system.basis is CorrectionBasis.LIFTED or states.cancellation > STIFF_CANCELLATION
    if converged and opts.cutoff_check and stiff and not system.complete:
        # stiff saddles: the modal reduction is checked by the same solve with the cutoff doubled until the peaks settle
        return settled_cutoff(solve_shooting, model, excitation, opts, response, states.cancellation)
    return response


def _response(
    model: StructuralModel,
    ops: CondensedOperators,
    opts: ShootingOptions,
    states: ContactStates | None,
    flow: PeriodFlow | None,
    N: int,
    outcome: SolverOutcome,
    residual: float,
    iterations: int,
    periods: int,
    note: str,
    record: dict,
    missed: NDArray | None = None,
    samples: tuple[NDArray, NDArray] | None = None,
    times: NDArray | None = None,
) -> PeriodicResponse:
    """The :class:`PeriodicResponse` of the samples (the linear solution where no correction is needed).

    ``missed``: per saddle, how much of its peak force the grid misses (the response's ``truncation_error``: the
    error of the sampled peaks, the only discretisation the shooting has); None: nothing missed (zeros).
    ``samples``: the flow's compressions and correction forces (:func:`~seafast.solvers.shooting.orbit.sampled_contact`);
    ``times``: each sample's time where some are not the grid's (:func:`~seafast.solvers.shooting.orbit.with_peaks`; None: the grid's).
    """
    omega = ops.omega_rad_s
    k_u = ops.saddle_stiffness_N_per_m
    H = N // 2 - 1
    t = np.arange(N, dtype=float) * (2.0 * np.pi / omega / N) if times is None else times
    X_lin = ops.linear_cargo_displacement[: H + 1]
    # q = basis @ coefficients: the linear solution's cos/sin columns, the modal coordinates and the correction forces
    columns = [np.ones((N, 1))] + [f(k * omega * t)[:, None] for k in range(1, X_lin.shape[0]) for f in (np.cos, np.sin)]
    rows = [X_lin[0].real[None, :]] + [r[None, :] for k in range(1, X_lin.shape[0]) for r in (X_lin[k].real, -X_lin[k].imag)]
    if states is not None and flow is not None and samples is not None:
        assert flow.state_samples is not None
        s = states.system
        delta, correction = samples
        columns += [flow.state_samples[:, : s.mode_count], correction]
        rows += [s.mode_shape.T, s.residual_displacement_m_per_N.T]
    else:
        delta = harmonics_to_time(real_to_complex_harmonics(ops.linear_compression_m), N)  # the linear solution
    basis, coefficients = np.hstack(columns), np.vstack(rows)
    # the cargo's displacements on harmonics 0 .. N/2 - 1 (the samples then exactly those harmonics): the few
    # channels' harmonics and their samples without the Nyquist term, kept factored (the (N, n_c) samples and
    # harmonics formed only where they are read: a study's moments come from the few channels)
    spectrum = time_to_harmonics(basis, H)
    alternating = np.where(np.arange(N) % 2 == 0, 1.0, -1.0)
    basis -= np.outer(alternating, alternating @ basis / N)  # the Nyquist term of each channel (as the inverse FFT would drop it)
    history = CargoHistory(basis, spectrum, coefficients)
    force = k_u * np.maximum(delta, 0.0)
    record = dict(
        record, harmonics=H, harmonics_selection="shooting", tolerance=float(opts.tolerance), cutoff_factor=float(opts.cutoff_factor)
    )
    return PeriodicResponse(
        method=SolverMethod.SHOOTING,
        omega_rad_s=float(omega),
        cargo_history=history,
        saddle_compression_time_m=delta,
        saddle_force_time_N=force,
        outcome=outcome,
        residual_norm=float(residual),
        iterations=int(iterations),
        message=note,
        harmonic_truncation_indicator=high_harmonic_energy_share(force, H),
        function_evaluations=int(periods),
        options=record,
        truncation_error=np.zeros(k_u.size) if missed is None else np.asarray(missed, dtype=float),
    )
