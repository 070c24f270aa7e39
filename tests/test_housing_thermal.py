"""The warm bore: a free ring under a uniform temperature rise grows by α ΔT R, the built-in
rod's bore alike, the clearance change, the warm clearance in the run's geometry, and the
reference temperature reproducing today bit for bit."""

from __future__ import annotations

import numpy as np
import pytest

from conrod.errors import CaseError
from conrod.housing.build import _cache_payload
from conrod.housing.cache import cache_key
from conrod.housing.fe import ClampedModel, Material, vector_basis
from conrod.housing.housing import Housing
from conrod.housing.mesher import Circle, FeMesh, annulus_mesh, quadratic_mesh
from conrod.housing.structure import StructuralHousing
from conrod.housing.thermal import unit_strain_bore
from conrod.simulation.simulation import Simulation
from elastic_helpers import kamaz_case

WARM = {"journal_temperature": 120.0, "housing_temperature": 100.0}
ALPHA = 11.5e-6


def free_ring(inner: float, outer: float) -> StructuralHousing:
    """A thick ring held only against rigid motion: u_y at (R_o, 0) and (−R_o, 0), u_x at
    (0, R_o) — which a uniform expansion leaves at zero."""
    points, triangles = annulus_mesh(inner, outer, 72, 6)
    mesh, groups = quadratic_mesh(points, triangles, {"big_end_bore": Circle(0, 0, inner),
                                                      "outer": Circle(0, 0, outer)})
    elements = mesh.t.shape[1]
    fe_mesh = FeMesh(mesh, groups, np.full(elements, 0.03), np.zeros(elements, int), ("all",),
                     inner)
    where = vector_basis(fe_mesh).doflocs

    def dof(x: float, y: float, component: int) -> int:
        return int(np.flatnonzero(np.hypot(where[0] - x, where[1] - y) < 1e-12)[component])

    held = np.array([dof(outer, 0.0, 1), dof(0.0, outer, 0), dof(-outer, 0.0, 1)])
    return StructuralHousing(ClampedModel(fe_mesh, Material(), held),
                             2.0 * np.pi * np.arange(72) / 72)


def test_a_free_ring_grows_by_alpha_delta_t_r():
    """Uniform temperature rise of a free ring: every bore node moves out by α ΔT R_i
    (measured 1.2e-7 relative: the curved P2 edges)."""
    inner = 0.045
    bore = unit_strain_bore(free_ring(inner, 0.075)) * ALPHA * 80.0
    np.testing.assert_allclose(bore, ALPHA * 80.0 * inner, rtol=1e-6)


@pytest.fixture(scope="module")
def warm_rod() -> Housing:
    return Housing.from_case(kamaz_case({"thermal": WARM}), use_cache=False)


def test_the_rods_bore_grows_as_a_free_ring(warm_rod):
    """The clamped rod at one temperature: its corrected bore grows by α ΔT R_b at every
    node (the held small end moves the big end, it does not distort it)."""
    warm = warm_rod.warm
    bore = warm.bore_displacement(warm_rod.projector)
    np.testing.assert_allclose(bore, ALPHA * 80.0 * warm.bore_radius, rtol=1e-5)


def test_the_clearance_change(warm_rod):
    """Δc = α_h ΔT_h R_b − α_s ΔT_h t_s − α_j ΔT_j R (−9.2 µm for the KamAZ bearing with the
    journal at 120 °C and the housing at 100 °C)."""
    warm = warm_rod.warm
    expected = ALPHA * (80.0 * (warm.bore_radius - warm.shell_thickness) - 100.0 * 0.04)
    assert warm.clearance_change(warm_rod.projector) == pytest.approx(expected, rel=1e-5)
    assert expected == pytest.approx(-9.2e-6, rel=1e-3)


def test_the_run_sees_the_warm_clearance(warm_rod):
    """The elastic run's film and a rigid bore (no FE model: a free ring) both get c + Δc."""
    case = kamaz_case({"thermal": WARM})
    cold = case.bearing.radial_clearance
    elastic = Simulation(case, film="reynolds", housing=warm_rod).geometry()
    assert elastic.radial_clearance == pytest.approx(cold - 9.2e-6, rel=1e-6)
    rigid = kamaz_case({"model": "rigid", "thermal": WARM})
    assert Simulation(rigid).geometry().radial_clearance == pytest.approx(cold - 9.2e-6,
                                                                          rel=1e-6)


def test_reference_temperature_is_todays_run_bit_for_bit():
    """Journal and housing at the reference temperature: no warm bore, the same cache key,
    housing and geometry."""
    today = kamaz_case(n_theta=24)
    cool = kamaz_case({"thermal": {"journal_temperature": 20.0, "housing_temperature": 20.0}},
                      n_theta=24)
    assert cache_key(_cache_payload(today)) == cache_key(_cache_payload(cool))
    first, second = (Housing.from_case(c, use_cache=False) for c in (today, cool))
    assert second.warm is None
    np.testing.assert_array_equal(first.compliance, second.compliance)
    assert Simulation(cool, film="reynolds", housing=second).geometry() == Simulation(
        today, film="reynolds", housing=first).geometry()


def test_assembly_and_warm_bore_together():
    """Assembled and warm: the film's profile is the assembled bore (the thermal distortion
    of a uniform temperature is round) and the clearance is the warm one."""
    case = kamaz_case({"thermal": WARM, "assembly": {"bolt_preload": 60e3}})
    housing = Housing.from_case(case, use_cache=False)
    geometry = Simulation(case, film="reynolds", housing=housing).geometry()
    field = geometry.profile.housing_bore.field(housing.angles, np.zeros(1), geometry.width)
    np.testing.assert_allclose(field[:, 0], housing.assembled_profile(), rtol=0, atol=1e-12)
    assert geometry.radial_clearance == pytest.approx(case.bearing.radial_clearance - 9.2e-6,
                                                      rel=1e-5)


def test_a_seizing_journal_is_refused():
    case = kamaz_case({"model": "rigid", "thermal": {"journal_temperature": 250.0,
                                                     "housing_temperature": 20.0}})
    with pytest.raises(CaseError, match=r"housing.thermal: journal at 250 degC"):
        Simulation(case).geometry()


def test_conduction_in_a_ring_and_its_free_growth():
    """Bore at 120 °C, outer circle at 60 °C (h → ∞ there), faces adiabatic: the FE field
    is T(r) = T_i + (T_o − T_i) ln(r/a)/ln(b/a) (measured 1.4e-3 K of 60 K), and the free
    ring's bore
    grows by α a T̄ with T̄ the area mean of ΔT (plane stress, Timoshenko & Goodier ch. 13;
    measured 3e-5 relative)."""
    from conrod.housing.conduction import Cooling, area_mean, temperature_field
    from conrod.housing.thermal import thermal_load

    inner, outer = 0.045, 0.075
    structure = free_ring(inner, outer)
    model = structure.model
    cooling = Cooling(45.0, 1.0e10, 60.0, face_heat_transfer=0.0)
    basis, values = temperature_field(model, lambda theta: np.full(np.shape(theta), 120.0),
                                      cooling)
    radius = np.hypot(*basis.doflocs)
    exact = 120.0 + (60.0 - 120.0) * np.log(radius / inner) / np.log(outer / inner)
    np.testing.assert_allclose(values, exact, rtol=0, atol=3e-3)
    rise = np.asarray(basis.interpolate(values)) - 20.0
    bore = structure.film_displacement(model.solve(thermal_load(model, ALPHA * rise)))
    mean = area_mean(basis, values, model.fe_mesh.thickness) - 20.0
    np.testing.assert_allclose(bore, ALPHA * inner * mean, rtol=1e-4)


def hot_cap(**extra) -> dict:
    return {"journal_temperature": 120.0, "shell_temperature_angles": [0.0, 180.0],
            "shell_temperatures": [110.0, 130.0], "ambient_temperature": 90.0, **extra}


def test_a_bore_hotter_at_the_cap_is_distorted_symmetrically():
    """Shell side 110 °C towards the small end, 130 °C at the cap, crankcase 90 °C: the
    bore is out of round (0.48 µm: a temperature linear in x alone would leave it round),
    symmetric about the rod axis within 5 % (measured 2.7 %: the mesh is not
    mirror-symmetric), and the film profile carries its out-of-round part."""
    case = kamaz_case({"thermal": hot_cap()})
    housing = Housing.from_case(case, use_cache=False)
    profile = housing.warm.profile(housing.projector)
    mirror = (-np.arange(72)) % 72
    assert np.ptp(profile) > 0.3e-6
    assert np.max(np.abs(profile - profile[mirror])) < 0.05 * np.max(np.abs(profile))
    geometry = Simulation(case, film="reynolds", housing=housing).geometry()
    field = geometry.profile.housing_bore.field(housing.angles, np.zeros(1), geometry.width)
    np.testing.assert_allclose(field[:, 0], profile, rtol=0, atol=1e-15)
    assert 90.0 < housing.warm.housing_temperature < 130.0
    assert housing.warm.shell_temperature == pytest.approx(120.0, rel=1e-3)


def test_an_isothermal_conducting_housing_is_the_uniform_one():
    """Shell side and crankcase at 100 °C: the conduction field is 100 °C everywhere, and
    the bore grows exactly as with housing_temperature = 100 (to 1e-9 relative)."""
    conducting = Housing.from_case(kamaz_case({"thermal": hot_cap(
        shell_temperature_angles=[0.0], shell_temperatures=[100.0],
        ambient_temperature=100.0)}, n_theta=24), use_cache=False)
    uniform = Housing.from_case(kamaz_case({"thermal": {
        "journal_temperature": 120.0, "housing_temperature": 100.0}}, n_theta=24),
        use_cache=False)
    np.testing.assert_allclose(conducting.warm.bore, uniform.warm.bore, rtol=1e-9)
    assert conducting.warm.housing_temperature == pytest.approx(100.0, rel=1e-12)


@pytest.mark.parametrize(("thermal", "match"), [
    ({"journal_temperature": 100.0}, r"give housing_temperature \(uniform\) or"),
    (hot_cap(shell_temperatures=[110.0]), r"shell_temperature_angles has 2 values"),
    (hot_cap(ambient_temperature=None), r"ambient_temperature is required"),
])
def test_bad_thermal_input_is_one_clear_line(thermal, match):
    thermal = {key: value for key, value in thermal.items() if value is not None}
    with pytest.raises(CaseError, match=match):
        kamaz_case({"thermal": thermal}, n_theta=24)


def test_conduction_needs_a_finite_element_housing():
    with pytest.raises(CaseError, match=r"shell_temperatures need a finite-element housing"):
        kamaz_case({"model": "rigid", "thermal": hot_cap()}, n_theta=24)


def test_conrod_housing_draws_the_housing_temperature():
    """A conducting housing: ``conrod housing`` registers the temperature map, drawn from
    the field the clearance change came from (its corner values between the crankcase and
    the hottest shell-side temperature)."""
    import conrod.output  # noqa: F401  (registers the figures)
    from conrod.output.registry import figures
    from conrod.simulation.housing_study import housing_study

    case = kamaz_case({"thermal": hot_cap()})
    results = housing_study(Housing.from_case(case, use_cache=False), case)
    spec = {figure.file: figure for figure in figures(results)}["housing_temperature.png"]
    assert spec.build().axes
    corners = results.housing.warm.corner_temperature
    assert corners.min() >= 90.0 - 1e-9 and corners.max() <= 130.0 + 1e-9
    assert results.summary["thermal"]["housing_temperature_field"].startswith("conduction")


def test_the_rigid_companion_of_a_conducting_housing_has_its_warm_clearance():
    """A housing conducting from its shell side: the rigid companion run (no FE model of
    its own) gets the elastic run's warm clearance, to round-off."""
    case = kamaz_case({"thermal": hot_cap()}, n_theta=24)
    housing = Housing.from_case(case)
    elastic = Simulation(case, film="reynolds", housing=housing)
    rigid = elastic.rigid_companion()
    assert rigid.geometry().radial_clearance == pytest.approx(
        elastic.geometry().radial_clearance, rel=1e-12)
    assert rigid.geometry().profile is None
