"""Rigid-body heave and pitch of the vessel in head seas (docs/theory.md#36-rigid-body-motions).

Linear potential flow (radiation + diffraction) with capytaine, hydrostatic stiffness from the
hull form, and the 2-DOF equation of motion in heave and pitch, giving response amplitude
operators (RAOs) per metre of wave amplitude. Results are cached on disk; coefficients can also
be imported from a capytaine NetCDF file or from WAMIT ``.1``/``.3`` output.

Conventions (seafast; other modules rely on them)
-------------------------------------------------
* Time dependence ``x(t) = Re(X exp(+i omega t))``.
* Coordinates: ``x`` from the aft perpendicular (AP), forward positive; ``z`` up. The vertical
  position of the centre of gravity is given **above the keel (baseline)**; internally
  (capytaine's frame) heights are relative to the design waterline, ``z_wl = z_keel - T``.
* Regular head-sea wave: ``zeta(x, t) = zeta_a cos(omega t + k (x - x_mid))``,
  ``x_mid = L/2`` (crest at midship at ``t = 0``; the wave travels towards ``-x``, from bow to
  stern; capytaine's ``wave_direction = pi``). The complex wave elevation per unit amplitude is
  ``exp(i k (x - x_mid))``, so the phases of all RAOs refer to the wave crest at midship.
* Heave ``w`` positive up, at ``x = reference_x_m`` (the CoG x). Pitch ``theta = dz/dx``, positive
  **bow up**. The rigid-body vertical displacement at ``x`` is ``w + theta (x - reference_x_m)``.
* DOF order everywhere: (heave, pitch). Generalised force conjugate to ``theta`` is the moment
  ``sum f_z (x - reference_x_m)`` (bow-up positive). Units of the 2x2 matrices: ``[[kg, kg m],
  [kg m, kg m^2]]`` (added mass), same per second (damping), ``[N/m, N]`` (stiffness row 1,
  column by column: N/m, N/rad; N, N m/rad); excitation ``[N/m, N m/m]`` per metre of wave
  amplitude.

Mapping from capytaine (and WAMIT) conventions: both use a rotation about ``+y`` (``eta_5``),
which with ``x`` forward is bow *down*, so ``theta = -eta_5``. Capytaine uses
``exp(-i omega t)``: its complex amplitudes are complex-conjugated. WAMIT already uses
``exp(+i omega t)``.

Long-wave limit (checked in the tests): the ship follows the wave, the vertical displacement at
``x_mid`` tends to ``1`` m/m with zero phase and ``theta/zeta_a`` tends to the wave slope ``i k``
(magnitude ``k`` rad/m, phase +90 deg).

Surge (for the cargo's axial analysis, docs/axial.md): ``x`` displacement of the pitch reference
point (the CoG: ``x = reference_x_m`` at ``reference_z_m`` above the keel), positive forward. When
the hydrodynamic data hold surge (capytaine's ``Surge`` dof, WAMIT mode 1), surge, heave and pitch
are also solved as one coupled 3-DOF system (head seas couple surge and pitch through added mass,
damping and excitation; DOF order (surge, heave, pitch) in the 3-DOF helpers): ``surge_rao_m_per_m``,
``coupled_heave_rao_m_per_m``, ``coupled_pitch_rao_rad_per_m``. The heave-pitch fields stay the
2-DOF solution of the heave-pitch coefficients (the source's model, unchanged bit for bit). Without
surge in the data the surge and coupled fields are ``None`` (never silently zero). A point at height
``z`` above the keel moves forward by ``surge - theta (z - z_ref)``.

Modules (one concern each; this package re-exports their public names):
:mod:`~seafast.excitation.hydrodynamics.motions` (:class:`RigidBodyMotions`, the result record),
:mod:`~seafast.excitation.hydrodynamics.equations` (dispersion relation, hydrostatic stiffness,
mass matrix, the rigid-body equation of motion, the base vessel's mass properties),
:mod:`~seafast.excitation.hydrodynamics.coefficients` (hydrodynamic coefficients in capytaine's
or WAMIT's DOFs to seafast motions: sign of pitch, wave phase, reference point, coupled surge),
:mod:`~seafast.excitation.hydrodynamics.capytaine_io` (reading capytaine datasets),
:mod:`~seafast.excitation.hydrodynamics.wamit` (WAMIT ``.1``/``.3`` readers),
:mod:`~seafast.excitation.hydrodynamics.bem` (the capytaine run and its disk cache:
:func:`compute_motions`), :mod:`~seafast.excitation.hydrodynamics.memory_cache`
(:class:`HydrodynamicsCache`: the datasets and coefficients a sequence of loadings shares),
:mod:`~seafast.excitation.hydrodynamics.load` (:func:`load_motions`, importing a file) and
:mod:`~seafast.excitation.hydrodynamics.strip_theory` (the independent strip-theory estimate).
"""

from seafast.excitation.hydrodynamics.bem import (
    BEM_DOFS,
    BEM_HEADINGS_DEG,
    MESH_ALGORITHM_VERSION,
    SIX_DOFS,
    compute_motions,
    default_cache_dir,
    six_dof_dataset,
)
from seafast.excitation.hydrodynamics.equations import (
    base_vessel_mass_properties,
    hydrostatic_stiffness_matrix,
    mass_matrix,
    solve_heave_pitch,
    solve_rigid_body,
    wavenumber_rad_per_m,
)
from seafast.excitation.hydrodynamics.heading_motions import SixDofMotions
from seafast.excitation.hydrodynamics.load import load_motions
from seafast.excitation.hydrodynamics.memory_cache import HydrodynamicsCache
from seafast.excitation.hydrodynamics.motions import RigidBodyMotions
from seafast.excitation.hydrodynamics.strip_theory import strip_theory_estimate
from seafast.excitation.hydrodynamics.wamit import read_wamit_1, read_wamit_3

__all__ = [
    "RigidBodyMotions",
    "HydrodynamicsCache",
    "base_vessel_mass_properties",
    "compute_motions",
    "load_motions",
    "read_wamit_1",
    "read_wamit_3",
    "hydrostatic_stiffness_matrix",
    "mass_matrix",
    "solve_heave_pitch",
    "solve_rigid_body",
    "BEM_DOFS",
    "strip_theory_estimate",
    "wavenumber_rad_per_m",
    "default_cache_dir",
    "MESH_ALGORITHM_VERSION",
    "SIX_DOFS",
    "BEM_HEADINGS_DEG",
    "SixDofMotions",
    "six_dof_dataset",
]
