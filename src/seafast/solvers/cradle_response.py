"""The periodic response of the 3-D cargo on its cradles, whichever solver found it (:class:`CradleResponse`).

The harmonic balance (:func:`~seafast.solvers.cradle_hbm.solve_cradle_hbm`), the exact-event shooting
(:func:`~seafast.solvers.cradle_shooting.solve_cradle_shooting`) and the time-domain references return it.

Units: engagements [m]; forces [N]; displacements [m, rad]; time [s].
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from seafast.fourier import period_fraction
from seafast.model.cradle import Side
from seafast.solvers.cradle_dynamics import CradleDynamics
from seafast.solvers.cradle_march import CradleMarch, Periodicity
from seafast.solvers.outcome import SolverOutcome

__all__ = ["CradleResponse", "cradle_response"]


@dataclass(frozen=True)
class CradleResponse:
    """One period of the steady state of the 3-D cargo on its cradles, sampled at ``t_n = n P T / N`` (P the
    ``period_multiple``: 1 but where the steady state repeats only every P wave periods).

    Attributes
    ----------
    outcome, residual, message
        How the solve ended (:class:`~seafast.solvers.outcome.SolverOutcome`), its largest residual relative to
        the largest linear engagement [-], and the account for people.
    omega_rad_s, harmonics
        The wave's frequency [rad/s] and H (0 for a time-sampled reference; of the base frequency
        ``omega_rad_s / period_multiple`` for a subharmonic).
    time_s
        Sample times (N,) [s], over ``period_multiple`` wave periods.
    engagement_m
        Every element's engagement (pads port then starboard per pair, stoppers, lashings) (N, m) [m]: compression,
        overclosure, stretch; open or slack where <= 0.
    element_force_N
        ``k max(s, 0)`` (N, m) [N]: exactly 0 where open or slack.
    pad_count, stopper_count
        Pads (two per pair) and stoppers, to split the elements.
    cargo_displacement_m
        Cargo DOFs over the period (N, 5 n) [m, rad] (:mod:`seafast.model.cargo3d`'s order), relative to the vessel's
        rigid-body frame, static part included.
    pad_normal
        Unit (y, z) push of each pad on the cargo, (n_pairs, 2, 2).
    peak_force_change
        With H chosen adaptively, the largest change of an element's peak force from the H before, over its force
        scale (:func:`~seafast.solvers.hbm.harmonics.force_scale_N`) [-]; 0 where the linear solution is exact
        (every element engaged all period); NaN at a fixed H.
    march
        Where the adaptive choice needed it (no H converging directly), the march of the correction system in
        time (:class:`~seafast.solvers.cradle_march.CradleMarch`): its ``periodicity`` says whether the steady state
        repeats every wave period (the harmonic balance then started from it), after several
        (``SUBHARMONIC``) or not at all (``NOT_PERIODIC``; ``outcome`` then ``NOT_PERIODIC``, or
        ``CONVERGED_SUBHARMONIC`` where the exact-event shooting found the subharmonic orbit); None otherwise.
    period_multiple
        The wave periods the response spans and repeats after (1; 2 to 6 for a subharmonic) [-].
    """

    outcome: SolverOutcome
    residual: float
    message: str
    omega_rad_s: float
    harmonics: int
    time_s: NDArray[np.float64]
    engagement_m: NDArray[np.float64]
    element_force_N: NDArray[np.float64]
    pad_count: int
    stopper_count: int
    cargo_displacement_m: NDArray[np.float64]
    pad_normal: NDArray[np.float64]
    peak_force_change: float = float("nan")
    march: CradleMarch | None = None
    period_multiple: int = 1

    @property
    def periodicity(self) -> Periodicity | None:
        """What the march found the steady state to be (None where no march was needed)."""
        return None if self.march is None else self.march.periodicity

    @property
    def converged(self) -> bool:
        return self.outcome.converged

    @property
    def pad_force_N(self) -> NDArray[np.float64]:
        """(N, n_pairs, 2): port, starboard pad of each pair [N]."""
        return self.element_force_N[:, : self.pad_count].reshape(len(self.time_s), -1, 2)

    @property
    def stopper_force_N(self) -> NDArray[np.float64]:
        return self.element_force_N[:, self.pad_count : self.pad_count + self.stopper_count]

    @property
    def lashing_tension_N(self) -> NDArray[np.float64]:
        return self.element_force_N[:, self.pad_count + self.stopper_count :]

    @property
    def pair_force_N(self) -> NDArray[np.float64]:
        """Each pair's resultant push on the cargo (N, n_pairs, 2): across (y, to port +) and up (z) [N]."""
        return np.einsum("tps,psj->tpj", self.pad_force_N, self.pad_normal)

    @property
    def max_force_N(self) -> NDArray[np.float64]:
        """Each element's largest force over the period (m,) [N]."""
        return np.max(self.element_force_N, axis=0)

    @property
    def min_force_N(self) -> NDArray[np.float64]:
        return np.min(self.element_force_N, axis=0)

    @property
    def open_fraction(self) -> NDArray[np.float64]:
        """Fraction of the period each element is open (pad lifted, stopper clear) or slack (lashing) (m,) [-]."""
        return np.mean(self.engagement_m <= 0.0, axis=0)


def cradle_response(
    dynamics: CradleDynamics,
    engagement_m: NDArray[np.float64],
    cargo_displacement_m: NDArray[np.float64],
    omega_rad_s: float,
    outcome: tuple[SolverOutcome, float, str, int],
    period_multiple: int = 1,
) -> CradleResponse:
    """A :class:`CradleResponse` of sampled engagements (N, m) and displacements (N, 5 n) over ``period_multiple``
    wave periods; ``outcome``: (outcome, relative residual, message, H)."""
    problem = dynamics.problem
    N = engagement_m.shape[0]
    k = problem.element_stiffness_N_per_m
    normals = np.array([[pair.pad_normal(side) for side in (Side.PORT, Side.STARBOARD)] for pair in problem.pad_pairs]).reshape(-1, 2, 2)
    return CradleResponse(
        outcome=outcome[0],
        residual=float(outcome[1]),
        message=outcome[2],
        omega_rad_s=float(omega_rad_s),
        harmonics=int(outcome[3]),
        time_s=period_fraction(N) * 2.0 * np.pi * int(period_multiple) / omega_rad_s,
        engagement_m=engagement_m,
        element_force_N=k * np.maximum(engagement_m, 0.0),
        pad_count=2 * len(problem.pad_pairs),
        stopper_count=len(problem.stoppers),
        cargo_displacement_m=cargo_displacement_m,
        pad_normal=normals,
        period_multiple=int(period_multiple),
    )
