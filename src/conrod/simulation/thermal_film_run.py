"""The thermal film over the cycle (``[solver] thermal = "film"``, docs/thermal.md).

Iteration: the periodic orbit with the viscosity field μ(T(θ, z)) of the lubricant's
viscosity–temperature law (the orbit's scalar viscosity, the reference of the film's
source terms, at the film's mean temperature) → the cycle-mean volume fluxes and
dissipation from one film solve per output angle (:meth:`film_flows`) → the steady film
energy equation (:func:`conrod.film.thermal.energy.solve_energy`) → T under-relaxed
(:data:`conrod.orbit.heat_balance.RELAXATION`), until the largest change of T is at most
``[solver] thermal_tolerance`` [K] or ``thermal_iterations`` are done (then a warning). The
thermal time constant of the bearing is long against a cycle, so one steady field per cycle
is solved, not a field per step. On the elastic bore the film is the elastic film carrying
the field (:mod:`conrod.ehd.viscosity_field`); with a ``[housing.thermal]`` that gives no
temperatures the bore is rebuilt warm from each energy solution before the next orbit
(:mod:`conrod.simulation.warm_film_run`).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable
from typing import Any

import numpy as np

from conrod.errors import CaseError
from conrod.film.capabilities import HasDeformedGap, HasViscosityField
from conrod.film.thermal.energy import ThermalWalls, solve_energy
from conrod.film.thermal.flows import FilmFlows, mean_flows
from conrod.orbit.characteristics import cycle_characteristics
from conrod.orbit.heat_balance import RELAXATION
from conrod.orbit.periodic import PeriodicOrbit, periodic_orbit
from conrod.orbit.problem import OrbitProblem
from conrod.results.cycle_results import CycleResults
from conrod.results.thermal import ThermalFilmResults
from conrod.simulation.orbit_outputs import film_asperity_force
from conrod.simulation.warm_film_run import WarmFilmBore, film_driven


@dataclasses.dataclass(frozen=True)
class ThermalFilmOrbit:
    """The converged orbit of the thermal film with the fields of the heat-balance orbit
    (``orbit``, ``problem``, ``cycle``, ``temperature`` — the film's mean [°C] —, ``cycles``,
    ``iterations``, ``asperity_force``) and the temperature field (``film``)."""

    orbit: PeriodicOrbit
    problem: OrbitProblem
    cycle: CycleResults
    temperature: float
    cycles: int
    iterations: int
    asperity_force: np.ndarray | None
    film: ThermalFilmResults
    rows: None = None
    """No film results kept for the sign-off: the thermal film's rows carry its temperature
    field, which the sign-off reads from the film (as :class:`~conrod.simulation.simulation.\
ThermalOrbit`'s ``rows``)."""


def thermal_orbit(sim: Any, heat_balance: Callable, progress: Any = None) -> Any:
    """The orbit of ``sim`` (a :class:`~conrod.simulation.simulation.Simulation`) with its
    film temperature: ``heat_balance(problem, progress)`` (the global heat balance) unless
    ``[solver] thermal = "film"``, then :func:`thermal_film_orbit`."""
    if sim.solver.thermal != "film":
        return heat_balance(sim.problem(), progress)
    return thermal_film_orbit(sim, progress)


def thermal_film_orbit(sim: Any, progress: Any = None) -> ThermalFilmOrbit:
    """Orbit and film temperature iterated to the tolerance (module docstring)."""
    lubricant, s = sim.case.lubricant, sim.solver
    supply = lubricant.supply_temperature
    walls = _walls(s, supply)
    warm = WarmFilmBore.start(sim, walls) if film_driven(sim) else None  # TEHD
    problem = sim.problem() if warm is None else warm.current.problem()
    film = _thermal_film(problem, lubricant)
    heat_capacity = lubricant.density_at(supply) * lubricant.specific_heat
    temperature = np.full(film.deformation_shape(), float(supply))
    iterations = (s.thermal_iterations if lubricant.temperature_dependent or warm is not None
                  else 1)
    state, cycles = None, 0
    for iteration in range(1, max(iterations, 1) + 1):
        current = _problem_at(problem, film, lubricant, temperature)
        orbit = periodic_orbit(current, s, integrator=sim.integrator(), start=state,
                               on_cycle=_reporter(progress, f"thermal film {iteration}"))
        cycles += orbit.cycles_run
        cycle = cycle_characteristics(current, orbit.last)
        flows = cycle_flows(current, cycle, orbit.last.film_memory)
        answer = solve_energy(flows, heat_capacity, supply, walls)
        change = (float(np.max(np.abs(answer.temperature - temperature)))
                  if lubricant.temperature_dependent else 0.0)  # μ(T) constant: no feedback
        if warm is not None:  # the warm bore's temperatures settle too
            change = max(change, warm.target_change(answer, flows.area, walls))
        if change <= s.thermal_tolerance or iteration >= iterations:
            break
        temperature = temperature + RELAXATION * (answer.temperature - temperature)
        if warm is not None:  # c + Δc and h₀(θ) of the relaxed temperatures
            warm.update(answer, flows.area, walls)
            problem = warm.current.problem()
            film = _thermal_film(problem, lubricant)
        state = orbit.last.end_state
    asperity = film_asperity_force(current, cycle, orbit.last.film_memory)
    result = _results(answer, flows, film, walls, cycle, (iteration, change), s, lubricant)
    if warm is not None:
        result = dataclasses.replace(result, warm_bore=warm.results())
    return ThermalFilmOrbit(orbit, current, cycle, result.mean_temperature, cycles, iteration,
                            asperity, result)


def cycle_flows(problem: OrbitProblem, cycle: CycleResults,
                film_memory: list | None = None) -> FilmFlows:
    """Cycle-mean fluxes and dissipation: one warm-started film solve per output angle
    (equally spaced in time at a constant crank speed) [m³/s, W]; a film on a deforming bore
    (:class:`~conrod.film.capabilities.HasDeformedGap`) starts each from the memory the
    orbit sampled there (``film_memory``: its bore deformation and crank angle)."""
    film = problem.film
    memory = film.initial_memory()
    sampled = film_memory if isinstance(film, HasDeformedGap) else None
    samples = []
    for i in range(len(cycle.crank_angle)):
        start = memory if sampled is None else sampled[i]
        flows, memory = film.film_flows(problem.row_state(cycle, i), start)
        samples.append(flows)
    return mean_flows(samples)


def _thermal_film(problem: OrbitProblem, lubricant: Any) -> Any:
    """The problem's film, refused in one line unless it takes a viscosity field."""
    film = problem.film
    if not isinstance(film, HasViscosityField):
        raise CaseError(f"[solver] thermal = 'film': film {film.name!r} cannot take a "
                        "viscosity field (allowed: reynolds on a rigid bore; or thermal = "
                        "'heat_balance')")
    if lubricant.pressure_viscosity_law() is not None:
        raise CaseError("[solver] thermal = 'film' with lubricant.pressure_viscosity = "
                        f"{lubricant.pressure_viscosity!r}: not combined (allowed: "
                        "pressure_viscosity = 'none', or thermal = 'heat_balance')")
    return film


def _problem_at(problem: OrbitProblem, film: Any, lubricant: Any,
                temperature: np.ndarray) -> OrbitProblem:
    """The orbit problem with the viscosity field of ``temperature`` [°C] and the scalar
    viscosity at its mean (the reference of the source terms) [Pa s]; a uniform field (a
    viscosity independent of temperature, or the first iteration at the supply
    temperature) is the scalar viscosity itself, and the orbit takes the film's fast paths
    for it (the same answer, :mod:`conrod.film.reynolds.viscosity_field`)."""
    reference = float(lubricant.viscosity_at(float(temperature.mean())))
    field = np.vectorize(lubricant.viscosity_at, otypes=[float])(temperature)
    uniform = bool(np.all(field == reference))
    return dataclasses.replace(problem, film=film.with_viscosity_field(
        None if uniform else field), viscosity=reference)


def _walls(solver: Any, supply: float) -> ThermalWalls:
    """The heat paths of ``[solver]`` (housing at the supply temperature unless given)."""
    housing = solver.thermal_housing_temperature
    return ThermalWalls(film_coefficient=solver.thermal_wall_coefficient,
                        housing_coefficient=solver.thermal_housing_coefficient,
                        housing_temperature=supply if housing is None else housing,
                        journal_temperature=solver.thermal_journal_temperature)


def _results(answer, flows, film, walls, cycle, progress, solver, lubricant
             ) -> ThermalFilmResults:
    """The run's temperature field and heat flows (``progress``: iterations, last change)."""
    theta, z = film.grid()
    iteration, change = progress
    return ThermalFilmResults(
        temperature=answer.temperature, theta=np.asarray(theta), z=np.asarray(z),
        journal_temperature=answer.journal_temperature,
        shell_temperature=answer.shell_temperature,
        housing_temperature=walls.housing_temperature,
        supply_temperature=lubricant.supply_temperature,
        generated=answer.generated, to_oil=answer.to_oil, to_journal=answer.to_journal,
        to_shell=answer.to_shell, friction_power=float(cycle.friction_power.mean()),
        squeeze_power=flows.squeeze_power, pumping_power=flows.pumping_power,
        iterations=iteration, change=change, tolerance=solver.thermal_tolerance,
        max_valid_temperature=lubricant.max_temperature)


def _reporter(progress: Any, stage: str) -> Callable[[int, float], None]:
    def on_cycle(cycle: int, error: float) -> None:
        if progress is not None:
            progress(stage, cycle, error)
    return on_cycle
