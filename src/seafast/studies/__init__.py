"""Parametric studies: grids over case keys, batched/parallel/resumable execution, design limits.

Typical use::

    from seafast.parallel.executor import ExecutionOptions
    from seafast.studies import load_study_spec, build_grid, run_study, rank_compliant

    spec, directory = load_study_spec("saddles")          # or a study YAML file
    grid = build_grid(spec, directory, {"wave.amplitude_m": 2.5})
    run = run_study(grid, "out/saddles")                   # all cores; resumable
    serial = run_study(grid, "out/serial", execution=ExecutionOptions(workers=1))
    ranking = rank_compliant(run.dataset)

Figures: :func:`seafast.output.study_plots.plot_study` (imported on demand: matplotlib).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from seafast.lazy import lazy_exports

if TYPE_CHECKING:
    from seafast.studies.assembly import assemble_dataset
    from seafast.studies.execution import evaluate_batch
    from seafast.studies.limits import DesignLimits, compliance, compliance_rows, format_table, rank_compliant
    from seafast.studies.runner import StudyRun, run_study
    from seafast.studies.spec import (
        BUILTIN_STUDIES,
        AxisSpec,
        LimitsSpec,
        StudyError,
        StudyGrid,
        StudySpec,
        build_grid,
        load_study_spec,
        study_spec_from_mapping,
    )
    from seafast.studies.store import PointRecord, point_store

# imported on first use (seafast.lazy), so the command line's parser does not load numpy/xarray
EXPORTS = {
    "seafast.studies.spec": (
        "BUILTIN_STUDIES",
        "AxisSpec",
        "LimitsSpec",
        "StudyError",
        "StudyGrid",
        "StudySpec",
        "build_grid",
        "load_study_spec",
        "study_spec_from_mapping",
    ),
    "seafast.studies.runner": ("StudyRun", "run_study"),
    "seafast.studies.store": ("PointRecord", "point_store"),
    "seafast.studies.execution": ("evaluate_batch",),
    "seafast.studies.assembly": ("assemble_dataset",),
    "seafast.studies.limits": ("DesignLimits", "compliance", "compliance_rows", "format_table", "rank_compliant"),
}
__all__ = [
    "BUILTIN_STUDIES",
    "AxisSpec",
    "LimitsSpec",
    "StudyError",
    "StudyGrid",
    "StudySpec",
    "build_grid",
    "load_study_spec",
    "study_spec_from_mapping",
    "PointRecord",
    "point_store",
    "StudyRun",
    "assemble_dataset",
    "evaluate_batch",
    "run_study",
    "DesignLimits",
    "compliance",
    "compliance_rows",
    "format_table",
    "rank_compliant",
]
lazy_exports(__name__, EXPORTS)
