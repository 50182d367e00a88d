"""Outputs of ``seafast sweep``: the frequency-response branch as CSV and a figure."""

from __future__ import annotations

import csv
from pathlib import Path
from typing import Any

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

__all__ = ["write_sweep_outputs"]

COLUMNS = ("omega_rad_s", "max_saddle_force_N", "max_gap_m", "max_cargo_deflection_m", "converged", "contact_preserved")


def write_sweep_outputs(branch: Any, model: Any, out_dir: str | Path) -> list[Path]:
    """Write ``frequency_response.csv`` and ``frequency_response.png``; return their paths."""
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    csv_path = out / "frequency_response.csv"
    with csv_path.open("w", newline="") as f:
        w = csv.writer(f)
        w.writerow(COLUMNS)
        for row in zip(*(getattr(branch, c) for c in COLUMNS)):
            w.writerow([("true" if v else "false") if isinstance(v, (bool, np.bool_)) else repr(float(v)) for v in row])
    omega = branch.omega_rad_s
    fig, axes = plt.subplots(3, 1, figsize=(8, 8), sharex=True)
    lost = ~np.asarray(branch.contact_preserved)
    for ax, values, label in (
        (axes[0], branch.max_saddle_force_N / 1e6, "max saddle force [MN]"),
        (axes[1], branch.max_gap_m * 1e3, "max detachment gap [mm]"),
        (axes[2], branch.max_cargo_deflection_m * 1e3, "max cargo deflection [mm]"),
    ):
        ax.plot(omega, values, "k-", lw=1.2)
        ax.plot(omega[lost], values[lost], "r.", ms=3, label="contact lost somewhere in the period")
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    for w in model.natural_frequencies_rad_s(True, 3):
        if omega.min() <= w <= omega.max():
            for ax in axes:
                ax.axvline(w, color="tab:blue", ls=":", lw=1)
    axes[0].legend(fontsize=8)
    axes[0].set_title("Nonlinear frequency response (arclength continuation)\ndotted: linear natural frequencies on bilateral saddles", fontsize=10)
    axes[-1].set_xlabel("excitation frequency [rad/s]")
    fig.tight_layout()
    png = out / "frequency_response.png"
    fig.savefig(png, dpi=200)
    plt.close(fig)
    return [csv_path, png]
