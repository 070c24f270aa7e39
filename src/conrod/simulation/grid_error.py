"""The grid-error estimate of a run on a grid film (``conrod run``; :mod:`conrod.results.
grid_error`): the same orbit on two coarser grids, h_min and p_max compared at the run's
critical crank angles, Richardson extrapolation with the observed order."""

from __future__ import annotations

import dataclasses
from typing import Any

import numpy as np

from conrod.cases.solver import SolverSection
from conrod.results.grid_error import GridError, GridEstimate, cell_size, richardson
from conrod.results.summary import film_minimum

GRID_FILMS = ("reynolds", "mass_conserving")
"""Films solved on the ``[solver]`` grid, whose answer depends on it [-]."""
RATIOS = (1.4, 2.0)
"""Coarsening of the two coarser grids: n_θ and n_z divided by about these [-]."""


def coarser_grids(grid: tuple[int, int]) -> list[tuple[int, int]]:
    """The two coarser grids of ``grid`` (n_θ, n_z): each count divided by about
    :data:`RATIOS`, even and within the ``[solver]`` limits, each strictly coarser than the
    one before; fewer when the grid cannot be coarsened."""
    low_theta = SolverSection.model_fields["n_theta"].metadata[0].ge
    low_z = SolverSection.model_fields["n_z"].metadata[0].ge
    grids, last = [], grid
    for ratio in RATIOS:
        candidate = (max(low_theta, 2 * round(grid[0] / ratio / 2)),
                     max(low_z, 2 * round(grid[1] / ratio / 2)))
        if cell_size(candidate) > cell_size(last) * 1.2:
            grids.append(candidate)
            last = candidate
    return grids


def with_grid_error(results: Any, simulation: Any, progress: Any = None) -> Any:
    """``results`` with ``summary.grid_error`` (:class:`GridError`) when the film has a grid
    that can be coarsened twice; unchanged otherwise. The coarser orbits run with the same
    case, integrator and settings but without a rigid companion."""
    solver = simulation.solver
    name = results.summary.film_model
    grid = (solver.n_theta, solver.n_z)
    coarse = coarser_grids(grid)
    if name not in GRID_FILMS or len(coarse) < 2:
        return results
    runs = [results] + [_coarse_run(simulation, g, progress) for g in coarse]
    grids = (grid, *coarse)
    thinnest = film_minimum(results.cycle)
    h_angle = thinnest[1] if thinnest is not None else results.summary.h_min_crank_angle
    p_angle = results.summary.p_max_crank_angle
    estimate = GridError(grids, _estimate("h_min", runs, grids, h_angle),
                         _estimate("p_max", runs, grids, p_angle))
    summary = dataclasses.replace(results.summary, grid_error=estimate)
    return _with_summary(results, summary)


def _coarse_run(simulation: Any, grid: tuple[int, int], progress: Any) -> Any:
    from conrod.simulation.simulation import Simulation

    staged = None
    if progress is not None:
        def staged(stage: str, cycle: int, error: float) -> None:
            progress(f"grid {grid[0]}x{grid[1]} {stage}", cycle, error)
    coarse = Simulation(simulation.case, film=simulation.solver.film,
                        integrator=simulation.solver.integrator, rigid_companion=False,
                        **{**_overrides(simulation), "n_theta": grid[0], "n_z": grid[1]})
    results = coarse.run(staged)
    return getattr(results, "elastic", results)


def _overrides(simulation: Any) -> dict[str, Any]:
    """The ``[solver]`` values the run set on top of the case's."""
    own, case = simulation.solver.model_dump(), simulation.case.solver.model_dump()
    return {key: value for key, value in own.items() if case.get(key) != value
            and key not in ("film", "integrator")}


def _estimate(quantity: str, runs: list[Any], grids, crank_angle: float) -> GridEstimate:
    values = tuple(_value_at(getattr(run, "elastic", run).cycle, quantity, crank_angle)
                   for run in runs)
    order, error = richardson(values, tuple(cell_size(g) for g in grids))
    return GridEstimate(quantity, float(np.degrees(crank_angle)), values, order, error)


def _value_at(cycle: Any, quantity: str, crank_angle: float) -> float:
    """The quantity at the output angle nearest ``crank_angle`` [rad]."""
    row = int(np.argmin(np.abs(np.asarray(cycle.crank_angle) - crank_angle)))
    return float(getattr(cycle, quantity)[row])


def _with_summary(results: Any, summary: Any) -> Any:
    if hasattr(results, "elastic"):
        return dataclasses.replace(results, elastic=dataclasses.replace(results.elastic,
                                                                        summary=summary))
    return dataclasses.replace(results, summary=summary)
