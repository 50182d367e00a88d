"""Harmonic balance with AFT for the cargo's axial stick-slip (docs/axial.md).

The problem (:class:`~seafast.solvers.axial.problem.AxialProblem`): the 2H+1 real harmonic
coefficients of the axial displacement ``u(t)``, the residual ``Z X + DFT[f_J + f_s] - F`` of the
rigid cargo's single axial DOF with the friction as a Jenkins element (the contacts' tangential
stiffness ``k_t`` in series with the Coulomb slider of capacity ``C(t)``). At the default
stiffness (1e12 N/m per saddle, a rigid contact) the periodic solution does not depend on it
(tests: 1e11 to 1e13 N/m agree to 1e-4) and converges to the rigid-Coulomb time-domain reference.

The shared Newton (:func:`seafast.solvers.newton.newton`, with
:data:`~seafast.solvers.axial.problem.AXIAL_GLOBALISATION`) from several starts, one after the other until one converges to a real periodic
state: stuck (exact when the friction holds: zero iterations), locked at the edge of the lock
range (shakedown), a given neighbouring solution, sliding all period (the describing function)
and frictionless, then a continuation in the contact stiffness from a soft (regularised) law to
the rigid one. A slip-free solution must pass the rigid-Coulomb check
(:func:`~seafast.solvers.axial.problem.lock_check`): the truncated series can balance the
harmonics on a locked state whose friction demand exceeds the capacity between them. Limitation
(docs/axial.md): a truncated Fourier series cannot hold the cargo exactly still, so long stick
phases between slips (friction coefficients just below the critical one) defeat every start;
that is reported (``converged=False``, the residual and each start's outcome), never raised, and
the case pipeline then solves the row with the time-domain reference.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, replace

import numpy as np
from numpy.typing import NDArray

from seafast.excitation.axial import AxialLoad
from seafast.fourier import complex_to_real_harmonics, real_to_complex_harmonics
from seafast.model.axial import AxialRestraint
from seafast.solvers.axial.problem import AXIAL_GLOBALISATION, AxialIterate, AxialProblem, evaluation_arrays, lock_check
from seafast.solvers.axial.response import AxialResponse, LockCheck, periodic_interpolation
from seafast.solvers.newton import NewtonResult, newton

__all__ = ["AxialHBMOptions", "solve_axial_hbm", "axial_time_samples"]


@dataclass(frozen=True, kw_only=True)
class AxialHBMOptions:
    """Settings of the axial harmonic balance.

    Parameters
    ----------
    harmonics
        H >= 1.
    time_samples
        AFT samples per period N >= 2H + 2 (the normal forces are interpolated onto them).
    tolerance
        Converged when ``max |R|`` is below ``tolerance`` times the load scale (the larger of
        ``max |F|`` and ``max C``).
    max_iterations
        Newton iterations per attempt.
    """

    harmonics: int = 25
    time_samples: int = 512
    tolerance: float = 1e-9
    max_iterations: int = 40

    def __post_init__(self) -> None:
        if not isinstance(self.harmonics, int) or self.harmonics < 1:
            raise ValueError(f"AxialHBMOptions.harmonics = {self.harmonics!r}; allowed an integer >= 1")
        if not isinstance(self.time_samples, int) or self.time_samples < 2 * self.harmonics + 2:
            raise ValueError(f"AxialHBMOptions.time_samples = {self.time_samples!r}; allowed an integer >= 2 harmonics + 2")
        if not (0.0 < self.tolerance < 1.0):
            raise ValueError(f"AxialHBMOptions.tolerance = {self.tolerance!r}; allowed 0 < tolerance < 1")
        if not isinstance(self.max_iterations, int) or self.max_iterations < 1:
            raise ValueError(f"AxialHBMOptions.max_iterations = {self.max_iterations!r}; allowed an integer >= 1")


def axial_time_samples(harmonics: int, vertical_samples: int, minimum: int = 512) -> int:
    """AFT samples for the axial HBM: a multiple of the vertical solution's N, at least ``max(minimum, 8 H)``.

    The slip transitions fall between samples: 512 samples keep that error below 0.1 % of the
    slip on the base case (256 give 1 %).
    """
    need = max(minimum, 8 * harmonics, 2 * harmonics + 2)
    return int(vertical_samples * math.ceil(need / vertical_samples))


@dataclass(frozen=True)
class _Attempt:
    """One Newton run from one start."""

    start: str
    X: NDArray
    norm: float
    iterations: int
    converged: bool
    state: AxialIterate
    check: LockCheck
    excess_N: float
    sample: int

    @property
    def accepted(self) -> bool:
        return self.converged and self.check is not LockCheck.VIOLATED

    def describe(self, N: int) -> str:
        if self.check is LockCheck.VIOLATED:
            return (
                f"{self.start}: converged on a locked state the friction cannot hold (needs {self.excess_N:.3g} N more than "
                f"available at t/T = {self.sample / N:.3f}): rejected"
            )
        if self.converged:
            return f"{self.start}: converged, {self.iterations} Newton iterations"
        return f"{self.start}: did not converge (residual {self.norm:.2e} after {self.iterations} iterations)"


def _newton(
    p: AxialProblem, X0: NDArray, options: AxialHBMOptions, first: tuple[NDArray, AxialIterate] | None = None
) -> NewtonResult[AxialIterate]:
    return newton(p, X0, tolerance=options.tolerance, max_iterations=options.max_iterations, globalisation=AXIAL_GLOBALISATION, first=first)


def _run(p: AxialProblem, start: str, X0: NDArray, options: AxialHBMOptions, first: tuple[NDArray, AxialIterate] | None = None) -> _Attempt:
    r = _newton(p, X0, options, first)
    ok = r.converged
    check, excess, sample = (
        lock_check(p, r.state.jenkins, r.state.displacement_m, options.tolerance) if ok else (LockCheck.NOT_LOCKED, 0.0, -1)
    )
    return _Attempt(start, r.u, r.relative_residual, r.iterations, ok, r.state, check, excess, sample)


def _continuation(p: AxialProblem, restraint: AxialRestraint, load: AxialLoad, options: AxialHBMOptions) -> _Attempt | None:
    """Newton along a contact stiffness rising from ``m (H w)^2`` (no stick chatter) to ``k_t``, from the sliding start.

    Only where the cargo can slide all period (the sliding start exists): long stick phases defeat
    it at every stiffness. Steps of a factor 3, shortened (square root of the factor) where Newton
    fails, at most :data:`_CONTINUATION_STEPS` solves; none if the softest problem fails.
    """
    kt = restraint.cargo_mass_kg * (p.H * p.omega_rad_s) ** 2
    if not kt < p.kt:
        return None
    X = AxialProblem(restraint, load, p.capacity, p.H, p.N, kt).sliding_guess()
    if X is None:
        return None
    factor, target, iterations = 1.0, kt, 0
    for _ in range(_CONTINUATION_STEPS):
        q = AxialProblem(restraint, load, p.capacity, p.H, p.N, target)
        r = _newton(q, X, options)
        iterations += r.iterations
        if r.converged:
            X, kt = r.u, target
            if kt >= p.kt:
                last = _run(p, "contact-stiffness continuation", X, options)
                return replace(last, iterations=iterations + last.iterations)
            factor = 3.0 if factor == 1.0 else min(3.0, factor**1.5)
        elif factor == 1.0:
            return None  # the softest, regularised problem already fails
        else:
            factor = math.sqrt(factor)
            if factor < 1.05:
                return None
        target = min(p.kt, kt * factor)
    return None


#: Newton solves the contact-stiffness continuation may take.
_CONTINUATION_STEPS = 24


def _attempts(
    p: AxialProblem, restraint: AxialRestraint, load: AxialLoad, options: AxialHBMOptions, given: NDArray | None
) -> list[_Attempt]:
    """Newton from each start in turn, smallest residual first, until one is accepted (then the last attempt).

    The stuck start first on its own: when the friction holds it is the answer (zero iterations).
    """
    stuck = p.stick_guess()
    ev = p.residual(stuck)
    if float(np.max(np.abs(ev[0]))) <= options.tolerance * p.scale:
        first = _run(p, "stuck", stuck, options, ev)
        if first.accepted:
            return [first]
    makers: list[tuple[str, Callable[[], NDArray | None]]] = [
        ("locked at the lock range's edge", p.locked_guess),
        ("given", lambda: given),
        ("sliding (describing function)", p.sliding_guess),
        ("frictionless", p.free_guess),
    ]
    starts: list[tuple[float, str, NDArray, tuple[NDArray, AxialIterate]]] = [(float(np.max(np.abs(ev[0]))), "stuck", stuck, ev)]
    for name, make in makers:
        X0 = make()
        if X0 is not None:
            ev0 = p.residual(X0)
            starts.append((float(np.max(np.abs(ev0[0]))), name, X0, ev0))
    out: list[_Attempt] = []
    for _, name, X0, ev0 in sorted(starts, key=lambda s: s[0]):
        out.append(_run(p, name, X0, options, ev0))
        if out[-1].accepted:
            return out
    attempt = _continuation(p, restraint, load, options)
    if attempt is not None:
        out.append(attempt)
    return out


def solve_axial_hbm(
    restraint: AxialRestraint,
    load: AxialLoad,
    normal_force_N: NDArray[np.float64],
    options: AxialHBMOptions = AxialHBMOptions(),
    initial_harmonics: NDArray[np.complex128] | None = None,
) -> AxialResponse:
    """Periodic axial stick-slip response of the rigid cargo by harmonic balance.

    Parameters
    ----------
    restraint
        Friction coefficients, tangential stiffness, lashings, stoppers, cargo mass.
    load
        Axial load harmonics [N] (forward +).
    normal_force_N
        Saddle contact forces over one period from the vertical solution [N], shape (N_v, n_s)
        (``N_v`` samples at ``t = n T / N_v``; linearly interpolated onto the AFT samples).
    options
        Harmonics, samples, tolerance.
    initial_harmonics
        Complex harmonics of ``u`` of a neighbouring solution to start from (one of the starts).

    Returns
    -------
    AxialResponse
        On ``options.time_samples`` samples; ``converged=False`` (with the residual) when no
        start converges to a real periodic state, never an exception. ``lock_check`` says
        whether a slip-free answer was checked (``HOLDS``) or a converged locked state was
        rejected (``VIOLATED``, then ``converged=False``).
    """
    H, N = options.harmonics, options.time_samples
    normal = periodic_interpolation(np.asarray(normal_force_N, dtype=float).reshape(np.shape(normal_force_N)[0], -1), N)
    capacity = restraint.capacity_N(normal)
    p = AxialProblem(restraint, load, capacity, H, N)
    given = None
    if initial_harmonics is not None:
        x0 = np.zeros(H + 1, dtype=complex)
        n0 = min(H + 1, len(initial_harmonics))
        x0[:n0] = np.asarray(initial_harmonics)[:n0]
        given = complex_to_real_harmonics(x0)
    attempts = _attempts(p, restraint, load, options, given)
    chosen = attempts[-1] if attempts[-1].accepted else min(attempts, key=lambda a: (a.check is LockCheck.VIOLATED, a.norm))
    ok = chosen.accepted
    rejected = any(a.check is LockCheck.VIOLATED for a in attempts)
    check = chosen.check if ok else (LockCheck.VIOLATED if rejected else LockCheck.NOT_LOCKED)
    path = f"from the {chosen.start} start" if ok else "did not converge to a periodic state"
    msg = f"axial HBM (H = {H}, N = {N}): {path}, {chosen.iterations} Newton iterations, residual {chosen.norm:.2e}"
    if check is LockCheck.HOLDS:
        msg += "; locked, the friction law checked at every sample"
    if len(attempts) > 1:
        msg += " (starts: " + "; ".join(a.describe(N) for a in attempts) + ")"
    if p.gauge:
        msg += "; no lashing or stopper restrains the cargo axially: its mean position is pinned"
    return AxialResponse(
        "hbm",
        load.omega_rad_s,
        capacity_N=capacity,
        load_N=p.load_t,
        converged=bool(ok),
        residual_norm=chosen.norm,
        iterations=int(sum(a.iterations for a in attempts)),
        message=msg,
        harmonics=real_to_complex_harmonics(chosen.X),
        options={
            "harmonics": H,
            "time_samples": N,
            "tolerance": options.tolerance,
            "max_iterations": options.max_iterations,
            "tangential_stiffness_N_per_m": p.kt,
        },
        lock_check=check,
        **evaluation_arrays(p, chosen.X, chosen.state),
    )
