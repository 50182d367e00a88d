"""Hull-girder bending of the vessel in still water and on a regular wave (quasi-static).

The ship is a free-free Timoshenko beam loaded by ``q(x) = b(x) - w(x)`` [N/m] (buoyancy minus
weight, positive upward). Sections are wall-sided (see :class:`~seafast.vessel.hull_form.HullForm`),
so the buoyancy per metre is ``rho g C_s B(x) d(x)`` with the local draught

    d(x) = T + sinkage - trim (x - x_mid) + zeta(x)

where ``sinkage`` [m] is positive when the ship sinks deeper, ``trim`` [rad] is the ship's
pitch rotation, positive bow up (trim by the stern), ``x_mid = L/2`` and ``zeta`` the wave
elevation (zero in still water). Sinkage and trim are solved so that the buoyancy equals the
weight and LCB = LCG (the two conditions are linear in sinkage and trim while no section
emerges, so one Newton step is exact; emergence is handled by continuing Newton).

Sign conventions (seafast): x from the AP forward [m]; z up; deflection positive up;
slope = dz/dx; shear force ``V(x) = int_0^x q dx`` (net upward force on the part aft of x) [N];
bending moment ``M(x) = int_0^x V dx`` [N m], sagging positive, hogging negative, so that
``M'' = q`` and ``M = EI psi'``. Timoshenko kinematics: ``dz/dx = psi - V / (G A_s)`` so
``z'' = M / (E I) - q / (G A_s)``; the shear deflection of a free-free hull relative to the
chord through its ends is exactly ``-M(x) / (G A_s)``.

Definiteness (documented choice): a free-free beam under a self-equilibrated load has two
rigid-body modes. seafast fixes them by putting the deflection relative to the chord through
the hull's end points (AP and FP): ``z(AP) = z(FP) = 0``. In the FE model this is done by
constraining the two end deflection DOFs; because the load is self-equilibrated to round-off,
the constraint forces vanish and nothing else changes. Only differences along the deck matter
to the cargo; the rigid-body motion of the ship is handled separately (RAOs).

Discretisation: nodes at a uniform spacing plus every break point of the hull form and the
loading; within each element the load is linear between its end values (so discontinuities
of the weight at item ends are exact); shear force and bending moment are integrated exactly
for that load (so they vanish at both ends to round-off); the deflection comes from
``seafast.model.beam`` Timoshenko elements with consistent nodal loads of the linear element
load.

Modules (one concern each; this package exports the public names of the analyses):
:mod:`~seafast.hull.girder` (:class:`HullGirder`, the factorised Timoshenko beam, the exact
shear force and bending moment of an element load), :mod:`~seafast.hull.grid` (the node grid and
the weight on its elements), :mod:`~seafast.hull.balance` (sinkage and trim,
:class:`HydrostaticBalanceError`), :mod:`~seafast.hull.still_water` (the still-water response; the
deflection from a loading computer's moment table), :mod:`~seafast.hull.wave` (the quasi-static
regular-wave response, at any heading), :mod:`~seafast.hull.oblique` (a wave at a heading as the
sections see it: apparent length along the ship, breadth factor), :mod:`~seafast.hull.transfer`
(transfer functions per metre of wave), :mod:`~seafast.hull.torsion` (the wave-torsion estimate,
not connected to the cargo),
:mod:`~seafast.hull.loads` (deck-load influence and patch loads, for the two-way coupling),
:mod:`~seafast.hull.rules` (IACS UR S11 wave coefficient and moments) and
:mod:`~seafast.hull.deck` (sampling a response on deck, the deck rise).
"""

from seafast.hull.balance import HydrostaticBalanceError
from seafast.hull.deck import deck_deflection_at, deck_harmonics_at, deck_rise_m
from seafast.hull.girder import DEFAULT_SHEAR_AREA_M2, HullGirder
from seafast.hull.loads import HullLoadResponse, deck_load_influence, patch_load_response
from seafast.hull.rules import iacs_wave_bending_moments_Nm, iacs_wave_coefficient
from seafast.hull.still_water import HullGirderResponse, deflection_from_bending_moment, still_water_response
from seafast.hull.transfer import WaveTransferFunctions, wave_transfer_functions
from seafast.hull.wave import WaveHullResponse, wave_response

__all__ = [
    "DEFAULT_SHEAR_AREA_M2",
    "HullGirder",
    "HullGirderResponse",
    "HydrostaticBalanceError",
    "WaveHullResponse",
    "still_water_response",
    "deflection_from_bending_moment",
    "deck_load_influence",
    "HullLoadResponse",
    "patch_load_response",
    "wave_response",
    "WaveTransferFunctions",
    "wave_transfer_functions",
    "iacs_wave_bending_moments_Nm",
    "iacs_wave_coefficient",
    "deck_deflection_at",
    "deck_harmonics_at",
    "deck_rise_m",
]
