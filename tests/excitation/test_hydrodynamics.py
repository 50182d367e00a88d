"""Tests of the rigid-body heave/pitch module (capytaine BEM, importers, conventions)."""

from __future__ import annotations

import math

import numpy as np
import pytest
import xarray as xr

from seafast.excitation.hydrodynamics import (
    HydrodynamicsCache,
    RigidBodyMotions,
    base_vessel_mass_properties,
    bem,
    capytaine_io,
    compute_motions,
    default_cache_dir,
    equations,
    hydrostatic_stiffness_matrix,
    load_motions,
    read_wamit_1,
    read_wamit_3,
    strip_theory_estimate,
)
from seafast.vessel.hull_form import HullForm
from seafast.vessel.hull_mesh import hull_mesh_arrays, mesh_hull

RHO, G = 1025.0, 9.81
COARSE_M = 8.0
OMEGA = np.array([0.15, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 1.0, 1.3])


@pytest.fixture(scope="module")
def hull() -> HullForm:
    return HullForm.tapered_box(171.0, 42.0, 6.5, 32000 / (171 * 42 * 6.5))


@pytest.fixture(scope="module")
def mass_props(hull):
    return base_vessel_mass_properties(hull)


@pytest.fixture(scope="module")
def cache_dir(tmp_path_factory):
    return tmp_path_factory.mktemp("hydro_cache")


@pytest.fixture(scope="module")
def coarse(hull, mass_props, cache_dir) -> RigidBodyMotions:
    return compute_motions(hull, **mass_props, omega_rad_s=OMEGA, panel_size_m=COARSE_M, cache_dir=cache_dir)


# ------------------------------------------------------------------------------ mesh
def test_mesh_hydrostatics_match_hull_form(hull, mass_props):
    import capytaine as cpt

    hm = hull_mesh_arrays(hull, COARSE_M)
    mesh, lid = mesh_hull(hull, COARSE_M)
    assert isinstance(mesh, cpt.ReflectionSymmetricMesh) and isinstance(lid, cpt.ReflectionSymmetricMesh)
    assert 100 < hm.nb_hull_panels_full < 400
    x_g, _, z_g = mass_props["centre_of_gravity_m"]
    rc = (x_g - hull.length_m / 2, 0.0, z_g - hull.draft_m)
    body = cpt.FloatingBody(
        mesh=mesh,
        lid_mesh=lid,
        dofs=cpt.rigid_body_dofs(only=["Heave", "Pitch"], rotation_center=rc),
        mass=mass_props["mass_kg"],
        center_of_mass=rc,
    )
    # outward normals -> positive displaced volume equal to the hull form's
    assert body.disp_volume == pytest.approx(hull.displaced_volume_m3(), rel=1e-6)
    assert body.waterplane_area == pytest.approx(np.trapezoid(hull.breadth_at(hull.station_x_m), hull.station_x_m), rel=1e-9)
    assert body.center_of_buoyancy[0] + hull.length_m / 2 == pytest.approx(hull.centre_of_buoyancy_x_m(), abs=0.05)
    # lid at the waterline, normals down
    assert np.allclose(body.lid_mesh.faces_centers[:, 2], 0.0) and np.all(body.lid_mesh.faces_normals[:, 2] < 0)
    c_cpt = body.compute_hydrostatic_stiffness(rho=RHO, g=G).values
    c = hydrostatic_stiffness_matrix(hull, **{k: mass_props[k] for k in ("mass_kg", "centre_of_gravity_m")})
    assert c_cpt[0, 0] == pytest.approx(c[0, 0], rel=1e-6)
    # capytaine's pitch (bow down) stiffness equals seafast's theta stiffness (sign^2)
    assert c_cpt[1, 1] == pytest.approx(c[1, 1], rel=5e-3)
    assert abs(c[0, 1]) < 1e-6 * math.sqrt(c[0, 0] * c[1, 1]) * hull.length_m  # LCF = LCB for a wall-sided hull


def test_chine_sections_keep_volume():
    h = HullForm(np.array([0.0, 50.0, 100.0]), np.array([20.0, 20.0, 10.0]), 5.0, section_area_coefficient=0.85)
    import capytaine as cpt

    mesh, _ = mesh_hull(h, 4.0)
    body = cpt.FloatingBody(mesh=mesh)
    assert body.disp_volume == pytest.approx(h.displaced_volume_m3(), rel=1e-3)
    assert body.center_of_buoyancy[2] == pytest.approx(equations._section_centroid_below_wl(h), rel=1e-2)


# ------------------------------------------------------------------------------ conventions
def test_long_wave_limit_conventions(coarse, hull):
    w = 0.15
    k = w**2 / G
    x_mid = hull.length_m / 2
    v_mid = coarse.vertical_displacement_rao(x_mid, w)
    assert abs(v_mid) == pytest.approx(1.0, abs=0.02)
    assert abs(np.degrees(np.angle(v_mid))) < 2.0
    _, pitch = coarse.rao_at(w)
    assert abs(pitch) == pytest.approx(k, rel=0.05)  # wave slope
    assert np.degrees(np.angle(pitch)) == pytest.approx(90.0, abs=5.0)  # theta = i k zeta (bow up first)
    assert coarse.reference_x_m == pytest.approx(hull.centre_of_buoyancy_x_m())
    assert coarse.wave_phase_reference_x_m == pytest.approx(x_mid)


def test_surge_long_wave_limit_and_coupling(coarse, hull):
    """Surge: in long waves the ship follows the orbital motion (|X| -> 1 m/m, phase +90 deg for a
    wave travelling towards -x); the surge-pitch coupling changes pitch by a few per cent at most."""
    assert coarse.has_surge and coarse.reference_z_m == pytest.approx(8.0)
    u = coarse.surge_at(0.15)
    assert abs(u) == pytest.approx(1.0, abs=0.03)
    assert np.degrees(np.angle(u)) == pytest.approx(90.0, abs=5.0)
    # heave and pitch stay the 2-DOF solution of their coefficients (the source's model) ...
    f2 = coarse.excitation_force
    z2 = (
        -(OMEGA[:, None, None] ** 2) * (coarse.mass_matrix + coarse.added_mass)
        + 1j * OMEGA[:, None, None] * coarse.radiation_damping
        + coarse.hydrostatic_stiffness
    )
    x2 = np.linalg.solve(z2, f2[..., None])[..., 0]
    np.testing.assert_allclose(x2[:, 0], coarse.heave_rao_m_per_m, rtol=1e-12)
    np.testing.assert_allclose(x2[:, 1], coarse.pitch_rao_rad_per_m, rtol=1e-12)
    # ... and the coupled solution differs from it through the surge coupling only, by a few per cent
    assert np.max(np.abs(coarse.coupled_heave_rao_m_per_m - coarse.heave_rao_m_per_m)) < 0.02
    rel = np.abs(np.abs(coarse.coupled_pitch_rao_rad_per_m) / np.abs(coarse.pitch_rao_rad_per_m) - 1.0)
    assert np.max(rel[OMEGA <= 0.8]) < 0.06
    assert np.max(rel[OMEGA <= 0.8]) > 1e-4  # the coupling is real, not dropped
    assert abs(coarse.coupled_at(0.15)[2]) == pytest.approx(0.15**2 / G, rel=0.05)  # coupled pitch -> wave slope too
    with pytest.raises(ValueError, match="no surge"):
        RigidBodyMotions(
            OMEGA,
            coarse.heave_rao_m_per_m,
            coarse.pitch_rao_rad_per_m,
            coarse.added_mass,
            coarse.radiation_damping,
            coarse.excitation_force,
            coarse.reference_x_m,
        ).surge_at(0.6)


def test_capytaine_file_without_surge_has_no_surge(hull, mass_props, cache_dir, coarse, tmp_path):
    """Imported heave/pitch-only data: no surge (None, never zero), heave and pitch by the 2-DOF solve."""
    import capytaine as cpt

    files = sorted(cache_dir.glob("motions_*.nc"))
    ds = capytaine_io.read_capytaine_netcdf(files[0])
    two = ds.sel(influenced_dof=["Heave", "Pitch"], radiating_dof=["Heave", "Pitch"])
    path = tmp_path / "heave_pitch.nc"
    cpt.export_dataset(path, two)
    m = load_motions(path, hull, **mass_props)
    assert not m.has_surge and m.surge_rao_m_per_m is None
    assert "surge_rao_real" not in m.to_dataset()
    # heave and pitch are the same 2-DOF solution, bit for bit (surge problems do not change them)
    np.testing.assert_array_equal(m.heave_rao_m_per_m, coarse.heave_rao_m_per_m)
    np.testing.assert_array_equal(m.pitch_rao_rad_per_m, coarse.pitch_rao_rad_per_m)
    assert m.coupled_pitch_rao_rad_per_m is None
    with pytest.raises(ValueError, match="no surge"):
        m.coupled_at(0.6)


def test_strip_theory_agrees_at_low_frequency(coarse, hull, mass_props):
    s = strip_theory_estimate(hull, **mass_props, omega_rad_s=OMEGA)
    low = OMEGA <= 0.5
    np.testing.assert_allclose(np.abs(coarse.heave_rao_m_per_m[low]), np.abs(s.heave_rao_m_per_m[low]), rtol=0.20)
    np.testing.assert_allclose(np.abs(coarse.pitch_rao_rad_per_m[low]), np.abs(s.pitch_rao_rad_per_m[low]), rtol=0.20)
    # hydrostatic long-wave limit of the excitation: rho g A_wp
    assert abs(coarse.excitation_force[0, 0]) == pytest.approx(coarse.hydrostatic_stiffness[0, 0], rel=0.15)


def test_added_mass_physical(coarse, mass_props):
    a33 = coarse.added_mass[:, 0, 0]
    assert np.all(a33 > 0) and np.all(coarse.radiation_damping[:, 0, 0] > 0)
    assert np.all(coarse.radiation_damping[:, 1, 1] > 0)
    assert 1.0 < a33[OMEGA == 0.6][0] / mass_props["mass_kg"] < 3.5


# ------------------------------------------------------------------------------ cache
def test_cache_avoids_second_bem_run(hull, mass_props, cache_dir, coarse, monkeypatch):
    def boom(*a, **k):
        raise AssertionError("BEM must not run on a cache hit")

    monkeypatch.setattr(bem, "_run_bem", boom)
    again = compute_motions(hull, **mass_props, omega_rad_s=OMEGA, panel_size_m=COARSE_M, cache_dir=cache_dir)
    np.testing.assert_array_equal(again.heave_rao_m_per_m, coarse.heave_rao_m_per_m)
    np.testing.assert_array_equal(again.excitation_force, coarse.excitation_force)
    with pytest.raises(AssertionError, match="BEM must not run"):  # other inputs -> other key
        compute_motions(hull, **mass_props, omega_rad_s=OMEGA, panel_size_m=COARSE_M, water_density_kg_per_m3=1000.0, cache_dir=cache_dir)


def test_a_memory_cache_reads_the_bem_file_and_extracts_its_coefficients_once(hull, mass_props, cache_dir, coarse):
    """A cargo study changes mass and CoG at every point: with a memory cache the BEM dataset is read and its
    coefficients extracted once for both loadings; the motions equal those without it (to the bit) and an
    import of the cache file (the loading matters)."""
    memory = HydrodynamicsCache()
    mp2 = dict(mass_props, mass_kg=1.1 * mass_props["mass_kg"], centre_of_gravity_m=(mass_props["centre_of_gravity_m"][0] - 3.0, 0.0, 8.0))
    first = compute_motions(hull, **mass_props, omega_rad_s=OMEGA, panel_size_m=COARSE_M, cache_dir=cache_dir, memory_cache=memory)
    second = compute_motions(hull, **mp2, omega_rad_s=OMEGA, panel_size_m=COARSE_M, cache_dir=cache_dir, memory_cache=memory)
    assert len(memory.datasets) == 1 and len(memory.coefficients) == 1
    (path,) = sorted(cache_dir.glob("motions_*.nc"))
    (held,) = memory.datasets.values()
    assert memory.dataset(path) is held and len(memory.datasets) == 1
    np.testing.assert_array_equal(first.heave_rao_m_per_m, coarse.heave_rao_m_per_m)
    np.testing.assert_array_equal(first.pitch_rao_rad_per_m, coarse.pitch_rao_rad_per_m)
    imported = load_motions(path, hull, **mp2)
    np.testing.assert_allclose(second.heave_rao_m_per_m, imported.heave_rao_m_per_m, rtol=1e-12)
    np.testing.assert_allclose(second.pitch_rao_rad_per_m, imported.pitch_rao_rad_per_m, rtol=1e-12)
    assert not np.allclose(second.pitch_rao_rad_per_m, coarse.pitch_rao_rad_per_m, rtol=1e-3)  # the loading matters
    with pytest.raises(ValueError, match="max_entries = 0"):
        HydrodynamicsCache(max_entries=0)


def test_cache_dir_from_environment(monkeypatch, tmp_path):
    monkeypatch.setenv("SEAFAST_CACHE_DIR", str(tmp_path))
    assert default_cache_dir() == tmp_path


# ------------------------------------------------------------------------------ importers
def test_load_capytaine_netcdf_and_reference_shift(hull, mass_props, cache_dir, coarse):
    files = sorted(cache_dir.glob("motions_*.nc"))
    assert files
    loaded = load_motions(files[0], hull, **mass_props)
    np.testing.assert_allclose(loaded.heave_rao_m_per_m, coarse.heave_rao_m_per_m, rtol=1e-10)
    # different CoG x: transfer of the coefficients vs a fresh BEM run about the new point
    mp2 = dict(mass_props, centre_of_gravity_m=(mass_props["centre_of_gravity_m"][0] + 6.0, 0.0, 8.0))
    shifted = load_motions(files[0], hull, **mp2)
    fresh = compute_motions(hull, **mp2, omega_rad_s=OMEGA, panel_size_m=COARSE_M, use_cache=False)
    assert shifted.reference_x_m == fresh.reference_x_m
    np.testing.assert_allclose(shifted.heave_rao_m_per_m, fresh.heave_rao_m_per_m, rtol=1e-3, atol=1e-5)
    np.testing.assert_allclose(shifted.pitch_rao_rad_per_m, fresh.pitch_rao_rad_per_m, rtol=1e-3, atol=1e-7)
    np.testing.assert_allclose(shifted.surge_rao_m_per_m, fresh.surge_rao_m_per_m, rtol=1e-3, atol=1e-5)


def _write_wamit(stem, omega, a, b, x, ulen, rho, g, heading=180.0):
    """Tiny WAMIT .1/.3 writer (modes 3, 5), independent of the parser under test."""
    idx = {3: 0, 5: 1}
    with open(f"{stem}.1", "w") as f:
        f.write(f"{-1.0:14.6e} 3 3 {1.234:14.6e}\n")  # zero-frequency line: must be skipped
        for n in np.argsort(2 * np.pi / omega):
            per = 2 * np.pi / omega[n]
            for i in (1, 3, 5):
                for j in (1, 3, 5):
                    if i == 1 or j == 1:
                        f.write(f"{per:14.7e} {i:5d} {j:5d} {9.9:14.7e} {9.9:14.7e}\n")
                        continue
                    kexp = 3 + (i > 3) + (j > 3)
                    s = rho * ulen**kexp
                    f.write(f"{per:14.7e} {i:5d} {j:5d} {a[n, idx[i], idx[j]] / s:14.7e} {b[n, idx[i], idx[j]] / (s * omega[n]):14.7e}\n")
    with open(f"{stem}.3", "w") as f:
        for n in np.argsort(2 * np.pi / omega):
            per = 2 * np.pi / omega[n]
            for beta in (90.0, heading):
                for i in (3, 5):
                    m = 2 if i <= 3 else 3
                    xv = x[n, idx[i]] / (rho * g * ulen**m) * (1.0 if beta == heading else 7.0)
                    f.write(
                        f"{per:14.7e} {beta:10.4f} {i:5d} {abs(xv):14.7e} {np.degrees(np.angle(xv)):10.4f} "
                        f"{xv.real:14.7e} {xv.imag:14.7e}\n"
                    )


def test_wamit_parser_round_trip(tmp_path):
    rng = np.random.default_rng(1)
    omega = np.array([0.3, 0.6, 0.9])
    a = rng.uniform(1e6, 1e8, (3, 2, 2)) * np.array([[1, 1e2], [1e2, 1e4]])
    b = rng.uniform(1e5, 1e7, (3, 2, 2)) * np.array([[1, 1e2], [1e2, 1e4]])
    x = (rng.normal(size=(3, 2)) + 1j * rng.normal(size=(3, 2))) * np.array([1e7, 1e9])
    ulen, rho, g = 10.0, 1025.0, 9.80665
    _write_wamit(tmp_path / "ship", omega, a, b, x, ulen, rho, g)
    w1, a1, b1 = read_wamit_1(tmp_path / "ship.1", ulen_m=ulen, water_density_kg_per_m3=rho)
    w3, x3 = read_wamit_3(tmp_path / "ship.3", ulen_m=ulen, water_density_kg_per_m3=rho, gravity_m_per_s2=g)
    np.testing.assert_allclose(w1, omega, rtol=1e-6)
    np.testing.assert_allclose(w3, omega, rtol=1e-6)
    np.testing.assert_allclose(a1, a, rtol=1e-6)
    np.testing.assert_allclose(b1, b, rtol=1e-6)
    np.testing.assert_allclose(x3, x, rtol=1e-5)
    with pytest.raises(ValueError, match="heading"):
        read_wamit_3(tmp_path / "ship.3", ulen_m=ulen, water_density_kg_per_m3=rho, gravity_m_per_s2=g, heading_deg=0.0)


def test_wamit_import_matches_capytaine(hull, mass_props, tmp_path):
    """capytaine's own WAMIT export of a BEM run about the origin reads back to the same RAOs."""
    import capytaine as cpt
    from capytaine.io.wamit import export_to_wamit

    omega = np.array([0.3, 0.5, 0.6, 0.8])
    ds = bem._run_bem(hull, omega, np.array([0.0, 0.0, 0.0]), COARSE_M, RHO, G, math.inf)
    nc = tmp_path / "bem.nc"
    cpt.export_dataset(nc, ds)
    ref = load_motions(nc, hull, **mass_props)
    # capytaine 3.0's .1 writer puts the radiating dof first ("I J" = motion, force), the
    # transpose of WAMIT's A_ij (force i due to motion j); the BEM matrices are not exactly
    # symmetric, so hand it the transposed matrices to obtain a WAMIT-conventional file.
    swapped = ds.copy()
    for v in ("added_mass", "radiation_damping"):
        da = ds[v].rename(influenced_dof="_tmp").rename(radiating_dof="influenced_dof").rename(_tmp="radiating_dof")
        swapped[v] = da.transpose(*ds[v].dims)
    export_to_wamit(swapped, str(tmp_path / "bem"), exports=("1", "3"))
    wam = load_motions(tmp_path / "bem", hull, **mass_props, ulen_m=1.0)
    np.testing.assert_allclose(wam.omega_rad_s, ref.omega_rad_s, rtol=1e-6)
    np.testing.assert_allclose(wam.heave_rao_m_per_m, ref.heave_rao_m_per_m, rtol=1e-3, atol=1e-5)
    np.testing.assert_allclose(wam.pitch_rao_rad_per_m, ref.pitch_rao_rad_per_m, rtol=1e-3, atol=1e-7)
    # mode 1 (surge) is read and solved with heave and pitch, as the capytaine file's Surge dof
    assert ref.has_surge and wam.has_surge
    np.testing.assert_allclose(wam.surge_rao_m_per_m, ref.surge_rao_m_per_m, rtol=1e-3, atol=1e-5)


# ------------------------------------------------------------------------------ container
def test_rao_at_and_dataset(coarse, tmp_path):
    h, p = coarse.rao_at(0.6)
    i = int(np.flatnonzero(OMEGA == 0.6)[0])
    assert h == coarse.heave_rao_m_per_m[i] and p == coarse.pitch_rao_rad_per_m[i]
    hh, _ = coarse.rao_at([0.45, 0.55])
    assert hh.shape == (2,)
    assert hh[0] == pytest.approx(0.5 * (coarse.heave_rao_m_per_m[3] + coarse.heave_rao_m_per_m[4]))
    with pytest.raises(ValueError, match=r"omega = 2\.5.*\[0\.15, 1\.3\]"):
        coarse.rao_at(2.5)
    ds = coarse.to_dataset()
    assert ds["heave_rao_real"].attrs["units"] == "m/m" and "long_name" in ds["pitch_rao_imag"].attrs
    path = tmp_path / "motions.nc"
    ds.to_netcdf(path)
    with xr.open_dataset(path) as back:
        np.testing.assert_allclose(back["pitch_rao_real"] + 1j * back["pitch_rao_imag"], coarse.pitch_rao_rad_per_m)
    with pytest.raises(ValueError, match="read-only"):
        coarse.heave_rao_m_per_m[0] = 0.0  # read-only arrays in a frozen dataclass


# ------------------------------------------------------------------------------ production mesh
@pytest.mark.slow
def test_production_mesh_base_hull(hull, mass_props, tmp_path):
    omega = np.linspace(0.2, 2.0, 19)
    omega = np.unique(np.round(np.append(omega, 0.6), 10))
    m = compute_motions(hull, **mass_props, omega_rad_s=omega, panel_size_m=3.0, cache_dir=tmp_path)
    h, p = m.rao_at(0.6)
    # independent estimate for a similar tapered box (C_b 0.685): heave ~0.22 m/m at 0.6 rad/s
    assert abs(h) == pytest.approx(0.22, rel=0.25)
    # pitch at lambda = L is very sensitive to the breadth distribution (taper lengths); the
    # quoted ~0.74 deg/m of the similar hull is not reproduced (this hull: ~1.1 deg/m), so the
    # check is against this hull's strip-theory estimate instead
    s = strip_theory_estimate(hull, **mass_props, omega_rad_s=[0.6])
    assert abs(p) == pytest.approx(abs(s.pitch_rao_rad_per_m[0]), rel=0.15)
    assert 0.5 < np.degrees(abs(p)) < 1.5
    # lid removes the irregular frequency (~1.3 rad/s): damping stays smooth and positive
    b33 = m.radiation_damping[:, 0, 0]
    assert np.all(b33 > 0)


def test_the_bem_cache_reads_back_as_capytaine_merges_it_without_importing_capytaine(hull, mass_props, cache_dir, coarse):
    """The complex values of a cache file merged as ``capytaine.io.xarray.merge_complex_values`` merges them."""
    import subprocess
    import sys

    from capytaine.io.xarray import merge_complex_values

    path = next(cache_dir.glob("motions_*.nc"))
    with xr.open_dataset(path) as opened:
        raw = opened.load()
    ours = capytaine_io.merge_complex_values(raw)
    assert "complex" in raw.coords and "complex" not in ours.coords
    assert ours.identical(merge_complex_values(raw))
    assert any(v.dtype.kind == "c" for v in ours.data_vars.values())
    probe = (
        "import sys; from seafast.excitation.hydrodynamics.capytaine_io import read_capytaine_netcdf; "
        f"read_capytaine_netcdf({str(path)!r}); print('capytaine' in sys.modules)"
    )
    done = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True, timeout=300)
    assert done.stdout.strip() == "False"
