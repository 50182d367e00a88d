"""The sea state's cradle columns on frictional pads against frictionless ones (docs/seastate.md#pad-friction-in-the-design-waves).

Run ``python benchmarks/bench_seastate_friction.py``. The base case in a long-crested beam sea (90 deg, Hs 3 m, Tp
10 s), one process, one BLAS thread, CPU time (the machine is shared): the cradle columns of `seafast seastate`
(transfer functions, spectral MPMs and the 12 design waves) without ``seafastening.friction_coefficient`` and with
0.2 (each design wave also solved by the frictional harmonic balance at H = 32, N = 256), interleaved. The last line
is ``key=value`` pairs: ``friction_vs_frictionless`` the frictional columns' time over the frictionless ones', and the
largest pad force of both design-wave rows [MN].
"""

from __future__ import annotations

import time

from benchutil import timed
from seafast.parallel.threads import one_blas_thread


def main() -> None:
    import seafast
    from seafast.analyses.seastate.cradle_design_wave import cradle_sea_state
    from seafast.analyses.seastate.spectral import spectral_analysis
    from seafast.excitation.vessel import VesselCache

    beam = {"sea_state.heading_deg": 90.0}
    with one_blas_thread(), VesselCache().shared():
        plain = spectral_analysis(seafast.load_case(None, beam))
        rough = spectral_analysis(seafast.load_case(None, {**beam, "seafastening.friction_coefficient": 0.2}))
        cradle_sea_state(plain)  # warm
        a, t0 = timed(lambda: cradle_sea_state(plain), 1, time.process_time)
        b, t1 = timed(lambda: cradle_sea_state(rough), 1, time.process_time)
    assert a.design is not None and b.design is not None
    f0, f1 = a.design.totals["F_pad_N"] * 1e-6, b.design.totals["F_pad_N"] * 1e-6
    print(f"frictionless: {t0:.0f} ms CPU, F_pad {f0:.3f} MN; mu = 0.2: {t1:.0f} ms CPU, F_pad {f1:.3f} MN")
    print(
        f"frictionless_ms={t0:.0f} friction_ms={t1:.0f} friction_vs_frictionless={t1 / t0:.1f} "
        f"F_pad_frictionless_MN={f0:.3f} F_pad_friction_MN={f1:.3f} converged={b.design.converged}"
    )


if __name__ == "__main__":
    main()
