"""A sea-state study's point in beam seas (with the cargo on its cradles) against head seas (docs/studies.md section 7).

Run ``python benchmarks/bench_sea_state_study.py``. The 2-point study of the tests (contact angle 35 and 50 deg, Hs
3 m, Tp 10 s, long-crested), one process, one BLAS thread, CPU time (the machine is shared): each point evaluated as
the study evaluates it (:func:`seafast.analyses.seastate.study.evaluate_sea_state`) at 180 deg (the vertical plane
alone) and at 90 deg (the vertical plane, then the cradles' spectral MPMs and design waves), after one warm call of
each, interleaved, the median of 3. The last line is ``key=value`` pairs: the CPU per point in head and beam seas [ms]
and their ratio.
"""

from __future__ import annotations

import time

from benchutil import timed
from seafast.parallel.threads import one_blas_thread

ANGLES_DEG = (35.0, 50.0)


def main() -> None:
    import seafast
    from seafast.analyses.seastate.study import evaluate_sea_state
    from seafast.excitation.vessel import VesselCache

    def case(heading_deg: float, angle_deg: float) -> seafast.Case:
        keys = {"sea_state.heading_deg": heading_deg, "sea_state.significant_height_m": 3.0}
        return seafast.load_case(None, keys | {"seafastening.saddle_contact_angle_deg": angle_deg})

    head_ms, beam_ms = [], []
    with one_blas_thread(), VesselCache().shared():
        for heading in (180.0, 90.0):
            evaluate_sea_state(case(heading, ANGLES_DEG[0]))  # warm: vessel, BEM data, cargo mesh
        for angle in ANGLES_DEG:
            head_ms.append(timed(lambda a=angle: evaluate_sea_state(case(180.0, a)), 3, time.process_time)[1])
            beam_ms.append(timed(lambda a=angle: evaluate_sea_state(case(90.0, a)), 3, time.process_time)[1])
    head, beam = sum(head_ms) / len(head_ms), sum(beam_ms) / len(beam_ms)
    for angle, h, b in zip(ANGLES_DEG, head_ms, beam_ms, strict=True):
        print(f"contact angle {angle:g} deg: head seas {h:.0f} ms CPU, beam seas {b:.0f} ms CPU")
    print(f"head_ms={head:.0f} beam_ms={beam:.0f} beam_vs_head={beam / head:.2f}")


if __name__ == "__main__":
    main()
