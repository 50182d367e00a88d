"""Deterministic fake evaluators for the study tests (importable by worker processes)."""

from __future__ import annotations

import logging
import math
import os
import time

from seafast.config.schema import Case
from seafast.model.warning import ModelWarning
from seafast.solvers.outcome import SolverWarning

EVAL_LOG_ENV = "SEAFAST_FAKE_EVAL_LOG"
SLEEP_ENV = "SEAFAST_FAKE_EVAL_SLEEP_S"

#: The fake's log: a note for every point, a warning where it raises too_few_harmonics (as the real solver does).
fake_logger = logging.getLogger("seafast.tests.fake_solver")


def fake_warnings(saddle_count: int, stiffness_N_per_m: float, load_case: str, model: str) -> tuple:
    """The fake's typed warnings of a row: too_few_harmonics on the dynamic nonlinear row of 4+ saddles at
    1e9 N/m and stiffer; rayleigh_fallback on both dynamic rows below 1e8 N/m."""
    out: tuple = ()
    if load_case == "dynamic" and model == "nonlinear" and saddle_count >= 4 and stiffness_N_per_m >= 1e9:
        out += (SolverWarning.TOO_FEW_HARMONICS,)
    if load_case == "dynamic" and stiffness_N_per_m < 1e8:
        out += (ModelWarning.RAYLEIGH_FALLBACK,)
    return out


def _log(case: Case) -> None:
    path = os.environ.get(EVAL_LOG_ENV)
    if path:
        key = f"{case.seafastening.saddle_count} {case.seafastening.saddle_stiffness_N_per_m!r}"
        with open(path, "a", encoding="utf-8") as fh:
            fh.write(f"{os.getpid()} {key}\n")


def fake_evaluate(case: Case) -> list[dict]:
    """A smooth deterministic response of the case's saddle count, stiffness, lashing and cargo, with the typed
    warnings of :func:`fake_warnings` and a log note per point (a warning where too_few_harmonics is raised)."""
    _log(case)
    delay = float(os.environ.get(SLEEP_ENV, "0") or 0)
    if delay:
        time.sleep(delay)
    n = case.seafastening.saddle_count
    k = float(case.seafastening.saddle_stiffness_N_per_m)
    fake_logger.info("fake solver: %d saddles at %g N/m", n, k)
    if SolverWarning.TOO_FEW_HARMONICS in fake_warnings(n, k, "dynamic", "nonlinear"):
        fake_logger.warning("fake solver: H = 16 leaves %d saddles at %g N/m unsettled", n, k)
    kl = case.seafastening.lashing.stiffness_N_per_m
    tl = case.seafastening.lashing.pretension_N
    L, D, t = case.cargo.length_m, case.cargo.diameter_m, case.cargo.wall_thickness_m
    rows = []
    for load_case, amp in (("static", 1.0), ("dynamic", 1.6)):
        for model, fac in (("linear", 1.0), ("nonlinear", 1.15)):
            F = amp * fac * 2.0e7 / n * (k / 1.1e9) ** 0.25 * (L / 74.0) * (1 + tl / 1e8)
            M = amp * fac * 5.0e7 * (L / 74.0) ** 2 / math.sqrt(n) * (1 + kl / 1e8)
            I_m4 = math.pi / 64 * (D**4 - (D - 2 * t) ** 4)
            rows.append(
                {
                    "load_case": load_case,
                    "model": model,
                    "u_c_m": 1e-3 * amp * fac * L / 74.0,
                    "u_s_m": F / k,
                    "u_d_m": 0.0 if model == "linear" else 1e-4 * amp * (n - 2),
                    "F_N": F,
                    "M_b_Nm": M,
                    "sigma_b_Pa": M * (D / 2) / I_m4,
                    "converged": True,
                    "contact_preserved": n <= 4,
                    "residual_norm": 1e-12 * n,
                    "iterations": 3 + n,
                    "warnings": fake_warnings(n, k, load_case, model),
                }
            )
    return rows


def failing_evaluate(case: Case) -> list[dict]:
    """Like :func:`fake_evaluate`, but a 5-saddle arrangement raises."""
    if case.seafastening.saddle_count == 5:
        raise RuntimeError("solver diverged for 5 saddles\n(second line)")
    rows = fake_evaluate(case)
    if case.seafastening.saddle_count == 6:
        for r in rows:
            if r["model"] == "nonlinear":
                r["converged"] = False
    return rows
