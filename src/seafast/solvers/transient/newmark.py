"""The integrator's time step and the Newmark operators of one step of the reduced correction system.

:func:`newmark_step` reduces the model's correction system (:func:`~seafast.solvers.modal_correction.modal_correction_system`)
and builds, for the step dt, the Newmark average-acceleration operators (predictor, force response, the step's
receptance at the saddles and the inverse contact matrix of every detached set): a :class:`NewmarkStep`.
:class:`MarchState` is the march's mutable state. The equations are in :mod:`seafast.solvers.transient`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from seafast.model.structure import StructuralModel
from seafast.solvers.exact_contact import solve_exact_contact
from seafast.solvers.modal_correction import ModalCorrectionSystem, modal_correction_system

__all__ = [
    "DEFAULT_STEPS_PER_PERIOD",
    "DEFAULT_CUTOFF_FACTOR",
    "PRECOMPUTED_SETS_LIMIT",
    "reference_frequency_rad_s",
    "time_step_s",
    "NewmarkStep",
    "newmark_step",
    "MarchState",
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


@dataclass(frozen=True)
class NewmarkStep:
    """The Newmark average-acceleration operators of one step dt of a reduced correction system.

    Attributes
    ----------
    reduced
        The correction system reduced to its modes below a cutoff plus static residual flexibility
        (:class:`~seafast.solvers.modal_correction.ModalCorrectionSystem`: frequencies, modes, residual and
        static flexibilities, ``k_u``).
    time_step_s
        Step dt [s].
    predictor
        (m, 3m): ``eta_p = predictor @ [eta, eta', eta'']``.
    force_response
        (m, n_s): ``eta_n+1 = eta_p + force_response @ c``.
    receptance_m_per_N
        G (n_s, n_s): the step receptance ``Phi_B K^-1 Phi_B^T + R_B``.
    set_inverses
        (2^n_s, n_s, n_s): ``(I - G diag(k_u 1_S))^-1`` for S coded by bits (saddle s = bit s);
        shape (0, n_s, n_s) beyond :data:`PRECOMPUTED_SETS_LIMIT` saddles.
    mode_deflection_bound
        (m,): max |z| of each mode over the cargo [m per unit modal coordinate].
    """

    reduced: ModalCorrectionSystem
    time_step_s: float
    predictor: NDArray[np.float64]
    force_response: NDArray[np.float64]
    receptance_m_per_N: NDArray[np.float64]
    set_inverses: NDArray[np.float64]
    mode_deflection_bound: NDArray[np.float64]

    @property
    def mode_count(self) -> int:
        return self.reduced.mode_count

    @property
    def saddle_count(self) -> int:
        return self.reduced.saddle_count

    def displacement_m(self, eta: NDArray, force_N: NDArray) -> NDArray[np.float64]:
        """q_c on the cargo DOFs from modal coordinates (..., m) and correction forces (..., n_s)."""
        return eta @ self.reduced.mode_shape.T + force_N @ self.reduced.residual_displacement_m_per_N.T

    def saddle_displacement_m(self, eta: NDArray, force_N: NDArray) -> NDArray[np.float64]:
        """q_c at the saddles' z DOFs (..., n_s) [m]."""
        r = self.reduced
        return eta @ r.saddle_mode_shape.T + force_N @ r.residual_displacement_m_per_N[r.saddle_dof].T


def newmark_step(
    model: StructuralModel,
    time_step_s: float,
    cutoff_rad_s: float | None = None,
    *,
    minimum_modes: int | None = None,
    precomputed_sets_limit: int = PRECOMPUTED_SETS_LIMIT,
) -> NewmarkStep:
    """Reduce the correction system of ``model`` and build its Newmark operators for the step ``time_step_s``.

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
    precomputed_sets_limit
        Up to this many saddles the contact matrices of every detached set are inverted up front
        (default :data:`PRECOMPUTED_SETS_LIMIT`); beyond, each trial set is solved directly.

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
    if n_s <= int(precomputed_sets_limit):
        codes = np.arange(2**n_s)
        masks = ((codes[:, None] >> np.arange(n_s)[None, :]) & 1).astype(float)
        mats = np.eye(n_s)[None] - G[None] * (k_u[None, :] * masks)[:, None, :]
        inverses = np.linalg.inv(mats)
    else:
        inverses = np.zeros((0, n_s, n_s))
    return NewmarkStep(
        reduced=reduced,
        time_step_s=dt,
        predictor=np.ascontiguousarray(predictor),
        force_response=np.ascontiguousarray(force_response),
        receptance_m_per_N=np.ascontiguousarray(G),
        set_inverses=np.ascontiguousarray(inverses),
        mode_deflection_bound=np.max(np.abs(phi[0::2]), axis=0, initial=0.0),
    )


@dataclass
class MarchState:
    """Mutable state of one march (modal coordinates and their rates, forces, detached set)."""

    eta: NDArray[np.float64]
    eta_dot: NDArray[np.float64]
    eta_ddot: NDArray[np.float64]
    force_N: NDArray[np.float64]
    detached: NDArray[np.bool_]

    @staticmethod
    def at_rest(system: NewmarkStep) -> MarchState:
        m, n_s = system.mode_count, system.saddle_count
        return MarchState(np.zeros(m), np.zeros(m), np.zeros(m), np.zeros(n_s), np.zeros(n_s, dtype=bool))

    @staticmethod
    def quasi_static(system: NewmarkStep, linear_compression_m: NDArray) -> MarchState:
        """At rest in the exact-contact static state of ``linear_compression_m`` (n_s,).

        ``c`` from ``delta = delta_lin - G_0 c``, ``G_0 = B^T K^-1 B``, solved exactly by
        :func:`~seafast.solvers.exact_contact.solve_exact_contact`; ``eta = Omega^-2 Phi_B^T c``
        (the static modal part; the residual flexibility carries the rest).
        """
        d_lin = np.asarray(linear_compression_m, dtype=float)
        r = system.reduced
        delta, c = solve_exact_contact(d_lin[None], r.static_flexibility_m_per_N, r.unilateral_stiffness_N_per_m)
        eta = (r.saddle_mode_shape.T @ c[0]) / r.natural_frequency_rad_s**2
        m = system.mode_count
        return MarchState(eta, np.zeros(m), np.zeros(m), c[0], delta[0] < 0.0)
