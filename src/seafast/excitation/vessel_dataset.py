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
from numpy.typing import NDArray

from seafast.excitation.cargo_acceleration import CargoPoints, acceleration_transfer
from seafast.excitation.deck_motion import RigidBodyAmplitudes
from seafast.excitation.hydrodynamics.heading_motions import SIX_DOF_NAMES, SIX_DOF_UNITS, SixDofMotions
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
    "head_sea_six_raos",
    "six_motion_dataset",
    "acceleration_dataset",
    "six_motion_attributes",
    "six_motion_variables",
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


_SIX_MEANING = {
    "surge": "surge (forward +) of the CoG",
    "sway": "sway (to port +) of the CoG",
    "heave": "heave (up +) of the CoG",
    "roll": "roll about x (starboard down +)",
    "pitch": "pitch theta = dz/dx (bow up +)",
    "yaw": "yaw about z (bow to port +)",
}

_HEADING = {
    "long_name": "wave heading: the direction the waves travel, from x (forward) towards y (port); 180 head seas",
    "units": "degree",
}


def head_sea_six_raos(m: RigidBodyMotions) -> NDArray[np.complex128]:
    """The six RAOs (n_w, 1, 6) of the head-sea model: coupled surge (NaN without surge), 0, heave, 0, pitch, 0.

    Heave and pitch are the heave-pitch model's (what the cargo takes); sway, roll and yaw vanish in head seas by the
    hull's symmetry.
    """
    n = m.omega_rad_s.size
    out = np.zeros((n, 1, 6), dtype=complex)
    out[:, 0, 0] = m.surge_rao_m_per_m if m.surge_rao_m_per_m is not None else np.nan
    out[:, 0, 2] = m.heave_rao_m_per_m
    out[:, 0, 4] = m.pitch_rao_rad_per_m
    return out


def six_motion_dataset(omega: NDArray[np.float64], headings: NDArray[np.float64], raos: NDArray[np.complex128], note: str) -> xr.Dataset:
    """``<dof>_rao6_real``/``_imag`` over (``rao_omega_rad_s``, ``heading_deg``) for the six DOFs (m/m, rad/m)."""
    data: Variables = {}
    for i, (name, unit) in enumerate(zip(SIX_DOF_NAMES, SIX_DOF_UNITS, strict=True)):
        for part, fn in (("real", np.real), ("imag", np.imag)):
            long_name = f"{_SIX_MEANING[name]} RAO per metre of wave amplitude, {part} part (exp(+i omega t), crest amidships; {note})"
            data[f"{name}_rao6_{part}"] = (("rao_omega_rad_s", "heading_deg"), fn(raos[:, :, i]), {"long_name": long_name, "units": unit})
    coords = {
        "rao_omega_rad_s": ("rao_omega_rad_s", omega, {"long_name": "wave frequency", "units": "rad/s"}),
        "heading_deg": ("heading_deg", headings, _HEADING),
    }
    return xr.Dataset(data, coords=coords)


def acceleration_dataset(
    omega: NDArray[np.float64],
    raos: NDArray[np.complex128],
    wave_omega_rad_s: float,
    amplitudes: NDArray[np.complex128] | None,
    points: CargoPoints,
    reference_m: tuple[float, float],
    gravity_m_per_s2: float = 9.81,
) -> xr.Dataset:
    """The analysed unit's accelerations in the ship frame: transfer functions over (frequency, heading) and the case's wave.

    ``cargo_acceleration_rao_real``/``_imag`` (rao_omega_rad_s, heading_deg, cargo_point, ship_axis) [m/s2 per m of wave]
    and, at the case's wave, ``cargo_acceleration_real``/``_imag``/``_amplitude`` (cargo_point, ship_axis) [m/s2]: the
    accelerometer's reading beyond g (rigid-body acceleration plus the dynamic gravity components of roll and pitch,
    :mod:`seafast.excitation.cargo_acceleration`). ``reference_m`` = (x_G from the AP, KG above the keel) of the RAOs.
    """
    rel = points.relative_to(*reference_m)
    tf = acceleration_transfer(raos, omega[:, None], rel, gravity_m_per_s2)  # (n_w, n_b, n_p, 3)
    what = "acceleration of the analysed cargo unit's axis, ship frame, with gravity's roll and pitch parts (a + (g theta, g phi, 0))"
    dims4 = ("rao_omega_rad_s", "heading_deg", "cargo_point", "ship_axis")
    data: Variables = {
        "cargo_acceleration_rao_real": (dims4, tf.real, {"long_name": f"{what} per metre of wave amplitude, real part", "units": "m/s2/m"}),
        "cargo_acceleration_rao_imag": (
            dims4,
            tf.imag,
            {"long_name": f"{what} per metre of wave amplitude, imaginary part", "units": "m/s2/m"},
        ),
    }
    if amplitudes is not None:
        a = acceleration_transfer(amplitudes, wave_omega_rad_s, rel, gravity_m_per_s2)  # (n_p, 3)
        dims2 = ("cargo_point", "ship_axis")
        data["cargo_acceleration_real"] = (dims2, a.real, {"long_name": f"{what} at the case's wave, real part", "units": "m/s2"})
        data["cargo_acceleration_imag"] = (dims2, a.imag, {"long_name": f"{what} at the case's wave, imaginary part", "units": "m/s2"})
        data["cargo_acceleration_amplitude"] = (dims2, np.abs(a), {"long_name": f"{what} at the case's wave, amplitude", "units": "m/s2"})
    coords = {
        "cargo_point": (
            "cargo_point",
            np.arange(points.x_cargo_m.size),
            {"long_name": "point of the analysed unit (aft end, middle, fore end)", "units": "1"},
        ),
        "cargo_point_x_m": ("cargo_point", points.x_cargo_m, {"long_name": "cargo x of the point, from the cargo's aft end", "units": "m"}),
        "ship_axis": ("ship_axis", ["x", "y", "z"], {"long_name": "ship-frame axis: x forward, y to port, z up"}),
    }
    ds = xr.Dataset(data, coords=coords)
    ds.attrs.update(cargo_point_y_m=float(points.y_m), cargo_point_z_m=float(points.z_m))
    return ds


def six_motion_attributes(q: NDArray[np.complex128], heading_deg: float) -> dict[str, float]:
    """Amplitudes [m, rad] and phases [rad] of the six motions at the case's wave, and the heading [deg]."""
    attrs: dict[str, float] = {"wave_heading_deg": float(heading_deg)}
    for name, unit, value in zip(SIX_DOF_NAMES, ("m", "m", "m", "rad", "rad", "rad"), q, strict=True):
        attrs[f"six_dof_{name}_amplitude_{unit}"] = float(abs(value))
        attrs[f"six_dof_{name}_phase_rad"] = float(np.angle(value))
    return attrs


def six_motion_variables(
    ds: xr.Dataset,
    motions: RigidBodyMotions | None,
    motions6: SixDofMotions | None,
    points: CargoPoints | None,
    wave_omega_rad_s: float,
    amplitudes: NDArray[np.complex128] | None,
    heading_deg: float,
    gravity_m_per_s2: float = 9.81,
) -> xr.Dataset:
    """``ds`` with the six RAOs over headings and the cargo's accelerations (when the vessel moves).

    Off head seas the six-DOF motions over every heading; in head seas the heave-pitch model's RAOs on one heading,
    180 deg (:func:`head_sea_six_raos`).
    """
    if motions6 is not None:
        omega, headings, raos = motions6.omega_rad_s, motions6.headings_deg, np.asarray(motions6.raos)
        ref, note = (motions6.reference_x_m, motions6.reference_z_m), "six-DOF BEM over headings"
        ds = xr.merge([ds, six_motion_dataset(omega, headings, raos, note)], compat="no_conflicts", join="outer", combine_attrs="override")
        ds.attrs.update(motions6.attributes())
    elif motions is not None:
        omega, headings, raos = motions.omega_rad_s, np.array([180.0]), head_sea_six_raos(motions)
        ref = (motions.reference_x_m, motions.reference_z_m)
        note = "head seas: heave-pitch model (surge coupled); sway, roll, yaw 0 by symmetry"
        ds = xr.merge([ds, six_motion_dataset(omega, headings, raos, note)], compat="no_conflicts", join="outer", combine_attrs="override")
    else:
        return ds
    if points is not None:
        ds = xr.merge(
            [ds, acceleration_dataset(omega, raos, wave_omega_rad_s, amplitudes, points, ref, gravity_m_per_s2)],
            compat="no_conflicts",
            join="outer",
            combine_attrs="override",
        )
    if amplitudes is not None:
        ds.attrs.update(six_motion_attributes(amplitudes, heading_deg))
    return ds
