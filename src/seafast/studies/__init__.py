"""Parametric studies: grids over case keys, batched/parallel/resumable execution, design limits.

Typical use::

    from seafast.studies import load_study_spec, build_grid, run_study, rank_compliant

    spec, directory = load_study_spec("saddles")          # or a study YAML file
    grid = build_grid(spec, directory, {"wave.amplitude_m": 2.5})
    run = run_study(grid, "out/saddles")                   # all cores; resumable
    ranking = rank_compliant(run.dataset)

Figures: :func:`seafast.output.study_plots.plot_study` (imported on demand: matplotlib).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from seafast.lazy import lazy_exports

if TYPE_CHECKING:
    from seafast.studies.limits import DesignLimits, compliance, compliance_rows, format_table, rank_compliant
    from seafast.studies.runner import (
        ExecutionOptions,
        PointRecord,
        PointStore,
        StudyRun,
        assemble_dataset,
        evaluate_batch,
        run_study,
    )
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
    "seafast.studies.runner": (
        "ExecutionOptions",
        "PointRecord",
        "PointStore",
        "StudyRun",
        "assemble_dataset",
        "evaluate_batch",
        "run_study",
    ),
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
    "ExecutionOptions",
    "PointRecord",
    "PointStore",
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
