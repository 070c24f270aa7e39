"""The film on a bore that deforms along the width (a 3-D compliance, one bore node per film
node (θ_j, z_k)): the films' exact response per node against central differences and
against their row response, the coupled answer of a plane housing seen on 3-D nodes against
the plane answer, and the implicit step's Jacobian with asperity contact."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from conrod.ehd.bore_system import nodal_force_weights
from conrod.film.base import BearingGeometry, FilmState
from conrod.film.rated_state import rated
from conrod.film.reynolds.film import ReynoldsFilm
from conrod.film.reynolds.memory import ReynoldsMemory
from conrod.housing.housing import Housing
from conrod.housing.transfer import node_weights
from conrod.simulation.simulation import Simulation
from elastic_helpers import (
    assert_jacobian_columns,
    kamaz_case,
    solved_step,
    step_jacobian_and_residual,
    step_request,
)

RADIUS, CLEARANCE, STEP = 0.04, 5.0e-5, 1.0e-4  # [m], [m], rate time step [s]


def over_the_width(housing: Housing, axial: np.ndarray, local: float = 0.0) -> Housing:
    """``housing`` seen on the film nodes (θ_j, z_k): C₃ = E C Eᵀ + ``local`` I with E the
    repetition of a row's value over the width (``local`` [m/N] adds a Winkler bedding at
    every node, which makes it three-dimensional), the inertia fields repeated."""
    count = len(axial)
    spread = np.kron(np.eye(len(housing.angles)), np.ones((count, 1)))
    compliance = spread @ housing.compliance @ spread.T + local * np.eye(spread.shape[0])
    return Housing(housing.angles, housing.radius, compliance,
                   np.repeat(housing.inertia_base, count, axis=0), housing.correction,
                   housing.kinematics, axial=axial)


def _reynolds_setup():
    geometry = BearingGeometry(diameter=2 * RADIUS, width=0.03, radial_clearance=CLEARANCE)
    film = ReynoldsFilm(geometry, n_theta=36, n_z=8).with_deformation_rate()
    theta, z = film.grid()
    rng = np.random.default_rng(1)
    bore = (3e-6 * np.cos(2 * theta))[:, None] * (1.0 + 10.0 * z)[None, :] + (
        1e-6 * rng.standard_normal((len(theta), len(z))))
    reference = bore - 2e-7 * np.sin(theta)[:, None]
    state = FilmState(eccentricity_x=0.7 * CLEARANCE * np.cos(0.3),
                      eccentricity_y=0.7 * CLEARANCE * np.sin(0.3), velocity_x=0.01,
                      velocity_y=-0.02, journal_speed=272.0, viscosity=0.0095)
    weights = node_weights(theta, z, RADIUS).ravel()

    def evaluate(u: np.ndarray):
        field = u.reshape(bore.shape)
        deformed = rated(state, field, (field - reference) / STEP)
        result = film.solve(deformed, with_pressure=True)
        return (deformed, result.pressure, weights * result.pressure.ravel(),
                np.array([result.force_x, result.force_y]))

    return film, theta, z, bore.ravel(), weights, evaluate


def test_reynolds_node_response_matches_central_differences_and_the_rows():
    """∂f/∂u and ∂F/∂u of single film nodes (36 × 9, ε = 0.7, the bore's rate in the
    squeeze term): within 1e-6 of the largest entry of central differences at 30 nodes
    (measured 6e-11), and summed over each row's nodes the row response (2e-16)."""
    film, theta, z, bore, weights, evaluate = _reynolds_setup()
    deformed, pressure, _, _ = evaluate(bore)
    response = film.thickness_response(deformed, ReynoldsMemory(pressure), weights, STEP)
    rows = film.thickness_response(deformed, ReynoldsMemory(pressure),
                                   nodal_force_weights(film, theta, RADIUS), STEP)
    n, m = len(theta), len(z)
    summed = response.nodal_by_bore.reshape(n, m, n, m).sum(axis=(1, 3))
    scale = np.max(np.abs(rows.nodal_by_bore))
    assert np.max(np.abs(summed - rows.nodal_by_bore)) <= 1e-12 * scale
    assert np.max(np.abs(response.force_by_bore.reshape(2, n, m).sum(axis=2)
                         - rows.force_by_bore)) <= 1e-12 * np.max(np.abs(rows.force_by_bore))
    assert np.allclose(response.nodal_by_velocity.reshape(n, m, 2).sum(axis=1),
                       rows.nodal_by_velocity, rtol=1e-12, atol=0.0)
    nodal_scale = np.max(np.abs(response.nodal_by_bore))
    force_scale = np.max(np.abs(response.force_by_bore))
    for q in np.random.default_rng(2).choice(n * m, 30, replace=False):
        step = np.zeros(n * m)
        step[q] = 1e-10
        _, _, f_plus, force_plus = evaluate(bore + step)
        _, _, f_minus, force_minus = evaluate(bore - step)
        column = (f_plus - f_minus) / 2e-10
        assert np.max(np.abs(column - response.nodal_by_bore[:, q])) <= 1e-6 * nodal_scale
        assert np.max(np.abs((force_plus - force_minus) / 2e-10
                             - response.force_by_bore[:, q])) <= 1e-6 * force_scale


def test_content_step_node_response_matches_central_differences_and_the_rows():
    """The mass-conserving film's content step, per node, on a film with full and
    broken-film cells (24 × 5): every column within 1e-5 of the largest central difference
    (measured 1.6e-8), and the row response as the sum over each row's nodes (2e-16)."""
    from conrod.film.mass_conserving.film import MassConservingFilm
    from test_ehd_jfo_response import N_THETA, N_Z, _ruptured_memory
    from test_ehd_jfo_response import STEP as CONTENT_STEP
    from test_orbit_jfo import OMEGA, fed_bearing

    geometry = fed_bearing()
    film = MassConservingFilm(geometry, n_theta=N_THETA, n_z=N_Z)
    c = geometry.radial_clearance
    state = FilmState(eccentricity_x=0.6 * c, eccentricity_y=0.2 * c,
                      velocity_x=0.05 * c * OMEGA, velocity_y=-0.1 * c * OMEGA,
                      journal_speed=OMEGA, shell_speed=0.0, viscosity=0.02)
    memory = _ruptured_memory(film, state)
    theta, z = film.grid()
    bore = ((0.05 * c * np.cos(2.0 * theta))[:, None] * (1 + 0.5 * z / z.max())[None, :])
    weights = node_weights(theta, z, geometry.radius).ravel()

    def solve(u: np.ndarray):
        deformed = dataclasses.replace(state, deformation=u.reshape(bore.shape))
        _, _, after = film.content_step(deformed, memory, CONTENT_STEP)
        return weights * film.gauge_pressure(after.pressure, deformed).ravel(), after, deformed

    _, after, deformed = solve(bore.ravel())
    exact = film.thickness_response(deformed, after, weights, CONTENT_STEP).nodal_by_bore
    rows = film.thickness_response(deformed, after,
                                   nodal_force_weights(film, theta, geometry.radius),
                                   CONTENT_STEP).nodal_by_bore
    n, m = bore.shape
    assert np.max(np.abs(exact.reshape(n, m, n, m).sum(axis=(1, 3)) - rows)) <= (
        1e-12 * np.max(np.abs(rows)))
    differences = np.empty_like(exact)
    for r in range(n * m):
        shift = np.zeros(n * m)
        shift[r] = 1e-11
        differences[:, r] = (solve(bore.ravel() + shift)[0]
                             - solve(bore.ravel() - shift)[0]) / 2e-11
    assert np.max(np.abs(exact - differences)) < 1e-5 * np.max(np.abs(differences))


@pytest.fixture(scope="module")
def kamaz_pair():
    """The KamAZ-740 built-in rod on a 36 × 8 Reynolds film, as a plane housing and seen on
    the 3-D film nodes (the same compliance repeated over the width)."""
    case = kamaz_case(n_theta=36, n_z=8, film="reynolds", integrator="implicit")
    plane = Housing.from_case(case)
    axial = np.linspace(-0.5 * case.bearing.width, 0.5 * case.bearing.width, 9)
    return case, plane, over_the_width(plane, axial)


def test_plane_housing_on_3d_nodes_gives_the_plane_answer(kamaz_pair):
    """A plane compliance seen on the film nodes (θ_j, z_k) couples to the same answer:
    the massless force balance (velocity and bore solved together, :meth:`balance_velocity`)
    at a loaded state gives the same velocity and, node by node, the plane bore displacement
    over the width, within 1e-7 of the clearance (both iterations converge to 1e-9 c;
    measured: velocities equal to 13 digits, 21 film solves each)."""
    case, plane, solid = kamaz_pair
    answers = []
    for housing in (plane, solid):
        problem = Simulation(case, housing=housing, rigid_companion=False).problem()
        film, c = problem.film, problem.clearance
        memory = film._static_memory()
        state = FilmState(eccentricity_x=0.6 * c * np.cos(3.4),
                          eccentricity_y=0.6 * c * np.sin(3.4), velocity_x=0.0,
                          velocity_y=0.0, journal_speed=272.0, shell_speed=0.0,
                          viscosity=problem.viscosity)
        vx, vy, residual, after = film.balance_velocity(
            state, (-10e3 * np.cos(3.4), -10e3 * np.sin(3.4)), memory, 0.7)
        assert residual < 1e-6
        answers.append((np.array([vx, vy]), housing.field_view(after.deformation), c))
    (v_plane, u_plane, c), (v_solid, u_solid, _) = answers
    assert u_solid.shape == (36, 9) and u_plane.shape == (36, 1)
    assert np.max(np.abs(u_solid - u_plane)) < 1e-7 * c
    assert np.max(np.abs(v_solid - v_plane)) < 1e-6 * np.max(np.abs(v_plane))
    assert np.max(np.abs(u_plane)) > 1e-2 * c  # the bore does deform


def test_plane_equivalent_of_a_repeated_plane_housing_is_itself(kamaz_pair):
    """Spreading a row force uniformly over the width and taking the width-mean undoes the
    repetition over the width: Sᵀ E C Eᵀ S = C."""
    _, plane, solid = kamaz_pair
    back = solid.plane_equivalent()
    assert back.uniform_in_z
    scale = np.max(np.abs(plane.compliance))
    assert np.max(np.abs(back.compliance - plane.compliance)) <= 1e-14 * scale
    assert np.allclose(back.inertia_base, plane.inertia_base, rtol=1e-14, atol=0.0)


def test_step_jacobian_on_3d_nodes_with_asperity_contact(kamaz_pair):
    """One BDF2 step of the journal with mass, the rod seen on the 3-D nodes with a Winkler
    bedding of its own at every node (a housing that deforms along the width), asperity
    contact active: the exact Jacobian against central differences at the journal columns
    and at bore nodes at an edge and mid-width of the contact row, within 1e-5 of each
    column's largest entry."""
    case, plane, _ = kamaz_pair
    axial = np.linspace(-0.5 * case.bearing.width, 0.5 * case.bearing.width, 9)
    solid = over_the_width(plane, axial, local=2e-10)
    mixed = case.model_copy(update={"contact": case.contact.model_copy(
        update={"model": "greenwood_tripp"})})
    problem = Simulation(mixed, housing=solid, rigid_companion=False).problem()
    film, c = problem.film, problem.clearance
    assert film.carries_asperity() and film.nodal.ndim == 1
    memory = film._static_memory()
    dt = np.radians(1.0) / problem.crank_speed
    direction = np.array([np.cos(3.5), np.sin(3.5)])
    request = step_request(
        problem, memory, position_reference=0.985 * c * direction,
        velocity_reference=np.zeros(2), tau=2.0 * dt / 3.0, dt=dt, load=-20e3 * direction,
        crank_angle=0.3, speeds=(272.0, 0.0))
    scale = c * problem.crank_speed
    done = solved_step(film, request, np.zeros(2), scale)
    assert done.newton.converged
    jac, residual, z0, payload = step_jacobian_and_residual(film, request, done.newton.own,
                                                            done.velocity, scale)
    assert np.hypot(*payload.contact_force()) >= 1e-3 * 20e3
    n = len(memory.deformation)
    row = int(np.argmin(payload.problem.h[:, 4]))
    assert_jacobian_columns(jac, residual, z0, (n, n + 1, row * 9, row * 9 + 4, 3 * 9 + 2))


@pytest.mark.slow
def test_solid_big_end_example_thins_the_film_at_its_stiff_face(tmp_path):
    """The shipped 3-D example (a big end stiffer at its rear face) on a 24 × 4 film (its
    180 bore nodes interpolated in θ): the bore's u(θ, z) is held and drawn, and at the
    smallest film the rear (stiff) face's edge carries a thinner film than mid-width and the
    front face (the front face gives way; as shipped, 36 × 8: 1.62 / 2.66 / 2.75 µm at the
    film nodes); the plane equivalent of the same body (its width-mean) has a thicker
    smallest film. ``conrod housing`` refuses the 3-D compliance with one line."""
    from conrod.cases.case import Case
    from conrod.errors import CaseError
    from conrod.output.registry import figures
    from conrod.simulation.housing_study import housing_study
    from elastic_helpers import EXAMPLES

    case = Case.from_toml(EXAMPLES / "kamaz_740_solid_big_end.toml").with_(
        solver__n_theta=24, solver__n_z=4, solver__output_step_deg=4.0)
    housing = Housing.from_case(case)
    assert not housing.uniform_in_z and housing.node_count == 24 * 5
    solid = Simulation(case, housing=housing, rigid_companion=False).run()
    plane = Simulation(case, housing=housing.plane_equivalent(), rigid_companion=False).run()
    assert solid.deformation_field.shape == (len(solid.cycle.crank_angle), 24, 5)
    index = int(np.argmin(solid.cycle.h_min))
    gap = solid.gap_field(index)
    row = int(np.argmin(gap.min(axis=1)))
    rear, middle, front = gap[row, 0], gap[row, 2], gap[row, -1]
    assert rear < 0.8 * middle and rear < 0.8 * front
    assert solid.summary.h_min < 0.9 * plane.summary.h_min
    names = {spec.file for spec in figures(solid)}
    assert "bore_deformation_width.png" in names
    spec = next(spec for spec in figures(solid) if spec.file == "bore_deformation_width.png")
    spec.build().savefig(tmp_path / "bore.png")
    assert "bore" in solid.headline_extra
    with pytest.raises(CaseError, match=r"3-D compliance \(120 film nodes over the width\)"):
        housing_study(housing, case)


@pytest.mark.slow
def test_content_steps_on_3d_nodes_give_the_plane_jfo_orbit():
    """The mass-conserving film's implicit content steps with the journal (its step system,
    journal and bore in one Newton iteration) on a Winkler bore seen on the 3-D nodes (each
    row's bedding repeated over the width): the periodic orbit of the plane bore, h_min and
    p_max within 1e-6 (24 × 4, 2° steps)."""
    import math

    from conrod.ehd.film import ElasticSettings
    from conrod.ehd.mass_conserving_ehd import elastic_film
    from conrod.film.mass_conserving.film import MassConservingFilm
    from elastic_helpers import WINKLER_SETTINGS, winkler_housing
    from test_orbit_jfo import OMEGA, fed_bearing, orbit

    geometry = fed_bearing()
    plane = winkler_housing(geometry, 24, 2e-9)
    base = MassConservingFilm(geometry, n_theta=24, n_z=4)
    settings = ElasticSettings(cycle=2 * math.pi, **WINKLER_SETTINGS)
    cycles = []
    for housing in (plane, over_the_width(plane, base.grid()[1])):
        result, cycle, _ = orbit(elastic_film(base, housing, OMEGA, settings))
        assert result.periodic
        cycles.append(cycle)
    assert cycles[1].h_min.min() == pytest.approx(cycles[0].h_min.min(), rel=1e-6)
    assert cycles[1].p_max.max() == pytest.approx(cycles[0].p_max.max(), rel=1e-6)
