"""The excitation seen by the cargo model: prescribed deck motion and cargo loads, per harmonic.

Harmonic convention (all of seafast): ``x(t) = Re(sum_k X_k exp(i k omega t))`` with k = 0 the
static (mean) part, which is real. Period fraction ``s = t / T``; t = 0 is the start of the
period.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

__all__ = ["HarmonicExcitation"]


@dataclass(frozen=True)
class HarmonicExcitation:
    """Prescribed deck DOFs and vessel-induced cargo loads, harmonics k = 0 .. n_k - 1.

    Parameters
    ----------
    omega_rad_s
        Fundamental (wave encounter) frequency [rad/s].
    deck_displacement
        Complex amplitudes of the deck DOFs (z [m], theta [rad] under each saddle, in the
        model's deck-DOF order), shape (n_k, n_deck_dofs). Row 0: still-water (static) part.
    cargo_load_N
        Complex amplitudes of vessel-induced nodal loads on the cargo DOFs [N, N m] (e.g. the
        rigid-body inertia load -M a_rb), shape (n_k, n_cargo_dofs). The cargo's own weight and
        the lashing pretension are *not* included: they belong to the structural model.
    cargo_line_load_N_per_m
        The same loads as per-element distributed loads [N/m] (used only to draw the
        bending-moment line inside elements), shape (n_k, n_elements).
    source
        Human-readable provenance, carried into results (e.g. "deck table 'hull.csv'").
    """

    omega_rad_s: float
    deck_displacement: NDArray[np.complex128]
    cargo_load_N: NDArray[np.complex128]
    cargo_line_load_N_per_m: NDArray[np.complex128]
    source: str = ""

    @property
    def harmonic_count(self) -> int:
        """Number of harmonics including k = 0."""
        return int(self.deck_displacement.shape[0])

    def static_part(self) -> HarmonicExcitation:
        """Only the k = 0 (still-water) part: the static load case."""
        return HarmonicExcitation(
            self.omega_rad_s,
            self.deck_displacement[:1],
            self.cargo_load_N[:1],
            self.cargo_line_load_N_per_m[:1],
            self.source,
        )

    def padded(self, harmonic_count: int) -> HarmonicExcitation:
        """The same excitation with zero rows appended (or truncated) to ``harmonic_count`` rows."""

        def fit(a: NDArray) -> NDArray:
            out = np.zeros((harmonic_count,) + a.shape[1:], dtype=complex)
            n = min(harmonic_count, a.shape[0])
            out[:n] = a[:n]
            return out

        return HarmonicExcitation(
            self.omega_rad_s, fit(self.deck_displacement), fit(self.cargo_load_N), fit(self.cargo_line_load_N_per_m), self.source
        )

    def at_frequency(self, omega_rad_s: float) -> HarmonicExcitation:
        """The same deck-motion amplitudes and rigid-body displacement amplitudes at another frequency.

        The vessel-induced cargo loads are rigid-body inertia (proportional to the square of
        each harmonic's frequency), so they scale with ``(omega / self.omega)^2``; the deck
        deflection amplitudes are kept. This is the structural frequency response to the
        case's excitation *shape*, used to sweep through the cargo's resonances.
        """
        scale = (omega_rad_s / self.omega_rad_s) ** 2 if self.omega_rad_s > 0 else 0.0
        return HarmonicExcitation(
            float(omega_rad_s),
            self.deck_displacement,
            np.concatenate([self.cargo_load_N[:1], scale * self.cargo_load_N[1:]]),
            np.concatenate([self.cargo_line_load_N_per_m[:1], scale * self.cargo_line_load_N_per_m[1:]]),
            self.source + f" (shape swept to {omega_rad_s:.4g} rad/s)",
        )
