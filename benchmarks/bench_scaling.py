"""How the condensed HBM solve grows with the cargo mesh and with the number of saddles.

Usage::

    python benchmarks/bench_scaling.py             # both sweeps, figure benchmarks/bench_scaling.png
    python benchmarks/bench_scaling.py --quick     # fewer repeats

The base case (its real vessel excitation, its own solver settings through
``seafast.solvers.from_case.solve_nonlinear``) with the cargo mesh refined through
``model.element_length_m`` from 77 to about 1000 nodes, and with 2 to 12 saddles on the base
mesh. Two timings per configuration, medians over repeats in this process, one BLAS thread:

* ``fresh``: the solve on a newly built model, so the model's banded operators are formed
  too: what every study point pays (the model build itself, mesh and Rayleigh eigen-solve, is
  memoised and not included);
* ``warm``: the solve of a model already solved once (what ``bench_hbm.py`` times: the model's
  operators cached).

A power law ``t = c n^p`` is fitted by least squares in log-log to each series. The last line is
``key=value`` pairs: ``mesh_exponent`` (fresh solve against nodes; target <= 1.2, every
factorisation being banded), ``mesh_exponent_warm``, ``saddle_exponent`` and
``saddle_exponent_warm`` (against the saddle count), and the timings at the ends of each sweep.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

from seafast.config import load_case
from seafast.excitation.vessel import vessel_excitation
from seafast.model.from_case import build_model
from seafast.parallel.threads import one_blas_thread
from seafast.solvers.from_case import solve_nonlinear

ELEMENT_LENGTHS_M = (1.0, 0.6, 0.35, 0.2, 0.12, 0.074)  # 77 ... ~1000 nodes on the 74 m pile
SADDLE_COUNTS = (2, 3, 4, 6, 8, 10, 12)
FIGURE = Path(__file__).resolve().parent / "bench_scaling.png"


class Configuration:
    """The base case with ``overrides``: its model, excitation and the two solve timings [s]."""

    def __init__(self, overrides: dict) -> None:
        self.case = load_case(overrides=overrides)
        self.model = build_model(self.case)
        self.excitation = vessel_excitation(self.case).cargo_excitation(self.model, self.case)
        response = solve_nonlinear(self.model, self.excitation, self.case, static=False)  # warms the model's operators
        assert response.converged, f"{overrides}: {response.message}"
        self.iterations = response.iterations
        self.fresh: list[float] = []
        self.warm: list[float] = []

    def time_once(self) -> None:
        t0 = time.perf_counter()
        solve_nonlinear(self.model, self.excitation, self.case, static=False)
        self.warm.append(time.perf_counter() - t0)
        fresh = build_model(self.case)  # memoised mesh and Rayleigh coefficients: a new model object
        t0 = time.perf_counter()
        solve_nonlinear(fresh, self.excitation, self.case, static=False)
        self.fresh.append(time.perf_counter() - t0)

    def row(self) -> dict[str, float]:
        return {
            "nodes": float(self.model.cargo.node_count),
            "saddles": float(self.model.saddle_count),
            "solve_ms": 1e3 * float(np.median(self.warm)),
            "fresh_ms": 1e3 * float(np.median(self.fresh)),
            "iterations": float(self.iterations),
        }


def time_all(configurations: list[Configuration], rounds: int) -> None:
    """Round-robin timing, so that a change of the machine's load touches every configuration alike."""
    for _ in range(rounds):
        for c in configurations:
            c.time_once()


def exponent(x: list[float], y: list[float]) -> float:
    """Least-squares slope of log y against log x."""
    return float(np.polyfit(np.log(x), np.log(y), 1)[0])


def plot(mesh: list[dict], saddles: list[dict], fits: dict[str, float], path: Path) -> Path:
    import matplotlib
    import matplotlib.ticker

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for ax, rows, key, label in ((axes[0], mesh, "nodes", "cargo mesh nodes [-]"), (axes[1], saddles, "saddles", "saddles [-]")):
        x = np.array([r[key] for r in rows])
        for series, marker, name in (("fresh_ms", "s", "new model"), ("solve_ms", "o", "model solved before")):
            y = np.array([r[series] for r in rows])
            p = fits[f"{'mesh' if key == 'nodes' else 'saddle'}_exponent{'' if series == 'fresh_ms' else '_warm'}"]
            c = np.exp(np.mean(np.log(y) - p * np.log(x)))
            ax.loglog(x, y, marker, label=f"{name}: t ~ n^{p:.2f}")
            ax.loglog(x, c * x**p, "--", color=ax.lines[-1].get_color(), linewidth=0.8)
        ax.set_xlabel(label)
        ax.set_xticks(x, [f"{v:g}" for v in x])  # the measured sizes
        ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        ax.yaxis.set_major_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
        ax.yaxis.set_minor_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
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
    rounds = 5 if args.quick else 25
    with one_blas_thread():
        mesh_cases = [Configuration({"model.element_length_m": length}) for length in ELEMENT_LENGTHS_M]
        saddle_cases = [Configuration({"seafastening.saddle_count": count}) for count in SADDLE_COUNTS]
        time_all(mesh_cases + saddle_cases, rounds)
    mesh = [c.row() for c in mesh_cases]
    saddles = [c.row() for c in saddle_cases]
    for length, row in zip(ELEMENT_LENGTHS_M, mesh, strict=True):
        print(
            f"element {length:5.3f} m: {row['nodes']:5.0f} nodes  new model {row['fresh_ms']:8.2f} ms  "
            f"solved before {row['solve_ms']:8.2f} ms  ({row['iterations']:.0f} iterations)"
        )
    for row in saddles:
        print(
            f"{row['saddles']:2.0f} saddles: new model {row['fresh_ms']:8.2f} ms  "
            f"solved before {row['solve_ms']:8.2f} ms  ({row['iterations']:.0f} iterations)"
        )
    fits = {
        "mesh_exponent": exponent([r["nodes"] for r in mesh], [r["fresh_ms"] for r in mesh]),
        "mesh_exponent_warm": exponent([r["nodes"] for r in mesh], [r["solve_ms"] for r in mesh]),
        "saddle_exponent": exponent([r["saddles"] for r in saddles], [r["fresh_ms"] for r in saddles]),
        "saddle_exponent_warm": exponent([r["saddles"] for r in saddles], [r["solve_ms"] for r in saddles]),
    }
    figure = plot(mesh, saddles, fits, args.figure)
    print(
        f"fitted t ~ nodes^p: new model p = {fits['mesh_exponent']:.2f} (target <= 1.2), "
        f"model solved before p = {fits['mesh_exponent_warm']:.2f}"
    )
    print(
        f"fitted t ~ saddles^p: new model p = {fits['saddle_exponent']:.2f}, "
        f"model solved before p = {fits['saddle_exponent_warm']:.2f}; figure {figure}"
    )
    print(
        " ".join(f"{k}={v:.3g}" for k, v in fits.items())
        + f" nodes_max={mesh[-1]['nodes']:.0f} fresh_ms_77_nodes={mesh[0]['fresh_ms']:.3g}"
        f" fresh_ms_max_nodes={mesh[-1]['fresh_ms']:.3g} warm_ms_max_nodes={mesh[-1]['solve_ms']:.3g}"
        f" fresh_ms_2_saddles={saddles[0]['fresh_ms']:.3g} fresh_ms_12_saddles={saddles[-1]['fresh_ms']:.3g}"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
