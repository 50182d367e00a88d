"""Study files: a YAML description of a parametric grid over case keys, validated with pydantic.

A study names a base case (a case file, or the built-in base case), fixed overrides of it
(``set``), one or more axes over numeric case keys (dotted paths such as ``cargo.length_m``),
optional derived keys computed from other keys (``cargo.wall_thickness_m: cargo.diameter_m / 110``)
and the design limits used to judge compliance::

    name: saddles
    axes:
      - key: seafastening.saddle_count
        values: [2, 3, 4, 5, 6, 7]
      - key: seafastening.saddle_stiffness_N_per_m
        start: 1.1e7
        stop: 1.1e10
        num: 20
        scale: log
    limits:
      max_saddle_force_N: 7.0e6
      max_bending_stress_Pa: 20.0e6

All input problems surface as :class:`StudyError` (a :class:`seafast.config.CaseError`) whose
message names the field, the value given and what is allowed.

Modules (this package re-exports their public names): :mod:`~seafast.studies.spec.errors`
(:class:`StudyError`), :mod:`~seafast.studies.spec.case_keys` (what a dotted case key is: its
numeric kind and its unit), :mod:`~seafast.studies.spec.expressions` (derived-key
expressions: parsing and evaluation), :mod:`~seafast.studies.spec.schema` (the pydantic models
of a study file), :mod:`~seafast.studies.spec.load` (reading and validating a study file or a
built-in study) and :mod:`~seafast.studies.spec.grid` (the resolved grid of points).
"""

from seafast.studies.spec.case_keys import case_key_kind, units_of_key
from seafast.studies.spec.errors import StudyError
from seafast.studies.spec.expressions import evaluate_expression, expression_keys
from seafast.studies.spec.grid import StudyGrid, build_grid
from seafast.studies.spec.load import BUILTIN_STUDIES, builtin_study_names, load_study_spec, study_spec_from_mapping
from seafast.studies.spec.schema import AxisSpec, LimitsSpec, StudySpec

__all__ = [
    "StudyError",
    "AxisSpec",
    "LimitsSpec",
    "StudySpec",
    "StudyGrid",
    "BUILTIN_STUDIES",
    "builtin_study_names",
    "load_study_spec",
    "study_spec_from_mapping",
    "build_grid",
    "case_key_kind",
    "evaluate_expression",
    "units_of_key",
    "expression_keys",
]
