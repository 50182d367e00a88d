"""The dynamics of each contact state of the correction system, in closed form.

The correction system of the saddles (:mod:`seafast.solvers.transient`, :mod:`seafast.solvers.modal_correction`):
the cargo's modes on bilateral saddles, ``eta'' + Xi eta' + Omega^2 eta = Phi_s^T c``, the correction
force ``c = k_u max(-delta, 0)`` where a saddle has lifted, and the compression
``delta = d(t) - Phi_s eta - R c`` (``d`` the linear compressions, ``R`` the static residual
flexibility of the modes left out). For a fixed set L of lifted saddles it is linear: on L,
``c_L = W_L (Phi_L eta - d_L)`` with ``W_L = (I - K_L R_LL)^-1 K_L``, so the state ``x = [eta; eta']``
obeys ``x' = A_L x + B_L d_L(t)`` with ``A_L = [[0, I], [-(Omega^2 - Phi_L^T W_L Phi_L), -Xi]]``. Its
response is known exactly: ``x(t) = Re(V e^{Lambda (t - t0)} V^-1) (x(t0) - x_p(t0)) + x_p(t)``, with
``x_p`` the particular solution of the excitation's harmonics (``(i k w - A_L) X_k = B_L D_k``).

On the lifted basis (:class:`~seafast.solvers.modal_correction.CorrectionBasis`, stiff saddles) the same holds with
the saddles in contact C adding their stiffness instead, ``Omega^2 + Phi_C^T W_C Phi_C`` with
``W_C = (I + K_C R_CC)^-1 K_C``, and the input ``g = f - K_u d`` in place of ``c`` (:func:`_lifted_state`).

A state with no stiffness against a rigid-body motion raises :class:`SingularStateError`, unless the states are
built with ``mechanisms`` (the 3-D cargo's cradles): then its vanishing roots are 0 and the constant load's part along
the motion is the particular solution's drift, ``x_p(t) = Re sum_k X_k e^{i k w t} + x_d t`` (``X_0`` without that
part), exact for a root 0 and, for a root within the vanishing bound, the same motion to ``|lambda| t``.

The vector field is continuous where a saddle changes state (``c_i = 0`` and ``delta_i = 0`` there from both
sides), so the flow's Jacobian is continuous too: the monodromy matrix of a period is the product of the
segments' ``e^{A_L tau}``, with no saltation terms.

Units: SI (m, rad, N, s); compressions positive when the saddle is compressed.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from seafast.solvers.modal_correction import CorrectionBasis, ModalCorrectionSystem

__all__ = [
    "ContactState",
    "ContactStates",
    "MECHANISM_CONDITION",
    "SingularStateError",
    "StateArrays",
    "lifted_code",
    "modal_exponential",
    "stiffness_cancellation",
]

_SMALLEST_EXPONENT = -300.0  # e^-300: a decayed mode, kept above the subnormal range (whose arithmetic is slow)


def lifted_code(lifted: NDArray[np.bool_]) -> int:
    """A contact state's code: bit i set when saddle i is lifted (:meth:`ContactStates.lifted_of` inverts it)."""
    return int(np.sum(np.left_shift(1, np.nonzero(lifted)[0]))) if np.any(lifted) else 0


def modal_exponential(exponent: NDArray[np.complex128]) -> NDArray[np.complex128]:
    """``e^{exponent}`` with the real parts held at or above -300 (decayed modes stay 1e-130, never subnormal)."""
    arg = np.asarray(exponent, dtype=complex)
    return np.exp(np.maximum(arg.real, _SMALLEST_EXPONENT) + 1j * arg.imag)


class SingularStateError(ValueError):
    """A contact state with no stiffness left against a rigid-body motion (every support lifted, no lashing)."""


@dataclass(frozen=True)
class ContactState:
    """One set of lifted saddles and its closed-form dynamics.

    Attributes
    ----------
    lifted
        (n_s,) which saddles are lifted (carry the correction force).
    eigenvalues, eigenvectors, inverse_eigenvectors
        ``A_L = V diag(Lambda) V^-1`` [1/s], complex, (2m,), (2m, 2m), (2m, 2m).
    particular
        ``X_k``, the particular solution's harmonics, complex (n_k, 2m): ``x_p(t) = Re sum_k X_k e^{i k w t}``.
    compression_state, compression_forcing
        ``delta = compression_state @ x + compression_forcing @ d`` [m per unit state], (n_s, 2m), (n_s, n_s).
    force_state, force_forcing
        ``c = force_state @ x + force_forcing @ d`` [N per unit state], (n_s, 2m), (n_s, n_s).
    modal_compression
        ``compression_state @ V`` (n_s, 2m): the compressions of the modal coordinates ``y = V^-1 x``.
    particular_compression
        The particular solution's compressions, complex harmonics (n_k, n_s) [m]: with ``z = V^-1 (x(t0) - x_p(t0))``,
        ``delta(t) = Re(modal_compression (e^{Lambda (t - t0)} z)) + Re sum_k P_k e^{i k w t} + drift_compression t``.
    drift, drift_compression
        The particular solution's drift (2m,) [state per s] and its compressions' (n_s,) [m/s]: zero but in a state
        with a rigid-body motion (a mechanism, root 0: :class:`ContactStates` ``mechanisms``), where the constant
        load's part along it moves the cargo at a constant rate, ``x_p(t) = Re sum_k X_k e^{i k w t} + drift t``.
    """

    lifted: NDArray[np.bool_]
    eigenvalues: NDArray[np.complex128]
    eigenvectors: NDArray[np.complex128]
    inverse_eigenvectors: NDArray[np.complex128]
    particular: NDArray[np.complex128]
    compression_state: NDArray[np.float64]
    compression_forcing: NDArray[np.float64]
    force_state: NDArray[np.float64]
    force_forcing: NDArray[np.float64]
    modal_compression: NDArray[np.complex128]
    particular_compression: NDArray[np.complex128]
    drift: NDArray[np.float64]
    drift_compression: NDArray[np.float64]

    def propagator(self, tau_s: float) -> NDArray[np.float64]:
        """``e^{A_L tau}`` (2m, 2m)."""
        V = self.eigenvectors
        return np.real((V * modal_exponential(self.eigenvalues * tau_s)[None, :]) @ self.inverse_eigenvectors)


@dataclass(frozen=True)
class StateArrays:
    """The built contact states stacked for the compiled march, and each code's index (-1: not built).

    ``table`` (2^n_s,): the index of the state with code c (bit i set when saddle i is lifted); the stacks
    (capacity, ...), their rows beyond the states built unused (zeros): eigenvalues, eigenvectors and their
    inverse, the modal and the particular compressions, the particular solution's harmonics, its drifts and the lifted
    sets, as in :class:`ContactState`.
    """

    table: NDArray[np.int64]
    eigenvalues: NDArray[np.complex128]
    eigenvectors: NDArray[np.complex128]
    inverse_eigenvectors: NDArray[np.complex128]
    modal_compression: NDArray[np.complex128]
    particular_compression: NDArray[np.complex128]
    particular: NDArray[np.complex128]
    drift_compression: NDArray[np.float64]
    drift: NDArray[np.float64]
    lifted: NDArray[np.bool_]


_STACKED_FIELDS = (
    "eigenvalues",
    "eigenvectors",
    "inverse_eigenvectors",
    "modal_compression",
    "particular_compression",
    "particular",
    "drift_compression",
    "drift",
    "lifted",
)
"""The :class:`ContactState` arrays that :class:`StateArrays` stacks."""

MAX_SADDLES = 24
"""Saddles at most (the table of contact states has 2^n_s entries)."""


class ContactStates:
    """The contact states of one model and excitation, built on first use and kept (a solve's own cache).

    Parameters
    ----------
    system
        The reduced correction system (modes, modal damping, residual flexibility, k_u).
    compression_harmonics
        ``D_k``, the linear compressions' complex harmonics (n_k, n_s) [m]: ``d(t) = Re sum_k D_k e^{i k w t}``.
    omega_rad_s
        The fundamental frequency w [rad/s].
    dynamics
        A cache of the states' excitation-independent parts (eigendecompositions) for this ``system``, kept by its
        owner (the model's ``derived_cache``) so that another excitation of the same model reuses them; None: none.
    mechanisms
        False (the default): a state with no stiffness against a rigid-body motion raises :class:`SingularStateError`.
        True: such a state (a mechanism: its vanishing roots, round-off of 0, taken as 0; a defective one, no
        damping along it, still raises) is marched exactly, the constant load's part along the motion drifting the
        cargo at a constant rate (:attr:`ContactState.drift`) -- the 3-D cargo on one pad, its stoppers open, slides
        across until another pad or a stopper takes it.
    """

    def __init__(
        self,
        system: ModalCorrectionSystem,
        compression_harmonics: NDArray[np.complex128],
        omega_rad_s: float,
        dynamics: dict[bytes, StateDynamics] | None = None,
        *,
        mechanisms: bool = False,
    ):
        self.system = system
        self.mechanisms = bool(mechanisms)
        self.harmonics = np.asarray(compression_harmonics, dtype=complex)
        self.omega_rad_s = float(omega_rad_s)
        if system.saddle_count > MAX_SADDLES:
            raise ValueError(f"saddles: {system.saddle_count}; allowed: at most {MAX_SADDLES} for the shooting solver")
        self._states: dict[bytes, ContactState] = {}
        self._order: list[ContactState] = []
        self._table = np.full(2**system.saddle_count, -1, dtype=np.int64)
        self._stacked: StateArrays | None = None
        self._stacked_count = 0
        self._dynamics = dynamics
        self.cancellation = 0.0
        """The largest, over the states built, of ``||Phi_L^T W_L Phi_L|| / lambda_min(Omega^2 - Phi_L^T W_L Phi_L)``:
        how much of the bilateral modes' stiffness a lifted state cancels (near-rigid saddles: above 1e8)."""

    @property
    def state_size(self) -> int:
        return 2 * self.system.mode_count

    @property
    def visited(self) -> int:
        """How many contact states were built."""
        return len(self._states)

    def get(self, lifted: NDArray[np.bool_]) -> ContactState:
        """The state with these saddles lifted."""
        key = np.asarray(lifted, dtype=bool).tobytes()
        state = self._states.get(key)
        if state is None:
            state = self._build(np.asarray(lifted, dtype=bool).copy())
            self._states[key] = state
            self._table[lifted_code(state.lifted)] = len(self._order)
            self._order.append(state)
        return state

    def lifted_of(self, code: int) -> NDArray[np.bool_]:
        """The lifted set of a state code (bit i: saddle i lifted)."""
        return np.array([(int(code) >> i) & 1 == 1 for i in range(self.system.saddle_count)])

    @property
    def arrays(self) -> StateArrays:
        """The built states stacked for the compiled march.

        The stacks have room for twice the states built when they were last grown, so a march that meets a new
        state adds one row to each instead of stacking them all again (a 7-saddle orbit visits some 20 states).
        """
        count, stacked = len(self._order), self._stacked
        if stacked is not None and self._stacked_count == count:
            return stacked
        if stacked is None or stacked.eigenvalues.shape[0] < count:
            first = self._order[0]
            shape = (max(2 * count, 4),)
            grown = {name: np.zeros(shape + getattr(first, name).shape, dtype=getattr(first, name).dtype) for name in _STACKED_FIELDS}
            if stacked is not None:
                for name in _STACKED_FIELDS:
                    grown[name][: self._stacked_count] = getattr(stacked, name)[: self._stacked_count]
            stacked = StateArrays(table=self._table, **grown)
        for index in range(self._stacked_count, count):
            for name in _STACKED_FIELDS:
                getattr(stacked, name)[index] = getattr(self._order[index], name)
        self._stacked, self._stacked_count = stacked, count
        return stacked

    def forcing(self, t_s: NDArray) -> NDArray[np.float64]:
        """``d(t)`` at the given times (n_t, n_s) [m]."""
        k = np.arange(self.harmonics.shape[0])
        phase = np.exp(1j * self.omega_rad_s * np.outer(np.atleast_1d(t_s), k))
        return np.real(phase @ self.harmonics)

    def _build(self, lifted: NDArray[np.bool_]) -> ContactState:
        key = np.asarray(lifted, dtype=bool).tobytes()
        dynamics = self._dynamics.get(key) if self._dynamics is not None else None
        if dynamics is None:
            dynamics = _state_dynamics(self.system, lifted, self.mechanisms)
            if self._dynamics is not None:
                self._dynamics[key] = dynamics
        lam, V, V_inv, input_matrix, force_state, force_forcing, compression_state, compression_forcing, cancellation = dynamics
        self.cancellation = max(self.cancellation, cancellation)
        w_k = 1j * self.omega_rad_s * np.arange(self.harmonics.shape[0])
        modal_input = V_inv @ (input_matrix @ self.harmonics.T)  # (2m, n_k)
        drift = np.zeros(V.shape[0])
        resonant = (w_k[None, :] == lam[:, None]) & (lam[:, None] == 0.0)  # a mechanism's root 0 and the constant load
        if np.any(resonant):  # x' = 0 x + u_0 along the mechanism: x_p = u_0 t, the drift
            zero = resonant[:, 0]
            drift = np.real(V[:, zero] @ modal_input[zero, 0])
            modal_input = np.where(resonant, 0.0, modal_input)
        particular = (V @ (modal_input / np.where(resonant, 1.0, w_k[None, :] - lam[:, None]))).T  # (n_k, 2m)
        return ContactState(
            lifted=lifted,
            eigenvalues=lam,
            eigenvectors=V,
            inverse_eigenvectors=V_inv,
            particular=np.asarray(particular, dtype=complex),
            compression_state=compression_state,
            compression_forcing=compression_forcing,
            force_state=force_state,
            force_forcing=force_forcing,
            modal_compression=np.asarray(compression_state @ V, dtype=complex),
            particular_compression=np.asarray(particular @ compression_state.T + self.harmonics @ compression_forcing.T, dtype=complex),
            drift=drift,
            drift_compression=np.asarray(compression_state @ drift, dtype=float),
        )


StateDynamics = tuple[NDArray, NDArray, NDArray, NDArray, NDArray, NDArray, NDArray, NDArray, float]
"""A contact state's excitation-independent part: eigenvalues, eigenvectors and their inverse, the input matrix, the
force and compression maps (state, forcing), and its stiffness cancellation (:attr:`ContactStates.cancellation`)."""


def stiffness_cancellation(system: ModalCorrectionSystem, lifted: NDArray[np.bool_]) -> float:
    """How much of the modal stiffness a contact state cancels (:attr:`ContactStates.cancellation`) [-]; 0 on the lifted basis."""
    if system.basis is CorrectionBasis.LIFTED:
        return 0.0
    return _bilateral_state(system, np.asarray(lifted, dtype=bool))[4]


def _bilateral_state(s: ModalCorrectionSystem, lifted: NDArray[np.bool_]) -> tuple[NDArray, NDArray, NDArray, NDArray, float]:
    """The stiffness, input matrix (rows of eta''), force maps and stiffness cancellation of a state, bilateral basis.

    The input is the correction force ``c``: ``c_L = W_L (Phi_L eta - d_L)`` on the lifted saddles, 0 elsewhere.
    """
    m, n_s = s.mode_count, s.saddle_count
    Phi, R, k_u = s.saddle_mode_shape, s.residual_flexibility_m_per_N, s.unilateral_stiffness_N_per_m
    L = np.nonzero(lifted)[0]
    W = np.linalg.solve(np.eye(L.size) - k_u[L, None] * R[np.ix_(L, L)], np.diag(k_u[L])) if L.size else np.zeros((0, 0))
    removed = Phi[L].T @ W @ Phi[L]
    stiffness = np.diag(s.natural_frequency_rad_s**2) - removed
    softest = float(np.min(np.linalg.eigvalsh(0.5 * (stiffness + stiffness.T)), initial=np.inf))
    cancellation = float(np.linalg.norm(removed, 2) / softest) if L.size and softest > 0.0 else 0.0
    modal_input = np.zeros((m, n_s))
    modal_input[:, L] = -Phi[L].T @ W
    force_state = np.zeros((n_s, 2 * m))
    force_state[L, :m] = W @ Phi[L]
    force_forcing = np.zeros((n_s, n_s))
    force_forcing[np.ix_(L, L)] = -W
    return stiffness, modal_input, force_state, force_forcing, cancellation


def _lifted_state(s: ModalCorrectionSystem, lifted: NDArray[np.bool_]) -> tuple[NDArray, NDArray, NDArray, NDArray, float]:
    """As :func:`_bilateral_state` on the lifted basis: the saddles in contact (C) add their stiffness, nothing cancels.

    The input is ``g = f - K_u d`` (:class:`~seafast.solvers.modal_correction.CorrectionBasis`): ``g_L = -K_L d_L``
    on the lifted saddles and, with ``W_C = (I + K_C R_CC)^-1 K_C``, ``g_C = -W_C (Phi_C eta - R_CL K_L d_L)`` on the
    saddles in contact (from ``delta_C = d_C - Phi_C eta - R_C. g`` and ``g_C = K_C (delta_C - d_C)``); the state's
    stiffness is ``Omega^2 + Phi_C^T W_C Phi_C``.
    """
    m, n_s = s.mode_count, s.saddle_count
    Phi, R, k_u = s.saddle_mode_shape, s.residual_flexibility_m_per_N, s.unilateral_stiffness_N_per_m
    L, C = np.nonzero(lifted)[0], np.nonzero(~np.asarray(lifted, dtype=bool))[0]
    W = np.linalg.solve(np.eye(C.size) + k_u[C, None] * R[np.ix_(C, C)], np.diag(k_u[C])) if C.size else np.zeros((0, 0))
    W = 0.5 * (W + W.T)
    stiffness = np.diag(s.natural_frequency_rad_s**2) + Phi[C].T @ W @ Phi[C]
    force_state = np.zeros((n_s, 2 * m))
    force_state[C, :m] = -W @ Phi[C]
    force_forcing = np.zeros((n_s, n_s))
    force_forcing[np.ix_(C, L)] = W @ R[np.ix_(C, L)] * k_u[None, L]
    force_forcing[L, L] = -k_u[L]
    modal_input = Phi.T @ force_forcing  # eta'' = ... + Phi_s^T g, the part of g driven by d
    return stiffness, modal_input, force_state, force_forcing, 0.0


MECHANISM_CONDITION = 1e10
"""Largest condition number of a mechanism state's eigenvectors: above it the root 0 is defective (nothing damps the
rigid-body motion: ``x'' = u_0``, a Jordan block the closed form cannot take) and the state raises."""


def _mechanism_roots(lam: NDArray, V: NDArray, small: NDArray[np.bool_]) -> bool:
    """Whether the vanishing roots ``small`` of a state are a rigid-body motion's root 0 it can march: real (round-off
    of 0, within the vanishing bound), the other roots stable, and the eigenvectors independent (not defective)."""
    return bool(np.all(lam[~small].real <= 0.0) and np.linalg.cond(V) <= MECHANISM_CONDITION)


def _state_dynamics(s: ModalCorrectionSystem, lifted: NDArray[np.bool_], mechanisms: bool = False) -> StateDynamics:
    """The closed form of one contact state, whatever the excitation (see the module docstring); ``mechanisms``: a
    rigid-body motion's vanishing roots taken as 0 instead of raising (:class:`ContactStates`)."""
    m, n_s = s.mode_count, s.saddle_count
    Phi, R = s.saddle_mode_shape, s.residual_flexibility_m_per_N
    L = np.nonzero(lifted)[0]
    build = _lifted_state if s.basis is CorrectionBasis.LIFTED else _bilateral_state
    stiffness, modal_input, force_state, force_forcing, cancellation = build(s, lifted)
    A = np.zeros((2 * m, 2 * m))
    A[:m, m:] = np.eye(m)
    A[m:, :m] = -stiffness
    A[m:, m:] = -s.modal_damping
    input_matrix = np.zeros((2 * m, n_s))
    input_matrix[m:] = modal_input
    compression_state = -np.hstack([Phi, np.zeros((n_s, m))]) - R @ force_state
    compression_forcing = np.eye(n_s) - R @ force_forcing
    lam, V = np.linalg.eig(A)
    # on the lifted basis every state is at least as stiff as the lashings (which hold the cargo: a slow root of a
    # soft, damped lashing mode is no rigid-body motion); on the bilateral basis a vanishing root is one -- vanishing
    # against the highest natural frequency kept, not the largest root, which the stiffness-proportional damping of a
    # stiff mode inflates to beta w^2 (7.5e8 1/s with every mode of a 3-D cargo, against a held mode's 2.5e-3 1/s)
    highest = float(np.max(s.natural_frequency_rad_s, initial=1.0))
    small = (np.abs(lam) <= 1e-9 * max(highest, 1.0)) if s.basis is CorrectionBasis.BILATERAL else np.zeros(lam.size, dtype=bool)
    if mechanisms and np.any(small) and _mechanism_roots(lam, V, small):
        lam = np.where(small, 0.0, lam)  # round-off of the rigid-body motion's root 0
    elif np.any(small) or np.any(lam.real > 0.0):
        raise SingularStateError(f"contact state with saddles {L.tolist()} lifted has no stiffness against a rigid-body motion")
    V = np.asarray(V, dtype=complex)
    return (
        np.asarray(lam, dtype=complex),
        V,
        np.asarray(np.linalg.inv(V), dtype=complex),
        input_matrix,
        force_state,
        force_forcing,
        compression_state,
        compression_forcing,
        cancellation,
    )
