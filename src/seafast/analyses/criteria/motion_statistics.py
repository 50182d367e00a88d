"""The ship's motions in the case's sea state at one heading, as the motion-analysis load cases take them (docs/criteria.md).

From the same spectral analysis as ``seafast seastate`` (:func:`seafast.analyses.seastate.spectral.spectral_analysis`:
the spectrum, the directions of a short-crested sea and their weights, the stochastic roll damping), the six rigid-body
motions per metre of wave amplitude at every direction: the six-DOF RAOs
(:func:`seafast.excitation.rao_extension.extended_six_dof_rao`, with the sea state's equivalent roll damping) off head
seas or in a short-crested sea, the heave-pitch model's heave and pitch in a long-crested head sea (as the sea-state
analysis itself). Any linear response ``X`` of them has the transfer functions ``H_X,j`` per direction, and

* the covariance of two responses ``C_XY = int sum_j w_j Re(H_X,j conj(H_Y,j)) S d omega`` (trapezoid on the sea
  state's grid, as :func:`~seafast.analyses.seastate.spectral.squared_response_statistics`), ``m0 = C_XX`` and ``m2``
  likewise with ``omega^2``;
* the most probable maximum over the sea state's duration, Rayleigh: ``sqrt(m0) sqrt(2 ln(D / Tz))``,
  ``Tz = 2 pi sqrt(m0 / m2)`` (:func:`~seafast.analyses.seastate.spectral.rayleigh_mpm`);
* at the extreme of a governing response ``X = u`` (where ``dX/dt = 0``), the expected value of every other linear
  response of the Gaussian sea, ``E[Y | X = u, dX/dt = 0] = u C_YX / C_XX`` (the velocity is uncorrelated with ``X``
  and zero at the extreme): the *simultaneous* roll, pitch and accelerations of the load case. For an angle this gives
  its own angular acceleration ``-u m2 / m0 = -u (2 pi / Tz)^2``, the default criteria's ``-(2 pi / T)^2`` times the
  angle with ``T = Tz``.

Accelerations at a point ``r`` from the motions' reference (the vessel's centre of gravity): the rigid body's
``-omega^2 (xi + Omega x r)`` (:mod:`seafast.excitation.cargo_acceleration`); the accelerometer's reading adds the
angles' gravity components ``g (theta, phi, 0)``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from seafast.analyses.seastate.spectral import SpectralAnalysis, rayleigh_mpm
from seafast.analyses.seastate.transfer import six_dof_motions
from seafast.config.schema import HEAD_SEAS_DEG
from seafast.excitation.cargo_acceleration import acceleration_transfer
from seafast.excitation.rao_extension import extended_six_dof_rao
from seafast.excitation.vessel import vessel_excitation

__all__ = ["SeaStateMotions", "LinearResponse", "sea_state_motions", "ROLL", "PITCH"]

ROLL, PITCH = 3, 4
"""Indices of roll (starboard down +) and pitch (bow up +) in the six motions ``(surge, sway, heave, roll, pitch, yaw)``."""


@dataclass(frozen=True)
class LinearResponse:
    """A linear response's transfer functions per direction, (n_d, n_w) [unit per m of wave amplitude]."""

    transfer: NDArray[np.complex128]


@dataclass(frozen=True)
class SeaStateMotions:
    """The six motions of one sea state at one mean heading, and their statistics.

    Attributes
    ----------
    heading_deg
        The sea's mean heading [deg] (180 head seas, 90 beam seas).
    omega_rad_s
        (n_w,) the sea state's frequencies [rad/s].
    density_m2_s_per_rad
        (n_w,) its one-sided wave spectrum [m^2 s/rad].
    weight
        (n_d,) the directions' weights [-] (one of 1 for a long-crested sea).
    raos
        (n_d, n_w, 6) the six motions per metre of wave amplitude ``(surge, sway, heave [m/m], roll, pitch bow up,
        yaw [rad/m])`` at the reference.
    reference_x_m, reference_z_m
        The motions' reference, the vessel's centre of gravity: from the aft perpendicular [m] and above the keel [m].
    duration_s
        The sea state's duration the maxima are taken over [s].
    gravity_m_per_s2
        g [m/s^2].
    """

    heading_deg: float
    omega_rad_s: NDArray[np.float64]
    density_m2_s_per_rad: NDArray[np.float64]
    weight: NDArray[np.float64]
    raos: NDArray[np.complex128]
    reference_x_m: float
    reference_z_m: float
    duration_s: float
    gravity_m_per_s2: float

    def motion(self, index: int) -> LinearResponse:
        """One of the six motions (0 surge ... 5 yaw) [m or rad per m]."""
        return LinearResponse(self.raos[:, :, index])

    def motion_acceleration(self, index: int) -> LinearResponse:
        """One of the six motions' accelerations ``-omega^2 q`` [m/s^2 or rad/s^2 per m]."""
        return LinearResponse(-(self.omega_rad_s**2)[None, :] * self.raos[:, :, index])

    def point_acceleration(self, point_m: NDArray[np.float64], axis: int) -> LinearResponse:
        """The accelerometer's reading beyond g at ``point_m`` (x, y, z from the reference) along ship ``axis`` [m/s^2 per m]."""
        f = acceleration_transfer(self.raos, self.omega_rad_s[None, :], np.reshape(point_m, (1, 3)), self.gravity_m_per_s2)
        return LinearResponse(f[:, :, 0, axis])

    def covariance(self, x: LinearResponse, y: LinearResponse, power: int = 0) -> float:
        """``int omega^power sum_j w_j Re(H_x,j conj(H_y,j)) S d omega`` [unit_x unit_y]."""
        w = self.omega_rad_s
        cross = np.tensordot(self.weight, np.real(x.transfer * np.conj(y.transfer)), axes=(0, 0))
        return float(np.trapezoid(w**power * cross * self.density_m2_s_per_rad, w))

    def mpm(self, x: LinearResponse) -> float:
        """The Rayleigh most probable maximum of ``x`` over the duration [unit]."""
        m0, m2 = self.covariance(x, x), self.covariance(x, x, 2)
        return float(rayleigh_mpm(np.array([m0]), np.array([m2]), self.duration_s)[0])

    def zero_crossing_period_s(self, x: LinearResponse) -> float:
        """``2 pi sqrt(m0 / m2)`` [s] (inf for a response without variance)."""
        m0, m2 = self.covariance(x, x), self.covariance(x, x, 2)
        return float(2.0 * np.pi * np.sqrt(m0 / m2)) if m2 > 0.0 else float("inf")

    def conditional(self, y: LinearResponse, x: LinearResponse, level: float) -> float:
        """``E[y | x = level, dx/dt = 0] = level C_yx / C_xx`` [unit_y] (0 when x has no variance)."""
        m0 = self.covariance(x, x)
        return level * self.covariance(y, x) / m0 if m0 > 0.0 else 0.0


def _reference_z_m(analysis: SpectralAnalysis) -> float:
    """The head-sea heave-pitch model's reference height above the keel [m] (its pitch axis through the centre of gravity)."""
    motions = vessel_excitation(analysis.case).motions
    return 0.0 if motions is None else float(motions.reference_z_m)


def _six_dof_raos(analysis: SpectralAnalysis) -> tuple[NDArray[np.float64], NDArray[np.complex128], float, float]:
    """``(weight, raos, reference_x_m, reference_z_m)`` of the directions: six-DOF, or the head-sea heave-pitch model."""
    case, sea = analysis.case, analysis.directional
    w = analysis.spectrum.omega_rad_s
    if sea is None or not sea.six_dof:
        tf = analysis.transfer
        assert tf.heading_deg == HEAD_SEAS_DEG
        raos = np.zeros((1, w.size, 6), dtype=complex)
        raos[0, :, 2], raos[0, :, PITCH] = tf.heave_m, tf.pitch_rad
        return np.ones(1), raos, float(tf.pitch_reference_x_m), _reference_z_m(analysis)
    weight, headings = np.asarray(sea.quadrature.weight, float), sea.quadrature.heading_deg
    motions6 = six_dof_motions(case)
    if motions6 is None:
        return weight, np.zeros((headings.size, w.size, 6), complex), 0.0, 0.0
    b_eq = 0.0 if sea.roll is None else float(sea.roll.equivalent_damping_Nms_per_rad)
    g, draught = case.model.gravity_m_per_s2, case.vessel.draft_m
    raos = np.stack(
        [
            extended_six_dof_rao(motions6, w, float(h), gravity_m_per_s2=g, draught_m=draught, additional_roll_damping_Nms_per_rad=b_eq)
            for h in headings
        ]
    )
    return weight, raos, float(motions6.reference_x_m), float(motions6.reference_z_m)


def sea_state_motions(analysis: SpectralAnalysis) -> SeaStateMotions:
    """The six motions of ``analysis``'s sea state at every direction (module docstring).

    Off head seas or in a short-crested sea: the six-DOF RAOs of :func:`seafast.analyses.seastate.transfer.six_dof_motions`
    with the sea state's stochastic roll damping added; in a long-crested head sea the heave-pitch model's heave and pitch
    (surge, sway, roll and yaw zero), as the sea-state analysis. ``vessel.motions: none``: all zero.
    """
    case, spectrum = analysis.case, analysis.spectrum
    weight, raos, x_ref, z_ref = _six_dof_raos(analysis)
    return SeaStateMotions(
        heading_deg=float(case.sea_state.heading_deg),
        omega_rad_s=spectrum.omega_rad_s,
        density_m2_s_per_rad=spectrum.density_m2_s_per_rad,
        weight=weight,
        raos=raos,
        reference_x_m=x_ref,
        reference_z_m=z_ref,
        duration_s=float(case.sea_state.duration_s),
        gravity_m_per_s2=case.model.gravity_m_per_s2,
    )
