"""The cradle columns of `seafast seastate` off head seas against the vertical plane's part of the same sea state.

Run ``python benchmarks/bench_seastate_cradle.py``. The base case in a long-crested beam sea (Hs 3 m, Tp 10 s, 256
frequencies), one process, one BLAS thread, CPU time (the machine is shared), median of the repeats, interleaved:
the vertical plane's spectral analysis and design waves (what `seafast seastate --no-monte-carlo` computed before)
against the cradle columns (the cradles' transfer functions, spectral MPMs and design waves by `solve_cradle_hbm`).
The vessel and its BEM come from the warm cache. Then one Monte Carlo realisation (half an hour, Hs 7 m, side
stoppers 1 mm off, 2 GN/m: the stoppers close) of the cargo on its cradles
(:func:`~seafast.analyses.seastate.cradle_realisation.evaluate_cradle_realisation`) against the vertical plane's
(:func:`~seafast.analyses.seastate.realisation.evaluate_realisation`), same sea, after a first one of each (kernels
compiled). The last line is ``key=value`` pairs: ``cradle_vs_vertical`` the cradle columns' time over the vertical
plane's, ``mc_cradle_vs_vertical`` the cradle realisation's over the vertical one's.
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
    mv, mc, steps = _monte_carlo_realisations()
    mc_pairs = f"mc_vertical_ms={mv:.0f} mc_cradle_ms={mc:.0f} mc_cradle_vs_vertical={mc / mv:.1f} mc_cradle_window_steps={steps}"
    print(f"vertical_ms={v:.0f} cradle_ms={c:.0f} cradle_vs_vertical={c / v:.2f} {mc_pairs}")


def _monte_carlo_realisations() -> tuple[float, float, int]:
    """CPU ms of one vertical and one cradle realisation of the same sea, and the cradle's fine steps in windows."""
    import seafast
    from seafast.analyses.seastate.cradle_realisation import evaluate_cradle_realisation
    from seafast.analyses.seastate.monte_carlo import build_cradle_plan, build_plan
    from seafast.analyses.seastate.realisation import evaluate_realisation

    overrides = {
        "sea_state.heading_deg": 90.0,
        "sea_state.significant_height_m": 7.0,
        "sea_state.duration_s": 1800.0,
        "seafastening.side_stopper.gap_m": 1e-3,
        "seafastening.side_stopper.stiffness_N_per_m": 2e9,
    }
    case = seafast.load_case(None, overrides)
    with one_blas_thread():
        plan, cradle = build_plan(case), build_cradle_plan(case)
        assert cradle is not None
        evaluate_realisation(plan, 0)
        evaluate_cradle_realisation(cradle, 0)
        mv = timed(lambda: evaluate_realisation(plan, 1), 1, time.process_time)[1]
        record, mc = timed(lambda: evaluate_cradle_realisation(cradle, 1), 1, time.process_time)
    print(f"Monte Carlo realisation, {overrides['sea_state.duration_s']:g} s: vertical {mv:.0f} ms CPU, cradle {mc:.0f} ms CPU")
    print(f"cradle: {record['windows']} windows, {record['window_steps']} fine steps; nonlinear {record['nonlinear']}")
    return mv, mc, int(record["window_steps"])


if __name__ == "__main__":
    main()
