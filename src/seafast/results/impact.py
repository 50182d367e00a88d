"""Whether a saddle's peak force is an elastic impact: a force set by the saddle stiffness, not by the sea.

Where a saddle lifts off and comes back, the re-contact is an impact of the cargo on the saddle's spring: the
force rises from zero in a pulse of the contact's own frequency. Per unit approach velocity ``v`` (the rate at
which the gap closes) the pulse peaks at ``G(k)``, the impact's force per unit velocity, so the impact estimate is

    F_imp = v G(k).

``G`` is computed here for the cargo's finite-element beam (free, struck in heave at the saddle's node by the
saddle's compression-only spring ``k``; :func:`impact_force_per_velocity_N_s_per_m`): ``sqrt(k m)`` for a rigid
cargo of effective mass ``m``, about ``k^(1/3)`` for a flexible one on stiff saddles, where the pulse is short and
only the cargo near the saddle takes part. Where ``F_imp`` exceeds the force the saddle carries with its contact
kept (the linear row's peak at that saddle), the saddle's peak is the impact: it grows with ``k``
(docs/theory.md, section 5.8, measures it on the base case: as ``k^0.4`` from 1.1e12 N/m, 18.9 to 117 MN at
1e14 N/m, the same on a mesh of half the element length) and is no answer about the monopile, whose saddle
has a finite, measured stiffness and a local shell flexibility the beam model does not hold; the bending moment
and the displacements converge as ``k`` grows and remain valid.

:func:`impact_check` reads this from a converged nonlinear response (no second solve): each saddle's
re-contacts (:func:`~seafast.solvers.impact_pulse.recontact_velocities_m_s`), the largest impact estimate against the contact-kept peak,
flagged above :data:`IMPACT_RATIO_LIMIT`. The spring cannot store more than the cargo's kinetic energy, so
``G <= sqrt(k m)`` with ``m`` the cargo's mass; where that bound already keeps a saddle under the limit (the base
case's saddles) ``G`` is not computed.

Units: SI (m, s, N, kg). Nothing here prints or writes files.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
import xarray as xr
from numpy.typing import NDArray

from seafast.config.modes import SolverMethod
from seafast.config.schema import Case
from seafast.fourier import harmonics_to_time
from seafast.model.structure import StructuralModel
from seafast.model.warning import ModelWarning
from seafast.results.dataset import LOAD_CASES, MODELS
from seafast.solvers.impact_pulse import impact_force_per_velocity_N_s_per_m, recontact_velocities_m_s
from seafast.solvers.periodic import PeriodicResponse

__all__ = [
    "IMPACT_RATIO_LIMIT",
    "SaddleImpact",
    "ImpactCheck",
    "impact_check",
    "case_impact",
    "with_impact",
    "impact_flags",
    "fixed_harmonics_reason",
]

IMPACT_RATIO_LIMIT = 1.0
"""A saddle's peak force is flagged as an elastic impact when its largest impact estimate ``v G(k)`` exceeds this
multiple of the force the saddle carries with its contact kept (the linear row's peak there) [-]."""


@dataclass(frozen=True)
class SaddleImpact:
    """One saddle's re-contacts over the period.

    Attributes
    ----------
    saddle
        The saddle's index (0 = aft-most).
    stiffness_N_per_m
        Its compression-only stiffness ``k`` [N/m].
    force_per_velocity_N_s_per_m
        ``G(k)``: the peak of the impact pulse per unit approach velocity [N s/m]; where even its energy bound
        ``sqrt(k m)`` (``m`` the cargo's mass) leaves the saddle unflagged, that bound (``bounded``).
    approach_velocity_m_s
        The fastest re-contact's approach velocity (rate of closing of the gap) [m/s], > 0.
    peak_force_N
        The saddle's peak force over the period [N].
    contact_kept_force_N
        The saddle's peak force with its contact kept (the linear row's) [N].
    """

    saddle: int
    stiffness_N_per_m: float
    force_per_velocity_N_s_per_m: float
    approach_velocity_m_s: float
    peak_force_N: float
    contact_kept_force_N: float
    bounded: bool = False

    @property
    def impact_force_N(self) -> float:
        """The elastic-impact estimate ``v G(k)`` [N]."""
        return self.approach_velocity_m_s * self.force_per_velocity_N_s_per_m

    @property
    def ratio(self) -> float:
        """``impact_force_N / contact_kept_force_N`` [-] (inf without a contact-kept force)."""
        return self.impact_force_N / self.contact_kept_force_N if self.contact_kept_force_N > 0.0 else math.inf

    @property
    def flagged(self) -> bool:
        """Whether the saddle's peak is an elastic impact (:data:`IMPACT_RATIO_LIMIT`)."""
        return self.ratio > IMPACT_RATIO_LIMIT


@dataclass(frozen=True)
class ImpactCheck:
    """The saddles' re-contacts of one nonlinear row (``saddles`` empty: none re-contacts)."""

    saddles: tuple[SaddleImpact, ...]

    @property
    def flagged(self) -> tuple[SaddleImpact, ...]:
        """The saddles whose peak force is an elastic impact."""
        return tuple(s for s in self.saddles if s.flagged)

    @property
    def largest_ratio(self) -> float:
        """The largest impact estimate over its saddle's contact-kept force [-] (0: no re-contact)."""
        return max((s.ratio for s in self.saddles), default=0.0)

    def warning_lines(self) -> list[str]:
        """One line per flagged saddle for people (CLI, results.nc)."""
        return [
            f"saddle {s.saddle + 1}: its peak force {s.peak_force_N / 1e6:.4g} MN is an elastic impact: re-contact at "
            f"{s.approach_velocity_m_s * 1e3:.3g} mm/s on k = {s.stiffness_N_per_m:.3g} N/m, impact estimate "
            f"{s.impact_force_N / 1e6:.3g} MN, more than the {s.contact_kept_force_N / 1e6:.3g} MN the saddle carries with its "
            "contact kept; the force grows with the saddle stiffness and is not an answer: use a measured saddle stiffness "
            "(and check the force with a mesh study, model.element_length_m); the bending moment and the displacements "
            "remain valid"
            for s in self.flagged
        ]


def impact_check(model: StructuralModel, response: PeriodicResponse, contact_kept_force_N: NDArray) -> ImpactCheck:
    """The saddles' re-contacts of a nonlinear response and whether each peak force is an elastic impact.

    Parameters
    ----------
    model
        The cargo model the response belongs to.
    response
        A nonlinear periodic response (its compressions and forces on the uniform grid of one wave period).
    contact_kept_force_N
        Each saddle's peak force with its contact kept (the linear row's) [N], (n_s,).
    """
    period = 2.0 * np.pi / float(response.omega_rad_s)
    rates = recontact_velocities_m_s(response.saddle_compression_time_m, period)
    stiffness = np.asarray(model.saddle_unilateral_stiffness_N_per_m, dtype=float)
    peaks = np.max(np.asarray(response.saddle_force_time_N, dtype=float), axis=0)
    kept = np.asarray(contact_kept_force_N, dtype=float)
    saddles = []
    for i, r in enumerate(rates):
        if r.size and stiffness[i] > 0.0:
            # the spring cannot store more than the cargo's kinetic energy: G <= sqrt(k m), which often settles it
            bound = math.sqrt(float(stiffness[i]) * model.cargo.mass_kg)
            bounded = float(np.max(r)) * bound <= IMPACT_RATIO_LIMIT * float(kept[i])
            G = bound if bounded else impact_force_per_velocity_N_s_per_m(model, i, float(stiffness[i]))
            saddles.append(SaddleImpact(i, float(stiffness[i]), G, float(np.max(r)), float(peaks[i]), float(kept[i]), bounded))
    return ImpactCheck(tuple(saddles))


def case_impact(model: StructuralModel, nonlinear: PeriodicResponse, linear_force_N: NDArray, time_samples: int) -> ImpactCheck:
    """:func:`impact_check` of a run's dynamic nonlinear row, the contact kept being the dynamic linear row's saddle
    forces (``linear_force_N``, harmonics (H+1, n_s), sampled on ``time_samples``); empty where the row did not converge."""
    if not nonlinear.converged:
        return ImpactCheck(())
    return impact_check(model, nonlinear, np.max(harmonics_to_time(linear_force_N, int(time_samples)), axis=0))


def with_impact(rows: list[dict[str, Any]], check: ImpactCheck) -> list[dict[str, Any]]:
    """The summary rows with ``F_within_validity`` (False where the row's peak saddle force is an elastic impact:
    the dynamic nonlinear row, when a saddle is flagged) and there ``ModelWarning.SADDLE_FORCE_ELASTIC_IMPACT``
    after the row's solver and model warnings."""
    out = []
    for row in rows:
        flagged = bool(check.flagged) and (row["load_case"], row["model"]) == ("dynamic", "nonlinear")
        warnings = tuple(row.get("warnings", ()))
        out.append(
            {
                **row,
                "F_within_validity": not flagged,
                "warnings": (*warnings, ModelWarning.SADDLE_FORCE_ELASTIC_IMPACT) if flagged else warnings,
            }
        )
    return out


def impact_flags(rows: list[dict[str, Any]]) -> xr.DataArray:
    """The rows' ``F_within_validity`` as a (load_case, model) variable of ``results.nc``."""
    values = [
        [next(bool(r["F_within_validity"]) for r in rows if (r["load_case"], r["model"]) == (lc, m)) for m in MODELS] for lc in LOAD_CASES
    ]
    return xr.DataArray(
        np.array(values),
        dims=("load_case", "model"),
        attrs={"long_name": "the row's peak saddle force is not an elastic impact at a re-contact (docs/limitations.md)", "units": "1"},
    )


def fixed_harmonics_reason(case: Case, model: StructuralModel, omega_rad_s: float) -> str | None:
    """Why a harmonic balance at a fixed ``solver.harmonics`` likely failed on the case's saddles (None: no such reason).

    A re-contact rings at the contact's frequency, ``k / G(k)`` on the stiffest saddle (``sqrt(k / m)`` for a mass
    ``m``; :func:`impact_force_per_velocity_N_s_per_m`); harmonics up to ``H omega`` below it cannot carry the impact.
    None unless ``solver.method`` is ``hbm`` with ``solver.harmonics`` set and ``H omega`` below that frequency.
    """
    H = case.solver.harmonics
    stiffness = np.asarray(model.saddle_unilateral_stiffness_N_per_m, dtype=float)
    if case.solver.method != SolverMethod.HBM or H is None or not np.any(stiffness > 0.0):
        return None
    i = int(np.argmax(stiffness))
    ringing = float(stiffness[i]) / impact_force_per_velocity_N_s_per_m(model, i, float(stiffness[i]))
    reach = int(H) * float(omega_rad_s)
    if reach >= ringing:
        return None
    return (
        f"the fixed solver.harmonics = {int(H)} reaches {reach:.3g} rad/s while a re-contact on the stiffest saddle "
        f"(k = {stiffness[i]:.3g} N/m) rings at about {ringing:.3g} rad/s: the harmonics likely cannot resolve the impacts; "
        "leave solver.harmonics unset: the default solver (exact-event shooting) solves the contact's events exactly"
    )
