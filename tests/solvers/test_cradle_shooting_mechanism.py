"""A contact state with a rigid-body motion (a mechanism) in the exact-event shooting: the constant load along it
drifts the cargo at a constant rate, marched in closed form.

Independent checks: a two-mode correction system whose first saddle, lifted, cancels its mode's stiffness exactly,
its orbit marched over a period by an adaptive Runge-Kutta integration of the same nonlinear equations (to 1e-7 of
the state's size; dropping the drift moves the state by its own size); and the 3-D cargo's Hs 5 m beam-sea design
wave that lifts all but one pad with its stoppers open, against the Newmark march of every cargo DOF.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import seafast
from seafast.analyses.seastate.cradle_design_wave import cradle_sea_state, design_wave_excitation, select_cradle_design_waves
from seafast.analyses.seastate.spectral import spectral_analysis
from seafast.solvers.cradle_march import march_cradle
from seafast.solvers.cradle_shooting import solve_cradle_shooting
from seafast.solvers.modal_correction import CorrectionBasis, ModalCorrectionSystem
from seafast.solvers.outcome import SolverOutcome
from seafast.solvers.shooting.options import ShootingOptions
from seafast.solvers.shooting.orbit import shoot_orbit
from seafast.solvers.shooting.states import ContactStates, SingularStateError

OMEGA_RAD_S = 1.0
K_N_PER_M = np.array([4.0, 100.0])
NATURAL_RAD_S = np.array([2.0, 20.0])  # the first mode's stiffness is its saddle's: lifted, nothing holds it
DAMPING = np.diag([3.0, 0.8])
HARMONICS = np.array([[0.5, 0.4], [1.0, 0.8j]], dtype=complex)  # d(t) = Re sum_k D_k e^{i k w t} [m]


def two_mode_system() -> ModalCorrectionSystem:
    """Two modes, one saddle each (``Phi_s = I``), every mode kept (no residual flexibility)."""
    eye = np.eye(2)
    return ModalCorrectionSystem(
        natural_frequency_rad_s=NATURAL_RAD_S,
        modal_damping=DAMPING,
        mode_shape=eye,
        saddle_mode_shape=eye,
        residual_displacement_m_per_N=np.zeros((2, 2)),
        residual_flexibility_m_per_N=np.zeros((2, 2)),
        static_flexibility_m_per_N=np.diag(1.0 / NATURAL_RAD_S**2),
        unilateral_stiffness_N_per_m=K_N_PER_M,
        saddle_dof=np.arange(2),
        cutoff_rad_s=math.inf,
        basis=CorrectionBasis.BILATERAL,
        complete=True,
    )


def reference_rate(t_s: float, x: np.ndarray) -> np.ndarray:
    """``eta'' + Xi eta' + Omega^2 eta = Phi_s^T c``, ``c = k max(-(d - Phi_s eta), 0)``: the equations themselves."""
    eta, rate = x[:2], x[2:]
    d = np.real(HARMONICS.T @ np.exp(1j * OMEGA_RAD_S * np.arange(HARMONICS.shape[0]) * t_s))
    c = K_N_PER_M * np.maximum(eta - d, 0.0)
    return np.concatenate([rate, -DAMPING @ rate - NATURAL_RAD_S**2 * eta + c])


def test_a_mechanism_state_drifts_in_closed_form_as_the_equations_integrated():
    system = two_mode_system()
    with pytest.raises(SingularStateError):
        ContactStates(system, HARMONICS, OMEGA_RAD_S).get(np.array([True, False]))
    states = ContactStates(system, HARMONICS, OMEGA_RAD_S, mechanisms=True)
    mechanism = states.get(np.array([True, False]))
    assert np.count_nonzero(mechanism.eigenvalues == 0.0) == 1
    # the constant load -k d_0 along the free mode against its damping xi: eta_0 drifts at -k D_0 / xi
    assert np.isclose(mechanism.drift[0], -K_N_PER_M[0] * HARMONICS[0, 0].real / DAMPING[0, 0], rtol=1e-12)
    assert np.all(mechanism.drift[1:] == 0.0)
    orbit = shoot_orbit(states, 256, 1.0, ShootingOptions(), K_N_PER_M)
    assert orbit.converged and orbit.flow.events >= 2
    assert orbit.flow.state_samples is not None and orbit.flow.state_codes is not None
    assert np.any(orbit.flow.state_codes == 1)  # the period passes through the mechanism (saddle 0 lifted)
    period = 2.0 * np.pi / OMEGA_RAD_S
    times = np.arange(orbit.samples) * (period / orbit.samples)
    x0 = orbit.flow.state_samples[0]
    ref = solve_ivp(reference_rate, (0.0, period), x0, "DOP853", t_eval=times, rtol=1e-12, atol=1e-13, max_step=period / 4096)
    size = float(np.max(np.abs(ref.y)))
    assert size > 1e-2
    assert np.max(np.abs(ref.y.T - orbit.flow.state_samples)) <= 1e-7 * size


CASE_HS5 = {
    "sea_state.heading_deg": 90.0,
    "sea_state.significant_height_m": 5.0,
    "sea_state.peak_period_s": 10.0,
    "seafastening.saddle_contact_angle_deg": 20.0,
    "seafastening.side_stopper.gap_m": 0.02,
    "seafastening.side_stopper.stiffness_N_per_m": 2e9,
}
"""docs/seastate.md's 20 deg pads with 20 mm, 2 GN/m stoppers in a long-crested beam sea, Hs 5 m, Tp 10 s."""


@pytest.mark.slow
def test_the_hs5_wave_through_a_one_pad_state_converges_and_matches_the_newmark_march():
    """The band's high end of the lashing maximum's waves (0.655 rad/s, 6.60 m): all but one pad lift and every
    stopper is open at once, a lateral rigid-body motion the lashings (holding only the vertical ones) do not hold. Converged,
    stable, the cutoff settled; every element's peak within 0.5 % of the Newmark march's at T / 8192 (measured 2.0e-3
    on a stopper, 1.7e-3 on a pad, 2e-6 on the lashings: the march's own step error, at T / 32768 1.5e-4); the
    lashings' range over the period (115 N of 74 kN) within 1 % (measured 1.3e-3; 1.4e-4 at T / 32768)."""
    analysis = spectral_analysis(seafast.load_case(None, CASE_HS5))
    state = cradle_sea_state(analysis, design_waves=False)  # the cradles, their transfer functions, the spectral MPMs
    sea = state.sea
    (wave,) = [
        w
        for w in select_cradle_design_waves(state.transfer, state.spectral)
        if (w.quantity, w.role) == ("lashing_tension_max_N", "band_high")
    ]
    assert abs(wave.omega_rad_s - 0.65520777) < 1e-7 and abs(wave.amplitude_m - 6.60033865) < 1e-6
    excitation = design_wave_excitation(sea, analysis.directional, wave)
    response = solve_cradle_shooting(sea.dynamics, excitation)
    assert response.outcome is SolverOutcome.CONVERGED, response.message
    assert "cutoff doubled" in response.message and "not converged" not in response.message
    march = march_cradle(sea.dynamics, excitation, 8192)
    assert march.periodicity.value == "periodic"
    peaks, reference = response.max_force_N, march.element_force_N.max(axis=0)
    assert np.all(peaks[6:12] > 1e6)  # every stopper strikes
    assert np.all(np.abs(reference - peaks) <= 5e-3 * reference), np.abs(reference - peaks) / reference
    lashings = slice(12, 16)
    swing = np.ptp(response.element_force_N[:, lashings], axis=0)
    swing_ref = np.ptp(march.element_force_N[:, lashings], axis=0)
    assert np.all(np.abs(swing - swing_ref) <= 1e-2 * swing_ref), (swing, swing_ref)
