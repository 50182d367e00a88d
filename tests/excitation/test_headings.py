"""The six rigid-body motions at every heading: BEM over headings, the loaded ship, roll, accelerations (docs/headings.md)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import minimize_scalar
from scipy.spatial.transform import Rotation

from seafast.config import load_case
from seafast.config.arrangement import abreast_lanes_m
from seafast.excitation.cargo_acceleration import acceleration_transfer, point_displacement_matrix
from seafast.excitation.hydrodynamics import compute_motions, six_dof_dataset
from seafast.excitation.hydrodynamics.equations import (
    roll_hydrostatic_stiffness_Nm_per_rad,
    transverse_metacentric_height_m,
)
from seafast.excitation.hydrodynamics.load import load_six_dof_coefficients
from seafast.excitation.hydrodynamics.six_dof import (
    LoadedShip,
    capytaine_six_dof_coefficients,
    rigid_transfer_matrix,
    six_dof_motions,
)
from seafast.excitation.vessel_inputs import hull_form_of, six_dof_motions_of, vessel_loading_of
from seafast.vessel.hull_form import HullForm
from seafast.vessel.loading import LightshipDistribution, VesselLoading, WeightItem
from seafast.vessel.mass_properties import (
    BALLAST_VCG_FRACTION,
    LIGHTSHIP_ROLL_RADIUS_FRACTION,
    LIGHTSHIP_VCG_FRACTION,
    loaded_ship_properties,
)

RHO, G = 1025.0, 9.81
COARSE_M = 8.0
OMEGA = np.array([0.1, 0.15, 0.2, 0.3, 0.4, 0.5, 0.55, 0.6, 0.65, 0.7, 0.75, 0.8, 0.9, 1.0])
HEADINGS = (0.0, 30.0, 60.0, 90.0, 120.0, 150.0, 180.0)


@pytest.fixture(scope="module")
def hull() -> HullForm:
    return HullForm.tapered_box(171.0, 42.0, 6.5, 32000 / (171 * 42 * 6.5))


@pytest.fixture(scope="module")
def cache_dir(tmp_path_factory):
    return tmp_path_factory.mktemp("hydro6_cache")


@pytest.fixture(scope="module")
def coefficients(hull, cache_dir):
    ds = six_dof_dataset(hull, omega_rad_s=OMEGA, headings_deg=HEADINGS, panel_size_m=COARSE_M, cache_dir=cache_dir)
    return capytaine_six_dof_coefficients(ds, float(ds.attrs["seafast_origin_x_m"]), G)


def _ship(hull: HullForm, kg_m: float = 6.5, roll_damping_ratio: float = 0.0) -> LoadedShip:
    return LoadedShip(
        RHO * hull.displaced_volume_m3(),
        (hull.centre_of_buoyancy_x_m(), 0.0, kg_m),
        14.0,
        0.25 * hull.length_m,
        0.26 * hull.length_m,
        roll_damping_ratio,
    )


@pytest.fixture(scope="module")
def motions(hull, coefficients):
    return six_dof_motions(coefficients, hull, _ship(hull), water_density_kg_per_m3=RHO, gravity_m_per_s2=G)


# ------------------------------------------------------------------------------ the loaded ship
def test_gm_of_a_box_barge_is_kb_plus_bm_minus_kg():
    length, breadth, draft, kg = 60.0, 20.0, 4.0, 7.0
    box = HullForm(np.array([0.0, length]), np.array([breadth, breadth]), draft)
    gm = transverse_metacentric_height_m(box, kg)
    assert gm == pytest.approx(draft / 2 + breadth**2 / (12 * draft) - kg, rel=1e-9)
    c44 = roll_hydrostatic_stiffness_Nm_per_rad(box, mass_kg=RHO * length * breadth * draft, centre_of_gravity_m=(30.0, 0.0, kg))
    assert c44 == pytest.approx(RHO * G * length * breadth * draft * gm, rel=1e-9)


def test_loaded_ship_properties_by_hand():
    """A lightship, the cargo on two lanes and one ballast layer: KG and the radii of gyration by hand."""
    length, breadth, depth = 100.0, 30.0, 10.0
    ls = LightshipDistribution(3.0e6, 50.0, length, 0.75)
    cargo = WeightItem("cargo", 30.0, 70.0, 2.0e6)
    ballast = WeightItem("ballast", 20.0, 80.0, 5.0e6)
    loading = VesselLoading(ls, (cargo, ballast))
    lanes = abreast_lanes_m(2, breadth)
    np.testing.assert_allclose(lanes, [-7.5, 7.5])
    p = loaded_ship_properties(
        loading, length_m=length, breadth_m=breadth, depth_m=depth, cargo_vcg_m=15.0, lanes_y_m=lanes, cargo_radius_of_gyration_m=3.0
    )
    z_ls, z_b = LIGHTSHIP_VCG_FRACTION * depth, BALLAST_VCG_FRACTION * depth
    kg = (3e6 * z_ls + 2e6 * 15.0 + 5e6 * z_b) / 10e6
    assert p.mass_kg == pytest.approx(10e6) and p.kg_m == pytest.approx(kg, rel=1e-12)
    i_xx = (
        3e6 * ((z_ls - kg) ** 2 + (LIGHTSHIP_ROLL_RADIUS_FRACTION * breadth) ** 2)
        + 2e6 * ((15.0 - kg) ** 2 + 7.5**2 + 3.0**2)
        + 5e6 * ((z_b - kg) ** 2 + breadth**2 / 12 + (2 * z_b) ** 2 / 12)
    )
    assert p.roll_radius_m == pytest.approx(math.sqrt(i_xx / 10e6), rel=1e-12)
    assert p.yaw_radius_m**2 == pytest.approx(
        p.pitch_radius_m**2 + (3e6 * breadth**2 / 12 + 2e6 * 7.5**2 + 5e6 * breadth**2 / 12) / 10e6, rel=1e-9
    )
    with pytest.raises(ValueError, match="not symmetric"):
        loaded_ship_properties(
            loading, length_m=length, breadth_m=breadth, depth_m=depth, cargo_vcg_m=15.0, lanes_y_m=[5.0], cargo_radius_of_gyration_m=3.0
        )


def test_default_cargo_is_the_outermost_unit_to_port_and_stays_on_deck():
    case = load_case()
    assert case.wave.heading_deg == 180.0
    assert case.cargo_transverse_position_m() == pytest.approx(42.0 / 4 * 1.5)
    with pytest.raises(ValueError, match=r"cargo\.transverse_position_m"):
        load_case(overrides={"cargo.transverse_position_m": -17.5})


# ------------------------------------------------------------------------------ symmetry and limits
def test_lateral_motions_vanish_in_head_and_following_seas_and_mirror(motions):
    scale = np.max(np.abs(motions.raos))
    for beta in (0.0, 180.0):
        j = list(motions.headings_deg).index(beta)
        assert np.max(np.abs(motions.raos[:, j, [1, 3, 5]])) < 1e-9 * scale
        assert np.max(np.abs(motions.raos[:, j, [0, 2, 4]])) > 1e-3 * scale
    for beta in (30.0, 90.0, 120.0):
        a, b = motions.rao_at(0.6, beta), motions.rao_at(0.6, 360.0 - beta)
        np.testing.assert_allclose(b, a * np.array([1, -1, 1, -1, 1, -1]), rtol=1e-9, atol=1e-12 * scale)


def test_interpolation_between_headings_is_smooth(motions):
    """The periodic spline over 30 deg steps against the BEM's own heading: 45 deg is not computed, 60 is."""
    exact = motions.raos[list(motions.omega_rad_s).index(0.6), list(motions.headings_deg).index(60.0)]
    np.testing.assert_allclose(motions.rao_at(0.6, 60.0), exact, rtol=1e-9, atol=1e-12)
    mid = motions.rao_at(0.6, 45.0)
    assert np.all(np.isfinite(mid)) and abs(mid[3]) > 0


def test_beam_seas_long_waves_follow_the_wave():
    """omega -> 0 in beam seas: heave -> 1 m/m, sway -> -i (the orbit), roll -> the wave slope: |roll| / k -> 1, phase
    -90 deg (starboard up first). The production mesh (the default BEM, from the disk cache): the deviation of roll grows
    like omega^2 towards resonance, and its extrapolation to omega = 0 from the three lowest frequencies is 1 within 1 %
    (the 3 m panels' quadrature of the roll moment; 8 m panels are 3 % off)."""
    case = load_case(overrides={"wave.heading_deg": 90.0, "vessel.roll_damping_ratio": 0.0})
    hull = hull_form_of(case)
    m6 = six_dof_motions_of(case, hull, vessel_loading_of(case, hull)[0])
    w, k = m6.omega_rad_s[:3], m6.wavenumber_rad_per_m[:3]
    q = m6.rao_at(w, 90.0)
    ratio = np.abs(q[:, 3]) / k
    assert abs(q[0, 2] - 1) < 0.002 and abs(q[0, 1] + 1j) < 0.03
    assert np.all(np.diff(ratio) > 0)
    assert np.polyval(np.polyfit(w**2, ratio, 2), 0.0) == pytest.approx(1.0, abs=0.01)
    assert np.degrees(np.angle(q[0, 3])) == pytest.approx(-90.0, abs=1.0)
    # the ship follows the water: its apparent gravity is normal to the surface, no transverse reading at the CoG
    reading = acceleration_transfer(q[0], w[0], np.zeros((1, 3)), G)[0]
    assert abs(reading[1]) < 0.1 * G * k[0] and abs(reading[2] - w[0] ** 2 * -1) < 0.01 * w[0] ** 2


def test_roll_resonance_is_at_the_natural_period(motions, hull):
    """The beam-sea roll RAO peaks at 2 pi sqrt((I44 + A44) / (rho g V GM)) within 1 %."""
    ship = _ship(hull)
    gm = transverse_metacentric_height_m(hull, ship.centre_of_gravity_m[2])
    c44 = RHO * G * hull.displaced_volume_m3() * gm
    assert motions.hydrostatic_stiffness[3, 3] == pytest.approx(c44, rel=1e-9)
    wn = motions.roll_natural_frequency_rad_s
    a44 = np.interp(wn, motions.omega_rad_s, motions.added_mass[:, 3, 3])
    period = 2 * math.pi * math.sqrt((motions.mass_matrix[3, 3] + a44) / c44)
    assert motions.roll_natural_period_s == pytest.approx(period, rel=2e-3)  # cubic vs linear A44
    peak = minimize_scalar(lambda w: -abs(motions.rao_at(w, 90.0)[3]), bounds=(0.4, 0.9), method="bounded", options={"xatol": 1e-7}).x
    assert 2 * math.pi / peak == pytest.approx(period, rel=0.01)


def test_additional_roll_damping_is_the_fraction_of_critical(hull, coefficients, motions):
    damped = six_dof_motions(coefficients, hull, _ship(hull, roll_damping_ratio=0.05), water_density_kg_per_m3=RHO, gravity_m_per_s2=G)
    wn = damped.roll_natural_frequency_rad_s
    i44, c44 = damped.mass_matrix[3, 3], damped.hydrostatic_stiffness[3, 3]
    a44 = float(damped._roll_added_inertia(wn))
    assert wn**2 * (i44 + a44) == pytest.approx(c44, rel=1e-10)
    assert damped.additional_roll_damping_Nms_per_rad == pytest.approx(0.05 * 2 * math.sqrt((i44 + a44) * c44), rel=1e-12)
    # at resonance the extra damping lowers the roll; heave, pitch and surge in head seas are untouched
    assert abs(damped.rao_at(wn, 90.0)[3]) < 0.8 * abs(motions.rao_at(wn, 90.0)[3])
    np.testing.assert_allclose(damped.rao_at(0.6, 180.0)[[0, 2, 4]], motions.rao_at(0.6, 180.0)[[0, 2, 4]], rtol=1e-12)


def test_head_seas_of_the_six_dof_run_equal_the_coupled_surge_heave_pitch_run(hull, coefficients, tmp_path):
    """Another BEM run (three DOFs about the CoG height) and another path: the 6-DOF solution at 180 deg, with the same
    mass properties, is the coupled surge-heave-pitch one: the reference transfer, the signs and the phases agree."""
    ship = _ship(hull, kg_m=8.0)
    m6 = six_dof_motions(coefficients, hull, ship, water_density_kg_per_m3=RHO, gravity_m_per_s2=G)
    m3 = compute_motions(
        hull,
        mass_kg=ship.mass_kg,
        centre_of_gravity_m=ship.centre_of_gravity_m,
        pitch_radius_of_gyration_m=ship.pitch_radius_m,
        omega_rad_s=OMEGA,
        panel_size_m=COARSE_M,
        cache_dir=tmp_path,
    )
    j = list(m6.headings_deg).index(180.0)
    for i, ref in ((0, m3.surge_rao_m_per_m), (2, m3.coupled_heave_rao_m_per_m), (4, m3.coupled_pitch_rao_rad_per_m)):
        np.testing.assert_allclose(m6.raos[:, j, i], ref, rtol=1e-5, atol=1e-7 * np.max(np.abs(ref)))


# ------------------------------------------------------------------------------ against capytaine's own pipeline
@pytest.fixture(scope="module")
def box_reference():
    """A 40 x 12 x 3 m box barge meshed and solved by capytaine alone, with capytaine's hydrostatics, inertia and RAOs."""
    import capytaine as cpt

    length, breadth, draft = 40.0, 12.0, 3.0
    mesh = cpt.mesh_parallelepiped(
        size=(length, breadth, draft), center=(0.0, 0.0, -draft / 2), resolution=(12, 5, 2), missing_sides={"top"}, name="box"
    )
    body = cpt.FloatingBody(
        mesh=mesh,
        lid_mesh=mesh.generate_lid(),
        dofs=cpt.rigid_body_dofs(rotation_center=(0, 0, -draft / 2)),
        center_of_mass=(0, 0, -draft / 2),
        name="box",
    )
    body.inertia_matrix = body.compute_rigid_body_inertia(rho=RHO)
    body.hydrostatic_stiffness = body.compute_hydrostatic_stiffness(rho=RHO, g=G)
    omega = np.array([0.6, 0.8, 1.0, 1.1, 1.2, 1.4])
    test_matrix = __import__("xarray").Dataset(
        coords={
            "omega": omega,
            "wave_direction": np.radians([0.0, 60.0, 90.0, 180.0]),
            "radiating_dof": list(body.dofs),
            "water_depth": [np.inf],
            "rho": [RHO],
            "g": [G],
        }
    )
    ds = cpt.BEMSolver().fill_dataset(test_matrix, body, progress_bar=False)
    box = HullForm(np.array([0.0, length]), np.array([breadth, breadth]), draft)
    # the box's hydrostatics by hand about its CoG (KG = T/2, so GM = BM = B^2/(12 T)); capytaine's own integrate the
    # panels' centres (4 % low across 5 panels), seafast's the hull form exactly
    volume, rg = length * breadth * draft, RHO * G
    stiffness = 0.0 * body.hydrostatic_stiffness
    stiffness.values[2, 2] = rg * length * breadth
    stiffness.values[3, 3] = rg * volume * breadth**2 / (12 * draft)
    stiffness.values[4, 4] = rg * volume * length**2 / (12 * draft)
    ds["hydrostatic_stiffness"] = stiffness  # capytaine's rao adds its `stiffness` argument to this one
    return ds, box, body, stiffness


def test_box_barge_roll_rao_equals_capytaine_rao(box_reference):
    """seafast's conversion, hydrostatics, mass matrix and equation against capytaine's own: the same dataset, two pipelines."""
    import capytaine as cpt

    ds, box, body, stiffness = box_reference
    m = RHO * box.displaced_volume_m3()
    inertia = np.asarray(body.inertia_matrix.values)
    ship = LoadedShip(m, (20.0, 0.0, 1.5), *(math.sqrt(inertia[i, i] / m) for i in (3, 4, 5)), roll_damping_ratio=0.0)
    coefficients = capytaine_six_dof_coefficients(ds, 20.0, G)
    ours = six_dof_motions(coefficients, box, ship, water_density_kg_per_m3=RHO, gravity_m_per_s2=G)
    # (the pitch term integrates x^2 by the trapezoid rule on 4001 points: 1e-7)
    np.testing.assert_allclose(ours.hydrostatic_stiffness, stiffness.values, rtol=1e-6, atol=1e-9 * stiffness.values.max())
    for beta in (60.0, 90.0):
        theirs = cpt.post_pro.rao(ds, wave_direction=math.radians(beta)).transpose("omega", "radiating_dof")
        roll_ref = np.conj(theirs.sel(radiating_dof="Roll").values)  # exp(-i omega t) -> exp(+i omega t)
        heave_ref = np.conj(theirs.sel(radiating_dof="Heave").values)
        j = list(ours.headings_deg).index(beta)
        np.testing.assert_allclose(ours.raos[:, j, 3], roll_ref, rtol=1e-6, atol=1e-9)
        np.testing.assert_allclose(ours.raos[:, j, 2], heave_ref, rtol=1e-6, atol=1e-9)
    # capytaine with a dissipation matrix = seafast's additional roll damping
    damped = six_dof_motions(
        coefficients,
        box,
        LoadedShip(m, ship.centre_of_gravity_m, ship.roll_radius_m, ship.pitch_radius_m, ship.yaw_radius_m, 0.1),
        water_density_kg_per_m3=RHO,
        gravity_m_per_s2=G,
    )
    dissipation = 0.0 * body.hydrostatic_stiffness
    dissipation.values[3, 3] = damped.additional_roll_damping_Nms_per_rad
    theirs = cpt.post_pro.rao(ds, wave_direction=math.radians(90.0), dissipation=dissipation).transpose("omega", "radiating_dof")
    np.testing.assert_allclose(
        damped.raos[:, list(damped.headings_deg).index(90.0), 3], np.conj(theirs.sel(radiating_dof="Roll").values), rtol=1e-6
    )


def test_seafast_mesh_of_the_box_barge_gives_capytaine_roll(box_reference, tmp_path):
    """seafast's own panel mesh and BEM run of the same box: roll in beam seas within the two meshes' discretisation (5 %)."""
    import capytaine as cpt

    ds, box, body, _ = box_reference
    m = RHO * box.displaced_volume_m3()
    inertia = np.asarray(body.inertia_matrix.values)
    ship = LoadedShip(m, (20.0, 0.0, 1.5), *(math.sqrt(inertia[i, i] / m) for i in (3, 4, 5)), roll_damping_ratio=0.0)
    own = six_dof_dataset(box, omega_rad_s=ds["omega"].values, headings_deg=(0.0, 90.0, 180.0), panel_size_m=2.0, cache_dir=tmp_path)
    ours = six_dof_motions(capytaine_six_dof_coefficients(own, 20.0, G), box, ship, water_density_kg_per_m3=RHO, gravity_m_per_s2=G)
    theirs = np.conj(cpt.post_pro.rao(ds, wave_direction=math.pi / 2).transpose("omega", "radiating_dof").sel(radiating_dof="Roll").values)
    np.testing.assert_allclose(np.abs(ours.raos[:, list(ours.headings_deg).index(90.0), 3]), np.abs(theirs), rtol=0.05)


def test_capytaine_netcdf_over_headings_imports_the_same_coefficients(box_reference, tmp_path):
    import capytaine as cpt

    ds, box, _, _ = box_reference
    path = tmp_path / "box6.nc"
    cpt.export_dataset(path, ds)
    again = load_six_dof_coefficients(path, box, origin_x_m=20.0, gravity_m_per_s2=G)
    direct = capytaine_six_dof_coefficients(ds, 20.0, G)
    np.testing.assert_allclose(again.excitation_force, direct.excitation_force, rtol=1e-12)
    np.testing.assert_allclose(again.added_mass, direct.added_mass, rtol=1e-12)
    np.testing.assert_allclose(again.headings_deg, [0.0, 60.0, 90.0, 180.0, 270.0, 300.0])


def test_wamit_files_over_headings_import_the_same_coefficients(box_reference, tmp_path):
    """capytaine's box written as WAMIT .1/.3 (non-dimensional, exp(+i omega t), BETA in degrees) and read back."""
    ds, box, _, _ = box_reference
    direct = capytaine_six_dof_coefficients(ds, 20.0, G)
    ulen = 2.0
    lines1, lines3 = [], []
    for n, w in enumerate(direct.omega_rad_s):
        per = 2 * math.pi / w
        for i in range(6):
            for j in range(6):
                kexp = 3 + (i >= 3) + (j >= 3)
                s = RHO * ulen**kexp
                lines1.append(
                    f"{per:.12e} {i + 1} {j + 1} {direct.added_mass[n, i, j] / s:.15e} {direct.radiation_damping[n, i, j] / (s * w):.15e}"
                )
        for jb, beta in enumerate(direct.headings_deg):
            if beta > 180.0:
                continue
            for i in range(6):
                x = direct.excitation_force[n, jb, i] / (RHO * G * ulen ** (2 if i < 3 else 3))
                lines3.append(f"{per:.12e} {beta:.4f} {i + 1} {abs(x):.15e} {np.degrees(np.angle(x)):.10f} {x.real:.15e} {x.imag:.15e}")
    (tmp_path / "box.1").write_text("\n".join(lines1))
    (tmp_path / "box.3").write_text("\n".join(lines3))
    read = load_six_dof_coefficients(tmp_path / "box.1", box, origin_x_m=20.0, ulen_m=ulen, gravity_m_per_s2=G)
    np.testing.assert_allclose(read.omega_rad_s, direct.omega_rad_s, rtol=1e-11)
    np.testing.assert_allclose(read.added_mass, direct.added_mass, rtol=1e-9, atol=1e-9 * np.abs(direct.added_mass).max())
    np.testing.assert_allclose(read.excitation_force, direct.excitation_force, rtol=1e-9, atol=1e-9 * np.abs(direct.excitation_force).max())
    np.testing.assert_allclose(read.headings_deg, direct.headings_deg)


# ------------------------------------------------------------------------------ reference transfer, accelerations
def test_rigid_transfer_moves_a_point_displacement():
    """``q_old = P q_new``: the displacement of any point is the same whichever reference describes the motion."""
    rng = np.random.default_rng(3)
    r_old, r_new, p = rng.normal(size=3), rng.normal(size=3), rng.normal(size=3)
    q_new = rng.normal(size=6)
    q_old = rigid_transfer_matrix(r_old - r_new) @ q_new
    np.testing.assert_allclose(q_old[:3] + np.cross(q_old[3:], p - r_old), q_new[:3] + np.cross(q_new[3:], p - r_new), rtol=1e-12)


def test_accelerations_against_finite_rotations():
    """The accelerometer reading of a point from the exact rigid-body kinematics (rotation matrices, a numerical second
    derivative, gravity rotated into the ship frame), linearised by a small amplitude, against the transfer function."""
    rng = np.random.default_rng(7)
    q = rng.normal(size=6) + 1j * rng.normal(size=6)  # (surge, sway, heave, roll, pitch bow up, yaw)
    r = np.array([[12.0, 15.75, 10.5], [-30.0, -5.0, 2.0]])
    omega, eps, g = 0.7, 1e-6, 9.81
    expected = acceleration_transfer(q, omega, r, g)
    t = np.linspace(0.0, 2 * math.pi / omega, 64, endpoint=False)
    dt = 1e-3

    def state(time):
        x = (eps * q * np.exp(1j * omega * time)).real
        rot = Rotation.from_rotvec([x[3], -x[4], x[5]])  # right-handed: pitch bow up is -eta5
        return x[:3], rot

    reading = np.empty((t.size, r.shape[0], 3))
    for n, tn in enumerate(t):
        pos = [state(tn + k * dt)[0] + state(tn + k * dt)[1].apply(r) for k in (-1, 0, 1)]
        acc_earth = (pos[0] - 2 * pos[1] + pos[2]) / dt**2
        rot = state(tn)[1]
        reading[n] = rot.inv().apply(acc_earth) - rot.inv().apply([0.0, 0.0, -g]) - np.array([0.0, 0.0, g])
    first = 2 * np.fft.fft(reading, axis=0)[1] / t.size / eps  # the exp(+i omega t) amplitude
    np.testing.assert_allclose(first, expected, rtol=2e-4, atol=2e-4 * np.abs(expected).max())


def test_point_displacement_matrix_signs():
    """Roll (starboard down) lifts a point to port, pitch (bow up) lifts a point forward and moves a high point aft."""
    t = point_displacement_matrix([[10.0, 5.0, 3.0]])[0]
    assert t[2, 3] == 5.0 and t[2, 4] == 10.0 and t[0, 4] == -3.0 and t[1, 3] == -3.0 and t[1, 5] == 10.0 and t[0, 5] == -5.0


def test_transfer_functions_refuse_a_heading_outside_the_circle():
    from seafast.analyses.seastate.transfer import transfer_functions
    from seafast.model.from_case import build_model

    case = load_case()
    for bad in (360.0, -1.0, float("nan")):
        with pytest.raises(ValueError, match=r"heading_deg = .*allowed: \[0, 360\)"):
            transfer_functions(case, build_model(case), np.array([0.5, 0.6]), heading_deg=bad)


# ------------------------------------------------------------------------------ the vessel excitation and results.nc
def test_vessel_excitation_off_head_seas_folds_roll_into_the_deck_and_reports_accelerations():
    from seafast.excitation.vessel import vessel_excitation

    case = load_case(overrides={"wave.heading_deg": 120.0})
    v = vessel_excitation(case)
    assert v.motions is None and v.motions6 is not None and v.motion_amplitudes is not None
    y, amplitude = case.cargo_transverse_position_m(), case.wave.amplitude_m
    q = v.motions6.rao_at(case.wave_frequency_rad_s(), 120.0) * amplitude
    np.testing.assert_allclose(v.motion_amplitudes, q, rtol=1e-12)
    assert v.rigid_body.heave_m == pytest.approx(q[2] + q[3] * y, rel=1e-12)
    assert v.rigid_body.surge_m == pytest.approx(q[0] - q[5] * y, rel=1e-12)
    ds = v.to_dataset()
    assert ds.sizes["heading_deg"] == 24 and ds.sizes["cargo_point"] == 3
    for name in [f"{d}_rao6_{p}" for d in ("surge", "sway", "heave", "roll", "pitch", "yaw") for p in ("real", "imag")] + [
        "cargo_acceleration_rao_real",
        "cargo_acceleration_amplitude",
    ]:
        assert ds[name].attrs["units"] and ds[name].attrs["long_name"], name
    assert ds["roll_rao6_real"].attrs["units"] == "rad/m" and ds["sway_rao6_imag"].attrs["units"] == "m/m"
    rel = v.cargo_points.relative_to(v.motions6.reference_x_m, v.motions6.reference_z_m)
    np.testing.assert_allclose(ds["cargo_acceleration_real"].values, acceleration_transfer(q, case.wave_frequency_rad_s(), rel, G).real)


def test_head_seas_report_the_heave_pitch_model_on_one_heading():
    from seafast.excitation.vessel import vessel_excitation

    v = vessel_excitation(load_case())
    ds = v.to_dataset()
    assert v.motions6 is None and list(ds["heading_deg"].values) == [180.0]
    np.testing.assert_array_equal(ds["heave_rao6_real"].values[:, 0], ds["heave_rao_real"].values)
    assert np.all(ds["roll_rao6_real"].values == 0) and np.all(ds["sway_rao6_imag"].values == 0)
    assert v.rigid_body.heave_m == v.motion_amplitudes[2] and ds["cargo_acceleration_amplitude"].values[:, 1].max() == 0.0


def test_rao_figure_off_head_seas_shows_heave_roll_and_pitch_at_the_heading(tmp_path):
    import matplotlib

    matplotlib.use("Agg")
    from seafast.excitation.vessel import vessel_excitation
    from seafast.output.plots import plot_raos

    ds = vessel_excitation(load_case(overrides={"wave.heading_deg": 90.0})).to_dataset()
    ds.attrs["wave_frequency_rad_s"] = 0.6
    assert "heave_rao_real" not in ds and plot_raos(ds, tmp_path / "raos.png").is_file()


def test_report_rao_figure_off_head_seas():
    from seafast.excitation.vessel import vessel_excitation
    from seafast.output.report.vessel_figures import rao_figure

    ds = vessel_excitation(load_case(overrides={"wave.heading_deg": 90.0})).to_dataset()
    ds.attrs["wave_frequency_rad_s"] = 0.6
    fig = rao_figure(ds)
    assert fig is not None and {"roll amplitude (starboard down +)", "heave phase"} <= {a.text for a in fig.layout.annotations}


def test_a_wave_outside_the_bem_grid_is_refused_off_head_seas():
    from seafast.excitation.vessel import vessel_excitation

    with pytest.raises(ValueError, match=r"wave\.length_m = 3000"):
        vessel_excitation(load_case(overrides={"wave.heading_deg": 90.0, "wave.length_m": 3000.0, "wave.amplitude_m": 1.0}))


def test_quadratic_roll_damping_is_linearised_on_the_coupled_motions(motions):
    """In a regular beam sea at roll resonance the harmonic equivalent of ``B44_2 |phi'| phi'`` is consistent with the
    six-DOF roll it gives (``B_eq = 8 / (3 pi) omega phi_a B44_2``), lowers the roll, and vanishes with ``B44_2``."""
    from seafast.excitation.hydrodynamics.roll_damping import QuadraticRollDamping

    wn, amplitude = motions.roll_natural_frequency_rad_s, 1.5
    linear = motions.rao_at(wn, 90.0)
    same, none = motions.rao_in_regular_wave(wn, 90.0, amplitude, QuadraticRollDamping(0.0))
    assert none is None and np.array_equal(same, linear)
    b2 = 0.05 * motions.mass_matrix[3, 3]  # a beta of 0.05 1/rad (ITTC's non-dimensional quadratic coefficient)
    rao, response = motions.rao_in_regular_wave(wn, 90.0, amplitude, QuadraticRollDamping(b2))
    assert response is not None and bool(response.converged[0])
    roll_amplitude = abs(rao[3]) * amplitude
    b_eq = float(response.equivalent_damping_Nms_per_rad[0])
    assert b_eq == pytest.approx(8.0 / (3.0 * math.pi) * wn * roll_amplitude * b2, rel=1e-8)
    assert roll_amplitude < 0.9 * abs(linear[3]) * amplitude
    # the other motions follow the damped roll through the coupling; heave hardly depends on roll damping
    assert abs(rao[2]) == pytest.approx(abs(linear[2]), rel=0.05)
