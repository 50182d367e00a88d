"""The case-file schema: typed, validated configuration of one seafast case.

Every key carries its SI unit in its name. Objects are immutable (frozen) and reject unknown
keys, so a misspelt key is an error rather than silently ignored. The dotted keys of
docs/interface.md#2-case-keys (``cargo.length_m``, ``solver.harmonics``, ...) are the attribute paths of
:class:`Case`.

The sections of the cargo, the sea-fastening, the vessel, the wave, the sea state and the limits are
declared here, the numerical settings (solver, model, output) in :mod:`seafast.config.solver_settings`
and the field types every section uses in :mod:`seafast.config.fields`; :class:`Case` gathers them.

Size: over 400 lines because each of those sections declares every key with its unit, default, limits and
description (one place for users to read the case format and for `seafast schema` to export it).
"""

from __future__ import annotations

import math
from itertools import pairwise
from pathlib import Path
from typing import Annotated, Any, Literal

from pydantic import Field, SerializerFunctionWrapHandler, field_validator, model_serializer, model_validator

from seafast.config.arrangement import abreast_lanes_m, evenly_spaced_saddles, transverse_position_error
from seafast.config.fields import Finite, NonNegative, NotBool, Positive, StrictSection
from seafast.config.modes import ContactSurface, DesignFormat, HullCargoCoupling, MotionCoupling
from seafast.config.operation import OperationConfig
from seafast.config.solver_settings import SOURCE_SOLVER_SETTINGS, ModelConfig, OutputConfig, SolverConfig

__all__ = [
    "Case",
    "CargoConfig",
    "CargoSectionConfig",
    "SeaFasteningConfig",
    "LashingConfig",
    "StopperConfig",
    "SideStopperConfig",
    "VesselConfig",
    "WaveConfig",
    "SolverConfig",
    "ModelConfig",
    "OutputConfig",
    "SeaStateConfig",
    "LimitsConfig",
    "CriteriaConfig",
    "BASE_SADDLE_STIFFNESS_N_PER_M",
    "BREAKING_STEEPNESS",
    "HEAD_SEAS_DEG",
    "SOURCE_SOLVER_SETTINGS",
    "max_significant_height_m",
]

BASE_SADDLE_STIFFNESS_N_PER_M = 1.1e9

DEFAULT_SADDLE_CONTACT_ANGLE_DEG = 45.0
"""Half-angle of a saddle's two pads from bottom dead centre [deg]: a 90 deg contact arc, the middle of the
60-120 deg arcs of monopile transport saddles (docs/criteria.md); a stand-in for the saddle's drawing."""


class CargoSectionConfig(StrictSection):
    """One segment of a piecewise (tapered) tube, positions along the cargo from its aft end."""

    x_start_m: NonNegative
    x_end_m: Positive
    diameter_start_m: Positive
    diameter_end_m: Positive
    wall_thickness_m: Positive

    @model_validator(mode="after")
    def _check(self) -> CargoSectionConfig:
        if self.x_end_m <= self.x_start_m:
            raise ValueError(f"x_end_m = {self.x_end_m} must be greater than x_start_m = {self.x_start_m}")
        d_min = min(self.diameter_start_m, self.diameter_end_m)
        if self.wall_thickness_m >= d_min / 2:
            raise ValueError(f"wall_thickness_m = {self.wall_thickness_m} must be less than half the smallest diameter ({d_min / 2})")
        return self


class CargoConfig(StrictSection):
    """The cargo: a steel tube (monopile), uniform or piecewise."""

    length_m: Positive = Field(74.0, description="Cargo length L_m [m]")
    diameter_m: Positive = Field(8.0, description="Outer diameter D of the uniform tube [m]")
    wall_thickness_m: Positive = Field(0.080, description="Wall thickness t of the uniform tube [m]")
    sections: tuple[CargoSectionConfig, ...] | None = Field(
        None, description="Piecewise tube segments covering [0, length_m]; replaces diameter_m/wall_thickness_m"
    )
    position_m: Finite | None = Field(
        None, description="x of the cargo midpoint on the ship from the aft perpendicular [m]; default midship"
    )
    youngs_modulus_Pa: Positive = 210e9
    poisson_ratio: Annotated[float, Field(gt=0, lt=0.5), NotBool] = 0.3
    density_kg_per_m3: Positive = 7850.0
    units_abreast: Annotated[int, Field(ge=1, le=20), NotBool] = Field(
        4, description="Identical cargo items side by side (their weights add on the hull; one is modelled)"
    )
    transverse_position_m: Finite | None = Field(
        None, description="y of the analysed unit's axis from the centreline, + to port [m]; null = the outermost abreast lane to port"
    )

    @model_validator(mode="after")
    def _check(self) -> CargoConfig:
        if self.sections is None:
            if self.wall_thickness_m >= self.diameter_m / 2:
                raise ValueError(f"wall_thickness_m = {self.wall_thickness_m} must be less than diameter_m / 2 = {self.diameter_m / 2}")
        else:
            if len(self.sections) == 0:
                raise ValueError("sections must list at least one segment (or be null for the uniform tube)")
            x = 0.0
            for i, s in enumerate(self.sections):
                if not math.isclose(s.x_start_m, x, abs_tol=1e-6):
                    raise ValueError(
                        f"sections[{i}].x_start_m = {s.x_start_m} must equal the previous segment's end ({x}); "
                        "segments must be contiguous from 0"
                    )
                x = s.x_end_m
            if not math.isclose(x, self.length_m, abs_tol=1e-6):
                raise ValueError(f"the last section ends at {x} m but length_m = {self.length_m}; they must match")
        return self


class LashingConfig(StrictSection):
    """Pretensioned lashing wires at the lashed saddles."""

    stiffness_N_per_m: NonNegative = Field(
        37.5e3, description="Wire axial stiffness k_l [N/m]; k_z and k_theta scale with it from 6.5 kN/m and 1.46 MN m/rad"
    )
    pretension_N: NonNegative = Field(210e3, description="Total pretension T_l [N], shared by the lashed saddles, acting downward")
    angle_deg: Annotated[float, Field(gt=0, le=90, allow_inf_nan=False), NotBool] = Field(
        45.0,
        description="Angle of the lashing wires from the deck [deg], fore/aft pairs in the ship's vertical-longitudinal plane: "
        "axial stiffness k_l cos^2(angle) per lashed saddle, axial pretension components cancel (axial analysis only, docs/axial.md)",
    )
    axial_stiffness_N_per_m: NonNegative | None = Field(
        None,
        description="Total axial stiffness of the lashings [N/m], given directly; replaces the one from angle_deg (axial analysis only)",
    )


class StopperConfig(StrictSection):
    """Optional end stoppers fore and aft of the cargo: unilateral axial springs with a gap (axial analysis)."""

    gap_m: NonNegative | None = Field(
        None, description="Axial gap between the cargo and each stopper, fore and aft [m]; null = no stoppers"
    )
    stiffness_N_per_m: Positive | None = Field(None, description="Axial stiffness of each stopper [N/m] (needed with gap_m)")

    @model_validator(mode="after")
    def _check(self) -> StopperConfig:
        if (self.gap_m is None) != (self.stiffness_N_per_m is None):
            given, missing = ("gap_m", "stiffness_N_per_m") if self.stiffness_N_per_m is None else ("stiffness_N_per_m", "gap_m")
            raise ValueError(f"{given} is set but {missing} is not; give both (stoppers) or neither (no stoppers)")
        return self


class SideStopperConfig(StrictSection):
    """Optional side stoppers beside every saddle, port and starboard: compression-only lateral springs with a gap
    (``seafast criteria``, docs/transverse.md)."""

    gap_m: NonNegative | None = Field(
        None, description="Lateral clearance between the cargo and each side stopper [m]; null = no side stoppers"
    )
    stiffness_N_per_m: Positive | None = Field(None, description="Lateral stiffness of each side stopper [N/m] (needed with gap_m)")

    @model_validator(mode="after")
    def _check(self) -> SideStopperConfig:
        if (self.gap_m is None) != (self.stiffness_N_per_m is None):
            given, missing = ("gap_m", "stiffness_N_per_m") if self.stiffness_N_per_m is None else ("stiffness_N_per_m", "gap_m")
            raise ValueError(f"{given} is set but {missing} is not; give both (side stoppers) or neither (none)")
        return self


class SeaFasteningConfig(StrictSection):
    """Saddles and lashings."""

    saddle_count: Annotated[int, Field(ge=1, le=50), NotBool] = Field(
        3, description="n saddles evenly from 0.2 L to 0.8 L, lashings at the two outermost"
    )
    saddle_positions_m: tuple[Finite, ...] | None = Field(
        None, description="Explicit saddle positions along the cargo from its aft end [m]; overrides saddle_count"
    )
    saddle_stiffness_N_per_m: Positive | tuple[Positive, ...] = Field(
        BASE_SADDLE_STIFFNESS_N_PER_M, description="Compression stiffness per saddle [N/m]: one value for all, or one per saddle"
    )
    lashed_saddles: tuple[Annotated[int, Field(ge=0), NotBool], ...] | None = Field(
        None, description="Indices (0-based, aft to fore) of lashed saddles; default the two outermost"
    )
    lashing: LashingConfig = LashingConfig()
    friction_coefficient: NonNegative | tuple[NonNegative, ...] | None = Field(
        None,
        description="Coulomb friction coefficient between cargo and saddles [-]: one value for all, or one per saddle; "
        "null = no axial analysis (the source's vertical model alone). Setting it runs the axial sliding analysis (docs/axial.md)",
    )
    tangential_stiffness_N_per_m: Positive | None = Field(
        None,
        description="Tangential (stick) stiffness of each saddle's friction contact, the Jenkins element's spring [N/m]; "
        "null = 1e12 N/m, a rigid contact (the results are then independent of it, docs/axial.md; axial analysis only)",
    )
    saddle_height_m: NonNegative = Field(
        1.0,
        description="Height of the cargo's underside (the saddles' contact line) above the deck [m] (the lever arms of the axial analysis, the motions and seafast criteria)",
    )
    stopper: StopperConfig = StopperConfig()
    saddle_contact_angle_deg: Annotated[float, Field(gt=0, lt=90, allow_inf_nan=False), NotBool] = Field(
        DEFAULT_SADDLE_CONTACT_ANGLE_DEG,
        description="Half-angle of each saddle's two pads from bottom dead centre [deg], 0 < alpha < 90 (a contact arc of "
        "2 alpha); default 45, the middle of typical monopile saddles' 60-120 deg arcs: set it from the saddle drawing "
        "(seafast criteria, docs/criteria.md)",
    )
    side_stopper: SideStopperConfig = SideStopperConfig()

    @field_validator("friction_coefficient", mode="before")
    @classmethod
    def _friction(cls, v: object) -> object:
        # one clear message instead of pydantic's two union-branch errors
        if v is None:
            return v
        values = list(v) if isinstance(v, (list, tuple)) else [v]
        if not values:
            raise ValueError("must list at least one value, or be null (no axial analysis)")
        numbers: list[float] = []
        for x in values:
            if isinstance(x, bool) or not isinstance(x, (int, float)) or not math.isfinite(x) or x < 0:
                raise ValueError(f"{x!r} is not allowed; a friction coefficient is a finite number >= 0 (one value, or one per saddle)")
            numbers.append(float(x))
        return tuple(numbers) if isinstance(v, (list, tuple)) else numbers[0]

    @field_validator("saddle_positions_m")
    @classmethod
    def _positions(cls, v: tuple[float, ...] | None) -> tuple[float, ...] | None:
        if v is None:
            return v
        if len(v) == 0:
            raise ValueError("must list at least one position, or be null to use saddle_count")
        if any(b <= a for a, b in pairwise(v)):
            raise ValueError(f"{list(v)}: positions must be strictly increasing (no coincident saddles)")
        return v


class VesselConfig(StrictSection):
    """Vessel particulars and the sources of the deck excitation."""

    length_m: Positive = Field(171.0, description="Length between perpendiculars L_s [m]")
    breadth_m: Positive = Field(42.0, description="Moulded breadth B [m]")
    draft_m: Positive = Field(6.5, description="Design draught T [m]")
    displacement_m3: Positive = Field(32000.0, description="Displaced volume [m^3]")
    hull_second_moment_m4: Positive = Field(103.8, description="Hull-girder second moment of area I_s [m^4]")
    hull_shear_area_m2: Positive | None = Field(None, description="Hull-girder effective shear area [m^2]; default documented")
    youngs_modulus_Pa: Positive = 210e9
    poisson_ratio: Annotated[float, Field(gt=0, lt=0.5), NotBool] = 0.3
    water_density_kg_per_m3: Positive = 1025.0
    lightship_mass_kg: Positive | None = Field(None, description="Lightship mass [kg]; default documented")
    hull_form_table: Path | None = Field(
        None, description="CSV with columns x_m, breadth_m (waterline breadth); default: tapered box from L, B, T, displacement"
    )
    still_water_bending_moment_table: Path | None = Field(
        None, description="CSV with columns x_m, bending_moment_Nm (sagging positive), e.g. from the loading computer"
    )
    deck_deflection_table: Path | None = Field(
        None, description="CSV x_m, still_water_m, wave_amplitude_m, wave_phase_rad; replaces the computed hull deflection"
    )
    motions: str = Field("bem", description="'bem' (computed with capytaine), 'none', or a path to capytaine NetCDF / WAMIT .1 output")
    bem_panel_size_m: Positive = Field(3.0, description="Target panel size of the BEM mesh [m]")
    motion_coupling: Literal[MotionCoupling.HEAVE_PITCH, MotionCoupling.SURGE_HEAVE_PITCH] = Field(
        MotionCoupling.HEAVE_PITCH,
        description="Rigid-body motions the vertical analysis uses: 'heave_pitch' (the 2-DOF solution, the source's model) or "
        "'surge_heave_pitch' (coupled with surge, when the hydrodynamic data hold it; docs/axial.md). The axial analysis "
        "always uses the coupled surge and pitch",
    )
    deck_height_m: Positive = Field(
        12.0,
        description="Height of the cargo deck above the keel [m] (moulded depth; the lever arms of pitch in the axial analysis and of roll and pitch in seafast criteria)",
    )
    vertical_centre_of_gravity_m: Positive | None = Field(
        None, description="Loaded ship's KG above the keel [m]; null = from the weight distribution (head seas: the 8 m of before)"
    )
    roll_radius_of_gyration_m: Positive | None = Field(
        None, description="Loaded ship's roll radius of gyration about its centre of gravity [m]; null = from the weight distribution"
    )
    roll_damping_ratio: Annotated[float, Field(ge=0, lt=1, allow_inf_nan=False), NotBool] = Field(
        0.05, description="Additional linear roll damping, fraction of critical 2 sqrt((I44 + A44) C44) [-] (docs/headings.md)"
    )
    coupling: Literal[HullCargoCoupling.ONE_WAY, HullCargoCoupling.TWO_WAY] = Field(
        HullCargoCoupling.ONE_WAY,
        description="'one_way' (the source's: the hull carries the cargo as a spread weight, the cargo follows the deck) or "
        "'two_way' (hull and cargo solved together: the cargo's deck forces load the quasi-static hull girder, still water and wave)",
    )
    roll_damping_quadratic_Nms2_per_rad2: NonNegative | None = Field(
        None,
        description="Quadratic roll damping B44_2 [N m s^2/rad^2]: the roll moment -B44_2 |phi'| phi' of bilge keels and eddies "
        "(from a decay test: B44_2 = 3 b (I44 + A44) / 4, docs/roll_damping.md), linearised per regular wave or per sea state; "
        "null = none (head seas have no roll and never read it)",
    )

    @model_validator(mode="after")
    def _check_coupling(self) -> VesselConfig:
        if self.coupling == "two_way":
            for key in ("deck_deflection_table", "still_water_bending_moment_table"):
                if getattr(self, key) is not None:
                    raise ValueError(
                        f"vessel.coupling = 'two_way' needs the computed hull girder and its loading; it cannot be combined "
                        f"with vessel.{key} (use 'one_way', or remove the table)"
                    )
        return self


HEAD_SEAS_DEG = 180.0
"""Head seas [deg], the default heading: the waves travel from bow to stern (the heave-pitch model serves it)."""

BREAKING_STEEPNESS = 1.0 / 7.0
"""Wave height over length above which a deep-water wave breaks (Michell's limit, ~0.142) [-]."""


class WaveConfig(StrictSection):
    """Regular head-sea wave, no steeper than the breaking limit (height over length at most 1/7)."""

    length_m: Positive = Field(171.0, description="Wave length lambda [m]")
    amplitude_m: NonNegative = Field(
        3.0, description="Wave amplitude zeta_a [m]; the height 2 zeta_a is at most 1/7 of the length (breaking limit)"
    )
    frequency_rad_s: Positive | None = Field(None, description="Wave frequency [rad/s]; default from deep-water dispersion")
    heading_deg: float = Field(
        HEAD_SEAS_DEG,
        ge=0.0,
        lt=360.0,
        description="Wave heading beta [deg]: the direction the waves travel, from the ship's x axis (forward) towards y (port); 180 = head seas, 90 = beam seas (waves from starboard), 0 = following seas",
    )

    @model_validator(mode="after")
    def _check(self) -> WaveConfig:
        steepness = 2.0 * self.amplitude_m / self.length_m
        if steepness > BREAKING_STEEPNESS:
            raise ValueError(
                f"amplitude_m = {self.amplitude_m} at length_m = {self.length_m}: the wave height 2 zeta_a is "
                f"{steepness:.3g} of the length, past the breaking limit 1/7 = {BREAKING_STEEPNESS:.3f} (no such regular "
                f"wave exists); allowed amplitude_m <= {0.5 * BREAKING_STEEPNESS * self.length_m:.3g} m at this length "
                "(amplitude in metres, half the wave height)"
            )
        return self


def max_significant_height_m(peak_period_s: float, gravity_m_per_s2: float = 9.81) -> float:
    """Steepest sea state that occurs (DNV-RP-C205, 3.5.5.4): Hs at the limiting steepness [m].

    The average steepness ``S_p = 2 pi Hs / (g Tp^2)`` of a sea state does not exceed 1/15 for
    ``Tp <= 8 s`` and 1/25 for ``Tp >= 15 s`` (linear in Tp between).
    """
    tp = float(peak_period_s)
    s_p = 1.0 / 15.0 if tp <= 8.0 else 1.0 / 25.0 if tp >= 15.0 else 1.0 / 15.0 + (tp - 8.0) / 7.0 * (1.0 / 25.0 - 1.0 / 15.0)
    return s_p * gravity_m_per_s2 * tp * tp / (2.0 * math.pi)


class SeaStateConfig(StrictSection):
    """Irregular sea for ``seafast seastate`` at a mean heading, long- or short-crested (not used by ``seafast run``)."""

    significant_height_m: Positive | None = Field(
        None,
        description="Significant wave height Hs = 4 sqrt(m0) [m]; required for jonswap/pierson_moskowitz; "
        "with a spectrum table: null uses the table as given, a value rescales it to this Hs",
    )
    peak_period_s: Positive | None = Field(
        None, description="Spectral peak period Tp [s]; required for jonswap/pierson_moskowitz; must be null with a spectrum table"
    )
    spectrum: str = Field(
        "jonswap", description="'jonswap' (DNV-RP-C205), 'pierson_moskowitz', or a CSV path with columns omega_rad_s,S_m2_s_per_rad"
    )
    peak_enhancement: Annotated[float, Field(ge=1.0, le=10.0, allow_inf_nan=False), NotBool] = Field(
        3.3, description="JONSWAP peak-enhancement factor gamma [-] (1 = Pierson-Moskowitz)"
    )
    duration_s: Annotated[float, Field(ge=60.0, le=86400.0, allow_inf_nan=False), NotBool] = Field(
        10800.0, description="Duration of the sea state over which maxima are taken [s] (3 hours)"
    )
    realisations: Annotated[int, Field(ge=3, le=10000), NotBool] = Field(
        20, description="Random-phase realisations of the nonlinear Monte Carlo reference"
    )
    seed: Annotated[int, Field(ge=0), NotBool] = Field(0, description="Seed of the random phases (reproducible realisations)")
    heading_deg: float = Field(
        HEAD_SEAS_DEG,
        ge=0.0,
        lt=360.0,
        description="Mean wave heading beta of the sea state [deg], as wave.heading_deg: the direction the waves travel, from "
        "the ship's x axis (forward) towards y (port); 180 = head seas, 90 = beam seas (waves from starboard), 0 = following seas",
    )
    spreading_exponent: Annotated[float, Field(gt=0.0, le=1000.0, allow_inf_nan=False), NotBool] | None = Field(
        None,
        description="Exponent s of the cos-2s directional spreading [-] (short-crested sea; wind seas about 5-15, swell 25 and "
        "more; up to 1000, beyond which the sea is long-crested within a fraction of a degree); null = long-crested",
    )
    random_amplitudes: bool = Field(
        True,
        description="Monte Carlo components with Rayleigh-distributed amplitudes (a Gaussian sea, true) or the "
        "deterministic amplitudes sqrt(2 S d_omega) (false: every record has the spectral variance, but the maxima "
        "vary less between records than in a Gaussian sea); the phases are the same either way",
    )

    @model_validator(mode="after")
    def _check(self) -> SeaStateConfig:
        parametric = self.spectrum in ("jonswap", "pierson_moskowitz")
        if not parametric:
            if not self.spectrum.strip() or "\0" in self.spectrum:
                raise ValueError(f"spectrum = {self.spectrum!r}: allowed 'jonswap', 'pierson_moskowitz' or a CSV file path")
            if self.peak_period_s is not None:
                raise ValueError(
                    f"peak_period_s = {self.peak_period_s}: with a spectrum table the peak period comes from the table; "
                    "set it to null (significant_height_m, if given, rescales the table)"
                )
        if self.significant_height_m is not None and self.peak_period_s is not None:
            hs_max = max_significant_height_m(self.peak_period_s)
            if self.significant_height_m > hs_max:
                raise ValueError(
                    f"significant_height_m = {self.significant_height_m} at peak_period_s = {self.peak_period_s} is steeper "
                    f"than any sea state (DNV-RP-C205 limiting steepness 2 pi Hs / (g Tp^2)); allowed Hs <= {hs_max:.2f} m at this Tp"
                )
        return self


class LimitsConfig(StrictSection):
    """Design limits the sea-state extremes are judged against; the cradle limits (a study file's names) off head seas
    only, None = not checked (an unset one is left out of the case's dump: case.yaml, fingerprints as before)."""

    max_saddle_force_N: Positive = Field(7.0e6, description="Largest allowed saddle force F [N]")
    max_bending_stress_Pa: Positive = Field(20.0e6, description="Largest allowed cargo bending stress sigma_b [Pa]")
    max_pad_force_N: Positive | None = Field(None, description="Largest pad force [N], off head seas; null: unchecked")
    max_lashing_tension_N: Positive | None = Field(None, description="Largest lashing tension [N], off head seas; null: unchecked")
    max_transverse_slip_m: Positive | None = Field(None, description="Largest cargo slip at a saddle [m], off head seas; null: unchecked")

    @model_serializer(mode="wrap")
    def _dump(self, handler: SerializerFunctionWrapHandler) -> dict[str, Any]:
        return {k: v for k, v in handler(self).items() if v is not None}  # only the cradle limits can be None


class CriteriaDesignConfig(StrictSection):
    """The design format of ``seafast criteria``: LRFD or allowable stress (docs/criteria.md)."""

    format: DesignFormat = Field(
        DesignFormat.ALLOWABLE_STRESS,
        description="'allowable_stress' (unfactored load effects against the yield stress times allowable_stress_factor) or "
        "'lrfd' (the ULS combinations a) and b) of permanent and environmental load factors against the yield over "
        "material_factor)",
    )
    yield_stress_Pa: Positive = Field(355.0e6, description="Characteristic yield stress of the cargo's steel [Pa] (S355: 355 MPa)")
    material_factor: Annotated[float, Field(ge=1.0, le=2.0, allow_inf_nan=False), NotBool] = Field(
        1.15, description="LRFD material factor gamma_M on the yield stress [-]"
    )
    allowable_stress_factor: Annotated[float, Field(gt=0.0, le=1.0, allow_inf_nan=False), NotBool] = Field(
        0.6, description="Allowable-stress format: the allowable bending stress as a fraction of the yield stress [-]"
    )


class CriteriaMotionConfig(StrictSection):
    """The motion-analysis branch of ``seafast criteria``: the case's sea state at each heading (docs/criteria.md)."""

    enabled: bool = Field(False, description="Add the motion-analysis load cases beside the default criteria")
    headings_deg: tuple[Annotated[float, Field(ge=0.0, lt=360.0, allow_inf_nan=False), NotBool], ...] | None = Field(
        None, description="Mean headings of the sea state [deg] (180 head seas, 90 beam seas); null = sea_state.heading_deg"
    )
    nonlinear: bool = Field(True, description="Add the nonlinear design-wave MPMs of F, M_b and sigma_b (as seafast seastate)")

    @field_validator("headings_deg")
    @classmethod
    def _distinct(cls, v: tuple[float, ...] | None) -> tuple[float, ...] | None:
        if v is not None and (len(v) == 0 or len(set(v)) != len(v)):
            raise ValueError(f"{list(v)!r}: allowed a non-empty list of distinct headings in [0, 360) deg, or null")
        return v


class CriteriaFrictionConfig(StrictSection):
    """The friction credit of ``seafast criteria`` (docs/criteria.md)."""

    contact: ContactSurface = Field(
        ContactSurface.STEEL_ON_STEEL,
        description="Materials in contact at the saddles: 'steel_on_steel' (no friction may be counted), 'steel_on_timber' or "
        "'steel_on_rubber' (seafastening.friction_coefficient counted, reduced by the vertical acceleration)",
    )


class CriteriaConfig(StrictSection):
    """Design criteria of the transport (``seafast criteria``, ``seafast operability``): design format, motion-analysis
    branch, friction credit, operation class."""

    operation: OperationConfig | None = Field(
        None, description="The operation class (weather-restricted with its alpha factor, or unrestricted on its route); null: none"
    )
    design: CriteriaDesignConfig = CriteriaDesignConfig()
    motion_analysis: CriteriaMotionConfig = CriteriaMotionConfig()
    friction: CriteriaFrictionConfig = CriteriaFrictionConfig()


class Case(StrictSection):
    """One seafast case: cargo, sea-fastening, vessel, wave, solver (and a sea state, limits)."""

    name: str = "case"
    cargo: CargoConfig = CargoConfig()
    seafastening: SeaFasteningConfig = SeaFasteningConfig()
    vessel: VesselConfig = VesselConfig()
    wave: WaveConfig = WaveConfig()
    solver: SolverConfig = SolverConfig()
    model: ModelConfig = ModelConfig()
    outputs: OutputConfig = OutputConfig()
    sea_state: SeaStateConfig = SeaStateConfig()
    limits: LimitsConfig = LimitsConfig()
    criteria: CriteriaConfig = CriteriaConfig()

    @model_validator(mode="after")
    def _check(self) -> Case:
        L = self.cargo.length_m
        sf = self.seafastening
        positions = self.saddle_positions_m()
        for i, x in enumerate(positions):
            if not (0.0 < x < L):
                raise ValueError(
                    f"seafastening.saddle_positions_m[{i}] = {x} lies outside the cargo; allowed: 0 < x < cargo.length_m = {L}"
                )
        if isinstance(sf.saddle_stiffness_N_per_m, tuple) and len(sf.saddle_stiffness_N_per_m) not in (1, len(positions)):
            raise ValueError(
                f"seafastening.saddle_stiffness_N_per_m has {len(sf.saddle_stiffness_N_per_m)} values for "
                f"{len(positions)} saddles; give one value, or one per saddle"
            )
        mu = sf.friction_coefficient
        if isinstance(mu, tuple) and len(mu) not in (1, len(positions)):
            raise ValueError(
                f"seafastening.friction_coefficient has {len(mu)} values for {len(positions)} saddles; give one value, or one per saddle"
            )
        if sf.lashed_saddles is not None:
            bad = [i for i in sf.lashed_saddles if i >= len(positions)]
            if bad:
                raise ValueError(
                    f"seafastening.lashed_saddles = {list(sf.lashed_saddles)} names saddle(s) {bad}; allowed 0..{len(positions) - 1}"
                )
        d_max = (
            self.cargo.diameter_m
            if self.cargo.sections is None
            else max(max(s.diameter_start_m, s.diameter_end_m) for s in self.cargo.sections)
        )
        if self.cargo.units_abreast * d_max > self.vessel.breadth_m:
            raise ValueError(
                f"cargo.units_abreast = {self.cargo.units_abreast} units of {d_max:g} m diameter need "
                f"{self.cargo.units_abreast * d_max:g} m of deck, more than vessel.breadth_m = {self.vessel.breadth_m:g}; "
                f"allowed units_abreast <= {int(self.vessel.breadth_m // d_max)}"
            )
        off_deck = transverse_position_error(self.cargo.transverse_position_m, d_max, self.vessel.breadth_m)
        if off_deck:
            raise ValueError(off_deck)
        if self.cargo.position_m is not None:
            half = L / 2
            if self.cargo.position_m - half < 0 or self.cargo.position_m + half > self.vessel.length_m:
                raise ValueError(
                    f"cargo.position_m = {self.cargo.position_m} puts the cargo (length {L} m) beyond the ship's ends; "
                    f"allowed {half} .. {self.vessel.length_m - half}"
                )
        return self

    # ---------------------------------------------------------------- derived values
    def saddle_positions_m(self) -> tuple[float, ...]:
        """Saddle positions along the cargo [m]: explicit list, or the arrangement rule."""
        sf = self.seafastening
        if sf.saddle_positions_m is not None:
            return tuple(sf.saddle_positions_m)
        return tuple(float(x) for x in evenly_spaced_saddles(sf.saddle_count, self.cargo.length_m))

    def saddle_stiffnesses_N_per_m(self) -> tuple[float, ...]:
        """Stiffness of each saddle [N/m]."""
        k = self.seafastening.saddle_stiffness_N_per_m
        n = len(self.saddle_positions_m())
        if isinstance(k, tuple):
            return k * n if len(k) == 1 else k
        return (float(k),) * n

    def friction_coefficients(self) -> tuple[float, ...] | None:
        """Friction coefficient of each saddle [-], or None when the axial analysis is off."""
        mu = self.seafastening.friction_coefficient
        if mu is None:
            return None
        n = len(self.saddle_positions_m())
        if isinstance(mu, tuple):
            return tuple(float(m) for m in mu) * n if len(mu) == 1 else tuple(float(m) for m in mu)
        return (float(mu),) * n

    def lashed_saddle_indices(self) -> tuple[int, ...]:
        """Indices of the lashed saddles (default: the two outermost)."""
        if self.seafastening.lashed_saddles is not None:
            return tuple(sorted(set(self.seafastening.lashed_saddles)))
        n = len(self.saddle_positions_m())
        return (0,) if n == 1 else (0, n - 1)

    def cargo_position_m(self) -> float:
        """x of the cargo midpoint from the AP [m] (default: midship)."""
        return self.cargo.position_m if self.cargo.position_m is not None else 0.5 * self.vessel.length_m

    def cargo_transverse_position_m(self) -> float:
        """y of the analysed unit's axis from the centreline [m], + to port: given, or the outermost abreast lane to port."""
        y = self.cargo.transverse_position_m
        return float(abreast_lanes_m(self.cargo.units_abreast, self.vessel.breadth_m)[-1] if y is None else y)

    def wave_frequency_rad_s(self) -> float:
        """Wave frequency [rad/s]: given, or deep-water dispersion omega = sqrt(2 pi g / lambda)."""
        if self.wave.frequency_rad_s is not None:
            return self.wave.frequency_rad_s
        return math.sqrt(2.0 * math.pi * self.model.gravity_m_per_s2 / self.wave.length_m)
