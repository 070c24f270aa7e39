"""The film energy equation (conrod.film.thermal.energy): an adiabatic plane slider against
its closed form, the isothermal limit, energy conservation on the flows of a solved
Reynolds film, and the mixing of recirculating oil with the supply at a groove."""

from __future__ import annotations

import numpy as np
import pytest

from conrod.film.base import BearingGeometry, FeedHole, FilmState
from conrod.film.reynolds.film import ReynoldsFilm
from conrod.film.thermal.energy import ThermalWalls, solve_energy
from conrod.film.thermal.flows import FilmFlows, mean_flows

RHO_C = 860.0 * 2000.0  # [J/(m^3 K)]
ADIABATIC = ThermalWalls(film_coefficient=0.0, housing_coefficient=0.0,
                         housing_temperature=0.0)


def _slider(n: int):
    """Long plane slider h = h_1 (1 + k (1 − x/B)) (inlet h_1(1 + k), outlet h_1), moving
    wall at U, p = 0 at both ends: closed-form pressure gradient and flux (Cameron), laid
    out as one strip of n cells with the inlet fed from outside and the outlet open."""
    length, h1, k, speed, mu, width = 0.05, 20e-6, 1.0, 10.0, 0.02, 1.0
    edges = np.linspace(0.0, length, n + 1)
    x = 0.5 * (edges[1:] + edges[:-1])
    h = h1 * (1.0 + k * (1.0 - x / length))
    h_star = 2.0 * h1 * (1.0 + k) / (2.0 + k)  # film thickness at the pressure peak
    q = 0.5 * speed * h_star * width  # [m^3/s]
    dpdx = 6.0 * mu * speed * (h - h_star) / h**3
    density = mu * speed**2 / h + h**3 / (12.0 * mu) * dpdx**2  # [W/m^2]
    dx = length / n
    east = np.full((n, 1), q)
    east[-1, 0] = 0.0  # the strip is not periodic: nothing flows from the outlet to the inlet
    flows = FilmFlows(east=east, north=np.zeros((n, 1)), dissipation=density[:, None] * dx * width,
                      area=np.full((n, 1), dx * width), supply=np.zeros((n, 1), bool))
    return flows, x, density, q, dx, width


def _closed_form_rise(x, q, length=0.05, h1=20e-6, k=1.0, speed=10.0, mu=0.02, width=1.0):
    """T(x) − T_0 = ∫₀ˣ D'(s) ds /(ρ c_p q), D' the dissipation per length [K] (fine
    quadrature of the closed-form dissipation)."""
    s = np.linspace(0.0, length, 200001)
    h = h1 * (1.0 + k * (1.0 - s / length))
    h_star = 2.0 * h1 * (1.0 + k) / (2.0 + k)
    dpdx = 6.0 * mu * speed * (h - h_star) / h**3
    power = (mu * speed**2 / h + h**3 / (12.0 * mu) * dpdx**2) * width
    cumulative = np.concatenate([[0.0], np.cumsum(0.5 * (power[1:] + power[:-1]) * np.diff(s))])
    return np.interp(x, s, cumulative) / (RHO_C * q)


def test_adiabatic_plane_slider_against_its_closed_form():
    errors = []
    for n in (50, 100, 200):
        flows, x, _, q, dx, _ = _slider(n)
        answer = solve_energy(flows, RHO_C, 40.0, ADIABATIC)
        rise = answer.temperature[:, 0] - 40.0
        outlet = _closed_form_rise(np.array([0.05]), q)[0]
        assert rise[-1] == pytest.approx(outlet, rel=1e-3)  # outlet: the total heat / (ρ c q)
        expected = _closed_form_rise(x + 0.5 * dx, q)  # a cell's value: its outflow face
        errors.append(np.max(np.abs(rise - expected)) / outlet)
        assert answer.to_oil == pytest.approx(answer.generated, rel=1e-12)
    assert errors[-1] < 2e-3
    assert errors[0] / errors[-1] > 3.0  # converges with the grid


def test_isothermal_limit_walls_hold_the_film_at_their_temperature():
    flows, *_ = _slider(50)
    walls = ThermalWalls(film_coefficient=1e12, housing_coefficient=1e12,
                         housing_temperature=80.0, journal_temperature=80.0)
    answer = solve_energy(flows, RHO_C, 40.0, walls)
    assert np.max(np.abs(answer.temperature - 80.0)) < 1e-3
    assert answer.shell_temperature == pytest.approx(80.0, abs=1e-3)


def _fed_film(n_theta: int = 48, n_z: int = 8):
    geometry = BearingGeometry(diameter=0.05, width=0.02, radial_clearance=25e-6,
                               supply_pressure=3e5,
                               feed_holes=(FeedHole(angle=np.pi / 2, diameter=0.005),))
    return ReynoldsFilm(geometry, n_theta=n_theta, n_z=n_z)


def test_energy_is_conserved_on_the_flows_of_a_solved_film():
    film = _fed_film()
    memory = film.initial_memory()
    samples = []
    for angle in np.linspace(0.0, 2 * np.pi, 12, endpoint=False):
        state = FilmState(eccentricity_x=15e-6 * np.cos(angle),
                          eccentricity_y=15e-6 * np.sin(angle),
                          velocity_x=-0.01 * np.sin(angle), velocity_y=0.01 * np.cos(angle),
                          journal_speed=300.0, viscosity=0.01)
        flows, memory = film.film_flows(state, memory)
        samples.append(flows)
    mean = mean_flows(samples)
    walls = ThermalWalls(film_coefficient=3000.0, housing_coefficient=500.0,
                         housing_temperature=90.0)
    answer = solve_energy(mean, RHO_C, 80.0, walls)
    assert abs(answer.imbalance) < 1e-9 * answer.generated
    assert abs(answer.to_journal) < 1e-9 * answer.generated  # adiabatic journal
    assert answer.to_shell == pytest.approx(500.0 * mean.area.sum()
                                            * (answer.shell_temperature - 90.0), rel=1e-9)
    assert answer.temperature.min() > 79.0  # nothing colder than the coolest source


def test_steady_dissipation_is_the_friction_power():
    film = _fed_film()
    state = FilmState(eccentricity_x=15e-6, eccentricity_y=5e-6, journal_speed=300.0,
                      viscosity=0.01)
    flows, _ = film.film_flows(state, film.initial_memory())
    result = film.solve(state)  # steady: no squeeze work; the supply pumps p_s Q_s in
    pumping = film.geometry.supply_pressure * result.supply_flow
    assert flows.pumping_power == pytest.approx(pumping, rel=1e-9)
    assert flows.squeeze_power == 0.0
    assert flows.generated_power == pytest.approx(result.friction_power + pumping, rel=0.03)


def test_squeezed_dissipation_is_friction_plus_squeeze_power():
    """−F·v exactly; dissipation = friction + squeeze + pumping power to the discretisation
    error, which falls at second order (measured 3.5 % → 0.93 % → 0.24 % at 48×8, 96×16,
    192×32)."""
    errors = []
    for n_theta, n_z in ((48, 8), (96, 16)):
        film = _fed_film(n_theta, n_z)
        state = FilmState(eccentricity_x=15e-6, eccentricity_y=5e-6, velocity_x=0.02,
                          velocity_y=-0.01, journal_speed=300.0, viscosity=0.01)
        flows, _ = film.film_flows(state, film.initial_memory())
        result = film.solve(state)
        squeeze = -(result.force_x * 0.02 + result.force_y * -0.01)  # −F·v [W]
        assert flows.squeeze_power == pytest.approx(squeeze, rel=1e-9)
        total = result.friction_power + squeeze + flows.pumping_power
        errors.append(abs(flows.generated_power / total - 1.0))
    assert errors[1] < 0.015
    assert errors[0] / errors[1] > 3.0


def test_supply_mixes_with_recirculating_oil_at_the_groove():
    flows, *_ = _slider(20)
    east = flows.east.copy()
    east[-1, 0] = 0.8 * east[0, 0]  # 80 % recirculates from the outlet back to the inlet
    recirculating = FilmFlows(east=east, north=flows.north, dissipation=flows.dissipation,
                              area=flows.area, supply=flows.supply)
    answer = solve_energy(recirculating, RHO_C, 40.0, ADIABATIC)
    t = answer.temperature[:, 0]
    q = east[0, 0]
    mixed = (0.8 * q * t[-1] + 0.2 * q * 40.0) / q  # (Q_rec T_rec + Q_s T_0)/(Q_rec + Q_s)
    first_rise = flows.dissipation[0, 0] / (RHO_C * q)
    assert t[0] == pytest.approx(mixed + first_rise, rel=1e-12)
    assert answer.to_oil == pytest.approx(answer.generated, rel=1e-12)
