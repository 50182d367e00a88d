"""Harmonic balance with Alternating Frequency-Time (HBM/AFT) for the unilateral saddles.

Equation of motion (docs/theory.md#5-harmonic-balance), cargo DOFs q, deck DOFs x_o prescribed::

    M q'' + D q' + K q = f_static + f_vessel(t) - K_co x_o(t) - D_co x_o'(t) + B f(delta(t)),
    delta = z_deck - z_cargo  (saddle compression, positive compressed),

(D_co: the damping acts on the cargo's motion relative to the quasi-static support motion,
:attr:`~seafast.model.structure.StructuralModel.support_damping_coupling`)

with f the contact law of the compression-only saddle part (force on the cargo, upward) and B
the map from saddles to cargo z DOFs. The periodic steady state is expanded in H harmonics
``x(t) = Re(sum_{k=0..H} X_k exp(i k omega t))``; the nonlinear force goes through AFT: inverse
DFT to N time samples ``t_n = n T / N``, the contact law per sample, DFT back.

Real harmonic layout (used by every unknown vector here): coefficient row 0 is the mean,
rows 2k-1 and 2k are the cosine and sine coefficients a_k, b_k of harmonic k, so
``x(t) = a_0 + sum_k a_k cos(k w t) + b_k sin(k w t)`` and ``X_k = a_k - i b_k``.

Two formulations, giving the same answer (to the solver tolerance):

``condensed`` (default)
    Every saddle is kept *bilaterally* in the linear part (well conditioned, never a
    mechanism); the nonlinearity is the correction force ``c = f(delta) - k_u delta`` that
    removes the tension a bilateral spring would carry. Per harmonic the receptance
    ``G_k = B^T (K_d^cc(k omega))^-1 B`` (one banded factorisation per harmonic) condenses the
    problem exactly onto the saddle compressions: unknowns are their n_s (2H+1) harmonic
    coefficients and ``R = delta - delta_lin + G DFT[c(IDFT delta)] = 0``, Jacobian
    ``I + G DFT diag(f'(delta) - k_u) IDFT``. Where contact is kept, c = 0 and the linear answer
    is exact. Cargo harmonics follow as ``X_k = X_lin,k + (K_d^cc)^-1 B C_k``.
``full`` (as the source)
    All cargo DOFs (n_c (2H+1) unknowns, the corrections to the linear response), linear part
    without the compression-only saddle springs, contact force from AFT on the saddle DOFs,
    analytic Jacobian. The linear part is block diagonal per harmonic and banded, coupled only
    through the saddle DOFs: the Jacobian is assembled sparse on a fixed pattern and factorised
    by a sparse LU (SuperLU) once per Newton iteration. Roughly 15x slower than ``condensed``
    (a dense LU per iteration, as the source, costs seconds); kept as a check and for fidelity
    to the source.

Start: the better (smaller residual) of the linear solution and the *quasi-static
exact-contact predictor* -- each AFT sample of the linear compression corrected by the exact
static contact problem with the static receptance G_0 (active-set solver of
:mod:`seafast.solvers.exact_contact`), then transformed back to harmonics. For wave excitation
(far below the cargo's modes) it is within a few per cent of the HBM solution, so Newton
converges in 2-6 iterations even where the piecewise-linear exact law makes Newton from the
linear solution cycle.

Solvers: ``newton`` (semi-smooth Newton with the exact law, the package's one Newton of
:mod:`seafast.solvers.newton`; globalised by a non-monotone Armijo line search on ``||R||^2 / 2``,
a Levenberg-Marquardt step where the line search fails, and an early exit on stagnation) and ``hybr`` (MINPACK's Powell hybrid method via
``scipy.optimize.root`` with the analytic Jacobian, as the source). If the direct solve fails,
a second direct solve starts from the linear solution, then the solver continues in the
contact-law sharpness kappa (soft to the requested law) and then in the dynamic excitation
amplitude (static state to full amplitude) before giving up; the response's ``outcome``
(:class:`~seafast.solvers.outcome.SolverOutcome`) says which: ``CONVERGED`` (direct solve),
``CONVERGED_BY_CONTINUATION`` or ``NOT_CONVERGED`` (reported, never raised); its ``path``
(:class:`~seafast.solvers.outcome.HBMPath`) which start and which route; the message tells people
the same in words.

Modules: :mod:`~seafast.solvers.hbm.options` (:class:`HBMOptions`, :data:`SAFE_HARMONICS`),
:mod:`~seafast.solvers.hbm.condensed` (operators and problem of the condensed formulation),
:mod:`~seafast.solvers.hbm.full` (the full-DOF problem), :mod:`~seafast.solvers.hbm.nonlinear`
(Newton's globalisation, hybr and the fallback chain, for any
:class:`~seafast.solvers.hbm.nonlinear.NonlinearProblem`), :mod:`~seafast.solvers.hbm.harmonics`
(the truncation indicator and the march's choice of H), :mod:`~seafast.solvers.hbm.fixed` (one solve
at a fixed H), :mod:`~seafast.solvers.hbm.adaptive` (the adaptive choice of H),
:mod:`~seafast.solvers.hbm.solve` (the entry point). The Fourier kernels are in
:mod:`seafast.fourier`, the dynamic stiffness in :mod:`seafast.solvers.dynamic_stiffness`.
"""

from seafast.solvers.hbm.condensed import CondensedOperators, CondensedProblem, condensed_operators
from seafast.solvers.hbm.fixed import CondensedSolution, solve_condensed
from seafast.solvers.hbm.options import SAFE_HARMONICS, SOURCE_OPTIONS, HBMOptions
from seafast.solvers.hbm.solve import solve_hbm

__all__ = [
    "HBMOptions",
    "SOURCE_OPTIONS",
    "SAFE_HARMONICS",
    "solve_hbm",
    "CondensedOperators",
    "CondensedProblem",
    "condensed_operators",
    "solve_condensed",
    "CondensedSolution",
]
