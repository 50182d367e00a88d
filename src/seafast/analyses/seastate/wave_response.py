"""Nonlinear periodic response of the cargo to one regular (or periodic) wave built from transfer functions.

The building block of the design-wave method (:mod:`seafast.analyses.seastate.design_wave`), the
conditioned wave (:mod:`seafast.analyses.seastate.conditioned_wave`) and the operability search
(:mod:`seafast.analyses.operability`): the excitation of a wave of any amplitude is the still-water part
plus the amplitude times the transfer functions of :mod:`seafast.analyses.seastate.transfer` (linear hull,
RAOs, inertia loads), and the compression-only saddles are solved by the condensed harmonic
balance (:func:`~seafast.solvers.hbm.condensed_operators`, :func:`~seafast.solvers.hbm.solve_condensed`).

Everything that does not depend on the amplitude is formed once per wave shape
(:func:`wave_operators`): the receptances of every harmonic, the linear (bilateral) solution at
unit amplitude, and the bending moment's influence lines. A solve at amplitude A
(:func:`solve_wave`) only scales the linear solution's dynamic harmonics and runs Newton, started
from a neighbouring amplitude's solution when one is given (warm start). The maxima are taken
over the period (:mod:`seafast.analyses.seastate.wave_maxima`): ``F_N`` the largest saddle contact force
(compression-only part), ``u_s_m`` the largest compression, ``u_d_m`` the largest gap, ``M_b_Nm``
and ``sigma_b_Pa`` the largest absolute bending moment and stress over the moment sample points of
the cargo (element ends and midpoints, as ``seafast run``), still water included; and, on request,
each at one location (:meth:`WaveSolution.maximum_at`). :func:`solve_wave_adaptive` is the converged
answer of one wave (exact-event shooting), what the fixed-H waves are measured against. Units SI;
compression positive when compressed; sagging moment positive.

Size: the wave's operators, its solution record and its two solves (fixed H, converged) share the moment
map and the maxima; cut apart they would pass the same half-dozen arrays back and forth.
"""

from __future__ import annotations

import weakref
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np
from numpy.typing import NDArray

from seafast.analyses.seastate.transfer import MOMENT_POINTS_PER_ELEMENT
from seafast.analyses.seastate.wave_maxima import location_maxima, location_maximum, period_maxima
from seafast.config.modes import ContactLawKind, Formulation
from seafast.excitation.harmonic import HarmonicExcitation
from seafast.fourier import complex_to_real_harmonics, real_dft_matrices, real_to_complex_harmonics, time_to_harmonics
from seafast.model.beam import bending_moment_line
from seafast.model.structure import StructuralModel
from seafast.solvers.contact import ContactLaw
from seafast.solvers.hbm import CondensedOperators, HBMOptions, condensed_operators, solve_condensed, solve_hbm
from seafast.solvers.hbm.options import samples_for
from seafast.solvers.shooting import solve_shooting

__all__ = [
    "MomentMap",
    "moment_map",
    "WaveOperators",
    "wave_operators",
    "WaveSolution",
    "solve_wave",
    "solve_wave_adaptive",
    "RESPONSE_QUANTITIES",
]

RESPONSE_QUANTITIES: tuple[str, ...] = ("F_N", "M_b_Nm", "sigma_b_Pa", "u_s_m", "u_d_m")
"""The maxima a wave solution reports (the quantity columns of seastate.csv)."""


@dataclass(frozen=True)
class MomentMap:
    """The bending moment at the cargo's moment sample points as a linear map.

    ``M = displacement_map @ q + load_map @ p`` for cargo DOFs q [m, rad] and element line loads
    p [N/m] (sagging positive), at the points of :attr:`x_m` (element ends and midpoints, ends
    shared by two elements twice), exactly :func:`~seafast.model.beam.bending_moment_line`.

    Attributes
    ----------
    x_m
        (n_x,) positions along the cargo from its aft end [m].
    displacement_map
        (n_x, n_c) [N m per m or rad].
    load_map
        (n_x, n_el) [N m per N/m].
    gravity_moment_Nm
        (n_x,) moment of the cargo's own weight line load alone [N m] (part of the still water).
    section_modulus_m3
        (n_x,) I / (D/2) [m^3]: stress = moment / modulus.
    """

    x_m: NDArray[np.float64]
    displacement_map: NDArray[np.float64]
    load_map: NDArray[np.float64]
    gravity_moment_Nm: NDArray[np.float64]
    section_modulus_m3: NDArray[np.float64]


_MOMENT_MAPS: dict[int, tuple[Any, MomentMap]] = {}  # id(model) -> (weak reference to it, its map)


def moment_map(model: StructuralModel) -> MomentMap:
    """The moment map of a model (built column by column from :func:`bending_moment_line`; kept per model object)."""
    held = _MOMENT_MAPS.get(id(model))
    if held is not None and held[0]() is model:
        return held[1]
    mm = _build_moment_map(model)
    if len(_MOMENT_MAPS) >= 8:
        _MOMENT_MAPS.pop(next(iter(_MOMENT_MAPS)))
    _MOMENT_MAPS[id(model)] = (weakref.ref(model), mm)
    return mm


def _build_moment_map(model: StructuralModel) -> MomentMap:
    beam = model.cargo
    n_c, n_el = model.cargo_dof_count, beam.element_count
    x_m, disp = bending_moment_line(
        beam.node_x_m, np.eye(n_c), beam.element_bending_stiffness_Nm2, None, np.zeros((n_c, n_el)), MOMENT_POINTS_PER_ELEMENT
    )
    _, load = bending_moment_line(
        beam.node_x_m, np.zeros((n_el, n_c)), beam.element_bending_stiffness_Nm2, None, np.eye(n_el), MOMENT_POINTS_PER_ELEMENT
    )
    modulus = np.repeat(beam.element_second_moment_m4 / (beam.element_outer_diameter_m / 2.0), MOMENT_POINTS_PER_ELEMENT + 1)
    load_map = np.ascontiguousarray(load.T)
    return MomentMap(
        x_m=np.asarray(x_m, dtype=float),
        displacement_map=np.ascontiguousarray(disp.T),
        load_map=load_map,
        gravity_moment_Nm=load_map @ beam.gravity_line_load_N_per_m,
        section_modulus_m3=modulus,
    )


@dataclass(frozen=True)
class WaveOperators:
    """What a wave shape's solves share, whatever the amplitude.

    Attributes
    ----------
    operators
        Condensed operators (receptances of harmonics 0 .. H, linear solution) at unit amplitude.
    unit_dynamic_compression_m
        Real-layout rows 1 .. 2H of the linear compression at unit amplitude, (2H, n_s) [m per m].
    moment_harmonics_Nm
        (H+1, n_x) complex linear moment: row 0 the still water, rows >= 1 per unit amplitude [N m].
    moment_influence_Nm_per_N
        (H+1, n_x, n_s) complex moment per unit upward saddle force harmonic [N m/N].
    section_modulus_m3
        (n_x,) [m^3].
    time_samples
        N, the AFT samples per period (the maxima are taken on them).
    """

    operators: CondensedOperators
    unit_dynamic_compression_m: NDArray[np.float64]
    moment_harmonics_Nm: NDArray[np.complex128]
    moment_influence_Nm_per_N: NDArray[np.complex128]
    section_modulus_m3: NDArray[np.float64]
    time_samples: int

    @property
    def omega_rad_s(self) -> float:
        """Fundamental frequency [rad/s]."""
        return float(self.operators.omega_rad_s)

    @property
    def harmonics(self) -> int:
        """H."""
        return int(self.operators.harmonics)

    def at_amplitude(self, amplitude: float) -> CondensedOperators:
        """The condensed operators of the wave at ``amplitude`` times the unit shape."""
        ops = self.operators
        lin = ops.linear_compression_m.copy()
        lin[1:] = amplitude * self.unit_dynamic_compression_m
        disp = ops.linear_cargo_displacement.copy()
        disp[1:] *= amplitude
        return replace(ops, linear_compression_m=lin, linear_cargo_displacement=disp)


def _real_map(A: NDArray[np.float64], B: NDArray[np.complex128]) -> NDArray[np.complex128]:
    """``A @ B`` for real A and complex B as two real BLAS products (numpy would promote A to complex)."""
    B = np.asarray(B)
    return A @ np.ascontiguousarray(B.real) + 1j * (A @ np.ascontiguousarray(B.imag))


def wave_operators(
    model: StructuralModel, excitation: HarmonicExcitation, options: HBMOptions, moments: MomentMap | None = None
) -> WaveOperators:
    """Operators of a wave shape: ``excitation`` holds the still water at k = 0 and unit amplitude above.

    ``options`` must fix the harmonics (``HBMOptions(harmonics=H)``); harmonics of the
    excitation above H are dropped (the design and conditioned waves choose H to hold them).
    """
    if options.harmonics is None:
        raise ValueError("wave_operators: options.harmonics must be set (a fixed H; the amplitude search reuses the operators)")
    fixed = options.with_harmonics(int(options.harmonics))
    H, N = fixed.fixed_grid()
    ops = condensed_operators(model, excitation, H)
    mm = moment_map(model) if moments is None else moments
    # the linear solution and the line loads live on the excitation's harmonics only
    n_k = min(excitation.harmonic_count, H + 1)
    moment = np.zeros((H + 1, mm.x_m.size), dtype=complex)
    moment[:n_k] = (
        _real_map(mm.displacement_map, ops.linear_cargo_displacement[:n_k].T)
        + _real_map(mm.load_map, excitation.cargo_line_load_N_per_m[:n_k].T)
    ).T
    moment[0] = moment[0].real + mm.gravity_moment_Nm
    Y = ops.cargo_influence  # (H+1, n_c, n_s)
    influence = _real_map(mm.displacement_map, Y.transpose(1, 0, 2).reshape(Y.shape[1], -1))
    influence = influence.reshape(-1, Y.shape[0], Y.shape[2]).transpose(1, 0, 2)  # (H+1, n_x, n_s)
    return WaveOperators(
        operators=ops,
        unit_dynamic_compression_m=ops.linear_compression_m[1:].copy(),
        moment_harmonics_Nm=moment,
        moment_influence_Nm_per_N=influence,
        section_modulus_m3=mm.section_modulus_m3,
        time_samples=N,
    )


@dataclass(frozen=True)
class WaveSolution:
    """The nonlinear periodic response to one wave and its maxima.

    Attributes
    ----------
    amplitude
        The amplitude factor the unit shape was scaled by (for a regular wave: its amplitude [m]).
    maxima
        ``F_N`` [N], ``M_b_Nm`` [N m], ``sigma_b_Pa`` [Pa], ``u_s_m`` [m], ``u_d_m`` [m]: maxima over the
        period, still water included (see the module docstring).
    linear_maxima
        The same of the linear (bilateral-saddle) model in the same wave (``u_d_m`` = 0), when asked for.
    linear_location_maxima
        With :attr:`linear_maxima`: the linear model's maximum of each quantity at each location,
        (n_s,) per saddle quantity and (n_x,) per moment quantity (:func:`~seafast.analyses.seastate.wave_maxima.location_maxima`).
    converged
        Whether the harmonic balance met its tolerance (never raised).
    residual_norm, iterations
        The solver's relative residual and Newton iterations.
    compression_harmonics_m
        Real-layout saddle-compression harmonics (2H+1, n_s) [m]: a warm start for a neighbouring
        amplitude, and the saddle maxima of :meth:`maximum_at`.
    lifted_off
        Whether some saddle detaches in this wave.
    harmonics
        H of the harmonic balance that gave it.
    moment_harmonics_Nm
        Real-layout bending-moment harmonics (2H+1, n_x) of the nonlinear response, still water included [N m].
    saddle_stiffness_N_per_m
        (n_s,) compression-only saddle stiffness [N/m].
    section_modulus_m3
        (n_x,) section modulus at the moment points [m^3].
    law
        The contact law of the solve.
    time_samples
        N of the solve (the maxima are located on its samples).
    """

    amplitude: float
    maxima: dict[str, float]
    linear_maxima: dict[str, float] | None
    converged: bool
    residual_norm: float
    iterations: int
    compression_harmonics_m: NDArray[np.float64]
    lifted_off: bool
    harmonics: int = -1
    linear_location_maxima: dict[str, NDArray[np.float64]] | None = None
    moment_harmonics_Nm: NDArray[np.float64] | None = None
    saddle_stiffness_N_per_m: NDArray[np.float64] | None = None
    section_modulus_m3: NDArray[np.float64] | None = None
    law: ContactLaw = field(default_factory=ContactLaw)
    time_samples: int = 0

    def maximum_at(self, quantity: str, location: int | NDArray[np.int64]) -> float:
        """The nonlinear maximum over the period of ``quantity`` at one location (or the largest over several), still water included.

        ``location``: the saddle index (``F_N`` [N], ``u_s_m`` [m], ``u_d_m`` [m]) or the index of
        the moment sample point (``M_b_Nm`` [N m], ``sigma_b_Pa`` [Pa]), or an array of them; read
        between the samples as :attr:`maxima` (:func:`~seafast.analyses.seastate.wave_maxima.location_maximum`).
        """
        if self.moment_harmonics_Nm is None or self.saddle_stiffness_N_per_m is None or self.section_modulus_m3 is None:
            raise ValueError("WaveSolution.maximum_at: this solution does not carry its harmonics")
        inverse, _ = real_dft_matrices(self.harmonics, self.time_samples)
        return location_maximum(
            quantity,
            location,
            self.compression_harmonics_m,
            self.moment_harmonics_Nm,
            inverse,
            self.saddle_stiffness_N_per_m,
            self.law,
            self.section_modulus_m3,
        )


def solve_wave(
    wave: WaveOperators, amplitude: float, options: HBMOptions, start: NDArray | None = None, *, linear: bool = False
) -> WaveSolution:
    """The nonlinear periodic response at ``amplitude`` times the wave's unit shape, and its maxima.

    Parameters
    ----------
    wave
        From :func:`wave_operators`.
    amplitude
        Scale of the dynamic part [-] (a regular wave of unit shape per metre: its amplitude in m).
    options
        Harmonic-balance settings (H and N are the wave's).
    start
        Real-layout compression harmonics (2H+1, n_s) of a neighbouring solution; if the solve
        from it fails, the solver's own start (quasi-static contact predictor) is tried.
    linear
        Also take the linear (bilateral-saddle) model's maxima in the same wave.

    Returns
    -------
    WaveSolution
        Non-convergence is reported in it, never raised.
    """
    H, N = wave.harmonics, wave.time_samples
    fixed = options.with_harmonics(H, N)
    ops = wave.at_amplitude(float(amplitude))
    sol = solve_condensed(ops, fixed, start)
    if start is not None and not sol.converged:
        sol = solve_condensed(ops, fixed, None)
    inverse, _ = real_dft_matrices(H, N)
    k_u = ops.saddle_stiffness_N_per_m
    scale = np.ones(H + 1)
    scale[1:] = amplitude
    moment_lin = wave.moment_harmonics_Nm * scale[:, None]
    C = real_to_complex_harmonics(sol.correction_force)  # (H+1, n_s) upward on the cargo [N]
    moment = complex_to_real_harmonics(moment_lin + (wave.moment_influence_Nm_per_N @ C[:, :, None])[:, :, 0])
    modulus = wave.section_modulus_m3
    linear_maxima, linear_locations = None, None
    if linear:
        moment_linear = complex_to_real_harmonics(moment_lin)
        linear_maxima = period_maxima(ops.linear_compression_m, moment_linear, inverse, k_u, fixed.law, modulus, False)
        linear_locations = location_maxima(ops.linear_compression_m, moment_linear, inverse, k_u, fixed.law, modulus, False)
    return WaveSolution(
        amplitude=float(amplitude),
        maxima=period_maxima(sol.saddle_compression, moment, inverse, k_u, fixed.law, modulus, True),
        linear_maxima=linear_maxima,
        converged=bool(sol.converged),
        residual_norm=float(sol.residual_norm),
        iterations=int(sol.iterations),
        compression_harmonics_m=sol.saddle_compression,
        lifted_off=bool(np.any(inverse @ sol.saddle_compression < 0.0)),
        harmonics=H,
        linear_location_maxima=linear_locations,
        moment_harmonics_Nm=moment,
        saddle_stiffness_N_per_m=np.asarray(k_u, dtype=float),
        section_modulus_m3=modulus,
        law=fixed.law,
        time_samples=N,
    )


CONVERGED_WAVE_HARMONICS = 128
"""Harmonics a converged wave solution carries (the base sea state's design-wave maxima within 1.2e-5 of those at 256)."""


def solve_wave_adaptive(
    model: StructuralModel, unit: HarmonicExcitation, amplitude: float, moments: MomentMap | None = None, options: HBMOptions | None = None
) -> WaveSolution:
    """The same as :func:`solve_wave`, converged: the package's default nonlinear solve.

    The harmonic balance's converged limit by exact-event shooting (:func:`~seafast.solvers.shooting.solve_shooting`)
    where the law is exact (its orbit's harmonics up to :data:`CONVERGED_WAVE_HARMONICS` kept), else (or if shooting
    cannot answer) the adaptive harmonic balance: the converged periodic answer the fixed-H design waves are
    measured against.
    """
    mm = moment_map(model) if moments is None else moments
    exc = HarmonicExcitation(
        unit.omega_rad_s,
        np.vstack([unit.deck_displacement[:1], amplitude * unit.deck_displacement[1:]]),
        np.vstack([unit.cargo_load_N[:1], amplitude * unit.cargo_load_N[1:]]),
        np.vstack([unit.cargo_line_load_N_per_m[:1], amplitude * unit.cargo_line_load_N_per_m[1:]]),
        unit.source,
    )
    opts = HBMOptions() if options is None else options
    r = solve_shooting(model, exc) if opts.law.name is ContactLawKind.EXACT and opts.formulation is Formulation.CONDENSED else None
    if r is not None and r.converged:
        H = min(CONVERGED_WAVE_HARMONICS, r.time_samples // 2 - 1)
        N = samples_for(H)
        X = np.asarray(r.cargo_displacement_harmonics)[: H + 1]
    else:
        r = solve_hbm(model, exc, opts)
        X = np.asarray(r.cargo_displacement_harmonics)
        H, N = X.shape[0] - 1, int(r.time_samples)
    line = np.zeros((H + 1, model.cargo.element_count), dtype=complex)
    m = min(exc.harmonic_count, H + 1)
    line[:m] = exc.cargo_line_load_N_per_m[:m]
    moment = _real_map(mm.displacement_map, X.T).T + _real_map(mm.load_map, line.T).T
    moment[0] = moment[0].real + mm.gravity_moment_Nm
    C = time_to_harmonics(r.saddle_compression_time_m, H)
    inverse, _ = real_dft_matrices(H, N)
    law = opts.law
    compression, moment_real = complex_to_real_harmonics(C), complex_to_real_harmonics(moment)
    k_u = np.asarray(model.saddle_unilateral_stiffness_N_per_m, dtype=float)
    return WaveSolution(
        amplitude=float(amplitude),
        maxima=period_maxima(compression, moment_real, inverse, k_u, law, mm.section_modulus_m3, True),
        linear_maxima=None,
        converged=bool(r.converged),
        residual_norm=float(r.residual_norm),
        iterations=int(r.iterations),
        compression_harmonics_m=compression,
        lifted_off=bool(np.any(r.saddle_compression_time_m < 0.0)),
        harmonics=H,
        moment_harmonics_Nm=moment_real,
        saddle_stiffness_N_per_m=k_u,
        section_modulus_m3=mm.section_modulus_m3,
        law=law,
        time_samples=N,
    )
