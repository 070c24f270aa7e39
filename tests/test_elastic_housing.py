"""The built-in rod housing: compliance properties, correction, clamp independence,
inertia superposition, export → import, distributed vs two-mass rod load."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from conrod.housing.compliance_io import write_compliance
from conrod.housing.correction import correction_projector
from conrod.housing.housing import Housing
from conrod.housing.inertia import rigid_rod_load_difference
from elastic_helpers import kamaz_case


@pytest.fixture(scope="module")
def housing() -> Housing:
    return Housing.from_case(kamaz_case(n_theta=72), use_cache=False)


def cosine_forces(housing: Housing, direction: float, load: float = 1.0e4) -> np.ndarray:
    """Nodal forces of a load ``load`` [N] spread as cos(θ − direction) over ±90° [N]."""
    relative = np.cos(housing.angles - direction)
    shape = np.where(relative > 0, relative, 0.0)
    return load * shape / np.sum(shape * relative)


def test_compliance_is_symmetric_and_positive_definite(housing):
    compliance = housing.compliance
    assert np.abs(compliance - compliance.T).max() <= 1e-12 * np.abs(compliance).max()
    assert np.linalg.eigvalsh(compliance).min() > 0.0


@pytest.mark.parametrize("method", ["least_squares_circle", "centroid"])
def test_correction_removes_a_rigid_translation_exactly(method):
    angles = 2 * np.pi * np.arange(72) / 72
    projector = correction_projector(angles, method)
    translation = 3e-6 * np.cos(angles) - 7e-6 * np.sin(angles)
    shape = 1e-6 * np.cos(2 * angles) + 0.5e-6 * np.sin(3 * angles) + 2e-6
    assert np.abs(projector @ translation).max() < 1e-12 * 7e-6
    np.testing.assert_allclose(projector @ (translation + shape), shape, atol=1e-18)


def test_corrected_deformation_does_not_depend_on_the_clamp(housing):
    """Small-end clamp vs a clamp across mid-shank: corrected bore deformation under loads
    in four directions changes by < 2 % of its range (raw changes far more)."""
    mid = Housing.from_case(kamaz_case({"clamp": "mid_shank"}, n_theta=72), use_cache=False)
    for direction in np.radians([0.0, 90.0, 180.0, 270.0]):
        forces = cosine_forces(housing, direction)
        small_end = housing.pressure_deformation(forces)
        mid_shank = mid.pressure_deformation(forces)
        scale = np.ptp(small_end)
        assert np.abs(mid_shank - small_end).max() < 0.02 * scale
        raw_change = np.abs(mid.pressure_deformation(forces, corrected=False)
                            - housing.pressure_deformation(forces, corrected=False)).max()
        assert raw_change > 0.02 * scale


def test_superposition_equals_a_direct_body_force_solve(housing):
    structure = housing.structure
    rng = np.random.default_rng(5)
    for crank_angle in rng.uniform(0.0, 4 * np.pi, 4):
        load = structure.model.body_load(housing.kinematics.body_force(crank_angle))
        direct = structure.film_displacement(structure.model.solve(load))
        superposed = housing.inertia_deformation(crank_angle, corrected=False)
        assert np.abs(superposed - direct).max() <= 1e-10 * np.abs(direct).max()


def test_export_then_import_reproduces_the_deformation(housing, tmp_path):
    path = write_compliance(tmp_path / "compliance.npz", housing.angles, housing.compliance,
                            housing.inertia_base)
    inertia = tmp_path / "inertia.npz"
    np.savez(inertia, angle_deg=np.degrees(housing.angles), inertia_base_m=housing.inertia_base)
    imported = Housing.from_case(kamaz_case({"model": "compliance", "compliance_file": str(path),
                                             "inertia_file": str(inertia)}, n_theta=72))
    forces = np.random.default_rng(2).uniform(0, 1e3, 72)
    for crank_angle in (0.3, 2.5):
        expected = housing.deformation(forces, crank_angle)
        got = imported.deformation(forces, crank_angle)
        assert np.abs(got - expected).max() <= 1e-14 * np.abs(expected).max()


def test_imported_matrix_is_interpolated_to_the_film_grid(housing, tmp_path):
    """A matrix on the 72 film angles imported into a 144-node film (C = L C₇₂ Lᵀ): symmetric,
    and the deformation of a smooth load agrees with the 72-node one at the common nodes
    within 3 % of its range (measured 2.3 %: linear interpolation of a 5° matrix)."""
    path = write_compliance(tmp_path / "c.npz", housing.angles, housing.compliance)
    fine = Housing.from_case(kamaz_case({"model": "compliance", "compliance_file": str(path)},
                                        n_theta=144))
    assert np.array_equal(fine.compliance, fine.compliance.T)
    coarse_forces = cosine_forces(housing, 0.4)
    fine_forces = cosine_forces(fine, 0.4)
    coarse = housing.pressure_deformation(coarse_forces)
    interpolated = fine.pressure_deformation(fine_forces)[::2]
    assert np.abs(interpolated - coarse).max() < 0.03 * np.ptp(coarse)


def test_fe_mass_of_the_rod_and_load_models(housing):
    """Mass properties of the FE rod; the distributed-mass load equals the two-mass load
    when J_G = m L1 L2 (the two-mass rod's own inertia), and differs otherwise."""
    case = kamaz_case(n_theta=72)
    props = housing.structure.model.mass_properties()
    assert 0.3 < props["mass"] < 10.0 and 0.0 < props["x"] < case.engine.rod_length
    equivalent = dict(props, inertia=props["mass"] * props["x"]
                      * (case.engine.rod_length - props["x"]))
    same = rigid_rod_load_difference(case, equivalent)
    assert same["max_load_difference_N"] < 1e-6 * 1e5
    different = rigid_rod_load_difference(case, props)
    assert different["max_load_difference_N"] > 1.0


def test_nodal_forces_carry_the_film_force_to_the_housing(housing):
    """Reynolds film at ε = 0.6: the resultant of the nodal forces on the housing equals
    minus the film force on the journal (the film model's own integration) within 1 %."""
    from conrod.film.base import BearingGeometry, FilmState
    from conrod.film.reynolds.film import ReynoldsFilm

    geometry = BearingGeometry(diameter=2 * housing.radius, width=0.03,
                               radial_clearance=5.0e-5)
    film = ReynoldsFilm(geometry, n_theta=72, n_z=16)
    state = FilmState(eccentricity_x=0.6 * 5e-5 * np.cos(0.4),
                      eccentricity_y=0.6 * 5e-5 * np.sin(0.4), journal_speed=300.0,
                      viscosity=0.01)
    result = film.solve(state, with_pressure=True)
    theta, z = film.grid()
    forces = housing.nodal_forces(result.pressure, z, theta)
    resultant = np.array([np.sum(forces * np.cos(housing.angles)),
                          np.sum(forces * np.sin(housing.angles))])
    journal = np.array([result.force_x, result.force_y])
    assert np.hypot(*(resultant + journal)) < 0.01 * np.hypot(*journal)


@settings(max_examples=30, deadline=None)
@given(st.integers(8, 60), st.floats(0.0, 0.45), st.integers(0, 2**31),
       st.sampled_from(["least_squares_circle", "centroid"]),
       st.floats(-1e-5, 1e-5), st.floats(-1e-5, 1e-5))
def test_correction_on_any_node_set(n_nodes, jitter, seed, method, a, b):
    """On jittered (non-uniform) node sets the projector is idempotent and removes a rigid
    translation."""
    shift = np.random.default_rng(seed).uniform(-jitter, jitter, n_nodes)
    angles = 2 * np.pi * (np.arange(n_nodes) + shift) / n_nodes
    angles = np.sort(np.mod(angles, 2 * np.pi))
    projector = correction_projector(angles, method)
    translation = a * np.cos(angles) + b * np.sin(angles)
    assert np.abs(projector @ translation).max() <= 1e-9 * max(abs(a), abs(b), 1e-30)
    np.testing.assert_allclose(projector @ projector, projector, atol=1e-9)


def test_film_field_is_the_bore_deformation_at_every_axial_node(housing):
    delta = housing.deformation(cosine_forces(housing, 0.0), 0.5)
    field = housing.film_field(delta, 17)
    assert field.shape == (len(housing.angles), 17)
    np.testing.assert_array_equal(field[:, 8], delta)


def test_compliance_cache_round_trip_and_key(tmp_path):
    case = kamaz_case(n_theta=24)
    first = Housing.from_case(case, cache_dir=tmp_path)
    second = Housing.from_case(case, cache_dir=tmp_path)
    assert not first.info["from_cache"] and second.info["from_cache"]
    np.testing.assert_array_equal(first.compliance, second.compliance)
    np.testing.assert_array_equal(first.inertia_base, second.inertia_base)
    other = Housing.from_case(kamaz_case({"cap_thickness": 0.012}, n_theta=24),
                              cache_dir=tmp_path)
    assert not other.info["from_cache"]
    assert len(list(tmp_path.glob("*.npz"))) == 2
