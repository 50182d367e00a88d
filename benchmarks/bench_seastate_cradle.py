"""The cradle columns of `seafast seastate` off head seas against the vertical plane's part of the same sea state.

Run ``python benchmarks/bench_seastate_cradle.py``. The base case in a long-crested beam sea (Hs 3 m, Tp 10 s, 256
frequencies), one process, one BLAS thread, CPU time (the machine is shared), median of the repeats, interleaved:
the vertical plane's spectral analysis and design waves (what `seafast seastate --no-monte-carlo` computed before)
against the cradle columns (the cradles' transfer functions, spectral MPMs and design waves by `solve_cradle_hbm`).
The vessel and its BEM come from the warm cache. The last line is ``key=value`` pairs: ``cradle_vs_vertical`` the
cradle columns' time over the vertical plane's.
"""

from __future__ import annotations

import time

from benchutil import timed
from seafast.parallel.threads import one_blas_thread


def main() -> None:
    import seafast
    from seafast.analyses.seastate.cradle_design_wave import cradle_sea_state
    from seafast.analyses.seastate.design_wave import sea_state_design_waves
    from seafast.analyses.seastate.spectral import spectral_analysis
    from seafast.excitation.vessel import VesselCache
    from seafast.model.from_case import build_model

    case = seafast.load_case(None, {"sea_state.heading_deg": 90.0})
    model = build_model(case)
    with one_blas_thread(), VesselCache().shared():
        analysis = spectral_analysis(case, model)  # warms the vessel
        vertical, cradle = [], []
        for _ in range(3):
            vertical.append(timed(lambda: sea_state_design_waves(spectral_analysis(case, model)), 1, time.process_time)[1])
            state, t = timed(lambda: cradle_sea_state(analysis), 1, time.process_time)
            cradle.append(t)
    v, c = sorted(vertical)[1], sorted(cradle)[1]
    assert state.design is not None
    print(f"vertical plane (spectral + design waves): {v:.0f} ms CPU")
    print(f"cradle columns ({len(state.design.waves)} design waves): {c:.0f} ms CPU")
    print(f"vertical_ms={v:.0f} cradle_ms={c:.0f} cradle_vs_vertical={c / v:.2f}")


if __name__ == "__main__":
    main()
