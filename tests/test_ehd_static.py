"""Static elastohydrodynamic equilibrium with an imported compliance and a constant load
table: the answer does not depend on the coupling algorithm, and the film carries the load."""

from __future__ import annotations

import dataclasses
import tomllib

import numpy as np
import pytest

from conrod.cases.case import Case
from conrod.ehd.film import ElasticFilm
from conrod.film.base import FilmState
from conrod.housing.housing import Housing
from conrod.simulation.simulation import Simulation
from elastic_helpers import EXAMPLES, kamaz_case, tight_coupling

N_THETA, N_Z = 36, 8
LOAD = 2_500.0  # [N] constant, pressing the journal towards θ = 200°
SOFTENING = 1.0  # the estimated KamAZ rod as it is: bore deformation of the order of h_min


@pytest.fixture(scope="module")
def case(tmp_path_factory) -> Case:
    """KamAZ bearing, a constant [load] table, the built-in rod's compliance exported and
    re-imported as `model = "compliance"`."""
    folder = tmp_path_factory.mktemp("static_ehd")
    builtin = Housing.from_case(kamaz_case(n_theta=N_THETA), use_cache=False)
    np.savez(folder / "c.npz", angle_deg=np.degrees(builtin.angles),
             compliance_m_per_N=SOFTENING * builtin.compliance)
    angles = np.arange(0.0, 721.0, 10.0)
    direction = np.radians(200.0)
    rows = [f"{a},{LOAD * np.cos(direction)},{LOAD * np.sin(direction)}" for a in angles]
    (folder / "load.csv").write_text("crank_angle_deg,load_x_N,load_y_N\n" + "\n".join(rows))
    data = tomllib.loads((EXAMPLES / "kamaz_740_truck_diesel.toml").read_text())
    data = {key: data[key] for key in ("title", "bearing", "lubricant")}
    data["load"] = {"table": "load.csv", "speed": 2600, "cycle_deg": 720}
    data["housing"] = {"model": "compliance", "compliance_file": "c.npz"}
    data["solver"] = {"film": "reynolds", "n_theta": N_THETA, "n_z": N_Z}
    return Case.from_dict(data, base_dir=folder)


def _equilibrium(film, loads, viscosity: float) -> tuple[np.ndarray, np.ndarray]:
    """(x, y) [m] where F + W = 0 with the journal at rest, and F + W [N] there."""
    c = film.geometry.radial_clearance
    load = np.array([loads.load_x[0], loads.load_y[0]])

    def residual(position):
        state = FilmState(eccentricity_x=c * position[0], eccentricity_y=c * position[1],
                          velocity_x=0.0, velocity_y=0.0,
                          journal_speed=float(loads.journal_speed[0]), shell_speed=0.0,
                          viscosity=viscosity)
        result = film.solve(state)
        return (np.array([result.force_x, result.force_y]) + load) / np.hypot(*load)

    position = 0.7 * load / np.hypot(*load)
    r = residual(position)
    for _ in range(40):  # Newton, finite-difference Jacobian, steps kept inside the circle
        if np.hypot(*r) <= 1e-9:
            break
        jac = np.column_stack([(residual(position + d) - r) / 1e-7
                               for d in (np.array([1e-7, 0.0]), np.array([0.0, 1e-7]))])
        step = -np.linalg.solve(jac, r)
        lam = 1.0
        while np.hypot(*(position + lam * step)) >= 0.995:
            lam *= 0.5
        position = position + lam * step
        r = residual(position)
    return c * position, r * np.hypot(*load)


def test_static_equilibrium_is_independent_of_the_coupling_algorithm(case):
    simulation = Simulation(case)
    film = simulation.film_model()
    assert isinstance(film, ElasticFilm) and film.housing.info["model"] == "compliance"
    loads, mu = simulation.load_cycle(), simulation.problem().viscosity
    slow = ElasticFilm(film.base, film.housing, film.crank_speed, dataclasses.replace(
        film.settings, method="fixed_point", relaxation=0.1, tolerance=1e-10,
        max_iterations=200))
    newton_position, newton_balance = _equilibrium(film, loads, mu)
    fixed_position, fixed_balance = _equilibrium(slow, loads, mu)
    rigid_position, _ = _equilibrium(film.base, loads, mu)
    c = film.geometry.radial_clearance
    # the two coupling algorithms give one equilibrium ...
    assert np.max(np.abs(newton_position - fixed_position)) <= 1e-6 * c
    # ... the film carries the load ...
    assert np.hypot(*newton_balance) <= 1e-6 * LOAD
    assert np.hypot(*fixed_balance) <= 1e-6 * LOAD
    # ... and the deformation matters: the elastic equilibrium is not the rigid one
    assert np.max(np.abs(newton_position - rigid_position)) >= 1e-3 * c


def test_coupling_converges_where_the_fixed_point_is_slow(case):
    """Newton with the film's exact response needs a fraction of the film solves of the
    under-relaxed fixed point, and a handful from the converged deformation of a nearby
    state (the orbit's warm start), each to the tight coupling tolerance of 1e-9 c (the
    rate of the iteration is what is measured; the default is 1e-7 c)."""
    simulation = Simulation(tight_coupling(case))
    film = simulation.film_model()
    loads, mu = simulation.load_cycle(), simulation.problem().viscosity
    c = film.geometry.radial_clearance
    state = FilmState(eccentricity_x=-0.75 * c * np.cos(0.3),
                      eccentricity_y=-0.75 * c * np.sin(0.3), velocity_x=0.0, velocity_y=0.0,
                      journal_speed=float(loads.journal_speed[0]), shell_speed=0.0, viscosity=mu)
    fast, memory = film.solve_with_memory(state, film._static_memory())
    slow = ElasticFilm(film.base, film.housing, film.crank_speed, dataclasses.replace(
        film.settings, method="fixed_point", relaxation=0.1, max_iterations=200)).solve(state)
    # from a rigid bore ...
    assert fast.extra["coupling_iterations"] < 0.3 * slow.extra["coupling_iterations"]
    # ... and from the deformation of a nearby state (the next step): the film solve at the
    # start and at most four Newton updates to max|G| <= 1e-9 c
    nearby = dataclasses.replace(state, eccentricity_x=state.eccentricity_x * 1.01)
    again, _ = film.solve_with_memory(nearby, memory)
    assert again.extra["coupling_iterations"] - memory.iterations <= 5
    assert again.extra["coupling_residual_m"] <= 1e-9 * c
    assert fast.extra["coupling_residual_m"] <= 1e-9 * c
    assert abs(fast.force_x - slow.force_x) <= 1e-6 * abs(fast.force_x)
