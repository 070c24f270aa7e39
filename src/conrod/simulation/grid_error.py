"""The grid-error estimate of a run on a grid film (``conrod run``; :mod:`conrod.results.
grid_error`): the same orbit on two coarser grids, the cycle's smallest film h_min and
largest p_max of each grid (each at its own critical crank angle: where the thinnest film
sits can move between neighbouring angles from grid to grid), Richardson extrapolation
with the observed order."""

from __future__ import annotations

import dataclasses
import functools
from typing import Any

import numpy as np

from conrod.cases.solver import SolverSection
from conrod.errors import ConvergenceError
from conrod.results.grid_error import GridError, GridEstimate, cell_size, richardson
from conrod.results.summary import film_minimum

GRID_FILMS = ("reynolds", "mass_conserving")
"""Films solved on the ``[solver]`` grid, whose answer depends on it [-]."""
RATIOS = (1.4, 2.0)
"""Coarsening of the two coarser grids: n_θ and n_z divided by about these [-]."""
FEATURE_CELLS = 3.0
"""A groove or hole spanning fewer axial cells than this on the run grid is not resolved:
its edges snap to other nodes on every grid and the values need not converge [-]."""


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


def estimate_grids(simulation: Any) -> tuple[tuple[int, int], ...]:
    """The coarser grids of ``simulation``'s grid-error estimate (() when its film has no
    grid or the grid cannot be coarsened twice)."""
    coarse = coarser_grids((simulation.solver.n_theta, simulation.solver.n_z))
    film = simulation.solver.film
    return tuple(coarse) if film in GRID_FILMS and len(coarse) == len(RATIOS) else ()


def coarse_jobs(simulation: Any) -> tuple[tuple[Any, Any], ...]:
    """The coarser orbits of the estimate as jobs (grid, function) for
    :func:`conrod.simulation.side_runs.beside`."""
    return tuple((grid, functools.partial(coarse_cycle, simulation, grid, None))
                 for grid in estimate_grids(simulation))


def with_grid_error(results: Any, simulation: Any, progress: Any = None) -> Any:
    """``results`` with ``summary.grid_error`` (:class:`GridError`) when the film has a grid
    that can be coarsened twice; unchanged otherwise. The coarser orbits run with the same
    case, integrator and settings but without a rigid companion (computed beside the run by
    :mod:`conrod.simulation.side_runs` where it started them)."""
    solver = simulation.solver
    grid = (solver.n_theta, solver.n_z)
    coarse = estimate_grids(simulation)
    if results.summary.film_model not in GRID_FILMS or not coarse:
        return results
    try:
        cycles = [getattr(results, "elastic", results).cycle] + [
            _coarse(simulation, g, progress) for g in coarse]
    except ConvergenceError as error:  # the run stands; its grid error is a doubt, said
        text = str(error).splitlines()[0] if str(error) else type(error).__name__
        warning = (f"grid error not estimated: the orbit on the coarser grid of the estimate "
                   f"({' or '.join(f'{g[0]} × {g[1]}' for g in coarse)}) failed ({text}); "
                   "the printed h_min and p_max carry no grid-error estimate "
                   "(a finer --grid, or --no-grid-error)")
        summary = dataclasses.replace(results.summary,
                                      warnings=(*results.summary.warnings, warning))
        return _with_summary(results, summary)
    grids = (grid, *coarse)
    estimate = GridError(grids, _estimate("h_min", cycles, grids),
                         _estimate("p_max", cycles, grids),
                         feature_note(simulation.geometry(), solver.n_z))
    summary = dataclasses.replace(results.summary, grid_error=estimate)
    return _with_summary(results, summary)


def feature_note(geometry: Any, n_z: int) -> str:
    """Words on the oil-supply feature worst resolved axially on the run grid ('' when every
    groove and hole spans at least :data:`FEATURE_CELLS` axial cells)."""
    spacing = geometry.width / n_z
    features = [("groove", groove.width) for groove in geometry.grooves
                if groove.width < geometry.width]
    features += [("hole", hole.diameter) for hole in geometry.feed_holes]
    if not features:
        return ""
    name, size = min(features, key=lambda item: item[1])
    cells = size / spacing
    if cells >= FEATURE_CELLS:
        return ""
    return (f"the {size * 1e3:.3g} mm {name} spans {cells:.1f} axial cells of the run grid: "
            "its edges fall on other nodes on every grid, so the values need not converge "
            "monotonically and the error can be larger or of the other sign (a finer n_z "
            "resolves it)")


def _coarse(simulation: Any, grid: tuple[int, int], progress: Any) -> Any:
    from conrod.simulation.side_runs import MISSING, take

    cycle = take(grid)
    return coarse_cycle(simulation, grid, progress) if cycle is MISSING else cycle


def coarse_cycle(simulation: Any, grid: tuple[int, int], progress: Any) -> Any:
    """The periodic cycle of ``simulation`` on ``grid`` (elastic where it is elastic): the
    orbit and its characteristics alone (:meth:`~conrod.simulation.simulation.Simulation.
    run_orbit`), without the elastic run's diagnostics (bore, stresses, film maps), which
    the estimate does not read."""
    from conrod.simulation.simulation import Simulation

    staged = None
    if progress is not None:
        def staged(stage: str, cycle: int, error: float) -> None:
            progress(f"grid {grid[0]}x{grid[1]} {stage}", cycle, error)
    coarse = Simulation(simulation.case, film=simulation.solver.film,
                        integrator=simulation.solver.integrator, rigid_companion=False,
                        signoff=False,
                        **{**_overrides(simulation), "n_theta": grid[0], "n_z": grid[1]})
    if coarse.elastic():
        from conrod.simulation.ehd_run import check_integrator

        check_integrator(coarse)
    return coarse.run_orbit(staged)[0].cycle


def _overrides(simulation: Any) -> dict[str, Any]:
    """The ``[solver]`` values the run set on top of the case's."""
    own, case = simulation.solver.model_dump(), simulation.case.solver.model_dump()
    return {key: value for key, value in own.items() if case.get(key) != value
            and key not in ("film", "integrator")}


def _estimate(quantity: str, cycles: list[Any], grids) -> GridEstimate:
    extremes = [_extreme(cycle, quantity) for cycle in cycles]
    values = tuple(value for value, _ in extremes)
    order, error = richardson(values, tuple(cell_size(g) for g in grids))
    return GridEstimate(quantity, float(np.degrees(extremes[0][1])), values, order, error,
                        tuple(float(np.degrees(angle)) for _, angle in extremes))


def _extreme(cycle: Any, quantity: str) -> tuple[float, float]:
    """(the cycle's smallest film h_min or largest p_max, its crank angle [rad])."""
    if quantity == "h_min":
        thinnest = film_minimum(cycle)
        if thinnest is not None:
            return thinnest
        row = int(np.argmin(cycle.h_min))
    else:
        row = int(np.argmax(cycle.p_max))
    return float(getattr(cycle, quantity)[row]), float(cycle.crank_angle[row])


def _with_summary(results: Any, summary: Any) -> Any:
    if hasattr(results, "elastic"):
        return dataclasses.replace(results, elastic=dataclasses.replace(results.elastic,
                                                                        summary=summary))
    return dataclasses.replace(results, summary=summary)
