"""The orchestrator: ``Simulation(case).run() -> RunResults`` (issue 4, SPEC S3).

.. code-block:: python

    from conrod import Case, Simulation
    results = Simulation(Case.from_toml("examples/passenger_car_diesel_2000rpm.toml")).run()
    results.summary.h_min          # [m]
    results.cycle.p_max            # [Pa] per output crank angle

Steps: loads (``[engine]`` via :mod:`conrod.loads.engine_loads` or ``[load]`` table) →
film model (``[solver] film``) → periodic orbit from the concentric start → heat balance
(viscosity from ``[lubricant]``, iterated when it depends on temperature) → characteristics
→ contact post-processing of :mod:`conrod.contact.analysis` when that module exists.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from typing import Any

from conrod.cases.case import Case
from conrod.contact.analysis import analyse_contact
from conrod.contact.asperity import kernel_parameters
from conrod.dynamics.characteristics import cycle_characteristics
from conrod.dynamics.heat_balance import effective_temperature, relaxed_update
from conrod.dynamics.periodic import PeriodicOrbit, periodic_orbit
from conrod.dynamics.problem import OrbitProblem
from conrod.errors import CaseError
from conrod.film.base import BearingGeometry, FilmModel, FilmState
from conrod.film.factory import build_film_model
from conrod.loads.cycle import LoadCycle
from conrod.results.cycle_results import CycleResults, RunResults
from conrod.results.summary import summarise

DEFAULT_TABLE_LOAD_MASS = 1.0
"""Moving mass for table loads when ``[solver] mass_x/mass_y`` are not given [kg]."""

ProgressCallback = Callable[[str, int, float], None]
"""progress(stage, cycle, periodicity_error) — called after every integrated cycle."""


class Simulation:
    """Periodic journal-centre orbit and characteristics of one case.

    case : Case  Validated case (needs ``[bearing]`` with ``radial_clearance``,
        ``[lubricant]`` and ``[engine]`` or ``[load]``).
    overrides : keyword arguments replacing ``[solver]`` fields (e.g. ``film="reynolds"``,
        ``integrator="rk2"``, ``max_cycles=2``); validated like the case file.
    """

    def __init__(self, case: Case, **overrides: Any):
        case.require("run", "bearing", "lubricant")
        if case.engine is None and case.load is None:
            raise CaseError("run needs either [engine] or [load] (a load table) in the case file")
        if case.bearing.radial_clearance is None:
            raise CaseError("bearing.radial_clearance: required by 'run' [m]")
        self.case = case
        self.solver = _solver_with(case, overrides)
        self._loads = self._read_loads()  # bad tables fail here, before any integration

    # -- components -------------------------------------------------------------------
    def geometry(self) -> BearingGeometry:
        """Bearing geometry with supply features from ``[bearing]``."""
        bearing = self.case.bearing
        for method in ("to_geometry", "geometry"):
            build = getattr(bearing, method, None)
            if callable(build):
                return build()
        return BearingGeometry(bearing.diameter, bearing.width, bearing.radial_clearance)

    def load_cycle(self) -> LoadCycle:
        """Load and surface speeds over the cycle (engine loads or the load table)."""
        return self._loads

    def _read_loads(self) -> LoadCycle:
        if self.case.load is not None:
            from conrod.loads.table_load import load_cycle_from_table

            return load_cycle_from_table(self.case.load, self.case.resolve(self.case.load.table))
        from conrod.loads.engine_loads import compute_engine_loads

        return compute_engine_loads(self.case).to_load_cycle()

    def masses(self) -> tuple[float, float]:
        """Moving masses along film x and y [kg] (seed 000 §3.2).

        ``[solver] mass_x/mass_y`` when given. For engine loads (rod frame, x towards the
        small end): along the rod the piston plus the whole rod, across it the rod mass
        reduced to the big end m_rod (L − L_1)/L (two-mass split). For table loads
        :data:`DEFAULT_TABLE_LOAD_MASS`.
        """
        s, engine = self.solver, self.case.engine
        if engine is not None:
            along = engine.piston_mass + engine.rod_mass
            across = engine.rod_mass * (engine.rod_length - engine.rod_cg_from_big_end) / (
                engine.rod_length
            )
        else:
            along = across = DEFAULT_TABLE_LOAD_MASS
        mass_x = s.mass_x if s.mass_x is not None else along
        mass_y = s.mass_y if s.mass_y is not None else (s.mass_x or across)
        return mass_x, mass_y

    def film(self) -> FilmModel:
        """The film model of ``[solver] film``."""
        return build_film_model(self.solver, self.geometry(),
                                pressure_viscosity=self.case.lubricant.pressure_viscosity_law())

    def problem(self, viscosity: float | None = None) -> OrbitProblem:
        """Orbit problem at ``viscosity`` [Pa s] (default: at the supply temperature)."""
        lubricant = self.case.lubricant
        mu = viscosity or lubricant.viscosity_at(lubricant.supply_temperature)
        mass_x, mass_y = self.masses()
        return OrbitProblem(
            self.film(), self.load_cycle(), mu, mass_x, mass_y,
            self.case.contact.dry_friction_coefficient, self.solver.contact_film_thickness,
            _asperity_parameters(self.case),
        )

    # -- run --------------------------------------------------------------------------
    def run(self, progress: ProgressCallback | None = None) -> RunResults:
        """Periodic orbit, heat balance, characteristics and contact post-processing."""
        start = time.perf_counter()
        problem = self.problem()
        orbit, cycles, iterations, temperature = self._thermal_orbit(problem, progress)
        problem = problem.with_viscosity(orbit[1])
        cycle = cycle_characteristics(problem, orbit[0].last)
        summary = summarise(
            cycle, orbit[0], problem, self.solver, temperature, cycles, iterations,
        )
        results = RunResults(cycle=cycle, summary=summary, clearance=problem.clearance)
        _attach_pressure_map(results, problem, orbit[0].last.film_history)
        results.previous_cycle_eccentricity = _previous(orbit[0])
        results.contact = _contact_analysis(self.case, cycle)
        summary.wall_time = time.perf_counter() - start
        return results

    def _thermal_orbit(self, problem: OrbitProblem, progress: ProgressCallback | None):
        """Orbit and effective temperature, iterated when μ depends on T (heat_balance)."""
        lubricant, s = self.case.lubricant, self.solver
        temperature = lubricant.supply_temperature
        viscosity, cycles, state = problem.viscosity, 0, None
        iterations = s.thermal_iterations if lubricant.temperature_dependent else 0
        for iteration in range(iterations + 1):
            stage = "orbit" if iteration == 0 else f"heat balance {iteration}"
            orbit = self._orbit(problem.with_viscosity(viscosity), state, stage, progress)
            cycles += orbit.cycles
            target = _heat_balance_temperature(problem.with_viscosity(viscosity), orbit, lubricant)
            if target is None or iteration == iterations:
                return (orbit, viscosity), cycles, iteration, target
            if abs(target - temperature) <= s.thermal_tolerance:
                return (orbit, viscosity), cycles, iteration, target
            temperature = relaxed_update(temperature, target)
            viscosity = lubricant.viscosity_at(temperature)
            state = orbit.last.end_state
        raise AssertionError("unreachable")  # pragma: no cover

    def _orbit(self, problem, state, stage, progress) -> PeriodicOrbit:
        def on_cycle(cycle: int, error: float) -> None:
            if progress is not None:
                progress(stage, cycle, error)

        return periodic_orbit(problem, self.solver, start=state, on_cycle=on_cycle)


def _solver_with(case: Case, overrides: dict[str, Any]):
    clean = {k: v for k, v in overrides.items() if v is not None}
    if not clean:
        return case.solver
    from conrod.cases.base import validate_section
    from conrod.cases.solver import SolverSection

    return validate_section(SolverSection, {**case.solver.model_dump(), **clean}, "solver")


def _heat_balance_temperature(
    problem: OrbitProblem, orbit: PeriodicOrbit, lubricant
) -> float | None:
    """T_eff [°C] from the mean friction power and side flow of ``orbit``."""
    cycle = cycle_characteristics(problem, orbit.last)
    return effective_temperature(
        float(cycle.friction_power.mean()), float(cycle.side_flow.mean()),
        lubricant.supply_temperature, lubricant.density_at(lubricant.supply_temperature),
        lubricant.specific_heat,
    )


def _attach_pressure_map(
    results: RunResults, problem: OrbitProblem, film_history: list | None = None
) -> None:
    """Pressure field at the crank angle of the largest p_max (with the film memory ϑ there,
    for a mass-conserving film)."""
    cycle: CycleResults = results.cycle
    i = int(cycle.p_max.argmax())
    state = FilmState(
        float(cycle.eccentricity_x[i]), float(cycle.eccentricity_y[i]),
        float(cycle.velocity_x[i]), float(cycle.velocity_y[i]),
        float(cycle.journal_speed[i]), float(cycle.shell_speed[i]), problem.viscosity,
        history=film_history[i] if film_history else None,
    )
    field = problem.film.solve(state, with_pressure=True).pressure
    if field is not None:
        results.pressure_at_p_max = field
        results.pressure_grid = problem.film.grid()


def _previous(orbit: PeriodicOrbit):
    import numpy as np

    if orbit.previous is None:
        return None
    return np.vstack([orbit.previous.x, orbit.previous.y])


def _asperity_parameters(case: Case):
    """Greenwood–Tripp kernel parameters when ``[contact] model = "greenwood_tripp"``."""
    if case.contact.model != "greenwood_tripp":
        return None
    return kernel_parameters(case)


def _contact_analysis(case: Case, cycle: CycleResults):
    """Contact post-processing: friction work, wear, Hertz stress (SPEC S4)."""
    return analyse_contact(case, cycle)


__all__ = ["Simulation"]
