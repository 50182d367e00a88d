"""How the condensed HBM solve grows with the cargo mesh and with the number of saddles.

Usage::

    python benchmarks/bench_scaling.py             # both sweeps, figure benchmarks/bench_scaling.png
    python benchmarks/bench_scaling.py --quick     # fewer repeats

The base case (its real vessel excitation, its own solver settings through
``seafast.pipeline.solve_nonlinear``) with the cargo mesh refined through
``model.element_length_m`` from 77 to about 1000 nodes, and with 2 to 12 saddles on the base
mesh. Two timings per configuration, medians over repeats in this process, one BLAS thread:

* ``solve``: the dynamic nonlinear solve of a model already solved once (what
  ``bench_hbm.py`` times: the model's banded operators are cached);
* ``fresh``: the same solve on a newly built model, so the model's operators are formed too
  (what every study point pays; the model build itself, mesh and Rayleigh eigen-solve, is not
  included).

A power law ``t = c n^p`` is fitted by least squares in log-log to each series. The last line is
``key=value`` pairs: ``mesh_exponent`` (solve time against nodes; target <= 1.2, every
factorisation being banded), ``mesh_exponent_fresh``, ``saddle_exponent`` and
``saddle_exponent_fresh`` (against the saddle count), and the timings at the ends of each sweep.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np
from threadpoolctl import threadpool_limits

from seafast.config import load_case
from seafast.excitation.vessel import vessel_excitation
from seafast.pipeline import build_model, solve_nonlinear

ELEMENT_LENGTHS_M = (1.0, 0.6, 0.35, 0.2, 0.12, 0.074)  # 77 ... ~1000 nodes on the 74 m pile
SADDLE_COUNTS = (2, 3, 4, 6, 8, 10, 12)
FIGURE = Path(__file__).resolve().parent / "bench_scaling.png"


def _median_ms(fn, min_repeats: int, budget_s: float) -> float:
    times: list[float] = []
    start = time.perf_counter()
    while len(times) < min_repeats or (time.perf_counter() - start < budget_s and len(times) < 200):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return 1e3 * float(np.median(times))


def time_case(overrides: dict, min_repeats: int, budget_s: float) -> dict[str, float]:
    """Nodes, saddles and the two median solve times [ms] of the base case with ``overrides``."""
    case = load_case(overrides=overrides)
    model = build_model(case)
    excitation = vessel_excitation(case).cargo_excitation(model, case)
    response = solve_nonlinear(model, excitation, case, static=False)  # warms the model's operators
    assert response.converged, f"{overrides}: {response.message}"
    solve = _median_ms(lambda: solve_nonlinear(model, excitation, case, static=False), min_repeats, budget_s)

    def on_a_new_model() -> None:
        fresh = build_model(case)  # the memoised mesh and Rayleigh coefficients: milliseconds
        t0 = time.perf_counter()
        solve_nonlinear(fresh, excitation, case, static=False)
        fresh_times.append(time.perf_counter() - t0)

    fresh_times: list[float] = []
    _median_ms(on_a_new_model, min_repeats, budget_s)
    return {
        "nodes": float(model.cargo.node_count),
        "saddles": float(model.saddle_count),
        "solve_ms": solve,
        "fresh_ms": 1e3 * float(np.median(fresh_times)),
        "iterations": float(response.iterations),
    }


def exponent(x: list[float], y: list[float]) -> float:
    """Least-squares slope of log y against log x."""
    return float(np.polyfit(np.log(x), np.log(y), 1)[0])


def plot(mesh: list[dict], saddles: list[dict], fits: dict[str, float], path: Path) -> Path:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for ax, rows, key, label in ((axes[0], mesh, "nodes", "cargo mesh nodes [-]"), (axes[1], saddles, "saddles", "saddles [-]")):
        x = np.array([r[key] for r in rows])
        for series, marker, name in (("solve_ms", "o", "solve"), ("fresh_ms", "s", "fresh model")):
            y = np.array([r[series] for r in rows])
            p = fits[f"{'mesh' if key == 'nodes' else 'saddle'}_exponent{'' if series == 'solve_ms' else '_fresh'}"]
            c = np.exp(np.mean(np.log(y) - p * np.log(x)))
            ax.loglog(x, y, marker, label=f"{name}: t ~ n^{p:.2f}")
            ax.loglog(x, c * x**p, "--", color=ax.lines[-1].get_color(), linewidth=0.8)
        ax.set_xlabel(label)
        ax.set_ylabel("median condensed HBM solve [ms]")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
    axes[0].set_title("base case, refined through model.element_length_m")
    axes[1].set_title("base case, 1 m elements, saddle_count")
    fig.tight_layout()
    fig.savefig(path, dpi=150)
    plt.close(fig)
    return path


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--quick", action="store_true", help="fewer repeats")
    parser.add_argument("--figure", type=Path, default=FIGURE, help="PNG to write (default: %(default)s)")
    args = parser.parse_args(argv)
    min_repeats, budget = (3, 0.2) if args.quick else (7, 1.0)
    mesh: list[dict] = []
    saddles: list[dict] = []
    with threadpool_limits(limits=1):
        for length in ELEMENT_LENGTHS_M:
            row = time_case({"model.element_length_m": length}, min_repeats, budget)
            mesh.append(row)
            print(f"element {length:5.3f} m: {row['nodes']:5.0f} nodes  solve {row['solve_ms']:8.2f} ms  fresh model {row['fresh_ms']:8.2f} ms  ({row['iterations']:.0f} iterations)")
        for count in SADDLE_COUNTS:
            row = time_case({"seafastening.saddle_count": count}, min_repeats, budget)
            saddles.append(row)
            print(f"{count:2d} saddles: solve {row['solve_ms']:8.2f} ms  fresh model {row['fresh_ms']:8.2f} ms  ({row['iterations']:.0f} iterations)")
    fits = {
        "mesh_exponent": exponent([r["nodes"] for r in mesh], [r["solve_ms"] for r in mesh]),
        "mesh_exponent_fresh": exponent([r["nodes"] for r in mesh], [r["fresh_ms"] for r in mesh]),
        "saddle_exponent": exponent([r["saddles"] for r in saddles], [r["solve_ms"] for r in saddles]),
        "saddle_exponent_fresh": exponent([r["saddles"] for r in saddles], [r["fresh_ms"] for r in saddles]),
    }
    figure = plot(mesh, saddles, fits, args.figure)
    print(f"fitted t ~ nodes^p: solve p = {fits['mesh_exponent']:.2f}, fresh model p = {fits['mesh_exponent_fresh']:.2f} (target <= 1.2)")
    print(f"fitted t ~ saddles^p: solve p = {fits['saddle_exponent']:.2f}, fresh model p = {fits['saddle_exponent_fresh']:.2f}; figure {figure}")
    print(
        " ".join(f"{k}={v:.3g}" for k, v in fits.items())
        + f" nodes_max={mesh[-1]['nodes']:.0f} solve_ms_77_nodes={mesh[0]['solve_ms']:.3g} solve_ms_max_nodes={mesh[-1]['solve_ms']:.3g}"
        f" fresh_ms_max_nodes={mesh[-1]['fresh_ms']:.3g} solve_ms_12_saddles={saddles[-1]['solve_ms']:.3g}"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
