"""The 3-D cargo on its cradles in beam seas against the vertical plane's default solve in head seas.

Run ``python benchmarks/bench_cradle.py``. The base case, in one process and one BLAS thread: the vertical
plane's default nonlinear solve (``solve_nonlinear``: exact-event shooting) in head seas, and the 3-D cargo's
default solve (``solve_cradle_hbm`` with H unset: exact-event shooting, the adaptive harmonic balance its fallback)
in beam seas (heading 90 deg), each pad pair at
the base case's saddle with a contact angle of 35 deg, a side stopper each side (20 mm gap) and today's lashing
springs; also with 20 deg pads, where the high-side pads lift and the solve is nonlinear. Both are timed from their
model (the vertical model's derived caches cleared, the 3-D dynamics built afresh), interleaved, median of the
repeats. For the lifting case also: the harmonic balance alone (adaptive H, ``shooting=False``) and its floors, the
operators alone up to the H it reached (their cost is a floor of any harmonic balance converged to 0.1 % of the
peaks) and the one solve from the linear solution at the first
H where it converges (the floor of the nonlinear part: no start is cheaper than a direct solve), the old default
(a fixed H = 64), and the peak forces of each against a solve at H = 512.
The last line is ``key=value`` pairs: ``beam_vs_head`` is the 3-D beam-sea time over the head-sea time (the
target: at most 3); ``beam_lift_vs_head`` the same with the 20 deg pads, ``lift_operators_vs_head`` and
``lift_direct_vs_head`` its two floors, ``lift_fixed64_vs_head`` the old default's; ``lift_peak_error`` and
``fixed64_peak_error`` the largest peak-force difference from H = 512 over the largest peak;
``lift_hbm_vs_head`` the harmonic balance alone (``shooting=False``, adaptive H: the default before) and
``hbm_peak_error`` its peaks' error; ``strong_lift_vs_head`` the default solve on 1.3 times the wave with the 20 deg
pads (strong lift-off) and ``strong_lift_outcome`` its outcome.
"""

from __future__ import annotations

import time

import numpy as np

from seafast.parallel.threads import one_blas_thread


def cradle_dynamics_for(model, alpha_deg: float):
    from seafast.model.cargo3d import build_cargo3d, vertical_plane_restraint
    from seafast.model.cradle import PadPair, Side, SideStopper
    from seafast.solvers.cradle_dynamics import cradle_dynamics_of
    from seafast.solvers.transverse_statics import CradleProblem

    cargo = build_cargo3d(model.cargo)
    springs, load = vertical_plane_restraint(model, cargo)
    springs[cargo.node_dofs(int(model.saddle_node[0]))[0]] += 1e8  # an axial restraint
    pairs = tuple(
        PadPair(float(x), alpha_deg, 4.0, float(k))
        for x, k in zip(model.saddle_x_m, model.saddle_unilateral_stiffness_N_per_m, strict=True)
    )
    stoppers = tuple(SideStopper(float(x), side, 0.02, 1e9) for x in model.saddle_x_m for side in (Side.PORT, Side.STARBOARD))
    return cargo, lambda: cradle_dynamics_of(model, CradleProblem(cargo, pairs, stoppers, spring_diagonal_N_per_m=springs, load_N=load))


def lift_floors(build, excitation, response, repeats: int = 2) -> dict[str, float]:
    """The lifting case's floors [ms]: the operators up to the H reached, and the direct solve at the first H
    after the first (the first converging one on the base case); the old fixed H = 64 [ms]; and the peak
    errors against H = 512 [-]."""
    from dataclasses import replace

    from seafast.solvers.cradle_dynamics import cradle_operators
    from seafast.solvers.cradle_hbm import ADAPTIVE_HARMONICS, solve_cradle_hbm
    from seafast.solvers.hbm import HBMOptions, solve_condensed

    def included(dynamics):
        problem = dynamics.problem
        mask = np.ones(len(problem.engagements), dtype=bool)
        mask[2 * len(problem.pad_pairs) : 2 * len(problem.pad_pairs) + len(problem.stoppers)] = False
        return mask

    adaptive = solve_cradle_hbm(build(), excitation, shooting=False)  # the harmonic balance alone: the H it reaches

    def operators():
        dynamics = build()
        return cradle_operators(dynamics, excitation, adaptive.harmonics, included(dynamics))

    H1 = ADAPTIVE_HARMONICS[1]
    ops1 = cradle_operators(build(), excitation, H1, included(build()))
    direct = replace(HBMOptions().with_harmonics(H1), continuation=False)
    fixed = HBMOptions(harmonics=64)
    times: dict[str, list[float]] = {"ops": [], "direct": [], "fixed64": [], "hbm": []}
    runs = {
        "hbm": lambda: solve_cradle_hbm(build(), excitation, shooting=False),
        "ops": operators,
        "direct": lambda: solve_condensed(ops1, direct),
        "fixed64": lambda: solve_cradle_hbm(build(), excitation, fixed),
    }
    results = {name: fn() for name, fn in runs.items()}
    for _ in range(repeats):
        for name, fn in runs.items():
            t0 = time.process_time()
            results[name] = fn()
            times[name].append(time.process_time() - t0)
    out = {name: 1e3 * float(np.median(t)) for name, t in times.items()}
    reference = solve_cradle_hbm(build(), excitation, HBMOptions(harmonics=512))
    scale = float(np.max(reference.max_force_N))
    out["lift_peak_error"] = float(np.max(np.abs(response.max_force_N - reference.max_force_N))) / scale
    out["hbm_peak_error"] = float(np.max(np.abs(results["hbm"].max_force_N - reference.max_force_N))) / scale
    out["hbm_harmonics"] = float(adaptive.harmonics)
    out["fixed64_peak_error"] = float(np.max(np.abs(results["fixed64"].max_force_N - reference.max_force_N))) / scale
    out["direct_converged"] = float(results["direct"].converged)
    return out


def strong_lift_off(build, excitation, factor: float = 1.3) -> dict:
    """The default solve on the wave ``factor`` times as high (20 deg pads: strong lift-off, every stopper closing):
    its time [ms], its outcome and message (one solve: seconds)."""
    from dataclasses import replace

    from seafast.solvers.cradle_hbm import solve_cradle_hbm

    rows = np.array([[1.0], [factor]])
    higher = replace(excitation, cargo_load_N=excitation.cargo_load_N * rows, deck_displacement=excitation.deck_displacement * rows)
    t0 = time.process_time()
    response = solve_cradle_hbm(build(), higher)
    return {"ms": 1e3 * (time.process_time() - t0), "outcome": response.outcome.value, "message": response.message}


def main() -> None:
    from seafast.config import load_case
    from seafast.excitation.cradle_loads import cradle_excitation_of
    from seafast.excitation.vessel import vessel_excitation
    from seafast.model.from_case import build_model
    from seafast.solvers.cradle_hbm import solve_cradle_hbm
    from seafast.solvers.from_case import solve_nonlinear

    head_case = load_case()
    beam_case = load_case(overrides={"wave.heading_deg": 90.0})
    with one_blas_thread():
        head_model = build_model(head_case)
        head_exc = vessel_excitation(head_case).cargo_excitation(head_model)
        beam_model = build_model(beam_case)
        beam_vessel = vessel_excitation(beam_case)
        runs = {}
        for alpha in (35.0, 20.0):
            cargo, build = cradle_dynamics_for(beam_model, alpha)
            runs[alpha] = (build, cradle_excitation_of(beam_vessel, beam_model, cargo))

        def head():
            head_model.derived_cache.clear()
            return solve_nonlinear(head_model, head_exc, head_case, static=False)

        solvers = {"head": head, **{a: (lambda a=a: solve_cradle_hbm(runs[a][0](), runs[a][1])) for a in runs}}
        results = {name: fn() for name, fn in solvers.items()}  # warm (compiled kernels)
        times: dict[object, list[float]] = {name: [] for name in solvers}
        for repeat in range(7):
            for name, fn in solvers.items():
                if name == 20.0 and repeat > 3:
                    continue  # a tenth of a second a solve: four are enough
                t0 = time.process_time()
                results[name] = fn()
                times[name].append(time.process_time() - t0)
    ms = {name: 1e3 * float(np.median(t)) for name, t in times.items()}
    with one_blas_thread():
        floors = lift_floors(runs[20.0][0], runs[20.0][1], results[20.0])
        strong = strong_lift_off(runs[20.0][0], runs[20.0][1])
    print(f"head seas, vertical plane ({results['head'].method}): {ms['head']:.1f} ms, {results['head'].message[:90]}")
    for alpha in runs:
        r = results[alpha]
        print(
            f"beam seas, 3-D on {alpha:g} deg pads: {ms[alpha]:.1f} ms; H = {r.harmonics}; largest pad {r.pad_force_N.max() / 1e6:.2f} MN, "
            f"stopper {r.stopper_force_N.max() / 1e6:.2f} MN, pads open {100 * r.open_fraction[: r.pad_count].max():.0f} % "
            f"of the period at most; {r.message[:200]}"
        )
    print(
        f"20 deg pads, the harmonic balance alone (shooting=False, the default before): {floors['hbm']:.1f} ms at "
        f"H = {floors['hbm_harmonics']:.0f}, peaks {floors['hbm_peak_error']:.1e} of the largest from H = 512; "
        f"its floors: operators up to that H {floors['ops']:.1f} ms; the direct solve at the second H "
        f"{floors['direct']:.1f} ms (converged: {bool(floors['direct_converged'])}); the old fixed H = 64 {floors['fixed64']:.1f} ms; "
        f"peaks against H = 512: the default {floors['lift_peak_error']:.1e}, "
        f"fixed H = 64 {floors['fixed64_peak_error']:.1e} of the largest"
    )
    print(
        f"20 deg pads, 1.3 times the wave (strong lift-off): the default solve {strong['ms']:.0f} ms, "
        f"{strong['outcome']}; {strong['message'][-260:]}"
    )
    head = ms["head"]
    ratios = f"beam_vs_head={ms[35.0] / head:.2f} beam_lift_vs_head={ms[20.0] / head:.2f}"
    floors_words = (
        f"lift_hbm_vs_head={floors['hbm'] / head:.2f} lift_operators_vs_head={floors['ops'] / head:.2f} "
        f"lift_direct_vs_head={floors['direct'] / head:.2f} "
        f"lift_fixed64_vs_head={floors['fixed64'] / head:.2f} lift_peak_error={floors['lift_peak_error']:.1e} "
        f"fixed64_peak_error={floors['fixed64_peak_error']:.1e} hbm_peak_error={floors['hbm_peak_error']:.1e}"
    )
    strong_words = f"strong_lift_vs_head={strong['ms'] / head:.0f} strong_lift_outcome={strong['outcome']}"
    print(f"{ratios} {floors_words} {strong_words} head_ms={head:.1f} beam_ms={ms[35.0]:.1f} beam_lift_ms={ms[20.0]:.1f}")


if __name__ == "__main__":
    main()
