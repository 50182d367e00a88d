"""The transient integrator of the saddles' contact problem: any loading, from any state, compiled.

One integrator serves every march of the nonlinear cargo: the Monte Carlo reference of a sea
state (:mod:`seafast.analyses.seastate.realisation`: windows, states, moment outputs, 3-hour records at a few
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
``q_c = Phi eta + R c`` (:func:`seafast.solvers.modal_correction.modal_correction_system`, the
:class:`~seafast.solvers.modal_correction.ModalCorrectionSystem` a :class:`NewmarkStep` carries): the
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

Modules: :mod:`~seafast.solvers.transient.newmark` (the time step, the Newmark operators of one step of
the reduced system, :class:`NewmarkStep`, and the march's state), :mod:`~seafast.solvers.transient.kernels`
(the compiled step loop and contact solve), :mod:`~seafast.solvers.transient.window` (:func:`march_window`,
a window of fine steps with its maxima), :mod:`~seafast.solvers.transient.record` (a whole record) and
:mod:`~seafast.solvers.transient.periodic_march` (one period marched over and over).

Units: SI throughout (m, rad, N, s). Nothing here prints, reads or writes files.
"""

from seafast.solvers.transient.newmark import (
    DEFAULT_CUTOFF_FACTOR,
    DEFAULT_STEPS_PER_PERIOD,
    PRECOMPUTED_SETS_LIMIT,
    MarchState,
    NewmarkStep,
    newmark_step,
    reference_frequency_rad_s,
    time_step_s,
)
from seafast.solvers.transient.periodic_march import PeriodicMarch, march_period, march_periodic
from seafast.solvers.transient.record import TransientRecord, integrate_record
from seafast.solvers.transient.window import MomentOutput, WindowOutcome, march_window

__all__ = [
    "DEFAULT_STEPS_PER_PERIOD",
    "DEFAULT_CUTOFF_FACTOR",
    "PRECOMPUTED_SETS_LIMIT",
    "reference_frequency_rad_s",
    "time_step_s",
    "NewmarkStep",
    "newmark_step",
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
