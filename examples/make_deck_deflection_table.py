"""Regenerate ``deck_deflection.csv``: the base case's computed hull deflection as a user table.

The table stands in for what a user would export from their own hull-girder analysis (loading
computer, FE model): still-water deflection and the first harmonic (amplitude, phase) of the
wave-induced deflection for the base case's wave (lambda = 171 m, zeta_a = 3 m), at 1.5 m
stations from the aft perpendicular (0) to the forward perpendicular (171 m).

Run from the repository root:  python examples/make_deck_deflection_table.py
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from seafast.config import load_case
from seafast.excitation.vessel import vessel_excitation

HERE = Path(__file__).resolve().parent


def main() -> Path:
    case = load_case(None, {"vessel.motions": "none"})
    vessel = vessel_excitation(case)
    sw, wave = vessel.still_water, vessel.wave
    x = np.linspace(0.0, case.vessel.length_m, 115)  # 1.5 m stations
    still = np.interp(x, sw.x_m, sw.deflection_m)
    w1 = wave.deflection_harmonics_m[1]  # complex first harmonic: w = Re(W1 exp(i omega t))
    w1_x = np.interp(x, wave.x_m, w1.real) + 1j * np.interp(x, wave.x_m, w1.imag)
    lines = [
        "# seafast example deck-deflection table (docs/interface.md#31-deck-deflection-table format). GENERATED, not measured:",
        "# the base case's own computed hull-girder deflection (default loading, tapered-box hull, Timoshenko beam),",
        "# still water + first harmonic of the quasi-static wave deflection for lambda = 171 m, zeta_a = 3 m,",
        "# written by examples/make_deck_deflection_table.py. x from the aft perpendicular; deflection up positive [m];",
        "# wave deflection = wave_amplitude_m * cos(omega t + wave_phase_rad), t = 0 at period fraction 0.",
        "x_m,still_water_m,wave_amplitude_m,wave_phase_rad",
    ]
    for xi, s, c in zip(x, still, w1_x, strict=True):
        lines.append(f"{xi:.2f},{s:.6e},{abs(c):.6e},{np.angle(c):.6f}")
    path = HERE / "deck_deflection.csv"
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


if __name__ == "__main__":
    print(f"wrote {main()}")
