"""The simulation's bearing geometry as built and warm: ``[housing.assembly]`` and
``[housing.thermal]`` through :mod:`conrod.housing.as_built`."""

from __future__ import annotations

from typing import Any

GRID_FILMS = ("reynolds", "mass_conserving")
"""Films that take a bore profile (the as-built bore) [-]."""


def as_built(simulation: Any, geometry: Any, film_by_name: bool) -> Any:
    """``geometry`` of ``[bearing]`` as built and warm for ``simulation``: the warm
    clearance, and the housing's static bore shape in the profile of a grid film named by
    the case or the simulation (``film_by_name``; a film object keeps its own geometry)."""
    from conrod.housing.as_built import run_geometry
    from conrod.housing.housing import Housing

    case = simulation.case.model_copy(update={"solver": simulation.solver})
    grid = film_by_name and simulation.solver.film in GRID_FILMS
    return run_geometry(geometry, simulation.case.housing, simulation.housing, case, grid,
                        lambda: Housing.from_case(case).warm)


def warm_note(simulation: Any) -> str:
    """`` (warm clearance … µm)`` for the headline's bore with ``[housing.thermal]``, else
    ''."""
    thermal = simulation.case.housing.thermal
    if thermal is None or not thermal.active:
        return ""
    return f" (warm clearance {simulation.geometry().radial_clearance * 1e6:.2f} µm)"
