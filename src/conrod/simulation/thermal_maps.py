"""Quasi-steady film temperature maps at chosen crank angles of a converged thermal film
run (``[solver] thermal_map_angles``, docs/thermal.md, *Temperature maps at chosen angles*).

The walls are slow (their thermal time constants are long against a cycle) and the oil's
transit time through the film is short, so at one instant the film's temperature is the
steady answer of that instant's flows with the journal and the shell held at their converged
cycle-mean temperatures. Per map: the output row nearest the asked angle (not interpolated),
one film solve of that row's state (:meth:`film_flows`, the converged viscosity field of
the cycle: the instant's temperature does not feed back into μ) and one energy solve
(:func:`conrod.film.thermal.energy.solve_energy`, fixed walls, the film's own volume change
A ∂h/∂t of the rigid bore carrying the cell's oil). No orbit is run again.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from conrod.cases.base import range_error
from conrod.film.base import FilmState
from conrod.film.thermal.energy import ThermalWalls, solve_energy
from conrod.film.tilt import tilt_fields
from conrod.results.thermal_maps import ThermalMapsResults
from conrod.simulation.thermal_film_run import ThermalFilmOrbit, thermal_orbit

__all__ = ["default_map_angles", "map_rows", "solve_maps", "thermal_maps", "thermal_orbit"]


def thermal_maps(sim: Any, thermal: Any) -> ThermalMapsResults | None:
    """The maps of ``[solver] thermal_map_angles`` of ``sim`` (a
    :class:`~conrod.simulation.simulation.Simulation`) for its converged orbit ``thermal``;
    None unless it is a :class:`ThermalFilmOrbit` with angles to map."""
    if not isinstance(thermal, ThermalFilmOrbit):
        return None
    asked = sim.solver.thermal_map_angles
    angles = default_map_angles(thermal.cycle) if asked is None else np.asarray(asked, float)
    if angles.size == 0:
        return None
    lubricant = sim.case.lubricant
    supply = lubricant.supply_temperature
    heat_capacity = lubricant.density_at(supply) * lubricant.specific_heat
    return solve_maps(thermal, angles, heat_capacity, supply, sim.solver.thermal_wall_coefficient)


def default_map_angles(cycle: Any) -> np.ndarray:
    """The crank angles of the smallest h_min and of the largest p_max (one when they are
    the same row) [deg]."""
    rows = [int(np.argmin(cycle.h_min)), int(np.argmax(cycle.p_max))]
    return np.asarray(cycle.crank_angle_deg)[sorted(set(rows))]


def map_rows(crank_angle_deg: np.ndarray, angles: np.ndarray, cycle_deg: float) -> np.ndarray:
    """Index of the output row nearest each asked angle [deg], the distance taken around the
    cycle of ``cycle_deg`` [deg]; an angle beyond the cycle is refused in one line."""
    for angle in angles:
        if not 0.0 <= angle <= cycle_deg:
            raise range_error("solver.thermal_map_angles", float(angle),
                              f"0 … {cycle_deg:g} (this case's cycle)", "deg")
    distance = np.abs(np.subtract.outer(angles, crank_angle_deg)) % cycle_deg
    return np.argmin(np.minimum(distance, cycle_deg - distance), axis=1)


def solve_maps(thermal: ThermalFilmOrbit, angles: np.ndarray, heat_capacity: float,
               supply: float, film_coefficient: float) -> ThermalMapsResults:
    """The maps at ``angles`` [deg] (module docstring); ρc_p = ``heat_capacity``
    [J/(m³ K)], supply temperature [°C], film-to-wall coefficient [W/(m² K)]."""
    problem, cycle, film = thermal.problem, thermal.cycle, thermal.film
    walls = ThermalWalls(film_coefficient=film_coefficient, housing_coefficient=0.0,
                         housing_temperature=film.housing_temperature,
                         journal_temperature=film.journal_temperature,
                         shell_temperature=film.shell_temperature)
    rows = map_rows(np.asarray(cycle.crank_angle_deg), angles,
                    float(np.degrees(problem.loads.cycle)))
    answers, shares = zip(*(_map_at(problem, cycle, int(i), heat_capacity, supply, walls)
                            for i in rows), strict=True)
    return ThermalMapsResults(
        requested_deg=angles, crank_angle_deg=np.asarray(cycle.crank_angle_deg)[rows],
        temperature=np.array([a.temperature for a in answers]),
        theta=np.asarray(film.theta), z=np.asarray(film.z),
        journal_temperature=film.journal_temperature,
        shell_temperature=film.shell_temperature,
        generated=np.array([a.generated for a in answers]),
        to_oil=np.array([a.to_oil for a in answers]),
        to_journal=np.array([a.to_journal for a in answers]),
        to_shell=np.array([a.to_shell for a in answers]),
        to_volume=np.array([a.to_volume for a in answers]),
        friction_power=np.asarray(cycle.friction_power)[rows],
        squeeze_share=np.array(shares))


def _map_at(problem: Any, cycle: Any, row: int, heat_capacity: float, supply: float,
            walls: ThermalWalls) -> tuple[Any, float]:
    """The energy answer (:class:`~conrod.film.thermal.energy.FilmTemperature`) of output row
    ``row`` — one film solve, one energy solve — and its squeeze share
    (:func:`squeeze_share`)."""
    state = problem.row_state(cycle, row)
    flows, _ = problem.film.film_flows(state, problem.film.initial_memory())
    volume_rate = flows.area * thickness_rate(state, *problem.film.grid())
    answer = solve_energy(flows, heat_capacity, supply, walls, volume_rate)
    return answer, squeeze_share(flows, volume_rate)


def squeeze_share(flows: Any, volume_rate: np.ndarray) -> float:
    """Share of the film area whose oil is squeezed out faster than oil flows in through
    the cell's faces, −A ∂h/∂t > Σ inflow [-]: there the oil stays longer than a transit
    and the quasi-steady temperature is too high (docs/thermal.md)."""
    east, north = flows.east, flows.north
    inflow = np.maximum(np.roll(east, 1, axis=0), 0.0) + np.maximum(-east, 0.0)
    inflow += np.maximum(-north, 0.0)
    inflow[:, 1:] += np.maximum(north[:, :-1], 0.0)
    squeezed = -volume_rate > inflow
    return float(flows.area[squeezed].sum() / flows.area.sum())


def thickness_rate(state: FilmState, theta: np.ndarray, z: np.ndarray) -> np.ndarray:
    """∂h/∂t of a rigid bore at the film nodes, −ė_x cos θ − ė_y sin θ plus the journal's
    tilt rate (:func:`conrod.film.tilt.tilt_fields`) [m/s], shape (n_θ, n_z + 1)."""
    cos, sin = np.cos(theta), np.sin(theta)
    rate = np.repeat((-state.velocity_x * cos - state.velocity_y * sin)[:, None], z.size, 1)
    if state.tilted:
        _, tilt_rate = tilt_fields(state, cos, sin, z)
        if tilt_rate is not None:
            rate = rate + tilt_rate
    return rate
