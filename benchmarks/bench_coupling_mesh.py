"""Two-way coupling against the cargo mesh: residual, its round-off floor, forces and cost.

Run ``python benchmarks/bench_coupling_mesh.py`` (about a minute on 2 cores). For each
``model.element_length_m`` the base case runs one-way and two-way in this process; the
still-water nonlinear row is then iterated on with a relative tolerance of 1e-14 to find the
floor where the coupling stalls (the round-off of the cargo's deck forces), and how far the
deck forces move from the converged state to that floor. Prints a table (docs/coupling.md,
section 2); the last line is ``key=value`` pairs.
"""

from __future__ import annotations

import numpy as np

from benchutil import timed
from seafast.parallel.threads import one_blas_thread

ELEMENT_LENGTHS_M = (1.0, 0.5, 0.2, 0.1)


def _one_length(length: float):
    """The base case at one element length: one-way and two-way timed, and the two-way
    still-water nonlinear row iterated to its round-off floor. Returns (result, floor, t_one, t_two)."""
    from seafast.analyses.run import run_case
    from seafast.config import load_case
    from seafast.coupling.deck_iteration import couple_deck, linear_coupling_jacobian
    from seafast.coupling.deck_loads import deck_forces_N
    from seafast.solvers.from_case import solve_nonlinear

    one_way = load_case(overrides={"model.element_length_m": length})
    case = load_case(overrides={"model.element_length_m": length, "vessel.coupling": "two_way"})
    with one_blas_thread():
        _, t_one = timed(lambda: run_case(one_way), 1)
        result, t_two = timed(lambda: run_case(case), 1)
        model, static = result.model, result.excitation.static_part()
        jac = linear_coupling_jacobian(model, static.omega_rad_s, result.compliance, 1)
        floor = couple_deck(
            model,
            static,
            result.compliance,
            lambda e: solve_nonlinear(model, e, case, static=True),
            lambda e, r: deck_forces_N(model, e, r, True, 1),
            1,
            jacobian0=jac,
            relative_tolerance=1e-14,
        )
    return result, floor, t_one, t_two


def main() -> None:
    from seafast.analyses.run import run_case
    from seafast.config import load_case

    run_case(load_case())  # the vessel (BEM from the disk cache) into memory
    print(
        f"{'L [m]':>6} {'nodes':>5} {'static nl res/steps':>20} {'dynamic nl res/steps':>21} {'tol [m]':>8} "
        f"{'floor [m]':>9} {'dP [N]':>7} {'F st nl [MN]':>12} {'F dyn nl [MN]':>13} {'M mid [MN m]':>12} {'2-way/1-way':>11}"
    )
    figures: dict[str, float] = {}
    for length in ELEMENT_LENGTHS_M:
        result, floor, t_one, t_two = _one_length(length)
        model = result.model
        rows = {(r["load_case"], r["model"]): r for r in result.summary}
        st, dy = result.coupling[("static", "nonlinear")], result.coupling[("dynamic", "nonlinear")]
        moved = float(np.abs(floor.deck_force_N[0].real - result.deck_couplings[("static", "nonlinear")].deck_force_N[0].real).max())
        hull = result.coupled_hull
        mid = int(np.argmin(np.abs(hull.x_m - result.vessel.girder.midship_x_m)))
        print(
            f"{length:6.2f} {model.cargo.node_count:5d} {st.residual_m:12.1e} / {st.iterations:<5d} "
            f"{dy.residual_m:13.1e} / {dy.iterations:<5d} "
            f"{st.tolerance_m:8.1e} {floor.residual_m:9.1e} {moved:7.1f} {rows[('static', 'nonlinear')]['F_N'] / 1e6:12.4f} "
            f"{rows[('dynamic', 'nonlinear')]['F_N'] / 1e6:13.4f} {hull.still_water_bending_moment_Nm[mid] / 1e6:12.2f} "
            f"{t_two / t_one:11.2f}"
        )
        if not all(s.converged for s in result.coupling.values()):
            print("  a row did NOT converge: " + "; ".join(s.message for s in result.coupling.values() if not s.converged))
        figures[f"floor_m_L{length:g}"] = floor.residual_m
        figures[f"force_to_floor_N_L{length:g}"] = moved
        figures[f"converged_L{length:g}"] = float(all(s.converged for s in result.coupling.values()))
        figures[f"two_way_vs_one_way_L{length:g}"] = t_two / t_one
    print(" ".join(f"{k}={v:.3g}" for k, v in figures.items()))


if __name__ == "__main__":
    main()
