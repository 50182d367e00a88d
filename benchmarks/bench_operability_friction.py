"""Operability's cradle limits on frictional pads against frictionless ones (docs/operability.md#operability-on-the-cradles).

Run ``python benchmarks/bench_operability_friction.py``. The base case in a long-crested beam sea (90 deg), the pads
limited to 5 MN (``limits.max_pad_force_N``), peak periods 8, 10 and 12 s, one process, one BLAS thread, CPU time
(the machine is shared), vessel in memory: what ``seafast operability`` computes per heading (the family of sea
states, the cargo on its cradles and the allowable-Hs search, ``allowable_sea_states`` from the case):

* ``frictionless_s``: without ``seafastening.friction_coefficient``;
* ``friction_s``: with 0.2, each design wave a frictional harmonic balance (H = 32, N = 256; the search led by H = 16);
* ``friction_unled_s``: the same without the H = 16 lead (every evaluation at H = 32, bracketing and Brent);
* ``friction_vs_frictionless``, ``friction_vs_unled``: the ratios; and the allowable Hs of the pad limit per Tp.

The last line is ``key=value`` pairs.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import seafast
import seafast.analyses.operability.allowable as allowable
from benchutil import timed
from seafast.analyses.operability.allowable import allowable_sea_states
from seafast.excitation.vessel import VesselCache
from seafast.parallel.threads import one_blas_thread

TPS = [8.0, 10.0, 12.0]
BEAM = {"sea_state.heading_deg": 90.0, "limits.max_pad_force_N": 5.0e6}


def main() -> None:
    plain = seafast.load_case(None, BEAM)
    rough = seafast.load_case(None, {**BEAM, "seafastening.friction_coefficient": 0.2})
    with one_blas_thread(), VesselCache().shared():
        allowable_sea_states(plain, TPS)  # warm
        a, t0 = timed(lambda: allowable_sea_states(plain, TPS), 1, time.process_time)
        b, t1 = timed(lambda: allowable_sea_states(rough, TPS), 1, time.process_time)
        led = allowable.proxy_friction
        allowable.proxy_friction = lambda friction: None  # every evaluation at the case's H
        try:
            c, t2 = timed(lambda: allowable_sea_states(rough, TPS), 1, time.process_time)
        finally:
            allowable.proxy_friction = led
    for p, q, r in zip(a.points, b.points, c.points, strict=True):
        print(
            f"Tp {p.peak_period_s:g} s: pad-force allowable Hs frictionless {p.hs_pad_force_nonlinear_m:.3f} m, "
            f"mu = 0.2 {q.hs_pad_force_nonlinear_m:.3f} m (unled {r.hs_pad_force_nonlinear_m:.3f} m); allowable "
            f"{p.hs_allowable_nonlinear_m:.3f} ({p.governing_nonlinear}) -> {q.hs_allowable_nonlinear_m:.3f} m ({q.governing_nonlinear})"
        )
    print(f"frictionless {t0 / 1e3:.2f} s CPU, mu = 0.2 {t1 / 1e3:.2f} s CPU, unled {t2 / 1e3:.2f} s CPU")
    hs = " ".join(f"hs_pad_mu02_tp{p.peak_period_s:g}={p.hs_pad_force_nonlinear_m:.4f}" for p in b.points)
    print(
        f"frictionless_s={t0 / 1e3:.2f} friction_s={t1 / 1e3:.2f} friction_unled_s={t2 / 1e3:.2f} "
        f"friction_vs_frictionless={t1 / t0:.1f} friction_vs_unled={t1 / t2:.2f} converged={b.converged and c.converged} {hs}"
    )


if __name__ == "__main__":
    main()
