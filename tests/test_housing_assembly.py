"""The assembled big end: shell crush against Lamé, bolt preload symmetric and carried by the
joint, zero assembly bit for bit today's housing and film, the assembled bore in the film,
the cache, and bad input."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from conrod.cases.case import Case
from conrod.errors import CaseError
from conrod.housing.assembly import crush_pressure
from conrod.housing.build import _cache_payload
from conrod.housing.cache import cache_key
from conrod.housing.housing import Housing
from conrod.simulation.simulation import Simulation
from elastic_helpers import kamaz_case, lame_bore_displacement, write_ring_msh

E_STEEL, NU_STEEL = 2.1e11, 0.3
MIRROR_72 = (-np.arange(72)) % 72
"""Film node of −θ_j for each node θ_j of a 72-node grid [-]."""


def ring_case(tmp_path, assembly: dict, n_theta: int = 144) -> Case:
    """A thick steel ring 45/75 mm, 30 mm wide, outer circle held, shell 2.5 mm."""
    inner, outer, width = 0.045, 0.075, 0.03
    mesh_file = write_ring_msh(tmp_path / "ring.msh", inner, outer, 144, 12)
    case = kamaz_case({"model": "mesh", "mesh_file": str(mesh_file), "thickness": width,
                       "shell_thickness": 0.0025, "assembly": assembly}, n_theta=n_theta)
    return case.model_copy(update={"bearing": case.bearing.model_copy(
        update={"diameter": 2 * inner - 0.005, "width": width})})


def test_crush_alone_on_a_thick_ring_is_lame(tmp_path):
    """Crush 40 µm: the contact pressure from the shell's compatibility with the Lamé
    opening, and a uniform bore expansion at every film node, both within 1 % (measured
    0.001 % and 0.03 %); the film sees no out-of-round (assembled clearance) or the whole
    expansion (nominal clearance)."""
    inner, outer, crush = 0.045, 0.075, 40.0e-6
    housing = Housing.from_case(ring_case(tmp_path, {"crush_height": crush}),
                                use_cache=False)
    opening = lame_bore_displacement(inner, outer, 1.0, E_STEEL, NU_STEEL)
    pressure = crush_pressure(crush, E_STEEL * 0.0025 / inner**2, opening)
    assembled = housing.assembly
    assert assembled.crush_pressure == pytest.approx(pressure, rel=1e-2)
    np.testing.assert_allclose(assembled.displacement, opening * pressure, rtol=1e-2)
    assert np.ptp(housing.assembled_profile()) < 1e-4 * opening * pressure
    nominal = Housing.from_case(ring_case(tmp_path, {"crush_height": crush,
                                                     "clearance_reference": "nominal"}),
                                use_cache=False)
    np.testing.assert_allclose(nominal.assembled_profile(), opening * pressure, rtol=1e-2)


def test_interference_is_crush_over_pi(tmp_path):
    """A radial interference δ is a crush height π δ."""
    by_crush = Housing.from_case(ring_case(tmp_path, {"crush_height": np.pi * 10e-6}, 72),
                                 use_cache=False)
    by_interference = Housing.from_case(ring_case(tmp_path, {"interference": 10e-6}, 72),
                                        use_cache=False)
    np.testing.assert_allclose(by_interference.assembly.displacement,
                               by_crush.assembly.displacement, rtol=1e-12)


@pytest.fixture(scope="module")
def preloaded() -> Housing:
    return Housing.from_case(kamaz_case({"assembly": {"bolt_preload": 60.0e3}}),
                             use_cache=False)


def test_bolt_preload_is_symmetric_about_the_rod_axis(preloaded):
    """The film profile at −θ is that at θ within 1.5 % of its largest value (measured
    0.7 %; the rod's mesh is not mirror-symmetric), and less on a finer mesh (measured 0.5 %
    at 2 mm elements)."""
    def asymmetry(housing: Housing) -> float:
        profile = housing.assembled_profile()
        return float(np.max(np.abs(profile - profile[MIRROR_72])) / np.max(np.abs(profile)))

    assert asymmetry(preloaded) < 0.015
    fine = Housing.from_case(kamaz_case({"element_size": 0.002,
                                         "assembly": {"bolt_preload": 60.0e3}}),
                             use_cache=False)
    assert asymmetry(fine) < asymmetry(preloaded)


def test_the_joint_carries_the_preload(preloaded):
    """Preload alone: the normal force across each joint side is −F within 2.5 % (measured
    0.9 % on both: stresses of P2 elements sampled at 16 points); the joint is pressed all
    along."""
    force = preloaded.assembly.joint_force()
    np.testing.assert_allclose(force, -60.0e3, rtol=0.025)
    assert np.all(preloaded.assembly.joint["stress_Pa"] < 0.0)


def test_preload_and_crush_add_up(preloaded):
    """The load case is linear: preload and crush together are their sum."""
    crushed = Housing.from_case(kamaz_case({"assembly": {"crush_height": 30e-6}}),
                                use_cache=False)
    both = Housing.from_case(kamaz_case({"assembly": {"bolt_preload": 60.0e3,
                                                      "crush_height": 30e-6}}),
                             use_cache=False)
    np.testing.assert_allclose(both.assembly.displacement, preloaded.assembly.displacement
                               + crushed.assembly.displacement, rtol=0, atol=1e-12)


def test_zero_assembly_is_todays_housing_and_film_bit_for_bit(tmp_path):
    """Preload 0 and crush 0: no assembled bore, the same compliance cache key, the same
    compliance and inertia fields and the same film geometry as without the section."""
    today = kamaz_case(n_theta=24)
    zero = kamaz_case({"assembly": {"bolt_preload": 0.0, "crush_height": 0.0}}, n_theta=24)
    assert cache_key(_cache_payload(today)) == cache_key(_cache_payload(zero))
    first = Housing.from_case(today, use_cache=False)
    second = Housing.from_case(zero, use_cache=False)
    assert second.assembly is None and second.assembled_profile() is None
    np.testing.assert_array_equal(first.compliance, second.compliance)
    np.testing.assert_array_equal(first.inertia_base, second.inertia_base)
    assert Simulation(zero, housing=second).geometry() == Simulation(
        today, housing=first).geometry()


def test_the_assembled_bore_is_the_films_profile(preloaded):
    """The grid film of the simulation carries h₀(θ_j) = the corrected assembled bore, mean
    removed, at every axial node; the rigid companion and a film that cannot deform (the
    short film: the bore stays rigid and round) run on the round bore."""
    case = kamaz_case({"assembly": {"bolt_preload": 60.0e3}})
    assert Simulation(case, film="short", housing=preloaded).geometry().profile is None
    simulation = Simulation(case, film="reynolds", housing=preloaded)
    geometry = simulation.geometry()
    z = np.linspace(-0.5 * geometry.width, 0.5 * geometry.width, 5)
    field = geometry.profile.field(preloaded.angles, z, geometry.radial_clearance,
                                   geometry.width)
    expected = preloaded.correct(preloaded.assembly.displacement)
    expected = expected - expected.mean()
    np.testing.assert_allclose(field, np.repeat(expected[:, None], 5, axis=1), rtol=0,
                               atol=1e-15)
    assert simulation.rigid_companion().geometry().profile is None


def test_assembly_cache_round_trip(tmp_path):
    """The assembled bore is cached beside the compliance and read back unchanged; another
    preload is another entry."""
    case = kamaz_case({"assembly": {"bolt_preload": 50.0e3}}, n_theta=24)
    first = Housing.from_case(case, cache_dir=tmp_path)
    second = Housing.from_case(case, cache_dir=tmp_path)
    assert not first.info["assembly_from_cache"] and second.info["assembly_from_cache"]
    np.testing.assert_array_equal(first.assembly.displacement, second.assembly.displacement)
    for name, value in first.assembly.joint.items():
        np.testing.assert_array_equal(value, second.assembly.joint[name])
    other = Housing.from_case(kamaz_case({"assembly": {"bolt_preload": 40.0e3}}, n_theta=24),
                              cache_dir=tmp_path)
    assert not other.info["assembly_from_cache"] and other.info["from_cache"]
    assert len(list(tmp_path.glob("*.npz"))) == 3


@pytest.mark.parametrize(("housing", "match"), [
    ({"assembly": {"bolt_preload": 5e4, "bolt_distance": 0.2}},
     r"housing.assembly.bolt_distance = 0.2: the bolts lie outside"),
    ({"assembly": {"bolt_preload": 5e4, "bolt_distance": 0.08}},
     r"housing.assembly.bolt_distance = 0.08: the bolts cut the bore"),
    ({"assembly": {"bolt_preload": 5e4, "bolt_thread_depth": 0.001}},
     r"housing.assembly.bolt_thread_depth = 0.001: the thread engagement crosses"),
    ({"assembly": {"crush_height": 1e-5, "interference": 1e-5}},
     r"give crush_height or interference, not both"),
    ({"assembly": {"bolt_preload": -1.0}}, r"bolt_preload"),
])
def test_bad_assembly_is_one_clear_line(housing, match):
    with pytest.raises(CaseError, match=match):
        Housing.from_case(kamaz_case(housing, n_theta=24), use_cache=False)


def test_preload_on_a_mesh_needs_the_bolts_given(tmp_path):
    with pytest.raises(CaseError, match=r"bolt_preload on an imported mesh needs "
                                        r"bolt_distance and bolt_thread_depth"):
        ring_case(tmp_path, {"bolt_preload": 1e4})


def test_conrod_housing_reports_the_assembled_bore_and_joint(tmp_path):
    """``conrod housing`` with the example's [housing.assembly] uncommented and a warm bore:
    the assembled bore table and figure, the joint table, and one truth between the table
    and the summary (out-of-roundness, joint pressure, clearance change)."""
    import csv
    import json

    from typer.testing import CliRunner

    from conrod.cli.app import _register_commands, app
    from elastic_helpers import EXAMPLES

    text = (EXAMPLES / "kamaz_740_truck_diesel.toml").read_text()
    text = text.replace("# [housing.assembly]\n# bolt_preload = 75.0e3",
                        "[housing.assembly]\nbolt_preload = 75.0e3")
    text = text.replace("# crush_height = 40.0e-6", "crush_height = 40.0e-6")
    text += ("\n[housing.thermal]\njournal_temperature = 105.0\n"
             "housing_temperature = 95.0\n")
    case = tmp_path / "kamaz.toml"
    case.write_text(text)
    _register_commands()
    out = tmp_path / "out"
    result = CliRunner().invoke(app, ["housing", str(case), "--out", str(out), "--no-cache"])
    assert result.exit_code == 0, result.output
    assert {"assembled_bore.csv", "joint_pressure.csv", "assembled_bore.png"} <= {
        p.name for p in out.iterdir()}
    summary = json.loads((out / "housing_summary.json").read_text())
    with (out / "assembled_bore.csv").open() as handle:
        rows = [row for row in csv.DictReader(
            line for line in handle if not line.startswith("#"))]
    profile = np.array([float(row["film_profile_m"]) for row in rows])
    assert summary["assembly"]["out_of_roundness_um"] == pytest.approx(np.ptp(profile) * 1e6,
                                                                        rel=1e-6)
    assert summary["assembly"]["bolt_preload_N"] == 75.0e3
    joint = summary["assembly"]["joint"]
    np.testing.assert_allclose(joint["normal_force_N"], -75.0e3 + 4.1e3, rtol=0.03)
    assert isinstance(joint["over_cycle"]["opens"], bool)
    assert summary["thermal"]["clearance_change_um"] == pytest.approx(
        11.5e-6 * (75.0 * (42.5e-3 - 2.5e-3) - 85.0 * 40e-3) * 1e6, rel=1e-5)


@pytest.mark.slow
def test_an_elastic_run_on_the_assembled_warm_bore():
    """An elastic run (the example's rod, Reynolds 36 × 8, coarse steps) on the assembled,
    warm bore reports what its bore carried — the assembled out-of-roundness and the warm
    clearance change of its housing — the bonded joint under its own film pressure and
    inertia, and a film-thickness map whose minimum is the film's h_min."""
    grid = {"n_theta": 36, "n_z": 8, "film": "reynolds", "integrator": "quasi_static",
            "quasi_static_step_deg": 2.0, "output_step_deg": 4.0}
    import tomllib

    from elastic_helpers import EXAMPLES

    rod = tomllib.loads((EXAMPLES / "kamaz_740_truck_diesel.toml").read_text())["housing"]
    case = kamaz_case({**rod, "assembly": {"bolt_preload": 75.0e3, "crush_height": 40e-6},
                       "thermal": {"journal_temperature": 105.0,
                                   "housing_temperature": 95.0}}, **grid)
    housing = Housing.from_case(case, use_cache=False)
    results = Simulation(case, housing=housing, rigid_companion=False).run()
    info = results.info
    assert info["assembled_out_of_round_um"] == pytest.approx(
        np.ptp(housing.assembled_profile()) * 1e6, rel=1e-12)
    assert info["thermal_clearance_change_um"] == pytest.approx(-4.6, abs=0.01)
    joint = info["joint_over_run"]
    assert isinstance(joint["opens"], bool) and 0.0 <= joint["open_share_of_joint"] <= 1.0
    assert (joint["smallest_pressure_Pa"] < 0.0) == joint["opens"]
    # one truth: the film-thickness map is the gap on the as-built bore the film solved
    # (measured 0.07 %; without the assembled shape its minimum was −0.05 µm: negative)
    elastic = results.elastic
    assert np.min(elastic.film_thickness) == pytest.approx(elastic.summary.h_min, rel=0.01)


def test_an_assembly_that_closes_the_film_is_refused(preloaded):
    """A preload whose bore would touch a centred journal: one line naming the as-built
    bore, not a film with a negative gap."""
    case = kamaz_case({"assembly": {"bolt_preload": 1.0e6}})
    with pytest.raises(CaseError, match=r"bearing profile \(with the as-built housing bore\)"):
        Simulation(case, film="reynolds").film_model()


@pytest.mark.parametrize(("split_angle", "bolt_distance"), [(30.0, None), (45.0, 0.1)])
def test_an_inclined_split_carries_the_preload(split_angle, bolt_distance):
    """Bolts perpendicular to an inclined split line: the bolt loads make no force and no
    moment (their bands sit on the bolt axes to 1e-7 N m), and each side of the joint
    carries −F within 2.5 % (measured 0.5–1.6 %)."""
    from conrod.housing.assembly import bolt_layout, bolt_load
    from conrod.housing.geometry import RodGeometry

    case = kamaz_case({"split_angle": split_angle, "assembly": {
        "bolt_preload": 6.0e4, **({} if bolt_distance is None else {
            "bolt_distance": bolt_distance})}})
    housing = Housing.from_case(case, use_cache=False)
    model = housing.structure.model
    geometry = RodGeometry(**case.housing.rod_outline(case.bearing.diameter,
                                                      case.engine.rod_length))
    load = bolt_load(model, bolt_layout(geometry, bolt_distance, None), 6.0e4)
    x, y = model.basis.doflocs[:, 0::2]
    assert abs(load[0::2].sum()) < 1e-6 and abs(load[1::2].sum()) < 1e-6
    assert abs(np.sum(x * load[1::2]) - np.sum(y * load[0::2])) < 1e-5
    np.testing.assert_allclose(housing.assembly.joint_force(), -6.0e4, rtol=0.025)


def test_crush_pulls_the_joint_apart_by_statics():
    """Crush alone: the cap's half of the bore pressure, 2 p R_b b, pulls the cap off; each
    joint side carries p R_b b in tension (statics of the cap; measured 0.9 %)."""
    housing = Housing.from_case(kamaz_case({"assembly": {"crush_height": 40e-6}}),
                                use_cache=False)
    assembled = housing.assembly
    pull = assembled.crush_pressure * housing.structure.bore_radius * 0.03
    np.testing.assert_allclose(assembled.joint_force(), pull, rtol=0.025)


def test_bolts_on_the_built_in_rod_read_back_as_a_mesh(tmp_path):
    """The built-in rod (one thickness everywhere) written as a gmsh file and imported
    (``model = "mesh"``, the same split, bolts and thread depth given): the same assembled
    bore within 5 % of its range (measured 2.7 %: the mesh's load bands are sized by the
    joint's length from the bore to the outline, 17.5 mm with the fillet, the built-in
    rod's by its thinner wall, 13.6 mm, and the mesh's cap outline is a polygon) and the
    same joint force within 2 %."""
    from conrod.housing.mesh_io import write_housing_mesh

    same = {"head_thickness": 0.03, "shank_thickness": 0.03, "small_end_thickness": 0.03}
    bolts = {"bolt_preload": 6.0e4, "bolt_distance": 0.1, "bolt_thread_depth": 0.008}
    built_in = Housing.from_case(kamaz_case({**same, "assembly": bolts}), use_cache=False)
    fe_mesh = built_in.structure.model.fe_mesh
    corners = int(fe_mesh.mesh.t.max()) + 1
    facets = fe_mesh.mesh.facets
    path = tmp_path / "rod.msh"
    write_housing_mesh(path, fe_mesh.mesh.doflocs[:, :corners].T, fe_mesh.mesh.t.T,
                       {"big_end_bore": facets[:, fe_mesh.boundaries["big_end_bore"]].T,
                        "clamp": facets[:, fe_mesh.boundaries["small_end_bore"]].T})
    imported = Housing.from_case(kamaz_case({"model": "mesh", "mesh_file": str(path),
                                             "thickness": 0.03, "assembly": bolts}),
                                 use_cache=False)
    first, second = built_in.assembled_profile(), imported.assembled_profile()
    assert np.max(np.abs(second - first)) < 0.05 * np.ptp(first)
    np.testing.assert_allclose(imported.assembly.joint_force(),
                               built_in.assembly.joint_force(), rtol=0.02)


def test_bolts_outside_an_imported_wall_are_refused(tmp_path):
    case = ring_case(tmp_path, {"bolt_preload": 1e4, "bolt_distance": 0.3,
                                "bolt_thread_depth": 0.01}, n_theta=72)
    with pytest.raises(CaseError, match=r"bolt_distance = 0.3: the bolts do not lie in the "
                                        r"wall at the split line"):
        Housing.from_case(case, use_cache=False)


@settings(max_examples=15, deadline=None)
@given(share=st.floats(0.2, 0.8), depth_share=st.floats(0.45, 0.8))
def test_bolt_loads_make_no_force_and_no_moment_anywhere_in_the_wall(preloaded, share,
                                                                     depth_share):
    """Bolts anywhere across the wall, threads at any depth in the head: the two bands of
    each bolt sit on its axis (the secant shift converges), so the pair makes no force and
    no moment (to 1e-5 N m for 60 kN)."""
    from conrod.housing.assembly import bolt_layout, bolt_load
    from conrod.housing.geometry import RodGeometry

    case = kamaz_case()
    geometry = RodGeometry(**case.housing.rod_outline(case.bearing.diameter,
                                                      case.engine.rod_length))
    wall = min(geometry.head_outer_radius, geometry.cap_outer_radius) - geometry.bore_radius
    distance = 2.0 * (geometry.bore_radius + share * wall)
    depth = depth_share * (geometry.head_outer_radius - geometry.bore_radius)
    model = preloaded.structure.model
    load = bolt_load(model, bolt_layout(geometry, distance, depth), 6.0e4)
    x, y = model.basis.doflocs[:, 0::2]
    assert abs(load[0::2].sum()) < 1e-6 and abs(load[1::2].sum()) < 1e-6
    assert abs(np.sum(x * load[1::2]) - np.sum(y * load[0::2])) < 1e-5
