"""The shared Newton kernel (solvers/newton.py): convergence, the acceptance rules, and each typed stop.

Small systems whose iterates are known exactly: a smooth system (quadratic convergence), a piecewise-linear
one (semi-smooth Newton terminates), scripted residuals that tell the non-monotone reference and the
converged-trial rule apart, and systems built to end in each :class:`NewtonStop`.
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest

from seafast.solvers.newton import DenseJacobian, Globalisation, Merit, NewtonStop, newton

SQUARES = Globalisation(merit=Merit.SUM_OF_SQUARES)
MONOTONE_MAX = Globalisation(merit=Merit.MAX_ABS, min_step=2.0**-29)


class Circle:
    """``R = [u0^2 + u1^2 - 4, u0 - u1]``: the root (sqrt 2, sqrt 2) from (1, 0.5)."""

    scale = 1.0

    def __init__(self) -> None:
        self.history: list[float] = []

    def residual(self, u):
        R = np.array([u[0] ** 2 + u[1] ** 2 - 4.0, u[0] - u[1]])
        self.history.append(float(np.max(np.abs(R))))
        return R, u.copy()

    def factorise(self, u):
        return DenseJacobian(np.array([[2.0 * u[0], 2.0 * u[1]], [1.0, -1.0]]))


class Kinked:
    """``R(u) = u + 2 max(u, 0) - 1`` (a saddle's exact law in one unknown): the root u = 1/3."""

    scale = 1.0

    def residual(self, u):
        return u + 2.0 * np.maximum(u, 0.0) - 1.0, u.copy()

    def factorise(self, u):
        return DenseJacobian(np.diag(1.0 + 2.0 * np.heaviside(u, 0.5)))


class Scripted:
    """A scalar residual given at listed points (default elsewhere), unit Jacobian: Newton steps ``d = -R``."""

    scale = 1.0

    def __init__(self, values: dict[float, float], default: float):
        self.values, self.default = values, default

    def residual(self, u):
        for x, r in self.values.items():
            if abs(float(u[0]) - x) < 1e-12:
                return np.array([r]), None
        return np.array([self.default]), None

    def factorise(self, state):
        return DenseJacobian(np.eye(1))


def test_a_smooth_system_converges_quadratically():
    system = Circle()
    r = newton(system, np.array([1.0, 0.5]), tolerance=1e-14, max_iterations=20, globalisation=SQUARES)
    assert r.stop is NewtonStop.CONVERGED and r.converged
    np.testing.assert_allclose(r.u, [math.sqrt(2.0), math.sqrt(2.0)], rtol=1e-14)
    # full steps, each residual within twice the previous one squared: 2.75, 2.1, 0.18, 2e-3, 2.6e-7, 4e-15
    errors = system.history
    assert r.iterations == len(errors) - 1 == r.evaluations - 1
    assert all(b <= 2.0 * a * a for a, b in itertools.pairwise(errors[1:]))


def test_semi_smooth_newton_terminates_on_a_piecewise_linear_residual():
    """From u = -2 the generalised Jacobian 1 steps to u = 1, where 3 steps to the root 1/3: two full steps."""
    r = newton(Kinked(), np.array([-2.0]), tolerance=1e-12, max_iterations=10, globalisation=SQUARES)
    assert r.converged and r.iterations == 2 and r.evaluations == 3 and r.u[0] == pytest.approx(1.0 / 3.0, rel=1e-15)


def test_the_armijo_reference_is_the_largest_of_the_last_memory_merits():
    """Iterates 0 (R = -1), 1 (R = -0.5), then the full step to 1.5 raises |R| to 0.6: above the current
    merit, below the first. Memory 4 accepts it (and converges at 2.1); memory 1 backtracks to 1.25."""
    values = {0.0: -1.0, 1.0: -0.5, 1.5: -0.6, 1.25: -0.1, 2.1: 0.0, 1.35: 0.0}
    kw = dict(tolerance=1e-9, max_iterations=10)
    wide = newton(Scripted(values, 5.0), np.array([0.0]), globalisation=Globalisation(merit=Merit.SUM_OF_SQUARES, memory=4), **kw)
    narrow = newton(Scripted(values, 5.0), np.array([0.0]), globalisation=SQUARES, **kw)
    assert wide.converged and wide.u[0] == pytest.approx(2.1) and wide.iterations == 3
    assert narrow.converged and narrow.u[0] == pytest.approx(1.35) and narrow.iterations == 3


def test_a_trial_that_meets_the_tolerance_is_accepted_when_asked():
    """The max-abs merit barely falls (1.00001e-3 to 1e-3, short of Armijo's 1e-4 share) but meets the
    tolerance 1e-3: accepted with ``accept_converged_trial``, else every shorter step is worse."""
    values = {0.0: -1.00001e-3, 1.00001e-3: -1.0e-3}
    kw = dict(tolerance=1e-3, max_iterations=5)
    taken = newton(
        Scripted(values, 1.0), np.array([0.0]), globalisation=Globalisation(merit=Merit.MAX_ABS, accept_converged_trial=True), **kw
    )
    refused = newton(Scripted(values, 1.0), np.array([0.0]), globalisation=Globalisation(merit=Merit.MAX_ABS), **kw)
    assert taken.converged and taken.iterations == 1 and taken.u[0] == pytest.approx(1.00001e-3)
    assert refused.stop is NewtonStop.LINE_SEARCH_FAILED and refused.u[0] == 0.0 and refused.iterations == 0


def test_each_way_of_stopping_is_typed():
    start = np.array([1.0, 0.5])
    capped = newton(Circle(), start, tolerance=1e-14, max_iterations=1, globalisation=SQUARES)
    assert capped.stop is NewtonStop.MAX_ITERATIONS and capped.iterations == 1 and capped.relative_residual > 1e-3

    class NotFinite(Circle):
        def residual(self, u):
            return np.array([np.nan, 0.0]), u.copy()

    bad = newton(NotFinite(), start, tolerance=1e-14, max_iterations=5, globalisation=SQUARES)
    assert bad.stop is NewtonStop.NON_FINITE and bad.iterations == 0 and not bad.converged

    class Uphill(Circle):
        def factorise(self, u):  # the Jacobian's sign flipped: the Newton direction climbs
            return DenseJacobian(-super().factorise(u).J)

    climbs = newton(Uphill(), start, tolerance=1e-14, max_iterations=5, globalisation=SQUARES)
    assert climbs.stop is NewtonStop.LINE_SEARCH_FAILED and np.array_equal(climbs.u, start)
    assert climbs.evaluations == 1 + 11  # the start, then steps 1 .. 1/1024
    with_lm = Globalisation(merit=Merit.SUM_OF_SQUARES, levenberg_marquardt=True)
    lm = newton(Uphill(), start, tolerance=1e-14, max_iterations=5, globalisation=with_lm)
    assert lm.stop is NewtonStop.LEVENBERG_MARQUARDT_FAILED and np.array_equal(lm.u, start)
    too_many = Globalisation(merit=Merit.SUM_OF_SQUARES, levenberg_marquardt=True, levenberg_marquardt_max_unknowns=1)
    assert newton(Uphill(), start, tolerance=1e-14, max_iterations=5, globalisation=too_many).stop is NewtonStop.LINE_SEARCH_FAILED


def test_levenberg_marquardt_steps_past_a_singular_jacobian_then_stagnation_stops():
    """``R = [u0 - 1, u1^2 - 1]`` at u1 = 0: J is singular, Levenberg-Marquardt moves u0 to 1 and leaves u1,
    whose residual -1 then stays: the merit stalls at 1/2 and the stagnation window ends it."""

    class Singular:
        scale = 1.0

        def residual(self, u):
            return np.array([u[0] - 1.0, u[1] ** 2 - 1.0]), u.copy()

        def factorise(self, u):
            return DenseJacobian(np.array([[1.0, 0.0], [0.0, 2.0 * u[1]]]))

    g = Globalisation(merit=Merit.SUM_OF_SQUARES, levenberg_marquardt=True, stagnation_window=3)
    r = newton(Singular(), np.array([3.0, 0.0]), tolerance=1e-12, max_iterations=50, globalisation=g)
    assert r.stop is NewtonStop.STAGNATED and r.levenberg_marquardt_steps == r.iterations == 6  # 2 windows of steps, then the check
    assert r.u[0] == pytest.approx(1.0, abs=1e-9) and r.u[1] == 0.0 and r.relative_residual == 1.0


def test_the_globalisation_is_validated():
    with pytest.raises(ValueError, match="memory"):
        Globalisation(merit=Merit.MAX_ABS, memory=0)
    with pytest.raises(ValueError, match="min_step"):
        Globalisation(merit=Merit.MAX_ABS, min_step=0.0)
    assert MONOTONE_MAX.memory == 1 and DenseJacobian(np.zeros((1, 1))).solve(np.ones(1)) is None
    assert DenseJacobian(np.zeros((1, 1)), least_squares=True).solve(np.ones(1)) == pytest.approx([0.0])
