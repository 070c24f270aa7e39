"""The time-step check of a fixed-step ``rk2`` orbit: the same run at half the step (or,
for rk2's automatic step, by the implicit integrator) and a warning when h_min moves by
more than :func:`conrod.results.summary.step_study_warnings` allows."""

from __future__ import annotations

import dataclasses
from typing import Any

from conrod.errors import CaseError, ConvergenceError
from conrod.results.summary import step_study_warnings
from conrod.simulation.simulation import Simulation


def with_step_check(results: Any, simulation: Simulation) -> Any:
    """``results`` of ``simulation`` with a warning when the orbit at half the step differs
    (h_min); unchanged when there is no reference run for this film."""
    solver = simulation.solver
    step = solver.step_deg  # None: rk2's automatic step, checked against implicit
    finer = ({"step_deg": step / 2.0, "integrator": solver.integrator}
             if step is not None else {"integrator": "implicit"})
    try:
        fine = Simulation(simulation.case, film=solver.film, max_cycles=solver.max_cycles,
                          n_theta=solver.n_theta, n_z=solver.n_z, signoff=False,
                          **finer).run()
    except (CaseError, ConvergenceError):  # no reference for this film: nothing to compare
        return results
    extra = tuple(step_study_warnings(results.summary, fine.summary, step))
    if not extra:
        return results
    summary = dataclasses.replace(results.summary, warnings=results.summary.warnings + extra)
    return dataclasses.replace(results, summary=summary)
