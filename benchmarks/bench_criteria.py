"""Design-criteria benchmark: the default criteria, and the motion-analysis branch at one heading against the sea-state
analysis it is built on.

Run as ``python benchmarks/bench_criteria.py`` (the six-DOF BEM must be in the disk cache, SEAFAST_CACHE_DIR). Figures,
all in one process, CPU time (the machine is shared), median of three after a warm-up:

* ``default_ms``: the eight default cases with their checks and friction credit (allowable stress);
* ``lrfd_vs_default``: the same in LRFD (two more exact solves per case), against ``default_ms``;
* ``heading_ms``: the motion branch at 135 deg: spectral analysis, design waves, motions, six load cases;
* ``heading_vs_seastate``: against the spectral analysis and design waves alone at that heading (what ``seafast
  seastate --no-monte-carlo`` computes): the branch's own cost on top of it.

The last line is ``key=value`` pairs.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from benchutil import timed
from seafast.analyses.criteria.check import criteria_check
from seafast.analyses.criteria.motion_branch import heading_criteria
from seafast.analyses.seastate.design_wave import sea_state_design_waves
from seafast.analyses.seastate.spectral import spectral_analysis
from seafast.config import load_case
from seafast.excitation.vessel import VesselCache
from seafast.model.cradle_case import build_cradle_case
from seafast.model.from_case import build_model

HEADING_DEG = 135.0


def main() -> None:
    cpu = time.process_time
    case = load_case()
    lrfd = load_case(overrides={"criteria.design.format": "lrfd"})
    cradle = build_cradle_case(case)
    _, default_ms = timed(lambda: criteria_check(case, cradle), 3, cpu)
    _, lrfd_ms = timed(lambda: criteria_check(lrfd, cradle), 3, cpu)
    print(f"default criteria, eight cases: {default_ms:.0f} ms CPU; LRFD {lrfd_ms:.0f} ms ({lrfd_ms / default_ms:.2f} x)")
    oblique = load_case(overrides={"sea_state.heading_deg": HEADING_DEG})
    with VesselCache().shared():
        heading_criteria(case, cradle, HEADING_DEG)  # warm-up: the vessel and its six-DOF motions in memory
        _, heading_ms = timed(lambda: heading_criteria(case, cradle, HEADING_DEG), 3, cpu)
        _, seastate_ms = timed(lambda: sea_state_design_waves(spectral_analysis(oblique, build_model(oblique))), 3, cpu)
    print(
        f"motion branch at {HEADING_DEG:g} deg: {heading_ms:.0f} ms CPU; the sea-state analysis and design waves alone "
        f"{seastate_ms:.0f} ms ({heading_ms / seastate_ms:.2f} x)"
    )
    print(
        f"default_ms={default_ms:.1f} lrfd_vs_default={lrfd_ms / default_ms:.2f} heading_ms={heading_ms:.1f} "
        f"heading_vs_seastate={heading_ms / seastate_ms:.2f}"
    )


if __name__ == "__main__":
    main()
