"""Cycle summary ([D2] Table 1 'cycle' columns) from the per-angle results."""

from __future__ import annotations

import math

import numpy as np

from conrod.results.cycle_results import CycleResults, RunSummary


def summarise(
    cycle: CycleResults, orbit, problem, solver, temperature: float | None,
    cycles: int, thermal_iterations: int, integrator: str | None = None,
) -> RunSummary:
    """Minimum h_min and maximum p_max with their angles, cycle means, diagnostics.

    ``orbit``: :class:`conrod.orbit.PeriodicOrbit`; ``problem``: the final
    :class:`OrbitProblem`; ``solver``: the ``[solver]`` section used; ``integrator``: name
    of the integrator (default: the one of ``solver``).
    """
    i_h, i_p = int(np.argmin(cycle.h_min)), int(np.argmax(cycle.p_max))
    warnings = []
    if not orbit.periodic:
        warnings.append(
            f"orbit not periodic after {orbit.cycles} cycles: periodicity error "
            f"{orbit.periodicity_error:.3g} > tolerance {solver.periodicity_tolerance:.3g} "
            "(raise solver.max_cycles)"
)
    error = orbit.periodicity_error
    return RunSummary(
        h_min=float(cycle.h_min[i_h]), h_min_crank_angle=float(cycle.crank_angle[i_h]),
        p_max=float(cycle.p_max[i_p]), p_max_crank_angle=float(cycle.crank_angle[i_p]),
        mean_h_min=float(cycle.h_min.mean()), mean_p_max=float(cycle.p_max.mean()),
        mean_friction_power=float(cycle.friction_power.mean()),
        mean_side_flow=float(cycle.side_flow.mean()),
        mean_supply_flow=float(cycle.supply_flow.mean()),
        effective_temperature=temperature, viscosity=problem.viscosity, cycles=cycles,
        periodicity_error=float(error) if math.isfinite(error) else 1.0,
        periodic=bool(orbit.periodic), film_model=str(problem.film.name),
        integrator=str(integrator or solver.integrator), wall_time=0.0,
        thermal_iterations=thermal_iterations,
        max_contact_force=float(cycle.contact_force.max()), warnings=tuple(warnings),
)
