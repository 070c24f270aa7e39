"""The thermal film on the elastic bore: the Reynolds film's exact response to the bore with
a viscosity field against central differences, the elastic film carrying a field (a uniform
field is the scalar answer), and the thermal film run on the elastic bore."""

from __future__ import annotations

import numpy as np
import pytest

from conrod.ehd.bore_system import nodal_force_weights
from conrod.film.base import FilmState
from conrod.film.rated_state import rated
from conrod.film.reynolds.film import ReynoldsFilm
from conrod.film.reynolds.memory import ReynoldsMemory
from test_ehd_response import CLEARANCE, RADIUS, STEP, bore_differences, plain_film, setup


def _field_film():
    film = plain_film()
    theta, z = film.grid()
    # a hot zone after the load, cooler edges: μ between 0.5 and 1.6 times μ_r
    mu = 0.0095 * (1.0 + 0.5 * np.cos(theta - 0.8)[:, None]) * (
        1.0 + 0.3 * (2.0 * z / 0.03)[None, :] ** 2)
    return film.with_viscosity_field(mu), theta, z


def test_response_with_a_viscosity_field_matches_central_differences():
    film, theta, bore, velocity, evaluate = setup(_field_film()[0])
    assert film.exact_thickness_response()
    deformed, pressure, _, _ = evaluate(bore, velocity)
    weights = nodal_force_weights(film, theta, RADIUS)
    response = film.thickness_response(deformed, ReynoldsMemory(pressure), weights, STEP)
    nodal, force = bore_differences(evaluate, bore, velocity)
    assert np.max(np.abs(nodal - response.nodal_by_bore)) <= 1e-6 * np.max(np.abs(nodal))
    assert np.max(np.abs(force - response.force_by_bore)) <= 1e-6 * np.max(np.abs(force))
    assert np.count_nonzero(np.max(np.abs(response.nodal_by_bore), axis=0)) >= len(theta) // 3
    for k in range(2):
        shift = np.zeros(2)
        shift[k] = 1e-6
        _, _, f_plus, _ = evaluate(bore, velocity + shift)
        _, _, f_minus, _ = evaluate(bore, velocity - shift)
        numeric = (f_plus - f_minus) / 2e-6
        assert np.max(np.abs(numeric - response.nodal_by_velocity[:, k])) <= 1e-6 * np.max(
            np.abs(numeric))
    # the scalar response is not the answer: the field matters in the response
    plain = plain_film().thickness_response(deformed, ReynoldsMemory(pressure), weights, STEP)
    assert np.max(np.abs(plain.nodal_by_bore - response.nodal_by_bore)) > 1e-2 * np.max(
        np.abs(nodal))


def _elastic_film(n_theta: int = 36, n_z: int = 8):
    import tomllib
    from pathlib import Path

    from conrod import Case
    from conrod.ehd.film import ElasticFilm, ElasticSettings
    from conrod.housing.housing import Housing
    from conrod.units import rpm_to_rad_s

    examples = Path(__file__).resolve().parents[1] / "examples"
    data = tomllib.loads((examples / "kamaz_740_truck_diesel.toml").read_text())
    data["solver"] = {"film": "reynolds", "n_theta": n_theta, "n_z": n_z}
    case = Case.from_dict(data, base_dir=examples)
    omega = rpm_to_rad_s(case.engine.speed)
    film = ElasticFilm(ReynoldsFilm(case.bearing.geometry(), n_theta=n_theta, n_z=n_z),
                       Housing.from_case(case), crank_speed=omega,
                       settings=ElasticSettings(tolerance=1e-9))  # compared to 1e-9 below
    c, angle = case.bearing.radial_clearance, np.radians(170.0)
    state = FilmState(eccentricity_x=0.9 * c * np.cos(angle),
                      eccentricity_y=0.9 * c * np.sin(angle), velocity_x=0.0,
                      velocity_y=0.0, journal_speed=omega, shell_speed=0.0,
                      viscosity=case.lubricant.viscosity)
    return film, state


def test_the_elastic_film_takes_a_viscosity_field_and_a_uniform_one_is_the_scalar():
    from conrod.film.capabilities import HasViscosityField

    film, state = _elastic_film()
    assert isinstance(film, HasViscosityField)
    assert film.with_viscosity_field(None) is film  # no field: the film itself
    scalar = film.solve(state, with_pressure=True)
    shape = film.deformation_shape()
    uniform = film.with_viscosity_field(np.full(shape, state.viscosity)).solve(
        state, with_pressure=True)
    assert uniform.force_x == pytest.approx(scalar.force_x, rel=1e-9)
    assert uniform.force_y == pytest.approx(scalar.force_y, rel=1e-9)
    assert uniform.min_film_thickness == pytest.approx(scalar.min_film_thickness, rel=1e-9)
    assert np.max(np.abs(uniform.pressure - scalar.pressure)) <= 1e-8 * scalar.max_pressure
    # a thinner oil on the loaded side: the elastic film carries less, the bore moves less
    theta, _ = film.grid()
    thin = state.viscosity * (1.0 - 0.4 * np.cos(theta - np.radians(170.0)))[:, None]
    hot = film.with_viscosity_field(np.repeat(thin, shape[1], axis=1))
    assert film.base.viscosity_field is None  # the original keeps the scalar viscosity
    warm = hot.solve(state, with_pressure=True)
    assert np.hypot(warm.force_x, warm.force_y) < 0.9 * np.hypot(scalar.force_x,
                                                                 scalar.force_y)
    assert warm.extra["coupling_residual_m"] <= 1e-9 * film.clearance


def test_the_elastic_films_flows_are_those_of_the_deformed_film():
    """film_flows on the elastic bore: the Reynolds film's flows on the bore the coupling
    finds (its dissipation = shear power of that deformed film)."""
    import dataclasses as dc

    film, state = _elastic_film()
    memory = dc.replace(film.initial_memory(), elapsed=10.0)  # past the rigid start and ramp
    flows, after = film.film_flows(state, memory)
    result, solved = film.solve_with_memory(state, memory, with_pressure=True)
    # the same coupling to its tolerance (1e-9 c; the chord Jacobians carry over)
    assert np.max(np.abs(after.deformation - solved.deformation)) <= 1e-12
    deformed = rated(state, film.film_field(after.deformation), None)
    direct, _ = film.base.film_flows(deformed, solved.inner)
    assert np.allclose(flows.dissipation, direct.dissipation, rtol=1e-9, atol=0.0)
    assert np.max(np.abs(solved.deformation)) > 1e-6  # the bore does deform here
    rigid, _ = film.base.film_flows(state, None if not hasattr(film.base, "initial_memory")
                                    else film.base.initial_memory())
    assert abs(rigid.dissipation.sum() - flows.dissipation.sum()) > 1e-3 * flows.dissipation.sum()


def test_per_node_response_with_a_field_sums_to_the_per_row_one():
    """A housing that deforms along the width moves single film nodes: with a viscosity
    field their response summed over the width is the response to whole rows."""
    film, theta, z = _field_film()
    state = FilmState(eccentricity_x=0.7 * CLEARANCE * np.cos(0.3),
                      eccentricity_y=0.7 * CLEARANCE * np.sin(0.3), velocity_x=0.01,
                      velocity_y=-0.02, journal_speed=272.0, viscosity=0.0095)
    deformed = rated(state, np.zeros(film.deformation_shape()), None)
    pressure = film.solve(deformed, with_pressure=True).pressure
    rows = nodal_force_weights(film, theta, RADIUS)
    by_row = film.thickness_response(deformed, ReynoldsMemory(pressure), rows, STEP)
    by_node = film.thickness_response(deformed, ReynoldsMemory(pressure), rows.ravel(), STEP)
    n_theta, n_nodes = rows.shape
    summed = by_node.nodal_by_bore.reshape(n_theta, n_nodes, n_theta, n_nodes).sum(axis=(1, 3))
    scale = np.max(np.abs(by_row.nodal_by_bore))
    assert np.max(np.abs(summed - by_row.nodal_by_bore)) <= 1e-9 * scale
    force = by_node.force_by_bore.reshape(2, n_theta, n_nodes).sum(axis=2)
    assert np.allclose(force, by_row.force_by_bore, rtol=0.0,
                       atol=1e-9 * np.max(np.abs(by_row.force_by_bore)))
