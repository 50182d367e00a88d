"""The transient integrator of the saddles' contact problem: any loading, from any state, compiled.

One integrator serves every march of the nonlinear cargo: the Monte Carlo reference of a sea
state (:mod:`seafast.seastate.realisation`: windows, states, moment outputs, 3-hour records at a few
microseconds a step) and the periodic march that starts the high-harmonic harmonic balance solves
(:func:`march_periodic`, used by :mod:`seafast.solvers.hbm.harmonics`). (The exact periodic references,
:mod:`seafast.solvers.references`, integrate all cargo DOFs on their own, independently of this.)

Superposition (the formulation of the condensed references and the HBM)
-----------------------------------------------------------------------
With every saddle bilateral the cargo is linear and time-invariant; its response ``q_lin`` to
deck motion, rigid-body inertia, weight and pretension is known in advance (e.g. synthesised in
the frequency domain). The nonlinear response is ``q = q_lin + q_c``: ``q_c`` is the response of
the *same* linear system (M, D and K with every saddle bilateral) to correction forces at the
saddles::

    M q_c'' + D q_c' + K q_c = B c(t),    c = k_u max(-delta, 0),    delta = delta_lin - B^T q_c,

``delta_lin = z_deck - z_cargo,lin`` the linear saddle compressions (positive compressed), k_u
the compression-only saddle stiffness and c (upward on the cargo) the tension a bilateral saddle
would carry, removed. The march is driven by ``delta_lin`` alone; ``q_c = 0`` while every saddle
stays compressed.

Modal reduction with static residual flexibility
------------------------------------------------
``q_c = Phi eta + R c`` (:func:`seafast.solvers.modal_correction.modal_correction_system`): the
mass-normalised undamped modes Phi of (K, M) up to ``cutoff_rad_s`` (their coupled modal damping
``Xi = Phi^T D Phi`` kept whole: the springs are undamped, so Rayleigh damping on the beam is not
modal), and for the truncated modes their static (residual) flexibility ``R = K^-1 B - Phi
Omega^-2 Phi^T B``. So ``eta'' + Xi eta' + Omega^2 eta = Phi^T B c``, and the static response to
saddle forces is exact whatever the cutoff; with every mode kept, ``R = 0`` and the march is the
full model's (a test checks this against the periodic full-DOF reference to round-off).

Newmark average acceleration (gamma = 1/2, beta = 1/4: unconditionally stable, no algorithmic
damping, so a free decay shows the model's own damping): per step the predictor
``eta_p = K^-1 [(4/dt^2 + 2/dt Xi) eta + (4/dt + Xi) eta' + eta'']`` with ``K = 4/dt^2 +
2/dt Xi + Omega^2``, then the step's contact problem condensed on the saddles::

    delta = delta_p - G c(delta),   delta_p = delta_lin,n+1 - Phi_B eta_p,
    G = Phi_B K^-1 Phi_B^T + R_B                                     (step receptance, n_s x n_s)

solved exactly: for a set S of detached saddles it is linear, ``(I - G diag(k_u 1_S)) delta =
delta_p``; the inverse of every set's matrix is precomputed (up to :data:`PRECOMPUTED_SETS_LIMIT`
saddles; beyond, each trial set is solved directly), an active-set iteration starts from the
previous step's set and stops when the signs agree, and enumeration of all sets is the fallback.
Then ``eta_n+1 = eta_p + K^-1 Phi_B^T c``, and the Newmark updates.

Time step: ``steps_per_period`` steps per period of the *reference frequency*, the highest of
the ``n_s`` lowest natural frequencies of the cargo on bilateral saddles (the modes in which it
moves on its saddle springs, which the saddle forces drive; base case 44, 51 and 72 rad/s).

Windows: :func:`march_window` starts a record at rest, marches while the caller's trigger says
the linear compression is near or below zero, and stops once every saddle is in contact and the
free vibration left is below a tolerance (``sum_r max|phi_r| sqrt(eta_r^2 + (eta_r'/omega_r)^2)
<= tolerance_m``, a bound on the cargo deflection it can still cause); outside windows
``q_c = 0`` exactly.

Units: SI throughout (m, rad, N, s). Nothing here prints, reads or writes files. Size: longer than
the house's ~400 lines because the compiled kernels and the Newmark operators whose arrays they take
are kept side by side (a change to one needs the other in view).
"""

from __future__ import annotations

from dataclasses import dataclass

import numba
import numpy as np
from numpy.typing import NDArray
from scipy.ndimage import spline_filter1d

from seafast.model.structure import StructuralModel
from seafast.solvers.exact_contact import solve_exact_contact
from seafast.solvers.modal_correction import modal_correction_system

__all__ = [
    "DEFAULT_STEPS_PER_PERIOD",
    "DEFAULT_CUTOFF_FACTOR",
    "PRECOMPUTED_SETS_LIMIT",
    "reference_frequency_rad_s",
    "time_step_s",
    "ModalCorrection",
    "modal_correction",
    "MomentOutput",
    "MarchState",
    "WindowOutcome",
    "march_window",
    "TransientRecord",
    "integrate_record",
    "PeriodicMarch",
    "march_period",
    "march_periodic",
]

DEFAULT_STEPS_PER_PERIOD = 16
"""Steps per period of the reference frequency. Regular wave: peak saddle force within 3e-4 and
peak gap within 0.2 % of 64 steps (``tests/solvers/test_transient.py``); 3-hour sea-state
records, where re-contacts ring: 3-hour maxima of force and moment within 0.1 %, gap within
0.5 % (``docs/monte_carlo.md``)."""

DEFAULT_CUTOFF_FACTOR = 4.0
"""Modes kept up to this multiple of the reference frequency (base case: 44, 51, 72, 167 rad/s)."""

PRECOMPUTED_SETS_LIMIT = 10
"""Largest saddle count for which the contact matrices of all 2^n_s detached sets are inverted up front."""


# ====================================================================== time step
def reference_frequency_rad_s(model: StructuralModel) -> float:
    """Highest of the ``n_s`` lowest natural frequencies on bilateral saddles [rad/s].

    These are the modes in which the cargo moves on its saddle springs (bounce, pitch, ...),
    the ones the saddle forces drive; the integrator's step resolves them.
    """
    return float(model.natural_frequencies_rad_s(True, count=max(model.saddle_count, 1))[-1])


def time_step_s(model: StructuralModel, steps_per_period: int = DEFAULT_STEPS_PER_PERIOD) -> float:
    """Integrator step [s]: ``steps_per_period`` steps per period of :func:`reference_frequency_rad_s`.

    Raises
    ------
    ValueError
        If ``steps_per_period`` is not an integer >= 2.
    """
    if isinstance(steps_per_period, bool) or int(steps_per_period) != steps_per_period or steps_per_period < 2:
        raise ValueError(f"steps_per_period = {steps_per_period!r}; allowed: an integer >= 2")
    return 2.0 * np.pi / reference_frequency_rad_s(model) / int(steps_per_period)


# ====================================================================== the reduced correction system
@dataclass(frozen=True)
class ModalCorrection:
    """The correction system reduced to its modes below a cutoff, with Newmark operators for one step.

    Attributes
    ----------
    time_step_s, cutoff_rad_s
        Step dt [s] and the highest kept natural frequency bound [rad/s].
    omega_rad_s
        Kept natural frequencies (m,) [rad/s].
    modes
        Kept mass-normalised modes on the cargo DOFs (n_c, m).
    predictor
        (m, 3m): ``eta_p = predictor @ [eta, eta', eta'']``.
    force_response
        (m, n_s): ``eta_n+1 = eta_p + force_response @ c``.
    saddle_modes
        Phi_B (n_s, m): the modes at the saddles' z DOFs.
    residual_displacement
        (n_c, n_s): ``K^-1 B - Phi Omega^-2 Phi_B^T`` [m/N], static flexibility of the truncated modes.
    receptance_m_per_N
        G (n_s, n_s): the step receptance.
    static_receptance_m_per_N
        ``B^T K^-1 B`` (n_s, n_s) [m/N].
    stiffness_N_per_m
        k_u (n_s,) [N/m].
    set_inverses
        (2^n_s, n_s, n_s): ``(I - G diag(k_u 1_S))^-1`` for S coded by bits (saddle s = bit s);
        shape (0, n_s, n_s) beyond :data:`PRECOMPUTED_SETS_LIMIT` saddles.
    mode_deflection_bound
        (m,): max |z| of each mode over the cargo [m per unit modal coordinate].
    saddle_dof
        (n_s,) cargo DOF index of each saddle's z.
    """

    time_step_s: float
    cutoff_rad_s: float
    omega_rad_s: NDArray[np.float64]
    modes: NDArray[np.float64]
    predictor: NDArray[np.float64]
    force_response: NDArray[np.float64]
    saddle_modes: NDArray[np.float64]
    residual_displacement: NDArray[np.float64]
    receptance_m_per_N: NDArray[np.float64]
    static_receptance_m_per_N: NDArray[np.float64]
    stiffness_N_per_m: NDArray[np.float64]
    set_inverses: NDArray[np.float64]
    mode_deflection_bound: NDArray[np.float64]
    saddle_dof: NDArray[np.intp]

    @property
    def mode_count(self) -> int:
        return int(self.omega_rad_s.size)

    @property
    def saddle_count(self) -> int:
        return int(self.stiffness_N_per_m.size)

    def displacement_m(self, eta: NDArray, force_N: NDArray) -> NDArray[np.float64]:
        """q_c on the cargo DOFs from modal coordinates (..., m) and correction forces (..., n_s)."""
        return eta @ self.modes.T + force_N @ self.residual_displacement.T

    def saddle_displacement_m(self, eta: NDArray, force_N: NDArray) -> NDArray[np.float64]:
        """q_c at the saddles' z DOFs (..., n_s) [m]."""
        return eta @ self.saddle_modes.T + force_N @ self.residual_displacement[self.saddle_dof].T


def modal_correction(
    model: StructuralModel, time_step_s: float, cutoff_rad_s: float | None = None, *, minimum_modes: int | None = None
) -> ModalCorrection:
    """Reduce the correction system of ``model`` and build its Newmark operators.

    Parameters
    ----------
    model
        The cargo structural model.
    time_step_s
        dt [s], > 0.
    cutoff_rad_s
        Keep the modes with natural frequency <= cutoff [rad/s];
        default :data:`DEFAULT_CUTOFF_FACTOR` times :func:`reference_frequency_rad_s`;
        ``numpy.inf`` keeps every mode (the full model).
    minimum_modes
        Keep at least this many modes (default ``n_s``: the modes the saddle forces drive).

    Raises
    ------
    ValueError
        For a non-positive step or cutoff.
    """
    dt = float(time_step_s)
    if not np.isfinite(dt) or dt <= 0.0:
        raise ValueError(f"time_step_s = {time_step_s!r}; allowed: a number > 0 [s]")
    cutoff = DEFAULT_CUTOFF_FACTOR * reference_frequency_rad_s(model) if cutoff_rad_s is None else float(cutoff_rad_s)
    if not cutoff > 0.0:
        raise ValueError(f"cutoff_rad_s = {cutoff_rad_s!r}; allowed: a number > 0 [rad/s] (inf keeps every mode)")
    n_s = model.saddle_count
    reduced = modal_correction_system(model, cutoff, minimum_modes=n_s if minimum_modes is None else int(minimum_modes))
    w, phi, xi = reduced.natural_frequency_rad_s, reduced.mode_shape, reduced.modal_damping
    m = w.size
    sad = reduced.saddle_dof
    phi_b = reduced.saddle_mode_shape
    residual = reduced.residual_displacement_m_per_N
    eye = np.eye(m)
    k_hat_inv = np.linalg.inv(4.0 / dt**2 * eye + 2.0 / dt * xi + np.diag(w**2))
    predictor = np.hstack([k_hat_inv @ (4.0 / dt**2 * eye + 2.0 / dt * xi), k_hat_inv @ (4.0 / dt * eye + xi), k_hat_inv])
    force_response = k_hat_inv @ phi_b.T
    G = phi_b @ force_response + residual[sad]
    k_u = reduced.unilateral_stiffness_N_per_m
    if n_s <= PRECOMPUTED_SETS_LIMIT:
        codes = np.arange(2**n_s)
        masks = ((codes[:, None] >> np.arange(n_s)[None, :]) & 1).astype(float)
        mats = np.eye(n_s)[None] - G[None] * (k_u[None, :] * masks)[:, None, :]
        inverses = np.linalg.inv(mats)
    else:
        inverses = np.zeros((0, n_s, n_s))
    return ModalCorrection(
        time_step_s=dt,
        cutoff_rad_s=cutoff,
        omega_rad_s=w,
        modes=phi,
        predictor=np.ascontiguousarray(predictor),
        force_response=np.ascontiguousarray(force_response),
        saddle_modes=np.ascontiguousarray(phi_b),
        residual_displacement=residual,
        receptance_m_per_N=np.ascontiguousarray(G),
        static_receptance_m_per_N=reduced.static_flexibility_m_per_N,
        stiffness_N_per_m=k_u,
        set_inverses=np.ascontiguousarray(inverses),
        mode_deflection_bound=np.max(np.abs(phi[0::2]), axis=0, initial=0.0),
        saddle_dof=sad,
    )


# ====================================================================== compiled kernels
@numba.njit(cache=True)
def _solve_contact(  # pragma: no cover - compiled
    d_pred: NDArray, G: NDArray, k: NDArray, inverses: NDArray, detached: NDArray, tol: float
) -> tuple[NDArray, bool]:
    """Exact contact of one step; returns (delta, ok), updates ``detached`` in place."""
    n = d_pred.size
    delta = np.empty(n)
    use_table = inverses.shape[0] > 0
    for _ in range(4 * n + 8):
        code = 0
        any_det = False
        for s in range(n):
            if detached[s]:
                code += 1 << s
                any_det = True
        if not any_det:
            delta[:] = d_pred
        elif use_table:
            delta[:] = inverses[code] @ d_pred
        else:
            A = np.eye(n)
            for s in range(n):
                if detached[s]:
                    A[:, s] -= G[:, s] * k[s]
            delta[:] = np.linalg.solve(A, d_pred)
        consistent = True
        for s in range(n):
            if (detached[s] and delta[s] > tol) or ((not detached[s]) and delta[s] < -tol):
                consistent = False
        if consistent:
            return delta, True
        for s in range(n):
            detached[s] = delta[s] < 0.0
    if not use_table:
        return delta, False
    best = np.inf  # cycling: enumerate every set, keep the least violating
    best_code = 0
    for code in range(inverses.shape[0]):
        d = inverses[code] @ d_pred
        violation = 0.0
        for s in range(n):
            v = d[s] if (code >> s) & 1 else -d[s]
            violation = max(violation, v)
        if violation < best:
            best, best_code = violation, code
    delta[:] = inverses[best_code] @ d_pred
    for s in range(n):
        detached[s] = (best_code >> s) & 1 == 1
    return delta, best <= tol


@numba.njit(cache=True)
def _bspline_row(coef: NDArray, x: float) -> NDArray:  # pragma: no cover - compiled
    """Cubic B-spline value of every channel at coarse position x (periodic coefficients (n, ch))."""
    n = coef.shape[0]
    i = int(np.floor(x))
    t = x - i
    w0 = (1.0 - t) ** 3 / 6.0
    w1 = (3.0 * t**3 - 6.0 * t**2 + 4.0) / 6.0
    w2 = (-3.0 * t**3 + 3.0 * t**2 + 3.0 * t + 1.0) / 6.0
    w3 = t**3 / 6.0
    return w0 * coef[(i - 1) % n] + w1 * coef[i % n] + w2 * coef[(i + 1) % n] + w3 * coef[(i + 2) % n]


@numba.njit(cache=True)
def _march(  # pragma: no cover - compiled
    start: int,
    stop: int,
    ratio: float,
    coef: NDArray,
    delta_static: NDArray,
    trigger: NDArray,
    dt: float,
    predictor: NDArray,
    force_response: NDArray,
    phi_b: NDArray,
    G: NDArray,
    k: NDArray,
    inverses: NDArray,
    omega: NDArray,
    mode_bound: NDArray,
    tol_state: float,
    tol_sign: float,
    eta: NDArray,
    deta: NDArray,
    ddeta: NDArray,
    c: NDArray,
    detached: NDArray,
    moment_static: NDArray,
    moment_basis: NDArray,
    modulus: NDArray,
    capture_every: int,
    capture_compression: NDArray,
    capture_lifted: NDArray,
) -> tuple[int, NDArray, int, int, bool]:
    """March from fine step ``start`` (state given, updated in place) until quiet and untriggered, or ``stop``.

    Fine step p is at coarse position p / ratio of the B-spline coefficients ``coef`` (n_tc,
    n_s + n_r): the first n_s channels are the dynamic linear compressions, the others the
    coefficients of the moment basis's linear part. Returns (end, maxima, lifted_steps, events,
    solved); maxima = [F, u_s, u_d, |M|, |sigma|] over the steps start+1 .. end.
    """
    n_s = delta_static.size
    m = omega.size
    n_x = moment_static.size
    n_h = moment_basis.shape[1]
    n_r = n_h - m - n_s
    state = np.empty(3 * m)
    h = np.empty(n_h)
    maxima = np.zeros(5)
    lifted_steps = 0
    events = 0
    solved = True
    n_tc = trigger.size
    n_b = capture_lifted.shape[0]
    was_detached = detached.copy()
    p = start
    while p < stop:
        p += 1
        x = p / ratio
        row = _bspline_row(coef, x)
        d_lin = delta_static + row[:n_s]
        state[:m] = eta
        state[m : 2 * m] = deta
        state[2 * m :] = ddeta
        eta_p = predictor @ state
        delta, ok = _solve_contact(d_lin - phi_b @ eta_p, G, k, inverses, detached, tol_sign)
        if not ok:
            solved = False
        for s in range(n_s):
            c[s] = k[s] * max(-delta[s], 0.0)
        eta_new = eta_p + force_response @ c
        ddeta_new = 4.0 / dt**2 * (eta_new - eta - dt * deta) - ddeta
        deta[:] = deta + 0.5 * dt * (ddeta + ddeta_new)
        ddeta[:] = ddeta_new
        eta[:] = eta_new
        # outputs at step p
        any_lift = False
        for s in range(n_s):
            d = delta[s]
            if k[s] * max(d, 0.0) > maxima[0]:
                maxima[0] = k[s] * max(d, 0.0)
            if d > maxima[1]:
                maxima[1] = d
            if -d > maxima[2]:
                maxima[2] = -d
            if d < 0.0:
                any_lift = True
                if not was_detached[s]:
                    events += 1
            was_detached[s] = d < 0.0
        if any_lift:
            lifted_steps += 1
        if n_x > 0:
            h[:n_r] = row[n_s:]
            h[n_r : n_r + m] = eta
            h[n_r + m :] = c
            moments = moment_static + moment_basis @ h
            for ix in range(n_x):
                a = abs(moments[ix])
                if a > maxima[3]:
                    maxima[3] = a
                if a / modulus[ix] > maxima[4]:
                    maxima[4] = a / modulus[ix]
        if capture_every > 0:
            b = p // capture_every
            if b < n_b:
                for s in range(n_s):
                    if delta[s] < 0.0:
                        capture_lifted[b, s] = True
                if p % capture_every == 0:
                    capture_compression[b] = delta
        # stop once every saddle is in contact, the caller's trigger is off and q_c is negligible
        if any_lift:
            continue
        i = int(np.floor(x)) % n_tc
        if trigger[i] or trigger[(i + 1) % n_tc]:
            continue
        bound = 0.0
        for r in range(m):
            bound += mode_bound[r] * np.sqrt(eta[r] ** 2 + (deta[r] / omega[r]) ** 2)
        if bound <= tol_state:
            break
    return p, maxima, lifted_steps, events, solved


# ====================================================================== Python interface
@dataclass(frozen=True)
class MomentOutput:
    """How the march evaluates the cargo's bending moment at every step (optional).

    ``M(x) = moment_static + basis @ [g(t), eta, c]`` with g the linear model's moment
    coordinates (the channels after the n_s compressions in the march's coefficients), so
    ``basis = [U | E Phi | E R]`` with E the moment-recovery map of the cargo DOFs.

    Attributes
    ----------
    moment_static_Nm
        (n_x,) still-water moment [N m].
    basis
        (n_x, n_r + m + n_s) [N m per unit coordinate].
    section_modulus_m3
        (n_x,) [m^3]; stress = |M| / modulus.
    """

    moment_static_Nm: NDArray[np.float64]
    basis: NDArray[np.float64]
    section_modulus_m3: NDArray[np.float64]


@dataclass(frozen=True)
class WindowOutcome:
    """What one call of :func:`march_window` found over steps start+1 .. end.

    Attributes
    ----------
    end
        Last fine step marched.
    max_saddle_force_N, max_compression_m, max_gap_m, max_bending_moment_Nm, max_bending_stress_Pa
        Maxima over the window (0 where nothing exceeded 0; moment and stress 0 without a
        :class:`MomentOutput`).
    lifted_steps
        Steps with at least one saddle detached.
    uplift_events
        Saddle separations (a saddle going from compressed to detached; summed over saddles).
    solved
        Every step's contact problem was solved exactly.
    """

    end: int
    max_saddle_force_N: float
    max_compression_m: float
    max_gap_m: float
    max_bending_moment_Nm: float
    max_bending_stress_Pa: float
    lifted_steps: int
    uplift_events: int
    solved: bool


@dataclass
class MarchState:
    """Mutable state of one march (modal coordinates and their rates, forces, detached set)."""

    eta: NDArray[np.float64]
    eta_dot: NDArray[np.float64]
    eta_ddot: NDArray[np.float64]
    force_N: NDArray[np.float64]
    detached: NDArray[np.bool_]

    @staticmethod
    def at_rest(system: ModalCorrection) -> MarchState:
        m, n_s = system.mode_count, system.saddle_count
        return MarchState(np.zeros(m), np.zeros(m), np.zeros(m), np.zeros(n_s), np.zeros(n_s, dtype=bool))

    @staticmethod
    def quasi_static(system: ModalCorrection, linear_compression_m: NDArray) -> MarchState:
        """At rest in the exact-contact static state of ``linear_compression_m`` (n_s,).

        ``c`` from ``delta = delta_lin - G_0 c``, ``G_0 = B^T K^-1 B``, solved exactly by
        :func:`~seafast.solvers.exact_contact.solve_exact_contact`; ``eta = Omega^-2 Phi_B^T c``
        (the static modal part; the residual flexibility carries the rest).
        """
        d_lin = np.asarray(linear_compression_m, dtype=float)
        delta, c = solve_exact_contact(d_lin[None], system.static_receptance_m_per_N, system.stiffness_N_per_m)
        eta = (system.saddle_modes.T @ c[0]) / system.omega_rad_s**2
        m = system.mode_count
        return MarchState(eta, np.zeros(m), np.zeros(m), c[0], delta[0] < 0.0)


def march_window(
    system: ModalCorrection,
    coefficients: NDArray[np.float64],
    ratio: int,
    delta_static_m: NDArray[np.float64],
    trigger: NDArray[np.bool_],
    start: int,
    stop: int,
    state: MarchState,
    *,
    tolerance_m: float,
    moments: MomentOutput | None = None,
    capture_every: int = 0,
    capture_compression: NDArray[np.float64] | None = None,
    capture_lifted: NDArray[np.bool_] | None = None,
) -> WindowOutcome:
    """March the correction system from fine step ``start`` until it may stop, or ``stop``.

    Parameters
    ----------
    system
        The reduced correction system (:func:`modal_correction`) for the fine step.
    coefficients
        Periodic cubic B-spline coefficients (n_tc, n_s [+ n_r]) of the dynamic linear
        compressions [m] (and the linear moment coordinates) on a coarse grid of ``ratio``
        fine steps per sample (``scipy.ndimage.spline_filter1d(..., mode='grid-wrap')``).
    delta_static_m
        (n_s,) still-water linear compression added to the dynamic part [m].
    trigger
        (n_tc,) coarse samples near which the march must go on (linear compression near or
        below zero).
    start, stop
        First (state) and last fine steps.
    state
        The state at ``start``; updated in place to the state at the end.
    tolerance_m
        Free-vibration bound below which a quiet march stops [m].
    moments
        Evaluate bending moment and stress maxima (optional).
    capture_every, capture_compression, capture_lifted
        Record the compression at steps that are multiples of ``capture_every`` into row
        ``p // capture_every`` of ``capture_compression`` (n_b, n_s), and mark the rows whose
        span had a detached saddle in ``capture_lifted``.
    """
    n_s = system.saddle_count
    k = system.stiffness_N_per_m
    if moments is None:
        ms, mb, mod = np.zeros(0), np.zeros((0, 1 + system.mode_count + n_s)), np.ones(0)
    else:
        ms, mb, mod = moments.moment_static_Nm, moments.basis, moments.section_modulus_m3
    cc = np.zeros((0, n_s)) if capture_compression is None else capture_compression
    cl = np.zeros((0, n_s), dtype=bool) if capture_lifted is None else capture_lifted
    tol_sign = 1e-12 * max(float(np.max(np.abs(delta_static_m))), float(np.max(np.abs(coefficients[:, :n_s]))), 1e-9)
    end, maxima, lifted, events, solved = _march(
        int(start),
        int(stop),
        float(ratio),
        coefficients,
        np.asarray(delta_static_m, dtype=float),
        trigger,
        system.time_step_s,
        system.predictor,
        system.force_response,
        system.saddle_modes,
        system.receptance_m_per_N,
        k,
        system.set_inverses,
        system.omega_rad_s,
        system.mode_deflection_bound,
        float(tolerance_m),
        tol_sign,
        state.eta,
        state.eta_dot,
        state.eta_ddot,
        state.force_N,
        state.detached,
        ms,
        mb,
        mod,
        int(capture_every),
        cc,
        cl,
    )
    F, u_s, u_d, M, sigma = (float(v) for v in maxima)
    return WindowOutcome(int(end), F, u_s, u_d, M, sigma, int(lifted), int(events), bool(solved))


# ====================================================================== whole records
@dataclass(frozen=True)
class TransientRecord:
    """One record marched from its first sample to its last.

    Attributes
    ----------
    time_s
        Sample times ``t_n = n dt`` [s] (n_t,).
    compression_m
        Nonlinear saddle compression ``delta = delta_lin - B^T q_c`` (n_t, n_s) [m].
    saddle_force_N
        Compression-only saddle force ``k_u max(delta, 0)`` (n_t, n_s) [N], upward on the cargo.
    solved
        Every step's contact problem was solved exactly.
    """

    time_s: NDArray[np.float64]
    compression_m: NDArray[np.float64]
    saddle_force_N: NDArray[np.float64]
    solved: bool


def integrate_record(system: ModalCorrection, linear_compression_m: NDArray, *, initial: MarchState | None = None) -> TransientRecord:
    """March one record of linear compressions sampled at the integrator's step.

    Parameters
    ----------
    system
        The reduced correction system for the step dt of the samples.
    linear_compression_m
        ``delta_lin`` at ``t_n = n dt`` (n_t, n_s) [m], still water included.
    initial
        State at t_0; default the quasi-static exact-contact state of ``delta_lin(t_0)``
        (q_c = 0 when every saddle is compressed).
    """
    d_lin = np.atleast_2d(np.asarray(linear_compression_m, dtype=float))
    n_t, n_s = d_lin.shape
    if n_s != system.saddle_count:
        raise ValueError(f"linear_compression_m has {n_s} columns; the model has {system.saddle_count} saddles")
    state = initial if initial is not None else MarchState.quasi_static(system, d_lin[0])
    # at integer positions the interpolating spline returns the samples themselves
    coef = np.ascontiguousarray(spline_filter1d(d_lin, order=3, axis=0, mode="grid-wrap"))
    compression = np.empty((n_t, n_s))
    lifted = np.zeros((n_t, n_s), dtype=bool)
    compression[0] = d_lin[0] - system.saddle_displacement_m(state.eta, state.force_N)
    outcome = march_window(
        system,
        coef,
        1,
        np.zeros(n_s),
        np.ones(n_t, dtype=bool),
        0,
        n_t - 1,
        state,
        tolerance_m=0.0,
        capture_every=1,
        capture_compression=compression,
        capture_lifted=lifted,
    )
    return TransientRecord(
        np.asarray(np.arange(n_t) * system.time_step_s, dtype=np.float64),
        compression,
        system.stiffness_N_per_m * np.maximum(compression, 0.0),
        outcome.solved,
    )


# ====================================================================== periodic march
@dataclass(frozen=True)
class PeriodicMarch:
    """The periodic state a march of one repeated period settled on.

    Attributes
    ----------
    compression_m
        The last period's compressions at ``t_n = n T / N`` (N, n_s) [m].
    periods
        Periods marched.
    change
        Last largest change of the compressions between two periods, over the largest linear compression [-].
    """

    compression_m: NDArray[np.float64]
    periods: int
    change: float


def march_periodic(
    system: ModalCorrection,
    linear_compression_m: NDArray[np.float64],
    *,
    max_periods: int = 50,
    tolerance: float = 1e-6,
) -> PeriodicMarch:
    """March one period of linear compressions over and over, from rest, until the compressions repeat.

    From rest with no correction force, the start is the linear periodic solution: the periodic state
    reached is the one the physical system settles on from there.

    Parameters
    ----------
    system
        The reduced correction system for the step ``T / N`` (the samples are the steps).
    linear_compression_m
        ``delta_lin`` over one period at ``t_n = n T / N``, (N, n_s) [m].
    max_periods, tolerance
        Stop when the largest change of ``delta`` between two periods is below ``tolerance`` times the
        largest linear compression, or after ``max_periods``.
    """
    d_lin = np.ascontiguousarray(linear_compression_m, dtype=float)
    n_s = d_lin.shape[1]
    if n_s != system.saddle_count:
        raise ValueError(f"linear_compression_m has {n_s} columns; the model has {system.saddle_count} saddles")
    scale = max(float(np.max(np.abs(d_lin))), 1e-12)
    state = MarchState.at_rest(system)
    previous: NDArray[np.float64] | None = None
    change = np.inf
    periods = 0
    delta = d_lin
    for periods in range(1, int(max_periods) + 1):  # noqa: B007 - the count is returned
        delta = march_period(system, d_lin, state)
        if previous is not None:
            change = float(np.max(np.abs(delta - previous))) / scale
            if change <= tolerance:
                break
        previous = delta
    return PeriodicMarch(delta, periods, change)


def march_period(system: ModalCorrection, linear_compression_m: NDArray[np.float64], state: MarchState) -> NDArray[np.float64]:
    """March one period of periodic linear compressions from ``state`` (updated in place to the period's end).

    Parameters
    ----------
    system
        The reduced correction system for the step ``T / N``.
    linear_compression_m
        ``delta_lin`` over one period at ``t_n = n T / N``, (N, n_s) [m] (step N is step 0 again).
    state
        The state at ``t_0``.

    Returns
    -------
    The compressions at ``t_0 .. t_{N-1}`` of this period (N, n_s) [m], ``t_0`` being the state's own.
    """
    d_lin = np.ascontiguousarray(linear_compression_m, dtype=float)
    N, n_s = d_lin.shape
    coef = np.ascontiguousarray(spline_filter1d(d_lin, order=3, axis=0, mode="grid-wrap"))  # periodic: step N is step 0
    captured = np.empty((N + 1, n_s))
    lifted = np.zeros((N + 1, n_s), dtype=bool)
    captured[0] = d_lin[0] - system.saddle_displacement_m(state.eta, state.force_N)
    march_window(
        system,
        coef,
        1,
        np.zeros(n_s),
        np.ones(N, dtype=bool),
        0,
        N,
        state,
        tolerance_m=0.0,
        capture_every=1,
        capture_compression=captured,
        capture_lifted=lifted,
    )
    return np.roll(captured[1:], 1, axis=0)  # t_1 .. t_N, and t_N is t_0 of the next period
