"""The vessel side of ``results.nc``: hull lines, RAOs and the rigid-body amplitudes as labelled variables.

The steps of :meth:`seafast.excitation.vessel.VesselExcitation.to_dataset`: the still-water hull
lines (:func:`still_water_variables`, or the deck line of a moment table,
:func:`moment_table_variables`), the wave-induced lines (:func:`wave_variables`), the RAOs
(:func:`rao_dataset`) and the amplitudes at the case's wave (:func:`rigid_body_attributes`).
Names, units and ``long_name`` as docs/interface.md lists them.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import xarray as xr

from seafast.excitation.deck_motion import RigidBodyAmplitudes
from seafast.excitation.hydrodynamics.motions import RigidBodyMotions
from seafast.excitation.vessel_inputs import DeckLine
from seafast.hull.still_water import HullGirderResponse
from seafast.hull.wave import WaveHullResponse

__all__ = [
    "Variables",
    "still_water_variables",
    "moment_table_variables",
    "wave_variables",
    "rao_dataset",
    "rigid_body_attributes",
]

Variables = dict[str, Any]
"""``name -> (dims, values, attrs)`` of data variables or coordinates, as ``xr.Dataset`` takes them."""

_ONE_WAY = "one-way: the cargo as a weight spread over its length (with vessel.coupling = two_way see the *_coupled_* variables)"

_ONE_WAY_LINES = (
    "hull_still_water_deflection_m",
    "hull_still_water_bending_moment_Nm",
    "hull_still_water_shear_force_N",
    "hull_weight_N_per_m",
)

_HULL_X = {"long_name": "x along the ship from the aft perpendicular", "units": "m"}


def _hull_coupling_attr(name: str) -> dict[str, str]:
    """``hull_coupling = one_way`` on the hull lines that the cargo's load distribution changes."""
    return {"hull_coupling": "one_way"} if name in _ONE_WAY_LINES else {}


def still_water_variables(sw: HullGirderResponse) -> tuple[Variables, Variables]:
    """(coords, data): the still-water hull lines on ``hull_x_m`` (deflection, moment, shear, weight, buoyancy)."""
    coords: Variables = {"hull_x_m": ("hull_x_m", sw.x_m, _HULL_X)}
    data: Variables = {}
    for name, values, long_name, units in (
        (
            "hull_still_water_deflection_m",
            sw.deflection_m,
            f"still-water hull deflection (chord through AP and FP, up +), {_ONE_WAY}",
            "m",
        ),
        (
            "hull_still_water_bending_moment_Nm",
            sw.bending_moment_Nm,
            f"still-water hull bending moment (sagging +), {_ONE_WAY}",
            "N m",
        ),
        ("hull_still_water_shear_force_N", sw.shear_force_N, f"still-water hull shear force, {_ONE_WAY}", "N"),
        (
            "hull_weight_N_per_m",
            sw.weight_N_per_m,
            "ship weight per metre, the cargo spread over its length (one-way loading)",
            "N/m",
        ),
        ("hull_buoyancy_N_per_m", sw.buoyancy_N_per_m, "still-water buoyancy per metre", "N/m"),
    ):
        data[name] = ("hull_x_m", values, {"long_name": long_name, "units": units, **_hull_coupling_attr(name)})
    return coords, data


def moment_table_variables(line: DeckLine) -> tuple[Variables, Variables]:
    """(coords, data): the still-water deflection from a moment table, on the table's ``hull_x_m``."""
    coords: Variables = {"hull_x_m": ("hull_x_m", line.x_m, _HULL_X)}
    data: Variables = {
        "hull_still_water_deflection_m": (
            "hull_x_m",
            line.deflection_m,
            {"long_name": "still-water hull deflection from the moment table", "units": "m"},
        )
    }
    return coords, data


def wave_variables(wv: WaveHullResponse, coords: Variables, data: Variables) -> None:
    """Add the wave-induced hull lines (over ``hull_period_fraction``) to ``coords`` and ``data``, in place.

    Only when the still-water lines lie on the same ``hull_x_m`` (a computed hull); a missing
    still-water moment (a moment table gives the deflection only) is added as zeros, marked
    ``not computed``.
    """
    if "hull_x_m" not in coords or not np.array_equal(wv.x_m, coords["hull_x_m"][1]):
        return
    coords["hull_period_fraction"] = (
        "hull_period_fraction",
        wv.period_fraction,
        {"long_name": "t/T of the hull wave balance", "units": "1"},
    )
    data["hull_wave_deflection_m"] = (
        ("hull_period_fraction", "hull_x_m"),
        wv.deflection_m,
        {"long_name": f"wave-induced hull deflection, {_ONE_WAY}", "units": "m", "hull_coupling": "one_way"},
    )
    data["hull_wave_bending_moment_Nm"] = (
        ("hull_period_fraction", "hull_x_m"),
        wv.bending_moment_Nm,
        {"long_name": f"wave-induced hull bending moment (sagging +), {_ONE_WAY}", "units": "N m", "hull_coupling": "one_way"},
    )
    if "hull_still_water_bending_moment_Nm" not in data:
        data["hull_still_water_bending_moment_Nm"] = (
            "hull_x_m",
            np.zeros_like(wv.x_m),
            {"long_name": "not computed", "units": "N m"},
        )


def rao_dataset(m: RigidBodyMotions) -> xr.Dataset:
    """Heave and pitch RAOs (and surge, when the data hold it) over ``rao_omega_rad_s``, real and imaginary parts."""
    rao = xr.Dataset(
        {
            "heave_rao_real": ("rao_omega_rad_s", m.heave_rao_m_per_m.real, {"long_name": "heave RAO, real part", "units": "m/m"}),
            "heave_rao_imag": (
                "rao_omega_rad_s",
                m.heave_rao_m_per_m.imag,
                {"long_name": "heave RAO, imaginary part", "units": "m/m"},
            ),
            "pitch_rao_real": (
                "rao_omega_rad_s",
                m.pitch_rao_rad_per_m.real,
                {"long_name": "pitch RAO (bow up), real part", "units": "rad/m"},
            ),
            "pitch_rao_imag": (
                "rao_omega_rad_s",
                m.pitch_rao_rad_per_m.imag,
                {"long_name": "pitch RAO (bow up), imaginary part", "units": "rad/m"},
            ),
        },
        coords={"rao_omega_rad_s": ("rao_omega_rad_s", m.omega_rad_s, {"long_name": "wave frequency", "units": "rad/s"})},
    )
    surge = m.surge_rao_m_per_m
    if surge is not None:
        rao["surge_rao_real"] = (
            "rao_omega_rad_s",
            surge.real,
            {"long_name": "surge RAO (forward +, at the pitch reference), real part", "units": "m/m"},
        )
        rao["surge_rao_imag"] = (
            "rao_omega_rad_s",
            surge.imag,
            {"long_name": "surge RAO (forward +, at the pitch reference), imaginary part", "units": "m/m"},
        )
    return rao


def rigid_body_attributes(rb: RigidBodyAmplitudes) -> dict[str, float]:
    """Amplitudes [m, rad] and phases [rad] of heave and pitch at the case's wave (and surge, when solved), and their reference [m]."""
    attrs = {
        "heave_amplitude_m": abs(rb.heave_m),
        "heave_phase_rad": float(np.angle(rb.heave_m)),
        "pitch_amplitude_rad": abs(rb.pitch_rad),
        "pitch_phase_rad": float(np.angle(rb.pitch_rad)),
        "pitch_reference_x_m": rb.reference_x_m,
    }
    if rb.surge_m is not None:
        attrs.update(surge_amplitude_m=abs(rb.surge_m), surge_phase_rad=float(np.angle(rb.surge_m)), pitch_reference_z_m=rb.reference_z_m)
    return attrs
