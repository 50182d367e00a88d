"""The vessel's rigid-body motions at the case's wave: what the cargo model takes (docs/headings.md#7-what-the-cargo-model-takes).

Head seas (:func:`rigid_body_amplitudes`): heave and pitch of the heave-pitch model (or coupled with surge), surge for
the axial analysis. Any other heading (:func:`six_dof_amplitudes`): the six motions, folded into the vertical plane of
the analysed unit (its deck rises by heave + roll y + pitch (x - x_G)) and into its axial motion (surge - yaw y).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from seafast.config.modes import MotionCoupling
from seafast.config.schema import Case
from seafast.excitation.deck_motion import RigidBodyAmplitudes
from seafast.excitation.hydrodynamics.heading_motions import SixDofMotions
from seafast.excitation.hydrodynamics.motions import RigidBodyMotions
from seafast.excitation.hydrodynamics.roll_damping import QuadraticRollDamping
from seafast.excitation.rao_extension import extended_rao

__all__ = ["rigid_body_amplitudes", "six_dof_amplitudes"]


def rigid_body_amplitudes(case: Case, motions: RigidBodyMotions, omega: float, amplitude: float) -> tuple[RigidBodyAmplitudes, str]:
    """Heave, pitch (and surge, coupled, when the data hold it) at the case's wave, and a description of their source.

    The RAOs are the BEM's inside its grid, blended into the long-wave limits below it and decayed
    above it (:func:`~seafast.excitation.rao_extension.extended_rao`); surge only inside the grid.
    """
    v = case.vessel
    heave_rao, pitch_rao = extended_rao(motions, omega, gravity_m_per_s2=case.model.gravity_m_per_s2, draught_m=v.draft_m)
    heave, pitch = complex(heave_rao), complex(pitch_rao)  # per metre of wave, at the one frequency
    surge = coupled_pitch = None
    inside = bool(motions.omega_rad_s[0] <= omega <= motions.omega_rad_s[-1])
    if motions.has_surge and inside:
        surge_c, heave_c, pitch_c = (complex(q) * amplitude for q in motions.coupled_at(omega))
        surge, coupled_pitch = surge_c, pitch_c
    vertical = "heave/pitch (2-DOF)"
    if v.motion_coupling is MotionCoupling.SURGE_HEAVE_PITCH and motions.has_surge and inside:
        heave, pitch = heave_c / amplitude, pitch_c / amplitude
        vertical = "heave/pitch coupled with surge"
    rigid = RigidBodyAmplitudes(
        heave * amplitude,
        pitch * amplitude,
        float(motions.reference_x_m),
        surge_m=surge,
        reference_z_m=float(motions.reference_z_m),
        coupled_pitch_rad=coupled_pitch,
    )
    axial = (
        ("; surge (coupled) for the axial analysis" if inside else "; no surge outside the BEM grid")
        if motions.has_surge
        else "; no surge in the data"
    )
    return rigid, f"{vertical} from {'capytaine BEM' if v.motions == 'bem' else Path(v.motions).name}{axial}"


def six_dof_amplitudes(
    case: Case, motions6: SixDofMotions, omega: float, amplitude: float
) -> tuple[RigidBodyAmplitudes, NDArray[np.complex128], str]:
    """The six motions at the case's wave and heading, and the vertical-plane amplitudes the cargo model takes.

    The cargo model is vertical: the deck under the analysed unit (at ``y = cargo_transverse_position_m``) rises by
    ``heave + roll y + pitch (x - x_G)``, so its "heave" is ``heave + roll y``; its axial motion (docs/axial.md) is
    ``surge - yaw y - pitch (z - z_G)``, so its "surge" is ``surge - yaw y``.
    """
    lo, hi = motions6.omega_rad_s[0], motions6.omega_rad_s[-1]
    if not lo <= omega <= hi:
        raise ValueError(
            f"wave.length_m = {case.wave.length_m:g} (omega = {omega:.4g} rad/s) at wave.heading_deg = {case.wave.heading_deg:g}: "
            f"the six-DOF motions cover omega {lo:g} to {hi:g} rad/s only (deep-water waves "
            f"{2 * np.pi * case.model.gravity_m_per_s2 / hi**2:.0f} to {2 * np.pi * case.model.gravity_m_per_s2 / lo**2:.0f} m)"
        )
    b2 = case.vessel.roll_damping_quadratic_Nms2_per_rad2
    quadratic = QuadraticRollDamping(float(b2)) if b2 else None
    rao, linearised = motions6.rao_in_regular_wave(omega, case.wave.heading_deg, amplitude, quadratic)
    q: NDArray[np.complex128] = rao * amplitude
    y = case.cargo_transverse_position_m()
    rigid = RigidBodyAmplitudes(
        complex(q[2] + q[3] * y),
        complex(q[4]),
        float(motions6.reference_x_m),
        surge_m=complex(q[0] - q[5] * y),
        reference_z_m=float(motions6.reference_z_m),
        coupled_pitch_rad=complex(q[4]),
    )
    description = (
        f"six-DOF motions at heading {case.wave.heading_deg:g} deg ({motions6.source}); the cargo's deck: heave, pitch and roll "
        f"at y = {y:g} m (vertical plane), surge and yaw for the axial analysis; the cargo across the ship (pads, "
        "stoppers and lashings) in seafast run's cradle rows only (docs/transverse.md)"
    )
    if linearised is not None:
        b_eq = float(linearised.equivalent_damping_Nms_per_rad[0])
        state = (
            "" if bool(linearised.converged[0]) else f", NOT converged (residual {float(linearised.residual_Nms_per_rad[0]):.3g} N m s/rad)"
        )
        description += f"; quadratic roll damping linearised harmonically: B_eq = {b_eq:.4g} N m s/rad{state}"
    return rigid, q, description
