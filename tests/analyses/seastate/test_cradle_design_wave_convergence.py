"""The cradle design waves that used to fail to converge (docs/seastate.md, the 20 deg pads with stoppers in a beam
sea): a contact state held only by a soft lashing mode is no rigid-body motion whatever modes are kept, the stoppers'
cutoff doubled until the peaks settle and the orbit is stable (against the Newmark march), and a period-doubled wave
read over its two periods."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg

import seafast
from seafast.analyses.seastate.cradle_design_wave import (
    cradle_sea_state,
    design_wave_excitation,
    select_cradle_design_waves,
    solve_cradle_design_wave,
)
from seafast.analyses.seastate.cradle_transfer import cradle_sea_model
from seafast.analyses.seastate.spectral import spectral_analysis
from seafast.excitation.cradle_loads import CradleExcitation
from seafast.fourier import real_to_complex_harmonics
from seafast.model.from_case import build_model
from seafast.solvers.cradle_dynamics import cradle_operators
from seafast.solvers.cradle_march import march_cradle
from seafast.solvers.cradle_shooting_system import cradle_correction_system, cradle_modes
from seafast.solvers.hbm.harmonics import force_scale_N
from seafast.solvers.outcome import SolverOutcome
from seafast.solvers.shooting.states import ContactStates, SingularStateError

PADS_20_STOPPERS = {
    "sea_state.heading_deg": 90.0,
    "sea_state.significant_height_m": 3.0,
    "sea_state.peak_period_s": 10.0,
    "seafastening.saddle_contact_angle_deg": 20.0,
    "seafastening.side_stopper.gap_m": 0.02,
    "seafastening.side_stopper.stiffness_N_per_m": 2e9,
}
"""docs/seastate.md's 20 deg pads with 20 mm, 2 GN/m stoppers in a long-crested beam sea, Hs 3 m, Tp 10 s."""


def test_a_state_held_by_a_soft_mode_is_no_rigid_body_motion_with_every_mode_kept():
    """Every element in, every mode of the 385-DOF cargo kept (the stiffest 8.9e5 rad/s, its Rayleigh damping's root
    7.5e8 1/s): the state with the starboard end pads and every stopper lifted is held by a soft mode (0.064 rad/s).
    Its slowest root equals the overdamped root of the full cargo's softest mode in that state (``K``, ``M`` DOF by DOF,
    its Rayleigh damping) within 2 % (measured 0.2 %), not flagged
    as a rigid-body motion; every pad and stopper lifted (nothing holds the cargo across) still is."""
    case = seafast.load_case(None, PADS_20_STOPPERS)
    sea = cradle_sea_model(case, build_model(case))
    dynamics = sea.dynamics
    problem = dynamics.problem
    included = np.ones(len(problem.engagements), dtype=bool)
    lifted = np.zeros(included.size, dtype=bool)
    lifted[[1, 5, 6, 7, 8, 9, 10, 11]] = True  # starboard pads of the end saddles, every stopper
    ops = cradle_operators(dynamics, cradle_still_water_excitation(dynamics), 1, included)
    system = cradle_correction_system(dynamics, ops, included, cradle_modes(dynamics, included), np.inf)
    assert system.complete
    states = ContactStates(system, real_to_complex_harmonics(ops.linear_compression_m), 0.65)
    roots = states.get(lifted).eigenvalues
    K0, M, D = dynamics.matrices
    A, k = problem.engagement_matrix, problem.element_stiffness_N_per_m
    K = K0 + A[~lifted].T @ (k[~lifted, None] * A[~lifted])
    w2, phi = scipy.linalg.eigh(K, M, subset_by_index=[0, 0])  # the soft mode, mass-normalised
    c = float(phi[:, 0] @ D @ phi[:, 0])
    reference = (-c + np.sqrt(c**2 - 4.0 * w2[0])) / 2.0  # its slow, overdamped root
    slowest = roots[np.argmin(np.abs(roots))]
    assert 1e-4 < abs(reference) < 1e-2 and np.max(np.abs(roots)) > 1e8
    assert abs(slowest - reference) <= 0.02 * abs(reference), (slowest, reference)
    free = np.zeros(included.size, dtype=bool)
    free[: 2 * len(problem.pad_pairs) + len(problem.stoppers)] = True
    with pytest.raises(SingularStateError):
        states.get(free)


def cradle_still_water_excitation(dynamics) -> CradleExcitation:
    """A wave of zero amplitude at 0.65 rad/s: the still water alone (the contact states' roots do not depend on it)."""
    deck = np.zeros((2, 2 * np.size(dynamics.deck_x_m)), dtype=complex)
    return CradleExcitation(0.65, np.zeros((2, dynamics.problem.cargo.dof_count), dtype=complex), deck, dynamics.deck_x_m)


@pytest.mark.slow
def test_the_stoppers_near_miss_wave_converges_and_matches_the_newmark_march():
    """The band's high end of the lashing maximum's waves (0.655 rad/s, 3.96 m): the pads lift and every stopper
    strikes; the cutoff doubled six times (the last change 4.8e-4, within the 1e-3 the check asks; it stopped at
    1.2e-3 where the sixth doubling's state was taken for a rigid-body motion). Converged and stable; every peak within
    0.5 % of its force scale of the Newmark march's at T / 32768 (measured 3.4e-3 on a stopper, 2e-4 on the pads and
    lashings)."""
    analysis = spectral_analysis(seafast.load_case(None, PADS_20_STOPPERS))
    state = cradle_sea_state(analysis, design_waves=False)  # the cradles, their transfer functions, the spectral MPMs
    sea = state.sea
    (wave,) = [
        w
        for w in select_cradle_design_waves(state.transfer, state.spectral)
        if (w.quantity, w.role) == ("lashing_tension_max_N", "band_high")
    ]
    excitation = design_wave_excitation(sea, analysis.directional, wave)
    response = solve_cradle_design_wave(sea.dynamics, excitation)
    assert response.outcome is SolverOutcome.CONVERGED, response.message
    assert "cutoff doubled 6 time(s)" in response.message and "harmonic balance" not in response.message
    march = march_cradle(sea.dynamics, excitation, 32768)
    peaks = response.max_force_N
    assert np.all(peaks[6:12] > 5e5)  # every stopper strikes
    change = np.abs(march.element_force_N.max(axis=0) - peaks) / force_scale_N(peaks)
    assert np.all(change <= 5e-3), change
