"""The case's numerical settings: the nonlinear solver (and its presets), the cargo model's discretisation and
damping, and what `seafast run` writes."""

from __future__ import annotations

from typing import Annotated, Literal, get_args

from pydantic import Field, ValidationInfo, field_validator, model_validator

from seafast.config.fields import NotBool, Positive, StrictSection
from seafast.config.modes import ContactLawKind, Formulation, NonlinearSolver, SolverMethod, TimeDomainStart

__all__ = ["ModelConfig", "OutputConfig", "SOURCE_SOLVER_SETTINGS", "SolverConfig"]


#: The source's method (``solver.preset: source``): the values it gives the keys the case leaves unset.
SOURCE_SOLVER_SETTINGS: dict[str, object] = {
    "contact_law": ContactLawKind.TANH,
    "regularisation_per_m": 1000.0,
    "harmonics": 5,
    "time_samples": 128,
    "nonlinear_solver": NonlinearSolver.HYBR,
}


class SolverConfig(StrictSection):
    """Nonlinear (contact) solver settings."""

    preset: Literal["default", "source"] = Field(
        "default",
        description="'default' (exact contact law, harmonics chosen adaptively until the saddle-force peaks settle) or "
        "'source' (the source's method: tanh law with kappa = 1000 1/m, 5 harmonics, 128 samples, Powell's hybrid "
        "method); a preset only fills the keys the case leaves unset",
    )
    # the modes are Literals of enum members: the values are the members, the JSON Schema lists them inline
    method: Literal[SolverMethod.HBM, SolverMethod.QUASI_STATIC, SolverMethod.TIME_DOMAIN, SolverMethod.SHOOTING] = Field(
        SolverMethod.HBM,
        description="hbm (harmonic balance, default; with solver.harmonics unset and the exact contact law its converged "
        "limit, every harmonic, computed by exact-event shooting), quasi_static or time_domain (the exact-contact "
        "references), or shooting (exact-event shooting on the piecewise-linear contact problem)",
    )
    formulation: Literal[Formulation.CONDENSED, Formulation.FULL] = Formulation.CONDENSED
    # a case starts the time-domain reference from the linear or the harmonic balance's solution only
    time_domain_start: Literal[TimeDomainStart.LINEAR, TimeDomainStart.HBM] = Field(
        TimeDomainStart.LINEAR,
        description="State the time-domain reference (solver.method: time_domain) starts from: 'linear' (the "
        "linear periodic solution at t = 0) or 'hbm' (the harmonic balance's solution with the case's settings: the "
        "reference then reports whether it stays on that orbit, solver outcome 'other_orbit' when it does not)",
    )
    contact_law: Literal[ContactLawKind.TANH, ContactLawKind.SOFTPLUS, ContactLawKind.EXACT] = Field(
        ContactLawKind.EXACT, description="Saddle contact law: exact (default), tanh (the source's regularisation) or softplus"
    )
    regularisation_per_m: Positive = Field(1000.0, description="Sharpness kappa of the regularised contact laws [1/m]")
    harmonics: Annotated[int, Field(ge=1, le=1024), NotBool] | None = Field(
        None,
        description="Number of harmonics H; default (null): the converged answer (with the exact contact law and the "
        "condensed formulation every harmonic, by exact-event shooting; otherwise H chosen adaptively until the "
        "saddle-force peaks settle to solver.truncation_tolerance)",
    )
    time_samples: Annotated[int, Field(ge=4, le=16384), NotBool] | None = Field(
        None,
        description="AFT time samples per period N; default (null): max(128, 2.5 H) (512 output samples for the references; "
        "the shooting solver chooses its own grid from the cargo's modes and its peaks)",
    )
    nonlinear_solver: Literal[NonlinearSolver.HYBR, NonlinearSolver.NEWTON] = Field(
        NonlinearSolver.NEWTON, description="newton (damped semi-smooth Newton, default) or hybr (Powell's hybrid method, as the source)"
    )
    tolerance: Positive = Field(1e-10, description="Relative residual tolerance")
    axial_harmonics: Annotated[int, Field(ge=1, le=400), NotBool] = Field(
        100, description="Number of harmonics of the axial (friction) harmonic balance (axial analysis only)"
    )
    truncation_tolerance: Annotated[float, Field(gt=0, lt=1), NotBool] = Field(
        1e-3,
        description="Largest estimated error of each saddle's peak force from the harmonics left out, relative to "
        "its force scale [-]: the adaptive harmonics' target, and the level above which a fixed H is reported as too few",
    )
    max_harmonics: Annotated[int, Field(ge=1, le=1024), NotBool] = Field(512, description="Upper bound of the adaptive H")

    @field_validator("method", "formulation", "time_domain_start", "contact_law", "nonlinear_solver", mode="before")
    @classmethod
    def _mode(cls, value: object, info: ValidationInfo) -> object:
        # a mode by its value, the allowed ones named by their values (pydantic's own message prints the members' reprs)
        allowed = get_args(cls.model_fields[str(info.field_name)].annotation)
        if not isinstance(value, str) or value not in allowed:
            names = [repr(str(m)) for m in allowed]
            raise ValueError("Input should be " + (", ".join(names[:-1]) + " or " + names[-1] if len(names) > 1 else names[0]))
        return type(allowed[0])(value)

    @model_validator(mode="before")
    @classmethod
    def _apply_preset(cls, data: object) -> object:
        if isinstance(data, dict) and data.get("preset") == "source":
            data = {**SOURCE_SOLVER_SETTINGS, **data}
        return data

    @model_validator(mode="after")
    def _check(self) -> SolverConfig:
        if self.harmonics is not None and self.time_samples is not None and self.time_samples < 2 * self.harmonics + 2:
            raise ValueError(f"time_samples = {self.time_samples} must be at least 2 * harmonics + 2 = {2 * self.harmonics + 2} (aliasing)")
        return self

    @property
    def reference_time_samples(self) -> int:
        """Output samples per period of the exact references: ``time_samples``, else 512."""
        return int(self.time_samples) if self.time_samples is not None else 512


class ModelConfig(StrictSection):
    """Discretisation, damping and environment."""

    element_length_m: Positive = Field(1.0, description="Target cargo finite-element length [m]")
    damping_ratio: Annotated[float, Field(ge=0, lt=1), NotBool] = Field(
        0.02, description="Rayleigh damping ratio at the first two cargo natural frequencies [-]"
    )
    gravity_m_per_s2: Positive = 9.81


class OutputConfig(StrictSection):
    """What `seafast run` writes besides summary.csv."""

    netcdf: bool = True
    plots: bool = True
